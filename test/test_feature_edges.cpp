// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Creases kept sharp: on a noisy cube, a noisy closed cylinder and a noisy octagonal prism
// (its sides 45 degrees apart, a chamfer's angle), feature_angle(30) finds at
// least 90 % of the clean mesh's sharp edges, with at most 5 % of what it finds not sharp, and
// its normals end 4 times closer to the clean ones than those of the call without creases, which
// rounds them; the edges it found, given in edge_is_constrained_map, give the same result bit for
// bit, and the map is not written without the angle; short curves are dropped from the detection,
// and curves that detour by a triangle or around a vertex straightened;
// the detection and the result are bit-identical with one thread and with four; bad angles are
// rejected with the mesh and the map untouched.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/generators.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
namespace CF = PMP::internal::Constrained_fairing;
using test::Mesh;
using test::Point;
using Edge_flags = Mesh::Property_map<Mesh::Edge_index, bool>;

namespace {

// The closed polyhedron `m` triangulated and remeshed to edges of about `length`, its edges
// sharper than 30 degrees kept; those edges are marked in the returned map.
Edge_flags remeshed_with_sharp_edges(Mesh& m, double length)
{
  PMP::triangulate_faces(m);
  Edge_flags sharp = m.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
  PMP::detect_sharp_edges(m, 30, sharp);
  PMP::isotropic_remeshing(faces(m), length, m, CGAL::parameters::number_of_iterations(3).edge_is_constrained_map(sharp));
  m.collect_garbage();
  for(auto e : edges(m))
    sharp[e] = false;
  PMP::detect_sharp_edges(m, 30, sharp);
  return sharp;
}

Mesh cube()
{
  Mesh m;
  CGAL::make_hexahedron(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0), Point(0, 1, 1), Point(0, 0, 1),
                        Point(1, 0, 1), Point(1, 1, 1), m);
  return m;
}

// A closed cylinder of radius 1 and height 2 whose sides are 64 flat facets (5.6 degrees
// apart, well under the angle): its sharp edges are the rims.
Mesh cylinder()
{
  Mesh m;
  CGAL::make_regular_prism(64, m, Point(0, 0, 0), 2., 1., true);
  return m;
}

// A closed prism of height 1 over a regular octagon of radius 1: its sides turn by 45 degrees.
Mesh octagonal_prism()
{
  Mesh m;
  CGAL::make_regular_prism(8, m, Point(0, 0, 0), 1., 1., true);
  return m;
}

double largest_normal_error(const Mesh& result, const Mesh& clean)
{
  double largest = 0;
  for(auto f : faces(clean))
  {
    const auto n = PMP::compute_face_normal(f, result), c = PMP::compute_face_normal(f, clean);
    largest = (std::max)(largest, std::acos((std::min)(1., n * c)) * 180 / CGAL_PI);
  }
  return largest;
}

// The bound as users check it, in double.
bool ball_holds(const Mesh& result, const Mesh& input, double eps)
{
  for(auto v : vertices(result))
  {
    const double d2 = CGAL::squared_distance(result.point(v), input.point(v));
    if(!(d2 <= eps * eps && std::sqrt(d2) <= eps))
      return false;
  }
  return true;
}

bool same_points(const Mesh& a, const Mesh& b)
{
  for(auto v : vertices(a))
    if(a.point(v) != b.point(v))
      return false;
  return true;
}

double mean_normal_error(const Mesh& result, const Mesh& clean)
{
  double sum = 0;
  for(auto f : faces(clean))
  {
    const auto n = PMP::compute_face_normal(f, result), c = PMP::compute_face_normal(f, clean);
    sum += std::acos((std::min)(1., n * c)) * 180 / CGAL_PI;
  }
  return sum / double(num_faces(clean));
}

