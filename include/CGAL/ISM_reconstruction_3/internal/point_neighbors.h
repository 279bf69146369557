// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_POINT_NEIGHBORS_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_POINT_NEIGHBORS_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/property_map.h>

#include <array>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// The k nearest input points of a location, by index (CGAL's kd-tree), built once and
// shared by the distance estimate and the tangent-plane signs. The tree holds each point
// with its index: a leaf's points are then read together, where an index into the input
// array would read them at random (dragon, 437k points: 0.2 s of queries).
class Point_neighbors
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef K::Point_3 P;
  typedef std::pair<P, std::uint32_t> Item;
  typedef CGAL::First_of_pair_property_map<Item> Point_pmap;
  typedef CGAL::Search_traits_3<K> Base_traits;
  typedef CGAL::Search_traits_adapter<Item, Point_pmap, Base_traits> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  typedef Search::Tree Tree;

public:
  explicit Point_neighbors(const std::vector<std::array<double, 3> >& points)
  {
    std::vector<Item> items;
    items.reserve(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      items.push_back(Item(P(points[i][0], points[i][1], points[i][2]), std::uint32_t(i)));
    m_tree.reset(new Tree(items.begin(), items.end()));
    m_tree->build();  // before the parallel queries: the tree is then only read
  }

  std::size_t size() const { return m_tree->size(); }

  // calls `visit(index, squared distance)` for the k nearest points of `q`, nearest first
  template <class Visitor>
  void for_nearest(const std::array<double, 3>& q, unsigned int k, const Visitor& visit) const
  {
    Search search(*m_tree, P(q[0], q[1], q[2]), k, 0, true, Search::Distance(Point_pmap()));
    for(const auto& item : search) visit(item.first.second, item.second);
  }

private:
  std::unique_ptr<Tree> m_tree;
};

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_POINT_NEIGHBORS_H
