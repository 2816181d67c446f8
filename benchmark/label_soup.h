// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the label-map benchmarks share: the soup of a label map with each point's labels, VTK's
// clamped Laplacian to compare with, the smallest angle, the joint fairing and a compact map of
// Voronoi cells.

#ifndef CGAL_CONSTRAINED_FAIRING_BENCHMARK_LABEL_SOUP_H
#define CGAL_CONSTRAINED_FAIRING_BENCHMARK_LABEL_SOUP_H

#include "benchmark_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_interfaces.h>
#include <CGAL/Polygon_mesh_processing/label_surface_nets.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <vector>

namespace label_soup {

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using benchmark::Point;
using Label = std::int32_t;
using Triangle = std::array<std::size_t, 3>;

struct Soup
{
  std::array<double, 3> spacing;
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  std::vector<std::array<Label, 2> > face_labels;
  std::vector<std::array<double, 3> > half_extents; // each point's box
  std::vector<std::set<Label> > around; // the labels of each point's triangles
};

// The soup of a label map, boxes shrunk by `margin` of the spacing.
inline Soup make_soup(const std::vector<Label>& labels, const std::array<std::size_t, 3>& size,
                      const std::array<double, 3>& spacing, double box_margin)
{
  Soup soup;
  soup.spacing = spacing;
  PMP::label_surface_nets(labels.data(), size, spacing, {0, 0, 0}, soup.points, soup.triangles, soup.face_labels,
                          soup.half_extents, Label(0), box_margin);
  soup.around.resize(soup.points.size());
  for(std::size_t f = 0; f < soup.triangles.size(); ++f)
    for(std::size_t v : soup.triangles[f])
      soup.around[v].insert(soup.face_labels[f].begin(), soup.face_labels[f].end());
  return soup;
}

// A compact label map: the Voronoi cells of 10 seeds inside a ball, on n^3 cubic voxels (the
// seeds drawn with a fixed seed, so that every run makes the same map).
template <typename L>
std::vector<L> voronoi_ball_labels(std::size_t n)
{
  const double c = double(n - 1) / 2, R = 0.43 * double(n);
  std::mt19937 random(1);
  std::uniform_real_distribution<double> uniform(-R / 2, R / 2);
  std::vector<std::array<double, 3> > seeds(10);
  for(auto& s : seeds)
    s = {c + uniform(random), c + uniform(random), c + uniform(random)};
  std::vector<L> labels(n * n * n, 0);
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t k = 0; k < n; ++k)
      {
        const double x = double(i), y = double(j), z = double(k);
        if((x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c) >= R * R)
          continue;
        double nearest = 1e300;
        for(std::size_t s = 0; s < seeds.size(); ++s)
        {
          const double d = (x - seeds[s][0]) * (x - seeds[s][0]) + (y - seeds[s][1]) * (y - seeds[s][1]) +
                           (z - seeds[s][2]) * (z - seeds[s][2]);
          if(d < nearest)
            nearest = d, labels[(i * n + j) * n + k] = L(s + 1);
        }
      }
  return labels;
}

// VTK's constrained smoothing of surface nets: each point towards the mean of its neighbours on
// its interface (a point of one interface) or its junction line (a point of three labels with
// two line neighbours), relaxation 0.5, clamped to its box; the others stay.
class Clamped_laplacian
{
public:
  explicit Clamped_laplacian(const Soup& soup) : m_soup(soup), m_neighbours(soup.points.size())
  {
    std::vector<std::set<std::size_t> > all(soup.points.size()), line(soup.points.size());
    std::map<std::pair<std::size_t, std::size_t>, std::set<Label> > edges;
    for(std::size_t f = 0; f < soup.triangles.size(); ++f)
      for(int c = 0; c < 3; ++c)
      {
        const std::size_t a = soup.triangles[f][std::size_t(c)], b = soup.triangles[f][std::size_t((c + 1) % 3)];
        all[a].insert(b);
        all[b].insert(a);
        edges[{(std::min)(a, b), (std::max)(a, b)}].insert(soup.face_labels[f].begin(), soup.face_labels[f].end());
      }
    for(const auto& e : edges)
      if(e.second.size() >= 3)
      {
        line[e.first.first].insert(e.first.second);
        line[e.first.second].insert(e.first.first);
      }
    for(std::size_t v = 0; v < soup.points.size(); ++v)
      if(soup.around[v].size() == 2)
        m_neighbours[v].assign(all[v].begin(), all[v].end());
      else if(soup.around[v].size() == 3 && line[v].size() == 2)
        m_neighbours[v].assign(line[v].begin(), line[v].end());
  }

  void step(std::vector<Point>& P) const
  {
    std::vector<Point> Q = P;
    for(std::size_t v = 0; v < P.size(); ++v)
    {
      if(m_neighbours[v].empty())
        continue;
      std::array<double, 3> mean{0, 0, 0};
      for(std::size_t u : m_neighbours[v])
        for(int c = 0; c < 3; ++c)
          mean[std::size_t(c)] += P[u][c] / double(m_neighbours[v].size());
      std::array<double, 3> q;
      for(int c = 0; c < 3; ++c)
      {
        const double x = P[v][c] + 0.5 * (mean[std::size_t(c)] - P[v][c]), c0 = m_soup.points[v][c];
        const double h = m_soup.spacing[std::size_t(c)] / 2;
        q[std::size_t(c)] = std::clamp(x, c0 - h, c0 + h);
      }
      Q[v] = Point(q[0], q[1], q[2]);
    }
    P.swap(Q);
  }

private:
  const Soup& m_soup;
  std::vector<std::vector<std::size_t> > m_neighbours;
};

inline double smallest_angle(const Soup& soup, const std::vector<Point>& P)
{
  double smallest = 180;
  for(const Triangle& t : soup.triangles)
  {
    const Point &a = P[t[0]], &b = P[t[1]], &c = P[t[2]];
    smallest = (std::min)({smallest, benchmark::angle_deg(b - a, c - a), benchmark::angle_deg(a - b, c - b),
                           benchmark::angle_deg(a - c, b - c)});
  }
  return smallest;
}

inline std::array<double, 3> half_of(const std::array<double, 3>& spacing)
{
  return {spacing[0] / 2, spacing[1] / 2, spacing[2] / 2};
}

// Joint fairing with the named parameters `np` besides the boxes: its points, time and iterations.
template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<Point> fair_jointly(const Soup& soup, int runs, double& seconds, std::size_t& iterations,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  std::vector<Point> P;
  const double cap = 2 * *std::max_element(soup.spacing.begin(), soup.spacing.end());
  seconds = benchmark::median_seconds(runs, [&] {
    P = soup.points;
    iterations = PMP::constrained_fairing_of_interfaces(P, soup.triangles, soup.face_labels, cap,
                                                        CFP::vertex_box_half_extents_map(
                                                          CGAL::make_property_map(soup.half_extents), np))
                   .number_of_iterations;
  });
  return P;
}

} // namespace label_soup

#endif // CGAL_CONSTRAINED_FAIRING_BENCHMARK_LABEL_SOUP_H
