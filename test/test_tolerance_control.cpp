// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Per-vertex tolerances, boxes with their own extents and centres, fixed vertices, face
// ranges and the per-vertex outputs: each vertex within its own bound exactly (in double, as a
// user checks it), what must not move bit-identical, bad values rejected with the mesh
// untouched.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>

#include <array>
#include <limits>
#include <string>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using PMP::Constrained_fairing_status;
using PMP::Deviation_bound;
using test::Mesh;
using test::Point;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;

const double noise = 0.02, eps = 0.02;

Mesh noisy_sphere()
{
  Mesh m = test::icosphere(3);
  test::add_noise(m, noise, 7);
  return m;
}

bool identical(const Point& a, const Point& b) { return test::identical({a}, {b}); }

double energy_of(Mesh m)
{
  return PMP::constrained_fairing(m, 1.0, CGAL::parameters::number_of_iterations(0)).initial_energy;
}

// Each vertex within its own radius, zero radii bit-identical, some vertices at their
// (different) bounds; the outputs agree with the points.
void check_vertex_tolerance()
{
  for(Deviation_bound shape : {Deviation_bound::BALL, Deviation_bound::BOX})
  {
    Mesh m = noisy_sphere();
    const std::vector<Point> in = test::points(m);
    auto tolerance = m.add_property_map<vertex_descriptor, double>("v:tolerance").first;
    auto deviation = m.add_property_map<vertex_descriptor, double>("v:deviation", -1.).first;
    auto at_bound = m.add_property_map<vertex_descriptor, bool>("v:at_bound").first;
    std::size_t k = 0, pinned = 0;
    for(auto v : vertices(m))
    {
      // from 0 to twice epsilon, which caps it
      put(tolerance, v, (k % 7 == 0) ? 0. : 2 * eps * double(k % 11) / 10.);
      pinned += get(tolerance, v) == 0;
      ++k;
    }
    const auto result = PMP::constrained_fairing(m, eps, CFP::vertex_tolerance_map(
                                                         tolerance, CFP::deviation_bound(shape, CFP::vertex_deviation_map(
                                                           deviation, CFP::vertex_at_bound_map(at_bound)))));
    CHECK(result);
    CHECK(result.final_energy < 0.5 * result.initial_energy);
    const std::vector<Point> out = test::points(m);
    std::size_t at_bound_count = 0, at_small_bound = 0, moved = 0;
    k = 0;
    for(auto v : vertices(m))
    {
      const double r = (std::min)(eps, get(tolerance, v));
      const std::vector<Point> p{out[k]}, p0{in[k]};
      CHECK(test::bound_violation(p, p0, r, shape) <= 0);
      if(r == 0)
        CHECK(identical(out[k], in[k]));
      moved += !identical(out[k], in[k]);
      const double d = std::sqrt(CGAL::squared_distance(out[k], in[k]));
      CHECK(std::abs(get(deviation, v) - d) <= 1e-12 * eps);
      if(get(at_bound, v))
      {
        ++at_bound_count;
        CHECK(r > 0);
        if(shape == Deviation_bound::BALL)
          CHECK(d >= r * (1 - 1e-9));
        at_small_bound += r < 0.5 * eps;
      }
      ++k;
    }
    CHECK(moved > 0 && moved + pinned >= num_vertices(m) * 9 / 10);
    CHECK(at_bound_count == result.number_of_vertices_at_bound);
    CHECK(at_small_bound > 0);
    CHECK(result.number_of_fixed_vertices == pinned); // a tolerance of 0 pins the vertex
    CHECK(result.max_deviation <= (shape == Deviation_bound::BALL ? eps : std::sqrt(3.) * eps));
  }
}

