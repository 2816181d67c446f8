// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tool on a mesh file: where the result goes, the sizes the options give, the file read
// (repaired with --repair), the library's call with what the user asked for and nothing else
// (every other setting at the library's default or rule),
// the result written with what a PLY input carried, and the one-line report.

#ifndef CONSTRAINED_FAIRING_TOOL_MESH_RUN_H
#define CONSTRAINED_FAIRING_TOOL_MESH_RUN_H

#include "tools/Tool_options.h"
#include "tools/Tool_progress.h"

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/estimate_noise_level.h>

#include "front_end/Epsilon_grammar.h"
#include "front_end/Mean_edge_length.h"
#include "front_end/Mesh_file.h"
#include "front_end/Output_files.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace Tool_mesh {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
namespace FE = Constrained_fairing_front_end;
using vertex_descriptor = Mesh::Vertex_index;
using face_descriptor = Mesh::Face_index;

inline bool writable_format(const std::string& path)
{
  return FE::has_extension(path, ".off") || FE::has_extension(path, ".obj") || FE::has_extension(path, ".ply") ||
         FE::has_extension(path, ".stl");
}

// OUT: as given, IN itself with --in-place alone, or IN's name with _faired in the current
// folder, in IN's format if it can be written; or the reason it cannot be.
inline std::string output_path(const Tool_options& options, std::string& out)
{
  const std::string& in = options.positional[0];
  const std::filesystem::path path(in);
  if(options.positional.size() > 1)
    out = options.positional[1];
  else if(options.in_place)
    out = in;
  else
    out = path.stem().string() + "_faired" + (writable_format(in) ? path.extension().string() : ".off");
  if(!writable_format(out))
    return "OUT must end with .off, .obj, .ply or .stl (got " + out + ")";
  if(!options.in_place && FE::is_same_file(in, out))
    return "OUT is IN (" + out + "): the result would replace the input; give another OUT, or --in-place";
  const std::filesystem::path folder = std::filesystem::path(out).parent_path();
  if(!folder.empty() && !std::filesystem::is_directory(folder))
    return "cannot write " + out + " (no folder " + folder.string() + ")";
  return std::string();
}

// The sizes the options give, read before the mesh so that a typo costs no reading.
struct Sizes
{
  FE::Epsilon_text eps;
  std::optional<double> feature_angle;
  std::optional<std::array<double, 3> > extents;
};

inline std::string read_sizes(const Tool_options& options, Sizes& sizes)
{
  sizes.eps = FE::parse_epsilon(options.eps.value_or(FE::default_epsilon_text));
  if(!sizes.eps.error.empty())
    return "--eps " + sizes.eps.error;
  // A malformed number is refused here; its range is the library's check.
  if(options.feature_angle)
  {
    std::istringstream text(*options.feature_angle);
    double degrees = 0;
    if(!(text >> degrees) || !text.eof())
      return "--feature-angle must be a number of degrees (got " + *options.feature_angle + ")";
    sizes.feature_angle = degrees;
  }
  if(options.extents)
  {
    std::istringstream in(*options.extents);
    std::array<double, 3> h{0, 0, 0};
    char comma1 = 0, comma2 = 0;
    if(!(in >> h[0] >> comma1 >> h[1] >> comma2 >> h[2]) || comma1 != ',' || comma2 != ',' || !in.eof() ||
       !std::all_of(h.begin(), h.end(), [](double x) { return std::isfinite(x) && x >= 0; }))
      return "--box-extents must be three non-negative numbers HX,HY,HZ (got " + *options.extents + ")";
    sizes.extents = h;
  }
  return std::string();
}

// The mesh as read, with what its file carried.
struct Input
{
  Mesh mesh;
  FE::Mesh_file_contents contents;
  std::vector<double> tolerances; // with --radius-from-property, one per vertex
};

inline std::string read_input(const Tool_options& options, Input& input)
{
  const std::string& in = options.positional[0];
  if(options.radius_property && !FE::has_extension(in, ".ply"))
    return "--radius-from-property needs a PLY input (" + in + ")";
  const std::string error = FE::read_triangle_mesh_file(in, true, options.repair, input.mesh, input.contents,
                                                        "; --repair makes a mesh of such a soup");
  if(!error.empty() || !options.radius_property)
    return error;
  std::vector<double> values;
  if(const std::string missing = FE::vertex_property_values(in, input.contents.properties, *options.radius_property,
                                                            values);
     !missing.empty())
    return missing;
  for(std::size_t origin : input.contents.vertex_origin)
    input.tolerances.push_back(values[origin]);
  return std::string();
}

// EPS caps every size; without it, the largest size the options give, or 0.25h. `text` says
// which, for the report.
inline std::string choose_epsilon(const Tool_options& options, const Sizes& sizes, const Input& input,
                                  double& epsilon, std::string& text)
{
  text = options.eps.value_or(FE::default_epsilon_text);
  if(!options.eps && (sizes.extents || options.radius_property))
  {
    epsilon = sizes.extents ? *std::max_element(sizes.extents->begin(), sizes.extents->end()) : 0;
    for(double t : input.tolerances)
      epsilon = (std::max)(epsilon, t);
    text = "the largest size given";
    return std::string();
  }
  if(sizes.eps.kind == FE::Epsilon_text::Kind::AUTO)
  {
    epsilon = PMP::estimate_noise_level(input.mesh);
    if(!(epsilon > 0))
      return "cannot estimate the noise level of so small a mesh; give --eps";
    std::ostringstream written;
    written << "auto, " << epsilon / FE::mean_edge_length(input.mesh) << "h";
    text = written.str();
  }
  else
    epsilon = sizes.eps.kind == FE::Epsilon_text::Kind::RELATIVE ? sizes.eps.value * FE::mean_edge_length(input.mesh)
                                                                 : sizes.eps.value;
  return std::string();
}

