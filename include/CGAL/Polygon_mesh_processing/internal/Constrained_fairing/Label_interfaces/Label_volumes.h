// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Each label's volume held at its input value, to within that value's own uncertainty, on a
// multi-label surface:
//
//   W = w * sum over labels l of n_l * (e_l / (A_l u_l))^2,   e_l = V_l - V0_l beyond +-s_l,
//
// over the labels whose surface is closed, V_l the volume that surface encloses (the divergence
// theorem over its triangles), V0_l that of the input, A_l the input surface's area, n_l the
// label's points and u_l the smaller of h, the input's mean edge length, and the label's
// thickness t_l = |V0_l| / A_l (the mean offset that would empty it): e_l / A_l is how far the
// surface has moved outwards on average, so W charges each point w times the square of that
// offset in units of u_l, as the bending energy charges each hinge about its squared angle.
//
// Why: surface nets through the dual cells' centres are the voxels' own faces, so V0_l is the
// label's voxel count times a voxel's volume, an unbiased estimate of the region's volume, while
// the bending energy alone widens every thin convex region up to its boxes (a tube's energy falls
// as it widens). But the count errs coherently where a flat patch of voxel faces caps the region
// (all columns under a cap end between the same two grid planes): each such plateau is off by a
// uniform fraction of the spacing h_a along its normal, a standard deviation of its area times
// h_a / sqrt(12). A plateau between steps that go up on one side and down on the other (a tilted
// surface's staircase) errs little, so each counts in proportion to |up - down| / (up + down) of
// the steps around it. The slack s_l is the resulting standard deviation: held to the count
// exactly, a ball of radius 24 voxels on 1 x 1 x 3 voxels ended 7.2 times closer to the truth
// than the raw nets instead of 8.9 (doc/design_notes.md).
//
// Labels thinner than h (t_l < h: a few voxels across, or a sheet or tube a voxel or two thick)
// are held at their count: the voxels resolve no cap of them, so nothing but the count tells
// their volume, while their boxes let the whole label shrink or swell and the bending energy,
// which does not see size, takes whatever the slack allows (a small block on an interface
// flattens into it, alone it swells; the slack is 71 % of one voxel's volume, 35 % of a block of
// 2 x 2 x 2). Their offset is measured in units of t_l, since in units of h losing the whole
// label would cost each point at most (t_l / h)^2, 1 / 36 for one voxel; and each point pays
// for its three hinges (a closed surface of n points has about 3 n edges), as the bending energy
// that would flatten the label into the interfaces around it is paid per hinge: n_l is 3 n_l
// there, so that a fraction f lost costs 3 w n_l f^2 (doc/design_notes.md, "Small labels").
//
// Evaluation: the volumes are summed per block of triangles, in parallel, then over the blocks
// in order. A triangle's part of the gradient depends on its points and its labels' pulls
// only, so the objective adds it in the bending energy's tiles (Bending_energy.h), where those
// points are at hand: gathered over each point's triangles in a pass of its own, it took a
// sixth of the time on a label map of 3 M triangles.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_LABEL_VOLUMES_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_LABEL_VOLUMES_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Rows_by_vertex.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Objective_terms.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Stiffness_and_reach.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Label_volumes final : public Triangle_term
{
public:
  // `triangles[f]` runs out of the region of the label numbered `sides[f][0]` into that of
  // `sides[f][1]` (labels numbered 0, 1, ...); X0 the input points; `weight` the term's, per
  // point, against the bending energy's hinges.
  Label_volumes(const std::vector<std::array<Index, 3> >& triangles, const std::vector<std::array<Index, 2> >& sides,
                const Points& X0, double weight)
  {
    Index labels = 0;
    for(const auto& s : sides)
      labels = (std::max)(labels, Index((std::max)(s[0], s[1]) + 1));
    const std::vector<bool> closed = closed_labels(triangles, sides, labels, std::size_t(X0.rows()));
    std::vector<Index> slot(labels, none);
    for(Index l = 0; l < labels; ++l)
      if(closed[l])
        slot[l] = Index(m_targets.size()), m_targets.push_back(0);
    m_sides.resize(triangles.size());
    for(std::size_t f = 0; f < triangles.size(); ++f)
    {
      m_sides[f] = {slot[sides[f][0]], slot[sides[f][1]]};
      if(m_sides[f][0] != none || m_sides[f][1] != none)
        m_triangles.push_back({triangles[f], m_sides[f]});
    }
    if(m_targets.empty())
      return;
    m_scale = unit_scale(X0);
    m_origin = X0.colwise().mean().transpose();
    const std::size_t L = m_targets.size();
    std::vector<double> area(L, 0.);
    double length = 0;
    for(const Triangle& t : m_triangles)
    {
      const Eigen::Vector3d a = point(X0, t.v[0]), b = point(X0, t.v[1]), c = point(X0, t.v[2]);
      for(Index s : t.sides)
        if(s != none)
          area[s] += (b - a).cross(c - a).norm() / 2;
      length += (b - a).norm() + (c - b).norm() + (a - c).norm();
    }
    const double h = length / double(3 * m_triangles.size());
    // Each label's points, each counted once: the labels at each point, without repeats.
    Rows_by_vertex<Index> labels_at(std::size_t(X0.rows()), [&](const auto& add) {
      for(const Triangle& t : m_triangles)
        for(Index s : t.sides)
          if(s != none)
            for(Index v : t.v)
              add(v, s);
    });
    labels_at.sort_rows(std::less<Index>());
    std::vector<double> points(L, 0.);
    for(std::size_t v = 0; v < std::size_t(X0.rows()); ++v)
      for(auto s = labels_at.begin(v); s != labels_at.end(v); ++s)
        if(s == labels_at.begin(v) || *s != *(s - 1))
          ++points[*s];
    volumes(X0, m_targets);
    m_volumes.resize(L);
    m_pull.resize(L);
    m_slack = count_slack(X0, L);
    m_weight.resize(L);
    for(std::size_t l = 0; l < L; ++l)
    {
      const double thickness = area[l] > 0 ? std::abs(m_targets[l]) / area[l] : 0;
      const double unit = thickness > 0 ? (std::min)(h, thickness) : h;
      const bool thin = thickness < h; // held at its count, each point for its three hinges
      const double charged = thin ? 3 * points[l] : points[l];
      m_weight[l] = area[l] > 0 ? weight * charged / (area[l] * unit * area[l] * unit) : 0;
      if(thin)
        m_slack[l] = 0;
    }
  }

  // The number of labels whose volume is held, and the slack of the l-th of them (0 for a label
  // thinner than the input's mean edge length).
  std::size_t size() const { return m_targets.size(); }
  std::size_t number_of_triangles() const { return m_sides.size(); }
  double slack(std::size_t l) const { return m_slack[l]; }

  double value(const Points& X) override
  {
    volumes(X, m_volumes);
    double sum = 0;
    for(std::size_t l = 0; l < m_targets.size(); ++l)
      sum += m_weight[l] * excess(l) * excess(l);
    return sum;
  }

  // Adds the gradient to G (the term on its own; the objective adds it triangle by triangle).
  double add_gradient(const Points& X, Points& G, Stiffness_and_reach*) override
  {
    const double energy = prepare_gradient(X);
    if(m_targets.empty())
      return energy; // no closed label: the term is zero
    Points G_scaled = Points::Zero(X.rows(), 3);
    for(const Triangle& t : m_triangles)
      add_gradient(t.sides, t.v, {m_scale * point(X, t.v[0]), m_scale * point(X, t.v[1]), m_scale * point(X, t.v[2])},
                   7, G_scaled);
    G += m_scale * G_scaled;
    return energy;
  }

  // The term at X, and each label's pull on its points, which the triangles' gradients below
  // use until the next call.
  double prepare_gradient(const Points& X) override
  {
    const double energy = value(X);
    for(std::size_t l = 0; l < m_targets.size(); ++l)
      m_pull[l] = 2 * m_weight[l] * excess(l) / 6;
    return energy;
  }

  // Adds triangle f's part of the gradient, with respect to its points p = s x at unit scale
  // (Triangle_terms, Bending_energy.h), at its corners k of bit k in `corners`: its part of the
  // volume, <x0, x1 x x2> / 6 about the origin, changes by <x_(k+1) x x_(k+2), dx_k> / 6 when
  // its corner k moves. The stiffness is left as the bending energy sets it: the term acts on
  // each label as a whole, a direction that the quasi-Newton memory learns.
  void add_gradient(Index f, const std::array<Index, 3>& v, const std::array<Eigen::Vector3d, 3>& p,
                    unsigned corners, Points& G) const override
  {
    add_gradient(m_sides[f], v, p, corners, G);
  }

private:
  static constexpr Index none = Index(-1);

  void add_gradient(const std::array<Index, 2>& sides, const std::array<Index, 3>& v,
                    const std::array<Eigen::Vector3d, 3>& p, unsigned corners, Points& G) const
  {
    double c = 0;
    if(sides[0] != none)
      c += m_pull[sides[0]];
    if(sides[1] != none)
      c += -m_pull[sides[1]];
    if(c == 0)
      return;
    const double inverse_scale = 1 / m_scale; // a power of two
    const std::array<Eigen::Vector3d, 3> x{inverse_scale * p[0] - m_origin, inverse_scale * p[1] - m_origin,
                                           inverse_scale * p[2] - m_origin};
    for(std::size_t k = 0; k < 3; ++k)
      if(corners & (1u << k))
        point(G, v[k]) += (c * inverse_scale) * x[(k + 1) % 3].cross(x[(k + 2) % 3]);
  }

  // e_l: how far V_l is off its target beyond the slack.
  double excess(std::size_t l) const
  {
    const double d = m_volumes[l] - m_targets[l];
    return d > m_slack[l] ? d - m_slack[l] : d < -m_slack[l] ? d + m_slack[l] : 0;
  }

  // The slack of each label: the standard deviation of its count's error, from the plateaus of
  // its surface (edge-joined triangles in one grid plane, the same labels on their sides), the
  // spacing along each axis the median length of the input's edges along it.
  std::vector<double> count_slack(const Points& X0, std::size_t L) const
  {
    const std::size_t m = m_triangles.size();
    std::vector<int> axis(m, -1);
    std::vector<double> area(m);
    for(std::size_t f = 0; f < m; ++f)
    {
      const auto& t = m_triangles[f];
      const Eigen::Vector3d N = (point(X0, t.v[1]) - point(X0, t.v[0])).cross(point(X0, t.v[2]) - point(X0, t.v[0]));
      area[f] = N.norm() / 2;
      for(int a = 0; a < 3; ++a)
        if(X0(t.v[0], a) == X0(t.v[1], a) && X0(t.v[0], a) == X0(t.v[2], a))
          axis[f] = a;
    }
    const std::array<double, 3> h = axis_spacings(X0);
    const Plane_edges edges = plane_edges(X0, axis);
    Plateaus plateaus(m);
    for(std::size_t i = 0; i + 1 < edges.size(); ++i)
      if(is_shared(edges, i))
      {
        const std::size_t f = std::get<2>(edges[i]), g = std::get<2>(edges[i + 1]);
        if(axis[f] == axis[g] && X0(m_triangles[f].v[0], axis[f]) == X0(m_triangles[g].v[0], axis[g]) &&
           m_triangles[f].sides == m_triangles[g].sides)
          plateaus.join(f, g);
      }
    std::vector<double> up(m, 0.), around(m, 0.);
    count_steps(X0, axis, edges, plateaus, up, around);
    std::vector<double> plateau(m, 0.);
    for(std::size_t f = 0; f < m; ++f)
      if(axis[f] >= 0)
        plateau[plateaus.find(f)] += area[f] * h[std::size_t(axis[f])] / std::sqrt(12.);
    for(std::size_t f = 0; f < m; ++f)
      if(axis[f] >= 0 && plateaus.find(f) == f)
        plateau[f] *= around[f] > 0 ? std::abs(up[f]) / around[f] : 1;
    std::vector<double> variance(L, 0.);
    for(std::size_t f = 0; f < m; ++f)
      if(axis[f] >= 0 && plateaus.find(f) == f)
        for(Index s : m_triangles[f].sides)
          if(s != none)
            variance[s] += plateau[f] * plateau[f];
    std::vector<double> slack(L);
    for(std::size_t l = 0; l < L; ++l)
      slack[l] = std::sqrt(variance[l]);
    return slack;
  }

  // The plateaus as a union-find of triangles.
  struct Plateaus
  {
    explicit Plateaus(std::size_t m) : parent(m)
    {
      for(std::size_t f = 0; f < m; ++f)
        parent[f] = f;
    }
    std::size_t find(std::size_t f)
    {
      while(parent[f] != f)
        f = parent[f] = parent[parent[f]];
      return f;
    }
    void join(std::size_t f, std::size_t g) { parent[find(f)] = find(g); }
    std::vector<std::size_t> parent;
  };

  // The spacing along each axis: the median length of the input's edges along it.
  std::array<double, 3> axis_spacings(const Points& X0) const
  {
    std::array<std::vector<double>, 3> lengths;
    for(const Triangle& t : m_triangles)
      for(std::size_t k = 0; k < 3; ++k)
      {
        const Eigen::Vector3d e = point(X0, t.v[(k + 1) % 3]) - point(X0, t.v[k]);
        for(int a = 0; a < 3; ++a)
          if(e[(a + 1) % 3] == 0 && e[(a + 2) % 3] == 0 && e[a] != 0)
            lengths[std::size_t(a)].push_back(std::abs(e[a]));
      }
    std::array<double, 3> h{0, 0, 0};
    for(std::size_t a = 0; a < 3; ++a)
      if(!lengths[a].empty())
      {
        const auto middle = lengths[a].begin() + std::ptrdiff_t(lengths[a].size() / 2);
        std::nth_element(lengths[a].begin(), middle, lengths[a].end());
        h[a] = *middle;
      }
    return h;
  }

  // The edges of the triangles in a grid plane, {a, b, triangle} with a < b, sorted.
  using Plane_edges = std::vector<std::tuple<Index, Index, std::size_t> >;
  Plane_edges plane_edges(const Points& X0, const std::vector<int>& axis) const
  {
    Plane_edges edges;
    for(std::size_t f = 0; f < m_triangles.size(); ++f)
      if(axis[f] >= 0)
        for(std::size_t k = 0; k < 3; ++k)
        {
          const Index a = m_triangles[f].v[k], b = m_triangles[f].v[(k + 1) % 3];
          edges.emplace_back((std::min)(a, b), (std::max)(a, b), f);
        }
    sort_by_vertex(edges, std::size_t(X0.rows()), [](const auto& e) { return std::get<0>(e); },
                   [](const auto& a, const auto& b) { return a < b; });
    return edges;
  }

  static bool is_shared(const Plane_edges& edges, std::size_t i)
  {
    return std::get<0>(edges[i]) == std::get<0>(edges[i + 1]) && std::get<1>(edges[i]) == std::get<1>(edges[i + 1]);
  }

  // The steps around each plateau: up (+1) or down (-1) along its axis, across its edges.
  void count_steps(const Points& X0, const std::vector<int>& axis, const Plane_edges& edges, Plateaus& plateaus,
                   std::vector<double>& up, std::vector<double>& around) const
  {
    for(std::size_t i = 0; i + 1 < edges.size(); ++i)
      if(is_shared(edges, i))
        for(int swap = 0; swap < 2; ++swap)
        {
          const std::size_t f = std::get<2>(edges[i + std::size_t(swap)]);
          const std::size_t g = std::get<2>(edges[i + 1 - std::size_t(swap)]);
          if(plateaus.find(f) == plateaus.find(g))
            continue;
          const int a = axis[f];
          const double plane = X0(m_triangles[f].v[0], a);
          const double c = (X0(m_triangles[g].v[0], a) + X0(m_triangles[g].v[1], a) + X0(m_triangles[g].v[2], a)) / 3;
          up[plateaus.find(f)] += c > plane ? 1 : c < plane ? -1 : 0;
          around[plateaus.find(f)] += 1;
        }
  }

  struct Triangle
  {
    std::array<Index, 3> v;
    std::array<Index, 2> sides; // positions in m_targets, or none
  };

  // A label's surface is closed if each of its edges is run through as often one way as the
  // other by its triangles, turned to face out of the label: a triangle's side from a to b counts
  // +1 for the triangle's first label and -1 for its second where a < b, the other way round
  // where a > b, summed per edge and label.
  static std::vector<bool> closed_labels(const std::vector<std::array<Index, 3> >& triangles,
                                         const std::vector<std::array<Index, 2> >& sides, Index labels,
                                         std::size_t number_of_points)
  {
    struct Side // of an edge (a, b), a < b, in a's row
    {
      Index b;
      std::array<Index, 2> labels;
      int way;
    };
    Rows_by_vertex<Side> edges(number_of_points, [&](const auto& add) {
      for(std::size_t f = 0; f < triangles.size(); ++f)
        for(std::size_t k = 0; k < 3; ++k)
        {
          const Index a = triangles[f][k], b = triangles[f][(k + 1) % 3];
          add((std::min)(a, b), Side{(std::max)(a, b), sides[f], a < b ? 1 : -1});
        }
    });
    edges.sort_rows([](const Side& x, const Side& y) { return x.b < y.b; });
    std::vector<bool> closed(labels, true);
    std::vector<std::pair<Index, int> > balance; // of each label on one edge
    const auto add = [&balance](Index label, int way) {
      const auto found =
        std::find_if(balance.begin(), balance.end(), [label](const auto& x) { return x.first == label; });
      if(found == balance.end())
        balance.emplace_back(label, way);
      else
        found->second += way;
    };
    for(std::size_t a = 0; a < number_of_points; ++a)
      for(auto i = edges.begin(a), j = i; i != edges.end(a); i = j)
      {
        balance.clear();
        for(j = i; j != edges.end(a) && j->b == i->b; ++j)
        {
          add(j->labels[0], j->way);
          add(j->labels[1], -j->way);
        }
        for(const auto& [label, sum] : balance)
          if(sum != 0)
            closed[label] = false;
      }
    return closed;
  }

  // Each block's volumes summed in parallel, then the blocks' added in order.
  void volumes(const Points& X, std::vector<double>& V)
  {
    const std::size_t L = m_targets.size();
    m_block_volumes.assign(number_of_blocks(m_triangles.size()) * L, 0.);
    parallel_for_blocks(m_triangles.size(), [&](std::size_t begin, std::size_t end, std::size_t block) {
      double* sum = m_block_volumes.data() + block * L;
      for(std::size_t f = begin; f < end; ++f)
      {
        const Triangle& t = m_triangles[f];
        const double part = (point(X, t.v[0]) - m_origin)
                              .dot((point(X, t.v[1]) - m_origin).cross(point(X, t.v[2]) - m_origin)) / 6;
        if(t.sides[0] != none)
          sum[t.sides[0]] += part;
        if(t.sides[1] != none)
          sum[t.sides[1]] -= part;
      }
    });
    std::fill(V.begin(), V.end(), 0.);
    for(std::size_t k = 0; k < m_block_volumes.size(); ++k)
      V[k % L] += m_block_volumes[k];
  }

  std::vector<Triangle> m_triangles;              // those with a held label on a side
  std::vector<std::array<Index, 2> > m_sides;     // of each input triangle, positions in m_targets or none
  std::vector<double> m_targets, m_volumes, m_weight, m_slack;
  std::vector<double> m_pull;                     // each label's gradient factor
  std::vector<double> m_block_volumes;            // each block of triangles' sums of parts
  Eigen::Vector3d m_origin = Eigen::Vector3d::Zero();
  double m_scale = 1;                             // the unit scale of the input (Points.h)
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_LABEL_VOLUMES_H
