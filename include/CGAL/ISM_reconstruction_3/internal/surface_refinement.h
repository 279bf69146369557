// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_SURFACE_REFINEMENT_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_SURFACE_REFINEMENT_H

#include <CGAL/ISM_reconstruction_3/internal/handle_removal.h>
#include <CGAL/ISM_reconstruction_3/internal/tangent_plane_signs.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// Why: the refinement stops a cell below the minimum number of points, so the leaves the
// surface crosses are about as large as 2-5 % of the box diagonal on 36k points. F is linear
// in a leaf: where the surface bends within one (the rim of the bunny's base, an ear tip)
// its zero level cuts the bend as a chord, up to 1 % of the diagonal away from the points
// (measured on bunny00: every query farther than 1 % on the wrong side was such a leaf, its
// four signs right). The points say where this happens: F should vanish on them.
//
// The indices of `points` in Morton (Z-curve) order of a 2^21 grid over their bounding box:
// consecutive points are near each other, so each is located by a short walk from the leaf
// of the one before (deterministic, unlike a shuffled spatial sort).
inline std::vector<std::uint32_t> morton_order(const std::vector<std::array<double, 3> >& points)
{
  double lo[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  for(const auto& p : points)
    for(int d = 0; d < 3; ++d) { lo[d] = (std::min)(lo[d], p[d]); hi[d] = (std::max)(hi[d], p[d]); }
  auto spread = [](std::uint64_t x) {  // the 21 bits of x, two zero bits between each
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffULL;
    x = (x | x << 16) & 0x1f0000ff0000ffULL;
    x = (x | x << 8) & 0x100f00f00f00f00fULL;
    x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2) & 0x1249249249249249ULL;
    return x;
  };
  std::vector<std::pair<std::uint64_t, std::uint32_t> > keys(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    std::uint64_t key = 0;
    for(int d = 0; d < 3; ++d)
    {
      const double t = hi[d] > lo[d] ? (points[i][d] - lo[d]) / (hi[d] - lo[d]) : 0.;
      key |= spread(std::uint64_t(t * double(0x1fffff))) << d;
    }
    keys[i] = std::make_pair(key, std::uint32_t(i));
  }
  std::sort(keys.begin(), keys.end());
  std::vector<std::uint32_t> order(points.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = keys[i].second;
  return order;
}

// The leaves in which F misses a point `points[i]` by more than `tolerance` times the
// leaf's longest edge and more than `noise_factor` times the median miss over all points
// (noise makes every point miss by about its amplitude; a bend misses by more), sorted,
// without the leaves at `max_level`. `value_in_leaf(c, x)` is F at x in leaf c; `order`
// (`morton_order(points)`) is the order in which the points are located, each by a walk from
// the leaf of the one before.
template <class Triangulation, class ValueInLeaf>
std::vector<typename Triangulation::Cell_index>
misfit_leaves(const Triangulation& tr, const std::vector<std::array<double, 3> >& xyz,
              const std::vector<std::array<double, 3> >& points, const std::vector<std::uint32_t>& order,
              const ValueInLeaf& value_in_leaf, double tolerance, double noise_factor, int max_level)
{
  typedef typename Triangulation::Cell_index Cell_index;
  typedef typename Triangulation::Point_3 Point_3;
  const std::size_t n = points.size();
  std::vector<Cell_index> leaf(n, -1);
  std::vector<float> miss(n, 0.f), size(n, 0.f);
  const std::size_t chunk = 256;
  for_each_index((n + chunk - 1) / chunk, [&](std::size_t k) {
    Cell_index hint = -1;
    for(std::size_t j = k * chunk; j < (std::min)(n, (k + 1) * chunk); ++j)
    {
      const std::size_t i = order[j];
      const Point_3 p(points[i][0], points[i][1], points[i][2]);
      Cell_index c = tr.walk_to(p, hint);
      if(c < 0)
      {
        if(tr.locate_root(p) < 0) continue;
        c = tr.locate(p);
      }
      hint = c;
      leaf[i] = c;
      miss[i] = float(std::abs(value_in_leaf(c, points[i])));
      size[i] = float(longest_edge(tr.vertices(c), xyz));
    }
  });
  std::vector<Cell_index> result;
  if(n == 0) return result;
  std::vector<float> sorted(miss);
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
  const double noise = noise_factor * double(sorted[n / 2]);
  for(std::size_t i = 0; i < n; ++i)
    if(leaf[i] >= 0 && tr.level(leaf[i]) < max_level && miss[i] > tolerance * size[i] && miss[i] > noise)
      result.push_back(leaf[i]);
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_SURFACE_REFINEMENT_H