// What the user asked for: the per-vertex maps, and the settings, where each one the user did
// not set keeps the library's default or rule (Constrained_fairing_settings.h); the maps not
// asked for are not passed at all.
struct Asked
{
  std::optional<Mesh::Property_map<vertex_descriptor, double> > tolerance;
  std::optional<Mesh::Property_map<vertex_descriptor, bool> > fixed;
  PMP::Constrained_fairing_settings settings;
};

// next(np), with `value` added to `np` by add(value, np) if it is given: each parameter the user
// did not ask for is not passed at all.
template <typename T, typename Add, typename NamedParameters, typename Next>
PMP::Constrained_fairing_result with_if_given(const std::optional<T>& value, const Add& add,
                                              const NamedParameters& np, const Next& next)
{
  if(value)
    return next(add(*value, np));
  return next(np);
}

// The library's call with the settings and the per-vertex maps asked for.
template <typename NamedParameters>
PMP::Constrained_fairing_result fair_asked(Mesh& mesh, double epsilon, const Asked& asked, const NamedParameters& np)
{
  const auto call = [&](const auto& with) {
    return PMP::constrained_fairing(mesh, epsilon, CFP::fairing_settings(asked.settings, with));
  };
  const auto fixed = [&](const auto& with) {
    return with_if_given(asked.fixed, [](const auto& map, const auto& p) { return p.vertex_is_constrained_map(map); },
                         with, call);
  };
  return with_if_given(asked.tolerance, [](const auto& map, const auto& p) { return CFP::vertex_tolerance_map(map, p); },
                       np, fixed);
}

// What the user asked for, the maps as maps of the mesh; removed again by forget().
inline Asked ask(const Tool_options& options, const Sizes& sizes, Input& input)
{
  Asked asked;
  if(options.box)
    asked.settings.set_deviation_bound(PMP::Deviation_bound::BOX);
  if(sizes.extents)
    asked.settings.set_box_half_extents(*sizes.extents);
  if(sizes.feature_angle)
    asked.settings.set("feature_angle", *sizes.feature_angle);
  if(options.accurate)
    asked.settings.set("objective", PMP::Constrained_fairing_objective::ACCURATE);
  if(options.tangential_motion)
    asked.settings.set("tangential_motion", true);
  Mesh& mesh = input.mesh;
  if(options.radius_property)
  {
    asked.tolerance = mesh.add_property_map<vertex_descriptor, double>("v:tolerance", 0.).first;
    for(vertex_descriptor v : vertices(mesh))
      put(*asked.tolerance, v, input.tolerances[v.idx()]);
  }
  if(options.fixed_border)
  {
    asked.fixed = mesh.add_property_map<vertex_descriptor, bool>("v:fixed", false).first;
    for(vertex_descriptor v : vertices(mesh))
      put(*asked.fixed, v, static_cast<bool>(CGAL::is_border(v, mesh)));
  }
  return asked;
}

inline void forget(Asked& asked, Mesh& mesh)
{
  if(asked.tolerance)
    mesh.remove_property_map(*asked.tolerance);
  if(asked.fixed)
    mesh.remove_property_map(*asked.fixed);
}

// The result's per-vertex outputs.
struct Outputs
{
  std::vector<double> deviation;
  std::vector<std::uint8_t> at_bound;
};

// The mesh as `out` gets it: a PLY output carries the input's properties, normals (nx, ny,
// nz) recomputed on the faired surface, then each vertex's deviation and whether it is at its
// bound, which replace those of an input that has them.
inline void add_carried_properties(const Input& input, const Outputs& outputs, Mesh& mesh)
{
  const FE::Ply_properties& carried = input.contents.properties;
  std::vector<FE::Ply_property> vertex;
  for(FE::Ply_property& p : FE::ply_properties_of(carried.vertex, input.contents.vertex_origin))
    if(p.name != "deviation" && p.name != "at_bound")
      vertex.push_back(std::move(p));
  for(FE::Ply_property& p : vertex)
    for(int c = 0; c < 3; ++c)
      if(p.name == std::string("n") + "xyz"[c])
        for(vertex_descriptor v : vertices(mesh))
          p.values[v.idx()] = PMP::compute_vertex_normal(v, mesh)[c];
  FE::add_ply_properties<vertex_descriptor>(vertex, "v:", mesh);
  FE::add_ply_properties<face_descriptor>(FE::ply_properties_of(carried.face, input.contents.face_origin), "f:", mesh);
  auto deviation = mesh.add_property_map<vertex_descriptor, double>("v:deviation", 0.).first;
  auto at_bound = mesh.add_property_map<vertex_descriptor, std::uint8_t>("v:at_bound", 0).first;
  for(vertex_descriptor v : vertices(mesh))
  {
    put(deviation, v, outputs.deviation[v.idx()]);
    put(at_bound, v, outputs.at_bound[v.idx()]);
  }
}

// A PLY output keeps the input's header comments.
inline std::string write_output(const std::string& out, const Mesh& mesh, const FE::Ply_properties& carried)
{
  return FE::write_file_through_partial(out, [&](const std::string& partial) {
    const bool written =
      FE::has_extension(out, ".ply")
        ? FE::write_PLY_mesh_file(partial, mesh, carried.comments)
        : CGAL::IO::write_polygon_mesh(partial, mesh, CGAL::parameters::stream_precision(17).verbose(false));
    if(written)
      return std::string();
    return "cannot write " + out + FE::unwritable_file_reason(partial);
  });
}

} // namespace Tool_mesh

#endif // CONSTRAINED_FAIRING_TOOL_MESH_RUN_H
