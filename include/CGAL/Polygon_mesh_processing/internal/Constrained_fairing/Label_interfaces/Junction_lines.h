// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The junction lines of a multi-label surface: its edges where three labels or more meet. A
// point on two junction edges is an inner point of its line, faired as a curve
// (Curve_bending.h); a point on one or on three junction edges or more (a line's end, a
// branch), or where four labels or more meet, ends its line (Curve_network.h) and stays where
// it is (Interface_input.h).

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_JUNCTION_LINES_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_JUNCTION_LINES_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_interfaces/Interface_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Curve_network.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The junction lines of a multi-label surface, from its sides (Interface_check.h): their
// curves, where a point where four labels or more meet ends its line too.
template <typename LabelPairRange>
Curve_network junction_lines(std::size_t n, const std::vector<Interface_side>& sides, const LabelPairRange& face_labels)
{
  using Label = std::decay_t<decltype(face_labels[0][0])>;
  std::vector<std::array<Index, 2> > edges;
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
      edges.push_back({Index(sides[i].a), Index(sides[i].b)});
  }
  return Curve_network(n, edges, [&labels](std::size_t v) {
    std::sort(labels[v].begin(), labels[v].end());
    return std::unique(labels[v].begin(), labels[v].end()) - labels[v].begin() >= 4;
  });
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_JUNCTION_LINES_H
