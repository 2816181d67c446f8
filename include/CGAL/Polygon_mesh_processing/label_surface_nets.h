// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PMP_LABEL_SURFACE_NETS_H
#define CGAL_PMP_LABEL_SURFACE_NETS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Dual_cell.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Net_untangling.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <boost/container/static_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

/*!
\ingroup PkgConstrainedFairingRef

The margin, as a fraction of the voxel spacing, that `label_surface_nets()` keeps between a point's
box and the sides of its dual cell: the boxes of two points are at least twice this apart, so
that no two points of a faired label map meet.
*/
constexpr double label_box_margin = 0.01;

/*!
\ingroup PkgConstrainedFairingRef

\brief extracts the interfaces between the labels of a 3-D label map as one triangle soup:
multi-label surface nets, each point with the box the fairing keeps it in.

`labels` holds `size[0] * size[1] * size[2]` voxels in C order: voxel `(i, j, k)` is
`labels[(i * size[1] + j) * size[2] + k]` (a C-contiguous numpy array `labels[i, j, k]`), and its
centre is at `origin + (i, j, k) * spacing`, coordinates in the array's axis order. Voxels
outside the array count as `background`.

- The dual cells are the cubes spanned by 8 neighbouring voxel centres. For each pair of
  neighbouring voxels `a`, `b` with different labels, two triangles (the quad of the four dual
  cells around their shared face) are added, with `face_labels` `{label(a), label(b)}`: their
  normal points from `a`'s region into `b`'s. The interface between two labels is so made of the
  same triangles for both, and a label's surface, the triangles that name it, is closed.
  Triangles against `background` are made too: `background` is the outside of the surfaces and
  gets none of its own.
- A dual cell whose voxels do not all have the same label gets a point at its centre, whose box
  is the cell shrunk by `margin * spacing` on every side. Where a label's voxels meet only along
  an edge or at a corner, the cell gets one point per sheet of the surface instead, each with a
  box in the part of the cell its triangles occupy (a half or, where the triangles of two points
  lie in one octant, a quarter of the cell along an axis), also `margin * spacing` from the
  planes that cut the cell there, and at its centre: the voxels of the two diagonals around an
  edge are never both joined; of two labels that alternate around an edge, the one whose voxels
  are joined around it anyway is, else the smaller label. Where a junction would pinch a label
  or two sheets would share an edge, a sheet gets several points on a ridge; the holes the ridge
  leaves in the interfaces are capped by triangles of the cell's points, around one more point
  in a free octant of the cell where they border several interfaces. Where two labels each touch
  themselves at the centre with others around, an edge of four labels next to the centre gets
  two points at the cell, one for the faces around each of two opposite voxels, and the other two
  labels meet between them across a triangle of those points and the next cell's point along the
  edge. Where none of these serves (four labels each on two opposite voxels of a cell, say; none
  in Debian's atlases), the cell gets a point on each edge around its centre (two where an
  edge's faces pair up) and a small ball of one label there, the holes of the other labels
  capped against it. So every label's surface is a manifold (made by `label_surface()` without
  splitting): none split on Debian's atlases or on 600 maps of random voxels of 3 to 6 labels.
  No two boxes meet: the points stay apart through any fairing within their boxes.
- Points of cells of several points, at the centres of their boxes, can fold a triangle onto its
  neighbour or through another: the points of such triangles, of any cell, move to the mean of
  their neighbours (with the points around them after the first round), within seven eighths
  of their boxes, for a few rounds while some cross; then those of the triangles still crossing,
  one at a time, each to the position of a grid over that part of its box that leaves the
  fewest crossings, and of those the least sharp triangles (up to a 6-degree needle), then the
  nearest, never adding a crossing. Each moved point's box shrinks to the largest one around it
  within the one it had (up to rounding). The triangles pass through each other only where
  that fails: none on Debian's atlases, 2 of 100 maps of 14^3 random voxels of 3 to 6 labels.
- A face whose corners hold several points is cut into triangles by diagonals between opposite
  cells where it can be, else, for the rest, the way whose triangles turn least from its normal,
  never into a triangle or a diagonal another face has.

Points are numbered in the order of their cells, `(i, j, k)` with `k` fastest, and within a
cell by their first triangle, the cap-only points last.

The boxes, `box_half_extents[p]` around `points[p]`, are those that
`constrained_fairing_of_interfaces()` takes as `vertex_box_half_extents_map`. The choice is
made from the labels alone: the same map gives the same soup whatever is done with it after.

\tparam Label an integer type
\tparam PointRange a `std::vector` of a point type constructible from three `double`
\tparam TriangleRange a `std::vector` of `std::array<I, 3>`, `I` an integer type
\tparam LabelPairRange a `std::vector` of `std::array<Label, 2>`
\tparam BoxRange a `std::vector` of `std::array<double, 3>`

\param labels the label map, `size[0] * size[1] * size[2]` values in C order
\param size the number of voxels along each axis
\param spacing the distance between voxel centres along each axis
\param origin the centre of voxel `(0, 0, 0)`
\param points the points, appended to
\param triangles the triangles, as indices into `points` counted from its size on entry
\param face_labels the two labels of each triangle, one per triangle
\param box_half_extents the half-extents of each point's box, one per point, appended to
\param background the label of the outside, which gets no surface of its own
\param margin the margin of the boxes, a fraction of the spacing in `[0, 0.125)`

\pre `0 <= margin < 0.125`
*/
template <typename Label, typename PointRange, typename TriangleRange, typename LabelPairRange, typename BoxRange>
void label_surface_nets(const Label* labels, const std::array<std::size_t, 3>& size,
                        const std::array<double, 3>& spacing, const std::array<double, 3>& origin,
                        PointRange& points, TriangleRange& triangles, LabelPairRange& face_labels,
                        BoxRange& box_half_extents, const Label background = Label(0),
                        const double margin = label_box_margin)
{
  using Point = typename PointRange::value_type;
  using Point_index = typename TriangleRange::value_type::value_type;
  using Cell = internal::Constrained_fairing::Dual_cell<Label>;
  using Epick = Exact_predicates_inexact_constructions_kernel;
  using Signed = std::ptrdiff_t;
  CGAL_precondition(margin >= 0 && margin < 0.125);
  const Signed n[3] = {Signed(size[0]), Signed(size[1]), Signed(size[2])};
  const auto label = [&](Signed i, Signed j, Signed k) {
    if(i < 0 || j < 0 || k < 0 || i >= n[0] || j >= n[1] || k >= n[2])
      return background;
    return labels[(std::size_t(i) * size[1] + std::size_t(j)) * size[2] + std::size_t(k)];
  };
  // Dual cell c = (ci, cj, ck), each in [0, n], lies between voxels c - 1 and c on each axis.
  const std::size_t cells[3] = {size[0] + 1, size[1] + 1, size[2] + 1};
  const auto cell_index = [&cells](const Signed c[3]) {
    return (std::size_t(c[0]) * cells[1] + std::size_t(c[1])) * cells[2] + std::size_t(c[2]);
  };
  // The bridges (Dual_cell.h), in the order of their cells: the cell after one along a split
  // ring's axis leaves that ring whole, so that the bridge ends at its point.
  std::vector<std::pair<std::array<Signed, 3>, typename Cell::Bridge> > bridges; // cell, bridge
  const auto cell_at = [&](const Signed c[3]) {
    unsigned unsplit = 0;
    for(int a = 0; a < 3; ++a)
      if(c[a] > 0)
      {
        std::array<Signed, 3> before = {c[0], c[1], c[2]};
        --before[std::size_t(a)];
        for(auto b = std::lower_bound(bridges.begin(), bridges.end(), before,
                                      [](const auto& x, const std::array<Signed, 3>& at) { return x.first < at; });
            b != bridges.end() && b->first == before; ++b)
          if(b->second.axis == a && b->second.side == 1)
            unsplit |= 1u << (2 * a);
      }
    return Cell([&](int d0, int d1, int d2) { return label(c[0] - 1 + d0, c[1] - 1 + d1, c[2] - 1 + d2); }, background,
                margin, unsplit);
  };

  // The points, cell by cell, each at the centre of its box; the cells of more than one point are
  // kept, in their order, with the point of each face's corner next to each of its dual edges.
  constexpr std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();
  std::vector<std::uint32_t> first_point(cells[0] * cells[1] * cells[2], none);
  std::vector<std::pair<std::size_t, std::array<std::int8_t, 24> > > split;
  std::vector<std::pair<std::array<std::size_t, 3>, std::array<Label, 2> > > caps; // points, labels
  std::vector<bool> of_split_cell;
  const std::size_t first = points.size(), first_triangle = triangles.size(), first_box = box_half_extents.size();
  std::size_t cell = 0;
  Signed c[3];
  for(c[0] = 0; c[0] <= n[0]; ++c[0])
    for(c[1] = 0; c[1] <= n[1]; ++c[1])
      for(c[2] = 0; c[2] <= n[2]; ++c[2], ++cell)
      {
        const Label l = label(c[0], c[1], c[2]);
        bool uniform = true;
        for(int o = 1; o < 8 && uniform; ++o)
          uniform = label(c[0] - (o & 1), c[1] - ((o >> 1) & 1), c[2] - ((o >> 2) & 1)) == l;
        if(uniform)
          continue;
        const Cell dual = cell_at(c);
        first_point[cell] = static_cast<std::uint32_t>(points.size() - first);
        if(dual.size() > 1)
        {
          split.emplace_back(cell, std::array<std::int8_t, 24>{});
          for(int f = 0; f < 12; ++f)
            for(int side = 0; side < 2; ++side)
              split.back().second[std::size_t(2 * f + side)] = std::int8_t(dual.point(f, (f / 4 + 1 + side) % 3));
          for(const auto& cap : dual.caps())
          {
            caps.push_back({{}, cap.labels});
            for(std::size_t k = 0; k < 3; ++k)
              caps.back().first[k] = first + first_point[cell] + std::size_t(cap.points[k]);
          }
          for(const auto& bridge : dual.bridges())
            bridges.push_back({{c[0], c[1], c[2]}, bridge});
        }
        for(int s = 0; s < dual.size(); ++s)
        {
          double centre[3];
          std::array<double, 3> half;
          for(int a = 0; a < 3; ++a)
          {
            const double lo = dual.low(s, a), hi = dual.high(s, a);
            centre[a] = origin[std::size_t(a)] + (double(c[a]) - 0.5 + 0.5 * (lo + hi)) * spacing[std::size_t(a)];
            half[std::size_t(a)] = 0.5 * (hi - lo) * spacing[std::size_t(a)];
          }
          points.push_back(Point(centre[0], centre[1], centre[2]));
          box_half_extents.push_back(half);
          of_split_cell.push_back(dual.size() > 1);
        }
      }

  // For each pair of neighbouring voxels a, b = a + e_axis with different labels, the four dual
  // cells around their face, counterclockwise seen from b; at each, the face's corner is one point
  // or, where its two dual edges there have different points, both. The polygon is cut into
  // triangles, pointing from a into b, by diagonals between opposite cells only: a diagonal
  // between neighbouring cells could be an edge of other faces too, and two faces of one label
  // around a dual edge could cut the same triangle. A quad gives (0, 1, 2) and (0, 2, 3).
  // (point, corner), two points at most per corner; held on the stack, as every face is cut
  using Polygon = boost::container::static_vector<std::pair<std::size_t, int>, 8>;
  Polygon polygon;
  std::vector<std::array<std::size_t, 3> > ears;
  const auto ear_at = [](const Polygon& left, std::size_t e) {
    const std::size_t m = left.size();
    return std::array<std::size_t, 3>{left[(e + m - 1) % m].first, left[e].first, left[(e + 1) % m].first};
  };
  const auto point_of = [&](std::size_t v) {
    return Epick::Point_3(CGAL::to_double(points[v][0]), CGAL::to_double(points[v][1]), CGAL::to_double(points[v][2]));
  };
  const auto flat = [&](const std::array<std::size_t, 3>& t) {
    return CGAL::collinear(point_of(t[0]), point_of(t[1]), point_of(t[2]));
  };
  // The points of a cell of several points at each face's corner (2 f + 0 next to its dual edge
  // along axis (f / 4 + 1) % 3, 2 f + 1 along the other), relative to its first; null for a
  // cell of one point.
  const auto corners_of = [&split](std::size_t index) -> const std::array<std::int8_t, 24>* {
    const auto found = std::lower_bound(split.begin(), split.end(), index,
                                        [](const auto& x, std::size_t i) { return x.first < i; });
    return found != split.end() && found->first == index ? &found->second : nullptr;
  };
  // The ears whose diagonal joins opposite cells, those whose triangle is not flat (points of
  // split cells can line up) first; flat: the ear, or what a quad leaves after it. A triangle is
  // its own ear, once.
  const auto opposite_ears = [&](const Polygon& left) {
    const std::size_t m = left.size();
    boost::container::static_vector<std::size_t, 8> order, flat_ones;
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
  };
  // Ears cut one after the other, each the first of opposite_ears(); where one leaves a polygon
  // that no ear of opposite cells can cut (a corner of two points next to it), the next instead.
  const std::function<bool(const Polygon&)> cut = [&](const Polygon& left) {
    if(left.size() < 3)
      return true;
    for(std::size_t e : opposite_ears(left))
    {
      Polygon rest = left;
      rest.erase(rest.begin() + std::ptrdiff_t(e));
      ears.push_back(ear_at(left, e));
      if(cut(rest))
        return true;
      ears.pop_back();
    }
    return false;
  };
  // Where ears of opposite cells alone cannot cut a face, the rest is cut so that its triangle
  // turned furthest from the face's axis (the least cosine between its normal and the axis) is
  // turned least, on the points at the centres of their boxes: from the voxels alone. The
  // polygon's first ear each time, the earlier rule, could lay triangles on three points of a
  // junction line in two faces along it, folded onto each other. A flat triangle ranks below
  // any other, and one that shares a triangle or a diagonal with another face's cut below that:
  // only a triangle with two points of one cell can be shared, and only a diagonal between
  // points of one cell or of neighbouring ones, which these cuts alone make. Two faces of one
  // label must share neither (a triangle twice, or an edge of four), so these faces are cut
  // after all others.
  std::vector<std::array<std::size_t, 3> > of_two_cells; // sorted, once all other faces are cut
  std::set<std::array<std::size_t, 2> > diagonals;       // of these cuts, sorted within
  const auto cut_before = [&](std::array<std::size_t, 3> t) {
    std::sort(t.begin(), t.end());
    return std::binary_search(of_two_cells.begin(), of_two_cells.end(), t) ||
           diagonals.count({t[0], t[1]}) != 0 || diagonals.count({t[1], t[2]}) != 0 ||
           diagonals.count({t[0], t[2]}) != 0;
  };
  const auto rank = [&](const std::array<std::size_t, 3>& t, int axis) {
    const Epick::Vector_3 normal =
      CGAL::cross_product(point_of(t[1]) - point_of(t[0]), point_of(t[2]) - point_of(t[0]));
    if(cut_before(t))
      return -3.0;
    const double length = std::sqrt(normal.squared_length());
    return length > 0 ? normal[axis] / length : -2.0;
  };
  const std::function<double(const Polygon&, int, std::vector<std::array<std::size_t, 3> >&)> least_folded =
    [&](const Polygon& left, int axis, std::vector<std::array<std::size_t, 3> >& best_cut) {
      if(left.size() < 3)
        return 2.0;
      double best = -4;
      for(std::size_t i = 1; i <= (left.size() == 3 ? 1 : left.size()); ++i)
      {
        const std::size_t e = i % left.size();
        Polygon rest = left;
        rest.erase(rest.begin() + std::ptrdiff_t(e));
        std::vector<std::array<std::size_t, 3> > cut_of_rest;
        const double worst = (std::min)(rank(ear_at(left, e), axis), least_folded(rest, axis, cut_of_rest));
        if(worst > best)
        {
          best = worst;
          best_cut.assign(1, ear_at(left, e));
          best_cut.insert(best_cut.end(), cut_of_rest.begin(), cut_of_rest.end());
        }
      }
      return best;
    };
  // The faces left for the end: axis, labels, polygon.
  std::vector<std::tuple<int, std::array<Label, 2>, Polygon> > dead_ends;
  const auto add_cut = [&](const Polygon& face, const std::array<Label, 2>& labels, bool dead_end) {
    const std::size_t m = face.size();
    for(const std::array<std::size_t, 3>& t : ears)
    {
      triangles.push_back({Point_index(t[0]), Point_index(t[1]), Point_index(t[2])});
      face_labels.push_back(labels);
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
        of_two_cells.push_back(t);
        std::sort(of_two_cells.back().begin(), of_two_cells.back().end());
      }
      for(std::size_t k = 0; dead_end && k < 3; ++k)
      {
        const std::size_t next = (k + 1) % 3; // the edge from point k to the next: a diagonal?
        if((at[k] + 1) % m != at[next] && (at[next] + 1) % m != at[k] && (corner[k] + 2) % 4 != corner[next])
          diagonals.insert({(std::min)(t[k], t[next]), (std::max)(t[k], t[next])});
      }
    }
  };
  for(int axis = 0; axis < 3; ++axis)
  {
    const int u = (axis + 1) % 3, w = (axis + 2) % 3; // (axis, u, w) is right-handed
    Signed lo[3] = {0, 0, 0};
    lo[axis] = -1;
    Signed a[3];
    for(a[0] = lo[0]; a[0] < n[0]; ++a[0])
      for(a[1] = lo[1]; a[1] < n[1]; ++a[1])
        for(a[2] = lo[2]; a[2] < n[2]; ++a[2])
        {
          Signed b[3] = {a[0], a[1], a[2]};
          ++b[axis];
          const Label la = label(a[0], a[1], a[2]), lb = label(b[0], b[1], b[2]);
          if(la == lb)
            continue;
          polygon.clear();
          const int du[4] = {0, 1, 1, 0}, dw[4] = {0, 0, 1, 1};
          for(int k = 0; k < 4; ++k)
          {
            Signed q[3];
            q[axis] = b[axis];
            q[u] = a[u] + du[k];
            q[w] = a[w] + dw[k];
            const std::size_t index = cell_index(q);
            const std::size_t base = first + first_point[index];
            const std::array<std::int8_t, 24>* corners = corners_of(index);
            if(!corners)
            {
              polygon.emplace_back(base, k);
              continue;
            }
            // In the block of cell q, voxel a has offsets (0, 1 - du, 1 - dw); the quad arrives
            // at corner k along u (k odd) or w and leaves along the other.
            const int face = 4 * axis + (1 - du[k]) + 2 * (1 - dw[k]);
            const int in = k % 2 == 1 ? 0 : 1;
            const std::size_t from = base + std::size_t((*corners)[std::size_t(2 * face + in)]),
                              to = base + std::size_t((*corners)[std::size_t(2 * face + 1 - in)]);
            polygon.emplace_back(from, k);
            if(to != from)
              polygon.emplace_back(to, k);
          }
          ears.clear();
          if(cut(polygon))
            add_cut(polygon, {la, lb}, false);
          else
            dead_ends.emplace_back(axis, std::array<Label, 2>{la, lb}, polygon);
        }
  }
  // No way to cut these by ears of opposite cells alone: at each step the first such ear while
  // there is one, then the least folded cut of the rest.
  std::sort(of_two_cells.begin(), of_two_cells.end());
  for(const auto& [axis, labels, face] : dead_ends)
  {
    ears.clear();
    Polygon left = face;
    while(left.size() >= 3)
    {
      const auto order = opposite_ears(left);
      if(order.empty())
        break;
      ears.push_back(ear_at(left, order.front()));
      left.erase(left.begin() + std::ptrdiff_t(order.front()));
    }
    std::vector<std::array<std::size_t, 3> > rest_cut;
    least_folded(left, axis, rest_cut);
    ears.insert(ears.end(), rest_cut.begin(), rest_cut.end());
    // Where the first ears leave only a triangle or a diagonal another face has cut, the whole
    // face is cut the least folded way instead, which shares none where any cut does not.
    if(std::any_of(ears.begin(), ears.end(), cut_before))
    {
      std::vector<std::array<std::size_t, 3> > whole_cut;
      if(least_folded(face, axis, whole_cut) > -3)
        ears = whole_cut;
    }
    const std::size_t before = of_two_cells.size();
    add_cut(face, labels, true);
    std::inplace_merge(of_two_cells.begin(), of_two_cells.begin() + std::ptrdiff_t(before), of_two_cells.end());
  }
  for(const auto& cap : caps)
  {
    triangles.push_back({Point_index(cap.first[0]), Point_index(cap.first[1]), Point_index(cap.first[2])});
    face_labels.push_back(cap.second);
  }
  // Each bridge: the triangle of its cell's two points and the point of the next cell along the
  // ring's half-axis, where the ring's faces meet (that cell leaves the ring whole). Its normal
  // points from the ring's voxel k into voxel k + 2 (the bridge's labels, in order) when the next
  // cell is on the positive side, and the other way on the negative side: the ring runs
  // counterclockwise around the axis, the points of the pairs around voxels k + 1 and k + 3.
  for(const auto& [at, bridge] : bridges)
  {
    Signed next[3] = {at[0], at[1], at[2]};
    next[bridge.axis] += bridge.side == 1 ? 1 : -1;
    const std::size_t here = first + first_point[cell_index(at.data())], index = cell_index(next);
    // The next cell's corner of a face of the ring: in its block, the face's voxels are on the
    // other side along the ring's axis.
    std::size_t there = first + first_point[index];
    if(const std::array<std::int8_t, 24>* corners = corners_of(index))
    {
      const int f = bridge.faces[0];
      const bool along_u = bridge.axis == (f / 4 + 1) % 3;
      there += std::size_t((*corners)[std::size_t(2 * (f ^ (along_u ? 1 : 2)) + (along_u ? 0 : 1))]);
    }
    std::array<std::size_t, 2> pair = {here + std::size_t(bridge.points[0]), here + std::size_t(bridge.points[1])};
    if(bridge.side == 0)
      std::swap(pair[0], pair[1]);
    triangles.push_back({Point_index(pair[0]), Point_index(pair[1]), Point_index(there)});
    face_labels.push_back(bridge.labels);
  }

  // Points of split cells can line up (a staircase of cells split alike): the middle point of a
  // triangle on a line moves off it by half its box along the axis the line runs least along, its
  // box shrunk to the half it moved into. The fairing straightens such junction lines again, and
  // the repair after it pulls the triangle back to this start: moved by a quarter of its box, a
  // triangle of Debian's inia19 atlas stayed a 4.85-degree needle.
  for(int round = 0; round < 4; ++round)
  {
    bool moved = false;
    for(std::size_t t = first_triangle; t < triangles.size(); ++t)
    {
      const std::array<Epick::Point_3, 3> p = {point_of(std::size_t(triangles[t][0])),
                                               point_of(std::size_t(triangles[t][1])),
                                               point_of(std::size_t(triangles[t][2]))};
      if(!CGAL::collinear(p[0], p[1], p[2]))
        continue;
      int middle = 0;
      while(middle < 2 && (p[std::size_t((middle + 1) % 3)] - p[std::size_t(middle)]) *
                              (p[std::size_t((middle + 2) % 3)] - p[std::size_t(middle)]) > 0)
        ++middle;
      const Epick::Vector_3 line = p[std::size_t((middle + 2) % 3)] - p[std::size_t((middle + 1) % 3)];
      std::size_t axis = 0;
      for(std::size_t a = 1; a < 3; ++a)
        if(std::abs(line[int(a)]) < std::abs(line[int(axis)]))
          axis = a;
      const std::size_t v = std::size_t(triangles[t][std::size_t(middle)]);
      const double shift = box_half_extents[first_box + v - first][axis] / 2;
      double x[3] = {p[std::size_t(middle)].x(), p[std::size_t(middle)].y(), p[std::size_t(middle)].z()};
      x[axis] += shift;
      points[v] = Point(x[0], x[1], x[2]);
      box_half_extents[first_box + v - first][axis] -= shift;
      moved = true;
    }
    if(!moved)
      break;
  }
  internal::Constrained_fairing::untangle_nets(points, triangles, box_half_extents, first, first_triangle, first_box,
                                               of_split_cell);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_LABEL_SURFACE_NETS_H
