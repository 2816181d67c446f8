// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Normal offsets (Bounds/Normal_offsets.h): each segment's ends are inside the bound by the
// user's check and as far as the line goes in it; projection lands on the line and inside the
// bound, and is the nearest point of the segment; an end binds only where the gradient pushes
// past it, and then stops the vertex; the restriction keeps the line; a vertex with no direction is the bound's own. On a separable quadratic, whose
// minimizer over each segment is known, the quasi-Newton method finds it; on a plane patch with
// noise across it, the default call recovers the plane. The default is the one documented: along
// the normals with the ball, sliding with the box and the accurate objective. Where the default
// stops, three times the iterations barely move the surface.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Active_set.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Deviation_bounds.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Normal_offsets.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Projected_lbfgs.h>

#include <cmath>
#include <random>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
namespace CF = PMP::internal::Constrained_fairing;

// n random starts inside their sets (`inside(i, q)`), random unit directions, every tenth zero.
struct Lines
{
  CF::Points S, N;
};

template <typename Bound>
Lines random_lines(const Bound& bound, const CF::Points& X0, double size, std::mt19937& random)
{
  std::uniform_real_distribution<double> unit(-1, 1);
  Lines lines{CF::Points(X0.rows(), 3), CF::Points(X0.rows(), 3)};
  for(std::size_t i = 0; i < std::size_t(X0.rows()); ++i)
  {
    Eigen::Vector3d offset;
    do
      offset = Eigen::Vector3d(unit(random), unit(random), unit(random));
    while(offset.norm() > 1);
    CF::point(lines.S, i) = CF::point(X0, i) + 0.9 * size * offset;
    bound.project(lines.S, i);
    Eigen::Vector3d n(unit(random), unit(random), unit(random));
    CF::point(lines.N, i) = i % 10 == 9 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(n.normalized());
  }
  return lines;
}

// The segments' ends, the projection and the restriction, for coordinates and sizes of very
// different magnitudes.
template <typename Bound>
void check_segments(double scale, double size)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  const std::size_t n = 200;
  CF::Points X0(n, 3);
  for(std::size_t i = 0; i < n; ++i)
    CF::point(X0, i) = scale * Eigen::Vector3d(unit(random), unit(random), unit(random));
  const Bound bound(X0, size);
  const Lines lines = random_lines(bound, X0, size, random);
  const CF::Normal_offset_bound<Bound> segments(bound, lines.S, lines.N);
  std::size_t outside = 0, not_furthest = 0, off_line = 0, not_nearest = 0, wrong_restriction = 0, free_differs = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const Eigen::Vector3d s = CF::point(lines.S, i), d = CF::point(lines.N, i);
    CF::Points X(n, 3);
    X.setZero();
    if(segments.is_free(i))
    {
      // the bound's own projection, bit for bit
      CF::point(X, i) = s + 3 * size * Eigen::Vector3d(1, -2, 0.5);
      CF::Points Y = X;
      segments.project(X, i);
      bound.project(Y, i);
      free_differs += CF::point(X, i) != CF::point(Y, i);
      continue;
    }
    for(double sign : {-1., 1.})
    {
      // far beyond an end: projected to it, inside, and the line leaves the set just after it
      CF::point(X, i) = s + sign * 10 * size * d;
      segments.project(X, i);
      outside += !bound.contains(X, i);
      const double t = (CF::point(X, i) - s).dot(d);
      CF::Points beyond = X;
      CF::point(beyond, i) = s + (t + sign * 1e-6 * size) * d;
      not_furthest += bound.contains(beyond, i);
      off_line += (CF::point(X, i) - s - t * d).norm() > 1e-12 * (scale + size);
      // at the end, pushed outwards: it binds, and the restriction stops it; pushed inwards: it
      // does not bind
      using Segments = CF::Normal_offset_bound<Bound>;
      typename Segments::Face face;
      const bool on_segment = segments.is_on_boundary(X, i, face);
      CHECK(on_segment && face.end == int(sign));
      typename Segments::Face blocked = face, inwards = face;
      wrong_restriction += !Segments::keep_blocked(blocked, -sign * d) || Segments::keep_blocked(inwards, sign * d);
      Eigen::Vector3d v(0.3, -0.2, 0.9);
      Segments::restrict(blocked, Eigen::Map<Eigen::Vector3d>(v.data()));
      wrong_restriction += !v.isZero();
    }
    {
      // inside the segment: on its line, which the restriction keeps
      using Segments = CF::Normal_offset_bound<Bound>;
      CF::point(X, i) = s + 0.01 * size * d;
      typename Segments::Face face;
      const bool on_segment = segments.is_on_boundary(X, i, face);
      CHECK(on_segment && face.end == 0);
      Eigen::Vector3d v(0.3, -0.2, 0.9);
      Segments::restrict(face, Eigen::Map<Eigen::Vector3d>(v.data()));
      wrong_restriction += (v - d.dot(Eigen::Vector3d(0.3, -0.2, 0.9)) * d).norm() > 1e-12;
    }
    // a point off the line, within the segment's reach: its nearest point on the line
    const Eigen::Vector3d across = d.unitOrthogonal();
    CF::point(X, i) = s + 0.01 * size * d + 0.5 * size * across;
    segments.project(X, i);
    outside += !bound.contains(X, i);
    not_nearest += (CF::point(X, i) - (s + 0.01 * size * d)).norm() > 1e-12 * (scale + size);
  }
  CHECK(outside == 0);
  CHECK(not_furthest == 0);
  CHECK(off_line == 0);
  CHECK(not_nearest == 0);
  CHECK(wrong_restriction == 0);
  CHECK(free_differs == 0);
}

