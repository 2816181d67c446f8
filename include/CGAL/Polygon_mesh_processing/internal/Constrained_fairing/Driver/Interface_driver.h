// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One call of constrained_fairing_of_interfaces(), on a multi-label surface given as a soup
// (points, triangles, the two labels of each triangle), in the phases of the mesh driver:
//  - check: the surface's structure (Interface_check.h), then every value (Value_check.h);
//  - junctions: an edge whose triangles name three labels or more is on a junction line; a
//    point on two junction edges is an inner point of its line, faired as a curve
//    (Junction_curves.h); a point on one or on three junction edges or more (a line's end, a
//    branch), or where four labels or more meet, stays where it is;
//  - order: the points in the Hilbert order of their input positions, the bounds read into it;
//  - build: the triangles, each oriented from its smaller label into its larger, and the hinges
//    of each interface: an edge of exactly two of its triangles (where an interface meets
//    itself along an edge, no hinge); the objective with the junction lines' term and the
//    labels' volumes (Label_volumes.h), each label's held at its input value;
//  - descend (Fairing_descent.h), pull back the points of triangles that cross (Crossing_repair.h),
//    report, and write back the points that moved.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_INTERFACE_DRIVER_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_INTERFACE_DRIVER_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Bound_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Fairing_descent.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Value_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Interface_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hilbert_order.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fidelity_anchor.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Junction_curves.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Label_volumes.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Crossing_repair.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Iteration_callback.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The needles the barrier against slivers pushes back on a multi-label surface, by their angle in
// degrees (3 on a mesh). Surface nets start from good triangles (45 degrees at least on cubic
// voxels, 18 on 1 x 1 x 3), and users mesh their surfaces for simulation. On the benchmark's
// balls (radii 24 and 17.3 voxels, cubic and 1 x 1 x 3) and three maps of 10 Voronoi labels
// (96^3), the smallest angle was 2.6 to 3.0 degrees with 3, 4.5 to 4.9 with 5 and 5.5 to 5.9
// with 6; the RMS distance to the true interfaces rose by 1 to 21 % from 3 to 6. With weight 0.3
// instead of 1 the Voronoi maps kept angles of 4.7 degrees.
constexpr double interface_sliver_angle = 6;

// The points of a multi-label surface as the bound parameters and the value check see them:
// point k is the key of the per-point maps and is named k in messages.
class Interface_part
{
public:
  explicit Interface_part(std::vector<bool> fixed) : m_fixed(std::move(fixed)) {}

  std::size_t size() const { return m_fixed.size(); }
  bool is_fixed(std::size_t k) const { return m_fixed[k]; }
  std::size_t number(std::size_t k) const { return k; }
  template <typename F>
  void for_each_vertex(const F& f) const
  {
    for(std::size_t k = 0; k < m_fixed.size(); ++k)
      f(k, k);
  }

private:
  std::vector<bool> m_fixed;
};

// The junction lines of a multi-label surface, from its sides (Interface_check.h): which points
// stay, and each inner point of a line with its two neighbours {p, i, n}.
struct Junctions
{
  std::vector<bool> fixed;
  std::vector<std::array<Index, 3> > inner;

