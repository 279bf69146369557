// Computes the data behind the figures of the ISM_reconstruction_3 user manual, with the
// package itself, from real data (libcgal-demo's bunny00.off and knot1.off).
//
//   make_figure_data <meshes dir> <output dir>
//
// writes into <output dir> plain text files that render_figures.py turns into PNGs:
//   kuhn_roots.txt        the 6 root tetrahedra of the unit cube (one per line, 4 x 3 coordinates)
//   conforming_slice.txt  slice z = const of the leaves after refining towards one point only
//   levels_<d>.txt        slice of the leaves of the bunny's model for maximum_depth = d
//   slice_points.txt      the bunny's input points near the slicing plane (2D)
//   sign_slice.txt        slice of the default bunny model with F at every polygon corner
//   truth_slice.txt, crossing_slice_<k>.txt  segments of bunny00.off and of the surface of
//                         that model with crossing_neighbors k on the same plane
//   <name>_points.xyz     the sampled input points (no normals)
//   <name>_reconstruction.off  ism_surface_reconstruction() with the default parameters
//   stats.txt             sizes, times and topology of every run (quoted in the manual)
// A slice line is "level n x1 y1 [f1] ... xn yn [fn]": a convex polygon, in the plane's
// 2D coordinates, where the plane cuts one leaf.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Bisection_triangulation_3.h>
#include <CGAL/ISM_reconstruction_function.h>
#include <CGAL/ism_surface_reconstruction.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include "ism_evaluation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef std::array<double, 3> Xyz;

