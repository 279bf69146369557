// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_FUNCTION_H
#define CGAL_ISM_RECONSTRUCTION_FUNCTION_H

#include <CGAL/Bisection_triangulation_3.h>
#include <CGAL/ISM_reconstruction_3/internal/settings.h>
#include <CGAL/ISM_reconstruction_3/internal/Block_array.h>
#include <CGAL/ISM_reconstruction_3/internal/local_fitting.h>
#include <CGAL/ISM_reconstruction_3/internal/memory_budget.h>
#include <CGAL/ISM_reconstruction_3/internal/ising_annealing.h>
#include <CGAL/ISM_reconstruction_3/internal/point_input.h>
#include <CGAL/ISM_reconstruction_3/internal/distance_estimation.h>
#include <CGAL/ISM_reconstruction_3/internal/topology_estimation.h>
#include <CGAL/ISM_reconstruction_3/internal/handle_removal.h>
#include <CGAL/ISM_reconstruction_3/internal/normalization.h>
#include <CGAL/ISM_reconstruction_3/internal/island_joining.h>
#include <CGAL/ISM_reconstruction_3/internal/isolated_points.h>
#include <CGAL/ISM_reconstruction_3/internal/point_clusters.h>
#include <CGAL/ISM_reconstruction_3/internal/normal_orientation.h>
#include <CGAL/ISM_reconstruction_3/internal/leaf_vertices.h>
#include <CGAL/ISM_reconstruction_3/internal/marching_tetrahedra.h>
#include <CGAL/ISM_reconstruction_3/internal/tangent_plane_signs.h>
#include <CGAL/ISM_reconstruction_3/internal/surface_refinement.h>
#include <CGAL/ISM_reconstruction_3/internal/escape_rays.h>
#include <CGAL/ISM_reconstruction_3/internal/winding_number.h>
#include <CGAL/ISM_reconstruction_3/internal/point_smoothing.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <memory>
#ifdef CGAL_ISM_TIMER
#include <iostream>
// the time since the last mark, of the steps inside the stages (stderr)
#define CGAL_ISM_TIMER_MARK(timer, what) \
  (std::cerr << "  [ISM timer] " << (what) << ": " << (timer).time() << " s\n", (timer).reset())
#else
#define CGAL_ISM_TIMER_MARK(timer, what) ((void)0)
#endif
#include <queue>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {

/*!
\ingroup PkgISMReconstruction3Ref

\brief The implicit simplicial model (ISM) of a point set without normals: a binary
multitriangulation of a box around the points with an in/out sign and a signed distance
estimate at every vertex (paper section 4). `operator()(p)` is the piecewise linear
function of eq. (1) with the identity reparametrisation: negative inside, positive
outside, defined in the whole box.

\cgalModels `ImplicitFunction` (as `Poisson_reconstruction_function`): it can be meshed by
CGAL's surface mesher or Mesh_3 through `bounding_sphere()` and `get_inner_point()`.

Copies share the triangulation, as copies of `Poisson_reconstruction_function` do: it is
never modified once computed, and a new call of `compute_implicit_function()` builds a new
one, so the copies made before keep their function. A copy still duplicates the input points
and the per-vertex arrays (positions, signs, values: about 33 bytes per vertex).

\tparam GeomTraits a model of `ISMReconstructionTraits_3`; every \cgal `Kernel` is one.

\sa `ism_surface_reconstruction()`, which builds one and meshes it by marching tetrahedra
*/
template <class GeomTraits>
class ISM_reconstruction_function
{
public:
  /// \name Types
  /// @{
  /*! the geometric traits class */
  typedef GeomTraits Geom_traits;
  /// the number type
  typedef typename Geom_traits::FT FT;
  /// the point type
  typedef typename Geom_traits::Point_3 Point;
  /// the vector type
  typedef typename Geom_traits::Vector_3 Vector;
  /// the sphere type, of `bounding_sphere()`
  typedef typename Geom_traits::Sphere_3 Sphere;
  /// the binary multitriangulation holding the function
  typedef Bisection_triangulation_3<Geom_traits> Triangulation;
  /// index of a cell of the triangulation
  typedef typename Triangulation::Cell_index Cell_index;
  /// index of a vertex of the triangulation
  typedef typename Triangulation::Vertex_index Vertex_index;
  /// all parameters of the method, with their defaults
  typedef ISM_reconstruction_3::Settings Settings;

  /// What a run measured: the time of each stage (seconds) and the sizes reached.
  /// `refinement_time`, `topology_time` (all annealing passes), `distance_time`;
  /// `number_of_points`, `number_of_leaves`, `number_of_vertices`, `deepest_level` of the
  /// final triangulation; `number_of_topology_passes`, `number_of_inside_vertices`,
  /// `number_of_flipped_islands` (see the named parameter `minimum_island_fraction`),
  /// `number_of_handle_vertices`, the vertices that changed side to remove thin handles
  /// (see `thin_handle_depth`); `number_of_tangent_plane_vertices`, the vertices whose side
  /// the oriented tangent planes of the points changed (see `tangent_plane_signs`);
  /// `number_of_misfit_leaves`, the leaves bisected because F missed their points or, where
  /// the points are sparser, because the surface crosses them (see
  /// `surface_refinement_passes`); `number_of_escaped_vertices`, the inside vertices turned
  /// outside because rays from them leave the box (see `escape_rays`); `number_of_joined_islands`,
  /// the inside clusters joined to another (see `join_islands`); `neighborhood_coplanarity`, the noise measure of
  /// `point_smoothing_noise`, and `number_of_point_smoothing_passes`; the refinement time
  /// includes the point smoothing;
  /// `final_energy`, the Ising energy of the signs found, and `all_outside_energy`, that of
  /// the all-outside labelling.
  struct Statistics
  {
    double refinement_time = 0, topology_time = 0, distance_time = 0;
    std::size_t number_of_points = 0, number_of_leaves = 0, number_of_vertices = 0;
    /// points taken away by replacing clusters of copies with their centroids (`merge_point_clusters`)
    std::size_t number_of_merged_points = 0;
    std::size_t number_of_isolated_points = 0;  ///< points left out: their 12 nearest points spread more than 20 times farther than the median point's (stray returns far from the surface)
    /// points in a leaf none of whose vertices is a vertex of a leaf the surface crosses: the
    /// surface does not reach them. A few are outliers (1 % outliers in the bunny's box: 0.7 %
    /// of the points); many mean parts thinner than about two point spacings, whose two sides
    /// no cell fits between (random points on an ellipsoid of axes 1, 1, 0.01: 58 %)
    std::size_t number_of_points_off_surface = 0;
    std::size_t number_of_topology_passes = 0, number_of_inside_vertices = 0, number_of_flipped_islands = 0;
    std::size_t number_of_handle_vertices = 0;
    /// inside vertices of the Ising signs (after the island removal), before the points'
    /// tangent planes and the later steps: 0 means the model found no inside region (cells
    /// too coarse for the points, e.g. a sphere of 300 random points: its centre outside, the
    /// surface then comes from the tangent planes alone and fell into 3-8 parts on 8 of 10,
    /// before `coarser_refinements`)
    std::size_t number_of_ising_inside_vertices = 0;
    /// times the computation was redone with twice `min_points_per_cell` because the later
    /// steps left no inside, or more inside clusters than the Ising signs had inside vertices
    /// (`coarser_refinements`); the statistics are those of the last computation, and
    /// `settings()` holds the `min_points_per_cell` it used
    std::size_t number_of_coarser_refinements = 0;
    std::size_t number_of_tangent_plane_vertices = 0;  ///< vertices whose side the oriented tangent planes changed
    std::size_t number_of_misfit_leaves = 0;  ///< leaves bisected by `surface_refinement_passes`
    std::size_t number_of_winding_number_vertices = 0;  ///< vertices re-signed by the winding number of the points (`winding_number_signs`)
    std::size_t number_of_escaped_vertices = 0;  ///< inside vertices turned outside because rays from them leave the box (`escape_rays`)
    std::size_t number_of_joined_islands = 0;  ///< inside clusters joined to another across one or two vertices (`join_islands`)
    std::size_t number_of_boundary_vertices_set_outside = 0;  ///< box boundary vertices left inside by the last annealing, set outside (only unclamped: `clamp_box_boundary(false)`)
    double neighborhood_coplanarity = 0;  ///< median coplanarity error of the points' 12 nearest points, the noise (`point_smoothing_noise`)
    std::size_t number_of_point_smoothing_passes = 0;  ///< jet-smoothing passes over the points (`point_smoothing_iterations`)
    unsigned int number_of_point_smoothing_neighbors = 0;  ///< the nearest points each jet fit took: `point_smoothing_neighbors`, more where the points are dense for their noise
    int deepest_level = 0;
    /// levels added to `maximum_depth` (up to 48) because far outliers or parts far apart make
    /// the points' extent 2^(n/3) times that of their bulk (98 % of them, or their largest group)
    int added_levels = 0;
    double final_energy = 0, all_outside_energy = 0;  ///< Ising energies; all-outside lower means the model failed
  };
  /// @}

private:
  typedef std::array<double, 3> Xyz;
  typedef ISM_reconstruction_3::internal::Leaf_vertices<Triangulation> Leaf_vertices;
  Geom_traits m_gt;
  std::vector<Xyz> m_points;
  std::vector<Xyz> m_given_points;  // the points before a merging of clusters, the removal of isolated points or a smoothing changed m_points
  bool m_shape_unchecked = false;   // on a line or a plane but for far points (check_point_set())
  // the k nearest points of m_points, from the noise measure to the end of the distance stage
  // (shared, as m_tr, so that the function stays copyable)
  std::shared_ptr<const ISM_reconstruction_3::internal::Point_neighbors> m_point_neighbors;
  Settings m_settings;
  // shared by copies, as in Poisson_reconstruction_function, so that the function can be
  // passed by value (CGAL's Implicit_surface_3 stores a copy); never modified after
  // compute_implicit_function(), which builds a new one
  std::shared_ptr<Triangulation> m_tr;
  std::vector<signed char> m_sign;
  std::vector<double> m_value;
  std::vector<Xyz> m_vertex_xyz;  // double copy of the triangulation's points
  Statistics m_stats;
  Point m_inner_point;
  Sphere m_bounding_sphere;
  // set last: a run that threw after the values were filled (no inside vertex) or was
  // cancelled at its end has values but no function
  bool m_completed = false;

public:
  /// \name Creation
  /// @{

