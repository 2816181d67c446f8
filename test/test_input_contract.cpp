// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every defect of the input contract, one by one: the call returns INVALID_INPUT with a message
// naming the defect and the element, and leaves the mesh bit-identical; the public check of a
// mesh (constrained_fairing_mesh_error()) names the same defect in the same words where the mesh
// itself breaks the contract, and none where its values do. The public check of a polygon soup
// names each defect that keeps a soup from becoming a mesh, in the words of the mesh's check,
// and accepts exactly the soups that CGAL's is_polygon_soup_a_polygon_mesh() accepts. Isolated
// vertices are allowed and do not move. A negative stopping threshold is a precondition.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_input_check.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <CGAL/exceptions.h>

#include <array>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using PMP::Constrained_fairing_status;
using test::Mesh;
using test::Point;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;
using halfedge_descriptor = boost::graph_traits<Mesh>::halfedge_descriptor;

// Connectivity alone, compared element by element.
bool same_connectivity(const Mesh& a, const Mesh& b)
{
  if(num_vertices(a) != num_vertices(b) || num_halfedges(a) != num_halfedges(b) || num_faces(a) != num_faces(b))
    return false;
  auto hb = halfedges(b).begin();
  for(halfedge_descriptor h : halfedges(a))
  {
    const halfedge_descriptor g = *hb++;
    if(target(h, a) != target(g, b) || next(h, a) != next(g, b) || face(h, a) != face(g, b))
      return false;
  }
  return true;
}

// Fairs a copy of m, expects INVALID_INPUT of the kind `defect` with `expected` in the message,
// and the copy unchanged.
void check_rejected(const Mesh& m, PMP::Constrained_fairing_defect defect, const std::string& expected,
                    double eps = 0.1)
{
  Mesh copy = m;
  const auto r = PMP::constrained_fairing(copy, eps);
  std::cout << "  \"" << r.message << "\"" << std::endl;
  CHECK(!r && r.status == Constrained_fairing_status::INVALID_INPUT);
  CHECK(r.defect == defect);
  CHECK(r.message.find(expected) != std::string::npos);
  CHECK(r.number_of_iterations == 0);
  CHECK(test::identical(test::points(copy), test::points(m)));
  CHECK(same_connectivity(copy, m));
  const PMP::Constrained_fairing_input_error own = PMP::constrained_fairing_mesh_error(m);
  const bool of_the_mesh = defect <= PMP::Constrained_fairing_defect::MESH_TOO_LARGE;
  CHECK(own.defect == (of_the_mesh ? defect : PMP::Constrained_fairing_defect::NONE));
  CHECK(own.message == (of_the_mesh ? r.message : std::string()));
}

// The triangle (a, b, c) with three edges of its own, whose other sides are border: the faces
// that add_face() refuses to glue (an edge with three faces, a face reversed against its
// neighbour) share vertices this way.
void add_detached_triangle(Mesh& m, std::array<vertex_descriptor, 3> v)
{
  const auto f = add_face(m);
  std::array<halfedge_descriptor, 3> h, o;
  for(int k = 0; k < 3; ++k)
  {
    h[k] = halfedge(add_edge(m), m);
    o[k] = opposite(h[k], m);
    set_target(h[k], v[(k + 1) % 3], m);
    set_target(o[k], v[k], m);
    set_face(h[k], f, m);
    set_face(o[k], boost::graph_traits<Mesh>::null_face(), m);
  }
  for(int k = 0; k < 3; ++k)
  {
    set_next(h[k], h[(k + 1) % 3], m);
    set_next(o[(k + 1) % 3], o[k], m);
    if(halfedge(v[k], m) == boost::graph_traits<Mesh>::null_halfedge())
      set_halfedge(v[k], o[k], m);
  }
  set_halfedge(f, h[0], m);
}

// A noisy patch of the plane, 4 x 4 vertices.
Mesh patch()
{
  Mesh m = test::plane_patch(4);
  test::add_noise(m, 0.05, 31);
  return m;
}

void check_epsilon()
{
  const Mesh m = patch();
  for(double eps : {0.0, -0.1, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                    -std::numeric_limits<double>::infinity()})
    check_rejected(m, PMP::Constrained_fairing_defect::INVALID_EPSILON, "epsilon must be a positive finite number", eps);
}

