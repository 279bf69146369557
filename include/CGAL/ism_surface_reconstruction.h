// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_SURFACE_RECONSTRUCTION_H
#define CGAL_ISM_SURFACE_RECONSTRUCTION_H

#include <CGAL/ISM_reconstruction_function.h>
#include <CGAL/ISM_reconstruction_3/internal/jet_crossing.h>
#include <CGAL/ISM_reconstruction_3/internal/marching_tetrahedra.h>
#include <CGAL/ISM_reconstruction_3/internal/normalization.h>
#include <CGAL/ISM_reconstruction_3/internal/taubin_smoothing.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {

/*!
  \ingroup PkgISMReconstruction3Ref
  \brief The times of the surface extraction stages, in seconds: `marching_time` and
  `smoothing_time`.
*/
struct Extraction_statistics
{
  double marching_time = 0, smoothing_time = 0;
};

/*!
  \ingroup PkgISMReconstruction3Ref
  \brief extracts the zero level of `function` by marching tetrahedra on the leaves of its
  triangulation, smooths it (Taubin lambda/mu), and writes it into `mesh`.

  Each crossed edge gives one shared vertex, so the surface is closed and 2-manifold by
  construction. `ism_surface_reconstruction()` calls it after
  `ISM_reconstruction_function::compute_implicit_function()`.

  \tparam TriangleMesh a model of `MutableFaceGraph` with an internal point property map
          whose value type is constructible from three `double`
  \param function a function on which `compute_implicit_function()` was called
  \param mesh receives the surface (added to what it already holds)
  \param smoothing_iterations the number of Taubin iterations, `0` for none
  \param lambda Taubin's lambda, the smoothing factor
  \param mu Taubin's mu, the inflating factor
  \param crossing_neighbors each vertex moves along its edge onto the quadric fitted to this
         many nearest input points (6 to 64); `0`: the linear zero crossing of the function
         (the paper), see the named parameter `crossing_neighbors`
  \return the times of the marching tetrahedra and of the smoothing
  \throws std::invalid_argument for an argument out of the range of the named parameter it
          mirrors (`smoothing_iterations`, `smoothing_lambda`, `smoothing_mu`, `crossing_neighbors`)
  \throws std::logic_error if `compute_implicit_function()` was not called, or did not
          complete (cancelled by its `callback`, or threw)
*/
template <class GeomTraits, class TriangleMesh>
Extraction_statistics extract_surface(const ISM_reconstruction_function<GeomTraits>& function, TriangleMesh& mesh,
                                      unsigned int smoothing_iterations, double lambda, double mu,
                                      unsigned int crossing_neighbors = Settings().crossing_neighbors);

