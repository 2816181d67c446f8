// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The discrete bending energy of Wardetzky et al., eq. (1) of Hildebrandt & Polthier (2007):
//
//   E = sum over interior edges e of  3 |e|^2 / (2 A_e) * cos(theta_e / 2)^2,
//
// A_e the summed area of the two triangles at e, theta_e the dihedral angle between them
// (pi when flat). With unit normals n1, n2, cos(theta_e / 2)^2 = (1 - <n1, n2>) / 2, so a
// hinge contributes (3/4) |e|^2 |n1 - n2|^2 / (2 A_e), and that last form keeps full
// relative precision on nearly flat hinges.
//
// Degenerate triangles. A triangle of zero area has no normal, and near zero its normal turns
// wildly under tiny moves: a hinge containing it has no meaningful dihedral angle, and its
// steep energy would throttle every step of the descent. So:
//  - hinges with a triangle that is degenerate in the input, of doubled area at most 1e-6 of
//    its longest squared edge (an angle of about a micro radian), are left out of the energy.
//    Their vertices are still faired by their other hinges.
//  - the remaining triangles' doubled areas and normals are regularized, so that triangles
//    degenerating during the descent cannot produce a NaN: with N the cross product of two
//    edges, l = sqrt(|N|^2 + delta^2) and n = N / l, delta 1e-9 of the input's mean doubled
//    area. In double, this leaves l and n unchanged on a triangle larger than a tenth of the
//    mean, and changes them by less than 1e-12 relatively on one a thousand times smaller.
//    A triangle collapsing to zero area gets a zero normal instead of an undefined
//    one, and its hinges cost about as much as a bend between unit normals 60 degrees apart.
// The energy and its gradient are then finite on every configuration of the points.
//
// Evaluation. The energy and its gradient are the solver's main cost, so they are computed
// in passes that run in parallel (Parallel_for.h) with no allocation once the buffers have
// their sizes: the triangles' normals and areas; the hinges, each computed once, adding its
// terms to its two triangles; per vertex, the gradient gathered from its corners and edges.
// The hinges are coloured so that no two of a colour share a triangle (at most five colours,
// a triangle having at most three hinges), and the colours are passed one after the other:
// within one, every triangle is written by one hinge only, and each triangle sums its
// hinges' terms in the same order whatever the number of threads.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BENDING_ENERGY_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BENDING_ENERGY_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Points.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// What the quasi-Newton method needs to know of each vertex besides the gradient.
struct Vertex_scales
{
  // along the surface normal: the Gauss-Newton diagonal (see value_and_gradient())
  Eigen::VectorXd stiffness;
  // the smallest height of the vertex over the opposite edge in its triangles: a move shorter
  // than that cannot flip or collapse one of them
  Eigen::VectorXd reach;

  void swap(Vertex_scales& other)
  {
    stiffness.swap(other.stiffness);
    reach.swap(other.reach);
  }
};

class Bending_energy
{
public:
  // Relative to the input's mean doubled area.
  static constexpr double area_regularization = 1e-9;
  // Relative to a triangle's longest squared edge.
  static constexpr double degenerate_area = 1e-6;

  // X0: the input points, which fix the regularization and the hinges left out.
  Bending_energy(const Hinge_mesh& mesh, const Points& X0) : m_mesh(mesh), m_scale(unit_scale(X0))
  {
    compute_triangles(X0);
    const std::size_t nt = m_mesh.triangles.size();
    double sum = 0; // of the unregularized doubled areas, delta being 0 so far
    std::vector<bool> degenerate(nt);
    for(std::size_t f = 0; f < nt; ++f)
    {
      sum += m_frame[f].l;
      const auto& v = m_mesh.triangles[f];
      double longest = 0;
      for(int k = 0; k < 3; ++k)
        longest = (std::max)(longest, (point(*m_points, v[k]) - point(*m_points, v[(k + 1) % 3])).squaredNorm());
      degenerate[f] = !(m_frame[f].l > degenerate_area * longest);
    }
    m_delta = nt == 0 ? 0 : area_regularization * sum / double(nt);
    build_adjacency(degenerate);
  }

