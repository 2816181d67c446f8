// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Joint fairing of the interfaces of a label map (constrained_fairing_of_interfaces()), on a ball
// cut by a tilted plane into two labels, with a cap of a third label on part of it: interfaces
// with analytic true surfaces (a sphere, a plane), a triple line around the ball, points where
// four labels meet (the outside counts), cubic and 1 x 1 x 3 voxels. Checked:
//  - every point stays in its box (label_surface_nets()), exactly in double, and where four labels
//    meet it does not move at all;
//  - the objective does not rise, and the interfaces come closer to their true surfaces than the
//    raw surface nets: 4 times on the sphere, twice on the plane, 1.5 times on the triple line
//    (measured: 8.2 and 8.0, 3.7 and 2.9, 1.9 and 3.0 with cubic and 1 x 1 x 3 voxels);
//  - each label's surface is still closed, valid and outward, and none intersects itself; a second
//    call gives the same points, bit for bit; the deviation map agrees with the result;
//  - the volume term (Label_volumes.h): its gradient against central finite differences, on
//    its own and as the objective adds it in the bending energy's tiles, on the triangles in the
//    mesh's order; a label whose surface is not closed is not held, the slack of a block of
//    8^3 voxels is that of its six faces, a block of 6^3 (thinner than the mean edge length)
//    has none; on a torus whose tube is 5 voxels across the faired surface lies inside the raw
//    nets on average (the bending energy alone kept it at or outside them);
//  - the crossing search of the repair (Crossing_repair.h) against every pair tested with CGAL's
//    do_intersect, over all pairs and over the pairs with a few changed triangles, on triangles
//    of sizes over three orders of magnitude; the sine of a triangle's smallest angle on known
//    triangles; the repair on a grid thrown at random in its boxes: no crossing left, every point
//    in its box at its start or pulled halfway back some times, no smallest angle under both the
//    repair's angle and its start's, a soup with nothing to repair untouched;
//  - bad soups and values are rejected with their defect, the points left bit-identical.

#include "ball_phantom.h"
#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_interfaces.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Deviation_bounds.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_interfaces/Label_volumes.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_interfaces/Crossing_repair.h>
#include <CGAL/Polygon_mesh_processing/label_surface.h>
#include <CGAL/Polygon_mesh_processing/label_surface_nets.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <set>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using test::Mesh;
using test::Point;
using Label = std::int32_t;
using Triangle = std::array<std::size_t, 3>;
using Labels = std::array<Label, 2>;

constexpr double centre = 15.5, radius = 10;

struct Soup
{
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  std::vector<Labels> face_labels;
  std::vector<std::array<double, 3> > half_extents; // each point's box
};

// Labels 1 and 2: the ball on either side of the plane x = tilt z; 3: a cap over it where y > 6.
const test::Ball_phantom ball{centre, radius, true};

Soup phantom(const std::array<double, 3>& spacing)
{
  const std::array<std::size_t, 3> size{32, 32, std::size_t(32 / spacing[2])};
  const std::vector<Label> labels = ball.labels<Label>(size, spacing);
  Soup soup;
  PMP::label_surface_nets(labels.data(), size, spacing, {0, 0, 0}, soup.points, soup.triangles, soup.face_labels,
                          soup.half_extents);
  return soup;
}

// The RMS distance of the points on only the ball-outside interfaces to the sphere, of those on
// only the 1-2 interface to the plane, and of those on both (the triple line) to their circle.
std::array<double, 3> distances(const Soup& soup, const std::vector<Point>& points)
{
  std::vector<std::set<Label> > around(points.size());
  for(std::size_t f = 0; f < soup.triangles.size(); ++f)
    for(std::size_t v : soup.triangles[f])
      around[v].insert(soup.face_labels[f].begin(), soup.face_labels[f].end());
  const std::array<double, 4> rms = ball.distances(points, around);
  return {rms[0], rms[1], rms[2]};
}

