// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The per-vertex property maps of a call, as the public functions read them from their named
// parameters (read_named_parameters.h): each one the user's map, or No_map where the user
// gave none, so that whether a map is given is known when compiling and an absent one costs
// nothing. The keys are the input's own (a mesh's vertex descriptors, a soup's point indices).

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_VERTEX_MAPS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_VERTEX_MAPS_H

#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <Eigen/Core>

#include <type_traits>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The place of a map the user did not give.
struct No_map
{};

template <typename Map>
constexpr bool is_given_map = !std::is_same_v<Map, No_map>;

// Whether `Map` is a given map that put() writes to.
template <typename Map, typename = void>
constexpr bool is_writable_map = false;
template <typename Map>
constexpr bool is_writable_map<Map, std::enable_if_t<is_given_map<Map> > > =
  std::is_convertible_v<typename boost::property_traits<Map>::category, boost::writable_property_map_tag>;

template <typename ToleranceMap, typename IsConstrainedMap, typename BoxHalfExtentsMap, typename BoxCenterMap,
          typename DeviationMap, typename AtBoundMap>
struct Vertex_maps
{
  static constexpr bool has_tolerance = is_given_map<ToleranceMap>;
  static constexpr bool has_box_half_extents = is_given_map<BoxHalfExtentsMap>;
  static constexpr bool has_box_center = is_given_map<BoxCenterMap>;
  static constexpr bool has_deviation = is_given_map<DeviationMap>;
  static constexpr bool has_at_bound = is_given_map<AtBoundMap>;

  template <typename Key>
  bool is_constrained(const Key& v) const
  {
    if constexpr(is_given_map<IsConstrainedMap>)
      return get(is_constrained_map, v);
    else
      return false;
  }

  // The values as given, in double (NaN and all); only for the maps that are given.
  template <typename Key>
  double given_tolerance(const Key& v) const
  {
    return CGAL::to_double(get(tolerance, v));
  }
  template <typename Key>
  Eigen::Vector3d given_box_half_extents(const Key& v) const
  {
    const auto& h = get(box_half_extents, v);
    return Eigen::Vector3d(CGAL::to_double(h[0]), CGAL::to_double(h[1]), CGAL::to_double(h[2]));
  }
  template <typename Key>
  Eigen::Vector3d given_box_center(const Key& v) const
  {
    const auto& c = get(box_center, v);
    return Eigen::Vector3d(CGAL::to_double(c.x()), CGAL::to_double(c.y()), CGAL::to_double(c.z()));
  }

  ToleranceMap tolerance;
  IsConstrainedMap is_constrained_map;
  BoxHalfExtentsMap box_half_extents;
  BoxCenterMap box_center;
  DeviationMap deviation;
  AtBoundMap at_bound;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_VERTEX_MAPS_H
