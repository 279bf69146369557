// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_HANDLE_REMOVAL_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_HANDLE_REMOVAL_H

#include <CGAL/ISM_reconstruction_3/internal/disjoint_sets.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// Whether the surface crosses a leaf: its vertices (`vertices`) carry both signs.
template <class Vertices>
bool is_crossed(const Vertices& v, const std::vector<signed char>& signs)
{
  return signs[v[0]] != signs[v[1]] || signs[v[0]] != signs[v[2]] || signs[v[0]] != signs[v[3]];
}

// Per vertex, 1 if it is a vertex of a leaf the surface crosses.
template <class Leaves>
std::vector<char> crossed_leaf_vertices(const Leaves& leaves, const std::vector<signed char>& signs)
{
  std::vector<char> on_crossed(signs.size(), 0);
  for(std::size_t c = 0; c < leaves.number_of_cells(); ++c)
  {
    const auto& v = leaves.vertices(typename Leaves::Cell_index(c));
    if(is_crossed(v, signs))
      for(int l = 0; l < 4; ++l) on_crossed[v[l]] = 1;
  }
  return on_crossed;
}

// The vertices of the leaves the surface crosses that are `wanted` and not `tested` yet,
// marked tested: one round of the passes that re-sign the surface's vertices and then test
// the vertices their changes expose.
template <class Leaves, class Wanted>
std::vector<std::uint32_t> untested_vertices_of_crossed_leaves(const Leaves& leaves, const std::vector<signed char>& signs,
                                                               std::vector<char>& tested, const Wanted& wanted)
{
  std::vector<std::uint32_t> found;
  for(std::size_t c = 0; c < leaves.number_of_cells(); ++c)
  {
    const auto& v = leaves.vertices(typename Leaves::Cell_index(c));
    if(!is_crossed(v, signs)) continue;
    for(int l = 0; l < 4; ++l)
      if(!tested[v[l]] && wanted(std::uint32_t(v[l])))
      {
        tested[v[l]] = 1;
        found.push_back(std::uint32_t(v[l]));
      }
  }
  return found;
}

// The longest edge of the leaf with vertices `v` (positions `xyz`): the size of a leaf.
template <class Vertices>
double longest_edge(const Vertices& v, const std::vector<std::array<double, 3> >& xyz)
{
  double longest2 = 0;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j)
    {
      double l2 = 0;
      for(int d = 0; d < 3; ++d) l2 += (xyz[v[i]][d] - xyz[v[j]][d]) * (xyz[v[i]][d] - xyz[v[j]][d]);
      longest2 = (std::max)(longest2, l2);
    }
  return std::sqrt(longest2);
}

// The leaves around the vertices v without `skip[v]`, as compressed rows: those of v are
// leaves[offsets[v]] .. leaves[offsets[v + 1] - 1] (none for the others).
template <class Triangulation>
void leaves_around_vertices(const Triangulation& tr, const std::vector<char>& skip,
                            std::vector<std::uint32_t>& offsets, std::vector<std::uint32_t>& leaves)
{
  typedef typename Triangulation::Cell_index Cell_index;
  const std::size_t n = tr.number_of_vertices();
  offsets.assign(n + 1, 0);
  for(Cell_index c = 0; c < Cell_index(tr.number_of_cells()); ++c)
    if(tr.is_leaf(c))
      for(int i = 0; i < 4; ++i)
        if(!skip[tr.vertex(c, i)]) ++offsets[tr.vertex(c, i) + 1];
  for(std::size_t v = 0; v < n; ++v) offsets[v + 1] += offsets[v];
  leaves.resize(offsets[n]);
  std::vector<std::uint32_t> fill(offsets.begin(), offsets.end() - 1);
  for(Cell_index c = 0; c < Cell_index(tr.number_of_cells()); ++c)
    if(tr.is_leaf(c))
      for(int i = 0; i < 4; ++i)
        if(!skip[tr.vertex(c, i)]) leaves[fill[tr.vertex(c, i)]++] = std::uint32_t(c);
}