// E = sum of w_i |x_i - m_i|^2: over each segment its minimizer is the point of the segment
// nearest to m_i.
class Separable_quadratic
{
public:
  Separable_quadratic(CF::Points M, Eigen::VectorXd w) : m_M(std::move(M)), m_w(std::move(w)) {}

  double value(const CF::Points& X)
  {
    CF::Points G;
    return value_and_gradient(X, G, nullptr);
  }

  double value_and_gradient(const CF::Points& X, CF::Points& G, CF::Stiffness_and_reach* scales)
  {
    const CF::Points D = X - m_M;
    G = 2 * (D.array().colwise() * m_w.array()).matrix();
    if(scales)
    {
      scales->stiffness = 2 * m_w;
      scales->reach = Eigen::VectorXd::Constant(X.rows(), std::numeric_limits<double>::infinity());
    }
    return (D.rowwise().squaredNorm().array() * m_w.array()).sum();
  }

private:
  CF::Points m_M;
  Eigen::VectorXd m_w;
};

template <typename Bound>
void check_known_minimizer()
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1, 1), weight(0.01, 100);
  const std::size_t n = 500;
  const double size = 0.1;
  CF::Points X0(n, 3), M(n, 3);
  Eigen::VectorXd w(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    CF::point(X0, i) = Eigen::Vector3d(unit(random), unit(random), unit(random));
    CF::point(M, i) = CF::point(X0, i) + 2 * size * Eigen::Vector3d(unit(random), unit(random), unit(random));
    w[Eigen::Index(i)] = weight(random);
  }
  const Bound bound(X0, size);
  const Lines lines = random_lines(bound, X0, size, random);
  const CF::Normal_offset_bound<Bound> segments(bound, lines.S, lines.N);
  // the nearest point of each segment to m_i (of the set, for a free vertex)
  CF::Points expected = M;
  for(std::size_t i = 0; i < n; ++i)
    if(!segments.is_free(i))
    {
      const Eigen::Vector3d s = CF::point(lines.S, i), d = CF::point(lines.N, i);
      CF::point(expected, i) = s + (CF::point(M, i) - s).dot(d) * d;
    }
  segments.project(expected);

  Separable_quadratic quadratic(M, w);
  CF::Normal_offset_objective<Separable_quadratic, Bound> offsets(quadratic, segments);
  CF::Projected_lbfgs<CF::Normal_offset_bound<Bound>, CF::Normal_offset_objective<Separable_quadratic, Bound> > solver(
    segments, offsets);
  CF::Points X = lines.S;
  // the paper's methods' window, with no threshold
  CF::Solver_options options = CF::default_options(PMP::Constrained_fairing_method::ACTIVE_SET_NEWTON);
  options.max_iterations = 500;
  options.threshold = 0;
  std::vector<double> energies;
  solver.run(X, options, [&](std::size_t, double e) {
    energies.push_back(e);
    return true;
  });
  double largest_error = 0;
  std::size_t outside = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    largest_error = (std::max)(largest_error, (CF::point(X, i) - CF::point(expected, i)).norm());
    outside += !bound.contains(X, i);
  }
  std::cout << "  separable quadratic over segments: largest distance to the known minimizer " << largest_error
            << " (sizes " << size << ") after " << energies.size() << " iterations" << std::endl;
  CHECK(largest_error <= 1e-6 * size);
  CHECK(outside == 0);
  CHECK(std::is_sorted(energies.rbegin(), energies.rend()));
}

