// Evaluation utilities shared by the tests and the benchmark of ISM_reconstruction_3.
//
// Everything here measures a reconstruction against a ground-truth closed triangle mesh
// (see DESIGN.md, "How we know it is right"): topology (components, genus, closed,
// 2-manifold), in/out accuracy on random queries in a box, and symmetric surface distances.
// It also builds analytic ground-truth meshes (sphere, torus, two spheres, nested spheres,
// trefoil tube) and samples points with their true normals on a mesh.
//
// Determinism: every random choice is drawn from std::mt19937_64 (whose output sequence
// is fixed by the C++ standard) through our own uniform and Box-Muller code, never from
// std::*_distribution (implementation-defined), so results are identical across
// standard libraries for a given seed.
#ifndef ISM_EVALUATION_H
#define ISM_EVALUATION_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace ISM_eval {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::FT FT;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Face_index face_descriptor;
typedef Mesh::Halfedge_index halfedge_descriptor;

namespace PMP = CGAL::Polygon_mesh_processing;

/// Side_of_triangle_mesh on `Mesh`, and the AABB tree type it uses (also used for distances).
typedef CGAL::Side_of_triangle_mesh<Mesh, K> Side_of_mesh;
typedef Side_of_mesh::AABB_tree Face_tree;

// ---------------------------------------------------------------------------------------
// Random numbers (portable: mt19937_64 output is specified by the standard)
// ---------------------------------------------------------------------------------------

