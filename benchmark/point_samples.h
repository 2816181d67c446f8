// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The point sets of the point set benchmarks: points sampled area-uniformly on a clean mesh,
// seeded isotropic Gaussian noise, and the clamp that puts a peer's result into the same balls.

#ifndef CGAL_CONSTRAINED_FAIRING_BENCHMARK_POINT_SAMPLES_H
#define CGAL_CONSTRAINED_FAIRING_BENCHMARK_POINT_SAMPLES_H

#include "benchmark_support.h"

#include <CGAL/bounding_box.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <string>
#include <vector>

namespace benchmark {

// `n` points on `mesh`, uniform by area.
inline std::vector<Point> sample(const Mesh& mesh, std::size_t n, unsigned seed)
{
  std::vector<std::array<Point, 3> > triangles;
  std::vector<double> areas;
  for(auto f : faces(mesh))
  {
    std::array<Point, 3> t;
    int k = 0;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
      t[std::size_t(k++)] = mesh.point(v);
    triangles.push_back(t);
    areas.push_back(std::sqrt(CGAL::squared_area(t[0], t[1], t[2])));
  }
  std::mt19937 random(seed);
  std::discrete_distribution<std::size_t> pick(areas.begin(), areas.end());
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Point> points;
  for(std::size_t i = 0; i < n; ++i)
  {
    const auto& t = triangles[pick(random)];
    double a = unit(random), b = unit(random);
    if(a + b > 1)
      a = 1 - a, b = 1 - b;
    points.push_back(t[0] + a * (t[1] - t[0]) + b * (t[2] - t[0]));
  }
  return points;
}

inline std::vector<Point> add_gaussian_noise(std::vector<Point> points, double sigma, unsigned seed)
{
  std::mt19937 random(seed);
  std::normal_distribution<double> normal(0, sigma);
  for(Point& p : points)
    p = p + K::Vector_3(normal(random), normal(random), normal(random));
  return points;
}

// Each point moved back into the ball of radius `eps` around its input.
inline void clamp(std::vector<Point>& points, const std::vector<Point>& input, double eps)
{
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const K::Vector_3 d = points[i] - input[i];
    const double length = std::sqrt(d.squared_length());
    if(length > eps)
      points[i] = input[i] + d * (eps / length);
  }
}

// The large point set of the scaling benchmarks: the mesh the arguments name (the bundled bunny
// by default), `--points` of it (`default_points` without) sampled, Gaussian noise of sigma = 1 %
// of the bounding sphere's radius.
struct Noisy_sample
{
  Mesh mesh;
  std::string name;
  std::vector<Point> noisy;
  double sigma = 0;
};

inline bool read_noisy_sample(const Arguments& arguments, const std::string& default_points, Noisy_sample& sample_set)
{
  if(!read_base_mesh(arguments, sample_set.mesh, sample_set.name))
    return false;
  const std::size_t n = std::stoul(arguments.option("points", default_points));
  const Mesh& mesh = sample_set.mesh;
  const auto box = CGAL::bounding_box(mesh.points().begin(), mesh.points().end());
  sample_set.sigma = 0.01 * std::sqrt(CGAL::squared_distance(box.min(), box.max())) / 2;
  sample_set.noisy = add_gaussian_noise(sample(mesh, n, 1), sample_set.sigma, 3);
  return true;
}

} // namespace benchmark

#endif // CGAL_CONSTRAINED_FAIRING_BENCHMARK_POINT_SAMPLES_H
