// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The bending energy of an operator form (Operator_bending.h), the seam through which an input
// without hinges brings its bending to the objective: with the cotangent Laplacian and
// barycentric masses of a sphere it measures the sphere's integral of (2H)^2, 16 pi; one form
// gives the same energy on the sphere scaled (its masses move with the points), and is blind to
// translations; its gradient agrees with central differences, with a Laplacian that is not
// symmetric too; and an objective without hinges (Fairing_objective.h) made of it reports it as
// its bending energy, with its quadratic part's Hessian diagonal as the stiffness.

#include "seeded_noise.h"
#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Operator_bending.h>

#include <Eigen/SparseCore>

#include <cmath>
#include <iostream>
#include <vector>

namespace CF = CGAL::Polygon_mesh_processing::internal::Constrained_fairing;
using test::Mesh;

CF::Points to_points(const Mesh& m, double scale = 1)
{
  CF::Points X(num_vertices(m), 3);
  for(auto v : vertices(m))
    X.row(v.idx()) << scale * m.point(v).x(), scale * m.point(v).y(), scale * m.point(v).z();
  return X;
}

// The cotangent Laplacian (x_j - x_i weighted by half the cotangents opposite edge ij) and
// each vertex's third of its triangles' areas and its normal, at X; `skew` scales the entries of the rows
// of vertices of odd index, which makes L not symmetric; the curvature normals along the
// normals, or whole.
CF::Operator_bending cotangent_form(const Mesh& m, const CF::Points& X, double skew = 1, bool along_normals = true)
{
  const Eigen::Index n = X.rows();
  std::vector<Eigen::Triplet<double> > entries;
  std::vector<CF::Mass_triangle> masses;
  CF::Points normals = CF::Points::Zero(n, 3);
  const auto row_scale = [skew](Eigen::Index i) { return i % 2 == 1 ? skew : 1.0; };
  for(auto f : faces(m))
  {
    std::array<Eigen::Index, 3> v;
    int k = 0;
    for(auto u : vertices_around_face(halfedge(f, m), m))
      v[std::size_t(k++)] = Eigen::Index(u.idx());
    const Eigen::Vector3d a = X.row(v[0]), b = X.row(v[1]), c = X.row(v[2]);
    for(Eigen::Index u : v)
      normals.row(u) += (b - a).cross(c - a).transpose();
    for(int i = 0; i < 3; ++i)
    {
      const Eigen::Index p = v[std::size_t(i)], q = v[std::size_t((i + 1) % 3)], o = v[std::size_t((i + 2) % 3)];
      const Eigen::Vector3d e1 = X.row(p) - X.row(o), e2 = X.row(q) - X.row(o);
      const double w = 0.5 * e1.dot(e2) / e1.cross(e2).norm();
      entries.emplace_back(p, q, w * row_scale(p));
      entries.emplace_back(q, p, w * row_scale(q));
      entries.emplace_back(p, p, -w * row_scale(p));
      entries.emplace_back(q, q, -w * row_scale(q));
      masses.push_back({{CF::Index(v[0]), CF::Index(v[1]), CF::Index(v[2])}, CF::Index(p)});
    }
  }
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(entries.begin(), entries.end());
  normals.rowwise().normalize();
  return CF::Operator_bending(std::move(L), along_normals ? std::move(normals) : CF::Points(), std::move(masses), X);
}

int main()
{
  const Mesh sphere = test::icosphere(5);
  const CF::Points X = to_points(sphere);
  CF::Operator_bending bending = cotangent_form(sphere, X);
  const double energy = bending.value(X);
  std::cout << "  unit sphere: " << energy << " against 16 pi = " << 16 * CGAL_PI << std::endl;
  CHECK(std::abs(energy - 16 * CGAL_PI) <= 0.01 * 16 * CGAL_PI);

  // Scale-invariant: the form gives the same energy on the sphere twice as large, as does the
  // form built there.
  CHECK(std::abs(bending.value(to_points(sphere, 2)) - energy) <= 1e-12 * energy);
  CF::Operator_bending larger = cotangent_form(sphere, to_points(sphere, 2));
  CHECK(std::abs(larger.value(to_points(sphere, 2)) - energy) <= 1e-12 * energy);
  // Translations cost nothing: the rows of L sum to zero.
  CF::Points moved = X;
  moved.rowwise() += Eigen::RowVector3d(0.3, -0.2, 0.1);
  CHECK(std::abs(bending.value(moved) - energy) <= 1e-9 * energy);

  // The gradient on a noisy sphere, alone and as the only term of an objective without hinges.
  Mesh noisy = test::icosphere(3);
  test::add_noise(noisy, 0.02, 5);
  CF::Points Y = to_points(noisy);
  CF::Operator_bending form = cotangent_form(noisy, Y);
  CF::Points G = CF::Points::Zero(Y.rows(), 3);
  const double value = form.add_gradient(Y, G, nullptr);
  CHECK(value == form.value(Y));
  const double error = test::gradient_error(Y, G, [&](const CF::Points& Z) { return form.value(Z); }, 1e-6);
  std::cout << "  gradient vs finite differences: relative error " << error << std::endl;
  CHECK(error < 1e-6);
  CF::Operator_bending skewed = cotangent_form(noisy, Y, 1.7);
  CF::Points S = CF::Points::Zero(Y.rows(), 3);
  skewed.add_gradient(Y, S, nullptr);
  const double skewed_error = test::gradient_error(Y, S, [&](const CF::Points& Z) { return skewed.value(Z); }, 1e-6);
  std::cout << "  with a Laplacian not symmetric: relative error " << skewed_error << std::endl;
  CHECK(skewed_error < 1e-6);
  CF::Operator_bending whole = cotangent_form(noisy, Y, 1.7, false);
  CF::Points W = CF::Points::Zero(Y.rows(), 3);
  whole.add_gradient(Y, W, nullptr);
  const double whole_error = test::gradient_error(Y, W, [&](const CF::Points& Z) { return whole.value(Z); }, 1e-6);
  std::cout << "  of the whole vector: relative error " << whole_error << std::endl;
  CHECK(whole_error < 1e-6 && whole.value(Y) > skewed.value(Y));

  CF::Fairing_objective objective;
  objective.add_term(form);
  CF::Points H;
  CF::Stiffness_and_reach scales;
  CHECK(objective.value_and_gradient(Y, H, &scales) == value);
  CHECK(H == G);
  CHECK(objective.value(Y) == value && objective.bending_energy(Y) == value);
  CHECK(objective.number_of_degenerate_hinges() == 0);
  CHECK((scales.stiffness.array() > 0).all() && std::isinf(scales.reach.minCoeff()));
  // The stiffness is the Hessian's diagonal along the normal of the quadratic part, with the
  // masses at the input; the masses' motion changes the second difference of the whole along
  // the normal (here nearly the point's direction from the centre) by far less than it.
  const double s = scales.stiffness[7];
  const Eigen::RowVector3d along = Y.row(7).normalized();
  CF::Points ahead = Y, behind = Y;
  ahead.row(7) += 1e-4 * along;
  behind.row(7) -= 1e-4 * along;
  const double curvature = (form.value(ahead) - 2 * value + form.value(behind)) / 1e-8;
  std::cout << "  stiffness " << s << " against the second difference " << curvature << std::endl;
  CHECK(curvature > 0.5 * s && curvature < 2 * s);
  return test::report("test_operator_bending");
}