  /*!
    Copies the points of `points` (through the `point_map` named parameter).
    \throws std::invalid_argument if the range is empty, holds a NaN or infinite
    coordinate, spans more than 1e32 or less than 1e-32 (the largest side of the points'
    bounding box: some sizes are held in single precision; scale such points, and the result
    back), has fewer distinct points than a cell needs, or all its points lie on a plane or a
    line (no closed surface can be reconstructed from them), unless a few far points alone
    make them so (then `compute_implicit_function()` decides, once the isolated points are
    left out).
    \throws std::length_error if the copy of the points would not fit in memory (see the named
    parameter `memory_limit`)
  */
  template <class PointRange, class NamedParameters = parameters::Default_named_parameters>
  explicit ISM_reconstruction_function(const PointRange& points,
                                       const NamedParameters& np = parameters::default_values())
  {
    typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
    typename NP_helper::Const_point_map point_map = NP_helper::get_const_point_map(points, np);
    m_gt = parameters::choose_parameter<Geom_traits>(parameters::get_parameter(np, internal_np::geom_traits));
    // a range need not have size() (std::forward_list, boost's filtered ranges)
    const std::size_t count = std::size_t(std::distance(points.begin(), points.end()));
    ISM_reconstruction_3::internal::Memory_guard::check_point_copy(
        parameters::choose_parameter(parameters::get_parameter(np, ISM_reconstruction_3::internal_np::memory_limit), std::size_t(0)),
        count);
    m_points.reserve(count);
    for(const auto& item : points)
    {
      const auto& p = get(point_map, item);
      m_points.push_back({{ to_double(p.x()), to_double(p.y()), to_double(p.z()) }});
    }
    m_shape_unchecked = ISM_reconstruction_3::internal::check_point_set(m_points, true);
    // Exact duplicates carry no information, and many copies of one point would keep a cell
    // above the minimum count at every level (and degenerate the kd-tree): keep one of each.
    std::sort(m_points.begin(), m_points.end());
    m_points.erase(std::unique(m_points.begin(), m_points.end()), m_points.end());
    m_stats.number_of_points = m_points.size();
  }
  /// @}

  /*!
    Runs the method: refinement with local fitting, topology estimation (Ising model by
    simulated annealing), distance estimation. Named parameters: see
    `ism_surface_reconstruction()`.
    \return `false` if the `callback` cancelled the run.
    \throws std::invalid_argument for a parameter out of range, or points that lie on a line
    or a plane but for a few far points that are not isolated (or kept: `remove_isolated_points(false)`)
    \throws std::runtime_error if 99 % of the points lie within half their spacing of a plane
    (an open sheet), no inside region was found, or far outliers make the box too large for
    the bulk of the points to be resolved
    \throws std::length_error, before the allocation, if the points or the refinement would
    need more memory than the process may use (see the named parameter `memory_limit`)
  */
  template <class NamedParameters = parameters::Default_named_parameters>
  bool compute_implicit_function(const NamedParameters& np = parameters::default_values())
  {
    return compute_implicit_function_with_settings(ISM_reconstruction_3::settings_from_parameters(np));
  }

  /// the same, from a `Settings` object
  bool compute_implicit_function_with_settings(const Settings& settings)
  {
    settings.check();
    // Why: the stop test counts points, not lengths, so few points (a sphere of 150 to 400
    // random points) are refined to leaves of 6 points as long as the sphere is thick. The
    // Ising signs then found no inside, or a vertex or two, on most such samplings, and the
    // tangent planes made the inside in 2 to 10 pieces. Leaves of 12 or 24 points keep
    // vertices deep inside whose edges cross the surface. Redone only when the steps after
    // the Ising signs leave no inside, or more inside clusters than the signs had inside
    // vertices: two small objects, one inside vertex each, are not.
    // A coarser result whose surface lies more than 3 times farther from the points (the
    // median) than the finer one's lost the surface, and the finer one is computed again: two
    // spheres of 100 points, one radius apart, came out as one blob in the gap between them on
    // 10 of 10 samplings (4 of 10 now in 2 parts; 2 times instead of 3 lost 8 of 60 single
    // spheres).
    Settings s = settings;
    double miss = 0;
    for(std::size_t coarser = 0;; ++coarser)
    {
      const bool may_coarsen = coarser < std::size_t(settings.coarser_refinements) &&
                               std::size_t(s.min_points_per_cell) < number_of_given_points();
      Outcome outcome = DONE;
      if(!compute_once(s, may_coarsen, coarser > 0 ? 3 * miss : 0., miss, outcome)) return false;
      if(outcome == WORSE)
      {
        s.min_points_per_cell /= 2;
        if(!compute_once(s, false, 0., miss, outcome)) return false;
        m_stats.number_of_coarser_refinements = coarser - 1;
        return true;
      }
      m_stats.number_of_coarser_refinements = coarser;
      if(outcome == DONE) return true;
      s.min_points_per_cell *= 2;
    }
  }

private:
  // the input's size (a computation may have left isolated points out of m_points)
  std::size_t number_of_given_points() const { return m_given_points.empty() ? m_points.size() : m_given_points.size(); }

  enum Outcome { DONE, COARSER_NEEDED, WORSE };

  // One computation with `settings`. If `may_coarsen`, one that would need coarser leaves
  // stops after the signs, COARSER_NEEDED (`miss`: the median distance from the points to
  // its surface); if `max_miss` > 0, one with no inside or a larger median miss stops there,
  // WORSE.
  bool compute_once(const Settings& settings, bool may_coarsen, double max_miss, double& miss, Outcome& outcome)
  {
    m_completed = false;
    m_settings = settings;
    m_stats = Statistics{};
    m_value.clear();  // operator() is then +1 until this computation completes
    m_voting_normals.clear();
    m_vouched_depth.clear();
    m_depth.clear();
    m_voting_radius.clear();
    m_point_neighbors.reset();  // of the points of a previous computation
    if(!m_given_points.empty())  // a previous computation removed or smoothed some
    {
      m_points.swap(m_given_points);
      std::vector<Xyz>().swap(m_given_points);
    }
    m_stats.number_of_points = m_points.size();
    CGAL::Real_timer timer;
    timer.start();
    if(m_settings.merge_point_clusters) merge_point_clusters();
    if(m_settings.remove_isolated_points) remove_isolated_points();
    // a line or a plane but for far points that are still there (else checked on removal)
    if(m_shape_unchecked && m_given_points.empty())
      ISM_reconstruction_3::internal::check_point_set(m_points);
    // one tree of the points for the sheet test, the noise measure and the smoothing
    if(!m_point_neighbors) m_point_neighbors.reset(new ISM_reconstruction_3::internal::Point_neighbors(m_points));
    ISM_reconstruction_3::internal::check_not_a_sheet(m_points, *m_point_neighbors);
    smooth_noisy_points();
    if(!refine())
      return false;
    m_stats.refinement_time = timer.time() - m_stats.topology_time;
    if(!report(0.75)) return false;

    timer.reset();
    ISM_reconstruction_3::internal::Annealing_schedule final_schedule;
    // after passes during refinement the final one refines their answer, "with a more
    // gradual decrease in temperature" (paper 4.4); from scratch it starts hot
    final_schedule.initial_temperature = m_stats.number_of_topology_passes > 0 ? m_settings.warm_start_temperature
                                                                                : m_settings.initial_temperature;
    final_schedule.number_of_sweeps = m_settings.number_of_sweeps;
    // a fast or long cooling underflows to 0 (0.977^99,999), which the annealing's
    // precondition refuses; the smallest normal double is zero temperature all the same
    final_schedule.final_temperature =
        (std::max)(final_schedule.initial_temperature * std::pow(m_settings.cooling_factor, m_settings.number_of_sweeps - 1),
                   (std::numeric_limits<double>::min)());
    estimate_topology(final_schedule, true);
    // the triangulation is final (up to the surface refinement, which updates them): its box
    // boundary and its leaves serve the islands and the handles
    std::vector<char> boundary = ISM_reconstruction_3::internal::box_boundary_vertices(*m_tr);
    ISM_reconstruction_3::internal::Leaf_vertices<Triangulation> leaves(*m_tr);
    if(m_settings.minimum_island_fraction > 0)
      m_stats.number_of_flipped_islands =
          ISM_reconstruction_3::internal::remove_islands(leaves, m_sign, boundary, m_settings.minimum_island_fraction);
    m_stats.number_of_inside_vertices = std::size_t(std::count(m_sign.begin(), m_sign.end(), -1));
    m_stats.number_of_ising_inside_vertices = m_stats.number_of_inside_vertices;
    m_stats.topology_time += timer.time();
    if(!report(0.9)) return false;

    timer.reset();
#ifdef CGAL_ISM_TIMER
    CGAL::Real_timer step;
    step.start();
#endif
    const std::vector<char> near_surface = ISM_reconstruction_3::internal::crossed_leaf_vertices(leaves, m_sign);
    // one kd-tree of the points serves the distances and the tangent planes
    if(!m_point_neighbors) m_point_neighbors.reset(new ISM_reconstruction_3::internal::Point_neighbors(m_points));
    const ISM_reconstruction_3::internal::Point_neighbors& neighbors = *m_point_neighbors;
    CGAL_ISM_TIMER_MARK(step, "kd-tree");
    m_value = ISM_reconstruction_3::internal::estimate_distances(m_points, neighbors, m_vertex_xyz, m_sign,
                                                                  working_estimate(), near_surface);
    CGAL_ISM_TIMER_MARK(step, "distances");
    if(m_settings.thin_handle_depth > 0) remove_thin_handles(leaves, boundary, m_value);
    CGAL_ISM_TIMER_MARK(step, "thin handles");
    if(m_settings.tangent_plane_signs) sign_by_tangent_planes(leaves, boundary, neighbors);
    CGAL_ISM_TIMER_MARK(step, "tangent planes");
    if(m_settings.surface_refinement_passes > 0) refine_surface_leaves(neighbors, boundary, leaves);
    CGAL_ISM_TIMER_MARK(step, "surface refinement");
    if(m_settings.escape_rays > 0) remove_escaping_inside(neighbors, leaves, boundary);
    CGAL_ISM_TIMER_MARK(step, "escape rays");
    if(m_settings.winding_number_signs) sign_by_winding_number(neighbors, leaves, boundary);
    std::vector<std::array<float, 3> >().swap(m_voting_normals);
    std::vector<float>().swap(m_vouched_depth);
    std::vector<double>().swap(m_depth);
    std::vector<float>().swap(m_voting_radius);
    CGAL_ISM_TIMER_MARK(step, "winding number");
    // after the arrays above are freed: with several inside clusters the joining holds about
    // 50 bytes a vertex
    if(m_settings.join_islands)
    {
      m_stats.number_of_joined_islands = ISM_reconstruction_3::internal::join_islands(
          leaves, m_vertex_xyz, boundary, m_sign, m_value, 1e-9 * std::sqrt(to_double(m_bounding_sphere.squared_radius())),
          [&](const Xyz& x) { return among_points(neighbors, x); });
      m_stats.number_of_inside_vertices = std::size_t(std::count(m_sign.begin(), m_sign.end(), -1));
    }
    m_stats.number_of_points_off_surface = count_points_off_surface(leaves);
    std::vector<Cell_index>().swap(m_leaf_of_point);
    m_point_neighbors.reset();
    // no inside at all (find_inner_point() would refuse it), or pieces the signs did not see
    // (the distance from the points to the surface only where a retry needs it: it builds a
    // kd-tree of the crossings, and every input's first computation may coarsen). The pieces
    // are counted as they were before the joining (one fewer per join): on random spheres of
    // 400-500 points the tangent planes had made a shell of 3 to 6 inside pieces around an
    // Ising inside of 1 to 4 vertices, the joining made it one, and the surface came out
    // hollow, its centre outside (5 of 30 samplings at 500 points, 2 at 400; now 0 and 1,
    // and 0 and 0 with the next rule)
    if(may_coarsen || max_miss > 0)
    {
      const std::size_t inside_clusters = ISM_reconstruction_3::internal::number_of_inside_clusters(leaves, m_sign);
      const bool coarser_needed =
          may_coarsen && (inside_clusters == 0 ||
                          inside_clusters + m_stats.number_of_joined_islands > m_stats.number_of_ising_inside_vertices);
      if(coarser_needed || max_miss > 0)
        miss = inside_clusters == 0 ? HUGE_VAL
                                    : ISM_reconstruction_3::internal::median_distance_to_crossings(
                                          m_points, m_vertex_xyz, leaves.cells(), m_value);
      // a result that needs coarser leaves itself is no candidate to go back from: random
      // spheres of 400-500 points whose leaves of 12 points saw no inside either, and lay
      // farther from the points than 3 times the leaves of 6, went back to those, a
      // tangent-plane shell hugging the points (3 of 40 samplings; now 0, and 0 of 270 of an
      // independent test's instead of 1; two spheres of 100-200 points, one radius apart, 2
      // parts on 22 of 130 samplings instead of 26: most come out as one blob either way)
      if(coarser_needed)
      {
        outcome = COARSER_NEEDED;
        return true;
      }
      if(max_miss > 0 && !(miss <= max_miss))
      {
        outcome = WORSE;
        return true;
      }
    }
    CGAL_ISM_TIMER_MARK(step, "joined islands");
    square_values();
    m_stats.distance_time = timer.time();
    find_inner_point();
    if(!report(1.)) return false;
    m_completed = true;
    return true;
  }

public:
  /// \name Evaluation
  /// @{

