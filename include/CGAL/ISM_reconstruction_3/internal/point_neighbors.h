// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_POINT_NEIGHBORS_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_POINT_NEIGHBORS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// The k nearest input points of a location, by index, built once and shared by the
// distance estimate, the tangent-plane signs and the point smoothing. A kd-tree of our own
// rather than CGAL's general one, for the few neighbours asked here (1, 6, 12, 24): on the
// queries the package makes (recorded on the 437,645-point dragon, one thread) it takes
// 28 % less time for the queries and 20-35 % less for the building, and keeps 35 bytes per
// point instead of 56.
//
// Each range of points is split at (about) its median along the widest extent of its box,
// so that the tree's shape follows from the range sizes alone: a range of at most
// `leaf_size` points is a leaf and needs no node, and the internal nodes are stored in
// preorder (the left child, if internal, is the next node). The points are stored in tree
// order, each with its input index.
//
// The result is the k smallest by (squared distance, index): ties go to the smaller index,
// so that it depends neither on the tree nor on the thread that asks. The squared distance
// is computed as the brute force and CGAL's kd-tree compute it (same operations, same
// order), hence the same values.
class Point_neighbors
{
  // Measured on the queries the package makes (recorded on the bunny, knot1 and the
  // dragon): 12 to 32 within 5 % of each other, 16 the fastest or tied, 8 slower by 4-9 %.
  // A leaf's points are read in a row, so a few too many cost less than another node.
  static constexpr std::uint32_t leaf_size = 16;
  // the result of k up to this is kept on the stack: no allocation per query
  static constexpr unsigned int stack_capacity = 64;

public:
  struct Box
  {
    double lo[3], hi[3];
    // whether x is in the box grown by `margin`
    bool contains(const std::array<double, 3>& x, double margin) const
    {
      for(int d = 0; d < 3; ++d)
        if(x[d] < lo[d] - margin || x[d] > hi[d] + margin) return false;
      return true;
    }
  };

private:
  // single precision, rounded outward: still a lower bound of every point's distance, in a
  // node half the size
  struct Float_box
  {
    float lo[3], hi[3];
  };
  struct Node
  {
    // the largest coordinate along `axis` of the left child and the smallest of the right
    // one: the slab between them is empty, which on a sampled surface is most of the volume
    double left_max, right_min;
    std::uint32_t right;  // the right child's node, if internal
    std::uint32_t axis;
    Float_box box;        // of the node's points, for the queries far from them (below)
  };
  struct Build_point  // 32 bytes
  {
    double p[3];
    std::uint32_t index;
  };
  struct Candidate
  {
    double d2;
    std::uint32_t index;
  };
  struct Search
  {
    double q[3];
    Candidate* best;  // sorted, `k` entries, the last is the one to beat
    unsigned int k;
  };

public:
  explicit Point_neighbors(const std::vector<std::array<double, 3> >& points)
  {
    const std::uint32_t n = std::uint32_t(points.size());
    m_points.resize(n);
    for(std::uint32_t i = 0; i < n; ++i)
      m_points[i] = Build_point{{points[i][0], points[i][1], points[i][2]}, i};
    if(n > 0)
    {
      m_box = box_of(m_points.data(), m_points.data() + n);
      m_nodes.reserve(n / leaf_size + 1);
      build(m_points.data(), 0, n, m_box);
    }
  }

  std::size_t size() const { return m_points.size(); }
  // the bounding box of the points (all zero if there are none)
  const Box& bounding_box() const { return m_box; }

  // calls `visit(index, squared distance)` for the k nearest points of `q`, nearest first
  // (all points if fewer than k); thread-safe: the tree is only read
  template <class Visitor>
  void for_nearest(const std::array<double, 3>& q, unsigned int k, const Visitor& visit) const
  {
    const std::uint32_t n = std::uint32_t(m_points.size());
    if(k > n) k = n;
    if(k == 0) return;
    Candidate on_stack[stack_capacity];
    std::vector<Candidate> on_heap;
    Candidate* best = on_stack;
    if(k > stack_capacity)
    {
      on_heap.resize(k);
      best = on_heap.data();
    }
    // sentinels that any point beats: the scan never asks whether the result is full
    std::fill(best, best + k, Candidate{std::numeric_limits<double>::infinity(), std::uint32_t(-1)});
    Search s{{q[0], q[1], q[2]}, best, k};
    double off[3];
    for(int d = 0; d < 3; ++d) off[d] = gap(q[d], m_box.lo[d], m_box.hi[d]);
    search(s, 0, 0, n, off);
    // a sentinel left only if no distance compared (a NaN in q): nothing to visit then
    for(unsigned int i = 0; i < k && best[i].index != std::uint32_t(-1); ++i) visit(best[i].index, best[i].d2);
  }

private:
  static Box box_of(const Build_point* first, const Build_point* last)
  {
    Box box{{first->p[0], first->p[1], first->p[2]}, {first->p[0], first->p[1], first->p[2]}};
    for(const Build_point* it = first + 1; it != last; ++it)
      for(int d = 0; d < 3; ++d)
      {
        box.lo[d] = (std::min)(box.lo[d], it->p[d]);
        box.hi[d] = (std::max)(box.hi[d], it->p[d]);
      }
    return box;
  }