/// Deterministic, portable random source: uniform doubles and standard normals.
class Rng {
public:
  explicit Rng(std::uint64_t seed) : gen_(seed) {}
  /// Uniform in [0, 1) with 53 random bits.
  double uniform() { return double(gen_() >> 11) * (1.0 / 9007199254740992.0); }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  /// A uniform point of `b`. It draws z, then y, then x: the order in which GCC evaluated
  /// three draws written as the arguments of one call (C++ leaves that order unspecified),
  /// so the samplings of earlier runs stay the same, and now on every compiler.
  Point_3 uniform_point(const CGAL::Bbox_3& b) {
    const double z = uniform(b.zmin(), b.zmax());
    const double y = uniform(b.ymin(), b.ymax());
    return Point_3(uniform(b.xmin(), b.xmax()), y, z);
  }
  /// Uniform integer in [0, n), n > 0 (rejection sampling, no modulo bias).
  std::uint64_t uniform_index(std::uint64_t n) {
    const std::uint64_t limit = (~std::uint64_t(0)) - ((~std::uint64_t(0)) % n);
    std::uint64_t x;
    do { x = gen_(); } while (x >= limit);
    return x % n;
  }
  /// Standard normal N(0,1), Box-Muller (both outputs used).
  double gaussian() {
    if (has_spare_) { has_spare_ = false; return spare_; }
    double u1 = uniform();
    while (u1 <= 0.0) u1 = uniform();
    const double u2 = uniform();
    const double rad = std::sqrt(-2.0 * std::log(u1));
    const double ang = 6.283185307179586476925286766559 * u2;
    spare_ = rad * std::sin(ang);
    has_spare_ = true;
    return rad * std::cos(ang);
  }
  std::mt19937_64& engine() { return gen_; }

private:
  std::mt19937_64 gen_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

// ---------------------------------------------------------------------------------------
// 7. Bounding boxes
// ---------------------------------------------------------------------------------------

inline double diagonal(const CGAL::Bbox_3& b) {
  const double dx = b.xmax() - b.xmin(), dy = b.ymax() - b.ymin(), dz = b.zmax() - b.zmin();
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

inline CGAL::Bbox_3 bbox(const Mesh& m) { return PMP::bbox(m); }

/// Box scaled about its center by `factor` (e.g. 1.1 adds 5% of each extent on each side).
inline CGAL::Bbox_3 scaled_bbox(const CGAL::Bbox_3& b, double factor) {
  const double cx = 0.5 * (b.xmin() + b.xmax()), cy = 0.5 * (b.ymin() + b.ymax()),
               cz = 0.5 * (b.zmin() + b.zmax());
  const double hx = 0.5 * factor * (b.xmax() - b.xmin()), hy = 0.5 * factor * (b.ymax() - b.ymin()),
               hz = 0.5 * factor * (b.zmax() - b.zmin());
  return CGAL::Bbox_3(cx - hx, cy - hy, cz - hz, cx + hx, cy + hy, cz + hz);
}

// ---------------------------------------------------------------------------------------
// 1. Reading
// ---------------------------------------------------------------------------------------

/// Reads a polygon mesh (OFF, OBJ, PLY, STL, TS). Tries the strict BGL reader first; if the
/// file is not a valid 2-manifold polygon mesh, falls back to the PMP reader that repairs and
/// orients the polygon soup. Non-triangle faces are triangulated. Returns false on failure
/// or on an empty mesh.
inline bool read_mesh(const std::string& file, Mesh& m) {
  m.clear();
  bool ok = CGAL::IO::read_polygon_mesh(file, m);
  if (!ok || !CGAL::is_valid_polygon_mesh(m)) {
    m.clear();
    ok = PMP::IO::read_polygon_mesh(file, m);
  }
  if (!ok || m.number_of_faces() == 0) return false;
  if (!CGAL::is_triangle_mesh(m)) {
    if (!PMP::triangulate_faces(m)) return false;
  }
  return true;
}

// ---------------------------------------------------------------------------------------
// Small geometric helpers
// ---------------------------------------------------------------------------------------

inline void face_points(const Mesh& m, face_descriptor f, Point_3& p, Point_3& q, Point_3& r) {
  halfedge_descriptor h = m.halfedge(f);
  p = m.point(m.source(h));
  q = m.point(m.target(h));
  r = m.point(m.target(m.next(h)));
}

inline double face_area(const Mesh& m, face_descriptor f) {
  Point_3 p, q, r;
  face_points(m, f, p, q, r);
  return std::sqrt(CGAL::to_double(CGAL::cross_product(q - p, r - p).squared_length())) * 0.5;
}

/// Unit normal of a triangle face following the mesh orientation (zero vector if degenerate).
inline Vector_3 face_unit_normal(const Mesh& m, face_descriptor f) {
  Point_3 p, q, r;
  face_points(m, f, p, q, r);
  Vector_3 n = CGAL::cross_product(q - p, r - p);
  const double l = std::sqrt(CGAL::to_double(n.squared_length()));
  return l > 0 ? n / l : Vector_3(0, 0, 0);
}

/// Writable face property map backed by a std::vector indexed by face index.
struct Face_vector_map {
  typedef face_descriptor key_type;
  typedef std::size_t value_type;
  typedef std::size_t& reference;
  typedef boost::read_write_property_map_tag category;
  std::vector<std::size_t>* v;
  friend std::size_t get(const Face_vector_map& m, face_descriptor f) { return (*m.v)[std::size_t(f)]; }
  friend void put(const Face_vector_map& m, face_descriptor f, std::size_t x) { (*m.v)[std::size_t(f)] = x; }
};

/// Per-face connected component id (faces connected through edges, PMP::connected_components),
/// indexed by std::size_t(face); returns the number of components.
inline std::size_t face_components(const Mesh& m, std::vector<std::size_t>& face_cc) {
  face_cc.assign(m.num_faces(), std::size_t(-1));  // num_faces() member: used + removed (index capacity)
  if (m.number_of_faces() == 0) return 0;
  return PMP::connected_components(m, Face_vector_map{&face_cc});
}

/// Signed volume enclosed by the faces of each component (sum of signed tetrahedra from a
/// vertex of the component; meaningful for closed components).
inline std::vector<double> component_signed_volumes(const Mesh& m, std::vector<std::size_t>& face_cc,
                                                    std::size_t& n_cc) {
  n_cc = face_components(m, face_cc);
  std::vector<double> vol(n_cc, 0.0);
  // Use a per-component reference point (first vertex met) to reduce cancellation.
  std::vector<Point_3> ref(n_cc);
  std::vector<bool> has_ref(n_cc, false);
  for (face_descriptor f : faces(m)) {
    const std::size_t c = face_cc[std::size_t(f)];
    Point_3 p, q, r;
    face_points(m, f, p, q, r);
    if (!has_ref[c]) { ref[c] = p; has_ref[c] = true; }
    const Vector_3 a = p - ref[c], b = q - ref[c], d = r - ref[c];
    vol[c] += CGAL::to_double(CGAL::scalar_product(a, CGAL::cross_product(b, d))) / 6.0;
  }
  return vol;
}

/// Signed volume of the whole mesh (positive for an outward-oriented closed mesh).
inline double signed_volume(const Mesh& m) {
  std::vector<std::size_t> cc;
  std::size_t n;
  std::vector<double> v = component_signed_volumes(m, cc, n);
  double s = 0;
  for (double x : v) s += x;
  return s;
}

/// Extracts the faces of component `c` into a new mesh.
inline Mesh extract_component(const Mesh& m, const std::vector<std::size_t>& face_cc, std::size_t c) {
  Mesh out;
  std::vector<vertex_descriptor> vmap(m.num_vertices());
  std::vector<bool> done(vmap.size(), false);
  for (face_descriptor f : faces(m)) {
    if (face_cc[std::size_t(f)] != c) continue;
    std::vector<vertex_descriptor> vs;
    for (vertex_descriptor v : vertices_around_face(m.halfedge(f), m)) {
      if (!done[std::size_t(v)]) { vmap[std::size_t(v)] = out.add_vertex(m.point(v)); done[std::size_t(v)] = true; }
      vs.push_back(vmap[std::size_t(v)]);
    }
    out.add_face(vs);
  }
  return out;
}

/// True if every component is oriented consistently with the volume it bounds: a component
/// at nesting depth d (number of other components enclosing it) has positive signed volume
/// if d is even (outer boundary) and negative if d is odd (cavity). For a single closed
/// component this is "signed volume > 0". Requires a closed, non-self-intersecting mesh;
/// returns false if the mesh is not closed.
inline bool is_outward_oriented(const Mesh& m) {
  if (m.number_of_faces() == 0) return true;
  if (!CGAL::is_closed(m) || !CGAL::is_triangle_mesh(m)) return false;
  std::vector<std::size_t> face_cc;
  std::size_t n_cc;
  std::vector<double> vol = component_signed_volumes(m, face_cc, n_cc);
  if (n_cc == 1) return vol[0] > 0;
  std::vector<Mesh> parts;
  parts.reserve(n_cc);
  for (std::size_t c = 0; c < n_cc; ++c) parts.push_back(extract_component(m, face_cc, c));
  std::vector<std::unique_ptr<Side_of_mesh>> sides;
  for (std::size_t c = 0; c < n_cc; ++c) sides.emplace_back(new Side_of_mesh(parts[c]));
  for (std::size_t c = 0; c < n_cc; ++c) {
    // A vertex of component c; components do not intersect, so it is strictly inside or
    // outside every other component.
    const Point_3 p = parts[c].point(*vertices(parts[c]).begin());
    std::size_t depth = 0;
    for (std::size_t o = 0; o < n_cc; ++o)
      if (o != c && (*sides[o])(p) == CGAL::ON_BOUNDED_SIDE) ++depth;
    const bool want_positive = (depth % 2 == 0);
    if ((vol[c] > 0) != want_positive) return false;
  }
  return true;
}

// ---------------------------------------------------------------------------------------
// 2. Area-weighted sampling with true normals
// ---------------------------------------------------------------------------------------

/// `n` points drawn uniformly by area on the faces of triangle mesh `m`, each with the unit
/// normal of the face it lies on (outward if `m` is outward oriented). If
/// `gaussian_noise_sigma` > 0, each point is displaced by an isotropic 3D gaussian vector
/// with standard deviation `gaussian_noise_sigma` (absolute units) per axis; the normal
/// stays the true face normal. Deterministic for a given mesh and seed.
inline std::vector<std::pair<Point_3, Vector_3>> sample_points(const Mesh& m, std::size_t n, unsigned seed,
                                                               double gaussian_noise_sigma = 0) {
  std::vector<std::pair<Point_3, Vector_3>> out;
  std::vector<face_descriptor> fs;
  std::vector<double> cumul;
  fs.reserve(m.number_of_faces());
  cumul.reserve(m.number_of_faces());
  double total = 0;
  for (face_descriptor f : faces(m)) {
    const double a = face_area(m, f);
    if (!(a > 0)) continue;
    total += a;
    fs.push_back(f);
    cumul.push_back(total);
  }
  if (fs.empty() || n == 0) return out;
  out.reserve(n);
  Rng rng(seed);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = rng.uniform() * total;
    std::size_t k = std::size_t(std::upper_bound(cumul.begin(), cumul.end(), t) - cumul.begin());
    if (k >= fs.size()) k = fs.size() - 1;
    const face_descriptor f = fs[k];
    Point_3 p, q, r;
    face_points(m, f, p, q, r);
    // Uniform point in a triangle: (1 - sqrt(u)) p + sqrt(u)(1 - v) q + sqrt(u) v r.
    const double su = std::sqrt(rng.uniform()), v = rng.uniform();
    const double a = 1 - su, b = su * (1 - v), c = su * v;
    double x = a * p.x() + b * q.x() + c * r.x();
    double y = a * p.y() + b * q.y() + c * r.y();
    double z = a * p.z() + b * q.z() + c * r.z();
    if (gaussian_noise_sigma > 0) {
      x += gaussian_noise_sigma * rng.gaussian();
      y += gaussian_noise_sigma * rng.gaussian();
      z += gaussian_noise_sigma * rng.gaussian();
    }
    out.emplace_back(Point_3(x, y, z), face_unit_normal(m, f));
  }
  return out;
}

/// Non-uniform sampling: the samples on one half of the surface (x above the samples' median)
/// and every `keep_one_in`-th of the others, so that one half is `keep_one_in` times denser
/// (the robustness test `nonuniform` and `benchmark_reconstruction --nonuniform`). `dense`, if
/// given, receives how many were kept on the dense half.
inline std::vector<std::pair<Point_3, Vector_3>> thin_one_half(const std::vector<std::pair<Point_3, Vector_3>>& samples,
                                                               std::size_t keep_one_in, std::size_t* dense = nullptr) {
  if (samples.empty() || keep_one_in == 0) return samples;
  std::vector<double> xs;
  for (const auto& s : samples) xs.push_back(s.first.x());
  std::nth_element(xs.begin(), xs.begin() + xs.size() / 2, xs.end());
  const double median = xs[xs.size() / 2];
  std::vector<std::pair<Point_3, Vector_3>> kept;
  std::size_t sparse_seen = 0, on_dense = 0;
  for (const auto& s : samples) {
    if (s.first.x() > median) {
      kept.push_back(s);
      ++on_dense;
    } else if (sparse_seen++ % keep_one_in == 0)
      kept.push_back(s);
  }
  if (dense) *dense = on_dense;
  return kept;
}

// ---------------------------------------------------------------------------------------
// 3. Analytic ground-truth meshes
// ---------------------------------------------------------------------------------------

namespace internal {

/// Builds a mesh from points and triangles; returns false if a face could not be added.
inline bool build_mesh(const std::vector<Point_3>& pts, const std::vector<std::array<std::size_t, 3>>& tris,
                       Mesh& m) {
  std::vector<vertex_descriptor> vs;
  vs.reserve(pts.size());
  for (const Point_3& p : pts) vs.push_back(m.add_vertex(p));
  bool ok = true;
  for (const auto& t : tris)
    if (m.add_face(vs[t[0]], vs[t[1]], vs[t[2]]) == Mesh::null_face()) ok = false;
  return ok;
}

/// Reverses the orientation of all faces of `m`.
inline void reverse(Mesh& m) { PMP::reverse_face_orientations(m); }

/// Orients a single closed component so that its signed volume is positive.
inline void orient_outward_single(Mesh& m) {
  if (signed_volume(m) < 0) reverse(m);
}

/// Appends mesh `b` to `a` (disjoint union).
inline void append(Mesh& a, const Mesh& b) { a.join(b); }

/// Closed tube of radius `r` around a closed smooth curve given by n_u samples `c`
/// (c[n_u] == c[0] implied), with n_v vertices per ring. Frames are rotation-minimizing
/// (double reflection), with the closing twist distributed evenly, so rings match.
inline Mesh tube(const std::vector<Point_3>& c, double r, std::size_t n_v) {
  const std::size_t n_u = c.size();
  std::vector<Vector_3> T(n_u);
  for (std::size_t i = 0; i < n_u; ++i) {
    Vector_3 t = c[(i + 1) % n_u] - c[(i + n_u - 1) % n_u];
    T[i] = t / std::sqrt(CGAL::to_double(t.squared_length()));
  }
  // Initial normal: any vector orthogonal to T[0].
  Vector_3 a = std::abs(T[0].x()) < 0.9 ? Vector_3(1, 0, 0) : Vector_3(0, 1, 0);
  Vector_3 N0 = a - CGAL::scalar_product(a, T[0]) * T[0];
  N0 = N0 / std::sqrt(CGAL::to_double(N0.squared_length()));
  std::vector<Vector_3> N(n_u + 1);
  N[0] = N0;
  auto transport = [&](const Vector_3& r0, std::size_t i, std::size_t j) {
    // double reflection method (Wang et al. 2008) from sample i to sample j
    const Vector_3 v1 = c[j] - c[i];
    const double c1 = CGAL::to_double(v1.squared_length());
    const Vector_3 rL = r0 - (2.0 / c1) * CGAL::scalar_product(v1, r0) * v1;
    const Vector_3 tL = T[i] - (2.0 / c1) * CGAL::scalar_product(v1, T[i]) * v1;
    const Vector_3 v2 = T[j] - tL;
    const double c2 = CGAL::to_double(v2.squared_length());
    Vector_3 rn = c2 > 0 ? rL - (2.0 / c2) * CGAL::scalar_product(v2, rL) * v2 : rL;
    rn = rn - CGAL::scalar_product(rn, T[j]) * T[j];
    return rn / std::sqrt(CGAL::to_double(rn.squared_length()));
  };
  for (std::size_t i = 0; i < n_u; ++i) N[i + 1] = transport(N[i], i, (i + 1) % n_u);
  // Closing angle between transported N[n_u] and N[0] around T[0].
  const Vector_3 B0 = CGAL::cross_product(T[0], N[0]);
  const double twist = std::atan2(CGAL::to_double(CGAL::scalar_product(N[n_u], B0)),
                                  CGAL::to_double(CGAL::scalar_product(N[n_u], N[0])));
  std::vector<Point_3> pts;
  pts.reserve(n_u * n_v);
  const double two_pi = 6.283185307179586476925286766559;
  for (std::size_t i = 0; i < n_u; ++i) {
    const Vector_3 Bi = CGAL::cross_product(T[i], N[i]);
    const double corr = -twist * double(i) / double(n_u);
    const Vector_3 Ni = std::cos(corr) * N[i] + std::sin(corr) * Bi;
    const Vector_3 Bc = CGAL::cross_product(T[i], Ni);
    for (std::size_t j = 0; j < n_v; ++j) {
      const double th = two_pi * double(j) / double(n_v);
      pts.push_back(c[i] + r * (std::cos(th) * Ni + std::sin(th) * Bc));
    }
  }
  std::vector<std::array<std::size_t, 3>> tris;
  tris.reserve(2 * n_u * n_v);
  for (std::size_t i = 0; i < n_u; ++i) {
    const std::size_t i1 = (i + 1) % n_u;
    for (std::size_t j = 0; j < n_v; ++j) {
      const std::size_t j1 = (j + 1) % n_v;
      const std::size_t a0 = i * n_v + j, a1 = i1 * n_v + j, b1 = i1 * n_v + j1, b0 = i * n_v + j1;
      tris.push_back({a0, a1, b1});
      tris.push_back({a0, b1, b0});
    }
  }
  Mesh m;
  build_mesh(pts, tris, m);
  orient_outward_single(m);
  return m;
}

}  // namespace internal

/// UV sphere: `resolution` (>= 2) latitude bands, 2*resolution longitudes, two poles.
/// Closed, genus 0, outward oriented. V = 2 + (res-1)*2res, F = 4 res (res-1).
inline Mesh make_sphere(const Point_3& center, double radius, std::size_t resolution = 32) {
  const std::size_t nl = std::max<std::size_t>(resolution, 2), nm = 2 * nl;
  const double pi = 3.14159265358979323846;
  std::vector<Point_3> pts;
  pts.push_back(center + Vector_3(0, 0, radius));  // north pole: 0
  for (std::size_t k = 1; k < nl; ++k) {
    const double th = pi * double(k) / double(nl);
    for (std::size_t j = 0; j < nm; ++j) {
      const double ph = 2 * pi * double(j) / double(nm);
      pts.push_back(center + radius * Vector_3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph),
                                               std::cos(th)));
    }
  }
  const std::size_t south = pts.size();
  pts.push_back(center + Vector_3(0, 0, -radius));
  auto id = [&](std::size_t k, std::size_t j) { return 1 + (k - 1) * nm + (j % nm); };
  std::vector<std::array<std::size_t, 3>> tris;
  for (std::size_t j = 0; j < nm; ++j) tris.push_back({0, id(1, j), id(1, j + 1)});
  for (std::size_t k = 1; k + 1 < nl; ++k)
    for (std::size_t j = 0; j < nm; ++j) {
      tris.push_back({id(k, j), id(k + 1, j), id(k + 1, j + 1)});
      tris.push_back({id(k, j), id(k + 1, j + 1), id(k, j + 1)});
    }
  for (std::size_t j = 0; j < nm; ++j) tris.push_back({south, id(nl - 1, j + 1), id(nl - 1, j)});
  Mesh m;
  internal::build_mesh(pts, tris, m);
  internal::orient_outward_single(m);
  return m;
}

