// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The bending energy of eq. (1): hand-computed values, zero on planes, invariance under rigid
// motions and uniform scaling, the analytic gradient against central finite differences, and
// the evaluation by tiles against a plain sum over the hinges.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Bending_energy.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <string>

namespace CF = CGAL::Polygon_mesh_processing::internal::Constrained_fairing;
using test::Indexed;
using test::Mesh;
using test::Point;

// Two triangles on the edge (0,0,0)-(1,0,0), the first in the plane z = 0, the second opened
// by `angle` from it: the dihedral angle between the faces is `angle`.
Mesh hinge(double angle)
{
  Mesh m;
  const auto a = m.add_vertex(Point(0, 0, 0)), b = m.add_vertex(Point(1, 0, 0));
  const auto c = m.add_vertex(Point(0.5, 1, 0));
  const auto d = m.add_vertex(Point(0.5, std::cos(angle), std::sin(angle)));
  m.add_face(a, b, c);
  m.add_face(b, a, d);
  return m;
}

double energy(const Mesh& m)
{
  const Indexed x(m);
  return CF::Bending_energy(x.hinges, x.X).value(x.X);
}

void check_hand_computed_hinges()
{
  // |e| = 1, both areas 1/2: E = 3 / (2 * 1) * cos(theta / 2)^2
  CHECK(std::abs(energy(hinge(CGAL_PI / 3)) - 1.5 * 0.75) < 1e-14); // theta = 60 deg
  CHECK(std::abs(energy(hinge(CGAL_PI / 2)) - 1.5 * 0.5) < 1e-14);  // theta = 90 deg
  CHECK(energy(hinge(CGAL_PI)) < 1e-30);                             // flat
  // The fold direction does not matter.
  CHECK(std::abs(energy(hinge(CGAL_PI / 3)) - energy(hinge(-CGAL_PI / 3 + 2 * CGAL_PI))) < 1e-14);
}

void check_zero_on_planes()
{
  Mesh plane = test::plane_patch(12);
  CHECK(energy(plane) == 0);
  // Tilted and shifted: zero up to rounding.
  for(auto v : vertices(plane))
  {
    const Point p = plane.point(v);
    plane.point(v) = Point(p.x() + 3, 0.6 * p.y() + 0.8 * p.z() - 2, -0.8 * p.y() + 0.6 * p.z() + 1);
  }
  CHECK(energy(plane) < 1e-25);
}

void check_invariance()
{
  Mesh m = test::icosphere(2);
  test::add_noise(m, 0.05, 1);
  const double E = energy(m);
  CHECK(E > 1);

  // A rotation about an oblique axis, then a translation.
  const CGAL::Aff_transformation_3<test::K> rotation(0.36, 0.48, -0.8, -0.8, 0.6, 0, 0.48, 0.64, 0.6);
  for(double scale : {1.0, 1e-3, 250.0})
  {
    Mesh moved = m;
    for(auto v : vertices(moved))
      moved.point(v) = CGAL::ORIGIN + scale * (rotation(moved.point(v)) - CGAL::ORIGIN) + test::Vector(7, -3, 2);
    CHECK(std::abs(energy(moved) - E) <= 1e-11 * E);
  }
}

// The analytic gradient against central differences of step `step` mean edge lengths, on
// `count` coordinates spread over the mesh (all of them if count is 0).
void check_gradient(const Mesh& m, std::size_t count, const std::string& name, double step = 1e-6)
{
  Indexed x(m);
  CF::Bending_energy E(x.hinges, x.X);
  CF::Points G;
  E.value_and_gradient(x.X, G);
  CHECK(G.allFinite());

  const double h = step * test::mean_edge_length(m);
  const Eigen::Index n = x.X.size();
  const Eigen::Index stride = count == 0 ? 1 : std::max<Eigen::Index>(1, n / Eigen::Index(count));
  const double relative_error =
    test::gradient_error(x.X, G, [&](const CF::Points& Y) { return E.value(Y); }, h, stride);
  std::cout << "  gradient vs finite differences, " << name << ": relative error " << relative_error << std::endl;
  CHECK(relative_error < 1e-6); // infinite, and failing, for a zero gradient
}

