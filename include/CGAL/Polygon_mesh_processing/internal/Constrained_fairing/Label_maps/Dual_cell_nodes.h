// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rings and nodes of a dual cell (Dual_cell.h), what both cells of a ring agree on: the
// block's voxels and faces, the rings of four voxels around the cell's half-axes, the node of
// each face at each ring (two where a ring's labels alternate), and the sheets the nodes make.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_NODES_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_NODES_H

#include <CGAL/assertions.h>

#include <boost/container/static_vector.hpp>

#include <algorithm>
#include <array>
#include <cstddef>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// Face f of a block lies between voxels voxel_of_face(f, 0) and voxel_of_face(f, 1), which differ
// along axis f / 4; voxel o has offsets (o & 1, (o >> 1) & 1, (o >> 2) & 1) from the block's first.
inline int voxel_of_face(int f, int side)
{
  const int a = f / 4, u = (a + 1) % 3, w = (a + 2) % 3;
  return (side << a) | ((f & 1) << u) | (((f >> 1) & 1) << w);
}

// The root of item v in a forest of parent links: the few items of a cell (nodes, voxels, seeds,
// loops) are joined by linking one root to another, with no ranks.
template <typename Parents>
int root_in(const Parents& parent, int v)
{
  while(parent[std::size_t(v)] != v)
    v = parent[std::size_t(v)];
  return v;
}

// The rings and nodes of a dual cell: what both cells of a ring agree on.
template <typename Label>
class Dual_cell_nodes
{
public:
  // `label(d0, d1, d2)`: the label of the voxel at offset d (each in -1 .. 2) from the block's first.
  template <typename LabelAt>
  explicit Dual_cell_nodes(const LabelAt& label)
  {
    for(int o = 0; o < 8; ++o)
      m_block[std::size_t(o)] = label(o & 1, (o >> 1) & 1, (o >> 2) & 1);
    for(int o = 0; o < 8; ++o)
      m_region[std::size_t(o)] = o;
    for(int f = 0; f < 12; ++f)
    {
      m_node[std::size_t(f)] = {-1, -1};
      const int x = voxel_of_face(f, 0), y = voxel_of_face(f, 1);
      m_active[std::size_t(f)] = m_block[std::size_t(x)] != m_block[std::size_t(y)];
      if(!m_active[std::size_t(f)])
        join_regions(x, y);
    }
    for(int a = 0; a < 3; ++a)
      for(int s = 0; s < 2; ++s)
        make_ring(label, a, s);
  }

  Label label(int o) const { return m_block[std::size_t(o)]; }
  bool uniform() const
  {
    for(int f = 0; f < 12; ++f)
      if(m_active[std::size_t(f)])
        return false;
    return true;
  }
  bool active(int f) const { return m_active[std::size_t(f)]; }
  // The node of face f at its dual edge along `axis` (not f / 4): 2 * ring + pair.
  int node(int f, int axis) const { return m_node[std::size_t(f)][axis == (f / 4 + 1) % 3 ? 0 : 1]; }
  // Ring 2 a + s: around the half-axis of axis a on side s; its faces in order around it.
  const std::array<int, 4>& ring_faces(int ring) const { return m_ring_faces[std::size_t(ring)]; }
  // The ring's voxels in the same order: face i of the ring lies between voxels i and i + 1.
  const std::array<int, 4>& ring_voxels(int ring) const { return m_ring_voxels[std::size_t(ring)]; }
  bool paired(int ring) const { return m_paired[std::size_t(ring)]; }
  // Whether the ring's four voxels have four different labels (its faces then join in one node).
  bool four_labels(int ring) const { return m_four_labels[std::size_t(ring)]; }
  // Splits the node of a ring of four labels as a paired ring's: the faces around voxel k + 1 (k
  // is 0 or 1) at node 0, those around voxel k + 3 at node 1. Voxels k and k + 2, of two labels,
  // then meet in the gap between the two nodes, and a face between them (a bridge) must close it.
  void split(int ring, int k)
  {
    CGAL_precondition(four_labels(ring) && (k == 0 || k == 1));
    pair_faces(ring, k);
  }
  // The sheet of each node (the nodes joined through faces), named by one of its nodes.
  std::array<int, 12> sheets() const
  {
    std::array<int, 12> parent;
    for(int v = 0; v < 12; ++v)
      parent[std::size_t(v)] = v;
    const auto root = [&parent](int v) { return root_in(parent, v); };
    for(int f = 0; f < 12; ++f)
      if(m_active[std::size_t(f)])
        parent[std::size_t(root(m_node[std::size_t(f)][0]))] = root(m_node[std::size_t(f)][1]);
    for(int v = 0; v < 12; ++v)
      parent[std::size_t(v)] = root(v);
    return parent;
  }
  int region(int o) const { return root_in(m_region, o); }

