// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The accurate objective (Constrained_fairing_objective::ACCURATE): the fidelity term's
// gradient against finite differences, its anchor (Fidelity_anchor.h) denoising without
// flattening or shrinking and within the bound, the user's bound exactly in double, the
// objective never rising with every method, the result closer to the true surface than the
// fairest one on a real mesh, and bad fidelity weights rejected with the mesh untouched.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Deviation_bounds.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Fidelity_anchor.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fidelity_term.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Sliver_barrier.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Fairing_settings.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cmath>
#include <limits>
#include <random>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
namespace CF = PMP::internal::Constrained_fairing;
using test::Mesh;
using test::Point;

CF::Points to_points(const Mesh& m)
{
  CF::Points X(num_vertices(m), 3);
  for(auto v : vertices(m))
    X.row(v.idx()) << m.point(v).x(), m.point(v).y(), m.point(v).z();
  return X;
}

// The objective with its fidelity term against central differences, away from the anchor
// (where the term's gradient vanishes), and the fidelity term's value by hand.
void check_gradient()
{
  const Mesh m = test::icosphere(2);
  const CF::Points X0 = to_points(m);
  const CF::Hinge_mesh hinges(m, get(boost::vertex_index, m));
  const double t = 0.1 * test::mean_edge_length(m);
  CF::Points X = X0, anchor = X0;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-t, t);
  for(Eigen::Index k = 0; k < X.size(); ++k)
  {
    X.data()[k] += u(rng);
    anchor.data()[k] += u(rng);
  }
  const double sliver_weight = CF::default_sliver_barrier_weight;
  CF::Fairing_objective plain(hinges, X0, sliver_weight, CF::default_sliver_threshold),
    objective(hinges, X0, sliver_weight, CF::default_sliver_threshold);
  CF::Fidelity_term fidelity(1000, [t](std::size_t) { return t; }, anchor);
  objective.add_term(fidelity);

  // The term by hand: mu / n * sum |x_i - a_i|^2 / t^2 over the n vertices.
  double sum = 0;
  for(std::size_t i = 0; i < num_vertices(m); ++i)
    sum += (CF::point(X, i) - CF::point(anchor, i)).squaredNorm() / (t * t);
  const double by_hand = 1000 * sum / double(num_vertices(m));
  CHECK(std::abs(objective.value(X) - plain.value(X) - by_hand) <= 1e-12 * by_hand);
  CHECK(objective.value(anchor) == plain.value(anchor));
  // A vertex of tolerance 0 does not move: it has no term and is not counted in n.
  CF::Fairing_objective pinned(hinges, X0, sliver_weight, CF::default_sliver_threshold);
  CF::Fidelity_term pinned_fidelity(1000, [t](std::size_t i) { return i == 0 ? 0. : t; }, anchor);
  pinned.add_term(pinned_fidelity);
  const double pinned_by_hand =
    1000 * (sum - (CF::point(X, 0) - CF::point(anchor, 0)).squaredNorm() / (t * t)) / double(num_vertices(m) - 1);
  CHECK(std::abs(pinned.value(X) - plain.value(X) - pinned_by_hand) <= 1e-12 * pinned_by_hand);

  CF::Points G;
  objective.value_and_gradient(X, G);
  const double error = test::gradient_error(X, G, [&](const CF::Points& Y) { return objective.value(Y); }, 1e-7);
  std::cout << "  objective gradient vs finite differences: relative error " << error << std::endl;
  CHECK(error < 1e-6);
}

// The barrier against slivers of the output `m`, relative to the input `m0`.
double sliver_barrier(const Mesh& m0, const Mesh& m)
{
  const test::Indexed in(m0), out(m);
  return CF::Sliver_barrier(in.hinges, in.X, CF::default_sliver_barrier_weight, CF::default_sliver_threshold)
    .value(out.X);
}

