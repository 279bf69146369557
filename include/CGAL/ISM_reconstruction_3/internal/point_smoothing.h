// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_POINT_SMOOTHING_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_POINT_SMOOTHING_H

#include <CGAL/ISM_reconstruction_3/internal/for_each_index.h>
#include <CGAL/ISM_reconstruction_3/internal/local_fitting.h>
#include <CGAL/ISM_reconstruction_3/internal/point_neighbors.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// Why: the Ising vote trusts each cell's plane. With gaussian noise of 0.5 % of the diagonal
// on the bunny, points stray 1-2 % off the surface and the planes of the small cells near
// them tilt, so that vertices up to 1.9 % deep inside took the outside sign (26-79 queries
// farther than 1 % of the diagonal on the wrong side, 3 samplings). Moving each point onto
// a quadric fitted to its neighbours (jet smoothing, as CGAL's jet_smooth_point_set, which
// took 1.3-2.8 s on 36k points against 0.1 s here) removes most of that noise before the
// refinement sees it. On clean points it would only blur detail, hence the noise test.

// The median coplanarity error of the k nearest points of every `stride`-th point: about
// 0.001 on clean scans (bunny00 at 36k points: 0.0007, the dragon: 0.005), 0.02 with
// gaussian noise of 0.1 % of the diagonal, 0.08 at 0.25 %, 0.13 at 0.5 % (k = 12).
inline double median_neighborhood_coplanarity(const std::vector<std::array<double, 3> >& points,
                                              const Point_neighbors& neighbors, unsigned int k, std::size_t stride)
{
  stride = (std::max)(stride, std::size_t(1));
  const std::size_t n = points.empty() ? 0 : (points.size() - 1) / stride + 1;
  if(n == 0) return 0;
  std::vector<float> errors(n, 0.f);
  for_each_index(n, [&](std::size_t j) {
    const std::array<double, 3>& p = points[j * stride];
    Moments moments(p);
    neighbors.for_nearest(p, k, [&](std::uint32_t i, double) { moments.add(points[i]); });
    Plane_fit fit;
    if(moments.fit(fit)) errors[j] = fit.coplanarity_error;
  });
  std::nth_element(errors.begin(), errors.begin() + std::ptrdiff_t(n / 2), errors.end());
  return double(errors[n / 2]);
}

// The neighbours the jet fit takes: at least `k`, more where the points are dense for their
// noise. The bunny at 300k points with gaussian noise of 0.5 % of the diagonal: its 24
// nearest points reach only about 1.3 sigma, their quadric follows the noise, and the output
// followed the noise's outer shell (vertices up to 2.1 % of the diagonal outside, about 200
// beyond 1 %); with 64 neighbours none beyond 1 %. At 36k points 24 reach 3 sigma, and 64
// over-smoothed the ears (vertices beyond 1 %: 2-19 -> 174-319). Sigma is measured as the
// median thickness (root mean square distance to their plane) of the 4k nearest points of
// every `stride`-th point, the reach as the median distance to the k-th nearest; k grows
// with the square of the reach missing to `jet_reach_over_noise` times sigma, up to 64 (the
// 12-neighbour coplanarity error cannot tell the densities apart: it saturates, 0.136,
// 0.147, 0.155 at 36k, 100k, 300k points).
// The bunny at 36k points with noise of 0.5 % of the diagonal, for which 24 neighbours were
// chosen, has a reach of 2.96 sigma by this measure (100k: 2.27, 300k: 1.84); below 2.7 the
// neighbours grow, so that the samplings the 24 were measured on keep them.
// Only points dense for their noise get more than one pass: where k points reach 2.7
// sigma, one pass takes the noise off, and every further pass pulls the two walls of a
// thin part towards each other, their noisy points being each other's neighbours. The
// bunny's own 37,706 vertices (its ears sampled 0.6 times as densely as by area) with
// noise of 0.5 % of the diagonal: three passes made the ears one sheet with a dent through
// it and met the robustness bar on 17 of 30 samplings, one pass on 25. Denser points need
// the passes: mean distance 0.095 % of the diagonal at 100k points instead of 0.108 % with
// one pass, 0.077 % instead of 0.105 % at 300k.
constexpr double jet_reach_over_noise = 2.7;
struct Jet_smoothing_plan
{
  unsigned int neighbors;
  bool dense_for_noise;  // k points reach less than jet_reach_over_noise sigma: all passes
};
inline Jet_smoothing_plan jet_smoothing_plan(const std::vector<std::array<double, 3> >& points,
                                             const Point_neighbors& neighbors, unsigned int k, std::size_t stride)
{
  stride = (std::max)(stride, std::size_t(1));
  const std::size_t n = points.empty() ? 0 : (points.size() - 1) / stride + 1;
  if(n == 0) return {k, false};
  std::vector<float> reach(n, 0.f), thickness(n, 0.f);
  for_each_index(n, [&](std::size_t j) {
    const std::array<double, 3>& p = points[j * stride];
    std::vector<std::uint32_t> near;
    Moments moments(p);
    unsigned int rank = 0;
    neighbors.for_nearest(p, 4 * k, [&](std::uint32_t i, double d2) {
      if(++rank == k) reach[j] = float(std::sqrt(d2));
      near.push_back(i);
      moments.add(points[i]);
    });
    Plane_fit fit;
    if(!moments.fit(fit) || near.empty()) return;
    double sum = 0;
    for(std::uint32_t i : near) sum += fit.signed_distance(points[i]) * fit.signed_distance(points[i]);
    thickness[j] = float(std::sqrt(sum / double(near.size())));
  });
  const auto median = [](std::vector<float>& v) {
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return double(v[v.size() / 2]);
  };
  const double r = median(reach), sigma = median(thickness);
  const double missing = jet_reach_over_noise * sigma / r;  // > 1: the reach falls short
  if(!(r > 0) || !(missing > 1)) return {k, false};
  return {unsigned((std::min)(64., std::ceil(double(k) * missing * missing))), true};
}

