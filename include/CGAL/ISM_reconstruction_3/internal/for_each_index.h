// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_FOR_EACH_INDEX_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_FOR_EACH_INDEX_H

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <cstddef>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// Runs `body(i)` for i in [0, n), in parallel when TBB is there. Each i must write only its
// own slot: then the result does not depend on the number of threads.
template <class Body>
void for_each_index(std::size_t n, const Body& body)
{
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 512), [&](const tbb::blocked_range<std::size_t>& r) {
    for(std::size_t i = r.begin(); i != r.end(); ++i) body(i);
  });
#else
  for(std::size_t i = 0; i < n; ++i) body(i);
#endif
}

// Calls `f(lo, hi)` on disjoint subranges covering [b, e), of about `grain` indices each, in
// parallel when TBB is there and the range holds more than two grains: for loops whose body
// is a few operations, where a call per index would cost more than the work. The result
// does not depend on the split when each index writes only its own slot.
template <class F>
void for_chunks(std::size_t b, std::size_t e, std::size_t grain, const F& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(e > b && e - b > 2 * grain)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(b, e, grain),
                      [&f](const tbb::blocked_range<std::size_t>& r) { f(r.begin(), r.end()); });
    return;
  }
#else
  (void)grain;
#endif
  if(b < e)
    f(b, e);
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_FOR_EACH_INDEX_H