// A global box of unequal half-extents; per-vertex extents and centres (voxel cells).
void check_boxes()
{
  {
    Mesh m = noisy_sphere();
    const std::vector<Point> in = test::points(m);
    const std::array<double, 3> h{0.25 * eps, 0.25 * eps, eps};
    const auto result = PMP::constrained_fairing(m, 2 * eps, CFP::box_half_extents(h));
    CHECK(result);
    const std::vector<Point> out = test::points(m);
    double largest_z = 0, largest_x = 0;
    for(std::size_t k = 0; k < in.size(); ++k)
    {
      CHECK(std::abs(out[k].x() - in[k].x()) <= h[0]);
      CHECK(std::abs(out[k].y() - in[k].y()) <= h[1]);
      CHECK(std::abs(out[k].z() - in[k].z()) <= h[2]);
      largest_x = (std::max)(largest_x, std::abs(out[k].x() - in[k].x()));
      largest_z = (std::max)(largest_z, std::abs(out[k].z() - in[k].z()));
    }
    CHECK(largest_x == h[0]);    // the box binds ...
    CHECK(largest_z > 2 * h[0]); // ... and its long axis is used
  }
  {
    // Cells of size 2 eps x 2 eps x 6 eps on a grid; each vertex's box is its cell, the centre
    // of which is not the vertex.
    Mesh m = noisy_sphere();
    auto centre = m.add_property_map<vertex_descriptor, Point>("v:centre").first;
    auto extents = m.add_property_map<vertex_descriptor, std::array<double, 3> >("v:extents").first;
    const std::array<double, 3> cell{2 * eps, 2 * eps, 6 * eps};
    for(auto v : vertices(m))
    {
      const Point p = m.point(v);
      put(centre, v, Point((std::floor(p.x() / cell[0]) + 0.5) * cell[0], (std::floor(p.y() / cell[1]) + 0.5) * cell[1],
                           (std::floor(p.z() / cell[2]) + 0.5) * cell[2]));
      put(extents, v, std::array<double, 3>{cell[0] / 2, cell[1] / 2, cell[2] / 2});
    }
    const auto result =
      PMP::constrained_fairing(m, 1.0, CFP::vertex_box_center_map(centre, CFP::vertex_box_half_extents_map(extents)));
    CHECK(result);
    CHECK(result.final_energy < 0.5 * result.initial_energy);
    for(auto v : vertices(m))
    {
      const Point c = get(centre, v), p = m.point(v);
      CHECK(std::abs(p.x() - c.x()) <= cell[0] / 2 && std::abs(p.y() - c.y()) <= cell[1] / 2 &&
            std::abs(p.z() - c.z()) <= cell[2] / 2);
    }
    // A centre that leaves the input outside its box is refused, the mesh untouched.
    Mesh bad = noisy_sphere();
    auto bad_centre = bad.add_property_map<vertex_descriptor, Point>("v:centre").first;
    for(auto v : vertices(bad))
      put(bad_centre, v, bad.point(v));
    put(bad_centre, *std::next(vertices(bad).begin(), 5), Point(10, 10, 10));
    const std::vector<Point> before = test::points(bad);
    const auto refused = PMP::constrained_fairing(bad, 1.0, CFP::vertex_box_center_map(bad_centre, CFP::box_half_extents(cell)));
    CHECK(refused.status == Constrained_fairing_status::INVALID_INPUT);
    CHECK(refused.message == "vertex 5 lies outside its box");
    CHECK(refused.defect == PMP::Constrained_fairing_defect::OUTSIDE_BOX);
    CHECK(test::identical(test::points(bad), before));
  }
}

