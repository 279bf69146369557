// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_ORIENT_NORMALS_H
#define CGAL_ISM_ORIENT_NORMALS_H

#include <CGAL/ISM_reconstruction_function.h>
#include <CGAL/ISM_reconstruction_3/parameters.h>
#include <CGAL/ISM_reconstruction_3/internal/normal_orientation.h>
#include <CGAL/ISM_reconstruction_3/internal/for_each_index.h>

#include <CGAL/pca_estimate_normals.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <iterator>
#include <utility>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal_np {

enum estimate_normals_t { estimate_normals };

} // namespace internal_np
} // namespace ISM_reconstruction_3

namespace parameters {

/// \cond SKIP_IN_MANUAL
template <typename K>
Named_function_parameters<K, ISM_reconstruction_3::internal_np::estimate_normals_t> estimate_normals(const K& k)
{
  return Named_function_parameters<K, ISM_reconstruction_3::internal_np::estimate_normals_t>(k);
}

template <typename K, typename T, typename Tag, typename Base>
Named_function_parameters<K, ISM_reconstruction_3::internal_np::estimate_normals_t,
                          Named_function_parameters<T, Tag, Base> >
estimate_normals(const K& k, const Named_function_parameters<T, Tag, Base>& np)
{
  return Named_function_parameters<K, ISM_reconstruction_3::internal_np::estimate_normals_t,
                                   Named_function_parameters<T, Tag, Base> >(k, np);
}
/// \endcond

} // namespace parameters