// Whether adding v to the set X (`in_set`, its components in `sets`) closes a loop: v's
// link meets X in more pieces (connected by link edges) than X has components there.
// `slot` maps a vertex to its index in `link` and is -1 elsewhere, as it is left (a lookup
// per link vertex instead of a search of `link`: the search took a third of the pass).
template <class Triangulation>
bool closes_loop(const Triangulation& tr, const std::vector<std::uint32_t>& offsets,
                 const std::vector<std::uint32_t>& leaves, const std::vector<char>& in_set, Disjoint_sets& sets,
                 std::uint32_t v, std::vector<std::uint32_t>& link, std::vector<std::int32_t>& slot,
                 Disjoint_sets& pieces_of_link, std::vector<std::uint32_t>& roots)
{
  link.clear();
  for(std::uint32_t i = offsets[v]; i < offsets[v + 1]; ++i)
    for(int l = 0; l < 4; ++l)
    {
      const std::uint32_t w = std::uint32_t(tr.vertex(leaves[i], l));
      if(w != v && in_set[w] && slot[w] < 0)
      {
        slot[w] = std::int32_t(link.size());
        link.push_back(w);
      }
    }
  auto clear_slots = [&] { for(std::uint32_t w : link) slot[w] = -1; };
  if(link.size() < 2)
  {
    clear_slots();
    return false;
  }
  pieces_of_link.reset(link.size());
  // the link's edges: the pairs of other vertices of a leaf around v
  for(std::uint32_t i = offsets[v]; i < offsets[v + 1]; ++i)
  {
    std::uint32_t other[3];
    int k = 0;
    for(int l = 0; l < 4; ++l)
    {
      const std::uint32_t w = std::uint32_t(tr.vertex(leaves[i], l));
      if(w != v) other[k++] = w;
    }
    for(int a = 0; a < 3; ++a)
      for(int b = a + 1; b < 3; ++b)
        if(in_set[other[a]] && in_set[other[b]])
          pieces_of_link.unite(std::uint32_t(slot[other[a]]), std::uint32_t(slot[other[b]]));
  }
  clear_slots();
  std::size_t pieces = 0;
  roots.clear();
  for(std::uint32_t j = 0; j < link.size(); ++j)
  {
    if(pieces_of_link.find(j) == j) ++pieces;
    roots.push_back(sets.find(link[j]));
  }
  std::sort(roots.begin(), roots.end());
  return pieces > std::size_t(std::unique(roots.begin(), roots.end()) - roots.begin());
}

// Why: marching tetrahedra separates the inside vertices from the outside ones along the
// leaves, so the surface has exactly one handle per independent loop of the set of inside
// vertices (and as many loops in the outside set). Where a part of the surface is about
// one leaf thick (the ears of the bunny) or noisy, the signs can close such a loop only
// through vertices lying on the surface: a hole through a thin plate, a bridge of noise.
// Even the true in/out signs, sampled at the leaf vertices, make such handles (measured).
//
// One sweep over the vertices of one side (`side`: -1 inside, +1 outside), deepest first
// (largest |value|), grows the set X of that side. The vertices of the box boundary and
// those at least `depth` from the surface (`deep`) are in X from the start, their
// components already in `sets`: the sweep only visits the others. Adding v closes a loop
// in X (`closes_loop()`); such a v changes side instead of joining X. Loops through deeper
// vertices (the hole of a torus, the tube of a knot) are kept. `depth_order`, if given, replaces
// |value| as the depth that orders the sweep (remove_thin_handles() says when).
template <class Triangulation>
void open_shallow_loops(const Triangulation& tr, const std::vector<std::uint32_t>& offsets,
                        const std::vector<std::uint32_t>& leaves, const std::vector<char>& deep, signed char side,
                        Disjoint_sets& sets, std::vector<signed char>& signs, std::vector<double>& values,
                        const std::vector<double>* depth_order = nullptr)
{
  const std::vector<double>& depth_of = depth_order ? *depth_order : values;
  const std::size_t n = signs.size();
  std::vector<std::uint32_t> order;
  std::vector<char> in_set(n, 0);
  for(std::size_t v = 0; v < n; ++v)
    if(signs[v] == side)
    {
      if(deep[v]) in_set[v] = 1;
      else order.push_back(std::uint32_t(v));
    }
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const double da = std::abs(depth_of[a]), db = std::abs(depth_of[b]);
    return da != db ? da > db : a < b;  // ties by index: deterministic
  });
  std::vector<std::uint32_t> link;   // the vertices of v's link in X
  std::vector<std::int32_t> slot(n, -1);
  Disjoint_sets pieces_of_link(0);   // over the indices into `link`
  std::vector<std::uint32_t> roots;
  const auto join = [&](std::uint32_t v) {
    in_set[v] = 1;
    for(std::uint32_t i = offsets[v]; i < offsets[v + 1]; ++i)
      for(int l = 0; l < 4; ++l)
      {
        const std::uint32_t w = std::uint32_t(tr.vertex(leaves[i], l));
        if(in_set[w]) sets.unite(w, v);
      }
  };
  const std::uint32_t none = std::uint32_t(-1);
  std::vector<std::uint32_t> cut;  // the vertices that changed side, deepest first
  for(std::uint32_t v : order)
  {
    if(closes_loop(tr, offsets, leaves, in_set, sets, v, link, slot, pieces_of_link, roots))
    {
      signs[v] = static_cast<signed char>(-side);
      values[v] = -values[v];
      cut.push_back(v);
      continue;
    }
    join(v);
  }
  // A loop closed by v may be one the shallower vertices after it fill: a ring around a
  // vertex the order put later. So the cut vertices are offered again, deepest first,
  // until none joins; the same test lets them in, so none closes a loop the sweep opened.
  // Measured on the 36k bunny, 20 samplings, the robustness bar (genus 0, every query
  // farther than 1 % of the diagonal right): 0.25 % noise 15 -> 20, 0.5 % 17 -> 18 of 20
  // (the misses were dents where the core of an ear was cut).
  for(bool again = !cut.empty(); again;)
  {
    again = false;
    for(std::uint32_t& v : cut)
      if(v != none && !closes_loop(tr, offsets, leaves, in_set, sets, v, link, slot, pieces_of_link, roots))
      {
        signs[v] = side;
        values[v] = -values[v];
        join(v);
        v = none;
        again = true;
      }
  }
}