// Fixed vertices do not move, bit for bit, and their hinges still count.
void check_fixed_vertices()
{
  Mesh m = noisy_sphere();
  const std::vector<Point> in = test::points(m);
  auto fixed = m.add_property_map<vertex_descriptor, bool>("v:fixed", false).first;
  std::size_t k = 0, number_fixed = 0;
  for(auto v : vertices(m))
    if(in[k++].z() > 0.3)
    {
      put(fixed, v, true);
      ++number_fixed;
    }
  const double energy_before = energy_of(m);
  const auto result = PMP::constrained_fairing(m, eps, CGAL::parameters::vertex_is_constrained_map(fixed));
  CHECK(result);
  CHECK(result.initial_energy == energy_before);
  CHECK(result.number_of_fixed_vertices == number_fixed);
  CHECK(result.final_energy < result.initial_energy);
  k = 0;
  std::size_t moved = 0;
  for(auto v : vertices(m))
  {
    if(get(fixed, v))
      CHECK(identical(m.point(v), in[k]));
    else
      moved += !identical(m.point(v), in[k]);
    ++k;
  }
  CHECK(moved > (num_vertices(m) - number_fixed) / 2);

  // Fixed vertices with per-vertex boxes: their boxes are not read, and they still stay.
  Mesh boxed = noisy_sphere();
  auto boxed_fixed = boxed.add_property_map<vertex_descriptor, bool>("v:fixed", false).first;
  auto extents = boxed.add_property_map<vertex_descriptor, std::array<double, 3> >("v:extents").first;
  k = 0;
  for(auto v : vertices(boxed))
  {
    put(boxed_fixed, v, in[k++].z() > 0.3);
    put(extents, v, std::array<double, 3>{eps, eps, 2 * eps});
  }
  const auto boxed_result = PMP::constrained_fairing(
    boxed, 2 * eps, CFP::vertex_box_half_extents_map(extents, CGAL::parameters::vertex_is_constrained_map(boxed_fixed)));
  CHECK(boxed_result && boxed_result.number_of_fixed_vertices == number_fixed);
  k = 0;
  for(auto v : vertices(boxed))
  {
    const Point p = boxed.point(v), p0 = in[k++];
    if(get(boxed_fixed, v))
      CHECK(identical(p, p0));
    else
      CHECK(std::abs(p.x() - p0.x()) <= eps && std::abs(p.y() - p0.y()) <= eps && std::abs(p.z() - p0.z()) <= 2 * eps);
  }
  CHECK(std::abs(energy_of(m) - result.final_energy) <= 1e-12 * result.final_energy); // summed in another order
}

// Only a region moves; everything else, its border included, is bit-identical; the whole
// mesh's energy falls; the region of all faces is the whole mesh.
void check_region()
{
  Mesh m = noisy_sphere();
  const std::vector<Point> in = test::points(m);
  std::vector<boost::graph_traits<Mesh>::face_descriptor> cap;
  for(auto f : faces(m))
    if(m.point(target(halfedge(f, m), m)).z() > 0.2)
      cap.push_back(f);
  auto outside = m.add_property_map<vertex_descriptor, bool>("v:outside", false).first;
  for(auto f : faces(m))
    for(auto v : vertices_around_face(halfedge(f, m), m))
      put(outside, v, get(outside, v) || std::find(cap.begin(), cap.end(), f) == cap.end());
  const double energy_before = energy_of(m);
  const auto result = PMP::constrained_fairing(cap, m, eps);
  CHECK(result);
  CHECK(result.initial_energy < energy_before);
  CHECK(result.final_energy < result.initial_energy);
  CHECK(energy_of(m) < energy_before - (result.initial_energy - result.final_energy) * (1 - 1e-9));
  std::size_t k = 0, moved = 0, inner = 0;
  for(auto v : vertices(m))
  {
    if(get(outside, v))
      CHECK(identical(m.point(v), in[k]));
    else
    {
      ++inner;
      moved += !identical(m.point(v), in[k]);
      CHECK(test::bound_violation(std::vector<Point>{m.point(v)}, std::vector<Point>{in[k]}, eps, Deviation_bound::BALL) <= 0);
    }
    ++k;
  }
  CHECK(inner > 50 && moved > inner / 2);

  // An empty face range does nothing, and says so.
  Mesh untouched = noisy_sphere();
  const auto none = PMP::constrained_fairing(std::vector<boost::graph_traits<Mesh>::face_descriptor>(), untouched, eps);
  CHECK(none.status == Constrained_fairing_status::CONVERGED && none.number_of_iterations == 0);
  CHECK(test::identical(test::points(untouched), test::points(noisy_sphere())));

  Mesh whole = noisy_sphere(), region = noisy_sphere();
  const auto a = PMP::constrained_fairing(whole, eps);
  const auto b = PMP::constrained_fairing(faces(region), region, eps);
  CHECK(a && b && a.final_energy == b.final_energy && a.number_of_iterations == b.number_of_iterations);
  CHECK(test::identical(test::points(whole), test::points(region)));
}

