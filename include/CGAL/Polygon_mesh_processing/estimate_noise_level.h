// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PMP_ESTIMATE_NOISE_LEVEL_H
#define CGAL_PMP_ESTIMATE_NOISE_LEVEL_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Mesh_noise_height.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Noise_heights.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

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
  const auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tmesh));
  std::vector<double> heights; // squared, divided by their variance factor
  internal::Constrained_fairing::Noise_height_scratch<TriangleMesh> scratch;
  for(auto v : vertices(tmesh))
  {
    double height = 0;
    if(internal::Constrained_fairing::mesh_noise_height(v, tmesh, vpm, scratch, height))
      heights.push_back(height);
  }
  return internal::Constrained_fairing::noise_radius(heights);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_ESTIMATE_NOISE_LEVEL_H
