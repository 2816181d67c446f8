// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One dual cell of a label map's surface nets: its points, which corner of each interface face
// each point is, and the box of each point. Decided from the voxels alone, so that every label's
// surface is a manifold that never touches itself, whatever the fairing does inside the boxes.
//
// A dual cell is the cube spanned by 8 voxel centres, its block. The interface faces inside the
// block (12 at most) meet at the cell's centre; on a small sphere around it, each face is an arc
// between two of the 6 half-axes, and the 4 voxels around a half-axis form a ring. At a ring, the
// faces join in one node, except where the ring's labels alternate X, Y, X, Y or X, Y, X, Z: there
// one label is the bridge, its two voxels joined through the edge, and the faces are paired around
// each voxel of the other diagonal, one node per pair. The bridge is the only repeated label, else
// the label whose two voxels are joined anyway through the block of either cell of the ring (both
// cannot be), else the smaller label. Seen from both cells of a ring the rule is the same.
//
// The faces joined through nodes make the cell's sheets; with one point per sheet, a label's
// surface is a manifold at the point when one region of that label (its voxels joined by faces
// and bridges) borders the sheet. Two regions of one label at one sheet (a junction that pinches
// a label, as where a label's voxels meet at the centre with two other labels around), or a ring
// whose two pairs are in one sheet here and in one sheet in the next cell too (a doubled edge),
// would make the label's surface touch itself. There the sheet gets several points: each region of
// the pinched label, each pair of the doubled ring (split in the ring's lower cell), seeds a point,
// every other node of the sheet takes the point of the nearest seed, and a face whose two nodes
// have different points gets both as its corner (its quad becomes a pentagon or more): the sheet
// becomes a ridge of points instead of a cone, and the regions no longer meet. The holes
// the ridge leaves are capped: by a fan of triangles of one interface where they border one, else
// by a fan around a junction, a point of no face, for each group of holes that share segments.
// Two labels pinched at one sheet, with two others around, can tie their seeds together (each
// node borders a region of each). Then rings whose four voxels have four labels are split: the
// faces around one diagonal's voxels at two nodes, so that the sheets part the pinched labels'
// regions, and the other diagonal's two labels meet in the gap between the nodes, across a
// bridge: a triangle of the two nodes' points and the next cell's point along the ring (that
// cell leaves the ring whole). The fewest splits that untie the seeds and close every
// label's surface are taken. Where none does, a label is left whole, unseeded, its regions passing
// each other through the gap that the other's ridge opens: the first whose leaving unties the
// seeds and lets the ridges close, the background first (it has no surface of its own, so nothing
// is left touching itself), then the block's labels in order. A label so left touches itself at
// the ridge.
//
// Where a label is still left touching itself at a point of the cell (four labels each on two
// opposite voxels of the block, say, or two pairs of a ring in one sheet in both its cells), every
// node gets a point of its own and the centre a small ball of one label: each other label's
// holes are capped between it and the ball, and the ball's regions open into it, joined through
// the centre. The ball parts every other label from itself. Its label is the first, the
// background before the block's labels in order, whose surfaces close, pass each point once and
// whose boxes are made; where none is, the cell stays as it was, and label_surface() splits the
// label that touches itself.
//
// Each point's box: the cell shrunk by `margin` (a fraction of the spacing) on every side for a
// cell of one point; with more, the half or whole of each axis that the quarters of its faces
// (inside the cell) cover, two points whose boxes meet cut apart, along the axis where their faces
// lie farthest apart, at the centre plane or, where both lie on one side of it, at the quarter
// plane; a junction takes an octant that no other box meets; and each box keeps `margin` from the
// planes that cut it. The boxes of different points never meet, so no two points can meet. Where
// the seeds still conflict or no box can be cut apart, the cell keeps one point per sheet, or
// takes the ball above.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_H

#include <CGAL/assertions.h>

#include <boost/container/static_vector.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

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