void check_fairing(const std::array<double, 3>& spacing)
{
  const Soup soup = phantom(spacing);
  const auto half = CGAL::make_property_map(soup.half_extents);
  std::vector<Point> points = soup.points;
  std::vector<double> deviation(points.size(), -1);
  const auto np = CFP::vertex_box_half_extents_map(half, CFP::vertex_deviation_map(CGAL::make_property_map(deviation)));
  const PMP::Constrained_fairing_result r =
    PMP::constrained_fairing_of_interfaces(points, soup.triangles, soup.face_labels, 2 * spacing[2], np);
  CHECK(r);
  CHECK(r.final_energy <= r.initial_energy && r.number_of_iterations > 0);

  // In the box, exactly; still where four labels meet.
  std::vector<std::set<Label> > around(points.size());
  for(std::size_t f = 0; f < soup.triangles.size(); ++f)
    for(std::size_t v : soup.triangles[f])
      around[v].insert(soup.face_labels[f].begin(), soup.face_labels[f].end());
  std::size_t four = 0;
  double largest = 0;
  for(std::size_t v = 0; v < points.size(); ++v)
  {
    for(int c = 0; c < 3; ++c)
      CHECK(std::abs(points[v][c] - soup.points[v][c]) <= soup.half_extents[v][std::size_t(c)]);
    if(around[v].size() >= 4)
    {
      ++four;
      CHECK(points[v] == soup.points[v]);
    }
    largest = (std::max)(largest, deviation[v]);
  }
  CHECK(four > 0 && r.number_of_fixed_vertices >= four);
  CHECK(largest == r.max_deviation);

  const std::array<double, 3> raw = distances(soup, soup.points), faired = distances(soup, points);
  std::cout << "  spacing (" << spacing[0] << ", " << spacing[1] << ", " << spacing[2] << "): RMS to the sphere "
            << raw[0] << " -> " << faired[0] << ", to the plane " << raw[1] << " -> " << faired[1]
            << ", triple line " << raw[2] << " -> " << faired[2] << std::endl;
  CHECK(faired[0] * 4 < raw[0]);
  CHECK(faired[1] * 2 < raw[1]);
  CHECK(faired[2] * 1.5 < raw[2]);

  // No needle under 5 degrees (the barrier pushes back those under 6).
  const double smallest = test::smallest_angle(points, soup.triangles);
  std::cout << "  smallest angle " << smallest << " degrees" << std::endl;
  CHECK(smallest >= 5);

  for(Label label : {1, 2, 3})
  {
    Mesh mesh;
    PMP::label_surface(points, soup.triangles, soup.face_labels, label, mesh);
    CHECK(CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_closed(mesh) && PMP::volume(mesh) > 0);
    CHECK(!PMP::does_self_intersect(mesh));
  }

  std::vector<Point> again = soup.points;
  PMP::constrained_fairing_of_interfaces(again, soup.triangles, soup.face_labels, 2 * spacing[2],
                                         CFP::vertex_box_half_extents_map(half));
  CHECK(again == points);
}

namespace CF = PMP::internal::Constrained_fairing;

// A soup as the volume term takes it: each triangle turned to run from its smaller label into its
// larger, the labels themselves as their numbers (the soups here have labels 0, 1, ...), and the
// points as the solver's matrix.
struct Oriented_soup
{
  std::vector<std::array<CF::Index, 3> > triangles;
  std::vector<std::array<CF::Index, 2> > sides;
  CF::Points X0;

  explicit Oriented_soup(const Soup& soup) : X0(Eigen::Index(soup.points.size()), 3)
  {
    for(std::size_t f = 0; f < soup.triangles.size(); ++f)
    {
      const Triangle& t = soup.triangles[f];
      const Labels& l = soup.face_labels[f];
      const bool flip = l[0] > l[1];
      triangles.push_back({CF::Index(t[0]), CF::Index(flip ? t[2] : t[1]), CF::Index(flip ? t[1] : t[2])});
      sides.push_back({CF::Index((std::min)(l[0], l[1])), CF::Index((std::max)(l[0], l[1]))});
    }
    for(std::size_t v = 0; v < soup.points.size(); ++v)
      CF::point(X0, v) = Eigen::Vector3d(soup.points[v].x(), soup.points[v].y(), soup.points[v].z());
  }
};

