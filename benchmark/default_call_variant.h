// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default call compiled twice from default_call_variant.cpp, each into a shared library of
// its own whose template instances stay inside it (hidden visibility): once with the flags of
// CGAL::CGAL, which include -frounding-math for GCC, and once without that flag. A benchmark
// linking both times the same driver under both flags in one process.

#ifndef CGAL_CONSTRAINED_FAIRING_BENCHMARK_DEFAULT_CALL_VARIANT_H
#define CGAL_CONSTRAINED_FAIRING_BENCHMARK_DEFAULT_CALL_VARIANT_H

#include "benchmark_support.h"

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>

namespace benchmark {

using Fairing_result = CGAL::Polygon_mesh_processing::Constrained_fairing_result;

// constrained_fairing(mesh, epsilon), built as through CGAL::CGAL (with -frounding-math)
__attribute__((visibility("default"))) Fairing_result default_call_with_cgal_flags(Mesh& mesh, double epsilon);

// the same call built without -frounding-math
__attribute__((visibility("default"))) Fairing_result default_call_without_rounding_math(Mesh& mesh, double epsilon);

} // namespace benchmark

#endif // CGAL_CONSTRAINED_FAIRING_BENCHMARK_DEFAULT_CALL_VARIANT_H