template <typename Label>
class Dual_cell
{
  static constexpr int none = -1;

public:
  // `label(d0, d1, d2)`: the label of the voxel at offset d (each in -2 .. 3) from the block's first.
  // `unsplit_rings`: bit r set where ring r may not be split, for the cell before this one along
  // its axis has split it (the bridge there ends at this cell's point of the ring).
  template <typename LabelAt>
  Dual_cell(const LabelAt& label, Label background, double margin, unsigned unsplit_rings = 0) : m_nodes(label)
  {
    m_point.fill(none);
    if(m_nodes.uniform())
      return;
    const std::array<int, 12> sheet = m_nodes.sheets();
    Dual_cell_seeds doubled;
    const unsigned doubled_rings = seed_doubled_edges(label, sheet, doubled);
    Dual_cell_seeds seeds = doubled;
    seed_pinched_labels(sheet, seeds, std::nullopt);
    // Two pinched labels may tie their seeds together; then rings of four labels are split, or
    // where no split serves, one of them is left whole, its regions joined through the gap that
    // the other's ridge opens between its own: the first label that unties the seeds and whose
    // ridges close, the background (which has no surface of its own) before the others in the
    // block's order.
    if(seeds.conflict() && place_with_bridges(label, margin, unsplit_rings))
      return;
    bool placed = false;
    if(seeds.conflict())
    {
      for(const Label whole : block_labels_background_first(background))
      {
        Dual_cell_seeds fewer = doubled;
        seed_pinched_labels(sheet, fewer, whole);
        if(!fewer.conflict() && place_points(sheet, fewer))
        {
          placed = true;
          break;
        }
      }
    }
    if(!placed)
      place_points(sheet, seeds);
    if(!make_boxes(margin))
    {
      one_point_per_sheet(sheet);
      make_boxes(margin);
    }
    if(!seeds.empty() && !manifold_at_points(background, doubled_rings))
      place_ball(background, margin);
  }

  // The number of points.
  int size() const { return m_count; }
  // The point of face f's corner at this cell next to its dual edge along `axis` (not f / 4);
  // -1 where face f has one label on both sides.
  int point(int f, int axis) const
  {
    return m_point[std::size_t(3 * f + (axis == (f / 4 + 1) % 3 ? 0 : 1))];
  }
  // The triangles that cap the cell's ridges, as points of the cell, with the labels on their two
  // sides: the normal of (p, q, r) points from the region of the first label into the second's.
  struct Cap
  {
    std::array<int, 3> points;
    std::array<Label, 2> labels;
  };
  const std::vector<Cap>& caps() const { return m_caps; }
  // The faces that close the gaps of the split rings of four labels (Dual_cell_nodes::split()):
  // each a triangle of the cell's points of the ring's two pairs and the next cell's point along
  // the ring's half-axis, between the labels of the two voxels that meet in the gap.
  struct Bridge
  {
    int axis, side;              // the ring's half-axis: side 1 towards the next cell along `axis`
    std::array<int, 2> points;   // the points of the faces around the ring's voxels k + 1 and k + 3
    std::array<int, 2> faces;    // a face of each pair
    std::array<Label, 2> labels; // of the ring's voxels k and k + 2
  };
  const std::vector<Bridge>& bridges() const { return m_bridges; }
  // Point p's box, relative to the cell's centre in spacings along axis c.
  double low(int p, int c) const { return m_low[std::size_t(p)][std::size_t(c)]; }
  double high(int p, int c) const { return m_high[std::size_t(p)][std::size_t(c)]; }

private:
  // Where two pinched labels tie their seeds together, rings of four labels are split: the faces
  // around one diagonal's voxels at two nodes, the other diagonal's labels meeting in the gap and
  // parted by a bridge. Of the choices (each ring left whole or split along either diagonal), the
  // first with the fewest splits that unties the seeds, closes every label's surface across the
  // cell's segments and makes the boxes; false, the rings whole, where none does.
  template <typename LabelAt>
  bool place_with_bridges(const LabelAt& label, double margin, unsigned unsplit_rings)
  {
    const Dual_cell_nodes<Label> whole = m_nodes;
    boost::container::static_vector<int, 6> rings;
    int choices = 1;
    for(int ring = 0; ring < 6; ++ring)
      if(whole.four_labels(ring) && !(unsplit_rings & (1u << ring)))
      {
        rings.push_back(ring);
        choices *= 3;
      }
    for(int splits = 1; splits <= int(rings.size()); ++splits)
      for(int choice = 0; choice < choices; ++choice)
      {
        int count = 0;
        for(int c = choice; c > 0; c /= 3)
          count += c % 3 != 0;
        if(count != splits)
          continue;
        m_nodes = whole;
        m_bridges.clear();
        m_caps.clear();
        m_first_junction = none;
        int c = choice;
        for(const int ring : rings)
        {
          const int k = c % 3 - 1;
          c /= 3;
          if(k < 0)
            continue;
          m_nodes.split(ring, k);
          const std::array<int, 4>& faces = m_nodes.ring_faces(ring);
          const std::array<int, 4>& voxels = m_nodes.ring_voxels(ring);
          m_bridges.push_back({ring / 2, ring % 2, {none, none}, {faces[std::size_t(k)], faces[std::size_t(k + 2)]},
                               {m_nodes.label(voxels[std::size_t(k)]), m_nodes.label(voxels[std::size_t(k + 2)])}});
        }
        const std::array<int, 12> sheet = m_nodes.sheets();
        Dual_cell_seeds seeds;
        seed_doubled_edges(label, sheet, seeds);
        seed_pinched_labels(sheet, seeds, std::nullopt);
        if(seeds.conflict() || !place_points(sheet, seeds))
          continue;
        bool apart = true;
        for(const Bridge& bridge : m_bridges)
          apart = apart && bridge.points[0] != bridge.points[1];
        if(apart && surfaces_closed() && make_boxes(margin))
          return true;
      }
    m_nodes = whole;
    m_bridges.clear();
    one_point_per_sheet(m_nodes.sheets());
    return false;
  }

