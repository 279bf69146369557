// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_ISOLATED_POINTS_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_ISOLATED_POINTS_H

#include <CGAL/ISM_reconstruction_3/internal/for_each_index.h>
#include <CGAL/ISM_reconstruction_3/internal/point_neighbors.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// A point whose 12 nearest points spread this many times farther than the median point's
// is isolated: a scanner's stray return, not a sample of the surface. Samples stay well
// below: at most 1.8 times on a uniform 60k sampling of the bunny, 2.2 with 0.5 % noise,
// 4.9 with one half ten times sparser (a density falling 100-fold: 10). Of 360 uniform
// outliers in the bounding box of the 36k bunny 3-7 are above, 360 points spread 1-2
// diagonals around it 40 or more times.
constexpr double isolated_spacing_ratio = 20;
constexpr unsigned int isolated_spacing_neighbors = 12;

// Per point, whether it is isolated (above). Sets of no more points than the neighbours
// have none.
inline std::vector<char> isolated_points(const std::vector<std::array<double, 3> >& points,
                                         const Point_neighbors& neighbors)
{
  const unsigned int k = isolated_spacing_neighbors;
  std::vector<char> isolated(points.size(), 0);
  if(points.size() <= k) return isolated;
  std::vector<double> spread(points.size(), 0.);
  for_each_index(points.size(), [&](std::size_t i) {
    neighbors.for_nearest(points[i], k, [&](std::uint32_t, double d2) { spread[i] = (std::max)(spread[i], d2); });
  });
  std::vector<double> sorted(spread);
  std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
  const double limit2 = isolated_spacing_ratio * isolated_spacing_ratio * sorted[sorted.size() / 2];
  for(std::size_t i = 0; i < points.size(); ++i) isolated[i] = spread[i] > limit2;
  return isolated;
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_ISOLATED_POINTS_H