/// Torus around the z axis through `center`: major radius R, minor radius r < R,
/// res_u samples around the axis, res_v around the tube. Closed, genus 1, outward.
inline Mesh make_torus(const Point_3& center, double R, double r, std::size_t res_u = 48,
                       std::size_t res_v = 24) {
  std::vector<Point_3> circle;
  const double pi = 3.14159265358979323846;
  for (std::size_t i = 0; i < res_u; ++i) {
    const double u = 2 * pi * double(i) / double(res_u);
    circle.push_back(center + Vector_3(R * std::cos(u), R * std::sin(u), 0));
  }
  return internal::tube(circle, r, res_v);
}

/// Two disjoint spheres (two components, genus 0 each), both outward.
inline Mesh make_two_spheres(const Point_3& c1, double r1, const Point_3& c2, double r2,
                             std::size_t resolution = 32) {
  Mesh m = make_sphere(c1, r1, resolution);
  internal::append(m, make_sphere(c2, r2, resolution));
  return m;
}

/// Spherical shell: outer sphere (outward) and inner sphere of radius r_inner < r_outer with
/// reversed orientation (normals towards the common center). Inside = between the spheres.
inline Mesh make_nested_spheres(const Point_3& center, double r_outer, double r_inner,
                                std::size_t resolution = 32) {
  Mesh m = make_sphere(center, r_outer, resolution);
  Mesh in = make_sphere(center, r_inner, resolution);
  internal::reverse(in);
  internal::append(m, in);
  return m;
}