  // False if the input has no area at all (in double): then the regularization vanishes
  // and the energy is undefined.
  bool is_defined() const { return m_delta * m_delta > 0; }

  // The number of hinges left out because of a degenerate triangle.
  std::size_t number_of_degenerate_hinges() const { return m_mesh.hinges.size() - m_number_of_hinges; }

  double value(const Points& X)
  {
    compute_triangles(X);
    return hinge_pass<false>();
  }

  // Returns the energy and writes its gradient to G (resized to X's shape). With
  // L = |e|^2, S = l1 + l2 and C = |n1 - n2|^2 / 2 (l and n the regularized doubled areas and
  // normals of the triangles T1 = (p0, p1, p2) and T2 = (p1, p0, p3) of a hinge), a hinge
  // contributes (3/2) L C / S, and
  //   dE = (3/2) (C/S dL + L/S dC - L C/S^2 dS).
  // For a triangle, dl = <n, dN> and dn = (dN - n <n, dN>) / l, so dS and dC are linear in the
  // triangles' dN: each hinge adds a vector coefficient a to each of its two triangles, with
  // dE = sum <a, dN>. Moving vertex k of a triangle by d changes N by d x (p_(k+1) - p_(k+2)),
  // so the triangle then adds a x (p_(k+2) - p_(k+1)) to the gradient at that vertex.
  //
  // With `scales`, also writes each vertex's reach and its stiffness along the surface normal: the
  // diagonal of the Gauss-Newton model of the Hessian, which drops the second derivatives of
  // the normals. Written as E = sum |r_h|^2 with r_h = w_h (n1 - n2), w_h^2 = 3 L / (4 S), and
  // |dn/dp| = |p_(k+2) - p_(k+1)| / l for vertex k of a triangle (one over its height), a vertex
  // gets sum over its corners of |p_(k+2) - p_(k+1)|^2 / l^2 times the triangle's sum of w_h^2.
  // It ranges over orders of magnitude on scans (small and needle triangles are stiff), which is
  // what the quasi-Newton method scales its steps by.
  double value_and_gradient(const Points& X, Points& G, Vertex_scales* scales = nullptr)
  {
    compute_triangles(X);
    const double energy = hinge_pass<true>();
    G.resize(X.rows(), 3);
    if(scales)
    {
      scales->stiffness.resize(X.rows());
      scales->reach.resize(X.rows());
    }
    const Points& P = *m_points;
    const double scale = m_scale; // back from the scaled points: E(s X) = E(X)
    parallel_for_blocks(m_mesh.number_of_vertices, [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t i = begin; i < end; ++i)
      {
        Eigen::Vector3d g = Eigen::Vector3d::Zero();
        double k_normal = 0, height2 = std::numeric_limits<double>::infinity();
        for(Index c = m_corner_begin[i]; c < m_corner_begin[i + 1]; ++c)
        {
          const Index f = m_corners[c] / 3, k = m_corners[c] % 3;
          const auto& v = m_mesh.triangles[f];
          const Eigen::Vector3d opposite = point(P, v[(k + 2) % 3]) - point(P, v[(k + 1) % 3]);
          g += m_coefficient[f].cross(opposite);
          const double l2 = m_frame[f].l * m_frame[f].l, o2 = opposite.squaredNorm();
          k_normal += m_hinge_weight[f] * o2 / l2;
          if(o2 > 0)
            height2 = (std::min)(height2, l2 / o2);
        }
        for(Index c = m_endpoint_begin[i]; c < m_endpoint_begin[i + 1]; ++c)
        {
          const Index h = m_endpoints[c] / 2;
          const auto& v = m_mesh.hinges[h].v;
          const Eigen::Vector3d e = point(P, v[1]) - point(P, v[0]);
          if(m_endpoints[c] % 2 == 0)
            g -= m_edge_factor[h] * e;
          else
            g += m_edge_factor[h] * e;
        }
        point(G, i) = scale == 1 ? g : Eigen::Vector3d(scale * g);
        if(scales)
        {
          scales->stiffness[static_cast<Eigen::Index>(i)] = scale * scale * k_normal;
          scales->reach[static_cast<Eigen::Index>(i)] = std::sqrt(height2) / scale;
        }
      }
    });
    return energy;
  }

