// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The map from a label map's voxel indices to the world (a NIfTI image's affine), split into
// the voxels' spacing (the lengths of its first three columns) and the rigid move, or mirror,
// that takes the spaced voxels into the world: the surfaces are made and faired in the spaced
// voxels, whose boxes are axis-aligned, then moved. The tool and the Python module both split
// it here, so that they refuse the same affines in the same words.

#ifndef CONSTRAINED_FAIRING_FRONT_END_VOXEL_FRAME_H
#define CONSTRAINED_FAIRING_FRONT_END_VOXEL_FRAME_H

#include <array>
#include <cmath>
#include <cstddef>
#include <string>

namespace Constrained_fairing_front_end {

struct Voxel_frame
{
  // world = affine[r] . (i, j, k, 1) for rows r = 0, 1, 2.
  using Affine = std::array<std::array<double, 4>, 3>;

  explicit Voxel_frame(const Affine& affine)
  {
    for(const auto& row : affine)
      for(double a : row)
        if(!std::isfinite(a))
        {
          error = "the affine must be finite";
          return;
        }
    for(std::size_t c = 0; c < 3; ++c)
    {
      spacing[c] = std::sqrt(affine[0][c] * affine[0][c] + affine[1][c] * affine[1][c] + affine[2][c] * affine[2][c]);
      if(!(spacing[c] > 0) || !std::isfinite(spacing[c]))
      {
        error = "the affine maps voxel axis " + std::to_string(c) + " to no direction: it must map the voxel "
                "axes to independent directions";
        return;
      }
      for(std::size_t r = 0; r < 3; ++r)
        axes[r][c] = affine[r][c] / spacing[c];
    }
    for(std::size_t r = 0; r < 3; ++r)
      translation[r] = affine[r][3];
    const double determinant = axes[0][0] * (axes[1][1] * axes[2][2] - axes[1][2] * axes[2][1]) -
                               axes[0][1] * (axes[1][0] * axes[2][2] - axes[1][2] * axes[2][0]) +
                               axes[0][2] * (axes[1][0] * axes[2][1] - axes[1][1] * axes[2][0]);
    if(!(std::abs(determinant) > 1e-12))
      error = "the affine maps the voxel axes to dependent directions: it must map them to independent ones";
    mirrors = determinant < 0;
  }

  // A point of the spaced voxels in the world.
  std::array<double, 3> to_world(const std::array<double, 3>& p) const
  {
    std::array<double, 3> w;
    for(std::size_t r = 0; r < 3; ++r)
      w[r] = axes[r][0] * p[0] + axes[r][1] * p[1] + axes[r][2] * p[2] + translation[r];
    return w;
  }

  std::string error; // why the affine is refused, or empty
  std::array<double, 3> spacing{1, 1, 1};
  std::array<std::array<double, 3>, 3> axes{};
  std::array<double, 3> translation{0, 0, 0};
  bool mirrors = false; // the faces are turned in the world, so that they stay outward
};

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_VOXEL_FRAME_H
