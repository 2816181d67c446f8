// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the benchmark programs share: the mesh type, seeded noise, the mean edge length, angles,
// the CHOLMOD solver type, median timing and the machine the figures come from.

#ifndef CGAL_CONSTRAINED_FAIRING_BENCHMARK_SUPPORT_H
#define CGAL_CONSTRAINED_FAIRING_BENCHMARK_SUPPORT_H

#include "../test/seeded_noise.h"

#include "front_end/Mean_edge_length.h"

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#ifdef CGAL_CONSTRAINED_FAIRING_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace benchmark {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

using Constrained_fairing_front_end::mean_edge_length;
using test::add_noise;

#ifdef CGAL_CONSTRAINED_FAIRING_HAS_CHOLMOD
// The paper's Newton method with CHOLMOD's supernodal Cholesky factorization.
using Cholmod_solver =
  CGAL::Eigen_solver_traits<Eigen::CholmodSupernodalLLT<CGAL::Eigen_sparse_matrix<double>::EigenType> >;
#endif

inline double angle_deg(const K::Vector_3& a, const K::Vector_3& b)
{
  const double c = a * b / std::sqrt(a.squared_length() * b.squared_length());
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180 / CGAL_PI;
}

// The smallest angle of the triangles of `m`, in degrees.
inline double smallest_angle_deg(const Mesh& m)
{
  double smallest = 180;
  for(auto f : faces(m))
  {
    const auto h = halfedge(f, m);
    const Point a = m.point(source(h, m)), b = m.point(target(h, m)), c = m.point(target(next(h, m), m));
    smallest = (std::min)({smallest, angle_deg(b - a, c - a), angle_deg(a - b, c - b), angle_deg(a - c, b - c)});
  }
  return smallest;
}

// The large test cases: `base` Loop subdivided `levels` times (CGAL's Subdivision_method_3),
// then seeded uniform-ball noise of radius 0.25 h, h the subdivided mesh's mean edge length.
// Returns h.
inline double make_noisy_case(const Mesh& base, unsigned int levels, Mesh& noisy)
{
  noisy = base;
  CGAL::Subdivision_method_3::Loop_subdivision(noisy, CGAL::parameters::number_of_iterations(levels));
  const double h = mean_edge_length(noisy);
  add_noise(noisy, 0.25 * h, 1);
  return h;
}

// The mesh the speed benchmarks start from, unless one is given: the bundled Stanford bunny of
// CGAL's sample data (75,408 triangles).
inline bool read_base_mesh(const std::string& given, Mesh& base, std::string& name)
{
  name = given.empty() ? std::string(CONSTRAINED_FAIRING_DATA_DIR "/bunny00.off") : given;
  return CGAL::IO::read_polygon_mesh(name, base);
}

inline double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The median of the values that `runs` calls of f return.
template <typename F>
double median_of(int runs, F&& f)
{
  std::vector<double> values;
  for(int r = 0; r < runs; ++r)
    values.push_back(f());
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
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

// The command line: positional arguments, `--runs N` (default 3) for median timing, and
// `--name VALUE` options.
struct Arguments
{
  std::vector<std::string> positional;
  std::vector<std::pair<std::string, std::string> > options;
  int runs = 3;

  Arguments(int argc, char* argv[])
  {
    for(int i = 1; i < argc; ++i)
    {
      const std::string a = argv[i];
      if(a == "--runs" && i + 1 < argc)
        runs = std::stoi(argv[++i]);
      else if(a.rfind("--", 0) == 0 && i + 1 < argc)
      {
        options.emplace_back(a.substr(2), argv[i + 1]);
        ++i;
      }
      else
        positional.push_back(a);
    }
  }

  std::string option(const std::string& name, const std::string& fallback) const
  {
    for(const auto& o : options)
      if(o.first == name)
        return o.second;
    return fallback;
  }
};

// `--threads K`: the library's loops run on at most K threads (default: all) while it lives.
class Thread_limit
{
public:
#ifdef CGAL_LINKED_WITH_TBB
  explicit Thread_limit(const Arguments& arguments)
    : m_limit(tbb::global_control::max_allowed_parallelism, threads(std::stoi(arguments.option("threads", "0"))))
  {}

private:
  static std::size_t threads(int k)
  {
    return k > 0 ? std::size_t(k) : std::size_t(tbb::this_task_arena::max_concurrency());
  }

  tbb::global_control m_limit;
#else
  explicit Thread_limit(const Arguments&) {}
#endif
};

// The base mesh of a speed benchmark: the command line's first positional argument, else the
// bundled bunny. Says on stderr which file could not be read.
inline bool read_base_mesh(const Arguments& arguments, Mesh& base, std::string& name)
{
  if(read_base_mesh(arguments.positional.empty() ? "" : arguments.positional[0], base, name))
    return true;
  std::cerr << "error: cannot read " << name << std::endl;
  return false;
}

// The process's memory in bytes as /proc/self/status gives it (Linux): a field such as "VmHWM:".
inline double process_memory_bytes(const std::string& field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while(std::getline(status, line))
    if(line.rfind(field, 0) == 0)
      return 1024 * std::stod(line.substr(field.size()));
  return 0;
}

// Peak resident memory of the process in bytes, the memory resident now, and the peak's reset.
inline double peak_memory_bytes() { return process_memory_bytes("VmHWM:"); }

inline double resident_memory_bytes() { return process_memory_bytes("VmRSS:"); }

inline void reset_peak_memory() { std::ofstream("/proc/self/clear_refs") << "5"; }

// The CPU model as the system names it (Linux: /proc/cpuinfo), and the number of threads the
// library's loops run on here (TBB's arena, 1 without TBB), printed with every figure since
// ratios differ from one CPU to another.
inline std::string machine_description()
{
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line, model = "unknown CPU";
  while(std::getline(cpuinfo, line))
    if(line.rfind("model name", 0) == 0)
    {
      model = line.substr(line.find(':') + 2);
      break;
    }
#ifdef CGAL_LINKED_WITH_TBB
  const int cpus = tbb::info::default_concurrency();
  const int threads = (std::min)(tbb::this_task_arena::max_concurrency(),
                                 int(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)));
#else
  const int threads = 1, cpus = 1;
#endif
  return model + ", " + std::to_string(cpus) + " CPUs, " + std::to_string(threads) + (threads == 1 ? " thread" : " threads");
}

} // namespace benchmark

#endif // CGAL_CONSTRAINED_FAIRING_BENCHMARK_SUPPORT_H
