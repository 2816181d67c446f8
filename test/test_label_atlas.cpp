// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A real segmentation: the block of 40^3 voxels that holds the most labels (among those on a grid
// of 20 voxels) of the Harvard-Oxford cortical atlas (HarvardOxford-cort-maxprob-thr0-1mm, from Debian's mricron-data, whose
// licence keeps it out of data/): ribbons one or two voxels thick, touching themselves and each
// other along edges and at corners. Skipped (exit code 77) where the package is absent. Checked,
// on the surface nets and after the fairing of all interfaces at once:
//  - no two points' boxes meet, and every faired point is in its box, exactly in double: no two
//    points at one position;
//  - every label's surface is made without splitting a point (a manifold as the nets make it),
//    closed, valid, outward (positive volume), and intersects itself nowhere;
//  - the fairing lowers the objective.
// Under sanitizers, a block of 24^3 voxels (on a grid of 12). And the same on a block of 8^3
// voxels of the inia19 atlas (the same package) where three points of split cells line up on a
// junction line: there the smallest angle ends at 5 degrees or more.

#include "test_support.h"

#include "front_end/Label_map_file.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_interfaces.h>
#include <CGAL/Polygon_mesh_processing/label_surface.h>
#include <CGAL/Polygon_mesh_processing/label_surface_nets.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using test::Mesh;
using test::Point;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;

// Each label's surface of the soup: made without splitting a point, closed, valid, outward, not
// intersecting itself. Returns the number of labels.
std::size_t check_surfaces(const std::vector<Point>& points, const std::vector<std::array<std::size_t, 3> >& triangles,
                           const std::vector<std::array<std::int64_t, 2> >& face_labels)
{
  std::set<std::int64_t> labels;
  for(const auto& pair : face_labels)
    for(std::int64_t l : pair)
      if(l != 0)
        labels.insert(l);
  for(std::int64_t label : labels)
  {
    Mesh mesh;
    std::vector<std::size_t> origin;
    PMP::label_surface(points, triangles, face_labels, label, mesh, &origin);
    std::sort(origin.begin(), origin.end());
    CHECK(std::adjacent_find(origin.begin(), origin.end()) == origin.end());
    CHECK(CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_closed(mesh));
    CHECK(PMP::volume(mesh) > 0);
    CHECK(!PMP::does_self_intersect(mesh));
  }
  return labels.size();
}

// The n^3 voxels of `map` from `first`.
std::vector<std::int64_t> block_of(const Constrained_fairing_front_end::Label_map& map, const std::array<std::size_t, 3>& first,
                                   std::size_t n)
{
  std::vector<std::int64_t> block;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t k = 0; k < n; ++k)
        block.push_back(map.labels[((first[0] + i) * map.size[1] + first[1] + j) * map.size[2] + first[2] + k]);
  return block;
}

// Every check above on the nets of an n^3 block and on their fairing. Returns the number of labels
// and the faired surfaces' smallest angle (degrees).
std::pair<std::size_t, double> check_block(const std::vector<std::int64_t>& block, std::size_t n, const std::string& name)
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<std::array<std::int64_t, 2> > face_labels;
  std::vector<std::array<double, 3> > half;
  PMP::label_surface_nets(block.data(), {n, n, n}, {1, 1, 1}, {0, 0, 0}, points, triangles, face_labels, half);
  std::vector<Box> boxes;
  for(std::size_t p = 0; p < points.size(); ++p)
    boxes.emplace_back(CGAL::Bbox_3(points[p].x() - half[p][0], points[p].y() - half[p][1], points[p].z() - half[p][2],
                                    points[p].x() + half[p][0], points[p].y() + half[p][1], points[p].z() + half[p][2]),
                       p);
  std::size_t meeting = 0;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box&, const Box&) { ++meeting; });
  CHECK(meeting == 0);
  const std::size_t labels = check_surfaces(points, triangles, face_labels);

  std::vector<Point> faired = points;
  const PMP::Constrained_fairing_result r = PMP::constrained_fairing_of_interfaces(
    faired, triangles, face_labels, 2.0, CFP::vertex_box_half_extents_map(CGAL::make_property_map(half)));
  CHECK(r && r.final_energy < r.initial_energy);
  for(std::size_t p = 0; p < points.size(); ++p)
    for(int c = 0; c < 3; ++c)
      CHECK(std::abs(faired[p][c] - points[p][c]) <= half[p][std::size_t(c)]);
  std::vector<Point> sorted = faired;
  std::sort(sorted.begin(), sorted.end());
  CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
  check_surfaces(faired, triangles, face_labels);
  const double smallest = test::smallest_angle(faired, triangles);
  std::cout << "  " << name << ": " << labels << " labels, " << points.size() << " points, " << triangles.size()
            << " triangles, " << r.number_of_iterations << " iterations, smallest angle " << smallest << " degrees"
            << std::endl;
  return {labels, smallest};
}

int main()
{
  const std::string templates = "/usr/share/mricron/templates/";
  const std::string atlas = templates + "HarvardOxford-cort-maxprob-thr0-1mm.nii.gz";
  if(!std::filesystem::exists(atlas))
  {
    std::cout << "test_label_atlas: skipped (no " << atlas << ": Debian's mricron-data)" << std::endl;
    return 77;
  }
  Constrained_fairing_front_end::Label_map map;
  const std::string error = Constrained_fairing_front_end::read_label_map(atlas, map);
  CHECK(error.empty());
  if(!error.empty())
    return test::report("test_label_atlas");

  // The block of n^3 voxels with the most labels, its corner on a grid of n / 2.
  const std::size_t n = test::under_sanitizers ? 24 : 40;
  std::array<std::size_t, 3> first{0, 0, 0};
  std::size_t most = 0;
  for(std::size_t a = 0; a + n <= map.size[0]; a += n / 2)
    for(std::size_t b = 0; b + n <= map.size[1]; b += n / 2)
      for(std::size_t c = 0; c + n <= map.size[2]; c += n / 2)
      {
        std::set<std::int64_t> held;
        for(std::size_t i = a; i < a + n; ++i)
          for(std::size_t j = b; j < b + n; ++j)
            for(std::size_t k = c; k < c + n; ++k)
              held.insert(map.labels[(i * map.size[1] + j) * map.size[2] + k]);
        if(held.size() > most)
          most = held.size(), first = {a, b, c};
      }
  CHECK(check_block(block_of(map, first, n), n, "Harvard-Oxford, " + std::to_string(n) + "^3").first >= 10);

  // inia19's block of 8^3 voxels at (49, 99, 34): three points of split cells on a junction line,
  // whose middle one the nets move off it. The fairing straightens the line again and the repair
  // pulls that triangle back to its start: 4.85 degrees when moved by a quarter of its box.
  const std::string inia19_file = templates + "inia19-NeuroMaps.nii.gz";
  Constrained_fairing_front_end::Label_map inia19;
  if(!std::filesystem::exists(inia19_file))
    std::cout << "  inia19: not in this mricron-data" << std::endl;
  else
  {
    const std::string inia19_error = Constrained_fairing_front_end::read_label_map(inia19_file, inia19);
    CHECK(inia19_error.empty());
    if(inia19_error.empty())
      CHECK(check_block(block_of(inia19, {49, 99, 34}, 8), 8, "inia19, 8^3").second >= 5);
  }
  return test::report("test_label_atlas");
}
