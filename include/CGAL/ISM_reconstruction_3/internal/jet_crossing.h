// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_JET_CROSSING_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_JET_CROSSING_H

#include <CGAL/ISM_reconstruction_3/internal/point_neighbors.h>
#include <CGAL/ISM_reconstruction_3/internal/point_smoothing.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// Where the surface crosses a leaf edge, for marching tetrahedra. F is linear along the
// edge, and its values are distance estimates from points up to a leaf away, so its zero
// crossing misses the points' surface by a fraction of the leaf: the mean distance to the
// truth was twice that of the points' own quadric (bunny at 36k points: 0.037 % of the
// diagonal against 0.019 %). The crossing moves along its edge onto the quadric fitted to
// its k nearest points (jet_projection(), the fit of the point smoothing), linearised at the
// foot of the crossing: two such steps. Each vertex stays on its edge, inside the leaves the
// surface crosses, so the surface keeps its triangles, its sides and its freedom from
// self-intersections; moving the vertices onto the quadric along its normal instead left 4-25
// intersecting pairs of triangles on the bunny with outliers (none on the edges).
// A move is refused where the fit is ill-posed: an edge within 6 degrees of tangent to the
// quadric, a crossing that ends 1.5 times farther from its nearest point than it started
// (a part with few points, where the quadric spans two sheets: bunny with 0.5 % noise, a
// crossing moved 1.3 % of the diagonal away from the points), or a move longer than half the
// reach of the fit (the distance to the k-th nearest point), where the quadric is
// extrapolated (3torus: 428 crossings ended more than 0.1 % of the diagonal farther from the
// truth, one 0.7 %, and put a query farther than 1 % on the wrong side; the bar over 20
// samplings of the bunny with one half ten times denser went 14 -> 15 of 20 with the limit).
// A move to an end of the edge stays allowed: there the quadric says that the surface does
// not cross the edge, and the crossing goes as near to the vertex as it may (refusing those
// lost a far query on the rotor and on the cow).
class Jet_crossing
{
public:
  typedef std::array<double, 3> Xyz;

  // `points` and `neighbors` must outlive the functor; k = 0: the linear crossing
  Jet_crossing(const std::vector<Xyz>& points, const Point_neighbors& neighbors, unsigned int k)
    : m_points(points), m_neighbors(neighbors), m_k(k)
  {}

  // the parameter in [0, 1] of the crossing on the edge [a, b], from F's linear crossing t
  double operator()(const Xyz& a, const Xyz& b, double t) const
  {
    if(m_k == 0 || m_points.empty()) return t;
    const Xyz e = {{ b[0] - a[0], b[1] - a[1], b[2] - a[2] }};
    const double length = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    // not past an end of the edge: a triangle of zero area is all the move may make
    const double lo = (std::min)(t, 1e-3), hi = (std::max)(t, 1 - 1e-3);
    const double start = t;
    Jet_frame at_start{{{ 0., 0., 0. }}, 0., 0.};  // reach 0: no move
    for(int step = 0; step < 2; ++step)
    {
      const Xyz x = at(a, e, t);
      Jet_frame frame;
      const Xyz y = jet_projection(x, m_points, m_neighbors, m_k, &frame);
      if(y == x) break;
      if(step == 0) at_start = frame;
      const Xyz& n = frame.normal;
      const double along = n[0] * e[0] + n[1] * e[1] + n[2] * e[2];
      if(!(std::abs(along) >= 0.1 * length)) break;
      const double s = (n[0] * (y[0] - a[0]) + n[1] * (y[1] - a[1]) + n[2] * (y[2] - a[2])) / along;
      t = (std::min)((std::max)(s, lo), hi);
    }
    if(t == start) return t;
    if(!(std::abs(t - start) * length <= 0.5 * at_start.radius)) return start;
    if(!(nearest_squared_distance(at(a, e, t)) <= 2.25 * at_start.nearest_squared_distance)) return start;
    return t;
  }

private:
  static Xyz at(const Xyz& a, const Xyz& e, double t) { return {{ a[0] + t * e[0], a[1] + t * e[1], a[2] + t * e[2] }}; }

  double nearest_squared_distance(const Xyz& x) const
  {
    double d2 = 0;
    m_neighbors.for_nearest(x, 1, [&](std::uint32_t, double d) { d2 = d; });
    return d2;
  }

  const std::vector<Xyz>& m_points;
  const Point_neighbors& m_neighbors;
  unsigned int m_k;
};

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_JET_CROSSING_H
