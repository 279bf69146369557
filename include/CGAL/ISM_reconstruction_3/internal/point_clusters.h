// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_POINT_CLUSTERS_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_POINT_CLUSTERS_H

#include <CGAL/ISM_reconstruction_3/internal/disjoint_sets.h>
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

// Several scans along the same beams, or points written again with rounding, put a few
// copies of each sample within a small fraction of the samples' spacing. The refinement
// counts points, not samples: a cell holding one such cluster of at least
// min_points_per_cell copies is bisected down to the deepest level, and the planes of the
// nearest points see a single sample. 5,000 directions on a sphere, each 8 times with
// radial noise 1e-4, came out in 470 pieces; 4 times, with genus 1; 9,000 points of the
// bunny 4 times (noise 1e-4 of the diagonal) with genus 10; 2,000 points 20 times, jittered
// by 1e-12, in 21 pieces. The same points once, or the clusters replaced by their
// centroids: one piece, genus 0.
//
// A point's cluster is its j nearest points when the (j+1)-th is more than
// `cluster_gap_ratio` times farther than the j-th. On surface samplings without copies
// 6-7 % of the points have such a gap (a close pair: the bunny, the armadillo, 5,000 random
// directions; 0.5 % noise 2 %), on the clouds above 95-100 %, with radial noise of 1/50 of
// the spacing still 97 %. So the clusters are merged only when more than
// `clustered_fraction` of the points are in one: a cloud without copies keeps every point.
constexpr double cluster_gap_ratio = 4;
constexpr unsigned int cluster_neighbors = 32;  // clusters of up to 31 copies
constexpr double clustered_fraction = 0.3;

// The size of the cluster of `x` (its nearest points before the first gap, itself
// included), or 0 without a gap among its `cluster_neighbors` nearest points.
inline unsigned int cluster_size(const std::array<double, 3>& x, const Point_neighbors& neighbors)
{
  double d2[cluster_neighbors];
  unsigned int k = 0;
  neighbors.for_nearest(x, cluster_neighbors, [&](std::uint32_t, double e2) { d2[k++] = e2; });
  // d2[0] is x itself (exact copies were removed when the points were read)
  for(unsigned int j = 1; j + 1 < k; ++j)
    if(d2[j + 1] > cluster_gap_ratio * cluster_gap_ratio * d2[j]) return j + 1;
  return 0;
}

// If most points are in clusters (above), the points with each cluster, and the clusters
// sharing points with it, replaced by their centroid, in the order of the clusters' first
// points (a run stays deterministic); else nothing (an empty vector).
inline std::vector<std::array<double, 3> > merged_point_clusters(const std::vector<std::array<double, 3> >& points,
                                                                const Point_neighbors& neighbors)
{
  typedef std::array<double, 3> Xyz;
  const std::size_t n = points.size();
  if(n <= cluster_neighbors) return {};
  // a sample of about 1,000 points decides (2.5 ms, the kd-tree then serves the next
  // stages): the clouds above are far from the bar on either side
  const std::size_t stride = (std::max)(std::size_t(1), n / 1000);
  std::size_t sampled = 0, clustered = 0;
  for(std::size_t i = 0; i < n; i += stride, ++sampled) clustered += cluster_size(points[i], neighbors) > 0;
  if(!(double(clustered) > clustered_fraction * double(sampled))) return {};

  std::vector<unsigned char> size(n, 0);
  for_each_index(n, [&](std::size_t i) { size[i] = static_cast<unsigned char>(cluster_size(points[i], neighbors)); });
  Disjoint_sets clusters(n);
  for(std::size_t i = 0; i < n; ++i)
    if(size[i] > 0)
      neighbors.for_nearest(points[i], size[i], [&](std::uint32_t j, double) { clusters.unite(std::uint32_t(i), j); });

  // sums of the offsets from each cluster's first point, which keeps the centroid's
  // precision far from the origin
  std::vector<std::uint32_t> slot(n, std::uint32_t(-1));
  std::vector<std::uint32_t> first;
  std::vector<Xyz> offset;
  std::vector<double> count;
  for(std::size_t i = 0; i < n; ++i)
  {
    std::uint32_t& s = slot[clusters.find(std::uint32_t(i))];
    if(s == std::uint32_t(-1))
    {
      s = std::uint32_t(first.size());
      first.push_back(std::uint32_t(i));
      offset.push_back({{ 0., 0., 0. }});
      count.push_back(0.);
    }
    for(int d = 0; d < 3; ++d) offset[s][d] += points[i][d] - points[first[s]][d];
    count[s] += 1;
  }
  std::vector<Xyz> merged(first.size());
  for(std::size_t s = 0; s < first.size(); ++s)
    for(int d = 0; d < 3; ++d) merged[s][d] = points[first[s]][d] + offset[s][d] / count[s];
  return merged;
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_POINT_CLUSTERS_H
