// Orients unoriented normals with the in/out function of the points
// (CGAL::ism_orient_normals()) and feeds them to CGAL's Poisson surface reconstruction.
// Compared with the usual jet_estimate_normals() + mst_orient_normals() pipeline, the
// orientation comes from a global in/out decision, so it does not flip across thin parts,
// close components or nested shells.
//
// Usage: ism_orient_normals_poisson_example [points.xyz|.ply|.off]   (default: the bunny's vertices)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/poisson_surface_reconstruction.h>
#include <CGAL/property_map.h>

#include <CGAL/ism_orient_normals.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef std::pair<Point, Vector> Point_with_normal;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;
typedef CGAL::Surface_mesh<Point> Mesh;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/bunny00.off");

  // Reads the points only: whatever normals the file has are not used.
  std::vector<Point_with_normal> points;
  if(!CGAL::IO::read_points(filename, std::back_inserter(points), CGAL::parameters::point_map(Point_map())))
  {
    std::cerr << "Error: cannot read points from " << filename << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << points.size() << " points read from " << filename << std::endl;

  // 1. Unoriented normals, from a local jet fit of the 18 nearest points. (Alternatively,
  //    CGAL::parameters::estimate_normals(true, np) below, np the chain given there,
  //    estimates them by PCA.)
  CGAL::jet_estimate_normals<CGAL::Parallel_if_available_tag>(
      points, 18, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));

  // 2. Orientation by the in/out function. The reconstruction's parameters (maximum_depth,
  //    random_seed, callback, ...) pass through; the points it could not orient are moved to
  //    the end of the range, as with mst_orient_normals(), and removed here.
  std::vector<Point_with_normal>::iterator unoriented_begin;
  try
  {
    unoriented_begin = CGAL::ism_orient_normals(
        points, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()).random_seed(1));
  }
  catch(const std::exception& e)  // bad points or parameters
  {
    std::cerr << "Error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << (points.end() - unoriented_begin) << " point(s) could not be oriented and are removed" << std::endl;
  points.erase(unoriented_begin, points.end());
  if(points.empty())
  {
    std::cerr << "Error: no normal could be oriented" << std::endl;
    return EXIT_FAILURE;
  }

  // 3. Poisson surface reconstruction from the oriented points.
  const double spacing = CGAL::compute_average_spacing<CGAL::Parallel_if_available_tag>(
      points, 6, CGAL::parameters::point_map(Point_map()));
  Mesh mesh;
  if(!CGAL::poisson_surface_reconstruction_delaunay(points.begin(), points.end(), Point_map(), Normal_map(), mesh,
                                                    spacing))
  {
    std::cerr << "Error: Poisson reconstruction failed" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "surface: " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces" << std::endl;
  if(!CGAL::IO::write_polygon_mesh("ism_orient_normals_poisson.off", mesh, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "Error: cannot write ism_orient_normals_poisson.off" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "written to ism_orient_normals_poisson.off" << std::endl;
  return EXIT_SUCCESS;
}
