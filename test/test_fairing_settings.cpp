// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The settings of a call as one value, as the front ends pass them (Constrained_fairing_settings.h):
// a call with fairing_settings() gives, bit for bit, the call with the same named parameters, for
// the default method and the paper's; a setting left unset keeps the library's rule, which the
// call that states it gives too (the vertices move along the normals in the default ball and
// slide in boxes and with the accurate objective, and the two differ); set() refuses a name or a
// type not of the table, and changes nothing then; the table's names are distinct; is_box_bound()
// says which bound a call uses, a ball named with box parameters being rejected. The epsilon of
// a label map (label_map_epsilon()) exceeds the diagonal of every box of its nets.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/label_map_epsilon.h>
#include <CGAL/Polygon_mesh_processing/label_surface_nets.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using PMP::Constrained_fairing_settings;
using test::Mesh;
using test::Point;

const double eps = 0.03;

Mesh noisy_sphere()
{
  Mesh m = test::icosphere(2);
  test::add_noise(m, 0.02, 7);
  return m;
}

// The points of `input` faired with `np`.
template <typename NamedParameters>
std::vector<Point> faired(const Mesh& input, const NamedParameters& np)
{
  Mesh m = input;
  const PMP::Constrained_fairing_result r = PMP::constrained_fairing(m, eps, np);
  CHECK(r);
  return test::points(m);
}

// The setting `name` of `settings`, if it is of type T.
template <typename T>
T setting(const Constrained_fairing_settings& settings, const std::string& name)
{
  T found{};
  settings.for_each_named_setting([&](const char* setting, const char*, const auto& value) {
    if constexpr(std::is_same_v<std::decay_t<decltype(value)>, T>)
      if(name == setting)
        found = value;
  });
  return found;
}

void check_same_as_named_parameters()
{
  const Mesh m = noisy_sphere();
  Constrained_fairing_settings settings;
  CHECK(settings.set("objective", PMP::Constrained_fairing_objective::ACCURATE));
  CHECK(settings.set("max_iterations", std::size_t(40)));
  CHECK(settings.set("feature_angle", 30.0));
  CHECK(settings.set("sliver_barrier_weight", 2.0));
  settings.set_box_half_extents({0.02, 0.025, 0.03});
  const std::array<double, 3> extents{0.02, 0.025, 0.03};
  CHECK(test::identical(
    faired(m, CFP::fairing_settings(settings)),
    faired(m, CFP::feature_angle(30.0, CFP::sliver_barrier_weight(
                                         2.0, CFP::box_half_extents(
                                                extents, CFP::fairing_objective(PMP::Constrained_fairing_objective::ACCURATE,
                                                                                CGAL::parameters::number_of_iterations(40))))))));

  Constrained_fairing_settings paper(PMP::Constrained_fairing_method::ACTIVE_SET_NEWTON);
  CHECK(paper.method() == PMP::Constrained_fairing_method::ACTIVE_SET_NEWTON);
  CHECK(paper.set("max_iterations", std::size_t(5)));
  CHECK(paper.set("conjugate_gradient_iterations", std::size_t(3)));
  CHECK(test::identical(faired(m, CFP::fairing_settings(paper)),
                        faired(m, CFP::conjugate_gradient_iterations(
                                    3, CFP::fairing_method(PMP::Constrained_fairing_method::ACTIVE_SET_NEWTON,
                                                           CGAL::parameters::number_of_iterations(5))))));
}

void check_rules_kept()
{
  const Mesh m = noisy_sphere();
  const auto iterations = CGAL::parameters::number_of_iterations(40);
  const Constrained_fairing_settings ball;
  const std::vector<Point> along_normals = faired(m, CFP::fairing_settings(ball, iterations));
  CHECK(test::identical(along_normals, faired(m, CFP::tangential_motion(false, iterations))));
  CHECK(!test::identical(along_normals, faired(m, CFP::tangential_motion(true, iterations))));

  Constrained_fairing_settings box;
  box.set_deviation_bound(PMP::Deviation_bound::BOX);
  CHECK(test::identical(faired(m, CFP::fairing_settings(box, iterations)),
                        faired(m, CFP::tangential_motion(true, CFP::deviation_bound(PMP::Deviation_bound::BOX, iterations)))));

  Constrained_fairing_settings accurate;
  CHECK(accurate.set("objective", PMP::Constrained_fairing_objective::ACCURATE));
  CHECK(test::identical(
    faired(m, CFP::fairing_settings(accurate, iterations)),
    faired(m, CFP::tangential_motion(true, CFP::fairing_objective(PMP::Constrained_fairing_objective::ACCURATE, iterations)))));
}

