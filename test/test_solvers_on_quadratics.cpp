// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The three solvers (the projected quasi-Newton method, the active set Newton method and the
// projected gradient method) on convex quadratics over the vertices of a plane patch, whose
// unconstrained minimizer lies partly outside the bound, so that the constrained one is known:
//  - in boxes, a separable quadratic: its minimizer clamped into the boxes;
//  - in balls, a quadratic separable per vertex and isotropic: its minimizer projected onto
//    the balls;
//  - in boxes, the quadratic coupled along the mesh edges: a plain projected gradient
//    iteration with a fixed step, run to its fixed point, gives the minimizer.
// Each run must reach that minimizer, stay exactly in the bound, never raise the energy, and
// stop converged, only once no step decreases the energy.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Deviation_bounds.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Active_set_newton.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Projected_lbfgs.h>

#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CF = PMP::internal::Constrained_fairing;
using CF::Points;
using PMP::Constrained_fairing_method;
using PMP::Constrained_fairing_status;
using PMP::Deviation_bound;

using Sparse_solver = CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType> >;
using Edges = std::vector<std::pair<std::size_t, std::size_t> >;

// f(X) = 1/2 sum_i sum_c w_ic d_ic^2 + tau/2 sum_{edges ij} |d_i - d_j|^2, with D = X - M: the
// quadratic 1/2 d^T A d, A = W + tau (L x I_3) symmetric positive definite (L the edges' graph
// Laplacian), non-negative and minimal at M; separable for tau = 0. A model of the solvers'
// Objective (Projected_line_search.h).
class Quadratic
{
public:
  Quadratic(const Points& M, const Points& W, const Edges& edges, double tau)
    : m_M(M), m_W(W), m_edges(edges), m_tau(tau)
  {
  }

  double value(const Points& X) { return value_and_gradient(X, m_G, nullptr); }

  // The evaluations so far, with or without the gradient.
  std::size_t evaluations() const { return m_evaluations; }

  // The gradient A D; the vertex scales: A's diagonal, averaged over the three coordinates,
  // and no limit on a move.
  double value_and_gradient(const Points& X, Points& G, CF::Stiffness_and_reach* scales)
  {
    ++m_evaluations;
    const Points D = X - m_M;
    G = m_W.cwiseProduct(D);
    for(const auto& e : m_edges)
    {
      const Eigen::Vector3d difference = m_tau * (CF::point(D, e.first) - CF::point(D, e.second));
      CF::point(G, e.first) += difference;
      CF::point(G, e.second) -= difference;
    }
    if(scales)
    {
      scales->stiffness = m_W.rowwise().mean();
      for(const auto& e : m_edges)
      {
        scales->stiffness[Eigen::Index(e.first)] += m_tau;
        scales->stiffness[Eigen::Index(e.second)] += m_tau;
      }
      scales->reach.setConstant(X.rows(), std::numeric_limits<double>::infinity());
    }
    return 0.5 * CF::dot(D, G);
  }

  // The largest eigenvalue of A at most (Gershgorin).
  double lipschitz_bound() const
  {
    Eigen::VectorXd row_sum = m_W.rowwise().maxCoeff();
    for(const auto& e : m_edges)
    {
      row_sum[Eigen::Index(e.first)] += 2 * m_tau;
      row_sum[Eigen::Index(e.second)] += 2 * m_tau;
    }
    return row_sum.maxCoeff();
  }

private:
  Points m_M, m_W;
  Edges m_edges;
  double m_tau;
  Points m_G; // value()'s unused gradient
  std::size_t m_evaluations = 0;
};

// The problems share the vertices of a plane patch, the size of their bound, and the mesh's
// edges; the active set Newton method also takes the mesh, for its Hessian model.
struct Setting
{
  test::Mesh mesh = test::plane_patch(12);
  test::Indexed indexed{mesh};
  const Points& X0 = indexed.X;
  const std::size_t n = static_cast<std::size_t>(X0.rows());
  const double eps = 0.3 * test::mean_edge_length(mesh);
  Edges edges;

  Setting()
  {
    for(auto e : mesh.edges())
      edges.emplace_back(mesh.vertex(e, 0).idx(), mesh.vertex(e, 1).idx());
  }
  Setting(const Setting&) = delete; // X0 refers to its own member

