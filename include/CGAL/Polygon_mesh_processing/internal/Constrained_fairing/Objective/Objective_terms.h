// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a term of the objective is, whichever input kind gives it (Fairing_objective.h adds the
// terms to the bending energy in the order they are given, and holds them by reference):
//  - an Objective_term is a sum over points: a mesh's creases and a multi-label surface's
//    junction lines (Curve_bending.h), the accurate objective's fidelity (Fidelity_term.h), the
//    bending energy of an operator form for an input without hinges (Operator_bending.h);
//  - a Triangle_term is a sum over the bending energy's triangles, whose gradient the energy's
//    tiles add where each triangle's points are at hand (Bending_energy.h), which saves a pass
//    over the triangles: a multi-label surface's volumes (Label_volumes.h).

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_OBJECTIVE_TERMS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_OBJECTIVE_TERMS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Stiffness_and_reach.h>

#include <Eigen/Core>

#include <array>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Objective_term
{
public:
  virtual ~Objective_term() = default;

  virtual double value(const Points& X) = 0;

  // The value at X; adds the gradient to G and, with `scales`, the diagonal of the term's
  // Gauss-Newton model to the stiffness (Stiffness_and_reach.h).
  virtual double add_gradient(const Points& X, Points& G, Stiffness_and_reach* scales) = 0;

  // Whether the term is the input's bending energy, which the result reports as such: an input
  // without hinges has it as a term.
  virtual bool is_bending() const { return false; }
};

class Triangle_term : public Objective_term
{
public:
  using Objective_term::add_gradient;

  // The value at X, and what the triangles' gradients below need at X, until the next call.
  virtual double prepare_gradient(const Points& X) = 0;

  // Adds triangle f's part of the gradient at its corners k of bit k in `corners`, with respect
  // to its points p at unit scale (Points.h); v are its vertices.
  virtual void add_gradient(Index f, const std::array<Index, 3>& v, const std::array<Eigen::Vector3d, 3>& p,
                            unsigned corners, Points& G) const = 0;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_OBJECTIVE_TERMS_H
