// Reconstructs a closed surface from points without normals with
// CGAL::ism_surface_reconstruction() and writes it to an OFF file.
//
// Usage: ism_reconstruction_example [points.xyz|.ply|.off]   (default: the bunny's vertices)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/ism_surface_reconstruction.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/bunny00.off");

  // Reads the points (for a mesh file, its vertices); normals, if any, are not needed.
  std::vector<Point> points;
  if(!CGAL::IO::read_points(filename, std::back_inserter(points)))
  {
    std::cerr << "Error: cannot read points from " << filename << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << points.size() << " points read from " << filename << std::endl;

  // The package's own parameters come first; CGAL's (random_seed, callback, point_map,
  // ...) chain after them.
  Mesh mesh;
  try
  {
    int reported = -1;
    CGAL::ism_surface_reconstruction(points, mesh,
                                     CGAL::parameters::maximum_depth(24)
                                         .random_seed(1)
                                         .callback([&reported](double progress) {
                                           const int percent = int(100 * progress);
                                           if(percent / 25 != reported / 25)
                                             std::cout << "progress: " << percent << " %" << std::endl;
                                           reported = percent;
                                           return true;  // false would cancel the reconstruction
                                         }));
  }
  catch(const std::exception& e)  // bad points or parameters, or no inside found
  {
    std::cerr << "Error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }

  std::cout << "surface: " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces" << std::endl;
  if(!CGAL::IO::write_polygon_mesh("ism_reconstruction.off", mesh, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "Error: cannot write ism_reconstruction.off" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "written to ism_reconstruction.off" << std::endl;
  return EXIT_SUCCESS;
}
