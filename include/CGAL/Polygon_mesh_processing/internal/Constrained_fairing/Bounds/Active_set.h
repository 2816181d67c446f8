// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The active set at a point X of the feasible set: the vertices on the boundary of their
// bound, each with the face of its set it is on. It is computed once per step, and then
// restricts any number of displacements to that face: a vertex on its sphere moves in the
// tangent plane, a coordinate at a side of its box stays. The restriction is an orthogonal
// projection, so a symmetric positive definite operator restricted to the face stays so.
//
// Two notions of "active" serve the solvers: every vertex on its boundary (the face of Omega
// that contains X, for the Newton method's subspace step), or only those that the descent
// direction -G pushes outwards (the binding constraints, for the quasi-Newton method).
// Both passes run in parallel over the blocks of Parallel_for.h, each block listing its own.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ACTIVE_SET_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ACTIVE_SET_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>

#include <CGAL/assertions.h>
#include <CGAL/use.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

template <typename Bound>
class Active_set
{
public:
  using Face = typename Bound::Face;

  // Every vertex of X on the boundary of its set.
  void compute(const Bound& bound, const Points& X)
  {
    collect(X, [&](std::size_t i, Face& face) { return bound.is_on_boundary(X, i, face); });
  }

  // The vertices of X that the descent direction -G pushes out of their set, with the part
  // of the face that blocks them.
  void compute(const Bound& bound, const Points& X, const Points& G)
  {
    collect(X, [&](std::size_t i, Face& face) {
      return bound.is_on_boundary(X, i, face) && Bound::keep_blocked(face, point(G, i));
    });
  }

  // V restricted to the face: its components that would leave it are removed.
  void restrict(Points& V) const
  {
    parallel_for_blocks(m_size,
                        [&](std::size_t begin, std::size_t end, std::size_t) { restrict_range(V, begin, end); });
  }

  // The same for the vertices [begin, end) only, a block of Parallel_for.h.
  void restrict_range(Points& V, std::size_t begin, std::size_t end) const
  {
    CGAL_precondition(begin % parallel_block_size == 0 &&
                      end == (std::min)(begin + parallel_block_size, m_size));
    CGAL_USE(end);
    for(const auto& a : m_blocks[begin / parallel_block_size])
      Bound::restrict(a.second, point(V, a.first));
  }

  std::size_t size() const
  {
    std::size_t count = 0;
    for(const auto& block : m_blocks)
      count += block.size();
    return count;
  }

private:
  // The vertices for which `active(i, face)` holds, listed per block of Parallel_for.h.
  template <typename Active>
  void collect(const Points& X, const Active& active)
  {
    m_size = static_cast<std::size_t>(X.rows());
    m_blocks.resize(number_of_blocks(m_size));
    parallel_for_blocks(m_size, [&](std::size_t begin, std::size_t end, std::size_t b) {
      auto& block = m_blocks[b];
      block.clear();
      Face face;
      for(std::size_t i = begin; i < end; ++i)
        if(active(i, face))
          block.emplace_back(static_cast<Index>(i), face);
    });
  }

  std::size_t m_size = 0; // the number of vertices
  std::vector<std::vector<std::pair<Index, Face> > > m_blocks;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ACTIVE_SET_H
