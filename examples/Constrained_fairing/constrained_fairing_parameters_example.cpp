// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The named parameters of constrained_fairing(): the paper's box bound, an iteration cap, a
// progress callback, and the paper's Newton method with a sparse solver of one's choice.
// Fails unless each bound holds, the cap is kept and the bending energy went down.
//
//   constrained_fairing_parameters_example [IN] [EPS]

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#ifdef CGAL_CONSTRAINED_FAIRING_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polyhedron = CGAL::Polyhedron_3<K>;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;

// The bending energy before and after, and the objective minimized, which adds a barrier
// against slivers, when it differs.
std::string energies(const PMP::Constrained_fairing_result& r)
{
  std::ostringstream text;
  text << "bending energy " << r.initial_bending_energy << " -> " << r.final_bending_energy;
  if(r.initial_energy != r.initial_bending_energy || r.final_energy != r.final_bending_energy)
    text << ", objective " << r.initial_energy << " -> " << r.final_energy;
  return text.str();
}

int main(int argc, char* argv[])
{
  const std::string in = argc > 1 ? argv[1] : CGAL_CONSTRAINED_FAIRING_DATA_DIR "/elephant_noisy.off";
  const double epsilon = argc > 2 ? std::stod(argv[2]) : 0.0055;

  Polyhedron mesh;
  if(!CGAL::IO::read_polygon_mesh(in, mesh))
  {
    std::cerr << "error: cannot read a polygon mesh from " << in << std::endl;
    return EXIT_FAILURE;
  }

  // Our own parameters start the pack; CGAL's chain after them as members.
  auto report = [](std::size_t iteration, double energy) {
    std::cout << "  iteration " << iteration << ": energy " << energy << std::endl;
    return true; // false would stop here and keep this iterate
  };
  Polyhedron box_mesh = mesh;
  /// [chaining]
  const auto box = PMP::constrained_fairing(
    box_mesh, epsilon,
    CFP::iteration_callback(report, CFP::deviation_bound(PMP::Deviation_bound::BOX)
                                      .number_of_iterations(30)
                                      .vertex_point_map(get(CGAL::vertex_point, box_mesh))));
  /// [chaining]
  if(!box)
  {
    std::cerr << "error: " << box.message << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "box of side 2 eps: " << energies(box) << ", max |p - p0| " << box.max_deviation << std::endl;

  // Or append CGAL's pack to one of ours: here the paper's Newton method, with a sparse solver
  // of one's choice to factorize its Hessian model.
#ifdef CGAL_CONSTRAINED_FAIRING_HAS_CHOLMOD
  using Solver = CGAL::Eigen_solver_traits<Eigen::CholmodSupernodalLLT<CGAL::Eigen_sparse_matrix<double>::EigenType> >;
#else
  using Solver = CGAL::Eigen_solver_traits<Eigen::SimplicialLLT<CGAL::Eigen_sparse_matrix<double>::EigenType> >;
#endif
  const auto ball = PMP::constrained_fairing(
    mesh, epsilon,
    CFP::fairing_method(PMP::Constrained_fairing_method::ACTIVE_SET_NEWTON,
                        CGAL::parameters::sparse_linear_solver(Solver())));
  if(!ball)
  {
    std::cerr << "error: " << ball.message << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "ball of radius eps: " << energies(ball) << " in " << ball.number_of_iterations
            << " iterations, max |p - p0| " << ball.max_deviation << std::endl;
  // The box's corners lie sqrt(3) eps away (up to rounding); the cap was 30 iterations.
  if(!(box.max_deviation <= std::sqrt(3.) * epsilon * (1 + 1e-12) && box.number_of_iterations <= 30 &&
       box.final_bending_energy < box.initial_bending_energy && ball.max_deviation <= epsilon &&
       ball.final_bending_energy < ball.initial_bending_energy))
  {
    std::cerr << "error: a bound, the iteration cap or the decrease of the bending energy does not hold" << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
