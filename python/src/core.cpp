// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The compiled part of the Python package cgal_constrained_fairing: constrained_fairing() and
// the noise estimate on numpy arrays, and CGAL's mesh readers and writers. The arrays arrive
// checked for shape and converted to their dtype by the pure-Python layer (_fairing.py); here
// they become the CGAL::Surface_mesh that a C++ program makes of the same points and triangles
// (polygon_soup_to_polygon_mesh), so that the result is bit-identical to the C++ call's.
// The computation runs without the GIL; the GIL is taken back only to call the Python
// progress callback and, every fifth of a second, to let Ctrl-C through.

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_input_check.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_interfaces.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_points.h>
#include <CGAL/Polygon_mesh_processing/estimate_noise_level.h>
#include <CGAL/Polygon_mesh_processing/estimate_noise_level_of_points.h>
#include <CGAL/Polygon_mesh_processing/label_map_epsilon.h>
#include <CGAL/Polygon_mesh_processing/label_surface.h>
#include <CGAL/Polygon_mesh_processing/label_surface_nets.h>

#include "front_end/Epsilon_grammar.h"
#include "front_end/Label_map_file.h"
#include "front_end/Mean_edge_length.h"
#include "front_end/Mesh_file.h"
#include "front_end/Output_files.h"
#include "front_end/Point_set_file.h"
#include "front_end/Tile_fairing.h"
#include "front_end/Voxel_frame.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace py = pybind11;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
namespace CF = PMP::internal::Constrained_fairing;
namespace FE = Constrained_fairing_front_end;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using vertex_descriptor = Mesh::Vertex_index;
using face_descriptor = Mesh::Face_index;

using Float_array = py::array_t<double, py::array::c_style>;
using Index_array = py::array_t<std::int64_t, py::array::c_style>;
using Mask_array = py::array_t<bool, py::array::c_style>;
using Triangle = std::array<std::size_t, 3>;

// The row of a vertex of the mesh, or of a point of a soup.
std::size_t row_of(vertex_descriptor v) { return std::size_t(v.idx()); }
std::size_t row_of(std::size_t k) { return k; }

// A read-only property map over the rows of a C-contiguous array of `Columns` elements per
// vertex, vertex i of the mesh (or point i of a soup) being row i: the per-vertex data of the
// named parameters.
template <typename Value, int Columns, typename Element = double, typename Key = vertex_descriptor>
struct Row_map
{
  using key_type = Key;
  using value_type = Value;
  using reference = Value;
  using category = boost::readable_property_map_tag;

  const Element* data = nullptr;

  friend Value get(const Row_map& map, Key v)
  {
    const Element* row = map.data + row_of(v) * Columns;
    if constexpr(Columns == 1)
      return row[0];
    else if constexpr(std::is_same_v<Value, Point>)
      return Point(row[0], row[1], row[2]);
    else
      return Value{row[0], row[1], row[2]};
  }
};

// A property map over an output array of one value per vertex: the deviations and the vertices
// at their bound.
template <typename Value, typename Key = vertex_descriptor>
struct Array_map
{
  using key_type = Key;
  using value_type = Value;
  using reference = Value&;
  using category = boost::read_write_property_map_tag;

  Value* data = nullptr;

  friend Value get(const Array_map& map, Key v) { return map.data[row_of(v)]; }
  friend void put(const Array_map& map, Key v, const Value& value) { map.data[row_of(v)] = value; }
};