namespace {

// The plane {x : (x - origin) . normal = 0}, with in-plane axes u, w for 2D coordinates.
struct Slice_plane
{
  Xyz origin, normal, u, w;
};

double dot(const Xyz& a, const Xyz& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Xyz sub(const Xyz& a, const Xyz& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }

// Where the plane cuts the segment [a, b], whose signed distances to it are sa and sb (of
// opposite signs), relative to the plane's origin.
Xyz plane_crossing(const Slice_plane& pl, const Xyz& a, const Xyz& b, double sa, double sb)
{
  const double t = sa / (sa - sb);
  Xyz x;
  for(int d = 0; d < 3; ++d) x[d] = a[d] + t * (b[d] - a[d]);
  return sub(x, pl.origin);
}

// Writes, for every leaf the plane cuts, its level and the convex cut polygon; with
// `values` (one per vertex), also the linearly interpolated value at every corner.
template <class Tr>
std::size_t write_slice(const Tr& tr, const Slice_plane& pl, const std::vector<double>* values,
                        const std::string& file)
{
  std::ofstream out(file);
  out << std::setprecision(7);
  std::vector<Xyz> xyz(tr.number_of_vertices());
  for(std::size_t v = 0; v < xyz.size(); ++v)
  {
    const auto& p = tr.point(int(v));
    xyz[v] = {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  }
  std::size_t n = 0;
  for(int c : tr.leaves())
  {
    const auto vs = tr.vertices(c);
    double s[4];
    int pos = 0, neg = 0;
    for(int i = 0; i < 4; ++i)
    {
      s[i] = dot(sub(xyz[vs[i]], pl.origin), pl.normal);
      (s[i] > 0 ? pos : neg)++;
    }
    if(pos == 0 || neg == 0) continue;
    std::vector<std::array<double, 3> > poly;  // 2D point + value
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        if((s[i] > 0) != (s[j] > 0))
        {
          const double t = s[i] / (s[i] - s[j]);
          const Xyz r = plane_crossing(pl, xyz[vs[i]], xyz[vs[j]], s[i], s[j]);
          const double f = values ? (*values)[vs[i]] + t * ((*values)[vs[j]] - (*values)[vs[i]]) : 0.;
          poly.push_back({{dot(r, pl.u), dot(r, pl.w), f}});
        }
    double cx = 0, cy = 0;
    for(const auto& q : poly) { cx += q[0]; cy += q[1]; }
    cx /= poly.size();
    cy /= poly.size();
    std::sort(poly.begin(), poly.end(), [&](const std::array<double, 3>& a, const std::array<double, 3>& b) {
      return std::atan2(a[1] - cy, a[0] - cx) < std::atan2(b[1] - cy, b[0] - cx);
    });
    out << tr.level(c) << ' ' << poly.size();
    for(const auto& q : poly)
    {
      out << ' ' << q[0] << ' ' << q[1];
      if(values) out << ' ' << q[2];
    }
    out << '\n';
    ++n;
  }
  return n;
}

// Writes the segments "x1 y1 x2 y2" (plane coordinates) where the triangles of `mesh` cross
// the plane.
template <class TriangleMesh>
std::size_t write_mesh_slice(const TriangleMesh& mesh, const Slice_plane& pl, const std::string& file)
{
  std::ofstream out(file);
  out << std::setprecision(9);
  std::size_t n = 0;
  for(auto f : faces(mesh))
  {
    Xyz x[3];
    double s[3];
    int i = 0;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
    {
      const auto& p = get(CGAL::vertex_point, mesh, v);
      x[i] = {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
      s[i] = dot(sub(x[i], pl.origin), pl.normal);
      ++i;
    }
    std::vector<Xyz> ends;
    for(int a = 0; a < 3; ++a)
    {
      const int b = (a + 1) % 3;
      if((s[a] > 0) == (s[b] > 0)) continue;
      ends.push_back(plane_crossing(pl, x[a], x[b], s[a], s[b]));
    }
    if(ends.size() != 2) continue;
    out << dot(ends[0], pl.u) << ' ' << dot(ends[0], pl.w) << ' ' << dot(ends[1], pl.u) << ' ' << dot(ends[1], pl.w)
        << '\n';
    ++n;
  }
  return n;
}

std::vector<Point_3> sample(const std::string& mesh_file, std::size_t n, unsigned seed)
{
  ISM_eval::Mesh m;
  if(!ISM_eval::read_mesh(mesh_file, m))
  {
    std::cerr << "cannot read " << mesh_file << std::endl;
    std::exit(1);
  }
  std::vector<Point_3> points;
  for(const auto& pn : ISM_eval::sample_points(m, n, seed)) points.push_back(pn.first);  // normals dropped
  return points;
}

void write_xyz(const std::vector<Point_3>& points, const std::string& file)
{
  std::ofstream out(file);
  out << std::setprecision(7);
  for(const Point_3& p : points) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " <meshes dir> <output dir>" << std::endl;
    return 2;
  }
  const std::string meshes = argv[1], out = std::string(argv[2]) + "/";
  std::ofstream stats(out + "stats.txt");

  // 1. The Kuhn cube, and conforming refinement towards one point
  {
    CGAL::Bisection_triangulation_3<K> tr(K::Iso_cuboid_3(Point_3(0, 0, 0), Point_3(1, 1, 1)));
    std::ofstream roots(out + "kuhn_roots.txt");
    for(int r = 0; r < 6; ++r)
    {
      for(int i = 0; i < 4; ++i)
      {
        const Point_3& p = tr.point(tr.vertex(r, i));
        roots << p.x() << ' ' << p.y() << ' ' << p.z() << (i < 3 ? ' ' : '\n');
      }
    }
    const Point_3 target(0.3, 0.62, 0.42);
    for(;;)
    {
      const int c = tr.locate(target);
      if(tr.level(c) >= 18) break;
      tr.bisect(c);
    }
    const Slice_plane pl{{{0, 0, 0.42}}, {{0, 0, 1}}, {{1, 0, 0}}, {{0, 1, 0}}};
    const std::size_t n = write_slice(tr, pl, nullptr, out + "conforming_slice.txt");
    stats << "conforming: leaves " << tr.number_of_leaves() << " sliced " << n << '\n';
  }

  // 2. Bunny: refinement at three depths, then the default model with its signs
  const std::vector<Point_3> bunny = sample(meshes + "/bunny00.off", 35947, 1);
  write_xyz(bunny, out + "bunny_points.xyz");
  // bunny00.off: y is up, the ears point to +y; slice across the body, normal to z
  const double z0 = 0.0137;
  const Slice_plane pl{{{0, 0, z0}}, {{0, 0, 1}}, {{1, 0, 0}}, {{0, 1, 0}}};
  {
    std::ofstream sp(out + "slice_points.txt");
    for(const Point_3& p : bunny)
      if(std::abs(p.z() - z0) < 0.01) sp << p.x() << ' ' << p.y() << '\n';
  }
  for(int depth : {12, 15, 18})
  {
    CGAL::ISM_reconstruction_function<K> f(bunny);
    f.compute_implicit_function(CGAL::parameters::maximum_depth(depth));
    const std::size_t n = write_slice(f.triangulation(), pl, nullptr, out + "levels_" + std::to_string(depth) + ".txt");
    stats << "bunny depth " << depth << ": leaves " << f.statistics().number_of_leaves << " sliced " << n << '\n';
  }
  {
    CGAL::Real_timer t;
    t.start();
    CGAL::ISM_reconstruction_function<K> f(bunny);
    f.compute_implicit_function();
    const double model_time = t.time();
    const auto& st = f.statistics();
    const std::size_t n = write_slice(f.triangulation(), pl, &f.values(), out + "sign_slice.txt");
    // the surface through F's linear zero crossings (the paper) and on the points' quadric
    ISM_eval::Mesh truth;
    ISM_eval::read_mesh(meshes + "/bunny00.off", truth);
    write_mesh_slice(truth, pl, out + "truth_slice.txt");
    const double diag = ISM_eval::diagonal(ISM_eval::bbox(truth));
    const CGAL::ISM_reconstruction_3::Settings defaults;
    for(unsigned int k : {0u, 12u})
    {
      Mesh mesh;
      CGAL::ISM_reconstruction_3::extract_surface(f, mesh, 0, defaults.smoothing_lambda, defaults.smoothing_mu, k);
      write_mesh_slice(mesh, pl, out + "crossing_slice_" + std::to_string(k) + ".txt");
      const ISM_eval::Distance_score d = ISM_eval::symmetric_distance(truth, mesh, 100000, 7);
      stats << "bunny crossing_neighbors " << k << ": mean distance " << 100 * d.mean / diag << " % of the diagonal, max "
            << 100 * d.max / diag << " %\n";
    }
    stats << "bunny default: points " << st.number_of_points << " leaves " << st.number_of_leaves << " vertices "
          << st.number_of_vertices << " deepest " << st.deepest_level << " inside " << st.number_of_inside_vertices
          << " energy " << st.final_energy << " all-outside " << st.all_outside_energy << " time " << model_time
          << " sliced " << n << '\n';
  }

  // 3. Reconstructions with the default parameters
  struct Input { const char* name; const char* file; std::size_t n; };
  for(const Input& in : {Input{"bunny", "bunny00.off", 35947}, Input{"knot", "knot1.off", 100000}})
  {
    const std::vector<Point_3> points = std::string(in.name) == "bunny" ? bunny : sample(meshes + "/" + in.file, in.n, 1);
    if(std::string(in.name) != "bunny") write_xyz(points, out + in.name + "_points.xyz");
    Mesh mesh;
    CGAL::Real_timer t;
    t.start();
    CGAL::ism_surface_reconstruction(points, mesh);
    const double time = t.time();
    CGAL::IO::write_polygon_mesh(out + in.name + "_reconstruction.off", mesh, CGAL::parameters::stream_precision(7));
    ISM_eval::Mesh truth;
    ISM_eval::read_mesh(meshes + "/" + in.file, truth);
    stats << in.name << ": points " << points.size() << " time " << time << " vertices " << mesh.number_of_vertices()
          << " faces " << mesh.number_of_faces() << " [" << ISM_eval::topology(mesh) << "] truth ["
          << ISM_eval::topology(truth) << "]\n";
  }
  std::cout << "figure data written to " << out << std::endl;
  return 0;
}
