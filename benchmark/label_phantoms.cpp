// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Label maps of the shapes a ball cut by a plane does not cover, judged against their analytic
// interfaces: a slab tilted against the grid inside a ball, tori whose tubes are 3, 5 and 8 mm
// across (their axes tilted), and a torus threaded through a ball; each on 1 mm cubic voxels and
// on thick slices of 0.8 x 0.8 x 2.4 mm. For each map, the RMS distance of the points to their
// true interface (a point where three labels meet: the root of the summed squared distances to
// its two surfaces) for the raw surface nets, VTK's clamped Laplacian at its best count of 1 to
// 1024 iterations, and constrained_fairing_of_interfaces() with each objective; the ratios and
// their geometric means over the maps; the smallest angle; the mean signed distance of the
// raw and the faired points on one surface. Then the ratios of the raw nets and of the clamp
// (at its best count there) to the default fairing measured on the faces, the surface users
// see: a surface whose faces are chords of a curved one, holding its volume, has its points
// outside it. Last, on the points of one surface, the ratio of the raw nets to the default, and
// the same with the default's mean offset taken away per band of the true normal's tilt to the
// slices: how close a fix of the offsets alone (a label's volume, a cap's height) could come.
//
//   label_phantoms [--threads K] [--margin M]

#include "label_soup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using benchmark::Point;
using namespace label_soup;

using Vec = std::array<double, 3>;
using Distance = std::function<double(const Vec&)>;

Vec unit(Vec v)
{
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}

double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Distance ball(Vec c, double R)
{
  return [=](const Vec& p) {
    return std::sqrt((p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]) + (p[2] - c[2]) * (p[2] - c[2])) - R;
  };
}

// The solid torus of centre c, axis a, radii R (of the ring) and r (of the tube).
Distance torus(Vec c, Vec a, double R, double r)
{
  a = unit(a);
  return [=](const Vec& p) {
    const Vec q{p[0] - c[0], p[1] - c[1], p[2] - c[2]};
    const double h = dot(q, a);
    const double rho = std::sqrt((std::max)(0., dot(q, q) - h * h));
    return std::sqrt((rho - R) * (rho - R) + h * h) - r;
  };
}

// A map's regions, by priority: a voxel centre takes the label 1 + k of the first region k whose
// signed distance is negative there, else the background 0. The interface of labels a < b is
// then the zero set of region a - 1 (of region b - 1 when a is the background).
struct Phantom
{
  std::string name;
  double extent; // of the grid, in mm, centred on the origin
  std::vector<Distance> regions;

  double distance(const std::set<Label>& around, const Point& p) const
  {
    std::vector<Label> surfaces;
    for(Label l : around)
      if(l != 0)
        surfaces.push_back(l);
    if(around.count(0) == 0)
      surfaces.pop_back();
    double sum = 0;
    for(Label l : surfaces)
    {
      const double d = regions[std::size_t(l - 1)]({p.x(), p.y(), p.z()});
      sum += d * d;
    }
    return std::sqrt(sum);
  }

  // The region whose zero set is point v's interface, where v lies on one surface only, else null.
  const Distance* surface_of(const Soup& soup, std::size_t v) const
  {
    if(soup.around[v].size() != 2)
      return nullptr;
    const Label l = soup.around[v].count(0) ? *soup.around[v].rbegin() : *soup.around[v].begin();
    return &regions[std::size_t(l - 1)];
  }

  // The mean signed distance of the points on one surface (positive outside its region): how
  // far a method moves the surfaces outwards, as the bending energy does to tubes.
  double bias(const Soup& soup, const std::vector<Point>& P) const
  {
    double sum = 0;
    std::size_t count = 0;
    for(std::size_t v = 0; v < P.size(); ++v)
      if(const Distance* region = surface_of(soup, v))
      {
        sum += (*region)({P[v].x(), P[v].y(), P[v].z()});
        ++count;
      }
    return sum / double((std::max)(count, std::size_t(1)));
  }

  // The RMS distance of the surface itself, as users see it: three points per triangle (at
  // barycentric 2/3, 1/6, 1/6), weighted by its area, each from the interface of its labels.
  double face_rms(const Soup& soup, const std::vector<Point>& P) const
  {
    double sum = 0, area = 0;
    for(std::size_t f = 0; f < soup.triangles.size(); ++f)
    {
      const Label a = (std::min)(soup.face_labels[f][0], soup.face_labels[f][1]);
      const Label b = (std::max)(soup.face_labels[f][0], soup.face_labels[f][1]);
      const Distance& region = regions[std::size_t((a == 0 ? b : a) - 1)];
      const Point &p = P[soup.triangles[f][0]], &q = P[soup.triangles[f][1]], &r = P[soup.triangles[f][2]];
      const double A = std::sqrt(CGAL::cross_product(q - p, r - p).squared_length()) / 2;
      for(const Point& x : {CGAL::barycenter(p, 4, q, 1, r, 1), CGAL::barycenter(p, 1, q, 4, r, 1),
                            CGAL::barycenter(p, 1, q, 1, r, 4)})
      {
        const double d = region({x.x(), x.y(), x.z()});
        sum += A / 3 * d * d;
      }
      area += A;
    }
    return std::sqrt(sum / area);
  }

