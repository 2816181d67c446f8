// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One part of a prepared problem (Fairing_problem.h) as a problem of its own, the rest of the
// surface frozen: the vertices that move, and around them a halo, the other vertices of the
// triangles of the hinges that touch them (a hinge counts when one of its four vertices moves,
// as with a face range). The halo is pinned where the whole's points are now; the moving
// vertices keep their sets of the whole (and their lines along the normals), so that fairing
// the parts in turn, in sweeps, descends the whole's objective over the whole's feasible set
// (a Schwarz method: each part's step only lowers the energy of the hinges it touches). Built
// from the whole's tables in time proportional to the part, not to the whole.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_PART_PROBLEM_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_PART_PROBLEM_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Rows_by_vertex.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// What the parts of one mesh share: each vertex's triangles and each triangle's hinges, and a
// place for each vertex in the part being built (none outside it).
struct Part_tables
{
  static constexpr Index none = ~Index(0);

  explicit Part_tables(const Hinge_mesh& mesh)
    : triangles_of_vertex(mesh.number_of_vertices,
                          [&](const auto& add) {
                            for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
                              for(Index v : mesh.triangles[f])
                                add(v, static_cast<Index>(f));
                          }),
      hinges_of_triangle(mesh.triangles.size(),
                         [&](const auto& add) {
                           for(std::size_t h = 0; h < mesh.hinges.size(); ++h)
                             for(Index f : mesh.hinges[h].f)
                               add(f, static_cast<Index>(h));
                         }),
      place(mesh.number_of_vertices, none)
  {}

  Rows_by_vertex<Index> triangles_of_vertex;
  Rows_by_vertex<Index> hinges_of_triangle; // rows by triangle
  std::vector<Index> place;
};

class Part_problem
{
public:
  // The part of `mesh` whose vertices `part` (sorted, each once) move, if `moving` lets them.
  Part_problem(const Hinge_mesh& mesh, const std::vector<bool>& moving, const std::vector<Index>& part,
               Part_tables& tables)
    : m_mesh(build(mesh, moving, part, tables))
  {}

  // The part's vertices in the whole's numbering: the moving ones first, then the halo.
  const std::vector<Index>& vertices() const { return m_vertices; }
  std::size_t number_of_moving_vertices() const { return m_number_of_moving; }
  const Hinge_mesh& mesh() const { return m_mesh; }
  std::vector<bool> moves() const
  {
    std::vector<bool> moves(m_vertices.size(), false);
    std::fill(moves.begin(), moves.begin() + std::ptrdiff_t(m_number_of_moving), true);
    return moves;
  }

  // The rows of the part's vertices in X, a matrix of the whole's rows.
  Points rows_of(const Points& X) const
  {
    Points Y(Eigen::Index(m_vertices.size()), 3);
    for(std::size_t k = 0; k < m_vertices.size(); ++k)
      point(Y, k) = point(X, m_vertices[k]);
    return Y;
  }

  // The part's moving vertices written back from Y into the whole's X.
  void write_moving(const Points& Y, Points& X) const
  {
    for(std::size_t k = 0; k < m_number_of_moving; ++k)
      point(X, m_vertices[k]) = point(Y, k);
  }

private:
  static void sort_and_unique(std::vector<Index>& items)
  {
    std::sort(items.begin(), items.end());
    items.erase(std::unique(items.begin(), items.end()), items.end());
  }

  void add_vertex(Index v, Part_tables& tables)
  {
    if(tables.place[v] != Part_tables::none)
      return;
    tables.place[v] = static_cast<Index>(m_vertices.size());
    m_vertices.push_back(v);
  }

  // The moving vertices, then the triangles that the part's hinges touch and the hinges.
  Hinge_mesh build(const Hinge_mesh& mesh, const std::vector<bool>& moving, const std::vector<Index>& part,
                   Part_tables& tables)
  {
    for(Index v : part)
      if(moving[v])
        add_vertex(v, tables);
    m_number_of_moving = m_vertices.size();
    std::vector<Index> triangles, hinges;
    for(std::size_t k = 0; k < m_number_of_moving; ++k)
      triangles.insert(triangles.end(), tables.triangles_of_vertex.begin(m_vertices[k]),
                       tables.triangles_of_vertex.end(m_vertices[k]));
    sort_and_unique(triangles);
    for(Index f : triangles)
      hinges.insert(hinges.end(), tables.hinges_of_triangle.begin(f), tables.hinges_of_triangle.end(f));
    sort_and_unique(hinges);
    for(Index h : hinges)
      triangles.insert(triangles.end(), mesh.hinges[h].f.begin(), mesh.hinges[h].f.end());
    sort_and_unique(triangles);
    Hinge_mesh piece = numbered(mesh, triangles, hinges, tables);
    for(Index v : m_vertices)
      tables.place[v] = Part_tables::none;
    return piece;
  }

  // The triangles in the part's numbering (the halo's vertices placed after the moving ones)
  // and the hinges as pairs of positions in that list.
  Hinge_mesh numbered(const Hinge_mesh& mesh, const std::vector<Index>& triangles, const std::vector<Index>& hinges,
                      Part_tables& tables)
  {
    std::vector<std::array<Index, 3> > list;
    list.reserve(triangles.size());
    for(Index f : triangles)
    {
      std::array<Index, 3> t;
      for(std::size_t c = 0; c < 3; ++c)
      {
        add_vertex(mesh.triangles[f][c], tables);
        t[c] = tables.place[mesh.triangles[f][c]];
      }
      list.push_back(t);
    }
    const auto position = [&triangles](Index f) {
      return static_cast<Index>(std::lower_bound(triangles.begin(), triangles.end(), f) - triangles.begin());
    };
    std::vector<std::array<Index, 2> > hinge_faces;
    hinge_faces.reserve(hinges.size());
    for(Index h : hinges)
      hinge_faces.push_back({position(mesh.hinges[h].f[0]), position(mesh.hinges[h].f[1])});
    return Hinge_mesh(m_vertices.size(), list, hinge_faces);
  }

  std::vector<Index> m_vertices;
  std::size_t m_number_of_moving = 0;
  Hinge_mesh m_mesh;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_PART_PROBLEM_H