void check_gradients()
{
  Mesh sphere = test::icosphere(2);
  test::add_noise(sphere, 0.05, 2);
  check_gradient(sphere, 0, "noisy icosphere (closed)");

  Mesh plane = test::plane_patch(10);
  test::add_noise(plane, 0.03, 3);
  check_gradient(plane, 0, "noisy plane patch (border)");

  // Strong random perturbation: irregular, obtuse triangles, large dihedral angles.
  Mesh rough = test::icosphere(1);
  test::add_noise(rough, 0.25, 4);
  check_gradient(rough, 0, "strongly perturbed icosphere");

  const std::size_t count = test::under_sanitizers ? 300 : 3000; // each a full evaluation, twice
  for(const std::string name : {"elephant.off", "head.off"})
  {
    Mesh real;
    CHECK(CGAL::IO::read_polygon_mesh(std::string(CONSTRAINED_FAIRING_DATA_DIR) + "/" + name, real));
    if(!is_empty(real))
      check_gradient(real, count,
                     name + (is_closed(real) ? " (closed, " : " (border, ") + std::to_string(count) + " coordinates)");
  }
}

// A mesh of many tiles (Bending_energy::tile_size vertices each), numbered as in its file,
// so that tiles are scattered over the surface and many triangles and hinges are shared by
// two tiles: the energy is the plain sum of the hinge terms, whatever the numbering, and the
// gradient matches finite differences.
void check_tiled_evaluation()
{
  Mesh bunny;
  CHECK(CGAL::IO::read_polygon_mesh(std::string(CONSTRAINED_FAIRING_DATA_DIR) + "/bunny00.off", bunny));
  CHECK(num_vertices(bunny) > 8 * CF::Bending_energy::tile_size);
  test::add_noise(bunny, 0.25 * test::mean_edge_length(bunny), 12);
  const Indexed x(bunny);
  const double E = CF::Bending_energy(x.hinges, x.X).value(x.X);
  const double reference = test::plain_bending_energy(bunny);
  std::cout << "  tiled energy " << E << ", plain sum " << reference << std::endl;
  CHECK(std::abs(E - reference) <= 1e-12 * reference);

  // Renumbered in reverse: other tiles, the same energy up to the order of the sums.
  const std::size_t n = num_vertices(bunny);
  CF::Points reversed(x.X.rows(), 3);
  for(std::size_t i = 0; i < n; ++i)
    reversed.row(static_cast<Eigen::Index>(n - 1 - i)) = x.X.row(static_cast<Eigen::Index>(i));
  auto reversed_index = bunny.add_property_map<Mesh::Vertex_index, std::size_t>("v:reversed").first;
  for(auto v : vertices(bunny))
    reversed_index[v] = n - 1 - std::size_t(v.idx());
  const CF::Hinge_mesh reversed_hinges(bunny, reversed_index);
  CHECK(std::abs(CF::Bending_energy(reversed_hinges, reversed).value(reversed) - E) <= 1e-12 * E);

  const std::size_t count = test::under_sanitizers ? 60 : 600;
  check_gradient(bunny, count, "noisy bunny, many tiles (" + std::to_string(count) + " coordinates)");
}

// Coordinates far outside the range where squared areas fit in double.
void check_extreme_scales()
{
  Mesh m = test::icosphere(2);
  test::add_noise(m, 0.05, 5);
  const Indexed x(m);
  CF::Bending_energy reference(x.hinges, x.X);
  CF::Points G;
  const double E = reference.value_and_gradient(x.X, G);
  for(double scale : {1e-200, 1e-150, 1e150, 1e200})
  {
    const CF::Points Y = scale * x.X;
    CF::Bending_energy scaled(x.hinges, Y);
    CF::Points GY;
    const double EY = scaled.value_and_gradient(Y, GY);
    CHECK(std::abs(EY - E) <= 1e-12 * E);
    CHECK(GY.allFinite() && (scale * GY - G).norm() <= 1e-10 * G.norm());
  }
}