void check_creases(Mesh clean, double length, const char* name)
{
  const Edge_flags sharp = remeshed_with_sharp_edges(clean, length);
  std::size_t sharp_count = 0;
  for(auto e : edges(clean))
    sharp_count += sharp[e];
  const double h = Constrained_fairing_front_end::mean_edge_length(clean);
  Mesh noisy = clean;
  test::add_noise(noisy, 0.25 * h, 7);
  const double eps = 0.25 * h;

  // The call without creases rounds them.
  Mesh rounded = noisy;
  CHECK(PMP::constrained_fairing(rounded, eps));
  const double rounded_error = mean_normal_error(rounded, clean);

  // Detected: at least 90 % of the clean sharp edges, at most 5 % of the found edges not sharp,
  // all of them written in the map; the normals 4 times closer to the clean ones.
  Mesh detected = noisy;
  Edge_flags found = detected.add_property_map<Mesh::Edge_index, bool>("e:found", false).first;
  const auto r = PMP::constrained_fairing(detected, eps, CFP::feature_angle(30., CGAL::parameters::edge_is_constrained_map(found)));
  CHECK(r);
  std::size_t found_count = 0, found_sharp = 0;
  for(auto e : edges(detected))
  {
    found_count += found[e];
    found_sharp += found[e] && sharp[e];
  }
  CHECK(r.number_of_feature_edges == found_count);
  CHECK(double(found_sharp) >= 0.9 * double(sharp_count));
  CHECK(double(found_count - found_sharp) <= 0.05 * double(found_count));
  const double error = mean_normal_error(detected, clean);
  CHECK(error <= 0.25 * rounded_error);
  CHECK(ball_holds(detected, noisy, eps));
  std::cout << name << ": " << num_faces(clean) << " faces, " << sharp_count << " sharp edges, " << found_count << " found ("
            << found_sharp << " sharp); mean normal error " << error << " degrees (" << rounded_error
            << " without creases), largest " << largest_normal_error(detected, clean) << std::endl;

  // Given: the same creases, the same result bit for bit; without the angle the map is not
  // written.
  Mesh given = noisy;
  Edge_flags marks = given.add_property_map<Mesh::Edge_index, bool>("e:marks", false).first;
  for(auto e : edges(given))
    marks[e] = found[e];
  const auto g = PMP::constrained_fairing(given, eps, CGAL::parameters::edge_is_constrained_map(marks));
  CHECK(g && g.number_of_feature_edges == found_count);
  CHECK(same_points(given, detected));
  std::size_t unchanged = 0;
  for(auto e : edges(given))
    unchanged += marks[e] == found[e];
  CHECK(unchanged == num_edges(given));
}

// Spurs and isolated lines of fewer than 8 edges, closed curves and clusters of fewer are
// dropped; longer ones and what joins them stay.
void check_short_curves()
{
  std::vector<std::array<CF::Index, 2> > edges;
  const auto path = [&edges](CF::Index first, CF::Index count) {
    for(CF::Index k = 0; k < count; ++k)
      edges.push_back(CF::sorted_edge(first + k, first + k + 1));
  };
  path(0, 20);   // a line of 20 edges: stays
  path(100, 3);  // a spur of 3 edges off vertex 10: dropped
  edges.push_back(CF::sorted_edge(10, 100));
  path(200, 5);  // an isolated line of 6 edges: dropped
  edges.push_back(CF::sorted_edge(205, 206));
  path(300, 2);  // a triangle: dropped
  edges.push_back(CF::sorted_edge(300, 302));
  path(400, 9);  // a closed curve of 10 edges: stays
  edges.push_back(CF::sorted_edge(400, 409));
  path(600, 2);  // a diamond of 5 edges, two vertices of degree 3: dropped
  for(CF::Index v : {600, 602})
    edges.push_back(CF::sorted_edge(v, 603));
  edges.push_back(CF::sorted_edge(600, 602));
  std::sort(edges.begin(), edges.end());
  CF::drop_short_curves(edges, CF::Feature_detection::shortest_spur);
  CHECK(edges.size() == 30);
  for(const auto& e : edges)
    CHECK(e[1] <= 20 || (e[0] >= 400 && e[1] < 410));
}

