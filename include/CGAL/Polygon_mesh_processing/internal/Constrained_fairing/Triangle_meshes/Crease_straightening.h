// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The detected crease curves (Feature_edges.h) straightened where they detour by a triangle or
// two off their line, which a noisy crease's detection does: the faces between the detour and the
// true crease are then faired into the wrong side's plane, turned by the crease's angle. A chain
// of two or three edges from u to w through vertices on no other crease edge is replaced by the
// hinge u w if there is one, a chain of three around a vertex x on no crease by u x w, and a
// chain of two u y w around such a vertex x (the two triangles' other side) by u x w where x is
// nearer the crease than y is (`nearer_crease()`: across the crease by the planes of its sides,
// where they are more than the detection's angle apart), and of two chains of two u y w and u z w
// (a diamond) the one farther from the line u w is dropped; each only if the curve heads on alike
// on both sides of the chain (a corner of the curve is kept). The other moves take edges off, and
// a swap takes off a vertex that no swap puts back, so the moves end; a smooth curve has no chain
// of the first two kinds (it would turn by 120 degrees within one or two edges). Measured in
// doc/design_notes.md, "Creases".

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_CREASE_STRAIGHTENING_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_CREASE_STRAIGHTENING_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Rows_by_vertex.h>

#include <CGAL/number_type_config.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <set>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The crease curves of a mesh at points X as the moves change them; `face_normal(f)` gives the
// normal of face f that the sides' planes are made of.
template <typename Face_normal>
class Crease_straightening
{
public:
  // A jog round a vertex is swapped to it where the vertex is this many times nearer the line
  // (where the crease's sides are not apart: nearer_crease()).
  static constexpr double jog_ratio = 1.5;

  // `edges`: the curves, sorted, each once; `degrees`: the angle over which the sides of a crease
  // are apart.
  Crease_straightening(const Hinge_mesh& mesh, const Points& X, const Face_normal& face_normal, double degrees,
                       const std::vector<std::array<Index, 2> >& edges)
    : m_mesh(mesh), m_X(X), m_face_normal(face_normal), m_apart(std::cos(degrees * CGAL_PI / 180)),
      m_faces_around(mesh.number_of_vertices,
                     [&mesh](const auto& add) {
                       for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
                         for(Index v : mesh.triangles[f])
                           add(v, Index(f));
                     }),
      m_neighbours(mesh.number_of_vertices,
                   [&mesh](const auto& add) {
                     for(const Hinge& h : mesh.hinges)
                     {
                       add(h.v[0], h.v[1]);
                       add(h.v[1], h.v[0]);
                     }
                   }),
      m_creases(edges.begin(), edges.end()), m_degree(mesh.number_of_vertices, 0),
      m_taken_off(mesh.number_of_vertices, false)
  {
    for(const auto& e : edges)
      for(Index v : e)
        ++m_degree[v];
  }

  // Makes moves until none is left.
  void straighten_all()
  {
    for(bool moved = true; moved;)
    {
      moved = false;
      for(Index u = 0; u < Index(m_mesh.number_of_vertices); ++u)
        for(auto v = m_neighbours.begin(u); v != m_neighbours.end(u) && m_degree[u] > 0; ++v)
          if(is_crease(u, *v) && straighten(u, *v))
          {
            moved = true;
            break;
          }
    }
  }

  // The curves, sorted, each once.
  std::vector<std::array<Index, 2> > edges() const { return {m_creases.begin(), m_creases.end()}; }

private:
  static bool has_corner(const std::array<Index, 3>& t, Index v) { return t[0] == v || t[1] == v || t[2] == v; }

  bool is_crease(Index a, Index b) const { return m_creases.count(sorted_edge(a, b)) != 0; }

  bool adjacent(Index a, Index b) const
  {
    return std::find(m_neighbours.begin(a), m_neighbours.end(a), b) != m_neighbours.end(a);
  }

