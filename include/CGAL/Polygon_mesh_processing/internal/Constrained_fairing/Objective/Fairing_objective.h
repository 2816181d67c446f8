// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The function the solvers minimize: the bending energy (Bending_energy.h), plus the barrier
// against slivers (Sliver_barrier.h), plus, on a multi-label surface, the barrier against folds
// (Fold_barrier.h), plus the bending of the curves the energy's hinges do not
// cross (Curve_bending.h: a mesh's creases, a multi-label surface's junction lines), plus, on a
// multi-label surface, its labels' volumes (Label_volumes.h), plus, for the
// accurate objective, a fidelity term that keeps the surface near an anchor a_i:
//
//   F = mu / n * sum_i |x_i - a_i|^2 / t_i^2,
//
// over the n vertices of nonzero tolerance t_i. F is dimensionless like the bending energy,
// and is mu when every vertex is its tolerance away from its anchor. Why: the bending energy is
// scale-invariant and does not care where in its band the surface sits, so its minimum
// flattens real detail up to the bound. The anchor is a denoised copy of the input (the
// caller's choice; the driver, Fairing_driver.h, makes it with Fidelity_anchor.h), which keeps
// the detail larger than the noise, while the bending energy removes what the filter leaves.
// Every vertex counts alike, as in the bending energy, whose terms are per hinge, and as in
// the noise of a scan, which is per point: weighted by vertex areas, the term held the vertices
// of small triangles too loosely, and their normals ended worse than those of a bounded Taubin
// smoothing (see benchmark/fairing_accuracy).

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_OBJECTIVE_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_OBJECTIVE_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Bending_energy.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Curve_bending.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fold_barrier.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_interfaces/Label_volumes.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Sliver_barrier.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Stiffness_and_reach.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>

#include <CGAL/assertions.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Fairing_objective
{
public:
  // `sliver_weight`: the weight of the barrier against slivers, 0 for none; `sliver_threshold`
  // the quality under which a triangle is a sliver.
  Fairing_objective(const Hinge_mesh& mesh, const Points& X0, double sliver_weight, double sliver_threshold)
    : m_mesh(mesh), m_bending(mesh, X0), m_barrier(mesh, X0, sliver_weight, sliver_threshold)
  {
  }

  // Adds the fidelity term of weight mu towards `anchor` (kept by reference); `tolerance(i)`
  // is vertex i's tolerance (no term for a vertex of tolerance 0, which does not move).
  template <typename Tolerance>
  void add_fidelity(double mu, const Tolerance& tolerance, const Points& anchor)
  {
    m_anchor = &anchor;
    const std::size_t n = m_mesh.number_of_vertices;
    std::size_t moving = 0;
    for(std::size_t i = 0; i < n; ++i)
      if(tolerance(i) > 0)
        ++moving;
    m_weight.assign(n, 0.);
    for(std::size_t i = 0; i < n; ++i)
    {
      const double t = tolerance(i);
      if(t > 0)
        m_weight[i] = mu / (double(moving) * t * t);
    }
  }

  // Adds the bending of the creases or junction lines (kept by reference).
  void add_curve_bending(const Curve_bending& curves) { m_curves = &curves; }

  // Adds the volumes of the labels of a multi-label surface (kept by reference), whose triangles
  // are the mesh's, in its order.
  void add_label_volumes(Label_volumes& volumes)
  {
    CGAL_precondition(volumes.number_of_triangles() == m_mesh.triangles.size());
    m_volumes = &volumes;
  }

  // Adds the barrier against folds.
  void add_fold_barrier(const Fold_barrier& folds) { m_folds = folds; }

  std::size_t number_of_degenerate_hinges() const { return m_bending.number_of_degenerate_hinges(); }

  double bending_energy(const Points& X) { return m_bending.value(X); }

  double value(const Points& X)
  {
    double sum = m_bending.value(X, Triangle_terms{m_barrier, nullptr}, m_folds);
    if(m_curves)
      sum += m_curves->value(X);
    if(m_volumes)
      sum += m_volumes->value(X);
    return sum + fidelity(X);
  }

  // As Bending_energy::value_and_gradient(); the fidelity term adds 2 w_i (x_i - x0_i) to the
  // gradient and 2 w_i to the stiffness, in every direction.
  double value_and_gradient(const Points& X, Points& G, Stiffness_and_reach* scales = nullptr)
  {
    double sum = m_volumes ? m_volumes->update_pulls(X) : 0;
    sum += m_bending.value_and_gradient(X, G, scales, Triangle_terms{m_barrier, m_volumes}, m_folds);
    if(m_curves)
      sum += m_curves->add_gradient(X, G, scales);
    if(m_weight.empty())
      return sum;
    parallel_for_blocks(m_weight.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t i = begin; i < end; ++i)
      {
        const double k = 2 * m_weight[i];
        point(G, i) += k * (point(X, i) - point(*m_anchor, i));
        if(scales)
          scales->stiffness[static_cast<Eigen::Index>(i)] += k;
      }
    });
    return sum + fidelity(X);
  }

private:
  // The terms evaluated in the bending energy's tiles (Bending_energy.h): the barrier's, and the
  // volumes' gradient at the pulls of their last update.
  struct Triangle_terms
  {
    static constexpr bool active = true;
    const Sliver_barrier& barrier;
    const Label_volumes* volumes;

    double value(Index f, const std::array<Eigen::Vector3d, 3>& p) const { return barrier.value(f, p); }

    double add_gradient(Index f, const std::array<Index, 3>& v, const std::array<Eigen::Vector3d, 3>& p,
                        unsigned corners, Points& G, Stiffness_and_reach* scales) const
    {
      if(volumes)
        volumes->add_gradient(f, v, p, corners, G);
      return barrier.add_gradient(f, v, p, corners, G, scales);
    }
  };

  double fidelity(const Points& X)
  {
    if(m_weight.empty())
      return 0;
    return parallel_sum(m_weight.size(), m_partial, [&](std::size_t begin, std::size_t end) {
      double sum = 0;
      for(std::size_t i = begin; i < end; ++i)
        sum += m_weight[i] * (point(X, i) - point(*m_anchor, i)).squaredNorm();
      return sum;
    });
  }

  const Hinge_mesh& m_mesh;
  const Points* m_anchor = nullptr;
  const Curve_bending* m_curves = nullptr;
  Label_volumes* m_volumes = nullptr;
  Bending_energy m_bending;
  Sliver_barrier m_barrier;
  Fold_barrier m_folds; // none but on a multi-label surface
  std::vector<double> m_weight; // empty without the fidelity term
  std::vector<double> m_partial;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_OBJECTIVE_H
