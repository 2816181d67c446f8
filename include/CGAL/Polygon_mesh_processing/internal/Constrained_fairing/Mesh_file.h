// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mesh files as the front ends read them (the command-line tool, the Python module): any
// format CGAL reads, as a polygon soup checked by Polygon_soup_check.h and made into a mesh by
// polygon_soup_to_polygon_mesh(), which keeps the file's order of vertices and faces; faces of
// more than three vertices triangulated. A PLY file may also give a number per vertex, read in
// the same pass. Failures are one line naming the file, with what CGAL said about it.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_FILE_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_FILE_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Polygon_soup_check.h>

#include <CGAL/IO/PLY/PLY_reader.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/iterator.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// CGAL's readers and writers explain failures on std::cerr; this keeps their words, while it
// lives, for a one-line message.
class Captured_cerr
{
public:
  Captured_cerr() : m_saved(std::cerr.rdbuf(m_text.rdbuf())) {}
  ~Captured_cerr() { std::cerr.rdbuf(m_saved); }
  Captured_cerr(const Captured_cerr&) = delete;
  Captured_cerr& operator=(const Captured_cerr&) = delete;

  // " (what CGAL said)", on one line, or nothing
  std::string reason() const
  {
    std::string text = m_text.str();
    std::replace(text.begin(), text.end(), '\n', ' ');
    while(!text.empty() && text.back() == ' ')
      text.pop_back();
    return text.empty() ? text : " (" + text + ")";
  }

private:
  std::ostringstream m_text;
  std::streambuf* m_saved;
};

// Reads `path` into `points` and `polygons`; returns an empty string or the reason.
template <typename Point>
std::string read_polygon_soup_file(const std::string& path, std::vector<Point>& points,
                                   std::vector<std::vector<std::size_t> >& polygons)
{
  Captured_cerr cgal;
  if(!CGAL::IO::read_polygon_soup(path, points, polygons))
    return "cannot read " + path + " as an OFF, OBJ, PLY or STL mesh" + cgal.reason();
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
  Captured_cerr cgal;
  PLY::PLY_reader reader(true);
  if(!stream || !reader.init(stream))
    return cannot + cgal.reason();
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
        return cannot + cgal.reason();
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
          return cannot + cgal.reason();
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
  polygon_soup_to_polygon_mesh(points, polygons, mesh);
  triangulated = static_cast<std::size_t>(std::count_if(
    polygons.begin(), polygons.end(), [](const std::vector<std::size_t>& p) { return p.size() > 3; }));
  if(triangulated > 0 && !triangulate_faces(mesh))
    return "cannot triangulate the faces of " + path + " with more than three vertices";
  return std::string();
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_FILE_H
