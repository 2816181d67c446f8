// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The front ends' --repair (Python's repair=True): a soup that is not a mesh (duplicate points
// or faces, faces of fewer than three distinct points, non-manifold edges or vertices, faces
// turned against their neighbours) made one by CGAL's soup repair, repair_polygon_soup() then
// orient_polygon_soup(), which merges, removes, duplicates and turns, and say what changed.
// Every point of the repaired soup is at the position of a point of the input (a duplicated
// point is a copy of its original), so each one's origin is found by its position: the
// bound, taken from the input position, holds for every copy, and the file's properties follow.

#ifndef CONSTRAINED_FAIRING_FRONT_END_SOUP_REPAIR_H
#define CONSTRAINED_FAIRING_FRONT_END_SOUP_REPAIR_H

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <CGAL/Polygon_mesh_processing/constrained_fairing_input_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace Constrained_fairing_front_end {

struct Soup_repair
{
  std::size_t input_points = 0, input_polygons = 0;
  std::size_t points_merged_or_removed = 0, polygons_removed = 0, points_duplicated = 0, polygons_turned = 0;
  std::vector<std::size_t> point_origin, polygon_origin; // the input's point and polygon of each

  bool changed() const
  {
    return points_merged_or_removed + polygons_removed + points_duplicated + polygons_turned > 0;
  }

  // "repaired: 3 duplicate or isolated points removed, ...", or that nothing needed it.
  std::string summary() const
  {
    if(!changed())
      return "repair: nothing to repair";
    std::ostringstream text;
    text << "repaired: " << points_merged_or_removed << " duplicate or isolated points merged or removed, "
         << polygons_removed << " duplicate or degenerate faces removed, " << points_duplicated
         << " points duplicated at non-manifold edges and vertices (each copy bound to the original's position), "
         << polygons_turned << " faces turned";
    return text.str();
  }
};

namespace internal {

template <typename Point>
std::array<double, 3> key_of(const Point& p)
{
  return {double(p.x()), double(p.y()), double(p.z())};
}

// Each polygon as its sorted point positions, the key that finds it again after the repair.
template <typename Point>
std::vector<std::array<double, 3> > polygon_key(const std::vector<Point>& points, const std::vector<std::size_t>& polygon)
{
  std::vector<std::array<double, 3> > key;
  for(std::size_t i : polygon)
    key.push_back(key_of(points[i]));
  std::sort(key.begin(), key.end());
  return key;
}

// The defects the repair cannot mend, in the library's words: the first index out of range
// (CGAL's repair assumes the indices exist), then the first point that is not finite (positions
// are the keys of Soup_repair, and NaN is no key).
template <typename Point>
CGAL::Polygon_mesh_processing::internal::Constrained_fairing::Input_error
unrepairable_error(const std::vector<Point>& points, const std::vector<std::vector<std::size_t> >& polygons)
{
  namespace CF = CGAL::Polygon_mesh_processing::internal::Constrained_fairing;
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t v : polygons[f])
      if(v >= points.size())
        return CF::missing_vertex_error(f, v, points.size());
  for(std::size_t v = 0; v < points.size(); ++v)
    if(!std::isfinite(double(points[v].x())) || !std::isfinite(double(points[v].y())) ||
       !std::isfinite(double(points[v].z())))
      return CF::non_finite_coordinate_error(v);
  return {};
}

} // namespace internal

// Repairs the soup in place; returns what it cannot mend as an error instead, before anything
// is changed.
template <typename Point>
CGAL::Polygon_mesh_processing::Constrained_fairing_input_error
repair_polygon_soup(std::vector<Point>& points, std::vector<std::vector<std::size_t> >& polygons, Soup_repair& repair)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  if(const auto error = internal::unrepairable_error(points, polygons))
    return {error.defect, error.message};
  repair.input_points = points.size();
  repair.input_polygons = polygons.size();
  std::map<std::array<double, 3>, std::size_t> point_by_position;
  for(std::size_t i = points.size(); i-- > 0;)
    point_by_position[internal::key_of(points[i])] = i; // the first of equal points
  std::map<std::vector<std::array<double, 3> >, std::size_t> polygon_by_key;
  std::vector<std::size_t> polygon_of_point(points.size(), 0); // for a polygon the repair simplified
  for(std::size_t f = polygons.size(); f-- > 0;)
  {
    polygon_by_key[internal::polygon_key(points, polygons[f])] = f;
    for(std::size_t v : polygons[f])
      polygon_of_point[v] = f;
  }

  PMP::repair_polygon_soup(points, polygons);
  const std::vector<std::vector<std::size_t> > repaired = polygons;
  const std::vector<Point> repaired_points = points;
  PMP::orient_polygon_soup(points, polygons);

  repair.points_merged_or_removed = repair.input_points - repaired_points.size();
  repair.polygons_removed = repair.input_polygons - polygons.size();
  repair.points_duplicated = points.size() - repaired_points.size();
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    bool same = true;
    for(std::size_t c = 0; c < polygons[f].size() && same; ++c)
      same = internal::key_of(points[polygons[f][c]]) == internal::key_of(repaired_points[repaired[f][c]]);
    repair.polygons_turned += same ? 0 : 1;
  }
  for(const Point& p : points)
    repair.point_origin.push_back(point_by_position.at(internal::key_of(p)));
  for(const std::vector<std::size_t>& polygon : polygons)
  {
    const auto found = polygon_by_key.find(internal::polygon_key(points, polygon));
    repair.polygon_origin.push_back(found != polygon_by_key.end() ? found->second
                                                                   : polygon_of_point[repair.point_origin[polygon[0]]]);
  }
  return {};
}

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_SOUP_REPAIR_H
