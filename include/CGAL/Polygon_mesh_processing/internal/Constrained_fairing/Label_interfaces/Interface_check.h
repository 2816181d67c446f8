// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The input contract's part that a multi-label surface can break, checked first: points and
// triangles, each triangle on three distinct existing points and between two different labels,
// within the solver's 32-bit indices, and each interface (the triangles of one pair of labels)
// consistently oriented: where two of its triangles share an edge, they run through it in
// opposite directions once the pair's triangles all point from its smaller label into its larger
// one. Several interfaces may meet along an edge (a junction line), and one interface may meet
// itself there (two sheets touching); neither is a defect.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_INTERFACE_CHECK_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_INTERFACE_CHECK_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Face_corners.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Rows_by_vertex.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// A side of a triangle of a multi-label surface: the edge (a < b), its interface, the triangle
// and whether it runs from a to b once oriented from the smaller label into the larger. In
// 32 bits (the check bounds the points and triangles first): the sort moves half the bytes.
struct Interface_side
{
  Index a, b, interface, face;
  bool forward;

  bool same_edge(const Interface_side& o) const { return a == o.a && b == o.b; }
};

// The sides of the triangles of a surface of `n` points, sorted by edge (a counting sort on its
// first point), then interface, then triangle; `interface_of[f]` numbers triangle f's pair of
// labels, `flipped[f]` says whether its labels run from the larger.
template <typename TriangleRange>
std::vector<Interface_side> interface_sides(std::size_t n, const TriangleRange& triangles,
                                            const std::vector<std::size_t>& interface_of, const std::vector<bool>& flipped)
{
  std::vector<Interface_side> sides;
  sides.reserve(3 * triangles.size());
  for(std::size_t f = 0; f < triangles.size(); ++f)
    for(std::size_t c = 0; c < 3; ++c)
    {
      const std::size_t s = std::size_t(triangles[f][c]), t = std::size_t(triangles[f][(c + 1) % 3]);
      sides.push_back({Index((std::min)(s, t)), Index((std::max)(s, t)), Index(interface_of[f]), Index(f),
                       (s < t) != flipped[f]});
    }
  sort_by_vertex(sides, n, [](const Interface_side& x) { return x.a; }, [](const Interface_side& x, const Interface_side& y) {
    return x.b != y.b ? x.b < y.b : x.interface != y.interface ? x.interface < y.interface : x.face < y.face;
  });
  return sides;
}

// The first defect of the surface of `n` points; on none, `interface_of` and `flipped` as for
// interface_sides(), and `sides` its result, which the check walks through.
template <typename TriangleRange, typename LabelPairRange>
Input_error interface_error(std::size_t n, const TriangleRange& triangles, const LabelPairRange& face_labels,
                            std::vector<std::size_t>& interface_of, std::vector<bool>& flipped,
                            std::vector<Interface_side>& sides)
{
  const std::size_t m = static_cast<std::size_t>(triangles.size());
  if(n == 0)
    return empty_mesh_error();
  if(m == 0)
    return no_faces_error();
  for(std::size_t f = 0; f < m; ++f)
  {
    if(Input_error error = face_corner_error(f, triangles[f], n))
      return error;
    if(face_labels[f][0] == face_labels[f][1])
      return same_labels_error(f);
  }
  if(n > (std::numeric_limits<Index>::max)() || m > Hinge_mesh::max_faces)
    return mesh_too_large_error((std::numeric_limits<Index>::max)(), Hinge_mesh::max_faces);

  // The interfaces, numbered in the order of their pairs of labels: the pairs of the runs of
  // neighbouring triangles that share theirs (most do) sorted without repeats, then each
  // triangle's looked up.
  const auto pair = [&](std::size_t f) {
    const auto& l = face_labels[f];
    return l[0] < l[1] ? std::make_pair(l[0], l[1]) : std::make_pair(l[1], l[0]);
  };
  using Pair = decltype(pair(0));
  std::vector<Pair> pairs;
  for(std::size_t f = 0; f < m; ++f)
    if(f == 0 || pair(f) != pair(f - 1))
      pairs.push_back(pair(f));
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  interface_of.assign(m, 0);
  flipped.assign(m, false);
  for(std::size_t f = 0; f < m; ++f)
  {
    interface_of[f] = f > 0 && pair(f) == pair(f - 1)
                        ? interface_of[f - 1]
                        : std::size_t(std::lower_bound(pairs.begin(), pairs.end(), pair(f)) - pairs.begin());
    flipped[f] = face_labels[f][1] < face_labels[f][0];
  }

  sides = interface_sides(n, triangles, interface_of, flipped);
  for(std::size_t i = 0, j = 0; i < sides.size(); i = j)
  {
    while(j < sides.size() && sides[j].same_edge(sides[i]) && sides[j].interface == sides[i].interface)
      ++j;
    if(j - i == 2 && sides[i].forward == sides[i + 1].forward)
    {
      const std::size_t from = sides[i].forward != flipped[sides[i].face] ? sides[i].a : sides[i].b;
      return inconsistent_orientation_error(sides[i].face, sides[i + 1].face, from,
                                            from == sides[i].a ? sides[i].b : sides[i].a);
    }
  }
  return {};
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_INTERFACE_CHECK_H
