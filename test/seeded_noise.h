// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The noise of the tests and benchmarks: every vertex moved uniformly at random inside a ball,
// from a seed, so that a mesh can be made again bit for bit.

#ifndef CGAL_CONSTRAINED_FAIRING_SEEDED_NOISE_H
#define CGAL_CONSTRAINED_FAIRING_SEEDED_NOISE_H

#include <CGAL/boost/graph/properties.h>

#include <random>

namespace test {

// Moves every vertex uniformly at random inside a ball of radius r (seeded).
template <typename PolygonMesh>
void add_noise(PolygonMesh& m, double r, unsigned int seed)
{
  using Point = typename boost::property_traits<
    typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type>::value_type;
  using Vector = typename CGAL::Kernel_traits<Point>::Kernel::Vector_3;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  auto vpm = get(CGAL::vertex_point, m);
  for(auto v : vertices(m))
  {
    Vector d;
    do
      d = Vector(u(rng), u(rng), u(rng));
    while(d.squared_length() > 1);
    put(vpm, v, get(vpm, v) + r * d);
  }
}

} // namespace test

#endif // CGAL_CONSTRAINED_FAIRING_SEEDED_NOISE_H
