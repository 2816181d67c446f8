// The defaults as the documentation states them, against the settings (Fairing_settings.h): the
// reference manual's named parameters (constrained_fairing.h) and its repair of label surfaces
// (constrained_fairing_of_interfaces.h), the user manual, the README and the tool's usage. A
// default changed in the code fails here until every text that states it is changed too; this runs
// in every build, with or without the Python module (whose docstrings
// python/tests/test_defaults.py checks against the same settings).

#include "test_support.h"

#include "front_end/Epsilon_grammar.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Sliver_barrier.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Named_settings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_interfaces/Crossing_repair.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

namespace CF = CGAL::Polygon_mesh_processing::internal::Constrained_fairing;
using Method = CGAL::Polygon_mesh_processing::Constrained_fairing_method;

// The file at `path` under the source tree, its runs of white space made single spaces.
std::string text_of(const std::string& path)
{
  std::ifstream in(std::string(CONSTRAINED_FAIRING_SOURCE_DIR) + "/" + path);
  CHECK(in.good());
  std::stringstream buffer;
  buffer << in.rdbuf();
  return std::regex_replace(buffer.str(), std::regex("\\s+"), " ");
}

// A number as the texts state it: integers as integers, others in the shortest scientific form
// that reads back exactly (1.25e-4, 1e-3).
std::string number(double x)
{
  if(x == std::floor(x) && std::abs(x) < 1e15)
    return std::to_string(static_cast<long long>(x));
  char buffer[64];
  for(int digits = 0; digits < 17; ++digits)
  {
    std::snprintf(buffer, sizeof buffer, "%.*e", digits, x);
    if(std::stod(buffer) == x)
      break;
  }
  const std::string text(buffer);
  const std::size_t e = text.find('e');
  return text.substr(0, e) + "e" + std::to_string(std::stoi(text.substr(e + 1)));
}

// A fraction in percent, as the texts state it: 0.01 as "1 %".
std::string percent(double fraction)
{
  std::ostringstream text;
  text << std::round(100 * fraction * 1e12) / 1e12 << " %";
  return text.str();
}

bool states(const std::string& text, const std::string& phrase)
{
  const bool found = text.find(phrase) != std::string::npos;
  if(!found)
    std::cerr << "not stated: " << phrase << std::endl;
  return found;
}

// \cgalParamDefault{...} of each named parameter of constrained_fairing.h (the text up to the
// next \cgalParam command, less its closing brace).
std::map<std::string, std::string> reference_defaults(const std::string& header)
{
  std::map<std::string, std::string> defaults;
  const std::string begin = "\\cgalParamNBegin{", fallback = "\\cgalParamDefault{";
  for(std::size_t at = header.find(begin); at != std::string::npos; at = header.find(begin, at + 1))
  {
    const std::size_t name = at + begin.size(), end = header.find("\\cgalParamNEnd", at);
    const std::size_t d = header.find(fallback, at);
    if(d == std::string::npos || d > end)
      continue;
    const std::size_t from = d + fallback.size(), to = header.rfind('}', header.find("\\cgalParam", from));
    defaults[header.substr(name, header.find('}', name) - name)] = header.substr(from, to - from);
  }
  return defaults;
}

