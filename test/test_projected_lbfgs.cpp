// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default solver, the projected quasi-Newton method: on a noisy plane within a bound that
// contains the plane, the minimum (energy 0) of the vertices free in their sets is known and must
// be approached (test_normal_offsets has the same on segments), with every
// iterate in the bound and the energy never rising; the result is bit-identical whatever the
// number of threads; no step flips or collapses a triangle; the inverse Hessian's three passes
// give the two-loop recursion's product; and the stopping rule tells slow progress from convergence and
// measures the surface's motion exactly.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Lbfgs_inverse_hessian.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
namespace CF = PMP::internal::Constrained_fairing;
using PMP::Deviation_bound;
using test::Mesh;
using test::Point;

void check_known_minimum(Deviation_bound shape)
{
  Mesh m = test::plane_patch(30);
  const double h = test::mean_edge_length(m);
  test::add_noise(m, 0.3 * h, 21);
  const std::vector<Point> input = test::points(m);
  std::vector<double> energies;
  const auto r = PMP::constrained_fairing(
    m, 0.3 * h,
    CFP::tangential_motion(true, CFP::iteration_callback([&](std::size_t, double e) { energies.push_back(e); return true; },
                            CFP::deviation_bound(shape).number_of_iterations(200))));
  CHECK(r);
  CHECK(test::bound_violation(test::points(m), input, 0.3 * h, shape) == 0);
  CHECK(std::is_sorted(energies.rbegin(), energies.rend()));
  CHECK(!energies.empty() && energies.back() == r.final_energy);
  // The plane has energy 0: 200 iterations must come within a ten-thousandth of the start.
  CHECK(r.final_energy <= 1e-4 * r.initial_energy);
  // One evaluation per iteration in the common case, and never many more.
  CHECK(r.number_of_energy_evaluations <= 2 * r.number_of_iterations + 1);
  double rms = 0;
  for(const Point& p : test::points(m))
    rms += p.z() * p.z();
  std::cout << "  noisy plane, " << (shape == Deviation_bound::BALL ? "ball" : "box") << ": energy "
            << r.initial_energy << " -> " << r.final_energy << " in " << r.number_of_iterations << " iterations, "
            << r.number_of_energy_evaluations << " evaluations, RMS height " << std::sqrt(rms / double(input.size()))
            << std::endl;
}

// Bit-identical results with one thread and with four, on a mesh of ten tiles of the energy's
// evaluation and blocks of the vector passes. Four threads are asked for whatever the machine
// has (TBB then shares its cores between them), so that the parallel loops really split.
// Without TBB the loops are sequential and there is nothing to compare: the check says it is
// skipped.
void check_thread_count_independence()
{
#ifdef CGAL_LINKED_WITH_TBB
  Mesh m = test::icosphere(6);
  const double h = test::mean_edge_length(m);
  test::add_noise(m, 0.25 * h, 22);
  Mesh one = m, four = m;
  PMP::Constrained_fairing_result r_one, r_four;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    r_one = PMP::constrained_fairing(one, 0.25 * h, CGAL::parameters::number_of_iterations(40));
  }
  int threads = 0;
  {
    tbb::global_control several(tbb::global_control::max_allowed_parallelism, 4);
    tbb::task_arena arena(4);
    arena.execute([&] {
      threads = tbb::this_task_arena::max_concurrency();
      r_four = PMP::constrained_fairing(four, 0.25 * h, CGAL::parameters::number_of_iterations(40));
    });
  }
  if(threads < 2)
  {
    std::cout << "  SKIPPED: thread-count independence, TBB gave " << threads << " thread" << std::endl;
    return;
  }
  CHECK(r_one && r_four && r_one.number_of_iterations == 40);
  CHECK(r_one.final_energy == r_four.final_energy);
  CHECK(test::identical(test::points(one), test::points(four)));
  std::cout << "  one thread and " << threads << " threads: bit-identical" << std::endl;
#else
  std::cout << "  SKIPPED: thread-count independence, built without TBB (the loops are sequential)" << std::endl;
#endif
}

