// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What per-vertex bounds cost against the scalar ball, in one process:
//
//   fairing_bounds [MESH] [--level 1] [--iterations 200] [--runs N]
//
// MESH (default: the bundled bunny) Loop subdivided `level` times (1: 301,632 triangles) with
// seeded noise of 0.25 h, epsilon = 0.25 h. Each variant runs exactly `iterations` iterations
// (no stopping rule), median of N runs; the figure compared is the time per energy
// evaluation (the solver's unit of work, since different bounds take different paths), and
// for the variant that states the scalar ball's problem through a map also the total time.
// Variants: the scalar ball; a vertex_tolerance_map of epsilon everywhere (the same problem);
// a vertex_tolerance_map from 0.5 to 1 epsilon; the scalar box; a box per vertex with its own
// centre and half-extents (vertex_box_center_map, vertex_box_half_extents_map); and 10 % of
// the vertices fixed (vertex_is_constrained_map).

#include "benchmark_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>

#include <array>
#include <iomanip>
#include <iostream>
#include <random>
#include <string>

using benchmark::Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;

int main(int argc, char* argv[])
{
  std::cout << benchmark::machine_description() << std::endl; // the CPU and threads of every figure below
  const benchmark::Arguments arguments(argc, argv);
  Mesh base, noisy;
  std::string name;
  if(!benchmark::read_base_mesh(arguments, base, name))
    return EXIT_FAILURE;
  const unsigned int level = unsigned(std::stoi(arguments.option("level", "1")));
  const unsigned int iterations = unsigned(std::stoi(arguments.option("iterations", "200")));
  const double eps = 0.25 * benchmark::make_noisy_case(base, level, noisy);
  std::cout << name << " Loop subdivided " << level << " times: " << num_faces(noisy) << " triangles; epsilon = 0.25 h = "
            << eps << "; " << iterations << " iterations each, medians of " << arguments.runs << " runs" << std::endl;

  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  auto same = noisy.add_property_map<vertex_descriptor, double>("v:same", eps).first;
  auto varying = noisy.add_property_map<vertex_descriptor, double>("v:varying").first;
  auto centre = noisy.add_property_map<vertex_descriptor, Mesh::Point>("v:centre").first;
  auto extents = noisy.add_property_map<vertex_descriptor, std::array<double, 3> >("v:extents").first;
  auto fixed = noisy.add_property_map<vertex_descriptor, bool>("v:fixed").first;
  for(auto v : vertices(noisy))
  {
    put(varying, v, eps * (0.5 + 0.5 * u(rng)));
    // a box of half-extents (eps, eps, 2 eps) whose centre is off the vertex by up to half of them
    const std::array<double, 3> h{eps, eps, 2 * eps};
    const Mesh::Point p = noisy.point(v);
    put(centre, v, Mesh::Point(p.x() + h[0] * (u(rng) - 0.5), p.y() + h[1] * (u(rng) - 0.5), p.z() + h[2] * (u(rng) - 0.5)));
    put(extents, v, h);
    put(fixed, v, u(rng) < 0.1);
  }

  struct Figures
  {
    double seconds = 0, per_evaluation = 0, energy = 0;
  };
  const auto measure = [&](const auto& np) {
    Figures f;
    f.per_evaluation = benchmark::median_of(arguments.runs, [&]() {
      Mesh m = noisy;
      const auto start = std::chrono::steady_clock::now();
      const auto result = PMP::constrained_fairing(m, 4 * eps, np);
      const double s = benchmark::seconds_since(start);
      if(!result)
        std::cerr << "error: " << result.message << std::endl;
      f.seconds = s;
      f.energy = result.final_energy;
      return s / double(result.number_of_energy_evaluations);
    });
    return f;
  };
  const auto fixed_count = [&](const auto& np) {
    return CFP::energy_decrease_threshold(0.0, np.number_of_iterations(iterations));
  };
  // The scalar ball is the reference; epsilon passed to the call is 4 eps and the maps (or the
  // ball's own tolerance map) say eps, so that every variant goes through the same path.
  const Figures ball = measure(fixed_count(CFP::vertex_tolerance_map(same)));
  Figures scalar;
  {
    scalar.per_evaluation = benchmark::median_of(arguments.runs, [&]() {
      Mesh m = noisy;
      const auto start = std::chrono::steady_clock::now();
      const auto result = PMP::constrained_fairing(m, eps, CFP::energy_decrease_threshold(0.0, CGAL::parameters::number_of_iterations(iterations)));
      scalar.seconds = benchmark::seconds_since(start);
      scalar.energy = result.final_energy;
      return scalar.seconds / double(result.number_of_energy_evaluations);
    });
  }
  const Figures rows[] = {
    scalar,
    ball,
    measure(fixed_count(CFP::vertex_tolerance_map(varying))),
    measure(fixed_count(CFP::box_half_extents(std::array<double, 3>{eps, eps, eps}))),
    measure(fixed_count(CFP::vertex_box_center_map(centre, CFP::vertex_box_half_extents_map(extents)))),
    measure(fixed_count(CFP::vertex_tolerance_map(same, CGAL::parameters::vertex_is_constrained_map(fixed)))),
  };
  const char* names[] = {"scalar ball", "tolerance map = epsilon", "tolerance map 0.5-1 epsilon", "scalar box",
                         "box per vertex, own centre", "ball, 10 % fixed"};
  std::cout << std::left << std::setw(30) << "variant" << std::right << std::setw(10) << "seconds" << std::setw(14)
            << "s/evaluation" << std::setw(10) << "ratio" << std::setw(12) << "energy" << std::endl;
  for(int k = 0; k < 6; ++k)
    std::cout << std::left << std::setw(30) << names[k] << std::right << std::fixed << std::setprecision(3) << std::setw(10)
              << rows[k].seconds << std::setprecision(5) << std::setw(14) << rows[k].per_evaluation << std::setprecision(3)
              << std::setw(10) << rows[k].per_evaluation / scalar.per_evaluation << std::setw(12) << rows[k].energy
              << std::endl;
  std::cout << "same problem through a tolerance map: total time ratio " << ball.seconds / scalar.seconds
            << ", energies " << (ball.energy == scalar.energy ? "identical" : "differ") << std::endl;
  return EXIT_SUCCESS;
}
