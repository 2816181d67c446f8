// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The cuts of the nets' faces into triangles. A face between two voxels is a polygon of the
// points of the four dual cells around it, counterclockwise seen from its second voxel; at each
// cell, its corner is one point or, where its two dual edges there have different points, both.
// It is cut into triangles by diagonals between opposite cells only: a diagonal between
// neighbouring cells could be an edge of other faces too, and two faces of one label around a
// dual edge could cut the same triangle. A quad gives (0, 1, 2) and (0, 2, 3).
//
// Where ears of opposite cells alone cannot cut a face (a dead end), the rest is cut so that its
// triangle turned furthest from the face's axis (the least cosine between its normal and the
// axis) is turned least, on the points at the centres of their boxes: from the voxels alone. The
// polygon's first ear each time, the earlier rule, could lay triangles on three points of a
// junction line in two faces along it, folded onto each other. A flat triangle ranks below any
// other, and one that shares a triangle or a diagonal with another face's cut below that: only a
// triangle with two points of one cell can be shared, and only a diagonal between points of one
// cell or of neighbouring ones, which these cuts alone make. Two faces of one label must share
// neither (a triangle twice, or an edge of four), so the dead ends are cut after all others.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FACE_CUTS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FACE_CUTS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Net_points.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/assertions.h>

#include <boost/container/static_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// A face's polygon: (point, corner), two points at most per corner; held on the stack, as every
// face is cut.
using Face_polygon = boost::container::static_vector<std::pair<std::size_t, int>, 8>;
using Net_triangle = std::array<std::size_t, 3>;
// A polygon's triangles, one fewer than its corners.
using Face_cut = boost::container::static_vector<Net_triangle, 6>;

// The ranks of a dead end's triangles: the cosine between a triangle's normal and the face's
// axis, in [-1, 1], or one of these below or above every cosine.
struct Cut_rank
{
  static constexpr double flat = -2;        // a flat triangle, below any other
  static constexpr double shared = -3;      // shared with another face's cut, below a flat one
  static constexpr double below_all = -4;   // where a search for the best starts
  static constexpr double nothing_left = 2; // the empty cut of fewer than three points
};

// The faces' cuts, on the points at the centres of their boxes: every face by cut(), then the
// dead ends by cut_dead_end(); each cut is recorded for the dead ends' after it.
template <typename PointRange>
class Face_cuts
{
public:
  explicit Face_cuts(const PointRange& points) : m_points(points) {}

  // The cut of a face by ears of opposite cells: ears cut one after the other, each the first
  // of opposite_ears(); where one leaves a polygon that no ear of opposite cells can cut (a
  // corner of two points next to it), the next instead. None for a dead end.
  std::optional<Face_cut> cut(const Face_polygon& face)
  {
    struct Step
    {
      Face_polygon left;
      Ear_order order;
      std::size_t next; // in `order`
    };
    CGAL_precondition(!m_dead_ends);
    // Each step's polygon has one point fewer than the one before (a face has 8 at most), down
    // to three.
    boost::container::static_vector<Step, 6> steps;
    Face_cut ears;
    if(face.size() < 3)
      return ears;
    steps.push_back({face, opposite_ears(face), 0});
    while(!steps.empty())
    {
      Step& step = steps.back();
      if(step.next == step.order.size())
      {
        steps.pop_back();
        if(!steps.empty())
          ears.pop_back(); // the ear that left this step's polygon
        continue;
      }
      const std::size_t e = step.order[step.next++];
      Face_polygon rest = step.left;
      rest.erase(rest.begin() + std::ptrdiff_t(e));
      ears.push_back(ear_at(step.left, e));
      if(rest.size() < 3)
      {
        record(face, ears);
        return ears;
      }
      steps.push_back({rest, opposite_ears(rest), 0});
    }
    return std::nullopt;
  }

