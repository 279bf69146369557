// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_LEAF_VERTICES_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_LEAF_VERTICES_H

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// The vertices of the leaves of a triangulation in one flat array, in cell order, seen as a
// triangulation whose cells are all leaves (the interface remove_islands() and
// remove_thin_handles() read). Why: after the topology these passes scan the leaves a dozen
// times; the cells hold 40 bytes each and half of them are inner cells, a leaf here 16 bytes
// (dragon, 437k points: 2.5M cells, 100 MB a scan, against 20 MB).
template <class Triangulation>
class Leaf_vertices
{
public:
  typedef typename Triangulation::Cell_index Cell_index;  // here the index of a leaf
  typedef typename Triangulation::Vertex_index Vertex_index;

  explicit Leaf_vertices(const Triangulation& tr) { assign(tr); }

  // the leaves of `tr` now (after further bisections); the old array is freed first
  void assign(const Triangulation& tr)
  {
    std::vector<std::array<Vertex_index, 4> >().swap(m_vertices);
    m_vertices.reserve(tr.number_of_leaves());
    for(typename Triangulation::Cell_index c = 0; c < typename Triangulation::Cell_index(tr.number_of_cells()); ++c)
      if(tr.is_leaf(c)) m_vertices.push_back(tr.vertices(c));
    m_number_of_vertices = tr.number_of_vertices();
  }

  std::size_t number_of_cells() const { return m_vertices.size(); }
  std::size_t number_of_vertices() const { return m_number_of_vertices; }
  bool is_leaf(Cell_index) const { return true; }
  Vertex_index vertex(Cell_index c, int i) const { return m_vertices[std::size_t(c)][i]; }
  const std::array<Vertex_index, 4>& vertices(Cell_index c) const { return m_vertices[std::size_t(c)]; }
  const std::vector<std::array<Vertex_index, 4> >& cells() const { return m_vertices; }

private:
  std::vector<std::array<Vertex_index, 4> > m_vertices;
  std::size_t m_number_of_vertices = 0;
};

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_LEAF_VERTICES_H
