// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Label maps from real segmentations and generated worst cases, judged as a user would judge
// their surfaces: for each map, surface nets faired by constrained_fairing_of_interfaces() in
// their boxes, then each label's surface made by label_surface(); per map, the labels whose
// surface is not closed, not a valid manifold made without splitting, not outward (volume), or
// intersects itself (PMP::does_self_intersect); the pairs of distinct points at one position;
// the points outside their boxes; the smallest angle; the folded triangles the result counts;
// the iterations, the energy evaluations and the time per iteration (the median of --runs calls,
// each on the unfaired nets), and that time per triangle against a compact map's of about a
// million triangles faired first in the same run (10 Voronoi labels in a ball, 256^3 voxels;
// --compact 0 leaves it out).
//
//   label_map_topology [--runs 3] [--threads K] [--margin M] [--compact 256] [FILE.nii[.gz] ...]
//
// Without files: the atlases of Debian's mricron-data (/usr/share/mricron/templates), skipped
// with a note when the package is absent, after the generated cases.

#include "benchmark_support.h"
#include "label_soup.h"

#include "front_end/Label_map_file.h"
#include "front_end/Voxel_frame.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_interfaces.h>
#include <CGAL/Polygon_mesh_processing/label_surface.h>
#include <CGAL/Polygon_mesh_processing/label_surface_nets.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using benchmark::Mesh;
using benchmark::Point;
using Label = std::int64_t;

struct Map
{
  std::string name;
  std::array<std::size_t, 3> size;
  std::array<double, 3> spacing;
  std::vector<Label> labels;
};

// The margin of the boxes (--margin, default label_box_margin).
double box_margin = PMP::label_box_margin;

// The calls whose median time is taken (--runs).
int runs = 3;

// The compact map's time per iteration and triangle, once it is known.
double compact_time = 0;

// Fairs and judges `map`; `compact`: it is the compact map that the others' times are compared with.
void judge(const Map& map, bool compact = false)
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<std::array<Label, 2> > face_labels;
  std::vector<std::array<double, 3> > half;
  PMP::label_surface_nets(map.labels.data(), map.size, map.spacing, {0, 0, 0}, points, triangles, face_labels, half,
                          Label(0), box_margin);
  const std::vector<Point> unfaired = points;
  PMP::Constrained_fairing_result result;
  const double seconds = benchmark::median_seconds(runs, [&] {
    points = unfaired;
    result = PMP::constrained_fairing_of_interfaces(
      points, triangles, face_labels, 2 * std::max({map.spacing[0], map.spacing[1], map.spacing[2]}),
      CFP::vertex_box_half_extents_map(CGAL::make_property_map(half)));
  });

  std::size_t outside = 0;
  for(std::size_t p = 0; p < points.size(); ++p)
    for(int c = 0; c < 3; ++c)
      outside += !(std::abs(points[p][c] - unfaired[p][c]) <= half[p][std::size_t(c)]);
  std::vector<Point> sorted = points;
  std::sort(sorted.begin(), sorted.end());
  std::size_t coincident = 0;
  for(std::size_t p = 1; p < sorted.size(); ++p)
    coincident += sorted[p] == sorted[p - 1];
  double smallest = 180;
  for(const auto& t : triangles)
  {
    const Point &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
    smallest = std::min({smallest, benchmark::angle_deg(b - a, c - a), benchmark::angle_deg(a - b, c - b),
                         benchmark::angle_deg(a - c, b - c)});
  }
  std::set<Label> labels;
  for(const auto& pair : face_labels)
    for(Label l : pair)
      if(l != 0)
        labels.insert(l);
  std::size_t open = 0, split = 0, inward = 0, crossing = 0;
  for(Label l : labels)
  {
    Mesh mesh;
    std::vector<std::size_t> origin;
    PMP::label_surface(points, triangles, face_labels, l, mesh, &origin);
    std::sort(origin.begin(), origin.end());
    open += !(CGAL::is_closed(mesh) && CGAL::is_valid_polygon_mesh(mesh));
    split += std::adjacent_find(origin.begin(), origin.end()) != origin.end();
    inward += !(PMP::volume(mesh) > 0);
    crossing += PMP::does_self_intersect(mesh);
  }
  const double per_iteration = seconds / double(std::max<std::size_t>(result.number_of_iterations, 1));
  std::cout << std::left << std::setw(44) << map.name << std::right << std::setw(5) << labels.size() << std::setw(9)
            << triangles.size() << std::setw(6) << open << std::setw(6) << split << std::setw(7) << inward
            << std::setw(7) << crossing << std::setw(7) << coincident << std::setw(7) << outside << std::setw(7)
            << std::setprecision(3) << smallest << std::setw(6) << result.number_of_folded_faces << std::setw(6)
            << result.number_of_iterations << std::setw(10)
            << std::setprecision(3) << per_iteration << std::setw(9) << std::setprecision(4) << seconds << std::setw(7)
            << result.number_of_energy_evaluations;
  const double per_triangle = per_iteration / double(triangles.size());
  if(compact)
    compact_time = per_triangle;
  else if(compact_time > 0)
    std::cout << std::setw(9) << std::setprecision(3) << per_triangle / compact_time;
  std::cout << (result ? "" : "  " + result.message) << std::endl;
}

