// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Point sets faired within a bound against CGAL's point smoothers. Points are sampled
// area-uniformly on clean meshes, moved by isotropic Gaussian noise of sigma = 1 % and 2 % of the
// bounding sphere's radius, and faired with eps = 3 sigma by constrained_fairing_of_points()
// (its two objectives) and by jet_smooth_point_set() and bilateral_smooth_point_set(), whose
// results are clamped into the same balls. The peers' parameters are tuned on the first mesh,
// held out, for each noise level, then frozen for the others. Figures, relative to sigma: the
// RMS distance from the result's points to the clean mesh, and the coverage, the RMS distance
// from an independent clean sample to the nearest result point; and the noise estimate
// (estimate_noise_level_of_points()) over sigma.
//
//   point_set_fairing [--points N] [--neighbors K] HELD_OUT.off MESH.off...
//
// Without meshes: CGAL's demo meshes (benchmark/get_demo_meshes.sh) and the bundled ones.

#include "benchmark_support.h"
#include "point_samples.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_points.h>
#include <CGAL/Polygon_mesh_processing/estimate_noise_level_of_points.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/bilateral_smooth_point_set.h>
#include <CGAL/bounding_box.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/jet_smooth_point_set.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using namespace benchmark;
using Point = K::Point_3;
using Vector = K::Vector_3;

struct Shape
{
  std::string name;
  Mesh mesh;
  double radius = 0;
};

struct Figures
{
  double distance = 0; // RMS to the clean mesh, over sigma
  double coverage = 0; // RMS from the clean sample to the nearest point, over sigma
};

Figures measure(const Shape& shape, const std::vector<Point>& points, const std::vector<Point>& clean, double sigma)
{
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> >;
  Tree tree(faces(shape.mesh).first, faces(shape.mesh).second, shape.mesh);
  tree.accelerate_distance_queries();
  Figures figures;
  for(const Point& p : points)
    figures.distance += tree.squared_distance(p);
  figures.distance = std::sqrt(figures.distance / double(points.size())) / sigma;
  using Search = CGAL::Orthogonal_k_neighbor_search<CGAL::Search_traits_3<K> >;
  Search::Tree result(points.begin(), points.end());
  for(const Point& q : clean)
    figures.coverage += Search(result, q, 1).begin()->second;
  figures.coverage = std::sqrt(figures.coverage / double(clean.size())) / sigma;
  return figures;
}

std::vector<Point> jet(std::vector<Point> points, unsigned k)
{
  CGAL::jet_smooth_point_set<CGAL::Parallel_if_available_tag>(points, k);
  return points;
}

// `iterations` passes of the bilateral smoothing, on normals estimated by jet fitting.
std::vector<Point> bilateral(const std::vector<Point>& input, unsigned k, double angle, int iterations)
{
  std::vector<std::pair<Point, Vector> > points;
  for(const Point& p : input)
    points.emplace_back(p, Vector(0, 0, 0));
  const auto maps = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<std::pair<Point, Vector> >())
                      .normal_map(CGAL::Second_of_pair_property_map<std::pair<Point, Vector> >());
  CGAL::jet_estimate_normals<CGAL::Parallel_if_available_tag>(points, k, maps);
  for(int i = 0; i < iterations; ++i)
    CGAL::bilateral_smooth_point_set<CGAL::Parallel_if_available_tag>(points, k, maps.sharpness_angle(angle));
  std::vector<Point> result;
  for(const auto& p : points)
    result.push_back(p.first);
  return result;
}

std::vector<Point> ours(std::vector<Point> points, double eps, std::size_t k, bool accurate)
{
  const auto objective = accurate ? PMP::Constrained_fairing_objective::ACCURATE : PMP::Constrained_fairing_objective::FAIREST;
  const auto result = PMP::constrained_fairing_of_points(points, eps, CFP::number_of_neighbors(k, CFP::fairing_objective(objective)));
  if(!result)
    std::cerr << "  fairing failed: " << result.message << std::endl;
  return points;
}

struct Peer_parameters
{
  unsigned jet_k = 0;
  unsigned bilateral_k = 0;
  double bilateral_angle = 0;
  int bilateral_iterations = 0;
};

// The peers' best parameters on the held-out shape at noise `sigma`.
Peer_parameters tune(const Shape& shape, const std::vector<Point>& clean, const std::vector<Point>& noisy, double sigma)
{
  Peer_parameters best;
  double best_jet = 1e300, best_bilateral = 1e300;
  for(unsigned k : {12u, 24u, 48u, 96u, 192u})
  {
    std::vector<Point> points = jet(noisy, k);
    clamp(points, noisy, 3 * sigma);
    const double d = measure(shape, points, clean, sigma).distance;
    if(d < best_jet)
      best_jet = d, best.jet_k = k;
  }
  for(unsigned k : {24u, 48u, 96u})
    for(double angle : {25., 60.})
      for(int iterations : {1, 3})
      {
        std::vector<Point> points = bilateral(noisy, k, angle, iterations);
        clamp(points, noisy, 3 * sigma);
        const double d = measure(shape, points, clean, sigma).distance;
        if(d < best_bilateral)
          best_bilateral = d, best.bilateral_k = k, best.bilateral_angle = angle, best.bilateral_iterations = iterations;
      }
  std::cout << "  tuned on " << shape.name << ": jet k = " << best.jet_k << "; bilateral k = " << best.bilateral_k
            << ", sharpness " << best.bilateral_angle << ", " << best.bilateral_iterations << " passes" << std::endl;
  return best;
}