namespace internal {

// extract_surface(), the mesh's points multiplied by 2^exponent (normalization.h)
template <class GeomTraits, class TriangleMesh>
Extraction_statistics extract_scaled_surface(const ISM_reconstruction_function<GeomTraits>& function, TriangleMesh& mesh,
                                             unsigned int smoothing_iterations, double lambda, double mu,
                                             unsigned int crossing_neighbors, int exponent)
{
  typedef typename boost::property_traits<
      typename boost::property_map<TriangleMesh, vertex_point_t>::type>::value_type Mesh_point;
  // the arguments are checked as the named parameters they mirror
  Settings arguments;
  arguments.smoothing_iterations = smoothing_iterations;
  arguments.smoothing_lambda = lambda;
  arguments.smoothing_mu = mu;
  arguments.crossing_neighbors = crossing_neighbors;
  arguments.check();
  // a cancelled or failed computation leaves no values: its leaves would be read past them
  if(!function.is_computed())
    throw std::logic_error("ISM reconstruction: extract_surface() needs a function whose compute_implicit_function() "
                           "completed (it was not called, was cancelled or failed)");
  Extraction_statistics stats;
  CGAL::Real_timer timer;
  timer.start();
  std::vector<std::array<double, 3> > points;
  std::vector<std::array<std::size_t, 3> > triangles;
  {
    // Only the leaves the surface crosses, in order (the others give no triangle), freed
    // before the mesh is built: all the leaves, 16 bytes each, made this the peak of the
    // tool (dragon, 437k points: 231 MB, now about 207 MB, as the topology and the tangent
    // planes).
    typedef typename ISM_reconstruction_function<GeomTraits>::Triangulation Triangulation;
    const Triangulation& tr = function.triangulation();
    const std::vector<double>& values = function.values();
    std::vector<std::array<double, 3> > vertices(tr.number_of_vertices());
    for(std::size_t v = 0; v < vertices.size(); ++v)
    {
      const auto& p = tr.point(int(v));
      vertices[v] = {{ to_double(p.x()), to_double(p.y()), to_double(p.z()) }};
    }
    std::vector<std::array<int, 4> > crossed;
    for(typename Triangulation::Cell_index c = 0; c < typename Triangulation::Cell_index(tr.number_of_cells()); ++c)
      if(tr.is_leaf(c))
      {
        const auto& v = tr.vertices(c);
        const bool inside = values[v[0]] < 0;
        if((values[v[1]] < 0) != inside || (values[v[2]] < 0) != inside || (values[v[3]] < 0) != inside)
          crossed.push_back(tr.positive_vertices(c));
      }
    if(crossing_neighbors == 0)
      internal::marching_tetrahedra(vertices, crossed, values, points, triangles);
    else
    {
      // the kd-tree of the function served its distances and was freed: a new one (5 ms at
      // 36k points)
      const std::vector<std::array<double, 3> >& input = function.input_points();
      const internal::Point_neighbors neighbors(input);
      internal::marching_tetrahedra(vertices, crossed, values, points, triangles,
                                    internal::Jet_crossing(input, neighbors, crossing_neighbors));
    }
  }
  stats.marching_time = timer.time();
  timer.reset();
  if(smoothing_iterations > 0)
    internal::taubin_smoothing(points, triangles, smoothing_iterations, lambda, mu);
  stats.smoothing_time = timer.time();
  std::vector<Mesh_point> mesh_points;
  mesh_points.reserve(points.size());
  for(const auto& p : points)
    mesh_points.push_back(Mesh_point(std::ldexp(p[0], exponent), std::ldexp(p[1], exponent), std::ldexp(p[2], exponent)));  // 2^0: exact
  std::vector<std::array<double, 3> >().swap(points);
  Polygon_mesh_processing::polygon_soup_to_polygon_mesh(mesh_points, triangles, mesh);
  return stats;
}

} // namespace internal

template <class GeomTraits, class TriangleMesh>
Extraction_statistics extract_surface(const ISM_reconstruction_function<GeomTraits>& function, TriangleMesh& mesh,
                                      unsigned int smoothing_iterations, double lambda, double mu,
                                      unsigned int crossing_neighbors)
{
  return internal::extract_scaled_surface(function, mesh, smoothing_iterations, lambda, mu, crossing_neighbors, 0);
}

} // namespace ISM_reconstruction_3

