// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_POINT_INPUT_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_POINT_INPUT_H

#include <CGAL/ISM_reconstruction_3/internal/disjoint_sets.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

typedef std::array<double, 3> Xyz;

// Principal axes of a point set, computed on coordinates centred and scaled to O(1) so
// that neither 1e30 nor 1e-30 coordinates overflow or underflow the covariance.
struct Principal_axes
{
  Xyz centroid;
  std::array<Xyz, 3> axis;        // unit eigenvectors, ascending eigenvalues
  std::array<double, 3> variance; // eigenvalues, in the scaled units
  double scale;                   // coordinates were divided by this
};

inline Principal_axes principal_axes(const std::vector<Xyz>& points)
{
  Principal_axes pa;
  long double c[3] = {0, 0, 0};
  for(const Xyz& p : points)
    for(int d = 0; d < 3; ++d) c[d] += p[d];
  for(int d = 0; d < 3; ++d) pa.centroid[d] = double(c[d] / points.size());
  double scale = 0;
  for(const Xyz& p : points)
    for(int d = 0; d < 3; ++d) scale = (std::max)(scale, std::abs(p[d] - pa.centroid[d]));
  pa.scale = scale > 0 ? scale : 1.;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for(const Xyz& p : points)
  {
    const Eigen::Vector3d q((p[0] - pa.centroid[0]) / pa.scale, (p[1] - pa.centroid[1]) / pa.scale,
                            (p[2] - pa.centroid[2]) / pa.scale);
    cov += q * q.transpose();
  }
  cov /= double(points.size());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
  for(int i = 0; i < 3; ++i)
  {
    pa.variance[i] = (std::max)(0., solver.eigenvalues()[i]);
    for(int d = 0; d < 3; ++d) pa.axis[i][d] = solver.eigenvectors()(d, i);
  }
  return pa;
}

// The extent along each axis (the longest) of the largest group of points that lie together:
// the occupied cells of a grid of n^3 cells over the points' box, joined across faces,
// edges and corners (a gap narrower than a cell is bridged), among the groups that hold at
// least 1 % of the points. Two objects far apart are two groups, each as large as itself;
// a stray point is a group too small to count. `all`: the points' extent. n is 32, fewer
// for fewer than 10,240 points: a surface as wide as the box crosses about pi n^2 cells, and
// with fewer than 3 points a cell its sampling leaves empty cells between occupied ones; at
// n = 32, 300 random points on a sphere fell into groups of a few points, and 3 to 9 levels
// were added "for far outliers" that were not there (session 44).
inline double largest_group_extent(const std::vector<Xyz>& points, const Xyz& lo, double all)
{
  const int n = (std::max)(4, (std::min)(32, int(std::sqrt(double(points.size()) / 10.))));
  const auto cell_of = [&](const Xyz& p) {
    int c = 0;
    for(int d = 2; d >= 0; --d)
      c = c * n + (std::min)(n - 1, (std::max)(0, int((p[d] - lo[d]) / all * n)));
    return c;
  };
  std::vector<std::uint32_t> count(n * n * n, 0);
  for(const Xyz& p : points) ++count[std::size_t(cell_of(p))];
  Disjoint_sets groups(count.size());
  for(int k = 0; k < n; ++k)
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i)
      {
        const int c = (k * n + j) * n + i;
        if(count[std::size_t(c)] == 0) continue;
        for(int dk = 0; dk <= 1; ++dk)  // each pair of touching cells once
          for(int dj = -1; dj <= 1; ++dj)
            for(int di = -1; di <= 1; ++di)
            {
              if(dk == 0 && (dj < 0 || (dj == 0 && di <= 0))) continue;
              const int ii = i + di, jj = j + dj, kk = k + dk;
              if(ii < 0 || jj < 0 || ii >= n || jj >= n || kk >= n) continue;
              const int e = (kk * n + jj) * n + ii;
              if(count[std::size_t(e)] > 0) groups.unite(std::uint32_t(c), std::uint32_t(e));
            }
      }
  std::vector<std::size_t> size(count.size(), 0);
  std::vector<Xyz> low(count.size(), {{ HUGE_VAL, HUGE_VAL, HUGE_VAL }}), high(count.size(), {{ -HUGE_VAL, -HUGE_VAL, -HUGE_VAL }});
  for(const Xyz& p : points)
  {
    const std::uint32_t g = groups.find(std::uint32_t(cell_of(p)));
    ++size[g];
    for(int d = 0; d < 3; ++d)
    {
      low[g][d] = (std::min)(low[g][d], p[d]);
      high[g][d] = (std::max)(high[g][d], p[d]);
    }
  }
  double largest = 0;
  for(std::size_t g = 0; g < size.size(); ++g)
    if(size[g] > 0 && size[g] >= points.size() / 100)
      for(int d = 0; d < 3; ++d) largest = (std::max)(largest, high[g][d] - low[g][d]);
  return largest > 0 ? largest : all;
}