void check_empty()
{
  check_rejected(Mesh(), PMP::Constrained_fairing_defect::EMPTY_MESH, "the mesh is empty");
  Mesh points_only;
  points_only.add_vertex(Point(0, 0, 0));
  points_only.add_vertex(Point(1, 0, 0));
  check_rejected(points_only, PMP::Constrained_fairing_defect::NO_FACES, "the mesh has no faces");
}

// Adds these vertices to m, in order.
std::vector<vertex_descriptor> add_vertices(Mesh& m, std::initializer_list<Point> points)
{
  std::vector<vertex_descriptor> v;
  for(const Point& p : points)
    v.push_back(m.add_vertex(p));
  return v;
}

void check_non_triangle_face()
{
  Mesh m = patch();
  for(auto e : edges(m))
    if(!is_border(e, m))
    {
      CGAL::Euler::join_face(halfedge(e, m), m);
      break;
    }
  check_rejected(m, PMP::Constrained_fairing_defect::NOT_TRIANGLE, "has 4 vertices: the mesh must be made of triangles");
  Mesh pentagon;
  pentagon.add_face(add_vertices(pentagon, {Point(1, 0, 0), Point(0.3, 0.95, 0), Point(-0.8, 0.6, 0), Point(-0.8, -0.6, 0),
                                            Point(0.3, -0.95, 0)}));
  check_rejected(pentagon, PMP::Constrained_fairing_defect::NOT_TRIANGLE, "face 0 has 5 vertices");
}

void check_non_manifold_vertex()
{
  // Two triangles that touch at vertex 0 only.
  Mesh m;
  const auto v = add_vertices(m, {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(-1, 0, 0.1), Point(0, -1, 0.1)});
  CHECK(m.add_face(v[0], v[1], v[2]) != Mesh::null_face());
  CHECK(m.add_face(v[0], v[3], v[4]) != Mesh::null_face());
  check_rejected(m, PMP::Constrained_fairing_defect::NON_MANIFOLD_VERTEX, "vertex 0 is non-manifold");
}

void check_non_manifold_edge()
{
  // A fin: a third triangle on the edge between vertices 0 and 1 of a glued pair.
  Mesh m;
  auto v = add_vertices(m, {Point(0, 0, 0), Point(1, 0, 0), Point(0.5, 1, 0), Point(0.5, -1, 0), Point(0.5, 0, 1)});
  m.add_face(v[0], v[1], v[2]);
  m.add_face(v[1], v[0], v[3]);
  add_detached_triangle(m, {v[0], v[1], v[4]});
  check_rejected(m, PMP::Constrained_fairing_defect::NON_MANIFOLD_EDGE, "the edge between vertices 0 and 1 has 3 faces (a non-manifold edge)");

  // Two faces through the same two vertices, by two different edges.
  Mesh seam;
  v = add_vertices(seam, {Point(0, 0, 0), Point(1, 0, 0), Point(0.5, 1, 0), Point(0.5, -1, 0)});
  seam.add_face(v[0], v[1], v[2]);
  add_detached_triangle(seam, {v[1], v[0], v[3]});
  check_rejected(seam, PMP::Constrained_fairing_defect::NON_MANIFOLD_EDGE, "through two different edges (a non-manifold edge)");
}

void check_inconsistent_orientation()
{
  // The second triangle runs along the shared edge in the same direction as the first.
  Mesh m;
  const auto v = add_vertices(m, {Point(0, 0, 0), Point(1, 0, 0), Point(0.5, 1, 0), Point(0.5, -1, 0)});
  m.add_face(v[0], v[1], v[2]);
  add_detached_triangle(m, {v[0], v[1], v[3]});
  check_rejected(m, PMP::Constrained_fairing_defect::INCONSISTENT_ORIENTATION, "faces 0 and 1 are oriented inconsistently: both run from vertex 0 to vertex 1");
}

void check_broken_structure()
{
  Mesh m = patch();
  // A halfedge that is its own next: next() no longer matches prev().
  const halfedge_descriptor h = halfedge(*faces(m).begin(), m);
  set_next(h, h, m);
  check_rejected(m, PMP::Constrained_fairing_defect::BROKEN_STRUCTURE, "the mesh's halfedge structure is broken");
}

