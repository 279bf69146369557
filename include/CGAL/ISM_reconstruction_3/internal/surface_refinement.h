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
// Where the sampling is sparser than elsewhere the leaves the surface crosses stay larger
// than the median one, and a chord there cuts deeper: a leaf this many times the median is
// in such a part, and gets passes of its own. A uniform sampling has no misfit leaf of that
// size after the first passes (bunny00 at 36k points, the 30 meshes of the survey), but
// crossed ones near the points, from none to about 1,100 (as the median falls among the
// levels' sizes): on 100 clean samplings of bunny00 1.8 % more output vertices.
constexpr double sparse_leaf_factor = 1.5;

// The leaves in which F misses a point `points[i]` by more than `tolerance` times the
// leaf's longest edge and more than `noise_factor` times the median miss over all points
// (noise makes every point miss by about its amplitude; a bend misses by more), sorted,
// without the leaves at `max_level` and those whose longest edge is not above `min_size`.
// `leaf_of(i)` is the leaf holding `points[i]` (-1: none), `value_in_leaf(c, x)` F at x in
// leaf c.
template <class Triangulation, class LeafOf, class ValueInLeaf>
std::vector<typename Triangulation::Cell_index>
misfit_leaves(const Triangulation& tr, const std::vector<std::array<double, 3> >& xyz,
              const std::vector<std::array<double, 3> >& points, const LeafOf& leaf_of,
              const ValueInLeaf& value_in_leaf, double tolerance, double noise_factor, int max_level,
              double min_size = 0.)
{
  typedef typename Triangulation::Cell_index Cell_index;
  const std::size_t n = points.size();
  std::vector<Cell_index> leaf(n, -1);
  std::vector<float> miss(n, 0.f), size(n, 0.f);
  for_each_index(n, [&](std::size_t i) {
    const Cell_index c = leaf_of(std::uint32_t(i));
    if(c < 0) return;
    leaf[i] = c;
    miss[i] = float(std::abs(value_in_leaf(c, points[i])));
    size[i] = float(longest_edge(tr.vertices(c), xyz));
  });
  std::vector<Cell_index> result;
  if(n == 0) return result;
  std::vector<float> sorted(miss);
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
  const double noise = noise_factor * double(sorted[n / 2]);
  for(std::size_t i = 0; i < n; ++i)
    if(leaf[i] >= 0 && tr.level(leaf[i]) < max_level && miss[i] > tolerance * size[i] && miss[i] > noise &&
       size[i] > min_size)
      result.push_back(leaf[i]);
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

// The leaves the surface crosses that are longer than `min_size` and whose four vertices have
// |value| below `max_value` (near the points), without those at `max_level`, sorted.
// Why: such a leaf of a sparse part can hold a bend of the surface and no point to show F
// missing it. Traced on the 36k bunny with one half ten times denser: the far query most
// samplings got wrong lies 1.05 % of the diagonal inside an ear of the sparse half, in a
// leaf whose vertices are 1.7-2.3 % from it and at most 0.5 % from the truth, three of them
// signed right: F, linear there, misses the ear's core. The vertices near the points keep
// out the leaves that reach into empty space: with 1 % outliers in the box, bisecting those
// too grew shells among the outliers (the bar met on 7 of 100 samplings instead of 100).
template <class Triangulation>
std::vector<typename Triangulation::Cell_index>
sparse_crossed_leaves(const Triangulation& tr, const std::vector<std::array<double, 3> >& xyz,
                      const std::vector<signed char>& signs, const std::vector<double>& values, double min_size,
                      double max_value, int max_level)
{
  typedef typename Triangulation::Cell_index Cell_index;
  std::vector<Cell_index> result;
  for(Cell_index c = 0; c < Cell_index(tr.number_of_cells()); ++c)
  {
    if(!tr.is_leaf(c) || tr.level(c) >= max_level) continue;
    const auto& v = tr.vertices(c);
    if(!is_crossed(v, signs) || !(longest_edge(v, xyz) > min_size)) continue;
    bool near = true;
    for(int l = 0; l < 4; ++l) near = near && std::abs(values[v[l]]) < max_value;
    if(near) result.push_back(c);
  }
  return result;
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_SURFACE_REFINEMENT_H