/// Trefoil knot tube: curve (sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t) scaled by `scale`
/// and translated to `center`, tube radius `tube_radius` (in units of the scaled curve;
/// default 0.35*scale; keep it below ~0.6*scale: distinct strands of the curve are at least
/// 1.21*scale apart and its radius of curvature is at least 1.28*scale).
/// Closed, genus 1, outward, knotted.
inline Mesh make_trefoil_tube(const Point_3& center = Point_3(0, 0, 0), double scale = 1.0,
                              double tube_radius = -1, std::size_t res_u = 240, std::size_t res_v = 16) {
  if (tube_radius <= 0) tube_radius = 0.35 * scale;
  std::vector<Point_3> curve;
  const double pi = 3.14159265358979323846;
  for (std::size_t i = 0; i < res_u; ++i) {
    const double t = 2 * pi * double(i) / double(res_u);
    curve.push_back(center + scale * Vector_3(std::sin(t) + 2 * std::sin(2 * t),
                                              std::cos(t) - 2 * std::cos(2 * t), -std::sin(3 * t)));
  }
  return internal::tube(curve, tube_radius, res_v);
}

// ---------------------------------------------------------------------------------------
// 4. Topology
// ---------------------------------------------------------------------------------------

struct Topology {
  std::size_t components = 0;  ///< edge-connected components of faces
  long euler = 0;              ///< V - E + F (vertices incident to faces only)
  int genus = 0;               ///< sum over components; for open meshes, uses boundary cycles
  bool closed = false;         ///< no border edge
  bool manifold = false;       ///< valid surface mesh, no non-manifold vertex, no isolated vertex
  bool self_consistent = false;///< closed && manifold && every component has an even chi <= 2
  std::size_t boundary_cycles = 0;  ///< number of border cycles (0 if closed)
  std::size_t isolated_vertices = 0;
  std::size_t non_manifold_vertices = 0;  ///< counted only if the mesh is a valid surface mesh
};