// Builds `mesh` from the arrays as a C++ program does from a polygon soup, after the library's
// check of a soup (constrained_fairing_polygon_soup_error()); returns the first defect found, and
// leaves `mesh` empty then. The defects a mesh can hold (an empty one, one without faces, ...) are
// left to constrained_fairing().
PMP::Constrained_fairing_input_error build_mesh(const Float_array& vertices, const Index_array& faces, Mesh& mesh)
{
  const std::size_t n = static_cast<std::size_t>(vertices.shape(0)), m = static_cast<std::size_t>(faces.shape(0));
  const std::int64_t* f = faces.data();
  std::vector<Triangle> triangles(m);
  {
    std::vector<std::array<std::int64_t, 3> > given(m);
    for(std::size_t i = 0; i < m; ++i)
      std::copy(f + 3 * i, f + 3 * i + 3, given[i].begin());
    if(PMP::Constrained_fairing_input_error error = PMP::constrained_fairing_polygon_soup_error(n, given))
      return error;
    for(std::size_t i = 0; i < m; ++i)
      for(std::size_t c = 0; c < 3; ++c)
        triangles[i][c] = static_cast<std::size_t>(given[i][c]);
  }
  std::vector<Point> points;
  points.reserve(n);
  const double* p = vertices.data();
  for(std::size_t i = 0; i < n; ++i)
    points.emplace_back(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
  PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  return {};
}

// `measure(mesh)` on the mesh of the arrays, as (value, defect, message): NaN and the first
// defect of the arrays, or the value and no defect. The mesh is held to the contract of
// constrained_fairing(), by the library's check of a mesh, as the measures are meant for its input.
template <typename Measure>
py::tuple measure_mesh(const Float_array& vertices, const Index_array& faces, const Measure& measure)
{
  PMP::Constrained_fairing_input_error error;
  double value = std::numeric_limits<double>::quiet_NaN();
  {
    py::gil_scoped_release release;
    Mesh mesh;
    error = build_mesh(vertices, faces, mesh);
    if(!error)
      error = PMP::constrained_fairing_mesh_error(mesh);
    if(!error)
      value = measure(mesh);
  }
  return py::make_tuple(value, error.defect, error.message);
}

// The noise estimate's squared normalized height of each vertex of `which` (NaN where the
// vertex cannot be used), so that a mesh in tiles gets the whole mesh's estimate from its tiles.
py::tuple noise_heights(const Float_array& vertices, const Index_array& faces, const Index_array& which)
{
  const std::size_t n = static_cast<std::size_t>(vertices.shape(0));
  py::array_t<double> heights(which.shape(0));
  double* out = heights.mutable_data();
  PMP::Constrained_fairing_input_error error;
  {
    py::gil_scoped_release release;
    Mesh mesh;
    error = build_mesh(vertices, faces, mesh);
    CF::Noise_height_scratch<Mesh> scratch;
    for(py::ssize_t k = 0; k < which.shape(0); ++k)
    {
      const std::int64_t i = which.data()[k];
      out[k] = std::numeric_limits<double>::quiet_NaN();
      if(!error && i >= 0 && std::size_t(i) < n)
        CF::mesh_noise_height(vertex_descriptor(Mesh::size_type(i)), mesh, mesh.points(), scratch, out[k]);
    }
  }
  return py::make_tuple(heights, error.defect, error.message);
}

// The iteration callback: the user's progress callback under the GIL, and Ctrl-C. Whatever
// Python raised stops the run and is kept for the caller to raise once the GIL is back.
class Python_callback
{
public:
  explicit Python_callback(py::object progress) : m_progress(std::move(progress)), m_last_check(clock::now()) {}

  bool operator()(std::size_t iteration, double energy)
  {
    const bool call = !m_progress.is_none();
    const auto now = clock::now();
    if(!call && now - m_last_check < std::chrono::milliseconds(200))
      return true;
    m_last_check = now;
    py::gil_scoped_acquire gil;
    try
    {
      if(PyErr_CheckSignals() != 0)
        throw py::error_already_set();
      return !(call && m_progress(iteration, energy).is(py::bool_(false)));
    }
    catch(py::error_already_set& e)
    {
      m_error = std::make_unique<py::error_already_set>(std::move(e));
      return false;
    }
  }

  // Raises what Python raised during the run, if anything; called with the GIL held.
  void raise_pending()
  {
    if(m_error)
    {
      py::error_already_set error = std::move(*m_error);
      m_error.reset();
      throw error;
    }
  }

private:
  using clock = std::chrono::steady_clock;
  py::object m_progress;
  clock::time_point m_last_check;
  std::unique_ptr<py::error_already_set> m_error;
};

// The options of a call as the user gave them: the named settings the user set, by their name
// in the library's table (Constrained_fairing_settings), and the bound's shape if named; each one
// unset keeps the library's default.
struct Options
{
  double epsilon = 0;
  std::string bound; // "ball", "box", or empty: the box if box arrays are given, as in C++
  PMP::Constrained_fairing_method method = PMP::Constrained_fairing_method::QUASI_NEWTON;
  py::dict given;

  // The library's settings, its defaults where the user gave nothing; with the GIL held.
  PMP::Constrained_fairing_settings settings() const
  {
    PMP::Constrained_fairing_settings asked(method);
    asked.for_each_named_setting([this](const char* name, const char*, auto& value) {
      if(given.contains(name))
        value = given[name].template cast<std::decay_t<decltype(value)> >();
    });
    if(!bound.empty())
      asked.set_deviation_bound(bound == "box" ? PMP::Deviation_bound::BOX : PMP::Deviation_bound::BALL);
    return asked;
  }
};

// The outputs of a call, a row per vertex (or point), made with the GIL held and filled without
// it; the report gives them when the call succeeded.
struct Fairing_outputs
{
  py::array_t<double> deviation;
  Mask_array at_bound;
  Float_array vertices;
  double* deviation_data;
  bool* at_bound_data;
  double* vertex_data;

  explicit Fairing_outputs(std::size_t n)
    : deviation(static_cast<py::ssize_t>(n)), at_bound(static_cast<py::ssize_t>(n)),
      vertices({static_cast<py::ssize_t>(n), py::ssize_t(3)}), deviation_data(deviation.mutable_data()),
      at_bound_data(at_bound.mutable_data()), vertex_data(vertices.mutable_data())
  {}
};

// The result as the Python layer reads it, with the output arrays when the call succeeded.
py::dict report_of(const PMP::Constrained_fairing_result& result, const Fairing_outputs& outputs)
{
  py::dict report;
  report["status"] = result.status;
  report["message"] = result.message;
  report["defect"] = result.defect;
  report["number_of_iterations"] = result.number_of_iterations;
  report["number_of_cg_iterations"] = result.number_of_cg_iterations;
  report["number_of_energy_evaluations"] = result.number_of_energy_evaluations;
  report["initial_energy"] = result.initial_energy;
  report["final_energy"] = result.final_energy;
  report["initial_bending_energy"] = result.initial_bending_energy;
  report["final_bending_energy"] = result.final_bending_energy;
  report["max_deviation"] = result.max_deviation;
  report["number_of_vertices_at_bound"] = result.number_of_vertices_at_bound;
  report["number_of_fixed_vertices"] = result.number_of_fixed_vertices;
  report["number_of_folded_faces"] = result.number_of_folded_faces;
  report["number_of_unfolded_faces"] = result.number_of_unfolded_faces;
  report["number_of_feature_edges"] = result.number_of_feature_edges;
  report["number_of_degenerate_edges"] = result.number_of_degenerate_edges;
  report["feature_edges"] = Index_array(std::vector<py::ssize_t>{0, 2});
  if(result)
  {
    report["vertices"] = outputs.vertices;
    report["deviation"] = outputs.deviation;
    report["at_bound"] = outputs.at_bound;
  }
  return report;
}

// The tolerances and the fixed vertices of a call, the user's or what the call without them
// uses (epsilon for every vertex, none fixed): one compiled pipeline serves both, bit for bit.
class Vertex_defaults
{
  std::vector<double> m_epsilons;
  std::unique_ptr<bool[]> m_none_fixed;

public:
  const double* const tolerance;
  const bool* const fixed;

  Vertex_defaults(std::size_t n, double epsilon, const std::optional<Float_array>& given_tolerance,
                  const std::optional<Mask_array>& given_fixed)
    : m_epsilons(given_tolerance ? 0 : n, epsilon), m_none_fixed(given_fixed ? nullptr : new bool[n]()),
      tolerance(given_tolerance ? given_tolerance->data() : m_epsilons.data()),
      fixed(given_fixed ? given_fixed->data() : m_none_fixed.get())
  {}
};

// The per-vertex named parameters of a call before `np` (the fixed vertices, the creases): the
// tolerances, the outputs and the callback; `Key` the vertices' type.
template <typename Key, typename NamedParameters>
auto vertex_parameters(const Vertex_defaults& given, const Fairing_outputs& outputs, Python_callback& callback,
                       const NamedParameters& np)
{
  return CFP::vertex_tolerance_map(
    Row_map<double, 1, double, Key>{given.tolerance},
    CFP::vertex_deviation_map(
      Array_map<double, Key>{outputs.deviation_data},
      CFP::vertex_at_bound_map(Array_map<bool, Key>{outputs.at_bound_data}, CFP::iteration_callback(std::ref(callback), np))));
}

// The box arrays the user gave, if any, beside the input points.
struct Box_arrays
{
  const Float_array& vertices;
  const std::optional<Float_array>& half_extents;
  const std::optional<Float_array>& centers;

  bool given() const { return half_extents || centers; }
};

// `fair_with` called with the settings and `np`, and the box maps if the library's rule says the
// call bounds by boxes (Constrained_fairing_settings::is_box_bound()): the user's half-extents, or
// the tolerance's cube (epsilon per axis), and centres, or the input points. A ball named with box
// arrays takes the box pipeline too, where the library rejects it (BOX_WITH_BALL).
template <typename Key, typename NamedParameters, typename Fair>
PMP::Constrained_fairing_result fair_in_bound(const PMP::Constrained_fairing_settings& settings, double epsilon,
                                              const Box_arrays& box, const NamedParameters& np, const Fair& fair_with)
{
  if(!settings.is_box_bound(box.given()))
    return fair_with(CFP::fairing_settings(settings, np));
  std::vector<double> cube;
  if(!box.half_extents)
    cube.assign(3 * static_cast<std::size_t>(box.vertices.shape(0)), epsilon);
  const double* extents = box.half_extents ? box.half_extents->data() : cube.data();
  const double* centers = box.centers ? box.centers->data() : box.vertices.data();
  return fair_with(CFP::fairing_settings(
    settings, CFP::vertex_box_half_extents_map(Row_map<std::array<double, 3>, 3, double, Key>{extents},
                                               CFP::vertex_box_center_map(Row_map<Point, 3, double, Key>{centers}, np))));
}

// A result that rejects the input for `error`.
PMP::Constrained_fairing_result rejected(const PMP::Constrained_fairing_input_error& error)
{
  PMP::Constrained_fairing_result result;
  result.status = PMP::Constrained_fairing_status::INVALID_INPUT;
  result.defect = error.defect;
  result.message = error.message;
  return result;
}

// The creases the user gives, each an edge (the Python layer checked; a pair that is not is left
// out), as the edge map to which the call adds those it detects.
Mesh::Property_map<Mesh::Edge_index, bool> given_creases(const std::optional<Index_array>& feature_edges, Mesh& mesh)
{
  const std::size_t n = mesh.number_of_vertices();
  auto crease_map = mesh.add_property_map<Mesh::Edge_index, bool>("e:crease", false).first;
  if(feature_edges)
    for(py::ssize_t k = 0; k < feature_edges->shape(0); ++k)
    {
      const std::int64_t* e = feature_edges->data() + 2 * k;
      if(e[0] < 0 || e[1] < 0 || std::size_t(e[0]) >= n || std::size_t(e[1]) >= n)
        continue;
      const auto h =
        CGAL::halfedge(vertex_descriptor(Mesh::size_type(e[0])), vertex_descriptor(Mesh::size_type(e[1])), mesh);
      if(h.second)
        crease_map[CGAL::edge(h.first, mesh)] = true;
    }
  return crease_map;
}

// The creases the call used, each as (smaller, larger) vertex, sorted.
std::vector<std::array<std::int64_t, 2> > used_creases(const Mesh& mesh,
                                                       const Mesh::Property_map<Mesh::Edge_index, bool>& crease_map)
{
  std::vector<std::array<std::int64_t, 2> > creases;
  for(auto e : mesh.edges())
    if(crease_map[e])
    {
      const std::int64_t a = mesh.source(mesh.halfedge(e)).idx(), b = mesh.target(mesh.halfedge(e)).idx();
      creases.push_back({(std::min)(a, b), (std::max)(a, b)});
    }
  std::sort(creases.begin(), creases.end());
  return creases;
}

// The faces of the region the Python layer checked.
std::vector<face_descriptor> region_faces_of(const std::optional<Index_array>& region)
{
  std::vector<face_descriptor> faces;
  if(region)
    for(py::ssize_t k = 0; k < region->shape(0); ++k)
      faces.push_back(face_descriptor(static_cast<Mesh::size_type>(region->data()[k])));
  return faces;
}

// The points of `mesh` into the rows of `out`.
void copy_points(const Mesh& mesh, double* out)
{
  for(vertex_descriptor v : mesh.vertices())
  {
    const Point& q = mesh.point(v);
    double* row = out + 3 * std::size_t(v.idx());
    row[0] = q.x();
    row[1] = q.y();
    row[2] = q.z();
  }
}

// constrained_fairing() on the arrays, which the Python layer has checked for shape (every
// per-vertex array has a row per vertex, the region's faces are distinct and exist), with the
// settings the user gave. Every per-vertex map is given, filled with what the call without it
// would use where the user gave none (Vertex_defaults, fair_in_bound()): the result is the same,
// bit for bit, with one compiled pipeline per bound shape.
py::dict fair(const Float_array& vertices, const Index_array& faces, const Options& options,
              const std::optional<Float_array>& tolerance, const std::optional<Mask_array>& fixed,
              const std::optional<Float_array>& box_half_extents, const std::optional<Float_array>& box_centers,
              const std::optional<Index_array>& region, const std::optional<Index_array>& feature_edges,
              py::object progress)
{
  const std::size_t n = static_cast<std::size_t>(vertices.shape(0));
  Python_callback callback(std::move(progress));
  const Fairing_outputs outputs(n);
  const PMP::Constrained_fairing_settings settings = options.settings();
  PMP::Constrained_fairing_result result;
  std::vector<std::array<std::int64_t, 2> > creases;
  {
    py::gil_scoped_release release;
    Mesh mesh;
    if(const PMP::Constrained_fairing_input_error error = build_mesh(vertices, faces, mesh))
      result = rejected(error);
    else
    {
      const auto crease_map = given_creases(feature_edges, mesh);
      const std::vector<face_descriptor> region_faces = region_faces_of(region);
      const Vertex_defaults given(n, options.epsilon, tolerance, fixed);
      const auto np = vertex_parameters<vertex_descriptor>(
        given, outputs, callback,
        CGAL::parameters::vertex_is_constrained_map(Row_map<bool, 1, bool>{given.fixed}).edge_is_constrained_map(crease_map));
      result = fair_in_bound<vertex_descriptor>(
        settings, options.epsilon, {vertices, box_half_extents, box_centers}, np, [&](const auto& all) {
          return region ? PMP::constrained_fairing(region_faces, mesh, options.epsilon, all)
                        : PMP::constrained_fairing(mesh, options.epsilon, all);
        });
      copy_points(mesh, outputs.vertex_data);
      creases = used_creases(mesh, crease_map);
    }
  }
  callback.raise_pending();
  py::dict report = report_of(result, outputs);
  if(result)
  {
    Index_array used({py::ssize_t(creases.size()), py::ssize_t(2)});
    for(std::size_t k = 0; k < creases.size(); ++k)
      std::copy(creases[k].begin(), creases[k].end(), used.mutable_data() + 2 * k);
    report["feature_edges"] = used;
  }
  return report;
}

// One tile of fair_tiled(): the owned vertices faired from `current`, the ghosts frozen there
// (Tile_fairing.h), but those `at_start`, taken at the smoothed start, with the settings fair()
// takes; `max_iterations` caps this sweep's descent.
py::dict fair_tile(const Float_array& vertices, const Float_array& current, const Index_array& faces,
                   const Mask_array& owned, const Mask_array& at_start, const Options& options,
                   std::size_t max_iterations)
{
  const std::size_t n = static_cast<std::size_t>(vertices.shape(0));
  const Fairing_outputs outputs(n);
  const PMP::Constrained_fairing_settings settings = options.settings();
  PMP::Constrained_fairing_result result;
  {
    py::gil_scoped_release release;
    Mesh mesh;
    if(const PMP::Constrained_fairing_input_error error = build_mesh(vertices, faces, mesh))
      result = rejected(error);
    else
    {
      FE::Tile_state tile{CF::Points(Eigen::Index(n), 3), std::vector<bool>(n), std::vector<bool>(n),
                          max_iterations};
      for(std::size_t i = 0; i < n; ++i)
      {
        CF::point(tile.current, i) = Eigen::Vector3d(current.data() + 3 * i);
        tile.owned[i] = owned.data()[i];
        tile.at_start[i] = at_start.data()[i];
      }
      const auto np = CFP::vertex_deviation_map(
        Array_map<double, vertex_descriptor>{outputs.deviation_data},
        CFP::vertex_at_bound_map(Array_map<bool, vertex_descriptor>{outputs.at_bound_data}));
      result = FE::fair_tile(mesh, options.epsilon, tile, CFP::fairing_settings(settings, np));
      copy_points(mesh, outputs.vertex_data);
    }
  }
  return report_of(result, outputs);
}

using Label = std::int64_t;
using Label_array = py::array_t<Label, py::array::c_style>;

// label_surface_nets() on a C-contiguous 3-D array of labels, as (points, triangles, labels,
// box half-extents).
py::tuple label_surface_nets(const Label_array& labels, const std::array<double, 3>& spacing,
                             const std::array<double, 3>& origin, Label background,
                             const std::array<std::size_t, 3>& first_voxel)
{
  const std::array<std::size_t, 3> size{std::size_t(labels.shape(0)), std::size_t(labels.shape(1)),
                                        std::size_t(labels.shape(2))};
  std::vector<Point> points;
  std::vector<std::array<std::int64_t, 3> > triangles;
  std::vector<std::array<Label, 2> > face_labels;
  std::vector<std::array<double, 3> > half_extents;
  {
    py::gil_scoped_release release;
    PMP::label_surface_nets(labels.data(), size, spacing, origin, points, triangles, face_labels, half_extents,
                            background, PMP::label_box_margin, first_voxel);
  }
  Float_array V({py::ssize_t(points.size()), py::ssize_t(3)}), H({py::ssize_t(points.size()), py::ssize_t(3)});
  Index_array F({py::ssize_t(triangles.size()), py::ssize_t(3)});
  Label_array L({py::ssize_t(face_labels.size()), py::ssize_t(2)});
  for(std::size_t i = 0; i < points.size(); ++i)
    for(int c = 0; c < 3; ++c)
    {
      V.mutable_data()[3 * i + std::size_t(c)] = points[i][c];
      H.mutable_data()[3 * i + std::size_t(c)] = half_extents[i][std::size_t(c)];
    }
  for(std::size_t f = 0; f < triangles.size(); ++f)
  {
    std::copy(triangles[f].begin(), triangles[f].end(), F.mutable_data() + 3 * f);
    std::copy(face_labels[f].begin(), face_labels[f].end(), L.mutable_data() + 2 * f);
  }
  return py::make_tuple(V, F, L, H);
}

// A multi-label soup of the arrays, which the Python layer has checked for shape.
struct Label_soup
{
  std::vector<Point> points;
  std::vector<std::array<std::int64_t, 3> > triangles;
  std::vector<std::array<Label, 2> > labels;

  Label_soup(const Float_array& vertices, const Index_array& faces, const Label_array& face_labels)
    : triangles(std::size_t(faces.shape(0))), labels(std::size_t(faces.shape(0)))
  {
    const double* p = vertices.data();
    for(py::ssize_t i = 0; i < vertices.shape(0); ++i, p += 3)
      points.emplace_back(p[0], p[1], p[2]);
    for(std::size_t f = 0; f < triangles.size(); ++f)
    {
      std::copy(faces.data() + 3 * f, faces.data() + 3 * f + 3, triangles[f].begin());
      std::copy(face_labels.data() + 2 * f, face_labels.data() + 2 * f + 2, labels[f].begin());
    }
  }
};

// constrained_fairing_of_interfaces() on the arrays, which the Python layer has checked for
// shape; as fair(), every per-point map is given.
py::dict fair_interfaces(const Float_array& vertices, const Index_array& faces, const Label_array& face_labels,
                         const Options& options, const std::optional<Float_array>& tolerance,
                         const std::optional<Mask_array>& fixed, const std::optional<Float_array>& box_half_extents,
                         const std::optional<Float_array>& box_centers, py::object progress)
{
  using Key = std::size_t;
  const std::size_t n = static_cast<std::size_t>(vertices.shape(0));
  Python_callback callback(std::move(progress));
  const Fairing_outputs outputs(n);
  const PMP::Constrained_fairing_settings settings = options.settings();
  PMP::Constrained_fairing_result result;
  {
    py::gil_scoped_release release;
    Label_soup soup(vertices, faces, face_labels);
    const Vertex_defaults given(n, options.epsilon, tolerance, fixed);
    const auto np = vertex_parameters<Key>(
      given, outputs, callback, CGAL::parameters::vertex_is_constrained_map(Row_map<bool, 1, bool, Key>{given.fixed}));
    result = fair_in_bound<Key>(settings, options.epsilon, {vertices, box_half_extents, box_centers}, np,
                                [&](const auto& all) {
                                  return PMP::constrained_fairing_of_interfaces(soup.points, soup.triangles,
                                                                                soup.labels, options.epsilon, all);
                                });
    for(std::size_t i = 0; i < n; ++i)
    {
      outputs.vertex_data[3 * i] = soup.points[i].x();
      outputs.vertex_data[3 * i + 1] = soup.points[i].y();
      outputs.vertex_data[3 * i + 2] = soup.points[i].z();
    }
  }
  callback.raise_pending();
  return report_of(result, outputs);
}

// A point set of the arrays, each point with its normal, given or to be written.
struct Point_set
{
  using Item = std::pair<Point, K::Vector_3>;
  std::vector<Item> items;

  Point_set(const Float_array& vertices, const std::optional<Float_array>& normals)
  {
    const double* p = vertices.data();
    const double* n = normals ? normals->data() : nullptr;
    for(py::ssize_t i = 0; i < vertices.shape(0); ++i, p += 3)
      items.emplace_back(Point(p[0], p[1], p[2]), n ? K::Vector_3(n[3 * i], n[3 * i + 1], n[3 * i + 2]) : K::Vector_3());
  }
};

// constrained_fairing_of_points() on the arrays, which the Python layer has checked for shape;
// as fair(), every per-point map is given; the normals read if given, and written.
py::dict fair_points(const Float_array& vertices, const std::optional<Float_array>& normals, std::size_t neighbors,
                     const Options& options, const std::optional<Float_array>& tolerance,
                     const std::optional<Mask_array>& fixed, const std::optional<Float_array>& box_half_extents,
                     const std::optional<Float_array>& box_centers, py::object progress)
{
  using Key = std::size_t;
  const std::size_t n = static_cast<std::size_t>(vertices.shape(0));
  Python_callback callback(std::move(progress));
  const Fairing_outputs outputs(n);
  Float_array faired_normals({static_cast<py::ssize_t>(n), py::ssize_t(3)});
  double* normal_data = faired_normals.mutable_data();
  const PMP::Constrained_fairing_settings settings = options.settings();
  PMP::Constrained_fairing_result result;
  {
    py::gil_scoped_release release;
    Point_set set(vertices, normals);
    const Vertex_defaults given(n, options.epsilon, tolerance, fixed);
    const auto np = vertex_parameters<Key>(
      given, outputs, callback,
      CGAL::parameters::vertex_is_constrained_map(Row_map<bool, 1, bool, Key>{given.fixed})
        .point_map(CGAL::First_of_pair_property_map<Point_set::Item>()));
    result = fair_in_bound<Key>(settings, options.epsilon, {vertices, box_half_extents, box_centers}, np,
                                [&](const auto& all) {
                                  const auto with_k = CFP::number_of_neighbors(neighbors, all);
                                  return normals ? PMP::constrained_fairing_of_points(
                                                     set.items, options.epsilon,
                                                     with_k.normal_map(CGAL::Second_of_pair_property_map<Point_set::Item>()))
                                                 : PMP::constrained_fairing_of_points(set.items, options.epsilon, with_k);
                                });
    for(std::size_t i = 0; i < n; ++i)
      for(int c = 0; c < 3; ++c)
      {
        outputs.vertex_data[3 * i + std::size_t(c)] = set.items[i].first[c];
        normal_data[3 * i + std::size_t(c)] = normals ? set.items[i].second[c] : 0.;
      }
  }
  callback.raise_pending();
  py::dict report = report_of(result, outputs);
  report["number_of_isolated_points"] = result.number_of_isolated_points;
  if(result && normals)
    report["normals"] = faired_normals;
  return report;
}


// The arrays of a mesh: its points and its triangles.
py::tuple mesh_arrays(const Mesh& mesh)
{
  Float_array V({py::ssize_t(mesh.number_of_vertices()), py::ssize_t(3)});
  Index_array F({py::ssize_t(mesh.number_of_faces()), py::ssize_t(3)});
  double* v = V.mutable_data();
  for(vertex_descriptor u : mesh.vertices())
  {
    const Point& p = mesh.point(u);
    *v++ = p.x();
    *v++ = p.y();
    *v++ = p.z();
  }
  std::int64_t* f = F.mutable_data();
  for(face_descriptor g : mesh.faces())
    for(vertex_descriptor u : vertices_around_face(mesh.halfedge(g), mesh))
      *f++ = std::int64_t(u.idx());
  return py::make_tuple(V, F);
}

// label_surface(): the closed surface of one label, as (vertices, faces).
py::tuple label_surface(const Float_array& vertices, const Index_array& faces, const Label_array& face_labels,
                        Label label)
{
  Mesh mesh;
  {
    py::gil_scoped_release release;
    const Label_soup soup(vertices, faces, face_labels);
    PMP::label_surface(soup.points, soup.triangles, soup.labels, label, mesh);
  }
  return mesh_arrays(mesh);
}

// Properties as the Python layer takes them: (name, PLY type, values as float64).
py::list property_list(const std::vector<FE::Ply_property>& properties)
{
  py::list list;
  for(const FE::Ply_property& p : properties)
  {
    Float_array values(py::ssize_t(p.values.size()));
    std::copy(p.values.begin(), p.values.end(), values.mutable_data());
    list.append(py::make_tuple(p.name, p.type, values));
  }
  return list;
}

// Reads a file as the command-line tool does (Mesh_file.h); a file of triangles gives its
// own arrays, in its order, and one with larger faces those of its triangulated mesh.
py::tuple read_mesh(const std::string& path)
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  std::string error;
  {
    py::gil_scoped_release release;
    error = FE::read_polygon_soup_file(path, points, polygons);
    const bool triangles =
      std::all_of(polygons.begin(), polygons.end(), [](const std::vector<std::size_t>& p) { return p.size() == 3; });
    if(error.empty() && !triangles)
    {
      Mesh mesh;
      std::size_t triangulated = 0;
      error = FE::make_triangle_mesh(path, points, polygons, mesh, triangulated);
      points.assign(mesh.points().begin(), mesh.points().end());
      polygons.clear();
      for(face_descriptor f : mesh.faces())
      {
        polygons.emplace_back();
        for(vertex_descriptor v : vertices_around_face(mesh.halfedge(f), mesh))
          polygons.back().push_back(std::size_t(v.idx()));
      }
    }
  }
  if(!error.empty())
    throw py::value_error(error);
  Float_array V({static_cast<py::ssize_t>(points.size()), py::ssize_t(3)});
  Index_array F({static_cast<py::ssize_t>(polygons.size()), py::ssize_t(3)});
  double* v = V.mutable_data();
  for(const Point& p : points)
  {
    *v++ = p.x();
    *v++ = p.y();
    *v++ = p.z();
  }
  std::int64_t* f = F.mutable_data();
  for(const auto& polygon : polygons)
    for(std::size_t c = 0; c < 3; ++c)
      *f++ = static_cast<std::int64_t>(polygon[c]);
  return py::make_tuple(V, F);
}