// The bundled noisy elephant (noise radius 0.25 h): the accurate objective ends closer to the
// clean elephant's surface, the user's bound holds exactly, the objective never rises, and the
// energies it reports are the mesh's, recomputed here.
void check_elephant()
{
  Mesh clean, noisy;
  CHECK(CGAL::IO::read_polygon_mesh(CONSTRAINED_FAIRING_DATA_DIR "/elephant.off", clean));
  CHECK(CGAL::IO::read_polygon_mesh(CONSTRAINED_FAIRING_DATA_DIR "/elephant_noisy.off", noisy));
  const double eps = 0.25 * 0.0219972;
  const std::vector<Point> input = test::points(noisy);
  for(auto method : {PMP::Constrained_fairing_method::QUASI_NEWTON, PMP::Constrained_fairing_method::ACTIVE_SET_NEWTON,
                     PMP::Constrained_fairing_method::PROJECTED_GRADIENT})
  {
    Mesh fairest = noisy, accurate = noisy;
    const auto r_fairest = PMP::constrained_fairing(fairest, eps, CFP::fairing_method(method));
    double previous = std::numeric_limits<double>::infinity();
    bool monotone = true;
    const auto r = PMP::constrained_fairing(
      accurate, eps,
      CFP::fairing_objective(PMP::Constrained_fairing_objective::ACCURATE,
                             CFP::fairing_method(method, CFP::iteration_callback([&](std::size_t, double e) {
                               monotone = monotone && e <= previous;
                               previous = e;
                               return true;
                             }))));
    CHECK(r && r_fairest);
    CHECK(monotone);
    CHECK(r.final_energy <= r.initial_energy);
    CHECK(test::bound_violation(test::points(accurate), input, eps, PMP::Deviation_bound::BALL) <= 0);
    // The bending energies reported are the meshes'. The fairest objective is the bending
    // energy plus the barrier against slivers; the accurate one adds a positive fidelity term.
    const auto near = [](double x, double y) { return std::abs(x - y) <= 1e-9 * std::abs(y); };
    CHECK(r.number_of_degenerate_edges == 0); // else the plain sums below would not be the energy
    const double bending_input = test::plain_bending_energy(noisy), bending = test::plain_bending_energy(accurate),
                 bending_fairest = test::plain_bending_energy(fairest);
    CHECK(near(r.initial_bending_energy, bending_input) && near(r_fairest.initial_bending_energy, bending_input));
    CHECK(near(r.final_bending_energy, bending) && near(r_fairest.final_bending_energy, bending_fairest));
    CHECK(near(r_fairest.initial_energy, bending_input + sliver_barrier(noisy, noisy)));
    CHECK(near(r_fairest.final_energy, bending_fairest + sliver_barrier(noisy, fairest)));
    CHECK(r.final_energy - (bending + sliver_barrier(noisy, accurate)) > 1e-6 * r.final_energy);
    const double rms_accurate = test::surface_rms(accurate, clean), rms_fairest = test::surface_rms(fairest, clean),
                 rms_input = test::surface_rms(noisy, clean);
    std::cout << "  elephant, method " << int(method) << ": surface RMS input " << rms_input << ", fairest "
              << rms_fairest << ", accurate " << rms_accurate << "; bending energy fairest "
              << r_fairest.final_bending_energy << ", accurate " << r.final_bending_energy << std::endl;
    CHECK(rms_accurate < 0.9 * rms_fairest);
    CHECK(rms_accurate < 0.8 * rms_input);
    CHECK(r.final_bending_energy < 0.5 * r.initial_bending_energy);
  }
}

// A per-vertex tolerance of 0 and fixed vertices stay bit-identical with the accurate
// objective too, and a box bound holds exactly.
void check_fixed_and_box()
{
  Mesh m = test::icosphere(3);
  const double eps = 0.25 * test::mean_edge_length(m);
  test::add_noise(m, eps, 5);
  const std::vector<Point> input = test::points(m);
  auto tolerance = m.add_property_map<Mesh::Vertex_index, double>("v:t", eps).first;
  for(auto v : vertices(m))
    if(v.idx() % 7 == 0)
      tolerance[v] = 0;
  Mesh ball = m, box = m;
  CHECK(PMP::constrained_fairing(ball, eps, CFP::fairing_objective(PMP::Constrained_fairing_objective::ACCURATE,
                                                                  CFP::vertex_tolerance_map(tolerance))));
  bool pinned = true;
  for(auto v : vertices(ball))
    if(v.idx() % 7 == 0)
      pinned = pinned && test::identical({ball.point(v)}, {input[v.idx()]});
  CHECK(pinned);
  CHECK(test::bound_violation(test::points(ball), input, eps, PMP::Deviation_bound::BALL) <= 0);
  CHECK(PMP::constrained_fairing(box, eps, CFP::fairing_objective(PMP::Constrained_fairing_objective::ACCURATE,
                                                                 CFP::deviation_bound(PMP::Deviation_bound::BOX))));
  CHECK(test::bound_violation(test::points(box), input, eps, PMP::Deviation_bound::BOX) <= 0);
}

