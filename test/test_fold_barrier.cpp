// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The barrier against folds: on a hinge turned by a known angle, nothing below the threshold and
// the hand-computed term above it, the same at any size; the objective's gradient with the
// barrier against central finite differences on a crumpled patch whose hinges turn up to a fold,
// and its stiffness no smaller than without the barrier;
// no barrier (its default or weight 0) leaves the objective's value and gradient bit for bit;
// on label maps of random voxels, the fairing leaves at most half the nets' folded triangles, and
// only where the nets have them, the boxes holding exactly.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_interfaces.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_interfaces/Interface_input.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Folded_triangles.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fold_barrier.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/label_surface_nets.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
namespace CF = PMP::internal::Constrained_fairing;
using test::Indexed;
using test::Mesh;
using test::Point;

// Two triangles on the edge from (0,0,0) to (s,0,0), their normals `degrees` apart.
Mesh hinge(double degrees, double s = 1)
{
  const double a = degrees * CGAL_PI / 180;
  Mesh m;
  const auto p0 = m.add_vertex(Point(0, 0, 0)), p1 = m.add_vertex(Point(s, 0, 0));
  const auto p2 = m.add_vertex(Point(0.5 * s, s, 0));
  const auto p3 = m.add_vertex(Point(0.5 * s, -s * std::cos(a), -s * std::sin(a)));
  m.add_face(p0, p1, p2);
  m.add_face(p1, p0, p3);
  return m;
}

// The objective with the barrier of `folds` less the one without, at the input points.
double barrier_term(const Mesh& m, const CF::Fold_barrier& folds)
{
  const Indexed x(m);
  CF::Fairing_objective with(x.hinges, x.X, 0, CF::default_sliver_threshold), without(x.hinges, x.X, 0,
                                                                                        CF::default_sliver_threshold);
  with.add_fold_barrier(folds);
  return with.value(x.X) - without.value(x.X);
}

void check_values()
{
  const double weight = 7, threshold = 60;
  const CF::Fold_barrier folds(weight, threshold);
  for(double degrees : {0., 30., 59.})
    CHECK(barrier_term(hinge(degrees), folds) == 0);
  for(double degrees : {61., 90., 150., 179.})
  {
    const double over = std::cos(threshold * CGAL_PI / 180) - std::cos(degrees * CGAL_PI / 180);
    const double expected = weight * over * over;
    CHECK(std::abs(barrier_term(hinge(degrees), folds) - expected) <= 1e-9 * expected);
    // Dimensionless: the same at any size.
    CHECK(std::abs(barrier_term(hinge(degrees, 1e-3), folds) - expected) <= 1e-9 * expected);
  }
  CHECK(barrier_term(hinge(150), CF::Fold_barrier(0, threshold)) == 0);
  CHECK(barrier_term(hinge(150), CF::Fold_barrier()) == 0);
}

// A grid of 8 x 8 points crumpled at random, so that some hinges turn by more than 90 degrees.
Mesh crumpled(unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> height(-0.8, 0.8);
  Mesh m;
  const int n = 8;
  std::vector<Mesh::Vertex_index> v;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
      v.push_back(m.add_vertex(Point(i, j, height(random))));
  for(int i = 0; i + 1 < n; ++i)
    for(int j = 0; j + 1 < n; ++j)
    {
      m.add_face(v[i * n + j], v[(i + 1) * n + j], v[(i + 1) * n + j + 1]);
      m.add_face(v[i * n + j], v[(i + 1) * n + j + 1], v[i * n + j + 1]);
    }
  return m;
}

void check_gradient()
{
  for(unsigned seed : {1u, 2u, 3u})
  {
    Indexed x(crumpled(seed));
    CF::Fairing_objective objective(x.hinges, x.X, 0, CF::default_sliver_threshold);
    CF::Fairing_objective plain(x.hinges, x.X, 0, CF::default_sliver_threshold);
    objective.add_fold_barrier(CF::Fold_barrier(CF::interface_fold_weight, CF::interface_fold_angle));
    CF::Points G;
    const double value = objective.value_and_gradient(x.X, G);
    // Some hinges pay, and the value is the one value() gives.
    CHECK(value > plain.value(x.X));
    CHECK(value == objective.value(x.X));
    const double error = test::gradient_error(x.X, G, [&](const CF::Points& Y) { return objective.value(Y); }, 1e-6);
    std::cout << "  crumpled patch " << seed << ": barrier " << value - plain.value(x.X)
              << ", gradient vs finite differences, relative error " << error << std::endl;
    CHECK(error < 1e-6);

    // The stiffness that scales the quasi-Newton steps counts the barrier's hinges too.
    CF::Stiffness_and_reach with_barrier, without_barrier;
    CF::Points G_with, G_without;
    objective.value_and_gradient(x.X, G_with, &with_barrier);
    plain.value_and_gradient(x.X, G_without, &without_barrier);
    CHECK((with_barrier.stiffness.array() >= without_barrier.stiffness.array()).all());
    CHECK((with_barrier.stiffness.array() > without_barrier.stiffness.array()).any());

    // No barrier, by default or of weight 0: the same bits as the objective without it.
    for(const CF::Fold_barrier& none : {CF::Fold_barrier(), CF::Fold_barrier(0, CF::interface_fold_angle)})
    {
      CF::Fairing_objective off(x.hinges, x.X, 0, CF::default_sliver_threshold);
      off.add_fold_barrier(none);
      CF::Points G_off, G_plain;
      CHECK(off.value_and_gradient(x.X, G_off) == plain.value_and_gradient(x.X, G_plain));
      CHECK(G_off == G_plain);
    }
  }
}

