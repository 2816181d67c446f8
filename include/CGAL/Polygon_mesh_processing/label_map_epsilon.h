// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The epsilon with which a label map's surfaces are faired in their boxes, the one rule that the
// front ends share.

#ifndef CGAL_PMP_LABEL_MAP_EPSILON_H
#define CGAL_PMP_LABEL_MAP_EPSILON_H

#include <array>
#include <cmath>

namespace CGAL {
namespace Polygon_mesh_processing {

/*!
\ingroup PkgConstrainedFairingRef

\brief the `epsilon` with which `constrained_fairing_of_interfaces()` fairs the surfaces that
`label_surface_nets()` makes of a label map of voxel spacing `spacing`, each point in its box:
the diagonal of a voxel, longer than any box's half-extents, so that the boxes alone bound the
points.

\param spacing the distance between voxel centres along each axis
*/
inline double label_map_epsilon(const std::array<double, 3>& spacing)
{
  return std::sqrt(spacing[0] * spacing[0] + spacing[1] * spacing[1] + spacing[2] * spacing[2]);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_LABEL_MAP_EPSILON_H
