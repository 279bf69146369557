// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_MARCHING_TETRAHEDRA_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_MARCHING_TETRAHEDRA_H

// Mesh extraction (paper section 4, step "mesh"): the zero level set of a piecewise
// linear function on a conforming tetrahedral mesh, as an indexed triangle mesh.
//
// Every crossed mesh edge gives exactly one output point, shared by all the tetrahedra
// around the edge, so on a conforming mesh with no zero value the output is a closed
// 2-manifold as soon as no boundary tetrahedron has a sign change.

#include <CGAL/ISM_reconstruction_3/internal/for_each_index.h>
#include <CGAL/ISM_reconstruction_3/internal/point_neighbors.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

/// \cond SKIP_IN_MANUAL

namespace marching_tetrahedra_detail {

inline std::uint64_t edge_key(int a, int b)
{
  if(b < a)
    std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint64_t>(static_cast<std::uint32_t>(b));
}

// The vertices of a tetrahedron's edge 0..5 (the inverse of local_edge()).
constexpr int edge_vertices[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

// Local index (0..5) of the edge {i, j} of a tetrahedron, i != j.
inline int local_edge(int i, int j)
{
  static const int table[4][4] = {{-1, 0, 1, 2}, {0, -1, 3, 4}, {1, 3, -1, 5}, {2, 4, 5, -1}};
  return table[i][j];
}

inline bool is_even_permutation(int a, int b, int c, int d)
{
  const int p[4] = {a, b, c, d};
  int inversions = 0;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j)
      if(p[j] < p[i])
        ++inversions;
  return inversions % 2 == 0;
}

// bit i set: vertex i of `t` is inside (negative)
template <class Tet>
int negative_mask(const Tet& t, const std::vector<double>& values)
{
  int mask = 0;
  for(int i = 0; i < 4; ++i)
  {
    CGAL_precondition(t[i] >= 0 && static_cast<std::size_t>(t[i]) < values.size());
    CGAL_precondition(values[static_cast<std::size_t>(t[i])] != 0.);
    if(values[static_cast<std::size_t>(t[i])] < 0.)
      mask |= 1 << i;
  }
  return mask;
}

inline double squared_distance(const std::array<double, 3>& p, const std::array<double, 3>& q)
{
  const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
  return dx * dx + dy * dy + dz * dz;
}

} // namespace marching_tetrahedra_detail

// Where a crossed edge [a, b] gives its point: the parameter in [0, 1] from F's linear zero
// crossing t; this one keeps it (jet_crossing.h moves it onto the points' quadric).
struct Linear_crossing
{
  double operator()(const std::array<double, 3>&, const std::array<double, 3>&, double t) const { return t; }
};

// The crossed edges of `tets` (see marching_tetrahedra()), sorted and unique, as keys of
// their sorted vertex pair, and in `points` one point each, at `crossing`'s point. Returns
// the number of crossed tetrahedra.
template <class Tets, class Crossing = Linear_crossing>
std::size_t crossing_points(const std::vector<std::array<double, 3> >& vertices, const Tets& tets,
                            const std::vector<double>& values, std::vector<std::uint64_t>& keys,
                            std::vector<std::array<double, 3> >& points, const Crossing& crossing = Crossing())
{
  using namespace marching_tetrahedra_detail;
  keys.clear();
  std::size_t number_of_crossed_tets = 0;
  for(const auto& t : tets)
  {
    const int mask = negative_mask(t, values);
    if(mask == 0 || mask == 15)
      continue;
    ++number_of_crossed_tets;
    for(const auto& e : edge_vertices)
      if(((mask >> e[0]) & 1) != ((mask >> e[1]) & 1))
        keys.push_back(edge_key(int(t[e[0]]), int(t[e[1]])));
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());

  points.resize(keys.size());
  // in parallel: a crossing may fit a quadric to the points near it (100 ms serial at 36k)
  for_each_index(keys.size(), [&](std::size_t i) {
    const std::size_t a = static_cast<std::size_t>(keys[i] >> 32);
    const std::size_t b = static_cast<std::size_t>(keys[i] & 0xFFFFFFFFULL);
    const double fa = values[a], fb = values[b];
    double t = fa / (fa - fb);  // opposite signs: the denominator is not zero
    t = (std::min)((std::max)(t, 0.), 1.);
    t = crossing(vertices[a], vertices[b], t);
    for(int k = 0; k < 3; ++k)
      points[i][k] = vertices[a][k] + t * (vertices[b][k] - vertices[a][k]);
  });
  return number_of_crossed_tets;
}

