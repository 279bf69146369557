// Refines a Bisection_triangulation_3 (a binary multitriangulation) around a point set
// until no leaf holds more than a few points, then walks its leaves and their adjacency.
//
// Usage: bisection_triangulation_example [points.xyz|.ply|.off]   (default: the bunny's vertices)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/bounding_box.h>

#include <CGAL/Bisection_triangulation_3.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef Kernel::Iso_cuboid_3 Iso_cuboid;
typedef CGAL::Bisection_triangulation_3<Kernel> BMT;
typedef BMT::Cell_index Cell_index;
typedef BMT::Vertex_index Vertex_index;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/bunny00.off");
  std::vector<Point> points;
  if(!CGAL::IO::read_points(filename, std::back_inserter(points)) || points.empty())
  {
    std::cerr << "Error: cannot read points from " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // A box around the points with a 10% margin, split into 6 tetrahedra.
  const Iso_cuboid bbox = CGAL::bounding_box(points.begin(), points.end());
  const Vector margin = 0.1 * (bbox.max() - bbox.min());
  BMT tr(Iso_cuboid(bbox.min() - margin, bbox.max() + margin));

  // Each cell owns the indices of the points it holds; on_bisect hands them to the
  // children (child_side() tells on which side of the bisecting plane a point lies).
  std::vector<std::vector<std::size_t> > points_in(6);
  for(std::size_t i = 0; i < points.size(); ++i)
    points_in[std::size_t(tr.locate(points[i]))].push_back(i);

  const std::size_t max_points_per_leaf = 10;
  const int max_level = 30;
  tr.refine([&](Cell_index c) { return points_in[std::size_t(c)].size() > max_points_per_leaf; },
            max_level,
            [&](Cell_index parent, Cell_index c0, Cell_index c1) {
              points_in.resize(tr.number_of_cells());
              for(std::size_t i : points_in[std::size_t(parent)])
                points_in[std::size_t(tr.child_side(parent, points[i]) == 0 ? c0 : c1)].push_back(i);
              std::vector<std::size_t>().swap(points_in[std::size_t(parent)]);
            });

  // Walk the leaves: levels, face neighbours (-1 on the box boundary), symmetry of adjacency.
  const std::vector<Cell_index> leaves = tr.leaves();
  std::map<int, std::size_t> leaves_per_level;
  std::size_t boundary_faces = 0, interior_faces = 0, non_empty = 0;
  bool symmetric = true;
  for(Cell_index c : leaves)
  {
    ++leaves_per_level[tr.level(c)];
    if(!points_in[std::size_t(c)].empty()) ++non_empty;
    for(int i = 0; i < 4; ++i)
    {
      const Cell_index n = tr.neighbor(c, i);
      if(n < 0) { ++boundary_faces; continue; }
      ++interior_faces;
      bool back = false;  // n must see c across the same face
      for(int j = 0; j < 4; ++j) back = back || tr.neighbor(n, j) == c;
      symmetric = symmetric && back && tr.is_leaf(n);
    }
  }
  const std::size_t faces = boundary_faces + interior_faces / 2;
  const std::size_t edges = tr.edges().size();

  // The leaves around an edge and around every vertex.
  std::vector<Cell_index> ring;
  tr.leaves_around_edge(leaves.front(), 0, 1, std::back_inserter(ring));
  std::vector<std::size_t> offsets;
  std::vector<Cell_index> incident;
  tr.leaves_around_vertices(offsets, incident);
  std::size_t max_valence = 0;
  for(std::size_t v = 0; v + 1 < offsets.size(); ++v) max_valence = (std::max)(max_valence, offsets[v + 1] - offsets[v]);

  // Point location descends the cell tree in O(level).
  const Cell_index holder = tr.locate(points.front());

  std::cout << points.size() << " points from " << filename << "\n"
            << "cells " << tr.number_of_cells() << ", leaves " << leaves.size() << " (" << non_empty
            << " holding points), vertices " << tr.number_of_vertices() << ", edges " << edges << ", faces " << faces
            << " (" << boundary_faces << " on the box boundary)\n"
            << "Euler characteristic V - E + F - T = "
            << long(tr.number_of_vertices()) - long(edges) + long(faces) - long(leaves.size()) << " (1 for a ball)\n"
            << "face adjacency symmetric: " << (symmetric ? "yes" : "NO") << "\n"
            << "leaves around edge 0-1 of leaf " << leaves.front() << ": " << ring.size() << "\n"
            << "largest number of leaves around a vertex: " << max_valence << "\n"
            << "the first point lies in leaf " << holder << " of level " << tr.level(holder) << "\n"
            << "leaves per level:";
  for(const auto& l : leaves_per_level) std::cout << " " << l.first << ":" << l.second;
  std::cout << std::endl;
  return symmetric ? EXIT_SUCCESS : EXIT_FAILURE;
}
