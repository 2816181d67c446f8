// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command-line tool: fairs a mesh file while keeping every vertex within epsilon of its
// input position, or makes a NIfTI-1 label map's surfaces, one closed surface per label, faired
// together within their voxels.
//
//   constrained_fairing [OPTIONS] IN [OUT]
//
// The arguments and options are described by `usage` below (--help prints it). Progress goes
// to stderr, updated in place on a terminal and as plain lines otherwise; the report is one
// line on stdout. On bad input or any failure, prints one line starting with "error:" and
// returns non-zero, and writes nothing: the output is written to a temporary file, renamed to
// OUT once complete.

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_interfaces.h>
#include <CGAL/Polygon_mesh_processing/estimate_noise_level.h>
#include <CGAL/Polygon_mesh_processing/label_surface.h>
#include <CGAL/Polygon_mesh_processing/label_surface_nets.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>

#include "front_end/Epsilon_grammar.h"
#include "front_end/Label_map_file.h"
#include "front_end/Mean_edge_length.h"
#include "front_end/Mesh_file.h"
#include "front_end/Voxel_frame.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;

const char* const usage = R"(usage: constrained_fairing [OPTIONS] IN [OUT]

Fairs a triangle mesh: minimizes its bending energy while every vertex stays within EPS of its
input position (Hildebrandt and Polthier, SGP 2007).

  IN    a mesh in any format CGAL reads (OFF, OBJ, PLY, STL); faces with more than three
        vertices are triangulated
  OUT   where to write the result (.off, .obj, .ply or .stl), full precision; default: IN's
        name with _faired, in the current folder (.off if IN's format cannot be written). A .ply
        also gets each vertex's distance to its input position (vertex property "deviation")
        and whether it ended on its bound ("at_bound", 0 or 1). An OUT that is IN is refused
        unless --in-place is given

  A label map IN (a segmentation, one integer label per voxel, 0 the background: NIfTI-1 .nii
  or .nii.gz, INRIMAGE-4 .inr or .inr.gz as CGAL's Mesh_3 reads them, numpy's .npy) gives one
  closed surface per label, its interfaces shared exactly with its neighbours', faired together
  with every point within its voxel, in world coordinates (a NIfTI file's sform, else its qform,
  else its voxel sizes; an INR file's voxel sizes and origin; a .npy file's voxel indices). OUT
  is then a folder, default IN's name with _surfaces in the current folder (seg.inr.gz:
  seg_surfaces), which gets label_<L>.ply for each label L (see --label-format); of the
  options, only --accurate applies.

options:
  --eps EPS                the tolerance: absolute (0.002), relative to the mean edge length h
                           (0.25h), or auto, the noise level estimated from the mesh itself; it
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
  --label-format EXT       a label map's surfaces as ply (default), off, obj or stl
  --in-place               let OUT be IN: the result replaces the input once complete
  --help                   this text
)";

using Constrained_fairing_front_end::default_epsilon_text;
using Constrained_fairing_front_end::Epsilon_text;
using Constrained_fairing_front_end::make_triangle_mesh;
using Constrained_fairing_front_end::mean_edge_length;
using Constrained_fairing_front_end::parse_epsilon;
using Constrained_fairing_front_end::read_PLY_soup_file;
using Constrained_fairing_front_end::read_polygon_soup_file;
using Constrained_fairing_front_end::unwritable_file_reason;

using Polygon = std::vector<std::size_t>;

// Reads a mesh from any format CGAL reads, its faces triangulated, `triangulated` of them, and
// with a `property` name, that vertex property of a PLY file into `values`, one per vertex.
// Returns an empty string or the reason it failed.
std::string read_mesh(const std::string& in, const std::string& property, Mesh& mesh, std::size_t& triangulated,
                      std::vector<double>& values)
{
  std::vector<K::Point_3> points;
  std::vector<Polygon> polygons;
  if(!property.empty() && std::filesystem::path(in).extension() != ".ply")
    return "--radius-from-property needs a PLY input (" + in + ")";
  const std::string error = property.empty() ? read_polygon_soup_file(in, points, polygons)
                                             : read_PLY_soup_file(in, property, points, polygons, values);
  return error.empty() ? make_triangle_mesh(in, points, polygons, mesh, triangulated) : error;
}

