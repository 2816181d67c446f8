// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The limited-memory BFGS inverse Hessian H of the quasi-Newton method (Projected_lbfgs.h): the
// BFGS updates of the last `memory` pairs (s_j, y_j) (steps and gradient changes) applied to
// H0 = gamma K^-1, K the vertices' stiffness (Stiffness_preconditioner.h) at the current iterate
// and gamma = s.y / (y.K^-1 y) for the newest pair.
//
// H q is the two-loop recursion's (Nocedal & Wright, Numerical Optimization, algorithm 7.4),
//
//   r = q;  newest to oldest: alpha_j = rho_j <s_j, r>, r -= alpha_j y_j;   r = H0 r;
//           oldest to newest: beta_j = rho_j <y_j, r>,  r += (alpha_j - beta_j) s_j,
//
// with rho_j = 1 / <s_j, y_j>, taken in three passes over the vertices instead of one per
// update. The dots expand: <s_j, r> = <s_j, q> - sum over the newer pairs i of alpha_i <s_j, y_i>,
// and <y_j, r> = <y_j, H0 r0> + sum over the older pairs i of (alpha_i - beta_i) <s_i, y_j>, r0 the
// vector after the first loop. The <s_i, y_j> of an older pair i and a newer j do not change
// while both are kept, and are taken in the first product after j is added. So: one pass for the
// <s_j, q> (and the newest pair's <s_i, y_j>), one that writes H0 r0 and takes its
// <y_j, H0 r0>, one that adds the s_j. On large meshes the direction is memory-bound, and with
// five pairs these passes move about half the bytes of the recursion's one pass per update
// (doc/design_notes.md, "The quasi-Newton method's vector work").
//
// The pairs are stored in single precision: they only shape the direction, whose descent the
// solver checks in double, and they are most of its memory.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_LBFGS_INVERSE_HESSIAN_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_LBFGS_INVERSE_HESSIAN_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Stiffness_preconditioner.h>

