// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_TOPOLOGY_ESTIMATION_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_TOPOLOGY_ESTIMATION_H

#include <CGAL/ISM_reconstruction_3/internal/disjoint_sets.h>
#include <CGAL/ISM_reconstruction_3/internal/ising_annealing.h>
#include <CGAL/ISM_reconstruction_3/internal/local_fitting.h>
#include <CGAL/ISM_reconstruction_3/internal/memory_budget.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

struct Topology_input
{
  double empty_cell_error = 0.05;  // eps_empty as a fraction of [eps_min, eps_max]
};

// Calls f(begin, end) on the chunks of [0, size) of `chunk_size` indices, in parallel with
// TBB; the chunks are fixed, so what f computes per chunk does not depend on the threads.
constexpr std::size_t chunk_size = 4096;
template <class F>
void for_each_chunk(std::size_t size, const F& f)
{
  const std::size_t number_of_chunks = (size + chunk_size - 1) / chunk_size;
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_for(std::size_t(0), number_of_chunks,
                    [&](std::size_t k) { f(k * chunk_size, (std::min)(size, (k + 1) * chunk_size)); });
#else
  for(std::size_t k = 0; k < number_of_chunks; ++k) f(k * chunk_size, (std::min)(size, (k + 1) * chunk_size));
#endif
}

// What each leaf proposes (paper 4.2): the side of each of its vertices with respect to its
// plane, or that it is empty, and the coplanarity error that weighs its proposal. This is
// all the edge weights need from the fits and the point counts, 5 bytes a cell against their
// 32: the last topology pass frees those before it builds the graph (dragon, 437k points:
// the peak of the whole run, 225 -> 199 MB).
struct Leaf_proposals
{
  enum { empty_bit = 16 };
  // per cell: bit l set when vertex l is on the negative side; empty_bit for an empty leaf
  std::vector<unsigned char> code;
  std::vector<float> coplanarity_error;  // per cell with points
  double eps_min = 0, eps_max = 1;       // over the leaves with points
};

template <class Triangulation, class FitArray, class CountFunction>
Leaf_proposals propose_signs(const Triangulation& tr, const std::vector<std::array<double, 3> >& xyz,
                             const FitArray& fits, CountFunction count)
{
  typedef typename Triangulation::Cell_index Cell_index;
  Leaf_proposals p;
  double eps_min = HUGE_VAL, eps_max = -HUGE_VAL;
  for(Cell_index c = 0; c < Cell_index(tr.number_of_cells()); ++c)
    if(tr.is_leaf(c) && count(c) > 0)
    {
      eps_min = (std::min)(eps_min, double(fits[c].coplanarity_error));
      eps_max = (std::max)(eps_max, double(fits[c].coplanarity_error));
    }
  if(eps_max >= eps_min) { p.eps_min = eps_min; p.eps_max = eps_max; }
  const std::size_t number_of_cells = tr.number_of_cells();
  p.code.assign(number_of_cells, 0);
  p.coplanarity_error.assign(number_of_cells, 0.f);
  // computed once in cell order: each leaf is met from each of its 4 vertices, which would
  // otherwise read its plane, its point count and the vertex positions again at random
  for_each_chunk(number_of_cells, [&](std::size_t b, std::size_t e) {
    for(std::size_t c = b; c < e; ++c)
    {
      if(!tr.is_leaf(Cell_index(c))) continue;
      if(count(Cell_index(c)) == 0) { p.code[c] = Leaf_proposals::empty_bit; continue; }
      unsigned char bits = 0;
      for(int l = 0; l < 4; ++l)
        if(fits[Cell_index(c)].side(xyz[tr.vertex(Cell_index(c), l)]) < 0) bits |= (unsigned char)(1 << l);
      p.code[c] = bits;
      p.coplanarity_error[c] = fits[Cell_index(c)].coplanarity_error;
    }
  });
  return p;
}