// How many times the points' extent exceeds that of their bulk along each axis (the longest
// of either): a few far outliers, or a second object far away, make the box that much
// larger, and the leaves near the surface that much coarser at the same level. The bulk is
// the smaller of 98 % of the points and their largest group (largest_group_extent()).
inline double extent_over_bulk_extent(const std::vector<Xyz>& points)
{
  if(points.size() < 100) return 1;
  std::vector<double> t(points.size());
  double all = 0, bulk = 0;
  Xyz lo;
  const std::size_t k = points.size() / 100;
  for(int d = 0; d < 3; ++d)
  {
    for(std::size_t i = 0; i < points.size(); ++i) t[i] = points[i][d];
    const auto [low, high] = std::minmax_element(t.begin(), t.end());
    lo[d] = *low;
    all = (std::max)(all, *high - *low);
    std::nth_element(t.begin(), t.begin() + k, t.end());
    const double low98 = t[k];
    std::nth_element(t.begin(), t.end() - 1 - k, t.end());
    bulk = (std::max)(bulk, t[t.size() - 1 - k] - low98);
  }
  if(std::isfinite(all) && all > 0) bulk = (std::min)(bulk, largest_group_extent(points, lo, all));
  const double ratio = all / bulk;  // inf or NaN when DBL_MAX and -DBL_MAX overflow the extent
  return ratio > 1 ? (std::min)(ratio, 1e300) : 1;
}

// The levels to add to maximum_depth so that the leaves can reach near the bulk of the
// points the size that many levels give without the outliers (three bisections halve the
// edges): none for an ordinary point set, whose ratio is below 2.
inline int far_outlier_levels(double extent_ratio)
{
  return extent_ratio < 2 ? 0 : 3 * int(std::floor(std::log2((std::min)(extent_ratio, 1e15))));
}

// Added to the message of a refusal (a line, a plane, no inside) when far outliers are the
// likely cause.
inline std::string far_outlier_hint(double extent_ratio)
{
  if(extent_ratio < 1e3) return std::string();
  return "; the bulk of the points (98 % of them, or their largest group) spans " +
         std::to_string(int(std::floor(std::log10(extent_ratio)))) +
         " orders of magnitude less than all of them: remove the far outliers first "
         "(e.g. CGAL::remove_outliers()), or reconstruct parts far apart one by one";
}