/// Topology of a surface mesh. genus = (2c - b - chi)/2 summed over components (b = number of
/// boundary cycles; 0 for closed meshes), i.e. (2c - chi)/2 for a closed orientable mesh.
inline Topology topology(const Mesh& m) {
  Topology t;
  t.manifold = CGAL::is_valid_polygon_mesh(m);
  std::size_t nv = 0;
  for (vertex_descriptor v : vertices(m)) {
    if (m.is_isolated(v)) { ++t.isolated_vertices; continue; }
    ++nv;
  }
  if (t.isolated_vertices > 0) t.manifold = false;
  if (t.manifold) {
    // linear-time scan (PMP::is_non_manifold_vertex is linear per vertex)
    std::vector<halfedge_descriptor> cones;
    PMP::non_manifold_vertices(m, std::back_inserter(cones));
    t.non_manifold_vertices = cones.size();
    if (!cones.empty()) t.manifold = false;
  }
  t.euler = long(nv) - long(m.number_of_edges()) + long(m.number_of_faces());
  t.closed = CGAL::is_closed(m);

  // boundary cycles
  std::vector<bool> seen(m.num_halfedges(), false);
  for (halfedge_descriptor h : halfedges(m)) {
    if (!m.is_border(h) || seen[std::size_t(h)]) continue;
    ++t.boundary_cycles;
    halfedge_descriptor g = h;
    std::size_t guard = 0;
    do { seen[std::size_t(g)] = true; g = m.next(g); } while (g != h && ++guard < seen.size());
  }

  if (m.number_of_faces() == 0) {
    t.self_consistent = t.manifold;
    return t;
  }
  std::vector<std::size_t> face_cc;
  t.components = face_components(m, face_cc);
  // per-component chi and boundary cycles
  std::vector<long> V(t.components, 0), E(t.components, 0), F(t.components, 0), B(t.components, 0);
  for (face_descriptor f : faces(m)) ++F[face_cc[std::size_t(f)]];
  for (Mesh::Edge_index e : edges(m)) {
    halfedge_descriptor h = m.halfedge(e);
    face_descriptor f = m.is_border(h) ? m.face(m.opposite(h)) : m.face(h);
    if (f != Mesh::null_face()) ++E[face_cc[std::size_t(f)]];
  }
  for (vertex_descriptor v : vertices(m)) {
    if (m.is_isolated(v)) continue;
    // component of any incident face
    for (halfedge_descriptor h : halfedges_around_target(m.halfedge(v), m)) {
      face_descriptor f = m.face(h);
      if (f == Mesh::null_face()) f = m.face(m.opposite(h));
      if (f != Mesh::null_face()) { ++V[face_cc[std::size_t(f)]]; break; }
    }
  }
  std::fill(seen.begin(), seen.end(), false);
  for (halfedge_descriptor h : halfedges(m)) {
    if (!m.is_border(h) || seen[std::size_t(h)]) continue;
    ++B[face_cc[std::size_t(m.face(m.opposite(h)))]];
    halfedge_descriptor g = h;
    std::size_t guard = 0;
    do { seen[std::size_t(g)] = true; g = m.next(g); } while (g != h && ++guard < seen.size());
  }
  long twice_genus = 0;
  bool even = true;
  for (std::size_t c = 0; c < t.components; ++c) {
    const long chi = V[c] - E[c] + F[c];
    const long tg = 2 - B[c] - chi;
    if (tg < 0 || (tg % 2) != 0) even = false;
    twice_genus += tg;
  }
  t.genus = int(twice_genus / 2);
  t.self_consistent = t.closed && t.manifold && even;
  return t;
}