int main()
{
  const CF::Fairing_settings q(Method::QUASI_NEWTON), p(Method::ACTIVE_SET_NEWTON);
  const CF::Fairing_settings g(Method::PROJECTED_GRADIENT);
  // The paper's methods share their defaults.
  CHECK(p.options.max_iterations == g.options.max_iterations && p.options.threshold == g.options.threshold &&
        p.options.window == g.options.window && p.options.smoothing_steps == g.options.smoothing_steps);

  // The reference manual.
  const std::string header = text_of("include/CGAL/Polygon_mesh_processing/constrained_fairing.h");
  const std::map<std::string, std::string> defaults = reference_defaults(header);
  const auto per_method = [](double quasi_newton, double paper) {
    return "`" + number(quasi_newton) + "` for `QUASI_NEWTON`, `" + number(paper) + "` for the paper's methods";
  };
  const std::string remaining = percent(q.options.remaining_fraction);
  CHECK(p.options.remaining_fraction == 0);
  CHECK(states(header, "is at most " + remaining + " of the energy, and, along the normals,"));
  CHECK(p.options.remaining_motion == 0 && q.options.remaining_motion > 0);
  const std::string motion = percent(q.options.remaining_motion);
  CHECK(states(header, "move across itself is at most " + motion + " of `epsilon`) or the last three"));
  CHECK(states(header, "the surface's motion still to come at most " + motion + " of"));
  CHECK(states(header, "decrease still to come is at most " + remaining + " of the energy"));
  CHECK(defaults.at("number_of_iterations") ==
        per_method(double(q.options.max_iterations), double(p.options.max_iterations)));
  CHECK(defaults.at("energy_decrease_threshold") == per_method(q.options.threshold, p.options.threshold));
  CHECK(defaults.at("initial_smoothing_steps") ==
        per_method(double(q.options.smoothing_steps), double(p.options.smoothing_steps)));
  CHECK(defaults.at("fidelity_weight") == "`" + number(q.fidelity_weight) + "`");
  CHECK(defaults.at("sliver_barrier_weight") == "`" + number(q.sliver_barrier_weight) + "`");
  CHECK(defaults.at("conjugate_gradient_iterations") == "`" + number(double(p.options.cg_iterations)) + "`");
  CHECK(q.objective == CGAL::Polygon_mesh_processing::Constrained_fairing_objective::FAIREST &&
        defaults.at("fairing_objective") == "`Constrained_fairing_objective::FAIREST`");
  // Every setting of the table is a documented named parameter.
  CF::Fairing_settings table;
  CF::for_each_named_setting(table, [&](const char*, const char* parameter, auto, const auto&) {
    CHECK(states(header, std::string("\\cgalParamNBegin{") + parameter + "}"));
  });
  // The barrier's needles of 3 degrees on meshes.
  CHECK(std::abs(CF::Sliver_barrier::threshold_of_angle(3) - q.sliver_threshold) < 1e-15);
  CHECK(states(header, "about that of a needle with a 3 degree angle"));

  // The user manual.
  const std::string manual = text_of("doc/Constrained_fairing/Constrained_fairing.txt");
  const int exponent = int(std::lround(std::log10(q.fidelity_weight)));
  CHECK(std::pow(10., exponent) == q.fidelity_weight);
  CHECK(states(manual, "by default `" + number(q.options.threshold) + "` over the last " +
                         std::to_string(q.options.window) + " iterations for the quasi-Newton method"));
  CHECK(p.options.window == 3);
  CHECK(states(manual, "`" + number(p.options.threshold) + "` over the last three for the paper's methods"));
  CHECK(states(manual, "`number_of_iterations` (default " + std::to_string(q.options.max_iterations) +
                         " for the quasi-Newton method, " + std::to_string(p.options.max_iterations) +
                         " for the others)"));
  CHECK(states(manual, "`conjugate_gradient_iterations` (default " + std::to_string(p.options.cg_iterations) + ")"));
  CHECK(states(manual, "`sliver_barrier_weight` (default " + number(q.sliver_barrier_weight) + ";"));
  CHECK(states(manual, "`fidelity_weight` (default \\f$ 10^" + std::to_string(exponent) + " \\f$;"));
  CHECK(states(manual, "waits until what is left to gain is at most " + remaining + " of the energy"));
  CHECK(states(manual,
               "pushes back needles under " + number(q.interface_sliver_angle) + " degrees, not 3 as on meshes"));

  // The repair after the descent on label surfaces (Crossing_repair.h), in the reference manual of
  // constrained_fairing_of_interfaces() and in the user manual.
  const std::string interfaces = text_of("include/CGAL/Polygon_mesh_processing/constrained_fairing_of_interfaces.h");
  const std::string repair_angle = number(CF::interface_repair_angle);
  CHECK(CF::crossing_repair_rounds == 6);
  CHECK(states(interfaces, "halfway at each of a point's first six pulls and all the way at its seventh"));
  CHECK(states(interfaces, "smallest angle is under both " + repair_angle + " degrees and its own in the input"));
  CHECK(states(interfaces, "no triangle's smallest angle is under both " + repair_angle + " degrees and its input's"));
  CHECK(states(manual, "smallest angle is under both " + repair_angle + " degrees and its own at the start"));
  CHECK(states(manual, "the repair after the descent takes over at " + repair_angle + " degrees"));

  // The named parameters that constrained_fairing_of_interfaces() reads (read_named_parameters.h),
  // each in its reference's list: the table's, feature_angle rejected, and the others.
  const std::size_t np_from = interfaces.find("\\param np "), np_to = interfaces.find("\\return", np_from);
  CHECK(np_from != std::string::npos && np_to != std::string::npos);
  const std::string soup_parameters = interfaces.substr(np_from, np_to - np_from);
  CF::for_each_named_setting(table, [&](const char*, const char* parameter, auto, const auto&) {
    const std::string name = parameter;
    CHECK(states(soup_parameters, "`" + name + (name == "feature_angle" ? "` is rejected" : "`")));
  });
  for(const char* parameter :
      {"fairing_method", "deviation_bound", "box_half_extents", "iteration_callback", "sparse_linear_solver",
       "vertex_tolerance_map", "vertex_is_constrained_map", "vertex_box_half_extents_map", "vertex_box_center_map",
       "vertex_deviation_map", "vertex_at_bound_map"})
    CHECK(states(soup_parameters, std::string("`") + parameter + "`"));

  // The barrier against folds on label surfaces (Fold_barrier.h), in both manuals.
  const std::string angle = number(CF::interface_fold_angle);
  for(const std::string* text : {&interfaces, &manual})
  {
    CHECK(states(*text, "more than " + angle + " degrees apart adds " + number(CF::interface_fold_weight) + " times"));
    CHECK(states(*text, "\\f$ (\\cos " + angle + "^\\circ - \\cos\\theta)^2 \\f$"));
  }

  // The README and the tool's usage.
  const std::string readme = text_of("README.md");
  CHECK(states(readme, "`number_of_iterations` (default " + std::to_string(q.options.max_iterations) + ")"));
  CHECK(states(readme, "is at most " + remaining + " of the energy"));
  CHECK(states(text_of("tools/constrained_fairing.cpp"),
               "Default: " + Constrained_fairing_front_end::default_epsilon_text + ","));
  return test::report("test_documented_defaults");
}