// The volume term on the phantom's soup, its points moved at random by up to half a voxel: its
// gradient against central differences; with the triangles of label 3's surface on one side
// dropped, label 3 (and the outside, which shares them) is no longer held.
void check_label_volumes()
{
  const Soup soup = phantom({1, 1, 1});
  const Oriented_soup oriented(soup);
  const auto& [triangles, sides, X0] = oriented;
  CF::Label_volumes volumes(triangles, sides, X0, CF::default_label_volume_weight);
  CHECK(volumes.size() == 4);
  CHECK(volumes.value(X0) == 0);

  // Grown by a tenth about the centre, beyond every slack, and shaken.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> move(-0.1, 0.1);
  CF::Points X = X0;
  for(Eigen::Index k = 0; k < X.size(); ++k)
    X.data()[k] = centre + 1.1 * (X.data()[k] - centre) + move(random);
  CF::Points G = CF::Points::Zero(X.rows(), 3);
  const double value = volumes.add_gradient(X, G, nullptr);
  CHECK(value > 0 && value == volumes.value(X));
  const double error = test::gradient_error(X, G, [&](const CF::Points& Y) { return volumes.value(Y); }, 1e-5, 7);
  std::cout << "  label volumes: gradient vs finite differences, relative error " << error << std::endl;
  CHECK(error < 1e-6);

  // The same term as the objective evaluates it, its gradient added in the bending energy's
  // tiles, on the triangles in the mesh's order (which a Hinge_mesh sorts): no hinges and no
  // barrier, so that the volumes alone are checked, against central differences.
  const CF::Hinge_mesh mesh(std::size_t(X0.rows()), triangles, {});
  std::vector<std::array<CF::Index, 2> > mesh_sides(sides.size());
  bool reordered = false;
  for(std::size_t f = 0; f < sides.size(); ++f)
  {
    mesh_sides[mesh.positions_of_list[f]] = sides[f];
    reordered = reordered || mesh.positions_of_list[f] != f;
  }
  CHECK(reordered);
  CF::Label_volumes in_mesh_order(mesh.triangles, mesh_sides, X0, CF::default_label_volume_weight);
  CF::Fairing_objective objective(mesh, X0, 0, CF::default_sliver_threshold);
  objective.add_term(in_mesh_order);
  CF::Points G_objective;
  const double objective_value = objective.value_and_gradient(X, G_objective);
  CHECK(objective_value > 0 && objective_value == in_mesh_order.value(X));
  const double objective_error =
    test::gradient_error(X, G_objective, [&](const CF::Points& Y) { return objective.value(Y); }, 1e-5, 7);
  std::cout << "  label volumes in the tiles: gradient vs finite differences, relative error " << objective_error
            << std::endl;
  CHECK(objective_error < 1e-6);

  std::vector<std::array<CF::Index, 3> > open_triangles;
  std::vector<std::array<CF::Index, 2> > open_sides;
  bool dropped = false;
  for(std::size_t f = 0; f < triangles.size(); ++f)
    if(sides[f] == std::array<CF::Index, 2>{0, 3} && !dropped)
      dropped = true;
    else
      open_triangles.push_back(triangles[f]), open_sides.push_back(sides[f]);
  CHECK(CF::Label_volumes(open_triangles, open_sides, X0, 1).size() == 2);

  // No label closed (one interface of two labels, open): the term is zero and adds nothing.
  std::vector<std::array<CF::Index, 3> > sheet;
  std::vector<std::array<CF::Index, 2> > sheet_sides;
  for(std::size_t f = 0; f < triangles.size(); ++f)
    if(sides[f] == std::array<CF::Index, 2>{0, 3})
      sheet.push_back(triangles[f]), sheet_sides.push_back({0, 1});
  sheet.pop_back(), sheet_sides.pop_back();
  CF::Label_volumes none_closed(sheet, sheet_sides, X0, 1);
  CHECK(none_closed.size() == 0);
  CF::Points G_none = CF::Points::Constant(X.rows(), 3, 0.5);
  CHECK(none_closed.add_gradient(X, G_none, nullptr) == 0 && none_closed.value(X) == 0);
  CHECK((G_none.array() == 0.5).all());

  // A block of k^3 voxels and its background (two labels).
  const auto block_volumes = [](std::size_t k) {
    const std::size_t m = k + 4;
    std::vector<Label> labels(m * m * m, 0);
    for(std::size_t i = 2; i < k + 2; ++i)
      for(std::size_t j = 2; j < k + 2; ++j)
        for(std::size_t l = 2; l < k + 2; ++l)
          labels[(i * m + j) * m + l] = 1;
    Soup block;
    PMP::label_surface_nets(labels.data(), {m, m, m}, {1., 1., 1.}, {0, 0, 0}, block.points, block.triangles,
                            block.face_labels, block.half_extents);
    const Oriented_soup oriented_block(block);
    return CF::Label_volumes(oriented_block.triangles, oriented_block.sides, oriented_block.X0, 1);
  };
  // 8 x 8 x 8 voxels: six caps of 64 voxel faces, each off by a uniform fraction of the spacing, a
  // standard deviation of 64 / sqrt(12) each.
  const CF::Label_volumes large = block_volumes(8);
  CHECK(large.size() == 2);
  for(std::size_t l = 0; l < 2; ++l)
    CHECK(std::abs(large.slack(l) - std::sqrt(6.) * 64 / std::sqrt(12.)) < 1e-9);
  // 6 x 6 x 6 voxels: a volume over area of one voxel, under the mean edge length (1.14): held at
  // the count, no slack.
  const CF::Label_volumes small = block_volumes(6);
  CHECK(small.size() == 2);
  for(std::size_t l = 0; l < 2; ++l)
    CHECK(small.slack(l) == 0);
}

