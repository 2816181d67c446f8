// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A binary volume and the simplest surface extraction from it, for the voxel examples and
// tests: naive surface nets, one vertex at the centre of each cell that has inside and outside
// corners, one quad (two triangles) per grid edge that crosses the boundary. The result is the
// terraced surface that segmentations produce; every vertex lies at its cell's centre, so the
// cell is the box around it that the fairing may use.

#ifndef CGAL_CONSTRAINED_FAIRING_EXAMPLES_SURFACE_NETS_H
#define CGAL_CONSTRAINED_FAIRING_EXAMPLES_SURFACE_NETS_H

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <array>
#include <cstddef>
#include <map>
#include <vector>

namespace voxels {

// Inside or outside at each point (i, j, k) of a regular grid, origin + (i sx, j sy, k sz).
struct Grid
{
  std::array<std::size_t, 3> size;
  std::array<double, 3> spacing;
  std::array<double, 3> origin;
  std::vector<bool> inside; // i fastest

  // `is_inside(x, y, z)` classifies each grid point.
  template <typename IsInside>
  Grid(std::array<std::size_t, 3> size, std::array<double, 3> spacing, std::array<double, 3> origin,
       const IsInside& is_inside)
    : size(size), spacing(spacing), origin(origin), inside(size[0] * size[1] * size[2])
  {
    for(std::size_t k = 0; k < size[2]; ++k)
      for(std::size_t j = 0; j < size[1]; ++j)
        for(std::size_t i = 0; i < size[0]; ++i)
          inside[index(i, j, k)] = is_inside(coordinate(0, double(i)), coordinate(1, double(j)), coordinate(2, double(k)));
  }

  std::size_t index(std::size_t i, std::size_t j, std::size_t k) const { return i + size[0] * (j + size[1] * k); }
  double coordinate(int axis, double t) const { return origin[std::size_t(axis)] + t * spacing[std::size_t(axis)]; }
};

// The surface nets of `grid` in `mesh`, outward oriented, made manifold where two sheets touch
// at a cell or an edge (CGAL's orient_polygon_soup() duplicates the shared vertices). The
// grid's outer points must be outside. Returns false if the soup cannot become a mesh.
template <typename Mesh>
bool surface_nets(const Grid& grid, Mesh& mesh)
{
  using Point = typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > triangles;
  std::map<std::array<std::size_t, 3>, std::size_t> cell_vertex;
  const auto vertex = [&](std::array<std::size_t, 3> cell) {
    const auto found = cell_vertex.emplace(cell, points.size());
    if(found.second)
      points.emplace_back(grid.coordinate(0, double(cell[0]) + 0.5), grid.coordinate(1, double(cell[1]) + 0.5),
                          grid.coordinate(2, double(cell[2]) + 0.5));
    return found.first->second;
  };
  for(int axis = 0; axis < 3; ++axis)
  {
    const int u = (axis + 1) % 3, w = (axis + 2) % 3; // (axis, u, w) is right-handed
    // The edges from p to p + 1 along `axis`; those on the grid's outer faces join two outside
    // points.
    std::array<std::size_t, 3> first{1, 1, 1}, p{};
    first[std::size_t(axis)] = 0;
    for(p[2] = first[2]; p[2] + 1 < grid.size[2]; ++p[2])
      for(p[1] = first[1]; p[1] + 1 < grid.size[1]; ++p[1])
        for(p[0] = first[0]; p[0] + 1 < grid.size[0]; ++p[0])
        {
          std::array<std::size_t, 3> q = p;
          ++q[std::size_t(axis)];
          const bool a = grid.inside[grid.index(p[0], p[1], p[2])], b = grid.inside[grid.index(q[0], q[1], q[2])];
          if(a == b)
            continue;
          // The four cells around the edge, counterclockwise seen from its end q.
          std::array<std::size_t, 4> quad;
          const int du[4] = {0, 1, 1, 0}, dw[4] = {0, 0, 1, 1};
          for(int c = 0; c < 4; ++c)
          {
            std::array<std::size_t, 3> cell = p;
            cell[std::size_t(u)] -= std::size_t(1 - du[c]);
            cell[std::size_t(w)] -= std::size_t(1 - dw[c]);
            quad[std::size_t(c)] = vertex(cell);
          }
          // Outward is from inside to outside: along the edge if p is inside.
          if(a)
          {
            triangles.push_back({quad[0], quad[1], quad[2]});
            triangles.push_back({quad[0], quad[2], quad[3]});
          }
          else
          {
            triangles.push_back({quad[0], quad[2], quad[1]});
            triangles.push_back({quad[0], quad[3], quad[2]});
          }
        }
  }
  CGAL::Polygon_mesh_processing::orient_polygon_soup(points, triangles);
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(triangles))
    return false;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  return true;
}

} // namespace voxels

#endif // CGAL_CONSTRAINED_FAIRING_EXAMPLES_SURFACE_NETS_H
