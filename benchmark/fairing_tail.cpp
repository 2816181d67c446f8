// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the default solver's slow tail does to the surface:
//
//   fairing_tail [MESH] [--level L] [--from A] [--to B]
//
// MESH (default: the bundled bunny) is Loop subdivided L times (default 1) and given seeded
// noise of 0.25 h, epsilon = 0.25 h, as in fairing_scaling. The default method, its vertices
// free to slide (tangential_motion(true), the default before the normal offsets), runs A
// (default 50) and B (default 300) iterations with no stopping rule, from the same start, so
// that the first A iterations of both runs are the same. Reports the energies, and how the
// vertices moved from iteration A to B: the RMS and the percentiles of the motion along the
// vertex normal (area-weighted, at B) and across it, in units of h. A tail that moves the
// vertices mostly across the normal slides them along the surface: it lowers the energy by
// reshaping triangles, not by changing the surface.

#include "benchmark_support.h"

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using benchmark::Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using Vector = benchmark::K::Vector_3;

int main(int argc, char* argv[])
{
  std::cout << benchmark::machine_description() << std::endl; // the CPU and threads of every figure below
  const benchmark::Arguments arguments(argc, argv);
  Mesh base;
  std::string name;
  if(!benchmark::read_base_mesh(arguments, base, name))
    return EXIT_FAILURE;
  const auto level = static_cast<unsigned int>(std::stoul(arguments.option("level", "1")));
  const auto from = static_cast<unsigned int>(std::stoul(arguments.option("from", "50")));
  const auto to = static_cast<unsigned int>(std::stoul(arguments.option("to", "300")));
  Mesh noisy;
  const double h = benchmark::make_noisy_case(base, level, noisy);

  Mesh A = noisy, B = noisy;
  const auto run = [&](Mesh& m, unsigned int iterations) {
    return PMP::constrained_fairing(
      m, 0.25 * h,
      CFP::tangential_motion(true, CFP::energy_decrease_threshold(0.0, CGAL::parameters::number_of_iterations(iterations))));
  };
  const auto ra = run(A, from);
  const auto rb = run(B, to);

  auto normal = B.add_property_map<Mesh::Vertex_index, Vector>("v:tail_normal").first;
  PMP::compute_vertex_normals(B, normal);
  std::vector<double> along, across;
  for(auto v : vertices(B))
  {
    const Vector d = B.point(v) - A.point(v);
    const double n = d * normal[v];
    along.push_back(std::abs(n) / h);
    across.push_back(std::sqrt((std::max)(0., d.squared_length() - n * n)) / h);
  }
  const auto rms = [](const std::vector<double>& x) {
    double s = 0;
    for(double a : x)
      s += a * a;
    return std::sqrt(s / double(x.size()));
  };
  const auto percentile = [](std::vector<double> x, double p) {
    std::sort(x.begin(), x.end());
    return x[static_cast<std::size_t>(p * double(x.size() - 1))];
  };
  std::cout << name << " Loop subdivided " << level << " times: " << num_faces(noisy)
            << " triangles; noise and epsilon 0.25 h = " << 0.25 * h << "\n"
            << "energy after " << from << " iterations " << ra.final_energy << ", after " << to << " iterations "
            << rb.final_energy << "\n"
            << "motion from iteration " << from << " to " << to << ", in h (RMS / median / 99th percentile):\n"
            << "  along the normal   " << rms(along) << " / " << percentile(along, 0.5) << " / " << percentile(along, 0.99)
            << "\n"
            << "  across the normal  " << rms(across) << " / " << percentile(across, 0.5) << " / "
            << percentile(across, 0.99) << std::endl;
  return EXIT_SUCCESS;
}
