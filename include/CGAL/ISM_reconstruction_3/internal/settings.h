// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_SETTINGS_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_SETTINGS_H

#include <CGAL/ISM_reconstruction_3/parameters.h>
#include <CGAL/Named_function_parameters.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace CGAL {
namespace ISM_reconstruction_3 {

/*!
  \ingroup PkgISMReconstruction3Ref
  \brief All parameters of the method, with their defaults.

  `settings_from_parameters()` fills it
  from named parameters. The defaults are the measured ones (see the user manual); the
  paper's settings (`paper_settings(true)`) change only what the paper fixes differently.
*/
struct Settings
{
  static constexpr int deepest_level = 48;  ///< the largest `maximum_depth`, also with the levels far outliers add
  int maximum_depth = 24;                 ///< deepest level of a cell (the paper's maximum level)
  int min_points_per_cell = 6;            ///< fitting and subdivision need this many points (paper: 5 to 10)
  bool sparse_cell_planes = true;         ///< a cell with fewer points takes the plane of that many points nearest its own (paper: its parent's plane)
  /*! if the steps after the Ising signs leave no inside, or more inside clusters than the signs had inside
      vertices (leaves too long for few points), the computation is redone with twice `min_points_per_cell`, up
      to this many times; 0: never (the paper) */
  int coarser_refinements = 2;
  double coplanarity_threshold = 0.;      ///< a cell whose coplanarity error is below this is not subdivided
  double empty_cell_error = 0.05;         ///< eps_empty as a fraction of [eps_min, eps_max]
  double initial_temperature = 15.;       ///< annealing from scratch (the first pass), in units of the mean |H_e|
  double warm_start_temperature = 3.;     ///< annealing from the previous signs (passes during refinement, and the final one after them)
  double cooling_factor = 0.97700;        ///< temperature ratio between sweeps of the final annealing (3 -> 0.3 in 100 sweeps)
  int number_of_sweeps = 100;             ///< sweeps of the final annealing
  long warm_start_interval = 0;           ///< bisections between topology passes during refinement; 0: whenever the leaves doubled; -1: none
  /*! seed of the annealing: the result depends only on the input and the seed */
  std::uint64_t random_seed = 1;
  unsigned int smoothing_iterations = 0;  ///< Taubin lambda/mu iterations on the output mesh (0: the marching-tetrahedra surface; Taubin on its irregular triangles folded 851 edges of the bunny against 17)
  /*! the marching-tetrahedra vertex of a crossed edge moves along the edge onto the quadric fitted to this
      many nearest points (jet_crossing.h); 0: F's linear zero crossing (the paper) */
  unsigned int crossing_neighbors = 12;
  /*! Taubin's lambda, the smoothing factor (> 0; with smoothing_iterations > 0 checked: 0 < lambda < -mu) */
  double smoothing_lambda = 0.5;
  /*! Taubin's mu, the inflating factor (< -lambda) */
  double smoothing_mu = -0.53;
  bool clamp_box_boundary = true;         ///< hold the box boundary vertices outside while annealing
  /*! how the value of a vertex is estimated (its sign comes from the Ising model) */
  Distance_estimate distance_estimate = LOCAL_PLANE_DISTANCE;
  double box_margin = 0.1;                ///< margin around the points, as a fraction of their largest extent
  /*! bytes the reconstruction may add to what the process holds; `0`: what the machine allows (physical
      memory, `ulimit -v` and `-d`, cgroup limits). A larger value does not raise those limits. */
  std::size_t memory_limit = 0;
  double minimum_island_fraction = 0.01;  ///< inside (or enclosed outside) clusters of fewer vertices than this fraction of the largest inside cluster are flipped; 0: keep all
  /*! a handle of the surface that only vertices nearer to it than this many times the size of the leaves
      it crosses (the median, or the local one where larger) hold open is removed (a tunnel filled, else a bridge cut); 0: keep all handles */
  double thin_handle_depth = 0.2;
  /*! near the points, a vertex takes the side of the tangent planes of its nearest points,
      whose normals (PCA) are oriented by the in/out function; false: the Ising sign (the paper) */
  bool tangent_plane_signs = true;
  /*! after the signs, the leaves in which F misses a point by more than `surface_refinement_tolerance` times
      their longest edge (and 3 times the median miss, the noise) are bisected, up to this many times; 0: none */
  int surface_refinement_passes = 2;
  /*! the miss of F at a point, relative to the longest edge of its leaf, above which the leaf is bisected */
  double surface_refinement_tolerance = 0.05;
  /*! then, an inside vertex of the surface's leaves away from the points is turned outside if this many rays
      from it, pointing away from its nearest point, all leave the box without meeting a point; 0: never (the paper) */
  int escape_rays = 5;
  /*! last, the vertices of the surface's leaves away from the points are re-signed by the winding number of the
      points, their normals oriented by F, where it is clearly inside or outside; false: never (the paper) */
  bool winding_number_signs = true;
  /*! last, an inside cluster but the largest is joined to another across one or two outside vertices among the
      points where this adds no handle (a part cut off at a neck too thin for the leaves); false: never (the paper) */
  bool join_islands = true;
  /*! first, the points whose 12 nearest points spread more than 20 times farther than the median point's are left
      out (stray returns far from the surface); false: never (the paper) */
  bool remove_isolated_points = true;
  /*! first of all, if most points have a few copies far closer to them than the next points (several scans
      along the same beams, points written again with rounding), each such cluster is replaced by its centroid;
      false: never (the paper) */
  bool merge_point_clusters = true;
  /*! before the refinement, noisy points (see `point_smoothing_noise`) are moved onto a quadric fitted to their
      `point_smoothing_neighbors` nearest points (jet smoothing), this many times; 0: never (the paper) */
  int point_smoothing_iterations = 3;
  /*! the nearest points a point's quadric is fitted to; more, up to 64, where the points are dense for their
      noise (so that they reach 2.7 sigma) */
  int point_smoothing_neighbors = 24;
  /*! the points are smoothed only if the median coplanarity error of their 12 nearest points exceeds this (clean
      scans: about 0.001, gaussian noise of 0.1 % of the diagonal: 0.02, 0.25 %: 0.08, 0.5 %: 0.13); 0: always */
  double point_smoothing_noise = 0.06;
  std::function<bool(double)> callback;   ///< progress in [0,1]; returning false cancels

