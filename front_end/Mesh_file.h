// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mesh files as the front ends read them (the command-line tool, the Python module): any
// format CGAL reads, as a polygon soup checked by the library's soup check
// (constrained_fairing_input_check.h) and made into a mesh by polygon_soup_to_polygon_mesh(),
// which keeps the file's order of vertices and faces; faces of more than three vertices
// triangulated. A PLY file may also give a number per vertex, read in
// the same pass. Failures are one line naming the file, made here: CGAL's readers are called
// quiet, since their own explanations go to std::cerr, which belongs to the whole process (the
// Python module reads files on several threads at once).

#ifndef CONSTRAINED_FAIRING_FRONT_END_MESH_FILE_H
#define CONSTRAINED_FAIRING_FRONT_END_MESH_FILE_H

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/iterator.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_input_check.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include "front_end/Ply_properties.h"
#include "front_end/Ply_reader.h"
#include "front_end/Soup_repair.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

namespace Constrained_fairing_front_end {

// Why `path` cannot be read as a mesh: missing, unreadable, or of a format CGAL does not read;
// otherwise its content, which CGAL's quiet reader rejected.
inline std::string unreadable_file_reason(const std::string& path)
{
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if(!fs::exists(status))
    return " (no such file)";
  if(fs::is_directory(status))
    return " (a directory)";
  if(!std::ifstream(path, std::ios::binary))
    return " (it cannot be opened)";
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if(extension != ".off" && extension != ".obj" && extension != ".ply" && extension != ".stl" && extension != ".ts")
    return extension.empty() ? " (no file extension)" : " (unknown file extension " + extension + ")";
  return " (not a valid " + extension.substr(1) + " file)";
}

// Why a mesh could not be written to `path`, which CGAL's quiet writer refused.
inline std::string unwritable_file_reason(const std::string& path)
{
  namespace fs = std::filesystem;
  const fs::path folder = fs::path(path).parent_path();
  std::error_code error;
  if(!folder.empty() && !fs::is_directory(folder, error))
    return " (no folder " + folder.string() + ")";
  return " (the file cannot be created or written)";
}

// Whether `path` ends with `extension` (".ply"), whatever the case.
inline bool has_extension(const std::string& path, const std::string& extension)
{
  std::string found = std::filesystem::path(path).extension().string();
  std::transform(found.begin(), found.end(), found.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return found == extension;
}

// Reads `path` into `points` and `polygons`; returns an empty string or the reason.
template <typename Point>
std::string read_polygon_soup_file(const std::string& path, std::vector<Point>& points,
                                   std::vector<std::vector<std::size_t> >& polygons)
{
  if(!CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false)))
    return "cannot read " + path + " as an OFF, OBJ, PLY or STL mesh" + unreadable_file_reason(path);
  return std::string();
}

namespace internal {

// The visitor of triangulate_faces() that gives each new triangle the polygon of the face it
// splits, faces being numbered as a Surface_mesh numbers them; copied by the call, so it holds
// the table by pointer.
template <typename TriangleMesh>
struct Face_origin_visitor
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  std::vector<std::size_t>* origin;
  std::size_t polygon = 0;

  void before_subface_creations(face_descriptor f) { polygon = (*origin)[std::size_t(f)]; }
  void after_subface_created(face_descriptor f)
  {
    if(std::size_t(f) >= origin->size())
      origin->resize(std::size_t(f) + 1);
    (*origin)[std::size_t(f)] = polygon;
  }
  void after_subface_creations() {}
};

// The list of vertex indices of a PLY face element, as CGAL's soup reader takes it: the first
// property "vertex_indices", else "vertex_index", that is a list of int or uint; `none` if there
// is none.
inline std::size_t ply_face_corners(const Ply_element_layout& element)
{
  for(const char* tag : {"vertex_indices", "vertex_index"})
  {
    const std::size_t k = element.index_of(tag);
    if(k != Ply_element_layout::none && element.properties[k].is_list &&
       (element.properties[k].type == "int" || element.properties[k].type == "uint"))
      return k;
  }
  return Ply_element_layout::none;
}

// The face element of a PLY file: its polygons and the properties carried; false if it has no
// list of vertex indices in a layout that CGAL's soup reader takes (the reason in `reason`).
inline bool read_PLY_face_element(std::istream& stream, Ply_format format, const Ply_element_layout& element,
                                  std::vector<std::vector<std::size_t> >& polygons, Ply_properties& properties,
                                  std::string& reason)
{
  const std::size_t corners = ply_face_corners(element);
  if(corners == Ply_element_layout::none)
  {
    reason = " (its faces have no list of vertex indices)";
    return false;
  }
  Ply_carried_properties carried(element, {element.properties[corners].name}, properties.dropped);
  Ply_item item;
  for(std::size_t j = 0; j < element.count; ++j)
  {
    if(!read_ply_item(stream, format, element, item))
    {
      reason = " (it ends before its face " + std::to_string(j) + ")";
      return false;
    }
    // A negative index becomes one out of range, which the soup's check names.
    polygons.emplace_back();
    for(double index : item.values[corners])
      polygons.back().push_back(static_cast<std::size_t>(static_cast<std::int64_t>(index)));
    carried.read_item(item);
  }
  properties.face = std::move(carried.properties);
  return true;
}