inline std::ostream& operator<<(std::ostream& os, const Topology& t) {
  return os << "components=" << t.components << " euler=" << t.euler << " genus=" << t.genus
            << " closed=" << t.closed << " manifold=" << t.manifold
            << " self_consistent=" << t.self_consistent << " boundary_cycles=" << t.boundary_cycles;
}

// ---------------------------------------------------------------------------------------
// 5. In/out accuracy
// ---------------------------------------------------------------------------------------

struct Inout_score {
  double overall = 0;   ///< fraction in [0,1] of queries whose side matches the truth
  double far = 0;       ///< same, over queries farther than far_fraction*diagonal from truth
  std::size_t n = 0;    ///< number of queries
  std::size_t n_far = 0;///< number of far queries
};

/// Fraction of `n_queries` uniform random points of `box` where `inside(p)` (bool) agrees
/// with the closed ground-truth mesh `truth` (CGAL::Side_of_triangle_mesh, parity based, so
/// nested and multi-component truths work; ON_BOUNDARY agrees with either answer).
/// "far" restricts to queries whose distance to the truth surface exceeds
/// `far_fraction * diagonal(box)`. If no query is far, `far` is 1.
template <class SignOracle>
Inout_score inout_accuracy(const Mesh& truth, const CGAL::Bbox_3& box, SignOracle inside,
                           std::size_t n_queries, double far_fraction = 0.01, unsigned seed = 0) {
  Inout_score s;
  Face_tree tree(faces(truth).first, faces(truth).second, truth);
  tree.accelerate_distance_queries();
  Side_of_mesh side(tree);
  const double far_d = far_fraction * diagonal(box);
  const double far_d2 = far_d * far_d;
  Rng rng(seed);
  std::size_t ok = 0, ok_far = 0;
  for (std::size_t i = 0; i < n_queries; ++i) {
    const double x = rng.uniform(box.xmin(), box.xmax());
    const double y = rng.uniform(box.ymin(), box.ymax());
    const double z = rng.uniform(box.zmin(), box.zmax());
    const Point_3 p(x, y, z);
    const CGAL::Bounded_side bs = side(p);
    const bool got = static_cast<bool>(inside(p));
    const bool match = (bs == CGAL::ON_BOUNDARY) || ((bs == CGAL::ON_BOUNDED_SIDE) == got);
    if (match) ++ok;
    if (CGAL::to_double(tree.squared_distance(p)) > far_d2) {
      ++s.n_far;
      if (match) ++ok_far;
    }
  }
  s.n = n_queries;
  s.overall = n_queries ? double(ok) / double(n_queries) : 1.0;
  s.far = s.n_far ? double(ok_far) / double(s.n_far) : 1.0;
  return s;
}