// Reads a file as the tool does with a PLY's properties and, with `repair`, --repair: as
// (vertices, faces, vertex properties, face properties, comments, dropped, repair summary), or
// (defect, message) if it is no mesh (the defect NONE where the reading failed).
py::tuple read_mesh_with_properties(const std::string& path, bool repair)
{
  Mesh mesh;
  FE::Mesh_file_contents contents;
  std::string error;
  {
    py::gil_scoped_release release;
    error = FE::read_triangle_mesh_file(path, true, repair, mesh, contents, "; repair=True makes a mesh of such a soup");
  }
  if(!error.empty())
    return py::make_tuple(contents.defect, error);
  const py::tuple arrays = mesh_arrays(mesh);
  const FE::Ply_properties& p = contents.properties;
  return py::make_tuple(arrays[0], arrays[1], property_list(FE::ply_properties_of(p.vertex, contents.vertex_origin)),
                        property_list(FE::ply_properties_of(p.face, contents.face_origin)), p.comments, p.dropped,
                        contents.repair ? contents.repair->summary() : std::string());
}

// The properties the Python layer gives, (name, PLY type, float64 values), as the front end's.
std::vector<FE::Ply_property> properties_of(const py::list& list)
{
  std::vector<FE::Ply_property> properties;
  for(const py::handle item : list)
  {
    const py::tuple t = item.cast<py::tuple>();
    const Float_array values = t[2].cast<Float_array>();
    properties.push_back({t[0].cast<std::string>(), t[1].cast<std::string>(),
                          std::vector<double>(values.data(), values.data() + values.size())});
  }
  return properties;
}

