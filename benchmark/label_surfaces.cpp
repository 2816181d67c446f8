// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Label maps to surfaces, judged against analytic interfaces:
//  - a ball cut by a tilted plane into two labels, on 64^3 cubic voxels and 64 x 64 x 21 voxels
//    of 1 x 1 x 3: the RMS distance of the points to their true interface (the sphere, the plane)
//    and of the triple line's points to its circle, for the raw surface nets, the clamped
//    Laplacian of VTK's vtkSurfaceNets3D (each point towards the mean of its neighbours on its
//    interface or line, relaxation 0.5, clamped to its voxel box; at its best count of 1 to 1024
//    iterations) and constrained_fairing_of_interfaces(); the smallest angle; the time against
//    fairing each label's surface alone with constrained_fairing() in the same boxes;
//  - a 256^3 map of 10 labels (the Voronoi cells of 10 seeds inside a ball): time and memory.
//
//   label_surfaces [--runs N] [--threads K] [--size 256] [--margin M]

#include "label_soup.h"
#include "../test/ball_phantom.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_interfaces.h>
#include <CGAL/Polygon_mesh_processing/label_surface.h>
#include <CGAL/Polygon_mesh_processing/label_surface_nets.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using benchmark::Mesh;
using benchmark::Point;
using namespace label_soup;

// The margin of the boxes (--margin, default label_box_margin).
double box_margin = PMP::label_box_margin;

// Each label's closed surface faired alone, in the same boxes: the time of all of them.
double fair_separately(const Soup& soup, const std::vector<Label>& labels, int runs)
{
  const double cap = 2 * *std::max_element(soup.spacing.begin(), soup.spacing.end());
  std::vector<Mesh> meshes;
  for(Label l : labels)
  {
    meshes.emplace_back();
    PMP::label_surface(soup.points, soup.triangles, soup.face_labels, l, meshes.back());
  }
  return benchmark::median_seconds(runs, [&] {
    for(const Mesh& mesh : meshes)
    {
      Mesh m = mesh;
      PMP::constrained_fairing(m, cap, CFP::box_half_extents(half_of(soup.spacing)));
    }
  });
}

void ball_case(const std::array<double, 3>& spacing, int runs)
{
  const std::size_t n = 64;
  const std::array<std::size_t, 3> size{n, n, std::size_t(double(n) / spacing[2])};
  const test::Ball_phantom ball{31.5, 24};
  const std::vector<Label> labels = ball.labels<Label>(size, spacing);
  const Soup soup = make_soup(labels, size, spacing, box_margin);

  // The clamped Laplacian at its best count, by the RMS distance of all points.
  const Clamped_laplacian laplacian(soup);
  std::vector<Point> L = soup.points, best_L = L;
  std::size_t best_count = 0, done = 0;
  double best = ball.distances(L, soup.around)[3];
  for(std::size_t count = 1; count <= 1024; count *= 2)
  {
    for(; done < count; ++done)
      laplacian.step(L);
    const double rms = ball.distances(L, soup.around)[3];
    if(rms < best)
      best = rms, best_count = count, best_L = L;
  }
  double seconds = 0;
  std::size_t iterations = 0;
  const std::vector<Point> P = fair_jointly(soup, runs, seconds, iterations);
  const double separately = fair_separately(soup, {1, 2}, runs);
  bool in_box = true;
  for(std::size_t v = 0; v < P.size(); ++v)
    for(int c = 0; c < 3; ++c)
      in_box = in_box && std::abs(P[v][c] - soup.points[v][c]) <= soup.half_extents[v][std::size_t(c)];

  const auto raw = ball.distances(soup.points, soup.around), lap = ball.distances(best_L, soup.around),
             ours = ball.distances(P, soup.around);
  std::cout << "ball cut by a plane, " << size[0] << " x " << size[1] << " x " << size[2] << " voxels of " << spacing[0]
            << " x " << spacing[1] << " x " << spacing[2] << ": " << soup.points.size() << " points, "
            << soup.triangles.size() << " triangles\n"
            << std::setprecision(3) << "  RMS distance (voxels)    all     sphere  plane   triple line  smallest angle\n";
  const auto row = [&](const char* name, const std::array<double, 4>& d, const std::vector<Point>& Q) {
    std::cout << "  " << std::left << std::setw(22) << name << std::right << std::setw(8) << d[3] << std::setw(8) << d[0]
              << std::setw(8) << d[1] << std::setw(13) << d[2] << std::setw(12) << smallest_angle(soup, Q) << "\n";
  };
  row("raw surface nets", raw, soup.points);
  row(("clamped Laplacian x" + std::to_string(best_count)).c_str(), lap, best_L);
  row("joint fairing", ours, P);
  std::cout << "  ratios: " << raw[3] / ours[3] << "x closer than raw (triple line " << raw[2] / ours[2] << "x), "
            << lap[3] / ours[3] << "x closer than the clamped Laplacian; every point in its box: "
            << (in_box ? "yes" : "NO") << "\n  time: joint " << seconds << " s (" << iterations
            << " iterations), each label alone " << separately << " s (" << separately / seconds << "x)\n";
}

void voronoi_case(std::size_t n, int runs)
{
  const std::array<std::size_t, 3> size{n, n, n};
  const std::vector<Label> labels = voronoi_ball_labels<Label>(n);
  benchmark::reset_peak_memory();
  const auto start = std::chrono::steady_clock::now();
  const Soup soup = make_soup(labels, size, {1, 1, 1}, box_margin);
  const double nets = benchmark::seconds_since(start);
  double seconds = 0;
  std::size_t iterations = 0;
  const std::vector<Point> P = fair_jointly(soup, runs, seconds, iterations);
  const double peak = benchmark::peak_memory_bytes();
  std::vector<Label> all;
  for(Label l = 1; l <= 10; ++l)
    all.push_back(l);
  const double separately = fair_separately(soup, all, 1);
  std::cout << "10 Voronoi labels in a ball, " << n << "^3 voxels: " << soup.points.size() << " points, "
            << soup.triangles.size() << " triangles\n  surface nets " << nets << " s, joint fairing " << seconds
            << " s (" << iterations << " iterations), together " << nets + seconds << " s; each label alone "
            << separately << " s (" << separately / seconds << "x); peak memory " << peak / 1e6 << " MB\n";
}

int main(int argc, char* argv[])
{
  const benchmark::Arguments arguments(argc, argv);
  const benchmark::Thread_limit threads(arguments);
  box_margin = std::stod(arguments.option("margin", std::to_string(PMP::label_box_margin)));
  std::cout << benchmark::machine_description() << ", boxes' margin " << box_margin << std::endl;
  ball_case({1, 1, 1}, arguments.runs);
  ball_case({1, 1, 3}, arguments.runs);
  voronoi_case(std::size_t(std::stoi(arguments.option("size", "256"))), arguments.runs);
  return 0;
}
