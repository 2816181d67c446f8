// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Loops over the elements of the mesh, in parallel with TBB when CGAL is linked with it
// (CGAL_LINKED_WITH_TBB), sequentially otherwise. The range is cut into blocks of a fixed size
// that does not depend on the number of threads, and every output is written by one block
// only; sums are taken per block and then added in block order. So results are bit-identical
// run to run and for any number of threads.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_PARALLEL_FOR_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_PARALLEL_FOR_H

#include <algorithm>
#include <cstddef>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// Elements per block: large enough to hide the scheduling, small enough to balance two to a
// few dozen threads on meshes of 10^5 elements and more.
constexpr std::size_t parallel_block_size = 4096;

inline std::size_t number_of_blocks(std::size_t n) { return (n + parallel_block_size - 1) / parallel_block_size; }

// Calls f(begin, end, block) for the blocks [begin, end) of [0, n).
template <typename F>
void parallel_for_blocks(std::size_t n, const F& f)
{
  const std::size_t blocks = number_of_blocks(n);
  const auto run = [&](std::size_t b) {
    const std::size_t begin = b * parallel_block_size;
    f(begin, (begin + parallel_block_size < n) ? begin + parallel_block_size : n, b);
  };
#ifdef CGAL_LINKED_WITH_TBB
  if(blocks > 1)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks, 1), [&](const tbb::blocked_range<std::size_t>& r) {
      for(std::size_t b = r.begin(); b != r.end(); ++b)
        run(b);
    });
    return;
  }
#endif
  for(std::size_t b = 0; b < blocks; ++b)
    run(b);
}

// The sums over [0, n) of `count` values: f(begin, end, sums) writes a block's partial sums to
// sums[0, count), and `result` gets their totals, each added in block order. `partial` is the
// caller's buffer, so that no call allocates once it has its size.
template <typename F>
void parallel_sums(std::size_t n, std::size_t count, std::vector<double>& partial, double* result, const F& f)
{
  const std::size_t blocks = number_of_blocks(n);
  partial.resize(blocks * count);
  parallel_for_blocks(n, [&](std::size_t begin, std::size_t end, std::size_t b) { f(begin, end, partial.data() + b * count); });
  std::fill(result, result + count, 0.);
  for(std::size_t b = 0; b < blocks; ++b)
    for(std::size_t c = 0; c < count; ++c)
      result[c] += partial[b * count + c];
}

// The sum over [0, n) of f(begin, end), a partial sum over a block.
template <typename F>
double parallel_sum(std::size_t n, std::vector<double>& partial, const F& f)
{
  double sum;
  parallel_sums(n, 1, partial, &sum, [&](std::size_t begin, std::size_t end, double* block) { block[0] = f(begin, end); });
  return sum;
}

// Runs items that need a scratch buffer each: for_each(n, f) calls f(item, worker) for every
// item in [0, n), `worker` in [0, size()) being the same for no two items that run at once: the
// index of the thread in TBB's current arena, whose size is taken at construction (a call from
// a larger arena runs sequentially). An item's result must not depend on which worker runs it.
class Worker_pool
{
public:
  std::size_t size() const { return m_size; }

  template <typename F>
  void for_each(std::size_t n, const F& f) const
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(n > 1 && m_size > 1 && static_cast<std::size_t>(tbb::this_task_arena::max_concurrency()) <= m_size)
    {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1), [&](const tbb::blocked_range<std::size_t>& r) {
        const auto worker = static_cast<std::size_t>(tbb::this_task_arena::current_thread_index());
        for(std::size_t item = r.begin(); item != r.end(); ++item)
          f(item, worker);
      });
      return;
    }
#endif
    for(std::size_t item = 0; item < n; ++item)
      f(item, 0);
  }

private:
#ifdef CGAL_LINKED_WITH_TBB
  std::size_t m_size = static_cast<std::size_t>((std::max)(1, tbb::this_task_arena::max_concurrency()));
#else
  std::size_t m_size = 1;
#endif
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_PARALLEL_FOR_H