// Hinges with a triangle degenerate in the input are left out; triangles that degenerate
// later keep the energy and its gradient finite and smooth.
void check_degenerate_triangles()
{
  // The second triangle of the hinge collapsed onto the shared edge: no hinge remains.
  Mesh collapsed = hinge(CGAL_PI / 3);
  collapsed.point(*std::prev(vertices(collapsed).end())) = Point(0.5, 0, 0);
  const Indexed c(collapsed);
  CF::Bending_energy E(c.hinges, c.X);
  CHECK(E.number_of_degenerate_hinges() == 1 && E.value(c.X) == 0);
  // A needle twice as thin as the threshold is left out too, and one twice as thick is not.
  for(double height : {0.5e-6, 2e-6})
  {
    Mesh needle = hinge(CGAL_PI / 3);
    needle.point(*std::prev(vertices(needle).end())) = Point(0.5, 0, height);
    const Indexed x(needle);
    CHECK(CF::Bending_energy(x.hinges, x.X).number_of_degenerate_hinges() == (height < 1e-6 ? 1u : 0u));
  }

  // A noisy sphere whose input is regular, evaluated where 30 triangles have collapsed to a
  // point, to a segment or onto a vertex.
  Mesh sphere = test::icosphere(2);
  test::add_noise(sphere, 0.05, 6);
  Indexed x(sphere);
  Mesh moved = sphere;
  test::make_degenerate(moved, 30.0 / double(num_faces(moved)), 7);
  const Indexed y(moved);
  CF::Bending_energy energy(x.hinges, x.X);
  CHECK(energy.number_of_degenerate_hinges() == 0);
  CF::Points G;
  const double value = energy.value_and_gradient(y.X, G);
  CHECK(std::isfinite(value) && G.allFinite());
  CHECK(test::number_of_degenerate_faces(moved) >= 30);
}

// The vertex scales of the quasi-Newton method. The stiffness along the normal (the
// Gauss-Newton diagonal): positive wherever a vertex is in a hinge, invariant under rigid
// motions, scaling as 1 / s^2 (the energy is scale invariant), and on a flat patch, where the
// Gauss-Newton model is exact to second order, a bound on the true second derivative along the
// normal: it cannot exceed 4 K (K sums the two triangles' terms of a hinge separately). The
// reach: the smallest height over the opposite edge, invariant and scaling as s.
void check_stiffness()
{
  Mesh m = test::icosphere(2);
  test::add_noise(m, 0.05, 11);
  const Indexed x(m);
  CF::Bending_energy E(x.hinges, x.X);
  CF::Points G;
  CF::Stiffness_and_reach S, S_moved, S_scaled;
  E.value_and_gradient(x.X, G, &S);
  const Eigen::VectorXd& K = S.stiffness;
  CHECK(K.size() == x.X.rows() && (K.array() > 0).all());
  CHECK(S.reach.size() == x.X.rows() && (S.reach.array() > 0).all());

  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const CF::Points moved = (x.X * R.transpose()).rowwise() + Eigen::RowVector3d(0.3, -2, 5);
  CF::Bending_energy(x.hinges, moved).value_and_gradient(moved, G, &S_moved);
  CHECK((S_moved.stiffness - K).norm() <= 1e-9 * K.norm());
  CHECK((S_moved.reach - S.reach).norm() <= 1e-9 * S.reach.norm());
  const CF::Points scaled = 4 * x.X;
  CF::Bending_energy(x.hinges, scaled).value_and_gradient(scaled, G, &S_scaled);
  CHECK((16 * S_scaled.stiffness - K).norm() <= 1e-12 * K.norm());
  CHECK((S_scaled.reach - 4 * S.reach).norm() <= 1e-12 * S.reach.norm());

  Mesh plane = test::plane_patch(7);
  Indexed p(plane);
  CF::Bending_energy flat(p.hinges, p.X);
  flat.value_and_gradient(p.X, G, &S);
  std::size_t interior = 0;
  for(Eigen::Index i = 0; i < p.X.rows(); ++i)
  {
    const double x0 = p.X(i, 0), y0 = p.X(i, 1);
    if(x0 <= 0 || x0 >= 1 || y0 <= 0 || y0 >= 1)
      continue;
    ++interior;
    const double d = 1e-4;
    CF::Points Y = p.X;
    Y(i, 2) = d;
    const double second = 2 * flat.value(Y) / (d * d); // E is 0 and stationary at the plane
    CHECK(second > 0 && second <= 4 * S.stiffness[i] * (1 + 1e-6));
    // the grid's triangles are right isosceles of legs 1/6: the height over the opposite edge
    // is 1/(6 sqrt 2) at a right angle, 1/6 at the others
    const double r = S.reach[i];
    CHECK(std::abs(r - 1 / (6 * std::sqrt(2.))) <= 1e-12 || std::abs(r - 1 / 6.) <= 1e-12);
  }
  CHECK(interior == 25);
}

int main()
{
  check_hand_computed_hinges();
  check_zero_on_planes();
  check_invariance();
  check_gradients();
  check_tiled_evaluation();
  check_extreme_scales();
  check_degenerate_triangles();
  check_stiffness();
  return test::report("test_bending_energy");
}
