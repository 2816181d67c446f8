// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// constrained_fairing_of_points() on a noisy sphere sampled at random: every point within the
// bound in double exactly (ball and box), in its order; the energy not higher than at the
// input and the points closer to the sphere, with either objective; the normals written where
// the map is writable, unit and outward as given; an outlier kept where it is and counted;
// the estimated normals those of CGAL's jet fit, oriented alike on each of two spheres; the
// result the same with one thread and with four; and each defect rejected with its message, the
// points and normals left bit-identical.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Point_sets/Point_normals.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/property_map.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <cmath>
#include <cstring>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Point_with_normal = std::pair<Point, Vector>;
using Point_map = CGAL::First_of_pair_property_map<Point_with_normal>;
using Normal_map = CGAL::Second_of_pair_property_map<Point_with_normal>;

const double sigma = 0.01;
const double eps = 3 * sigma;

// n points on the unit sphere, uniform by area, moved by Gaussian noise of `sigma`, with the
// sphere's normals.
std::vector<Point_with_normal> noisy_sphere(std::size_t n, unsigned seed)
{
  std::mt19937 random(seed);
  std::normal_distribution<double> normal(0, 1);
  std::vector<Point_with_normal> points;
  for(std::size_t i = 0; i < n; ++i)
  {
    Vector d(normal(random), normal(random), normal(random));
    d = d / std::sqrt(d.squared_length());
    const Vector noise(normal(random), normal(random), normal(random));
    points.emplace_back(CGAL::ORIGIN + d + sigma * noise, d);
  }
  return points;
}

std::vector<Point> positions(const std::vector<Point_with_normal>& points)
{
  std::vector<Point> p;
  for(const auto& q : points)
    p.push_back(q.first);
  return p;
}

double rms_to_sphere(const std::vector<Point>& points)
{
  double sum = 0;
  for(const Point& p : points)
    sum += CGAL::square(std::sqrt((p - CGAL::ORIGIN).squared_length()) - 1);
  return std::sqrt(sum / double(points.size()));
}

// Bit for bit, NaN included.
bool identical(const std::vector<Point_with_normal>& a, const std::vector<Point_with_normal>& b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    for(int c = 0; c < 3; ++c)
      if(std::memcmp(&a[i].first[c], &b[i].first[c], sizeof(double)) != 0 ||
         std::memcmp(&a[i].second[c], &b[i].second[c], sizeof(double)) != 0)
        return false;
  return true;
}

template <typename NamedParameters>
PMP::Constrained_fairing_result fair(std::vector<Point_with_normal>& points, double epsilon, const NamedParameters& np)
{
  return PMP::constrained_fairing_of_points(points, epsilon, np.point_map(Point_map()));
}

void check_fairing(PMP::Constrained_fairing_objective objective, const char* name)
{
  const std::vector<Point_with_normal> input = noisy_sphere(4000, 1);
  std::vector<Point_with_normal> points = input;
  const auto result = fair(points, eps, CFP::fairing_objective(objective, CGAL::parameters::normal_map(Normal_map())));
  const double before = rms_to_sphere(positions(input)), after = rms_to_sphere(positions(points));
  std::cout << "  " << name << ": " << result.number_of_iterations << " iterations, energy " << result.initial_energy
            << " -> " << result.final_energy << ", distance to the sphere " << before / sigma << " -> " << after / sigma
            << " sigma" << std::endl;
  CHECK(result && result.final_energy <= result.initial_energy);
  CHECK(result.final_bending_energy < 0.01 * result.initial_bending_energy);
  CHECK(test::bound_violation(positions(points), positions(input), eps, PMP::Deviation_bound::BALL) <= 0);
  CHECK(after < 0.6 * before);
  // the normals written: unit, outward as the given ones
  std::size_t outward = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    CHECK(std::abs(points[i].second.squared_length() - 1) < 1e-12);
    outward += points[i].second * input[i].second > 0.9;
  }
  CHECK(outward == points.size());
}

// Without normals: estimated, then oriented; a far point is isolated and stays.
void check_estimated_normals_and_outlier()
{
  std::vector<Point> input = positions(noisy_sphere(3000, 2));
  input.push_back(Point(0, 0, 5));
  std::vector<Point> points = input;
  const auto result = PMP::constrained_fairing_of_points(points, eps);
  std::cout << "  estimated normals: distance " << rms_to_sphere({input.begin(), input.end() - 1}) / sigma << " -> "
            << rms_to_sphere({points.begin(), points.end() - 1}) / sigma << " sigma, "
            << result.number_of_isolated_points << " isolated" << std::endl;
  CHECK(result && result.number_of_isolated_points == 1 && points.back() == input.back());
  CHECK(result.number_of_fixed_vertices >= 1);
  CHECK(rms_to_sphere({points.begin(), points.end() - 1}) < 0.6 * rms_to_sphere({input.begin(), input.end() - 1}));
  CHECK(test::bound_violation(points, input, eps, PMP::Deviation_bound::BALL) <= 0);
}

