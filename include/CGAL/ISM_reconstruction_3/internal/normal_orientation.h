// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_NORMAL_ORIENTATION_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_NORMAL_ORIENTATION_H

#include <CGAL/ISM_reconstruction_3/internal/for_each_index.h>
#include <CGAL/ISM_reconstruction_3/internal/point_neighbors.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// The orientation test of `ism_orient_normals()`, for one point p with normal n.
//
// F is piecewise linear on the leaves, with f(v) = S_v d(v) at the vertices (S_v the Ising
// sign, d(v) a distance to the nearest points). Near a data point the leaves are small (a
// leaf is only split while it holds enough points) and F is, wherever the signs are right,
// close to a signed distance: it increases along the outward normal.
//
// The gradient of F in the leaf holding p would be the natural test, but it is the least
// robust one: p lies ON the surface, so the leaf holding it is the one where the signs are
// least certain (one vertex with a wrong sign, or a leaf whose vertices all carry one sign
// because the zero level passes through a neighbour, makes F there a V-shaped |d|
// interpolated linearly, whose gradient can point anywhere). Instead we look for the zero
// level of F along the line of n: the first step h (half a leaf, then one leaf) for which
// F(p - h n) and F(p + h n) have opposite signs means that the reconstructed surface
// crosses the normal line right at p, and the sign of F(p + h n) says on which side n
// points. Such a decision is "confident". The steps stay within one leaf size, far below
// the thickness of any part the function resolves (the leaves around a thin part that F
// resolves are much smaller than its thickness). Measured with the true normals of 12,000
// samples: the sign of the gradient in the leaf was wrong for 40 points of the trefoil tube,
// 101 of the bunny and 495 of the bunny with 0.5 % noise; the crossing test for 0, 0 and 1,
// and was not confident for 0.6 %, 4.6 % and 14.5 % of the points, oriented by propagation.
//
// Without a crossing that close, the function is not reliable at p (the Ising model has
// missed a piece of the surface there, or p is an outlier): the relative central
// difference (F(p + h n) - F(p - h n)) / (|F(p + h n)| + |F(p - h n)|) at up to 4 leaf
// sizes, about 1 for a signed distance crossed along n and 0 for a normal tangent to the
// level sets, is kept as a weak decision, used only where no confident neighbour can
// orient p (see `propagate_orientations()`).
struct Orientation_test
{
  signed char sign = 0;     // +1: n points outside, -1: n points inside, 0: unknown
  bool confident = false;   // the zero level of F crosses the normal line within one leaf size
  double relative = 0;      // the strength of a weak decision, in [0, 1]
  double leaf_size = 0;     // the longest edge of the leaf holding p
};

// `leaf`: the leaf holding p
template <class Function>
Orientation_test ism_orientation_of(const Function& function, const std::array<double, 3>& p,
                                    const std::array<double, 3>& n, typename Function::Triangulation::Cell_index leaf)
{
  typedef typename Function::Point Point;
  typedef typename Function::Triangulation Triangulation;
  Orientation_test result;
  const Triangulation& tr = function.triangulation();
  const auto v = tr.vertices(leaf);
  double size2 = 0;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j)
    {
      const Point &a = tr.point(v[i]), &b = tr.point(v[j]);
      double l2 = 0;
      for(int d = 0; d < 3; ++d)
      {
        const double x = to_double(a[d]) - to_double(b[d]);
        l2 += x * x;
      }
      size2 = (std::max)(size2, l2);
    }
  result.leaf_size = std::sqrt(size2);
  const double nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if(!(nn > 0) || !(result.leaf_size > 0)) return result;
  // the points are located by walks from p's leaf, each step from the leaf of the last
  typename Triangulation::Cell_index plus = leaf, minus = leaf;
  for(double step : { 0.5, 1., 2., 4. })
  {
    const double h = step * result.leaf_size / nn;
    const double fp = to_double(function(Point(p[0] + h * n[0], p[1] + h * n[1], p[2] + h * n[2]), plus));
    const double fm = to_double(function(Point(p[0] - h * n[0], p[1] - h * n[1], p[2] - h * n[2]), minus));
    const double scale = std::abs(fp) + std::abs(fm);
    if(!(scale > 0)) continue;
    if(step <= 1. && (fp > 0) != (fm > 0))
    {
      result.sign = fp > 0 ? 1 : -1;
      result.confident = true;
      result.relative = 1.;
      return result;
    }
    const double relative = std::abs(fp - fm) / scale;
    if(relative > result.relative)
    {
      result.relative = relative;
      result.sign = fp > fm ? 1 : -1;
    }
  }
  return result;
}

