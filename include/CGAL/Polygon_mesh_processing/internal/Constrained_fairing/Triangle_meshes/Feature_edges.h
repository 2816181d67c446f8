// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The creases of a mesh, kept sharp: the energy has no hinge across a feature edge, and the
// feature edges form curves (Curve_network.h) faired as curves (Curve_bending.h).
//
// Detection, where the user gives an angle: a hinge is a crease when the bilaterally filtered
// normals of its two faces (Normal_filter.h) are more than the angle apart, and more than
// `jump_ratio` times the smaller angle across each face's other hinges; then the curves that end
// freely after fewer than `shortest_spur` edges (spurs off a crease, isolated edges) and the closed
// curves of fewer edges are dropped, until none is left; the curves' detours off their line are
// straightened (`straighten_creases`), judged at points smoothed by Taubin steps, since the noise
// moves a vertex by more than the distances that tell which of two vertices the crease passes. Why
// filtered normals: the dihedral angles of a noisy mesh scatter by tens of degrees (0.25 times the
// edge length of noise turns a face by about 20 degrees), so a dihedral test on the input marks
// noise and misses creases alike; the filter averages the normals on each side of a crease and
// leaves the two sides apart. Why a jump: a crease turns the surface across one edge, while a
// smooth bend of a coarse mesh, or what noise the filter left, turns it alike across the faces'
// other edges (measured in doc/design_notes.md, "Creases").

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FEATURE_EDGES_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FEATURE_EDGES_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Normal_filter.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Smoothed_start.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Rows_by_vertex.h>

#include <CGAL/number_type_config.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <set>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

struct Feature_detection
{
  static constexpr std::size_t filter_steps = 10;
  static constexpr double normal_difference_sigma = 0.4;
  static constexpr std::size_t shortest_spur = 8;
  static constexpr double jump_ratio = 1.5;
  // a jog round a vertex is swapped to it where the vertex is this many times nearer the line
  // (where the crease's sides are not apart: below)
  static constexpr double jog_ratio = 1.5;
  // Taubin steps (Smoothed_start.h) before the jogs are judged, as many as the accurate
  // objective's anchor takes (Fidelity_anchor.h)
  static constexpr std::size_t jog_smoothing_steps = 10;
};

// A bound that holds every point: Taubin steps in free space.
struct No_bound
{
  void project(Points&) const {}
};

// An edge as its two vertices, the smaller first.
inline std::array<Index, 2> sorted_edge(Index a, Index b)
{
  return a < b ? std::array<Index, 2>{a, b} : std::array<Index, 2>{b, a};
}

// Drops the curves of `edges` (sorted, each once) that end freely after fewer than `shortest`
// edges, the closed curves of fewer, and the clusters of fewer edges however joined, until none
// is left.
inline void drop_short_curves(std::vector<std::array<Index, 2> >& edges, std::size_t shortest)
{
  for(bool dropped = true; dropped && !edges.empty();)
  {
    dropped = false;
    // The edges' vertices, numbered 0 to m - 1 in increasing order, and the edges around each.
    std::vector<Index> vertex;
    for(const auto& e : edges)
      vertex.insert(vertex.end(), e.begin(), e.end());
    std::sort(vertex.begin(), vertex.end());
    vertex.erase(std::unique(vertex.begin(), vertex.end()), vertex.end());
    // each edge's ends in that numbering, found once
    std::vector<std::array<std::size_t, 2> > ends(edges.size());
    for(std::size_t e = 0; e < edges.size(); ++e)
      for(std::size_t k = 0; k < 2; ++k)
        ends[e][k] = std::size_t(std::lower_bound(vertex.begin(), vertex.end(), edges[e][k]) - vertex.begin());
    const Rows_by_vertex<std::size_t> around(vertex.size(), [&](const auto& add) {
      for(std::size_t e = 0; e < edges.size(); ++e)
        for(std::size_t v : ends[e])
          add(v, e);
    });
    const auto degree = [&around](std::size_t v) { return std::size_t(around.end(v) - around.begin(v)); };
    const auto other = [&ends](std::size_t e, std::size_t v) { return ends[e][0] == v ? ends[e][1] : ends[e][0]; };
    std::vector<bool> drop(edges.size(), false), seen(edges.size(), false);
    // From vertex v along edge e, through the vertices on two edges: the edges passed, and
    // whether the walk came back to where it started.
    std::vector<std::size_t> path;
    const auto walk = [&](std::size_t v, std::size_t e) {
      path.clear();
      const std::size_t start = v;
      for(;;)
      {
        path.push_back(e);
        seen[e] = true;
        v = other(e, v);
        if(v == start || degree(v) != 2)
          return v == start;
        e = around.begin(v)[0] == e ? around.begin(v)[1] : around.begin(v)[0];
      }
    };
    const auto drop_path = [&]() {
      if(path.size() < shortest)
        for(std::size_t e : path)
          drop[e] = true;
    };
    for(std::size_t v = 0; v < vertex.size(); ++v)
      if(degree(v) == 1 && !seen[around.begin(v)[0]])
      {
        walk(v, around.begin(v)[0]);
        drop_path();
      }
    for(std::size_t e = 0; e < edges.size(); ++e)
      if(!seen[e] && degree(ends[e][0]) == 2 && degree(ends[e][1]) == 2 && walk(ends[e][0], e))
        drop_path();
    // the clusters, by a search over the edges
    std::vector<bool> reached(edges.size(), false);
    for(std::size_t first = 0; first < edges.size(); ++first)
    {
      if(reached[first])
        continue;
      path.assign(1, first);
      reached[first] = true;
      for(std::size_t k = 0; k < path.size(); ++k)
        for(std::size_t v : ends[path[k]])
          for(auto e = around.begin(v); e != around.end(v); ++e)
            if(!reached[*e])
            {
              reached[*e] = true;
              path.push_back(*e);
            }
      drop_path();
    }
    std::size_t kept = 0;
    for(std::size_t e = 0; e < edges.size(); ++e)
      if(!drop[e])
        edges[kept++] = edges[e];
      else
        dropped = true;
    edges.resize(kept);
  }
}