// A label map file as the tool reads it (front_end/Label_map_file.h), as (labels, affine): the
// labels an (I, J, K) int64 array that owns the reader's vector, the affine 4 x 4.
py::tuple read_label_map_file(const std::string& path)
{
  auto map = std::make_unique<FE::Label_map>();
  std::string error;
  {
    py::gil_scoped_release release;
    error = FE::read_label_map(path, *map);
  }
  if(!error.empty())
    throw py::value_error(error);
  Float_array affine({py::ssize_t(4), py::ssize_t(4)});
  for(std::size_t r = 0; r < 4; ++r)
    for(std::size_t c = 0; c < 4; ++c)
      affine.mutable_data()[4 * r + c] = r < 3 ? map->affine[r][c] : double(c == 3);
  auto labels = std::make_unique<std::vector<std::int64_t> >(std::move(map->labels));
  const py::capsule owner(labels.get(), [](void* p) { delete static_cast<std::vector<std::int64_t>*>(p); });
  const std::int64_t* data = labels.release()->data();
  const std::array<std::size_t, 3>& n = map->size;
  Index_array array({py::ssize_t(n[0]), py::ssize_t(n[1]), py::ssize_t(n[2])}, data, owner);
  return py::make_tuple(array, affine);
}

void write_mesh(const std::string& path, const Float_array& vertices, const Index_array& faces)
{
  const std::size_t n = static_cast<std::size_t>(vertices.shape(0)), m = static_cast<std::size_t>(faces.shape(0));
  std::string error;
  {
    py::gil_scoped_release release;
    std::vector<Point> points;
    points.reserve(n);
    for(std::size_t i = 0; i < n; ++i)
      points.emplace_back(vertices.data()[3 * i], vertices.data()[3 * i + 1], vertices.data()[3 * i + 2]);
    std::vector<Triangle> triangles(m);
    for(std::size_t i = 0; i < m; ++i)
      for(std::size_t c = 0; c < 3; ++c)
        triangles[i][c] = static_cast<std::size_t>(faces.data()[3 * i + c]);
    if(!CGAL::IO::write_polygon_soup(path, points, triangles, CGAL::parameters::stream_precision(17).verbose(false)))
      error = "cannot write " + path + FE::unwritable_file_reason(path);
  }
  if(!error.empty())
    throw py::value_error(error);
}