// A torus whose tube is 5 voxels across, its axis tilted against the grid: the faired points'
// mean signed distance to it, which the bending energy alone keeps at the raw nets' or widens.
void check_thin_tube()
{
  const std::array<std::size_t, 3> size{30, 30, 30};
  const double R = 9, r = 2.5, c = 14.5;
  const double n = std::sqrt(0.2 * 0.2 + 0.35 * 0.35 + 1);
  const std::array<double, 3> axis{0.2 / n, 0.35 / n, 1 / n};
  const auto signed_distance = [&](double x, double y, double z) {
    x -= c, y -= c, z -= c;
    const double along = x * axis[0] + y * axis[1] + z * axis[2];
    const double across = std::sqrt((std::max)(0., x * x + y * y + z * z - along * along));
    return std::sqrt((across - R) * (across - R) + along * along) - r;
  };
  std::vector<Label> labels(size[0] * size[1] * size[2], 0);
  for(std::size_t i = 0; i < size[0]; ++i)
    for(std::size_t j = 0; j < size[1]; ++j)
      for(std::size_t k = 0; k < size[2]; ++k)
        labels[(i * size[1] + j) * size[2] + k] = signed_distance(double(i), double(j), double(k)) < 0 ? 1 : 0;
  Soup soup;
  PMP::label_surface_nets(labels.data(), size, {1., 1., 1.}, {0, 0, 0}, soup.points, soup.triangles,
                          soup.face_labels, soup.half_extents);
  std::vector<Point> points = soup.points;
  CHECK(PMP::constrained_fairing_of_interfaces(points, soup.triangles, soup.face_labels, 2.,
                                               CFP::vertex_box_half_extents_map(
                                                 CGAL::make_property_map(soup.half_extents))));
  const auto mean = [&](const std::vector<Point>& P) {
    double sum = 0;
    for(const Point& p : P)
      sum += signed_distance(p.x(), p.y(), p.z());
    return sum / double(P.size());
  };
  std::cout << "  torus, tube 5 voxels across: mean signed distance raw " << mean(soup.points) << ", faired "
            << mean(points) << std::endl;
  CHECK(mean(soup.points) > 0.04);
  CHECK(mean(points) < mean(soup.points));
}