int main(int argc, char** argv)
{
  std::size_t n = 50000, k = PMP::internal::Constrained_fairing::default_number_of_neighbors;
  std::vector<std::string> paths;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--points" && i + 1 < argc)
      n = std::stoul(argv[++i]);
    else if(a == "--neighbors" && i + 1 < argc)
      k = std::stoul(argv[++i]);
    else
      paths.push_back(a);
  }
  if(paths.empty())
  {
    const std::string demo = CONSTRAINED_FAIRING_DEMO_DATA, data = CONSTRAINED_FAIRING_DATA_DIR;
    paths = {demo + "/camel.off", data + "/bunny00.off", data + "/elephant.off", demo + "/armadillo.off",
             demo + "/bull.off", demo + "/femur.off", demo + "/homer.off"};
  }
  std::cout << machine_description() << "\n" << n << " points, eps = 3 sigma, " << k << " neighbours\n";
  std::vector<Shape> shapes;
  for(const std::string& path : paths)
  {
    Shape s;
    if(!CGAL::IO::read_polygon_mesh(path, s.mesh) || is_empty(s.mesh))
    {
      std::cout << "skipped (cannot read): " << path << std::endl;
      continue;
    }
    s.name = path.substr(path.find_last_of('/') + 1);
    const auto box = CGAL::bounding_box(s.mesh.points().begin(), s.mesh.points().end());
    s.radius = std::sqrt(CGAL::squared_distance(box.min(), box.max())) / 2;
    shapes.push_back(std::move(s));
  }
  if(shapes.size() < 2)
  {
    std::cout << "skipped: needs a held-out mesh and one more" << std::endl;
    return 0;
  }
  for(double level : {0.01, 0.02})
  {
    std::cout << "\nsigma = " << level * 100 << " % of the radius\n";
    std::vector<std::vector<double> > rows;
    Peer_parameters peers;
    std::cout << std::setw(16) << "shape" << " | distance: jet bilateral fairest accurate | coverage: jet bilateral fairest accurate | noisy\n";
    for(std::size_t s = 0; s < shapes.size(); ++s)
    {
      const Shape& shape = shapes[s];
      const double sigma = level * shape.radius;
      const std::vector<Point> clean = sample(shape.mesh, n, 1), truth = sample(shape.mesh, n, 2);
      const std::vector<Point> noisy = add_gaussian_noise(clean, sigma, 3);
      if(s == 0)
        peers = tune(shape, truth, noisy, sigma);
      std::vector<Point> j = jet(noisy, peers.jet_k), b = bilateral(noisy, peers.bilateral_k, peers.bilateral_angle, peers.bilateral_iterations);
      clamp(j, noisy, 3 * sigma);
      clamp(b, noisy, 3 * sigma);
      const auto t0 = std::chrono::steady_clock::now();
      const std::vector<Point> f = ours(noisy, 3 * sigma, k, false);
      const double seconds = seconds_since(t0);
      const std::vector<Point> a = ours(noisy, 3 * sigma, k, true);
      const Figures fj = measure(shape, j, truth, sigma), fb = measure(shape, b, truth, sigma),
                    ff = measure(shape, f, truth, sigma), fa = measure(shape, a, truth, sigma),
                    fn = measure(shape, noisy, truth, sigma);
      std::cout << std::setw(16) << shape.name << (s == 0 ? "*" : " ") << std::fixed << std::setprecision(3) << "| "
                << fj.distance << " " << fb.distance << " " << ff.distance << " " << fa.distance << " | " << fj.coverage
                << " " << fb.coverage << " " << ff.coverage << " " << fa.coverage << " | " << fn.distance << " | "
                << PMP::estimate_noise_level_of_points(noisy) / sigma << "  ("
                << std::setprecision(1) << seconds << " s)" << std::endl;
      if(s > 0)
        rows.push_back({fj.distance, fb.distance, ff.distance, fa.distance, fj.coverage, fb.coverage, ff.coverage, fa.coverage});
    }
    // geometric means over the shapes not held out, and the worst ratios to the better peer
    std::vector<double> mean(8, 0.);
    double worst_fairest = 0, worst_accurate = 0, worst_cov_f = 0, worst_cov_a = 0;
    for(const auto& r : rows)
    {
      for(std::size_t c = 0; c < 8; ++c)
        mean[c] += std::log(r[c]) / double(rows.size());
      const double peer = std::min(r[0], r[1]), peer_cov = std::min(r[4], r[5]);
      worst_fairest = std::max(worst_fairest, r[2] / peer);
      worst_accurate = std::max(worst_accurate, r[3] / peer);
      worst_cov_f = std::max(worst_cov_f, r[6] / peer_cov);
      worst_cov_a = std::max(worst_cov_a, r[7] / peer_cov);
    }
    for(double& m : mean)
      m = std::exp(m);
    const double peer = std::min(mean[0], mean[1]), peer_cov = std::min(mean[4], mean[5]);
    std::cout << std::setprecision(3) << "geometric mean (held out excluded): distance jet " << mean[0] << ", bilateral "
              << mean[1] << ", fairest " << mean[2] << " (" << mean[2] / peer << " x the better peer, worst shape "
              << worst_fairest << " x), accurate " << mean[3] << " (" << mean[3] / peer << " x, worst " << worst_accurate
              << " x); coverage fairest " << mean[6] / peer_cov << " x, accurate " << mean[7] / peer_cov
              << " x the better peer's (worst " << worst_cov_f << ", " << worst_cov_a << ")" << std::endl;
  }
  return 0;
}
