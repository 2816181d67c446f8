// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How close to the truth constrained_fairing_of_points() gets against the iterations it is
// allowed, on a large point set: N points sampled area-uniformly on a mesh (the bundled bunny by
// default), Gaussian noise of sigma = 1 % of the bounding sphere's radius, eps = 3 sigma. For
// each objective and each limit of `number_of_iterations`: the iterations run, the RMS distance
// from the points to the clean mesh over sigma, the final energy and the time of the call; and
// CGAL's jet_smooth_point_set() with 24 neighbours, clamped into the same balls, as the
// reference. Prints the CPU model and the threads. Why: the default stopping rule runs the
// point sets' descent to its limit of 1,000 iterations at 200,000 points and more, and whether
// those iterations bring the points closer to the truth decides what a faster descent or an
// earlier stop may give up.
//
//   point_set_iterations [MESH] [--points N] [--threads K]

#include "benchmark_support.h"
#include "point_samples.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_points.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/jet_smooth_point_set.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using namespace benchmark;

namespace {

using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> >;

// The RMS distance from the points to the clean mesh.
double rms_distance(const Tree& clean, const std::vector<Point>& points)
{
  double sum = 0;
  for(const Point& p : points)
    sum += clean.squared_distance(p);
  return std::sqrt(sum / double(points.size()));
}

void sweep(const Tree& clean, const std::vector<Point>& noisy, double sigma, PMP::Constrained_fairing_objective objective,
           const std::string& name)
{
  for(unsigned limit : {25u, 50u, 100u, 200u, 400u, 1000u})
  {
    std::vector<Point> points = noisy;
    const auto start = std::chrono::steady_clock::now();
    const PMP::Constrained_fairing_result result = PMP::constrained_fairing_of_points(
      points, 3 * sigma, CFP::fairing_objective(objective).number_of_iterations(limit));
    const double seconds = seconds_since(start);
    std::cout << name << ", at most " << limit << " iterations: " << result.number_of_iterations
              << " run, distance to the truth " << rms_distance(clean, points) / sigma << " sigma, energy "
              << result.final_energy << ", " << seconds << " s" << std::endl;
  }
}

} // namespace

int main(int argc, char* argv[])
{
  const Arguments arguments(argc, argv);
  const Thread_limit thread_limit(arguments);
  Noisy_sample sample_set;
  if(!read_noisy_sample(arguments, "200000", sample_set))
    return 1;
  const std::vector<Point>& noisy = sample_set.noisy;
  const double sigma = sample_set.sigma;
  const Mesh& mesh = sample_set.mesh;
  Tree clean(faces(mesh).first, faces(mesh).second, mesh);
  clean.accelerate_distance_queries();
  std::cout << machine_description() << "\n" << noisy.size() << " points on " << sample_set.name
            << ", sigma = 1 % of the radius, eps = 3 sigma; distances to the clean mesh, RMS\n"
            << "noisy input: " << rms_distance(clean, noisy) / sigma << " sigma" << std::endl;

  std::vector<Point> jet = noisy;
  CGAL::jet_smooth_point_set<CGAL::Parallel_if_available_tag>(jet, 24);
  clamp(jet, noisy, 3 * sigma);
  std::cout << "jet_smooth_point_set, k = 24, clamped: " << rms_distance(clean, jet) / sigma << " sigma" << std::endl;
  sweep(clean, noisy, sigma, PMP::Constrained_fairing_objective::FAIREST, "fairest (the default)");
  sweep(clean, noisy, sigma, PMP::Constrained_fairing_objective::ACCURATE, "accurate");
  return 0;
}