// Triangles of their own points (none shared), of sizes from 0.002 to 2 in a unit cube: the
// crossings found, over all pairs and over the pairs with the changed triangles, are those of
// CGAL's do_intersect over every pair.
void check_crossing_search()
{
  namespace CF = PMP::internal::Constrained_fairing;
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0, 1), side(-1, 1);
  const std::size_t m = 600;
  CF::Points X(Eigen::Index(3 * m), 3);
  std::vector<std::array<CF::Index, 3> > triangles(m);
  for(std::size_t f = 0; f < m; ++f)
  {
    const double size = 0.002 * std::pow(1000., unit(random));
    const double c[3] = {unit(random), unit(random), unit(random)};
    for(std::size_t k = 0; k < 3; ++k)
    {
      triangles[f][k] = CF::Index(3 * f + k);
      for(int a = 0; a < 3; ++a)
        X(Eigen::Index(3 * f + k), a) = c[a] + size * side(random);
    }
  }
  const auto triangle = [&](std::size_t f) {
    const auto p = [&](CF::Index v) { return K::Point_3(X(v, 0), X(v, 1), X(v, 2)); };
    return K::Triangle_3(p(triangles[f][0]), p(triangles[f][1]), p(triangles[f][2]));
  };
  std::vector<std::vector<bool> > meets(m, std::vector<bool>(m, false));
  for(std::size_t f = 0; f < m; ++f)
    for(std::size_t g = f + 1; g < m; ++g)
      meets[f][g] = meets[g][f] = CGAL::do_intersect(triangle(f), triangle(g));
  const CF::Triangle_crossings crossings(triangles);
  std::size_t found = 0;
  for(const std::size_t every : {0, 2, 37, 211})
  {
    std::vector<bool> changed;
    if(every > 0)
      for(std::size_t f = 0; f < m; ++f)
        changed.push_back(f % every == 0);
    const std::vector<bool> crossing = crossings.find(X, changed);
    for(std::size_t f = 0; f < m; ++f)
    {
      bool expected = false;
      for(std::size_t g = 0; g < m; ++g)
        expected = expected || (meets[f][g] && (changed.empty() || changed[f] || changed[g]));
      CHECK(crossing[f] == expected);
      found += crossing[f];
    }
  }
  std::cout << "  crossing search: " << found << " crossing triangles found as every pair's test finds them"
            << std::endl;
  CHECK(found > 0);
}

// The sine of a triangle's smallest angle (Hinge_mesh.h) on triangles whose angles are known.
void check_smallest_angle_sine()
{
  namespace CF = PMP::internal::Constrained_fairing;
  CF::Points X(4, 3);
  X << 0, 0, 0, 4, 0, 0, 0, 3, 0, 2, 2 * std::sqrt(3.), 0;
  CHECK(std::abs(CF::smallest_angle_sine(X, {0, 1, 2}) - 0.6) < 1e-15);
  CHECK(std::abs(CF::smallest_angle_sine(X, {2, 0, 1}) - 0.6) < 1e-15);
  X.row(2) << 4, 0, 0; // coincident points
  CHECK(CF::smallest_angle_sine(X, {0, 1, 2}) == 0);
  X.row(2) << 8, 0, 0; // collinear
  CHECK(CF::smallest_angle_sine(X, {0, 1, 2}) == 0);
  CHECK(std::abs(CF::smallest_angle_sine(X, {0, 1, 3}) - std::sqrt(3.) / 2) < 1e-15);
  for(const double scale : {1e-200, 1e200}) // no square underflows or overflows
    CHECK(std::abs(CF::smallest_angle_sine(scale * X, {0, 1, 3}) - std::sqrt(3.) / 2) < 1e-15);
}