// As test_projected_lbfgs's check, with creases: a cube of 19,200 faces, more than four blocks
// of the parallel loops over faces, edges and vertices, four threads asked for whatever the
// machine has. Without TBB the loops are sequential: the check says it is skipped.
void check_thread_count_independence()
{
#ifdef CGAL_LINKED_WITH_TBB
  Mesh noisy = test::grid_cube(40);
  const double eps = 0.25 / 40;
  test::add_noise(noisy, eps, 11);
  Mesh one = noisy, four = noisy;
  Edge_flags found_one = one.add_property_map<Mesh::Edge_index, bool>("e:found", false).first;
  Edge_flags found_four = four.add_property_map<Mesh::Edge_index, bool>("e:found", false).first;
  const auto call = [&](Mesh& m, Edge_flags found) {
    return PMP::constrained_fairing(
      m, eps, CFP::feature_angle(30., CGAL::parameters::edge_is_constrained_map(found).number_of_iterations(40)));
  };
  PMP::Constrained_fairing_result r_one, r_four;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    r_one = call(one, found_one);
  }
  int threads = 0;
  {
    tbb::global_control several(tbb::global_control::max_allowed_parallelism, 4);
    tbb::task_arena arena(4);
    arena.execute([&] {
      threads = tbb::this_task_arena::max_concurrency();
      r_four = call(four, found_four);
    });
  }
  if(threads < 2)
  {
    std::cout << "  SKIPPED: thread-count independence, TBB gave " << threads << " thread" << std::endl;
    return;
  }
  CHECK(r_one && r_four && r_one.number_of_feature_edges > 0);
  CHECK(r_one.number_of_feature_edges == r_four.number_of_feature_edges);
  CHECK(r_one.final_energy == r_four.final_energy && r_one.number_of_iterations == r_four.number_of_iterations);
  CHECK(same_points(one, four));
  std::size_t same_marks = 0;
  for(auto e : edges(one))
    same_marks += found_one[e] == found_four[e];
  CHECK(same_marks == num_edges(one));
  std::cout << "creases, one thread and " << threads << " threads: " << r_one.number_of_feature_edges
            << " edges, bit-identical" << std::endl;
#else
  std::cout << "  SKIPPED: thread-count independence, built without TBB (the loops are sequential)" << std::endl;
#endif
}

// An n x n patch of the plane of equilateral triangles: vertex (i, j) at (i + j / 2, j sqrt(3) / 2),
// each cell cut along its diagonal from (i + 1, j) to (i, j + 1); every inner vertex has six
// neighbours.
Mesh equilateral_patch(std::size_t n)
{
  Mesh m;
  std::vector<Mesh::Vertex_index> v;
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i)
      v.push_back(m.add_vertex(Point(double(i) + 0.5 * double(j), std::sqrt(3.) / 2 * double(j), 0)));
  for(std::size_t j = 0; j + 1 < n; ++j)
    for(std::size_t i = 0; i + 1 < n; ++i)
    {
      const auto a = v[j * n + i], b = v[j * n + i + 1], c = v[(j + 1) * n + i + 1], d = v[(j + 1) * n + i];
      m.add_face(a, b, d);
      m.add_face(b, c, d);
    }
  return m;
}

