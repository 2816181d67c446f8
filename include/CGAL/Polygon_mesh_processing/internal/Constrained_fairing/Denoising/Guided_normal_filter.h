// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Guided filtering of the face normals (W. Zhang, B. Deng, J. Zhang, S. Bouaziz, L. Liu,
// "Guided mesh normal filtering", Computer Graphics Forum 2015), for the feature detection: each
// face's guide is the mean normal of the most consistent patch that holds it (a patch: the faces
// round one face's corners; consistent: its normals all near their mean), and
// each step replaces a face's normal by the mean of its patch's, weighted by area, by a Gaussian
// of the distance between centroids and by a Gaussian of the difference between guides. Why:
// a bilateral filter weighs two faces by how far apart their own noisy normals are, so across
// a crease of 45 degrees (unit normals 0.77 apart) it still mixes the two sides, step after
// step, and the crease fades below any angle a user would give; a patch on one side of the
// crease is consistent where one across it is not, so the guides on the two sides stay as far
// apart as the sides themselves, and a narrow Gaussian in the guides keeps them apart.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_GUIDED_NORMAL_FILTER_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_GUIDED_NORMAL_FILTER_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Face_normals.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Rows_by_vertex.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Guided_normal_filter
{
public:
  // The width of the Gaussian in the difference of guides (0.25: about 14 degrees), and the
  // steps: swept over 0.2 to 0.6 and 2 to 10 steps on the crease benchmark's CAD parts and
  // organic meshes (doc/design_notes.md, "Creases"): wider or longer lets the sides of a
  // 45-degree crease mix again, and more steps sharpen a smooth surface's bends into creases.
  static constexpr double guide_difference_sigma = 0.25;
  static constexpr std::size_t steps = 3;

  explicit Guided_normal_filter(const Hinge_mesh& mesh) : m_mesh(mesh), m_patches(patches(mesh)) {}

  // The faces' unit normals, areas and centroids at the points X, before filtering.
  void set_points(const Points& X) { m_faces.set(m_mesh, X); }

  // `steps` steps of the filter, each with guides from the normals it starts from.
  void filter(std::size_t steps)
  {
    if(!m_faces.set_widths(m_mesh, guide_difference_sigma))
      return;
    std::vector<Eigen::Vector3d>& normal = m_faces.normal;
    const std::size_t nf = normal.size();
    std::vector<Eigen::Vector3d> mean(nf), guide(nf), filtered(nf);
    std::vector<double> spread(nf);
    for(std::size_t step = 0; step < steps; ++step)
    {
      parallel_for_blocks(nf, [&](std::size_t begin, std::size_t end, std::size_t) {
        for(std::size_t f = begin; f < end; ++f)
          spread[f] = patch_spread(f, mean[f]);
      });
      parallel_for_blocks(nf, [&](std::size_t begin, std::size_t end, std::size_t) {
        for(std::size_t f = begin; f < end; ++f)
        {
          // the most consistent patch that holds f: that of one of f's patch's faces
          Index best = Index(f);
          for(auto g = m_patches.begin(f); g != m_patches.end(f); ++g)
            if(spread[*g] < spread[best])
              best = *g;
          guide[f] = mean[best];
        }
      });
      parallel_for_blocks(nf, [&](std::size_t begin, std::size_t end, std::size_t) {
        for(std::size_t f = begin; f < end; ++f)
        {
          Eigen::Vector3d sum = Eigen::Vector3d::Zero();
          for(auto g = m_patches.begin(f); g != m_patches.end(f); ++g)
            sum += m_faces.weight(f, *g, guide[f], guide[*g]) * normal[*g];
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
  // Each triangle's patch: the triangles round its corners, each once, itself among them.
  static Rows_by_vertex<Index> patches(const Hinge_mesh& mesh)
  {
    const Rows_by_vertex<Index> around(mesh.number_of_vertices, [&](const auto& add) {
      for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
        for(Index v : mesh.triangles[f])
          add(v, Index(f));
    });
    std::vector<Index> patch;
    return Rows_by_vertex<Index>(mesh.triangles.size(), [&](const auto& add) {
      for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
      {
        patch.clear();
        for(Index v : mesh.triangles[f])
          patch.insert(patch.end(), around.begin(v), around.end(v));
        std::sort(patch.begin(), patch.end());
        patch.erase(std::unique(patch.begin(), patch.end()), patch.end());
        for(Index g : patch)
          add(f, g);
      }
    });
  }

  // The area-weighted mean of f's patch's normals, as a unit vector in `mean`, and the largest
  // squared difference of those normals from it: a patch that reaches across a crease holds a
  // face far from its mean however few of its faces lie there, while the mean squared
  // difference let a face by a crease take its guide from a patch on the other side
  // (doc/design_notes.md, "Creases").
  double patch_spread(std::size_t f, Eigen::Vector3d& mean) const
  {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for(auto g = m_patches.begin(f); g != m_patches.end(f); ++g)
      sum += m_faces.area[*g] * m_faces.normal[*g];
    const double length = sum.norm();
    if(!(length > 0))
    {
      mean = m_faces.normal[f];
      return 4; // a patch of no area is the least consistent of all
    }
    mean = sum / length;
    double spread = 0;
    for(auto g = m_patches.begin(f); g != m_patches.end(f); ++g)
      spread = (std::max)(spread, (m_faces.normal[*g] - mean).squaredNorm());
    return spread;
  }

  const Hinge_mesh& m_mesh;
  Rows_by_vertex<Index> m_patches; // by triangle: the triangles round its corners
  Face_normals m_faces;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_GUIDED_NORMAL_FILTER_H