Map generated(const std::string& name, std::array<std::size_t, 3> size, const std::array<double, 3>& spacing,
              const std::function<Label(std::size_t, std::size_t, std::size_t)>& f)
{
  Map map{name, size, spacing, std::vector<Label>(size[0] * size[1] * size[2])};
  for(std::size_t i = 0; i < size[0]; ++i)
    for(std::size_t j = 0; j < size[1]; ++j)
      for(std::size_t k = 0; k < size[2]; ++k)
        map.labels[(i * size[1] + j) * size[2] + k] = f(i, j, k);
  return map;
}

int main(int argc, char* argv[])
{
  const benchmark::Arguments arguments(argc, argv);
  const benchmark::Thread_limit threads(arguments);
  box_margin = std::stod(arguments.option("margin", std::to_string(PMP::label_box_margin)));
  runs = arguments.runs;
  std::cout << benchmark::machine_description() << ", boxes' margin " << box_margin << "\n"
            << std::left << std::setw(44) << "map" << std::right
            << "labels triangles  open split inward crossing coinc. outside  angle folds iter.    s/iter  total s  evals  /compact"
            << std::endl;
  if(const auto n = std::size_t(std::stoi(arguments.option("compact", "256"))); n > 0)
    judge(Map{"compact: 10 Voronoi labels, " + std::to_string(n) + "^3", {n, n, n}, {1, 1, 1},
              label_soup::voronoi_ball_labels<Label>(n)},
          true);
  std::vector<std::string> files(arguments.positional.begin(), arguments.positional.end());
  if(files.empty())
  {
    const auto inner = [](std::size_t i, std::size_t j, std::size_t k, std::size_t n) {
      return i >= 2 && j >= 2 && k >= 2 && i + 2 < n && j + 2 < n && k + 2 < n;
    };
    for(int parity : {0, 1})
      judge(generated("checkerboard, 2 labels" + std::string(parity ? ", background" : ""), {12, 12, 12}, {1, 1, 1},
                      [&](std::size_t i, std::size_t j, std::size_t k) {
                        return inner(i, j, k, 12) ? Label((i + j + k) % 2 + (parity ? 0 : 1)) : 0;
                      }));
    judge(generated("checkerboard, 3 labels", {12, 12, 12}, {1, 1, 1}, [&](std::size_t i, std::size_t j, std::size_t k) {
      return inner(i, j, k, 12) ? Label((i + 2 * j + k) % 3 + 1) : 0;
    }));
    std::mt19937 random(3);
    for(int labels : {2, 3, 5})
    {
      std::uniform_int_distribution<int> pick(0, labels - 1);
      judge(generated("random voxels, " + std::to_string(labels) + " labels", {14, 14, 14}, {1, 1, 1},
                      [&](std::size_t, std::size_t, std::size_t) { return Label(pick(random)); }));
    }
    std::uniform_int_distribution<int> pick(0, 1);
    judge(generated("random voxels, 1 x 1 x 3", {14, 14, 6}, {1, 1, 3},
                    [&](std::size_t, std::size_t, std::size_t) { return Label(pick(random)); }));
    judge(generated("diagonal one-voxel tubes", {16, 16, 16}, {1, 1, 1}, [](std::size_t i, std::size_t j, std::size_t k) {
      return (i == j && j == k) ? 1 : (i == j + 2 && k == 8) ? 2 : (j + k == 15 && i == 4) ? 3 : 0;
    }));
    judge(generated("one-voxel sheets, tilted", {20, 20, 20}, {1, 1, 1}, [](std::size_t i, std::size_t j, std::size_t k) {
      return (std::size_t(0.3 * double(i) + 0.5 * double(j)) + 4 == k) ? 1 : (i + 2 * k == 30) ? 2 : 0;
    }));
    const std::string templates = "/usr/share/mricron/templates";
    if(!std::filesystem::is_directory(templates))
      std::cout << "(no " << templates << ": install Debian's mricron-data for the atlases)" << std::endl;
    else
      for(const char* atlas : {"aal", "AICHAmc", "brodmann", "HarvardOxford-cort-maxprob-thr0-1mm",
                               "JHU-WhiteMatter-labels-1mm", "JHU-WhiteMatter-labels-2mm", "jhu189", "natbrainlab",
                               "inia19-NeuroMaps"})
        files.push_back(templates + "/" + atlas + ".nii.gz");
  }
  for(const std::string& file : files)
  {
    Constrained_fairing_front_end::Label_map read;
    const std::string error = Constrained_fairing_front_end::read_label_map(file, read);
    if(!error.empty())
    {
      std::cout << file << ": " << error << std::endl;
      continue;
    }
    const Constrained_fairing_front_end::Voxel_frame frame(read.affine);
    if(!frame.error.empty())
    {
      std::cout << file << ": " << frame.error << std::endl;
      continue;
    }
    judge(Map{std::filesystem::path(file).filename().string(), read.size, frame.spacing, std::move(read.labels)});
  }
  return 0;
}