// Straightens the crease curves `edges` (sorted, each once) of `mesh` where they detour by a
// triangle or two off their line, which a noisy crease's detection does: the faces between the
// detour and the true crease are then faired into the wrong side's plane, turned by the
// crease's angle. A chain of two or three edges from u to w through vertices on no other crease
// edge is replaced by the hinge u w if there is one, a chain of three around a vertex x on no
// crease by u x w, and a chain of two u y w around such a vertex x (the two triangles' other
// side) by u x w where x is nearer the crease than y is (`nearer_crease` below: across the
// crease by the planes of its sides, whose normals `face_normal(f)` gives, where they are more
// than `degrees` apart), and of two chains of two u y w and u z w (a diamond) the one farther
// from the line u w is dropped; each only if the curve heads on alike on both sides of the chain
// (a corner of the curve is kept).
// The other moves take edges off, and a swap takes off a vertex that no swap puts back, so the
// moves end; a smooth curve has no chain of the first two kinds (it would turn by 120 degrees
// within one or two edges).
template <typename Face_normal>
void straighten_creases(const Hinge_mesh& mesh, const Points& X, const Face_normal& face_normal, double degrees,
                        std::vector<std::array<Index, 2> >& edges)
{
  if(edges.empty())
    return;
  const std::size_t n = mesh.number_of_vertices;
  const Rows_by_vertex<Index> faces_around(n, [&](const auto& add) {
    for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
      for(Index v : mesh.triangles[f])
        add(v, Index(f));
  });
  const auto has_corner = [](const std::array<Index, 3>& t, Index v) { return t[0] == v || t[1] == v || t[2] == v; };
  // The plane of the faces around v that do not have `other` as a corner: the mean of their
  // normals, through the mean of their corners but v (so that v's own noise is not in it).
  // False where those normals cancel.
  const auto side_plane = [&](Index v, Index other, Eigen::Vector3d& normal, double& offset) {
    normal.setZero();
    for(auto f = faces_around.begin(v); f != faces_around.end(v); ++f)
      if(!has_corner(mesh.triangles[*f], other))
        normal += face_normal(*f);
    if(!(normal.norm() > 0))
      return false;
    normal.normalize();
    offset = 0;
    std::size_t count = 0;
    for(auto f = faces_around.begin(v); f != faces_around.end(v); ++f)
      if(!has_corner(mesh.triangles[*f], other))
        for(Index c : mesh.triangles[*f])
          if(c != v)
          {
            offset += normal.dot(X.row(c).transpose());
            ++count;
          }
    offset /= double(count);
    return true;
  };
  const double apart = std::cos(degrees * CGAL_PI / 180);
  const Rows_by_vertex<Index> neighbours(n, [&](const auto& add) {
    for(const Hinge& h : mesh.hinges)
    {
      add(h.v[0], h.v[1]);
      add(h.v[1], h.v[0]);
    }
  });
  const auto adjacent = [&](Index a, Index b) {
    return std::find(neighbours.begin(a), neighbours.end(a), b) != neighbours.end(a);
  };
  std::set<std::array<Index, 2> > creases(edges.begin(), edges.end());
  std::vector<unsigned> degree(n, 0);
  for(const auto& e : edges)
    for(Index v : e)
      ++degree[v];
  const auto remove = [&](Index a, Index b) {
    creases.erase(sorted_edge(a, b));
    --degree[a];
    --degree[b];
  };
  const auto insert = [&](Index a, Index b) {
    creases.insert(sorted_edge(a, b));
    ++degree[a];
    ++degree[b];
  };
  const auto crease_neighbour = [&](Index v, Index not_this) {
    for(auto w = neighbours.begin(v); w != neighbours.end(v); ++w)
      if(*w != not_this && creases.count(sorted_edge(v, *w)))
        return *w;
    return v;
  };
  // Whether the curve heads on alike before u (coming from u's crease neighbour other than
  // `from_u`) and after w (towards w's other than `from_w`), within 60 degrees, two edges away
  // where it can: a detour does, a corner of the curve does not. Ends and junctions tell
  // nothing, and allow the move.
  const auto two_edges_on = [&](Index v, Index from) {
    for(std::size_t step = 0; step < 2 && degree[v] == 2; ++step)
    {
      const Index next = crease_neighbour(v, from);
      from = v;
      v = next;
    }
    return v;
  };
  const auto continues = [&](Index u, Index from_u, Index w, Index from_w) {
    if(degree[u] != 2 || degree[w] != 2)
      return true;
    const Eigen::Vector3d a = (X.row(u) - X.row(two_edges_on(u, from_u))).transpose();
    const Eigen::Vector3d b = (X.row(two_edges_on(w, from_w)) - X.row(w)).transpose();
    return a.dot(b) > 0.5 * a.norm() * b.norm();
  };
  // How far m is from the line through u and w, times |w - u|.
  const auto off_chord = [&](Index m, Index u, Index w) {
    const Eigen::Vector3d a = (X.row(m) - X.row(u)).transpose(), b = (X.row(w) - X.row(u)).transpose();
    return a.cross(b).norm();
  };
  // Whether a chain u y w should go round x instead (the vertex of its two triangles on no
  // crease). A crease lies on the planes of both its sides, so where the sides (x's faces but
  // the two, and y's but those) are more than the angle apart: whether x is nearer y's side's
  // plane than y is to x's, a test across the crease whose planes average the noise, and nearer
  // the line u w, which the noise alone can turn; where the sides are not apart, whether x is
  // clearly nearer the line.
  const auto nearer_crease = [&](Index x, Index y, Index u, Index w, double y_off) {
    const double x_off = off_chord(x, u, w);
    if(!(x_off < y_off))
      return false;
    Eigen::Vector3d n_x, n_y;
    double c_x = 0, c_y = 0;
    if(side_plane(x, y, n_x, c_x) && side_plane(y, x, n_y, c_y) && n_x.dot(n_y) < apart)
      return std::abs(n_y.dot(X.row(x).transpose()) - c_y) < std::abs(n_x.dot(X.row(y).transpose()) - c_x);
    return Feature_detection::jog_ratio * x_off < y_off;
  };
  // the vertices a swap took off a curve, which no swap puts back (so that the swaps end)
  std::vector<bool> taken_off(n, false);
  // Tries the moves on the chain from u through u's crease neighbour `first`; true if one was made.
  const auto straighten = [&](Index u, Index first) {
    std::array<Index, 4> chain = {u, first, u, u};
    for(std::size_t k = 2; k <= 3; ++k)
    {
      const Index inner = chain[k - 1];
      if(degree[inner] != 2)
        return false;
      chain[k] = crease_neighbour(inner, chain[k - 2]);
      const Index w = chain[k];
      if(w == u)
        return false;
      if(!continues(u, chain[1], w, chain[k - 1]))
        continue;
      if(adjacent(u, w) && !creases.count(sorted_edge(u, w)))
      {
        for(std::size_t j = 0; j < k; ++j)
          remove(chain[j], chain[j + 1]);
        insert(u, w);
        return true;
      }
      if(k == 2)
      {
        const double inner_off = off_chord(inner, u, w);
        for(auto x = neighbours.begin(u); x != neighbours.end(u); ++x)
        {
          // the other path of a diamond, nearer the line (inner itself is not)
          if(degree[*x] == 2 && creases.count(sorted_edge(u, *x)) && creases.count(sorted_edge(*x, w)) &&
             off_chord(*x, u, w) < inner_off)
          {
            remove(u, inner);
            remove(inner, w);
            return true;
          }
          // the vertex the jog goes round, nearer the crease
          if(degree[*x] == 0 && !taken_off[*x] && adjacent(*x, w) && adjacent(*x, inner) &&
             nearer_crease(*x, inner, u, w, inner_off))
          {
            remove(u, inner);
            remove(inner, w);
            insert(u, *x);
            insert(*x, w);
            taken_off[inner] = true;
            return true;
          }
        }
      }
      if(k == 3)
        for(auto x = neighbours.begin(u); x != neighbours.end(u); ++x)
          if(degree[*x] == 0 && adjacent(*x, w))
          {
            for(std::size_t j = 0; j < k; ++j)
              remove(chain[j], chain[j + 1]);
            insert(u, *x);
            insert(*x, w);
            return true;
          }
    }
    return false;
  };
  for(bool moved = true; moved;)
  {
    moved = false;
    for(Index u = 0; u < Index(n); ++u)
      for(auto v = neighbours.begin(u); v != neighbours.end(u) && degree[u] > 0; ++v)
        if(creases.count(sorted_edge(u, *v)) && straighten(u, *v))
        {
          moved = true;
          break;
        }
  }
  edges.assign(creases.begin(), creases.end());
}