  /// F(p) by linear interpolation in the leaf holding `p`; outside the box, a positive value;
  /// `+1` everywhere before `compute_implicit_function()` completed.
  FT operator()(const Point& p) const
  {
    // no function yet, or its computation was cancelled or threw: outside everywhere
    if(!is_computed()) return FT(1);
    return value_at(p);
  }

  /// F(p), locating `p` by a walk across the leaves from the leaf `hint`
  /// (`Triangulation::locate(p, hint)`), which then holds `p`'s leaf: evaluating F at
  /// nearby points this way skips the descent of the cell tree.
  FT operator()(const Point& p, Cell_index& hint) const
  {
    if(!is_computed()) return FT(1);
    return value_at(p, hint);
  }

  /// a sphere holding the points, inside which the function is meant to be meshed
  Sphere bounding_sphere() const { return m_bounding_sphere; }
  /// `true` once `compute_implicit_function()` completed (it was called, and neither
  /// cancelled nor thrown): only then are there values, an inner point and a surface
  bool is_computed() const { return m_completed; }
  /*! a point where the function is negative (the deepest inside vertex)
      \throws std::logic_error if `compute_implicit_function()` was not called or did not
      complete (cancelled, or threw): there is no such point then */
  const Point& get_inner_point() const
  {
    if(!is_computed())
      throw std::logic_error("ISM_reconstruction_function: get_inner_point() needs a completed compute_implicit_function()");
    return m_inner_point;
  }
  /// @}

  /// \name Access
  /// @{
  /*! the binary multitriangulation: its leaves carry the function
      \throws std::logic_error if `compute_implicit_function()` was not called */
  const Triangulation& triangulation() const
  {
    if(!m_tr) throw std::logic_error("ISM_reconstruction_function: compute_implicit_function() was not called");
    return *m_tr;
  }
  /// the in/out sign of a vertex: -1 inside, +1 outside
  int sign(Vertex_index v) const { return m_sign[v]; }
  /// the value f(v) of a vertex: its sign times the estimated distance
  double value(Vertex_index v) const { return m_value[v]; }
  /// the signs of all vertices, indexed by vertex
  const std::vector<signed char>& signs() const { return m_sign; }
  /// the values of all vertices, indexed by vertex
  const std::vector<double>& values() const { return m_value; }
  /// what the last run measured
  const Statistics& statistics() const { return m_stats; }
  /// the parameters of the last run
  const Settings& settings() const { return m_settings; }
  /// the input points (as doubles, sorted, exact duplicates removed) as the last computation
  /// used them: clusters of copies merged (`merge_point_clusters`), isolated points left out
  /// (`remove_isolated_points`), smoothed if it found them noisy (`point_smoothing_iterations`)
  const std::vector<std::array<double, 3> >& input_points() const { return m_points; }
  /// @}

private:
  bool report(double progress) const { return !m_settings.callback || m_settings.callback(progress); }

  // Isolated points (isolated_points.h) are left out of the whole computation, the points as
  // given kept for the next one. Each stage took them for the surface: 200 stray points
  // spread 1-2 diagonals around a scanned bunny, fitted in large cells and given large discs
  // by the winding number, made a shell that held the bunny's outside inside, and the output
  // was their hull.
  void remove_isolated_points()
  {
    namespace I = ISM_reconstruction_3::internal;
    if(!m_point_neighbors) m_point_neighbors.reset(new I::Point_neighbors(m_points));
    const std::vector<char> isolated = I::isolated_points(m_points, *m_point_neighbors);
    m_stats.number_of_isolated_points = std::size_t(std::count(isolated.begin(), isolated.end(), 1));
    if(m_stats.number_of_isolated_points == 0) return;  // the tree serves the next stages
    if(m_given_points.empty()) m_given_points = m_points;
    std::size_t kept = 0;
    for(std::size_t i = 0; i < m_points.size(); ++i)
      if(!isolated[i]) m_points[kept++] = m_points[i];
    m_points.resize(kept);
    check_points_left(std::to_string(m_stats.number_of_isolated_points) +
                      " isolated points are left out (remove_isolated_points(false) keeps them)");
  }

  // point_clusters.h says why
  void merge_point_clusters()
  {
    namespace I = ISM_reconstruction_3::internal;
    m_point_neighbors.reset(new I::Point_neighbors(m_points));
    std::vector<Xyz> merged = I::merged_point_clusters(m_points, *m_point_neighbors);
    if(merged.empty()) return;  // the tree serves the next stages
    m_stats.number_of_merged_points = m_points.size() - merged.size();
    m_given_points.swap(m_points);
    m_points.swap(merged);
    check_points_left("clusters of copies are merged into " + std::to_string(m_points.size()) +
                      " points (merge_point_clusters(false) keeps them)");
  }

  // After points were left out or merged, what is left must still bound a volume (a dense
  // line among sparse points would not); the tree of the points is built again.
  void check_points_left(const std::string& what)
  {
    try
    {
      ISM_reconstruction_3::internal::check_point_set(m_points);
    }
    catch(const std::invalid_argument& e)
    {
      throw std::runtime_error(std::string(e.what()) + ", once the " + what);
    }
    m_point_neighbors.reset(new ISM_reconstruction_3::internal::Point_neighbors(m_points));
  }

  // Noisy points tilt the planes of the small cells (point_smoothing.h says why): they are
  // jet-smoothed before the refinement, the points as given kept for the next computation.
  void smooth_noisy_points()
  {
    namespace I = ISM_reconstruction_3::internal;
    // 20,000 neighbourhoods measure the median well and cost 20 ms; measured also without
    // smoothing, since the thin-handle removal asks whether the points are noisy
    m_stats.neighborhood_coplanarity =
        I::median_neighborhood_coplanarity(m_points, *m_point_neighbors, 12, m_points.size() / 20000);
    if(m_settings.point_smoothing_iterations == 0 ||
       (m_settings.point_smoothing_noise > 0 && !(m_stats.neighborhood_coplanarity > m_settings.point_smoothing_noise)))
      return;  // the tree then serves the distance stage
    if(m_given_points.empty()) m_given_points = m_points;
    const I::Jet_smoothing_plan plan = I::jet_smoothing_plan(
        m_points, *m_point_neighbors, unsigned(m_settings.point_smoothing_neighbors), m_points.size() / 2000);
    m_stats.number_of_point_smoothing_neighbors = plan.neighbors;
    const int passes = plan.dense_for_noise ? m_settings.point_smoothing_iterations : 1;
    for(int pass = 0; pass < passes; ++pass)
    {
      if(pass > 0) m_point_neighbors.reset(new I::Point_neighbors(m_points));
      m_points = I::jet_smoothed(m_points, *m_point_neighbors, m_stats.number_of_point_smoothing_neighbors);
      ++m_stats.number_of_point_smoothing_passes;
    }
    m_point_neighbors.reset();  // of the points before the last pass
  }

