// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The checks of the input contract that a front end makes on its own: of a polygon soup before
// it becomes a mesh, and of a mesh before anything but a fairing is computed on it, each defect
// named as constrained_fairing() names it.

#ifndef CGAL_PMP_CONSTRAINED_FAIRING_INPUT_CHECK_H
#define CGAL_PMP_CONSTRAINED_FAIRING_INPUT_CHECK_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Polygon_soup_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Triangle_meshes/Mesh_check.h>

#include <CGAL/boost/graph/properties.h>

#include <cstddef>
#include <string>

namespace CGAL {
namespace Polygon_mesh_processing {

/// \ingroup PkgConstrainedFairingRef
/// A defect of an input and the message that names it and the first vertex or face concerned,
/// as a call that rejects the input reports them (`Constrained_fairing_result::defect` and
/// `message`). Converts to `true` when there is a defect.
struct Constrained_fairing_input_error
{
  /// the defect, `Constrained_fairing_defect::NONE` if there is none
  Constrained_fairing_defect defect = Constrained_fairing_defect::NONE;
  /// the message, empty if there is no defect
  std::string message;

  /// `true` when there is a defect
  explicit operator bool() const { return defect != Constrained_fairing_defect::NONE; }
};

/*!
\ingroup PkgConstrainedFairingRef

\brief the first defect of a polygon soup that keeps CGAL's `polygon_soup_to_polygon_mesh()` from
making of it a mesh that `constrained_fairing()` takes, in the order of `Constrained_fairing_defect`.

A front end that reads a soup (a file, arrays) names its defects with this check before it
builds the mesh, which a soup with one of them cannot become: a face with fewer than three
corners, a corner that refers to no point or to a point twice (`INVALID_FACE`), more points or
corners than 32-bit indices hold (`MESH_TOO_LARGE`), an edge of more than two faces
(`NON_MANIFOLD_EDGE`), two faces running the same way along an edge (`INCONSISTENT_ORIENTATION`),
a point whose faces form more than one fan (`NON_MANIFOLD_VERTEX`). Faces and points are numbered
from 0 in the soup's order. The other defects of the input contract, an empty soup among them,
are for `constrained_fairing()` to name on the mesh.

\tparam PolygonRange a random access range of random access ranges of point indices, of any
integer type

\param number_of_points the number of points the indices refer to
\param polygons the faces, each listing its corners in order
*/
template <typename PolygonRange>
Constrained_fairing_input_error constrained_fairing_polygon_soup_error(std::size_t number_of_points,
                                                                       const PolygonRange& polygons)
{
  const auto error = internal::Constrained_fairing::polygon_soup_error(number_of_points, polygons);
  return {error.defect, error.message};
}

/*!
\ingroup PkgConstrainedFairingRef

\brief the first defect of `tmesh` among those of the input contract that a mesh itself can
break, as `constrained_fairing()` checks them first: no vertex or no face, broken halfedge
links, a face that is not a triangle, a non-manifold edge, inconsistent orientation, a
non-manifold vertex, too many vertices or faces.

A front end that computes something else on a mesh meant for `constrained_fairing()` (its mean
edge length, `estimate_noise_level()`) names its defects as the fairing would. Vertices and faces
are numbered from 0 in the order `vertices(tmesh)` and `faces(tmesh)` list them.

\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`

\param tmesh the mesh
*/
template <typename TriangleMesh>
Constrained_fairing_input_error constrained_fairing_mesh_error(const TriangleMesh& tmesh)
{
  auto number = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tmesh);
  std::size_t count = 0;
  for(auto v : vertices(tmesh))
    put(number, v, count++);
  const auto error = internal::Constrained_fairing::mesh_error(tmesh, number);
  return {error.defect, error.message};
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_CONSTRAINED_FAIRING_INPUT_CHECK_H
