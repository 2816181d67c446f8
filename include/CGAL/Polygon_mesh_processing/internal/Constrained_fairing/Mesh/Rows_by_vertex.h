// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A table with a row of items per vertex, in one array (compressed rows), filled by a
// counting sort: the vertex-to-triangle table, the hinges and triangles sorted by vertex, the
// input check's edges. Nearly linear in the mesh's size, where a comparison sort of everything
// is not (it was the largest single cost of the set-up at a million triangles).

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ROWS_BY_VERTEX_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ROWS_BY_VERTEX_H

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

template <typename T>
struct Rows_by_vertex
{
  // Vertex v's items are items[first[v]] to items[first[v + 1] - 1].
  std::vector<std::size_t> first;
  std::vector<T> items;

  // The items that `emit_all(add)` passes to add(v, item), v in [0, n), each vertex's in the
  // order they come. `emit_all` runs twice: to count the items of each vertex, then to place
  // them.
  template <typename Emit_all>
  Rows_by_vertex(std::size_t n, const Emit_all& emit_all) : first(n + 1, 0)
  {
    emit_all([this](std::size_t v, const T&) { ++first[v + 1]; });
    for(std::size_t v = 0; v < n; ++v)
      first[v + 1] += first[v];
    items.resize(first[n]);
    std::vector<std::size_t> next(first.begin(), first.end() - 1);
    emit_all([&](std::size_t v, const T& item) { items[next[v]++] = item; });
  }

  typename std::vector<T>::const_iterator begin(std::size_t v) const { return items.begin() + std::ptrdiff_t(first[v]); }
  typename std::vector<T>::const_iterator end(std::size_t v) const { return items.begin() + std::ptrdiff_t(first[v + 1]); }

  // Sorts each vertex's items by `less`.
  template <typename Less>
  void sort_rows(const Less& less)
  {
    for(std::size_t v = 0; v + 1 < first.size(); ++v)
      std::sort(items.begin() + std::ptrdiff_t(first[v]), items.begin() + std::ptrdiff_t(first[v + 1]), less);
  }
};

// Sorts `items` by `less`, whose first key is vertex(item), in [0, n): placed by that vertex,
// then each vertex's few items sorted.
template <typename T, typename Vertex, typename Less>
void sort_by_vertex(std::vector<T>& items, std::size_t n, const Vertex& vertex, const Less& less)
{
  Rows_by_vertex<T> table(n, [&](const auto& add) {
    for(const T& x : items)
      add(vertex(x), x);
  });
  table.sort_rows(less);
  items.swap(table.items);
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ROWS_BY_VERTEX_H
