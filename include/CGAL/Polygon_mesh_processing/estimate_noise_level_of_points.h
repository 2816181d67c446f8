// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PMP_ESTIMATE_NOISE_LEVEL_OF_POINTS_H
#define CGAL_PMP_ESTIMATE_NOISE_LEVEL_OF_POINTS_H

#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Noise_heights.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/read_named_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Point_sets/Point_set_noise.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <cstddef>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

/*!
\ingroup PkgConstrainedFairingRef

\brief estimates the noise of a point set, as a distance to pass as `epsilon` to
`constrained_fairing_of_points()`.

The measure of `estimate_noise_level()` on each point's `number_of_neighbors` nearest neighbours
instead of a vertex's two rings: a cubic height field is fitted to them by least squares, in the
frame of the plane that fits them best, and the point's height over it, divided by the variance
factor the fit gives, is the noise along the normal plus the fit's own error. The median of the
squared heights is that of a noise uniform in a ball of radius `r`, and about `1.1 r` is returned
(`estimate_noise_level()`'s calibration, made on meshes; measured with points each moved uniformly
at random inside a ball of radius `r`: 1.07 to 1.17 `r` on points sampled at random from seven
shapes, 1.02 to 1.08 `r` on the vertices of regular meshes), and
for Gaussian noise of standard deviation `sigma` in each coordinate about `2.2 sigma`. That holds
while the noise is smaller than the neighbourhoods: up to a noise radius of about twice the
points' mean spacing, or `sigma` about the spacing. Beyond, the nearest neighbours of a point are
mostly those of heights near its own, which hides the noise, and the estimate is low (`1.4 sigma`
for `sigma` twice the spacing): pass more neighbours, or the scanner's precision as `epsilon`. The
estimate is `0` when there are no more points than `number_of_neighbors` or no fit can be made.

\tparam PointRange a model of `Range` whose iterator is a model of `ForwardIterator`
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param points the point set, only read
\param np the named parameters:
  \cgalNamedParamsBegin
    \cgalParamNBegin{point_map}
      \cgalParamDescription{a property map associating points to the elements of `points`}
      \cgalParamType{a model of `ReadablePropertyMap` whose value type is a `Point_3`}
      \cgalParamDefault{`CGAL::Identity_property_map<value_type>`}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_neighbors}
      \cgalParamDescription{the neighbours each point's fit is made of (at least 14, the cubic's
        ten coefficients and a margin)}
      \cgalParamType{`std::size_t`}
      \cgalParamDefault{32}
    \cgalParamNEnd
  \cgalNamedParamsEnd

\return the estimated noise radius, in the points' units

\sa `constrained_fairing_of_points()`, `estimate_noise_level()`
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
double estimate_noise_level_of_points(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  namespace CF = internal::Constrained_fairing;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Value = typename std::iterator_traits<typename PointRange::const_iterator>::value_type;
  const auto point_map = choose_parameter(get_parameter(np, internal_np::point_map), Identity_property_map<Value>());
  const std::size_t k = CF::read_fairing_settings(np).number_of_neighbors;
  CGAL_precondition(k >= CF::noise_fit_points);
  CF::Points X(Eigen::Index(std::distance(points.begin(), points.end())), 3);
  Eigen::Index i = 0;
  for(const auto& item : points)
  {
    const auto& p = get(point_map, item);
    X.row(i++) << CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z());
  }
  if(std::size_t(X.rows()) <= k)
    return 0;
  std::vector<double> heights = CF::point_set_noise_heights(X, k);
  return CF::noise_radius(heights);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_ESTIMATE_NOISE_LEVEL_OF_POINTS_H
