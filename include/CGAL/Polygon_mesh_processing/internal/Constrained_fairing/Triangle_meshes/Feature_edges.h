// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The creases of a mesh, kept sharp: the energy has no hinge across a feature edge, and the
// feature edges form curves (Curve_network.h) faired as curves (Curve_bending.h).
//
// Detection, where the user gives an angle: a hinge is a crease when the guided filtered normals
// of its two faces (Guided_normal_filter.h) are more than the angle apart, and more than
// `jump_ratio` times the smaller angle across each face's other hinges; then the curves that end
// freely after fewer than `shortest_spur` edges (spurs off a crease, isolated edges) and the closed
// curves of fewer edges are dropped, until none is left; the curves' detours off their line are
// straightened (Crease_straightening.h), judged at points smoothed by Taubin steps, since the noise
// moves a vertex by more than the distances that tell which of two vertices the crease passes. Why
// filtered normals: the dihedral angles of a noisy mesh scatter by tens of degrees (0.25 times the
// edge length of noise turns a face by about 20 degrees), so a dihedral test on the input marks
// noise and misses creases alike; the filter averages the normals on each side of a crease and
// leaves the two sides apart, even those of a 45-degree chamfer, which a bilateral filter
// (Normal_filter.h) blended below 30 degrees. Why a jump: a crease turns the surface across one
// edge, while a smooth bend of a coarse mesh, or what noise the filter left, turns it alike
// across the faces' other edges (measured in doc/design_notes.md, "Creases").

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FEATURE_EDGES_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FEATURE_EDGES_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Fidelity_anchor.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Guided_normal_filter.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Smoothed_start.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Rows_by_vertex.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Triangle_meshes/Crease_straightening.h>

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

// The shortest spur and the jump (top of this file; the filter's settings are its own,
// Guided_normal_filter.h).
struct Feature_detection
{
  static constexpr std::size_t shortest_spur = 8;
  static constexpr double jump_ratio = 1.5;
  // Taubin steps (Smoothed_start.h) before the jogs are judged: the accurate objective's
  // anchor's, which the jogs' sweep from 0 to 40 steps kept
  static constexpr std::size_t jog_smoothing_steps = Fidelity_anchor::anchor_taubin_steps;
};

// A bound that holds every point: Taubin steps in free space.
struct No_bound
{
  void project(Points&) const {}
};

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

// The hinges of `mesh` whose faces' filtered normals at X are more than `degrees` apart, and
// jump (above), short curves dropped: sorted, each once.
inline std::vector<std::array<Index, 2> > detect_feature_edges(const Hinge_mesh& mesh, const Points& X, double degrees)
{
  Guided_normal_filter filter(mesh);
  filter.set_points(X);
  filter.filter(Guided_normal_filter::steps);
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