// Writes a PLY file of a mesh with properties, as the tool writes its PLY output.
void write_mesh_with_properties(const std::string& path, const Float_array& vertices, const Index_array& faces,
                                const py::list& vertex_properties, const py::list& face_properties,
                                const std::string& comments)
{
  const std::vector<FE::Ply_property> vertex = properties_of(vertex_properties), face = properties_of(face_properties);
  std::string error;
  {
    py::gil_scoped_release release;
    Mesh mesh;
    if(const PMP::Constrained_fairing_input_error defect = build_mesh(vertices, faces, mesh))
      error = path + ": properties are written with a mesh, and this is not one: " + defect.message;
    else
    {
      FE::add_ply_properties<vertex_descriptor>(vertex, "v:", mesh);
      FE::add_ply_properties<face_descriptor>(face, "f:", mesh);
      if(!FE::write_PLY_mesh_file(path, mesh, comments))
        error = "cannot write " + path + FE::unwritable_file_reason(path);
    }
  }
  if(!error.empty())
    throw py::value_error(error);
}

// A point set file as the tool reads it (front_end/Point_set_file.h): (points, normals or None,
// vertex properties, comments, dropped), a PLY file's normals among its properties.
py::tuple read_point_set(const std::string& path)
{
  FE::Point_set_contents<Point, K::Vector_3> contents;
  std::string error;
  {
    py::gil_scoped_release release;
    error = FE::read_point_set_file(path, contents);
  }
  if(!error.empty())
    throw py::value_error(error);
  const py::ssize_t n = py::ssize_t(contents.points.size());
  Float_array P({n, py::ssize_t(3)}), N({n, py::ssize_t(3)});
  for(py::ssize_t i = 0; i < n; ++i)
    for(int c = 0; c < 3; ++c)
    {
      P.mutable_data()[3 * i + c] = contents.points[std::size_t(i)].first[c];
      N.mutable_data()[3 * i + c] = contents.points[std::size_t(i)].second[c];
    }
  const FE::Ply_properties& p = contents.properties;
  return py::make_tuple(P, contents.has_normals ? py::object(N) : py::object(py::none()), property_list(p.vertex),
                        p.comments, p.dropped);
}