  void remove(Index a, Index b)
  {
    m_creases.erase(sorted_edge(a, b));
    --m_degree[a];
    --m_degree[b];
  }

  void insert(Index a, Index b)
  {
    m_creases.insert(sorted_edge(a, b));
    ++m_degree[a];
    ++m_degree[b];
  }

  // The edges of `chain` up to chain[k] taken off the curves.
  void remove_chain(const std::array<Index, 4>& chain, std::size_t k)
  {
    for(std::size_t j = 0; j < k; ++j)
      remove(chain[j], chain[j + 1]);
  }

  // The plane of the faces around v that do not have `other` as a corner: the mean of their
  // normals, through the mean of their corners but v (so that v's own noise is not in it).
  // False where those normals cancel.
  bool side_plane(Index v, Index other, Eigen::Vector3d& normal, double& offset) const
  {
    normal.setZero();
    for(auto f = m_faces_around.begin(v); f != m_faces_around.end(v); ++f)
      if(!has_corner(m_mesh.triangles[*f], other))
        normal += m_face_normal(*f);
    if(!(normal.norm() > 0))
      return false;
    normal.normalize();
    offset = 0;
    std::size_t count = 0;
    for(auto f = m_faces_around.begin(v); f != m_faces_around.end(v); ++f)
      if(!has_corner(m_mesh.triangles[*f], other))
        for(Index c : m_mesh.triangles[*f])
          if(c != v)
          {
            offset += normal.dot(m_X.row(c).transpose());
            ++count;
          }
    offset /= double(count);
    return true;
  }

  // v's crease neighbour other than `not_this`, or v itself.
  Index crease_neighbour(Index v, Index not_this) const
  {
    for(auto w = m_neighbours.begin(v); w != m_neighbours.end(v); ++w)
      if(*w != not_this && is_crease(v, *w))
        return *w;
    return v;
  }

  // The point two edges on from v, away from `from`, or where the curve ends or branches before.
  Index two_edges_on(Index v, Index from) const
  {
    for(std::size_t step = 0; step < 2 && m_degree[v] == 2; ++step)
    {
      const Index next = crease_neighbour(v, from);
      from = v;
      v = next;
    }
    return v;
  }

  // Whether the curve heads on alike before u (coming from u's crease neighbour other than
  // `from_u`) and after w (towards w's other than `from_w`), within 60 degrees, two edges away
  // where it can: a detour does, a corner of the curve does not. Ends and junctions tell
  // nothing, and allow the move.
  bool continues(Index u, Index from_u, Index w, Index from_w) const
  {
    if(m_degree[u] != 2 || m_degree[w] != 2)
      return true;
    const Eigen::Vector3d a = (m_X.row(u) - m_X.row(two_edges_on(u, from_u))).transpose();
    const Eigen::Vector3d b = (m_X.row(two_edges_on(w, from_w)) - m_X.row(w)).transpose();
    return a.dot(b) > 0.5 * a.norm() * b.norm();
  }

  // How far m is from the line through u and w, times |w - u|.
  double off_chord(Index m, Index u, Index w) const
  {
    const Eigen::Vector3d a = (m_X.row(m) - m_X.row(u)).transpose(), b = (m_X.row(w) - m_X.row(u)).transpose();
    return a.cross(b).norm();
  }

  // Whether a chain u y w should go round x instead (the vertex of its two triangles on no
  // crease). A crease lies on the planes of both its sides, so where the sides (x's faces but
  // the two, and y's but those) are more than the angle apart: whether x is nearer y's side's
  // plane than y is to x's, a test across the crease whose planes average the noise, and nearer
  // the line u w, which the noise alone can turn; where the sides are not apart, whether x is
  // clearly nearer the line.
  bool nearer_crease(Index x, Index y, Index u, Index w, double y_off) const
  {
    const double x_off = off_chord(x, u, w);
    if(!(x_off < y_off))
      return false;
    Eigen::Vector3d n_x, n_y;
    double c_x = 0, c_y = 0;
    if(side_plane(x, y, n_x, c_x) && side_plane(y, x, n_y, c_y) && n_x.dot(n_y) < m_apart)
      return std::abs(n_y.dot(m_X.row(x).transpose()) - c_y) < std::abs(n_x.dot(m_X.row(y).transpose()) - c_x);
    return jog_ratio * x_off < y_off;
  }

