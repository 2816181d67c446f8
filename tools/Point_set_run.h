// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tool on a point set file (Point_set_file.h): constrained_fairing_of_points(), every point
// kept in its order, the result in OUT's format.

#ifndef CONSTRAINED_FAIRING_TOOL_POINT_SET_RUN_H
#define CONSTRAINED_FAIRING_TOOL_POINT_SET_RUN_H

#include "tools/Tool_options.h"
#include "tools/Tool_progress.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_points.h>
#include <CGAL/Polygon_mesh_processing/estimate_noise_level_of_points.h>

#include "front_end/Epsilon_grammar.h"
#include "front_end/Output_files.h"
#include "front_end/Point_set_file.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/property_map.h>

#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace Tool_point_set {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
namespace FE = Constrained_fairing_front_end;
using Contents = FE::Point_set_contents<K::Point_3, K::Vector_3>;
using Item = std::pair<K::Point_3, K::Vector_3>;

inline bool point_set_format(const std::string& path)
{
  return FE::has_extension(path, ".xyz") || FE::has_extension(path, ".pwn") || FE::has_extension(path, ".ply") ||
         FE::has_extension(path, ".off");
}

// The options that apply to a point set, EPS absolute or auto (`epsilon` then 0); OUT as given,
// IN with --in-place, or IN's name with _faired in the current folder; or the reason the run
// cannot start.
inline std::string point_set_options_error(const Tool_options& options, double& epsilon, std::string& out)
{
  if(options.fixed_border || options.repair || options.force || options.extents || options.radius_property ||
     options.label_format || options.feature_angle)
    return "of the options, only --eps, --accurate, --tangential-motion, --box and --in-place apply to a point set";
  const FE::Epsilon_text eps = FE::parse_epsilon(options.eps.value_or(""));
  if(!options.eps || !eps.error.empty() || eps.kind == FE::Epsilon_text::Kind::RELATIVE)
    return "a point set needs --eps as a distance (such as 0.002) or auto: it has no edges for h";
  epsilon = eps.kind == FE::Epsilon_text::Kind::AUTO ? 0 : eps.value;
  const std::string& in = options.positional[0];
  out = options.positional.size() > 1 ? options.positional[1]
        : options.in_place            ? in
                                      : std::filesystem::path(in).stem().string() + "_faired" +
                               std::filesystem::path(in).extension().string();
  if(!point_set_format(out))
    return "OUT must end with .xyz, .pwn, .ply or .off for a point set (got " + out + ")";
  if(!options.in_place && FE::is_same_file(in, out))
    return "OUT is IN (" + out + "): the result would replace the input; give another OUT, or --in-place";
  return std::string();
}

template <typename NamedParameters>
PMP::Constrained_fairing_result fair_points(Contents& contents, double epsilon, const Tool_options& options,
                                            const NamedParameters& np)
{
  const auto asked =
    CFP::fairing_objective(options.accurate ? PMP::Constrained_fairing_objective::ACCURATE
                                            : PMP::Constrained_fairing_objective::FAIREST,
                           CFP::deviation_bound(options.box ? PMP::Deviation_bound::BOX : PMP::Deviation_bound::BALL,
                                                np.point_map(CGAL::First_of_pair_property_map<Item>())));
  const auto with_motion = [&](const auto& all) {
    return contents.has_normals
             ? PMP::constrained_fairing_of_points(contents.points, epsilon,
                                                  all.normal_map(CGAL::Second_of_pair_property_map<Item>()))
             : PMP::constrained_fairing_of_points(contents.points, epsilon, all);
  };
  return options.tangential_motion ? with_motion(CFP::tangential_motion(true, asked)) : with_motion(asked);
}

inline int fair_point_set_file(const Tool_options& options)
{
  double epsilon = 0;
  std::string out;
  if(const std::string error = point_set_options_error(options, epsilon, out); !error.empty())
    return report_error(error);
  const std::string& in = options.positional[0];
  Tool_progress progress;
  progress.phase("reading " + in);
  Contents contents;
  if(const std::string error = FE::read_point_set_file(in, contents); !error.empty())
    return report_error(error);
  const std::size_t n = contents.points.size();
  if(epsilon == 0) // --eps auto
  {
    epsilon = PMP::estimate_noise_level_of_points(contents.points, CGAL::parameters::point_map(
                                                                     CGAL::First_of_pair_property_map<Item>()));
    if(!(epsilon > 0))
      return report_error("cannot estimate the noise level of so few points; give --eps");
    std::cout << "eps: auto, " << epsilon << std::endl;
  }
  std::vector<double> deviation(n, 0.);
  std::vector<std::uint8_t> at_bound(n, 0);
  progress.phase("checking and starting (" + std::to_string(n) + " points)");
  const PMP::Constrained_fairing_result result = fair_points(
    contents, epsilon, options,
    CFP::iteration_callback(std::ref(progress),
                            CFP::vertex_deviation_map(CGAL::make_property_map(deviation),
                                                      CFP::vertex_at_bound_map(CGAL::make_property_map(at_bound)))));
  progress.done();
  if(!result)
    return report_error(result.message + "; nothing written");
  std::vector<FE::Ply_property> extra = {{"deviation", "double", deviation}, {"at_bound", "uchar", {}}};
  for(std::uint8_t b : at_bound)
    extra[1].values.push_back(b);
  progress.phase("writing " + out);
  const std::string write_error = FE::write_file_through_partial(out, [&](const std::string& partial) {
    return FE::write_point_set_file(partial, contents.points, contents.has_normals, contents.properties, extra)
             ? std::string()
             : "cannot write " + out + FE::unwritable_file_reason(partial);
  });
  progress.done();
  if(!write_error.empty())
    return report_error(write_error + "; nothing written");
  if(!FE::has_extension(out, ".ply") && !contents.properties.vertex.empty())
    std::cout << "note: the properties of " << in << " are carried to a .ply OUT only" << std::endl;
  std::cout << "wrote " << out << ": " << n << " points; eps " << epsilon << "; " << result.number_of_iterations
            << " iterations; bending energy " << result.initial_bending_energy << " -> "
            << result.final_bending_energy << "; deviation at most " << result.max_deviation << ", "
            << result.number_of_vertices_at_bound << " at the bound, " << result.number_of_isolated_points
            << " isolated; " << std::setprecision(3) << progress.seconds() << " s" << std::endl;
  return EXIT_SUCCESS;
}

} // namespace Tool_point_set

#endif // CONSTRAINED_FAIRING_TOOL_POINT_SET_RUN_H