// No point of the soup fixed by the user.
struct No_constraints
{
  bool is_constrained(std::size_t) const { return false; }
};

// The folded triangles of a multi-label soup with a point that moves: those whose normal points
// against the sum of its hinge neighbours' (Folded_triangles.h), the triangles oriented and the
// hinges paired as the fairing does (Interface_input.h), the result's count.
std::set<std::array<CF::Index, 3> > folds_of(std::vector<Point> points,
                                             const std::vector<std::array<std::size_t, 3> >& triangles,
                                             const std::vector<std::array<std::int64_t, 2> >& face_labels)
{
  CF::Interface_input<std::vector<Point>, std::vector<std::array<std::size_t, 3> >,
                      std::vector<std::array<std::int64_t, 2> > >
    input(points, triangles, face_labels);
  CHECK(!input.structure_error());
  const CF::Numbered_part part = input.part(No_constraints());
  const CF::Points X = input.input_points(part);
  std::vector<bool> moving(part.size());
  for(std::size_t k = 0; k < part.size(); ++k)
    moving[k] = !part.is_fixed(k);
  const CF::Hinge_mesh mesh = input.hinges(part, {}, X, CF::Fairing_settings());
  std::set<std::array<CF::Index, 3> > folded;
  for(CF::Index f : CF::folded_moving_triangles(mesh, moving, X))
    folded.insert(mesh.triangles[f]);
  return folded;
}

// Random voxels of 3 and 5 labels, whose nets have folded triangles: the fairing leaves at most
// half as many, only where the nets have them, every point in its box, and the result counts
// them. Without the barrier it left more than half on each (80, 83, 134 and 115 of 64, 80, 210
// and 216, counted with the triangles of fixed points).
void check_label_maps()
{
  for(int labels : {3, 5})
    for(unsigned seed : {1u, 2u})
    {
      const std::size_t n = 12;
      std::mt19937 random(seed);
      std::uniform_int_distribution<int> pick(0, labels - 1);
      std::vector<std::int64_t> map(n * n * n);
      for(auto& l : map)
        l = pick(random);
      std::vector<Point> nets;
      std::vector<std::array<std::size_t, 3> > triangles;
      std::vector<std::array<std::int64_t, 2> > face_labels;
      std::vector<std::array<double, 3> > half;
      PMP::label_surface_nets(map.data(), {n, n, n}, {1., 1., 1.}, {0, 0, 0}, nets, triangles, face_labels, half);
      std::vector<Point> points = nets;
      const PMP::Constrained_fairing_result r = PMP::constrained_fairing_of_interfaces(
        points, triangles, face_labels, 2.0, CFP::vertex_box_half_extents_map(CGAL::make_property_map(half)));
      CHECK(r);
      for(std::size_t p = 0; p < points.size(); ++p)
        for(int c = 0; c < 3; ++c)
          CHECK(std::abs(points[p][c] - nets[p][c]) <= half[p][std::size_t(c)]);
      const auto before = folds_of(nets, triangles, face_labels), after = folds_of(points, triangles, face_labels);
      std::cout << "  random voxels of " << labels << " labels, seed " << seed << ": " << before.size()
                << " folded triangles in the nets, " << after.size() << " faired" << std::endl;
      CHECK(!before.empty());
      CHECK(2 * after.size() <= before.size());
      // the crossing repair's pulls towards the nets bring back only the nets' folds
      CHECK(std::includes(before.begin(), before.end(), after.begin(), after.end()));
      // counted after the crossing repair
      CHECK(r.number_of_folded_faces == after.size());
    }
}

int main()
{
  check_values();
  check_gradient();
  check_label_maps();
  return test::report("test_fold_barrier");
}