  template <typename LabelPairRange>
  Junctions(std::size_t n, const std::vector<Interface_side>& sides, const LabelPairRange& face_labels)
    : fixed(n, false)
  {
    using Label = std::decay_t<decltype(face_labels[0][0])>;
    std::vector<std::vector<std::size_t> > neighbours(n);
    std::vector<std::vector<Label> > labels(n);
    for(std::size_t i = 0, j = 0; i < sides.size(); i = j)
    {
      std::vector<Label> around;
      while(j < sides.size() && sides[j].same_edge(sides[i]))
      {
        for(const Label l : face_labels[sides[j].face])
          around.push_back(l);
        ++j;
      }
      std::sort(around.begin(), around.end());
      around.erase(std::unique(around.begin(), around.end()), around.end());
      for(std::size_t v : {sides[i].a, sides[i].b})
        labels[v].insert(labels[v].end(), around.begin(), around.end());
      if(around.size() >= 3)
      {
        neighbours[sides[i].a].push_back(sides[i].b);
        neighbours[sides[i].b].push_back(sides[i].a);
      }
    }
    for(std::size_t v = 0; v < n; ++v)
    {
      std::sort(labels[v].begin(), labels[v].end());
      const std::size_t meeting = std::size_t(std::unique(labels[v].begin(), labels[v].end()) - labels[v].begin());
      const std::size_t degree = neighbours[v].size();
      fixed[v] = meeting >= 4 || (degree != 0 && degree != 2);
      if(degree == 2 && !fixed[v])
        inner.push_back({Index(neighbours[v][0]), Index(v), Index(neighbours[v][1])});
    }
  }
};

// The labels of each triangle numbered 0, 1, ... in increasing order, the smaller first.
template <typename LabelPairRange>
std::vector<std::array<Index, 2> > dense_label_sides(const LabelPairRange& face_labels)
{
  using Label = std::decay_t<decltype(face_labels[0][0])>;
  std::vector<Label> labels;
  for(const auto& pair : face_labels)
    labels.insert(labels.end(), pair.begin(), pair.end());
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  const auto number = [&labels](Label l) {
    return Index(std::lower_bound(labels.begin(), labels.end(), l) - labels.begin());
  };
  std::vector<std::array<Index, 2> > sides;
  sides.reserve(face_labels.size());
  for(const auto& pair : face_labels)
  {
    const Index a = number(pair[0]), b = number(pair[1]);
    sides.push_back({(std::min)(a, b), (std::max)(a, b)});
  }
  return sides;
}

