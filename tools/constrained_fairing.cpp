// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command-line tool: fairs a mesh file while keeping every vertex within epsilon of its
// input position, or makes a label map's surfaces, one closed surface per label, faired
// together within their voxels.
//
//   constrained_fairing [OPTIONS] IN [OUT]
//
// The arguments and options are described by `usage` below (--help prints it). Progress goes
// to stderr (Tool_progress.h); the report is one line on stdout. On bad input or any failure,
// prints one line starting with "error:" and returns non-zero, and writes nothing: outputs are
// written to temporary files, renamed into place once complete (front_end/Output_files.h).

#include "tools/Label_map_run.h"
#include "tools/Mesh_run.h"
#include "tools/Point_set_run.h"
#include "tools/Tool_options.h"
#include "tools/Tool_progress.h"

#include "front_end/Label_map_file.h"

#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

const char* const usage = R"(usage: constrained_fairing [OPTIONS] IN [OUT]

Fairs a triangle mesh: minimizes its bending energy while every vertex stays within EPS of its
input position (Hildebrandt and Polthier, SGP 2007).

  IN    a mesh in any format CGAL reads (OFF, OBJ, PLY, STL); faces with more than three
        vertices are triangulated
  OUT   where to write the result (.off, .obj, .ply or .stl), full precision; default: IN's
        name with _faired, in the current folder (.off if IN's format cannot be written). A .ply
        carries every vertex and face property of a PLY IN (colours, a scanner's confidence,
        ...; normals recomputed), and gets each vertex's distance to its input position (vertex
        property "deviation") and whether it ended on its bound ("at_bound", 0 or 1). An OUT
        that is IN is refused unless --in-place is given

  A point set IN (.xyz, .pwn with normals, or a .ply or .off without faces) is faired by
  constrained_fairing_of_points(), every point kept in its order, into OUT of those formats
  (default IN's name with _faired); a .ply carries IN's vertex properties, its normals (nx, ny,
  nz) faired, and gets "deviation" and "at_bound". EPS must then be a distance or auto (the
  noise estimated from the points' neighbourhoods); of the options, only --accurate,
  --tangential-motion, --box and --in-place apply.

  A label map IN (a segmentation, one integer label per voxel, 0 the background: NIfTI-1 .nii
  or .nii.gz, INRIMAGE-4 .inr or .inr.gz as CGAL's Mesh_3 reads them, numpy's .npy) gives one
  closed surface per label, its interfaces shared exactly with its neighbours', faired together
  with every point within its voxel, in world coordinates (a NIfTI file's sform, else its qform,
  else its voxel sizes; an INR file's voxel sizes and origin; a .npy file's voxel indices). OUT
  is then a folder, default IN's name with _surfaces in the current folder (seg.inr.gz:
  seg_surfaces), which gets label_<L>.ply for each label L (see --label-format) and nothing else: a new folder appears complete, an existing one keeps its
  other files, and a label_<L> file already there is refused unless --force is given. An OUT
  that is IN or an existing file is refused. Of the options, only --accurate, --label-format
  and --force apply.

options:
  --eps EPS                the tolerance: absolute (0.002), relative to the mean edge length h
                           (0.25h), or auto, the noise level estimated from IN itself; it
                           caps every other size below. Default: 0.25h, or the largest size
                           the options give
  --box                    each coordinate within EPS of its input value (a cube) instead of
                           the ball of radius EPS
  --box-extents HX,HY,HZ   a box of these half-extents around each vertex (a voxel's half
                           size, for surfaces extracted from volumes; implies --box)
  --radius-from-property NAME
                           each vertex's own tolerance, read from the vertex property NAME of
                           the PLY input (a scanner's per-point accuracy); 0 pins a vertex
  --fixed-border           vertices on the mesh's border do not move
  --accurate               the accurate objective: closer to the true surface of a noisy scan,
                           a little less fair; not for surfaces extracted from volumes
  --tangential-motion      let the vertices also slide along the surface, as they do with
                           --box and --accurate: a lower bending energy, but farther from the
                           true surface; by default each moves along the normal of the
                           smoothed start only
  --feature-angle DEG      keep creases sharp: the edges across which the face normals, after a
                           bilateral filter, are more than DEG degrees apart (0 < DEG < 180;
                           30 suits machined parts and CAD models) are faired as curves, and
                           the surface on either side as its own
  --repair                 make a mesh of a soup that is not one (CGAL's soup repair: duplicate
                           points and faces merged, non-manifold edges and vertices split into
                           copies, faces turned to agree), saying what changed; each copy of a
                           point stays within EPS of the original's position
  --label-format EXT       a label map's surfaces as ply (default), off, obj or stl
  --force                  replace the label_<L> files of a label map's OUT folder
  --in-place               let OUT be IN (OUT may then be left out): the result replaces the
                           input once complete
  --help                   this text

Options take their value as the next argument or after "=" (--eps=0.01).
)";

namespace {

using namespace Tool_mesh;

// The report, one line. The bending energy is the paper's measure of fairness; the objective
// minimized adds the barrier against slivers and, for --accurate, the fidelity term.
std::string report_line(const Tool_options& options, const Asked& asked, const std::string& out, const Mesh& mesh,
                        double epsilon, const std::string& eps_text, const PMP::Constrained_fairing_result& result)
{
  const bool ply = FE::has_extension(out, ".ply"), box = asked.settings.is_box_bound(false);
  std::ostringstream line;
  line << options.positional[0] << " -> " << out << (ply ? " (with deviation and at_bound)" : "") << ": "
       << num_vertices(mesh) << " vertices; eps " << epsilon << " (" << eps_text << "), "
       << (box ? "box" + (options.extents ? " " + *options.extents : std::string()) : std::string("ball"))
       << (options.radius_property ? ", tolerance from " + *options.radius_property : "")
       << (options.fixed_border ? ", border fixed" : "") << (options.accurate ? ", accurate" : "")
       << (options.tangential_motion ? ", tangential motion" : "")
       << (options.feature_angle ? ", creases over " + *options.feature_angle + " degrees" : "") << "; "
       << result.number_of_iterations << " iterations ("
       << (result.status == PMP::Constrained_fairing_status::CONVERGED ? "converged" : "iteration limit")
       << "); bending energy " << result.initial_bending_energy << " -> " << result.final_bending_energy;
  if(result.initial_energy != result.initial_bending_energy || result.final_energy != result.final_bending_energy)
    line << ", objective " << result.initial_energy << " -> " << result.final_energy;
  line << "; deviation at most " << result.max_deviation << ", " << result.number_of_vertices_at_bound
       << " at the bound, " << result.number_of_fixed_vertices << " fixed";
  if(result.number_of_unfolded_faces > 0 || result.number_of_folded_faces > 0)
    line << ", " << result.number_of_unfolded_faces << " faces unfolded, " << result.number_of_folded_faces
         << " left folded";
  if(options.feature_angle)
    line << ", " << result.number_of_feature_edges << " crease edges";
  if(result.number_of_degenerate_edges > 0)
    line << ", " << result.number_of_degenerate_edges << " edges with a degenerate triangle left out";
  return line.str();
}

// What the run noticed in the file: triangulated faces, the repair, properties not carried.
void print_notes(const Tool_options& options, const std::string& out, const FE::Mesh_file_contents& contents)
{
  if(contents.triangulated > 0)
    std::cout << "note: " << contents.triangulated << " faces with more than three vertices were triangulated"
              << std::endl;
  if(contents.repair)
    std::cout << "note: " << contents.repair->summary() << std::endl;
  const FE::Ply_properties& p = contents.properties;
  if(!FE::has_extension(out, ".ply") && !(p.vertex.empty() && p.face.empty()))
    std::cout << "note: the properties of " << options.positional[0] << " are carried to a .ply OUT only" << std::endl;
  for(const std::string& dropped : p.dropped)
    std::cout << "note: not carried: " << dropped << std::endl;
}

int fair_mesh_file(const Tool_options& options)
{
  std::string out;
  Sizes sizes;
  if(const std::string error = output_path(options, out); !error.empty())
    return report_error(error);
  if(const std::string error = read_sizes(options, sizes); !error.empty())
    return report_error(error);
  Tool_progress progress;
  progress.phase("reading " + options.positional[0]);
  Input input;
  if(const std::string error = read_input(options, input); !error.empty())
    return report_error(error);
  double epsilon = 0;
  std::string eps_text;
  if(const std::string error = choose_epsilon(options, sizes, input, epsilon, eps_text); !error.empty())
    return report_error(error);

  // Only what the user asked for is passed: the plain call takes the library's own defaults.
  Mesh& mesh = input.mesh;
  Asked asked = ask(options, sizes, input);
  progress.judge_by(asked.settings);
  auto deviation = mesh.add_property_map<vertex_descriptor, double>("v:deviation", 0.).first;
  auto at_bound = mesh.add_property_map<vertex_descriptor, bool>("v:at_bound", false).first;
  progress.phase("checking and starting (" + std::to_string(num_vertices(mesh)) + " vertices)");
  const PMP::Constrained_fairing_result result = fair_asked(
    mesh, epsilon, asked,
    CFP::iteration_callback(std::ref(progress),
                            CFP::vertex_deviation_map(deviation, CFP::vertex_at_bound_map(at_bound))));
  progress.done();
  if(!result)
    return report_error(result.message + "; nothing written");

  // The maps given to the library go; only a PLY output carries properties.
  forget(asked, mesh);
  Outputs outputs;
  for(vertex_descriptor v : vertices(mesh))
  {
    outputs.deviation.push_back(get(deviation, v));
    outputs.at_bound.push_back(std::uint8_t(get(at_bound, v)));
  }
  mesh.remove_property_map(deviation);
  mesh.remove_property_map(at_bound);
  if(FE::has_extension(out, ".ply"))
    add_carried_properties(input, outputs, mesh);
  progress.phase("writing " + out);
  const std::string write_error = write_output(out, mesh, input.contents.properties);
  progress.done();
  if(!write_error.empty())
    return report_error(write_error + "; nothing written");
  print_notes(options, out, input.contents);
  std::cout << report_line(options, asked, out, mesh, epsilon, eps_text, result) << "; " << std::setprecision(3)
            << progress.seconds() << " s" << std::endl;
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char* argv[])
{
  const Tool_options options = parse_tool_options(argc, argv);
  if(options.help)
  {
    std::cout << usage;
    return EXIT_SUCCESS;
  }
  if(!options.error.empty())
    return report_error(options.error);
  const std::string& in = options.positional[0];
  if(Constrained_fairing_front_end::is_label_map_file(in))
    return fair_label_map(options, in);
  if(Constrained_fairing_front_end::is_point_set_file(in))
    return Tool_point_set::fair_point_set_file(options);
  if(options.label_format || options.force)
    return report_error(std::string(options.label_format ? "--label-format" : "--force") + " applies to a label map (" +
                Constrained_fairing_front_end::label_map_extensions + ") only");
  return fair_mesh_file(options);
}