  // --- refinement (paper Program 1): a priority queue of cells by coplanarity error
  bool refine()
  {
    namespace I = ISM_reconstruction_3::internal;
    // the sparse cells' planes; the same tree then serves the distances
    if(m_settings.sparse_cell_planes && !m_point_neighbors) m_point_neighbors.reset(new I::Point_neighbors(m_points));
    const I::Oriented_box box = I::bounding_parallelepiped(m_points, m_settings.box_margin);
    // far outliers not isolated (a group of them) or parts far apart widen the box: the
    // levels they cost are given back, so that the bulk is not left 150 vertices. Beyond the
    // deepest level they cannot all be: with 10 points far from the 36k bunny (before
    // isolated points were left out), 6 levels short (leaves 4 times as long near the bulk)
    // it came out right, 9 short as 5,148 output vertices instead of 21,565, 12 short as a
    // blob of 574. Refused, with the ways out.
    const double extent_ratio = I::extent_over_bulk_extent(m_points);
    const int wanted_levels = I::far_outlier_levels(extent_ratio);
    const int free_levels = Settings::deepest_level - m_settings.maximum_depth;
    if(wanted_levels > free_levels + 6)
      throw std::runtime_error("ISM reconstruction: far outliers or parts far apart make the box too large for the "
                               "bulk of the points to be resolved (it would need " + std::to_string(wanted_levels) +
                               " levels more than maximum_depth " + std::to_string(m_settings.maximum_depth) +
                               ", and the deepest level is " + std::to_string(Settings::deepest_level) +
                               "): remove the far outliers first (e.g. CGAL::remove_outliers()), reconstruct parts "
                               "far apart one by one, or lower maximum_depth");
    m_stats.added_levels = (std::min)(wanted_levels, free_levels);
    m_tr.reset(new Triangulation(Point(box.origin[0], box.origin[1], box.origin[2]),
                                 Vector(box.axis[0][0], box.axis[0][1], box.axis[0][2]),
                                 Vector(box.axis[1][0], box.axis[1][1], box.axis[1][2]),
                                 Vector(box.axis[2][0], box.axis[2][1], box.axis[2][2]), m_gt));
    m_bounding_sphere = Sphere(Point(box.data_center[0], box.data_center[1], box.data_center[2]),
                               FT(box.data_radius * box.data_radius * 1.1025));
    Triangulation& tr = *m_tr;
    m_vertex_xyz.clear();  // those of a previous computation belong to its triangulation
    sync_vertices();
    m_sign.assign(tr.number_of_vertices(), 1);

    // refuses, before allocating it, what would not fit in memory: up front from the number
    // of points, then whenever the number of cells grew by 1/8 (memory_budget.h, issue 8)
    I::Memory_guard memory_guard(m_settings.memory_limit, m_points.size(), m_settings.maximum_depth);
    // each cell owns the contiguous range [m_range[c][0], m_range[c][1]) of m_cell_points
    m_cell_points.clear();
    m_cell_points.reserve(m_points.size());
    m_cell_point_index.clear();
    m_cell_point_index.reserve(m_points.size());
    m_range.assign(6, {{0, 0}});
    m_fit.assign(6, I::Plane_fit());
    {
      std::vector<std::vector<std::uint32_t> > by_root(6);
      for(std::uint32_t i = 0; i < m_points.size(); ++i)
      {
        const Cell_index r = tr.locate_root(point_of(i));
        by_root[r < 0 ? 0 : r].push_back(i);  // r < 0 cannot happen: the box holds every point
      }
      for(int r = 0; r < 6; ++r)
      {
        m_range[r][0] = std::uint32_t(m_cell_points.size());
        for(std::uint32_t i : by_root[r])
        {
          m_cell_points.push_back(m_points[i]);
          m_cell_point_index.push_back(i);
        }
        m_range[r][1] = std::uint32_t(m_cell_points.size());
      }
    }
    for(Cell_index r = 0; r < 6; ++r) fit(r, -1);

    typedef std::pair<double, Cell_index> Entry;  // max-heap on eps; ties by index for determinism
    std::priority_queue<Entry> queue;
    // A cell that meets a stop test when it is made meets it for good (its level, points and
    // fit never change): left out of the queue, which then pops the others in the same
    // order. (Most cells are such leaves; the heap operations on them were 40 % of the
    // refinement's own time on the dragon.)
    auto enqueue = [&](Cell_index c) {
      if(!stop(c)) queue.push(Entry(m_fit[c].coplanarity_error, c));
    };
    for(Cell_index r = 0; r < 6; ++r) enqueue(r);

    long since_topology = 0;
    std::size_t leaves_at_last_topology = tr.number_of_leaves();
    ISM_reconstruction_3::internal::Annealing_schedule warm;
    warm.initial_temperature = m_settings.warm_start_temperature;
    warm.final_temperature = 0.3;
    warm.number_of_sweeps = 30;
    const std::size_t report_every = 4096;
    std::size_t bisections = 0;

    auto on_bisect = [&](Cell_index p, Cell_index c0, Cell_index c1) {
      if(m_range.size() < tr.number_of_cells())
      {
        m_range.resize(tr.number_of_cells());
        m_fit.resize(tr.number_of_cells());
      }
      const std::uint32_t m = partition_cell_points(
          m_range[p][0], m_range[p][1], [&](const Xyz& x) { return tr.child_side(p, Point(x[0], x[1], x[2])) == 0; });
      m_range[c0] = {{ m_range[p][0], m }};
      m_range[c1] = {{ m, m_range[p][1] }};
      fit(c0, p);
      fit(c1, p);
      // the new midpoint takes a sign from its edge: the endpoints' if they agree,
      // else the one on its side of the parent's plane (a warm start for annealing)
      const int k = Triangulation::refinement_index(tr.level(p));
      const Vertex_index z = tr.vertex(c0, k);
      if(std::size_t(z) >= m_sign.size())
      {
        sync_vertices();
        const Vertex_index a = tr.vertex(p, 0), bb = tr.vertex(p, k);
        signed char s = m_sign[a];
        if(m_sign[a] != m_sign[bb] && count(p) > 0)
          s = m_fit[p].side(m_vertex_xyz[z]) == m_fit[p].side(m_vertex_xyz[a]) ? m_sign[a] : m_sign[bb];
        m_sign.resize(tr.number_of_vertices(), s);
      }
      enqueue(c0);
      enqueue(c1);
      ++since_topology;
      ++bisections;
    };

    while(!queue.empty())
    {
      const Cell_index c = queue.top().second;
      queue.pop();
      if(!tr.is_leaf(c))  // bisected since, to keep the triangulation conforming
        continue;
      tr.bisect(c, on_bisect);
      memory_guard.check(tr.number_of_cells());
      // topology during refinement (the paper's multigrid): every k bisections, or
      // whenever the number of leaves doubled (default). The first pass anneals from the
      // full temperature; later ones start cold from the previous signs. Measured on
      // bunny00 (36k points, 3 samplings): 200 sweeps from a cold start got stuck in 1 of 3
      // (9 components), the warm-started passes never did.
      const long k = m_settings.warm_start_interval;
      if((k > 0 && since_topology >= k) || (k == 0 && tr.number_of_leaves() >= 2 * leaves_at_last_topology))
      {
        CGAL::Real_timer t;
        t.start();
        if(m_stats.number_of_topology_passes == 0)
        {
          ISM_reconstruction_3::internal::Annealing_schedule first;
          first.initial_temperature = m_settings.initial_temperature;
          estimate_topology(first);
        }
        else
          estimate_topology(warm);
        m_stats.topology_time += t.time();
        since_topology = 0;
        leaves_at_last_topology = tr.number_of_leaves();
      }
      if(bisections >= report_every)
      {
        bisections = 0;
        // progress: a rough guess from the number of leaves relative to the points
        const double guess = double(tr.number_of_leaves()) / double(4 * m_points.size() + 64);
        if(!report(0.7 * (std::min)(1., guess))) return false;
      }
    }
    // the leaf of each point, for the point location of the distance stage (a descent of
    // 24 levels per point, 0.5 s of CPU on the dragon, with a walk)
    m_leaf_of_point.assign(m_points.size(), -1);
    for(Cell_index c = 0; c < Cell_index(tr.number_of_cells()); ++c)
      if(tr.is_leaf(c))
        for(std::uint32_t i = m_range[c][0]; i < m_range[c][1]; ++i) m_leaf_of_point[m_cell_point_index[i]] = c;
    std::vector<Xyz>().swap(m_cell_points);
    std::vector<std::uint32_t>().swap(m_cell_point_index);
    return true;
  }

  // Moves the cell points in [b, e) for which `first_child` holds before the others, with
  // their indices; returns the end of the first ones. The swaps of libstdc++'s
  // std::partition, so that the points of each cell, and the sums of their fits, keep the
  // order they had before the indices moved along.
  template <class Predicate>
  std::uint32_t partition_cell_points(std::uint32_t b, std::uint32_t e, const Predicate& first_child)
  {
    for(;;)
    {
      while(b != e && first_child(m_cell_points[b])) ++b;
      if(b == e) return b;
      --e;
      while(b != e && !first_child(m_cell_points[e])) --e;
      if(b == e) return b;
      std::swap(m_cell_points[b], m_cell_points[e]);
      std::swap(m_cell_point_index[b], m_cell_point_index[e]);
      ++b;
    }
  }