// The hinges of `mesh` whose faces' filtered normals at X are more than `degrees` apart, and
// jump (above), short curves dropped: sorted, each once.
inline std::vector<std::array<Index, 2> > detect_feature_edges(const Hinge_mesh& mesh, const Points& X, double degrees)
{
  Normal_filter filter(mesh);
  filter.set_points(X);
  filter.filter(Feature_detection::filter_steps, Feature_detection::normal_difference_sigma);
  // Each hinge's angle between the filtered normals, and each face's hinges.
  constexpr Index no_hinge = ~Index(0);
  std::vector<double> angle(mesh.hinges.size());
  std::vector<std::array<Index, 3> > face_hinges(mesh.triangles.size(), {no_hinge, no_hinge, no_hinge});
  std::vector<unsigned char> count(mesh.triangles.size(), 0);
  for(std::size_t k = 0; k < mesh.hinges.size(); ++k)
  {
    const Hinge& h = mesh.hinges[k];
    angle[k] = std::acos(std::clamp(filter.normal(h.f[0]).dot(filter.normal(h.f[1])), -1., 1.));
    for(Index f : h.f)
      face_hinges[f][count[f]++] = Index(k);
  }
  // The smallest angle across face f's hinges other than k (0 if it has none).
  const auto smallest_other = [&](Index f, std::size_t k) {
    double smallest = 0;
    bool any = false;
    for(Index j : face_hinges[f])
      if(j != no_hinge && j != k)
      {
        smallest = any ? (std::min)(smallest, angle[j]) : angle[j];
        any = true;
      }
    return smallest;
  };
  const double threshold = degrees * CGAL_PI / 180;
  std::vector<std::array<Index, 2> > edges;
  for(std::size_t k = 0; k < mesh.hinges.size(); ++k)
  {
    // a face of no area has no normal, so no crease beside it
    const Hinge& h = mesh.hinges[k];
    if(filter.normal(h.f[0]).isZero(0) || filter.normal(h.f[1]).isZero(0))
      continue;
    if(angle[k] > threshold &&
       angle[k] > Feature_detection::jump_ratio * (std::max)(smallest_other(h.f[0], k), smallest_other(h.f[1], k)))
      edges.push_back(h.v);
  }
  drop_short_curves(edges, Feature_detection::shortest_spur);
  // The detours are judged at smoothed points (top of this file).
  Points smoothed = X;
  smooth_start(mesh, No_bound(), Feature_detection::jog_smoothing_steps, smoothed);
  straighten_creases(mesh, smoothed, [&filter](Index f) { return filter.normal(f); }, degrees, edges);
  drop_short_curves(edges, Feature_detection::shortest_spur);
  return edges;
}

// Removes the hinges across the edges `edges` (sorted, each once) from `mesh`.
inline void remove_hinges(Hinge_mesh& mesh, const std::vector<std::array<Index, 2> >& edges)
{
  mesh.hinges.erase(std::remove_if(mesh.hinges.begin(), mesh.hinges.end(),
                                   [&edges](const Hinge& h) {
                                     return std::binary_search(edges.begin(), edges.end(), h.v);
                                   }),
                    mesh.hinges.end());
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FEATURE_EDGES_H
