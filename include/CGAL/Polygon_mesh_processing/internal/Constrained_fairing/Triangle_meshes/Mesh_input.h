// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A triangle mesh as the driver (Fairing_driver.h) fairs it, a model of its Input concept
// (Fairing_input.h): the whole mesh, or the part that a face range moves (Mesh_part.h). Its
// vertices are named in messages by their position in vertices(tmesh); its hinges are its
// interior edges but its creases (Feature_edges.h: those the user marks and those detected),
// whose curves are faired as curves (Curve_bending.h) and whose points, which have no surface
// normal, slide; it has no repair.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_INPUT_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_INPUT_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Fidelity_anchor.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Curve_network.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Curve_bending.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Vertex_maps.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Triangle_meshes/Feature_edges.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Triangle_meshes/Mesh_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Triangle_meshes/Mesh_part.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

template <typename TriangleMesh, typename VertexPointMap, typename FaceRange, typename FeatureEdgeMap = No_map>
class Mesh_input
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Point_3 = typename boost::property_traits<VertexPointMap>::value_type;
  using Part = Mesh_part<TriangleMesh>;
  using Number_map = typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<std::size_t> >::type;

public:
  // The faces of `region` move, or the whole mesh if it is null; `feature_edges` marks the
  // creases the user gives (No_map: none).
  Mesh_input(TriangleMesh& tmesh, const VertexPointMap& vpm, const FaceRange* region,
             const FeatureEdgeMap& feature_edges = FeatureEdgeMap())
    : m_tmesh(tmesh), m_vpm(vpm), m_region(region), m_feature_edge_map(feature_edges),
      m_vertex_index(get(CGAL::dynamic_vertex_property_t<std::size_t>(), tmesh))
  {}

  Input_error structure_error()
  {
    m_user_number.emplace(get(CGAL::dynamic_vertex_property_t<std::size_t>(), m_tmesh));
    std::size_t count = 0;
    for(auto v : vertices(m_tmesh))
      put(*m_user_number, v, count++);
    return mesh_error(m_tmesh, *m_user_number);
  }

  // The numbers of the vertices in messages are no longer needed once the part has them.
  template <typename VertexMaps>
  Part part(const VertexMaps& maps)
  {
    const auto is_constrained = [&maps](vertex_descriptor v) { return maps.is_constrained(v); };
    Part part = m_region ? Part(*m_region, m_tmesh, *m_user_number, is_constrained) : Part(m_tmesh, is_constrained);
    m_user_number.reset();
    return part;
  }

  Points input_points(const Part& part) const
  {
    Points X0(static_cast<Eigen::Index>(part.size()), 3);
    part.for_each_vertex([&](std::size_t k, vertex_descriptor v) {
      const Point_3& p = get(m_vpm, v);
      point(X0, k) = Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    });
    return X0;
  }

  // The triangles of the part, its vertices numbered in the part's order.
  std::vector<std::array<Index, 3> > triangles(const Part& part) const
  {
    auto place = get(CGAL::dynamic_vertex_property_t<Index>(), m_tmesh);
    part.for_each_vertex([&](std::size_t k, vertex_descriptor v) { put(place, v, static_cast<Index>(k)); });
    std::vector<std::array<Index, 3> > triangles;
    const auto add = [&](auto f) {
      const auto h = halfedge(f, m_tmesh);
      triangles.push_back({get(place, source(h, m_tmesh)), get(place, target(h, m_tmesh)),
                           get(place, target(next(h, m_tmesh), m_tmesh))});
    };
    if(part.triangles().empty())
      for(auto f : faces(m_tmesh))
        add(f);
    else
      for(auto f : part.triangles())
        add(f);
    return triangles;
  }

  void order(const Part& part, const std::vector<Index>& rank)
  {
    part.for_each_vertex([&](std::size_t k, vertex_descriptor v) { put(m_vertex_index, v, std::size_t(rank[k])); });
  }

  // With a face range, a hinge counts when one of its four vertices moves. No hinge crosses a
  // crease: an edge between two triangles that the user marks, or one detected at the input
  // points X0 with the settings' feature angle. With a face range, a crease's curve ends where it
  // leaves the part's triangles.
  Hinge_mesh hinges(const Part& part, const std::vector<bool>& moving, const Points& X0,
                    const Fairing_settings& settings)
  {
    Hinge_mesh mesh = m_region ? Hinge_mesh(m_tmesh, part.triangles(), part.size(), m_vertex_index,
                                            [&](const std::array<Index, 4>& v) {
                                              return moving[v[0]] || moving[v[1]] || moving[v[2]] || moving[v[3]];
                                            })
                               : Hinge_mesh(m_tmesh, m_vertex_index);
    m_part = &part;
    if constexpr(is_given_map<FeatureEdgeMap>)
      for_each_edge_of_part([&](auto e, Index a, Index b) {
        if(!is_border(e, m_tmesh) && get(m_feature_edge_map, e))
          m_feature_edges.push_back(sorted_edge(a, b));
      });
    if(settings.feature_angle)
    {
      m_detected_edges = detect_feature_edges(mesh, X0, *settings.feature_angle);
      m_feature_edges.insert(m_feature_edges.end(), m_detected_edges.begin(), m_detected_edges.end());
    }
    std::sort(m_feature_edges.begin(), m_feature_edges.end());
    m_feature_edges.erase(std::unique(m_feature_edges.begin(), m_feature_edges.end()), m_feature_edges.end());
    remove_hinges(mesh, m_feature_edges);
    if(!m_feature_edges.empty())
      mesh.creases = Curve_network(part.size(), m_feature_edges);
    m_creases = mesh.creases;
    return mesh;
  }

  std::size_t number_of_feature_edges() const { return m_feature_edges.size(); }

  static constexpr bool bends_by_hinges = true;

  // The accurate objective's anchor: the normal filter, then a vertex fit (Fidelity_anchor.h).
  template <typename Bound>
  void denoise(const Hinge_mesh& mesh, const Bound& bound, Points& X) const
  {
    Fidelity_anchor(mesh).apply(bound, X);
  }

  // The points of the creases have no surface normal: they slide freely in their bounds where
  // the others move along the normals (Normal_offsets.h); none without creases, an empty list.
  std::vector<bool> sliding_points(const Part&) const
  {
    return m_creases.on_curve;
  }

  double sliver_threshold(const Fairing_settings& settings) const { return settings.sliver_threshold; }

  void add_terms(Fairing_objective& objective, const Hinge_mesh&, const Points& X0, const Fairing_settings& settings)
  {
    if(m_creases.inner.empty())
      return;
    m_curves.emplace(m_creases.inner, X0, settings.curve_weight);
    objective.add_term(*m_curves);
  }

  template <typename Bound>
  void repair(const Hinge_mesh&, const Bound&, const std::vector<bool>&, const Points&, Points&, Fairing_objective&,
              const Fairing_settings&, Constrained_fairing_result&) const
  {}

  // With a face range, the output maps read 0 and false outside the part.
  template <typename VertexMaps>
  void clear_outputs(const VertexMaps& maps) const
  {
    if(!m_region)
      return;
    for(auto v : vertices(m_tmesh))
    {
      if constexpr(VertexMaps::has_deviation)
        put(maps.deviation, v, 0);
      if constexpr(VertexMaps::has_at_bound)
        put(maps.at_bound, v, false);
    }
  }

  // The detected creases are marked in the user's map of feature edges, if it is writable.
  void write_own_outputs() const
  {
    if constexpr(is_writable_map<FeatureEdgeMap>)
      if(!m_detected_edges.empty())
        for_each_edge_of_part([&](auto e, Index a, Index b) {
          if(std::binary_search(m_detected_edges.begin(), m_detected_edges.end(), sorted_edge(a, b)))
            put(m_feature_edge_map, e, true);
        });
  }

  void write(vertex_descriptor v, double x, double y, double z) { put(m_vpm, v, Point_3(x, y, z)); }

