// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// estimate_noise_level(): on meshes with seeded uniform-ball noise of known radius r (a plane,
// a sphere, the bundled bunny), the estimate is within 10 % of r; on clean smooth meshes it is
// a small fraction of the edge length; it is 0 on meshes too small to fit; it works through a
// vertex point map and on Polyhedron_3.
// estimate_noise_level_of_points(), on those meshes' vertices as point sets: about 1.1 r (its
// documented calibration), within 12 %; a small fraction of the spacing when clean; 0 for too
// few points; the same for the points in another order and through a point map.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/estimate_noise_level.h>
#include <CGAL/Polygon_mesh_processing/estimate_noise_level_of_points.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/generators.h>

#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
using test::Mesh;
using test::Point;

void check_noisy(const Mesh& clean, const std::string& name)
{
  const double h = test::mean_edge_length(clean);
  const double floor = PMP::estimate_noise_level(clean);
  std::cout << "  " << name << ": clean " << floor / h << " h";
  CHECK(floor < 0.05 * h);
  for(double d : {0.1, 0.25, 0.5})
  {
    Mesh noisy = clean;
    test::add_noise(noisy, d * h, 7);
    const double ratio = PMP::estimate_noise_level(noisy) / (d * h);
    std::cout << ", noise " << d << " h: " << ratio;
    CHECK(std::abs(ratio - 1) < 0.1);
  }
  std::cout << std::endl;
}

// The points of `mesh`, in its vertex order.
std::vector<Point> points_of(const Mesh& mesh)
{
  return std::vector<Point>(mesh.points().begin(), mesh.points().end());
}

void check_noisy_points(const Mesh& clean, const std::string& name)
{
  const double h = test::mean_edge_length(clean);
  const double floor = PMP::estimate_noise_level_of_points(points_of(clean));
  std::cout << "  " << name << " as points: clean " << floor / h << " h";
  CHECK(floor < 0.25 * h);
  for(double d : {0.25, 0.5, 1.0})
  {
    Mesh noisy = clean;
    test::add_noise(noisy, d * h, 7);
    const double ratio = PMP::estimate_noise_level_of_points(points_of(noisy)) / (d * h);
    std::cout << ", noise " << d << " h: " << ratio;
    CHECK(std::abs(ratio - 1.1) < 0.12);
  }
  std::cout << std::endl;
}

void check_point_set_calls()
{
  Mesh sphere = test::icosphere(4);
  test::add_noise(sphere, 0.5 * test::mean_edge_length(sphere), 11);
  std::vector<Point> points = points_of(sphere);
  const double estimate = PMP::estimate_noise_level_of_points(points);
  CHECK(estimate > 0);
  // Another order: the same neighbourhoods, the same median, up to the order of the sums.
  std::vector<Point> reversed(points.rbegin(), points.rend());
  CHECK(std::abs(PMP::estimate_noise_level_of_points(reversed) - estimate) <= 1e-12 * estimate);
  // Through a point map, with more neighbours.
  std::vector<std::pair<Point, int> > items;
  for(const Point& p : points)
    items.emplace_back(p, 0);
  const auto map = CGAL::First_of_pair_property_map<std::pair<Point, int> >();
  CHECK(PMP::estimate_noise_level_of_points(items, CGAL::parameters::point_map(map)) == estimate);
  CHECK(PMP::estimate_noise_level_of_points(
          items, CGAL::Polygon_mesh_processing::constrained_fairing_parameters::number_of_neighbors(
                   64, CGAL::parameters::point_map(map))) > 0);
  // No more points than neighbours.
  points.resize(32);
  CHECK(PMP::estimate_noise_level_of_points(points) == 0);
  CHECK(PMP::estimate_noise_level_of_points(std::vector<Point>()) == 0);
}

int main()
{
  check_noisy(test::plane_patch(120), "plane");
  check_noisy(test::icosphere(5), "sphere");
  Mesh bunny;
  CHECK(CGAL::IO::read_polygon_mesh(CONSTRAINED_FAIRING_DATA_DIR "/bunny00.off", bunny));
  check_noisy(bunny, "bunny");
  check_noisy_points(test::plane_patch(120), "plane");
  check_noisy_points(test::icosphere(5), "sphere");
  check_noisy_points(bunny, "bunny");
  check_point_set_calls();

  // Too few vertices for a fit, and no vertex at all.
  Mesh tetrahedron;
  CGAL::make_tetrahedron(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), tetrahedron);
  CHECK(PMP::estimate_noise_level(tetrahedron) == 0);
  CHECK(PMP::estimate_noise_level(Mesh()) == 0);

  // A vertex point map other than the mesh's, and a Polyhedron_3.
  Mesh sphere = test::icosphere(4);
  const double h = test::mean_edge_length(sphere);
  Mesh noisy = sphere;
  test::add_noise(noisy, 0.25 * h, 9);
  auto moved = sphere.add_property_map<Mesh::Vertex_index, Point>("v:moved").first;
  for(auto v : vertices(sphere))
    moved[v] = noisy.point(v);
  const double through_map = PMP::estimate_noise_level(sphere, CGAL::parameters::vertex_point_map(moved));
  CHECK(through_map == PMP::estimate_noise_level(noisy));
  CGAL::Polyhedron_3<test::K> polyhedron;
  CGAL::copy_face_graph(noisy, polyhedron);
  CHECK(std::abs(PMP::estimate_noise_level(polyhedron) - through_map) <= 1e-12 * through_map);
  return test::report("test_noise_estimate");
}