// The jet projection of `p`: along the normal of the PCA plane of its k nearest points,
// onto the quadric h(u, v) = a0 + a1 u + a2 v + a3 u^2 + a4 uv + a5 v^2 fitted by least
// squares to its k nearest points (itself included) in that plane's frame. A quadric, not
// the plane: projecting on the plane flattened the curved parts (clean bunny: mean distance
// 0.039 -> 0.081 % of the diagonal; with the quadric 0.041 %). Where the quadric is not
// determined (fewer than 6 points, all on a line), the point goes onto the plane.
// `p` itself if the points do not fit a plane.
// What the projection of a point saw, for a caller that judges the move: the PCA normal, the
// distance to the farthest of the k points (the reach of the fit) and the squared distance
// to the nearest.
struct Jet_frame
{
  std::array<double, 3> normal;
  double radius;
  double nearest_squared_distance;
};

inline std::array<double, 3> jet_projection(const std::array<double, 3>& p, const std::vector<std::array<double, 3> >& points,
                                            const Point_neighbors& neighbors, unsigned int k,
                                            Jet_frame* frame = nullptr)
{
  std::uint32_t near[64];
  const unsigned int m = (std::min)(k, 64u);
  unsigned int count = 0;
  double nearest2 = std::numeric_limits<double>::infinity();
  Moments moments(p);
  neighbors.for_nearest(p, m, [&](std::uint32_t q, double d2) {
    near[count++] = q;
    nearest2 = (std::min)(nearest2, d2);
    moments.add(points[q]);
  });
  Plane_fit fit;
  if(!moments.fit(fit)) return p;
  const Eigen::Vector3d n(fit.normal[0], fit.normal[1], fit.normal[2]);
  const Eigen::Vector3d t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  // the frame is scaled by the neighbourhood's radius: the normal equations stay well
  // conditioned whatever the units
  double radius2 = 0;
  for(unsigned int j = 0; j < count; ++j)
  {
    const std::array<double, 3>& q = points[near[j]];
    radius2 = (std::max)(radius2, (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) + (q[2] - p[2]) * (q[2] - p[2]));
  }
  if(!(radius2 > 0)) return p;
  const double scale = 1. / std::sqrt(radius2);
  if(frame) *frame = Jet_frame{{{ n[0], n[1], n[2] }}, std::sqrt(radius2), nearest2};
  Eigen::Matrix<double, 6, 6> normal_matrix = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
  for(unsigned int j = 0; j < count; ++j)
  {
    const std::array<double, 3>& q = points[near[j]];
    const Eigen::Vector3d d(q[0] - p[0], q[1] - p[1], q[2] - p[2]);
    const double u = d.dot(t1) * scale, v = d.dot(t2) * scale, h = d.dot(n) * scale;
    const Eigen::Matrix<double, 6, 1> row = (Eigen::Matrix<double, 6, 1>() << 1, u, v, u * u, u * v, v * v).finished();
    normal_matrix.noalias() += row * row.transpose();
    rhs += h * row;
  }
  double a0 = -fit.signed_distance(p) * scale;  // the plane, unless the quadric is determined
  if(count >= 6)
  {
    const Eigen::LDLT<Eigen::Matrix<double, 6, 6> > ldlt(normal_matrix);
    // the points do not pin a quadric down (all on a line or a conic of the plane) when a
    // pivot vanishes; then, or for a jump beyond the neighbourhood, the plane
    const Eigen::Matrix<double, 6, 1> pivots = ldlt.vectorD().cwiseAbs();
    if(ldlt.info() == Eigen::Success && pivots.minCoeff() > 1e-10 * pivots.maxCoeff())
    {
      const Eigen::Matrix<double, 6, 1> a = ldlt.solve(rhs);
      if(std::isfinite(a[0]) && std::abs(a[0]) <= 1.) a0 = a[0];
    }
  }
  const double shift = a0 / scale;
  return {{ p[0] + shift * n[0], p[1] + shift * n[1], p[2] + shift * n[2] }};
}

// One jet-smoothing step: every point moved by its jet projection.
inline std::vector<std::array<double, 3> > jet_smoothed(const std::vector<std::array<double, 3> >& points,
                                                        const Point_neighbors& neighbors, unsigned int k)
{
  std::vector<std::array<double, 3> > smoothed(points.size());
  for_each_index(points.size(), [&](std::size_t i) { smoothed[i] = jet_projection(points[i], points, neighbors, k); });
  return smoothed;
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_POINT_SMOOTHING_H