// A line along row 5 of an equilateral patch that detours by a triangle is straightened,
// wherever the detour is, and so is one that detours around a vertex of the row; a corner of the
// curve is kept; a jog round a vertex takes the vertex when it is clearly nearer the line, and of
// two paths of a jog found at once the farther is dropped.
void check_straightening()
{
  constexpr std::size_t n = 12;
  const Mesh patch = equilateral_patch(n);
  const CF::Hinge_mesh mesh(patch, get(CGAL::vertex_index, patch));
  CF::Points X(num_vertices(patch), 3);
  for(auto v : vertices(patch))
    X.row(v.idx()) << patch.point(v).x(), patch.point(v).y(), patch.point(v).z();
  using Edges = std::vector<std::array<CF::Index, 2> >;
  const auto at = [](std::size_t i, std::size_t j) { return CF::Index(j * n + i); };
  const auto path = [&](std::initializer_list<std::array<std::size_t, 2> > points, Edges edges) {
    for(auto p = points.begin(); p + 1 != points.end(); ++p)
      edges.push_back(CF::sorted_edge(at((*p)[0], (*p)[1]), at((*(p + 1))[0], (*(p + 1))[1])));
    std::sort(edges.begin(), edges.end());
    return edges;
  };
  const auto without = [&](Edges edges, std::size_t first, std::size_t last) {
    edges.erase(std::remove_if(edges.begin(), edges.end(),
                               [&](const auto& e) {
                                 for(std::size_t i = first; i < last; ++i)
                                   if(e == CF::sorted_edge(at(i, 5), at(i + 1, 5)))
                                     return true;
                                 return false;
                               }),
                edges.end());
    return edges;
  };
  const auto straightened = [&](Edges edges) {
    CF::straighten_creases(mesh, X, [](CF::Index) { return Eigen::Vector3d(0, 0, 1); }, 30., edges);
    return edges;
  };
  Edges line;
  for(std::size_t i = 0; i + 1 < n; ++i)
    line = path({{i, 5}, {i + 1, 5}}, line);
  CHECK(straightened(line) == line);
  for(std::size_t i = 1; i + 2 < n; ++i)
  {
    // by the triangle above edge i, and by the one below it
    CHECK(straightened(path({{i, 5}, {i, 6}, {i + 1, 5}}, without(line, i, i + 1))) == line);
    CHECK(straightened(path({{i, 5}, {i + 1, 4}, {i + 1, 5}}, without(line, i, i + 1))) == line);
  }
  // around (5, 5), above it and below it
  CHECK(straightened(path({{4, 5}, {4, 6}, {5, 6}, {6, 5}}, without(line, 4, 6))) == line);
  CHECK(straightened(path({{4, 5}, {5, 4}, {6, 4}, {6, 5}}, without(line, 4, 6))) == line);
  // a corner: along row 5 to (6, 5), then up towards (6, 11), and then a sharper one
  const Edges corner = path({{0, 5}, {1, 5}, {2, 5}, {3, 5}, {4, 5}, {5, 5}, {6, 5}, {6, 6}, {6, 7}, {6, 8}, {6, 9}}, {});
  CHECK(straightened(corner) == corner);
  const Edges sharper = path({{0, 5}, {1, 5}, {2, 5}, {3, 5}, {4, 5}, {5, 5}, {6, 5}, {5, 6}, {4, 7}, {3, 8}, {2, 9}}, {});
  CHECK(straightened(sharper) == sharper);
  // a jog from row 5 to row 6, through (5, 5) or round it by (4, 6): either kept where the two
  // are as far from the line from (4, 5) to (5, 6), the one through (5, 5) taken where it is
  // clearly the nearer
  const Edges jog = path({{0, 5}, {1, 5}, {2, 5}, {3, 5}, {4, 5}, {5, 5}, {5, 6}, {6, 6}, {7, 6}, {8, 6}, {9, 6}, {10, 6}}, {});
  const Edges round = path({{0, 5}, {1, 5}, {2, 5}, {3, 5}, {4, 5}, {4, 6}, {5, 6}, {6, 6}, {7, 6}, {8, 6}, {9, 6}, {10, 6}}, {});
  CHECK(straightened(jog) == jog);
  CHECK(straightened(round) == round);
  X.row(at(5, 5)) += 0.3 * Eigen::RowVector3d(-0.5, std::sqrt(3.) / 2, 0);
  CHECK(straightened(round) == jog);
  CHECK(straightened(jog) == jog);
  // both paths at once (a diamond): the one farther from the line dropped
  Edges both = jog;
  both.insert(both.end(), round.begin(), round.end());
  std::sort(both.begin(), both.end());
  both.erase(std::unique(both.begin(), both.end()), both.end());
  CHECK(both.size() == jog.size() + 2);
  CHECK(straightened(both) == jog);

  // The same jog on a roof whose ridge runs through (4, 5) and (5, 6), between (5, 5) and (4, 6):
  // the sides' planes 90 degrees apart, the face normals those of the planes (as filtered ones
  // are). Where (5, 5) is nearer the ridge along its side's plane, by less than `jog_ratio`, the
  // test across the crease takes the jog through it; where it is not nearer, or is nearer the
  // other side's plane but farther from the line, the jog is kept; the line alone (sides not
  // apart) keeps it too.
  const Eigen::Vector2d ridge = X.block<1, 2>(at(4, 5), 0).transpose();
  const Eigen::Vector2d along = (X.block<1, 2>(at(5, 6), 0).transpose() - ridge).normalized();
  const Eigen::Vector2d across(along.y(), -along.x());
  const auto side = [&](const Eigen::Vector2d& p) { return (p - ridge).dot(across); };
  CF::Points roof(X.rows(), 3);
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < n; ++j)
    {
      const Eigen::Vector2d p(double(i) + 0.5 * double(j), std::sqrt(3.) / 2 * double(j));
      roof.row(at(i, j)) << p.x(), p.y(), std::abs(side(p));
    }
  const auto plane_normal = [&](double s) {
    return Eigen::Vector3d(-s * across.x(), -s * across.y(), 1).normalized();
  };
  const auto roof_normal = [&](CF::Index f) {
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for(CF::Index v : mesh.triangles[f])
      c += roof.block<1, 2>(v, 0).transpose() / 3;
    return plane_normal(side(c) > 0 ? 1 : -1);
  };
  CHECK(side(roof.block<1, 2>(at(5, 5), 0).transpose()) > 0.49);
  CHECK(side(roof.block<1, 2>(at(4, 6), 0).transpose()) < -0.49);
  const auto on_roof = [&](const CF::Points& points, Edges edges) {
    CF::straighten_creases(mesh, points, roof_normal, 30., edges);
    return edges;
  };
  CHECK(on_roof(roof, round) == round);
  CF::Points nearer = roof;
  nearer.block<1, 2>(at(5, 5), 0) -= 0.15 * across.transpose();
  nearer(at(5, 5), 2) = 0.35;
  CHECK(on_roof(nearer, round) == jog);
  Edges by_line = round;
  CF::straighten_creases(mesh, nearer, [](CF::Index) { return Eigen::Vector3d(0, 0, 1); }, 30., by_line);
  CHECK(by_line == round);
  CF::Points lifted = roof;
  lifted.block<1, 2>(at(5, 5), 0) -= 0.4 * across.transpose();
  lifted(at(5, 5), 2) = 0.75;
  CHECK(on_roof(lifted, round) == round);
}