void check_non_finite_coordinates()
{
  for(double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
  {
    Mesh m = patch();
    m.point(*std::next(vertices(m).begin(), 6)) = Point(0.3, bad, 0);
    check_rejected(m, PMP::Constrained_fairing_defect::NON_FINITE_COORDINATE, "vertex 6 has a NaN or infinite coordinate");
  }
}

void check_no_area()
{
  Mesh m = patch();
  for(auto v : vertices(m))
    m.point(v) = Point(m.point(v).x(), 0, 0); // every vertex on the x axis
  check_rejected(m, PMP::Constrained_fairing_defect::NO_AREA, "all triangles of the mesh have zero area");
}

void check_isolated_vertices()
{
  Mesh m = patch();
  const auto isolated = m.add_vertex(Point(5, 5, 5));
  const std::vector<Point> input = test::points(m);
  const auto r = PMP::constrained_fairing(m, 0.05);
  CHECK(r && r.final_energy < r.initial_energy);
  CHECK(m.point(isolated) == Point(5, 5, 5));
  CHECK(!test::identical(test::points(m), input));
}

void check_threshold_precondition()
{
  Mesh m = patch();
  const std::vector<Point> input = test::points(m);
#ifdef CGAL_NO_PRECONDITIONS
  // Release builds: a negative threshold never stops the iterations.
  const auto r = PMP::constrained_fairing(m, 0.05, CFP::energy_decrease_threshold(-1.0).number_of_iterations(4));
  CHECK(r.status == Constrained_fairing_status::ITERATION_LIMIT_REACHED && r.number_of_iterations == 4);
#else
  bool thrown = false;
  try
  {
    PMP::constrained_fairing(m, 0.05, CFP::energy_decrease_threshold(-1.0));
  }
  catch(const CGAL::Precondition_exception&)
  {
    thrown = true;
  }
  CHECK(thrown);
  CHECK(test::identical(test::points(m), input));
#endif
}

// The soup `polygons` of `n` points: named `defect`, with `expected` in the message, or accepted,
// as CGAL's own test of a soup says.
void check_soup(std::size_t n, const std::vector<std::vector<std::size_t> >& polygons,
                PMP::Constrained_fairing_defect defect, const std::string& expected)
{
  const PMP::Constrained_fairing_input_error error = PMP::constrained_fairing_polygon_soup_error(n, polygons);
  std::cout << "  \"" << error.message << "\"" << std::endl;
  CHECK(error.defect == defect);
  CHECK(error.message.find(expected) != std::string::npos);
  CHECK(bool(error) == (defect != PMP::Constrained_fairing_defect::NONE));
  const bool indices_exist = defect != PMP::Constrained_fairing_defect::INVALID_FACE;
  if(indices_exist)
    CHECK(!error == PMP::is_polygon_soup_a_polygon_mesh(polygons));
}

void check_polygon_soups()
{
  using D = PMP::Constrained_fairing_defect;
  check_soup(5, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4, 1}}, D::NONE, "");
  check_soup(3, {{0, 1}}, D::INVALID_FACE, "face 0 has 2 vertices");
  check_soup(3, {{0, 1, 2}, {0, 1, 3}}, D::INVALID_FACE, "face 1 refers to vertex 3, but there are 3 vertices");
  check_soup(3, {{0, 1, 2}, {2, 1, 1}}, D::INVALID_FACE, "face 1 refers to vertex 1 twice");
  check_soup(5, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}, D::NON_MANIFOLD_EDGE,
             "the edge between vertices 0 and 1 has 3 faces (a non-manifold edge)");
  check_soup(4, {{0, 1, 2}, {0, 1, 3}}, D::INCONSISTENT_ORIENTATION,
             "faces 0 and 1 are oriented inconsistently: both run from vertex 0 to vertex 1");
  check_soup(5, {{0, 1, 2}, {0, 3, 4}}, D::NON_MANIFOLD_VERTEX, "vertex 0 is non-manifold");
  // The mesh of an accepted soup is the mesh that the call and the mesh's check accept.
  const std::vector<Point> points{Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0.2), Point(0, 1, 0), Point(-1, 0.5, 0)};
  const std::vector<std::vector<std::size_t> > polygons{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
  Mesh m;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, m);
  CHECK(!PMP::constrained_fairing_mesh_error(m) && PMP::constrained_fairing(m, 0.1));
}

int main()
{
  check_epsilon();
  check_empty();
  check_non_triangle_face();
  check_non_manifold_vertex();
  check_non_manifold_edge();
  check_inconsistent_orientation();
  check_broken_structure();
  check_non_finite_coordinates();
  check_no_area();
  check_isolated_vertices();
  check_threshold_precondition();
  check_polygon_soups();
  return test::report("test_input_contract");
}
