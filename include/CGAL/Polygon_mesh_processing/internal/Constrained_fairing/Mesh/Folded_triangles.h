// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Folds: triangles turned over against their neighbours, n . (n1 + n2 + n3) < 0 with n the
// triangle's area-weighted normal and n1..n3 those of its neighbours across the hinges of the
// energy. The fold repair re-seeds them (Fold_repair.h), the crossing repair pulls them back
// (Crossing_repair.h), and the result counts those with a vertex that moves.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FOLDED_TRIANGLES_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FOLDED_TRIANGLES_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The folded triangles of X.
inline std::vector<Index> folded_triangles(const Hinge_mesh& mesh, const Points& X)
{
  std::vector<Eigen::Vector3d> around(mesh.triangles.size(), Eigen::Vector3d::Zero());
  for(const Hinge& h : mesh.hinges)
  {
    around[h.f[0]] += area_normal(mesh, X, h.f[1]);
    around[h.f[1]] += area_normal(mesh, X, h.f[0]);
  }
  std::vector<Index> folded;
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    if(area_normal(mesh, X, f).dot(around[f]) < 0)
      folded.push_back(static_cast<Index>(f));
  return folded;
}

// The folded triangles of X with a `moving` vertex: those the result counts.
inline std::vector<Index> folded_moving_triangles(const Hinge_mesh& mesh, const std::vector<bool>& moving,
                                                  const Points& X)
{
  std::vector<Index> folded = folded_triangles(mesh, X);
  folded.erase(std::remove_if(folded.begin(), folded.end(),
                              [&](Index f) {
                                const auto& t = mesh.triangles[f];
                                return !moving[t[0]] && !moving[t[1]] && !moving[t[2]];
                              }),
               folded.end());
  return folded;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FOLDED_TRIANGLES_H