bool writable_format(const std::string& out)
{
  const std::string ext = std::filesystem::path(out).extension().string();
  return ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl";
}

// Writes to a temporary file beside `out`, renamed to `out` once complete. Returns an empty
// string or the reason it failed.
std::string write_mesh(const std::string& out, const Mesh& mesh)
{
  std::filesystem::path partial(out);
  partial.replace_filename("." + partial.stem().string() + ".partial" + partial.extension().string());
  std::error_code error;
  if(CGAL::IO::write_polygon_mesh(partial.string(), mesh, CGAL::parameters::stream_precision(17).verbose(false)))
  {
    std::filesystem::rename(partial, out, error);
    if(!error)
      return std::string();
  }
  std::error_code ignored;
  std::filesystem::remove(partial, ignored);
  return "cannot write " + out + (error ? " (" + error.message() + ")" : unwritable_file_reason(partial.string()));
}

// Parses "HX,HY,HZ" (three non-negative numbers). Returns false if malformed.
bool parse_extents(const std::string& text, std::array<double, 3>& h)
{
  std::istringstream in(text);
  char comma1 = 0, comma2 = 0;
  if(!(in >> h[0] >> comma1 >> h[1] >> comma2 >> h[2]) || comma1 != ',' || comma2 != ',' || !in.eof())
    return false;
  return std::all_of(h.begin(), h.end(), [](double x) { return std::isfinite(x) && x >= 0; });
}

struct Options
{
  std::vector<std::string> positional;
  bool box = false, fixed_border = false, accurate = false, tangential_motion = false, in_place = false, help = false;
  std::optional<std::string> eps;
  std::string extents, radius_property, error;
  std::optional<std::string> label_format, feature_angle;
};

Options parse_options(int argc, char* argv[])
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const auto value = [&](std::string& target) {
      if(i + 1 < argc)
        target = argv[++i];
      else
        o.error = a + " needs a value";
    };
    if(a == "--help" || a == "-h")
      o.help = true;
    else if(a == "--box")
      o.box = true;
    else if(a == "--fixed-border")
      o.fixed_border = true;
    else if(a == "--accurate")
      o.accurate = true;
    else if(a == "--tangential-motion")
      o.tangential_motion = true;
    else if(a == "--in-place")
      o.in_place = true;
    else if(a == "--eps")
      value(o.eps.emplace());
    else if(a == "--box-extents")
      value(o.extents);
    else if(a == "--radius-from-property")
      value(o.radius_property);
    else if(a == "--label-format")
      value(o.label_format.emplace());
    else if(a == "--feature-angle")
      value(o.feature_angle.emplace());
    else if(a.size() > 2 && a.compare(0, 2, "--") == 0)
      o.error = "unknown option " + a + " (see --help)";
    else
      o.positional.push_back(a);
  }
  if(o.error.empty() && o.positional.empty())
    o.error = "no input mesh (see --help)";
  if(o.positional.size() > 2)
    o.error = "too many arguments (see --help)";
  return o;
}

int fail(const std::string& message)
{
  std::cerr << "error: " << message << std::endl;
  return EXIT_FAILURE;
}

// Whether `a` and `b` name one existing file (through links and relative paths alike).
bool is_same_file(const std::string& a, const std::string& b)
{
  std::error_code error;
  const bool same = std::filesystem::equivalent(a, b, error);
  return !error && same;
}

// IN's name with _faired, in the current folder, in IN's format if it can be written.
std::string default_output(const std::string& in)
{
  const std::filesystem::path path(in);
  const std::string ext = writable_format(in) ? path.extension().string() : ".off";
  return path.stem().string() + "_faired" + ext;
}

// Progress on stderr: on a terminal one line rewritten at most ten times a second, otherwise a
// plain line every 100 iterations.
class Progress
{
public:
  Progress() : m_terminal(isatty(STDERR_FILENO) != 0), m_start(std::chrono::steady_clock::now()) {}

