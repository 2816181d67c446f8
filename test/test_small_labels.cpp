// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Small labels keep their volumes: a label of 1 to 64 voxels (one voxel, 1 x 1 x 2, 2 x 2 x 1,
// an L of 3, 2 x 2 x 2, a block of 8 less a corner, 1 x 2 x 4, 3 x 3 x 3, an L of 10, 4 x 4 x 4,
// 4 x 4 x 2) alone in the background, inside one label, on the plane between two and on the line
// where three meet, on cubic voxels and on 0.62 x 0.62 x 1.33 mm (a CT's thick slices), made into
// surface nets and faired by constrained_fairing_of_interfaces() in their boxes. Checked: every
// point in its box; every label's surface (label_surface()) closed, and the volume it encloses
// within 10 % of its voxel count times a voxel's volume for labels of 8 voxels or more, within
// 25 % below that. Before the volumes of labels thinner than the spacing were held at their
// count, one voxel on the plane between two labels ended with no volume, a block of 2 x 2 x 2
// with a quarter of it, and one alone in the background swelled by a fifth.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_interfaces.h>
#include <CGAL/Polygon_mesh_processing/label_surface.h>
#include <CGAL/Polygon_mesh_processing/label_surface_nets.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using test::Mesh;
using test::Point;
using Label = std::int32_t;

constexpr std::size_t n = 16, c = n / 2;
constexpr Label small = 3;

struct Shape
{
  std::string name;
  std::array<std::size_t, 3> size;
  std::vector<std::array<std::size_t, 3> > left_out; // voxels of the box that are not the label's
};

const std::vector<Shape> shapes{
  {"1", {1, 1, 1}, {}},
  {"1x1x2", {1, 1, 2}, {}},
  {"2x2x1", {2, 2, 1}, {}},
  {"L of 3", {2, 2, 1}, {{1, 1, 0}}},
  {"2x2x2", {2, 2, 2}, {}},
  {"2x2x2 less a corner", {2, 2, 2}, {{1, 1, 1}}},
  {"1x2x4", {1, 2, 4}, {}},
  {"3x3x3", {3, 3, 3}, {}},
  {"L of 10", {3, 3, 2}, {{1, 1, 0}, {1, 2, 0}, {2, 1, 0}, {2, 2, 0}, {1, 1, 1}, {1, 2, 1}, {2, 1, 1}, {2, 2, 1}}},
  {"4x4x4", {4, 4, 4}, {}},
  {"4x4x2", {4, 4, 2}, {}}};

enum class Place { background, inside_one, between_two, between_three };
const char* name(Place p)
{
  return p == Place::background ? "alone" : p == Place::inside_one ? "in 1" : p == Place::between_two ? "on 1|2" : "on 1|2|4";
}

// n^3 voxels: labels 1, 2 and 4 in a block 2 voxels inside the array's sides, cut by z = c
// (1 below; above, 2 where y < c and 4 beyond, for three); the small label straddles the cut.
std::vector<Label> label_map(const Shape& shape, Place place)
{
  std::vector<Label> labels(n * n * n, 0);
  const auto at = [&labels](std::size_t i, std::size_t j, std::size_t k) -> Label& { return labels[(i * n + j) * n + k]; };
  if(place != Place::background)
    for(std::size_t i = 2; i < n - 2; ++i)
      for(std::size_t j = 2; j < n - 2; ++j)
        for(std::size_t k = 2; k < n - 2; ++k)
          at(i, j, k) = place == Place::inside_one || k < c ? 1 : place == Place::between_two || j < c ? 2 : 4;
  const auto& s = shape.size;
  const std::size_t i0 = c - s[0] / 2, j0 = (s[1] == 1 ? c : c - s[1] / 2), k0 = (s[2] == 1 ? c : c - s[2] / 2);
  for(std::size_t i = 0; i < s[0]; ++i)
    for(std::size_t j = 0; j < s[1]; ++j)
      for(std::size_t k = 0; k < s[2]; ++k)
        if(std::find(shape.left_out.begin(), shape.left_out.end(), std::array<std::size_t, 3>{i, j, k}) ==
           shape.left_out.end())
          at(i0 + i, j0 + j, k0 + k) = small;
  return labels;
}

void check_volumes(const Shape& shape, Place place, const std::array<double, 3>& spacing)
{
  const std::vector<Label> labels = label_map(shape, place);
  std::vector<Point> nets;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<std::array<Label, 2> > face_labels;
  std::vector<std::array<double, 3> > half_extents;
  PMP::label_surface_nets(labels.data(), {n, n, n}, spacing, {0, 0, 0}, nets, triangles, face_labels, half_extents);
  std::vector<Point> points = nets;
  const double cap = std::sqrt(spacing[0] * spacing[0] + spacing[1] * spacing[1] + spacing[2] * spacing[2]);
  CHECK(PMP::constrained_fairing_of_interfaces(points, triangles, face_labels, cap,
                                               CFP::vertex_box_half_extents_map(CGAL::make_property_map(half_extents))));
  for(std::size_t v = 0; v < points.size(); ++v)
    for(int a = 0; a < 3; ++a)
      CHECK(std::abs(points[v][a] - nets[v][a]) <= half_extents[v][std::size_t(a)]);

  std::cout << "  " << std::setw(20) << shape.name << " " << std::setw(8) << name(place) << ", spacing " << spacing[2]
            << ": faired volume over the count";
  const double voxel = spacing[0] * spacing[1] * spacing[2];
  for(Label label : {1, 2, 4, 3})
  {
    const std::size_t count = std::size_t(std::count(labels.begin(), labels.end(), label));
    if(count == 0)
      continue;
    Mesh mesh;
    PMP::label_surface(points, triangles, face_labels, label, mesh);
    CHECK(CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_closed(mesh));
    const double ratio = PMP::volume(mesh) / (double(count) * voxel);
    std::cout << "  " << label << ": " << std::fixed << std::setprecision(3) << ratio << std::defaultfloat;
    CHECK(std::abs(ratio - 1) <= (count >= 8 ? 0.10 : 0.25));
  }
  std::cout << std::endl;
}

int main()
{
  // Under the sanitizers, the cubic voxels alone (the same code, half the calls).
  std::vector<std::array<double, 3> > spacings{{1, 1, 1}};
  if(!test::under_sanitizers)
    spacings.push_back({0.617188, 0.617188, 1.33333});
  for(const auto& spacing : spacings)
    for(const Shape& shape : shapes)
      for(Place place : {Place::background, Place::inside_one, Place::between_two, Place::between_three})
        check_volumes(shape, place, spacing);
  return test::report("test_small_labels");
}