  // Whether each label's surface is closed across the segments between the cell's points: each
  // segment that a face's corner, a cap or a bridge of the label runs along has two of them.
  bool surfaces_closed() const
  {
    std::vector<std::pair<Label, std::array<int, 2> > > uses;
    const auto use = [&uses](Label l, int p, int q) {
      if(p != q)
        uses.push_back({l, {(std::min)(p, q), (std::max)(p, q)}});
    };
    for(int f = 0; f < 12; ++f)
      if(m_nodes.active(f))
        for(int side = 0; side < 2; ++side)
          use(m_nodes.label(voxel_of_face(f, side)), m_point[std::size_t(3 * f)], m_point[std::size_t(3 * f + 1)]);
    for(const Cap& cap : m_caps)
      for(const Label l : cap.labels)
        for(std::size_t k = 0; k < 3; ++k)
          use(l, cap.points[k], cap.points[(k + 1) % 3]);
    for(const Bridge& bridge : m_bridges)
      for(const Label l : bridge.labels)
        use(l, bridge.points[0], bridge.points[1]);
    std::sort(uses.begin(), uses.end());
    for(std::size_t i = 0; i < uses.size();)
    {
      std::size_t j = i;
      while(j < uses.size() && uses[j] == uses[i])
        ++j;
      if(j - i != 2)
        return false;
      i = j;
    }
    return true;
  }