  bool operator()(std::size_t iteration, double energy)
  {
    const double elapsed = seconds();
    if(m_terminal ? elapsed - m_shown < 0.1 : iteration % 100 != 0)
      return true;
    m_shown = elapsed;
    std::ostringstream line;
    line << "iteration " << iteration << ", energy " << energy << ", " << std::fixed << std::setprecision(1) << elapsed
         << " s";
    if(m_terminal)
      std::cerr << "\r" << line.str() << "\x1b[K" << std::flush;
    else
      std::cerr << line.str() << std::endl;
    m_dirty = m_terminal;
    return true;
  }

  // Clears the terminal line.
  void done()
  {
    if(m_dirty)
      std::cerr << "\r\x1b[K" << std::flush;
    m_dirty = false;
  }

  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count(); }

private:
  bool m_terminal, m_dirty = false;
  std::chrono::steady_clock::time_point m_start;
  double m_shown = -1;
};

// The per-vertex and box parameters the user asked for; the others are not passed at all.
struct Asked
{
  std::optional<Mesh::Property_map<vertex_descriptor, double> > tolerance;
  std::optional<Mesh::Property_map<vertex_descriptor, bool> > fixed;
  std::optional<std::array<double, 3> > extents;
  std::optional<double> feature_angle;
  bool box = false;
};

// The library's call with `np` and the bound asked for: a box of the given extents, the cube
// of the tolerance, or the default ball.
template <typename NamedParameters>
PMP::Constrained_fairing_result fair_with_bound(Mesh& mesh, double epsilon, const Asked& asked,
                                                const NamedParameters& np)
{
  if(asked.extents)
    return PMP::constrained_fairing(mesh, epsilon, CFP::box_half_extents(*asked.extents, np));
  if(asked.box)
    return PMP::constrained_fairing(mesh, epsilon, CFP::deviation_bound(PMP::Deviation_bound::BOX, np));
  return PMP::constrained_fairing(mesh, epsilon, np);
}

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

// The library's call with the per-vertex maps and the creases asked for, then the bound.
template <typename NamedParameters>
PMP::Constrained_fairing_result fair_asked(Mesh& mesh, double epsilon, const Asked& asked, const NamedParameters& np)
{
  const auto bound = [&](const auto& with) { return fair_with_bound(mesh, epsilon, asked, with); };
  const auto creases = [&](const auto& with) {
    return with_if_given(asked.feature_angle, [](double a, const auto& p) { return CFP::feature_angle(a, p); }, with,
                         bound);
  };
  const auto fixed = [&](const auto& with) {
    return with_if_given(asked.fixed, [](const auto& map, const auto& p) { return p.vertex_is_constrained_map(map); },
                         with, creases);
  };
  return with_if_given(asked.tolerance, [](const auto& map, const auto& p) { return CFP::vertex_tolerance_map(map, p); },
                       np, fixed);
}

