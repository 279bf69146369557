// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_TOPOLOGY_ESTIMATION_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_TOPOLOGY_ESTIMATION_H

#include <CGAL/ISM_reconstruction_3/internal/ising_annealing.h>
#include <CGAL/ISM_reconstruction_3/internal/local_fitting.h>

#include <algorithm>
#include <array>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

struct Topology_input
{
  double empty_cell_error = 0.05;  // eps_empty as a fraction of [eps_min, eps_max]
};

// The edge weights of paper 4.2 on the leaf mesh:
//   H_e = - sum over leaves s around e of S^s_v0 S^s_v1 (eps_max - eps_s) / (eps_max - eps_min),
// where S^s_v is the side of v with respect to the plane of s; an empty leaf proposes the
// same sign for all its vertices with eps_s = eps_empty. Built per vertex from the leaves
// around it, so each edge's weight is summed in one place without a global hash.
template <class Triangulation, class CountFunction>
Coupling_graph build_coupling_graph(const Triangulation& tr, const std::vector<std::array<double, 3> >& xyz,
                                    const std::vector<Plane_fit>& fits, CountFunction count,
                                    const Topology_input& in)
{
  typedef typename Triangulation::Cell_index Cell_index;
  double eps_min = HUGE_VAL, eps_max = -HUGE_VAL;
  for(Cell_index c = 0; c < Cell_index(tr.number_of_cells()); ++c)
    if(tr.is_leaf(c) && count(c) > 0)
    {
      eps_min = (std::min)(eps_min, fits[c].coplanarity_error);
      eps_max = (std::max)(eps_max, fits[c].coplanarity_error);
    }
  if(!(eps_max >= eps_min)) { eps_min = 0; eps_max = 1; }
  const double range = eps_max > eps_min ? eps_max - eps_min : 1.;
  const double w_empty = 1. - in.empty_cell_error;
  auto weight = [&](Cell_index c) {
    return eps_max > eps_min ? (eps_max - fits[c].coplanarity_error) / range : 1.;
  };

  std::vector<std::size_t> offsets;
  std::vector<Cell_index> cells;
  tr.leaves_around_vertices(offsets, cells);
  const std::size_t n = tr.number_of_vertices();
  Coupling_graph g;
  g.offsets.assign(n + 1, 0);
  g.adjacency.reserve(14 * n);
  g.weights.reserve(14 * n);
  for(std::size_t u = 0; u < n; ++u)
  {
    const std::size_t first = g.adjacency.size();
    for(std::size_t i = offsets[u]; i < offsets[u + 1]; ++i)
    {
      const Cell_index c = cells[i];
      const bool empty = count(c) == 0;
      const double w = empty ? w_empty : weight(c);
      const int su = empty ? 1 : fits[c].side(xyz[u]);
      for(int l = 0; l < 4; ++l)
      {
        const int v = tr.vertex(c, l);
        if(std::size_t(v) == u) continue;
        const int sv = empty ? 1 : fits[c].side(xyz[v]);
        const double h = -double(su * sv) * w;
        std::size_t j = first;
        while(j < g.adjacency.size() && g.adjacency[j] != v) ++j;
        if(j == g.adjacency.size()) { g.adjacency.push_back(v); g.weights.push_back(h); }
        else g.weights[j] += h;
      }
    }
    g.offsets[u + 1] = g.adjacency.size();
  }
  return g;
}

// The vertices on the boundary of the box: those of leaf faces without a neighbour.
template <class Triangulation>
std::vector<char> box_boundary_vertices(const Triangulation& tr)
{
  typedef typename Triangulation::Cell_index Cell_index;
  std::vector<char> boundary(tr.number_of_vertices(), 0);
  for(Cell_index c = 0; c < Cell_index(tr.number_of_cells()); ++c)
    if(tr.is_leaf(c))
      for(int i = 0; i < 4; ++i)
        if(tr.neighbor(c, i) < 0)
          for(int l = 0; l < 4; ++l)
            if(l != i) boundary[tr.vertex(c, l)] = 1;
  return boundary;
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_TOPOLOGY_ESTIMATION_H