  // The RMS distance of the points on one surface, and the same with the mean signed distance
  // of each band of them taken away, the bands those whose true normal is within 30 degrees of
  // the slices' normal (the caps), 30 to 60 degrees, and further: at best what a method that
  // knew the truth's offsets, a label's volume or a cap's height, could remove from the error.
  std::array<double, 2> one_surface_rms(const Soup& soup, const std::vector<Point>& P) const
  {
    std::array<double, 3> sum{0, 0, 0}, squares{0, 0, 0}, count{0, 0, 0};
    for(std::size_t v = 0; v < P.size(); ++v)
      if(const Distance* surface = surface_of(soup, v))
      {
        const Distance& region = *surface;
        const Vec p{P[v].x(), P[v].y(), P[v].z()};
        const double step = 1e-5;
        Vec normal;
        for(std::size_t c = 0; c < 3; ++c)
        {
          Vec a = p, b = p;
          a[c] += step, b[c] -= step;
          normal[c] = region(a) - region(b);
        }
        const double cosine = std::abs(unit(normal)[2]);
        const std::size_t band = cosine > std::cos(CGAL_PI / 6) ? 0 : cosine > std::cos(CGAL_PI / 3) ? 1 : 2;
        const double d = region(p);
        sum[band] += d, squares[band] += d * d, ++count[band];
      }
    double all = 0, offsets_removed = 0, n = 0;
    for(std::size_t band = 0; band < 3; ++band)
      if(count[band] > 0)
      {
        all += squares[band], n += count[band];
        offsets_removed += squares[band] - sum[band] * sum[band] / count[band];
      }
    return {std::sqrt(all / n), std::sqrt(offsets_removed / n)};
  }

  double rms(const Soup& soup, const std::vector<Point>& P) const
  {
    double sum = 0;
    for(std::size_t v = 0; v < P.size(); ++v)
    {
      const double d = distance(soup.around[v], P[v]);
      sum += d * d;
    }
    return std::sqrt(sum / double(P.size()));
  }
};

std::vector<Phantom> phantoms()
{
  const Vec tilted = unit({0.3, 0.5, 0.81});
  const Distance slab_in_ball = [ball = ball({0, 0, 0}, 20), tilted](const Vec& p) {
    return (std::max)(std::abs(dot(p, tilted)) - 2.5, ball(p));
  };
  const Vec axis{0.2, 0.35, 1};
  return {{"tilted slab 5 mm in a ball", 46, {slab_in_ball, ball({0, 0, 0}, 20)}},
          {"torus, tube 3 mm", 34, {torus({0, 0, 0}, axis, 12, 1.5)}},
          {"torus, tube 5 mm", 36, {torus({0, 0, 0}, axis, 12, 2.5)}},
          {"torus, tube 8 mm", 38, {torus({0, 0, 0}, axis, 12, 4)}},
          {"torus through a ball", 44, {torus({9, 0, 0}, {0.1, 1, 0.2}, 9, 2.5), ball({0, 0, 0}, 8)}}};
}

Soup make_phantom_soup(const Phantom& phantom, const std::array<double, 3>& spacing, double margin)
{
  std::array<std::size_t, 3> size;
  for(int c = 0; c < 3; ++c)
    size[std::size_t(c)] = std::size_t(std::ceil(phantom.extent / spacing[std::size_t(c)])) + 1;
  std::vector<Label> labels(size[0] * size[1] * size[2], 0);
  for(std::size_t i = 0; i < size[0]; ++i)
    for(std::size_t j = 0; j < size[1]; ++j)
      for(std::size_t k = 0; k < size[2]; ++k)
      {
        const Vec p{(double(i) - double(size[0] - 1) / 2) * spacing[0],
                    (double(j) - double(size[1] - 1) / 2) * spacing[1],
                    (double(k) - double(size[2] - 1) / 2) * spacing[2]};
        for(std::size_t r = 0; r < phantom.regions.size(); ++r)
          if(phantom.regions[r](p) < 0)
          {
            labels[(i * size[1] + j) * size[2] + k] = Label(r + 1);
            break;
          }
      }
  Soup soup = make_soup(labels, size, spacing, margin);
  // Centred on the origin, as the phantom.
  for(Point& p : soup.points)
    p = Point(p.x() - double(size[0] - 1) / 2 * spacing[0], p.y() - double(size[1] - 1) / 2 * spacing[1],
              p.z() - double(size[2] - 1) / 2 * spacing[2]);
  return soup;
}

struct Row
{
  double raw, clamp, default_objective, accurate;
  double raw_faces, clamp_faces, default_faces; // the same on the faces
  double raw_one_surface, default_one_surface, default_offsets_removed; // one_surface_rms()
};