// The repair after the descent (Crossing_repair.h) on a grid whose points were thrown at random
// within their boxes, nearly flat so that many triangles turn over onto their neighbours, as a
// descent that folded it might leave them, some points held; on a flat grid and on one with a
// squashed column of needles at the start. No crossing is left; every point stays in its box, at
// its start or pulled halfway back some times; every triangle ends with its smallest angle at
// least the repair's angle or its start's, and none folded, which the pulls of crossings alone do
// not keep. A soup with nothing to repair is left bit for bit.
void check_crossing_repair()
{
  namespace CF = PMP::internal::Constrained_fairing;
  const std::size_t n = 25;
  const double half = 0.45, smallest_sine = std::sin(CF::interface_repair_angle * CGAL_PI / 180);
  std::vector<std::array<CF::Index, 3> > triangles;
  std::vector<std::array<CF::Index, 2> > hinge_faces;
  for(std::size_t i = 0; i + 1 < n; ++i)
    for(std::size_t j = 0; j + 1 < n; ++j)
    {
      const CF::Index a = CF::Index(i * n + j), b = a + 1, c = CF::Index(a + n), d = c + 1;
      const CF::Index f = CF::Index(triangles.size());
      triangles.push_back({a, c, d}), triangles.push_back({a, d, b});
      hinge_faces.push_back({f, f + 1}); // the diagonal a-d
      if(j + 2 < n)
        hinge_faces.push_back({f + 1, f + 2}); // b-d, with the square of the next j
      if(i + 2 < n)
        hinge_faces.push_back({f, f + 2 * CF::Index(n - 1) + 1}); // c-d, with that of the next i
    }
  const CF::Hinge_mesh mesh(n * n, triangles, hinge_faces);
  CHECK(mesh.hinges.size() == hinge_faces.size());
  const CF::Triangle_crossings crossings(triangles);
  std::vector<bool> moving(n * n);
  for(std::size_t v = 0; v < n * n; ++v)
    moving[v] = v % 7 != 3;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> offset(-half, half), lift(-0.05, 0.05);
  std::size_t crossed = 0, folded = 0, needles_at_start = 0, worse_without = 0, folded_without = 0;
  for(int trial = 0; trial < 20; ++trial)
  {
    // Odd trials start with column 12 squashed against column 11: needles at the start.
    CF::Points X0(Eigen::Index(n * n), 3);
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t j = 0; j < n; ++j)
        X0.row(Eigen::Index(i * n + j)) << (trial % 2 == 1 && i == 12 ? 11.05 : double(i)), double(j), 0.;
    for(const auto& t : triangles)
      needles_at_start += CF::smallest_angle_sine(X0, t) < smallest_sine;
    CHECK(CF::folded_triangles(mesh, X0).empty());
    const CF::Box_bound bound(X0, half);
    CF::Points thrown = X0;
    for(std::size_t v = 0; v < n * n; ++v)
      if(moving[v])
        thrown.row(Eigen::Index(v)) += Eigen::RowVector3d(offset(random), offset(random), lift(random));
    const std::vector<bool> at_throw = crossings.find(thrown, {});
    crossed += std::size_t(std::count(at_throw.begin(), at_throw.end(), true));
    folded += CF::folded_triangles(mesh, thrown).size();
    for(const double sine : {smallest_sine, 0.})
    {
      CF::Points X = thrown;
      CF::repair_crossings_needles_and_folds(mesh, bound, moving, sine, X0, X);
      const std::vector<bool> crossing = crossings.find(X, {});
      CHECK(std::count(crossing.begin(), crossing.end(), true) == 0);
      for(Eigen::Index v = 0; v < X.rows(); ++v)
      {
        bool pulled = X.row(v) == X0.row(v);
        for(int k = 0; k <= int(CF::crossing_repair_rounds); ++k)
          pulled = pulled || (X.row(v) - X0.row(v) - std::ldexp(1., -k) * (thrown.row(v) - X0.row(v))).norm() < 1e-12;
        CHECK(pulled);
        for(int c = 0; c < 3; ++c)
          CHECK(std::abs(X(v, c) - X0(v, c)) <= half);
      }
      const std::size_t folds = CF::folded_triangles(mesh, X).size();
      for(const auto& t : triangles)
      {
        const bool kept = CF::smallest_angle_sine(X, t) >= (std::min)(smallest_sine, CF::smallest_angle_sine(X0, t));
        if(sine > 0)
          CHECK(kept);
        else
          worse_without += !kept;
      }
      if(sine > 0)
        CHECK(folds == 0);
      else
        folded_without += folds;
    }
    if(trial % 2 == 1)
      continue;
    // The flat grid lifted as a whole but for its held points: nothing crosses, no needle, no fold.
    CF::Points X = X0;
    for(std::size_t v = 0; v < n * n; ++v)
      if(moving[v])
        X(Eigen::Index(v), 2) += 0.3;
    const CF::Points lifted = X;
    CHECK(CF::repair_crossings_needles_and_folds(mesh, bound, moving, smallest_sine, X0, X) == 0);
    CHECK((X.array() == lifted.array()).all());
  }
  std::cout << "  crossing repair: " << crossed << " crossing triangles and " << folded
            << " folded ones thrown, none left; " << needles_at_start << " needles at the start kept; "
            << worse_without << " needles and " << folded_without
            << " folds left by the pulls of crossings alone, none with the angle and the folds" << std::endl;
  CHECK(crossed > 0);
  CHECK(folded > 0);
  CHECK(needles_at_start > 0);
  CHECK(worse_without > 0);
  CHECK(folded_without > 0);
}