/// Callable `bool(const Point_3&)`: true if the point is inside the closed triangle mesh
/// (or on it), by CGAL::Side_of_triangle_mesh (ray parity: valid for several components and
/// nested components whatever their orientation). Holds its own AABB tree; copies share it.
/// The mesh must outlive the oracle. An empty mesh has nothing inside.
class Inside_oracle {
public:
  explicit Inside_oracle(const Mesh& m) {
    if (m.number_of_faces() == 0) return;
    tree_ = std::make_shared<Face_tree>(faces(m).first, faces(m).second, m);
    tree_->build();
    side_ = std::make_shared<Side_of_mesh>(*tree_);
  }
  bool operator()(const Point_3& p) const { return side_ && (*side_)(p) != CGAL::ON_UNBOUNDED_SIDE; }
  CGAL::Bounded_side side(const Point_3& p) const { return side_ ? (*side_)(p) : CGAL::ON_UNBOUNDED_SIDE; }

private:
  std::shared_ptr<Face_tree> tree_;
  std::shared_ptr<Side_of_mesh> side_;
};

inline Inside_oracle inside_oracle(const Mesh& reconstructed) { return Inside_oracle(reconstructed); }

// ---------------------------------------------------------------------------------------
// 6. Distances
// ---------------------------------------------------------------------------------------

