// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The anchor of the accurate objective (Fairing_objective.h): a denoised copy of the input, made
// in three stages, every vertex kept in its bound:
//  1. projected Taubin steps (Smoothed_start.h), which remove most of the noise without
//     shrinking the surface;
//  2. bilateral filtering of the face normals (Normal_filter.h);
//  3. the vertices moved to fit the filtered normals (X. Sun, P. L. Rosin, R. R. Martin,
//     F. C. Langbein, "Fast and effective feature-preserving mesh denoising", IEEE TVCG 2007):
//     x_i <- x_i + 1/|F_i| sum over the faces f of x_i of n_f n_f^T (c_f - x_i), c_f the
//     centroid, each step followed by a move back into the bound.
// Why: Taubin's filter passes what is left of the noise at the scales it keeps, and it rounds
// creases; the normal filter averages the normals that agree and leaves apart those that do
// not, so that the vertex fit removes the rest of the noise along the normals without flattening
// the shape. Over edge neighbours only and a few steps: over the faces around the vertices, or
// with more steps, the filter flattened the curved parts of coarse meshes (benchmark
// fairing_accuracy; the user manual gives the figures).

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FIDELITY_ANCHOR_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FIDELITY_ANCHOR_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Normal_filter.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Smoothed_start.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Mesh_operators.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Fidelity_anchor
{
public:
  // The stages' sizes, chosen on the benchmark fairing_accuracy over its whole set of meshes
  // and noise levels: the Taubin steps, the normal filter's steps (its Gaussian's width is the
  // filter's, Normal_filter.h) and the vertex fit's steps.
  static constexpr std::size_t anchor_taubin_steps = 10;
  static constexpr std::size_t normal_filter_steps = 5;
  static constexpr std::size_t normal_fit_steps = 10;

  explicit Fidelity_anchor(const Hinge_mesh& mesh)
    : m_mesh(mesh), m_vertex_triangles(vertex_triangles(mesh)), m_filter(mesh)
  {}

  // Replaces X, feasible in `bound`, by its anchor, feasible too.
  template <typename Bound>
  void apply(const Bound& bound, Points& X)
  {
    smooth_start(m_mesh, bound, anchor_taubin_steps, X);
    m_filter.set_points(X);
    m_filter.filter(normal_filter_steps);
    for(std::size_t step = 0; step < normal_fit_steps; ++step)
    {
      fit_vertices(X);
      bound.project(X);
    }
  }

private:
  // One step of the vertex fit, with the filtered normals and the current centroids.
  void fit_vertices(Points& X)
  {
    const std::size_t nf = m_mesh.triangles.size();
    m_centroid.resize(nf);
    parallel_for_blocks(nf, [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t f = begin; f < end; ++f)
        m_centroid[f] = centroid(m_mesh, X, f);
    });
    parallel_for_blocks(m_mesh.number_of_vertices, [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t i = begin; i < end; ++i)
      {
        const auto first = m_vertex_triangles.begin(i), last = m_vertex_triangles.end(i);
        if(first == last)
          continue;
        Eigen::Vector3d move = Eigen::Vector3d::Zero();
        for(auto f = first; f != last; ++f)
        {
          const Eigen::Vector3d& n = m_filter.normal(*f);
          move += n * n.dot(m_centroid[*f] - point(X, i));
        }
        point(X, i) += move / double(last - first);
      }
    });
  }

  const Hinge_mesh& m_mesh;
  Rows_by_vertex<Index> m_vertex_triangles; // for the vertex fit's gather
  Normal_filter m_filter;
  std::vector<Eigen::Vector3d> m_centroid;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FIDELITY_ANCHOR_H