  // The labels of the block, each once (no allocation: every cell of the map asks).
  boost::container::static_vector<Label, 8> block_labels() const
  {
    boost::container::static_vector<Label, 8> labels;
    for(int o = 0; o < 8; ++o)
      if(std::find(labels.begin(), labels.end(), label(o)) == labels.end())
        labels.push_back(label(o));
    return labels;
  }
  // The same, the background first: the label whose choice caps no surface of its own.
  boost::container::static_vector<Label, 8> block_labels_background_first(Label background) const
  {
    boost::container::static_vector<Label, 8> labels = block_labels();
    std::stable_partition(labels.begin(), labels.end(), [background](Label l) { return l == background; });
    return labels;
  }
  // f(face, voxel) for each face with a voxel of label l on one of its sides.
  template <typename F>
  void for_each_side_of(Label l, const F& f) const
  {
    for(int face = 0; face < 12; ++face)
      if(active(face))
        for(int side = 0; side < 2; ++side)
          if(label(voxel_of_face(face, side)) == l)
            f(face, voxel_of_face(face, side));
  }
  // The nodes of face f at its dual edges along axes (f / 4 + 1) % 3 and (f / 4 + 2) % 3.
  int first_node(int f) const { return node(f, (f / 4 + 1) % 3); }
  int second_node(int f) const { return node(f, (f / 4 + 2) % 3); }

private:
  void join_regions(int x, int y) { m_region[std::size_t(region(x))] = region(y); }

  template <typename LabelAt>
  void make_ring(const LabelAt& label, int a, int s)
  {
    const int ring_index = 2 * a + s, u = (a + 1) % 3, w = (a + 2) % 3;
    const int pu[4] = {0, 1, 1, 0}, pw[4] = {0, 0, 1, 1};
    std::array<Label, 4> ring, near, far;
    std::array<int, 4> voxel, face;
    for(int i = 0; i < 4; ++i)
    {
      int d[3];
      d[a] = s, d[u] = pu[i], d[w] = pw[i];
      voxel[std::size_t(i)] = d[0] | (d[1] << 1) | (d[2] << 2);
      ring[std::size_t(i)] = m_block[std::size_t(voxel[std::size_t(i)])];
      d[a] = 1 - s;
      near[std::size_t(i)] = label(d[0], d[1], d[2]);
      d[a] = s == 1 ? 2 : -1;
      far[std::size_t(i)] = label(d[0], d[1], d[2]);
    }
    for(int i = 0; i < 4; ++i)
    {
      // The face between ring voxels i and i + 1, which differ along u (i even) or w.
      const int b = i % 2 == 0 ? u : w, o = voxel[std::size_t(i)] & voxel[std::size_t((i + 1) % 4)];
      face[std::size_t(i)] = 4 * b + ((o >> ((b + 1) % 3)) & 1) + 2 * ((o >> ((b + 2) % 3)) & 1);
    }
    m_ring_faces[std::size_t(ring_index)] = face;
    m_ring_voxels[std::size_t(ring_index)] = voxel;
    int count = 0;
    for(int i = 0; i < 4; ++i)
      count += ring[std::size_t(i)] != ring[std::size_t((i + 1) % 4)];
    const bool repeat02 = ring[0] == ring[2], repeat13 = ring[1] == ring[3];
    m_paired[std::size_t(ring_index)] = count == 4 && (repeat02 || repeat13);
    m_four_labels[std::size_t(ring_index)] = count == 4 && !repeat02 && !repeat13;
    if(!m_paired[std::size_t(ring_index)])
    {
      for(int i = 0; i < 4; ++i)
        set_node(ring_index, i, 0);
      return;
    }
    // Voxels i and i + 2 of the ring joined through a layer beside it.
    const auto joined = [&](const std::array<Label, 4>& layer, int i) {
      const Label x = ring[std::size_t(i)];
      return layer[std::size_t(i)] == x && layer[std::size_t(i + 2)] == x &&
             (layer[std::size_t(i + 1)] == x || layer[std::size_t((i + 3) % 4)] == x);
    };
    bool bridge02;
    if(repeat02 != repeat13)
      bridge02 = repeat02;
    else
    {
      const bool joined02 = joined(near, 0) || joined(far, 0), joined13 = joined(near, 1) || joined(far, 1);
      bridge02 = joined02 != joined13 ? joined02 : ring[0] < ring[1];
    }
    const int k = bridge02 ? 0 : 1; // the bridge's voxels are k and k + 2
    join_regions(voxel[std::size_t(k)], voxel[std::size_t(k + 2)]);
    pair_faces(ring_index, k);
  }

  // Face i of the ring at node `pair` of the ring.
  void set_node(int ring, int i, int pair)
  {
    const int f = m_ring_faces[std::size_t(ring)][std::size_t(i)];
    if(m_active[std::size_t(f)])
      m_node[std::size_t(f)][ring / 2 == (f / 4 + 1) % 3 ? 0 : 1] = 2 * ring + pair;
  }

  // Pair 0 around voxel k + 1 (faces k, k + 1), pair 1 around voxel k + 3 (faces k + 2, k + 3).
  void pair_faces(int ring, int k)
  {
    set_node(ring, k, 0);
    set_node(ring, k + 1, 0);
    set_node(ring, k + 2, 1);
    set_node(ring, (k + 3) % 4, 1);
  }

  std::array<Label, 8> m_block;
  std::array<int, 8> m_region;
  std::array<bool, 12> m_active;
  std::array<std::array<int, 2>, 12> m_node;
  std::array<std::array<int, 4>, 6> m_ring_faces, m_ring_voxels;
  std::array<bool, 6> m_paired, m_four_labels;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_NODES_H
