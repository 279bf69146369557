// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_ESCAPE_RAYS_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_ESCAPE_RAYS_H

#include <CGAL/ISM_reconstruction_3/internal/handle_removal.h>
#include <CGAL/ISM_reconstruction_3/internal/point_neighbors.h>
#include <CGAL/ISM_reconstruction_3/internal/tangent_plane_signs.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// Where a thin part is about as thick as the noise (the bunny's ears with gaussian noise of
// 0.5 % of the diagonal) or two parts are close, the leaves hold both sides of it and the
// Ising signs put a leaf-thick slab on one side of the points inside; the tangent planes,
// oriented by that same function, confirm it. Such a slab is told by a test that does not
// use F: from an inside vertex away from the points, a ray pointing away from its nearest
// point leaves the box without coming near a point, whereas from a vertex of a closed
// sampled solid every ray meets the far wall. Five rays in a cone of 27 degrees about that
// direction must all leave: one ray slipped through a concave web of 3torus and opened a
// handle.

typedef std::array<double, 3> Escape_xyz;

// Whether the ray from `x` along the unit `direction` leaves the points' bounding box
// (grown by `hit_radius`) before passing nearer than `hit_radius` to a point. Sphere tracing: no point is nearer
// than the distance to the nearest point, so the ray advances by it (at least
// `hit_radius` a step). A ray still inside after 400 steps (grazing a surface) counts as
// stopped.
inline bool ray_escapes(const Point_neighbors& neighbors, Escape_xyz x, const Escape_xyz& direction,
                        double hit_radius)
{
  const Point_neighbors::Box& box = neighbors.bounding_box();
  for(int step = 0; step < 400; ++step)
  {
    if(!box.contains(x, hit_radius)) return true;
    double d = 0;
    neighbors.for_nearest(x, 1, [&](std::uint32_t, double d2) { d = std::sqrt(d2); });
    if(d < hit_radius) return false;
    for(int k = 0; k < 3; ++k) x[k] += d * direction[k];
  }
  return false;
}

// Whether all `rays` rays from `x` escape: one along the unit `u`, the others tilted from it
// by atan(`tilt`) around it.
inline bool all_rays_escape(const Point_neighbors& neighbors, const Escape_xyz& x, const Escape_xyz& u, int rays,
                            double tilt, double hit_radius)
{
  // e1, e2: an orthonormal basis of the plane orthogonal to u
  const Escape_xyz a = std::abs(u[0]) < 0.9 ? Escape_xyz{{ 1., 0., 0. }} : Escape_xyz{{ 0., 1., 0. }};
  Escape_xyz e1 = {{ u[1] * a[2] - u[2] * a[1], u[2] * a[0] - u[0] * a[2], u[0] * a[1] - u[1] * a[0] }};
  const double l1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  for(double& c : e1) c /= l1;
  const Escape_xyz e2 = {{ u[1] * e1[2] - u[2] * e1[1], u[2] * e1[0] - u[0] * e1[2], u[0] * e1[1] - u[1] * e1[0] }};
  for(int r = 0; r < rays; ++r)
  {
    Escape_xyz w = u;
    if(r > 0)
    {
      const double angle = 6.283185307179586 * (r - 1) / (rays - 1);
      for(int d = 0; d < 3; ++d) w[d] = u[d] + tilt * (std::cos(angle) * e1[d] + std::sin(angle) * e2[d]);
      const double l = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
      for(double& c : w) c /= l;
    }
    if(!ray_escapes(neighbors, x, w, hit_radius)) return false;
  }
  return true;
}

// Turns outside the inside vertices of the crossed leaves from which all `rays` rays
// escape (tested only where `worth_testing(v, u)`, u the unit vector away from the nearest
// point), then, once, those that became such vertices: a slab is a leaf or two thick (on
// the bunny with 0.5 % noise a second round turns 1-3 vertices, a third none), whereas
// through a part of the surface left unsampled (a scan without its underside) each further
// round dug deeper into the inside, up to 6 rounds, and opened handles. A vertex is tested
// once, and only if its nearest point is farther than its hit radius, `hit_radius_of(v)`
// (nearer, the tangent planes decide). The value of a vertex turned outside is its distance
// to its nearest point. `fixed`: the box boundary. Returns the number of vertices turned
// outside.
template <class Leaves, class HitRadiusOf, class WorthTesting>
std::size_t remove_escaping_inside(const Leaves& leaves, const std::vector<Escape_xyz>& vertex_xyz,
                                   const std::vector<Escape_xyz>& points, const Point_neighbors& neighbors,
                                   const std::vector<char>& fixed, int rays, const HitRadiusOf& hit_radius_of,
                                   const WorthTesting& worth_testing, std::vector<signed char>& signs, std::vector<double>& values)
{
  if(rays <= 0 || points.empty()) return 0;
  const double tilt = 0.5;
  std::vector<char> tested(signs.size(), 0);
  std::size_t turned = 0;
  for(int round = 0; round < 2; ++round)
  {
    const std::vector<std::uint32_t> candidates =
        untested_vertices_of_crossed_leaves(leaves, signs, tested, [&](std::uint32_t v) { return signs[v] < 0 && !fixed[v]; });
    std::vector<double> outside_value(candidates.size(), 0.);  // 0: stays inside
    for_each_index(candidates.size(), [&](std::size_t j) {
      const Escape_xyz& x = vertex_xyz[candidates[j]];
      Escape_xyz nearest{};
      double distance = 0;
      neighbors.for_nearest(x, 1, [&](std::uint32_t i, double d2) { nearest = points[i]; distance = std::sqrt(d2); });
      const double hit_radius = hit_radius_of(candidates[j]);
      if(!(distance > hit_radius)) return;
      const Escape_xyz u = {{ (x[0] - nearest[0]) / distance, (x[1] - nearest[1]) / distance, (x[2] - nearest[2]) / distance }};
      if(worth_testing(candidates[j], u) && all_rays_escape(neighbors, x, u, rays, tilt, hit_radius))
        outside_value[j] = distance;
    });
    std::size_t turned_now = 0;
    for(std::size_t j = 0; j < candidates.size(); ++j)
      if(outside_value[j] > 0)
      {
        signs[candidates[j]] = 1;
        values[candidates[j]] = (std::max)(outside_value[j], std::abs(values[candidates[j]]));
        ++turned_now;
      }
    turned += turned_now;
    if(turned_now == 0) break;
  }
  return turned;
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_ESCAPE_RAYS_H