  // The points in a leaf none of whose vertices is on a leaf the surface crosses (one leaf
  // of slack: noise puts points a little off the surface, in the leaf next to it).
  std::size_t count_points_off_surface(const Leaf_vertices& leaves) const
  {
    const std::vector<char> on_surface = ISM_reconstruction_3::internal::crossed_leaf_vertices(leaves, m_sign);
    std::size_t off = 0;
    for(std::uint32_t i = 0; i < m_points.size(); ++i)
    {
      const auto& v = m_tr->vertices(leaf_of_point(i));
      off += !(on_surface[v[0]] || on_surface[v[1]] || on_surface[v[2]] || on_surface[v[3]]);
    }
    return off;
  }

  // The leaf holding m_points[i] (below the one of the refinement if the surface
  // refinement bisected it since).
  Cell_index leaf_of_point(std::uint32_t i) const
  {
    Cell_index c = m_leaf_of_point[i];
    while(!m_tr->is_leaf(c)) c = m_tr->child(c, m_tr->child_side(c, point_of(i)));
    return c;
  }

  std::size_t count(Cell_index c) const { return m_range[c][1] - m_range[c][0]; }

  Point point_of(std::uint32_t i) const { return Point(m_points[i][0], m_points[i][1], m_points[i][2]); }

  // paper 4.1: cells with fewer points than the minimum inherit the parent's plane and error.
  // Where the points are sparse the parent is large and its plane a chord: across a thin
  // ear it put the ear's tip outside (the bunny with one half ten times sparser: 36 of
  // seeds 21-60 right, 39 with the plane of the points nearest the cell's own,
  // `sparse_cell_planes`). The cell still stops: it has too few points to be bisected.
  void fit(Cell_index c, Cell_index parent)
  {
    const std::size_t n = count(c);
    const unsigned int minimum = unsigned(m_settings.min_points_per_cell);
    if(n >= minimum || (n > 0 && m_settings.sparse_cell_planes && m_point_neighbors))
    {
      ISM_reconstruction_3::internal::Moments moments(m_cell_points[m_range[c][0]]);
      if(n >= minimum)
        for(std::uint32_t i = m_range[c][0]; i < m_range[c][1]; ++i) moments.add(m_cell_points[i]);
      else
      {
        Xyz centroid = {{ 0., 0., 0. }};
        for(std::uint32_t i = m_range[c][0]; i < m_range[c][1]; ++i)
          for(int d = 0; d < 3; ++d) centroid[d] += m_cell_points[i][d];
        for(int d = 0; d < 3; ++d) centroid[d] /= double(n);
        m_point_neighbors->for_nearest(centroid, minimum, [&](std::uint32_t j, double) { moments.add(m_points[j]); });
      }
      if(moments.fit(m_fit[c])) return;
    }
    m_fit[c] = parent >= 0 ? m_fit[parent] : ISM_reconstruction_3::internal::Plane_fit();
  }

  // maximum_depth and the levels far outliers added (refine())
  int maximum_depth() const { return m_settings.maximum_depth + m_stats.added_levels; }

  // the stop test: maximum level, minimum number of points, coplanarity error
  bool stop(Cell_index c) const
  {
    return m_tr->level(c) >= maximum_depth() || count(c) < std::size_t(m_settings.min_points_per_cell) ||
           m_fit[c].coplanarity_error < m_settings.coplanarity_threshold;
  }

  void sync_vertices()
  {
    for(std::size_t v = m_vertex_xyz.size(); v < m_tr->number_of_vertices(); ++v)
    {
      const Point& p = m_tr->point(Vertex_index(v));
      m_vertex_xyz.push_back({{ to_double(p.x()), to_double(p.y()), to_double(p.z()) }});
    }
  }

  // paper 4.2: minimise the Ising energy over the leaf mesh
  // `last`: the refinement is over, and the per-cell point ranges and fits, which only
  // serve it and the topology, are freed as soon as the leaves' proposals are read
  void estimate_topology(const ISM_reconstruction_3::internal::Annealing_schedule& schedule, bool last = false)
  {
    namespace I = ISM_reconstruction_3::internal;
    sync_vertices();
    m_sign.resize(m_tr->number_of_vertices(), 1);
    I::Topology_input in;
    in.empty_cell_error = m_settings.empty_cell_error;
    I::Leaf_proposals proposals = I::propose_signs(*m_tr, m_vertex_xyz, m_fit, [&](Cell_index c) { return count(c); });
    if(last)
    {
      m_range = decltype(m_range)();
      m_fit = decltype(m_fit)();
      // without this, freeing these 64 MB lowered the resident memory by 2 MB
      I::return_free_heap_memory();
    }
    I::Coupling_graph graph = I::build_coupling_graph(*m_tr, std::move(proposals), in);
    m_stats.all_outside_energy = I::ising_energy(graph, std::vector<signed char>(m_sign.size(), 1));
    std::vector<char> clamped;
    const std::vector<char> boundary = I::box_boundary_vertices(*m_tr);
    if(m_settings.clamp_box_boundary)
    {
      clamped = boundary;
      for(std::size_t v = 0; v < boundary.size(); ++v)
        if(boundary[v]) m_sign[v] = 1;
    }
    m_stats.final_energy = I::anneal(std::move(graph), m_sign, clamped, schedule,
                                     m_settings.random_seed + 0x9E3779B97F4A7C15ULL * m_stats.number_of_topology_passes);
    ++m_stats.number_of_topology_passes;
    // D is symmetric under S -> -S: the box boundary is outside (a no-op when clamped)
    long boundary_sum = 0;
    for(std::size_t v = 0; v < boundary.size(); ++v)
      if(boundary[v]) boundary_sum += m_sign[v];
    if(boundary_sum < 0)
      for(signed char& s : m_sign) s = static_cast<signed char>(-s);
    // Unclamped (the paper), a box boundary vertex can stay inside after the flip, and the
    // surface would open where the inside meets the box (a sparse open cylinder, or the
    // bunny at 2,000 points with the paper's settings and eps_empty 1: closed no). The
    // margin keeps the points off the box, so its boundary is outside: set so last, the
    // result is closed whatever the annealing did.
    if(last)
      for(std::size_t v = 0; v < boundary.size(); ++v)
        if(boundary[v] && m_sign[v] < 0)
        {
          m_sign[v] = 1;
          ++m_stats.number_of_boundary_vertices_set_outside;
        }
    m_stats.number_of_leaves = m_tr->number_of_leaves();
    m_stats.number_of_vertices = m_tr->number_of_vertices();
    m_stats.number_of_inside_vertices = std::size_t(std::count(m_sign.begin(), m_sign.end(), -1));
  }

  // Whether `x` lies among the points, not in the open space between two objects: no
  // farther from its nearest point than that point is from its 6th nearest. Measured, in
  // units of that distance: the bridges that joined a bunny's ear tip back (2,000-4,000
  // points, 120 samplings, 39 bridge vertices) 0.11-0.97, the bridges between two spheres
  // or cylinders 9 point spacings apart 1.49-1.83 (3 spacings apart: 0.93, still joined).
  bool among_points(const ISM_reconstruction_3::internal::Point_neighbors& neighbors, const Xyz& x) const
  {
    std::uint32_t nearest = 0;
    double d2 = HUGE_VAL, spacing2 = 0;
    neighbors.for_nearest(x, 1, [&](std::uint32_t i, double d) { nearest = i; d2 = d; });
    if(!(d2 < HUGE_VAL)) return false;
    neighbors.for_nearest(m_points[nearest], 7, [&](std::uint32_t, double d) { spacing2 = d; });
    return d2 <= spacing2;
  }

  // after the distances: the depth of a vertex decides whether the loop it closes is thin
  // `depth`: the values whose magnitude says how deep a vertex is (the handles are judged on
  // the distances of paper 4.3 also after the tangent planes changed some values)
  void remove_thin_handles(const Leaf_vertices& leaves, const std::vector<char>& boundary, std::vector<double>& depth)
  {
    namespace I = ISM_reconstruction_3::internal;
    // With noisy points, the inside sweep goes deepest first by the larger of the paper's
    // distance and the tangent-plane distance (m_value, where the tangent planes voted),
    // which is about the true depth in the core of a thin part (handle_removal.h says why
    // the order matters). Measured on the 36k bunny, samplings with a handle / meeting the
    // robustness bar (genus 0, every query farther than 1 % of the diagonal right): noise of
    // 0.15 % 2 -> 0 / 6 -> 8 of 10, 0.2 % 4 -> 1 / 5 -> 6 of 10, 0.25 % 1 -> 0 / 10 -> 16 of
    // 30, 0.5 % 8 -> 8 / 9 -> 11 of 30, but 0.1 % 0 -> 1 of 10; on clean points it gave a
    // handle at 12k points (1 of 10), hence only above 10 times a clean scan's noise (clean
    // bunny at 8k-36k points 0.0004-0.003, 0.1 % noise 0.02). Knots, eight, double torus at
    // 0.25 and 0.5 % unchanged. (Before the tangent planes `depth` is m_value: the same order.)
    std::vector<double> inside_order;
    if(m_stats.neighborhood_coplanarity > 0.01)
    {
      inside_order.resize(depth.size());
      for(std::size_t v = 0; v < depth.size(); ++v)
        inside_order[v] = m_sign[v] < 0 ? (std::max)(std::abs(depth[v]), std::abs(m_value[v])) : std::abs(depth[v]);
    }
    const std::size_t changed = I::remove_thin_handles(leaves, m_vertex_xyz, boundary, m_settings.thin_handle_depth,
                                                       m_sign, depth, inside_order.empty() ? nullptr : &inside_order, true);
    m_stats.number_of_handle_vertices += changed;
    if(changed > 0 && m_settings.minimum_island_fraction > 0)
      // vertices that changed side can leave a speck of one sign (bunny with 0.5 % noise,
      // homer: a second component); taking a small ball out of a region leaves its loops
      m_stats.number_of_flipped_islands += I::remove_islands(leaves, m_sign, boundary, m_settings.minimum_island_fraction);
    for(std::size_t v = 0; v < m_sign.size(); ++v) m_value[v] = m_sign[v] * std::abs(m_value[v]);
    m_stats.number_of_inside_vertices = std::size_t(std::count(m_sign.begin(), m_sign.end(), -1));
  }

