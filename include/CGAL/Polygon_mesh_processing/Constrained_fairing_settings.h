// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The settings of a call as one value that a front end fills at run time, by the settings' names,
// and the named parameter that passes them: the library's own table and rules, so that no front
// end restates a default or a rule (internal/Constrained_fairing/Parameters/Fairing_settings.h).

#ifndef CGAL_PMP_CONSTRAINED_FAIRING_SETTINGS_H
#define CGAL_PMP_CONSTRAINED_FAIRING_SETTINGS_H

#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Named_settings.h>

#include <CGAL/Named_function_parameters.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <type_traits>

namespace CGAL {
namespace Polygon_mesh_processing {

/*!
\ingroup PkgConstrainedFairingRef

\brief the settings of a call of `constrained_fairing()` or `constrained_fairing_of_interfaces()`
as one value, for a front end whose user sets them at run time (a command line, a scripting
language): the method, the settings a user sets by name, the shape of the bound and the
half-extents of every vertex's box, each at the library's default until it is set.

A call takes them with `constrained_fairing_parameters::fairing_settings()`. The named parameters
given beside it that set one of these settings override it, except `fairing_method()`: the
method is chosen when the settings are made, as it chooses the others' defaults. A setting left
unset keeps the library's default, or its rule: `tangential_motion` unset, for example, lets the
call choose by the method, the bound and the objective, as it does when the named parameter is
not given.
*/
class Constrained_fairing_settings
{
public:
  /// the defaults of `method`
  explicit Constrained_fairing_settings(Constrained_fairing_method method = Constrained_fairing_method::QUASI_NEWTON)
    : m_settings(method)
  {}

  /// the method, which chose the defaults
  Constrained_fairing_method method() const { return m_settings.method; }

  /// calls `f(name, parameter, value)` for each setting that a user sets by name, always in
  /// the same order: `name` (a `const char*`) its name in the front ends (the keyword of the
  /// Python module), `parameter` (a `const char*`) the named parameter that sets it, `value` a
  /// reference to its value, of the named parameter's type or, for a setting whose default
  /// follows from the others (`tangential_motion`, `feature_angle`), a `std::optional` of it,
  /// unset until it is set.
  template <typename F>
  void for_each_named_setting(const F& f)
  {
    internal::Constrained_fairing::for_each_named_setting(
      m_settings, [&f](const char* name, const char* parameter, auto, auto& value) { f(name, parameter, value); });
  }

  /// the same on a constant, `value` a constant reference
  template <typename F>
  void for_each_named_setting(const F& f) const
  {
    internal::Constrained_fairing::for_each_named_setting(
      m_settings, [&f](const char* name, const char* parameter, auto, const auto& value) { f(name, parameter, value); });
  }

  /// sets the setting called `name` by `for_each_named_setting()` to `value`, of the setting's
  /// type (for a `std::optional`, of its value type); returns `false`, and sets nothing, if
  /// no setting has that name and type
  template <typename T>
  bool set(const std::string& name, const T& value)
  {
    bool found = false;
    for_each_named_setting([&](const char* setting, const char*, auto& field) {
      using Field = std::decay_t<decltype(field)>;
      if constexpr(std::is_same_v<Field, T> || std::is_same_v<Field, std::optional<T> >)
        if(name == setting)
        {
          field = value;
          found = true;
        }
    });
    return found;
  }

  /// sets the shape of the bound, as `deviation_bound()` does
  void set_deviation_bound(Deviation_bound bound) { m_settings.deviation_bound = bound; }

  /// sets the half-extents of every vertex's box along x, y and z, as `box_half_extents()` does
  void set_box_half_extents(const std::array<double, 3>& half_extents) { m_settings.box_half_extents = half_extents; }

  /// whether a call with these settings bounds the vertices by boxes, given whether it also
  /// gives `vertex_box_half_extents_map()` or `vertex_box_center_map()`: the box set as the
  /// shape, or any box parameter given with no shape set (with `Deviation_bound::BALL` set, a
  /// call that gives a box parameter is rejected: `Constrained_fairing_defect::BOX_WITH_BALL`)
  bool is_box_bound(bool box_maps_given) const
  {
    internal::Constrained_fairing::Fairing_settings settings = m_settings;
    settings.has_box_parameter = settings.box_half_extents.has_value() || box_maps_given;
    return settings.is_box();
  }

  /// the number of iterations over which the stopping rule averages the energy's relative
  /// decrease, which `energy_decrease_threshold()` bounds
  std::size_t energy_decrease_window() const { return m_settings.options.window; }

  /// the fraction of the energy that the decrease still to come, extrapolated from the last two
  /// windows, must not exceed for the call to stop; `0` if the method does not wait for it
  double energy_remaining_fraction() const { return m_settings.options.remaining_fraction; }

  /// the fraction of `epsilon`, root mean square, that the motion of the surface still to
  /// come must not exceed for the call to stop where the vertices move along the normals; `0`
  /// if the method does not wait for it
  double remaining_motion() const { return m_settings.options.remaining_motion; }

  /// \cond SKIP_IN_MANUAL
  const internal::Constrained_fairing::Fairing_settings& plain_settings() const { return m_settings; }
  /// \endcond

private:
  internal::Constrained_fairing::Fairing_settings m_settings;
};

namespace constrained_fairing_parameters {

/// all the settings of `settings` at once: a `Constrained_fairing_settings`
inline Named_function_parameters<internal::Constrained_fairing::Fairing_settings,
                                 internal::Constrained_fairing::fairing_settings_t>
fairing_settings(const Constrained_fairing_settings& settings)
{
  return Named_function_parameters<internal::Constrained_fairing::Fairing_settings,
                                   internal::Constrained_fairing::fairing_settings_t>(settings.plain_settings());
}

/// the same, appended to an existing pack `base`
template <typename NP_T, typename NP_Tag, typename NP_Base>
Named_function_parameters<internal::Constrained_fairing::Fairing_settings,
                          internal::Constrained_fairing::fairing_settings_t,
                          Named_function_parameters<NP_T, NP_Tag, NP_Base> >
fairing_settings(const Constrained_fairing_settings& settings, const Named_function_parameters<NP_T, NP_Tag, NP_Base>& base)
{
  return Named_function_parameters<internal::Constrained_fairing::Fairing_settings,
                                   internal::Constrained_fairing::fairing_settings_t,
                                   Named_function_parameters<NP_T, NP_Tag, NP_Base> >(settings.plain_settings(), base);
}

} // namespace constrained_fairing_parameters

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_CONSTRAINED_FAIRING_SETTINGS_H