// No step flips or collapses a triangle. Each vertex moves at most a tenth of its smallest
// height in its triangles (its reach), so a triangle's area vector N changes by at most 0.3 |N|
// to first order (moving vertex v by d adds d x e, e the opposite edge, and |e| h_v = |N|) and
// 0.03 |N| to second order (|d_u x d_v| <= h_u h_v / 100 <= |N| / 100). Checked between
// consecutive iterates of a run on a sphere with noise of half its edge length, from the
// input itself (no smoothed start), where triangles are small and the steps long.
void check_no_step_flips_a_triangle()
{
  Mesh m = test::icosphere(4);
  const double h = test::mean_edge_length(m);
  test::add_noise(m, 0.5 * h, 23);
  std::vector<std::vector<Point> > iterates;
  for(std::size_t k = 1; k <= 30; ++k)
  {
    Mesh run = m;
    const auto r = PMP::constrained_fairing(
      run, 0.5 * h,
      CFP::initial_smoothing_steps(0, CFP::energy_decrease_threshold(0., CGAL::parameters::number_of_iterations(k))));
    CHECK(r && r.number_of_iterations == k);
    iterates.push_back(test::points(run));
  }
  double worst = 0; // the largest |N' - N| / |N|
  for(std::size_t k = 1; k < iterates.size(); ++k)
    for(auto f : faces(m))
    {
      const auto area_vector = [&](const std::vector<Point>& p) {
        const auto g = halfedge(f, m);
        const Point &a = p[source(g, m)], &b = p[target(g, m)], &c = p[target(next(g, m), m)];
        return CGAL::cross_product(b - a, c - a);
      };
      const test::Vector before = area_vector(iterates[k - 1]), after = area_vector(iterates[k]);
      worst = (std::max)(worst, std::sqrt((after - before).squared_length() / before.squared_length()));
    }
  CHECK(worst <= 0.34);
  std::cout << "  29 steps on a noisy sphere: a triangle's area vector changed by at most " << worst
            << " of itself in one step" << std::endl;
}

// The inverse Hessian's three passes against the two-loop recursion (Nocedal & Wright, alg.
// 7.4) taken literally on the same pairs, stored in single precision, with H0 = gamma K^-1:
// after each of 1 to 9 pairs (one skipped, of negative curvature), on vectors of several blocks
// and a partial one, with stiffnesses spread over orders of magnitude and some zero. Also the
// secant condition H y = s of the newest pair, which BFGS holds whatever H0.
void check_inverse_hessian()
{
  using Hessian = CF::Lbfgs_inverse_hessian;
  const Eigen::Index n = static_cast<Eigen::Index>(3 * CF::parallel_block_size + 123);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(-1, 1), exponent(-3, 3);
  Eigen::VectorXd stiffness(n), curvature(n), inverse_k(n);
  for(Eigen::Index i = 0; i < n; ++i)
  {
    stiffness[i] = i % 97 == 0 ? 0 : std::pow(10., exponent(random));
    inverse_k[i] = stiffness[i] > 0 ? 1 / stiffness[i] : 0;
    curvature[i] = std::pow(10., exponent(random));
  }
  const auto random_points = [&] {
    CF::Points X(n, 3);
    for(Eigen::Index i = 0; i < X.size(); ++i)
      X.data()[i] = uniform(random);
    return X;
  };
  Hessian H;
  std::vector<std::pair<Eigen::MatrixXd, Eigen::MatrixXd> > kept; // oldest first
  const auto three_passes = [&](const CF::Points& q) {
    CF::Points D;
    CHECK(H.start(D, stiffness, [&](CF::Points& Q, std::size_t begin, std::size_t end) {
      for(std::size_t i = begin; i < end; ++i)
        CF::point(Q, i) = CF::point(q, i);
    }));
    CF::parallel_for_blocks(std::size_t(n), [&](std::size_t begin, std::size_t end, std::size_t) {
      H.finish_rows(D, begin, end);
    });
    return D;
  };
  const auto dot = [](const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return a.cwiseProduct(b).sum(); };
  const auto two_loop = [&](const CF::Points& q) {
    Eigen::MatrixXd d = q;
    std::vector<double> alpha(kept.size());
    for(std::size_t j = kept.size(); j-- > 0;)
    {
      alpha[j] = dot(kept[j].first, d) / dot(kept[j].first, kept[j].second);
      d -= alpha[j] * kept[j].second;
    }
    const Eigen::MatrixXd& y = kept.back().second;
    const double gamma = dot(kept.back().first, y) / dot(y, inverse_k.asDiagonal() * y);
    d = gamma * (inverse_k.asDiagonal() * d);
    for(std::size_t j = 0; j < kept.size(); ++j)
    {
      const double beta = dot(kept[j].second, d) / dot(kept[j].first, kept[j].second);
      d += (alpha[j] - beta) * kept[j].first;
    }
    return d;
  };
  const auto relative_error = [](const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    return (a - b).norm() / b.norm();
  };

  // Pairs of a convex quadratic's gradients, but a concave one's for the sixth, which is skipped
  // and takes the oldest pair's slot; after each, the product as the solver takes it.
  double against_two_loop = 0, secant = 0;
  CF::Points X = random_points();
  for(int k = 0; k < int(Hessian::memory) + 4; ++k)
  {
    const double sign = k == 5 ? -1 : 1;
    const CF::Points X_next = X + 0.1 * random_points();
    const CF::Points G = sign * (curvature.asDiagonal() * X), G_next = sign * (curvature.asDiagonal() * X_next);
    H.add_pair(X, X_next, G, G_next);
    if(sign > 0)
    {
      kept.emplace_back((X_next - X).cast<float>().cast<double>(), (G_next - G).cast<float>().cast<double>());
      if(kept.size() > Hessian::memory)
        kept.erase(kept.begin());
    }
    else if(kept.size() == Hessian::memory)
      kept.erase(kept.begin());
    X = X_next;
    CHECK(H.number_of_pairs() == kept.size());
    const CF::Points q = random_points();
    against_two_loop = (std::max)(against_two_loop, relative_error(three_passes(q), two_loop(q)));
    secant = (std::max)(secant, relative_error(three_passes(kept.back().second), kept.back().first));
  }
  CHECK(against_two_loop < 1e-10);
  CHECK(secant < 1e-10);
  std::cout << "  inverse Hessian of 1 to " << Hessian::memory << " pairs: relative difference at most "
            << against_two_loop << " to the two-loop recursion, " << secant << " to the secant condition" << std::endl;
}

