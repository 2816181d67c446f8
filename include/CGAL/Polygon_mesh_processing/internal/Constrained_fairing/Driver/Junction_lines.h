// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The junction lines of a multi-label surface: its edges where three labels or more meet. A
// point on two junction edges is an inner point of its line, faired as a curve
// (Junction_curves.h); a point on one or on three junction edges or more (a line's end, a
// branch), or where four labels or more meet, stays where it is.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_JUNCTION_LINES_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_JUNCTION_LINES_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Interface_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The junction lines of a multi-label surface, from its sides (Interface_check.h): which points
// stay, and each inner point of a line with its two neighbours {p, i, n}.
struct Junction_lines
{
  std::vector<bool> fixed;
  std::vector<std::array<Index, 3> > inner;

  template <typename LabelPairRange>
  Junction_lines(std::size_t n, const std::vector<Interface_side>& sides, const LabelPairRange& face_labels)
    : fixed(n, false)
  {
    using Label = std::decay_t<decltype(face_labels[0][0])>;
    std::vector<std::vector<std::size_t> > neighbours(n);
    std::vector<std::vector<Label> > labels(n);
    for(std::size_t i = 0, j = 0; i < sides.size(); i = j)
    {
      std::vector<Label> around;
      while(j < sides.size() && sides[j].same_edge(sides[i]))
      {
        for(const Label l : face_labels[sides[j].face])
          around.push_back(l);
        ++j;
      }
      std::sort(around.begin(), around.end());
      around.erase(std::unique(around.begin(), around.end()), around.end());
      for(std::size_t v : {sides[i].a, sides[i].b})
        labels[v].insert(labels[v].end(), around.begin(), around.end());
      if(around.size() >= 3)
      {
        neighbours[sides[i].a].push_back(sides[i].b);
        neighbours[sides[i].b].push_back(sides[i].a);
      }
    }
    for(std::size_t v = 0; v < n; ++v)
    {
      std::sort(labels[v].begin(), labels[v].end());
      const std::size_t meeting = std::size_t(std::unique(labels[v].begin(), labels[v].end()) - labels[v].begin());
      const std::size_t degree = neighbours[v].size();
      fixed[v] = meeting >= 4 || (degree != 0 && degree != 2);
      if(degree == 2 && !fixed[v])
        inner.push_back({Index(neighbours[v][0]), Index(v), Index(neighbours[v][1])});
    }
  }
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_JUNCTION_LINES_H
