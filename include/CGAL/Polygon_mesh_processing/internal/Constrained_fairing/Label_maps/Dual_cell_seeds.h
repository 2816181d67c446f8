// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The seeds of a dual cell's points (Dual_cell.h): each pair of a doubled edge, and each region
// of a label pinched at a sheet, seeds a point on the nodes of its faces.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_SEEDS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_SEEDS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Dual_cell_nodes.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The seeds of a cell's points: ids planted on nodes. The ids planted on one node are one point;
// the ids of the two pairs of a doubled ring, and of two regions of one label at one sheet, must
// stay apart, or the cell keeps one point per sheet (a conflict).
class Dual_cell_seeds
{
public:
  static constexpr int none = -1;

  Dual_cell_seeds() { m_seed.fill(none); }

  int new_id()
  {
    m_parent.push_back(int(m_parent.size()));
    return int(m_parent.size()) - 1;
  }
  void plant(int node, int id)
  {
    if(m_seed[std::size_t(node)] == none)
      m_seed[std::size_t(node)] = id;
    else
      m_parent[std::size_t(root(id))] = root(m_seed[std::size_t(node)]);
  }
  void keep_apart(int id, int other) { m_apart.push_back({id, other}); }
  bool empty() const { return m_parent.empty(); }
  bool conflict() const
  {
    for(const auto& pair : m_apart)
      if(root(pair[0]) == root(pair[1]))
        return true;
    return false;
  }
  // Each node's point, numbered 0, 1, ... in the order of the nodes (none where unseeded), and
  // their number.
  int points(std::array<int, 12>& point_of_node) const
  {
    std::vector<int> number(m_parent.size(), none);
    int count = 0;
    for(std::size_t v = 0; v < 12; ++v)
    {
      point_of_node[v] = none;
      if(m_seed[v] == none)
        continue;
      int& n = number[std::size_t(root(m_seed[v]))];
      if(n == none)
        n = count++;
      point_of_node[v] = n;
    }
    return count;
  }

private:
  int root(int i) const { return root_in(m_parent, i); }

  std::vector<int> m_parent;
  std::array<int, 12> m_seed;
  std::vector<std::array<int, 2> > m_apart;
};

// Doubled edges: a paired ring whose two pairs are one sheet here and in the next cell along
// its axis; each pair seeds a point. Returns the rings so doubled, a bit per ring. `label`: as
// Dual_cell_nodes takes it, reaching one voxel further along each axis.
template <typename Label, typename LabelAt>
unsigned seed_doubled_edges(const Dual_cell_nodes<Label>& nodes, const LabelAt& label, const std::array<int, 12>& sheet,
                            Dual_cell_seeds& seeds)
{
  constexpr int none = Dual_cell_seeds::none;
  unsigned doubled = 0;
  for(int a = 0; a < 3; ++a)
  {
    const int ring = 2 * a + 1;
    if(!nodes.paired(ring) || sheet[std::size_t(2 * ring)] != sheet[std::size_t(2 * ring + 1)])
      continue;
    const Dual_cell_nodes<Label> next([&](int d0, int d1, int d2) {
      int d[3] = {d0, d1, d2};
      ++d[a];
      return label(d[0], d[1], d[2]);
    });
    if(!next.paired(2 * a))
      continue;
    // The next cell sees the same ring as its ring 2 a, with the same pairs.
    int x = none, y = none;
    for(int f : next.ring_faces(2 * a))
      if(next.active(f))
      {
        const int node = next.node(f, a);
        (node % 2 == 0 ? x : y) = node;
      }
    const std::array<int, 12> next_sheet = next.sheets();
    if(x != none && y != none && next_sheet[std::size_t(x)] == next_sheet[std::size_t(y)])
    {
      const int p = seeds.new_id(), q = seeds.new_id();
      seeds.plant(2 * ring, p);
      seeds.plant(2 * ring + 1, q);
      seeds.keep_apart(p, q);
      doubled |= 1u << ring;
    }
  }
  return doubled;
}

// Pinched labels: a label with two regions or more at one sheet; each region seeds the nodes
// of its faces there. The label `whole` seeds none.
template <typename Label>
void seed_pinched_labels(const Dual_cell_nodes<Label>& nodes, const std::array<int, 12>& sheet, Dual_cell_seeds& seeds,
                         std::optional<Label> whole)
{
  constexpr int none = Dual_cell_seeds::none;
  for(const Label pinched : nodes.block_labels())
  {
    if(pinched == whole)
      continue;
    // The id of each (sheet, region) of the label, where a sheet holds two regions or more.
    std::array<std::array<int, 8>, 12> id_of;
    for(auto& ids : id_of)
      ids.fill(none);
    nodes.for_each_side_of(pinched, [&](int f, int o2) {
      id_of[std::size_t(sheet[std::size_t(nodes.first_node(f))])][std::size_t(nodes.region(o2))] = 0;
    });
    for(auto& ids : id_of)
    {
      if(std::count(ids.begin(), ids.end(), none) > 6)
      {
        ids.fill(none);
        continue;
      }
      std::vector<int> made;
      for(int& id : ids)
        if(id != none)
        {
          id = seeds.new_id();
          for(int other : made)
            seeds.keep_apart(other, id);
          made.push_back(id);
        }
    }
    nodes.for_each_side_of(pinched, [&](int f, int o2) {
      const int id = id_of[std::size_t(sheet[std::size_t(nodes.first_node(f))])][std::size_t(nodes.region(o2))];
      if(id != none)
        seeds.plant(nodes.first_node(f), id), seeds.plant(nodes.second_node(f), id);
    });
  }
}

// Each seeded node's point spread to the other nodes of its sheet, each taking the nearest
// seed's (breadth first, through the faces); the nodes of sheets with no seed stay none.
template <typename Label>
void spread_seeds(const Dual_cell_nodes<Label>& nodes, std::array<int, 12>& point_of_node)
{
  constexpr int none = Dual_cell_seeds::none;
  std::vector<int> queue;
  for(int v = 0; v < 12; ++v)
    if(point_of_node[std::size_t(v)] != none)
      queue.push_back(v);
  for(std::size_t q = 0; q < queue.size(); ++q)
    for(int f = 0; f < 12; ++f)
    {
      if(!nodes.active(f))
        continue;
      const int from = queue[q], to = nodes.first_node(f) == from    ? nodes.second_node(f)
                                      : nodes.second_node(f) == from ? nodes.first_node(f)
                                                                     : none;
      if(to != none && point_of_node[std::size_t(to)] == none)
        point_of_node[std::size_t(to)] = point_of_node[std::size_t(from)], queue.push_back(to);
    }
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_SEEDS_H
