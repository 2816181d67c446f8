// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PMP_LABEL_SURFACE_NETS_H
#define CGAL_PMP_LABEL_SURFACE_NETS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Label_grid.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Lined_up_points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Net_points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Net_triangles.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Net_untangling.h>

#include <CGAL/assertions.h>

#include <array>
#include <cstddef>

namespace CGAL {
namespace Polygon_mesh_processing {

/*!
\ingroup PkgConstrainedFairingRef

The margin, as a fraction of the voxel spacing, that `label_surface_nets()` keeps between a point's
box and the sides of its dual cell: the boxes of two points are at least twice this apart, so
that no two points of a faired label map meet.
*/
constexpr double label_box_margin = 0.01;

/*!
\ingroup PkgConstrainedFairingRef

\brief extracts the interfaces between the labels of a 3-D label map as one triangle soup:
multi-label surface nets, each point with the box the fairing keeps it in.

`labels` holds `size[0] * size[1] * size[2]` voxels in C order: voxel `(i, j, k)` is
`labels[(i * size[1] + j) * size[2] + k]` (a C-contiguous numpy array `labels[i, j, k]`), and its
centre is at `origin + (i, j, k) * spacing`, coordinates in the array's axis order. Voxels
outside the array count as `background`.

- The dual cells are the cubes spanned by 8 neighbouring voxel centres. For each pair of
  neighbouring voxels `a`, `b` with different labels, two triangles (the quad of the four dual
  cells around their shared face) are added, with `face_labels` `{label(a), label(b)}`: their
  normal points from `a`'s region into `b`'s. The interface between two labels is so made of the
  same triangles for both, and a label's surface, the triangles that name it, is closed.
  Triangles against `background` are made too: `background` is the outside of the surfaces and
  gets none of its own.
- A dual cell whose voxels do not all have the same label gets a point at its centre, whose box
  is the cell shrunk by `margin * spacing` on every side. Where a label's voxels meet only along
  an edge or at a corner, the cell gets one point per sheet of the surface instead, each with a
  box in the part of the cell its triangles occupy (a half or, where the triangles of two points
  lie in one octant, a quarter of the cell along an axis), also `margin * spacing` from the
  planes that cut the cell there, and at its centre: the voxels of the two diagonals around an
  edge are never both joined; of two labels that alternate around an edge, the one whose voxels
  are joined around it anyway is, else the smaller label. Where a junction would pinch a label
  or two sheets would share an edge, a sheet gets several points on a ridge; the holes the ridge
  leaves in the interfaces are capped by triangles of the cell's points, around one more point
  in a free octant of the cell where they border several interfaces. Where two labels each touch
  themselves at the centre with others around, an edge of four labels next to the centre gets
  two points at the cell, one for the faces around each of two opposite voxels, and the other two
  labels meet between them across a triangle of those points and the next cell's point along the
  edge. Where none of these serves (four labels each on two opposite voxels of a cell, say; none
  in Debian's atlases), the cell gets a point on each edge around its centre (two where an
  edge's faces pair up) and a small ball of one label there, the holes of the other labels
  capped against it. So every label's surface is a manifold (made by `label_surface()` without
  splitting): none split on Debian's atlases or on 600 maps of random voxels of 3 to 6 labels.
  No two boxes meet: the points stay apart through any fairing within their boxes.
- Points of cells of several points, at the centres of their boxes, can fold a triangle onto its
  neighbour or through another: the points of such triangles, of any cell, move to the mean of
  their neighbours (with the points around them after the first round), within seven eighths
  of their boxes, for a few rounds while some cross; then those of the triangles still crossing,
  one at a time, each to the position of a grid over that part of its box that leaves the
  fewest crossings, and of those the least sharp triangles (up to a 6-degree needle), then the
  nearest, never adding a crossing. Each moved point's box shrinks to the largest one around it
  within the one it had (up to rounding). The triangles pass through each other only where
  that fails: none on Debian's atlases, 2 of 100 maps of 14^3 random voxels of 3 to 6 labels.
- A face whose corners hold several points is cut into triangles by diagonals between opposite
  cells where it can be, else, for the rest, the way whose triangles turn least from its normal,
  never into a triangle or a diagonal another face has.

Points are numbered in the order of their cells, `(i, j, k)` with `k` fastest, and within a
cell by their first triangle, the cap-only points last.

The boxes, `box_half_extents[p]` around `points[p]`, are those that
`constrained_fairing_of_interfaces()` takes as `vertex_box_half_extents_map`. The choice is
made from the labels alone: the same map gives the same soup whatever is done with it after.

\tparam Label an integer type
\tparam PointRange a `std::vector` of a point type constructible from three `double`
\tparam TriangleRange a `std::vector` of `std::array<I, 3>`, `I` an integer type
\tparam LabelPairRange a `std::vector` of `std::array<Label, 2>`
\tparam BoxRange a `std::vector` of `std::array<double, 3>`

\param labels the label map, `size[0] * size[1] * size[2]` values in C order
\param size the number of voxels along each axis
\param spacing the distance between voxel centres along each axis
\param origin the centre of voxel `(0, 0, 0)`, or with `first_voxel` that of the larger map
\param points the points, appended to
\param triangles the triangles, as indices into `points` counted from its size on entry
\param face_labels the two labels of each triangle, one per triangle
\param box_half_extents the half-extents of each point's box, one per point, appended to
\param background the label of the outside, which gets no surface of its own
\param margin the margin of the boxes, a fraction of the spacing in `[0, 0.125)`
\param first_voxel where `labels` is a box of a larger map (a chunk of a volume too large to be
       read whole), the index in that map of its voxel `(0, 0, 0)`: the points are placed as the
       larger map's nets place them, bit for bit, so that the cells of two chunks that read
       enough voxels around them get the same points (the voxels outside `labels` still count as
       `background`)

\pre `0 <= margin < 0.125`
*/
template <typename Label, typename PointRange, typename TriangleRange, typename LabelPairRange, typename BoxRange>
void label_surface_nets(const Label* labels, const std::array<std::size_t, 3>& size,
                        const std::array<double, 3>& spacing, const std::array<double, 3>& origin,
                        PointRange& points, TriangleRange& triangles, LabelPairRange& face_labels,
                        BoxRange& box_half_extents, const Label background = Label(0),
                        const double margin = label_box_margin,
                        const std::array<std::size_t, 3>& first_voxel = {0, 0, 0})
{
  namespace Cf = internal::Constrained_fairing;
  CGAL_precondition(margin >= 0 && margin < 0.125);
  const Cf::Label_grid<Label> grid(labels, size, background, first_voxel);
  const std::size_t first = points.size(), first_triangle = triangles.size(), first_box = box_half_extents.size();
  const Cf::Net_points<Label> net(grid, spacing, origin, margin, points, box_half_extents);
  Cf::make_net_triangles(grid, net, points, triangles, face_labels);
  Cf::move_lined_up_points(points, triangles, box_half_extents, first, first_triangle, first_box);
  Cf::untangle_nets(points, triangles, box_half_extents, first, first_triangle, first_box, net.of_split_cell());
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_LABEL_SURFACE_NETS_H
