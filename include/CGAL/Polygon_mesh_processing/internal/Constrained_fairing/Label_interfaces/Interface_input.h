// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A multi-label surface as the driver (Fairing_driver.h) fairs it, a model of its Input concept
// (Fairing_input.h): a soup of points, triangles and the two labels of each triangle. What
// differs from a mesh:
//  - its structure is checked by Interface_check.h, and its junction lines (Junction_lines.h)
//    fix their ends and branches;
//  - its triangles are oriented from their smaller label into their larger, and its hinges are
//    the edges of exactly two triangles of one interface (where an interface meets itself along
//    an edge, no hinge);
//  - its objective adds the junction lines' term (Curve_bending.h), the labels' volumes
//    (Label_volumes.h), each label's held at its input value, and a barrier against folds
//    (Fold_barrier.h); its barrier against slivers pushes back needles of a larger angle;
//  - after the descent, the points of triangles that cross, of needles and of folds are pulled
//    back (Crossing_repair.h).

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_INTERFACE_INPUT_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_INTERFACE_INPUT_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Fidelity_anchor.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_interfaces/Crossing_repair.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_interfaces/Interface_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Numbered_part.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_interfaces/Junction_lines.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_interfaces/Label_volumes.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Folded_triangles.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Curve_bending.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fold_barrier.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Sliver_barrier.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Fairing_settings.h>

#include <CGAL/assertions.h>
#include <CGAL/number_type_config.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

template <typename PointRange, typename TriangleRange, typename LabelPairRange>
class Interface_input
{
  using Point = typename PointRange::value_type;

public:
  Interface_input(PointRange& points, const TriangleRange& triangles, const LabelPairRange& face_labels)
    : m_points(points), m_triangles(triangles), m_face_labels(face_labels)
  {
    CGAL_precondition(face_labels.size() == triangles.size());
  }

  // The soup's structure; then its junction lines and its triangles, each oriented from its
  // smaller label into its larger.
  Input_error structure_error()
  {
    const std::size_t n = m_points.size(), m = m_triangles.size();
    std::vector<std::size_t> interface_of;
    std::vector<bool> flipped;
    if(Input_error error = interface_error(n, m_triangles, m_face_labels, interface_of, flipped, m_sides))
      return error;
    m_junctions.emplace(junction_lines(n, m_sides, m_face_labels));
    m_oriented.resize(m);
    for(std::size_t f = 0; f < m; ++f)
    {
      const auto& t = m_triangles[f];
      m_oriented[f] = flipped[f] ? std::array<Index, 3>{Index(t[0]), Index(t[2]), Index(t[1])}
                                 : std::array<Index, 3>{Index(t[0]), Index(t[1]), Index(t[2])};
    }
    return {};
  }

  // The points that end or branch a junction line stay, and those the user fixed.
  template <typename VertexMaps>
  Numbered_part part(const VertexMaps& maps) const
  {
    std::vector<bool> fixed = m_junctions->end;
    for(std::size_t k = 0; k < fixed.size(); ++k)
      fixed[k] = fixed[k] || maps.is_constrained(k);
    return Numbered_part(std::move(fixed));
  }

  Points input_points(const Numbered_part& part) const
  {
    Points X0(static_cast<Eigen::Index>(part.size()), 3);
    for(std::size_t k = 0; k < part.size(); ++k)
      point(X0, k) = Eigen::Vector3d(CGAL::to_double(m_points[k].x()), CGAL::to_double(m_points[k].y()),
                                     CGAL::to_double(m_points[k].z()));
    return X0;
  }

  const std::vector<std::array<Index, 3> >& triangles(const Numbered_part&) const { return m_oriented; }

  void order(const Numbered_part&, const std::vector<Index>& rank)
  {
    for(auto& t : m_oriented)
      for(Index& v : t)
        v = rank[v];
    for(auto& line : m_junctions->inner)
      for(Index& v : line)
        v = rank[v];
  }

  // A hinge where exactly two triangles of one interface share an edge.
  Hinge_mesh hinges(const Numbered_part& part, const std::vector<bool>&, const Points&, const Fairing_settings&) const
  {
    std::vector<std::array<Index, 2> > hinge_faces;
    for(std::size_t i = 0, j = 0; i < m_sides.size(); i = j)
    {
      while(j < m_sides.size() && m_sides[j].same_edge(m_sides[i]) && m_sides[j].interface == m_sides[i].interface)
        ++j;
      if(j - i == 2)
        hinge_faces.push_back({Index(m_sides[i].face), Index(m_sides[i + 1].face)});
    }
    return Hinge_mesh(part.size(), m_oriented, hinge_faces);
  }

