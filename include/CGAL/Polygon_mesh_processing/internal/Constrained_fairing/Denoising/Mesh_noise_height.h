// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One vertex's part of a mesh's noise estimate (estimate_noise_level.h): its squared height
// over the cubic fitted to its two rings, divided by the fit's variance factor. Apart from the
// estimate so that a mesh cut into tiles gives each vertex the same height from its tile as
// from the whole mesh, its two rings being in the tile.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_NOISE_HEIGHT_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_NOISE_HEIGHT_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Noise_heights.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <Eigen/Dense>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The scratch of mesh_noise_height(), kept across vertices so that they reuse its storage.
template <typename TriangleMesh>
struct Noise_height_scratch
{
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> ring;
  std::vector<Eigen::Vector3d> points;
};

// The squared normalized height of `v` into `height`; false where `v` cannot be used: an
// isolated vertex, a zero normal, fewer than noise_fit_points neighbours within two edges, an
// ill-posed fit.
template <typename TriangleMesh, typename VertexPointMap>
bool mesh_noise_height(typename boost::graph_traits<TriangleMesh>::vertex_descriptor v, const TriangleMesh& tmesh,
                       const VertexPointMap& vpm, Noise_height_scratch<TriangleMesh>& scratch, double& height)
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  const auto position = [&](vertex_descriptor w) {
    const auto& p = get(vpm, w);
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  if(halfedge(v, tmesh) == boost::graph_traits<TriangleMesh>::null_halfedge())
    return false;
  const Eigen::Vector3d p = position(v);
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for(face_descriptor f : faces_around_target(halfedge(v, tmesh), tmesh))
  {
    if(f == boost::graph_traits<TriangleMesh>::null_face())
      continue;
    const auto h = halfedge(f, tmesh);
    const Eigen::Vector3d a = position(source(h, tmesh)), b = position(target(h, tmesh)),
                          c = position(target(next(h, tmesh), tmesh));
    n += (b - a).cross(c - a);
  }
  if(!(n.norm() > 0))
    return false;
  auto& ring = scratch.ring;
  ring.clear();
  for(vertex_descriptor w : vertices_around_target(halfedge(v, tmesh), tmesh))
    ring.push_back(w);
  const std::size_t first_ring = ring.size();
  for(std::size_t k = 0; k < first_ring; ++k)
    for(vertex_descriptor w : vertices_around_target(halfedge(ring[k], tmesh), tmesh))
      if(w != v && std::find(ring.begin(), ring.end(), w) == ring.end())
        ring.push_back(w);
  if(ring.size() < noise_fit_points)
    return false;
  scratch.points.clear();
  for(vertex_descriptor w : ring)
    scratch.points.push_back(position(w));
  double residual = 0, factor = 1;
  if(!cubic_residual(p, n.normalized(), scratch.points, residual, factor))
    return false;
  height = residual * residual / factor;
  return true;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_NOISE_HEIGHT_H
