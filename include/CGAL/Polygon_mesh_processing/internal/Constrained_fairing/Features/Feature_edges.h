// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The creases of a mesh, kept sharp: the energy has no hinge across a feature edge, and the
// feature edges form curves (Curve_network.h) faired as curves (Curve_bending.h).
//
// Detection, where the user gives an angle: a hinge is a crease when the bilaterally filtered
// normals of its two faces (Normal_filter.h) are more than the angle apart; then the curves that
// end freely after fewer than `shortest_spur` edges (spurs off a crease, isolated edges) and the
// closed curves of fewer edges are dropped, until none is left. Why filtered normals: the
// dihedral angles of a noisy mesh scatter by tens of degrees (0.25 times the edge length of
// noise turns a face by about 20 degrees), so a dihedral test on the input marks noise and
// misses creases alike; the filter averages the normals on each side of a crease and leaves the
// two sides apart.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FEATURE_EDGES_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FEATURE_EDGES_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Normal_filter.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>

#include <CGAL/number_type_config.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
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
};

// An edge as its two vertices, the smaller first.
inline std::array<Index, 2> sorted_edge(Index a, Index b) { return a < b ? std::array<Index, 2>{a, b} : std::array<Index, 2>{b, a}; }

// Drops the curves of `edges` (sorted, each once) that end freely after fewer than `shortest`
// edges, and the closed curves of fewer, until none is left.
inline void drop_short_curves(std::size_t n, std::vector<std::array<Index, 2> >& edges, std::size_t shortest)
{
  for(bool dropped = true; dropped;)
  {
    dropped = false;
    std::vector<std::vector<std::size_t> > around(n); // edges by vertex
    for(std::size_t e = 0; e < edges.size(); ++e)
      for(Index v : edges[e])
        around[v].push_back(e);
    std::vector<bool> drop(edges.size(), false), seen(edges.size(), false);
    // From vertex v along edge e, through the vertices on two edges: the edges passed, and
    // whether the walk came back to where it started.
    const auto walk = [&](Index v, std::size_t e, std::vector<std::size_t>& path) {
      path.clear();
      const Index start = v;
      for(;;)
      {
        path.push_back(e);
        seen[e] = true;
        v = edges[e][0] == v ? edges[e][1] : edges[e][0];
        if(v == start || around[v].size() != 2)
          return v == start;
        e = around[v][0] == e ? around[v][1] : around[v][0];
      }
    };
    std::vector<std::size_t> path;
    for(std::size_t v = 0; v < n; ++v)
      if(around[v].size() == 1 && !seen[around[v][0]])
      {
        walk(Index(v), around[v][0], path);
        if(path.size() < shortest)
          for(std::size_t e : path)
            drop[e] = true;
      }
    for(std::size_t e = 0; e < edges.size(); ++e)
      if(!seen[e] && around[edges[e][0]].size() == 2 && around[edges[e][1]].size() == 2)
        if(walk(edges[e][0], e, path) && path.size() < shortest)
          for(std::size_t f : path)
            drop[f] = true;
    std::size_t kept = 0;
    for(std::size_t e = 0; e < edges.size(); ++e)
      if(!drop[e])
        edges[kept++] = edges[e];
      else
        dropped = true;
    edges.resize(kept);
  }
}

// The hinges of `mesh` whose faces' filtered normals at X are more than `degrees` apart, short
// curves dropped: sorted, each once.
inline std::vector<std::array<Index, 2> > detect_feature_edges(const Hinge_mesh& mesh, const Points& X, double degrees)
{
  Normal_filter filter(mesh);
  filter.set_points(X);
  filter.filter(Feature_detection::filter_steps, Feature_detection::normal_difference_sigma);
  const double cosine = std::cos(degrees * CGAL_PI / 180);
  std::vector<std::array<Index, 2> > edges;
  for(const Hinge& h : mesh.hinges)
    if(filter.normal(h.f[0]).dot(filter.normal(h.f[1])) < cosine)
      edges.push_back(h.v);
  drop_short_curves(mesh.number_of_vertices, edges, Feature_detection::shortest_spur);
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