// The median longest edge of the leaves with vertices of both signs: the size of the
// leaves the surface crosses, the scale of its detail (it grows with the noise).
template <class Triangulation>
double median_surface_leaf_size(const Triangulation& tr, const std::vector<std::array<double, 3> >& xyz,
                                const std::vector<signed char>& signs)
{
  typedef typename Triangulation::Cell_index Cell_index;
  std::vector<double> sizes;
  for(Cell_index c = 0; c < Cell_index(tr.number_of_cells()); ++c)
    if(tr.is_leaf(c) && is_crossed(tr.vertices(c), signs)) sizes.push_back(longest_edge(tr.vertices(c), xyz));
  if(sizes.empty()) return 0;
  std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
  return sizes[sizes.size() / 2];
}

// Per vertex, the longest edge of the smallest leaf around it: the size of the leaves at
// that place. Where the sampling is uniform, at the vertices near the points it is the
// median size of the leaves the surface crosses or one level below (0.88 of it, measured on
// bunny00 at 36k points); where the points are sparser the leaves, and it, are larger.
constexpr double smallest_over_median_leaf = 0.88;
template <class Triangulation>
std::vector<float> smallest_leaf_at_vertices(const Triangulation& tr, const std::vector<std::array<double, 3> >& xyz)
{
  typedef typename Triangulation::Cell_index Cell_index;
  std::vector<float> size(tr.number_of_vertices(), HUGE_VALF);
  for(Cell_index c = 0; c < Cell_index(tr.number_of_cells()); ++c)
    if(tr.is_leaf(c))
    {
      const float e = float(longest_edge(tr.vertices(c), xyz));
      for(int l = 0; l < 4; ++l) size[tr.vertex(c, l)] = (std::min)(size[tr.vertex(c, l)], e);
    }
  return size;
}

// Removes the handles of the surface that only vertices nearer to the surface than
// `relative_depth` times the median size of the leaves it crosses hold open: first the
// outside sweep (a tunnel through a thin plate is filled), then the inside sweep (a thin
// bridge is cut). Returns the number of vertices that changed side.
// `local_size`: where the leaves at a vertex are larger than the median (their smallest over
// 0.88, as for the voting radius), their size instead: a sparser part of the sampling has
// larger leaves, and its handles as deep as the dense part's, relative to its leaves, stayed
// (bunny00, one half ten times denser: genus 1 on 2 of 20 samplings, 1 with this; 0.5 %
// noise: 1 of 20, 0).
// `inside_order`, if given, orders the inside sweep instead of |values| (which still decide
// which vertices are shallow): between the two walls of a thin part the paper's plane
// distance is about 0 (the nearest points lie on both walls), so the core of the part comes
// after its skin, whose two sides the sweep has then joined around the part's rim, and the
// core closes a loop and is cut. A depth that grows inwards keeps the part whole.
template <class Triangulation>
std::size_t remove_thin_handles(const Triangulation& tr, const std::vector<std::array<double, 3> >& xyz,
                                const std::vector<char>& boundary, double relative_depth,
                                std::vector<signed char>& signs, std::vector<double>& values,
                                const std::vector<double>* inside_order = nullptr, bool local_size = false)
{
  const double median = median_surface_leaf_size(tr, xyz, signs);
  if(!(median > 0)) return 0;
  typedef typename Triangulation::Cell_index Cell_index;
  const std::size_t n = signs.size();
  std::vector<float> local;
  if(local_size) local = smallest_leaf_at_vertices(tr, xyz);
  std::vector<char> deep(n);
  for(std::size_t v = 0; v < n; ++v)
  {
    const double size = local_size ? (std::max)(median, local[v] / smallest_over_median_leaf) : median;
    deep[v] = boundary[v] || !(std::abs(values[v]) < relative_depth * size);
  }
  std::vector<std::uint32_t> offsets, leaves;  // only the shallow vertices are visited
  leaves_around_vertices(tr, deep, offsets, leaves);
  // the components of the deep vertices of each side, one pass over the leaves (in order
  // in memory, unlike vertex by vertex)
  Disjoint_sets sets(n);
  for(Cell_index c = 0; c < Cell_index(tr.number_of_cells()); ++c)
    if(tr.is_leaf(c)) unite_same_sign(tr.vertices(c), signs, [&](std::uint32_t v) { return deep[v] != 0; }, sets);
  const std::vector<signed char> before = signs;
  open_shallow_loops(tr, offsets, leaves, deep, 1, sets, signs, values);
  // the outside sweep only moved shallow vertices: the deep ones inside keep their components
  open_shallow_loops(tr, offsets, leaves, deep, -1, sets, signs, values, inside_order);
  std::size_t changed = 0;
  for(std::size_t v = 0; v < n; ++v) changed += signs[v] != before[v];
  return changed;
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_HANDLE_REMOVAL_H
