// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL's AABB tree of a triangle mesh's faces, the distance to a surface in the tests and the
// benchmarks, under the name of its traits in CGAL 5.5 and in CGAL 6.

#ifndef CONSTRAINED_FAIRING_TEST_TRIANGLE_TREE_H
#define CONSTRAINED_FAIRING_TEST_TRIANGLE_TREE_H

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/version_macros.h>
#if CGAL_VERSION_MAJOR >= 6
#include <CGAL/AABB_traits_3.h>
#else
#include <CGAL/AABB_traits.h>
#endif

namespace test {

template <typename Kernel, typename TriangleMesh>
#if CGAL_VERSION_MAJOR >= 6
using Triangle_tree = CGAL::AABB_tree<CGAL::AABB_traits_3<Kernel, CGAL::AABB_face_graph_triangle_primitive<TriangleMesh> > >;
#else
using Triangle_tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<TriangleMesh> > >;
#endif

} // namespace test

#endif // CONSTRAINED_FAIRING_TEST_TRIANGLE_TREE_H
