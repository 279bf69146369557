// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_BLOCK_ARRAY_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_BLOCK_ARRAY_H

#include <algorithm>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// An append-only array stored in fixed-size blocks. Growing never moves or copies what
// is stored (a std::vector would copy the whole cell array at every reallocation, and
// leave up to half of its capacity unused), and indexing stays O(1): a shift and a mask.
template <class T, unsigned LogBlockSize = 15>
class Block_array
{
  static constexpr std::size_t block_size = std::size_t(1) << LogBlockSize;
  static constexpr std::size_t mask = block_size - 1;
  std::vector<std::unique_ptr<T[]> > m_blocks;
  std::size_t m_size = 0;

public:
  Block_array() = default;
  Block_array(Block_array&&) = default;
  Block_array& operator=(Block_array&&) = default;
  // a deep copy, block by block (the blocks hold the elements, not pointers to them)
  Block_array(const Block_array& other) : m_size(other.m_size)
  {
    m_blocks.reserve(other.m_blocks.size());
    for(const auto& b : other.m_blocks)
    {
      m_blocks.emplace_back(new T[block_size]);
      std::copy(b.get(), b.get() + block_size, m_blocks.back().get());
    }
  }
  Block_array& operator=(const Block_array& other)
  {
    if(this != &other) { Block_array copy(other); *this = std::move(copy); }
    return *this;
  }

  std::size_t size() const { return m_size; }
  bool empty() const { return m_size == 0; }
  std::size_t capacity() const { return m_blocks.size() * block_size; }

  T& operator[](std::size_t i) { return m_blocks[i >> LogBlockSize][i & mask]; }
  const T& operator[](std::size_t i) const { return m_blocks[i >> LogBlockSize][i & mask]; }
  T& back() { return (*this)[m_size - 1]; }
  const T& back() const { return (*this)[m_size - 1]; }

  void reserve(std::size_t n)
  {
    while(capacity() < n)
      m_blocks.emplace_back(new T[block_size]);  // default-initialised: pages are touched on first write
  }

  // new elements are default-initialised (left unset for trivial types)
  void resize(std::size_t n)
  {
    reserve(n);
    m_size = n;
  }

  void assign(std::size_t n, const T& t)
  {
    resize(n);
    for(std::size_t i = 0; i < n; ++i) (*this)[i] = t;
  }

  void push_back(const T& t)
  {
    if(m_size == capacity())
      reserve(m_size + 1);
    (*this)[m_size++] = t;
  }

  // frees the blocks beyond the last used one
  void shrink_to_fit()
  {
    m_blocks.resize((m_size + block_size - 1) >> LogBlockSize);
    m_blocks.shrink_to_fit();
  }

  std::size_t memory_usage() const
  {
    return capacity() * sizeof(T) + m_blocks.capacity() * sizeof(std::unique_ptr<T[]>);
  }
};

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_BLOCK_ARRAY_H
