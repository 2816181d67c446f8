// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The bounds and the active set: the ball's membership test is the user's check; projected
// points satisfy the bound exactly in double arithmetic, as a user checks it, for coordinates
// and tolerances of very different magnitudes; projection is the nearest point; the active set
// restricts a direction to the face of the set a vertex is on, and with a gradient only where
// -g pushes outwards.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Active_set.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Deviation_bounds.h>

#include <type_traits>

namespace CF = CGAL::Polygon_mesh_processing::internal::Constrained_fairing;
using test::Point;

Point row(const CF::Points& X, Eigen::Index i) { return Point(X(i, 0), X(i, 1), X(i, 2)); }

// The user's checks, on CGAL points.
bool user_ball_check(const Point& p, const Point& p0, double eps)
{
  const double d2 = CGAL::squared_distance(p, p0);
  return d2 <= eps * eps && std::sqrt(d2) <= eps;
}

bool user_box_check(const Point& p, const Point& p0, double eps)
{
  return std::abs(p.x() - p0.x()) <= eps && std::abs(p.y() - p0.y()) <= eps && std::abs(p.z() - p0.z()) <= eps;
}

template <typename Bound>
constexpr bool is_ball = std::is_same<Bound, CF::Ball_bound>::value;

template <typename Bound>
bool user_check(const Point& p, const Point& p0, double eps)
{
  return is_ball<Bound> ? user_ball_check(p, p0, eps) : user_box_check(p, p0, eps);
}

template <typename Bound>
void check_projection()
{
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1, 1), exponent(-9, 0);
  std::size_t moved = 0, on_face = 0;
  for(double magnitude : {1e-3, 1.0, 1e3, 1e6})
  {
    const Eigen::Index n = 2000;
    CF::Points X0(n, 3), X(n, 3);
    const double eps = magnitude * std::pow(10., exponent(rng));
    for(Eigen::Index i = 0; i < n; ++i)
      for(int c = 0; c < 3; ++c)
      {
        X0(i, c) = magnitude * u(rng);
        // from well inside to far outside the bound
        X(i, c) = X0(i, c) + eps * 3 * u(rng) * (i % 3 == 0 ? 1e-3 : 1.0);
      }
    const CF::Points before = X;
    const Bound bound(X0, eps);
    bound.project(X);
    CF::Active_set<Bound> active;
    active.compute(bound, X);
    CF::Points V(n, 3);
    for(Eigen::Index i = 0; i < V.size(); ++i)
      V.data()[i] = u(rng);
    const CF::Points V_before = V;
    active.restrict(V);
    for(Eigen::Index i = 0; i < n; ++i)
    {
      const Point p = row(X, i), p0 = row(X0, i), q = row(before, i);
      CHECK(user_check<Bound>(p, p0, eps));
      CHECK(bound.contains(X, static_cast<std::size_t>(i)));
      if(user_check<Bound>(q, p0, eps))
      {
        CHECK(p == q); // feasible points do not move
        continue;
      }
      ++moved;
      // nearest point of the set, up to rounding of the coordinates
      const double slack = 64 * std::numeric_limits<double>::epsilon() * (magnitude + eps);
      if(is_ball<Bound>)
      {
        const Point exact = p0 + (q - p0) * (eps / std::sqrt(CGAL::squared_distance(q, p0)));
        CHECK(std::sqrt(CGAL::squared_distance(p, exact)) <= slack);
      }
      else
        for(int c = 0; c < 3; ++c)
          CHECK(std::abs(p[c] - std::clamp(q[c], p0[c] - eps, p0[c] + eps)) <= slack);

      // A projected point is on the face: a restricted direction does not leave it.
      const Eigen::Vector3d d = (X.row(i) - X0.row(i)).transpose();
      if(is_ball<Bound>)
        CHECK(std::abs(V.row(i).dot(d)) <= 1e-9 * V.row(i).norm() * d.norm());
      else
        for(int c = 0; c < 3; ++c)
          CHECK(V(i, c) == (X(i, c) != before(i, c) ? 0.0 : V_before(i, c)));
      ++on_face;
    }
  }
  CHECK(moved > 1000);
  CHECK(on_face == moved);
}