void check_bad_weights()
{
  for(double mu : {-1., std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
  {
    Mesh m = test::icosphere(2);
    test::add_noise(m, 0.01, 1);
    const std::vector<Point> before = test::points(m);
    const auto r = PMP::constrained_fairing(
      m, 0.01, CFP::fidelity_weight(mu, CFP::fairing_objective(PMP::Constrained_fairing_objective::ACCURATE)));
    CHECK(r.status == PMP::Constrained_fairing_status::INVALID_INPUT);
    CHECK(r.message.find("fidelity_weight") != std::string::npos);
    CHECK(r.defect == PMP::Constrained_fairing_defect::INVALID_FIDELITY_WEIGHT);
    CHECK(test::identical(test::points(m), before));
  }
  // Weight 0: the bending energy alone, the same as the fairest objective.
  Mesh m = test::icosphere(2);
  test::add_noise(m, 0.01, 1);
  Mesh fairest = m;
  const auto r = PMP::constrained_fairing(
    m, 0.01, CFP::fidelity_weight(0., CFP::fairing_objective(PMP::Constrained_fairing_objective::ACCURATE)));
  const auto r_fairest = PMP::constrained_fairing(fairest, 0.01);
  CHECK(r && r.final_energy == r_fairest.final_energy && r.final_bending_energy == r_fairest.final_bending_energy);
  CHECK(test::identical(test::points(m), test::points(fairest)));
}

// The anchor of a plane and of a sphere: a clean plane, free to move by t, keeps every height
// exactly 0; noise uniform in a ball of radius t falls to half or less along the normal; the
// sphere's radius moves by less than a fifth of the noise radius; every vertex stays within t
// of its input, exactly.
void check_anchor()
{
  std::mt19937 rng(5);
  // Noise of radius `noise` (0: none), then the anchor within the ball of radius t.
  const auto denoise = [&](const Mesh& clean, double noise, double t, CF::Points& X0, CF::Points& X) {
    X0 = to_points(clean);
    std::uniform_real_distribution<double> u(-1, 1);
    for(Eigen::Index i = 0; i < X0.rows(); ++i)
    {
      Eigen::Vector3d d;
      do
        d = Eigen::Vector3d(u(rng), u(rng), u(rng));
      while(d.squaredNorm() > 1);
      X0.row(i) += noise * d.transpose();
    }
    X = X0;
    const CF::Hinge_mesh hinges(clean, get(boost::vertex_index, clean));
    CF::Fidelity_anchor(hinges).apply(CF::Ball_bound(X0, t), X);
    for(Eigen::Index i = 0; i < X0.rows(); ++i)
      CHECK((X.row(i) - X0.row(i)).squaredNorm() <= t * t);
  };
  CF::Points X0, X;
  const Mesh plane = test::plane_patch(30);
  const double h = test::mean_edge_length(plane);
  denoise(plane, 0, 0.25 * h, X0, X);
  CHECK(X.col(2).cwiseAbs().maxCoeff() == 0);
  CHECK(X != X0); // the vertices did move, along the plane
  denoise(plane, 0.25 * h, 0.25 * h, X0, X);
  std::cout << "plane, noise 0.25 h: RMS height " << std::sqrt(X0.col(2).squaredNorm() / double(X0.rows()))
            << " -> " << std::sqrt(X.col(2).squaredNorm() / double(X.rows())) << std::endl;
  CHECK(X.col(2).squaredNorm() * 4 <= X0.col(2).squaredNorm());

  const Mesh sphere = test::icosphere(3);
  const double hs = test::mean_edge_length(sphere);
  denoise(sphere, 0.25 * hs, 0.25 * hs, X0, X);
  double radius = 0, error2 = 0, error2_input = 0;
  for(Eigen::Index i = 0; i < X.rows(); ++i)
  {
    radius += X.row(i).norm();
    error2 += CGAL::square(X.row(i).norm() - 1);
    error2_input += CGAL::square(X0.row(i).norm() - 1);
  }
  radius /= double(X.rows());
  std::cout << "sphere, noise 0.25 h: mean radius " << radius << ", RMS radial error " << std::sqrt(error2_input / double(X.rows()))
            << " -> " << std::sqrt(error2 / double(X.rows())) << std::endl;
  CHECK(std::abs(radius - 1) <= 0.05 * hs);
  CHECK(error2 * 4 <= error2_input);
}

int main()
{
  check_gradient();
  check_anchor();
  check_elephant();
  check_fixed_and_box();
  check_bad_weights();
  return test::report("test_accurate_objective");
}