// A call that must fail with `defect`, leaving the points as they were.
template <typename NamedParameters>
void check_rejected(std::vector<Point> points, const std::vector<Triangle>& triangles,
                    const std::vector<Labels>& face_labels, double epsilon, PMP::Constrained_fairing_defect defect,
                    const NamedParameters& np)
{
  const std::vector<Point> input = points;
  const PMP::Constrained_fairing_result r =
    PMP::constrained_fairing_of_interfaces(points, triangles, face_labels, epsilon, np);
  CHECK(!r && r.status == PMP::Constrained_fairing_status::INVALID_INPUT && r.defect == defect && !r.message.empty());
  CHECK(test::identical(points, input));
}

void check_bad_input()
{
  using D = PMP::Constrained_fairing_defect;
  const Soup soup = phantom({1, 1, 1});
  const auto box = CFP::box_half_extents(std::array<double, 3>{0.5, 0.5, 0.5});
  std::vector<Triangle> triangles = soup.triangles;
  std::vector<Labels> labels = soup.face_labels;
  check_rejected(soup.points, {}, {}, 1, D::NO_FACES, box);
  check_rejected({}, soup.triangles, soup.face_labels, 1, D::EMPTY_MESH, box);
  labels[7] = {2, 2};
  check_rejected(soup.points, triangles, labels, 1, D::INVALID_FACE, box);
  labels = soup.face_labels;
  triangles[5][1] = soup.points.size();
  check_rejected(soup.points, triangles, labels, 1, D::INVALID_FACE, box);
  triangles[5][1] = triangles[5][0];
  check_rejected(soup.points, triangles, labels, 1, D::INVALID_FACE, box);
  triangles = soup.triangles;
  std::swap(triangles[9][1], triangles[9][2]);
  check_rejected(soup.points, triangles, labels, 1, D::INCONSISTENT_ORIENTATION, box);
  std::vector<Point> points = soup.points;
  points[3] = Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  check_rejected(points, soup.triangles, soup.face_labels, 1, D::NON_FINITE_COORDINATE, box);
  check_rejected(soup.points, soup.triangles, soup.face_labels, 0, D::INVALID_EPSILON, box);
  check_rejected(soup.points, soup.triangles, soup.face_labels, 1, D::INVALID_BOX_EXTENTS,
                 CFP::box_half_extents(std::array<double, 3>{0.5, -1, 0.5}));
  // a soup detects no creases: feature_angle is rejected, not ignored, whatever its value
  for(double angle : {30., 200.})
    check_rejected(soup.points, soup.triangles, soup.face_labels, 1, D::INVALID_FEATURE_ANGLE,
                   CFP::feature_angle(angle, box));
}

int main()
{
  check_fairing({1, 1, 1});
  check_fairing({1, 1, 3});
  check_label_volumes();
  check_thin_tube();
  check_crossing_search();
  check_smallest_angle_sine();
  check_crossing_repair();
  check_bad_input();
  return test::report("test_interface_fairing");
}
