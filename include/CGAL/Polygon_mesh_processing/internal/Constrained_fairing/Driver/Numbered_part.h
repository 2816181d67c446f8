// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The points of an input numbered 0 to n - 1, a multi-label surface's or a point set's, as the
// driver, the value check and the bounds see them (the counterpart of Mesh_part.h for a mesh):
// every point takes part, its number is the key of the per-point maps.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NUMBERED_PART_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NUMBERED_PART_H

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// Point k is the key of the per-point maps and is named k in messages.
class Numbered_part
{
public:
  // No creases are detected: a multi-label surface's curves are its junction lines, a point set
  // has no edges (`feature_angle` is rejected, Value_check.h).
  static constexpr bool detects_creases = false;

  explicit Numbered_part(std::vector<bool> fixed) : m_fixed(std::move(fixed)) {}

  std::size_t size() const { return m_fixed.size(); }
  bool is_fixed(std::size_t k) const { return m_fixed[k]; }
  std::size_t number(std::size_t k) const { return k; }
  template <typename F>
  void for_each_vertex(const F& f) const
  {
    for(std::size_t k = 0; k < m_fixed.size(); ++k)
      f(k, k);
  }

private:
  std::vector<bool> m_fixed;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NUMBERED_PART_H
