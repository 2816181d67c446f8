// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Input concept: what a kind of input (a room: Triangle_meshes/, Label_interfaces/)
// supplies to the driver's phases (Fairing_driver.h), each member in the phase that calls it.
// `Part` is what part() returns: size(), number(k) (vertex k's name in messages), is_fixed(k)
// and for_each_vertex(f) with f(k, key), key that of the per-vertex maps.
//  - check: structure_error() -> Input_error, the first defect of the input's structure (none:
//    an empty error); part(maps) -> Part, the vertices that take part and which of them stay;
//    input_points(part) -> Points, on the part's numbering; triangles(part), the triangles of
//    the part on that numbering, for the area check (Value_check.h);
//  - order: order(part, rank), its own numbering moved to the solver's (rank[k], vertex k's);
//  - build: hinges(part, moving, X0, settings) -> Hinge_mesh; `bends_by_hinges`, a static
//    constexpr bool: whether the bending energy is the hinges' (Bending_energy.h), or else one
//    of the input's terms; number_of_feature_edges(), the creases it keeps; sliding_points(part) -> std::vector<bool>, the points with no surface
//    normal (empty: none); sliver_threshold(settings); add_terms(objective, mesh, X0,
//    settings), its own terms of the objective (Objective_terms.h), which it keeps alive;
//    denoise(mesh, bound, X), the accurate objective's anchor: X, the input points, denoised
//    within the bound;
//  - after the descent: repair(mesh, bound, moving, X0, X, objective, settings, result);
//  - write back: clear_outputs(maps), the per-vertex outputs of what does not take part;
//    write_own_outputs(), what only this kind writes (a mesh's detected creases in the user's
//    edge map); write(key, x, y, z), a point that moved.
// check_fairing_input<Input, VertexMaps>() states at compile time which member a kind lacks.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_INPUT_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_INPUT_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Deviation_bounds.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Fairing_settings.h>

#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

namespace input_concept {

template <typename, template <typename...> class Member, typename... Arguments>
struct detect : std::false_type
{};
template <template <typename...> class Member, typename... Arguments>
struct detect<std::void_t<Member<Arguments...> >, Member, Arguments...> : std::true_type
{};
template <template <typename...> class Member, typename... Arguments>
constexpr bool has = detect<void, Member, Arguments...>::value;

template <typename T>
T& a();

template <typename I>
using structure_error = decltype(Input_error(a<I>().structure_error()));
template <typename I, typename M>
using part = decltype(a<I>().part(a<const M>()));
template <typename I, typename P>
using input_points = decltype(Points(a<const I>().input_points(a<const P>())));
template <typename I, typename P>
using triangles = decltype(a<const I>().triangles(a<const P>()).size());
template <typename I, typename P>
using order = decltype(a<I>().order(a<const P>(), a<const std::vector<Index> >()));
template <typename I, typename P>
using hinges = decltype(Hinge_mesh(
  a<I>().hinges(a<const P>(), a<const std::vector<bool> >(), a<const Points>(), a<const Fairing_settings>())));
template <typename I>
using number_of_feature_edges = decltype(std::size_t(a<const I>().number_of_feature_edges()));
template <typename I, typename P>
using sliding_points = decltype(std::vector<bool>(a<const I>().sliding_points(a<const P>())));
template <typename I>
using sliver_threshold = decltype(double(a<const I>().sliver_threshold(a<const Fairing_settings>())));
template <typename I>
using add_terms = decltype(a<I>().add_terms(a<Fairing_objective>(), a<const Hinge_mesh>(), a<const Points>(),
                                            a<const Fairing_settings>()));
template <typename I>
using bends_by_hinges = decltype(bool(I::bends_by_hinges));
template <typename I>
using denoise = decltype(a<const I>().denoise(a<const Hinge_mesh>(), a<const Ball_bound>(), a<Points>()));
template <typename I>
using repair = decltype(a<I>().repair(a<const Hinge_mesh>(), a<const Ball_bound>(),
                                            a<const std::vector<bool> >(), a<const Points>(), a<Points>(),
                                            a<Fairing_objective>(), a<const Fairing_settings>(),
                                            a<Constrained_fairing_result>()));
template <typename I, typename M>
using clear_outputs = decltype(a<const I>().clear_outputs(a<const M>()));
template <typename I>
using write_own_outputs = decltype(a<I>().write_own_outputs());

} // namespace input_concept

template <typename Input, typename VertexMaps>
constexpr bool check_fairing_input()
{
  namespace C = input_concept;
  static_assert(C::has<C::structure_error, Input>, "an Input has structure_error() -> Input_error");
  static_assert(C::has<C::part, Input, VertexMaps>, "an Input has part(maps)");
  if constexpr(C::has<C::part, Input, VertexMaps>)
  {
    using Part = std::decay_t<C::part<Input, VertexMaps> >;
    static_assert(C::has<C::input_points, Input, Part>, "an Input has input_points(part) -> Points");
    static_assert(C::has<C::triangles, Input, Part>, "an Input has triangles(part)");
    static_assert(C::has<C::order, Input, Part>, "an Input has order(part, rank)");
    static_assert(C::has<C::hinges, Input, Part>, "an Input has hinges(part, moving, X0, settings) -> Hinge_mesh");
    static_assert(C::has<C::sliding_points, Input, Part>, "an Input has sliding_points(part) -> std::vector<bool>");
  }
  static_assert(C::has<C::bends_by_hinges, Input>, "an Input has a static constexpr bool bends_by_hinges");
  static_assert(C::has<C::denoise, Input>, "an Input has denoise(mesh, bound, X)");
  static_assert(C::has<C::number_of_feature_edges, Input>, "an Input has number_of_feature_edges()");
  static_assert(C::has<C::sliver_threshold, Input>, "an Input has sliver_threshold(settings) -> double");
  static_assert(C::has<C::add_terms, Input>, "an Input has add_terms(objective, mesh, X0, settings)");
  static_assert(C::has<C::repair, Input>, "an Input has repair(mesh, bound, moving, X0, X, objective, settings, result)");
  static_assert(C::has<C::clear_outputs, Input, VertexMaps>, "an Input has clear_outputs(maps)");
  static_assert(C::has<C::write_own_outputs, Input>, "an Input has write_own_outputs()");
  return true;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_INPUT_H