  /// The settings of the paper (section 4): squared nearest-point distance, no clamping
  /// (the global sign is fixed afterwards from the box corners), topology every 1000
  /// subdivisions, Taubin smoothing.
  static Settings paper()
  {
    Settings s;
    s.clamp_box_boundary = false;
    s.distance_estimate = NEAREST_POINT_SQUARED_DISTANCE;
    s.warm_start_interval = 1000;
    s.min_points_per_cell = 8;
    s.sparse_cell_planes = false;
    s.coarser_refinements = 0;
    s.coplanarity_threshold = 1e-3;
    s.minimum_island_fraction = 0;
    s.thin_handle_depth = 0;
    s.tangent_plane_signs = false;
    s.surface_refinement_passes = 0;
    s.escape_rays = 0;
    s.winding_number_signs = false;
    s.join_islands = false;
    s.remove_isolated_points = false;
    s.merge_point_clusters = false;
    s.point_smoothing_iterations = 0;
    s.smoothing_iterations = 3;
    s.crossing_neighbors = 0;
    return s;
  }

  /// \throws std::invalid_argument with a message naming the parameter if one is out of range
  void check() const
  {
    auto fail = [](const std::string& name, const std::string& value, const char* range) {
      throw std::invalid_argument("ISM reconstruction: parameter " + name + " = " + value + " is out of range " + range);
    };
    // ten digits: a value just beyond a bound (1.000001e6) must not print as the bound
    auto str = [](double v) { std::ostringstream os; os << std::setprecision(10) << v; return os.str(); };
    if(maximum_depth < 1 || maximum_depth > deepest_level)
      fail("maximum_depth", std::to_string(maximum_depth), ("[1, " + std::to_string(deepest_level) + "]").c_str());
    if(min_points_per_cell < 3 || min_points_per_cell > 1000000)
      fail("min_points_per_cell", std::to_string(min_points_per_cell), "[3, 1000000]");
    if(coarser_refinements < 0 || coarser_refinements > 10)
      fail("coarser_refinements", std::to_string(coarser_refinements), "[0, 10]");
    if(!(coplanarity_threshold >= 0 && coplanarity_threshold < 1. / 3))
      fail("coplanarity_threshold", str(coplanarity_threshold), "[0, 1/3)");
    if(!(empty_cell_error >= 0 && empty_cell_error <= 1)) fail("empty_cell_error", str(empty_cell_error), "[0, 1]");
    if(!(initial_temperature > 0 && initial_temperature <= 1e6))
      fail("initial_temperature", str(initial_temperature), "(0, 1e6]");
    if(!(warm_start_temperature > 0 && warm_start_temperature <= 1e6))
      fail("warm_start_temperature", str(warm_start_temperature), "(0, 1e6]");
    if(!(cooling_factor > 0 && cooling_factor <= 1)) fail("cooling_factor", str(cooling_factor), "(0, 1]");
    if(number_of_sweeps < 1 || number_of_sweeps > 100000)
      fail("number_of_sweeps", std::to_string(number_of_sweeps), "[1, 100000]");
    if(warm_start_interval < -1) fail("warm_start_interval", std::to_string(warm_start_interval), "[-1, inf)");
    if(crossing_neighbors != 0 && (crossing_neighbors < 6 || crossing_neighbors > 64))
      fail("crossing_neighbors", std::to_string(crossing_neighbors), "0 or [6, 64]");
    if(smoothing_iterations > 10000) fail("smoothing_iterations", std::to_string(smoothing_iterations), "[0, 10000]");
    if(!(std::abs(smoothing_lambda) <= 1)) fail("smoothing_lambda", str(smoothing_lambda), "[-1, 1]");
    if(!(std::abs(smoothing_mu) <= 1)) fail("smoothing_mu", str(smoothing_mu), "[-1, 1]");
    // Taubin's filter multiplies a frequency k in [0, 2] of the umbrella operator by
    // (1 - lambda k)(1 - mu k) per iteration; Taubin lets it exceed 1 slightly at low k (no
    // shrinking), far above 1 it diverges. Even the slight excess compounds: with the
    // defaults (at most 1.00085) 10,000 iterations blew a unit sphere up to radius 126, so
    // the gain over all the iterations is bounded too (1.1: about 110 iterations).
    if(smoothing_iterations > 0)
    {
      double gain = 0;
      for(int i = 0; i <= 2000; ++i)
      {
        const double k = i / 1000.;
        gain = (std::max)(gain, std::abs((1 - smoothing_lambda * k) * (1 - smoothing_mu * k)));
      }
      const std::string filter = "ISM reconstruction: smoothing_lambda = " + str(smoothing_lambda) +
                                 " with smoothing_mu = " + str(smoothing_mu);
      if(gain > 1.01)
        throw std::invalid_argument(filter + " makes Taubin smoothing diverge (|(1 - lambda k)(1 - mu k)| > 1.01 for some k in [0, 2])");
      // near k = 0 the factor is about 1 - (lambda + mu) k: unless mu < -lambda < 0 every
      // frequency shrinks, the lowest, the shape itself, too (lambda = mu = 1, 10,000
      // iterations: the bunny to a point; lambda 0.5, mu 0.53, 1,000: to 28 % of its volume)
      if(!(smoothing_lambda > 0 && smoothing_mu < -smoothing_lambda))
        throw std::invalid_argument(filter + " shrinks the surface: Taubin smoothing needs 0 < lambda < -mu");
      if(smoothing_iterations * std::log(gain) > std::log(1.1))
        throw std::invalid_argument(filter + " amplifies low frequencies by up to " + str(gain) +
                                    " per iteration: smoothing_iterations = " + std::to_string(smoothing_iterations) +
                                    " would inflate the surface (at most " +
                                    std::to_string(int(std::log(1.1) / std::log(gain))) + " iterations)");
    }
    if(distance_estimate != NEAREST_POINT_SQUARED_DISTANCE && distance_estimate != NEAREST_POINT_DISTANCE &&
       distance_estimate != LOCAL_PLANE_DISTANCE)
      fail("distance_estimate", std::to_string(int(distance_estimate)), "(one of the three Distance_estimate values)");
    if(!(box_margin > 0 && box_margin <= 10)) fail("box_margin", str(box_margin), "(0, 10]");
    if(!(minimum_island_fraction >= 0 && minimum_island_fraction < 1))
      fail("minimum_island_fraction", str(minimum_island_fraction), "[0, 1)");
    if(!(thin_handle_depth >= 0 && thin_handle_depth <= 10)) fail("thin_handle_depth", str(thin_handle_depth), "[0, 10]");
    if(surface_refinement_passes < 0 || surface_refinement_passes > 10)
      fail("surface_refinement_passes", std::to_string(surface_refinement_passes), "[0, 10]");
    if(!(surface_refinement_tolerance > 0 && surface_refinement_tolerance <= 1))
      fail("surface_refinement_tolerance", str(surface_refinement_tolerance), "(0, 1]");
    if(escape_rays < 0 || escape_rays > 64) fail("escape_rays", std::to_string(escape_rays), "[0, 64]");
    if(point_smoothing_iterations < 0 || point_smoothing_iterations > 100)
      fail("point_smoothing_iterations", std::to_string(point_smoothing_iterations), "[0, 100]");
    if(point_smoothing_neighbors < 6 || point_smoothing_neighbors > 64)
      fail("point_smoothing_neighbors", std::to_string(point_smoothing_neighbors), "[6, 64]");
    if(!(point_smoothing_noise >= 0 && point_smoothing_noise < 1. / 3))
      fail("point_smoothing_noise", str(point_smoothing_noise), "[0, 1/3)");
  }
};

namespace internal {

// An integer parameter may be given as any arithmetic type. Converting a NaN or a value
// beyond the field's type is undefined or wraps (maximum_depth(4294967320LL) ran at depth
// 24, maximum_depth(NaN) printed -2147483648), and a fraction would be cut silently
// (maximum_depth(2.7) ran at 2): refused here, naming the parameter, before the conversion.
template <class T, class V>
T integer_parameter(const V& v, T, const char* name)
{
  bool exact = true;
  if constexpr(std::is_floating_point<V>::value)
    exact = v == std::floor(v) && v >= double(std::numeric_limits<T>::lowest()) &&
            v < std::ldexp(1., std::numeric_limits<T>::digits);  // 2^digits: max() + 1, exact
  else if constexpr(std::is_integral<V>::value)
  {
    bool negative = false;
    if constexpr(std::is_signed<V>::value) negative = v < 0;
    exact = negative ? std::is_signed<T>::value && std::intmax_t(v) >= std::intmax_t(std::numeric_limits<T>::lowest())
                     : std::uintmax_t(v) <= std::uintmax_t(std::numeric_limits<T>::max());
  }
  if(!exact)
  {
    std::ostringstream os;
    os << "ISM reconstruction: parameter " << name << " = " << std::setprecision(12) << v
       << " is not an integer in the range of its type";
    throw std::invalid_argument(os.str());
  }
  return T(v);
}
template <class T>
T integer_parameter(const CGAL::internal_np::Param_not_found&, T default_value, const char*)
{
  return default_value;
}

} // namespace internal

/// Reads the named parameters into `Settings` (the paper's defaults when `paper_settings(true)`).
template <class NamedParameters>
Settings settings_from_parameters(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace inp = ISM_reconstruction_3::internal_np;
  const bool paper = choose_parameter(get_parameter(np, inp::paper_settings), false);
  const Settings d = paper ? Settings::paper() : Settings();
  Settings s;
  s.maximum_depth = internal::integer_parameter(get_parameter(np, inp::maximum_depth), d.maximum_depth, "maximum_depth");
  s.min_points_per_cell = internal::integer_parameter(get_parameter(np, CGAL::internal_np::min_points_per_cell), d.min_points_per_cell, "min_points_per_cell");
  s.coplanarity_threshold = choose_parameter(get_parameter(np, inp::coplanarity_threshold), d.coplanarity_threshold);
  s.empty_cell_error = choose_parameter(get_parameter(np, inp::empty_cell_error), d.empty_cell_error);
  s.initial_temperature = choose_parameter(get_parameter(np, inp::initial_temperature), d.initial_temperature);
  s.warm_start_temperature = choose_parameter(get_parameter(np, inp::warm_start_temperature), d.warm_start_temperature);
  s.cooling_factor = choose_parameter(get_parameter(np, inp::cooling_factor), d.cooling_factor);
  s.number_of_sweeps = internal::integer_parameter(get_parameter(np, inp::number_of_sweeps), d.number_of_sweeps, "number_of_sweeps");
  s.warm_start_interval = internal::integer_parameter(get_parameter(np, inp::warm_start_interval), d.warm_start_interval, "warm_start_interval");
  s.random_seed = internal::integer_parameter(get_parameter(np, CGAL::internal_np::random_seed), d.random_seed, "random_seed");
  s.smoothing_iterations = internal::integer_parameter(get_parameter(np, inp::smoothing_iterations), d.smoothing_iterations, "smoothing_iterations");
  s.crossing_neighbors = internal::integer_parameter(get_parameter(np, inp::crossing_neighbors), d.crossing_neighbors, "crossing_neighbors");
  s.smoothing_lambda = choose_parameter(get_parameter(np, inp::smoothing_lambda), d.smoothing_lambda);
  s.smoothing_mu = choose_parameter(get_parameter(np, inp::smoothing_mu), d.smoothing_mu);
  s.clamp_box_boundary = choose_parameter(get_parameter(np, inp::clamp_box_boundary), d.clamp_box_boundary);
  s.distance_estimate = choose_parameter(get_parameter(np, inp::distance_estimate), d.distance_estimate);
  s.box_margin = choose_parameter(get_parameter(np, inp::box_margin), d.box_margin);
  s.minimum_island_fraction = choose_parameter(get_parameter(np, inp::minimum_island_fraction), d.minimum_island_fraction);
  s.thin_handle_depth = choose_parameter(get_parameter(np, inp::thin_handle_depth), d.thin_handle_depth);
  s.tangent_plane_signs = choose_parameter(get_parameter(np, inp::tangent_plane_signs), d.tangent_plane_signs);
  s.surface_refinement_passes = internal::integer_parameter(get_parameter(np, inp::surface_refinement_passes), d.surface_refinement_passes, "surface_refinement_passes");
  s.surface_refinement_tolerance =
      choose_parameter(get_parameter(np, inp::surface_refinement_tolerance), d.surface_refinement_tolerance);
  s.escape_rays = internal::integer_parameter(get_parameter(np, inp::escape_rays), d.escape_rays, "escape_rays");
  s.winding_number_signs = choose_parameter(get_parameter(np, inp::winding_number_signs), d.winding_number_signs);
  s.join_islands = choose_parameter(get_parameter(np, inp::join_islands), d.join_islands);
  s.sparse_cell_planes = choose_parameter(get_parameter(np, inp::sparse_cell_planes), d.sparse_cell_planes);
  s.coarser_refinements = internal::integer_parameter(get_parameter(np, inp::coarser_refinements), d.coarser_refinements, "coarser_refinements");
  s.remove_isolated_points = choose_parameter(get_parameter(np, inp::remove_isolated_points), d.remove_isolated_points);
  s.merge_point_clusters = choose_parameter(get_parameter(np, inp::merge_point_clusters), d.merge_point_clusters);
  s.point_smoothing_iterations = internal::integer_parameter(get_parameter(np, inp::point_smoothing_iterations), d.point_smoothing_iterations, "point_smoothing_iterations");
  s.point_smoothing_neighbors = internal::integer_parameter(get_parameter(np, inp::point_smoothing_neighbors), d.point_smoothing_neighbors, "point_smoothing_neighbors");
  s.point_smoothing_noise = choose_parameter(get_parameter(np, inp::point_smoothing_noise), d.point_smoothing_noise);
  s.memory_limit = internal::integer_parameter(get_parameter(np, inp::memory_limit), d.memory_limit, "memory_limit");
  s.callback = choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  return s;
}

} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_SETTINGS_H