  // Doubled edges: a paired ring whose two pairs are one sheet here and in the next cell along
  // its axis; each pair seeds a point. Returns the rings so doubled, a bit per ring.
  template <typename LabelAt>
  unsigned seed_doubled_edges(const LabelAt& label, const std::array<int, 12>& sheet, Dual_cell_seeds& seeds) const
  {
    unsigned doubled = 0;
    for(int a = 0; a < 3; ++a)
    {
      const int ring = 2 * a + 1;
      if(!m_nodes.paired(ring) || sheet[std::size_t(2 * ring)] != sheet[std::size_t(2 * ring + 1)])
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
  // of its faces there.
  void seed_pinched_labels(const std::array<int, 12>& sheet, Dual_cell_seeds& seeds, std::optional<Label> whole) const
  {
    for(const Label pinched : block_labels())
    {
      if(pinched == whole)
        continue;
      // The id of each (sheet, region) of the label, where a sheet holds two regions or more.
      std::array<std::array<int, 8>, 12> id_of;
      for(auto& ids : id_of)
        ids.fill(none);
      for_each_side_of(pinched, [&](int f, int o2) {
        id_of[std::size_t(sheet[std::size_t(first_node(f))])][std::size_t(m_nodes.region(o2))] = 0;
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
      for_each_side_of(pinched, [&](int f, int o2) {
        const int id = id_of[std::size_t(sheet[std::size_t(first_node(f))])][std::size_t(m_nodes.region(o2))];
        if(id != none)
          seeds.plant(first_node(f), id), seeds.plant(second_node(f), id);
      });
    }
  }

  // The labels of the block, each once (no allocation: every cell of the map asks).
  boost::container::static_vector<Label, 8> block_labels() const
  {
    boost::container::static_vector<Label, 8> labels;
    for(int o = 0; o < 8; ++o)
      if(std::find(labels.begin(), labels.end(), m_nodes.label(o)) == labels.end())
        labels.push_back(m_nodes.label(o));
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
      if(m_nodes.active(face))
        for(int side = 0; side < 2; ++side)
          if(m_nodes.label(voxel_of_face(face, side)) == l)
            f(face, voxel_of_face(face, side));
  }
  int first_node(int f) const { return m_nodes.node(f, (f / 4 + 1) % 3); }
  int second_node(int f) const { return m_nodes.node(f, (f / 4 + 2) % 3); }

  // Every node takes a point: its seed's, the nearest seed's in its sheet (breadth first), or
  // its sheet's own; on a conflict, or where the ridges cannot be closed, one point per sheet.
  // Returns false where a split was wanted but not made.
  bool place_points(const std::array<int, 12>& sheet, const Dual_cell_seeds& seeds)
  {
    std::array<int, 12> point_of_node;
    const int count = seeds.points(point_of_node);
    const bool split = count > 0 && !seeds.conflict();
    if(split)
    {
      std::vector<int> queue;
      for(int v = 0; v < 12; ++v)
        if(point_of_node[std::size_t(v)] != none)
          queue.push_back(v);
      for(std::size_t q = 0; q < queue.size(); ++q)
        for(int f = 0; f < 12; ++f)
        {
          if(!m_nodes.active(f))
            continue;
          const int from = queue[q], to = first_node(f) == from   ? second_node(f)
                                          : second_node(f) == from ? first_node(f)
                                                                   : none;
          if(to != none && point_of_node[std::size_t(to)] == none)
            point_of_node[std::size_t(to)] = point_of_node[std::size_t(from)], queue.push_back(to);
        }
    }
    for(int v = 0; v < 12; ++v)
      if(!split || point_of_node[std::size_t(v)] == none)
        point_of_node[std::size_t(v)] = (split ? count : 0) + sheet[std::size_t(v)];
    number_points(point_of_node);
    if(split && !close_ridges())
    {
      one_point_per_sheet(sheet);
      return false;
    }
    return count == 0 || split;
  }

  void one_point_per_sheet(const std::array<int, 12>& sheet)
  {
    number_points(sheet);
    m_caps.clear();
    m_first_junction = none;
  }

  // Face f's corner as its polygon runs through it (Label_surface_nets.h: counterclockwise seen
  // from its second voxel): from the point next to the edge it arrives by to the one it leaves by.
  std::array<int, 2> corner(int f) const
  {
    const std::array<int, 2> axes = corner_axes(f);
    return {point(f, axes[0]), point(f, axes[1])};
  }
  // The axes of the dual edges it arrives by and leaves by.
  static std::array<int, 2> corner_axes(int f)
  {
    const int a = f / 4, u = (a + 1) % 3, w = (a + 2) % 3, o = voxel_of_face(f, 0);
    const int du = 1 - ((o >> u) & 1), dw = 1 - ((o >> w) & 1);
    const bool odd = du != dw; // corners 1 and 3 of (0, 0), (1, 0), (1, 1), (0, 1)
    return {odd ? u : w, odd ? w : u};
  }

  // Whether each label's surface stays closed across the segments where a face's corner is two
  // points: two of its faces or bridges on each segment, or else, where the faces on segments are
  // all of one interface, the holes the faces leave (the segments each used once) capped by
  // triangles of that interface fanned around each loop. The caps follow the faces only, so a
  // cell with bridges that needs caps does not close (place_with_bridges() checks again).
  bool close_ridges()
  {
    m_caps.clear();
    if(surfaces_closed())
      return true;
    std::vector<std::array<int, 2> > once; // directed from the smaller label into the larger
    bool one_interface = true;
    std::array<Label, 2> interface{};
    for(int f = 0; f < 12; ++f)
    {
      if(!m_nodes.active(f))
        continue;
      std::array<int, 2> e = corner(f);
      if(e[0] == e[1])
        continue;
      std::array<Label, 2> sides = {m_nodes.label(voxel_of_face(f, 0)), m_nodes.label(voxel_of_face(f, 1))};
      if(sides[1] < sides[0])
        std::swap(sides[0], sides[1]), std::swap(e[0], e[1]);
      one_interface = one_interface && (once.empty() || sides == interface);
      interface = sides;
      const auto reverse = std::find(once.begin(), once.end(), std::array<int, 2>{e[1], e[0]});
      if(reverse != once.end())
        once.erase(reverse);
      else
        once.push_back(e);
    }
    if(once.empty())
      return true;
    if(!one_interface)
      return cap_around_junctions();
    // The holes' loops: each segment used once, followed head to tail; the cap runs against them.
    while(!once.empty())
    {
      std::vector<int> loop = {once.front()[1], once.front()[0]};
      once.erase(once.begin());
      while(loop.back() != loop.front())
      {
        const auto next = std::find_if(once.begin(), once.end(),
                                       [&](const std::array<int, 2>& e) { return e[1] == loop.back(); });
        if(next == once.end())
          return false;
        loop.push_back((*next)[0]);
        once.erase(next);
      }
      loop.pop_back();
      for(std::size_t k = 1; k + 1 < loop.size(); ++k)
        m_caps.push_back({{loop[0], loop[k], loop[k + 1]}, interface});
    }
    return true;
  }

  // The holes of label l: the segments its faces use once, run with the label on their left seen
  // from outside, followed head to tail into loops of points; false where a point is passed twice
  // (the label would touch itself there).
  bool hole_loops(Label l, std::vector<std::vector<int> >& loops) const
  {
    std::vector<std::array<int, 2> > once;
    for_each_side_of(l, [&](int f, int voxel) {
      std::array<int, 2> e = corner(f);
      if(voxel == voxel_of_face(f, 1))
        std::swap(e[0], e[1]); // the polygon runs counterclockwise seen from the other side
      if(e[0] == e[1])
        return;
      const auto reverse = std::find(once.begin(), once.end(), std::array<int, 2>{e[1], e[0]});
      if(reverse != once.end())
        once.erase(reverse);
      else
        once.push_back(e);
    });
    // Each point of a hole is left once and reached once, so the segments make loops.
    std::array<int, 40> out, in;
    out.fill(none);
    in.fill(0);
    for(std::size_t s = 0; s < once.size(); ++s)
    {
      if(out[std::size_t(once[s][0])] != none)
        return false;
      out[std::size_t(once[s][0])] = int(s);
      ++in[std::size_t(once[s][1])];
    }
    for(int p = 0; p < 40; ++p)
      if(in[std::size_t(p)] != (out[std::size_t(p)] != none ? 1 : 0))
        return false;
    loops.clear();
    std::vector<bool> used(once.size(), false);
    for(std::size_t first = 0; first < once.size(); ++first)
      if(!used[first])
      {
        loops.emplace_back();
        for(std::size_t s = first; !used[s]; s = std::size_t(out[std::size_t(once[s][1])]))
        {
          used[s] = true;
          loops.back().push_back(once[s][0]);
        }
      }
    return true;
  }

  // Where no choice above keeps every label's surface from touching itself (four labels each on
  // two opposite voxels of the block, say): every node its own point and, at the centre, a small
  // ball of one label. Each other label's holes are capped between it and the ball, fanned around
  // each loop; the ball's own regions open into it, joined through the centre. Every label but
  // the ball's is so parted from itself at the centre, by the ball. The block's labels in order,
  // the background first, and the first kept whose surfaces close and pass each point once and
  // whose boxes are made; where none is, the cell stays as it was.
  void place_ball(Label background, double margin)
  {
    const auto before = std::make_tuple(m_count, m_point, m_low, m_high, m_caps, m_first_junction);
    const boost::container::static_vector<Label, 8> labels = block_labels_background_first(background);
    std::array<int, 12> own;
    for(int v = 0; v < 12; ++v)
      own[std::size_t(v)] = v;
    std::vector<std::vector<int> > loops;
    for(const Label ball : labels)
    {
      number_points(own);
      m_caps.clear();
      m_first_junction = none;
      bool capped = true;
      for(const Label l : block_labels())
        if(l != ball)
        {
          if(!hole_loops(l, loops))
          {
            capped = false;
            break;
          }
          for(const std::vector<int>& loop : loops)
            for(std::size_t k = 1; k + 1 < loop.size(); ++k)
              m_caps.push_back({{loop[0], loop[k + 1], loop[k]}, {l, ball}});
        }
      if(capped && surfaces_closed() && manifold_at_points(background) && make_boxes(margin))
        return;
    }
    std::tie(m_count, m_point, m_low, m_high, m_caps, m_first_junction) = before;
  }

  // Whether the surface of every label but `skip` passes each point of the cell once: around the
  // point, the label's faces, caps and bridges make one fan closed on itself. A fan's arms are
  // the dual edges out of the cell, by node, and the segments to the cell's other points; the two
  // nodes of a `doubled` ring (a bit per ring) at one point are one dual edge.
  bool manifold_at_points(Label skip, unsigned doubled = 0) const
  {
    std::array<int, 12> arm_of_node;
    for(int v = 0; v < 12; ++v)
      arm_of_node[std::size_t(v)] = v;
    for(int ring = 0; ring < 6; ++ring)
      if((doubled >> ring) & 1u)
      {
        int at[2] = {none, none};
        for(int f = 0; f < 12; ++f)
          if(m_nodes.active(f))
            for(int axis = 0; axis < 3; ++axis)
              if(axis != f / 4 && m_nodes.node(f, axis) / 2 == ring)
                at[m_nodes.node(f, axis) % 2] = point(f, axis);
        if(at[0] == at[1])
          arm_of_node[std::size_t(2 * ring + 1)] = 2 * ring;
      }
    std::vector<std::array<int, 2> > wedges; // arms: node, or 12 + the other point
    for(const Label l : block_labels())
    {
      if(l == skip)
        continue;
      for(int p = 0; p < m_count; ++p)
      {
        wedges.clear();
        for_each_side_of(l, [&](int f, int) {
          const std::array<int, 2> axes = corner_axes(f);
          const int a = point(f, axes[0]), b = point(f, axes[1]);
          const int in = arm_of_node[std::size_t(m_nodes.node(f, axes[0]))],
                    out = arm_of_node[std::size_t(m_nodes.node(f, axes[1]))];
          if(a == p)
            wedges.push_back({in, b == p ? out : 12 + b});
          else if(b == p)
            wedges.push_back({12 + a, out});
        });
        for(const Cap& cap : m_caps)
          if(cap.labels[0] == l || cap.labels[1] == l)
            for(std::size_t k = 0; k < 3; ++k)
              if(cap.points[k] == p)
                wedges.push_back({12 + cap.points[(k + 1) % 3], 12 + cap.points[(k + 2) % 3]});
        for(const Bridge& bridge : m_bridges)
          if(bridge.labels[0] == l || bridge.labels[1] == l)
            for(std::size_t k = 0; k < 2; ++k)
              if(bridge.points[k] == p)
                wedges.push_back({12 + bridge.points[1 - k],
                                  arm_of_node[std::size_t(m_nodes.node(bridge.faces[k], bridge.axis))]});
        // One closed fan: every arm in two wedges, all joined.
        std::array<int, 52> uses{}, parent;
        for(int x = 0; x < 52; ++x)
          parent[std::size_t(x)] = x;
        const auto root = [&parent](int x) { return root_in(parent, x); };
        for(const auto& w : wedges)
        {
          ++uses[std::size_t(w[0])], ++uses[std::size_t(w[1])];
          parent[std::size_t(root(w[0]))] = root(w[1]);
        }
        int fans = 0;
        for(int x = 0; x < 52; ++x)
        {
          if(uses[std::size_t(x)] != 0 && uses[std::size_t(x)] != 2)
            return false;
          fans += uses[std::size_t(x)] != 0 && root(x) == x;
        }
        if(fans > 1)
          return false;
      }
    }
    return true;
  }

  // Where the holes border several interfaces: each label's holes are the segments its faces use
  // once, run with the label on their left seen from outside, and each must be the reverse of one
  // other label's. The holes of a label make loops (a point that two of them pass would pinch the
  // label); loops that share segments make a group, and each group gets a new point, a junction,
  // the apex of a fan of caps, one per segment, between the two labels whose holes run along it.
  // Two loops of one label in a group would touch at its junction: no caps then.
  bool cap_around_junctions()
  {
    struct Hole_segment
    {
      std::array<int, 2> ends;
      Label label;
      int loop;
    };
    std::vector<Hole_segment> holes;
    std::vector<Label> loop_label;
    std::vector<std::vector<int> > loops;
    for(const Label l : block_labels())
    {
      if(!hole_loops(l, loops))
        return false;
      for(const std::vector<int>& points : loops)
      {
        const int loop = int(loop_label.size());
        loop_label.push_back(l);
        for(std::size_t k = 0; k < points.size(); ++k)
          holes.push_back({{points[k], points[(k + 1) % points.size()]}, l, loop});
      }
    }
    // The groups of loops, joined through the segments they share.
    std::vector<int> group(loop_label.size());
    for(std::size_t k = 0; k < group.size(); ++k)
      group[k] = int(k);
    const auto root = [&group](int k) { return root_in(group, k); };
    std::vector<Label> across(holes.size());
    for(std::size_t h = 0; h < holes.size(); ++h)
    {
      int count = 0;
      for(const Hole_segment& g : holes)
      {
        if(g.ends == holes[h].ends && &g != &holes[h])
          return false;
        if(g.ends[0] == holes[h].ends[1] && g.ends[1] == holes[h].ends[0])
        {
          ++count;
          across[h] = g.label;
          group[std::size_t(root(holes[h].loop))] = root(g.loop);
        }
      }
      if(count != 1)
        return false;
    }
    // One junction per group, numbered after the points.
    std::vector<int> junction(group.size(), none);
    int junctions = 0;
    for(std::size_t k = 0; k < group.size(); ++k)
    {
      int& j = junction[std::size_t(root(int(k)))];
      if(j == none)
        j = m_count + junctions++;
      for(std::size_t other = 0; other < k; ++other)
        if(loop_label[other] == loop_label[k] && root(int(other)) == root(int(k)))
          return false;
    }
    for(std::size_t h = 0; h < holes.size(); ++h)
      if(holes[h].label < across[h])
        m_caps.push_back({{junction[std::size_t(root(holes[h].loop))], holes[h].ends[1], holes[h].ends[0]},
                          {holes[h].label, across[h]}});
    m_first_junction = m_count;
    m_count += junctions;
    return true;
  }

  // Points numbered 0, 1, ... by the first face (and its first corner) that has them.
  void number_points(const std::array<int, 12>& point_of_node)
  {
    std::array<int, 40> number;
    number.fill(-1);
    m_count = 0;
    for(int f = 0; f < 12; ++f)
    {
      if(!m_nodes.active(f))
        continue;
      for(int side = 0; side < 2; ++side)
      {
        const int axis = (f / 4 + 1 + side) % 3;
        int& n = number[std::size_t(point_of_node[std::size_t(m_nodes.node(f, axis))])];
        if(n < 0)
          n = m_count++;
        m_point[std::size_t(3 * f + side)] = n;
      }
    }
    for(Bridge& bridge : m_bridges)
      for(std::size_t pair = 0; pair < 2; ++pair)
        bridge.points[pair] = point(bridge.faces[pair], bridge.axis);
  }

  // A box along each axis: the quarters [first, last) of the cell it spans.
  using Box_range = std::array<std::array<int, 2>, 3>;

  // Whether the boxes are made without merging points that a cap needs apart.
  bool make_boxes(double margin)
  {
    // Which halves (bit 0 lower, bit 1 upper) of each axis the point's faces cover, and where
    // they lie: the faces whose corner is the point alone, else all that touch it.
    std::vector<std::array<int, 3> > halves(std::size_t(m_count), std::array<int, 3>{0, 0, 0});
    std::vector<std::array<double, 3> > centroid(std::size_t(m_count), std::array<double, 3>{0, 0, 0});
    std::vector<bool> alone(std::size_t(m_count), false);
    for(int f = 0; f < 12; ++f)
      if(m_nodes.active(f) && m_point[std::size_t(3 * f)] == m_point[std::size_t(3 * f + 1)])
        alone[std::size_t(m_point[std::size_t(3 * f)])] = true;
    for(int f = 0; f < 12; ++f)
    {
      if(!m_nodes.active(f))
        continue;
      const int p = m_point[std::size_t(3 * f)], q = m_point[std::size_t(3 * f + 1)];
      for(int side = 0; side < (p == q ? 1 : 2); ++side)
      {
        const int point = side == 0 ? p : q;
        if(alone[std::size_t(point)] != (p == q))
          continue;
        const int a = f / 4, o = voxel_of_face(f, 0);
        for(int c = 0; c < 3; ++c)
          if(c != a)
          {
            const int upper = (o >> c) & 1;
            halves[std::size_t(point)][std::size_t(c)] |= upper ? 2 : 1;
            centroid[std::size_t(point)][std::size_t(c)] += upper ? 1 : -1;
          }
      }
    }
    for(auto& h : halves)
      for(int& axis : h)
        if(axis == 0)
          axis = 3;
    if(m_count == 1)
      halves[0] = {3, 3, 3};
    std::vector<Box_range> range(halves.size());
    for(std::size_t p = 0; p < range.size(); ++p)
      for(std::size_t c = 0; c < 3; ++c)
        range[p][c] = {(halves[p][c] & 1) ? 0 : 2, (halves[p][c] & 2) ? 4 : 2};
    // Boxes that meet are cut apart, at the axis where the two lie farthest apart: at the centre
    // plane where both reach across it, else (two points whose faces lie in one octant) in the
    // middle of the part they share.
    for(std::size_t x = 0; x < range.size(); ++x)
      for(std::size_t y = x + 1; y < range.size(); ++y)
      {
        if(is_junction(int(x)) || is_junction(int(y)) || !meet(range[x], range[y]))
          continue;
        if(cut_apart(range[x], range[y], centroid[x], centroid[y], true) ||
           cut_apart(range[x], range[y], centroid[x], centroid[y], false))
          continue;
        // Merged, the points of a cap or a bridge could coincide and leave its hole open.
        if(!m_caps.empty() || !m_bridges.empty())
          return false;
        merge(int(x), int(y));
        return make_boxes(margin);
      }
    for(int j = m_first_junction; j != none && j < m_count; ++j)
      if(!place_junction(j, range, centroid))
        return false;
    m_low.assign(range.size(), {});
    m_high.assign(range.size(), {});
    for(std::size_t p = 0; p < range.size(); ++p)
      for(std::size_t c = 0; c < 3; ++c)
      {
        m_low[p][c] = 0.25 * range[p][c][0] - 0.5 + margin;
        m_high[p][c] = 0.25 * range[p][c][1] - 0.5 - margin;
      }
    return true;
  }

  static bool meet(const Box_range& x, const Box_range& y)
  {
    for(std::size_t c = 0; c < 3; ++c)
      if((std::max)(x[c][0], y[c][0]) >= (std::min)(x[c][1], y[c][1]))
        return false;
    return true;
  }

  // Cuts boxes x and y apart along the axis where their faces lie farthest apart, at the centre
  // plane or in the middle of their common part; false where no axis can part them so.
  static bool cut_apart(Box_range& x, Box_range& y, const std::array<double, 3>& x_centroid,
                        const std::array<double, 3>& y_centroid, bool at_centre)
  {
    int best = -1, plane = 2;
    double apart = -1;
    bool x_lower = true;
    for(std::size_t c = 0; c < 3; ++c)
    {
      const int t = at_centre ? 2 : ((std::max)(x[c][0], y[c][0]) + (std::min)(x[c][1], y[c][1])) / 2;
      const double d = y_centroid[c] - x_centroid[c];
      if(x[c][0] < t && t < y[c][1] && d >= 0 && d > apart)
        best = int(c), apart = d, x_lower = true, plane = t;
      if(y[c][0] < t && t < x[c][1] && -d > apart)
        best = int(c), apart = -d, x_lower = false, plane = t;
    }
    if(best < 0)
      return false;
    std::array<int, 2>& lower = x_lower ? x[std::size_t(best)] : y[std::size_t(best)];
    std::array<int, 2>& upper = x_lower ? y[std::size_t(best)] : x[std::size_t(best)];
    lower[1] = (std::min)(lower[1], plane);
    upper[0] = (std::max)(upper[0], plane);
    return true;
  }

  bool is_junction(int p) const { return m_first_junction != none && p >= m_first_junction; }

  // Junction j, which has no faces of its own, takes the octant of the cell that no other box
  // meets (of the junctions, those placed before it), the one on the side of the points of its
  // caps; false where every octant is taken.
  bool place_junction(int j, std::vector<Box_range>& range, const std::vector<std::array<double, 3> >& centroid) const
  {
    std::array<double, 3> around{0, 0, 0};
    for(const Cap& cap : m_caps)
      if(cap.points[0] == j)
        for(std::size_t k = 1; k < 3; ++k)
          for(std::size_t c = 0; c < 3; ++c)
            around[c] += centroid[std::size_t(cap.points[k])][c];
    bool found = false;
    double best_side = 0;
    for(int octant = 0; octant < 8; ++octant)
    {
      Box_range box;
      double side = 0;
      for(std::size_t c = 0; c < 3; ++c)
      {
        const bool upper = (octant >> c) & 1;
        box[c] = {upper ? 2 : 0, upper ? 4 : 2};
        side += upper ? around[c] : -around[c];
      }
      bool free = true;
      for(int p = 0; p < m_count && free; ++p)
        free = (p >= j && is_junction(p)) || !meet(box, range[std::size_t(p)]);
      if(free && (!found || side > best_side))
        range[std::size_t(j)] = box, best_side = side, found = true;
    }
    return found;
  }

  // Point y becomes point x; the points after y are renumbered.
  void merge(int x, int y)
  {
    const auto renumber = [x, y](int& p) {
      if(p == y)
        p = x;
      else if(p > y)
        --p;
    };
    for(int& p : m_point)
      renumber(p);
    --m_count;
  }

  Dual_cell_nodes<Label> m_nodes;
  int m_count = 0;
  std::array<int, 36> m_point;
  std::vector<std::array<double, 3> > m_low, m_high;
  std::vector<Cap> m_caps;
  std::vector<Bridge> m_bridges;
  int m_first_junction = none; // the points from here on are apexes of caps, no corners of faces
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_H