// The edge weights of paper 4.2 on the leaf mesh:
//   H_e = - sum over leaves s around e of S^s_v0 S^s_v1 (eps_max - eps_s) / (eps_max - eps_min),
// where S^s_v is the side of v with respect to the plane of s; an empty leaf proposes the
// same sign for all its vertices with eps_s = eps_empty. Built per vertex from the leaves
// around it, so each edge's weight is summed in one place without a global hash.
// `proposals` are freed once read.
template <class Triangulation>
Coupling_graph build_coupling_graph(const Triangulation& tr, Leaf_proposals&& proposals, const Topology_input& in)
{
  typedef typename Triangulation::Cell_index Cell_index;
  const double eps_min = proposals.eps_min, eps_max = proposals.eps_max;
  const double range = eps_max > eps_min ? eps_max - eps_min : 1.;
  const double w_empty = 1. - in.empty_cell_error;
  const std::vector<float>& error = proposals.coplanarity_error;
  auto weight = [&](Cell_index c) {
    return eps_max > eps_min ? (eps_max - error[c]) / range : 1.;
  };
  const std::vector<unsigned char>& code = proposals.code;
  enum { empty_bit = Leaf_proposals::empty_bit };
  const std::size_t n = tr.number_of_vertices();

  std::vector<std::size_t> offsets;
  std::vector<Cell_index> cells;
  tr.leaves_around_vertices(offsets, cells);
  // The row of vertex u: its neighbours, in the order first met, and the summed weights (in
  // double precision). `slot` maps a vertex to its place in the row, -1 elsewhere as left
  // (searching the row instead took a fifth of the graph's time).
  auto build_row = [&](std::size_t u, std::vector<int>& neighbors, std::vector<double>& row, std::vector<int>& slot) {
    for(int v : neighbors) slot[v] = -1;
    neighbors.clear();
    row.clear();
    for(std::size_t i = offsets[u]; i < offsets[u + 1]; ++i)
    {
      const Cell_index c = cells[i];
      const unsigned char bits = code[c];
      const bool empty = (bits & empty_bit) != 0;
      const double w = empty ? w_empty : weight(c);
      int lu = 0;
      while(std::size_t(tr.vertex(c, lu)) != u) ++lu;
      for(int l = 0; l < 4; ++l)
      {
        if(l == lu) continue;
        const int v = tr.vertex(c, l);
        // S_u S_v = -1 exactly when the two sides differ
        const double h = (((bits >> l) ^ (bits >> lu)) & 1) ? w : -w;
        if(slot[v] < 0)
        {
          slot[v] = int(neighbors.size());
          neighbors.push_back(v);
          row.push_back(h);
        }
        else row[std::size_t(slot[v])] += h;
      }
    }
  };
  // The rows are built once, per chunk of vertices (in parallel with TBB), and
  // concatenated once the leaf incidences are freed: the peak (the rows twice) is then no
  // higher than that of the annealing, which also holds the graph twice. Each row depends
  // only on its vertex: the graph is the same for any number of threads.
  struct Rows
  {
    std::vector<std::size_t> degrees;
    std::vector<int> adjacency;
    std::vector<float> weights;
  };
  std::vector<Rows> parts((n + chunk_size - 1) / chunk_size);
  // one slot array per thread (4 bytes a vertex), all -1 between rows
#ifdef CGAL_LINKED_WITH_TBB
  tbb::enumerable_thread_specific<std::vector<int> > slots([n] { return std::vector<int>(n, -1); });
#else
  std::vector<int> the_slots(n, -1);
#endif
  for_each_chunk(n, [&](std::size_t b, std::size_t e) {
    Rows& part = parts[b / chunk_size];
#ifdef CGAL_LINKED_WITH_TBB
    std::vector<int>& slot = slots.local();
#else
    std::vector<int>& slot = the_slots;
#endif
    std::vector<int> neighbors;
    std::vector<double> row;
    for(std::size_t u = b; u < e; ++u)
    {
      build_row(u, neighbors, row, slot);
      part.degrees.push_back(neighbors.size());
      part.adjacency.insert(part.adjacency.end(), neighbors.begin(), neighbors.end());
      for(double h : row) part.weights.push_back(float(h));
    }
    for(int v : neighbors) slot[v] = -1;
    // exact sizes: the slack of the growth would add up to the size of the graph
    part.adjacency.shrink_to_fit();
    part.weights.shrink_to_fit();
  });
  std::vector<std::size_t>().swap(offsets);
  std::vector<Cell_index>().swap(cells);
  proposals = Leaf_proposals();
  Coupling_graph g;
  g.offsets.assign(n + 1, 0);
  std::size_t total = 0;
  for(const Rows& part : parts) total += part.adjacency.size();
  g.adjacency.reserve(total);
  g.weights.reserve(total);
  std::size_t u = 0;
  for(Rows& part : parts)
  {
    for(std::size_t d : part.degrees) { g.offsets[u + 1] = g.offsets[u] + d; ++u; }
    g.adjacency.insert(g.adjacency.end(), part.adjacency.begin(), part.adjacency.end());
    g.weights.insert(g.weights.end(), part.weights.begin(), part.weights.end());
    part = Rows();
  }
  // the parts are small heap blocks: returned, they do not add to the annealing's peak
  return_free_heap_memory();
  return g;
}

