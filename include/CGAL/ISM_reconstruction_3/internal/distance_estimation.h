// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_DISTANCE_ESTIMATION_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_DISTANCE_ESTIMATION_H

#include <CGAL/ISM_reconstruction_3/parameters.h>
#include <CGAL/ISM_reconstruction_3/internal/local_fitting.h>
#include <CGAL/ISM_reconstruction_3/internal/for_each_index.h>
#include <CGAL/ISM_reconstruction_3/internal/point_neighbors.h>

#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// The distance from `x` to the patch of points `patch[0..m)` in the plane fitted to them: the
// plane's distance where x lies over the patch, and past its rim (beyond the farthest point
// in x's direction) the distance to the rim added. The plane alone gave a vertex 2 point
// spacings past an ear's tip, along the tip's plane, the value 0.001 (the bunny with 0.5 %
// noise), and the surface bulged 2.8 % of the diagonal out to it.
inline double distance_to_patch(const Plane_fit& plane, const std::array<double, 3>& x,
                                const std::array<const std::array<double, 3>*, 12>& patch, unsigned int m)
{
  const double h = plane.signed_distance(x);
  const double n[3] = { double(plane.normal[0]), double(plane.normal[1]), double(plane.normal[2]) };
  double c[3] = { 0, 0, 0 };
  for(unsigned int i = 0; i < m; ++i)
    for(int d = 0; d < 3; ++d) c[d] += (*patch[i])[d] - x[d];
  for(double& a : c) a /= m;
  // u: from the patch's centroid towards x, in the plane
  const double cn = c[0] * n[0] + c[1] * n[1] + c[2] * n[2];
  double u[3] = { -(c[0] - cn * n[0]), -(c[1] - cn * n[1]), -(c[2] - cn * n[2]) };
  const double t = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  if(!(t > 0)) return std::abs(h);
  for(double& a : u) a /= t;
  double rim = -HUGE_VAL;  // along u, from the centroid
  for(unsigned int i = 0; i < m; ++i)
  {
    double along = 0;
    for(int d = 0; d < 3; ++d) along += ((*patch[i])[d] - x[d] - c[d]) * u[d];
    rim = (std::max)(rim, along);
  }
  const double past_rim = t - rim;
  return past_rim > 0 ? std::sqrt(h * h + past_rim * past_rim) : std::abs(h);
}

// Paper 4.3, extended to every vertex so that F is defined in the whole box:
// f(v) = S_v * d(v), d from the nearest data points found by CGAL's kd-tree. The value is
// never zero, so marching tetrahedra sees no degenerate crossing. Only the vertices from
// `first` on are estimated (those a refinement added), the others get 0.
inline std::vector<double> estimate_distances(const std::vector<std::array<double, 3> >& points,
                                              const Point_neighbors& neighbors,
                                              const std::vector<std::array<double, 3> >& vertices,
                                              const std::vector<signed char>& signs, Distance_estimate mode,
                                              const std::vector<char>& near_surface = std::vector<char>(),
                                              std::size_t first = 0)
{
  double box_lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, box_hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for(const auto& p : points)
    for(int d = 0; d < 3; ++d) { box_lo[d] = (std::min)(box_lo[d], p[d]); box_hi[d] = (std::max)(box_hi[d], p[d]); }
  const double diag = std::sqrt((box_hi[0] - box_lo[0]) * (box_hi[0] - box_lo[0]) + (box_hi[1] - box_lo[1]) * (box_hi[1] - box_lo[1]) +
                                (box_hi[2] - box_lo[2]) * (box_hi[2] - box_lo[2]));
  const double tiny = 1e-9 * (diag > 0 ? diag : 1.);
  // The plane fit only matters where marching tetrahedra interpolates: at the vertices of
  // leaves with a sign change (`near_surface`, all vertices if empty); elsewhere one
  // nearest point is enough to give F its magnitude.
  const unsigned int k_plane = mode == LOCAL_PLANE_DISTANCE ? unsigned((std::min<std::size_t>)(12, points.size())) : 1;
  std::vector<double> values(vertices.size());

  auto one = [&](std::size_t v) {
    const unsigned int k = (near_surface.empty() || near_surface[v]) ? k_plane : 1;
    double nearest2 = HUGE_VAL, farthest2 = 0;
    Moments moments(vertices[v]);
    std::array<const std::array<double, 3>*, 12> patch;
    unsigned int m = 0;
    neighbors.for_nearest(vertices[v], k, [&](std::uint32_t i, double d2) {
      nearest2 = (std::min)(nearest2, d2);
      farthest2 = (std::max)(farthest2, d2);
      moments.add(points[i]);
      if(m < patch.size()) patch[m++] = &points[i];
    });
    double d;
    if(mode == NEAREST_POINT_SQUARED_DISTANCE) d = nearest2;
    else d = std::sqrt(nearest2);
    Plane_fit plane;
    // near the points, the distance to their fitted plane (to the patch they span in it);
    // farther than the neighbourhood's radius the plane says nothing and the nearest point
    // is used
    if(mode == LOCAL_PLANE_DISTANCE && k > 1 && nearest2 <= 0.5 * farthest2 && moments.fit(plane))
      d = (std::min)(d, distance_to_patch(plane, vertices[v], patch, m));
    values[v] = signs[v] * (std::max)(d, mode == NEAREST_POINT_SQUARED_DISTANCE ? tiny * tiny : tiny);
  };
  for_chunks((std::min)(first, vertices.size()), vertices.size(), 1024, [&](std::size_t lo, std::size_t hi) {
    for(std::size_t v = lo; v < hi; ++v) one(v);
  });
  return values;
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_DISTANCE_ESTIMATION_H