// A label map's surfaces: surface nets in the voxels' frame (spacing the lengths of the
// affine's columns), faired together within the voxel boxes, each label's surface moved into
// the world (turned where the affine mirrors, so that it stays outward) and written into a
// temporary folder renamed to `out` once complete.
int fair_label_map(const Options& options, const std::string& in)
{
  namespace FE = Constrained_fairing_front_end;
  if(options.eps || options.box || !options.extents.empty() || !options.radius_property.empty() ||
     options.fixed_border || options.in_place || options.tangential_motion || options.feature_angle)
    return fail("of the options, only --accurate and --label-format apply to a label map");
  const std::string format = options.label_format.value_or("ply");
  if(format != "ply" && format != "off" && format != "obj" && format != "stl")
    return fail("--label-format must be ply, off, obj or stl (got " + format + ")");
  const std::filesystem::path out = options.positional.size() > 1 ? std::filesystem::path(options.positional[1])
                                                                  : std::filesystem::path(FE::label_map_stem(in) + "_surfaces");
  const std::filesystem::path parent = std::filesystem::absolute(out).parent_path();
  if(!std::filesystem::is_directory(parent))
    return fail("cannot write " + out.string() + " (no folder " + parent.string() + ")");

  FE::Label_map map;
  const std::string read_error = FE::read_label_map(in, map);
  if(!read_error.empty())
    return fail(read_error);
  const FE::Voxel_frame frame(map.affine);
  if(!frame.error.empty())
    return fail(in + ": " + frame.error);
  const std::array<double, 3>& spacing = frame.spacing;

  std::vector<K::Point_3> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<std::array<std::int64_t, 2> > face_labels;
  std::vector<std::array<double, 3> > half_extents;
  PMP::label_surface_nets(map.labels.data(), map.size, spacing, {0, 0, 0}, points, triangles, face_labels, half_extents);
  if(triangles.empty())
    return fail(in + ": the label map holds nothing but the background label 0; nothing written");
  Progress progress;
  const PMP::Constrained_fairing_result result = PMP::constrained_fairing_of_interfaces(
    points, triangles, face_labels, std::sqrt(spacing[0] * spacing[0] + spacing[1] * spacing[1] + spacing[2] * spacing[2]),
    CFP::vertex_box_half_extents_map(
      CGAL::make_property_map(half_extents),
      CFP::iteration_callback(std::ref(progress),
                              CFP::fairing_objective(options.accurate ? PMP::Constrained_fairing_objective::ACCURATE
                                                                      : PMP::Constrained_fairing_objective::FAIREST))));
  progress.done();
  if(!result)
    return fail(result.message + "; nothing written");

  std::set<std::int64_t> labels;
  for(const auto& pair : face_labels)
    for(std::int64_t l : pair)
      if(l != 0)
        labels.insert(l);
  std::filesystem::path partial = out;
  partial.replace_filename("." + out.filename().string() + ".partial");
  std::error_code ignored;
  std::filesystem::remove_all(partial, ignored);
  std::filesystem::create_directory(partial, ignored);
  for(std::int64_t label : labels)
  {
    Mesh mesh;
    PMP::label_surface(points, triangles, face_labels, label, mesh);
    for(vertex_descriptor v : vertices(mesh))
    {
      const K::Point_3& p = mesh.point(v);
      const std::array<double, 3> w = frame.to_world({p.x(), p.y(), p.z()});
      mesh.point(v) = K::Point_3(w[0], w[1], w[2]);
    }
    if(frame.mirrors)
      PMP::reverse_face_orientations(mesh);
    const std::string file = (partial / ("label_" + std::to_string(label) + "." + format)).string();
    if(!CGAL::IO::write_polygon_mesh(file, mesh, CGAL::parameters::stream_precision(17).verbose(false)))
    {
      std::filesystem::remove_all(partial, ignored);
      return fail("cannot write " + file + FE::unwritable_file_reason(file) + "; nothing written");
    }
  }
  std::filesystem::remove_all(out, ignored);
  std::error_code error;
  std::filesystem::rename(partial, out, error);
  if(error)
  {
    std::filesystem::remove_all(partial, ignored);
    return fail("cannot write " + out.string() + " (" + error.message() + "); nothing written");
  }
  std::cout << in << " -> " << out.string() << "/: " << labels.size() << " labels (" << map.size[0] << " x "
            << map.size[1] << " x " << map.size[2] << " voxels of " << spacing[0] << " x " << spacing[1] << " x "
            << spacing[2] << "), " << points.size() << " points, " << triangles.size() << " triangles; "
            << result.number_of_iterations << " iterations ("
            << (result.status == PMP::Constrained_fairing_status::CONVERGED ? "converged" : "iteration limit")
            << "); bending energy " << result.initial_bending_energy << " -> " << result.final_bending_energy
            << "; every point in its voxel, " << result.number_of_fixed_vertices << " fixed; " << std::setprecision(3)
            << progress.seconds() << " s" << std::endl;
  return EXIT_SUCCESS;
}