  // Near the points, the side of their oriented tangent planes (tangent_plane_signs.h); the
  // normals are oriented by this function as ism_orient_normals() does. Measured on bunny00
  // at 36k points, 13 samplings: in/out 99.64-99.70 % -> 99.76-99.80 %, queries farther
  // than 1 % of the diagonal on the wrong side 0-3 -> 0, mean distance 0.075 -> 0.051 %.
  void sign_by_tangent_planes(const Leaf_vertices& leaves, const std::vector<char>& boundary,
                              const ISM_reconstruction_3::internal::Point_neighbors& neighbors)
  {
    namespace I = ISM_reconstruction_3::internal;
#ifdef CGAL_ISM_TIMER
    CGAL::Real_timer step;
    step.start();
#endif
    const double radius = set_voting_radii(leaves);
    // the handles are judged on the distances of paper 4.3 (on the tangent-plane distances
    // they left the bunny a handle on 1 of 13 samplings)
    m_depth = m_value;
    m_stats.number_of_tangent_plane_vertices = vote_by_tangent_planes(neighbors, boundary, 0, radius);
    CGAL_ISM_TIMER_MARK(step, "tangent planes: votes");
    if(m_stats.number_of_tangent_plane_vertices == 0) return;
    remove_islands_and_thin_handles(leaves, boundary);
    CGAL_ISM_TIMER_MARK(step, "tangent planes: islands and thin handles");
  }

  // After vertices changed side: islands, then the thin handles, judged on m_depth; the
  // values and the depths follow the signs.
  void remove_islands_and_thin_handles(const Leaf_vertices& leaves, const std::vector<char>& boundary)
  {
    if(m_settings.minimum_island_fraction > 0)
      m_stats.number_of_flipped_islands +=
          ISM_reconstruction_3::internal::remove_islands(leaves, m_sign, boundary, m_settings.minimum_island_fraction);
    for(std::size_t v = 0; v < m_sign.size(); ++v)
    {
      m_value[v] = m_sign[v] * std::abs(m_value[v]);
      m_depth[v] = m_sign[v] * std::abs(m_depth[v]);
    }
    if(m_settings.thin_handle_depth > 0) remove_thin_handles(leaves, boundary, m_depth);
    m_stats.number_of_inside_vertices = std::size_t(std::count(m_sign.begin(), m_sign.end(), -1));
  }

  // The voting radius of each vertex (m_voting_radius): 0.75 times the size of the leaves
  // the surface crosses there, the median one or, where the leaves are larger (a sparser
  // sampling), the local one. The Ising signs of a leaf's vertices are wrong up to about a
  // leaf from the points, and with one median for all a sparse part was left its wrong
  // signs: bunny00, one half 10 times denser (the robustness case nonuniform), dents 1.5-2 %
  // of the diagonal deep on the sparse half, the median being that of the dense half. The
  // local size is the smallest leaf at the vertex over 0.88, the ratio of the two where the
  // sampling is uniform (smallest_leaf_at_vertices()), so that there the median decides.
  // Measured on nonuniform, 4 samplings: queries farther than 1 % of the diagonal on the
  // wrong side 81-126 -> 3-17, genus 2-6 -> 0-1; the uniform bunny (clean, 0.25 and 0.5 %
  // noise), knot1 and eight unchanged up to a query. The larger leaves' median at the vertex
  // instead of the smallest leaf did better on nonuniform (3-8) but gave 4-23 wrong queries
  // at 0.5 % noise (2-3). Returns the median radius.
  double set_voting_radii(const Leaf_vertices& leaves)
  {
    namespace I = ISM_reconstruction_3::internal;
    const double radius = 0.75 * I::median_surface_leaf_size(leaves, m_vertex_xyz, m_sign);
    m_voting_radius = I::smallest_leaf_at_vertices(leaves, m_vertex_xyz);
    for(float& r : m_voting_radius) r = float((std::max)(radius, 0.75 / ISM_reconstruction_3::internal::smallest_over_median_leaf * r));
    return radius;
  }

  // The estimate the steps after the signs work with. The paper's squared distance is
  // applied once F is final (square_values()): those steps compare |value| with distances
  // (a leaf's size, a voting radius, an escape distance) and the tangent planes and the
  // winding number write distances, so with squared values a result depended on the unit of
  // the coordinates (the bunny scaled by 1000 gave 41,067 output vertices instead of 22,463).
  ISM_reconstruction_3::Distance_estimate working_estimate() const
  {
    return m_settings.distance_estimate == ISM_reconstruction_3::NEAREST_POINT_SQUARED_DISTANCE
               ? ISM_reconstruction_3::NEAREST_POINT_DISTANCE
               : m_settings.distance_estimate;
  }

  // F of the paper's estimate (4.3): the squared distance, signed
  void square_values()
  {
    if(m_settings.distance_estimate != ISM_reconstruction_3::NEAREST_POINT_SQUARED_DISTANCE) return;
    for(double& f : m_value) f *= std::abs(f);
  }

  // The vertices from `first` on that are not `fixed` and have a point nearer than their
  // voting radius take the side of the oriented tangent planes of their nearest points;
  // returns the number of vertices that changed side. `radius`: the median voting radius.
  std::size_t vote_by_tangent_planes(const ISM_reconstruction_3::internal::Point_neighbors& neighbors,
                                     const std::vector<char>& fixed, std::size_t first, double radius)
  {
    namespace I = ISM_reconstruction_3::internal;
    // no point is nearer than its radius to a vertex whose distance estimate is not (it is
    // at most the distance to the nearest point): only the others look for voters
    std::vector<char> without_voters(fixed);
    without_voters.resize(m_value.size(), 0);
    for(std::size_t v = 0; v < m_value.size(); ++v)
      if(v < first || !(std::abs(m_value[v]) < m_voting_radius[v])) without_voters[v] = 1;
    const std::vector<I::Voters> voters =
        I::voters_of_vertices(m_vertex_xyz, without_voters, neighbors, [&](std::size_t v) { return double(m_voting_radius[v]); });
    const double tiny = 1e-9 * std::sqrt(to_double(m_bounding_sphere.squared_radius()));
    auto vote = [&](const auto& normal_of, const auto& vouched_depth_of) {
      return I::sign_by_tangent_planes(m_points, neighbors, m_vertex_xyz, voters, normal_of, vouched_depth_of, radius, tiny,
                                       m_sign, m_value);
    };
    // the normals of the first call serve the vertices the surface refinement adds: their
    // voters are points near the surface, which voted for a vertex before
    if(!m_voting_normals.empty())
      return vote(
          [&](std::uint32_t i) {
            return Xyz{{ double(m_voting_normals[i][0]), double(m_voting_normals[i][1]), double(m_voting_normals[i][2]) }};
          },
          [&](std::uint32_t i) { return m_vouched_depth[i]; });
    // the points that vote, and their slot in the arrays below
    std::vector<std::uint32_t> slot(m_points.size(), I::no_voter), which;
    for(const I::Voters& w : voters)
      for(std::uint32_t i : w)
        if(i != I::no_voter && slot[i] == I::no_voter) slot[i] = 0;
    for(std::uint32_t i = 0; i < m_points.size(); ++i)
      if(slot[i] == 0) { slot[i] = std::uint32_t(which.size()); which.push_back(i); }
    const std::size_t n = which.size();
    if(n == 0) return 0;  // no vertex near the points
    std::vector<Xyz> xyz(n), normals;
    for(std::size_t j = 0; j < n; ++j) xyz[j] = m_points[which[j]];
    std::vector<float> coplanarity_errors, radii;
    I::estimate_point_normals(m_points, neighbors, which, 12, normals, coplanarity_errors, radii);
    std::vector<I::Orientation_test> tests(n);
    std::vector<char> outside(n, 0);
    I::for_each_index(n, [&](std::size_t j) {
      tests[j] = I::ism_orientation_of(Values_as_they_stand{*this}, xyz[j], normals[j], leaf_of_point(which[j]));
      if(!tests[j].confident) outside[j] = value_at(Point(xyz[j][0], xyz[j][1], xyz[j][2])) > 0;
    });
    // A point votes if its neighbourhood is one sheet (coplanarity error below 0.05, or twice
    // the median with noise: 0.08 at 0.25 %) and its orientation is sure: tested directly, or
    // propagated to a point the function leaves outside (a part the Ising signs lost, whose
    // points the propagation reaches along the part). Propagated into a part the function
    // fills (homer's ear canal, a crease), orientations were wrong; a tube thinner than the
    // neighbourhood (the camel's tail) has no normal. A point passes its orientation on
    // (propagate_orientations()) below twice that bound: a thin part's rim does not (0.104
    // and 0.157 at the sparse ear tip traced in session 33, the bound 0.05); at the bound
    // itself 0.5 % noise lost samplings (seeds 101-200: the bar met on 89, at twice the
    // bound 90, without the rule 93).
    std::vector<float> sorted(coplanarity_errors);
    std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
    const double max_error = (std::max)(0.05, 2. * double(sorted[n / 2]));
    std::vector<char> one_sheet(n);
    for(std::size_t j = 0; j < n; ++j) one_sheet[j] = coplanarity_errors[j] <= 2. * max_error;
    I::propagate_orientations(xyz, normals, tests, 18, 0.5, one_sheet);
    // the depth a point vouches for (sign_by_tangent_planes()): half its neighbourhood's
    // radius where its orientation was only passed on to it. Without the test of the points
    // behind a deeper vertex (has_points_behind()), ear tips the Ising signs lost were not
    // restored: the robustness bar was met at 0.5 % noise on 76 of seeds 21-100 (80 with
    // the test, 77 without the rule), the non-uniform bunny on 44 of seeds 21-74 (48, 48;
    // dents at the ears).
    std::vector<float> vouched_depth(n);
    for(std::size_t j = 0; j < n; ++j)
    {
      const bool votes = tests[j].sign != 0 && coplanarity_errors[j] <= max_error && (tests[j].confident || outside[j]);
      for(int d = 0; d < 3; ++d) normals[j][d] = votes ? tests[j].sign * normals[j][d] : 0.;
      vouched_depth[j] = tests[j].confident ? HUGE_VALF : 0.5f * radii[j];
    }
    if(m_settings.surface_refinement_passes > 0)
    {
      m_voting_normals.assign(m_points.size(), {{ 0.f, 0.f, 0.f }});
      m_vouched_depth.assign(m_points.size(), 0.f);
      for(std::size_t j = 0; j < n; ++j)
      {
        for(int d = 0; d < 3; ++d) m_voting_normals[which[j]][d] = float(normals[j][d]);
        m_vouched_depth[which[j]] = vouched_depth[j];
      }
    }
    return vote([&](std::uint32_t i) -> const Xyz& { return normals[slot[i]]; },
                [&](std::uint32_t i) { return vouched_depth[slot[i]]; });
  }

