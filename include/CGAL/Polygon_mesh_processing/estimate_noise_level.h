// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PMP_ESTIMATE_NOISE_LEVEL_H
#define CGAL_PMP_ESTIMATE_NOISE_LEVEL_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Noise_heights.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

/*!
\ingroup PkgConstrainedFairingRef

\brief estimates the noise of a triangle mesh, as a distance to pass as `epsilon` to
`constrained_fairing()`.

At each vertex, a cubic height field is fitted by least squares to its neighbours up to two
edges away, in the frame of the vertex normal; the vertex's height over it is the noise along
the normal plus the fit's own error, whose variance the fit gives. The median of the squared
heights, each divided by its variance factor, is then that of a noise uniform in a ball of
radius `r`, and `r` is returned: on a mesh whose vertices were each moved uniformly at random
inside a ball of radius `r` (so that every vertex of the clean mesh is within `r` of the noisy
one), the estimate is about `r`. The median leaves out creases, corners and other places the
fit cannot follow, as long as they are fewer than half the vertices. For Gaussian noise of
standard deviation `sigma` in each coordinate, the estimate is about `2.1 sigma`.

A clean mesh also gets a nonzero estimate: the shape at the scale of two rings that a cubic
does not follow, and any roughness of its own. The two add in quadrature. That floor is a few
hundredths of the mean edge length on smooth, finely meshed surfaces, and up to a quarter of it
on coarse meshes of detailed shapes, where the estimate of a small noise is too high
accordingly (see the benchmark `fairing_accuracy`). Vertices with fewer than fourteen
neighbours within two edges are not used; the estimate is `0` when no vertex can be used.

\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param tmesh a triangle mesh
\param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones
          listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{the position of each vertex of `tmesh`, only read}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and
                   `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tmesh)`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\return the estimated noise radius, in the mesh's units

\sa `constrained_fairing()`
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
double estimate_noise_level(const TriangleMesh& tmesh, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;

  const auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tmesh));
  const auto position = [&](vertex_descriptor v) {
    const auto& p = get(vpm, v);
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };

  std::vector<double> heights; // squared, divided by their variance factor
  std::vector<vertex_descriptor> ring;
  std::vector<Eigen::Vector3d> points;
  for(vertex_descriptor v : vertices(tmesh))
  {
    if(halfedge(v, tmesh) == boost::graph_traits<TriangleMesh>::null_halfedge())
      continue;
    const Eigen::Vector3d p = position(v);
    // The normal: the sum of the doubled area vectors of the faces around v.
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
      continue;
    ring.clear();
    for(vertex_descriptor w : vertices_around_target(halfedge(v, tmesh), tmesh))
      ring.push_back(w);
    const std::size_t first_ring = ring.size();
    for(std::size_t k = 0; k < first_ring; ++k)
      for(vertex_descriptor w : vertices_around_target(halfedge(ring[k], tmesh), tmesh))
        if(w != v && std::find(ring.begin(), ring.end(), w) == ring.end())
          ring.push_back(w);
    if(ring.size() < internal::Constrained_fairing::noise_fit_points)
      continue;
    points.clear();
    for(vertex_descriptor w : ring)
      points.push_back(position(w));
    double residual = 0, factor = 1;
    if(internal::Constrained_fairing::cubic_residual(p, n.normalized(), points, residual, factor))
      heights.push_back(residual * residual / factor);
  }
  return internal::Constrained_fairing::noise_radius(heights);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_ESTIMATE_NOISE_LEVEL_H
