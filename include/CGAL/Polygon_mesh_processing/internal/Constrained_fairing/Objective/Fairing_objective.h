// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The function the solvers minimize: the bending energy of the hinges (Bending_energy.h) with
// the barrier against slivers (Sliver_barrier.h) and, if given, against folds (Fold_barrier.h),
// for an input with triangles; plus the terms the input and the driver give, in that order
// (Objective_terms.h): a mesh's creases, a multi-label surface's junction lines and volumes, the
// accurate objective's fidelity; an input without hinges gives its bending as a term
// (Operator_bending.h). The sum is taken in the same order by value() and value_and_gradient(),
// but for the terms over triangles: their values come first in value_and_gradient(), which
// makes their gradients ready before the bending energy's tiles add them.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_OBJECTIVE_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_OBJECTIVE_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Bending_energy.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fold_barrier.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Objective_terms.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Sliver_barrier.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Stiffness_and_reach.h>

#include <CGAL/assertions.h>

#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Fairing_objective
{
public:
  // The hinges' bending energy and the barrier against slivers: `sliver_weight` its weight, 0
  // for none; `sliver_threshold` the quality under which a triangle is a sliver.
  Fairing_objective(const Hinge_mesh& mesh, const Points& X0, double sliver_weight, double sliver_threshold)
    : m_hinges(std::in_place, mesh, X0, sliver_weight, sliver_threshold)
  {}

  // No hinges: the terms alone, one of which is the bending energy.
  Fairing_objective() = default;

  // Adds a term (kept by reference) after those already given.
  void add_term(Objective_term& term) { m_terms.push_back({&term, nullptr}); }
  void add_term(Triangle_term& term)
  {
    CGAL_precondition(m_hinges.has_value());
    m_terms.push_back({&term, &term});
    m_triangle_terms.push_back(&term);
  }

  // Adds the barrier against folds of the hinges.
  void add_fold_barrier(const Fold_barrier& folds)
  {
    CGAL_precondition(m_hinges.has_value());
    m_hinges->folds = folds;
  }

  std::size_t number_of_degenerate_hinges() const
  {
    return m_hinges ? m_hinges->bending.number_of_degenerate_hinges() : 0;
  }

  // The input's bending energy alone, the paper's measure of fairness.
  double bending_energy(const Points& X)
  {
    double sum = m_hinges ? m_hinges->bending.value(X) : 0;
    for(const Term& t : m_terms)
      if(t.term->is_bending())
        sum += t.term->value(X);
    return sum;
  }

  double value(const Points& X)
  {
    double sum = m_hinges ? m_hinges->bending.value(X, In_tiles{m_hinges->barrier, m_triangle_terms}, m_hinges->folds)
                          : 0;
    for(const Term& t : m_terms)
      sum += t.term->value(X);
    return sum;
  }

  // As Bending_energy::value_and_gradient(), with each term's gradient and stiffness added.
  double value_and_gradient(const Points& X, Points& G, Stiffness_and_reach* scales = nullptr)
  {
    double sum = 0;
    for(Triangle_term* t : m_triangle_terms)
      sum += t->prepare_gradient(X);
    if(m_hinges)
      sum += m_hinges->bending.value_and_gradient(X, G, scales, In_tiles{m_hinges->barrier, m_triangle_terms},
                                                  m_hinges->folds);
    else
      without_hinges(X, G, scales);
    for(const Term& t : m_terms)
      if(!t.triangle)
        sum += t.term->add_gradient(X, G, scales);
    return sum;
  }

private:
  struct Term
  {
    Objective_term* term;
    Triangle_term* triangle; // the same term if it is over triangles, else null
  };

  // The terms evaluated in the bending energy's tiles (Bending_energy.h): the barrier's, and the
  // gradients of the terms over triangles, made ready by their prepare_gradient().
  struct In_tiles
  {
    static constexpr bool active = true;
    const Sliver_barrier& barrier;
    const std::vector<Triangle_term*>& terms;

    double value(Index f, const std::array<Eigen::Vector3d, 3>& p) const { return barrier.value(f, p); }

    double add_gradient(Index f, const std::array<Index, 3>& v, const std::array<Eigen::Vector3d, 3>& p,
                        unsigned corners, Points& G, Stiffness_and_reach* scales) const
    {
      for(const Triangle_term* t : terms)
        t->add_gradient(f, v, p, corners, G);
      return barrier.add_gradient(f, v, p, corners, G, scales);
    }
  };

  struct Hinge_terms
  {
    Hinge_terms(const Hinge_mesh& mesh, const Points& X0, double sliver_weight, double sliver_threshold)
      : bending(mesh, X0), barrier(mesh, X0, sliver_weight, sliver_threshold)
    {}

    Bending_energy bending;
    Sliver_barrier barrier;
    Fold_barrier folds; // none unless given
  };

  // What the hinges' energy sets before the terms add to it: a zero gradient, no stiffness,
  // and no triangle to flip.
  static void without_hinges(const Points& X, Points& G, Stiffness_and_reach* scales)
  {
    G = Points::Zero(X.rows(), 3);
    if(scales)
    {
      scales->stiffness = Eigen::VectorXd::Zero(X.rows());
      scales->reach = Eigen::VectorXd::Constant(X.rows(), std::numeric_limits<double>::infinity());
    }
  }

  std::optional<Hinge_terms> m_hinges; // none for an input without hinges
  std::vector<Term> m_terms;
  std::vector<Triangle_term*> m_triangle_terms;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_OBJECTIVE_H