#include <CGAL/assertions.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Lbfgs_inverse_hessian
{
public:
  // The number of pairs kept.
  static constexpr std::size_t memory = 5;

  std::size_t number_of_pairs() const { return m_pairs; }

  // Drops the pairs: H becomes H0.
  void clear() { m_pairs = 0; }

  // Drops the pairs and returns their memory.
  void release()
  {
    clear();
    for(std::size_t k = 0; k < memory; ++k)
    {
      m_s[k].resize(0, 3);
      m_y[k].resize(0, 3);
    }
  }

  // Adds s = X_next - X and y = G_next - G if their curvature s.y is positive (else the pair
  // would make H indefinite and is skipped); the oldest pair goes when `memory` are kept.
  void add_pair(const Points& X, const Points& X_next, const Points& G, const Points& G_next)
  {
    // The newest pair's <s_i, y> are taken by start(), which must come between.
    CGAL_precondition(m_pairs < 2 || m_products_taken);
    const std::size_t slot = (m_newest + 1) % memory;
    Float_points &s = m_s[slot], &y = m_y[slot];
    s.resize(X.rows(), 3);
    y.resize(X.rows(), 3);
    const double sy = parallel_sum(static_cast<std::size_t>(X.rows()), m_partial, [&](std::size_t begin, std::size_t end) {
      for(std::size_t i = begin; i < end; ++i)
      {
        const auto row = static_cast<Eigen::Index>(i);
        s.row(row) = (point(X_next, i) - point(X, i)).transpose().cast<float>();
        y.row(row) = (point(G_next, i) - point(G, i)).transpose().cast<float>();
      }
      return dot_rows(s, y, begin, end);
    });
    if(!(sy > 0))
    {
      if(m_pairs == memory) // the slot held the oldest pair
        --m_pairs;
      return;
    }
    m_rho[slot] = 1 / sy;
    m_newest = slot;
    if(m_pairs < memory)
      ++m_pairs;
    m_products_taken = false;
  }

  // The first two passes of H q, with at least one pair: `write_q(Q, begin, end)` writes the
  // rows [begin, end) of q to Q (a block of Parallel_for.h), and Q becomes H0 r0. Returns false
  // if H q is not defined in double (H0 degenerate), else finish_rows() gives H q.
  template <typename Write_q>
  bool start(Points& Q, const Eigen::VectorXd& stiffness, const Write_q& write_q)
  {
    CGAL_precondition(m_pairs > 0);
    const std::size_t m = m_pairs;
    const std::size_t n = static_cast<std::size_t>(stiffness.size());
    Q.resize(static_cast<Eigen::Index>(n), 3);
    // The <s_j, q>, the <s_i, y> of the newest pair's y for the older pairs i, and its
    // <y, K^-1 y> for gamma.
    std::array<double, 2 * memory> sums{};
    const Float_points& newest_y = m_y[m_newest];
    parallel_sums(n, 2 * m, m_partial, sums.data(), [&](std::size_t begin, std::size_t end, double* block) {
      write_q(Q, begin, end);
      for(std::size_t j = 0; j < m; ++j)
        block[j] = dot_rows(m_s[pair(j)], Q, begin, end);
      for(std::size_t i = 0; i + 1 < m; ++i)
        block[m + i] = dot_rows(m_s[pair(i)], newest_y, begin, end);
      block[2 * m - 1] = inverse_stiffness_norm2_rows(stiffness, newest_y, begin, end);
    });
    for(std::size_t i = 0; i + 1 < m; ++i)
      m_sy[pair(i)][m_newest] = sums[m + i];
    m_products_taken = true;
    m_gamma = 1 / (m_rho[m_newest] * sums[2 * m - 1]);
    for(std::size_t j = m; j-- > 0;) // newest to oldest
    {
      double sr = sums[j];
      for(std::size_t i = j + 1; i < m; ++i)
        sr -= m_alpha[i] * m_sy[pair(j)][pair(i)];
      m_alpha[j] = m_rho[pair(j)] * sr;
    }

    // H0 r0 and its <y_j, H0 r0>, in loops over the block's coordinates, which vectorize.
    parallel_sums(n, m, m_partial, sums.data(), [&](std::size_t begin, std::size_t end, double* block) {
      double* r = Q.data();
      for(std::size_t j = 0; j < m; ++j)
      {
        const float* y = m_y[pair(j)].data();
        for(std::size_t t = 3 * begin; t < 3 * end; ++t)
          r[t] -= m_alpha[j] * double(y[t]);
      }
      for(std::size_t i = begin; i < end; ++i)
      {
        const double k = stiffness[static_cast<Eigen::Index>(i)];
        point(Q, i) = k > 0 ? Eigen::Vector3d((m_gamma / k) * point(Q, i)) : Eigen::Vector3d::Zero();
      }
      for(std::size_t j = 0; j < m; ++j)
        block[j] = dot_rows(m_y[pair(j)], Q, begin, end);
    });
    for(std::size_t j = 0; j < m; ++j) // oldest to newest
    {
      double yr = sums[j];
      for(std::size_t i = 0; i < j; ++i)
        yr += m_step[i] * m_sy[pair(i)][pair(j)];
      m_step[j] = m_alpha[j] - m_rho[pair(j)] * yr;
    }
    bool finite = std::isfinite(m_gamma);
    for(std::size_t j = 0; j < m; ++j)
      finite = finite && std::isfinite(m_step[j]);
    return finite;
  }

  // The last pass, after start(): the rows [begin, end) of Q become those of H q.
  void finish_rows(Points& Q, std::size_t begin, std::size_t end) const
  {
    for(std::size_t j = 0; j < m_pairs; ++j)
    {
      const float* s = m_s[pair(j)].data();
      for(std::size_t t = 3 * begin; t < 3 * end; ++t)
        Q.data()[t] += m_step[j] * double(s[t]);
    }
  }

private:
  // The slot of the j-th pair, oldest first.
  std::size_t pair(std::size_t j) const { return (m_newest + 1 + memory - m_pairs + j) % memory; }

  std::array<Float_points, memory> m_s, m_y;
  std::array<double, memory> m_rho{};
  // m_sy[i][j] = <s_i, y_j> for the slot i of an older pair than that of slot j
  std::array<std::array<double, memory>, memory> m_sy{};
  std::size_t m_pairs = 0, m_newest = 0;
  bool m_products_taken = false; // the newest pair's <s_i, y_j>
  // from start(), per pair oldest first: the alpha_j, and the alpha_j - beta_j
  std::array<double, memory> m_alpha{}, m_step{};
  double m_gamma = 0;
  std::vector<double> m_partial;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_LBFGS_INVERSE_HESSIAN_H
