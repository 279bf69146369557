// Builds the implicit function of a point set without normals
// (CGAL::ISM_reconstruction_function) and meshes its zero level with CGAL's surface
// mesher, exactly as CGAL's poisson_reconstruction_example.cpp does with a
// Poisson_reconstruction_function.
//
// Usage: ism_surface_mesher_example [points.xyz|.ply|.off]   (default: the bunny's vertices)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_default_triangulation_3.h>
#include <CGAL/make_surface_mesh.h>
#include <CGAL/Implicit_surface_3.h>
#include <CGAL/IO/facets_in_complex_2_to_triangle_mesh.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/compute_average_spacing.h>

#include <CGAL/ISM_reconstruction_function.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::FT FT;
typedef Kernel::Point_3 Point;
typedef Kernel::Sphere_3 Sphere;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::ISM_reconstruction_function<Kernel> ISM_function;
typedef CGAL::Surface_mesh_default_triangulation_3 STr;
typedef CGAL::Surface_mesh_complex_2_in_triangulation_3<STr> C2t3;
typedef CGAL::Implicit_surface_3<Kernel, ISM_function> Surface_3;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/bunny00.off");

  // Surface mesher options, relative to the average spacing of the points (as for Poisson)
  const FT sm_angle = 20.0;     // min triangle angle in degrees
  const FT sm_radius = 30;      // max triangle size
  const FT sm_distance = 0.375; // surface approximation error

  std::vector<Point> points;
  if(!CGAL::IO::read_points(filename, std::back_inserter(points)))
  {
    std::cerr << "Error: cannot read points from " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // The implicit function: negative inside, positive outside, defined in the whole box
  // around the points (and positive beyond it). No normals are needed.
  try
  {
    ISM_function function(points);
    if(!function.compute_implicit_function(CGAL::parameters::random_seed(1)))
      return EXIT_FAILURE;  // only a callback can cancel

    const FT average_spacing = CGAL::compute_average_spacing<CGAL::Sequential_tag>(points, 6);

    // a point inside, and a sphere around the points, centred at it
    const Point inner_point = function.get_inner_point();
    const Sphere bsphere = function.bounding_sphere();
    const FT radius = std::sqrt(bsphere.squared_radius());
    const FT sm_sphere_radius = 5.0 * radius;
    const FT sm_dichotomy_error = sm_distance * average_spacing / 1000.0;  // << sm_distance
    // The surface holds a copy of the function (copies share the triangulation).
    Surface_3 surface(function, Sphere(inner_point, sm_sphere_radius * sm_sphere_radius),
                      sm_dichotomy_error / sm_sphere_radius);

    CGAL::Surface_mesh_default_criteria_3<STr> criteria(sm_angle, sm_radius * average_spacing,
                                                        sm_distance * average_spacing);
    STr tr;
    C2t3 c2t3(tr);
    CGAL::make_surface_mesh(c2t3, surface, criteria, CGAL::Manifold_with_boundary_tag());
    if(tr.number_of_vertices() == 0)
    {
      std::cerr << "Error: the surface mesher found no surface" << std::endl;
      return EXIT_FAILURE;
    }

    Mesh mesh;
    CGAL::facets_in_complex_2_to_triangle_mesh(c2t3, mesh);
    std::cout << "surface mesher: " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces (from "
              << function.statistics().number_of_leaves << " leaves)" << std::endl;
    if(!CGAL::IO::write_polygon_mesh("ism_surface_mesher.off", mesh, CGAL::parameters::stream_precision(17)))
    {
      std::cerr << "Error: cannot write ism_surface_mesher.off" << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << "written to ism_surface_mesher.off" << std::endl;
  }
  catch(const std::exception& e)  // bad points, or no inside found
  {
    std::cerr << "Error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