struct Distance_score {
  double mean = 0;  ///< average of the two directed mean distances
  double max = 0;   ///< max of the two directed maxima (Hausdorff estimate)
};

/// Directed distances from `n` area-weighted samples of `a` to the surface of `b`.
inline Distance_score directed_distance(const Mesh& a, const Mesh& b, std::size_t n, unsigned seed) {
  Distance_score d;
  if (a.number_of_faces() == 0 || b.number_of_faces() == 0 || n == 0) {
    d.mean = d.max = std::numeric_limits<double>::infinity();
    return d;
  }
  Face_tree tree(faces(b).first, faces(b).second, b);
  tree.accelerate_distance_queries();
  const auto samples = sample_points(a, n, seed);
  double sum = 0, mx = 0;
  for (const auto& s : samples) {
    const double dd = std::sqrt(CGAL::to_double(tree.squared_distance(s.first)));
    sum += dd;
    mx = (std::max)(mx, dd);
  }
  d.mean = samples.empty() ? 0 : sum / double(samples.size());
  d.max = mx;
  return d;
}

/// Symmetric distance estimate between the surfaces of `a` and `b` (absolute units):
/// `samples_per_mesh` area-weighted samples on each, distance to the other via AABB tree.
/// Infinite if either mesh is empty.
inline Distance_score symmetric_distance(const Mesh& a, const Mesh& b, std::size_t samples_per_mesh,
                                         unsigned seed) {
  const Distance_score ab = directed_distance(a, b, samples_per_mesh, seed);
  const Distance_score ba = directed_distance(b, a, samples_per_mesh, seed + 1);
  Distance_score d;
  d.mean = 0.5 * (ab.mean + ba.mean);
  d.max = (std::max)(ab.max, ba.max);
  return d;
}

// ---------------------------------------------------------------------------------------
// Hole filling (ground truths with small holes, e.g. ChineseDragon-10kv.off)
// ---------------------------------------------------------------------------------------

/// Fills every hole of `m` (PMP::triangulate_refine_and_fair_hole when Eigen is available,
/// else triangulate_and_refine_hole). Returns true if the mesh is closed afterwards.
inline bool close_holes(Mesh& m) {
  std::vector<halfedge_descriptor> border_cycles;
  PMP::extract_boundary_cycles(m, std::back_inserter(border_cycles));
  for (halfedge_descriptor h : border_cycles) {
    if (!m.is_border(h)) continue;  // already filled
    std::vector<face_descriptor> nf;
    std::vector<vertex_descriptor> nv;
#ifdef CGAL_EIGEN3_ENABLED
    const bool ok = std::get<0>(PMP::triangulate_refine_and_fair_hole(
        m, h, std::back_inserter(nf), std::back_inserter(nv)));
    if (!ok) {
      nf.clear();
      nv.clear();
      if (m.is_border(h)) PMP::triangulate_and_refine_hole(m, h, std::back_inserter(nf), std::back_inserter(nv));
    }
#else
    PMP::triangulate_and_refine_hole(m, h, std::back_inserter(nf), std::back_inserter(nv));
#endif
  }
  return CGAL::is_closed(m);
}

}  // namespace ISM_eval

#endif  // ISM_EVALUATION_H
