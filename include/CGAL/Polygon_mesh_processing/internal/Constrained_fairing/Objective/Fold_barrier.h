// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A barrier against folds, added to the objective of a multi-label surface: with
// C = |n1 - n2|^2 / 2 = 1 - cos(theta) for the unit normals of a hinge's two triangles (theta
// the angle between them, 0 when flat),
//
//   P = nu * sum over the hinges with C > C0 of (C - C0)^2,
//
// C0 = 1 - cos(theta0), theta0 the angle from which a hinge pays (Fairing_settings.h), nu the
// weight. Why: the bending energy's hinge costs at most 3 |e|^2 / (2 A_e) however far it turns,
// so where the junction lines, the volumes and the boxes pull, a triangle turns over against its
// neighbours at no great cost. On Debian's atlases 5 to 740 triangles ended turned over, most with
// a point on a junction line, after the fold repair's re-seed and second descent had undone a
// fifth of them; with P, the descent ends with none on seven of the nine and no second descent there
// (doc/design_notes.md, "A barrier against folds on label surfaces"). P leaves every hinge turned
// less than theta0 alone, so it changes no smooth part of the surface; like the bending energy it
// is dimensionless and counts per hinge.
//
// Evaluation: a hinge's term depends on its C only, so the bending energy adds it in its tiles,
// where C is at hand (Bending_energy.h), to its value, to dE/dC, and to the weight of the hinge's
// normals in the stiffness that scales the quasi-Newton steps. Written as r^2 with
// r = sqrt(nu) (C - C0), its Gauss-Newton model is 2 nu (dC)^2, dC = <n1 - n2, dn1 - dn2>, at
// most 2 nu |n1 - n2|^2 |dn1 - dn2|^2, where the bending energy's w_h^2 |n1 - n2|^2 gives
// 2 w_h^2 |dn1 - dn2|^2: the hinge's weight w_h^2 gains nu |n1 - n2|^2 = 2 nu C. Left out, the
// steps overshot where the barrier holds stiff hinges: a round of fold repair on random voxels
// of 5 labels took 726 evaluations for its 100 iterations, against 101 with it.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FOLD_BARRIER_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FOLD_BARRIER_H

#include <CGAL/number_type_config.h>

#include <cmath>
#include <limits>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Fold_barrier
{
public:
  // No barrier: no hinge pays.
  Fold_barrier() = default;

  // Hinges turned more than `degrees` pay, with weight `weight` (none if it is 0).
  Fold_barrier(double weight, double degrees)
    : m_weight(weight),
      m_threshold(weight > 0 ? 1 - std::cos(degrees * CGAL_PI / 180) : std::numeric_limits<double>::infinity())
  {}

  // The term of a hinge of C = |n1 - n2|^2 / 2, and its derivative with respect to C.
  double value(double C) const
  {
    const double over = C - m_threshold;
    return over > 0 ? m_weight * over * over : 0;
  }
  double derivative(double C) const
  {
    const double over = C - m_threshold;
    return over > 0 ? 2 * m_weight * over : 0;
  }
  // What it adds to the hinge's weight w_h^2 in the stiffness (see above).
  double stiffness_weight(double C) const { return C > m_threshold ? 2 * m_weight * C : 0; }

private:
  double m_weight = 0;
  double m_threshold = std::numeric_limits<double>::infinity();
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FOLD_BARRIER_H
