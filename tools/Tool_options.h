// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command line of the tool: options as `--name VALUE` or `--name=VALUE`, then IN and OUT.

#ifndef CONSTRAINED_FAIRING_TOOL_OPTIONS_H
#define CONSTRAINED_FAIRING_TOOL_OPTIONS_H

#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

struct Tool_options
{
  std::vector<std::string> positional;
  bool box = false, fixed_border = false, accurate = false, tangential_motion = false, in_place = false,
       force = false, repair = false, help = false;
  std::optional<std::string> eps, extents, radius_property, label_format, feature_angle;
  std::string error;
};

namespace internal {

// The option `name` that takes a value, as a member of Tool_options; null for another.
inline std::optional<std::string> Tool_options::*valued_option(const std::string& name)
{
  if(name == "--eps")
    return &Tool_options::eps;
  if(name == "--box-extents")
    return &Tool_options::extents;
  if(name == "--radius-from-property")
    return &Tool_options::radius_property;
  if(name == "--label-format")
    return &Tool_options::label_format;
  if(name == "--feature-angle")
    return &Tool_options::feature_angle;
  return nullptr;
}

// The flag `name` as a member of Tool_options; null for another.
inline bool Tool_options::*flag_option(const std::string& name)
{
  if(name == "--help" || name == "-h")
    return &Tool_options::help;
  if(name == "--box")
    return &Tool_options::box;
  if(name == "--fixed-border")
    return &Tool_options::fixed_border;
  if(name == "--accurate")
    return &Tool_options::accurate;
  if(name == "--tangential-motion")
    return &Tool_options::tangential_motion;
  if(name == "--in-place")
    return &Tool_options::in_place;
  if(name == "--force")
    return &Tool_options::force;
  if(name == "--repair")
    return &Tool_options::repair;
  return nullptr;
}

} // namespace internal

// The options of the command line; `error` says what is wrong with it, if anything. The value
// of an option is the next argument, whatever it looks like (--eps -0.01 is a tolerance, which
// the grammar then refuses as negative).
inline Tool_options parse_tool_options(int argc, char* argv[])
{
  Tool_options o;
  for(int i = 1; i < argc && o.error.empty(); ++i)
  {
    const std::string a = argv[i];
    const std::size_t equals = a.compare(0, 2, "--") == 0 ? a.find('=') : std::string::npos;
    const std::string name = a.substr(0, equals);
    if(const auto valued = internal::valued_option(name))
    {
      if(equals != std::string::npos)
        (o.*valued) = a.substr(equals + 1);
      else if(i + 1 < argc)
        (o.*valued) = argv[++i];
      else
        o.error = a + " needs a value";
    }
    else if(const auto flag = internal::flag_option(name))
    {
      if(equals != std::string::npos)
        o.error = name + " takes no value (got " + a + ")";
      o.*flag = true;
    }
    else if(a.size() > 1 && a[0] == '-')
      o.error = "unknown option " + a + " (see --help)";
    else
      o.positional.push_back(a);
  }
  if(o.error.empty() && o.positional.empty())
    o.error = "no input mesh (see --help)";
  if(o.error.empty() && o.positional.size() > 2)
    o.error = "too many arguments (see --help)";
  return o;
}

// The tool's one line on a failure.
inline int report_error(const std::string& message)
{
  std::cerr << "error: " << message << std::endl;
  return EXIT_FAILURE;
}

#endif // CONSTRAINED_FAIRING_TOOL_OPTIONS_H