// Refuses, with a message, what cannot bound a volume: no points, non-finite
// coordinates, too few distinct points, all points on a line or a plane. If
// `far_points_may_go`, points on a line or a plane only to the spread that a few far ones
// give them (the bulk spans 1e3 times less) pass, and true is returned: the removal of the
// isolated points may leave the far ones out, and what is left must be checked again (a
// sphere with one point 1e8 away had been refused as "all points lie on a line").
inline bool check_point_set(const std::vector<Xyz>& points, bool far_points_may_go = false)
{
  if(points.empty())
    throw std::invalid_argument("ISM reconstruction: the point set is empty");
  for(std::size_t i = 0; i < points.size(); ++i)
    for(int d = 0; d < 3; ++d)
      if(!std::isfinite(points[i][d]))
        throw std::invalid_argument("ISM reconstruction: point " + std::to_string(i) +
                                    " has a NaN or infinite coordinate");
  // Sizes held in single precision (the kd-tree's boxes, voting radii and normals, the
  // leaves' coplanarity errors) stop following the points beyond float's range: the bunny
  // gives the same surface scaled from 1e-35 to 1e38, another at 1e40 and 1e-40, and a
  // sphere scaled by 1e150 or 1e-150 found no inside; at 1e308 the box overflowed. Refused
  // here, with the way out, rather than answered with a wrong mesh or a misleading error.
  {
    double span = 0;
    for(int d = 0; d < 3; ++d)
    {
      double lo = HUGE_VAL, hi = -HUGE_VAL;
      for(const Xyz& p : points)
      {
        lo = (std::min)(lo, p[d]);
        hi = (std::max)(hi, p[d]);
      }
      span = (std::max)(span, hi - lo);
    }
    if(span > 0 && !(span >= 1e-32 && span <= 1e32))
    {
      std::ostringstream os;
      os << "ISM reconstruction: the points span ";
      if(std::isfinite(span)) os << span; else os << "more than a double holds";
      os << " (the largest side of their bounding box), outside the supported 1e-32 to 1e32"
            " (some sizes are held in single precision): scale the points, and the result back"
         << far_outlier_hint(extent_over_bulk_extent(points));
      throw std::invalid_argument(os.str());
    }
  }
  // only whether there are that many distinct points, so a scan that stops there, not a
  // sort of a copy (0.2 s on the dragon's 437k points)
  const std::size_t minimum = 10;
  std::vector<Xyz> distinct;
  for(std::size_t i = 0; i < points.size() && distinct.size() < minimum; ++i)
    if(std::find(distinct.begin(), distinct.end(), points[i]) == distinct.end()) distinct.push_back(points[i]);
  if(distinct.size() < minimum)
    throw std::invalid_argument("ISM reconstruction: " + std::to_string(distinct.size()) +
                                (distinct.size() == 1 ? " distinct point (of " : " distinct points (of ") +
                                std::to_string(points.size()) +
                                "); at least " + std::to_string(minimum) + " are needed to bound a volume");
  // duplicates weigh the variances but cannot make a zero one positive, or the reverse
  const Principal_axes pa = principal_axes(points);
  const double largest = pa.variance[2];
  // A point 1e10 away from a unit sphere, or two spheres 1e6 apart, make a line to these
  // variances: the message says how near (a millionth of the spread, not exactly), and the
  // far-outlier hint why.
  const char* shape = pa.variance[1] <= 1e-12 * largest ? "line" : (pa.variance[0] <= 1e-12 * largest ? "plane" : nullptr);
  if(shape == nullptr) return false;
  const double extent_ratio = extent_over_bulk_extent(points);
  if(far_points_may_go && !far_outlier_hint(extent_ratio).empty()) return true;
  throw std::invalid_argument(std::string("ISM reconstruction: all points lie on a ") + shape +
                              " (to a millionth of their spread); they cannot bound a volume" + far_outlier_hint(extent_ratio));
}

