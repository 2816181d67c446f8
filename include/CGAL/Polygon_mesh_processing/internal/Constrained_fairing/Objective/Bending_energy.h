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
//    its longest squared edge (an angle of about a micro radian: degenerate_triangles() in
//    Mesh_operators.h), are left out of the energy. Their vertices are still faired by their
//    other hinges.
//  - the remaining triangles' doubled areas and normals are regularized, so that triangles
//    degenerating during the descent cannot produce a NaN: with N the cross product of two
//    edges, l = sqrt(|N|^2 + delta^2) and n = N / l, delta 1e-9 of the input's mean doubled
//    area. In double, this leaves l and n unchanged on a triangle larger than a tenth of the
//    mean, and changes them by less than 1e-12 relatively on one a thousand times smaller.
//    A triangle collapsing to zero area gets a zero normal instead of an undefined
//    one, and its hinges cost about as much as a bend between unit normals 60 degrees apart.
// The energy and its gradient are then finite on every configuration of the points.
//
// Evaluation. The energy and its gradient are the solver's main cost. On large meshes it is
// the memory traffic that costs, not the arithmetic, so the mesh is cut into tiles of
// consecutive vertices (which the Hilbert order makes compact patches) whose data fits in a
// core's cache, and each tile is evaluated in one go: the normals and areas of the triangles it
// needs, its triangles' hinges, then the gradient of its vertices. A triangle or hinge at a
// tile's border is computed by both tiles; its energy counts in the tile of its first vertex
// only. The tiles run in parallel (Parallel_for.h), each in a scratch buffer of its worker,
// with no allocation once the buffers have their sizes. Every sum runs in an order fixed by the
// tiles, so the results are the same whatever the number of threads.
//
// Terms of one triangle each (the barrier against slivers, the labels' volumes' gradient) are
// evaluated in the same tiles, where the triangle's points are at hand, rather than in passes
// of their own over the mesh (such passes took a quarter of the time on a label map of 3 M
// triangles). A model of `Triangle_terms`, at the unit-scaled points p of triangle f:
//  - `static constexpr bool active`, false for none;
//  - `double value(Index f, const std::array<Eigen::Vector3d, 3>& p) const`: the triangle's term;
//  - `double add_gradient(Index f, const std::array<Index, 3>& v, const std::array<Eigen::Vector3d, 3>& p,
//    unsigned corners, Points& G, Stiffness_and_reach* scales) const`: the term, whose gradient
//    with respect to p (and Gauss-Newton stiffness) it adds at the corners k of bit k in
//    `corners`.
// A triangle's term counts in the tile of its first corner; its gradient is added at its corners
// in the tile, in the order of the tile's triangles.
// The barrier against folds (Fold_barrier.h), a function of a hinge's |n1 - n2|^2 only, is
// added to the hinge's term where that is at hand.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BENDING_ENERGY_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BENDING_ENERGY_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Mesh_operators.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fold_barrier.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Stiffness_and_reach.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>

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

// No terms of one triangle.
struct No_triangle_terms
{
  static constexpr bool active = false;
  double value(Index, const std::array<Eigen::Vector3d, 3>&) const { return 0; }
  double add_gradient(Index, const std::array<Index, 3>&, const std::array<Eigen::Vector3d, 3>&, unsigned, Points&,
                      Stiffness_and_reach*) const
  {
    return 0;
  }
};

class Bending_energy
{
public:
  // Relative to the input's mean doubled area.
  static constexpr double area_regularization = 1e-9;
  // Vertices per tile: with their triangles and hinges, under a megabyte of scratch, which
  // stays in a core's cache.
  static constexpr std::size_t tile_size = 4096;

  // X0: the input points, which fix the regularization and the hinges left out.
  Bending_energy(const Hinge_mesh& mesh, const Points& X0) : m_mesh(mesh), m_unit_scaled(X0)
  {
    const Points& P = m_unit_scaled(X0);
    m_delta = regularization(mesh.triangles, P);
    build_tiles(degenerate_triangles(m_mesh, P));
  }

  // Whether the energy is defined on `triangles` (of a Hinge_mesh, or the same in another order)
  // with the input points X0: false if they have no area at all (in double), for the
  // regularization then vanishes.
  static bool is_defined(const std::vector<std::array<Index, 3> >& triangles, const Points& X0)
  {
    Unit_scaled_points unit_scaled(X0);
    const double delta = regularization(triangles, unit_scaled(X0));
    return delta * delta > 0;
  }

  // The number of hinges left out because of a degenerate triangle.
  std::size_t number_of_degenerate_hinges() const { return m_mesh.hinges.size() - m_number_of_hinges; }