  // The cut of a dead end, once all other faces are cut: at each step the first ear of opposite
  // cells while there is one, then the least folded cut of the rest.
  Face_cut cut_dead_end(const Face_polygon& face, int axis)
  {
    if(!m_dead_ends)
    {
      std::sort(m_of_two_cells.begin(), m_of_two_cells.end());
      m_dead_ends = true;
    }
    Face_cut ears;
    Face_polygon left = face;
    while(left.size() >= 3)
    {
      const Ear_order order = opposite_ears(left);
      if(order.empty())
        break;
      ears.push_back(ear_at(left, order.front()));
      left.erase(left.begin() + std::ptrdiff_t(order.front()));
    }
    const Face_cut rest_cut = least_folded(left, axis).second;
    ears.insert(ears.end(), rest_cut.begin(), rest_cut.end());
    // Where the first ears leave only a triangle or a diagonal another face has cut, the whole
    // face is cut the least folded way instead, which shares none where any cut does not.
    if(std::any_of(ears.begin(), ears.end(), [this](const Net_triangle& t) { return cut_before(t); }))
    {
      const std::pair<double, Face_cut> whole = least_folded(face, axis);
      if(whole.first > Cut_rank::shared)
        ears = whole.second;
    }
    record(face, ears);
    return ears;
  }

private:
  using Ear_order = boost::container::static_vector<std::size_t, 8>;

  static Net_triangle ear_at(const Face_polygon& left, std::size_t e)
  {
    const std::size_t m = left.size();
    return {left[(e + m - 1) % m].first, left[e].first, left[(e + 1) % m].first};
  }

  bool flat(const Net_triangle& t) const
  {
    return CGAL::collinear(net_point(m_points, t[0]), net_point(m_points, t[1]), net_point(m_points, t[2]));
  }

  // The ears whose diagonal joins opposite cells, those whose triangle is not flat (points of
  // split cells can line up) first; flat: the ear, or what a quad leaves after it. A triangle is
  // its own ear, once.
  Ear_order opposite_ears(const Face_polygon& left) const
  {
    const std::size_t m = left.size();
    Ear_order order, flat_ones;
    if(m == 3)
    {
      order.push_back(1);
      return order;
    }
    for(std::size_t e = 1; e <= m; ++e)
      if((left[(e + m - 1) % m].second + 2) % 4 == left[(e + 1) % m].second)
      {
        const bool is_flat =
            flat(ear_at(left, e % m)) ||
            (m == 4 && flat({left[(e + 1) % m].first, left[(e + 2) % m].first, left[(e + 3) % m].first}));
        (is_flat ? flat_ones : order).push_back(e % m);
      }
    order.insert(order.end(), flat_ones.begin(), flat_ones.end());
    return order;
  }

  // Whether triangle t, or one of its sides as a diagonal, is another dead end's or a triangle
  // of two cells of any face's cut.
  bool cut_before(Net_triangle t) const
  {
    std::sort(t.begin(), t.end());
    return std::binary_search(m_of_two_cells.begin(), m_of_two_cells.end(), t) ||
           m_diagonals.count({t[0], t[1]}) != 0 || m_diagonals.count({t[1], t[2]}) != 0 ||
           m_diagonals.count({t[0], t[2]}) != 0;
  }

  // Triangle t's rank in a dead end across `axis` (Cut_rank).
  double rank(const Net_triangle& t, int axis) const
  {
    const Exact_predicates_inexact_constructions_kernel::Vector_3 normal = CGAL::cross_product(
      net_point(m_points, t[1]) - net_point(m_points, t[0]), net_point(m_points, t[2]) - net_point(m_points, t[0]));
    if(cut_before(t))
      return Cut_rank::shared;
    const double length = std::sqrt(normal.squared_length());
    return length > 0 ? normal[axis] / length : Cut_rank::flat;
  }