  // The moves on a chain of two u inner w that is no hinge's: the other path of a diamond kept,
  // or the jog swapped to the vertex it goes round. True if one was made.
  bool move_jog(Index u, Index inner, Index w)
  {
    const double inner_off = off_chord(inner, u, w);
    for(auto x = m_neighbours.begin(u); x != m_neighbours.end(u); ++x)
    {
      // the other path of a diamond, nearer the line (inner itself is not)
      if(m_degree[*x] == 2 && is_crease(u, *x) && is_crease(*x, w) && off_chord(*x, u, w) < inner_off)
      {
        remove(u, inner);
        remove(inner, w);
        return true;
      }
      // the vertex the jog goes round, nearer the crease
      if(m_degree[*x] == 0 && !m_taken_off[*x] && adjacent(*x, w) && adjacent(*x, inner) &&
         nearer_crease(*x, inner, u, w, inner_off))
      {
        remove(u, inner);
        remove(inner, w);
        insert(u, *x);
        insert(*x, w);
        m_taken_off[inner] = true;
        return true;
      }
    }
    return false;
  }

  // The move on a chain of three from u to w that is no hinge's: through a vertex on no crease
  // between u and w. True if it was made.
  bool go_round(const std::array<Index, 4>& chain)
  {
    const Index u = chain[0], w = chain[3];
    for(auto x = m_neighbours.begin(u); x != m_neighbours.end(u); ++x)
      if(m_degree[*x] == 0 && adjacent(*x, w))
      {
        remove_chain(chain, 3);
        insert(u, *x);
        insert(*x, w);
        return true;
      }
    return false;
  }

  // Tries the moves on the chain from u through u's crease neighbour `first`; true if one was made.
  bool straighten(Index u, Index first)
  {
    std::array<Index, 4> chain = {u, first, u, u};
    for(std::size_t k = 2; k <= 3; ++k)
    {
      const Index inner = chain[k - 1];
      if(m_degree[inner] != 2)
        return false;
      chain[k] = crease_neighbour(inner, chain[k - 2]);
      const Index w = chain[k];
      if(w == u)
        return false;
      if(!continues(u, chain[1], w, chain[k - 1]))
        continue;
      if(adjacent(u, w) && !is_crease(u, w))
      {
        remove_chain(chain, k);
        insert(u, w);
        return true;
      }
      if(k == 2 ? move_jog(u, inner, w) : go_round(chain))
        return true;
    }
    return false;
  }

  const Hinge_mesh& m_mesh;
  const Points& m_X;
  const Face_normal& m_face_normal;
  const double m_apart; // the cosine of the angle over which the sides are apart
  const Rows_by_vertex<Index> m_faces_around, m_neighbours;
  std::set<std::array<Index, 2> > m_creases;
  std::vector<unsigned> m_degree; // each vertex's crease edges
  // the vertices a swap took off a curve, which no swap puts back (so that the swaps end)
  std::vector<bool> m_taken_off;
};

// Straightens the crease curves `edges` (sorted, each once) of `mesh` at the points X, the sides
// of a crease apart where their normals are more than `degrees` apart (above).
template <typename Face_normal>
void straighten_creases(const Hinge_mesh& mesh, const Points& X, const Face_normal& face_normal, double degrees,
                        std::vector<std::array<Index, 2> >& edges)
{
  if(edges.empty())
    return;
  Crease_straightening<Face_normal> curves(mesh, X, face_normal, degrees, edges);
  curves.straighten_all();
  edges = curves.edges();
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_CREASE_STRAIGHTENING_H