// A plane patch with noise across it only, within a ball twice the noise: the plane is on every
// segment, so the energy must fall to nearly 0, the bound holding in double.
void check_plane_recovered()
{
  test::Mesh m = test::plane_patch(30);
  const double h = test::mean_edge_length(m);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1, 1);
  for(auto v : vertices(m))
  {
    const test::Point p = m.point(v);
    m.point(v) = test::Point(p.x(), p.y(), 0.2 * h * unit(random));
  }
  const std::vector<test::Point> input = test::points(m);
  std::vector<double> energies;
  const auto r = PMP::constrained_fairing(
    m, 0.4 * h,
    CFP::tangential_motion(false, CFP::iteration_callback([&](std::size_t, double e) {
                                    energies.push_back(e);
                                    return true;
                                  },
                                  CFP::energy_decrease_threshold(0., CGAL::parameters::number_of_iterations(400)))));
  std::cout << "  plane patch, noise across it: energy " << r.initial_energy << " -> " << r.final_energy << " in "
            << r.number_of_iterations << " iterations" << std::endl;
  CHECK(r);
  CHECK(r.final_energy <= 1e-4 * r.initial_energy);
  CHECK(test::bound_violation(test::points(m), input, 0.4 * h, PMP::Deviation_bound::BALL) == 0);
  CHECK(std::is_sorted(energies.rbegin(), energies.rend()));
}

// Unset, tangential_motion is false with the ball and true with the box and the accurate
// objective (the documented default): the default call is bit for bit the call that sets it so,
// and differs from the other.
void check_default()
{
  test::Mesh m = test::icosphere(3);
  const double h = test::mean_edge_length(m);
  test::add_noise(m, 0.25 * h, 3);
  const auto run = [&](const auto& np) {
    test::Mesh copy = m;
    CHECK(PMP::constrained_fairing(copy, 0.25 * h, np));
    return test::points(copy);
  };
  const auto ball = CFP::deviation_bound(PMP::Deviation_bound::BALL);
  const auto box = CFP::deviation_bound(PMP::Deviation_bound::BOX);
  CHECK(test::identical(run(ball), run(CFP::tangential_motion(false, ball))));
  CHECK(!test::identical(run(ball), run(CFP::tangential_motion(true, ball))));
  CHECK(test::identical(run(box), run(CFP::tangential_motion(true, box))));
  CHECK(!test::identical(run(box), run(CFP::tangential_motion(false, box))));
  const auto accurate = CFP::fairing_objective(PMP::Constrained_fairing_objective::ACCURATE);
  CHECK(test::identical(run(accurate), run(CFP::tangential_motion(true, accurate))));
  CHECK(!test::identical(run(accurate), run(CFP::tangential_motion(false, accurate))));
}

// The honest stop: where the default call stops, having judged the surface's motion (Surface_motion.h),
// three times as many iterations with the stopping rule off move its points by at most 1 % of
// epsilon (RMS: along the normals, each point's displacement is the surface's motion there).
void check_honest_stop()
{
  test::Mesh m = test::icosphere(4);
  const double h = test::mean_edge_length(m), eps = 0.25 * h;
  test::add_noise(m, eps, 5);
  test::Mesh long_run = m;
  const auto r = PMP::constrained_fairing(m, eps);
  CHECK(r.status == PMP::Constrained_fairing_status::CONVERGED);
  const auto r_long = PMP::constrained_fairing(
    long_run, eps, CFP::energy_decrease_threshold(0., CGAL::parameters::number_of_iterations(3 * r.number_of_iterations)));
  CHECK(r_long.number_of_iterations > r.number_of_iterations);
  const std::vector<test::Point> a = test::points(m), b = test::points(long_run);
  double squares = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
    squares += CGAL::squared_distance(a[i], b[i]);
  const double moved = std::sqrt(squares / double(a.size())) / eps;
  std::cout << "  honest stop: " << r.number_of_iterations << " iterations; " << r_long.number_of_iterations
            << " move the points by " << 100 * moved << " % of epsilon (RMS), the energy by "
            << 100 * (r.final_energy - r_long.final_energy) / r.final_energy << " %" << std::endl;
  CHECK(moved <= 0.01);
  CHECK(r.final_energy - r_long.final_energy <= 0.03 * r.final_energy);
}

int main()
{
  check_honest_stop();
  for(double scale : {1e-3, 1., 1e6})
    for(double size : {1e-6 * scale, 0.1 * scale, 10 * scale})
    {
      check_segments<CF::Ball_bound>(scale, size);
      check_segments<CF::Box_bound>(scale, size);
    }
  check_known_minimizer<CF::Ball_bound>();
  check_known_minimizer<CF::Box_bound>();
  check_plane_recovered();
  check_default();
  return test::report("test_normal_offsets");
}