void check_set()
{
  Constrained_fairing_settings settings;
  const std::size_t iterations = setting<std::size_t>(settings, "max_iterations");
  CHECK(iterations > 0);
  CHECK(!settings.set("no_such_setting", 1.0));
  CHECK(!settings.set("max_iterations", 1.5));
  CHECK(!settings.set("objective", 1));
  CHECK(setting<std::size_t>(settings, "max_iterations") == iterations);
  CHECK(setting<PMP::Constrained_fairing_objective>(settings, "objective") == PMP::Constrained_fairing_objective::FAIREST);
  CHECK(!setting<std::optional<bool> >(settings, "tangential_motion"));
  CHECK(settings.set("tangential_motion", false));
  CHECK(setting<std::optional<bool> >(settings, "tangential_motion") == std::optional<bool>(false));

  std::set<std::string> names, parameters;
  std::size_t count = 0;
  settings.for_each_named_setting([&](const char* name, const char* parameter, const auto&) {
    names.insert(name);
    parameters.insert(parameter);
    ++count;
  });
  CHECK(count > 0 && names.size() == count && parameters.size() == count);
}

void check_box_bound()
{
  const Constrained_fairing_settings unset;
  CHECK(!unset.is_box_bound(false) && unset.is_box_bound(true));
  Constrained_fairing_settings box, ball, extents;
  box.set_deviation_bound(PMP::Deviation_bound::BOX);
  ball.set_deviation_bound(PMP::Deviation_bound::BALL);
  extents.set_box_half_extents({0.01, 0.01, 0.01});
  CHECK(box.is_box_bound(false) && box.is_box_bound(true));
  CHECK(!ball.is_box_bound(false) && ball.is_box_bound(true));
  CHECK(extents.is_box_bound(false));

  // A ball named with a box parameter: the call reads the box, and rejects it.
  Mesh m = noisy_sphere();
  const std::vector<Point> input = test::points(m);
  const auto centres = m.add_property_map<Mesh::Vertex_index, Point>("v:centre").first;
  for(auto v : vertices(m))
    centres[v] = m.point(v);
  const PMP::Constrained_fairing_result r =
    PMP::constrained_fairing(m, eps, CFP::fairing_settings(ball, CFP::vertex_box_center_map(centres)));
  CHECK(!r && r.defect == PMP::Constrained_fairing_defect::BOX_WITH_BALL);
  CHECK(test::identical(test::points(m), input));
}

void check_label_map_epsilon()
{
  const std::array<std::size_t, 3> size{6, 5, 4};
  std::vector<std::uint8_t> labels(size[0] * size[1] * size[2], 0);
  for(std::size_t i = 1; i < 4; ++i)
    for(std::size_t j = 1; j < 4; ++j)
      for(std::size_t k = 1; k < 3; ++k)
        labels[(i * size[1] + j) * size[2] + k] = std::uint8_t(1 + (i + j) % 2);
  for(const std::array<double, 3>& spacing : {std::array<double, 3>{1, 1, 1}, std::array<double, 3>{0.5, 0.75, 2.5}})
  {
    std::vector<Point> points;
    std::vector<std::array<std::size_t, 3> > triangles;
    std::vector<std::array<std::uint8_t, 2> > face_labels;
    std::vector<std::array<double, 3> > half_extents;
    PMP::label_surface_nets(labels.data(), size, spacing, {0, 0, 0}, points, triangles, face_labels, half_extents);
    CHECK(!half_extents.empty());
    const double epsilon = PMP::label_map_epsilon(spacing);
    for(const std::array<double, 3>& h : half_extents)
      CHECK(2 * std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]) < epsilon);
  }
}

int main()
{
  check_same_as_named_parameters();
  check_rules_kept();
  check_set();
  check_box_bound();
  check_label_map_epsilon();
  return test::report("test_fairing_settings");
}
