// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_DISJOINT_SETS_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_DISJOINT_SETS_H

#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// Union-find with path halving and union by size, for sets that only grow. (Without the
// sizes, the trees over the dragon's 228k vertices grew deep enough that the finds took most
// of the island and handle passes.)
class Disjoint_sets
{
public:
  explicit Disjoint_sets(std::size_t n) { reset(n); }
  std::uint32_t find(std::uint32_t x)
  {
    while(m_parent[x] != x) x = m_parent[x] = m_parent[m_parent[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b)
  {
    a = find(a);
    b = find(b);
    if(a == b) return;
    if(m_size[a] < m_size[b]) std::swap(a, b);
    m_parent[b] = a;
    m_size[a] += m_size[b];
  }
  void reset(std::size_t n)
  {
    m_parent.resize(n);
    std::iota(m_parent.begin(), m_parent.end(), std::uint32_t(0));
    m_size.assign(n, 1);
  }

private:
  std::vector<std::uint32_t> m_parent, m_size;
};

// Unites the vertices `v` of a leaf that have the same sign and pass `keep`: each with the
// first such vertex of its sign (at most 3 unions where the 6 edges would make 6).
template <class Vertices, class Keep>
void unite_same_sign(const Vertices& v, const std::vector<signed char>& signs, const Keep& keep, Disjoint_sets& sets)
{
  std::int64_t first[2] = {-1, -1};
  for(int l = 0; l < 4; ++l)
  {
    const std::uint32_t w = std::uint32_t(v[l]);
    if(!keep(w)) continue;
    std::int64_t& f = first[signs[w] > 0];
    if(f < 0) f = w;
    else sets.unite(w, std::uint32_t(f));
  }
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_DISJOINT_SETS_H
