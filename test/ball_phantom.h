// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A ball cut by the tilted plane x = tilt z into labels 1 (x < tilt z) and 2, optionally with a
// cap of label 3 over part of it: its label map, and how far a soup's points lie from its true
// interfaces (the sphere, the plane, the triple circle where they meet). The joint fairing's
// test and benchmark/label_surfaces both measure on it.

#ifndef CGAL_CONSTRAINED_FAIRING_TEST_BALL_PHANTOM_H
#define CGAL_CONSTRAINED_FAIRING_TEST_BALL_PHANTOM_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <set>
#include <vector>

namespace test {

struct Ball_phantom
{
  static constexpr double tilt = 0.3;

  double centre, radius; // in world units, the same along each axis
  bool cap = false;      // label 3, 2.5 thick, over the part y > 6 of the ball

  // The labels of voxel (i, j, k) at (i, j, k) times `spacing`, at labels[(i J + j) K + k].
  template <typename Label>
  std::vector<Label> labels(const std::array<std::size_t, 3>& size, const std::array<double, 3>& spacing) const
  {
    std::vector<Label> labels(size[0] * size[1] * size[2], 0);
    for(std::size_t i = 0; i < size[0]; ++i)
      for(std::size_t j = 0; j < size[1]; ++j)
        for(std::size_t k = 0; k < size[2]; ++k)
        {
          const double x = double(i) * spacing[0] - centre, y = double(j) * spacing[1] - centre,
                       z = double(k) * spacing[2] - centre;
          const double r2 = x * x + y * y + z * z;
          Label& l = labels[(i * size[1] + j) * size[2] + k];
          if(r2 < radius * radius)
            l = x < tilt * z ? 1 : 2;
          else if(cap && r2 < (radius + 2.5) * (radius + 2.5) && y > 6)
            l = 3;
        }
    return labels;
  }

  // The RMS distances of the points on only the ball's outer interfaces to the sphere, of those
  // on only the 1-2 interface to the plane, of those on both (the triple line) to their circle,
  // and of all of these together; `around[v]` holds the labels of point v's triangles.
  template <typename Point, typename Label>
  std::array<double, 4> distances(const std::vector<Point>& points, const std::vector<std::set<Label> >& around) const
  {
    const double norm = std::sqrt(1 + tilt * tilt);
    std::array<double, 4> sum{0, 0, 0, 0};
    std::array<std::size_t, 4> count{0, 0, 0, 0};
    for(std::size_t v = 0; v < points.size(); ++v)
    {
      const double x = points[v].x() - centre, y = points[v].y() - centre, z = points[v].z() - centre;
      const double to_plane = (x - tilt * z) / norm, to_sphere = std::sqrt(x * x + y * y + z * z) - radius;
      const std::set<Label>& a = around[v];
      double d2;
      std::size_t kind;
      if(a == std::set<Label>{0, 1} || a == std::set<Label>{0, 2})
        d2 = to_sphere * to_sphere, kind = 0;
      else if(a == std::set<Label>{1, 2})
        d2 = to_plane * to_plane, kind = 1;
      else if(a == std::set<Label>{0, 1, 2})
      {
        // off the plane, and off the sphere within it
        const double px = x - to_plane / norm, pz = z + tilt * to_plane / norm;
        const double in_plane = std::sqrt(px * px + y * y + pz * pz) - radius;
        d2 = to_plane * to_plane + in_plane * in_plane, kind = 2;
      }
      else
        continue;
      sum[kind] += d2, ++count[kind];
      sum[3] += d2, ++count[3];
    }
    std::array<double, 4> rms;
    for(std::size_t k = 0; k < 4; ++k)
      rms[k] = std::sqrt(sum[k] / double((std::max)(count[k], std::size_t(1))));
    return rms;
  }
};

} // namespace test

#endif // CGAL_CONSTRAINED_FAIRING_TEST_BALL_PHANTOM_H
