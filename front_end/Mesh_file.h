// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mesh files as the front ends read them (the command-line tool, the Python module): any
// format CGAL reads, as a polygon soup checked by Polygon_soup_check.h and made into a mesh by
// polygon_soup_to_polygon_mesh(), which keeps the file's order of vertices and faces; faces of
// more than three vertices triangulated. A PLY file may also give a number per vertex, read in
// the same pass. Failures are one line naming the file, made here: CGAL's readers are called
// quiet, since their own explanations go to std::cerr, which belongs to the whole process (the
// Python module reads files on several threads at once).

#ifndef CONSTRAINED_FAIRING_FRONT_END_MESH_FILE_H
#define CONSTRAINED_FAIRING_FRONT_END_MESH_FILE_H

#include <CGAL/IO/PLY/PLY_reader.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/iterator.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include "front_end/Polygon_soup_check.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
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

// Reads `path` into `points` and `polygons`; returns an empty string or the reason.
template <typename Point>
std::string read_polygon_soup_file(const std::string& path, std::vector<Point>& points,
                                   std::vector<std::vector<std::size_t> >& polygons)
{
  if(!CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false)))
    return "cannot read " + path + " as an OFF, OBJ, PLY or STL mesh" + unreadable_file_reason(path);
  return std::string();
}

// Reads the PLY file `path` into `points` and `polygons` as read_polygon_soup_file() does, and
// the float or double vertex property `name` into `values`, one per point; returns an empty
// string or the reason. CGAL's readers of a soup drop the other properties of the vertices, and
// its reader of a mesh with them needs a valid mesh: this reads both from one pass, with CGAL's
// PLY parser.
template <typename Point>
std::string read_PLY_soup_file(const std::string& path, const std::string& name, std::vector<Point>& points,
                               std::vector<std::vector<std::size_t> >& polygons, std::vector<double>& values)
{
  namespace PLY = CGAL::IO::internal;
  const std::string cannot = "cannot read " + path + " as a PLY mesh";
  std::ifstream stream(path, std::ios::binary);
  PLY::PLY_reader reader(false);
  if(!stream || !reader.init(stream))
    return cannot + unreadable_file_reason(path);
  bool has_vertices = false;
  for(std::size_t i = 0; i < reader.number_of_elements(); ++i)
  {
    PLY::PLY_element& element = reader.element(i);
    if(element.name() == "face" || element.name() == "faces")
    {
      // The four layouts that CGAL's soup reader accepts.
      const char* tag = element.has_property<std::vector<std::int32_t> >("vertex_indices") ||
                            element.has_property<std::vector<std::uint32_t> >("vertex_indices")
                          ? "vertex_indices"
                          : "vertex_index";
      const bool is_signed = element.has_property<std::vector<std::int32_t> >(tag);
      if(!is_signed && !element.has_property<std::vector<std::uint32_t> >(tag))
        return cannot + " (its faces have no list of vertex indices)";
      const bool read =
        is_signed ? PLY::read_PLY_faces<std::int32_t>(stream, element, polygons, CGAL::Emptyset_iterator(), tag)
                  : PLY::read_PLY_faces<std::uint32_t>(stream, element, polygons, CGAL::Emptyset_iterator(), tag);
      if(!read)
        return cannot + " (its faces cannot be read)";
      continue;
    }
    const bool vertex = element.name() == "vertex" || element.name() == "vertices";
    if(vertex)
    {
      has_vertices = true;
      // has_property<double> accepts float too, as assign(double&) reads both.
      for(const char* coordinate : {"x", "y", "z"})
        if(!element.has_property<double>(coordinate))
          return cannot + " (its vertices have no float or double " + coordinate + ")";
      if(!element.has_property<double>(name.c_str()))
        return path + " has no float or double vertex property " + name;
    }
    for(std::size_t j = 0; j < element.number_of_items(); ++j)
    {
      for(std::size_t k = 0; k < element.number_of_properties(); ++k)
      {
        element.property(k)->get(stream);
        if(stream.fail())
          return cannot + " (it ends before its " + element.name() + " " + std::to_string(j) + ")";
      }
      if(vertex)
      {
        double x = 0, y = 0, z = 0, value = 0;
        element.assign(x, "x");
        element.assign(y, "y");
        element.assign(z, "z");
        element.assign(value, name.c_str());
        points.emplace_back(x, y, z);
        values.push_back(value);
      }
    }
  }
  if(!has_vertices)
    return path + " has no float or double vertex property " + name;
  return std::string();
}

// Checks the soup read from `path`, makes `mesh` of it, and triangulates its faces of more
// than three vertices, `triangulated` of them; returns an empty string or the reason.
template <typename Point, typename TriangleMesh>
std::string make_triangle_mesh(const std::string& path, const std::vector<Point>& points,
                               const std::vector<std::vector<std::size_t> >& polygons, TriangleMesh& mesh,
                               std::size_t& triangulated)
{
  if(const Input_error soup = polygon_soup_error(points.size(), polygons))
    return path + ": " + soup.message;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  triangulated = static_cast<std::size_t>(std::count_if(
    polygons.begin(), polygons.end(), [](const std::vector<std::size_t>& p) { return p.size() > 3; }));
  if(triangulated > 0 && !CGAL::Polygon_mesh_processing::triangulate_faces(mesh))
    return "cannot triangulate the faces of " + path + " with more than three vertices";
  return std::string();
}

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_MESH_FILE_H
