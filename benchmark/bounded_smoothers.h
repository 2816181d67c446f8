// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The yardsticks of the accuracy benchmark: the naive way to bound a smoother. Each step moves
// every vertex at once towards the mean of its neighbours (uniform weights), then back into
// the ball of radius eps around its input position. Laplacian steps use the factor 0.5 (VTK's
// relaxation factor, vtkConstrainedSmoothingFilter); Taubin's steps alternate 0.5 and -0.53
// (G. Taubin, SIGGRAPH 1995), and one iteration is such a pair.

#ifndef CGAL_CONSTRAINED_FAIRING_BENCHMARK_BOUNDED_SMOOTHERS_H
#define CGAL_CONSTRAINED_FAIRING_BENCHMARK_BOUNDED_SMOOTHERS_H

#include "benchmark_support.h"

#include <cmath>
#include <cstddef>
#include <vector>

namespace benchmark {

class Bounded_smoother
{
public:
  enum Kind { LAPLACIAN, TAUBIN };

  Bounded_smoother(const Mesh& input, double eps, Kind kind) : m_input(input), m_eps(eps), m_kind(kind)
  {
    m_neighbours.resize(num_vertices(input));
    for(auto v : vertices(input))
      for(auto w : vertices_around_target(halfedge(v, input), input))
        m_neighbours[v.idx()].push_back(w);
  }

  // One iteration on `mesh`, which has the input's connectivity.
  void iterate(Mesh& mesh) const
  {
    step(mesh, 0.5);
    if(m_kind == TAUBIN)
      step(mesh, -0.53);
  }

private:
  void step(Mesh& mesh, double factor) const
  {
    std::vector<Point> next(num_vertices(mesh));
    for(auto v : vertices(mesh))
    {
      const auto& around = m_neighbours[v.idx()];
      K::Vector_3 mean = CGAL::NULL_VECTOR;
      for(auto w : around)
        mean = mean + (mesh.point(w) - CGAL::ORIGIN);
      const Point p = mesh.point(v);
      const Point target = around.empty() ? p : CGAL::ORIGIN + mean / double(around.size());
      next[v.idx()] = p + factor * (target - p);
    }
    for(auto v : vertices(mesh))
    {
      const Point& p0 = m_input.point(v);
      const K::Vector_3 move = next[v.idx()] - p0;
      K::Vector_3 d = move;
      // Scaled back onto the ball, shortened by a few ulps until it is inside in double.
      for(double length = std::sqrt(move.squared_length()); d.squared_length() > m_eps * m_eps; length *= 1 + 1e-15)
        d = move * (m_eps / length);
      mesh.point(v) = p0 + d;
    }
  }

  const Mesh& m_input;
  double m_eps;
  Kind m_kind;
  std::vector<std::vector<Mesh::Vertex_index> > m_neighbours;
};

} // namespace benchmark

#endif // CGAL_CONSTRAINED_FAIRING_BENCHMARK_BOUNDED_SMOOTHERS_H
