// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_PARAMETERS_H
#define CGAL_ISM_RECONSTRUCTION_3_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

// The package's own named parameters. CGAL 5.5 has no supported way to add members to
// `Named_function_parameters` without editing its headers, so ours are free functions
// in `CGAL::parameters` that start a chain (`maximum_depth(12).point_map(pm)`) or wrap
// one (`maximum_depth(12, coplanarity_threshold(1e-3))`); CGAL's own parameters chain
// after them as usual.

namespace CGAL {
namespace ISM_reconstruction_3 {

/*!
  \ingroup PkgISMReconstruction3Ref
  \brief How the value at a vertex is estimated (its sign always comes from the Ising
  model); the named parameter `distance_estimate`.
*/
enum Distance_estimate
{
  /// the paper's: the squared distance to the nearest data point (section 4.3); the steps
  /// after the signs work on the distance, and the values are squared once F is final
  NEAREST_POINT_SQUARED_DISTANCE,
  /// the distance to the nearest data point
  NEAREST_POINT_DISTANCE,
  /// the distance to the plane fitted to the nearest data points, or to the rim of the patch
  /// they span in it where the vertex lies past it (default: linear interpolation along an
  /// edge then places the zero crossing on the fitted plane)
  LOCAL_PLANE_DISTANCE
};

namespace internal_np {

enum maximum_depth_t { maximum_depth };
enum coplanarity_threshold_t { coplanarity_threshold };
enum empty_cell_error_t { empty_cell_error };
enum initial_temperature_t { initial_temperature };
enum warm_start_temperature_t { warm_start_temperature };
enum cooling_factor_t { cooling_factor };
enum number_of_sweeps_t { number_of_sweeps };
enum warm_start_interval_t { warm_start_interval };
enum smoothing_iterations_t { smoothing_iterations };
enum crossing_neighbors_t { crossing_neighbors };
enum smoothing_lambda_t { smoothing_lambda };
enum smoothing_mu_t { smoothing_mu };
enum clamp_box_boundary_t { clamp_box_boundary };
enum distance_estimate_t { distance_estimate };
enum box_margin_t { box_margin };
enum paper_settings_t { paper_settings };
enum minimum_island_fraction_t { minimum_island_fraction };
enum thin_handle_depth_t { thin_handle_depth };
enum tangent_plane_signs_t { tangent_plane_signs };
enum surface_refinement_passes_t { surface_refinement_passes };
enum surface_refinement_tolerance_t { surface_refinement_tolerance };
enum point_smoothing_iterations_t { point_smoothing_iterations };
enum point_smoothing_neighbors_t { point_smoothing_neighbors };
enum point_smoothing_noise_t { point_smoothing_noise };
enum memory_limit_t { memory_limit };
enum escape_rays_t { escape_rays };
enum winding_number_signs_t { winding_number_signs };
enum join_islands_t { join_islands };
enum sparse_cell_planes_t { sparse_cell_planes };
enum coarser_refinements_t { coarser_refinements };
enum remove_isolated_points_t { remove_isolated_points };
enum merge_point_clusters_t { merge_point_clusters };

} // namespace internal_np
} // namespace ISM_reconstruction_3

namespace parameters {

#define CGAL_ISM_ADD_NAMED_PARAMETER(NAME)                                                          \
  template <typename K>                                                                            \
  Named_function_parameters<K, ISM_reconstruction_3::internal_np::NAME##_t> NAME(const K& k)       \
  {                                                                                                \
    return Named_function_parameters<K, ISM_reconstruction_3::internal_np::NAME##_t>(k);           \
  }                                                                                                \
  template <typename K, typename T, typename Tag, typename Base>                                    \
  Named_function_parameters<K, ISM_reconstruction_3::internal_np::NAME##_t,                        \
                            Named_function_parameters<T, Tag, Base> >                              \
  NAME(const K& k, const Named_function_parameters<T, Tag, Base>& np)                              \
  {                                                                                                \
    return Named_function_parameters<K, ISM_reconstruction_3::internal_np::NAME##_t,               \
                                     Named_function_parameters<T, Tag, Base> >(k, np);             \
  }

/// \cond SKIP_IN_MANUAL
CGAL_ISM_ADD_NAMED_PARAMETER(maximum_depth)
CGAL_ISM_ADD_NAMED_PARAMETER(coplanarity_threshold)
CGAL_ISM_ADD_NAMED_PARAMETER(empty_cell_error)
CGAL_ISM_ADD_NAMED_PARAMETER(initial_temperature)
CGAL_ISM_ADD_NAMED_PARAMETER(warm_start_temperature)
CGAL_ISM_ADD_NAMED_PARAMETER(cooling_factor)
CGAL_ISM_ADD_NAMED_PARAMETER(number_of_sweeps)
CGAL_ISM_ADD_NAMED_PARAMETER(warm_start_interval)
CGAL_ISM_ADD_NAMED_PARAMETER(smoothing_iterations)
CGAL_ISM_ADD_NAMED_PARAMETER(crossing_neighbors)
CGAL_ISM_ADD_NAMED_PARAMETER(smoothing_lambda)
CGAL_ISM_ADD_NAMED_PARAMETER(smoothing_mu)
CGAL_ISM_ADD_NAMED_PARAMETER(clamp_box_boundary)
CGAL_ISM_ADD_NAMED_PARAMETER(distance_estimate)
CGAL_ISM_ADD_NAMED_PARAMETER(box_margin)
CGAL_ISM_ADD_NAMED_PARAMETER(paper_settings)
CGAL_ISM_ADD_NAMED_PARAMETER(minimum_island_fraction)
CGAL_ISM_ADD_NAMED_PARAMETER(thin_handle_depth)
CGAL_ISM_ADD_NAMED_PARAMETER(tangent_plane_signs)
CGAL_ISM_ADD_NAMED_PARAMETER(surface_refinement_passes)
CGAL_ISM_ADD_NAMED_PARAMETER(surface_refinement_tolerance)
CGAL_ISM_ADD_NAMED_PARAMETER(point_smoothing_iterations)
CGAL_ISM_ADD_NAMED_PARAMETER(point_smoothing_neighbors)
CGAL_ISM_ADD_NAMED_PARAMETER(point_smoothing_noise)
CGAL_ISM_ADD_NAMED_PARAMETER(memory_limit)
CGAL_ISM_ADD_NAMED_PARAMETER(escape_rays)
CGAL_ISM_ADD_NAMED_PARAMETER(winding_number_signs)
CGAL_ISM_ADD_NAMED_PARAMETER(join_islands)
CGAL_ISM_ADD_NAMED_PARAMETER(sparse_cell_planes)
CGAL_ISM_ADD_NAMED_PARAMETER(coarser_refinements)
CGAL_ISM_ADD_NAMED_PARAMETER(remove_isolated_points)
CGAL_ISM_ADD_NAMED_PARAMETER(merge_point_clusters)
/// \endcond

#undef CGAL_ISM_ADD_NAMED_PARAMETER

} // namespace parameters
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_PARAMETERS_H