// The normals estimated without CGAL's own search and graph: along CGAL's jet fit over the same
// k nearest (the point among them), and oriented alike over each component: outward on two
// noisy spheres apart (each tree starts at its highest point, pointed up).
void check_estimated_normals_as_cgal()
{
  namespace CF = PMP::internal::Constrained_fairing;
  std::vector<Point_with_normal> points = noisy_sphere(3000, 5), second = noisy_sphere(2000, 6);
  for(const auto& [p, n] : second)
    points.emplace_back(p + Vector(5, 0, 0), n);
  CF::Points X(Eigen::Index(points.size()), 3);
  for(std::size_t i = 0; i < points.size(); ++i)
    X.row(Eigen::Index(i)) << points[i].first.x(), points[i].first.y(), points[i].first.z();
  const std::size_t k = 24;
  const CF::Points N = CF::estimated_normals(X, CF::Point_neighbours(X, k));
  std::vector<Point_with_normal> cgal = points;
  CGAL::jet_estimate_normals<CGAL::Sequential_tag>(cgal, unsigned(k), CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));
  std::size_t along = 0, outward = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const Vector n(N(Eigen::Index(i), 0), N(Eigen::Index(i), 1), N(Eigen::Index(i), 2));
    CHECK(std::abs(n.squared_length() - 1) < 1e-12);
    along += std::abs(n * cgal[i].second) > 1 - 1e-9;
    outward += n * points[i].second > 0.5;
  }
  std::cout << "  estimated normals: " << along << " of " << points.size() << " along CGAL's jet fit, " << outward
            << " outward" << std::endl;
  CHECK(along == points.size());
  CHECK(outward == points.size());
}

void check_box()
{
  const std::vector<Point_with_normal> input = noisy_sphere(3000, 3);
  std::vector<Point_with_normal> points = input;
  const auto result = fair(points, eps, CFP::deviation_bound(PMP::Deviation_bound::BOX));
  std::cout << "  box: distance to the sphere " << rms_to_sphere(positions(input)) / sigma << " -> "
            << rms_to_sphere(positions(points)) / sigma << " sigma, energy " << result.initial_energy << " -> "
            << result.final_energy << " in " << result.number_of_iterations << " iterations, " << result.message << std::endl;
  CHECK(result && result.final_energy <= result.initial_energy);
  CHECK(test::bound_violation(positions(points), positions(input), eps, PMP::Deviation_bound::BOX) <= 0);
  CHECK(rms_to_sphere(positions(points)) < 0.7 * rms_to_sphere(positions(input)));
}

void check_thread_count_independence()
{
#ifdef CGAL_LINKED_WITH_TBB
  const std::vector<Point_with_normal> input = noisy_sphere(20000, 4);
  std::vector<Point_with_normal> one = input, four = input;
  const auto call = [](std::vector<Point_with_normal>& p) {
    return fair(p, eps, CGAL::parameters::number_of_iterations(30));
  };
  PMP::Constrained_fairing_result r_one, r_four;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    r_one = call(one);
  }
  int threads = 0;
  {
    tbb::global_control several(tbb::global_control::max_allowed_parallelism, 4);
    tbb::task_arena arena(4);
    arena.execute([&] {
      threads = tbb::this_task_arena::max_concurrency();
      r_four = call(four);
    });
  }
  if(threads < 2)
  {
    std::cout << "  SKIPPED: thread-count independence, TBB gave " << threads << " thread" << std::endl;
    return;
  }
  CHECK(r_one && r_four && r_one.final_energy == r_four.final_energy);
  CHECK(identical(one, four));
#else
  std::cout << "  SKIPPED: thread-count independence, no TBB" << std::endl;
#endif
}

// Each defect: its code, its message, and the points and normals bit-identical.
template <typename NamedParameters>
void check_rejected(std::vector<Point_with_normal> points, const NamedParameters& np, PMP::Constrained_fairing_defect defect,
                    const std::string& message)
{
  const std::vector<Point_with_normal> before = points;
  const auto result = fair(points, eps, np.normal_map(Normal_map()));
  std::cout << "  rejected: " << result.message << std::endl;
  CHECK(!result && result.defect == defect && result.message == message);
  CHECK(identical(points, before));
}

void check_defects()
{
  using D = PMP::Constrained_fairing_defect;
  const std::vector<Point_with_normal> sphere = noisy_sphere(200, 5);
  const auto none = CGAL::parameters::default_values();
  check_rejected(sphere, CFP::number_of_neighbors(2), D::INVALID_NUMBER_OF_NEIGHBORS,
                 "number_of_neighbors is 2, it must be at least 3");
  std::vector<Point_with_normal> nan = sphere;
  nan[7].first = Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  check_rejected(nan, none, D::NON_FINITE_COORDINATE, "vertex 7 has a NaN or infinite coordinate");
  std::vector<Point_with_normal> flat_normal = sphere;
  flat_normal[9].second = Vector(0, 0, 0);
  check_rejected(flat_normal, none, D::INVALID_NORMAL, "the normal of point 9 is zero, NaN or infinite");
  check_rejected(std::vector<Point_with_normal>(sphere.begin(), sphere.begin() + 32), none, D::TOO_FEW_POINTS,
                 "the point set has 32 points, not more than its 32 neighbours (number_of_neighbors)");
  std::vector<Point_with_normal> twice = sphere;
  twice[150].first = twice[20].first;
  check_rejected(twice, none, D::DUPLICATE_POINTS, "points 20 and 150 coincide");
  std::vector<Point_with_normal> line;
  for(int i = 0; i < 50; ++i)
    line.emplace_back(Point(0.1 * i, 0.2 * i, 0), Vector(0, 0, 1));
  check_rejected(line, none, D::NO_SURFACE,
                 "no point has neighbours around it in its tangent plane: the points are on one line");
  check_rejected(sphere, CFP::fairing_method(PMP::Constrained_fairing_method::ACTIVE_SET_NEWTON), D::METHOD_NEEDS_MESH,
                 "the paper's methods need a mesh's hinges; a point set is faired by QUASI_NEWTON (the default)");
}

int main()
{
  check_fairing(PMP::Constrained_fairing_objective::FAIREST, "fairest");
  check_fairing(PMP::Constrained_fairing_objective::ACCURATE, "accurate");
  check_estimated_normals_and_outlier();
  check_estimated_normals_as_cgal();
  check_box();
  check_thread_count_independence();
  check_defects();
  return test::report("test_point_set_fairing");
}
