// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one check of a face's corners, wherever faces come as indices (a polygon soup, a
// multi-label surface, numpy arrays): each corner names an existing point, none twice.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FACE_CORNERS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FACE_CORNERS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>

#include <cstddef>
#include <iterator>
#include <type_traits>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The defect of face f, whose corners `polygon` (a random access range of point indices of any
// integer type) index `n` points: a negative or too large index, or a point listed twice.
template <typename Polygon>
Input_error face_corner_error(std::size_t f, const Polygon& polygon, std::size_t n)
{
  const std::size_t k = static_cast<std::size_t>(std::size(polygon));
  for(std::size_t c = 0; c < k; ++c)
  {
    const auto v = polygon[c];
    bool negative = false;
    if constexpr(std::is_signed_v<std::decay_t<decltype(v)> >)
      negative = v < 0;
    if(negative || static_cast<std::size_t>(v) >= n)
      return missing_vertex_error(f, v, n);
    for(std::size_t d = 0; d < c; ++d)
      if(polygon[d] == v)
        return repeated_vertex_error(f, static_cast<std::size_t>(v));
  }
  return {};
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FACE_CORNERS_H
