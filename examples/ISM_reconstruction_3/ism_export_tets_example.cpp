// Exports the tetrahedral mesh behind a reconstruction: the leaves of the binary
// multitriangulation, with the in/out sign and the signed distance estimate at every
// vertex, to a VTK .vtu file (open it in ParaView; clip by "sign" to see the inside).
//
// Usage: ism_export_tets_example [points.xyz|.ply|.off]   (default: the bunny's vertices)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>

#include <CGAL/ISM_reconstruction_function.h>
#include <CGAL/ISM_reconstruction_3/IO/tet_mesh_io.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::ISM_reconstruction_function<Kernel> ISM_function;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/bunny00.off");
  std::vector<Point> points;
  if(!CGAL::IO::read_points(filename, std::back_inserter(points)))
  {
    std::cerr << "Error: cannot read points from " << filename << std::endl;
    return EXIT_FAILURE;
  }

  try
  {
    ISM_function function(points);
    // a shallower triangulation than the default keeps the file small
    function.compute_implicit_function(CGAL::parameters::maximum_depth(18));

    const ISM_function::Triangulation& tr = function.triangulation();
    // the leaves as positively oriented tetrahedra on the triangulation's vertices
    const std::vector<std::array<ISM_function::Vertex_index, 4> > tets = tr.leaf_tetrahedra();

    // per-vertex fields: the sign (-1 inside, +1 outside) and the value f(v) (the sign
    // times the distance estimate)
    std::vector<CGAL::IO::Tet_mesh_vertex_field> fields;
    fields.emplace_back("sign", std::vector<double>(function.signs().begin(), function.signs().end()));
    fields.emplace_back("distance", function.values());

    if(!CGAL::IO::write_tet_mesh("ism_tets.vtu", tr.points(), tets, fields))
    {
      std::cerr << "Error: cannot write ism_tets.vtu" << std::endl;
      return EXIT_FAILURE;
    }
    const std::size_t inside = std::count(function.signs().begin(), function.signs().end(), -1);
    std::cout << tets.size() << " tetrahedra, " << tr.number_of_vertices() << " vertices (" << inside
              << " inside) written to ism_tets.vtu" << std::endl;
  }
  catch(const std::exception& e)  // bad points, or no inside found
  {
    std::cerr << "Error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
