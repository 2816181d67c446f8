// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Point set files as the tool reads and writes them: .xyz (x y z per line), .pwn (with the
// normal), and .ply or .off files without faces. A PLY file's vertex properties are read with
// its points (Mesh_file.h's parser) and carried to a PLY output, its normals (nx, ny, nz) used
// and written back faired; the points keep their order and count.

#ifndef CONSTRAINED_FAIRING_FRONT_END_POINT_SET_FILE_H
#define CONSTRAINED_FAIRING_FRONT_END_POINT_SET_FILE_H

#include "front_end/Mesh_file.h"
#include "front_end/Ply_properties.h"
#include "front_end/Ply_reader.h"

#include <CGAL/IO/read_xyz_points.h>
#include <CGAL/IO/write_xyz_points.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace Constrained_fairing_front_end {

inline const std::string point_set_extensions = ".xyz, .pwn, or .ply and .off without faces";

// Whether `path` holds a point set: an .xyz or .pwn file, or a .ply or .off file whose header
// declares points and no face (a file of neither is a mesh's, refused as empty).
inline bool is_point_set_file(const std::string& path)
{
  if(has_extension(path, ".xyz") || has_extension(path, ".pwn"))
    return true;
  std::ifstream stream(path, std::ios::binary);
  if(!stream)
    return false;
  if(has_extension(path, ".ply"))
  {
    Ply_header header;
    if(!read_ply_header(stream, header))
      return false;
    bool points = false;
    for(const Ply_element_layout& element : header.elements)
    {
      if((element.name == "face" || element.name == "faces") && element.count > 0)
        return false;
      points = points || ((element.name == "vertex" || element.name == "vertices") && element.count > 0);
    }
    return points;
  }
  if(!has_extension(path, ".off"))
    return false;
  // OFF, COFF, NOFF, ... then the counts, comments skipped
  std::string word, line;
  std::vector<long long> counts;
  while(counts.size() < 2 && std::getline(stream, line))
  {
    std::istringstream words(line.substr(0, line.find('#')));
    while(counts.size() < 2 && words >> word)
      if(word.find("OFF") == std::string::npos)
      {
        long long count = 0;
        if(!(std::istringstream(word) >> count))
          return false;
        counts.push_back(count);
      }
  }
  return counts.size() == 2 && counts[0] > 0 && counts[1] == 0;
}

template <typename Point, typename Vector>
struct Point_set_contents
{
  std::vector<std::pair<Point, Vector> > points;
  bool has_normals = false;
  Ply_properties properties; // a PLY file's, the normals among them
};

// Reads the point set file `path`; returns an empty string or the reason.
template <typename Point, typename Vector>
std::string read_point_set_file(const std::string& path, Point_set_contents<Point, Vector>& contents)
{
  using Item = std::pair<Point, Vector>;
  if(has_extension(path, ".xyz") || has_extension(path, ".pwn"))
  {
    contents.has_normals = has_extension(path, ".pwn");
    std::ifstream stream(path);
    const auto maps = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Item>())
                        .normal_map(CGAL::Second_of_pair_property_map<Item>());
    if(!stream || !CGAL::IO::read_XYZ(stream, std::back_inserter(contents.points), maps))
      return "cannot read " + path + " as a point set" + unreadable_file_reason(path);
    return std::string();
  }
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  const std::string error = has_extension(path, ".ply") ? read_PLY_mesh_file(path, points, polygons, contents.properties)
                                                        : read_polygon_soup_file(path, points, polygons);
  if(!error.empty())
    return error;
  const std::array<const Ply_property*, 3> n = {contents.properties.vertex_property("nx"),
                                                contents.properties.vertex_property("ny"),
                                                contents.properties.vertex_property("nz")};
  contents.has_normals = n[0] && n[1] && n[2];
  for(std::size_t i = 0; i < points.size(); ++i)
    contents.points.emplace_back(points[i], contents.has_normals
                                              ? Vector(n[0]->values[i], n[1]->values[i], n[2]->values[i])
                                              : Vector(0, 0, 0));
  return std::string();
}

// Writes the points (and the normals if the file has them) to `path` in its format: a PLY
// output with the `properties` (the normals replaced by `points`' own) and the per-point
// `extra` ones, binary, full precision; false if it cannot.
template <typename Point, typename Vector>
bool write_point_set_file(const std::string& path, const std::vector<std::pair<Point, Vector> >& points,
                          bool has_normals, Ply_properties properties, const std::vector<Ply_property>& extra)
{
  using Item = std::pair<Point, Vector>;
  if(has_extension(path, ".xyz") || has_extension(path, ".pwn"))
  {
    std::ofstream stream(path);
    stream.precision(17);
    const auto maps = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Item>());
    return (has_extension(path, ".pwn")
              ? CGAL::IO::write_XYZ(stream, points, maps.normal_map(CGAL::Second_of_pair_property_map<Item>()))
              : CGAL::IO::write_XYZ(stream, points, maps)) &&
           stream.flush();
  }
  CGAL::Surface_mesh<Point> mesh;
  for(const Item& p : points)
    mesh.add_vertex(p.first);
  if(has_extension(path, ".off"))
  {
    std::ofstream stream(path);
    stream.precision(17);
    return CGAL::IO::write_OFF(stream, mesh) && stream.flush();
  }
  // The normals where the properties have them, else first after the positions.
  for(int c = 0; c < 3 && has_normals; ++c)
  {
    const std::string name = std::string("n") + "xyz"[c];
    auto p = std::find_if(properties.vertex.begin(), properties.vertex.end(),
                          [&name](const Ply_property& q) { return q.name == name; });
    if(p == properties.vertex.end())
      p = properties.vertex.insert(properties.vertex.begin() + c, Ply_property{name, "double", {}});
    p->values.resize(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      p->values[i] = points[i].second[c];
  }
  add_ply_properties<typename CGAL::Surface_mesh<Point>::Vertex_index>(properties.vertex, "v:", mesh);
  add_ply_properties<typename CGAL::Surface_mesh<Point>::Vertex_index>(extra, "v:", mesh);
  return write_PLY_mesh_file(path, mesh, properties.comments);
}

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_POINT_SET_FILE_H