template <class Triangulation, class FitArray, class CountFunction>
Coupling_graph build_coupling_graph(const Triangulation& tr, const std::vector<std::array<double, 3> >& xyz,
                                    const FitArray& fits, CountFunction count, const Topology_input& in)
{
  return build_coupling_graph(tr, propose_signs(tr, xyz, fits, count), in);
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

// Clusters of vertices of equal sign connected by leaf edges, by union-find over the edges of
// each leaf: one pass over the leaves in memory order (the edge list of the triangulation,
// which an adjacency search needs, took 0.45 s of the dragon's 437k points). `root[v]`: the
// vertex that names v's cluster (of v's sign); `size[r]`: the number of vertices of the
// cluster named r, 0 if r names none.
template <class Triangulation>
void equal_sign_clusters(const Triangulation& tr, const std::vector<signed char>& signs,
                         std::vector<std::uint32_t>& root, std::vector<std::uint32_t>& size)
{
  typedef typename Triangulation::Cell_index Cell_index;
  const std::size_t n = signs.size();
  Disjoint_sets clusters(n);
  for(Cell_index c = 0; c < Cell_index(tr.number_of_cells()); ++c)
    if(tr.is_leaf(c)) unite_same_sign(tr.vertices(c), signs, [](std::uint32_t) { return true; }, clusters);
  root.resize(n);
  size.assign(n, 0);
  for(std::size_t v = 0; v < n; ++v)
  {
    root[v] = clusters.find(std::uint32_t(v));
    ++size[root[v]];
  }
}

// The number of clusters of inside vertices (connected by leaf edges).
template <class Triangulation>
std::size_t number_of_inside_clusters(const Triangulation& tr, const std::vector<signed char>& signs)
{
  std::vector<std::uint32_t> root, size;
  equal_sign_clusters(tr, signs, root, size);
  std::size_t clusters = 0;
  for(std::size_t v = 0; v < signs.size(); ++v)
    if(root[v] == v && signs[v] < 0) ++clusters;
  return clusters;
}

// Flips small islands of the in/out labelling: a cluster of inside vertices (connected by
// leaf edges) smaller than `fraction` of the largest inside cluster becomes outside, and a
// cluster of outside vertices that does not reach the box boundary and is smaller than that
// becomes inside. Noise leaves such specks (tiny spurious components or cavities) that no
// energy term distinguishes from real ones. Returns the number of clusters flipped.
template <class Triangulation>
std::size_t remove_islands(const Triangulation& tr, std::vector<signed char>& signs,
                           const std::vector<char>& boundary, double fraction)
{
  const std::size_t n = signs.size();
  std::vector<std::uint32_t> root, size;
  equal_sign_clusters(tr, signs, root, size);
  // per root: whether the cluster reaches the box boundary
  std::vector<char> touches_boundary(n, 0);
  for(std::size_t v = 0; v < n; ++v)
    if(boundary[v]) touches_boundary[root[v]] = 1;
  std::size_t largest_inside = 0;
  for(std::size_t v = 0; v < n; ++v)
    if(root[v] == v && signs[v] < 0) largest_inside = (std::max)(largest_inside, std::size_t(size[v]));
  const double threshold = fraction * double(largest_inside);
  std::vector<char> flip(n, 0);
  std::size_t flipped = 0;
  for(std::size_t v = 0; v < n; ++v)
    if(root[v] == v && double(size[v]) < threshold && (signs[v] < 0 || !touches_boundary[v]))
    {
      flip[v] = 1;
      ++flipped;
    }
  for(std::size_t v = 0; v < n; ++v)
    if(flip[root[v]]) signs[v] = static_cast<signed char>(-signs[v]);
  return flipped;
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_TOPOLOGY_ESTIMATION_H
