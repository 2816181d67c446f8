// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Folds: triangles turned over against their neighbours, n . (n1 + n2 + n3) < 0 with n the
// triangle's area-weighted normal and n1..n3 those of its neighbours across the hinges of the
// energy. At heavy noise the descent keeps some of the input's: no step may flip or collapse a
// triangle (Projected_lbfgs.h limits each move to half the vertex's reach), so a triangle
// folded at the start stays folded, held there by the bound and by its neighbours, a local
// minimum of the energy. The repair re-seeds the vertices of the folded triangles and of
// their neighbours: a few projected Laplacian steps on them alone, each vertex moved to the
// mean of its neighbours and back into its bound, which opens the fold since the bound allows
// the flat configuration around it; the caller then descends again from there and keeps the
// outcome only if its objective is not higher.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FOLD_REPAIR_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FOLD_REPAIR_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Points.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The Laplacian steps of a re-seed.
constexpr std::size_t reseed_steps = 10;

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

// Re-seeds the vertices of the `folded` triangles and their neighbours in X, which stays
// feasible.
template <typename Bound>
void reseed_folds(const Hinge_mesh& mesh, const Bound& bound, const std::vector<Index>& folded, Points& X)
{
  const std::size_t n = static_cast<std::size_t>(X.rows());
  std::vector<bool> in_fold(n, false), moves(n, false);
  for(Index f : folded)
    for(Index v : mesh.triangles[f])
      in_fold[v] = true;
  for(const auto& t : mesh.triangles)
    if(in_fold[t[0]] || in_fold[t[1]] || in_fold[t[2]])
      for(Index v : t)
        moves[v] = true;
  // Neighbours from the triangles, as in Smoothed_start.h.
  Points sum(X.rows(), 3);
  std::vector<double> count(n, 0.);
  for(std::size_t step = 0; step < reseed_steps; ++step)
  {
    sum.setZero();
    std::fill(count.begin(), count.end(), 0.);
    for(const auto& t : mesh.triangles)
      for(int k = 0; k < 3; ++k)
        if(moves[t[std::size_t(k)]])
        {
          point(sum, t[std::size_t(k)]) +=
            point(X, t[std::size_t((k + 1) % 3)]) + point(X, t[std::size_t((k + 2) % 3)]);
          count[t[std::size_t(k)]] += 2;
        }
    for(std::size_t i = 0; i < n; ++i)
      if(moves[i] && count[i] > 0)
      {
        point(X, i) = point(sum, i) / count[i];
        bound.project(X, i);
      }
  }
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FOLD_REPAIR_H