// Bad per-vertex values: a clear error naming the vertex, the mesh untouched.
void check_bad_values()
{
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for(double bad : {-1e-3, nan, inf})
  {
    Mesh m = noisy_sphere();
    const std::vector<Point> before = test::points(m);
    auto tolerance = m.add_property_map<vertex_descriptor, double>("v:tolerance", eps).first;
    put(tolerance, *std::next(vertices(m).begin(), 17), bad);
    const auto result = PMP::constrained_fairing(m, eps, CFP::vertex_tolerance_map(tolerance));
    CHECK(result.status == Constrained_fairing_status::INVALID_INPUT);
    CHECK(result.message.find("vertex 17 has a negative, NaN or infinite tolerance") == 0);
    CHECK(result.defect == PMP::Constrained_fairing_defect::INVALID_TOLERANCE);
    CHECK(test::identical(test::points(m), before));

    auto extents = m.add_property_map<vertex_descriptor, std::array<double, 3> >("v:extents").first;
    for(auto v : vertices(m))
      put(extents, v, std::array<double, 3>{eps, eps, eps});
    put(extents, *std::next(vertices(m).begin(), 3), std::array<double, 3>{eps, bad, eps});
    const auto box = PMP::constrained_fairing(m, eps, CFP::vertex_box_half_extents_map(extents));
    CHECK(box.status == Constrained_fairing_status::INVALID_INPUT);
    CHECK(box.message.find("the box half-extents of vertex 3 must be finite and non-negative") == 0);
    CHECK(box.defect == PMP::Constrained_fairing_defect::INVALID_BOX_EXTENTS);
    CHECK(test::identical(test::points(m), before));

    const auto global = PMP::constrained_fairing(m, eps, CFP::box_half_extents(std::array<double, 3>{eps, eps, bad}));
    CHECK(global.status == Constrained_fairing_status::INVALID_INPUT);
    CHECK(global.defect == PMP::Constrained_fairing_defect::INVALID_BOX_EXTENTS);
    CHECK(test::identical(test::points(m), before));

    if(!std::isfinite(bad))
    {
      auto centre = m.add_property_map<vertex_descriptor, Point>("v:centre").first;
      for(auto v : vertices(m))
        put(centre, v, m.point(v));
      put(centre, *std::next(vertices(m).begin(), 4), Point(0, bad, 0));
      const auto centred = PMP::constrained_fairing(m, eps, CFP::vertex_box_center_map(centre));
      CHECK(centred.defect == PMP::Constrained_fairing_defect::INVALID_BOX_CENTER);
      CHECK(centred.message.find("the box centre of vertex 4 has a NaN or infinite coordinate") == 0);
      CHECK(test::identical(test::points(m), before));
      m.remove_property_map(centre);
    }
  }
  Mesh m = noisy_sphere();
  const std::vector<Point> before = test::points(m);
  const auto mixed = PMP::constrained_fairing(
    m, eps, CFP::deviation_bound(Deviation_bound::BALL, CFP::box_half_extents(std::array<double, 3>{eps, eps, eps})));
  CHECK(mixed.status == Constrained_fairing_status::INVALID_INPUT);
  CHECK(mixed.message == "box half-extents or centres were given with the ball bound");
  CHECK(mixed.defect == PMP::Constrained_fairing_defect::BOX_WITH_BALL);
  CHECK(test::identical(test::points(m), before));
}

int main()
{
  check_vertex_tolerance();
  check_boxes();
  check_fixed_vertices();
  check_region();
  check_bad_values();
  return test::report("test_tolerance_control");
}
