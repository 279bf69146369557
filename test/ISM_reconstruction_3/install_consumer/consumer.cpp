// Builds against the installed headers only: a BMT and a small reconstruction.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/ism_surface_reconstruction.h>
#include <cmath>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

int main()
{
  CGAL::Bisection_triangulation_3<K> bt(K::Iso_cuboid_3(K::Point_3(0, 0, 0), K::Point_3(1, 1, 1)));
  bt.refine_uniformly(3);
  std::vector<K::Point_3> points;
  for(int i = 0; i < 60; ++i)
    for(int j = 0; j < 30; ++j)
    {
      const double u = 2 * M_PI * i / 60, v = M_PI * (j + 0.5) / 30;
      points.push_back(K::Point_3(std::cos(u) * std::sin(v), std::sin(u) * std::sin(v), std::cos(v)));
    }
  CGAL::Surface_mesh<K::Point_3> mesh;
  CGAL::ism_surface_reconstruction(points, mesh, CGAL::parameters::maximum_depth(18));
  std::cout << bt.number_of_leaves() << " leaves, " << mesh.number_of_faces() << " faces\n";
  return (bt.number_of_leaves() == 48 && CGAL::is_closed(mesh) && mesh.number_of_faces() > 0) ? 0 : 1;
}
