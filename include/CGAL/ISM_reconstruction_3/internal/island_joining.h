// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_ISLAND_JOINING_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_ISLAND_JOINING_H

#include <CGAL/ISM_reconstruction_3/internal/disjoint_sets.h>
#include <CGAL/ISM_reconstruction_3/internal/topology_estimation.h>
#include <CGAL/ISM_reconstruction_3/internal/winding_number.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// Joins every inside cluster but the largest to another inside cluster across one or two
// outside vertices, where this adds no handle. Why: where the points are sparse, a thin neck
// (the base of the bunny's ear tip at 3,000-8,000 points) can hold no inside vertex, while
// the tangent planes and the surface refinement sign a few vertices beyond it inside; those
// become a second component floating a leaf away from the body, too large for the island
// removal to take as a speck (bunny00, 20 samplings each: two components on 9 at 3,000
// points, 1 at 4,000 and 6,000, 1 at 8,000). Objects farther apart than two vertices, or
// than about three point spacings (`among_points`), stay apart (test_reconstruction's two
// spheres, the nested spheres). Each join flips the bridge of least |value| (its vertices
// nearest the points) and is kept only if 2 chi of the surface falls by exactly 4: one
// component fewer, no handle more. The box boundary stays outside, so that the surface
// stays closed. Returns the number of joins; `tiny`: the value of a flipped vertex whose
// value was 0. Joining
// already after the annealing, before the island removal (clusters of 5 vertices or more),
// to keep a sparse ear that the removal takes as a speck (non-uniform bunny, seed 199, 12
// vertices): the bar met on 56 of 80 non-uniform samplings (seeds 21-100) against 67; the
// annealing's other specks of that size, joined, left bumps and a handle.
// `among_points(x)`: whether the point x lies among the input points. Two vertices are two
// point spacings only where the leaves are small; between objects apart by far more than
// their point spacing the leaves are large, and two vertices spanned the gap (two spheres of
// radius 1 0.5 apart, 10k points each, were joined by a bar): a bridge vertex must lie among
// the points, and so must the middle of each edge that ties it to a cluster or to the other
// bridge vertex (five spheres of 800 points, 1.2 apart: a bridge vertex beside one sphere
// reached the next across a leaf edge as long as the gap, and three components came out).
template <class Leaves, class Among_points>
std::size_t join_islands(const Leaves& leaves, const std::vector<std::array<double, 3> >& xyz,
                         const std::vector<char>& boundary, std::vector<signed char>& signs,
                         std::vector<double>& values, double tiny, const Among_points& among_points)
{
  typedef typename Leaves::Cell_index Cell_index;
  const std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();
  const std::size_t n = signs.size();
  std::size_t joined = 0;
  std::vector<signed char> may_bridge(n, -1);  // among_points(xyz[v]), asked once
  const auto bridge_allowed = [&](std::size_t v) {
    if(may_bridge[v] < 0) may_bridge[v] = among_points(xyz[v]) ? 1 : 0;
    return may_bridge[v] != 0;
  };
  const auto edge_among_points = [&](std::size_t v, std::size_t w) {
    return among_points(std::array<double, 3>{{ (xyz[v][0] + xyz[w][0]) / 2, (xyz[v][1] + xyz[w][1]) / 2,
                                                (xyz[v][2] + xyz[w][2]) / 2 }});
  };
  for(;;)
  {
    std::vector<std::uint32_t> root, size;
    equal_sign_clusters(leaves, signs, root, size);
    std::uint32_t largest = none;
    std::size_t number_of_clusters = 0;
    for(std::size_t v = 0; v < n; ++v)
      if(size[v] > 0 && signs[v] < 0)
      {
        ++number_of_clusters;
        if(largest == none || size[v] > size[largest]) largest = std::uint32_t(v);
      }
    if(number_of_clusters < 2) return joined;

    // per outside vertex that may be a bridge, up to two inside clusters it shares a leaf with
    std::vector<std::array<std::uint32_t, 2> > near(n, {{ none, none }});
    for(std::size_t c = 0; c < leaves.number_of_cells(); ++c)
    {
      const auto& v = leaves.vertices(Cell_index(c));
      for(int i = 0; i < 4; ++i)
        if(signs[v[i]] > 0 && !boundary[v[i]])
          for(int j = 0; j < 4; ++j)
            if(signs[v[j]] < 0 && bridge_allowed(std::size_t(v[i])))
            {
              const std::uint32_t r = root[v[j]];
              std::array<std::uint32_t, 2>& a = near[v[i]];
              // the edge is asked only for a cluster not recorded yet: once per cluster
              // and bridge vertex, mostly
              if(a[1] != none || a[0] == r || !edge_among_points(std::size_t(v[i]), std::size_t(v[j]))) continue;
              if(a[0] == none) a[0] = r;
              else a[1] = r;
            }
    }
    // the cheapest bridge of each cluster but the largest: one outside vertex next to it and
    // to another cluster, or two outside vertices of a leaf, one next to each
    struct Bridge
    {
      double cost;
      std::uint32_t from, to, a, b;  // clusters, bridge vertices (b: none for one)
    };
    std::vector<Bridge> best(n, Bridge{ std::numeric_limits<double>::infinity(), none, none, none, none });
    const auto offer = [&](std::uint32_t s, std::uint32_t t, std::uint32_t a, std::uint32_t b) {
      const double cost = std::abs(values[a]) + (b == none ? 0. : std::abs(values[b]));
      if(s != largest && cost < best[s].cost) best[s] = Bridge{ cost, s, t, a, b };
    };
    for(std::size_t v = 0; v < n; ++v)
      if(near[v][1] != none)
      {
        offer(near[v][0], near[v][1], std::uint32_t(v), none);
        offer(near[v][1], near[v][0], std::uint32_t(v), none);
      }
    for(std::size_t c = 0; c < leaves.number_of_cells(); ++c)
    {
      const auto& v = leaves.vertices(Cell_index(c));
      for(int i = 0; i < 4; ++i)
        for(int j = 0; j < 4; ++j)
        {
          const std::uint32_t a = std::uint32_t(v[i]), b = std::uint32_t(v[j]);
          if(i == j || near[a][0] == none || near[b][0] == none) continue;
          bool asked = false, among = false;
          for(std::uint32_t s : near[a])
            for(std::uint32_t t : near[b])
              if(s != none && t != none && s != t)
              {
                if(!asked) among = edge_among_points(a, b), asked = true;
                if(among) offer(s, t, a, b);
              }
        }
    }
    std::vector<Bridge> bridges;
    for(const Bridge& br : best)
      if(br.a != none) bridges.push_back(br);
    if(bridges.empty()) return joined;
    std::sort(bridges.begin(), bridges.end(), [](const Bridge& x, const Bridge& y) { return x.cost < y.cost; });

    // the leaves around each bridge vertex, for the Euler characteristic of the change
    std::vector<char> in_bridge(n, 0);
    for(const Bridge& br : bridges)
    {
      in_bridge[br.a] = 1;
      if(br.b != none) in_bridge[br.b] = 1;
    }
    std::vector<std::pair<std::uint32_t, std::uint32_t> > around;  // (vertex, leaf)
    for(std::size_t c = 0; c < leaves.number_of_cells(); ++c)
      for(int i = 0; i < 4; ++i)
      {
        const std::uint32_t v = std::uint32_t(leaves.vertex(Cell_index(c), i));
        if(in_bridge[v]) around.push_back(std::make_pair(v, std::uint32_t(c)));
      }
    std::sort(around.begin(), around.end());
    const auto leaves_around = [&](std::uint32_t v, std::vector<std::uint32_t>& cells) {
      auto it = std::lower_bound(around.begin(), around.end(), std::make_pair(v, std::uint32_t(0)));
      for(; it != around.end() && it->first == v; ++it) cells.push_back(it->second);
    };

    // clusters joined in this round: a second bridge between them would make a handle,
    // which the Euler characteristic cannot tell from a join
    Disjoint_sets merged(n);
    std::vector<std::uint32_t> cells;
    std::vector<std::uint64_t> edges;
    std::size_t joined_now = 0;
    for(const Bridge& br : bridges)
    {
      if(merged.find(br.from) == merged.find(br.to) || signs[br.a] < 0 || (br.b != none && signs[br.b] < 0)) continue;
      cells.clear();
      leaves_around(br.a, cells);
      if(br.b != none) leaves_around(br.b, cells);
      std::sort(cells.begin(), cells.end());
      cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
      const auto touches_bridge = [&](std::uint64_t p, std::uint64_t q) {
        return p == br.a || q == br.a || (br.b != none && (p == br.b || q == br.b));
      };
      const long before = twice_euler_characteristic(leaves, cells, touches_bridge, signs, edges);
      signs[br.a] = -1;
      if(br.b != none) signs[br.b] = -1;
      if(twice_euler_characteristic(leaves, cells, touches_bridge, signs, edges) == before - 4)
      {
        for(std::uint32_t v : { br.a, br.b })
          if(v != none) values[v] = values[v] != 0 ? -std::abs(values[v]) : -tiny;
        merged.unite(br.from, br.to);
        ++joined_now;
      }
      else
      {
        signs[br.a] = 1;
        if(br.b != none) signs[br.b] = 1;
      }
    }
    if(joined_now == 0) return joined;
    joined += joined_now;
  }
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_ISLAND_JOINING_H
