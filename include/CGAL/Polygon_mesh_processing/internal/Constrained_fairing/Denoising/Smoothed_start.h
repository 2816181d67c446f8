// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The starting point of the quasi-Newton method: a few steps of projected Taubin smoothing of
// the input, x_i <- P(x_i + f (mean of its neighbours - x_i)), all vertices at once, f
// alternately lambda > 0 and mu < 0. Plain Laplacian steps (f > 0 only) shrink the surface,
// and inside the bound that shrinkage stays.
//
// Why: the bending energy is not convex, and descent from a terraced input stops in a poor
// local minimum: on surface nets of a sphere on 1 x 1 x 3 voxels, each vertex in its cell, the
// quasi-Newton method from the input stays in the terraces, far from the sphere, and from the
// smoothed start it ends close to it (test_voxel_workflow prints both). Averaging with the
// neighbours moves each terrace as a whole towards the slope it stands for, which no step that
// lowers the energy locally does. On noisy scans the smoothed start also leads to lower minima;
// a step costs less than a gradient evaluation. Neighbours are taken from the triangles
// (Neighbour_mean, Mesh_operators.h), so that border vertices are smoothed along the border;
// the points of a mesh's creases (Hinge_mesh::creases) are smoothed along their curves, and their
// ends and corners stay, so that the creases are not rounded and the normals of the points next
// to them, along which those points move (Normal_offsets.h), are their sides'.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SMOOTHED_START_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SMOOTHED_START_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Mesh_operators.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// Taubin's smoothing factors (G. Taubin, "A signal processing approach to fair surface
// design", SIGGRAPH 1995): a shrinking step, then an inflating one.
constexpr double taubin_lambda = 0.5, taubin_mu = -0.53;

// `steps` steps from X, feasible on entry and after.
template <typename Bound>
void smooth_start(const Hinge_mesh& mesh, const Bound& bound, std::size_t steps, Points& X)
{
  const std::size_t n = static_cast<std::size_t>(X.rows());
  const std::vector<bool>& on_crease = mesh.creases.on_curve;
  Neighbour_mean neighbours(mesh, [&on_crease](std::size_t i) { return on_crease.empty() || !on_crease[i]; });
  Points along(static_cast<Eigen::Index>(mesh.creases.inner.size()), 3);
  for(std::size_t step = 0; step < steps; ++step)
  {
    neighbours.gather(X);
    const double lambda = step % 2 == 0 ? taubin_lambda : taubin_mu;
    for(std::size_t k = 0; k < mesh.creases.inner.size(); ++k)
    {
      const auto& t = mesh.creases.inner[k];
      point(along, k) = (1 - lambda) * point(X, t[1]) + (lambda / 2) * (point(X, t[0]) + point(X, t[2]));
    }
    for(std::size_t i = 0; i < n; ++i)
      if(neighbours.count(i) > 0)
        point(X, i) = (1 - lambda) * point(X, i) + (lambda / neighbours.count(i)) * neighbours.sum(i);
    for(std::size_t k = 0; k < mesh.creases.inner.size(); ++k)
      point(X, mesh.creases.inner[k][1]) = point(along, k);
    bound.project(X);
  }
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SMOOTHED_START_H
