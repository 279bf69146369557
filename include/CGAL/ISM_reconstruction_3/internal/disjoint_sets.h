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
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// Union-find with path halving, for sets that only grow.
class Disjoint_sets
{
public:
  explicit Disjoint_sets(std::size_t n) : m_parent(n) { std::iota(m_parent.begin(), m_parent.end(), std::uint32_t(0)); }
  std::uint32_t find(std::uint32_t x)
  {
    while(m_parent[x] != x) x = m_parent[x] = m_parent[m_parent[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) { m_parent[find(a)] = find(b); }
  void reset(std::size_t n)
  {
    m_parent.resize(n);
    std::iota(m_parent.begin(), m_parent.end(), std::uint32_t(0));
  }

private:
  std::vector<std::uint32_t> m_parent;
};

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_DISJOINT_SETS_H