  static float down(double x)
  {
    float f = float(x);
    if(double(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
  }
  static float up(double x)
  {
    float f = float(x);
    if(double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
  }

  // Where [b, e) splits: the left side gets half of its leaves (rounded down), every leaf but
  // the last full. Then the leaf size is what was measured whatever the number of points
  // (halving sizes would give leaves of anything between half and all of `leaf_size`), and
  // the split is still within half a leaf of the median.
  static std::uint32_t split(std::uint32_t b, std::uint32_t e)
  {
    const std::uint32_t leaves = (e - b + leaf_size - 1) / leaf_size;
    return b + leaf_size * (leaves / 2);
  }

  // `box` is that of the points [b, e)
  void build(Build_point* pts, std::uint32_t b, std::uint32_t e, const Box& box)
  {
    if(e - b <= leaf_size) return;
    std::uint32_t axis = 0;
    for(std::uint32_t d = 1; d < 3; ++d)
      if(box.hi[d] - box.lo[d] > box.hi[axis] - box.lo[axis]) axis = d;
    const std::uint32_t mid = split(b, e);
    std::nth_element(pts + b, pts + mid, pts + e,
                     [axis](const Build_point& x, const Build_point& y) { return x.p[axis] < y.p[axis]; });
    const Box left = box_of(pts + b, pts + mid), right = box_of(pts + mid, pts + e);
    const std::uint32_t node = std::uint32_t(m_nodes.size());
    const Float_box outward{{down(box.lo[0]), down(box.lo[1]), down(box.lo[2])},
                            {up(box.hi[0]), up(box.hi[1]), up(box.hi[2])}};
    m_nodes.push_back(Node{left.hi[axis], right.lo[axis], 0, axis, outward});
    build(pts, b, mid, left);
    m_nodes[node].right = std::uint32_t(m_nodes.size());
    build(pts, mid, e, right);
  }

  static double gap(double x, double lo, double hi) { return x < lo ? lo - x : (x > hi ? x - hi : 0.); }

  static void offer(Search& s, double d2, std::uint32_t index)
  {
    Candidate* best = s.best;
    unsigned int j = s.k - 1;
    if(d2 == best[j].d2 && index > best[j].index) return;
    while(j > 0 && (d2 < best[j - 1].d2 || (d2 == best[j - 1].d2 && index < best[j - 1].index)))
    {
      best[j] = best[j - 1];
      --j;
    }
    best[j] = Candidate{d2, index};
  }

  // Depth first, nearer child first. `off` holds, per axis, a lower bound of the distance
  // from q to the points of the range along that axis (Arya and Mount's incremental
  // distance: crossing a split changes one term). Each term is one rounded subtraction of q
  // and a coordinate not nearer than any of the points', so, rounding being monotone, their
  // squares summed afresh (not updated by differences) never exceed a point's computed
  // squared distance. The tie rule needs that: a range at exactly the k-th distance may hold
  // a smaller index, so only a range strictly farther is skipped.
  void search(Search& s, std::uint32_t node, std::uint32_t b, std::uint32_t e, const double off[3]) const
  {
    if(e - b <= leaf_size)
    {
      for(std::uint32_t i = b; i < e; ++i)
      {
        const double* const p = m_points[i].p;
        const double dx = s.q[0] - p[0], dy = s.q[1] - p[1], dz = s.q[2] - p[2];
        const double d2 = dx * dx + dy * dy + dz * dz;
        if(d2 <= s.best[s.k - 1].d2) offer(s, d2, m_points[i].index);
      }
      return;
    }
    const Node& nd = m_nodes[node];
    const std::uint32_t mid = split(b, e), a = nd.axis;
    const double to_left = s.q[a] - nd.left_max, to_right = s.q[a] - nd.right_min;
    // q before the middle of the empty slab is before right_min too (left_max <= right_min,
    // and the signs of these rounded differences are exact), so |q - right_min| bounds the
    // right side; the other way round for the left side
    const bool left_first = to_left + to_right < 0;
    const std::uint32_t left = node + 1, right = nd.right;
    if(left_first) search(s, left, b, mid, off);
    else search(s, right, mid, e, off);
    double o[3] = {off[0], off[1], off[2]};
    o[a] = left_first ? -to_right : to_left;
    if(o[0] * o[0] + o[1] * o[1] + o[2] * o[2] > s.best[s.k - 1].d2) return;
    const std::uint32_t fb = left_first ? mid : b, fe = left_first ? e : mid, far = left_first ? right : left;
    // The splits alone bound a range by its cell, and the cells of a surface's points are
    // mostly empty: far from the points (the distance estimate's vertices away from the
    // surface) the search would visit many cells near q whose points are not. The box of the
    // far child, read only when the splits did not exclude it and in the node the search reads
    // next anyway, excludes most of them (dragon, queries with k = 1: 40 % less time). A
    // leaf's box is not checked: it would be one more read to save the reading of the leaf.
    if(fe - fb > leaf_size)
    {
      const Float_box& box = m_nodes[far].box;
      for(int d = 0; d < 3; ++d) o[d] = (std::max)(o[d], gap(s.q[d], box.lo[d], box.hi[d]));
      if(o[0] * o[0] + o[1] * o[1] + o[2] * o[2] > s.best[s.k - 1].d2) return;
    }
    search(s, far, fb, fe, o);
  }

  std::vector<Node> m_nodes;
  // in tree order, with their input indices: sorted in place as the tree is built, with no
  // copy into separate arrays after it, which doubled the memory of the building (dragon:
  // the peak of the run was the tree of the 378k points that vote, 210 -> 202 MB)
  std::vector<Build_point> m_points;
  Box m_box{};                                 // of all points: the first bound of a query
};

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_POINT_NEIGHBORS_H
