// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_NORMALIZATION_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_NORMALIZATION_H

#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// The method holds sizes in single precision (the kd-tree's boxes, the leaf sizes, the voting
// radii, the misses of the surface refinement, the spacings of the winding number: wrong
// beyond 3.4e38 and below 1e-38), and computes squares (distances: 1e+-154) and cubes (the
// barycentric coordinates in a leaf, the winding number: 1e+-103) of lengths. The surface of
// ism_surface_reconstruction() and of the tool is therefore computed on the points scaled by
// a power of two, which is exact: the exponent e below, 0 (the points as they are, the same
// result to the bit as without the scaling) for a span (the largest side of the points'
// bounding box) in [2^-32, 2^32), else the one that brings the span into [1, 2). The mesh
// is scaled back by 2^-e, also exactly (unless it falls below 2.2e-308, in subnormals).
constexpr int unscaled_span_exponent = 32;

template <class PointRange, class PointMap>
int normalizing_exponent(const PointRange& points, PointMap point_map)
{
  double lo[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  for(const auto& item : points)
  {
    const auto& p = get(point_map, item);
    const double x[3] = { to_double(p.x()), to_double(p.y()), to_double(p.z()) };
    for(int d = 0; d < 3; ++d)
      if(std::isfinite(x[d]))
      {
        lo[d] = (std::min)(lo[d], x[d]);
        hi[d] = (std::max)(hi[d], x[d]);
      }
  }
  // half the span: hi - lo overflows for points near +-DBL_MAX
  double half = 0;
  for(int d = 0; d < 3; ++d)
    if(hi[d] > lo[d]) half = (std::max)(half, 0.5 * hi[d] - 0.5 * lo[d]);
  if(!(half > 0) || !std::isfinite(half)) return 0;  // refused by the reconstruction
  const int k = std::ilogb(half) + 1;                // the span is in [2^k, 2^(k+1)), about
  if(k >= -unscaled_span_exponent && k < unscaled_span_exponent) return 0;
  return -k;
}

// `p` times 2^e, exactly (the scaling above, and back with -e)
template <class Point>
Point scaled_point(const Point& p, int e)
{
  return Point(std::ldexp(to_double(p.x()), e), std::ldexp(to_double(p.y()), e), std::ldexp(to_double(p.z()), e));
}

// the points of `PointMap` times 2^e: the scaled points are read through it, not copied
template <class PointMap>
struct Scaled_point_map
{
  typedef typename boost::property_traits<PointMap>::key_type key_type;
  typedef typename boost::property_traits<PointMap>::value_type value_type;
  typedef value_type reference;
  typedef boost::readable_property_map_tag category;

  PointMap point_map;
  int e;

  Scaled_point_map(PointMap map, int exponent) : point_map(map), e(exponent) {}
  friend value_type get(const Scaled_point_map& m, const key_type& key)
  {
    return scaled_point(value_type(get(m.point_map, key)), m.e);
  }
};

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_NORMALIZATION_H