  // The unconstrained minimizer: each vertex moved by up to 1.5 eps along each axis (seeded), so
  // that about a third of the coordinates end outside their box, and about 85 % of the vertices
  // outside their ball.
  Points minimizer(unsigned int seed) const
  {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> offset(-1.5 * eps, 1.5 * eps);
    Points M = X0;
    for(Eigen::Index i = 0; i < M.size(); ++i)
      M.data()[i] += offset(random);
    return M;
  }

  // Weights w_ic in [1, 4], the same for a vertex's three coordinates if `isotropic`.
  Points weights(unsigned int seed, bool isotropic) const
  {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> weight(1, 4);
    Points W(X0.rows(), 3);
    for(Eigen::Index i = 0; i < X0.rows(); ++i)
    {
      W.row(i).setConstant(weight(random));
      if(!isotropic)
        for(int c = 1; c < 3; ++c)
          W(i, c) = weight(random);
    }
    return W;
  }
};

std::vector<test::Point> to_points(const Points& X)
{
  std::vector<test::Point> result;
  for(std::size_t i = 0; i < static_cast<std::size_t>(X.rows()); ++i)
    result.emplace_back(X(Eigen::Index(i), 0), X(Eigen::Index(i), 1), X(Eigen::Index(i), 2));
  return result;
}

const char* name(Constrained_fairing_method method)
{
  switch(method)
  {
  case Constrained_fairing_method::QUASI_NEWTON: return "quasi-Newton";
  case Constrained_fairing_method::ACTIVE_SET_NEWTON: return "active set Newton";
  default: return "projected gradient";
  }
}

// Runs `method` from the centres of the bound to the end, and checks it against the
// constrained minimizer X_star.
template <typename Bound>
void check_run(const Setting& setting, const Bound& bound, Deviation_bound shape, Quadratic& f,
               Constrained_fairing_method method, const Points& X_star, const char* problem)
{
  // the paper's methods' window, for each method
  CF::Solver_options options = CF::default_options(Constrained_fairing_method::ACTIVE_SET_NEWTON);
  options.threshold = 0; // on until no step decreases the energy any more
  options.max_iterations = 5000;
  options.cauchy_steps_only = method == Constrained_fairing_method::PROJECTED_GRADIENT;
  Points X = setting.X0;
  std::vector<double> energies;
  const auto callback = [&](std::size_t, double e) {
    energies.push_back(e);
    return true;
  };
  // One solver object runs twice from the same start, as fold repair reuses it: both runs
  // must be the same, and each must count the evaluations it made.
  CF::Projected_lbfgs<Bound, Quadratic> quasi_newton(bound, f);
  CF::Active_set_newton<Bound, Sparse_solver, Quadratic> active_set(setting.indexed.hinges, bound, f, Sparse_solver());
  CF::Solver_report report;
  for(int run = 0; run < 2; ++run)
  {
    X = setting.X0;
    energies.clear();
    const std::size_t before = f.evaluations();
    const CF::Solver_report previous = report;
    report = method == Constrained_fairing_method::QUASI_NEWTON ? quasi_newton.run(X, options, callback)
                                                                 : active_set.run(X, options, callback);
    CHECK(report.energy_evaluations == f.evaluations() - before);
    if(run == 1)
      CHECK(report.iterations == previous.iterations && report.final_energy == previous.final_energy);
  }

  CHECK(report.status == Constrained_fairing_status::CONVERGED);
  CHECK(test::bound_violation(to_points(X), to_points(setting.X0), setting.eps, shape) == 0);
  for(std::size_t i = 0; i < setting.n; ++i)
    CHECK(bound.contains(X, i));
  CHECK(!energies.empty() && energies.front() <= f.value(setting.X0));
  CHECK(std::is_sorted(energies.rbegin(), energies.rend()));
  CHECK(!energies.empty() && energies.back() == report.final_energy);
  CHECK((report.cg_iterations > 0) == (method == Constrained_fairing_method::ACTIVE_SET_NEWTON));
  // Near the minimizer the energy changes by the square of the distance to it, so a run that
  // stops when the energy no longer decreases in double is about sqrt(1e-16) eps away; a wrong
  // minimizer would be a sizeable part of eps away.
  const double error = (X - X_star).rowwise().norm().maxCoeff() / setting.eps;
  const double E_star = f.value(X_star);
  const double excess = (report.final_energy - E_star) / E_star;
  CHECK(error <= 1e-5);
  CHECK(std::abs(excess) <= 1e-12);
  std::cout << "  " << problem << ", " << name(method) << ": " << report.iterations << " iterations, "
            << report.energy_evaluations << " evaluations, largest error " << error
            << " eps, relative energy excess " << excess << std::endl;
}