  // The slabs of inside that the Ising signs and the tangent planes put beside a thin part
  // (escape_rays.h), removed; then the islands and thin handles this leaves. Measured on
  // bunny00 with gaussian noise of 0.5 % of the diagonal, 36k points, 5 samplings: queries
  // farther than 1 % of the diagonal on the wrong side 8, 1, 7, 4, 9 -> 1, 0, 1, 1, 0, genus 1
  // on 1 of 5 -> 0 of 5; the survey of 30 meshes: all far queries right on 18 -> 21 (cow,
  // camel, armadillo), none worse; 3torus at 50k points: 12 -> 4, genus 3 kept (one ray
  // instead of five: genus 4). The hit radius is 0.4 times the voting radius of the tangent
  // planes: 0.3 let rays slip between noisy points out of the solid (genus 1 on 3 of 5), 0.7
  // left more slabs.
  // `leaves`, `boundary`: the leaves and box boundary vertices of the final triangulation
  void remove_escaping_inside(const ISM_reconstruction_3::internal::Point_neighbors& neighbors, const Leaf_vertices& leaves,
                              const std::vector<char>& boundary)
  {
    namespace I = ISM_reconstruction_3::internal;
    if(m_voting_radius.size() != m_sign.size()) set_voting_radii(leaves);
    if(m_depth.size() != m_value.size()) m_depth = m_value;
    const std::size_t turned = I::remove_escaping_inside(
        leaves, m_vertex_xyz, m_points, neighbors, boundary, m_settings.escape_rays,
        [&](std::uint32_t v) { return 0.4 * double(m_voting_radius[v]); },
        [&](std::uint32_t v, const Xyz& u) {
          const Xyz& x = m_vertex_xyz[v];
          const double l = 3. * double(m_voting_radius[v]);
          return value_at(Point(x[0] + l * u[0], x[1] + l * u[1], x[2] + l * u[2])) > 0;
        },
        m_sign, m_value);
    m_stats.number_of_escaped_vertices = turned;
    if(turned > 0) remove_islands_and_thin_handles(leaves, boundary);
  }

  // The pockets that every local test confirms (winding_number.h says why), re-signed by the
  // winding number of the points, their normals oriented by this function, in two stages:
  // first only the vertices farther from the points than their spacing, then, to fill the
  // rest of the pockets, outside vertices down to a quarter of it. After each stage the
  // islands and thin handles are removed; a stage that leaves the surface with a lower Euler
  // characteristic (a handle more, or a pocket's island kept by the removal) is undone.
  // Measured on the 36k bunny (genus 0 and no query farther than 1 % of the diagonal on the
  // wrong side): one half ten times denser, 10 of 20 samplings instead of 0; gaussian noise of
  // 0.5 % of the diagonal, 16 of 20 instead of 10; of 0.25 %, 10 of 10 instead of 7. Over 30
  // meshes of libcgal-demo, the truth's topology on 23 instead of 19, none worse.
  void sign_by_winding_number(const ISM_reconstruction_3::internal::Point_neighbors& neighbors,
                              const Leaf_vertices& leaves, const std::vector<char>& boundary)
  {
    namespace I = ISM_reconstruction_3::internal;
#ifdef CGAL_ISM_TIMER
    CGAL::Real_timer step;
    step.start();
#endif
    std::vector<float> spacing;
    // the points that voted for the tangent planes have their normal (the PCA of the same 12
    // points) oriented already
    const std::vector<Xyz> dipoles = I::point_dipoles(m_points, neighbors, 12, [&](std::uint32_t i, const Xyz& n) {
      if(!m_voting_normals.empty())
      {
        const std::array<float, 3>& m = m_voting_normals[i];
        const double dot = m[0] * n[0] + m[1] * n[1] + m[2] * n[2];
        if(dot != 0) return dot > 0 ? 1 : -1;
      }
      return int(I::ism_orientation_of(Values_as_they_stand{*this}, m_points[i], n, leaf_of_point(i)).sign);
    }, spacing);
    CGAL_ISM_TIMER_MARK(step, "winding number: dipoles");
    const I::Winding_number w(m_points, dipoles);
    CGAL_ISM_TIMER_MARK(step, "winding number: octree");
    if(m_depth.size() != m_value.size()) m_depth = m_value;
    std::vector<std::uint64_t> edges;
    const auto every_edge = [](std::uint64_t, std::uint64_t) { return true; };
    long euler = 0;
    bool euler_known = false;  // computed once a stage changes a sign (most runs change none)
    I::Winding_number_rule rule;
    I::Winding_number_cache cache(leaves, boundary);
    for(const double fill_reach : { 1., 0.25 })
    {
      rule.fill_reach = fill_reach;
      const std::vector<signed char> old_sign = m_sign;
      const std::vector<double> old_value = m_value, old_depth = m_depth;
      const std::size_t changed =
          I::sign_by_winding_number(leaves, m_vertex_xyz, neighbors, spacing, w, boundary, rule, cache, m_sign, m_value);
      CGAL_ISM_TIMER_MARK(step, "winding number: signs");
      if(changed == 0) continue;
      if(!euler_known) euler = I::twice_euler_characteristic(leaves, {}, every_edge, old_sign, edges);
      euler_known = true;
      for(std::size_t v = 0; v < m_sign.size(); ++v)
        if((m_sign[v] < 0) != (m_depth[v] < 0)) m_depth[v] = m_value[v];
      // the thin-handle sweep after a stage's fills once cut a dent into the old inside (0.5 %
      // noise, one far-wrong query); undoing or restoring such cuts lost more samplings than
      // it saved (development notes, session 31)
      remove_islands_and_thin_handles(leaves, boundary);
      CGAL_ISM_TIMER_MARK(step, "winding number: islands and thin handles");
      const long new_euler = I::twice_euler_characteristic(leaves, {}, every_edge, m_sign, edges);
      if(new_euler < euler)
      {
        m_sign = old_sign;
        m_value = old_value;
        m_depth = old_depth;
        continue;
      }
      euler = new_euler;
      m_stats.number_of_winding_number_vertices += changed;
    }
  }

  // per input point, its oriented normal if it votes, else 0 (12 bytes a point, kept from the
  // tangent planes to the end of the winding number)
  std::vector<std::array<float, 3> > m_voting_normals;
  std::vector<float> m_vouched_depth;  // of the points, the depth each vouches for (vote_by_tangent_planes())
  // per vertex, the value of paper 4.3 (before the tangent planes), signed as the vertex: the
  // thin handles are judged on it
  std::vector<double> m_depth;
  // per vertex, how near its nearest point must be for the tangent planes to vote
  // (set_voting_radii()), from the tangent planes to the end of the surface refinement
  std::vector<float> m_voting_radius;  // 4 bytes a vertex