  // Its junction lines are not creases.
  std::size_t number_of_feature_edges() const { return 0; }

  static constexpr bool bends_by_hinges = true;

  // The accurate objective's anchor: the normal filter, then a vertex fit (Fidelity_anchor.h).
  template <typename Bound>
  void denoise(const Hinge_mesh& mesh, const Bound& bound, Points& X) const
  {
    Fidelity_anchor(mesh).apply(bound, X);
  }

  // The points of the junction lines, which have no surface normal: they slide freely in their
  // boxes where the others move along the normals (Normal_offsets.h).
  std::vector<bool> sliding_points(const Numbered_part& part) const
  {
    std::vector<bool> sliding(part.size(), false);
    for(const auto& line : m_junctions->inner)
      for(Index v : line)
        sliding[v] = true;
    return sliding;
  }

  double sliver_threshold(const Fairing_settings& settings) const
  {
    return Sliver_barrier::threshold_of_angle(settings.interface_sliver_angle);
  }

  // The volumes' triangles in the mesh's order, in which the objective evaluates them.
  void add_terms(Fairing_objective& objective, const Hinge_mesh& mesh, const Points& X0, const Fairing_settings& settings)
  {
    m_curves.emplace(m_junctions->inner, X0, settings.curve_weight);
    const std::vector<std::array<Index, 2> > sides = dense_label_sides();
    std::vector<std::array<Index, 2> > mesh_sides(sides.size());
    for(std::size_t f = 0; f < sides.size(); ++f)
      mesh_sides[mesh.positions_of_list[f]] = sides[f];
    m_volumes.emplace(mesh.triangles, mesh_sides, X0, settings.label_volume_weight);
    objective.add_term(*m_curves);
    objective.add_term(*m_volumes);
    // Without the barrier against slivers, the user asked for the energy without barriers.
    if(settings.sliver_barrier_weight > 0)
      objective.add_fold_barrier(Fold_barrier(interface_fold_weight, interface_fold_angle));
  }

  // The result counts the folds left after the pulls (with the barrier, only the start's).
  template <typename Bound>
  void repair(const Hinge_mesh& mesh, const Bound& bound, const std::vector<bool>& moving, const Points& X0,
              Points& X, Fairing_objective& objective, const Fairing_settings& settings,
              Constrained_fairing_result& result) const
  {
    // Without the barrier, needles and folds are the user's choice.
    const double smallest_sine =
      settings.sliver_barrier_weight > 0 ? std::sin(interface_repair_angle * CGAL_PI / 180) : 0;
    if(repair_crossings_needles_and_folds(mesh, bound, moving, smallest_sine, X0, X) > 0)
    {
      result.final_energy = objective.value(X);
      result.final_bending_energy = objective.bending_energy(X);
      result.number_of_folded_faces = folded_moving_triangles(mesh, moving, X).size();
    }
  }

  template <typename VertexMaps>
  void clear_outputs(const VertexMaps&) const
  {}

  void write_own_outputs() const {}

  void write(std::size_t k, double x, double y, double z) { m_points[k] = Point(x, y, z); }

private:
  // The labels of each triangle numbered 0, 1, ... in increasing order, the smaller first.
  std::vector<std::array<Index, 2> > dense_label_sides() const
  {
    using Label = std::decay_t<decltype(m_face_labels[0][0])>;
    std::vector<Label> labels;
    for(const auto& pair : m_face_labels)
      labels.insert(labels.end(), pair.begin(), pair.end());
    std::sort(labels.begin(), labels.end());
    labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
    const auto number = [&labels](Label l) {
      return Index(std::lower_bound(labels.begin(), labels.end(), l) - labels.begin());
    };
    std::vector<std::array<Index, 2> > sides;
    sides.reserve(m_face_labels.size());
    for(const auto& pair : m_face_labels)
    {
      const Index a = number(pair[0]), b = number(pair[1]);
      sides.push_back({(std::min)(a, b), (std::max)(a, b)});
    }
    return sides;
  }

  PointRange& m_points;
  const TriangleRange& m_triangles;
  const LabelPairRange& m_face_labels;
  std::vector<Interface_side> m_sides;
  std::optional<Curve_network> m_junctions;
  std::vector<std::array<Index, 3> > m_oriented; // in the soup's numbering, then the solver's
  std::optional<Curve_bending> m_curves;
  std::optional<Label_volumes> m_volumes;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_INTERFACE_INPUT_H