/*!
  \ingroup PkgISMReconstruction3Ref

  \brief orients the normals of `points` by the in/out function of the points.

  Orients the normals of `points` by the in/out function of the points, the
  `ISM_reconstruction_function` computed from the same points (their normals are not used
  to compute it): a normal is flipped where the function decreases along it, so that every
  oriented normal points outside. Unlike `mst_orient_normals()`, which propagates one
  orientation along a graph of nearest neighbours, the decision is global (an Ising model
  over the whole box), so that it does not leak across thin parts, close components or
  nested shells.

  A point is oriented directly when the zero level of the function crosses its normal line
  within one leaf of the triangulation around it. The few others (where the in/out model
  missed a piece of the surface, or far from the surface) take the orientation of their
  oriented nearest neighbours, propagated along the most parallel normals first as in
  `mst_orient_normals()`, but from every directly oriented point at once (except one that
  its directly oriented neighbours along the tangent plane contradict) and never farther
  than twice the local leaf size per step; a point that this propagation does not reach is
  oriented by the sign of the central difference of the function along its normal if that
  is clear, and is otherwise left unoriented.

  The normals to orient are those of the `normal_map`; with `estimate_normals(true)`
  unoriented normals are first estimated by PCA of the 18 nearest points
  (`pca_estimate_normals()`). A null or non-finite normal is left unoriented.

  This method modifies the order of input points so as to pack all the points it could
  orient first and returns an iterator over the first point with an unoriented normal (see
  erase-remove idiom). For this reason it should not be called on sorted containers. If
  the in/out function cannot be computed (no inside region is found, or the `callback`
  cancels the run), no normal is changed and `points.begin()` is returned.

  Points far from unit size (a bounding box larger than 2^32 or smaller than 2^-32) are
  taken scaled by a power of two, exactly, as by `ism_surface_reconstruction()`.

  The orientation is as good as the in/out function: parts and gaps thinner than about
  three point spacings are not resolved by it (see the user manual). Outliers are not
  detected (they are oriented like the other points); remove them first, e.g. with
  `remove_outliers()`.

  \tparam PointRange a model of `Range`. The value type of its iterator is the key type of
  the named parameters `point_map` and `normal_map`.

  \param points input point range
  \param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{point_map}
      \cgalParamDescription{a property map associating points to the elements of the point set `points`}
      \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type
                     of the iterator of `PointRange` and whose value type is `geom_traits::Point_3`}
      \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`}
    \cgalParamNEnd
    \cgalParamNBegin{normal_map}
      \cgalParamDescription{a property map associating normals to the elements of the point set `points`}
      \cgalParamType{a model of `ReadWritePropertyMap` whose key type is the value type
                     of the iterator of `PointRange` and whose value type is `geom_traits::Vector_3`}
    \cgalParamNEnd
    \cgalParamNBegin{estimate_normals}
      \cgalParamDescription{if `true`, the normals are first estimated (unoriented) by PCA of
                            the 18 nearest points, overwriting the `normal_map`}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
    \cgalParamNBegin{geom_traits}
      \cgalParamDescription{an instance of a geometric traits class}
      \cgalParamType{a model of `Kernel`}
      \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
    \cgalParamNEnd
  \cgalNamedParamsEnd
  All the named parameters of `ism_surface_reconstruction()` (`maximum_depth`,
  `min_points_per_cell`, `empty_cell_error`, `random_seed`, `callback`, ...) are passed to
  `ISM_reconstruction_function::compute_implicit_function()`.

  \return iterator over the first point with an unoriented normal.
  \throws std::invalid_argument for bad input points or a parameter out of range
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
typename PointRange::iterator ism_orient_normals(PointRange& points,
                                                 const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;

  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Point_map PointMap;
  typedef typename NP_helper::Normal_map NormalMap;
  typedef typename NP_helper::Geom_traits Kernel;
  typedef typename Kernel::Vector_3 Vector;
  typedef typename PointRange::iterator Iterator;
  typedef typename std::iterator_traits<Iterator>::value_type Enriched_point;

  CGAL_static_assertion_msg(NP_helper::has_normal_map(), "Error: no normal map");

  PointMap point_map = NP_helper::get_point_map(points, np);
  NormalMap normal_map = NP_helper::get_normal_map(points, np);
  const bool estimate = choose_parameter(get_parameter(np, ISM_reconstruction_3::internal_np::estimate_normals), false);

  if(points.begin() == points.end())
    return points.end();

  // the function needs no normals: computed first, so that a cancelled or failed run leaves
  // the normals as they were, estimated ones included. Points far from unit size are taken
  // scaled by 2^e, exactly, as by ism_surface_reconstruction() (normalization.h): a normal's
  // direction does not change.
  const int e = ISM_reconstruction_3::internal::normalizing_exponent(points, point_map);
  const ISM_reconstruction_3::internal::Scaled_point_map<PointMap> scaled_point_map(point_map, e);
  ISM_reconstruction_function<Kernel> function = ISM_reconstruction_3::internal::normalized_function<Kernel>(points, np, e);
  try
  {
    if(!function.compute_implicit_function(np))
      return points.begin();
  }
  catch(const std::runtime_error&)  // no inside region: nothing can be oriented
  {
    return points.begin();
  }
  if(estimate)
    pca_estimate_normals<Parallel_if_available_tag>(
        points, 18, parameters::point_map(scaled_point_map).normal_map(normal_map).geom_traits(Kernel()));

  // the test, point by point (read-only on the function, so in parallel)
  std::vector<Iterator> items;
  for(Iterator it = points.begin(); it != points.end(); ++it) items.push_back(it);
  std::vector<std::array<double, 3> > xyz(items.size()), normals(items.size());
  std::vector<ISM_reconstruction_3::internal::Orientation_test> tests(items.size());
  auto test = [&](std::size_t i) {
    const auto p = get(scaled_point_map, *items[i]);
    const Vector n = get(normal_map, *items[i]);
    xyz[i] = {{ to_double(p.x()), to_double(p.y()), to_double(p.z()) }};
    normals[i] = {{ to_double(n.x()), to_double(n.y()), to_double(n.z()) }};
    if(std::isfinite(normals[i][0]) && std::isfinite(normals[i][1]) && std::isfinite(normals[i][2]))
      tests[i] = ISM_reconstruction_3::internal::ism_orientation_of(function, xyz[i], normals[i]);
  };
  ISM_reconstruction_3::internal::for_chunks(0, items.size(), 256, [&](std::size_t lo, std::size_t hi) {
    for(std::size_t i = lo; i < hi; ++i) test(i);
  });
  // where the function is not sure, the confident neighbours decide
  ISM_reconstruction_3::internal::propagate_orientations(xyz, normals, tests, 18, 0.5);
  std::vector<signed char> decision(items.size());
  for(std::size_t i = 0; i < items.size(); ++i) decision[i] = tests[i].sign;

  // flip, then pack the oriented points first (as mst_orient_normals())
  std::deque<Enriched_point> oriented_points, unoriented_points;
  for(std::size_t i = 0; i < items.size(); ++i)
  {
    if(decision[i] < 0)
      put(normal_map, *items[i], -get(normal_map, *items[i]));
    if(decision[i] != 0)
      oriented_points.push_back(*items[i]);
    else
      unoriented_points.push_back(*items[i]);
  }
  const Iterator first_unoriented_point = std::copy(oriented_points.begin(), oriented_points.end(), points.begin());
  std::copy(unoriented_points.begin(), unoriented_points.end(), first_unoriented_point);
  return first_unoriented_point;
}

} // namespace CGAL

#endif // CGAL_ISM_ORIENT_NORMALS_H