// With a gradient, only the vertices that -g pushes out of their set are active, and a
// restricted -g moves each vertex along its face or inwards: a short step stays inside, up
// to second order.
template <typename Bound>
void check_binding_constraints()
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const Eigen::Index n = 3000;
  const double eps = 0.01;
  CF::Points X0(n, 3), X(n, 3), G(n, 3);
  for(Eigen::Index i = 0; i < X0.size(); ++i)
  {
    X0.data()[i] = u(rng);
    X.data()[i] = X0.data()[i] + 2 * eps * u(rng);
    G.data()[i] = u(rng);
  }
  const Bound bound(X0, eps);
  bound.project(X);
  CF::Active_set<Bound> on_face, binding;
  on_face.compute(bound, X);
  binding.compute(bound, X, G);
  CHECK(binding.size() > 0);
  CHECK(binding.size() < on_face.size());

  CF::Points D = -G;
  binding.restrict(D);
  std::size_t moved_inwards = 0;
  for(Eigen::Index i = 0; i < n; ++i)
  {
    const Eigen::Vector3d d = (X.row(i) - X0.row(i)).transpose(), v = D.row(i).transpose();
    const Eigen::Vector3d g = G.row(i).transpose();
    CHECK(v.dot(g) <= 0); // still a descent direction at every vertex
    if(is_ball<Bound>)
    {
      if(d.norm() >= eps * (1 - 1e-12))
      {
        CHECK(v.dot(d) <= 1e-12 * v.norm() * d.norm()); // along the sphere or inwards
        moved_inwards += v.dot(d) < -1e-9 * v.norm() * d.norm();
      }
    }
    else
      for(int c = 0; c < 3; ++c)
      {
        const bool at_lower = X(i, c) <= X0(i, c) - eps * (1 - 1e-12), at_upper = X(i, c) >= X0(i, c) + eps * (1 - 1e-12);
        if(at_lower)
          CHECK(v[c] >= 0);
        if(at_upper)
          CHECK(v[c] <= 0);
        moved_inwards += (at_lower && v[c] > 0) || (at_upper && v[c] < 0);
      }
  }
  CHECK(moved_inwards > 0); // vertices pulled inwards are free
}

void check_max_deviation()
{
  CF::Points X0 = CF::Points::Zero(3, 3), X = X0;
  X.row(1) << 0, 3, 4;
  CHECK(CF::Ball_bound(X0, 10).max_deviation(X) == 5);
  CHECK(CF::Box_bound(X0, 10).max_deviation(X) == 5);
}

// The ball's membership test, which skips the square root well inside the ball, against the
// user's check, on points from 0.9 to 1.02 eps away, with eps from 1e-170 (where eps^2 is
// subnormal or zero) to 1e100.
void check_ball_membership()
{
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> u(-1, 1), exponent(-170, 100), radius(0.9, 1.02);
  std::size_t inside = 0, disagreements = 0;
  for(int trial = 0; trial < 200000; ++trial)
  {
    const double eps = std::pow(10., exponent(rng));
    const Point c(eps * u(rng), eps * u(rng), eps * u(rng));
    test::Vector d(u(rng), u(rng), u(rng));
    d = d / std::sqrt(d.squared_length());
    const Point q = c + radius(rng) * eps * d;
    const double qa[3] = {q.x(), q.y(), q.z()}, ca[3] = {c.x(), c.y(), c.z()};
    const bool user = user_ball_check(q, c, eps);
    inside += user;
    disagreements += CF::is_in_ball(qa, ca, eps) != user;
  }
  CHECK(disagreements == 0);
  CHECK(inside > 0 && inside < 200000);
  std::cout << "  ball membership: " << inside << " of 200000 points inside, " << disagreements
            << " disagreements with the user's check" << std::endl;
}

int main()
{
  check_ball_membership();
  check_projection<CF::Ball_bound>();
  check_projection<CF::Box_bound>();
  check_binding_constraints<CF::Ball_bound>();
  check_binding_constraints<CF::Box_bound>();
  check_max_deviation();
  return test::report("test_deviation_bounds");
}
