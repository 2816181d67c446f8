// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PMP_LABEL_SURFACE_NETS_H
#define CGAL_PMP_LABEL_SURFACE_NETS_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

/*!
\ingroup PkgConstrainedFairingRef

\brief extracts the interfaces between the labels of a 3-D label map as one triangle soup:
multi-label surface nets.

`labels` holds `size[0] * size[1] * size[2]` voxels in C order: voxel `(i, j, k)` is
`labels[(i * size[1] + j) * size[2] + k]` (a C-contiguous numpy array `labels[i, j, k]`), and its
centre is at `origin + (i, j, k) * spacing`, coordinates in the array's axis order. Voxels
outside the array count as `background`.

- A point is put at the centre of each dual cell (the cube spanned by 8 neighbouring voxel
  centres) whose voxels do not all have the same label. Each point stays in its dual cell, a box
  of half-extents `spacing / 2` around it: the bound that `constrained_fairing()`'s
  `box_half_extents` and the fairing of interfaces use. Points are numbered in the order of
  their cells, `(i, j, k)` with `k` fastest.
- For each pair of neighbouring voxels `a`, `b` with different labels, two triangles (the quad
  of the four dual cells around their shared face) are added, with `face_labels` `{label(a),
  label(b)}`: their normal points from `a`'s region into `b`'s. The interface between two
  labels is so made of the same triangles for both, and a label's surface, the triangles that
  name it, is closed. Triangles against `background` are made too: `background` is the outside
  of the surfaces and gets none of its own.

A label's surface may touch itself along an edge or at a point where its voxels touch only
along an edge or at a corner: `label_surface()` splits it there.

\tparam Label an integer type
\tparam PointRange a `std::vector` of a point type constructible from three `double`
\tparam TriangleRange a `std::vector` of `std::array<I, 3>`, `I` an integer type
\tparam LabelPairRange a `std::vector` of `std::array<Label, 2>`

\param labels the label map, `size[0] * size[1] * size[2]` values in C order
\param size the number of voxels along each axis
\param spacing the distance between voxel centres along each axis
\param origin the centre of voxel `(0, 0, 0)`
\param points the points, appended to
\param triangles the triangles, as indices into `points` counted from its size on entry
\param face_labels the two labels of each triangle, one per triangle
\param background the label of the outside, which gets no surface of its own
*/
template <typename Label, typename PointRange, typename TriangleRange, typename LabelPairRange>
void label_surface_nets(const Label* labels, const std::array<std::size_t, 3>& size,
                        const std::array<double, 3>& spacing, const std::array<double, 3>& origin,
                        PointRange& points, TriangleRange& triangles, LabelPairRange& face_labels,
                        const Label background = Label(0))
{
  using Point = typename PointRange::value_type;
  using Point_index = typename TriangleRange::value_type::value_type;
  using Signed = std::ptrdiff_t;
  const Signed n[3] = {Signed(size[0]), Signed(size[1]), Signed(size[2])};
  const auto label = [&](Signed i, Signed j, Signed k) {
    if(i < 0 || j < 0 || k < 0 || i >= n[0] || j >= n[1] || k >= n[2])
      return background;
    return labels[(std::size_t(i) * size[1] + std::size_t(j)) * size[2] + std::size_t(k)];
  };
  // Dual cell c = (ci, cj, ck), each in [0, n], lies between voxels c - 1 and c on each axis.
  const std::size_t cells[3] = {size[0] + 1, size[1] + 1, size[2] + 1};
  const auto cell_index = [&](const Signed c[3]) {
    return (std::size_t(c[0]) * cells[1] + std::size_t(c[1])) * cells[2] + std::size_t(c[2]);
  };

  // f(a, b, quad) for each pair of neighbouring voxels a, b = a + e_axis with different labels,
  // quad the four dual cells around their face, counterclockwise seen from b: the triangles
  // (quad[0], quad[1], quad[2]) and (quad[0], quad[2], quad[3]) point from a into b.
  const auto for_each_face = [&](const auto& f) {
    for(int axis = 0; axis < 3; ++axis)
    {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3; // (axis, u, w) is right-handed
      Signed lo[3] = {0, 0, 0};
      lo[axis] = -1;
      Signed a[3];
      for(a[0] = lo[0]; a[0] < n[0]; ++a[0])
        for(a[1] = lo[1]; a[1] < n[1]; ++a[1])
          for(a[2] = lo[2]; a[2] < n[2]; ++a[2])
          {
            Signed b[3] = {a[0], a[1], a[2]};
            ++b[axis];
            const Label la = label(a[0], a[1], a[2]), lb = label(b[0], b[1], b[2]);
            if(la == lb)
              continue;
            std::array<std::size_t, 4> quad;
            const int du[4] = {0, 1, 1, 0}, dw[4] = {0, 0, 1, 1};
            for(int c = 0; c < 4; ++c)
            {
              Signed cell[3];
              cell[axis] = b[axis];
              cell[u] = a[u] + du[c];
              cell[w] = a[w] + dw[c];
              quad[std::size_t(c)] = cell_index(cell);
            }
            f(la, lb, quad);
          }
    }
  };

  // The cells that get a point, numbered in their order.
  constexpr std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();
  std::vector<std::uint32_t> point_of_cell(cells[0] * cells[1] * cells[2], none);
  for_each_face([&](Label, Label, const std::array<std::size_t, 4>& quad) {
    for(std::size_t cell : quad)
      point_of_cell[cell] = 0;
  });
  const std::size_t first = points.size();
  std::size_t cell = 0;
  for(std::size_t ci = 0; ci < cells[0]; ++ci)
    for(std::size_t cj = 0; cj < cells[1]; ++cj)
      for(std::size_t ck = 0; ck < cells[2]; ++ck, ++cell)
        if(point_of_cell[cell] != none)
        {
          point_of_cell[cell] = static_cast<std::uint32_t>(points.size() - first);
          points.push_back(Point(origin[0] + (double(ci) - 0.5) * spacing[0],
                                 origin[1] + (double(cj) - 0.5) * spacing[1],
                                 origin[2] + (double(ck) - 0.5) * spacing[2]));
        }
  for_each_face([&](Label la, Label lb, const std::array<std::size_t, 4>& quad) {
    std::array<std::size_t, 4> p;
    for(int c = 0; c < 4; ++c)
      p[std::size_t(c)] = first + point_of_cell[quad[std::size_t(c)]];
    triangles.push_back({Point_index(p[0]), Point_index(p[1]), Point_index(p[2])});
    triangles.push_back({Point_index(p[0]), Point_index(p[2]), Point_index(p[3])});
    face_labels.push_back({la, lb});
    face_labels.push_back({la, lb});
  });
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_LABEL_SURFACE_NETS_H