  // Bisects the leaves in which F misses the points (surface_refinement.h says why), up to
  // `surface_refinement_passes` times, then as many times again only those larger than
  // sparse_leaf_factor times the median leaf the surface crosses, with the crossed leaves of
  // that size near the points (sparse_crossed_leaves() says why). A new vertex takes F's
  // value at its place on the edge it halves, so the surface is unchanged until its distance
  // is estimated and, near the points, the tangent planes give its side. Measured on bunny00
  // at 36k points, 13 samplings: mean distance 0.055-0.059 -> 0.037-0.039 % of the diagonal,
  // far in/out errors on 3 -> 1 sampling; at 0.25 % noise 2 of 3 -> 0 of 3. The passes on
  // the large leaves (session 19): one half ten times denser, the bar met on 10 -> 13 of 20
  // samplings (seed 7's far query was in a leaf of 4 % of the diagonal that the second pass
  // made); all passes on all leaves did as well there but cost 0.5 % noise samplings and the
  // survey handles (development notes, session 17), which these passes do not touch.
  // Unchanged: clean, 0.25 % and 0.5 % noise, 1 % outliers (20 samplings each), the survey.
  // The crossed leaves near the points (session 27), held-out seeds 21-100 and 101-200: one
  // half ten times denser 58 -> 67 of 80 and 74 -> 83 of 100 (mean distance 0.050 -> 0.044 %);
  // 0.5 % noise 76 and 92 either way; clean, 0.25 % noise, 1 % outliers 100 of 100 either way.
  // `leaves`, `boundary`: the leaves and box boundary vertices of the triangulation before,
  // after it on return
  void refine_surface_leaves(const ISM_reconstruction_3::internal::Point_neighbors& neighbors,
                             std::vector<char>& boundary, Leaf_vertices& leaves)
  {
    namespace I = ISM_reconstruction_3::internal;
    Triangulation& tr = *m_tr;
    // the voting radii of the tangent planes before the leaves shrink
    const double radius = set_voting_radii(leaves);
    I::Memory_guard memory_guard(m_settings.memory_limit, m_points.size(), m_settings.maximum_depth);
    std::vector<char> fixed = boundary;
    if(m_depth.size() != m_value.size()) m_depth = m_value;  // no tangent planes
#ifdef CGAL_ISM_TIMER
    CGAL::Real_timer step;
    step.start();
#endif
    const double sparse_leaf_size = I::sparse_leaf_factor * I::median_surface_leaf_size(leaves, m_vertex_xyz, m_sign);
    const int passes = m_settings.surface_refinement_passes;
    for(int pass = 0; pass < 2 * passes; ++pass)
    {
      // 3 times the median miss: a bend that a leaf cuts misses the points by more than the
      // noise (0.25 % noise refined 13k leaves of 63k at tolerance 0.05 without it, 1.5k with)
      std::vector<Cell_index> to_bisect = I::misfit_leaves(
          tr, m_vertex_xyz, m_points, [&](std::uint32_t i) { return leaf_of_point(i); },
          [&](Cell_index c, const Xyz& x) { return interpolate(c, x); },
          m_settings.surface_refinement_tolerance, 3., maximum_depth(), pass < passes ? 0. : sparse_leaf_size);
      if(pass >= passes)
      {
        const std::vector<Cell_index> crossed =
            I::sparse_crossed_leaves(tr, m_vertex_xyz, m_sign, m_value, sparse_leaf_size,
                                     0.5 * sparse_leaf_size, maximum_depth());
        std::vector<Cell_index> both;
        std::set_union(to_bisect.begin(), to_bisect.end(), crossed.begin(), crossed.end(), std::back_inserter(both));
        to_bisect.swap(both);
      }
      CGAL_ISM_TIMER_MARK(step, "surface refinement: leaves to bisect " + std::to_string(to_bisect.size()));
      if(to_bisect.empty()) break;
      m_stats.number_of_misfit_leaves += to_bisect.size();
      const std::size_t first = tr.number_of_vertices();
      for(Cell_index c : to_bisect)
        if(tr.is_leaf(c))
          tr.bisect(c, [&](Cell_index p, Cell_index c0, Cell_index) {
            const int k = Triangulation::refinement_index(tr.level(p));
            const Vertex_index z = tr.vertex(c0, k);
            if(std::size_t(z) < m_value.size()) return;
            const Vertex_index a = tr.vertex(p, 0), b = tr.vertex(p, k);
            const double f = 0.5 * (m_value[a] + m_value[b]);
            m_value.resize(std::size_t(z) + 1, f);
            // the radius of the larger leaves around its edge's ends
            m_voting_radius.resize(std::size_t(z) + 1, (std::max)(m_voting_radius[a], m_voting_radius[b]));
            m_sign.resize(std::size_t(z) + 1, static_cast<signed char>(f < 0 ? -1 : 1));
            // a midpoint on the box boundary halves an edge between two of its vertices:
            // held as they are (more than needed, without a pass over the leaves)
            fixed.resize(std::size_t(z) + 1, char(fixed[a] && fixed[b]));
          });
      memory_guard.check(tr.number_of_cells());
      sync_vertices();
      const std::vector<double> d =
          I::estimate_distances(m_points, neighbors, m_vertex_xyz, m_sign, working_estimate(), {}, first);
      std::copy(d.begin() + std::ptrdiff_t(first), d.end(), m_value.begin() + std::ptrdiff_t(first));
      m_depth.insert(m_depth.end(), d.begin() + std::ptrdiff_t(first), d.end());
      CGAL_ISM_TIMER_MARK(step, "surface refinement: bisections and distances, new vertices " + std::to_string(m_value.size() - first));
      if(m_settings.tangent_plane_signs)
        m_stats.number_of_tangent_plane_vertices += vote_by_tangent_planes(neighbors, fixed, first, radius);
      CGAL_ISM_TIMER_MARK(step, "surface refinement: votes");
    }
    if(m_stats.number_of_misfit_leaves == 0) return;
    // the new sides can close small loops (bunny with 0.25 % noise: genus 1 on 2 of 3 without)
    leaves.assign(tr);
    boundary = I::box_boundary_vertices(tr);
    remove_islands_and_thin_handles(leaves, boundary);
    CGAL_ISM_TIMER_MARK(step, "surface refinement: islands and thin handles");
    m_stats.number_of_leaves = tr.number_of_leaves();
    m_stats.number_of_vertices = tr.number_of_vertices();
  }

  // F(p) from the values as they stand: operator() once the computation completed; the
  // steps after the distances (tangent planes, escape rays) read it before
  // vertices the surface refinement added have no value yet: F reads outside, as before them
  bool has_values() const { return m_tr && m_value.size() == m_tr->number_of_vertices(); }

  FT value_at(const Point& p) const
  {
    if(!has_values()) return FT(1);
    const Xyz x = {{ to_double(p.x()), to_double(p.y()), to_double(p.z()) }};
    // a NaN is nowhere, so outside: the distance below would be NaN
    if(std::isnan(x[0]) || std::isnan(x[1]) || std::isnan(x[2]))
      return FT(2 * std::sqrt(to_double(m_bounding_sphere.squared_radius())));
    const Cell_index r = m_tr->locate_root(p);
    if(r < 0)
    {
      const Xyz c = {{ to_double(m_bounding_sphere.center().x()), to_double(m_bounding_sphere.center().y()),
                       to_double(m_bounding_sphere.center().z()) }};
      // the distance to the centre, positive: the small term relative, as the values inside
      return FT(std::sqrt((x[0] - c[0]) * (x[0] - c[0]) + (x[1] - c[1]) * (x[1] - c[1]) + (x[2] - c[2]) * (x[2] - c[2])) +
                1e-9 * std::sqrt(to_double(m_bounding_sphere.squared_radius())));
    }
    Cell_index c = r;
    while(!m_tr->is_leaf(c))
      c = m_tr->child(c, m_tr->child_side(c, p));
    return FT(interpolate(c, x));
  }

  FT value_at(const Point& p, Cell_index& hint) const
  {
    if(!has_values()) return FT(1);
    const Cell_index c = m_tr->walk_to(p, hint);
    if(c < 0) return value_at(p);
    hint = c;
    return FT(interpolate(c, {{ to_double(p.x()), to_double(p.y()), to_double(p.z()) }}));
  }

  // what ism_orientation_of() reads while the computation runs (operator() is +1 until it
  // completes)
  struct Values_as_they_stand
  {
    typedef typename ISM_reconstruction_function::Point Point;
    typedef typename ISM_reconstruction_function::Triangulation Triangulation;
    const ISM_reconstruction_function& function;
    const Triangulation& triangulation() const { return *function.m_tr; }
    FT operator()(const Point& p, Cell_index& hint) const { return function.value_at(p, hint); }
  };

  void find_inner_point()
  {
    int deepest = 0;
    for(Cell_index c = 0; c < Cell_index(m_tr->number_of_cells()); ++c) deepest = (std::max)(deepest, m_tr->level(c));
    m_stats.deepest_level = deepest;
    std::size_t best = 0;
    for(std::size_t v = 1; v < m_value.size(); ++v)
      if(m_value[v] < m_value[best]) best = v;
    if(m_value.empty() || m_value[best] >= 0)
      throw std::runtime_error("ISM reconstruction: no vertex was found inside the surface "
                               "(the points may not sample a closed surface densely enough)" +
                               ISM_reconstruction_3::internal::far_outlier_hint(
                                   ISM_reconstruction_3::internal::extent_over_bulk_extent(m_points)));
    m_inner_point = m_tr->point(Vertex_index(best));
  }

  double interpolate(Cell_index c, const Xyz& x) const
  {
    const auto v = m_tr->vertices(c);
    const Xyz& a = m_vertex_xyz[v[0]];
    double m[3][3], r[3];
    for(int i = 0; i < 3; ++i)
    {
      for(int j = 0; j < 3; ++j) m[j][i] = m_vertex_xyz[v[i + 1]][j] - a[j];
      r[i] = x[i] - a[i];
    }
    // barycentric coordinates by Cramer's rule
    auto det = [](const double (&q)[3][3]) {
      return q[0][0] * (q[1][1] * q[2][2] - q[1][2] * q[2][1]) - q[0][1] * (q[1][0] * q[2][2] - q[1][2] * q[2][0]) +
             q[0][2] * (q[1][0] * q[2][1] - q[1][1] * q[2][0]);
    };
    const double d = det(m);
    double w[4], sum = 0;
    for(int i = 0; i < 3; ++i)
    {
      double q[3][3];
      for(int a1 = 0; a1 < 3; ++a1)
        for(int b1 = 0; b1 < 3; ++b1) q[a1][b1] = (b1 == i) ? r[a1] : m[a1][b1];
      w[i + 1] = det(q) / d;
      sum += w[i + 1];
    }
    w[0] = 1 - sum;
    double f = 0;
    for(int i = 0; i < 4; ++i) f += w[i] * m_value[v[i]];
    return f;
  }

  // The points themselves, not indices to them, are partitioned as cells are bisected:
  // a cell's points then sit together in memory. With an index array every level read
  // the points at random, a cache miss per point and level (dragon, 437k points:
  // refinement 1.65 -> 1.5 s). A copy, so that m_points keeps its order and a second run
  // gives the same result; freed after the refinement, below the peak of the topology.
  std::vector<Xyz> m_cell_points;
  std::vector<std::uint32_t> m_cell_point_index;  // of each cell point in m_points
  std::vector<Cell_index> m_leaf_of_point;        // per point of m_points, to the end of the distance stage
  // per cell, in blocks: growing them never copies (as the triangulation's cells)
  ISM_reconstruction_3::internal::Block_array<std::array<std::uint32_t, 2> > m_range;
  ISM_reconstruction_3::internal::Block_array<ISM_reconstruction_3::internal::Plane_fit> m_fit;
};

namespace ISM_reconstruction_3 {
namespace internal {

// The function of `points` as the package's functions compute it: on the points scaled by
// 2^e (read through a map, not copied) when they are far from unit size, else on the
// points as they are (normalization.h; the exponent comes from normalizing_exponent()).
template <class Geom_traits, class PointRange, class NamedParameters>
ISM_reconstruction_function<Geom_traits> normalized_function(const PointRange& points, const NamedParameters& np, int e)
{
  if(e == 0)
    return ISM_reconstruction_function<Geom_traits>(points, np);
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  const Scaled_point_map<typename NP_helper::Const_point_map> scaled(NP_helper::get_const_point_map(points, np), e);
  return ISM_reconstruction_function<Geom_traits>(
      points, parameters::memory_limit(
                  parameters::choose_parameter(parameters::get_parameter(np, internal_np::memory_limit), std::size_t(0)),
                  parameters::point_map(scaled).geom_traits(NP_helper::get_geom_traits(points, np))));
}

} // namespace internal
} // namespace ISM_reconstruction_3

} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_FUNCTION_H