// The iteration at which `options`' rule stops on the energies `energy(k)`, k = 0, 1, ..., or 0
// if it runs all `iterations`.
template <typename Energy>
std::size_t stopping_iteration(CF::Solver_options options, const Energy& energy, std::size_t iterations)
{
  options.max_iterations = iterations;
  CF::Stopping_rule rule(options);
  CF::Solver_report report;
  rule.push(energy(0));
  for(std::size_t k = 1; k <= iterations; ++k)
    if(!rule.next_iteration(energy(k), CF::Always_continue(), report))
      return k;
  return 0;
}

void check_stopping_rule()
{
  const CF::Solver_options options = CF::default_options(PMP::Constrained_fairing_method::QUASI_NEWTON);
  const double fraction = options.remaining_fraction;
  CHECK(fraction > 0);
  // Steady progress ten times slower than the threshold: never taken for convergence.
  const auto steady = [&](std::size_t k) { return 100 * (1 - 0.1 * options.threshold * double(k)); };
  CHECK(stopping_iteration(options, steady, 1000) == 0);
  // Slowly fading progress, where the extrapolation is exact: the run stops at the first
  // iteration where what remains is at most the fraction of the energy, while the threshold
  // alone stops it earlier, with more than that left.
  const double floor = 100, rate = 0.995;
  const auto fading = [&](std::size_t k) { return floor + 50 * std::pow(rate, double(k)); };
  const auto remaining_is_small = [&](std::size_t k) {
    return fading(k) - floor <= fraction * fading(k) * (1 + 1e-9);
  };
  const std::size_t stop = stopping_iteration(options, fading, 1000);
  CHECK(stop > 0);
  CHECK(remaining_is_small(stop));
  CHECK(!remaining_is_small(stop - 1));
  // A shape that has not settled holds the stop back, however small the energy's remainder.
  {
    CF::Stopping_rule rule(options);
    CF::Solver_report report;
    rule.push(fading(0));
    for(std::size_t k = 1; k <= 1000; ++k)
      CHECK(rule.next_iteration(fading(k), CF::Always_continue(), report, false));
  }
  CF::Solver_options threshold_alone = options;
  threshold_alone.remaining_fraction = 0;
  const std::size_t early = stopping_iteration(threshold_alone, fading, 1000);
  CHECK(early > 0 && early < stop && !remaining_is_small(early));
  // No decrease over a whole window, with no earlier window to extrapolate from: stationary.
  const auto flat = [&](std::size_t) { return 40.; };
  CHECK(stopping_iteration(options, flat, 1000) == options.window);
  // The rule keeps two windows whatever the iterations allowed: a limit of the size type's
  // largest value allocates nothing in proportion to it, and stops where any limit does.
  CF::Solver_options unlimited = options;
  unlimited.max_iterations = (std::numeric_limits<std::size_t>::max)();
  CF::Stopping_rule rule(unlimited);
  CF::Solver_report report;
  rule.push(fading(0));
  std::size_t k = 1;
  while(rule.next_iteration(fading(k), CF::Always_continue(), report))
    ++k;
  CHECK(k == stop);
}