Row measure(const Phantom& phantom, const std::array<double, 3>& spacing, double margin)
{
  const Soup soup = make_phantom_soup(phantom, spacing, margin);
  const Clamped_laplacian laplacian(soup);
  std::vector<Point> L = soup.points;
  std::size_t best_count = 0, done = 0;
  double best = phantom.rms(soup, L), best_faces = phantom.face_rms(soup, L);
  for(std::size_t count = 1; count <= 1024; count *= 2)
  {
    for(; done < count; ++done)
      laplacian.step(L);
    const double rms = phantom.rms(soup, L);
    if(rms < best)
      best = rms, best_count = count;
    best_faces = (std::min)(best_faces, phantom.face_rms(soup, L));
  }
  double seconds = 0;
  std::size_t iterations = 0;
  const std::vector<Point> P = fair_jointly(soup, 1, seconds, iterations);
  std::size_t accurate_iterations = 0;
  const std::vector<Point> A = fair_jointly(soup, 1, seconds, accurate_iterations,
                                            CFP::fairing_objective(PMP::Constrained_fairing_objective::ACCURATE));
  const std::array<double, 2> one_surface = phantom.one_surface_rms(soup, P);
  const Row row{phantom.rms(soup, soup.points), best, phantom.rms(soup, P), phantom.rms(soup, A),
                phantom.face_rms(soup, soup.points), best_faces, phantom.face_rms(soup, P),
                phantom.one_surface_rms(soup, soup.points)[0], one_surface[0], one_surface[1]};
  std::cout << std::left << std::setw(28) << phantom.name << std::right << std::setw(4) << spacing[0] << "x"
            << spacing[1] << "x" << std::setw(3) << spacing[2] << std::setw(8) << soup.points.size() << std::setw(9)
            << row.raw << std::setw(9) << row.clamp << std::setw(5) << best_count << std::setw(9)
            << row.default_objective << std::setw(5) << iterations << std::setw(9) << row.accurate << std::setw(5)
            << accurate_iterations << std::setw(8) << row.raw / row.default_objective << std::setw(8)
            << row.clamp / row.default_objective << std::setw(8) << row.raw / row.accurate << std::setw(8)
            << row.clamp / row.accurate << std::setw(8) << smallest_angle(soup, P) << std::setw(9)
            << phantom.bias(soup, soup.points) << std::setw(9) << phantom.bias(soup, P) << std::setw(8)
            << row.raw_faces / row.default_faces << std::setw(8) << row.clamp_faces / row.default_faces << std::setw(8)
            << row.raw_one_surface / row.default_one_surface << std::setw(8)
            << row.raw_one_surface / row.default_offsets_removed << std::endl;
  return row;
}

int main(int argc, char* argv[])
{
  const benchmark::Arguments arguments(argc, argv);
  const benchmark::Thread_limit threads(arguments);
  const double margin = std::stod(arguments.option("margin", std::to_string(PMP::label_box_margin)));
  std::cout << benchmark::machine_description() << ", boxes' margin " << margin << "\n"
            << std::setprecision(3) << "RMS distance to the true interfaces (mm); ratios: raw or clamp over the "
            << "fairing\nmap                         voxels (mm) points      raw    clamp   at  default  its "
            << "accurate  its raw/def clamp/def raw/acc clamp/acc angle  raw bias def bias faces: raw/def clamp/def one surface: raw/def less offsets\n";
  std::array<double, 8> log_sum{0, 0, 0, 0, 0, 0, 0, 0};
  std::array<double, 8> worst{1e300, 1e300, 1e300, 1e300, 1e300, 1e300, 1e300, 1e300};
  std::size_t count = 0;
  for(const Phantom& phantom : phantoms())
    for(const std::array<double, 3>& spacing : {std::array<double, 3>{1, 1, 1}, std::array<double, 3>{0.8, 0.8, 2.4}})
    {
      const Row r = measure(phantom, spacing, margin);
      const std::array<double, 8> ratio{r.raw / r.default_objective,        r.clamp / r.default_objective,
                                        r.raw / r.accurate,                 r.clamp / r.accurate,
                                        r.raw_faces / r.default_faces,      r.clamp_faces / r.default_faces,
                                        r.raw_one_surface / r.default_one_surface,
                                        r.raw_one_surface / r.default_offsets_removed};
      for(std::size_t k = 0; k < 8; ++k)
        log_sum[k] += std::log(ratio[k]), worst[k] = (std::min)(worst[k], ratio[k]);
      ++count;
    }
  std::cout << "geometric means (worst): default " << std::exp(log_sum[0] / double(count)) << "x raw (" << worst[0]
            << "), " << std::exp(log_sum[1] / double(count)) << "x clamp (" << worst[1] << "); accurate "
            << std::exp(log_sum[2] / double(count)) << "x raw (" << worst[2] << "), "
            << std::exp(log_sum[3] / double(count)) << "x clamp (" << worst[3] << ")\n"
            << "on the faces: default " << std::exp(log_sum[4] / double(count)) << "x raw (" << worst[4] << "), "
            << std::exp(log_sum[5] / double(count)) << "x clamp (" << worst[5] << ")\n"
            << "on the points of one surface: default " << std::exp(log_sum[6] / double(count)) << "x raw (" << worst[6]
            << "), with each band's mean offset removed " << std::exp(log_sum[7] / double(count)) << "x raw ("
            << worst[7] << ")\n";
  return 0;
}