  // Of the cuts of `face` into ears, the first (ears in polygon order, from the second) whose
  // worst triangle ranks highest, with that rank: a search over every order of the ears.
  std::pair<double, Face_cut> least_folded(const Face_polygon& face, int axis) const
  {
    struct Step
    {
      Face_polygon left;
      std::size_t next;       // the ear to try next, from 1 to the polygon's size (a triangle: 1)
      std::size_t ear;        // the ear being tried
      double ear_rank;        // its rank
      double best;            // the best worst rank of the ears tried
      Face_cut best_cut;
    };
    if(face.size() < 3)
      return {Cut_rank::nothing_left, Face_cut()};
    // The best cut of what the step's ear leaves, ranked `worst` at the ear.
    const auto settle = [](Step& step, double worst, const Face_cut& rest) {
      if(worst > step.best)
      {
        step.best = worst;
        step.best_cut.assign(1, ear_at(step.left, step.ear));
        step.best_cut.insert(step.best_cut.end(), rest.begin(), rest.end());
      }
    };
    // As in cut(), six steps at most.
    boost::container::static_vector<Step, 6> steps;
    steps.push_back({face, 1, 0, 0, Cut_rank::below_all, Face_cut()});
    for(;;)
    {
      Step& step = steps.back();
      const std::size_t m = step.left.size();
      if(step.next > (m == 3 ? 1 : m))
      {
        const std::pair<double, Face_cut> done = {step.best, step.best_cut};
        steps.pop_back();
        if(steps.empty())
          return done;
        settle(steps.back(), (std::min)(steps.back().ear_rank, done.first), done.second);
        continue;
      }
      step.ear = step.next++ % m;
      step.ear_rank = rank(ear_at(step.left, step.ear), axis);
      Face_polygon rest = step.left;
      rest.erase(rest.begin() + std::ptrdiff_t(step.ear));
      if(rest.size() < 3)
        settle(step, (std::min)(step.ear_rank, Cut_rank::nothing_left), Face_cut());
      else
        steps.push_back({rest, 1, 0, 0, Cut_rank::below_all, Face_cut()});
    }
  }

  // A face's cut, for the cuts after it: its triangles of two cells and, of a dead end, its
  // diagonals.
  void record(const Face_polygon& face, const Face_cut& cut)
  {
    const std::size_t m = face.size(), before = m_of_two_cells.size();
    for(const Net_triangle& t : cut)
    {
      std::size_t at[3]; // the triangle's points in the polygon
      int corner[3];
      for(std::size_t k = 0; k < 3; ++k)
      {
        at[k] = std::size_t(std::find_if(face.begin(), face.end(), [&](const auto& x) { return x.first == t[k]; }) -
                            face.begin());
        corner[k] = face[at[k]].second;
      }
      if(corner[0] == corner[1] || corner[1] == corner[2] || corner[0] == corner[2])
      {
        m_of_two_cells.push_back(t);
        std::sort(m_of_two_cells.back().begin(), m_of_two_cells.back().end());
      }
      for(std::size_t k = 0; m_dead_ends && k < 3; ++k)
      {
        const std::size_t next = (k + 1) % 3; // the edge from point k to the next: a diagonal?
        if((at[k] + 1) % m != at[next] && (at[next] + 1) % m != at[k] && (corner[k] + 2) % 4 != corner[next])
          m_diagonals.insert({(std::min)(t[k], t[next]), (std::max)(t[k], t[next])});
      }
    }
    if(m_dead_ends)
      std::inplace_merge(m_of_two_cells.begin(), m_of_two_cells.begin() + std::ptrdiff_t(before), m_of_two_cells.end());
  }

  const PointRange& m_points;
  bool m_dead_ends = false;                     // whether the dead ends are being cut
  std::vector<Net_triangle> m_of_two_cells;     // sorted within; all sorted from the dead ends on
  std::set<std::array<std::size_t, 2> > m_diagonals; // of the dead ends' cuts, sorted within
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FACE_CUTS_H
