// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tool on a label map: surface nets in the voxels' frame (spacing the lengths of the
// affine's columns), faired together within the voxel boxes, each label's surface moved into
// the world (turned where the affine mirrors, so that it stays outward) and written as
// OUT/label_<L>.<ext> (front_end/Output_files.h: a new folder appears whole, an existing one
// only gets these files, replaced only with --force).

#ifndef CONSTRAINED_FAIRING_TOOL_LABEL_MAP_RUN_H
#define CONSTRAINED_FAIRING_TOOL_LABEL_MAP_RUN_H

#include "tools/Tool_options.h"
#include "tools/Tool_progress.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_interfaces.h>
#include <CGAL/Polygon_mesh_processing/label_map_epsilon.h>
#include <CGAL/Polygon_mesh_processing/label_surface.h>
#include <CGAL/Polygon_mesh_processing/label_surface_nets.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>

#include "front_end/Label_map_file.h"
#include "front_end/Mesh_file.h"
#include "front_end/Output_files.h"
#include "front_end/Voxel_frame.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <set>
#include <string>
#include <vector>

// A label map's multi-label surface, in the voxels' frame.
struct Label_nets
{
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<std::array<std::int64_t, 2> > face_labels;
  std::vector<std::array<double, 3> > half_extents;
  std::vector<std::int64_t> labels; // those with a surface, sorted

  // The file name of each label's surface, in the order of `labels`.
  std::vector<std::string> file_names(const std::string& format) const
  {
    std::vector<std::string> names;
    for(std::int64_t label : labels)
      names.push_back("label_" + std::to_string(label) + "." + format);
    return names;
  }
};

// Why the options do not suit a label map, or an empty string; `format` is set.
inline std::string label_map_options_error(const Tool_options& options, std::string& format)
{
  if(options.eps || options.box || options.extents || options.radius_property || options.fixed_border ||
     options.in_place || options.tangential_motion || options.feature_angle || options.repair)
    return "of the options, only --accurate, --label-format and --force apply to a label map";
  format = options.label_format.value_or("ply");
  if(format != "ply" && format != "off" && format != "obj" && format != "stl")
    return "--label-format must be ply, off, obj or stl (got " + format + ")";
  return std::string();
}

// The nets of `map` in the voxels' frame of spacing `spacing`, and the labels that have a surface.
inline void make_label_nets(const Constrained_fairing_front_end::Label_map& map, const std::array<double, 3>& spacing,
                            Label_nets& nets)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  PMP::label_surface_nets(map.labels.data(), map.size, spacing, {0, 0, 0}, nets.points, nets.triangles,
                          nets.face_labels, nets.half_extents);
  std::set<std::int64_t> labels;
  for(const auto& pair : nets.face_labels)
    for(std::int64_t l : pair)
      if(l != 0)
        labels.insert(l);
  nets.labels.assign(labels.begin(), labels.end());
}

// Writes each label's closed surface of `nets`, in the world of `frame`, into `out`.
inline std::string write_label_surfaces(const Label_nets& nets, const Constrained_fairing_front_end::Voxel_frame& frame,
                                        const std::string& format, const std::filesystem::path& out)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  namespace FE = Constrained_fairing_front_end;
  using Mesh = CGAL::Surface_mesh<Label_nets::Point>;
  const auto write = [&](const std::string& path, std::size_t k) {
    Mesh mesh;
    PMP::label_surface(nets.points, nets.triangles, nets.face_labels, nets.labels[k], mesh);
    for(auto v : vertices(mesh))
    {
      const Label_nets::Point& p = mesh.point(v);
      const std::array<double, 3> w = frame.to_world({p.x(), p.y(), p.z()});
      mesh.point(v) = Label_nets::Point(w[0], w[1], w[2]);
    }
    if(frame.mirrors)
      PMP::reverse_face_orientations(mesh);
    if(CGAL::IO::write_polygon_mesh(path, mesh, CGAL::parameters::stream_precision(17).verbose(false)))
      return std::string();
    return "cannot write " + path + FE::unwritable_file_reason(path);
  };
  return FE::write_files_into_folder(out, nets.file_names(format), write);
}

// IN's name without its label map extension, with _surfaces, in the current folder.
inline std::filesystem::path default_label_output(const std::string& in)
{
  return Constrained_fairing_front_end::label_map_stem(in) + "_surfaces";
}

// The tool on the label map `in`.
inline int fair_label_map(const Tool_options& options, const std::string& in)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  namespace CFP = PMP::constrained_fairing_parameters;
  namespace FE = Constrained_fairing_front_end;
  std::string format;
  if(const std::string error = label_map_options_error(options, format); !error.empty())
    return report_error(error);
  const std::filesystem::path out =
    options.positional.size() > 1 ? std::filesystem::path(options.positional[1]) : default_label_output(in);
  // Checked before a long run rather than after it, and again once the labels are known.
  if(const std::string error = FE::output_folder_error(in, out, {}, options.force); !error.empty())
    return report_error(error + "; nothing written");
  Tool_progress progress;
  progress.phase("reading " + in);
  FE::Label_map map;
  if(const std::string error = FE::read_label_map(in, map); !error.empty())
    return report_error(error);
  const FE::Voxel_frame frame(map.affine);
  if(!frame.error.empty())
    return report_error(in + ": " + frame.error);
  const std::array<double, 3>& h = frame.spacing;
  progress.phase("surface nets");
  Label_nets nets;
  make_label_nets(map, h, nets);
  if(nets.triangles.empty())
    return report_error(in + ": the label map holds nothing but the background label 0; nothing written");
  if(const std::string error = FE::output_folder_error(in, out, nets.file_names(format), options.force); !error.empty())
    return report_error(error + "; nothing written");
  progress.phase("fairing " + std::to_string(nets.points.size()) + " points");
  const PMP::Constrained_fairing_result result = PMP::constrained_fairing_of_interfaces(
    nets.points, nets.triangles, nets.face_labels, PMP::label_map_epsilon(h),
    CFP::vertex_box_half_extents_map(
      CGAL::make_property_map(nets.half_extents),
      CFP::iteration_callback(std::ref(progress),
                              CFP::fairing_objective(options.accurate ? PMP::Constrained_fairing_objective::ACCURATE
                                                                      : PMP::Constrained_fairing_objective::FAIREST))));
  progress.done();
  if(!result)
    return report_error(result.message + "; nothing written");
  progress.phase("writing " + out.string());
  const std::string write_error = write_label_surfaces(nets, frame, format, out);
  progress.done();
  if(!write_error.empty())
    return report_error(write_error + "; nothing written");
  const std::size_t n = nets.labels.size();
  std::cout << in << " -> " << out.string() << "/: " << n << (n == 1 ? " label (" : " labels (") << map.size[0]
            << " x " << map.size[1] << " x " << map.size[2] << " voxels of " << h[0] << " x " << h[1] << " x " << h[2]
            << "), " << nets.points.size() << " points, " << nets.triangles.size() << " triangles; "
            << result.number_of_iterations << " iterations ("
            << (result.status == PMP::Constrained_fairing_status::CONVERGED ? "converged" : "iteration limit")
            << "); bending energy " << result.initial_bending_energy << " -> " << result.final_bending_energy
            << "; every point in its voxel, " << result.number_of_fixed_vertices << " fixed; " << std::setprecision(3)
            << progress.seconds() << " s" << std::endl;
  return EXIT_SUCCESS;
}

#endif // CONSTRAINED_FAIRING_TOOL_LABEL_MAP_RUN_H
