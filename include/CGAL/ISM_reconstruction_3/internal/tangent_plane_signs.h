// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_TANGENT_PLANE_SIGNS_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_TANGENT_PLANE_SIGNS_H

#include <CGAL/ISM_reconstruction_3/internal/for_each_index.h>
#include <CGAL/ISM_reconstruction_3/internal/local_fitting.h>
#include <CGAL/ISM_reconstruction_3/internal/point_neighbors.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// The Ising signs are decided on the leaves' vertices, and the leaves near the points are
// about as large as a thin part of the surface is thick (an ear tip, a foot of the bunny):
// one vertex inside such a part given the wrong sign loses a piece of it a leaf deep. The
// points know better there, once their normals are oriented: the sign of a vertex near the
// points is the side of their tangent planes it lies on (the signed distance of Hoppe et
// al., SIGGRAPH 1992), with normals oriented by the in/out function itself.

// Unoriented normals by PCA of the k nearest points of each of `points[which[j]]`, with the
// coplanarity error of the fit (large where the neighbourhood is not a piece of one sheet: a
// tube or a plate thinner than it, a crease, noise) and the neighbourhood's radius (the
// distance to the k-th nearest point).
inline void estimate_point_normals(const std::vector<std::array<double, 3> >& points, const Point_neighbors& neighbors,
                                   const std::vector<std::uint32_t>& which, unsigned int k,
                                   std::vector<std::array<double, 3> >& normals,
                                   std::vector<float>& coplanarity_errors, std::vector<float>& radii)
{
  normals.assign(which.size(), {{ 0., 0., 0. }});
  coplanarity_errors.assign(which.size(), 1.f);
  radii.assign(which.size(), 0.f);
  for_each_index(which.size(), [&](std::size_t j) {
    const auto& p = points[which[j]];
    Moments moments(p);
    double farthest2 = 0;
    neighbors.for_nearest(p, k, [&](std::uint32_t i, double d2) {
      moments.add(points[i]);
      farthest2 = (std::max)(farthest2, d2);
    });
    radii[j] = float(std::sqrt(farthest2));
    Plane_fit fit;
    if(!moments.fit(fit)) return;
    normals[j] = {{ fit.normal[0], fit.normal[1], fit.normal[2] }};
    coplanarity_errors[j] = fit.coplanarity_error;
  });
}

// The voters of each vertex v: its 6 nearest points if the nearest is closer than
// `radius_of(v)` and the vertex is not on the box boundary (`fixed`: those stay outside so
// that the surface stays closed), else none (all entries `no_voter`). Only these points need an
// oriented normal: on the dragon (437k points) they are about a third of the points. A
// tighter gate, the nearest point within 0.6 times the 12th nearest (against the webs a
// sparse sampling leaves in a gap under two spacings wide: a wall's normals oriented the
// wrong way vote its vertices a spacing away inside), met the robustness bar on fewer
// samplings (seeds 21-100: non-uniform 65 against 67, 0.5 % noise 71 against 76).
typedef std::array<std::uint32_t, 6> Voters;
constexpr std::uint32_t no_voter = std::uint32_t(-1);

template <class RadiusOf>
std::vector<Voters> voters_of_vertices(const std::vector<std::array<double, 3> >& vertices,
                                       const std::vector<char>& fixed, const Point_neighbors& neighbors,
                                       const RadiusOf& radius_of)
{
  std::vector<Voters> voters(vertices.size());
  for_each_index(vertices.size(), [&](std::size_t v) {
    Voters& w = voters[v];
    w.fill(no_voter);
    if(fixed[v]) return;
    double nearest2 = HUGE_VAL;
    int m = 0;
    neighbors.for_nearest(vertices[v], 6, [&](std::uint32_t i, double d2) {
      w[m++] = i;
      nearest2 = (std::min)(nearest2, d2);
    });
    const double radius = radius_of(v);
    if(!(nearest2 < radius * radius)) w.fill(no_voter);
  });
  return voters;
}

// the same with one radius for all vertices
inline std::vector<Voters> voters_of_vertices(const std::vector<std::array<double, 3> >& vertices,
                                              const std::vector<char>& fixed, const Point_neighbors& neighbors,
                                              double radius)
{
  return voters_of_vertices(vertices, fixed, neighbors, [radius](std::size_t) { return radius; });
}

