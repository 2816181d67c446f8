// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bilateral filtering of the face normals (Y. Zheng, H. Fu, O. K.-C. Au, C.-L. Tai, "Bilateral
// normal filtering for mesh denoising", IEEE TVCG 2011): each face's unit normal replaced by the
// mean of its own and its edge neighbours' (across the hinges), weighted by area, by a Gaussian
// of the distance between centroids (its width the mean such distance) and by a Gaussian of the
// difference between normals. Why: it averages the normals that agree and leaves apart those that
// do not, so that noise goes and creases stay. The accurate objective's anchor fits its vertices
// to the filtered normals (Fidelity_anchor.h); the feature detection filters otherwise
// (Guided_normal_filter.h), since this filter blends the sides of a 45-degree crease.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NORMAL_FILTER_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NORMAL_FILTER_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Face_normals.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Normal_filter
{
public:
  // The width of the Gaussian in the difference of unit normals (0.4: about 23 degrees): chosen
  // for the accurate objective's anchor on the benchmark fairing_accuracy over its whole set of
  // meshes and noise levels.
  static constexpr double normal_difference_sigma = 0.4;

  explicit Normal_filter(const Hinge_mesh& mesh) : m_mesh(mesh)
  {
    // Each triangle's edge neighbours, from the hinges (a border edge has none).
    m_neighbours.assign(mesh.triangles.size(), {no_face, no_face, no_face});
    std::vector<unsigned char> count(mesh.triangles.size(), 0);
    for(const Hinge& h : mesh.hinges)
      for(int k = 0; k < 2; ++k)
      {
        const Index f = h.f[std::size_t(k)];
        m_neighbours[f][count[f]++] = h.f[std::size_t(1 - k)];
      }
  }

  // The faces' unit normals, areas and centroids at the points X, before filtering.
  void set_points(const Points& X) { m_faces.set(m_mesh, X); }

  // `steps` steps of the filter.
  void filter(std::size_t steps)
  {
    if(!m_faces.set_widths(m_mesh, normal_difference_sigma))
      return;
    std::vector<Eigen::Vector3d>& normal = m_faces.normal;
    std::vector<Eigen::Vector3d> filtered(normal.size());
    for(std::size_t step = 0; step < steps; ++step)
    {
      parallel_for_blocks(normal.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
        for(std::size_t f = begin; f < end; ++f)
        {
          Eigen::Vector3d sum = m_faces.area[f] * normal[f];
          for(Index g : m_neighbours[f])
            if(g != no_face)
              sum += m_faces.weight(f, g, normal[f], normal[g]) * normal[g];
          const double length = sum.norm();
          filtered[f] = length > 0 ? Eigen::Vector3d(sum / length) : normal[f];
        }
      });
      normal.swap(filtered);
    }
  }

  // Face f's filtered unit normal (zero for a face of zero area).
  const Eigen::Vector3d& normal(std::size_t f) const { return m_faces.normal[f]; }

private:
  static constexpr Index no_face = ~Index(0);

  const Hinge_mesh& m_mesh;
  std::vector<std::array<Index, 3> > m_neighbours; // by triangle, no_face past its edge neighbours
  Face_normals m_faces;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NORMAL_FILTER_H