/*!
  \ingroup PkgISMReconstruction3Ref

  \brief reconstructs a closed, 2-manifold surface from `points`, which need no normals.

  The method estimates the in/out function of the points (see the user manual,
  \ref Chapter_ISM_Surface_Reconstruction): refinement of a binary multitriangulation of a
  box around the points with local PCA fitting, topology estimation by an Ising model
  solved by simulated annealing, distance estimation, then marching tetrahedra and Taubin
  smoothing. It builds an `ISM_reconstruction_function` and meshes it with
  `ISM_reconstruction_3::extract_surface()`. The output is closed and 2-manifold by
  construction; it may have several components, and handles, as the sampled surface.
  Points whose bounding box's largest side is outside [2^-32, 2^32) are reconstructed scaled
  by a power of two that brings it into [1, 2), and the surface scaled back: exact, so any
  extent a double holds gives the surface of the points at unit size, scaled.

  One of the package's own named parameters starts the chain and \cgal's follow, as in
  `parameters::maximum_depth(20).random_seed(7).point_map(pm)`; more of the package's wrap
  one another, each taking the rest of the chain as its last argument:
  `parameters::smoothing_iterations(3, parameters::crossing_neighbors(16, parameters::maximum_depth(20))).point_map(pm)`
  (\cgal 5.5's named-parameter class cannot take members of another package without editing
  its headers, so `.smoothing_lambda(...)` after a parameter does not compile).

  \tparam PointRange a model of `ConstRange` whose value type is the key type of the
          named parameter `point_map`
  \tparam TriangleMesh a model of `MutableFaceGraph` with an internal point property map
          whose value type is constructible from three `double`
  \tparam NamedParameters a sequence of named parameters

  \param points the input points
  \param mesh receives the surface (added to what it already holds)
  \param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{maximum_depth}
      \cgalParamDescription{the deepest level of a cell of the binary multitriangulation (the paper's maximum level). Edges halve every 3 levels: cells of level 24 are 2^8 = 256 times smaller than the box. When a few far outliers, or parts far apart, make the extent of all the points 2^k times that of their bulk (k >= 1), 3k levels are added, up to 48, so that one stray point does not coarsen the surface, nor two objects far apart each other (the statistic `added_levels`). The bulk is 98 % of the points or, if smaller, the largest group of points that lie together (at least 1 % of them, no gap wider than 1/32 of the extent).}
      \cgalParamType{`int`, in [1, 48]}
      \cgalParamDefault{`24`}
    \cgalParamNEnd
    \cgalParamNBegin{min_points_per_cell}
      \cgalParamDescription{a cell with fewer points is not bisected, and does not fit a plane to its own points: it takes the plane of that many points nearest them, or inherits the plane and coplanarity error of its parent (`sparse_cell_planes`; the paper uses 5 to 10)}
      \cgalParamType{`int`, in [3, 1000000]}
      \cgalParamDefault{`6`}
    \cgalParamNEnd
    \cgalParamNBegin{sparse_cell_planes}
      \cgalParamDescription{if `true`, a cell with fewer than `min_points_per_cell` points (but some) takes the plane and coplanarity error of the `min_points_per_cell` points nearest its points' centroid; `false`: it inherits its parent's (the paper). Where the points are sparse the parent is large and its plane a chord of the surface: across a thin part it put the tip outside. Measured on the bunny at 36k points with one half ten times sparser (the robustness bar: one component, genus 0, every query farther than 1 % of the diagonal on the right side): 172 of 180 samplings (seeds 21-200) instead of 165 (8 gained, 1 lost); with gaussian noise of 0.5 % of the diagonal 87 of 90 either way (the same misses)}
      \cgalParamType{Boolean}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{coarser_refinements}
      \cgalParamDescription{if the steps after the Ising signs leave no inside region, or more inside clusters than the signs had inside vertices (the signs saw almost nothing inside and the tangent planes made the inside in pieces), the computation is redone with twice `min_points_per_cell`, up to this many times (`Statistics::number_of_coarser_refinements`; `settings()` then holds the `min_points_per_cell` used), unless the coarser surface lies more than 3 times farther from the points (the median) than the finer one, which is then computed again; `0`: never (the paper). Few points are refined down to leaves as long as the object is thick: random points on a unit sphere, 120 to 400 of them, came out in one part on 19 of 60 samplings with leaves of 6 points, on 60 of 60 with this; the 36k bunny and the survey's meshes never trigger it}
      \cgalParamType{`int`, in [0, 10]}
      \cgalParamDefault{`2`}
    \cgalParamNEnd
    \cgalParamNBegin{coplanarity_threshold}
      \cgalParamDescription{a cell whose coplanarity error l0 / (l0 + l1 + l2) (l0 <= l1 <= l2 the eigenvalues of the covariance of its points) is below this is not bisected; `0`: only the depth and the number of points stop the refinement}
      \cgalParamType{`double`, in [0, 1/3)}
      \cgalParamDefault{`0`}
    \cgalParamNEnd
    \cgalParamNBegin{empty_cell_error}
      \cgalParamDescription{the error eps_empty of empty cells as a fraction t of [eps_min, eps_max], the range of the errors of the non-empty cells: empty cells couple their vertices with the weight 1 - t}
      \cgalParamType{`double`, in [0, 1]}
      \cgalParamDefault{`0.05`}
    \cgalParamNEnd
    \cgalParamNBegin{initial_temperature}
      \cgalParamDescription{the first temperature of an annealing from scratch (the first topology pass), in units of J, the mean absolute edge weight of the Ising energy}
      \cgalParamType{`double`, in (0, 1e6]}
      \cgalParamDefault{`15`}
    \cgalParamNEnd
    \cgalParamNBegin{warm_start_temperature}
      \cgalParamDescription{the first temperature, in units of J, of an annealing that starts from the previous signs: the passes during refinement, and the final pass after them}
      \cgalParamType{`double`, in (0, 1e6]}
      \cgalParamDefault{`3`}
    \cgalParamNEnd
    \cgalParamNBegin{cooling_factor}
      \cgalParamDescription{the ratio between the temperatures of two consecutive sweeps of the final annealing (the default goes from 3 J to 0.3 J in 100 sweeps)}
      \cgalParamType{`double`, in (0, 1]}
      \cgalParamDefault{`0.977`}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_sweeps}
      \cgalParamDescription{the number of sweeps of the final annealing, each visiting every vertex once}
      \cgalParamType{`int`, in [1, 100000]}
      \cgalParamDefault{`100`}
    \cgalParamNEnd
    \cgalParamNBegin{warm_start_interval}
      \cgalParamDescription{the number of bisections between two topology passes during refinement; `0`: a pass whenever the number of leaves doubled; `-1`: no pass during refinement}
      \cgalParamType{`long`, at least -1}
      \cgalParamDefault{`0`}
    \cgalParamNEnd
    \cgalParamNBegin{random_seed}
      \cgalParamDescription{the seed of the annealing: the result depends only on the input and the seed, not on the number of threads}
      \cgalParamType{`std::uint64_t`}
      \cgalParamDefault{`1`}
    \cgalParamNEnd
    \cgalParamNBegin{clamp_box_boundary}
      \cgalParamDescription{if `true`, the vertices of the box boundary are held outside during annealing; if `false`, they anneal freely and the global sign is fixed afterwards (the paper)}
      \cgalParamType{`bool`}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{minimum_island_fraction}
      \cgalParamDescription{after the annealing, a cluster of inside vertices smaller than this fraction of the largest inside cluster is set outside, and a cluster of outside vertices that does not reach the box boundary and is smaller than that is set inside; `0`: keep all}
      \cgalParamType{`double`, in [0, 1)}
      \cgalParamDefault{`0.01`}
    \cgalParamNEnd
    \cgalParamNBegin{thin_handle_depth}
      \cgalParamDescription{after the distances, a handle of the surface that only vertices nearer to the surface than this many times the size of the leaves it crosses (the median one, or the local one where the leaves are larger: a sparser sampling) hold open is removed: a sweep of the outside vertices, deepest first, moves inside each vertex near the surface that would close a loop of the outside (a tunnel through a thin plate is filled), then a sweep of the inside vertices moves outside such a vertex of the inside (a thin bridge is cut); `0`: keep all handles (the paper). Measured at 36k points with the default: the bunny has genus 0 on 13 of 13 samplings (7 of 13 without) and on 6 of 6 with 0.25 % and 0.5 % noise (2 of 6 without), 3torus genus 3 (8 without); the elephant of libcgal-demo loses its 3 thin handles}
      \cgalParamType{`double`, in [0, 10]}
      \cgalParamDefault{`0.2`}
    \cgalParamNEnd
    \cgalParamNBegin{tangent_plane_signs}
      \cgalParamDescription{after the distances and the handles, a vertex nearer to the points than 0.75 times the size of the leaves the surface crosses (the median, or the local one where the leaves are larger: a sparser sampling) takes the side of the tangent planes of its nearest points (PCA normals oriented by the in/out function, as `ism_orient_normals()` does) and its distance to them as value; islands and thin handles are then removed again; `false`: the Ising sign of every vertex (the paper). Measured at 36k points: no query farther than 1 % of the diagonal on the wrong side on 13 of 13 samplings of the bunny (8 of 13 without), mean distance 0.051 % of the diagonal instead of 0.075 %; on 21 meshes of libcgal-demo 14 such queries instead of 28, homer gains a handle}
      \cgalParamType{`bool`}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{surface_refinement_passes}
      \cgalParamDescription{after the signs, every leaf in which F misses one of its points by more than `surface_refinement_tolerance` times the leaf's longest edge, and by more than 3 times the median miss over all points (the noise), is bisected; a new vertex takes the value of F at its place, then its distance estimate and, near the points, the side of their tangent planes; this is repeated up to this many times, then as many times again on the leaves larger than 1.5 times the median leaf the surface crosses (the parts sampled more sparsely than the rest), those that miss a point and those the surface crosses whose four vertices are nearer to the points than half that size, then islands and thin handles are removed again; `0`: none (the paper). Measured on the bunny at 36k points, 13 samplings: mean distance 0.037-0.039 % of the diagonal instead of 0.055-0.059 %, queries farther than 1 % of the diagonal on the wrong side on 1 sampling instead of 3; with 0.25 % noise on 0 of 3 samplings instead of 2; no gain at 0.5 % noise; with one half ten times denser, the robustness bar met on 13 of 20 samplings instead of 10 by the passes on the larger leaves, and on 150 of 180 held-out samplings instead of 132 by also bisecting the crossed ones}
      \cgalParamType{`int`, in [0, 10]}
      \cgalParamDefault{`2`}
    \cgalParamNEnd
    \cgalParamNBegin{surface_refinement_tolerance}
      \cgalParamDescription{the miss of F at a point, relative to the longest edge of the leaf holding it, above which `surface_refinement_passes` bisects the leaf (0.1 left 2 of the 13 bunny samplings a far error, 0.05 one)}
      \cgalParamType{`double`, in (0, 1]}
      \cgalParamDefault{`0.05`}
    \cgalParamNEnd
    \cgalParamNBegin{escape_rays}
      \cgalParamDescription{after the surface refinement, every inside vertex of the leaves the surface crosses whose nearest point is farther than 0.4 times its voting radius (see `tangent_plane_signs`) casts this many rays, one pointing away from that point and the others 27 degrees around it; if they all leave the bounding box of the points without passing that near a point, the vertex is turned outside, and so on inwards; islands and thin handles are then removed again; `0`: never (the paper). This removes the slab of inside that the Ising signs put beside a part as thin as the leaves (the bunny's ears with noise). Measured on the bunny at 36k points with gaussian noise of 0.5 % of the diagonal, 5 samplings: 0 to 1 queries farther than 1 % of the diagonal on the wrong side instead of 1 to 9, genus 0 on 5 of 5 instead of 4 of 5; on 30 meshes of libcgal-demo every far query right on 21 instead of 18, none worse; about 0.1 s on the 437k-point dragon}
      \cgalParamType{`int`, in [0, 64]}
      \cgalParamDefault{`5`}
    \cgalParamNEnd
    \cgalParamNBegin{winding_number_signs}
      \cgalParamDescription{last, the vertices of the leaves the surface crosses are re-signed by the generalized winding number of the points (Barill et al. 2018; each point a disc of the area its 12 nearest points cover, its PCA normal oriented by F): an outside vertex farther from its nearest point than that point's spacing (the distance to its 12th nearest point) is turned inside where the winding number exceeds 0.6, an inside vertex farther than 0.3 times the spacing is turned outside where it is below 0.2, and so on inwards; then, in a second stage, outside vertices down to a quarter of the spacing are turned inside likewise. A group of re-signed vertices that would add a handle keeps its signs, and a stage that lowers the Euler characteristic of the surface once islands and thin handles are removed again is undone. This fills the pockets of outside, a few leaves deep, that all local tests confirm where the points are sparse or two walls are close; `false`: never (the paper). Measured on the bunny at 36k points (every query farther than 1 % of the diagonal on the right side and genus 0): one half ten times denser, 10 of 20 samplings instead of 0; gaussian noise of 0.5 % of the diagonal, 16 of 20 instead of 10; 0.25 %, 10 of 10 instead of 7; clean and with 1 % outliers, 5 of 5 either way; with the cut reaching 0.3 spacing (1 before) at w below 0.2 (0.3), over seeds 21-200 of these samplings, 0.5 % noise 168 of 180 instead of 152, one half ten times denser 132 instead of 127; about 0.15 s on 36k points}
      \cgalParamType{Boolean}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{join_islands}
      \cgalParamDescription{last, every inside cluster of vertices but the largest is joined to another inside cluster across one or two outside vertices, those of least |F| (nearest to the points), if that lowers the number of components of the surface by one and adds no handle, and if each bridge vertex lies among the points (no farther from its nearest point than that point is from its 6th nearest); a cluster farther than that, about two to three point spacings, stays a component of its own, however large the leaves between them (two unit spheres 0.5 apart, 8,000 points: two components; before this condition, one). This joins back a part cut off at a neck too thin for the leaves where the points are sparse; `false`: never (the paper). Measured on the bunny, 20 samplings each: one component (and genus 0) on 20 of 20 at 3,000 points instead of 11, 20 instead of 19 at 4,000 and 6,000, 19 instead of 18 at 8,000 (the last one has genus 1 either way); at 36k points, 160 samplings with 0.5 % noise or one half ten times denser and the meshes of test_reconstruction (two spheres, nested spheres): the same output}
      \cgalParamType{Boolean}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{merge_point_clusters}
      \cgalParamDescription{first of all, if more than 30 % of the points (judged on about 1,000 of them) have their nearest points, up to some j of at most 31, more than 4 times closer than the next one, each such cluster of copies, with the clusters sharing points with it, is replaced by its centroid (`statistics().number_of_merged_points`); `false`: never (the paper). Several scans along the same beams, or points written again with rounding, give such clouds; the refinement counts points, not samples, so a cell holding one cluster was bisected down to the deepest level, and the planes of the nearest points saw one sample: 5,000 random directions on a sphere, each 8 times with radial noise 1e-4, came out in 470 pieces (one with this), 4 times with radial noise 1e-3 in 13 pieces of genus 21 (one, genus 0), 9,000 points of the bunny 4 times (noise 1e-4 of the diagonal) with genus 10 (0), 2,000 points 20 times jittered by 1e-12 in 21 pieces (one). Samplings without copies stay far below the 30 %: at most 8 % over the 30 meshes of the survey (close pairs), 2 % with 0.5 % noise; their points are kept as they are}
      \cgalParamType{Boolean}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{remove_isolated_points}
      \cgalParamDescription{first, the points whose 12 nearest points spread more than 20 times farther than the median point's are left out of the whole computation (stray returns of a scanner far from the surface: samples of a surface stay below 2 where uniform, below 5 with one half ten times sparser); `false`: never (the paper). Every stage took such points for the surface: 200 points spread 1 to 2 diagonals around a scanned bunny (76k points) made a shell whose inside held the bunny's outside, and the output was their hull (13,652 of 20k queries on the wrong side, 0 with); clutter in a box 3 times the object's, 0.4 % of the points, 680 (0 with); the 36k bunny with 360 points 1 to 2 diagonals around (`robustness_outliers_far`, samplings 1-20): the robustness bar (one component, genus 0, every query farther than 1 % of the diagonal on the right side) met on 20 instead of 11; with 1 % uniform outliers in the box, of which 3 to 7 are isolated, samplings 21-100: 80 instead of 79; noisy and non-uniform samplings of the surface have no isolated point (unchanged)}
      \cgalParamType{Boolean}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{point_smoothing_iterations}
      \cgalParamDescription{before the refinement, if the points are noisy (`point_smoothing_noise`), each point is moved along the normal of its neighbours' PCA plane onto a quadric fitted by least squares to its `point_smoothing_neighbors` nearest points (jet smoothing), this many times where the points are dense for their noise (their `point_smoothing_neighbors` nearest points reach less than 2.7 times its deviation), once where they are not (the passes made: `statistics().number_of_point_smoothing_passes`): there further passes pull the two walls of a thin part onto one sheet (the bunny's own 37,706 vertices with gaussian noise of 0.5 % of the diagonal: the robustness bar met on 25 of 30 samplings with one pass, 17 with three); `0`: never (the paper). Measured on the bunny at 36k points with gaussian noise of 0.5 % of the diagonal, 6 samplings: 14 queries farther than 1 % of the diagonal on the wrong side in all instead of 221, mean distance 0.124-0.130 % of the diagonal instead of 0.24-0.27 %, genus 1 on one sampling instead of two; clean points and noise up to about 0.2 % are left as they are (see `point_smoothing_noise`)}
      \cgalParamType{`int`, in [0, 100]}
      \cgalParamDefault{`3`}
    \cgalParamNEnd
    \cgalParamNBegin{point_smoothing_neighbors}
      \cgalParamDescription{the number of nearest points (the point itself included) a point's quadric is fitted to (36 did worse than 24 on 36k points at 0.5 % noise); more, up to 64, where the points are dense for their noise, so that the neighbours reach 2.7 times the noise's sigma (the bunny with 0.5 % noise: 24 at 36k points, 35 at 100k, 52 at 300k, where 24 left the output on the noise's outer shell); the number taken is `statistics().number_of_point_smoothing_neighbors`}
      \cgalParamType{`int`, in [6, 64]}
      \cgalParamDefault{`24`}
    \cgalParamNEnd
    \cgalParamNBegin{point_smoothing_noise}
      \cgalParamDescription{the points are smoothed only if the median coplanarity error of the 12 nearest points of a point exceeds this: about 0.001 for clean scans (bunny 0.0007, dragon 0.005), 0.02 with gaussian noise of 0.1 % of the diagonal, 0.08 with 0.25 %, 0.13 with 0.5 %; `0`: always. The default smooths 0.25 % noise and leaves 0.15 % (0.1 until session 25: at 0.25 % the smoothing had left the bunny a handle on 2 of 4 samplings, which the later stages now remove): on 100 samplings of the bunny at 0.25 % noise the robustness bar (genus 0, every query farther than 1 % of the diagonal right) is met on 99 instead of 95, mean distance 0.066 % of the diagonal instead of 0.105 %}
      \cgalParamType{`double`, in [0, 1/3)}
      \cgalParamDefault{`0.06`}
    \cgalParamNEnd
    \cgalParamNBegin{distance_estimate}
      \cgalParamDescription{how the value of a vertex (its sign times a distance) is estimated}
      \cgalParamType{`CGAL::ISM_reconstruction_3::Distance_estimate`}
      \cgalParamDefault{`CGAL::ISM_reconstruction_3::LOCAL_PLANE_DISTANCE`}
    \cgalParamNEnd
    \cgalParamNBegin{box_margin}
      \cgalParamDescription{the margin between the points and the box, as a fraction of the largest extent of the points}
      \cgalParamType{`double`, in (0, 10]}
      \cgalParamDefault{`0.1`}
    \cgalParamNEnd
    \cgalParamNBegin{crossing_neighbors}
      \cgalParamDescription{the vertex of the output on a crossed leaf edge moves along the edge onto the quadric fitted by least squares to this many nearest points (the fit of the jet smoothing, two linearised steps), unless the edge is within 6 degrees of tangent to the quadric, the move is longer than half the distance to the k-th nearest point, or it ends 1.5 times farther from the nearest point than it started; every vertex stays on its edge, so the triangles, the topology and the absence of self-intersections are those of the linear crossings; `0`: the linear zero crossing of F (the paper). Measured on the bunny at 36k points, 20 samplings each: mean distance to the truth 0.022 % of the diagonal instead of 0.037 % (clean), 0.021 % instead of 0.035 % (1 % outliers), 0.047 % instead of 0.074 % (one half ten times denser), the same with gaussian noise; the bar (genus 0, every query farther than 1 % of the diagonal right) met on 15 of 20 samplings instead of 13 with one half denser, 20 instead of 19 at 0.5 % noise; every far query right on 27 of the 30 meshes of the survey instead of 25. About 0.04 s at 36k points on 2 threads}
      \cgalParamType{`unsigned int`, `0` or in [6, 64]}
      \cgalParamDefault{`12`}
    \cgalParamNEnd
    \cgalParamNBegin{smoothing_iterations}
      \cgalParamDescription{the number of Taubin lambda/mu iterations on the output mesh; `0`: no smoothing (the default: on the irregular triangles of marching tetrahedra, 3 iterations folded 851 edges of the bunny by more than 120 degrees, against 17 unsmoothed, without improving the distance to the truth)}
      \cgalParamType{`unsigned int`, in [0, 10000], and such that the filter's largest gain per iteration, max over k in [0, 2] of |(1 - lambda k)(1 - mu k)|, raised to this power stays within 1.1 (Taubin's filter lifts the low frequencies slightly: with the default lambda and mu, at most 1.00085, so at most 112 iterations; 10,000 of them blew a sphere up to 126 times its radius); beyond, `std::invalid_argument` says how many are allowed}
      \cgalParamDefault{`0`}
    \cgalParamNEnd
    \cgalParamNBegin{smoothing_lambda}
      \cgalParamDescription{Taubin's lambda, the smoothing factor}
      \cgalParamType{`double`, in [-1, 1], and with `smoothing_mu` a filter whose gain |(1 - lambda k)(1 - mu k)| stays below 1.01 for k in [0, 2] (else it diverges: lambda = 1 with the default mu is refused) and with 0 < lambda < -mu (else every frequency shrinks, the shape's too: lambda = mu = 1 made the bunny a point), checked when `smoothing_iterations` > 0}
      \cgalParamDefault{`0.5`}
    \cgalParamNEnd
    \cgalParamNBegin{smoothing_mu}
      \cgalParamDescription{Taubin's mu, the inflating factor}
      \cgalParamType{`double`, in [-1, 1]}
      \cgalParamDefault{`-0.53`}
    \cgalParamNEnd
    \cgalParamNBegin{memory_limit}
      \cgalParamDescription{the number of bytes the reconstruction may add to what the process already holds; `0`: what the machine allows, the least of the physical memory, the limits `RLIMIT_AS` (`ulimit -v`) and `RLIMIT_DATA` (`ulimit -d`) and the cgroup memory limits (on Linux; no limit elsewhere). The memory is estimated up front from the number of points, then whenever the number of cells grew by 1/8 (64 MiB + 160 bytes per point + 160 bytes per cell, measured at the peak of the whole method with some margin); beyond the limit, `std::length_error` is thrown before the allocation, with the memory needed and available in its message. A value larger than what the machine allows does not raise that.}
      \cgalParamType{`std::size_t`}
      \cgalParamDefault{`0`}
    \cgalParamNEnd
    \cgalParamNBegin{paper_settings}
      \cgalParamDescription{if `true`, every parameter not given takes the value of the paper instead of the default above (`ISM_reconstruction_3::Settings::paper()`: `min_points_per_cell(8)`, `sparse_cell_planes(false)`, `coarser_refinements(0)`, `coplanarity_threshold(1e-3)`, `warm_start_interval(1000)`, `clamp_box_boundary(false)`, `minimum_island_fraction(0)`, `thin_handle_depth(0)`, `tangent_plane_signs(false)`, `surface_refinement_passes(0)`, `escape_rays(0)`, `winding_number_signs(false)`, `join_islands(false)`, `remove_isolated_points(false)`, `merge_point_clusters(false)`, `point_smoothing_iterations(0)`, `crossing_neighbors(0)`, `smoothing_iterations(3)`, `distance_estimate(NEAREST_POINT_SQUARED_DISTANCE)`)}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
    \cgalParamNBegin{callback}
      \cgalParamDescription{a function called with the progress, in [0, 1]; if it returns `false`, the reconstruction stops and the function returns `false`}
      \cgalParamType{`std::function<bool(double)>`}
      \cgalParamDefault{an empty function: no callback}
    \cgalParamNEnd
    \cgalParamNBegin{point_map}
      \cgalParamDescription{a property map associating points to the elements of the point range}
      \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type of the iterator of `PointRange` and whose value type is `geom_traits::Point_3`}
      \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`}
    \cgalParamNEnd
    \cgalParamNBegin{geom_traits}
      \cgalParamDescription{an instance of a geometric traits class}
      \cgalParamType{a model of `ISMReconstructionTraits_3`}
      \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \return `false` if the `callback` cancelled the run, `true` otherwise.
  \throws std::invalid_argument for bad input (no points, a non-finite coordinate, too few
          distinct points, all points on a plane or a line) or a parameter out of range
  \throws std::runtime_error if no inside region was found, or far outliers make the box too
          large for the bulk of the points to be resolved (remove them first)
  \throws std::length_error, before the allocation, if the points or the refinement would need
          more memory than the process may use (`memory_limit`)

  \sa `ISM_reconstruction_function`
  \sa `ISM_reconstruction_3::Settings`
*/
template <class PointRange, class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
bool ism_surface_reconstruction(const PointRange& points, TriangleMesh& mesh,
                                const NamedParameters& np = parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits Geom_traits;
  const ISM_reconstruction_3::Settings settings = ISM_reconstruction_3::settings_from_parameters(np);
  // points far from unit size are reconstructed scaled by 2^e, exactly (normalization.h)
  const int e = ISM_reconstruction_3::internal::normalizing_exponent(points, NP_helper::get_const_point_map(points, np));
  ISM_reconstruction_function<Geom_traits> function =
      ISM_reconstruction_3::internal::normalized_function<Geom_traits>(points, np, e);
  if(!function.compute_implicit_function_with_settings(settings))
    return false;
  ISM_reconstruction_3::internal::extract_scaled_surface(function, mesh, settings.smoothing_iterations,
                                                         settings.smoothing_lambda, settings.smoothing_mu,
                                                         settings.crossing_neighbors, -e);
  return true;
}

} // namespace CGAL

#endif // CGAL_ISM_SURFACE_RECONSTRUCTION_H
