// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The time and memory of constrained_fairing_of_points() on a large point set, against CGAL's
// jet_smooth_point_set() with 24 neighbours in the same process: N points sampled area-uniformly
// on a mesh (the bundled bunny by default), Gaussian noise of sigma = 1 % of the bounding
// sphere's radius, eps = 3 sigma. Prints the CPU model and the threads; the median time of
// `--runs` calls of each, the ratios to jet's, the peak memory a call adds to the process (its
// input held) per point, the bound checked in double, and whether one thread gives the same
// points as all.
//
//   point_set_scaling [MESH] [--points N] [--runs R] [--threads K]

#include "benchmark_support.h"
#include "point_samples.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_points.h>

#include <CGAL/jet_smooth_point_set.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <cstddef>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using namespace benchmark;

namespace {

struct Call
{
  std::vector<Point> points;
  PMP::Constrained_fairing_result result;
  double added_bytes = 0; // the peak above what the process held before the call
};

Call fair(const std::vector<Point>& noisy, double eps, PMP::Constrained_fairing_objective objective)
{
  Call call;
  call.points = noisy;
  const double before = resident_memory_bytes();
  reset_peak_memory();
  call.result = PMP::constrained_fairing_of_points(call.points, eps, CFP::fairing_objective(objective));
  call.added_bytes = peak_memory_bytes() - before;
  return call;
}

// The points farther than eps from their input, in double.
std::size_t out_of_bound(const std::vector<Point>& points, const std::vector<Point>& input, double eps)
{
  std::size_t count = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
    count += !(CGAL::squared_distance(points[i], input[i]) <= eps * eps);
  return count;
}

// The same call on one thread: whether it gives the same points, bit for bit.
bool same_on_one_thread(const std::vector<Point>& noisy, double eps, PMP::Constrained_fairing_objective objective,
                        const std::vector<Point>& expected)
{
#ifdef CGAL_LINKED_WITH_TBB
  const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
#endif
  return fair(noisy, eps, objective).points == expected;
}

void report(const std::string& name, const std::vector<Point>& noisy, double eps,
            PMP::Constrained_fairing_objective objective, int runs, double jet_seconds)
{
  const Call first = fair(noisy, eps, objective);
  const double seconds = median_seconds(runs, [&] { fair(noisy, eps, objective); });
  const double n = double(noisy.size());
  std::cout << name << ": " << seconds << " s (" << seconds / jet_seconds << " x jet's), "
            << first.result.number_of_iterations << " iterations, " << first.added_bytes / n
            << " bytes per point above the input, " << out_of_bound(first.points, noisy, eps)
            << " points out of the bound, " << first.result.number_of_isolated_points << " isolated; one thread "
            << (same_on_one_thread(noisy, eps, objective, first.points) ? "gives the same points" : "DIFFERS")
            << std::endl;
}

} // namespace

int main(int argc, char* argv[])
{
  const Arguments arguments(argc, argv);
  const Thread_limit thread_limit(arguments);
  Noisy_sample sample_set;
  if(!read_noisy_sample(arguments, "1000000", sample_set))
    return 1;
  const std::vector<Point>& noisy = sample_set.noisy;
  const double eps = 3 * sample_set.sigma;
  std::cout << machine_description() << "\n" << noisy.size() << " points on " << sample_set.name << ", sigma = 1 % of the radius, eps = 3 sigma, median of "
            << arguments.runs << " runs\n";

  const double jet_seconds = median_seconds(arguments.runs, [&] {
    std::vector<Point> points = noisy;
    CGAL::jet_smooth_point_set<CGAL::Parallel_if_available_tag>(points, 24);
  });
  std::cout << "jet_smooth_point_set, k = 24: " << jet_seconds << " s" << std::endl;
  report("fairest (the default)", noisy, eps, PMP::Constrained_fairing_objective::FAIREST, arguments.runs, jet_seconds);
  report("accurate", noisy, eps, PMP::Constrained_fairing_objective::ACCURATE, arguments.runs, jet_seconds);
  return 0;
}
