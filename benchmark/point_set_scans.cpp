// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Real scans faired as the tool fairs them: each file read as the tool reads it (its normals
// used where it has them), epsilon its estimated noise (--eps auto), each objective. Prints per
// scan and objective the points, epsilon over the points' mean spacing, the points out of the
// bound in double (0 expected), the isolated points, the iterations, the bending energy before
// and after, and the median time of --runs calls.
//
//   point_set_scans [SCAN...] [--runs R] [--threads K]
//
// Without scans: CGAL's demo scans of data/points_3 (benchmark/get_demo_meshes.sh).

#include "benchmark_support.h"

#include "front_end/Point_set_file.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_points.h>
#include <CGAL/Polygon_mesh_processing/estimate_noise_level_of_points.h>

#include <CGAL/compute_average_spacing.h>

#include <cstddef>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using namespace benchmark;
using Item = std::pair<Point, K::Vector_3>;
using Point_map = CGAL::First_of_pair_property_map<Item>;
using Normal_map = CGAL::Second_of_pair_property_map<Item>;

namespace {

struct Scan
{
  std::string name;
  std::vector<Item> points;
  bool has_normals = false;
};

void fair_scan(const Scan& scan, double eps, PMP::Constrained_fairing_objective objective, int runs)
{
  std::vector<Item> points;
  PMP::Constrained_fairing_result result;
  const double seconds = median_seconds(runs, [&] {
    points = scan.points;
    const auto maps = CFP::fairing_objective(objective, CGAL::parameters::point_map(Point_map()));
    result = scan.has_normals ? PMP::constrained_fairing_of_points(points, eps, maps.normal_map(Normal_map()))
                              : PMP::constrained_fairing_of_points(points, eps, maps);
  });
  std::size_t out = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
    out += !(CGAL::squared_distance(points[i].first, scan.points[i].first) <= eps * eps);
  std::cout << "  " << (objective == PMP::Constrained_fairing_objective::ACCURATE ? "accurate" : "fairest ") << ": "
            << (result ? "" : "FAILED (" + result.message + "), ") << out << " out of the bound, "
            << result.number_of_isolated_points << " isolated, " << result.number_of_iterations << " iterations, bending "
            << result.initial_bending_energy << " -> " << result.final_bending_energy << ", " << seconds << " s"
            << std::endl;
}

} // namespace

int main(int argc, char* argv[])
{
  const Arguments arguments(argc, argv);
  const Thread_limit thread_limit(arguments);
  std::vector<std::string> paths = arguments.positional;
  if(paths.empty())
    for(const char* name : {"kitten.xyz", "oni.pwn", "hippo1.ply", "building.ply"})
      paths.push_back(CONSTRAINED_FAIRING_DEMO_DATA "/../points_3/" + std::string(name));
  std::cout << machine_description() << ", median of " << arguments.runs << " runs\n";
  for(const std::string& path : paths)
  {
    Constrained_fairing_front_end::Point_set_contents<Point, K::Vector_3> contents;
    const std::string error = Constrained_fairing_front_end::read_point_set_file(path, contents);
    if(!error.empty())
    {
      std::cout << "skipped: " << error << std::endl;
      continue;
    }
    const Scan scan{path.substr(path.find_last_of('/') + 1), std::move(contents.points), contents.has_normals};
    const auto maps = CGAL::parameters::point_map(Point_map());
    const double eps = PMP::estimate_noise_level_of_points(scan.points, maps);
    const double spacing = CGAL::compute_average_spacing<CGAL::Sequential_tag>(scan.points, 6, maps);
    std::cout << scan.name << ": " << scan.points.size() << " points" << (scan.has_normals ? " with normals" : "")
              << ", eps (estimated) " << eps << " = " << eps / spacing << " x the mean spacing" << std::endl;
    for(const auto objective : {PMP::Constrained_fairing_objective::FAIREST, PMP::Constrained_fairing_objective::ACCURATE})
      fair_scan(scan, eps, objective, arguments.runs);
  }
  return 0;
}