template <class Function>
Orientation_test ism_orientation_of(const Function& function, const std::array<double, 3>& p,
                                    const std::array<double, 3>& n)
{
  const typename Function::Triangulation& tr = function.triangulation();
  const typename Function::Point pp(p[0], p[1], p[2]);
  if(tr.locate_root(pp) < 0) return Orientation_test();
  return ism_orientation_of(function, p, n, tr.locate(pp));
}

// Orients the points without a confident test from their confident neighbours: Prim's
// algorithm from all confident points at once on the graph of the k nearest neighbours of
// the other points, along the edges of largest |n_i . n_j| first (Hoppe's propagation,
// the one of `mst_orient_normals()`, but seeded everywhere the in/out function is sure, so
// that it only bridges the small gaps of the function and cannot carry a wrong orientation
// across a whole part). An edge longer than twice the leaf size at its oriented end is not
// followed: it would jump between parts the function separates, which are at least a leaf
// apart. A point it cannot reach keeps its weak decision if that is strong enough, else
// stays unoriented (`sign` 0).
//
// Two guards against one wrong seed orienting a whole part the Ising signs lost (session 33:
// the non-uniform bunny with its sparse half taken across z, both ears sparse; one ear's
// 143 voting points got their side from one confident point at the ear's base, where the
// function had filled the concave corner, and grew a web 6 % of the diagonal high):
// - a confident point that its confident neighbours of the same sheet (seen along the
//   tangent plane, normals within 60 degrees) contradict more than they agree with is not a
//   seed (at that ear base: 8 of its 18 nearest points contradicted it, one agreed), judged
//   again by the seeds that stand until none falls;
// - a point that is not `one_sheet` (a thin part's rim, whose neighbourhood spans both walls)
//   takes an orientation but does not pass it on: the rim's mid-plane normal would carry one
//   wall's side onto the other wall (the same ear's tip, and the webs of session 31).
// `one_sheet` empty: every point passes it on. Neither guard is enough alone: with the seed
// guard only, that ear's new (right) seed had its side turned at the ear's tip (73 wrong
// voting points, genus 5 still); the one-sheet rule alone (session 32) changed none of the
// webs of the sparse half taken across x. Dropping the votes of points whose weak decision
// disagrees was no net gain (session 31).
inline void propagate_orientations(const std::vector<std::array<double, 3> >& points,
                                   const std::vector<std::array<double, 3> >& normals,
                                   std::vector<Orientation_test>& tests, unsigned int k,
                                   double min_weak_relative_difference,
                                   const std::vector<char>& one_sheet = std::vector<char>())
{
  const std::size_t size = points.size();
  if(size == 0) return;
  auto dot = [&](std::uint32_t i, std::uint32_t j) {
    const auto &a = normals[i], &b = normals[j];
    const double la = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    const double lb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    return (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (la * lb);
  };
  auto distance2 = [&](std::uint32_t i, std::uint32_t j) {
    double d2 = 0;
    for(int d = 0; d < 3; ++d) d2 += (points[i][d] - points[j][d]) * (points[i][d] - points[j][d]);
    return d2;
  };
  // a neighbour seen along the normal rather than along the tangent plane lies on the other
  // side of a part thinner than the neighbourhood: its normal is (anti)parallel to this one
  // whatever their true orientations, and following it would orient both walls alike
  auto is_tangential = [&](std::uint32_t i, std::uint32_t j) {
    const double d = std::sqrt(distance2(i, j));
    for(std::uint32_t a : { i, j })
    {
      const auto& n = normals[a];
      const double ln = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      double along = 0;
      for(int c = 0; c < 3; ++c) along += n[c] * (points[j][c] - points[i][c]);
      if(std::abs(along) > 0.5 * ln * d) return false;
    }
    return true;
  };

  const Point_neighbors neighbors(points);
  const unsigned int kk = unsigned((std::min<std::size_t>)(k + 1, size));
  // Rounds until no seed is demoted (at most 8, to bound the cost): a seed is judged by the
  // seeds that stand, since the one that agreed with a wrong seed may itself be contradicted
  // (session 40, the non-uniform bunny of seed 184: at an ear's base the function had filled,
  // a wrong seed agreed with by one other wrong seed and contradicted by one right one kept
  // its standing, then oriented 30 points of the ear the Ising signs lost, and the tangent
  // planes grew a web 4 % of the diagonal high between the ears; demoted in the second round).
  std::vector<char> contradicted(size, 0);
  for(int round = 0; round < 8; ++round)
  {
    for_chunks(0, size, 64, [&](std::size_t lo, std::size_t hi) {
      for(std::size_t i = lo; i < hi; ++i)
      {
        if(!tests[i].confident) continue;
        double agree = 0, disagree = 0;
        neighbors.for_nearest(points[i], kk, [&](std::uint32_t j, double) {
          if(j == i || !tests[j].confident || !is_tangential(std::uint32_t(i), j)) return;
          const double c = dot(std::uint32_t(i), j);
          if(!(std::abs(c) >= 0.5)) return;
          ((c > 0) == (tests[i].sign == tests[j].sign) ? agree : disagree) += std::abs(c);
        });
        contradicted[i] = disagree > agree;
      }
    });
    std::size_t demoted = 0;
    for(std::size_t i = 0; i < size; ++i)
      if(contradicted[i] && tests[i].confident)
      {
        tests[i].confident = false;
        ++demoted;
      }
    if(demoted == 0) break;
  }

  std::vector<std::uint32_t> uncertain;
  for(std::size_t i = 0; i < size; ++i)
    if(!tests[i].confident) uncertain.push_back(std::uint32_t(i));
  if(uncertain.empty()) return;
  std::vector<std::vector<std::uint32_t> > knn(uncertain.size());
  auto query = [&](std::size_t u) {
    neighbors.for_nearest(points[uncertain[u]], kk, [&](std::uint32_t i, double) {
      if(i != uncertain[u]) knn[u].push_back(i);
    });
  };
  for_chunks(0, uncertain.size(), 64, [&](std::size_t lo, std::size_t hi) {
    for(std::size_t u = lo; u < hi; ++u) query(u);
  });

  // undirected adjacency (compressed rows) of the edges with at least one uncertain end
  std::vector<std::size_t> offset(size + 1, 0);
  for(std::size_t u = 0; u < uncertain.size(); ++u)
    for(std::uint32_t j : knn[u]) { ++offset[uncertain[u] + 1]; ++offset[j + 1]; }
  for(std::size_t i = 0; i < size; ++i) offset[i + 1] += offset[i];
  std::vector<std::uint32_t> adjacency(offset[size]);
  {
    std::vector<std::size_t> fill(offset.begin(), offset.end() - 1);
    for(std::size_t u = 0; u < uncertain.size(); ++u)
      for(std::uint32_t j : knn[u])
      {
        adjacency[fill[uncertain[u]]++] = j;
        adjacency[fill[j]++] = uncertain[u];
      }
  }

  std::vector<char> oriented(size, 0);
  std::vector<signed char> sign(size, 0);
  typedef std::pair<double, std::pair<std::uint32_t, std::uint32_t> > Edge;  // |cos|, (from, to)
  std::priority_queue<Edge> queue;
  auto push_edges = [&](std::uint32_t i) {
    const double reach2 = 4. * tests[i].leaf_size * tests[i].leaf_size;
    for(std::size_t e = offset[i]; e < offset[i + 1]; ++e)
    {
      const std::uint32_t j = adjacency[e];
      if(!oriented[j] && distance2(i, j) <= reach2 && is_tangential(i, j))
      {
        const double c = dot(i, j);
        if(std::isfinite(c)) queue.push(Edge(std::abs(c), std::make_pair(i, j)));
      }
    }
  };
  for(std::size_t i = 0; i < size; ++i)
    if(tests[i].confident)
    {
      oriented[i] = 1;
      sign[i] = tests[i].sign;
      if(offset[i + 1] > offset[i]) push_edges(std::uint32_t(i));
    }
  while(!queue.empty())
  {
    const std::uint32_t i = queue.top().second.first, j = queue.top().second.second;
    queue.pop();
    if(oriented[j]) continue;
    oriented[j] = 1;
    sign[j] = static_cast<signed char>(dot(i, j) >= 0 ? sign[i] : -sign[i]);
    if(one_sheet.empty() || one_sheet[j]) push_edges(j);
  }
  for(std::uint32_t i : uncertain)
  {
    if(oriented[i])
      tests[i].sign = sign[i];
    else if(tests[i].relative < min_weak_relative_difference)
      tests[i].sign = 0;
  }
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_NORMAL_ORIENTATION_H
