// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the benchmark programs share: the mesh type, seeded noise, the mean edge length and
// median timing.

#ifndef CGAL_CONSTRAINED_FAIRING_BENCHMARK_SUPPORT_H
#define CGAL_CONSTRAINED_FAIRING_BENCHMARK_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <string>
#include <vector>

namespace benchmark {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

inline double mean_edge_length(const Mesh& mesh)
{
  double sum = 0;
  for(auto e : edges(mesh))
    sum += CGAL::Polygon_mesh_processing::edge_length(e, mesh);
  return sum / double(num_edges(mesh));
}

// Moves every vertex uniformly at random inside a ball of the given radius.
inline void add_noise(Mesh& mesh, double radius, unsigned int seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  for(auto v : vertices(mesh))
  {
    K::Vector_3 d;
    do
      d = K::Vector_3(u(rng), u(rng), u(rng));
    while(d.squared_length() > 1);
    mesh.point(v) = mesh.point(v) + radius * d;
  }
}

// The median wall-clock time of `runs` calls of f.
template <typename F>
double median_seconds(int runs, F&& f)
{
  std::vector<double> t;
  for(int r = 0; r < runs; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

// The command line: positional arguments, and `--runs N` (default 3) for median timing.
struct Arguments
{
  std::vector<std::string> positional;
  int runs = 3;

  Arguments(int argc, char* argv[])
  {
    for(int i = 1; i < argc; ++i)
    {
      if(std::string(argv[i]) == "--runs" && i + 1 < argc)
        runs = std::stoi(argv[++i]);
      else
        positional.push_back(argv[i]);
    }
  }
};

} // namespace benchmark

#endif // CGAL_CONSTRAINED_FAIRING_BENCHMARK_SUPPORT_H