// Whether points lie behind `x` (the vertex lies between two walls): one of its 48 nearest
// points lies, seen from x along the outward normal of one of its voters, on the far side by
// more than 0.3 times its distance. 48 because a sparse wall behind a dense one is missed by
// fewer: with the 24 nearest, the non-uniform bunny met the robustness bar on 72 and 90 of
// seeds 21-100 and 101-200 instead of 73 and 91 (a vertex inside an ear base, 0.026 behind
// the dense wall's voters, the sparse wall's points farther than the dense wall's 24th).
template <class NormalOf>
bool has_points_behind(const std::vector<std::array<double, 3> >& points, const Point_neighbors& neighbors,
                       const std::array<double, 3>& x, const Voters& voters, const NormalOf& normal_of)
{
  std::array<std::array<double, 3>, std::tuple_size<Voters>::value> unit;  // the voters' normals, of length 1
  int m = 0;
  for(std::uint32_t i : voters)
  {
    if(i == no_voter) continue;
    const std::array<double, 3>& n = normal_of(i);
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if(length > 0) unit[m++] = {{ n[0] / length, n[1] / length, n[2] / length }};
  }
  bool behind = false;
  neighbors.for_nearest(x, 48, [&](std::uint32_t j, double d2) {
    const auto& q = points[j];
    for(int k = 0; k < m; ++k)
    {
      const auto& n = unit[k];
      if((q[0] - x[0]) * n[0] + (q[1] - x[1]) * n[1] + (q[2] - x[2]) * n[2] < -0.3 * std::sqrt(d2)) behind = true;
    }
  });
  return behind;
}

// Re-signs the vertices that have voters. Each voter with an outward normal (`normal_of(i)`
// null: it must not vote) votes with its signed distance (v - p).n, weighted by the inverse
// distance; a vertex whose weighted signed distance is below 0.3 times its weighted
// distance lies beside the tangent planes rather than in front of them (past the rim of a
// plate, along a crease) and keeps its sign. The value of a re-signed vertex is that
// weighted signed distance (never below `tiny`). Returns the number of vertices that
// changed side.
//
// A voter vouches for the inside only `vouched_depth_of(i)` deep (infinite where the in/out
// function tested its orientation; where the orientation was only passed on to it, in a
// part the Ising signs lost, half its neighbourhood's radius): an outside vertex deeper
// behind its voters' planes than the deepest they vouch for goes inside only between two
// walls (has_points_behind()). Such parts are thin, and at a thin part's tip or knife edge
// the points' plane is the part's mid-plane, so that what lies far behind it is the other
// side of the part: on the bunny with 0.5 % noise, an ear tip thinner than the noise (its
// voters' normals 55 to 90 degrees from the truth's) had vertices 2 point spacings past it
// voted inside, and the surface bulged 2.5 % of the diagonal out.
template <class NormalOf, class VouchedDepthOf>
std::size_t sign_by_tangent_planes(const std::vector<std::array<double, 3> >& points, const Point_neighbors& neighbors,
                                   const std::vector<std::array<double, 3> >& vertices,
                                   const std::vector<Voters>& voters, const NormalOf& normal_of,
                                   const VouchedDepthOf& vouched_depth_of, double radius, double tiny,
                                   std::vector<signed char>& signs, std::vector<double>& values)
{
  std::vector<char> changed(vertices.size(), 0);
  for_each_index(vertices.size(), [&](std::size_t v) {
    const auto& x = vertices[v];
    double weights = 0, signed_sum = 0, distance_sum = 0, vouched_depth = 0;
    for(std::uint32_t i : voters[v])
    {
      if(i == no_voter) continue;
      const std::array<double, 3>& n = normal_of(i);
      if(n[0] == 0 && n[1] == 0 && n[2] == 0) continue;
      vouched_depth = (std::max)(vouched_depth, double(vouched_depth_of(i)));
      const auto& p = points[i];
      const double d = std::sqrt((x[0] - p[0]) * (x[0] - p[0]) + (x[1] - p[1]) * (x[1] - p[1]) + (x[2] - p[2]) * (x[2] - p[2]));
      const double w = 1. / (d + 1e-3 * radius);
      weights += w;
      signed_sum += w * ((x[0] - p[0]) * n[0] + (x[1] - p[1]) * n[1] + (x[2] - p[2]) * n[2]);
      distance_sum += w * d;
    }
    if(!(weights > 0) || !(std::abs(signed_sum) >= 0.3 * distance_sum)) return;
    const signed char s = signed_sum > 0 ? 1 : -1;
    if(s < 0 && signs[v] > 0 && -signed_sum > vouched_depth * weights && !has_points_behind(points, neighbors, x, voters[v], normal_of))
      return;
    changed[v] = s != signs[v];
    signs[v] = s;
    values[v] = s * (std::max)(std::abs(signed_sum / weights), tiny);
  });
  return std::size_t(std::count(changed.begin(), changed.end(), 1));
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_TANGENT_PLANE_SIGNS_H
