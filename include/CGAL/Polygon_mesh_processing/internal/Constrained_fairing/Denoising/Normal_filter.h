// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bilateral filtering of the face normals (Y. Zheng, H. Fu, O. K.-C. Au, C.-L. Tai, "Bilateral
// normal filtering for mesh denoising", IEEE TVCG 2011): each face's unit normal replaced by the
// mean of its own and its edge neighbours' (across the hinges), weighted by area, by a Gaussian
// of the distance between centroids (its width the mean such distance) and by a Gaussian of the
// difference between normals. Why: it averages the normals that agree and leaves apart those that
// do not, so that noise goes and creases stay. The accurate objective's anchor fits its vertices
// to the filtered normals (Fidelity_anchor.h); the feature detection compares them across each
// hinge (Feature_edges.h).

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NORMAL_FILTER_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NORMAL_FILTER_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Normal_filter
{
public:
  // The width of the Gaussian in the difference of unit normals (0.4: about 23 degrees), for the
  // accurate objective's anchor and the feature detection alike: chosen for the anchor on the
  // benchmark fairing_accuracy over its whole set of meshes and noise levels, and kept by the
  // detection's sweep from 0.3 to 0.6 (doc/design_notes.md, "Creases").
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
  void set_points(const Points& X)
  {
    const std::size_t nf = m_mesh.triangles.size();
    m_normal.resize(nf);
    m_centroid.resize(nf);
    m_area.resize(nf);
    parallel_for_blocks(nf, [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t f = begin; f < end; ++f)
      {
        const Eigen::Vector3d normal = area_normal(m_mesh, X, f);
        const double length = normal.norm();
        m_area[f] = length / 2;
        m_normal[f] = length > 0 ? Eigen::Vector3d(normal / length) : Eigen::Vector3d::Zero();
        m_centroid[f] = centroid(m_mesh, X, f);
      }
    });
  }

  // `steps` steps of the filter.
  void filter(std::size_t steps)
  {
    const double spacing = centroid_spacing();
    if(!(spacing > 0))
      return;
    constexpr double sigma = normal_difference_sigma;
    const double spatial = 1 / (2 * spacing * spacing), range = 1 / (2 * sigma * sigma);
    std::vector<Eigen::Vector3d> filtered(m_normal.size());
    for(std::size_t step = 0; step < steps; ++step)
    {
      parallel_for_blocks(m_normal.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
        for(std::size_t f = begin; f < end; ++f)
        {
          Eigen::Vector3d sum = m_area[f] * m_normal[f];
          for(Index g : m_neighbours[f])
            if(g != no_face)
              sum += m_area[g] * std::exp(-spatial * (m_centroid[f] - m_centroid[g]).squaredNorm()) *
                     std::exp(-range * (m_normal[f] - m_normal[g]).squaredNorm()) * m_normal[g];
          const double length = sum.norm();
          filtered[f] = length > 0 ? Eigen::Vector3d(sum / length) : m_normal[f];
        }
      });
      m_normal.swap(filtered);
    }
  }

  // Face f's filtered unit normal (zero for a face of zero area).
  const Eigen::Vector3d& normal(std::size_t f) const { return m_normal[f]; }

private:
  static constexpr Index no_face = ~Index(0);

  // The mean distance between the centroids of edge neighbours: the spatial Gaussian's width.
  double centroid_spacing() const
  {
    double sum = 0;
    for(const Hinge& h : m_mesh.hinges)
      sum += (m_centroid[h.f[0]] - m_centroid[h.f[1]]).norm();
    return m_mesh.hinges.empty() ? 0 : sum / double(m_mesh.hinges.size());
  }

  const Hinge_mesh& m_mesh;
  std::vector<std::array<Index, 3> > m_neighbours; // by triangle, no_face past its edge neighbours
  std::vector<Eigen::Vector3d> m_normal, m_centroid;
  std::vector<double> m_area;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NORMAL_FILTER_H
