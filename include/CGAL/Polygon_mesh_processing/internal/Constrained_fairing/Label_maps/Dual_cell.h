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
// Each point gets a box that no other point's meets (Dual_cell_boxes.h). Where the seeds still
// conflict or no box can be cut apart, the cell keeps one point per sheet, or takes the ball
// above.
//
// The parts, one header each: the rings and nodes (Dual_cell_nodes.h), the seeds
// (Dual_cell_seeds.h), the points as the corners of the faces, with the caps and bridges
// (Dual_cell_points.h), the checks of the labels' surfaces at the points (Dual_cell_manifold.h),
// the caps of the ridges (Ridge_caps.h) and the boxes (Dual_cell_boxes.h).

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Dual_cell_boxes.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Dual_cell_manifold.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Dual_cell_nodes.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Dual_cell_points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Dual_cell_seeds.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Ridge_caps.h>

#include <boost/container/static_vector.hpp>

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

template <typename Label>
class Dual_cell
{
  static constexpr int none = -1;

public:
  using Cap = Dual_cell_cap<Label>;
  using Bridge = Dual_cell_bridge<Label>;

  // `label(d0, d1, d2)`: the label of the voxel at offset d (each in -2 .. 3) from the block's first.
  // `unsplit_rings`: bit r set where ring r may not be split, for the cell before this one along
  // its axis has split it (the bridge there ends at this cell's point of the ring).
  template <typename LabelAt>
  Dual_cell(const LabelAt& label, Label background, double margin, unsigned unsplit_rings = 0) : m_nodes(label)
  {
    if(m_nodes.uniform())
      return;
    const std::array<int, 12> sheet = m_nodes.sheets();
    Dual_cell_seeds doubled;
    const unsigned doubled_rings = seed_doubled_edges(m_nodes, label, sheet, doubled);
    Dual_cell_seeds seeds = doubled;
    seed_pinched_labels(m_nodes, sheet, seeds, std::optional<Label>());
    // Two pinched labels may tie their seeds together; then rings of four labels are split, or
    // where no split serves, one of them is left whole.
    if(seeds.conflict() && place_with_bridges(label, margin, unsplit_rings))
      return;
    if(!seeds.conflict() || !place_leaving_whole(sheet, doubled, background))
      place_points(sheet, seeds);
    if(!make_boxes(m_nodes, m_points, margin, m_boxes))
    {
      m_points.one_per_sheet(m_nodes, sheet);
      make_boxes(m_nodes, m_points, margin, m_boxes);
    }
    if(!seeds.empty() && !manifold_at_points(m_nodes, m_points, background, doubled_rings))
      place_ball(background, margin);
  }

  // The number of points.
  int size() const { return m_points.count; }
  // The point of face f's corner at this cell next to its dual edge along `axis` (not f / 4);
  // -1 where face f has one label on both sides.
  int point(int f, int axis) const { return m_points.point(f, axis); }
  // The triangles that cap the cell's ridges.
  const std::vector<Cap>& caps() const { return m_points.caps; }
  // The faces that close the gaps of the split rings of four labels.
  const std::vector<Bridge>& bridges() const { return m_points.bridges; }
  // Point p's box, relative to the cell's centre in spacings along axis c.
  double low(int p, int c) const { return m_boxes.low[std::size_t(p)][std::size_t(c)]; }
  double high(int p, int c) const { return m_boxes.high[std::size_t(p)][std::size_t(c)]; }

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
        if(count == splits && place_with_splits(label, margin, whole, rings, choice))
          return true;
      }
    m_nodes = whole;
    m_points.bridges.clear();
    m_points.one_per_sheet(m_nodes, m_nodes.sheets());
    return false;
  }

  // Choice c of place_with_bridges(): ring rings[i] left whole where the i-th base-3 digit of
  // c is 0, else split along diagonal k, the digit less 1.
  template <typename LabelAt>
  bool place_with_splits(const LabelAt& label, double margin, const Dual_cell_nodes<Label>& whole,
                         const boost::container::static_vector<int, 6>& rings, int choice)
  {
    m_nodes = whole;
    m_points.bridges.clear();
    m_points.clear_caps();
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
      m_points.bridges.push_back({ring / 2, ring % 2, {none, none}, {faces[std::size_t(k)], faces[std::size_t(k + 2)]},
                                  {m_nodes.label(voxels[std::size_t(k)]), m_nodes.label(voxels[std::size_t(k + 2)])}});
    }
    const std::array<int, 12> sheet = m_nodes.sheets();
    Dual_cell_seeds seeds;
    seed_doubled_edges(m_nodes, label, sheet, seeds);
    seed_pinched_labels(m_nodes, sheet, seeds, std::optional<Label>());
    if(seeds.conflict() || !place_points(sheet, seeds))
      return false;
    bool apart = true;
    for(const Bridge& bridge : m_points.bridges)
      apart = apart && bridge.points[0] != bridge.points[1];
    return apart && surfaces_closed(m_nodes, m_points) && make_boxes(m_nodes, m_points, margin, m_boxes);
  }

  // Where no split serves, one pinched label is left whole, its regions joined through the gap
  // that the other's ridge opens between its own: the first label that unties the seeds and
  // whose ridges close, the background (which has no surface of its own) before the others in
  // the block's order. False where none does.
  bool place_leaving_whole(const std::array<int, 12>& sheet, const Dual_cell_seeds& doubled, Label background)
  {
    for(const Label whole : m_nodes.block_labels_background_first(background))
    {
      Dual_cell_seeds fewer = doubled;
      seed_pinched_labels(m_nodes, sheet, fewer, std::optional<Label>(whole));
      if(!fewer.conflict() && place_points(sheet, fewer))
        return true;
    }
    return false;
  }

  // Every node takes a point: its seed's, the nearest seed's in its sheet (breadth first), or
  // its sheet's own; on a conflict, or where the ridges cannot be closed, one point per sheet.
  // Returns false where a split was wanted but not made.
  bool place_points(const std::array<int, 12>& sheet, const Dual_cell_seeds& seeds)
  {
    std::array<int, 12> point_of_node;
    const int count = seeds.points(point_of_node);
    const bool split = count > 0 && !seeds.conflict();
    if(split)
      spread_seeds(m_nodes, point_of_node);
    for(int v = 0; v < 12; ++v)
      if(!split || point_of_node[std::size_t(v)] == none)
        point_of_node[std::size_t(v)] = (split ? count : 0) + sheet[std::size_t(v)];
    m_points.number(m_nodes, point_of_node);
    if(split && !close_ridges(m_nodes, m_points))
    {
      m_points.one_per_sheet(m_nodes, sheet);
      return false;
    }
    return count == 0 || split;
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
    const Dual_cell_points<Label> points_before = m_points;
    const Dual_cell_boxes boxes_before = m_boxes;
    std::array<int, 12> own;
    for(int v = 0; v < 12; ++v)
      own[std::size_t(v)] = v;
    for(const Label ball : m_nodes.block_labels_background_first(background))
    {
      m_points.number(m_nodes, own);
      m_points.clear_caps();
      if(cap_against_ball(m_nodes, m_points, ball) && surfaces_closed(m_nodes, m_points) &&
         manifold_at_points(m_nodes, m_points, background) && make_boxes(m_nodes, m_points, margin, m_boxes))
        return;
    }
    m_points = points_before;
    m_boxes = boxes_before;
  }

  Dual_cell_nodes<Label> m_nodes;
  Dual_cell_points<Label> m_points;
  Dual_cell_boxes m_boxes;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_H