// Points within half their spacing of one plane (99 % of them) sample an open sheet, or a
// plate thinner than the points are apart: no cell can hold a vertex between its sides. The
// exact plane is refused above; near it the output was garbage without a word (an
// independent black-box run, session 41: a unit disk of 10,000 points with noise 1e-3 came
// out as 12 blobs, 5,000 points on a plane and one 0.5 above it as a slab with a spike to
// that point). 1 % may stray (that point). A closed surface has points on both sides of
// any plane through its centroid, and a plate as thick as the spacing gave 5 parts and genus
// 14 anyway: nothing that could be reconstructed is refused. `neighbors`: a kd-tree of
// `points` (Point_neighbors).
template <class Neighbors>
void check_not_a_sheet(const std::vector<Xyz>& points, const Neighbors& neighbors)
{
  if(points.size() < 2) return;
  const Principal_axes pa = principal_axes(points);
  const Xyz& n = pa.axis[0];  // across the plane of the two largest variances
  std::vector<double> offset(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    offset[i] = std::abs((points[i][0] - pa.centroid[0]) * n[0] + (points[i][1] - pa.centroid[1]) * n[1] +
                         (points[i][2] - pa.centroid[2]) * n[2]);
  const std::size_t at = points.size() * 99 / 100;
  std::nth_element(offset.begin(), offset.begin() + std::ptrdiff_t(at), offset.end());
  const double thickness = offset[at];
  // the median distance to the nearest other point, of at most 20,000 of them
  const std::size_t stride = (std::max)(std::size_t(1), points.size() / 20000);
  std::vector<double> spacing;
  for(std::size_t i = 0; i < points.size(); i += stride)
  {
    double d2 = 0;
    neighbors.for_nearest(points[i], 2, [&](std::uint32_t j, double d) { if(j != i) d2 = d; });
    spacing.push_back(std::sqrt(d2));
  }
  std::nth_element(spacing.begin(), spacing.begin() + std::ptrdiff_t(spacing.size() / 2), spacing.end());
  const double median_spacing = spacing[spacing.size() / 2];
  if(thickness < 0.5 * median_spacing)
  {
    std::ostringstream os;
    os << "ISM reconstruction: 99 % of the points lie within " << thickness << " of a plane, less than half their "
       << "spacing (median " << median_spacing << "): an open sheet, or a plate thinner than the sampling; "
       << "they cannot bound a volume";
    throw std::runtime_error(os.str());
  }
}

// The bounding cell (paper section 4): centred on the points, axes from PCA, scaled to
// a parallelepiped around them with a margin. Each side is at least half the longest, so
// that the tetrahedra stay within a 2:1 anisotropy.
struct Oriented_box
{
  Xyz origin;
  std::array<Xyz, 3> axis;  // full edge vectors
  Xyz data_center;          // centre of the points' extent
  double data_radius;       // half the diagonal of the points' extent
};

inline Oriented_box bounding_parallelepiped(const std::vector<Xyz>& points, double margin)
{
  const Principal_axes pa = principal_axes(points);
  double lo[3], hi[3];
  for(int i = 0; i < 3; ++i) { lo[i] = HUGE_VAL; hi[i] = -HUGE_VAL; }
  for(const Xyz& p : points)
    for(int i = 0; i < 3; ++i)
    {
      double t = 0;
      for(int d = 0; d < 3; ++d) t += (p[d] - pa.centroid[d]) * pa.axis[i][d];
      lo[i] = (std::min)(lo[i], t);
      hi[i] = (std::max)(hi[i], t);
    }
  double longest = 0;
  for(int i = 0; i < 3; ++i) longest = (std::max)(longest, hi[i] - lo[i]);
  Oriented_box box;
  box.origin = pa.centroid;
  box.data_center = pa.centroid;
  double diag2 = 0;
  for(int i = 0; i < 3; ++i)
  {
    const double side = (std::max)(hi[i] - lo[i], 0.5 * longest) + 2 * margin * longest;
    const double mid = 0.5 * (lo[i] + hi[i]);
    for(int d = 0; d < 3; ++d)
    {
      box.axis[i][d] = side * pa.axis[i][d];
      box.origin[d] += (mid - 0.5 * side) * pa.axis[i][d];
      box.data_center[d] += mid * pa.axis[i][d];
    }
    diag2 += (hi[i] - lo[i]) * (hi[i] - lo[i]);
  }
  box.data_radius = 0.5 * std::sqrt(diag2);
  return box;
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_POINT_INPUT_H