// The surface's motion (Surface_motion.h): each vertex's displacement over a window relative to
// its own bound's size, pinned and free vertices left out (all of a sliding run's), exact far
// from the origin; the remainder
// extrapolated from windows whose motion falls by a fixed ratio is exact, so the rule settles at
// the first window where it is at most the fraction, and a window with no motion settles.
void check_surface_motion()
{
  const double origin = 1e6, fraction = 0.005, ratio = 0.6;
  const std::vector<double> sizes{1e-3, 0., 4e-3, 2e-3};
  CF::Points X0(4, 3);
  for(Eigen::Index i = 0; i < 4; ++i)
    X0.row(i) << origin + double(i), origin, -origin;
  const CF::Ball_bound bound(X0, CF::Bound_sizes(sizes));
  // Normal offsets along x; vertex 3 moves freely, vertex 1 is pinned.
  CF::Points N = CF::Points::Zero(4, 3);
  for(Eigen::Index i = 0; i < 3; ++i)
    N(i, 0) = 1;
  const CF::Normal_offset_bound<CF::Ball_bound> offsets(bound, X0, N);
  // Window k moves each vertex along x by a fraction m_k = 0.2 ratio^k of its size, and the free
  // vertex across by ten times as much, which must not count.
  const auto window_motion = [&](std::size_t k) { return 0.2 * std::pow(ratio, double(k)); };
  const auto remainder = [&](std::size_t k) { return window_motion(k) * ratio / (1 - ratio); };
  CF::Points X = X0;
  CF::Surface_motion motion;
  motion.end_window(offsets, X);
  CHECK(!motion.has_settled(fraction));
  std::size_t settled = 0;
  for(std::size_t k = 0; k < 40 && settled == 0; ++k)
  {
    for(Eigen::Index i = 0; i < 4; ++i)
      X(i, 0) += window_motion(k) * sizes[std::size_t(i)];
    X(3, 1) += 10 * window_motion(k) * sizes[3];
    motion.end_window(offsets, X);
    CHECK(std::abs(motion.last_window() - window_motion(k)) <= 1e-4 * window_motion(k));
    if(motion.has_settled(fraction))
      settled = k;
  }
  CHECK(settled > 0);
  CHECK(remainder(settled) <= fraction * (1 + 1e-4));
  CHECK(remainder(settled - 1) > fraction);
  motion.end_window(offsets, X);
  CHECK(motion.last_window() == 0 && motion.has_settled(fraction));

  // Sliding vertices (the bound itself): none counts, so the shape never holds the stop back.
  CF::Surface_motion sliding;
  sliding.end_window(bound, X0);
  CHECK(sliding.has_settled(fraction));
}

int main()
{
  check_surface_motion();
  check_stopping_rule();
  check_inverse_hessian();
  check_known_minimum(Deviation_bound::BALL);
  check_known_minimum(Deviation_bound::BOX);
  check_thread_count_independence();
  check_no_step_flips_a_triangle();
  return test::report("test_projected_lbfgs");
}