template <typename PointRange, typename TriangleRange, typename LabelPairRange, typename NamedParameters>
Constrained_fairing_result fair_interfaces(PointRange& points, const TriangleRange& triangles,
                                           const LabelPairRange& face_labels, double epsilon,
                                           const Fairing_settings& settings, const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  using Point = typename PointRange::value_type;
  using Sparse_linear_solver =
    typename internal_np::Lookup_named_param_def<internal_np::sparse_linear_solver_t, NamedParameters,
                                                 Default_sparse_linear_solver>::type;
  CGAL_precondition(face_labels.size() == triangles.size());
  CGAL_precondition(settings.options.threshold >= 0);

  Constrained_fairing_result result;
  const auto reject = [&result](Input_error error) {
    result.defect = error.defect;
    result.message = std::move(error.message);
    return std::move(result);
  };
  // check
  const std::size_t n = points.size(), m = triangles.size();
  std::vector<std::size_t> interface_of;
  std::vector<bool> flipped;
  std::vector<Interface_side> sides;
  if(Input_error error = interface_error(n, triangles, face_labels, interface_of, flipped, sides))
    return reject(std::move(error));
  Junctions junctions(n, sides, face_labels);
  const auto is_constrained = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                                               CGAL::Static_boolean_property_map<std::size_t, false>());
  std::vector<bool> fixed = junctions.fixed;
  for(std::size_t k = 0; k < n; ++k)
    fixed[k] = fixed[k] || get(is_constrained, k);
  const Interface_part part(fixed);
  Points X0(static_cast<Eigen::Index>(n), 3);
  for(std::size_t k = 0; k < n; ++k)
    point(X0, k) = Eigen::Vector3d(CGAL::to_double(points[k].x()), CGAL::to_double(points[k].y()),
                                   CGAL::to_double(points[k].z()));
  // The triangles, each from its smaller label into its larger.
  std::vector<std::array<Index, 3> > oriented(m);
  for(std::size_t f = 0; f < m; ++f)
  {
    const auto& t = triangles[f];
    oriented[f] = flipped[f] ? std::array<Index, 3>{Index(t[0]), Index(t[2]), Index(t[1])}
                             : std::array<Index, 3>{Index(t[0]), Index(t[1]), Index(t[2])};
  }
  if(Input_error error = value_error(part, X0, [&] { return oriented; }, epsilon, settings, np))
    return reject(std::move(error));

  // order
  const std::vector<Index> rank = hilbert_rank(X0);
  Bound_parameters bounds;
  bounds.read(part, rank, epsilon, np);
  Points ordered(X0.rows(), 3);
  std::vector<bool> moving(n);
  for(std::size_t k = 0; k < n; ++k)
  {
    point(ordered, rank[k]) = point(X0, k);
    moving[rank[k]] = !fixed[k];
  }
  X0.swap(ordered);
  for(auto& t : oriented)
    for(Index& v : t)
      v = rank[v];
  for(auto& line : junctions.inner)
    for(Index& v : line)
      v = rank[v];

  // build: a hinge where exactly two triangles of one interface share an edge
  std::vector<std::array<Index, 2> > hinge_faces;
  for(std::size_t i = 0, j = 0; i < sides.size(); i = j)
  {
    while(j < sides.size() && sides[j].same_edge(sides[i]) && sides[j].interface == sides[i].interface)
      ++j;
    if(j - i == 2)
      hinge_faces.push_back({Index(sides[i].face), Index(sides[i + 1].face)});
  }
  const Hinge_mesh mesh(n, oriented, hinge_faces);
  const Junction_curves curves(junctions.inner, X0, Junction_curves::default_weight);
  Label_volumes volumes(oriented, dense_label_sides(face_labels), X0, Label_volumes::default_weight);

  const auto descend = [&](const auto& bound) {
    Fairing_objective energy(mesh, X0, settings.sliver_barrier_weight,
                             Sliver_barrier::threshold_of_angle(interface_sliver_angle));
    energy.add_junction_curves(curves);
    energy.add_label_volumes(volumes);
    Points anchor;
    if(settings.is_accurate())
    {
      anchor = X0;
      Fidelity_anchor(mesh).apply(bound, anchor);
      energy.add_fidelity(settings.fidelity_weight, [&bound](std::size_t i) { return bound.size(i); }, anchor);
    }
    const auto solver = choose_parameter<Sparse_linear_solver>(get_parameter(np, internal_np::sparse_linear_solver));
    Points X;
    Fairing_descent<std::decay_t<decltype(bound)>, Sparse_linear_solver>(mesh, bound, moving, settings, solver)
      .run(X0, energy, anchor, Iteration_callback(choose_parameter(get_parameter(np, iteration_callback),
                                                                   Always_continue())),
           X, result);
    if(!result)
      return;
    if(repair_crossings(oriented, bound, moving, X0, X) > 0)
    {
      result.final_energy = energy.value(X);
      result.final_bending_energy = energy.bending_energy(X);
    }
    // report and write back
    count_bound(bound, moving, X, result);
    if constexpr(!is_default_parameter<NamedParameters, vertex_deviation_map_t>::value)
    {
      const auto deviation_map = get_parameter(np, vertex_deviation_map);
      for(std::size_t k = 0; k < n; ++k)
        put(deviation_map, k, bound.deviation(X, rank[k]));
    }
    if constexpr(!is_default_parameter<NamedParameters, vertex_at_bound_map_t>::value)
    {
      const auto at_bound_map = get_parameter(np, vertex_at_bound_map);
      for(std::size_t k = 0; k < n; ++k)
        put(at_bound_map, k, is_at_bound(bound, moving, X, rank[k]));
    }
    for(std::size_t k = 0; k < n; ++k)
      if(point(X, rank[k]) != point(X0, rank[k]))
        points[k] = Point(X(rank[k], 0), X(rank[k], 1), X(rank[k], 2));
  };
  if(bounds.is_box())
    descend(bounds.box(X0));
  else
    descend(std::move(bounds).ball(X0));
  return result;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_INTERFACE_DRIVER_H