// The vertex element of a PLY file: its points and the properties carried; false if its
// coordinates are not float or double scalars (the reason in `reason`).
template <typename Point>
bool read_PLY_vertex_element(std::istream& stream, Ply_format format, const Ply_element_layout& element,
                             std::vector<Point>& points, Ply_properties& properties, std::string& reason)
{
  std::size_t xyz[3];
  for(int c = 0; c < 3; ++c)
  {
    const std::string coordinate(1, "xyz"[c]);
    xyz[c] = element.index_of(coordinate);
    const Ply_property_layout* p = xyz[c] == Ply_element_layout::none ? nullptr : &element.properties[xyz[c]];
    if(p == nullptr || p->is_list || (p->type != "float" && p->type != "double"))
    {
      reason = " (its vertices have no float or double " + coordinate + ")";
      return false;
    }
  }
  Ply_carried_properties carried(element, {"x", "y", "z"}, properties.dropped);
  Ply_item item;
  for(std::size_t j = 0; j < element.count; ++j)
  {
    if(!read_ply_item(stream, format, element, item))
    {
      reason = " (it ends before its " + element.name + " " + std::to_string(j) + ")";
      return false;
    }
    points.emplace_back(item.values[xyz[0]][0], item.values[xyz[1]][0], item.values[xyz[2]][0]);
    carried.read_item(item);
  }
  properties.vertex = std::move(carried.properties);
  return true;
}

// Another element of a PLY file, read through and named in `dropped`.
inline bool skip_PLY_element(std::istream& stream, Ply_format format, const Ply_element_layout& element,
                             std::vector<std::string>& dropped, std::string& reason)
{
  dropped.push_back("element " + element.name);
  Ply_item item;
  for(std::size_t j = 0; j < element.count; ++j)
    if(!read_ply_item(stream, format, element, item))
    {
      reason = " (it ends before its " + element.name + " " + std::to_string(j) + ")";
      return false;
    }
  return true;
}

} // namespace internal

// Reads the PLY file `path` into `points` and `polygons` as read_polygon_soup_file() does, and
// every scalar property of its vertices and faces into `properties` (Ply_properties.h), in the
// same pass (Ply_reader.h); returns an empty string or the reason.
template <typename Point>
std::string read_PLY_mesh_file(const std::string& path, std::vector<Point>& points,
                               std::vector<std::vector<std::size_t> >& polygons, Ply_properties& properties)
{
  const std::string cannot = "cannot read " + path + " as a PLY mesh";
  std::ifstream stream(path, std::ios::binary);
  Ply_header header;
  if(!stream || !read_ply_header(stream, header))
    return cannot + unreadable_file_reason(path);
  // CGAL's writer adds its own line to every header: it is not the user's.
  properties.comments = header.comments;
  const std::string own = "Generated by the CGAL library\n";
  for(std::size_t at; (at = properties.comments.find(own)) != std::string::npos;)
    properties.comments.erase(at, own.size());
  for(const Ply_element_layout& element : header.elements)
  {
    std::string reason;
    const bool read =
      element.name == "face" || element.name == "faces"
        ? internal::read_PLY_face_element(stream, header.format, element, polygons, properties, reason)
      : element.name == "vertex" || element.name == "vertices"
        ? internal::read_PLY_vertex_element(stream, header.format, element, points, properties, reason)
        : internal::skip_PLY_element(stream, header.format, element, properties.dropped, reason);
    if(!read)
      return cannot + reason;
  }
  return std::string();
}

// The float or double vertex property `name` of the PLY file `path`, read into `properties`,
// as one value per vertex; returns an empty string or the reason.
inline std::string vertex_property_values(const std::string& path, const Ply_properties& properties,
                                          const std::string& name, std::vector<double>& values)
{
  const Ply_property* property = properties.vertex_property(name);
  if(property == nullptr || (property->type != "float" && property->type != "double"))
    return path + " has no float or double vertex property " + name;
  values = property->values;
  return std::string();
}

