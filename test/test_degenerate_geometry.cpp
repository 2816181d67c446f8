// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Meshes with 5 % of their triangles made degenerate (collinear vertices, duplicated vertices,
// all three vertices at one point) are faired like any other: no NaN, the bound holds exactly,
// the energy is finite, never rises and falls as on any noisy mesh, no new degenerate triangle
// appears, and two runs give bit-identical results. And loose triangles whose coordinates span
// 1e-41 to 1e37 (an input the fuzzer found): the energy never rises, whatever the number of
// iterations allowed. Under sanitizers, the real meshes each with one kind of bound (the
// elephant in balls, the head in boxes), the icosphere with both.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <string>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using PMP::Deviation_bound;
using test::Mesh;
using test::Point;

bool all_finite(const std::vector<Point>& points)
{
  for(const Point& p : points)
    if(!(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z())))
      return false;
  return true;
}

void check_fairing(const Mesh& clean, const std::string& name, Deviation_bound shape)
{
  Mesh m = clean;
  const double h = test::mean_edge_length(m);
  test::add_noise(m, 0.25 * h, 21);
  const std::size_t changed = test::make_degenerate(m, 0.05, 22);
  const std::size_t degenerate = test::number_of_degenerate_faces(m);
  const std::vector<Point> input = test::points(m);
  CHECK(changed > 0 && degenerate >= changed);

  std::vector<double> energies;
  auto record = [&](std::size_t, double e) { energies.push_back(e); return true; };
  Mesh first = m;
  const auto r = PMP::constrained_fairing(first, 0.25 * h, CFP::iteration_callback(record, CFP::deviation_bound(shape)));
  const std::vector<Point> output = test::points(first);
  const std::size_t degenerate_after = test::number_of_degenerate_faces(first);
  std::cout << "  " << name << (shape == Deviation_bound::BALL ? ", ball: " : ", box: ") << changed << " of "
            << num_faces(m) << " faces made degenerate, " << degenerate << " degenerate faces -> "
            << degenerate_after << "; energy " << r.initial_energy << " -> " << r.final_energy << " in "
            << r.number_of_iterations << " iterations " << r.message << std::endl;

  CHECK(r);
  CHECK(r.number_of_degenerate_edges >= changed);
  CHECK(all_finite(output));
  CHECK(test::bound_violation(output, input, 0.25 * h, shape) <= 0);
  CHECK(std::isfinite(r.initial_energy) && std::isfinite(r.final_energy));
  // Degenerate triangles do not stall the fairing of the rest.
  CHECK(r.final_energy < 0.5 * r.initial_energy);
  double previous = r.initial_energy;
  for(double e : energies)
  {
    CHECK(e <= previous);
    previous = e;
  }
  CHECK(degenerate_after <= degenerate);

  Mesh second = m;
  const auto r2 = PMP::constrained_fairing(second, 0.25 * h, CFP::deviation_bound(shape));
  CHECK(r2.number_of_iterations == r.number_of_iterations && r2.final_energy == r.final_energy);
  CHECK(test::identical(test::points(second), output));
}

// The fuzzer's octahedron of eight loose triangles at extreme coordinates, in a ball of a quarter
// of its mean edge length (1.1e36), cut after 1 to 12 iterations: the line search's slope came
// out positive there and let the energy rise from 19,329 to 28,330.
void check_extreme_coordinates()
{
  Mesh mesh;
  CHECK(CGAL::IO::read_polygon_mesh(std::string(CONSTRAINED_FAIRING_SOURCE_DIR) +
                                      "/test/fuzz/corpus/octahedron_extreme_coordinates.stl",
                                    mesh));
  double sum = 0;
  for(auto e : edges(mesh))
    sum += std::sqrt(CGAL::squared_distance(mesh.point(source(e, mesh)), mesh.point(target(e, mesh))));
  const double epsilon = 0.25 * sum / double(num_edges(mesh));
  for(unsigned int iterations = 1; iterations <= 12; ++iterations)
  {
    Mesh faired = mesh;
    const auto result = PMP::constrained_fairing(
      faired, epsilon, CFP::deviation_bound(Deviation_bound::BALL).number_of_iterations(iterations));
    CHECK(result);
    CHECK(result.final_energy <= result.initial_energy);
  }
}

int main()
{
  const Mesh sphere = test::icosphere(3);
  Mesh elephant, head;
  CHECK(CGAL::IO::read_polygon_mesh(std::string(CONSTRAINED_FAIRING_DATA_DIR) + "/elephant.off", elephant));
  CHECK(CGAL::IO::read_polygon_mesh(std::string(CONSTRAINED_FAIRING_DATA_DIR) + "/head.off", head));
  for(Deviation_bound shape : {Deviation_bound::BALL, Deviation_bound::BOX})
  {
    check_fairing(sphere, "icosphere", shape);
    if(!test::under_sanitizers || shape == Deviation_bound::BALL)
      check_fairing(elephant, "elephant.off", shape);
    if(!test::under_sanitizers || shape == Deviation_bound::BOX)
      check_fairing(head, "head.off (border)", shape);
  }
  check_extreme_coordinates();
  return test::report("test_degenerate_geometry");
}
