// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A label map as the surface nets read it: its voxels in C order, the background outside them,
// and its dual cells, the cubes spanned by 8 neighbouring voxel centres.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_LABEL_GRID_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_LABEL_GRID_H

#include <array>
#include <cstddef>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

template <typename Label>
class Label_grid
{
public:
  using Signed = std::ptrdiff_t;

  // `first` is the index of voxel (0, 0, 0) in a larger map that the grid is a box of.
  Label_grid(const Label* labels, const std::array<std::size_t, 3>& size, Label background,
             const std::array<std::size_t, 3>& first = {0, 0, 0})
    : m_labels(labels), m_size(size), m_background(background), m_first(first)
  {
  }

  Label background() const { return m_background; }
  // The number of voxels along axis a.
  Signed voxels(int a) const { return Signed(m_size[std::size_t(a)]); }
  // Cell or voxel index c along axis a in the larger map.
  double in_map(Signed c, int a) const { return double(c + Signed(m_first[std::size_t(a)])); }
  // Voxel (i, j, k), or the background outside the map.
  Label label(Signed i, Signed j, Signed k) const
  {
    if(i < 0 || j < 0 || k < 0 || i >= voxels(0) || j >= voxels(1) || k >= voxels(2))
      return m_background;
    return m_labels[(std::size_t(i) * m_size[1] + std::size_t(j)) * m_size[2] + std::size_t(k)];
  }

  // Dual cell c = (ci, cj, ck), each in [0, n], lies between voxels c - 1 and c on each axis.
  std::size_t cell_count() const { return (m_size[0] + 1) * (m_size[1] + 1) * (m_size[2] + 1); }
  std::size_t cell_index(const Signed c[3]) const
  {
    return (std::size_t(c[0]) * (m_size[1] + 1) + std::size_t(c[1])) * (m_size[2] + 1) + std::size_t(c[2]);
  }
  // Whether the 8 voxels around dual cell c have one label (the cell then has no point).
  bool uniform(const Signed c[3]) const
  {
    const Label l = label(c[0], c[1], c[2]);
    bool uniform = true;
    for(int o = 1; o < 8 && uniform; ++o)
      uniform = label(c[0] - (o & 1), c[1] - ((o >> 1) & 1), c[2] - ((o >> 2) & 1)) == l;
    return uniform;
  }

private:
  const Label* m_labels;
  std::array<std::size_t, 3> m_size;
  Label m_background;
  std::array<std::size_t, 3> m_first;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_LABEL_GRID_H