private:
  // f(e, a, b) for each edge e of the part (twice for an edge between two of its faces), a and
  // b its ends in the solver's order.
  template <typename F>
  void for_each_edge_of_part(const F& f) const
  {
    const auto index = [this](auto v) { return static_cast<Index>(get(m_vertex_index, v)); };
    const auto visit = [&](auto h) { f(edge(h, m_tmesh), index(source(h, m_tmesh)), index(target(h, m_tmesh))); };
    if(!m_region)
      for(auto e : edges(m_tmesh))
        visit(halfedge(e, m_tmesh));
    else
      for(auto f : m_part->triangles())
        for(auto h : halfedges_around_face(halfedge(f, m_tmesh), m_tmesh))
          visit(h);
  }

  TriangleMesh& m_tmesh;
  VertexPointMap m_vpm;
  const FaceRange* m_region;
  FeatureEdgeMap m_feature_edge_map;
  std::optional<Number_map> m_user_number; // each vertex's position in vertices(tmesh), until the part
  Number_map m_vertex_index;               // each vertex's place in the solver's order, from the order phase on
  const Part* m_part = nullptr;            // the driver's, from the hinges on
  std::vector<std::array<Index, 2> > m_feature_edges;  // the creases, sorted, from the hinges on
  std::vector<std::array<Index, 2> > m_detected_edges; // those the feature angle found, sorted
  Curve_network m_creases;                 // the hinge mesh's, for the sliding points and the curves' term
  std::optional<Curve_bending> m_curves;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_INPUT_H
