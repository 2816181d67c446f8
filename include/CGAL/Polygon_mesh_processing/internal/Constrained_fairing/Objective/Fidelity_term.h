// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The accurate objective's fidelity term, which keeps the surface near an anchor a_i:
//
//   F = mu / n * sum_i |x_i - a_i|^2 / t_i^2,
//
// over the n vertices of nonzero tolerance t_i. F is dimensionless like the bending energy,
// and is mu when every vertex is its tolerance away from its anchor. Why: the bending energy is
// scale-invariant and does not care where in its band the surface sits, so its minimum
// flattens real detail up to the bound. The anchor is a denoised copy of the input (the
// input's choice, its denoise(): a mesh's is Fidelity_anchor.h, a point set's a jet fit), which keeps
// the detail larger than the noise, while the bending energy removes what the filter leaves.
// Every vertex counts alike, as in the bending energy, whose terms are per hinge, and as in
// the noise of a scan, which is per point: weighted by vertex areas, the term held the vertices
// of small triangles too loosely, and their normals ended worse than those of a bounded Taubin
// smoothing (see benchmark/fairing_accuracy).

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FIDELITY_TERM_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FIDELITY_TERM_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Objective_terms.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Fidelity_term final : public Objective_term
{
public:
  // The term of weight mu towards `anchor` (kept by reference); `tolerance(i)` is vertex i's
  // tolerance (no term for a vertex of tolerance 0, which does not move).
  template <typename Tolerance>
  Fidelity_term(double mu, const Tolerance& tolerance, const Points& anchor) : m_anchor(anchor)
  {
    const std::size_t n = static_cast<std::size_t>(anchor.rows());
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

  double value(const Points& X) override
  {
    return parallel_sum(m_weight.size(), m_partial, [&](std::size_t begin, std::size_t end) {
      double sum = 0;
      for(std::size_t i = begin; i < end; ++i)
        sum += m_weight[i] * (point(X, i) - point(m_anchor, i)).squaredNorm();
      return sum;
    });
  }

  // Adds 2 w_i (x_i - a_i) to the gradient and 2 w_i to the stiffness, in every direction.
  double add_gradient(const Points& X, Points& G, Stiffness_and_reach* scales) override
  {
    parallel_for_blocks(m_weight.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t i = begin; i < end; ++i)
      {
        const double k = 2 * m_weight[i];
        point(G, i) += k * (point(X, i) - point(m_anchor, i));
        if(scales)
          scales->stiffness[static_cast<Eigen::Index>(i)] += k;
      }
    });
    return value(X);
  }

private:
  const Points& m_anchor;
  std::vector<double> m_weight;
  std::vector<double> m_partial;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FIDELITY_TERM_H
