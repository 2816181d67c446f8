// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a PLY file carries besides its positions and faces, carried from input to output by the
// tool, the Python module and the batch: every scalar property of its vertices (colours, a
// scanner's confidence, ...) and of its faces, each with its name and type, in the file's order.
// They are read with CGAL's PLY parser in the same pass as the soup, and written by CGAL's
// Surface_mesh writer as property maps of the same C++ type ("v:<name>", "f:<name>"), which
// it writes as PLY properties of that type, in the order they were added. What is not carried
// (other elements, list properties) is named in `dropped`, for the front ends to say so.

#ifndef CONSTRAINED_FAIRING_FRONT_END_PLY_PROPERTIES_H
#define CONSTRAINED_FAIRING_FRONT_END_PLY_PROPERTIES_H

#include <CGAL/IO/PLY/PLY_reader.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace Constrained_fairing_front_end {

struct Ply_property
{
  std::string name;
  std::string type; // char, uchar, short, ushort, int, uint, float or double: as CGAL writes it
  std::vector<double> values; // one per vertex or face; a double holds each of these types exactly
};

struct Ply_properties
{
  std::vector<Ply_property> vertex, face;
  std::vector<std::string> dropped; // what the file has that is not carried, e.g. "element edge"
  std::string comments; // the header's comment lines, each ended by a newline

  const Ply_property* vertex_property(const std::string& name) const
  {
    for(const Ply_property& p : vertex)
      if(p.name == name)
        return &p;
    return nullptr;
  }
};

// f(T(), name) for the C++ type T of the PLY type `type` (either spelling, "uchar" or
// "uint8"), with the name CGAL's writer gives it; false for another type.
template <typename F>
bool with_ply_type(const std::string& type, const F& f)
{
  if(type == "char" || type == "int8")
    f(std::int8_t(), "char");
  else if(type == "uchar" || type == "uint8")
    f(std::uint8_t(), "uchar");
  else if(type == "short" || type == "int16")
    f(std::int16_t(), "short");
  else if(type == "ushort" || type == "uint16")
    f(std::uint16_t(), "ushort");
  else if(type == "int" || type == "int32")
    f(std::int32_t(), "int");
  else if(type == "uint" || type == "uint32")
    f(std::uint32_t(), "uint");
  else if(type == "float" || type == "float32")
    f(float(), "float");
  else if(type == "double" || type == "float64")
    f(double(), "double");
  else
    return false;
  return true;
}

namespace internal {

// The type of a scalar property that CGAL's parser made, or an empty string for a list.
inline std::string ply_scalar_type(CGAL::IO::internal::PLY_read_number* property)
{
  namespace PLY = CGAL::IO::internal;
  std::string type;
  for(const char* name : {"char", "uchar", "short", "ushort", "int", "uint", "float", "double"})
    with_ply_type(name, [&](auto zero, const char* spelled) {
      if(type.empty() && dynamic_cast<PLY::PLY_read_typed_number<decltype(zero)>*>(property) != nullptr)
        type = spelled;
    });
  return type;
}

// The value last read by a scalar property of type `type`.
inline double ply_scalar_value(CGAL::IO::internal::PLY_read_number* property, const std::string& type)
{
  namespace PLY = CGAL::IO::internal;
  double value = 0;
  with_ply_type(type, [&](auto zero, const char*) {
    value = double(static_cast<PLY::PLY_read_typed_number<decltype(zero)>*>(property)->buffer());
  });
  return value;
}

} // namespace internal

// The scalar properties of a PLY element that are carried (all but `skipped`, the positions or
// the faces' indices), each with its index among the element's properties; its list properties
// other than `skipped` named in `dropped`.
struct Ply_carried_properties
{
  std::vector<std::size_t> index;
  std::vector<Ply_property> properties;

  Ply_carried_properties(CGAL::IO::internal::PLY_element& element, const std::vector<std::string>& skipped,
                         std::vector<std::string>& dropped)
  {
    for(std::size_t k = 0; k < element.number_of_properties(); ++k)
    {
      const std::string& name = element.property(k)->name();
      if(std::find(skipped.begin(), skipped.end(), name) != skipped.end())
        continue;
      const std::string type = internal::ply_scalar_type(element.property(k));
      if(type.empty())
        dropped.push_back(element.name() + " list property " + name);
      else
      {
        index.push_back(k);
        properties.push_back({name, type, {}});
      }
    }
  }

  // Appends the values of the item just read.
  void read_item(CGAL::IO::internal::PLY_element& element)
  {
    for(std::size_t p = 0; p < index.size(); ++p)
      properties[p].values.push_back(internal::ply_scalar_value(element.property(index[p]), properties[p].type));
  }
};

// The properties of the items `origin` names, in that order: item k's values are those of the
// file's item origin[k] (the vertex or polygon that a vertex or face of the mesh comes from).
inline std::vector<Ply_property> ply_properties_of(const std::vector<Ply_property>& properties,
                                                   const std::vector<std::size_t>& origin)
{
  std::vector<Ply_property> taken;
  for(const Ply_property& p : properties)
  {
    taken.push_back({p.name, p.type, {}});
    for(std::size_t k : origin)
      taken.back().values.push_back(p.values[k]);
  }
  return taken;
}

// Adds `properties`, one value per item in order, to `mesh` as property maps "<prefix><name>"
// of their types; a property the mesh already has is left as it is. Key is the mesh's
// Vertex_index or Face_index.
template <typename Key, typename Point>
void add_ply_properties(const std::vector<Ply_property>& properties, const char* prefix,
                        CGAL::Surface_mesh<Point>& mesh)
{
  for(const Ply_property& p : properties)
    with_ply_type(p.type, [&](auto zero, const char*) {
      using T = decltype(zero);
      auto added = mesh.template add_property_map<Key, T>(prefix + p.name, T());
      if(!added.second)
        return;
      for(std::size_t k = 0; k < p.values.size(); ++k)
        put(added.first, Key(static_cast<typename CGAL::Surface_mesh<Point>::size_type>(k)), static_cast<T>(p.values[k]));
    });
}

// Writes `mesh` with its property maps to the PLY file `path`, binary, full precision, with the
// input's header `comments`; false if it cannot.
template <typename Point>
bool write_PLY_mesh_file(const std::string& path, const CGAL::Surface_mesh<Point>& mesh, const std::string& comments)
{
  std::ofstream stream(path, std::ios::binary);
  CGAL::IO::set_mode(stream, CGAL::IO::BINARY);
  return CGAL::IO::write_PLY(stream, mesh, comments, CGAL::parameters::stream_precision(17)) && stream.flush();
}

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_PLY_PROPERTIES_H
