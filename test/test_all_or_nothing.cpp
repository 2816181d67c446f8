// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whatever fails midway (the linear solver, an exception from the callback or the solver, any
// allocation), the mesh is left bit-identical to the input, and so is the edge map that the
// detection of creases writes. Each allocation the call makes is made to fail in turn.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>

#include <algorithm>
#include <cstdlib>
#include <new>
#include <stdexcept>
#include <vector>

namespace {

// Allocation failure injection: while `armed`, the allocation numbered `fail_at` (counting
// from 0) throws std::bad_alloc.
bool armed = false;
std::size_t allocations = 0, fail_at = 0;

void* allocate(std::size_t size)
{
  if(armed && allocations++ == fail_at)
    throw std::bad_alloc();
  if(void* p = std::malloc(size == 0 ? 1 : size))
    return p;
  throw std::bad_alloc();
}

} // namespace

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
using PMP::Constrained_fairing_status;
using test::Mesh;
using test::Point;

// The default solver, made to fail (return false) or throw at its call number `fail_at`:
// call 0 is the factorization, the others are solves.
struct Failing_solver : PMP::internal::Constrained_fairing::Default_sparse_linear_solver
{
  using Base = PMP::internal::Constrained_fairing::Default_sparse_linear_solver;
  std::size_t fail_at;
  bool throws;
  std::size_t* calls;

  bool fail() const
  {
    if((*calls)++ != fail_at)
      return false;
    if(throws)
      throw std::runtime_error("solver failure");
    return true;
  }
  bool factor(const Matrix& A, NT& D) { return !fail() && Base::factor(A, D); }
  bool linear_solver(const Vector& B, Vector& X) { return !fail() && Base::linear_solver(B, X); }
};

Mesh noisy_sphere()
{
  Mesh m = test::icosphere(2);
  test::add_noise(m, 0.3 * test::mean_edge_length(m), 41);
  return m;
}

void check_solver_failure()
{
  const Mesh input = noisy_sphere();
  for(std::size_t fail_at : {0, 1, 20})
    for(bool throws : {false, true})
    {
      Mesh m = input;
      std::size_t calls = 0;
      bool thrown = false;
      try
      {
        const auto r = PMP::constrained_fairing(
          m, 0.05,
          CFP::fairing_method(PMP::Constrained_fairing_method::ACTIVE_SET_NEWTON,
                              CGAL::parameters::sparse_linear_solver(
                                Failing_solver{Failing_solver::Base(), fail_at, throws, &calls})));
        CHECK(r.status == Constrained_fairing_status::LINEAR_SOLVER_FAILED && !r.message.empty());
      }
      catch(const std::runtime_error&)
      {
        thrown = true;
      }
      CHECK(thrown == throws && calls > fail_at);
      CHECK(test::identical(test::points(m), test::points(input)));
    }
}

void check_callback_exception()
{
  const Mesh input = noisy_sphere();
  Mesh m = input;
  bool thrown = false;
  try
  {
    PMP::constrained_fairing(m, 0.05, CFP::iteration_callback([](std::size_t iteration, double) -> bool {
                               if(iteration == 3)
                                 throw std::runtime_error("stop");
                               return true;
                             }));
  }
  catch(const std::runtime_error&)
  {
    thrown = true;
  }
  CHECK(thrown);
  CHECK(test::identical(test::points(m), test::points(input)));
}

using Edge_flags = Mesh::Property_map<Mesh::Edge_index, bool>;

// The flags of the edge map "e:marks" of m (of a copy: all false if m has no such map).
std::vector<bool> marked(Mesh m)
{
  const Edge_flags marks = m.add_property_map<Mesh::Edge_index, bool>("e:marks", false).first;
  std::vector<bool> flags;
  for(auto e : edges(m))
    flags.push_back(marks[e]);
  return flags;
}

// Each allocation of `fair(m)` on a copy m of `noisy` made to fail in turn: most runs throw
// std::bad_alloc, and each leaves the mesh and its edge map "e:marks", if any, as they were; a
// failure absorbed on the way (an output string stream naming a property map sets its failbit)
// gives the run without failures.
template <typename Fair>
void check_allocation_failures(const Mesh& noisy, const Fair& fair, const char* name)
{
  // Count the allocations of a whole run.
  Mesh counted = noisy;
  allocations = 0;
  fail_at = std::size_t(-1);
  armed = true;
  const auto reference = fair(counted);
  armed = false;
  const std::size_t total = allocations;
  CHECK(reference && total > 10);

  std::size_t failures = 0, unchanged = 0;
  for(std::size_t k = 0; k < total; ++k)
  {
    Mesh m = noisy;
    allocations = 0;
    fail_at = k;
    armed = true;
    try
    {
      const auto r = fair(m);
      armed = false;
      CHECK(r.status == reference.status && test::identical(test::points(m), test::points(counted)));
      CHECK(marked(m) == marked(counted));
    }
    catch(const std::bad_alloc&)
    {
      armed = false;
      ++failures;
      unchanged += test::identical(test::points(m), test::points(noisy)) && marked(m) == marked(noisy) ? 1 : 0;
    }
  }
  std::cout << "  " << name << ": " << total << " allocations, each made to fail: " << failures
            << " runs threw std::bad_alloc, " << unchanged << " of them left the input unchanged" << std::endl;
  CHECK(failures > total / 2 && unchanged == failures);
}

void check_allocation_failures()
{
  Mesh sphere = test::icosphere(1);
  test::add_noise(sphere, 0.05, 42);
  check_allocation_failures(
    sphere, [](Mesh& m) { return PMP::constrained_fairing(m, 0.05, CGAL::parameters::number_of_iterations(3)); },
    "sphere");
  // The creases detected are written in the map only once the call has succeeded.
  Mesh cube = test::grid_cube(4);
  const double eps = 0.05 / 4;
  test::add_noise(cube, eps, 42);
  cube.add_property_map<Mesh::Edge_index, bool>("e:marks", false);
  const auto fair_with_creases = [eps](Mesh& m) {
    const Edge_flags marks = m.add_property_map<Mesh::Edge_index, bool>("e:marks", false).first;
    return PMP::constrained_fairing(
      m, eps, CFP::feature_angle(30., CGAL::parameters::edge_is_constrained_map(marks).number_of_iterations(3)));
  };
  check_allocation_failures(cube, fair_with_creases, "cube with creases");
  Mesh detected = cube;
  const auto r = fair_with_creases(detected);
  CHECK(r.number_of_feature_edges == 48);
  const std::vector<bool> flags = marked(detected);
  CHECK(std::count(flags.begin(), flags.end(), true) == 48);
}

int main()
{
  check_solver_failure();
  check_callback_exception();
  check_allocation_failures();
  return test::report("test_all_or_nothing");
}
