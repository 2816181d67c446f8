// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The points of a label map's surface nets, made cell by cell in the order of the cells, each
// at the centre of its box (Dual_cell.h), and what the triangles need of the cells of several
// points: the point of each face's corner, the caps of their ridges and their bridges.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NET_POINTS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NET_POINTS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Dual_cell.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Label_grid.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// Point v of a soup, as the predicates of the nets take it.
template <typename PointRange>
Exact_predicates_inexact_constructions_kernel::Point_3 net_point(const PointRange& points, std::size_t v)
{
  using Point_3 = Exact_predicates_inexact_constructions_kernel::Point_3;
  return Point_3(CGAL::to_double(points[v][0]), CGAL::to_double(points[v][1]), CGAL::to_double(points[v][2]));
}

template <typename Label>
class Net_points
{
public:
  using Signed = std::ptrdiff_t;
  using Cell = Dual_cell<Label>;
  // The point of each face's corner at a cell of several points, relative to its first: 2 f + 0
  // next to face f's dual edge along axis (f / 4 + 1) % 3, 2 f + 1 next to the other.
  using Corners = std::array<std::int8_t, 24>;
  // A cap of a cell's ridge, its points indices into the soup's.
  struct Cap
  {
    std::array<std::size_t, 3> points;
    std::array<Label, 2> labels;
  };
  // A bridge (Dual_cell.h) and its cell.
  using Cell_bridge = std::pair<std::array<Signed, 3>, typename Cell::Bridge>;

  // Appends the points of the cells of `grid` to `points` and their boxes to `half_extents`.
  template <typename PointRange, typename BoxRange>
  Net_points(const Label_grid<Label>& grid, const std::array<double, 3>& spacing, const std::array<double, 3>& origin,
             double margin, PointRange& points, BoxRange& half_extents)
    : m_first(points.size()), m_first_point(grid.cell_count(), none)
  {
    std::size_t index = 0;
    Signed c[3];
    for(c[0] = 0; c[0] <= grid.voxels(0); ++c[0])
      for(c[1] = 0; c[1] <= grid.voxels(1); ++c[1])
        for(c[2] = 0; c[2] <= grid.voxels(2); ++c[2], ++index)
          if(!grid.uniform(c))
            add_cell(grid, c, index, spacing, origin, margin, points, half_extents);
  }

  // The first point of cell `index` (not uniform), an index into the soup's points.
  std::size_t first_point(std::size_t index) const { return m_first + m_first_point[index]; }
  // The corners of cell `index`; null for a cell of one point.
  const Corners* corners(std::size_t index) const
  {
    const auto found = std::lower_bound(m_split.begin(), m_split.end(), index,
                                        [](const auto& x, std::size_t i) { return x.first < i; });
    return found != m_split.end() && found->first == index ? &found->second : nullptr;
  }
  const std::vector<Cap>& caps() const { return m_caps; }
  // In the order of their cells.
  const std::vector<Cell_bridge>& bridges() const { return m_bridges; }
  // Whether each point, counted from the first made, is one of a cell of several points.
  const std::vector<bool>& of_split_cell() const { return m_of_split_cell; }

private:
  static constexpr std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();

  // The cell after one along a split ring's axis leaves that ring whole, so that the bridge ends
  // at its point.
  Cell cell_at(const Label_grid<Label>& grid, const Signed c[3], double margin) const
  {
    unsigned unsplit = 0;
    for(int a = 0; a < 3; ++a)
      if(c[a] > 0)
      {
        std::array<Signed, 3> before = {c[0], c[1], c[2]};
        --before[std::size_t(a)];
        for(auto b = std::lower_bound(m_bridges.begin(), m_bridges.end(), before,
                                      [](const auto& x, const std::array<Signed, 3>& at) { return x.first < at; });
            b != m_bridges.end() && b->first == before; ++b)
          if(b->second.axis == a && b->second.side == 1)
            unsplit |= 1u << (2 * a);
      }
    return Cell([&](int d0, int d1, int d2) { return grid.label(c[0] - 1 + d0, c[1] - 1 + d1, c[2] - 1 + d2); },
                grid.background(), margin, unsplit);
  }

  template <typename PointRange, typename BoxRange>
  void add_cell(const Label_grid<Label>& grid, const Signed c[3], std::size_t index, const std::array<double, 3>& spacing,
                const std::array<double, 3>& origin, double margin, PointRange& points, BoxRange& half_extents)
  {
    using Point = typename PointRange::value_type;
    const Cell dual = cell_at(grid, c, margin);
    m_first_point[index] = static_cast<std::uint32_t>(points.size() - m_first);
    if(dual.size() > 1)
    {
      m_split.emplace_back(index, Corners{});
      for(int f = 0; f < 12; ++f)
        for(int side = 0; side < 2; ++side)
          m_split.back().second[std::size_t(2 * f + side)] = std::int8_t(dual.point(f, (f / 4 + 1 + side) % 3));
      for(const auto& cap : dual.caps())
      {
        m_caps.push_back({{}, cap.labels});
        for(std::size_t k = 0; k < 3; ++k)
          m_caps.back().points[k] = first_point(index) + std::size_t(cap.points[k]);
      }
      for(const auto& bridge : dual.bridges())
        m_bridges.push_back({{c[0], c[1], c[2]}, bridge});
    }
    for(int s = 0; s < dual.size(); ++s)
    {
      double centre[3];
      std::array<double, 3> half;
      for(int a = 0; a < 3; ++a)
      {
        const double lo = dual.low(s, a), hi = dual.high(s, a);
        centre[a] = origin[std::size_t(a)] + (grid.in_map(c[a], a) - 0.5 + 0.5 * (lo + hi)) * spacing[std::size_t(a)];
        half[std::size_t(a)] = 0.5 * (hi - lo) * spacing[std::size_t(a)];
      }
      points.push_back(Point(centre[0], centre[1], centre[2]));
      half_extents.push_back(half);
      m_of_split_cell.push_back(dual.size() > 1);
    }
  }

  std::size_t m_first;
  std::vector<std::uint32_t> m_first_point;
  std::vector<std::pair<std::size_t, Corners> > m_split; // in the order of the cells
  std::vector<Cap> m_caps;
  std::vector<Cell_bridge> m_bridges;
  std::vector<bool> m_of_split_cell;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NET_POINTS_H