int main(int argc, char* argv[])
{
  const Options options = parse_options(argc, argv);
  if(options.help)
  {
    std::cout << usage;
    return EXIT_SUCCESS;
  }
  if(!options.error.empty())
    return fail(options.error);
  const std::string in = options.positional[0];
  if(Constrained_fairing_front_end::is_label_map_file(in))
    return fair_label_map(options, in);
  if(options.label_format)
    return fail(std::string("--label-format applies to a label map (") + Constrained_fairing_front_end::label_map_extensions +
                ") only");
  const std::string out = options.positional.size() > 1 ? options.positional[1] : default_output(in);

  if(!writable_format(out))
    return fail("OUT must end with .off, .obj, .ply or .stl (got " + out + ")");
  if(!options.in_place && is_same_file(in, out))
    return fail("OUT is IN (" + out + "): the result would replace the input; give another OUT, or --in-place");
  // Checked before a long run rather than after it.
  const std::filesystem::path folder = std::filesystem::path(out).parent_path();
  if(!folder.empty() && !std::filesystem::is_directory(folder))
    return fail("cannot write " + out + " (no folder " + folder.string() + ")");
  const Epsilon_text eps = parse_epsilon(options.eps.value_or(default_epsilon_text));
  if(!eps.error.empty())
    return fail("--eps " + eps.error);
  // A malformed number is refused here; its range is the library's check.
  std::optional<double> feature_angle;
  if(options.feature_angle)
  {
    std::istringstream text(*options.feature_angle);
    double degrees = 0;
    if(!(text >> degrees) || !text.eof())
      return fail("--feature-angle must be a number of degrees (got " + *options.feature_angle + ")");
    feature_angle = degrees;
  }
  std::array<double, 3> extents{0, 0, 0};
  if(!options.extents.empty() && !parse_extents(options.extents, extents))
    return fail("--box-extents must be three non-negative numbers HX,HY,HZ (got " + options.extents + ")");
  Mesh mesh;
  std::size_t triangulated = 0;
  std::vector<double> tolerances;
  const std::string read_error = read_mesh(in, options.radius_property, mesh, triangulated, tolerances);
  if(!read_error.empty())
    return fail(read_error);

  // EPS caps every size; without it, the largest size the options give, or 0.25h.
  std::string eps_text = options.eps.value_or(default_epsilon_text);
  double epsilon = 0;
  if(options.eps || (options.extents.empty() && options.radius_property.empty()))
  {
    if(eps.kind == Epsilon_text::Kind::AUTO)
    {
      epsilon = PMP::estimate_noise_level(mesh);
      if(!(epsilon > 0))
        return fail("cannot estimate the noise level of so small a mesh; give --eps");
      std::ostringstream text;
      text << "auto, " << epsilon / mean_edge_length(mesh) << "h";
      eps_text = text.str();
    }
    else
      epsilon = eps.kind == Epsilon_text::Kind::RELATIVE ? eps.value * mean_edge_length(mesh) : eps.value;
  }
  else
  {
    epsilon = options.extents.empty() ? 0 : *std::max_element(extents.begin(), extents.end());
    for(double t : tolerances)
      epsilon = (std::max)(epsilon, t);
    eps_text = "the largest size given";
  }
  if(triangulated > 0)
    std::cout << "note: " << triangulated << " faces with more than three vertices were triangulated" << std::endl;

  // Only what the user asked for is passed: the plain call takes the library's own defaults.
  Asked asked;
  asked.box = options.box;
  asked.feature_angle = feature_angle;
  if(!options.extents.empty())
    asked.extents = extents;
  if(!options.radius_property.empty())
  {
    asked.tolerance = mesh.add_property_map<vertex_descriptor, double>("v:tolerance", 0.).first;
    for(vertex_descriptor v : vertices(mesh))
      put(*asked.tolerance, v, tolerances[v.idx()]);
  }
  if(options.fixed_border)
  {
    asked.fixed = mesh.add_property_map<vertex_descriptor, bool>("v:fixed", false).first;
    for(vertex_descriptor v : vertices(mesh))
      put(*asked.fixed, v, static_cast<bool>(CGAL::is_border(v, mesh)));
  }
  auto deviation = mesh.add_property_map<vertex_descriptor, double>("v:deviation", 0.).first;
  auto at_bound = mesh.add_property_map<vertex_descriptor, bool>("v:at_bound", false).first;
  Progress progress;
  const bool box = options.box || !options.extents.empty();
  const PMP::Constrained_fairing_result result = fair_asked(
    mesh, epsilon, asked,
    CFP::iteration_callback(
      std::ref(progress),
      CFP::tangential_motion(
        options.tangential_motion || box || options.accurate,
        CFP::fairing_objective(options.accurate ? PMP::Constrained_fairing_objective::ACCURATE
                                                : PMP::Constrained_fairing_objective::FAIREST,
                               CFP::vertex_deviation_map(deviation, CFP::vertex_at_bound_map(at_bound))))));
  progress.done();
  if(!result)
    return fail(result.message + "; nothing written");

  // Only a PLY output carries the per-vertex results; the maps given to the library go.
  if(asked.tolerance)
    mesh.remove_property_map(*asked.tolerance);
  if(asked.fixed)
    mesh.remove_property_map(*asked.fixed);
  const bool ply = std::filesystem::path(out).extension() == ".ply";
  std::vector<std::uint8_t> flags;
  for(vertex_descriptor v : vertices(mesh))
    flags.push_back(std::uint8_t(get(at_bound, v)));
  mesh.remove_property_map(at_bound);
  if(ply)
  {
    auto at_bound_flag = mesh.add_property_map<vertex_descriptor, std::uint8_t>("v:at_bound", 0).first;
    std::size_t k = 0;
    for(vertex_descriptor v : vertices(mesh))
      put(at_bound_flag, v, flags[k++]);
  }
  else
    mesh.remove_property_map(deviation);
  const std::string write_error = write_mesh(out, mesh);
  if(!write_error.empty())
    return fail(write_error + "; nothing written");

  // The report, one line. The bending energy is the paper's measure of fairness; the objective
  // minimized adds the barrier against slivers and, for --accurate, the fidelity term.
  std::cout << in << " -> " << out << (ply ? " (with deviation and at_bound)" : "") << ": " << num_vertices(mesh)
            << " vertices; eps " << epsilon << " (" << eps_text << "), "
            << (box ? "box" + (options.extents.empty() ? std::string() : " " + options.extents) : std::string("ball"))
            << (options.radius_property.empty() ? "" : ", tolerance from " + options.radius_property)
            << (options.fixed_border ? ", border fixed" : "") << (options.accurate ? ", accurate" : "")
            << (options.tangential_motion ? ", tangential motion" : "")
            << (options.feature_angle ? ", creases over " + *options.feature_angle + " degrees" : "") << "; "
            << result.number_of_iterations << " iterations ("
            << (result.status == PMP::Constrained_fairing_status::CONVERGED ? "converged" : "iteration limit")
            << "); bending energy " << result.initial_bending_energy << " -> " << result.final_bending_energy;
  if(result.initial_energy != result.initial_bending_energy || result.final_energy != result.final_bending_energy)
    std::cout << ", objective " << result.initial_energy << " -> " << result.final_energy;
  std::cout << "; deviation at most " << result.max_deviation << ", " << result.number_of_vertices_at_bound
            << " at the bound, " << result.number_of_fixed_vertices << " fixed";
  if(result.number_of_unfolded_faces > 0 || result.number_of_folded_faces > 0)
    std::cout << ", " << result.number_of_unfolded_faces << " faces unfolded, " << result.number_of_folded_faces
              << " left folded";
  if(options.feature_angle)
    std::cout << ", " << result.number_of_feature_edges << " crease edges";
  if(result.number_of_degenerate_edges > 0)
    std::cout << ", " << result.number_of_degenerate_edges << " edges with a degenerate triangle left out";
  std::cout << "; " << std::setprecision(3) << progress.seconds() << " s" << std::endl;
  return EXIT_SUCCESS;
}