// Writes a point set file as the tool writes its output: the normals if given (a PLY's nx, ny,
// nz replaced by them), a PLY's vertex properties and comments.
void write_point_set(const std::string& path, const Float_array& points, const std::optional<Float_array>& normals,
                     const py::list& vertex_properties, const std::string& comments)
{
  FE::Ply_properties properties;
  properties.vertex = properties_of(vertex_properties);
  properties.comments = comments;
  bool written = false;
  {
    py::gil_scoped_release release;
    std::vector<std::pair<Point, K::Vector_3> > items;
    const double* v = points.data();
    for(py::ssize_t i = 0; i < points.shape(0); ++i, v += 3)
    {
      const double* n = normals ? normals->data() + 3 * i : nullptr;
      items.emplace_back(Point(v[0], v[1], v[2]), n ? K::Vector_3(n[0], n[1], n[2]) : K::Vector_3(0, 0, 0));
    }
    written = FE::write_point_set_file(path, items, bool(normals), std::move(properties), {});
  }
  if(!written)
    throw py::value_error("cannot write " + path + FE::unwritable_file_reason(path));
}

// Writes meshes (V, F) as the files `names` of `folder`, as the tool writes a label map's
// surfaces (front_end/Output_files.h); refuses, before writing anything, what that refuses
// (`source` being the input, or empty).
void write_files_into_folder(const std::string& source, const std::string& folder,
                             const std::vector<std::string>& names, const std::vector<py::tuple>& meshes, bool force)
{
  std::vector<std::pair<Float_array, Index_array> > arrays;
  for(const py::tuple& mesh : meshes)
    arrays.emplace_back(mesh[0].cast<Float_array>(), mesh[1].cast<Index_array>());
  std::string error;
  {
    py::gil_scoped_release release;
    error = FE::output_folder_error(source, folder, names, force);
    if(error.empty())
      error = FE::write_files_into_folder(folder, names, [&](const std::string& path, std::size_t k) {
        std::vector<Point> points;
        const Float_array& V = arrays[k].first;
        for(py::ssize_t i = 0; i < V.shape(0); ++i)
          points.emplace_back(V.data()[3 * i], V.data()[3 * i + 1], V.data()[3 * i + 2]);
        std::vector<Triangle> triangles(std::size_t(arrays[k].second.shape(0)));
        for(std::size_t f = 0; f < triangles.size(); ++f)
          for(std::size_t c = 0; c < 3; ++c)
            triangles[f][c] = std::size_t(arrays[k].second.data()[3 * f + c]);
        if(CGAL::IO::write_polygon_soup(path, points, triangles, CGAL::parameters::stream_precision(17).verbose(false)))
          return std::string();
        return "cannot write " + path + FE::unwritable_file_reason(path);
      });
  }
  if(!error.empty())
    throw py::value_error(error);
}

