// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Crossings: two triangles of a soup that pass through each other, found exactly, with the
// predicates of CGAL's self-intersection test: two triangles that share an edge cross when they
// fold onto each other, two that share a point when the side of one opposite it meets the other,
// others when they meet; a triangle collapsed to a segment crosses any other near it. Used by
// the crossing repair (Crossing_repair.h) and by the untangling of label maps' nets
// (Net_untangling.h).

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_TRIANGLE_CROSSINGS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_TRIANGLE_CROSSINGS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Triangle_crossings
{
  using Kernel = Exact_predicates_inexact_constructions_kernel;
  using Box = Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;

public:
  explicit Triangle_crossings(const std::vector<std::array<Index, 3> >& triangles) : m_triangles(triangles) {}

  // Whether each triangle crosses another in X, among the pairs with one of the `changed`
  // triangles (all where `changed` is empty).
  std::vector<bool> find(const Points& X, const std::vector<bool>& changed) const
  {
    // The boxes of all the triangles, or those of the `changed` ones (`some`) and of the
    // triangles near them. CGAL's parallel box intersection copies its ranges nine times over: it
    // gets pointers, as in CGAL's self-intersection test, not boxes (0.4 GB more on a map of 0.85 M
    // triangles).
    std::vector<Box> boxes, some;
    std::vector<const Box*> handles, near;
    if(changed.empty())
    {
      boxes.reserve(m_triangles.size());
      for(std::size_t f = 0; f < m_triangles.size(); ++f)
        boxes.push_back(box(X, f));
      handles.reserve(boxes.size());
      for(const Box& b : boxes)
        handles.push_back(&b);
    }
    else
    {
      for(std::size_t f = 0; f < m_triangles.size(); ++f)
        if(changed[f])
          some.push_back(box(X, f));
      for(const Box& b : some)
        handles.push_back(&b);
      if(!some.empty())
        boxes = boxes_near(X, some);
      for(const Box& b : boxes)
        near.push_back(&b);
    }
    // Flags that the threads of the box intersection set: the set found does not depend on the
    // order of the pairs, as a pair is skipped only when both its triangles cross already.
    std::vector<std::atomic<bool> > flags(m_triangles.size());
    for(auto& flag : flags)
      flag.store(false, std::memory_order_relaxed);
    const auto test = [&](const Box* a, const Box* b) {
      const std::size_t f = a->info(), g = b->info();
      if(f != g && (!flags[f].load(std::memory_order_relaxed) || !flags[g].load(std::memory_order_relaxed)) &&
         cross(X, m_triangles[f], m_triangles[g]))
      {
        flags[f].store(true, std::memory_order_relaxed);
        flags[g].store(true, std::memory_order_relaxed);
      }
    };
    // The cutoff under which the boxes are tested pairwise is CGAL's self-intersection test's:
    // at the default of 10, the segment tree's recursion took twice as long on a million
    // triangles.
    const std::ptrdiff_t cutoff = 2000;
    if(changed.empty())
      box_self_intersection_d<Parallel_if_available_tag>(handles.begin(), handles.end(), test, cutoff);
    else if(!handles.empty())
      box_intersection_d<Parallel_if_available_tag>(handles.begin(), handles.end(), near.begin(), near.end(), test,
                                                    cutoff);
    std::vector<bool> crossing(m_triangles.size());
    for(std::size_t f = 0; f < m_triangles.size(); ++f)
      crossing[f] = flags[f].load(std::memory_order_relaxed);
    return crossing;
  }

  // Whether triangles s and t of X pass through each other (the test of `find`).
  static bool cross(const Points& X, const std::array<Index, 3>& s, const std::array<Index, 3>& t)
  {
    const auto p = [&X](Index v) { return Kernel::Point_3(X(v, 0), X(v, 1), X(v, 2)); };
    // A triangle collapsed to a segment has no side: it counts as crossing, to be pulled back.
    if(collinear(p(s[0]), p(s[1]), p(s[2])) || collinear(p(t[0]), p(t[1]), p(t[2])))
      return true;
    int shared = 0, i = 0, j = 0;
    for(int a = 0; a < 3; ++a)
      for(int b = 0; b < 3; ++b)
        if(s[std::size_t(a)] == t[std::size_t(b)])
          ++shared, i = a, j = b;
    if(shared >= 2)
    {
      // The third points of s and t, on the same side of the shared edge in one plane.
      int a = 0, b = 0;
      while(a < 3 && (s[std::size_t(a)] == t[0] || s[std::size_t(a)] == t[1] || s[std::size_t(a)] == t[2]))
        ++a;
      while(b < 3 && (t[std::size_t(b)] == s[0] || t[std::size_t(b)] == s[1] || t[std::size_t(b)] == s[2]))
        ++b;
      if(a == 3 || b == 3)
        return true; // one triangle twice
      const Kernel::Point_3 u = p(s[std::size_t((a + 1) % 3)]), v = p(s[std::size_t((a + 2) % 3)]);
      return coplanar(u, v, p(s[std::size_t(a)]), p(t[std::size_t(b)])) &&
             coplanar_orientation(u, v, p(s[std::size_t(a)]), p(t[std::size_t(b)])) == POSITIVE;
    }
    const Kernel::Triangle_3 S(p(s[0]), p(s[1]), p(s[2])), T(p(t[0]), p(t[1]), p(t[2]));
    if(shared == 1)
      return do_intersect(S, Kernel::Segment_3(p(t[std::size_t((j + 1) % 3)]), p(t[std::size_t((j + 2) % 3)]))) ||
             do_intersect(T, Kernel::Segment_3(p(s[std::size_t((i + 1) % 3)]), p(s[std::size_t((i + 2) % 3)])));
    return do_intersect(S, T);
  }

private:
  // The boxes of the triangles that may meet one of `some`: those that meet a cell of a grid that
  // one of `some` meets, the cells as large as the largest of `some`. A pass over the triangles
  // with a few lookups each, which keeps only the boxes near: the repair's rounds change a few
  // triangles, and the box intersection with all of them sorted every box in every round (5 s of
  // Harvard-Oxford's repair), and writing the boxes of all took 0.2 s a round.
  std::vector<Box> boxes_near(const Points& X, const std::vector<Box>& some) const
  {
    std::vector<Box> near;
    double size = 0;
    for(const Box& b : some)
      for(int c = 0; c < 3; ++c)
        size = (std::max)(size, b.max_coord(c) - b.min_coord(c));
    if(!(size > 0) || !std::isfinite(size))
    {
      for(std::size_t f = 0; f < m_triangles.size(); ++f)
        near.push_back(box(X, f));
      return near;
    }
    using Cell = std::array<std::int64_t, 3>;
    // clamped, which keeps the cells of boxes that meet in common
    const auto cell = [size](double x) { return std::int64_t((std::max)(-1e15, (std::min)(1e15, std::floor(x / size)))); };
    const auto cells = [&cell](const Box& b, Cell& lo, Cell& hi) {
      for(int c = 0; c < 3; ++c)
      {
        lo[std::size_t(c)] = cell(b.min_coord(c));
        hi[std::size_t(c)] = cell(b.max_coord(c));
      }
      return double(hi[0] - lo[0] + 1) * double(hi[1] - lo[1] + 1) * double(hi[2] - lo[2] + 1);
    };
    std::vector<Cell> marked;
    Cell lo, hi, k;
    for(const Box& b : some)
    {
      cells(b, lo, hi);
      for(k[0] = lo[0]; k[0] <= hi[0]; ++k[0])
        for(k[1] = lo[1]; k[1] <= hi[1]; ++k[1])
          for(k[2] = lo[2]; k[2] <= hi[2]; ++k[2])
            marked.push_back(k);
    }
    std::sort(marked.begin(), marked.end());
    marked.erase(std::unique(marked.begin(), marked.end()), marked.end());
    for(std::size_t f = 0; f < m_triangles.size(); ++f)
    {
      const Box b = box(X, f);
      // a box over many cells (a long triangle) is kept without looking them up
      bool meets = cells(b, lo, hi) > 64;
      for(k[0] = lo[0]; !meets && k[0] <= hi[0]; ++k[0])
        for(k[1] = lo[1]; !meets && k[1] <= hi[1]; ++k[1])
          for(k[2] = lo[2]; !meets && k[2] <= hi[2]; ++k[2])
            meets = std::binary_search(marked.begin(), marked.end(), k);
      if(meets)
        near.push_back(b);
    }
    return near;
  }

  Box box(const Points& X, std::size_t f) const
  {
    double lo[3], hi[3];
    for(int c = 0; c < 3; ++c)
    {
      lo[c] = hi[c] = X(m_triangles[f][0], c);
      for(int k = 1; k < 3; ++k)
      {
        lo[c] = (std::min)(lo[c], X(m_triangles[f][std::size_t(k)], c));
        hi[c] = (std::max)(hi[c], X(m_triangles[f][std::size_t(k)], c));
      }
    }
    return Box(Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]), f);
  }

  const std::vector<std::array<Index, 3> >& m_triangles;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_TRIANGLE_CROSSINGS_H
