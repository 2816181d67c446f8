// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The iteration callback as the solvers hold it: one type whatever callable the user passes,
// so that the solvers are compiled once whatever callbacks a program passes.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ITERATION_CALLBACK_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ITERATION_CALLBACK_H

#include <cstddef>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// A callable bool(std::size_t iteration, double energy), held by reference.
class Iteration_callback
{
public:
  template <typename Callback>
  Iteration_callback(const Callback& callback)
    : m_callback(&callback), m_call([](const void* f, std::size_t iteration, double energy) {
        return bool((*static_cast<const Callback*>(f))(iteration, energy));
      })
  {}

  bool operator()(std::size_t iteration, double energy) const { return m_call(m_callback, iteration, energy); }

private:
  const void* m_callback;
  bool (*m_call)(const void*, std::size_t, double);
};

// The callback of a call that passes none.
struct Always_continue
{
  bool operator()(std::size_t, double) const { return true; }
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ITERATION_CALLBACK_H