private:
  // Of the hinges, so that no two of a colour share a triangle.
  static constexpr std::size_t max_colours = 5;

  // A triangle's regularized doubled area l and unit normal n.
  struct Frame
  {
    Eigen::Vector3d n;
    double l;
  };

  // The counted hinges in colour order, and for each vertex its corners (3 f + k) and the
  // hinges it ends (2 h + end), both in CSR form.
  void build_adjacency(const std::vector<bool>& degenerate)
  {
    const std::size_t n = m_mesh.number_of_vertices;
    m_corner_begin.assign(n + 1, 0);
    m_endpoint_begin.assign(n + 1, 0);
    for(const auto& t : m_mesh.triangles)
      for(Index v : t)
        ++m_corner_begin[v + 1];
    // Greedy colouring: a hinge takes the smallest colour that no other hinge of its two
    // triangles has yet; the hinges are then listed colour by colour, in index order.
    std::vector<std::uint8_t> colour(m_mesh.hinges.size(), 0);
    std::vector<std::uint8_t> used(m_mesh.triangles.size(), 0); // colours taken, as bits
    std::array<std::size_t, max_colours + 1> count{};
    m_number_of_hinges = 0;
    for(std::size_t h = 0; h < m_mesh.hinges.size(); ++h)
    {
      const Hinge& hinge = m_mesh.hinges[h];
      if(degenerate[hinge.f[0]] || degenerate[hinge.f[1]])
        continue;
      ++m_number_of_hinges;
      const unsigned taken = used[hinge.f[0]] | used[hinge.f[1]];
      std::uint8_t c = 0;
      while(taken & (1u << c))
        ++c;
      colour[h] = c;
      ++count[c + 1];
      for(Index side = 0; side < 2; ++side)
      {
        used[hinge.f[side]] = static_cast<std::uint8_t>(used[hinge.f[side]] | (1u << c));
        ++m_endpoint_begin[hinge.v[side] + 1];
      }
    }
    for(std::size_t c = 0; c < max_colours; ++c)
      count[c + 1] += count[c];
    m_colour_begin.assign(count.begin(), count.end());
    m_hinge_order.resize(m_number_of_hinges);
    for(std::size_t h = 0; h < m_mesh.hinges.size(); ++h)
    {
      const Hinge& hinge = m_mesh.hinges[h];
      if(!degenerate[hinge.f[0]] && !degenerate[hinge.f[1]])
        m_hinge_order[count[colour[h]]++] = static_cast<Index>(h);
    }
    for(std::size_t i = 0; i < n; ++i)
    {
      m_corner_begin[i + 1] += m_corner_begin[i];
      m_endpoint_begin[i + 1] += m_endpoint_begin[i];
    }
    m_corners.resize(m_corner_begin[n]);
    m_endpoints.resize(m_endpoint_begin[n]);
    std::vector<Index> next(m_corner_begin.begin(), m_corner_begin.end() - 1);
    for(std::size_t f = 0; f < m_mesh.triangles.size(); ++f)
      for(Index k = 0; k < 3; ++k)
        m_corners[next[m_mesh.triangles[f][k]]++] = static_cast<Index>(3 * f + k);
    next.assign(m_endpoint_begin.begin(), m_endpoint_begin.end() - 1);
    for(std::size_t h = 0; h < m_mesh.hinges.size(); ++h)
    {
      const Hinge& hinge = m_mesh.hinges[h];
      if(!degenerate[hinge.f[0]] && !degenerate[hinge.f[1]])
        for(Index end = 0; end < 2; ++end)
          m_endpoints[next[hinge.v[end]]++] = static_cast<Index>(2 * h + end);
    }
    m_coefficient.resize(m_mesh.triangles.size());
    m_hinge_weight.resize(m_mesh.triangles.size());
    m_edge_factor.resize(m_mesh.hinges.size());
  }

  // The scaled points s X, and the regularized doubled area l and normal n of every
  // triangle.
  void compute_triangles(const Points& X)
  {
    if(m_scale == 1)
      m_points = &X;
    else
    {
      m_scaled.noalias() = m_scale * X;
      m_points = &m_scaled;
    }
    const Points& P = *m_points;
    m_frame.resize(m_mesh.triangles.size());
    parallel_for_blocks(m_mesh.triangles.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t f = begin; f < end; ++f)
      {
        const auto& v = m_mesh.triangles[f];
        const Eigen::Vector3d p0 = point(P, v[0]);
        const Eigen::Vector3d N = (point(P, v[1]) - p0).cross(point(P, v[2]) - p0);
        const double l = std::sqrt(N.squaredNorm() + m_delta * m_delta);
        m_frame[f].l = l;
        m_frame[f].n = l > 0 ? Eigen::Vector3d(N / l) : Eigen::Vector3d::Zero();
      }
    });
  }

  // The energy, colour by colour (so that value() and value_and_gradient() add the same
  // terms in the same order); with `gradient`, also each triangle's coefficient a and sum of
  // w_h^2, and each hinge's edge factor 2 dE/dL.
  template <bool gradient>
  double hinge_pass()
  {
    if(gradient)
      parallel_for_blocks(m_mesh.triangles.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
        for(std::size_t f = begin; f < end; ++f)
        {
          m_coefficient[f].setZero();
          m_hinge_weight[f] = 0;
        }
      });
    double energy = 0;
    for(std::size_t c = 0; c < max_colours; ++c)
    {
      const std::size_t first = m_colour_begin[c];
      energy += parallel_sum(m_colour_begin[c + 1] - first, m_partial, [&](std::size_t begin, std::size_t end) {
        double sum = 0;
        for(std::size_t k = first + begin; k < first + end; ++k)
        {
          const Index h = m_hinge_order[k];
          const Hinge& hinge = m_mesh.hinges[h];
          const Frame& F1 = m_frame[hinge.f[0]];
          const Frame& F2 = m_frame[hinge.f[1]];
          const Eigen::Vector3d e = point(*m_points, hinge.v[1]) - point(*m_points, hinge.v[0]);
          const Eigen::Vector3d d = F1.n - F2.n;
          const double L = e.squaredNorm(), S = F1.l + F2.l, C = 0.5 * d.squaredNorm();
          const double kC = 1.5 * L / S; // dE/dC
          sum += kC * C;
          if(!gradient)
            continue;
          const double kS = -kC * C / S; // dE/dS
          m_coefficient[hinge.f[0]] += (kC / F1.l) * (d - d.dot(F1.n) * F1.n) + kS * F1.n;
          m_coefficient[hinge.f[1]] -= (kC / F2.l) * (d - d.dot(F2.n) * F2.n) - kS * F2.n;
          m_hinge_weight[hinge.f[0]] += 0.5 * kC;
          m_hinge_weight[hinge.f[1]] += 0.5 * kC;
          m_edge_factor[h] = 3 * C / S;
        }
        return sum;
      });
    }
    return energy;
  }

  const Hinge_mesh& m_mesh;
  std::size_t m_number_of_hinges = 0; // those without a degenerate triangle
  double m_scale, m_delta = 0;
  std::vector<Index> m_hinge_order;         // the counted hinges, colour by colour
  std::vector<std::size_t> m_colour_begin; // where each colour starts in m_hinge_order
  std::vector<Index> m_corner_begin, m_corners, m_endpoint_begin, m_endpoints;
  // recomputed at each evaluation: the scaled points (X itself when the scale is 1), and per
  // triangle and hinge
  const Points* m_points = nullptr;
  Points m_scaled;
  std::vector<Frame> m_frame;
  std::vector<Eigen::Vector3d> m_coefficient;
  std::vector<double> m_hinge_weight, m_edge_factor, m_partial;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BENDING_ENERGY_H