// The median distance from `points` to the crossings of F's zero level with the edges of
// `tets` (the vertices of its marching tetrahedra); infinite without one.
template <class Tets>
double median_distance_to_crossings(const std::vector<std::array<double, 3> >& points,
                                    const std::vector<std::array<double, 3> >& vertices, const Tets& tets,
                                    const std::vector<double>& values)
{
  std::vector<std::uint64_t> keys;
  std::vector<std::array<double, 3> > crossings;
  crossing_points(vertices, tets, values, keys, crossings);
  if(crossings.empty() || points.empty()) return HUGE_VAL;
  const Point_neighbors near(crossings);
  std::vector<double> distance(points.size());
  for_each_index(points.size(), [&](std::size_t i) {
    near.for_nearest(points[i], 1, [&](std::uint32_t, double d2) { distance[i] = std::sqrt(d2); });
  });
  std::nth_element(distance.begin(), distance.begin() + std::ptrdiff_t(distance.size() / 2), distance.end());
  return distance[distance.size() / 2];
}

// `vertices`: one point per vertex; `tets`: positively oriented tetrahedra
// (det[p1-p0, p2-p0, p3-p0] > 0); `values`: one per vertex, never 0, negative = inside.
// Output: `out_points` holds one point per crossed edge (at `crossing`'s point),
// in increasing order of the edge's sorted vertex pair; `out_triangles` the triangles,
// tetrahedra in input order, oriented so that their normal points toward positive values.
// A tetrahedron with one vertex of one sign gives one triangle; two and two give a
// quadrilateral split along its shorter diagonal (the first one on a tie).
template <class Crossing = Linear_crossing>
void marching_tetrahedra(const std::vector<std::array<double, 3> >& vertices,
                         const std::vector<std::array<int, 4> >& tets,
                         const std::vector<double>& values,
                         std::vector<std::array<double, 3> >& out_points,
                         std::vector<std::array<std::size_t, 3> >& out_triangles,
                         const Crossing& crossing = Crossing())
{
  using namespace marching_tetrahedra_detail;
  CGAL_precondition(values.size() == vertices.size());
  out_points.clear();
  out_triangles.clear();

  // 1. The crossed edges, sorted and unique: one output point each.
  std::vector<std::uint64_t> keys;
  const std::size_t number_of_crossed_tets = crossing_points(vertices, tets, values, keys, out_points, crossing);

  // 2. The triangles.
  // For a positively oriented tet, if (i, j, k, l) is an even permutation of (0, 1, 2, 3),
  // the triangle (e_ij, e_ik, e_il) has its normal pointing away from vertex i, and the
  // quadrilateral (e_ik, e_il, e_jl, e_jk) has its normal pointing toward k and l.
  static const int others[4][3] = {{1, 2, 3}, {2, 0, 3}, {0, 1, 3}, {0, 2, 1}};
  out_triangles.reserve(2 * number_of_crossed_tets);
  for(const std::array<int, 4>& t : tets)
  {
    const int mask = negative_mask(t, values);
    if(mask == 0 || mask == 15)
      continue;
    std::array<std::size_t, 6> point_of_edge;
    for(int e = 0; e < 6; ++e)
    {
      const int i = edge_vertices[e][0], j = edge_vertices[e][1];
      if(((mask >> i) & 1) != ((mask >> j) & 1))
      {
        const std::uint64_t key = edge_key(t[i], t[j]);
        point_of_edge[e] =
          static_cast<std::size_t>(std::lower_bound(keys.begin(), keys.end(), key) - keys.begin());
      }
    }
    auto p = [&](int i, int j) { return point_of_edge[local_edge(i, j)]; };

    const int number_of_negatives = ((mask >> 0) & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1) + ((mask >> 3) & 1);
    if(number_of_negatives == 1 || number_of_negatives == 3)
    {
      // The vertex alone on its side.
      const int lone_mask = number_of_negatives == 1 ? mask : (~mask & 15);
      const int i = lone_mask == 1 ? 0 : lone_mask == 2 ? 1 : lone_mask == 4 ? 2 : 3;
      const int j = others[i][0], k = others[i][1], l = others[i][2];
      if(number_of_negatives == 1)  // i inside: normal away from i
        out_triangles.push_back({p(i, j), p(i, k), p(i, l)});
      else                          // i outside: normal toward i
        out_triangles.push_back({p(i, j), p(i, l), p(i, k)});
    }
    else
    {
      int neg[2], pos[2];
      int nn = 0, np = 0;
      for(int i = 0; i < 4; ++i)
      {
        if((mask >> i) & 1)
          neg[nn++] = i;
        else
          pos[np++] = i;
      }
      const int a = neg[0], b = neg[1];
      int c = pos[0], d = pos[1];
      if(!is_even_permutation(a, b, c, d))
        std::swap(c, d);
      // Quadrilateral q0 q1 q2 q3, normal toward c and d (positive side).
      const std::size_t q0 = p(a, c), q1 = p(a, d), q2 = p(b, d), q3 = p(b, c);
      if(squared_distance(out_points[q0], out_points[q2]) <= squared_distance(out_points[q1], out_points[q3]))
      {
        out_triangles.push_back({q0, q1, q2});
        out_triangles.push_back({q0, q2, q3});
      }
      else
      {
        out_triangles.push_back({q0, q1, q3});
        out_triangles.push_back({q1, q2, q3});
      }
    }
  }
}

/// \endcond

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_MARCHING_TETRAHEDRA_H
