// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a PLY file carries besides its positions and faces, carried from input to output by the
// tool, the Python module and the batch: every scalar property of its vertices (colours, a
// scanner's confidence, ...) and of its faces, each with its name and type, in the file's order.
// They are read in the same pass as the soup (Ply_reader.h), and written by CGAL's
// Surface_mesh writer as property maps of the same C++ type ("v:<name>", "f:<name>"), which
// it writes as PLY properties of that type, in the order they were added. What is not carried
// (other elements, list properties) is named in `dropped`, for the front ends to say so.

#ifndef CONSTRAINED_FAIRING_FRONT_END_PLY_PROPERTIES_H
#define CONSTRAINED_FAIRING_FRONT_END_PLY_PROPERTIES_H

#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>

#include "front_end/Ply_reader.h"

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

// The scalar properties of a PLY element that are carried (all but `skipped`, the positions or
// the faces' indices), each with its index among the element's properties; its list properties
// other than `skipped` named in `dropped`.
struct Ply_carried_properties
{
  std::vector<std::size_t> index;
  std::vector<Ply_property> properties;

  Ply_carried_properties(const Ply_element_layout& element, const std::vector<std::string>& skipped,
                         std::vector<std::string>& dropped)
  {
    for(std::size_t k = 0; k < element.properties.size(); ++k)
    {
      const Ply_property_layout& property = element.properties[k];
      if(std::find(skipped.begin(), skipped.end(), property.name) != skipped.end())
        continue;
      if(property.is_list)
        dropped.push_back(element.name + " list property " + property.name);
      else
      {
        index.push_back(k);
        properties.push_back({property.name, property.type, {}});
      }
    }
  }

  // Appends the values of the item just read.
  void read_item(const Ply_item& item)
  {
    for(std::size_t p = 0; p < index.size(); ++p)
      properties[p].values.push_back(item.values[index[p]][0]);
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