// Checks the soup read from `path`, makes `mesh` of it, and triangulates its faces of more
// than three vertices, `triangulated` of them; returns an empty string or the reason. With
// `face_polygon`, also the polygon each face of `mesh` comes from (a polygon's triangles all
// come from it), which carries the file's face properties to the triangles. `repair_hint` ends
// the message of a defect that the soup repair mends; `defect`, if given, gets the soup's.
template <typename Point, typename TriangleMesh>
std::string make_triangle_mesh(const std::string& path, const std::vector<Point>& points,
                               const std::vector<std::vector<std::size_t> >& polygons, TriangleMesh& mesh,
                               std::size_t& triangulated, std::vector<std::size_t>* face_polygon = nullptr,
                               const std::string& repair_hint = std::string(),
                               CGAL::Polygon_mesh_processing::Constrained_fairing_defect* defect = nullptr)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Defect = CGAL::Polygon_mesh_processing::Constrained_fairing_defect;
  if(const PMP::Constrained_fairing_input_error soup = PMP::constrained_fairing_polygon_soup_error(points.size(), polygons))
  {
    const bool repairable = soup.defect == Defect::NON_MANIFOLD_EDGE || soup.defect == Defect::NON_MANIFOLD_VERTEX ||
                            soup.defect == Defect::INCONSISTENT_ORIENTATION ||
                            (soup.defect == Defect::INVALID_FACE && soup.message.find("but there are") == std::string::npos);
    if(defect != nullptr)
      *defect = soup.defect;
    return path + ": " + soup.message + (repairable ? repair_hint : std::string());
  }
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  triangulated = static_cast<std::size_t>(std::count_if(
    polygons.begin(), polygons.end(), [](const std::vector<std::size_t>& p) { return p.size() > 3; }));
  // The soup's polygons become the mesh's faces in their order.
  std::vector<std::size_t> origin(polygons.size());
  for(std::size_t f = 0; f < origin.size(); ++f)
    origin[f] = f;
  internal::Face_origin_visitor<TriangleMesh> visitor{&origin};
  if(triangulated > 0 && !PMP::triangulate_faces(mesh, CGAL::parameters::visitor(visitor)))
    return "cannot triangulate the faces of " + path + " with more than three vertices";
  if(face_polygon != nullptr)
    *face_polygon = std::move(origin);
  return std::string();
}

// What a mesh file gives besides the mesh: where each vertex and face of the mesh comes from in
// the file (a triangle from its polygon, a repaired point from the input point at its position),
// the PLY properties read, and what was triangulated and repaired.
struct Mesh_file_contents
{
  std::vector<std::size_t> vertex_origin, face_origin;
  Ply_properties properties;
  std::size_t triangulated = 0;
  std::optional<Soup_repair> repair;
  // The defect that made the soup no mesh, for front ends that name it as the library does.
  CGAL::Polygon_mesh_processing::Constrained_fairing_defect defect =
    CGAL::Polygon_mesh_processing::Constrained_fairing_defect::NONE;
};

// Reads `path` into `mesh`: with `properties`, a PLY file's vertex and face properties too; with
// `repair`, its soup repaired first (Soup_repair.h); without, a defect the repair mends is named
// with `repair_hint` (how the front end asks for it). Returns an empty string or the reason.
template <typename TriangleMesh>
std::string read_triangle_mesh_file(const std::string& path, bool properties, bool repair, TriangleMesh& mesh,
                                    Mesh_file_contents& contents, const std::string& repair_hint)
{
  using Point = typename boost::property_traits<
    typename boost::property_map<TriangleMesh, boost::vertex_point_t>::type>::value_type;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  const bool ply = properties && has_extension(path, ".ply");
  std::string error = ply ? read_PLY_mesh_file(path, points, polygons, contents.properties)
                          : read_polygon_soup_file(path, points, polygons);
  if(!error.empty())
    return error;
  std::vector<std::size_t> polygon_origin(polygons.size());
  std::iota(polygon_origin.begin(), polygon_origin.end(), std::size_t(0));
  contents.vertex_origin.resize(points.size());
  std::iota(contents.vertex_origin.begin(), contents.vertex_origin.end(), std::size_t(0));
  if(repair)
  {
    contents.repair.emplace();
    if(const CGAL::Polygon_mesh_processing::Constrained_fairing_input_error defect =
         repair_polygon_soup(points, polygons, *contents.repair))
      return path + ": " + defect.message;
    contents.vertex_origin = contents.repair->point_origin;
    polygon_origin = contents.repair->polygon_origin;
  }
  std::vector<std::size_t> face_polygon;
  error = make_triangle_mesh(path, points, polygons, mesh, contents.triangulated, &face_polygon,
                             repair ? std::string() : repair_hint, &contents.defect);
  if(!error.empty())
    return error;
  for(std::size_t polygon : face_polygon)
    contents.face_origin.push_back(polygon_origin[polygon]);
  return std::string();
}

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_MESH_FILE_H
