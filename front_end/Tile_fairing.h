// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One tile of a mesh too large for one process (the Python module's fair_tiled(), which schedules
// the sweeps on Dask): the triangles around the vertices the tile
// owns, out to rings of its neighbours' vertices (the ghosts). The smoothed start and the
// normals along which the vertices move are made from the tile's input points, as the whole
// call makes them (Fairing_problem::start): a smoothing step reaches one ring farther, so with
// more rings than steps they are the whole call's at the owned vertices. The owned vertices
// then descend from where the earlier sweeps left them, every ghost frozen there
// (Fairing_problem::fair_part): each tile's descent lowers the whole's objective within the
// whole's bound, so that sweeps over tiles that share no hinge descend it as one problem does
// (a Schwarz method). fair_tiled()'s first sweep lets the ghosts near a tile's vertices descend
// too and keeps its own vertices' points alone (an overlap), so that they are not bent towards
// ghosts still at the smoothed start.

#ifndef CONSTRAINED_FAIRING_FRONT_END_TILE_FAIRING_H
#define CONSTRAINED_FAIRING_FRONT_END_TILE_FAIRING_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Fairing_driver.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/read_named_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Triangle_meshes/Mesh_input.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace Constrained_fairing_front_end {

namespace CF = CGAL::Polygon_mesh_processing::internal::Constrained_fairing;
using Fairing_result = CGAL::Polygon_mesh_processing::Constrained_fairing_result;

// Where a tile's vertices are now, in the order of vertices(tmesh), and which of them it owns.
struct Tile_state
{
  CF::Points current;          // a row per vertex, within its bound about the input point
  std::vector<bool> owned;     // the vertices that descend; the others are ghosts
  std::vector<bool> at_start;  // the vertices not faired yet, taken at the smoothed start
  std::size_t max_iterations;  // of this sweep's descent
};

// The owned vertices of `tmesh` (whose points are the input's) faired from `tile.current`, the
// ghosts frozen there, but those `at_start`, which the first sweep takes at the smoothed start
// (where the whole call starts: with two rings more than the smoothing steps, the start is the
// whole call's out to the second ring, which the owned vertices' hinges reach); the mesh's
// points then hold the tile's new state. The named parameters are those of
// constrained_fairing() that a whole mesh takes (no face range, no creases: a part's objective
// has no crease term).
template <typename TriangleMesh, typename NamedParameters>
Fairing_result fair_tile(TriangleMesh& tmesh, double epsilon, const Tile_state& tile, const NamedParameters& np)
{
  CGAL_precondition(std::size_t(tile.current.rows()) == num_vertices(tmesh));
  CGAL_precondition(tile.owned.size() == num_vertices(tmesh) && tile.at_start.size() == num_vertices(tmesh));
  using Faces = std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>;
  const auto vpm = get_property_map(CGAL::vertex_point, tmesh);
  CF::Mesh_input<TriangleMesh, std::remove_const_t<decltype(vpm)>, Faces> input(tmesh, vpm, nullptr);
  Fairing_result descent;
  descent.status = CGAL::Polygon_mesh_processing::Constrained_fairing_status::CONVERGED;
  const auto step = [&](auto& problem, CF::Points& X, auto& result) {
    problem.start(X, result);
    const std::vector<CF::Index>& rank = problem.built().rank;
    std::vector<CF::Index> part;
    for(std::size_t k = 0; k < rank.size(); ++k)
    {
      if(tile.owned[k])
        part.push_back(rank[k]);
      if(!tile.at_start[k])
        CF::point(X, rank[k]) = CF::point(tile.current, k);
    }
    std::sort(part.begin(), part.end());
    if(tile.max_iterations > 0)
    {
      const CF::Iteration_callback callback(CF::read_iteration_callback(np));
      descent = problem.fair_part(part, callback, X, tile.max_iterations);
    }
    problem.finish(X, result);
    result.status = descent.status;
    result.message = descent.message;
    result.number_of_iterations = descent.number_of_iterations;
    result.number_of_energy_evaluations = descent.number_of_energy_evaluations;
    result.number_of_folded_faces = descent.number_of_folded_faces;
  };
  return CF::run_fairing_phases(input, epsilon, CF::read_fairing_settings(np), CF::read_vertex_maps(np),
                                CF::read_sparse_linear_solver(np), step);
}

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_TILE_FAIRING_H