std::size_t max_threads()
{
#ifdef CGAL_LINKED_WITH_TBB
  return static_cast<std::size_t>(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
#else
  return 1;
#endif
}

#ifdef CGAL_LINKED_WITH_TBB
std::unique_ptr<tbb::global_control> thread_limit;
#endif

void set_max_threads(std::size_t threads)
{
#ifdef CGAL_LINKED_WITH_TBB
  thread_limit.reset();
  if(threads > 0)
    thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
#else
  (void)threads;
#endif
}

// The enums of the library.
void bind_enums(py::module_& m)
{
  py::enum_<PMP::Constrained_fairing_status>(m, "Status")
    .value("CONVERGED", PMP::Constrained_fairing_status::CONVERGED)
    .value("ITERATION_LIMIT_REACHED", PMP::Constrained_fairing_status::ITERATION_LIMIT_REACHED)
    .value("CANCELLED", PMP::Constrained_fairing_status::CANCELLED)
    .value("INVALID_INPUT", PMP::Constrained_fairing_status::INVALID_INPUT)
    .value("LINEAR_SOLVER_FAILED", PMP::Constrained_fairing_status::LINEAR_SOLVER_FAILED);
  using D = PMP::Constrained_fairing_defect;
  py::enum_<D>(m, "Defect")
    .value("NONE", D::NONE)
    .value("EMPTY_MESH", D::EMPTY_MESH)
    .value("NO_FACES", D::NO_FACES)
    .value("INVALID_FACE", D::INVALID_FACE)
    .value("BROKEN_STRUCTURE", D::BROKEN_STRUCTURE)
    .value("NOT_TRIANGLE", D::NOT_TRIANGLE)
    .value("NON_MANIFOLD_EDGE", D::NON_MANIFOLD_EDGE)
    .value("INCONSISTENT_ORIENTATION", D::INCONSISTENT_ORIENTATION)
    .value("NON_MANIFOLD_VERTEX", D::NON_MANIFOLD_VERTEX)
    .value("MESH_TOO_LARGE", D::MESH_TOO_LARGE)
    .value("NON_FINITE_COORDINATE", D::NON_FINITE_COORDINATE)
    .value("INVALID_EPSILON", D::INVALID_EPSILON)
    .value("INVALID_FIDELITY_WEIGHT", D::INVALID_FIDELITY_WEIGHT)
    .value("INVALID_SLIVER_BARRIER_WEIGHT", D::INVALID_SLIVER_BARRIER_WEIGHT)
    .value("INVALID_FEATURE_ANGLE", D::INVALID_FEATURE_ANGLE)
    .value("BOX_WITH_BALL", D::BOX_WITH_BALL)
    .value("INVALID_BOX_EXTENTS", D::INVALID_BOX_EXTENTS)
    .value("INVALID_TOLERANCE", D::INVALID_TOLERANCE)
    .value("INVALID_BOX_CENTER", D::INVALID_BOX_CENTER)
    .value("OUTSIDE_BOX", D::OUTSIDE_BOX)
    .value("NO_AREA", D::NO_AREA)
    .value("TOO_FEW_POINTS", D::TOO_FEW_POINTS)
    .value("INVALID_NUMBER_OF_NEIGHBORS", D::INVALID_NUMBER_OF_NEIGHBORS)
    .value("DUPLICATE_POINTS", D::DUPLICATE_POINTS)
    .value("INVALID_NORMAL", D::INVALID_NORMAL)
    .value("NO_SURFACE", D::NO_SURFACE)
    .value("METHOD_NEEDS_MESH", D::METHOD_NEEDS_MESH);
  py::enum_<PMP::Constrained_fairing_method>(m, "Method")
    .value("QUASI_NEWTON", PMP::Constrained_fairing_method::QUASI_NEWTON)
    .value("ACTIVE_SET_NEWTON", PMP::Constrained_fairing_method::ACTIVE_SET_NEWTON)
    .value("PROJECTED_GRADIENT", PMP::Constrained_fairing_method::PROJECTED_GRADIENT);
  py::enum_<PMP::Constrained_fairing_objective>(m, "Objective")
    .value("FAIREST", PMP::Constrained_fairing_objective::FAIREST)
    .value("ACCURATE", PMP::Constrained_fairing_objective::ACCURATE);
}

// The options of a call, the library's table of named settings and its defaults, and the
// tolerance's grammar.
void bind_settings(py::module_& m)
{
  py::class_<Options>(m, "Options")
    .def(py::init<>())
    .def_readwrite("epsilon", &Options::epsilon)
    .def_readwrite("bound", &Options::bound)
    .def_readwrite("method", &Options::method)
    .def_readwrite("given", &Options::given);
  m.def(
    "default_settings",
    [](PMP::Constrained_fairing_method method) {
      const PMP::Constrained_fairing_settings defaults(method);
      py::dict d;
      defaults.for_each_named_setting([&d](const char* name, const char*, const auto& value) { d[name] = value; });
      d["energy_decrease_window"] = defaults.energy_decrease_window();
      d["energy_remaining_fraction"] = defaults.energy_remaining_fraction();
      d["remaining_motion"] = defaults.remaining_motion();
      return d;
    },
    py::arg("method"));
  m.def("named_settings", [] {
    py::list table;
    PMP::Constrained_fairing_settings().for_each_named_setting(
      [&table](const char* name, const char* parameter, const auto&) { table.append(py::make_tuple(name, parameter)); });
    return table;
  });
  m.def(
    "parse_epsilon",
    [](const std::string& text) {
      const FE::Epsilon_text eps = FE::parse_epsilon(text);
      if(!eps.error.empty())
        throw py::value_error("eps " + eps.error);
      const char* kind = eps.kind == FE::Epsilon_text::Kind::AUTO       ? "auto"
                         : eps.kind == FE::Epsilon_text::Kind::RELATIVE ? "h"
                                                                         : "value";
      return py::make_tuple(kind, eps.value);
    },
    py::arg("text"));
  m.attr("default_epsilon") = FE::default_epsilon_text;
}

// The fairing of a mesh and the measures of one.
void bind_fairing(py::module_& m)
{
  m.def("fair", &fair, py::arg("vertices"), py::arg("faces"), py::arg("options"), py::arg("tolerance"),
        py::arg("fixed"), py::arg("box_half_extents"), py::arg("box_centers"), py::arg("region"), py::arg("feature_edges"),
        py::arg("progress"));
  m.def("fair_tile", &fair_tile, py::arg("vertices"), py::arg("current"), py::arg("faces"), py::arg("owned"),
        py::arg("at_start"), py::arg("options"), py::arg("max_iterations"));
  m.def(
    "mean_edge_length",
    [](const Float_array& vertices, const Index_array& faces) {
      return measure_mesh(vertices, faces, [](const Mesh& mesh) { return FE::mean_edge_length(mesh); });
    },
    py::arg("vertices"), py::arg("faces"));
  m.def(
    "estimate_noise_level",
    [](const Float_array& vertices, const Index_array& faces) {
      return measure_mesh(vertices, faces, [](const Mesh& mesh) { return PMP::estimate_noise_level(mesh); });
    },
    py::arg("vertices"), py::arg("faces"));
  m.def("noise_heights", &noise_heights, py::arg("vertices"), py::arg("faces"), py::arg("which"));
  m.def(
    "noise_radius",
    [](std::vector<double> heights) { return CF::noise_radius(heights); },
    py::arg("heights"));
  m.def(
    "estimate_noise_level_of_points",
    [](const Float_array& vertices, std::size_t neighbors) {
      py::gil_scoped_release release;
      std::vector<Point> points;
      const double* p = vertices.data();
      for(py::ssize_t i = 0; i < vertices.shape(0); ++i, p += 3)
        points.emplace_back(p[0], p[1], p[2]);
      return PMP::estimate_noise_level_of_points(points, CFP::number_of_neighbors(neighbors));
    },
    py::arg("vertices"), py::arg("neighbors"));
}

// Label maps: their surfaces, their fairing and the frame of their voxels.
void bind_label_maps(py::module_& m)
{
  m.attr("label_box_margin") = PMP::label_box_margin;
  m.def("label_map_epsilon", &PMP::label_map_epsilon, py::arg("spacing"));
  m.def(
    "voxel_frame",
    [](const FE::Voxel_frame::Affine& affine) {
      const FE::Voxel_frame frame(affine);
      return py::make_tuple(frame.error, frame.spacing, frame.axes, frame.translation, frame.mirrors);
    },
    py::arg("affine"));
  m.def("label_surface_nets", &label_surface_nets, py::arg("labels"), py::arg("spacing"), py::arg("origin"),
        py::arg("background"), py::arg("first_voxel") = std::array<std::size_t, 3>{0, 0, 0});
  m.def("fair_interfaces", &fair_interfaces, py::arg("vertices"), py::arg("faces"), py::arg("face_labels"),
        py::arg("options"), py::arg("tolerance"), py::arg("fixed"), py::arg("box_half_extents"),
        py::arg("box_centers"), py::arg("progress"));
  m.def("label_surface", &label_surface, py::arg("vertices"), py::arg("faces"), py::arg("face_labels"),
        py::arg("label"));
  m.def("fair_points", &fair_points, py::arg("vertices"), py::arg("normals"), py::arg("neighbors"), py::arg("options"),
        py::arg("tolerance"), py::arg("fixed"), py::arg("box_half_extents"), py::arg("box_centers"),
        py::arg("progress"));
}

// The files, read and written as the tool reads and writes them.
void bind_files(py::module_& m)
{
  m.def("read_mesh", &read_mesh, py::arg("path"));
  m.def("read_label_map_file", &read_label_map_file, py::arg("path"));
  m.def("write_mesh", &write_mesh, py::arg("path"), py::arg("vertices"), py::arg("faces"));
  m.def("write_files_into_folder", &write_files_into_folder, py::arg("source"), py::arg("folder"), py::arg("names"),
        py::arg("meshes"), py::arg("force"));
  m.def("read_mesh_with_properties", &read_mesh_with_properties, py::arg("path"), py::arg("repair"));
  m.def("is_point_set_file", &FE::is_point_set_file, py::arg("path"));
  m.def("read_point_set", &read_point_set, py::arg("path"));
  m.def("write_point_set", &write_point_set, py::arg("path"), py::arg("points"), py::arg("normals"),
        py::arg("vertex_properties"), py::arg("comments"));
  m.def("write_mesh_with_properties", &write_mesh_with_properties, py::arg("path"), py::arg("vertices"),
        py::arg("faces"), py::arg("vertex_properties"), py::arg("face_properties"), py::arg("comments"));
}

} // namespace

PYBIND11_MODULE(_core, m)
{
  m.doc() = "The compiled part of cgal_constrained_fairing; call the functions of the package instead.";
  bind_enums(m);
  bind_settings(m);
  bind_fairing(m);
  bind_label_maps(m);
  bind_files(m);
  m.def("max_threads", &max_threads);
  m.def("set_max_threads", &set_max_threads, py::arg("threads"));
#ifdef CGAL_LINKED_WITH_TBB
  m.attr("with_tbb") = true;
#else
  m.attr("with_tbb") = false;
#endif
}