  // The energy, plus the `terms` of the triangles (see above) and the barrier against folds of
  // the hinges (Fold_barrier.h).
  template <typename Triangle_terms = No_triangle_terms>
  double value(const Points& X, const Triangle_terms& terms = {}, const Fold_barrier& folds = {})
  {
    m_points = &m_unit_scaled(X);
    m_workers.for_each(m_tiles.size(), [&](std::size_t t, std::size_t worker) {
      m_partial[t] = evaluate_tile<false>(m_tiles[t], m_scratch[worker], nullptr, nullptr, terms, folds);
    });
    return sum_of_partials();
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
  //
  // With `terms`, adds the triangles' terms to the energy and their gradients and stiffnesses;
  // with `folds`, the hinges' terms (Fold_barrier.h) to the energy, their dE/dC to kC below and
  // their weight to w_h^2.
  template <typename Triangle_terms = No_triangle_terms>
  double value_and_gradient(const Points& X, Points& G, Stiffness_and_reach* scales = nullptr,
                            const Triangle_terms& terms = {}, const Fold_barrier& folds = {})
  {
    m_points = &m_unit_scaled(X);
    G.resize(X.rows(), 3);
    if(scales)
    {
      scales->stiffness.resize(X.rows());
      scales->reach.resize(X.rows());
    }
    m_workers.for_each(m_tiles.size(), [&](std::size_t t, std::size_t worker) {
      m_partial[t] = evaluate_tile<true>(m_tiles[t], m_scratch[worker], &G, scales, terms, folds);
    });
    return sum_of_partials();
  }

private:
  // A hinge of a tile: its edge's vertices, and where its two triangles are in the tile's list.
  // The tiles hold copies of their triangles' and hinges' vertices, so that an evaluation reads
  // them in sequence rather than through an index into the whole mesh (a tenth faster at a
  // million triangles).
  struct Tile_hinge
  {
    std::array<Index, 2> v;
    std::array<Index, 2> f;
  };

  // The vertices [vertex_begin, vertex_end); the triangles it needs, m_tile_triangles[
  // triangle_begin, triangle_end), of which the first up to `owned_triangle_end` contain one of
  // its vertices (in index order) and the others share a hinge with one of them; their hinges,
  // m_tile_hinges[hinge_begin, hinge_end), of which those up to `owned_hinge_end` start at one of
  // its vertices and count in its energy (each part in index order).
  struct Tile
  {
    std::size_t vertex_begin, vertex_end;
    std::size_t triangle_begin, owned_triangle_end, triangle_end;
    std::size_t hinge_begin, owned_hinge_end, hinge_end;
  };

  // A triangle's regularized doubled area l and unit normal n, and for the gradient what its
  // hinges add to it: in one record, so that a hinge reads and writes one place per triangle
  // (with three arrays, the evaluation took 8 % longer at a million triangles).
  struct Frame
  {
    Eigen::Vector3d n;
    double l, inverse_l;
    Eigen::Vector3d coefficient; // the triangle's a
    double hinge_weight;         // the triangle's sum of w_h^2
  };

  // What a tile computes, per triangle of the tile.
  struct Scratch
  {
    std::vector<Frame> frame;
  };

  // The regularization of the areas: a fraction of the mean doubled area at the unit-scaled
  // input points P.
  static double regularization(const std::vector<std::array<Index, 3> >& triangles, const Points& P)
  {
    const std::size_t nt = triangles.size();
    double sum = 0; // of the unregularized doubled areas
    for(const auto& t : triangles)
      sum += area_normal(P, t).norm();
    return nt == 0 ? 0 : area_regularization * sum / double(nt);
  }

  static constexpr Index no_hinge = ~Index(0);

  // The counted hinges of each triangle (no_hinge for the others), and their number.
  std::vector<std::array<Index, 3> > counted_hinges(const std::vector<bool>& degenerate)
  {
    std::vector<std::array<Index, 3> > triangle_hinges(m_mesh.triangles.size(), {no_hinge, no_hinge, no_hinge});
    m_number_of_hinges = 0;
    for(std::size_t h = 0; h < m_mesh.hinges.size(); ++h)
    {
      const Hinge& hinge = m_mesh.hinges[h];
      if(degenerate[hinge.f[0]] || degenerate[hinge.f[1]])
        continue;
      ++m_number_of_hinges;
      for(Index f : hinge.f)
        *std::find(triangle_hinges[f].begin(), triangle_hinges[f].end(), no_hinge) = static_cast<Index>(h);
    }
    return triangle_hinges;
  }

  // The tiles: the triangles and hinges each needs.
  void build_tiles(const std::vector<bool>& degenerate)
  {
    const std::size_t n = m_mesh.number_of_vertices, nt = m_mesh.triangles.size();
    constexpr Index none = no_hinge;
    const std::vector<std::array<Index, 3> > triangle_hinges = counted_hinges(degenerate);
    const Rows_by_vertex<Index> around = vertex_triangles(m_mesh);

    // Each tile's triangles, numbered in the tile by `slot` (valid where `stamp` is the tile's
    // number), and hinges.
    std::vector<Index> triangle_stamp(nt, none), triangle_slot(nt), hinge_stamp(m_mesh.hinges.size(), none);
    std::size_t largest_triangles = 0;
    std::vector<Tile_hinge> others;
    std::vector<Index> owned, hinges, triangle_ids;
    for(std::size_t begin = 0; begin < n; begin += tile_size)
    {
      const Index t = static_cast<Index>(m_tiles.size());
      Tile tile;
      tile.vertex_begin = begin;
      tile.vertex_end = (std::min)(begin + tile_size, n);
      tile.triangle_begin = m_tile_triangles.size();
      triangle_ids.clear();
      const auto add_triangle = [&](Index f) {
        if(triangle_stamp[f] == t)
          return;
        triangle_stamp[f] = t;
        triangle_slot[f] = static_cast<Index>(m_tile_triangles.size() - tile.triangle_begin);
        m_tile_triangles.push_back(m_mesh.triangles[f]);
        m_tile_triangle_ids.push_back(f);
        triangle_ids.push_back(f);
      };
      // The triangles of its vertices, in index order (neighbours in memory).
      owned.clear();
      for(std::size_t i = tile.vertex_begin; i < tile.vertex_end; ++i)
        owned.insert(owned.end(), around.begin(i), around.end(i));
      std::sort(owned.begin(), owned.end());
      for(Index f : owned)
        add_triangle(f);
      tile.owned_triangle_end = m_tile_triangles.size();
      // The hinges of the tile's triangles, those starting in the tile first, each part in
      // index order.
      tile.hinge_begin = m_tile_hinges.size();
      others.clear();
      hinges.clear();
      for(Index f : triangle_ids)
        for(Index h : triangle_hinges[f])
          if(h != none && hinge_stamp[h] != t)
          {
            hinge_stamp[h] = t;
            hinges.push_back(h);
          }
      std::sort(hinges.begin(), hinges.end());
      for(Index h : hinges)
      {
        const Hinge& hinge = m_mesh.hinges[h];
        add_triangle(hinge.f[0]);
        add_triangle(hinge.f[1]);
        const Tile_hinge local{hinge.v, {triangle_slot[hinge.f[0]], triangle_slot[hinge.f[1]]}};
        if(hinge.v[0] >= tile.vertex_begin && hinge.v[0] < tile.vertex_end)
          m_tile_hinges.push_back(local);
        else
          others.push_back(local);
      }
      tile.owned_hinge_end = m_tile_hinges.size();
      m_tile_hinges.insert(m_tile_hinges.end(), others.begin(), others.end());
      tile.triangle_end = m_tile_triangles.size();
      tile.hinge_end = m_tile_hinges.size();
      largest_triangles = (std::max)(largest_triangles, tile.triangle_end - tile.triangle_begin);
      m_tiles.push_back(tile);
    }
    m_partial.resize(m_tiles.size());
    m_scratch.resize(m_workers.size());
    for(Scratch& scratch : m_scratch)
      scratch.frame.resize(largest_triangles);
  }

  // The tile's energy (its own hinges' terms, in order, then its triangles' terms); with
  // `gradient`, also the gradient, and the scales if asked, of its vertices.
  template <bool gradient, typename Triangle_terms>
  double evaluate_tile(const Tile& tile, Scratch& scratch, Points* G, Stiffness_and_reach* scales,
                       const Triangle_terms& terms, const Fold_barrier& folds) const
  {
    compute_frames<gradient>(tile, scratch);
    if constexpr(gradient)
      clear_gradient(tile, *G, scales);
    double energy = 0;
    add_hinges<gradient>(tile, scratch, G, folds, energy);
    if constexpr(!gradient)
    {
      add_triangle_values(tile, terms, energy);
      return energy;
    }
    else
    {
      add_corners(tile, scratch, *G, scales, terms, energy);
      scale_back(tile, *G, scales);
      return energy;
    }
  }

  // The frames of the tile's triangles at the points: for the energy those of the tile's own
  // hinges' triangles, which contain a vertex of the tile; for the gradient all of them, their
  // hinges' coefficients and weights cleared.
  template <bool gradient>
  void compute_frames(const Tile& tile, Scratch& scratch) const
  {
    const Points& P = *m_points;
    const std::array<Index, 3>* triangles = m_tile_triangles.data() + tile.triangle_begin;
    const std::size_t frames = (gradient ? tile.triangle_end : tile.owned_triangle_end) - tile.triangle_begin;
    for(std::size_t k = 0; k < frames; ++k)
    {
      const auto& v = triangles[k];
      const Eigen::Vector3d p0 = point(P, v[0]);
      const Eigen::Vector3d N = (point(P, v[1]) - p0).cross(point(P, v[2]) - p0);
      const double l = std::sqrt(N.squaredNorm() + m_delta * m_delta);
      scratch.frame[k].l = l;
      scratch.frame[k].inverse_l = l > 0 ? 1 / l : 0;
      // N / l, not N times 1 / l: a flat hinge's normals are then equal to the last bit.
      scratch.frame[k].n = l > 0 ? Eigen::Vector3d(N / l) : Eigen::Vector3d::Zero();
      if(gradient)
      {
        scratch.frame[k].coefficient.setZero();
        scratch.frame[k].hinge_weight = 0;
      }
    }
  }

  // The gradient, and the scales if asked, of the tile's vertices set to zero, before the terms
  // are added to them.
  static void clear_gradient(const Tile& tile, Points& G, Stiffness_and_reach* scales)
  {
    for(std::size_t i = tile.vertex_begin; i < tile.vertex_end; ++i)
    {
      point(G, i).setZero();
      if(scales)
      {
        scales->stiffness[static_cast<Eigen::Index>(i)] = 0;
        scales->reach[static_cast<Eigen::Index>(i)] = 0;
      }
    }
  }

  // Adds the terms of the tile's own hinges, in order, to `energy`; with `gradient`, goes over
  // all the tile's hinges, adding each one's coefficients and weights to its triangles' frames
  // and its edge's term to its vertices in the tile, as they are computed.
  template <bool gradient>
  void add_hinges(const Tile& tile, Scratch& scratch, Points* G, const Fold_barrier& folds, double& energy) const
  {
    const Points& P = *m_points;
    const std::size_t first = tile.vertex_begin, size = tile.vertex_end - tile.vertex_begin;
    const std::size_t owned = tile.owned_hinge_end - tile.hinge_begin;
    const std::size_t hinges = (gradient ? tile.hinge_end : tile.owned_hinge_end) - tile.hinge_begin;
    for(std::size_t j = 0; j < hinges; ++j)
    {
      const Tile_hinge& hinge = m_tile_hinges[tile.hinge_begin + j];
      Frame& F1 = scratch.frame[hinge.f[0]];
      Frame& F2 = scratch.frame[hinge.f[1]];
      const Eigen::Vector3d e = point(P, hinge.v[1]) - point(P, hinge.v[0]);
      const Eigen::Vector3d d = F1.n - F2.n;
      const double L = e.squaredNorm(), inverse_S = 1 / (F1.l + F2.l), C = 0.5 * d.squaredNorm();
      const double kC = 1.5 * L * inverse_S; // dE/dC
      if(j < owned)
        energy += kC * C + folds.value(C);
      if(!gradient)
        continue;
      const double kS = -kC * C * inverse_S; // dE/dS
      const double kN = kC + folds.derivative(C); // d(E + P)/dC
      F1.coefficient += (kN * F1.inverse_l) * (d - d.dot(F1.n) * F1.n) + kS * F1.n;
      F2.coefficient -= (kN * F2.inverse_l) * (d - d.dot(F2.n) * F2.n) - kS * F2.n;
      const double weight = 0.5 * kC + folds.stiffness_weight(C); // w_h^2, and the barrier's
      F1.hinge_weight += weight;
      F2.hinge_weight += weight;
      const Eigen::Vector3d edge_term = (3 * C * inverse_S) * e; // 2 dE/dL times the edge
      if(hinge.v[0] - first < size)
        point(*G, hinge.v[0]) -= edge_term;
      if(hinge.v[1] - first < size)
        point(*G, hinge.v[1]) += edge_term;
    }
  }

  // Adds the terms of the triangles that count in the tile (those of its first corner in it), in
  // order, to `energy`.
  template <typename Triangle_terms>
  void add_triangle_values(const Tile& tile, const Triangle_terms& terms, double& energy) const
  {
    if(!Triangle_terms::active)
      return;
    const Points& P = *m_points;
    const std::array<Index, 3>* triangles = m_tile_triangles.data() + tile.triangle_begin;
    const Index* ids = m_tile_triangle_ids.data() + tile.triangle_begin;
    const std::size_t first = tile.vertex_begin, size = tile.vertex_end - tile.vertex_begin;
    for(std::size_t k = 0; k < tile.owned_triangle_end - tile.triangle_begin; ++k)
    {
      const auto& v = triangles[k];
      if(v[0] - first < size)
        energy += terms.value(ids[k], {point(P, v[0]), point(P, v[1]), point(P, v[2])});
    }
  }

  // Then the corners' terms of the gradient: for each triangle with a corner in the tile, its
  // triangle terms' gradient (their values added to `energy` where they count in the tile), then
  // its frame's coefficient at its corners in the tile, and with `scales` their stiffness and
  // inverse squared reach. Each triangle's edges are computed once, for its corners in the tile.
  template <typename Triangle_terms>
  void add_corners(const Tile& tile, const Scratch& scratch, Points& G, Stiffness_and_reach* scales,
                   const Triangle_terms& terms, double& energy) const
  {
    const Points& P = *m_points;
    const std::array<Index, 3>* triangles = m_tile_triangles.data() + tile.triangle_begin;
    const Index* ids = m_tile_triangle_ids.data() + tile.triangle_begin;
    const std::size_t first = tile.vertex_begin, size = tile.vertex_end - tile.vertex_begin;
    for(std::size_t k = 0; k < tile.owned_triangle_end - tile.triangle_begin; ++k)
    {
      const auto& v = triangles[k];
      const std::array<Eigen::Vector3d, 3> p{point(P, v[0]), point(P, v[1]), point(P, v[2])};
      if(Triangle_terms::active)
      {
        unsigned corners = 0;
        for(std::size_t corner = 0; corner < 3; ++corner)
          if(v[corner] - first < size)
            corners |= 1u << corner;
        const double term = terms.add_gradient(ids[k], v, p, corners, G, scales);
        if(v[0] - first < size)
          energy += term;
      }
      const double inverse_l2 = scratch.frame[k].inverse_l * scratch.frame[k].inverse_l;
      for(std::size_t corner = 0; corner < 3; ++corner)
      {
        if(v[corner] - first >= size)
          continue;
        const Eigen::Vector3d opposite = p[(corner + 2) % 3] - p[(corner + 1) % 3];
        point(G, v[corner]) += scratch.frame[k].coefficient.cross(opposite);
        if(scales)
        {
          // the stiffness and the inverse squared reach, until scaled below
          const auto row = static_cast<Eigen::Index>(v[corner]);
          const double o2 = opposite.squaredNorm() * inverse_l2;
          scales->stiffness[row] += scratch.frame[k].hinge_weight * o2;
          scales->reach[row] = (std::max)(scales->reach[row], o2);
        }
      }
    }
  }

  // The gradient and the scales of the tile's vertices back from the scaled points: E(s X) = E(X).
  void scale_back(const Tile& tile, Points& G, Stiffness_and_reach* scales) const
  {
    const double scale = m_unit_scaled.scale();
    for(std::size_t i = tile.vertex_begin; i < tile.vertex_end; ++i)
    {
      if(scale != 1)
        point(G, i) = Eigen::Vector3d(scale * point(G, i));
      if(scales)
      {
        const auto row = static_cast<Eigen::Index>(i);
        scales->stiffness[row] = scale * scale * scales->stiffness[row];
        scales->reach[row] = scales->reach[row] > 0 ? 1 / (scale * std::sqrt(scales->reach[row]))
                                                    : std::numeric_limits<double>::infinity();
      }
    }
  }

  double sum_of_partials() const
  {
    double sum = 0;
    for(double s : m_partial)
      sum += s;
    return sum;
  }

  const Hinge_mesh& m_mesh;
  std::size_t m_number_of_hinges = 0; // those without a degenerate triangle
  Unit_scaled_points m_unit_scaled;
  double m_delta = 0;
  std::vector<Tile> m_tiles;
  std::vector<std::array<Index, 3> > m_tile_triangles;
  std::vector<Index> m_tile_triangle_ids; // their numbers in the mesh
  std::vector<Tile_hinge> m_tile_hinges;
  Worker_pool m_workers;
  std::vector<Scratch> m_scratch; // one per worker
  // recomputed at each evaluation: the scaled points, and the tiles' energies
  const Points* m_points = nullptr;
  std::vector<double> m_partial;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BENDING_ENERGY_H
