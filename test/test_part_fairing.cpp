// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The driver's phases called apart (Fairing_driver.h, Fairing_problem.h): a mesh prepared once
// and faired as 2 and 8 parts, each with its halo frozen, 10 iterations a part, in sweeps until
// no vertex moves 1 % of eps in one, reaches the surface of the whole call (its energy to 1 %,
// its surface to 1 % of eps RMS), with the default and the accurate objective, the bound
// holding exactly in double and the energy never rising from sweep to sweep; a part's problem
// is the size of the part and its halo, not of the mesh (Part_problem.h); and the Input concept
// (Fairing_input.h) tells a kind that lacks a member.

#include "seeded_noise.h"
#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Fairing_driver.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Fairing_input.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Part_problem.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/read_named_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Triangle_meshes/Mesh_input.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
namespace CF = PMP::internal::Constrained_fairing;
using test::Mesh;
using test::Point;

// What the sweeps did.
struct Sweeps
{
  std::vector<double> energies; // the whole's objective after each sweep
  std::size_t count = 0;
  double last_motion = 0;       // the largest motion of a vertex in the last sweep
};

// `m` faired as `parts` ranges of the solver's order (the Hilbert order: compact pieces of the
// surface), in sweeps until no vertex moves more than 1 % of eps in one, at most 40.
template <typename NamedParameters>
PMP::Constrained_fairing_result fair_in_parts(Mesh& m, double eps, std::size_t parts, const NamedParameters& np,
                                             Sweeps& sweeps)
{
  using Faces = std::vector<Mesh::Face_index>;
  CF::Mesh_input<Mesh, decltype(get(CGAL::vertex_point, m)), Faces> input(m, get(CGAL::vertex_point, m), nullptr);
  const auto step = [&](auto& problem, CF::Points& X, PMP::Constrained_fairing_result& result) {
    problem.start(X, result);
    const std::size_t n = static_cast<std::size_t>(X.rows());
    for(sweeps.count = 1; sweeps.count <= 40; ++sweeps.count)
    {
      const CF::Points before = X;
      for(std::size_t p = 0; p < parts; ++p)
      {
        std::vector<CF::Index> part;
        for(std::size_t i = p * n / parts; i < (p + 1) * n / parts; ++i)
          part.push_back(CF::Index(i));
        CHECK(problem.fair_part(part, CF::Iteration_callback(CF::Always_continue()), X, 10));
      }
      sweeps.energies.push_back(problem.built().energy.value(X));
      sweeps.last_motion = (X - before).rowwise().norm().maxCoeff();
      if(sweeps.last_motion <= 0.01 * eps)
        break;
    }
    problem.finish(X, result);
    result.status = PMP::Constrained_fairing_status::CONVERGED;
  };
  return CF::run_fairing_phases(input, eps, CF::read_fairing_settings(np), CF::read_vertex_maps(np),
                                CF::read_sparse_linear_solver(np), step);
}

template <typename NamedParameters>
void check_parts_reach_the_whole(const Mesh& noisy, double eps, PMP::Deviation_bound shape, const NamedParameters& np,
                                 const std::string& name)
{
  Mesh whole = noisy;
  const PMP::Constrained_fairing_result reference = PMP::constrained_fairing(whole, eps, np);
  CHECK(reference);
  const std::vector<Point> in = test::points(noisy);
  for(std::size_t parts : {2, 8})
  {
    Mesh m = noisy;
    Sweeps sweeps;
    const PMP::Constrained_fairing_result result = fair_in_parts(m, eps, parts, np, sweeps);
    CHECK(result);
    const std::vector<Point> faired = test::points(m);
    CHECK(test::bound_violation(faired, in, eps, shape) == 0);
    for(std::size_t s = 1; s < sweeps.energies.size(); ++s)
      CHECK(sweeps.energies[s] <= sweeps.energies[s - 1]);
    CHECK(sweeps.last_motion <= 0.01 * eps);
    const double energy_ratio = result.final_energy / reference.final_energy;
    const double distance = test::surface_rms(m, whole) / eps;
    std::cout << "  " << name << ", " << parts << " parts: " << sweeps.count << " sweeps, energy "
              << energy_ratio << " of the whole call's, RMS distance to its surface " << distance << " eps"
              << std::endl;
    CHECK(energy_ratio <= 1.01);
    CHECK(distance <= 0.01);
  }
}

// A part's problem holds the part and its halo: the vertices of the triangles of the hinges
// that touch the part, at most 3 rings around one vertex.
void check_part_size()
{
  const Mesh m = test::icosphere(4);
  CF::Points X0(num_vertices(m), 3);
  for(auto v : vertices(m))
    X0.row(v.idx()) << m.point(v).x(), m.point(v).y(), m.point(v).z();
  auto index = get(CGAL::vertex_index, m);
  const CF::Hinge_mesh mesh(m, index);
  CF::Part_tables tables(mesh);
  const std::vector<bool> moving(num_vertices(m), true);
  for(CF::Index v : {CF::Index(0), CF::Index(100), CF::Index(2000)})
  {
    const CF::Part_problem piece(mesh, moving, {v}, tables);
    const std::size_t valence = std::size_t(std::distance(tables.triangles_of_vertex.begin(v),
                                                          tables.triangles_of_vertex.end(v)));
    CHECK(piece.number_of_moving_vertices() == 1);
    CHECK(piece.mesh().triangles.size() == 2 * valence); // its triangles and their neighbours
    CHECK(piece.mesh().hinges.size() == 2 * valence);    // its edges' and its triangles' far edges
    CHECK(piece.vertices().size() == 1 + 2 * valence);
    CHECK(std::all_of(tables.place.begin(), tables.place.end(), [](CF::Index p) { return p == CF::Part_tables::none; }));
  }
}

struct Not_an_input
{
  CF::Input_error structure_error() { return {}; }
};

void check_input_concept()
{
  namespace C = CF::input_concept;
  using Maps = decltype(CF::read_vertex_maps(CGAL::parameters::default_values()));
  using Input = CF::Mesh_input<Mesh, decltype(get(CGAL::vertex_point, std::declval<Mesh&>())), std::vector<Mesh::Face_index> >;
  CHECK((CF::check_fairing_input<Input, Maps>()));
  CHECK((C::has<C::structure_error, Not_an_input>));
  CHECK(!(C::has<C::part, Not_an_input, Maps>));
  CHECK(!(C::has<C::add_terms, Not_an_input>));
  CHECK(!(C::has<C::write_own_outputs, Not_an_input>));
}

int main()
{
  check_part_size();
  check_input_concept();
  Mesh elephant;
  CHECK(CGAL::IO::read_polygon_mesh(std::string(CONSTRAINED_FAIRING_DATA_DIR) + "/elephant_noisy.off", elephant));
  const double eps = 0.25 * test::mean_edge_length(elephant);
  check_parts_reach_the_whole(elephant, eps, PMP::Deviation_bound::BALL, CGAL::parameters::default_values(),
                              "noisy elephant, normal offsets");
  check_parts_reach_the_whole(elephant, eps, PMP::Deviation_bound::BALL, CFP::fairing_objective(PMP::Constrained_fairing_objective::ACCURATE),
                              "noisy elephant, accurate");
  return test::report("test_part_fairing");
}
