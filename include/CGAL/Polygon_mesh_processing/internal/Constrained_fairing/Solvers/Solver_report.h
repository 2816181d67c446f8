// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a solver answers, which the driver turns into the public result once.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SOLVER_REPORT_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SOLVER_REPORT_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>

#include <cstddef>
#include <string>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

struct Solver_report
{
  Constrained_fairing_status status = Constrained_fairing_status::ITERATION_LIMIT_REACHED;
  std::string message;
  std::size_t iterations = 0;
  std::size_t cg_iterations = 0;
  std::size_t energy_evaluations = 0;
  double final_energy = 0;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SOLVER_REPORT_H
