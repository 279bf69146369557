// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_SURFACE_RECONSTRUCTION_H
#define CGAL_ISM_SURFACE_RECONSTRUCTION_H

#include <CGAL/ISM_reconstruction_function.h>
#include <CGAL/ISM_reconstruction_3/internal/marching_tetrahedra.h>
#include <CGAL/ISM_reconstruction_3/internal/taubin_smoothing.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {

/// Times of the surface extraction stages (seconds).
struct Extraction_statistics
{
  double marching_time = 0, smoothing_time = 0;
};

/*!
  \ingroup PkgISMReconstruction3Ref
  Extracts the zero level of `function` by marching tetrahedra on the leaves of its
  triangulation, smooths it (Taubin lambda/mu), and writes it into `mesh`. Each crossed
  edge gives one shared vertex, so the surface is closed and 2-manifold by construction.
*/
template <class GeomTraits, class TriangleMesh>
Extraction_statistics extract_surface(const ISM_reconstruction_function<GeomTraits>& function, TriangleMesh& mesh,
                                      unsigned int smoothing_iterations, double lambda, double mu)
{
  typedef typename boost::property_traits<
      typename boost::property_map<TriangleMesh, vertex_point_t>::type>::value_type Mesh_point;
  Extraction_statistics stats;
  CGAL::Real_timer timer;
  timer.start();
  const auto& tr = function.triangulation();
  std::vector<std::array<double, 3> > vertices(tr.number_of_vertices());
  for(std::size_t v = 0; v < vertices.size(); ++v)
  {
    const auto& p = tr.point(int(v));
    vertices[v] = {{ to_double(p.x()), to_double(p.y()), to_double(p.z()) }};
  }
  const std::vector<std::array<int, 4> > tets = tr.leaf_tetrahedra();
  std::vector<std::array<double, 3> > points;
  std::vector<std::array<std::size_t, 3> > triangles;
  internal::marching_tetrahedra(vertices, tets, function.values(), points, triangles);
  stats.marching_time = timer.time();
  timer.reset();
  if(smoothing_iterations > 0)
    internal::taubin_smoothing(points, triangles, smoothing_iterations, lambda, mu);
  stats.smoothing_time = timer.time();
  std::vector<Mesh_point> mesh_points;
  mesh_points.reserve(points.size());
  for(const auto& p : points) mesh_points.push_back(Mesh_point(p[0], p[1], p[2]));
  Polygon_mesh_processing::polygon_soup_to_polygon_mesh(mesh_points, triangles, mesh);
  return stats;
}

} // namespace ISM_reconstruction_3

/*!
  \ingroup PkgISMReconstruction3Ref

  Reconstructs a closed, 2-manifold surface from `points` (no normals) by the in/out
  function of the paper: BMT refinement with local PCA fitting, Ising topology estimation
  by simulated annealing, distance estimation, marching tetrahedra and Taubin smoothing.

  \tparam PointRange a model of `ConstRange` whose value type is a point or holds one through `point_map`
  \tparam TriangleMesh a model of `MutableFaceGraph`

  \param points the input points
  \param mesh receives the surface (appended to what it holds)
  \param np an optional sequence of named parameters among the ones listed below:
  `maximum_depth`, `min_points_per_cell`, `coplanarity_threshold`, `empty_cell_error`,
  `initial_temperature`, `cooling_factor`, `number_of_sweeps`, `warm_start_interval`,
  `random_seed`, `smoothing_iterations`, `smoothing_lambda`, `smoothing_mu`,
  `clamp_box_boundary`, `distance_estimate`, `box_margin`, `paper_settings`, `callback`,
  `point_map`, `geom_traits` (see the reference manual for their meaning and defaults).

  \return `false` if the `callback` cancelled the run, `true` otherwise.
  \throws std::invalid_argument for bad input or a parameter out of range
  \throws std::runtime_error if no inside region was found
*/
template <class PointRange, class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
bool ism_surface_reconstruction(const PointRange& points, TriangleMesh& mesh,
                                const NamedParameters& np = parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits Geom_traits;
  ISM_reconstruction_function<Geom_traits> function(points, np);
  const ISM_reconstruction_3::Settings settings = ISM_reconstruction_3::settings_from_parameters(np);
  if(!function.compute_implicit_function_with_settings(settings))
    return false;
  ISM_reconstruction_3::extract_surface(function, mesh, settings.smoothing_iterations, settings.smoothing_lambda,
                                        settings.smoothing_mu);
  return true;
}

} // namespace CGAL

#endif // CGAL_ISM_SURFACE_RECONSTRUCTION_H