void check_bad_angles()
{
  Mesh clean = cube();
  remeshed_with_sharp_edges(clean, 0.25);
  test::add_noise(clean, 0.05, 3);
  for(double angle : {0., 180., -10., 200., std::numeric_limits<double>::quiet_NaN()})
  {
    Mesh m = clean;
    Edge_flags marks = m.add_property_map<Mesh::Edge_index, bool>("e:marks", false).first;
    const auto r = PMP::constrained_fairing(m, 0.05, CFP::feature_angle(angle, CGAL::parameters::edge_is_constrained_map(marks)));
    CHECK(r.status == PMP::Constrained_fairing_status::INVALID_INPUT);
    CHECK(r.defect == PMP::Constrained_fairing_defect::INVALID_FEATURE_ANGLE);
    CHECK(r.message.find("feature_angle") != std::string::npos);
    CHECK(same_points(m, clean));
    std::size_t marked = 0;
    for(auto e : edges(m))
      marked += marks[e];
    CHECK(marked == 0);
  }
}

} // namespace

int main()
{
  check_short_curves();
  check_straightening();
  check_bad_angles();
  check_thread_count_independence();
  check_creases(cube(), 0.08, "cube");
  check_creases(cylinder(), 0.15, "cylinder");
  check_creases(octagonal_prism(), 0.06, "octagonal prism");
  return test::report("test_feature_edges");
}