template <typename Bound>
void check_methods(const Setting& setting, const Bound& bound, Deviation_bound shape, Quadratic& f, const Points& M,
                   const Points& X_star, const char* problem)
{
  // Partly outside: the unconstrained minimizer of some vertices is in their set, and of some not.
  std::size_t outside = 0;
  for(std::size_t i = 0; i < setting.n; ++i)
    outside += bound.contains(M, i) ? 0 : 1;
  CHECK(outside > setting.n / 10 && outside < setting.n - setting.n / 10);
  for(Constrained_fairing_method method :
      {Constrained_fairing_method::QUASI_NEWTON, Constrained_fairing_method::ACTIVE_SET_NEWTON,
       Constrained_fairing_method::PROJECTED_GRADIENT})
    check_run(setting, bound, shape, f, method, X_star, problem);
}

// Separable in boxes: the minimizer is M clamped into the boxes.
void check_separable_box(const Setting& setting)
{
  const Points M = setting.minimizer(1);
  Quadratic f(M, setting.weights(2, false), {}, 0);
  const CF::Box_bound bound(setting.X0, setting.eps);
  const Points X_star = M.array().max(setting.X0.array() - setting.eps).min(setting.X0.array() + setting.eps).matrix();
  check_methods(setting, bound, Deviation_bound::BOX, f, M, X_star, "separable, boxes");
}

// Separable per vertex and isotropic in balls: vertex i's term is w_i/2 |x_i - m_i|^2, whose
// minimizer in the ball is m_i projected onto it.
void check_separable_ball(const Setting& setting)
{
  const Points M = setting.minimizer(3);
  Quadratic f(M, setting.weights(4, true), {}, 0);
  const CF::Ball_bound bound(setting.X0, setting.eps);
  Points X_star = M;
  for(std::size_t i = 0; i < setting.n; ++i)
  {
    const Eigen::Vector3d d = CF::point(M, i) - CF::point(setting.X0, i);
    if(d.norm() > setting.eps)
      CF::point(X_star, i) = CF::point(setting.X0, i) + (setting.eps / d.norm()) * d;
  }
  check_methods(setting, bound, Deviation_bound::BALL, f, M, X_star, "separable, balls");
}

// Coupled along the edges in boxes: X = P(X - grad f(X) / L) with L >= A's largest eigenvalue
// contracts by 1 - 1/L at least (A's smallest eigenvalue is at least 1), to the minimizer.
void check_coupled_box(const Setting& setting)
{
  const Points M = setting.minimizer(5);
  Quadratic f(M, setting.weights(6, false), setting.edges, 0.5);
  const CF::Box_bound bound(setting.X0, setting.eps);
  const double step = 1 / f.lipschitz_bound();
  Points X_star = setting.X0, G, previous;
  double change = 0;
  for(int k = 0; k < 2000; ++k)
  {
    previous = X_star;
    f.value_and_gradient(X_star, G, nullptr);
    X_star -= step * G;
    bound.project(X_star);
    change = (X_star - previous).cwiseAbs().maxCoeff();
  }
  CHECK(change <= 1e-13 * setting.eps); // at its fixed point up to rounding
  check_methods(setting, bound, Deviation_bound::BOX, f, M, X_star, "coupled, boxes");
}

int main()
{
  const Setting setting;
  std::cout << "  " << setting.n << " vertices, " << setting.edges.size() << " edges" << std::endl;
  check_separable_box(setting);
  check_separable_ball(setting);
  check_coupled_box(setting);
  return test::report("test_solvers_on_quadratics");
}
