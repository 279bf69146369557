// Tests of the internal algorithms on flat arrays: Ising annealing, marching
// tetrahedra, Taubin smoothing, removal of thin handles, escape rays, winding number.

#include <CGAL/ISM_reconstruction_3/internal/ising_annealing.h>
#include <CGAL/ISM_reconstruction_3/internal/distance_estimation.h>
#include <CGAL/ISM_reconstruction_3/internal/jet_crossing.h>
#include <CGAL/ISM_reconstruction_3/internal/marching_tetrahedra.h>
#include <CGAL/ISM_reconstruction_3/internal/taubin_smoothing.h>
#include <CGAL/ISM_reconstruction_3/internal/handle_removal.h>
#include <CGAL/ISM_reconstruction_3/internal/tangent_plane_signs.h>
#include <CGAL/ISM_reconstruction_3/internal/surface_refinement.h>
#include <CGAL/ISM_reconstruction_3/internal/point_smoothing.h>
#include <CGAL/ISM_reconstruction_3/internal/escape_rays.h>
#include <CGAL/ISM_reconstruction_3/internal/winding_number.h>
#include <CGAL/ISM_reconstruction_3/internal/island_joining.h>
#include <CGAL/ISM_reconstruction_3/internal/normal_orientation.h>
#include <CGAL/ISM_reconstruction_3/internal/point_input.h>
#include <CGAL/Bisection_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace internal = CGAL::ISM_reconstruction_3::internal;

typedef std::array<double, 3> Point;
typedef std::array<std::size_t, 3> Triangle;

static int number_of_failures = 0;

#define CHECK(cond, what)                                                        \
  do {                                                                           \
    if(!(cond)) {                                                                \
      ++number_of_failures;                                                      \
      std::cerr << "FAILED: " << what << "  [" #cond "] line " << __LINE__ << std::endl; \
    }                                                                            \
  } while(false)

// ---------------------------------------------------------------------------
// Graph helpers

struct Edge { int u, v; double w; };

internal::Coupling_graph graph_from_edges(std::size_t n, const std::vector<Edge>& edges)
{
  internal::Coupling_graph g;
  g.offsets.assign(n + 1, 0);
  for(const Edge& e : edges) { ++g.offsets[e.u + 1]; ++g.offsets[e.v + 1]; }
  for(std::size_t v = 0; v < n; ++v) g.offsets[v + 1] += g.offsets[v];
  g.adjacency.resize(g.offsets[n]);
  g.weights.resize(g.offsets[n]);
  std::vector<std::size_t> next(g.offsets.begin(), g.offsets.end() - 1);
  for(const Edge& e : edges)
  {
    g.adjacency[next[e.u]] = e.v; g.weights[next[e.u]++] = e.w;
    g.adjacency[next[e.v]] = e.u; g.weights[next[e.v]++] = e.w;
  }
  return g;
}

// Edges of an nx*ny*nz grid; `kuhn`: the 7 offsets in {0,1}^3 \ 0 (14 neighbours,
// the edges of the 6-tetrahedra Kuhn triangulation), otherwise the 3 axis offsets.
std::vector<std::pair<int, int> > grid_edges(int nx, int ny, int nz, bool kuhn)
{
  std::vector<std::pair<int, int> > edges;
  auto id = [&](int i, int j, int k) { return (k * ny + j) * nx + i; };
  for(int k = 0; k < nz; ++k)
    for(int j = 0; j < ny; ++j)
      for(int i = 0; i < nx; ++i)
        for(int d = 1; d < 8; ++d)
        {
          const int di = d & 1, dj = (d >> 1) & 1, dk = (d >> 2) & 1;
          if(!kuhn && di + dj + dk != 1) continue;
          if(i + di >= nx || j + dj >= ny || k + dk >= nz) continue;
          edges.emplace_back(id(i, j, k), id(i + di, j + dj, k + dk));
        }
  return edges;
}

bool on_grid_boundary(int v, int nx, int ny, int nz)
{
  const int i = v % nx, j = (v / nx) % ny, k = v / (nx * ny);
  return i == 0 || j == 0 || i == nx - 1 || j == ny - 1 ||
         (nz > 1 && (k == 0 || k == nz - 1));
}

std::vector<signed char> random_signs(std::size_t n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::vector<signed char> s(n);
  for(auto& x : s) x = (rng() & 1) ? 1 : -1;
  return s;
}

void ferromagnet_test(int nx, int ny, int nz, const std::string& name)
{
  const std::size_t n = std::size_t(nx) * ny * nz;
  std::vector<Edge> edges;
  for(auto e : grid_edges(nx, ny, nz, false)) edges.push_back({e.first, e.second, -1.});
  const internal::Coupling_graph g = graph_from_edges(n, edges);
  std::vector<signed char> s = random_signs(n, 7);
  std::vector<char> clamped(n, 0);
  for(std::size_t v = 0; v < n; ++v)
    if(on_grid_boundary(int(v), nx, ny, nz)) { clamped[v] = 1; s[v] = -1; }
  const double e = internal::anneal(g, s, clamped, internal::Annealing_schedule(), 42);
  const bool all_minus = std::all_of(s.begin(), s.end(), [](signed char x) { return x == -1; });
  CHECK(all_minus, name << ": ferromagnet with clamped -1 boundary does not end all -1");
  CHECK(std::abs(e + double(edges.size())) < 1e-9, name << ": energy " << e << " != " << -double(edges.size()));
}

void planted_test()
{
  const int nx = 20, ny = 20, nz = 20;
  const std::size_t n = std::size_t(nx) * ny * nz;
  std::mt19937 rng(123);
  std::uniform_real_distribution<double> mag(0.2, 1.8);
  const std::vector<signed char> planted = random_signs(n, 99);
  std::vector<Edge> edges;
  double ground = 0.;
  for(auto e : grid_edges(nx, ny, nz, true))
  {
    const double w = -mag(rng) * planted[e.first] * planted[e.second];
    edges.push_back({e.first, e.second, w});
    ground -= std::abs(w);
  }
  const internal::Coupling_graph g = graph_from_edges(n, edges);
  std::vector<signed char> s = random_signs(n, 5);
  std::vector<char> clamped(n, 0);
  for(std::size_t v = 0; v < n; v += 97) { clamped[v] = 1; s[v] = planted[v]; }
  const double e = internal::anneal(g, s, clamped, internal::Annealing_schedule(), 2024);
  std::size_t wrong = 0;
  for(std::size_t v = 0; v < n; ++v) if(s[v] != planted[v]) ++wrong;
  CHECK(wrong == 0, "planted instance: " << wrong << " of " << n << " signs differ from the planted ones");
  CHECK(std::abs(e - ground) < 1e-6 * std::abs(ground), "planted instance: energy " << e << " != ground " << ground);
  CHECK(std::abs(e - internal::ising_energy(g, s)) < 1e-9 * std::abs(ground), "anneal() return value != ising_energy()");
}

void energy_test()
{
  std::mt19937 rng(3);
  const std::size_t n = 300;
  std::vector<Edge> edges;
  std::uniform_int_distribution<int> vert(0, int(n) - 1);
  std::uniform_real_distribution<double> w(-2., 2.);
  std::set<std::pair<int, int> > seen;
  while(edges.size() < 2000)
  {
    int a = vert(rng), b = vert(rng);
    if(a == b) continue;
    if(a > b) std::swap(a, b);
    if(!seen.insert({a, b}).second) continue;
    edges.push_back({a, b, double(float(w(rng)))});  // the graph stores weights in single precision
  }
  const internal::Coupling_graph g = graph_from_edges(n, edges);
  const std::vector<signed char> s = random_signs(n, 11);
  double brute = 0.;
  for(const Edge& e : edges) brute += e.w * s[e.u] * s[e.v];
  const double e = internal::ising_energy(g, s);
  CHECK(std::abs(e - brute) < 1e-9 * (1. + std::abs(brute)), "ising_energy " << e << " != brute force " << brute);

  // A short anneal never ends above a zero-temperature local minimum check:
  // no single flip lowers the energy after the final pass.
  std::vector<signed char> t = s;
  const double ea = internal::anneal(g, t, {}, internal::Annealing_schedule(), 1);
  bool local_min = true;
  for(std::size_t v = 0; v < n; ++v)
  {
    double h = 0.;
    for(std::size_t k = g.offsets[v]; k < g.offsets[v + 1]; ++k) h += g.weights[k] * t[g.adjacency[k]];
    if(-2. * t[v] * h < -1e-12) local_min = false;
  }
  CHECK(local_min, "after anneal(), a single flip still lowers the energy");
  CHECK(ea <= e, "anneal() raised the energy of a spin glass: " << ea << " > " << e);

  // The overload that frees the graph gives the same signs, and the energy up to the
  // quantisation of the weights (2^-24 max |H_e| per edge).
  {
    internal::Coupling_graph copy = g;
    std::vector<signed char> r = s;
    std::vector<char> clamped(n, 0);
    for(std::size_t v = 0; v < n; v += 7) clamped[v] = 1;
    std::vector<signed char> q = s;
    const double eq = internal::anneal(g, q, clamped, internal::Annealing_schedule(), 5);
    const double er = internal::anneal(std::move(copy), r, clamped, internal::Annealing_schedule(), 5);
    CHECK(r == q, "anneal(Coupling_graph&&) found other signs than anneal(const Coupling_graph&)");
    CHECK(copy.adjacency.empty() && copy.weights.empty(), "anneal(Coupling_graph&&) did not free the graph");
    CHECK(std::abs(er - eq) < 1e-6 * (1. + std::abs(eq)), "anneal(Coupling_graph&&) energy " << er << " != " << eq);
  }
}

// A frustrated instance (random-sign couplings on the Kuhn grid): sensitive to every
// random number, so a good determinism test.
internal::Coupling_graph spin_glass(int m, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> w(-1., 1.);
  std::vector<Edge> edges;
  for(auto e : grid_edges(m, m, m, true)) edges.push_back({e.first, e.second, w(rng)});
  return graph_from_edges(std::size_t(m) * m * m, edges);
}

void determinism_test()
{
  const int m = 40;  // 64000 vertices: large enough to be split between threads
  const internal::Coupling_graph g = spin_glass(m, 8);
  const std::size_t n = g.number_of_vertices();
  const std::vector<signed char> start = random_signs(n, 1);
  std::vector<char> clamped(n, 0);
  for(std::size_t v = 0; v < n; v += 50) clamped[v] = 1;
  internal::Annealing_schedule sched;
  sched.number_of_sweeps = 50;

  std::vector<signed char> a = start, b = start, c = start;
  const double ea = internal::anneal(g, a, clamped, sched, 77);
  const double eb = internal::anneal(g, b, clamped, sched, 77);
  CHECK(a == b && ea == eb, "same seed twice gives different results");
  internal::anneal(g, c, clamped, sched, 78);
  CHECK(a != c, "different seeds give identical results (suspicious)");
  for(std::size_t v = 0; v < n; ++v)
    if(clamped[v]) CHECK(a[v] == start[v], "clamped vertex " << v << " flipped");

#ifdef CGAL_LINKED_WITH_TBB
  std::vector<signed char> s1 = start, s2 = start;
  double e1, e2;
  {
    tbb::global_control gc(tbb::global_control::max_allowed_parallelism, 1);
    e1 = internal::anneal(g, s1, clamped, sched, 77);
  }
  {
    tbb::global_control gc(tbb::global_control::max_allowed_parallelism, 2);
    e2 = internal::anneal(g, s2, clamped, sched, 77);
  }
  CHECK(s1 == s2 && e1 == e2, "1 thread and 2 threads give different results");
  CHECK(s1 == a, "TBB-limited run differs from the default run");
  std::cout << "  determinism: 1 vs 2 TBB threads identical: " << (s1 == s2 ? "yes" : "NO") << std::endl;
#else
  std::cout << "  (TBB not linked: thread-count test skipped)" << std::endl;
#endif
}

void degenerate_annealing_test()
{
  // empty graphs
  {
    internal::Coupling_graph g;
    std::vector<signed char> s;
    CHECK(internal::anneal(g, s, {}, internal::Annealing_schedule(), 1) == 0., "empty graph energy");
    g.offsets.push_back(0);
    CHECK(internal::anneal(g, s, std::vector<char>(), internal::Annealing_schedule(), 1) == 0., "empty graph (offsets {0}) energy");
  }
  // vertices without edges
  {
    internal::Coupling_graph g;
    g.offsets.assign(5, 0);
    std::vector<signed char> s = {1, -1, 1, 1};
    const auto s0 = s;
    CHECK(internal::anneal(g, s, {}, internal::Annealing_schedule(), 1) == 0., "edgeless graph energy");
    CHECK(s == s0, "edgeless graph: signs changed");
  }
  // all-zero weights
  {
    std::vector<Edge> edges;
    for(auto e : grid_edges(10, 10, 10, true)) edges.push_back({e.first, e.second, 0.});
    const internal::Coupling_graph g = graph_from_edges(1000, edges);
    std::vector<signed char> s = random_signs(1000, 4);
    const auto s0 = s;
    const double e = internal::anneal(g, s, {}, internal::Annealing_schedule(), 1);
    CHECK(e == 0. && std::isfinite(e), "all-zero weights energy " << e);
    CHECK(s == s0, "all-zero weights: signs changed");
  }
  // all clamped
  {
    const internal::Coupling_graph g = spin_glass(6, 2);
    std::vector<signed char> s = random_signs(216, 4);
    const auto s0 = s;
    const double e = internal::anneal(g, s, std::vector<char>(216, 1), internal::Annealing_schedule(), 1);
    CHECK(s == s0, "all clamped: signs changed");
    CHECK(e == internal::ising_energy(g, s0), "all clamped: energy");
  }
  // no sweeps, only the zero-temperature pass; and a single sweep
  {
    const internal::Coupling_graph g = spin_glass(8, 3);
    std::vector<signed char> s = random_signs(512, 4);
    const double e0 = internal::ising_energy(g, s);
    internal::Annealing_schedule sched;
    sched.number_of_sweeps = 0;
    const double e = internal::anneal(g, s, {}, sched, 1);
    CHECK(e <= e0, "zero-temperature pass raised the energy");
    sched.number_of_sweeps = 1;
    sched.final_zero_temperature_pass = false;
    const double e1 = internal::anneal(g, s, {}, sched, 1);
    CHECK(std::isfinite(e1), "single sweep energy not finite");
  }
}

// ---------------------------------------------------------------------------
// Meshes

double orientation_det(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
  const double a[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
  const double b[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
  const double c[3] = {p3[0] - p0[0], p3[1] - p0[1], p3[2] - p0[2]};
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

struct Tet_mesh
{
  std::vector<Point> points;
  std::vector<std::array<int, 4> > tets;
  double h;
};

// n^3 cubes on [-1,1]^3, each split into 6 Kuhn tetrahedra, positively oriented.
// `shuffle`: then apply a random even permutation to each tet's corners.
Tet_mesh kuhn_grid(int n, bool shuffle)
{
  Tet_mesh m;
  m.h = 2. / n;
  auto id = [&](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  for(int k = 0; k <= n; ++k)
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i)
        m.points.push_back({-1. + i * m.h, -1. + j * m.h, -1. + k * m.h});
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  const int even[12][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 0, 3, 2}, {1, 2, 0, 3}, {1, 3, 2, 0},
                           {2, 0, 1, 3}, {2, 1, 3, 0}, {2, 3, 0, 1}, {3, 0, 2, 1}, {3, 1, 0, 2}, {3, 2, 1, 0}};
  std::mt19937 rng(5);
  for(int k = 0; k < n; ++k)
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i)
        for(const auto& p : perms)
        {
          int c[3] = {i, j, k};
          std::array<int, 4> t;
          t[0] = id(c[0], c[1], c[2]);
          for(int s = 0; s < 3; ++s)
          {
            ++c[p[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          if(orientation_det(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]) < 0)
            std::swap(t[2], t[3]);
          if(shuffle)
          {
            const int* e = even[rng() % 12];
            t = {t[e[0]], t[e[1]], t[e[2]], t[e[3]]};
          }
          m.tets.push_back(t);
        }
  return m;
}

struct Surface_check
{
  bool closed_manifold = true;
  std::string error;
  long euler = 0;
  double volume = 0.;
};

Surface_check check_surface(const std::vector<Point>& pts, const std::vector<Triangle>& tris)
{
  Surface_check r;
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  for(const Triangle& t : tris)
    for(int i = 0; i < 3; ++i)
    {
      if(t[i] == t[(i + 1) % 3]) { r.closed_manifold = false; r.error = "degenerate triangle"; }
      ++directed[{t[i], t[(i + 1) % 3]}];
    }
  std::size_t undirected = 0;
  for(const auto& d : directed)
  {
    if(d.second != 1) { r.closed_manifold = false; r.error = "directed edge used twice (inconsistent orientation)"; }
    auto opp = directed.find({d.first.second, d.first.first});
    if(opp == directed.end() || opp->second != 1) { r.closed_manifold = false; r.error = "boundary or non-manifold edge"; }
    if(d.first.first < d.first.second) ++undirected;
  }
  // vertex links: the triangles around each vertex form a single cycle
  std::vector<std::map<std::size_t, std::size_t> > link(pts.size());
  std::vector<std::size_t> valence(pts.size(), 0);
  for(const Triangle& t : tris)
    for(int i = 0; i < 3; ++i)
    {
      link[t[i]][t[(i + 1) % 3]] = t[(i + 2) % 3];
      ++valence[t[i]];
    }
  std::size_t used = 0;
  for(std::size_t v = 0; v < pts.size(); ++v)
  {
    if(valence[v] == 0) continue;
    ++used;
    if(link[v].size() != valence[v]) { r.closed_manifold = false; r.error = "non-manifold vertex link"; continue; }
    std::size_t start = link[v].begin()->first, cur = start, steps = 0;
    do {
      auto it = link[v].find(cur);
      if(it == link[v].end()) break;
      cur = it->second;
      ++steps;
    } while(cur != start && steps <= valence[v]);
    if(cur != start || steps != valence[v]) { r.closed_manifold = false; r.error = "vertex link is not one cycle"; }
  }
  r.euler = long(used) - long(undirected) + long(tris.size());
  for(const Triangle& t : tris)
    r.volume += orientation_det({0., 0., 0.}, pts[t[0]], pts[t[1]], pts[t[2]]) / 6.;
  return r;
}

template <class Function>
std::vector<double> sample(const Tet_mesh& m, const Function& f)
{
  std::vector<double> v(m.points.size());
  for(std::size_t i = 0; i < v.size(); ++i)
  {
    double x = f(m.points[i]);
    if(std::abs(x) < 1e-9) x = 1e-9;  // never 0
    v[i] = x;
  }
  return v;
}

const Point sphere_center = {0.013, -0.021, 0.017};
const double sphere_radius = 0.63;
double sphere_value(const Point& p)
{
  const double dx = p[0] - sphere_center[0], dy = p[1] - sphere_center[1], dz = p[2] - sphere_center[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz) - sphere_radius;
}
const double torus_R = 0.55, torus_r = 0.22;
double torus_value(const Point& p)
{
  const double q = std::sqrt(p[0] * p[0] + p[1] * p[1]) - torus_R;
  return std::sqrt(q * q + p[2] * p[2]) - torus_r;
}
double two_spheres_value(const Point& p)
{
  const double a = std::sqrt((p[0] - 0.45) * (p[0] - 0.45) + p[1] * p[1] + p[2] * p[2]) - 0.35;
  const double b = std::sqrt((p[0] + 0.45) * (p[0] + 0.45) + p[1] * p[1] + p[2] * p[2]) - 0.3;
  return (std::min)(a, b);
}

void marching_test(const Tet_mesh& m, double (*f)(const Point&), const std::string& name,
                   long expected_euler, double expected_volume)
{
  const std::vector<double> values = sample(m, f);
  std::vector<Point> pts;
  std::vector<Triangle> tris;
  internal::marching_tetrahedra(m.points, m.tets, values, pts, tris);
  const Surface_check c = check_surface(pts, tris);
  CHECK(!tris.empty(), name << ": empty output");
  CHECK(c.closed_manifold, name << ": not a closed oriented 2-manifold: " << c.error);
  CHECK(c.euler == expected_euler, name << ": Euler characteristic " << c.euler << " != " << expected_euler);
  CHECK(c.volume > 0., name << ": negative enclosed volume (inward orientation)");
  const double rel = std::abs(c.volume - expected_volume) / expected_volume;
  CHECK(rel < 0.03, name << ": volume " << c.volume << " vs " << expected_volume);
  std::cout << "  " << name << ": " << pts.size() << " points, " << tris.size() << " triangles, chi = " << c.euler
            << ", volume error " << 100. * rel << " %" << std::endl;

  // one point per crossed edge, all distinct
  std::set<std::pair<int, int> > crossed;
  for(const auto& t : m.tets)
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        if((values[t[i]] < 0) != (values[t[j]] < 0))
          crossed.insert({(std::min)(t[i], t[j]), (std::max)(t[i], t[j])});
  CHECK(crossed.size() == pts.size(), name << ": " << pts.size() << " points for " << crossed.size() << " crossed edges");
  std::vector<Point> sorted = pts;
  std::sort(sorted.begin(), sorted.end());
  CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end(), name << ": duplicated output points");

  // deterministic
  std::vector<Point> pts2;
  std::vector<Triangle> tris2;
  internal::marching_tetrahedra(m.points, m.tets, values, pts2, tris2);
  CHECK(pts == pts2 && tris == tris2, name << ": output differs between two runs");
}

// Tet_mesh seen as the leaves of a triangulation, for remove_thin_handles()
struct Tet_mesh_leaves
{
  typedef int Cell_index;
  const Tet_mesh& m;
  std::size_t number_of_cells() const { return m.tets.size(); }
  std::size_t number_of_vertices() const { return m.points.size(); }
  bool is_leaf(int) const { return true; }
  int vertex(int c, int i) const { return m.tets[c][i]; }
  const std::array<int, 4>& vertices(int c) const { return m.tets[c]; }
};

// A ball drilled through by a hole one grid vertex wide whose vertices lie near the surface
// (|value| 0.03), all others far from it: a handle only vertices on the surface hold open,
// filled.
double drilled_sphere_value(const Point& p)
{
  const double ball = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 0.63;
  if(ball > 0) return 1.;
  return std::sqrt(p[0] * p[0] + p[1] * p[1]) < 0.01 ? 0.03 : -1.;
}

// The same hole (a cylinder of radius h/2 around the z axis) with true distances: the ring
// of vertices around it is shallow too, so the inside sweep closes rings around vertices it
// visits later and cuts them; the restore pass of open_shallow_loops() must give them back
// (without it the handle stays: chi 0).
double drilled_sphere_distance(const Point& p)
{
  const double ball = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 0.63;
  if(ball > 0) return ball;
  const double r = std::sqrt(p[0] * p[0] + p[1] * p[1]);
  if(r < 0.01) return 0.025;
  return -(std::min)(-ball, r - 0.025);
}

// the sign of each value, and the vertices on the grid's boundary (the cube [-1, 1]^3)
void signs_and_boundary(const Tet_mesh& m, const std::vector<double>& values, std::vector<signed char>& signs,
                        std::vector<char>& boundary)
{
  signs.assign(values.size(), 1);
  boundary.assign(values.size(), 0);
  for(std::size_t v = 0; v < values.size(); ++v)
  {
    if(values[v] < 0) signs[v] = -1;
    for(int d = 0; d < 3; ++d)
      if(std::abs(std::abs(m.points[v][d]) - 1.) < 1e-9) boundary[v] = 1;
  }
}

void thin_handle_test(const Tet_mesh& m, double (*f)(const Point&), const std::string& name, long euler_before,
                      long euler_after, double relative_depth = 0.58, bool local_size = false)
{
  std::vector<double> values = sample(m, f);
  std::vector<Point> pts;
  std::vector<Triangle> tris;
  internal::marching_tetrahedra(m.points, m.tets, values, pts, tris);
  CHECK(check_surface(pts, tris).euler == euler_before, name << ": the input has Euler characteristic "
                                                            << check_surface(pts, tris).euler << ", not " << euler_before);
  std::vector<signed char> signs;
  std::vector<char> boundary;
  signs_and_boundary(m, values, signs, boundary);
  // the median longest edge of a Kuhn tet is the cube diagonal, h sqrt(3): depth 0.05 > 0.03
  const std::size_t changed = internal::remove_thin_handles(Tet_mesh_leaves{m}, m.points, boundary, relative_depth,
                                                            signs, values, nullptr, local_size);
  for(std::size_t v = 0; v < values.size(); ++v)
    CHECK((values[v] < 0) == (signs[v] < 0), name << ": value and sign of vertex " << v << " disagree");
  internal::marching_tetrahedra(m.points, m.tets, values, pts, tris);
  const Surface_check c = check_surface(pts, tris);
  CHECK(c.closed_manifold, name << ": not a closed 2-manifold after handle removal: " << c.error);
  CHECK(c.euler == euler_after, name << ": Euler characteristic " << c.euler << " after handle removal, expected "
                                     << euler_after);
  std::cout << "  " << name << ": " << changed << " vertices changed side, chi " << euler_before << " -> " << c.euler
            << std::endl;
}

// A flat ring of 8 grid vertices around a centre, on one side, all else on the other; the
// sweep visits the ring first (deeper), so the last ring vertex closes a loop around the
// centre and is cut. With the centre on the ring's side, visited after, that loop is filled
// and the restore pass must give the cut vertex back: nothing changes side. With the centre
// on the other side the ring is a real loop of shallow vertices and stays cut.
void ring_restore_test(bool with_centre)
{
  const int n = 8;
  const Tet_mesh m = kuhn_grid(n, false);
  auto id = [&](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  const std::size_t nv = m.points.size();
  std::vector<signed char> signs(nv, 1);
  std::vector<double> values(nv, 1.);
  std::size_t on_plate = 0;
  for(int j = 3; j <= 5; ++j)
    for(int i = 3; i <= 5; ++i)
    {
      const bool centre = i == 4 && j == 4;
      if(centre && !with_centre) continue;
      const std::uint32_t v = std::uint32_t(id(i, j, 4));
      ++on_plate;
      signs[v] = -1;
      values[v] = centre ? -0.1 : -0.2;  // the ring deeper than the centre
    }
  const std::vector<signed char> before = signs;
  std::vector<char> skip(nv, 0), deep(nv, 0);
  std::vector<std::uint32_t> offsets, leaves;
  const Tet_mesh_leaves tr{m};
  internal::leaves_around_vertices(tr, skip, offsets, leaves);
  internal::Disjoint_sets sets(nv);
  internal::open_shallow_loops(tr, offsets, leaves, deep, -1, sets, signs, values);
  std::size_t changed = 0;
  for(std::size_t v = 0; v < nv; ++v)
  {
    changed += signs[v] != before[v];
    CHECK((values[v] < 0) == (signs[v] < 0), "ring: value and sign of vertex " << v << " disagree");
  }
  const std::string name = with_centre ? "ring around a later centre" : "ring around nothing";
  CHECK(changed == (with_centre ? 0u : 1u), name << ": " << changed << " vertices changed side, expected "
                                                 << (with_centre ? 0 : 1));
  std::cout << "  " << name << ": " << changed << " of " << on_plate << " vertices changed side" << std::endl;
}

double radius_variance(const std::vector<Point>& pts, const Point& c)
{
  double s = 0., s2 = 0.;
  for(const Point& p : pts)
  {
    const double r = std::sqrt((p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]) + (p[2] - c[2]) * (p[2] - c[2]));
    s += r;
    s2 += r * r;
  }
  const double n = double(pts.size());
  return s2 / n - (s / n) * (s / n);
}

void taubin_test(const Tet_mesh& m)
{
  std::vector<Point> pts;
  std::vector<Triangle> tris;
  internal::marching_tetrahedra(m.points, m.tets, sample(m, sphere_value), pts, tris);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> noise(-0.25 * m.h, 0.25 * m.h);
  for(Point& p : pts)
  {
    Point d = {p[0] - sphere_center[0], p[1] - sphere_center[1], p[2] - sphere_center[2]};
    const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double e = noise(rng);
    for(int k = 0; k < 3; ++k) p[k] += e * d[k] / r;
  }
  const double var0 = radius_variance(pts, sphere_center);
  const double vol0 = check_surface(pts, tris).volume;
  std::vector<Point> smoothed = pts;
  internal::taubin_smoothing(smoothed, tris, 10, 0.5, -0.53);
  const double var1 = radius_variance(smoothed, sphere_center);
  const double vol1 = check_surface(smoothed, tris).volume;
  const double dvol = std::abs(vol1 - vol0) / vol0;
  CHECK(var1 < 0.5 * var0, "taubin: radius variance " << var0 << " -> " << var1 << " not halved");
  CHECK(dvol < 0.02, "taubin: volume changed by " << 100. * dvol << " %");
  std::cout << "  taubin: radius std " << std::sqrt(var0) << " -> " << std::sqrt(var1) << ", volume change "
            << 100. * dvol << " %" << std::endl;

  // deterministic, default arguments, degenerate input
  std::vector<Point> again = pts;
  internal::taubin_smoothing(again, tris, 10);
  CHECK(again == smoothed, "taubin: not deterministic / defaults differ from (0.5, -0.53)");
  std::vector<Point> empty;
  internal::taubin_smoothing(empty, {}, 3, 0.5, -0.53);
  std::vector<Point> lone = {{1., 2., 3.}};
  internal::taubin_smoothing(lone, {}, 3, 0.5, -0.53);
  CHECK(lone[0] == Point({1., 2., 3.}), "taubin: isolated vertex moved");
}

// A plate z in [-t, t] sampled on both faces, normals oriented outward (+z above, -z below),
// with the points of one patch left without a normal. Vertices on the z axis: the one
// between the faces must go inside, those beyond the faces outside, one past the plate's
// rim (beside the tangent planes) and one of the box boundary must keep their sign, and a
// vertex whose only voters have no normal must keep its sign. Then with orientations that
// vouch for 0.01 only: the vertex between the faces (0.02 deep) still goes inside, a vertex
// 0.03 behind one face with nothing behind it keeps its sign, one 0.005 behind goes inside.
void tangent_plane_test()
{
  const double t = 0.02, h = 0.01;
  std::vector<std::array<double, 3> > points, normals;
  for(int i = -20; i <= 20; ++i)
    for(int j = -20; j <= 20; ++j)
      for(int side : { -1, 1 })
      {
        const double x = i * h, y = j * h;
        points.push_back({{ x, y, side * t }});
        const bool silent = x > 0.12 && y > 0.12;  // a patch of points that may not vote
        normals.push_back({{ 0., 0., silent ? 0. : double(side) }});
      }
  const internal::Point_neighbors neighbors(points);
  // vertices: between the faces, above, below, past the rim (x = 0.24, beyond the plate's
  // edge at 0.2, just above the upper face's plane), fixed, in the silent patch (between
  // its faces)
  const std::vector<std::array<double, 3> > vertices = {
      {{ 0.001, 0.002, 0. }}, {{ 0.001, 0.002, 0.035 }}, {{ 0.001, 0.002, -0.035 }},
      {{ 0.24, 0.002, 0.021 }}, {{ 0.05, 0.05, 0. }}, {{ 0.165, 0.165, 0. }} };
  const std::vector<char> fixed = { 0, 0, 0, 0, 1, 0 };
  const double radius = 0.05;
  const std::vector<internal::Voters> voters = internal::voters_of_vertices(vertices, fixed, neighbors, radius);
  CHECK(voters[4][0] == internal::no_voter, "tangent planes: a box boundary vertex has no voters");
  std::vector<signed char> signs = { 1, -1, -1, 1, 1, 1 };
  std::vector<double> values = { 0.5, -0.5, -0.5, 0.5, 0.5, 0.5 };
  const auto normal_of = [&](std::uint32_t i) -> const std::array<double, 3>& { return normals[i]; };
  const std::size_t changed = internal::sign_by_tangent_planes(
      points, neighbors, vertices, voters, normal_of, [](std::uint32_t) { return HUGE_VALF; }, radius, 1e-12, signs, values);
  CHECK(signs[0] == -1 && values[0] < 0 && std::abs(values[0] + t) < 1e-3,
        "tangent planes: a vertex between the faces of a plate goes inside, at the plate's half thickness");
  CHECK(signs[1] == 1 && std::abs(values[1] - 0.015) < 2e-3, "tangent planes: a vertex above the plate goes outside");
  CHECK(signs[2] == 1 && std::abs(values[2] - 0.015) < 2e-3, "tangent planes: a vertex below the plate goes outside");
  CHECK(signs[3] == 1 && values[3] == 0.5, "tangent planes: a vertex past the rim, beside the planes, keeps its sign");
  CHECK(signs[4] == 1 && values[4] == 0.5, "tangent planes: a box boundary vertex keeps its sign");
  CHECK(signs[5] == 1 && values[5] == 0.5, "tangent planes: voters without a normal do not vote");
  CHECK(changed == 3, "tangent planes: 3 vertices changed side, got " + std::to_string(changed));

  // the upper face alone, and the plate again, with orientations that vouch for 0.01
  std::vector<std::array<double, 3> > sheet;
  for(std::size_t i = 0; i < points.size(); ++i)
    if(points[i][2] > 0) sheet.push_back(points[i]);
  const internal::Point_neighbors sheet_neighbors(sheet);
  const std::vector<std::array<double, 3> > below = { {{ 0.001, 0.002, t - 0.03 }}, {{ 0.001, 0.002, t - 0.005 }} };
  const std::vector<internal::Voters> sheet_voters = internal::voters_of_vertices(below, { 0, 0 }, sheet_neighbors, radius);
  const std::array<double, 3> up = {{ 0., 0., 1. }};
  std::vector<signed char> sheet_signs = { 1, 1 };
  std::vector<double> sheet_values = { 0.5, 0.5 };
  internal::sign_by_tangent_planes(sheet, sheet_neighbors, below, sheet_voters,
                                   [&](std::uint32_t) -> const std::array<double, 3>& { return up; },
                                   [](std::uint32_t) { return 0.01f; }, radius, 1e-12, sheet_signs, sheet_values);
  CHECK(sheet_signs[0] == 1 && sheet_values[0] == 0.5,
        "tangent planes: a vertex deeper behind one wall than its voters vouch for keeps its sign");
  CHECK(sheet_signs[1] == -1, "tangent planes: a vertex within the depth its voters vouch for goes inside");
  signs = { 1, -1, -1, 1, 1, 1 };
  internal::sign_by_tangent_planes(points, neighbors, vertices, voters, normal_of, [](std::uint32_t) { return 0.01f; },
                                   radius, 1e-12, signs, values);
  CHECK(signs[0] == -1, "tangent planes: a vertex between two walls goes inside deeper than its voters vouch for");
}

// The leaves in which F misses the points (surface_refinement.h): F linear (z - 0.5) on a
// uniform Bisection_triangulation_3 of the unit cube. Points on its zero level miss nothing;
// a point a quarter of its leaf above it is reported, alone; noise of the same amplitude on
// every point hides it (3 times the median miss); a leaf at the maximum level, or not longer
// than the minimum size, is not reported.
void misfit_leaves_test()
{
  typedef CGAL::Epick K;
  typedef CGAL::Bisection_triangulation_3<K> Tr;
  Tr tr(K::Iso_cuboid_3(K::Point_3(0, 0, 0), K::Point_3(1, 1, 1)));
  tr.refine_uniformly(9);
  std::vector<Point> xyz;
  for(std::size_t v = 0; v < tr.number_of_vertices(); ++v)
    xyz.push_back({{ tr.point(int(v)).x(), tr.point(int(v)).y(), tr.point(int(v)).z() }});
  // F at x in its leaf: linear vertex values z - 0.5 interpolate to exactly that
  auto f = [](Tr::Cell_index, const Point& x) { return x[2] - 0.5; };
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.05, 0.95);
  std::vector<Point> points;
  for(int i = 0; i < 400; ++i) points.push_back({{ u(rng), u(rng), 0.5 }});
  // the leaf of points[i] (of the set being tested)
  auto leaf_in = [&tr](const std::vector<Point>& pts) {
    return [&tr, &pts](std::uint32_t i) { return tr.locate(K::Point_3(pts[i][0], pts[i][1], pts[i][2])); };
  };
  CHECK(internal::misfit_leaves(tr, xyz, points, leaf_in(points), f, 0.05, 3., 30).empty(),
        "misfit leaves: points on the zero level of a linear F miss nothing");
  // level 9: cubes of side 1/8, the longest edge of a leaf 0.125 sqrt(3) = 0.22
  const Point above = {{ 0.31, 0.42, 0.5 + 0.0625 }};
  points.push_back(above);
  const auto misfit = internal::misfit_leaves(tr, xyz, points, leaf_in(points), f, 0.05, 3., 30);
  const Tr::Cell_index holder = tr.locate(K::Point_3(above[0], above[1], above[2]));
  CHECK(misfit.size() == 1 && misfit[0] == holder, "misfit leaves: the leaf of the one point off the zero level, alone");
  CHECK(internal::misfit_leaves(tr, xyz, points, leaf_in(points), f, 0.05, 3., tr.level(holder)).empty(),
        "misfit leaves: a leaf at the maximum level is not reported");
  // the passes on the sparse parts' leaves (min_size): only leaves longer than it
  CHECK(internal::misfit_leaves(tr, xyz, points, leaf_in(points), f, 0.05, 3., 30, 0.25).empty(),
        "misfit leaves: a leaf (0.22 long) not longer than min_size 0.25 is not reported");
  CHECK(internal::misfit_leaves(tr, xyz, points, leaf_in(points), f, 0.05, 3., 30, 0.2) == misfit,
        "misfit leaves: ... one longer than min_size 0.2 is");
  std::vector<Point> noisy(points);
  for(std::size_t i = 0; i + 1 < noisy.size(); ++i) noisy[i][2] += (i % 2 ? 1 : -1) * 0.03;
  CHECK(internal::misfit_leaves(tr, xyz, noisy, leaf_in(noisy), f, 0.05, 3., 30).empty(),
        "misfit leaves: a miss of 2 times the noise is not a bend");
  CHECK(internal::misfit_leaves(tr, xyz, noisy, leaf_in(noisy), f, 0.05, 1.5, 30).size() == 1,
        "misfit leaves: ... but of more than 1.5 times the noise it is");
}

// Jet smoothing (point_smoothing.h) on a unit sphere sampled on a Fibonacci spiral: the noise
// measure tells clean from noisy (2 % radial noise), the quadric leaves clean points where they are (a plane
// would pull them inwards by about r^2/2), removes most of a radial noise, and a line of
// points, on which no quadric is determined, stays a line.
void point_smoothing_test()
{
  const int n = 4000;
  std::vector<Point> clean, noisy;
  std::mt19937 rng(11);
  std::normal_distribution<double> gauss(0., 0.02);
  for(int i = 0; i < n; ++i)
  {
    const double z = 1 - (2 * i + 1.) / n, r = std::sqrt(1 - z * z), phi = i * 2.399963229728653;
    clean.push_back({{ r * std::cos(phi), r * std::sin(phi), z }});
    const double s = 1 + gauss(rng);
    noisy.push_back({{ s * clean.back()[0], s * clean.back()[1], s * clean.back()[2] }});
  }
  auto radial_rms = [](const std::vector<Point>& p) {
    double s = 0;
    for(const Point& x : p) s += std::pow(std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) - 1, 2);
    return std::sqrt(s / double(p.size()));
  };
  const internal::Point_neighbors clean_neighbors(clean), noisy_neighbors(noisy);
  const double clean_noise = internal::median_neighborhood_coplanarity(clean, clean_neighbors, 12, 1);
  const double noisy_noise = internal::median_neighborhood_coplanarity(noisy, noisy_neighbors, 12, 3);
  CHECK(clean_noise < 0.003, "point smoothing: a clean sphere measures no noise, got " + std::to_string(clean_noise));
  CHECK(noisy_noise > 0.03, "point smoothing: 2 % radial noise measures above 0.03, got " + std::to_string(noisy_noise));
  const std::vector<Point> kept = internal::jet_smoothed(clean, clean_neighbors, 24);
  CHECK(radial_rms(kept) < 2e-4, "point smoothing: the quadric keeps clean points on the sphere, rms " +
                                     std::to_string(radial_rms(kept)));
  std::vector<Point> smoothed = noisy;
  for(int pass = 0; pass < 3; ++pass)
  {
    const internal::Point_neighbors neighbors(smoothed);
    smoothed = internal::jet_smoothed(smoothed, neighbors, 24);
  }
  CHECK(radial_rms(smoothed) < 0.4 * radial_rms(noisy), "point smoothing: 3 passes remove most of the noise, rms " +
                                                            std::to_string(radial_rms(noisy)) + " -> " +
                                                            std::to_string(radial_rms(smoothed)));
  std::vector<Point> line;
  for(int i = 0; i < 50; ++i) line.push_back({{ 0.1 * i, 0.2 * i, -0.05 * i }});
  const internal::Point_neighbors line_neighbors(line);
  const std::vector<Point> on_line = internal::jet_smoothed(line, line_neighbors, 24);
  double moved = 0;
  for(int i = 0; i < 50; ++i)
    for(int d = 0; d < 3; ++d) moved = std::max(moved, std::abs(on_line[i][d] - line[i][d]));
  // (up to the single-precision normal of the plane fit)
  CHECK(moved < 1e-6, "point smoothing: points on a line stay there, moved " + std::to_string(moved));

  // the same noise twenty times denser: the 24 nearest points reach under 2 sigma, so the
  // jet fits take more, and every pass; on the 4,000 points (reach about 7 sigma) they stay
  // 24, and one pass
  std::vector<Point> dense;
  const int m = 80000;
  for(int i = 0; i < m; ++i)
  {
    const double z = 1 - (2 * i + 1.) / m, r = std::sqrt(1 - z * z), phi = i * 2.399963229728653, s = 1 + gauss(rng);
    dense.push_back({{ s * r * std::cos(phi), s * r * std::sin(phi), s * z }});
  }
  const internal::Point_neighbors dense_neighbors(dense);
  const internal::Jet_smoothing_plan sparse_plan = internal::jet_smoothing_plan(noisy, noisy_neighbors, 24, noisy.size() / 2000);
  const internal::Jet_smoothing_plan dense_plan = internal::jet_smoothing_plan(dense, dense_neighbors, 24, dense.size() / 2000);
  const unsigned int k_sparse = sparse_plan.neighbors, k_dense = dense_plan.neighbors;
  std::cout << "  jet neighbours for 2 % noise: " << k_sparse << " at 4,000 points, " << k_dense << " at 80,000" << std::endl;
  CHECK(k_sparse == 24 && k_dense >= 28 && k_dense <= 64,
        "point smoothing: jet neighbours 24 at 4,000 noisy points and 28-64 at 80,000, got " + std::to_string(k_sparse) +
            " and " + std::to_string(k_dense));
  CHECK(!sparse_plan.dense_for_noise && dense_plan.dense_for_noise,
        "point smoothing: one pass at 4,000 noisy points, every pass at 80,000");
}

// The local-plane distance (distance_estimation.h) over a disk of points is the plane's
// distance; past the disk's rim it is about the distance to the disk (the plane alone gave 0
// in the disk's plane: an ear tip's plane carried the surface out past its points).
void disk_distance_test()
{
  std::vector<Point> disk;  // radius 0.5 about (1, 2, 0.3) in the plane z = 0.3, 400 points
  for(int i = 0; i < 400; ++i)
  {
    const double r = 0.5 * std::sqrt((i + 0.5) / 400), phi = i * 2.399963229728653;
    disk.push_back({{ 1 + r * std::cos(phi), 2 + r * std::sin(phi), 0.3 }});
  }
  const internal::Point_neighbors neighbors(disk);
  const std::vector<Point> vertices = {{{ 1.1, 2.05, 0.35 }}, {{ 1.58, 2., 0.3 }}, {{ 1., 2.6, 0.31 }}};
  const std::vector<double> d =
      internal::estimate_distances(disk, neighbors, vertices, std::vector<signed char>(3, 1), CGAL::ISM_reconstruction_3::LOCAL_PLANE_DISTANCE);
  CHECK(std::abs(d[0] - 0.05) < 1e-6, "disk distance: 0.05 over the disk, got " << d[0]);
  // past the rim: at least 3/4 of the distance to the disk, at most that to the nearest point
  const double to_disk[3] = { 0.05, 0.08, std::sqrt(0.1 * 0.1 + 0.01 * 0.01) };
  for(int v = 1; v < 3; ++v)
  {
    double nearest = HUGE_VAL;
    for(const Point& p : disk)
      nearest = std::min(nearest, std::sqrt(std::pow(p[0] - vertices[v][0], 2) + std::pow(p[1] - vertices[v][1], 2) +
                                            std::pow(p[2] - vertices[v][2], 2)));
    CHECK(d[v] >= 0.75 * to_disk[v] && d[v] <= nearest, "disk distance: " << to_disk[v] << " from the disk past its rim (nearest point "
                                                                             << nearest << "), got " << d[v]);
  }
}

// n points spread evenly on the sphere of centre 0 and radius `radius` (a Fibonacci spiral)
void add_sphere_points(std::vector<std::array<double, 3> >& points, int n, double radius)
{
  for(int i = 0; i < n; ++i)
  {
    const double z = 1 - (2. * i + 1) / n, r = std::sqrt(1 - z * z), phi = i * 2.399963229728653;
    points.push_back({{ radius * r * std::cos(phi), radius * r * std::sin(phi), radius * z }});
  }
}

// The extent of the points over that of their bulk (point_input.h), from which far outliers
// and parts far apart add levels: an evenly sampled sphere of any size is its own bulk (a
// grid of 32^3 cells whatever the number of points split 800 of them into groups of a few
// points: ratio 3.9, 3 levels "for far outliers"), while a second sphere or a cluster far
// away is seen.
void bulk_extent_test()
{
  for(int n : { 120, 300, 800, 2000, 5000, 40000 })
  {
    std::vector<std::array<double, 3> > points;
    add_sphere_points(points, n, 1.);
    const double ratio = internal::extent_over_bulk_extent(points);
    CHECK(internal::far_outlier_levels(ratio) == 0,
          "bulk extent: " << n << " points on a sphere are all bulk, yet the ratio is " << ratio);
  }
  for(int n : { 300, 5000 })
  {
    std::vector<std::array<double, 3> > points;
    add_sphere_points(points, n, 1.);
    std::vector<std::array<double, 3> > two = points;
    for(std::array<double, 3> p : points) two.push_back({{ p[0] + 100., p[1], p[2] }});
    const double two_ratio = internal::extent_over_bulk_extent(two);
    CHECK(two_ratio > 30, "bulk extent: two spheres 100 radii apart (" << n << " points each) give " << two_ratio);
    // 2 % of the points in a cluster 1000 radii away
    for(int i = 0; i < n / 50; ++i) points.push_back({{ 1000. + 0.01 * i, 0., 0. }});
    const double far_ratio = internal::extent_over_bulk_extent(points);
    CHECK(far_ratio > 300, "bulk extent: a cluster 1000 radii away (" << n << " points) gives " << far_ratio);
  }
}

// Jet crossings (jet_crossing.h): F's values are off by up to 80 % (as distance estimates
// from points a leaf away are); the linear crossings inherit the error,
// the crossings moved along their edges onto the quadric of the sphere's points must not.
// The triangles stay those of the linear crossings, an edge almost tangent to the points
// keeps its linear crossing, and k = 0 is the linear crossing.
void jet_crossing_test(const Tet_mesh& m)
{
  std::vector<Point> points;
  add_sphere_points(points, 20000, sphere_radius);
  for(Point& p : points)
    for(int d = 0; d < 3; ++d) p[d] += sphere_center[d];
  const internal::Point_neighbors neighbors(points);
  std::vector<double> values = sample(m, sphere_value);
  // distances off by a factor 0.2 to 1.8: the signs, hence the crossed edges, stay right
  for(std::size_t i = 0; i < values.size(); ++i)
  {
    const Point& p = m.points[i];
    values[i] *= 1 + 0.8 * std::cos(7 * p[0] + 5 * p[1] - 3 * p[2]);
  }
  // the mean distance to the sphere, and the fraction of the crossings farther than h / 50
  auto radial_error = [&](const std::vector<Point>& pts, double& far_fraction) {
    double sum = 0;
    std::size_t far = 0;
    for(const Point& p : pts)
    {
      const double e = std::abs(sphere_value(p));
      sum += e;
      if(e > 0.02 * m.h) ++far;
    }
    far_fraction = double(far) / double(pts.size());
    return sum / double(pts.size());
  };
  std::vector<Point> linear, jet, none;
  std::vector<Triangle> linear_tris, jet_tris, none_tris;
  internal::marching_tetrahedra(m.points, m.tets, values, linear, linear_tris);
  internal::marching_tetrahedra(m.points, m.tets, values, jet, jet_tris, internal::Jet_crossing(points, neighbors, 12));
  internal::marching_tetrahedra(m.points, m.tets, values, none, none_tris, internal::Jet_crossing(points, neighbors, 0));
  double linear_far, jet_far;
  const double linear_mean = radial_error(linear, linear_far), jet_mean = radial_error(jet, jet_far);
  std::cout << "  distance to the sphere, mean " << linear_mean << " -> " << jet_mean << ", farther than h/50 "
            << 100 * linear_far << " % -> " << 100 * jet_far << " %" << std::endl;
  const Surface_check c = check_surface(jet, jet_tris);
  // (the quadrilaterals may take the other diagonal)
  CHECK(c.closed_manifold && c.euler == 2 && jet.size() == linear.size() && jet_tris.size() == linear_tris.size(),
        "jet crossing: not the linear crossings' sphere: " << c.error);
  CHECK(none == linear && none_tris == linear_tris, "jet crossing: k = 0 must be the linear crossing");
  CHECK(linear_mean > 0.02 * m.h, "jet crossing: the perturbed F should miss the sphere, mean " << linear_mean);
  CHECK(jet_mean < 0.1 * linear_mean && jet_far < 0.05, "jet crossing: the crossings did not move onto the sphere");
  // an edge at 1.8 degrees to the sphere's tangent plane at its pole
  const Point pole = {sphere_center[0], sphere_center[1], sphere_center[2] + sphere_radius};
  const Point a = {pole[0] - 0.05, pole[1], pole[2] + 0.0016}, b = {pole[0] + 0.05, pole[1], pole[2] - 0.0016};
  CHECK(internal::Jet_crossing(points, neighbors, 12)(a, b, 0.3) == 0.3,
        "jet crossing: an edge almost tangent to the points must keep its crossing");
}

// Points on a sphere of radius 0.5 (the closed sampled solid) in the grid on [-1,1]^3; the
// inside: the vertices in the ball, and a slab beside it (0.5 < x < 0.6, |y|, |z| < 0.2) such
// as the Ising signs leave beside a thin part. The escape rays must remove the slab, keep
// the ball, and keep a slab that rays cannot leave (one walled in by a second sphere).
void escape_rays_test(const Tet_mesh& grid)
{
  for(bool walled : { false, true })
  {
    std::vector<std::array<double, 3> > points;
    add_sphere_points(points, 20000, 0.5);
    if(walled) add_sphere_points(points, 20000, 0.8);
    const internal::Point_neighbors neighbors(points);
    const std::size_t nv = grid.points.size();
    std::vector<signed char> signs(nv, 1);
    std::vector<double> values(nv, 1.);
    std::vector<char> fixed(nv, 0);
    std::size_t ball = 0, slab = 0;
    auto in_slab = [](const Point& p) { return p[0] > 0.5 && p[0] < 0.6 && std::abs(p[1]) < 0.2 && std::abs(p[2]) < 0.2; };
    for(std::size_t v = 0; v < nv; ++v)
    {
      const Point& p = grid.points[v];
      const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      if(r < 0.5 || in_slab(p))
      {
        signs[v] = -1;
        values[v] = -1.;
        (r < 0.5 ? ball : slab) += 1;
      }
      for(int d = 0; d < 3; ++d) fixed[v] = fixed[v] || std::abs(std::abs(p[d]) - 1) < 1e-9;
    }
    const std::vector<signed char> before = signs;
    const Tet_mesh_leaves leaves{grid};
    const std::size_t turned = internal::remove_escaping_inside(
        leaves, grid.points, points, neighbors, fixed, 5, [&](std::uint32_t) { return 0.4 * grid.h; },
        [](std::uint32_t, const std::array<double, 3>&) { return true; }, signs, values);
    std::size_t slab_left = 0, ball_lost = 0;
    for(std::size_t v = 0; v < nv; ++v)
    {
      const Point& p = grid.points[v];
      const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      if(before[v] < 0 && signs[v] < 0 && r >= 0.5) ++slab_left;
      if(r < 0.5 && signs[v] > 0) ++ball_lost;
      if(before[v] != signs[v]) CHECK(values[v] > 0, "escape rays: a vertex turned outside has a negative value");
    }
    const std::string name = walled ? "escape rays, slab walled in by a second sphere: " : "escape rays: ";
    CHECK(ball > 100 && slab > 10, name << "test set-up: " << ball << " ball and " << slab << " slab vertices");
    CHECK(ball_lost == 0, name << ball_lost << " of the " << ball << " vertices of the sampled ball turned outside");
    if(walled)
      CHECK(turned == 0 && slab_left == slab, name << turned << " vertices turned outside, none may");
    else
      CHECK(slab_left == 0 && turned == slab, name << slab_left << " of " << slab << " slab vertices left inside, "
                                                   << turned << " turned outside");
  }
  // one ray: from outside the sphere away from it, it leaves; towards it, it stops
  std::vector<std::array<double, 3> > points;
  add_sphere_points(points, 2000, 1.);
  const internal::Point_neighbors neighbors(points);
  // (0.75, 0, 0.75): outside the unit sphere, inside the points' bounding box
  const double a = std::sqrt(0.5);
  CHECK(internal::ray_escapes(neighbors, {{ 0.75, 0., 0.75 }}, {{ a, 0., a }}, 0.05), "escape rays: a ray away from a sphere stops");
  CHECK(!internal::ray_escapes(neighbors, {{ 0.75, 0., 0.75 }}, {{ -a, 0., -a }}, 0.05), "escape rays: a ray into a sphere leaves");
  CHECK(!internal::ray_escapes(neighbors, {{ 0., 0., 0. }}, {{ 0.6, 0., 0.8 }}, 0.05), "escape rays: a ray from a sphere's center leaves");
}

// The winding number of 20,000 points on a sphere of radius 0.5, normals oriented outwards:
// the Barnes-Hut sum agrees with the direct one and is about 1 inside, 0 outside. The Euler
// characteristic of the zero level set of a sphere, a torus and two spheres. Then a ball of
// inside vertices with a dent drilled from outside to its centre (|y|, |z| < 0.15, x > 0):
// the re-signing must fill the dent where it is farther from the points than their spacing,
// turn no vertex outside the sphere inside, and keep the surface's Euler characteristic.
void winding_number_test(const Tet_mesh& grid)
{
  std::vector<std::array<double, 3> > points;
  add_sphere_points(points, 20000, 0.5);
  const internal::Point_neighbors neighbors(points);
  std::vector<float> spacing;
  const std::vector<std::array<double, 3> > dipoles = internal::point_dipoles(
      points, neighbors, 12, [&](std::uint32_t i, const std::array<double, 3>& n) {
        return n[0] * points[i][0] + n[1] * points[i][1] + n[2] * points[i][2] > 0 ? 1 : -1;
      }, spacing);
  const internal::Winding_number w(points, dipoles);
  auto direct = [&](const std::array<double, 3>& x) {
    double sum = 0;
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      const double d[3] = { points[i][0] - x[0], points[i][1] - x[1], points[i][2] - x[2] };
      const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      sum += (d[0] * dipoles[i][0] + d[1] * dipoles[i][1] + d[2] * dipoles[i][2]) / (r2 * std::sqrt(r2));
    }
    return sum / (4. * 3.14159265358979323846);
  };
  for(const double r : { 0., 0.2, 0.4, 0.45, 0.55, 0.6, 0.8, 1.5 })
  {
    const std::array<double, 3> x = {{ r * 0.6, r * 0.48, r * 0.64 }};
    const double fast = w(x), slow = direct(x);
    // a far node counts as one dipole at its centroid: a few per cent, far inside the margin of 0.3 / 0.7
    CHECK(std::abs(fast - slow) < 0.04, "winding number: Barnes-Hut " << fast << " vs direct " << slow << " at radius " << r);
    if(r < 0.45) CHECK(std::abs(fast - 1) < 0.05, "winding number: " << fast << " at radius " << r << " inside the sphere");
    if(r > 0.55) CHECK(std::abs(fast) < 0.05, "winding number: " << fast << " at radius " << r << " outside the sphere");
  }
  CHECK(std::abs(spacing[0] - 0.0245) < 0.005, "winding number: spacing " << spacing[0] << " of 20,000 points on the sphere");
  CHECK(internal::Winding_number(points, std::vector<std::array<double, 3> >(points.size(), {{ 0., 0., 0. }}))({{ 0., 0., 0. }}) == 0,
        "winding number: no dipoles must give 0");

  const Tet_mesh_leaves leaves{grid};
  const std::size_t nv = grid.points.size();
  std::vector<std::uint64_t> edges;
  const auto every_edge = [](std::uint64_t, std::uint64_t) { return true; };
  auto signs_of = [&](double (*f)(const Point&)) {
    std::vector<signed char> s(nv);
    for(std::size_t v = 0; v < nv; ++v) s[v] = f(grid.points[v]) < 0 ? -1 : 1;
    return s;
  };
  CHECK(internal::twice_euler_characteristic(leaves, {}, every_edge, signs_of(sphere_value), edges) == 4, "Euler characteristic: sphere");
  CHECK(internal::twice_euler_characteristic(leaves, {}, every_edge, signs_of(torus_value), edges) == 0, "Euler characteristic: torus");
  CHECK(internal::twice_euler_characteristic(leaves, {}, every_edge, signs_of(two_spheres_value), edges) == 8, "Euler characteristic: two spheres");

  std::vector<signed char> signs(nv, 1);
  std::vector<double> values(nv, 1.);
  std::vector<char> fixed(nv, 0);
  auto radius = [](const Point& p) { return std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]); };
  auto in_dent = [](const Point& p) { return p[0] > 0 && std::abs(p[1]) < 0.15 && std::abs(p[2]) < 0.15; };
  std::size_t dent = 0;
  for(std::size_t v = 0; v < nv; ++v)
  {
    const Point& p = grid.points[v];
    if(radius(p) < 0.5 && !in_dent(p)) { signs[v] = -1; values[v] = -1.; }
    if(radius(p) < 0.5 - 0.03 && in_dent(p)) ++dent;
    for(int d = 0; d < 3; ++d) fixed[v] = fixed[v] || std::abs(std::abs(p[d]) - 1) < 1e-9;
  }
  const std::vector<signed char> before = signs;
  const long euler = internal::twice_euler_characteristic(leaves, {}, every_edge, signs, edges);
  internal::Winding_number_cache cache(leaves, fixed);
  const std::size_t changed = internal::sign_by_winding_number(leaves, grid.points, neighbors, spacing, w, fixed,
                                                               internal::Winding_number_rule(), cache, signs, values);
  std::size_t dent_left = 0, wrong = 0;
  for(std::size_t v = 0; v < nv; ++v)
  {
    const Point& p = grid.points[v];
    if(radius(p) < 0.5 - 0.03 && in_dent(p) && signs[v] > 0) ++dent_left;
    if(radius(p) > 0.5 && signs[v] < 0) ++wrong;
    if(before[v] != signs[v]) CHECK(values[v] * signs[v] > 0, "winding number: a re-signed vertex's value has the wrong sign");
  }
  CHECK(dent > 50, "winding number: test set-up, " << dent << " dent vertices");
  CHECK(dent_left == 0, "winding number: " << dent_left << " of the " << dent << " dent vertices deeper than the spacing left outside");
  CHECK(wrong == 0, "winding number: " << wrong << " vertices outside the sphere turned inside");
  CHECK(changed > 0 && internal::twice_euler_characteristic(leaves, {}, every_edge, signs, edges) == euler,
        "winding number: " << changed << " vertices re-signed, the surface's Euler characteristic changed");

  // A flat pocket: the vertices of the plane x = 0 with |y| <= 0.3 and z >= -0.2 are outside,
  // a slit through the ball's top. The winding number says inside (0.9) in the slit's middle
  // (|y| <= 0.1, -0.05 <= z <= 0.1), weakly inside (0.55) on the strip from there down to the
  // slit's closed end, and outside on the rest. Filling the middle alone makes a pillar across
  // the slit, a handle: refused. Grown by three rings of leaves through the strip, the fill
  // reaches the slit's end, adds no handle, and is kept.
  const auto in_slit = [](const Point& p) { return std::abs(p[0]) < 1e-9 && std::abs(p[1]) < 0.3 + 1e-9 && p[2] > -0.2 - 1e-9; };
  const auto in_middle = [](const Point& p) { return std::abs(p[1]) < 0.1 + 1e-9 && p[2] > -0.05 - 1e-9 && p[2] < 0.1 + 1e-9; };
  const auto in_strip = [&](const Point& p) { return std::abs(p[1]) < 0.1 + 1e-9 && p[2] < -0.05 - 1e-9; };
  const auto slit_w = [&](const Point& p) { return in_slit(p) ? (in_middle(p) ? 0.9 : in_strip(p) ? 0.55 : 0.2) : radius(p) < 0.5 ? 1. : 0.; };
  for(const int growth_steps : { 3, 2, 0 })
  {
    std::vector<signed char> slit_signs(nv, 1);
    std::vector<double> slit_values(nv, 1.);
    std::size_t middle = 0, strip = 0;
    for(std::size_t v = 0; v < nv; ++v)
    {
      const Point& p = grid.points[v];
      if(radius(p) < 0.5 && !in_slit(p)) { slit_signs[v] = -1; slit_values[v] = -1.; }
      middle += in_slit(p) && in_middle(p);
      strip += in_slit(p) && in_strip(p);
    }
    const long slit_euler = internal::twice_euler_characteristic(leaves, {}, every_edge, slit_signs, edges);
    internal::Winding_number_rule rule;
    rule.growth_steps = growth_steps;
    internal::Winding_number_cache slit_cache(leaves, fixed);
    internal::sign_by_winding_number(leaves, grid.points, neighbors, spacing, slit_w, fixed, rule, slit_cache,
                                     slit_signs, slit_values);
    std::size_t filled = 0, wrong_fill = 0;
    for(std::size_t v = 0; v < nv; ++v)
    {
      const Point& p = grid.points[v];
      if(!in_slit(p)) continue;
      const bool expected = in_middle(p) || in_strip(p);
      if(slit_signs[v] < 0) (expected ? filled : wrong_fill) += 1;
    }
    const std::string name = "winding number, slit, " + std::to_string(growth_steps) + " growth steps: ";
    CHECK(slit_euler == 4 && middle == 20 && strip == 15, name << "test set-up, 2 chi " << slit_euler << ", " << middle
                                                                << " middle and " << strip << " strip vertices");
    CHECK(wrong_fill == 0, name << wrong_fill << " slit vertices filled where the winding number says outside");
    CHECK(filled == (growth_steps >= 3 ? middle + strip : 0), name << filled << " middle and strip vertices filled");
    CHECK(internal::twice_euler_characteristic(leaves, {}, every_edge, slit_signs, edges) == slit_euler,
          name << "the surface's Euler characteristic changed");
  }
}

// The PCA normals of the points are single precision (Plane_fit): read back as double they
// must be floats, and the same with 1 and 2 threads. GCC 12 at -O3 dropped the rounding of
// two components in some inlined copies of the loop body, so which chunks were rounded
// depended on the scheduling (F differed by 1e-10 between runs under load).
void point_normals_test()
{
  std::mt19937 rng(3);
  std::normal_distribution<double> gauss;
  std::vector<std::array<double, 3> > points;
  for(int i = 0; i < 10000; ++i)
  {
    const double x = gauss(rng), y = gauss(rng), z = gauss(rng), r = std::sqrt(x * x + y * y + z * z);
    points.push_back({{ x / r, 0.6 * y / r, 0.3 * z / r }});
  }
  std::vector<std::uint32_t> which(points.size());
  for(std::uint32_t i = 0; i < which.size(); ++i) which[i] = i;
  const internal::Point_neighbors neighbors(points);
  auto normals_with = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    std::vector<std::array<double, 3> > normals;
    std::vector<float> errors, radii;
    internal::estimate_point_normals(points, neighbors, which, 12, normals, errors, radii);
    return normals;
  };
  const std::vector<std::array<double, 3> > one = normals_with(1), two = normals_with(2);
  std::size_t unrounded = 0;
  for(const auto& n : two)
    for(double c : n) unrounded += double(float(c)) != c;
  CHECK(unrounded == 0, "point normals: " << unrounded << " components are not single precision");
  CHECK(one == two, "point normals: 1 and 2 threads differ");
}

// The propagation of orientations (normal_orientation.h). (1) A 30x30 grid of the plane z = 0,
// normals +-z, every 7th point a confident seed saying "+z is outside", one of them saying the
// opposite: the contradicted seed is overruled, and every point ends up +z. (2) A folded sheet
// (two walls z = 0 and z = 0.05, 0.05 apart, joined by a half-tube rim at x = 1), seeded on
// the lower wall only: the lower wall is outside below (-z), the upper above (+z). The rim's
// points, marked as not one sheet, must not pass the lower wall's side on: the upper wall
// stays unoriented or right, never "-z outside". (3) The plane again, with 8 neighbours (the
// ring around a grid point): two wrong seeds side by side, A with one right seed in its ring,
// B with three; B falls at once, A only when judged again without B (one round would leave A
// standing on a tie and turn the points around it).
void propagation_test()
{
  using internal::Orientation_test;
  {
    std::vector<std::array<double, 3> > points, normals;
    for(int i = 0; i < 30; ++i)
      for(int j = 0; j < 30; ++j)
      {
        points.push_back({{ 0.01 * i, 0.01 * j, 0. }});
        normals.push_back({{ 0., 0., (i + j) % 2 ? 1. : -1. }});
      }
    std::vector<Orientation_test> tests(points.size());
    std::size_t wrong_seed = 15 * 30 + 15;
    for(std::size_t k = 0; k < points.size(); ++k)
    {
      tests[k].leaf_size = 0.02;
      if(k % 7 == 0 || k == wrong_seed)
      {
        tests[k].confident = true;
        tests[k].sign = static_cast<signed char>(normals[k][2] > 0 ? 1 : -1);
        tests[k].relative = 1.;
      }
    }
    tests[wrong_seed].sign = static_cast<signed char>(-tests[wrong_seed].sign);
    internal::propagate_orientations(points, normals, tests, 18, 0.5);
    std::size_t wrong = 0;
    for(std::size_t k = 0; k < points.size(); ++k) wrong += tests[k].sign * normals[k][2] <= 0;
    CHECK(wrong == 0, "propagation: " << wrong << " of 900 plane points point inside (one seed contradicted by its neighbours)");
  }
  {
    const double h = 0.025, pi = 3.14159265358979323846;
    std::vector<std::array<double, 3> > points, normals;
    std::vector<char> one_sheet;
    std::vector<int> wall;  // 0 lower, 1 upper, 2 rim
    for(int j = 0; j < 20; ++j)
    {
      const double y = 0.01 * j;
      for(int i = 0; i <= 100; ++i)
        for(int w = 0; w < 2; ++w)
        {
          points.push_back({{ 0.01 * i, y, 2. * h * w }});
          normals.push_back({{ 0., 0., 1. }});  // unoriented: both walls alike
          one_sheet.push_back(1);
          wall.push_back(w);
        }
      for(int a = 1; a < 8; ++a)
      {
        const double t = -0.5 * pi + pi * a / 8.;
        points.push_back({{ 1. + h * std::cos(t), y, h + h * std::sin(t) }});
        // a rim point's neighbourhood spans both walls: its fitted normal is the mid-plane's
        normals.push_back({{ 0., 0., 1. }});
        one_sheet.push_back(0);
        wall.push_back(2);
      }
    }
    std::vector<Orientation_test> tests(points.size());
    for(std::size_t k = 0; k < points.size(); ++k)
    {
      tests[k].leaf_size = 0.02;
      if(wall[k] == 0 && points[k][0] < 0.3)
      {
        tests[k].confident = true;
        tests[k].sign = -1;  // +z points inside the fold
        tests[k].relative = 1.;
      }
    }
    std::vector<Orientation_test> without = tests;
    internal::propagate_orientations(points, normals, tests, 18, 0.5, one_sheet);
    internal::propagate_orientations(points, normals, without, 18, 0.5);
    std::size_t upper_wrong = 0, upper_wrong_without = 0, lower_wrong = 0;
    for(std::size_t k = 0; k < points.size(); ++k)
    {
      if(wall[k] == 1) { upper_wrong += tests[k].sign < 0; upper_wrong_without += without[k].sign < 0; }
      if(wall[k] == 0) lower_wrong += tests[k].sign != -1;
    }
    CHECK(lower_wrong == 0, "propagation: " << lower_wrong << " lower-wall points of the fold not oriented outside (-z)");
    CHECK(upper_wrong == 0, "propagation: " << upper_wrong << " upper-wall points of the fold oriented across the rim");
    // the case is one the rule is needed for
    CHECK(upper_wrong_without > 0, "propagation: without the one-sheet rule the rim did not turn the upper wall");
  }
  {
    std::vector<std::array<double, 3> > points, normals;
    for(int i = 0; i < 30; ++i)
      for(int j = 0; j < 30; ++j)
      {
        points.push_back({{ 0.01 * i, 0.01 * j, 0. }});
        normals.push_back({{ 0., 0., (i + j) % 2 ? 1. : -1. }});
      }
    auto at = [](int i, int j) { return std::size_t(30 * i + j); };
    std::vector<Orientation_test> tests(points.size());
    auto seed = [&](std::size_t k, bool right) {
      tests[k].confident = true;
      tests[k].sign = static_cast<signed char>((normals[k][2] > 0) == right ? 1 : -1);
      tests[k].relative = 1.;
    };
    for(Orientation_test& t : tests) t.leaf_size = 0.02;
    const std::size_t a = at(15, 15), b = at(16, 15);
    seed(a, false);
    seed(b, false);
    seed(at(14, 15), true);  // A's only right neighbour; backed by the seeds at i = 12, 13
    for(int i : { 12, 13, 17, 18 })
      for(int j : { 14, 15, 16 }) seed(at(i, j), true);
    internal::propagate_orientations(points, normals, tests, 8, 0.5);
    std::size_t wrong = 0;
    for(std::size_t k = 0; k < points.size(); ++k) wrong += tests[k].sign * normals[k][2] <= 0;
    CHECK(!tests[a].confident && !tests[b].confident, "propagation: a wrong seed backed only by a fallen wrong seed stands");
    CHECK(wrong == 0, "propagation: " << wrong << " of 900 plane points point inside (a wrong seed judged once)");
  }
}

// Islands on the 40^3 Kuhn grid (spacing 0.05): two boxes `gap` grid layers apart are joined
// across one or two outside vertices and stay apart across three; a ring cut at two places
// into two arcs is joined at one cut only (joining both would make a handle, which the
// Euler characteristic cannot tell from a join).
double box_value(const Point& p, double x0, double x1)
{
  const double c[3] = { 0.5 * (x0 + x1), 0., 0. }, half[3] = { 0.5 * (x1 - x0), 0.3, 0.3 };
  double d = -1e9;
  for(int k = 0; k < 3; ++k) d = (std::max)(d, std::abs(p[k] - c[k]) - half[k]);
  return d;
}
double cut_ring_value(const Point& p) { return (std::max)(torus_value(p), 0.025 - std::abs(p[0])); }

template <class Function>
void join_islands_case(const Tet_mesh& m, const Function& f, const std::string& name, long euler_before,
                       long euler_after, std::size_t joins,
                       const std::function<bool(const Point&)>& among_points = [](const Point&) { return true; })
{
  std::vector<double> values = sample(m, f);
  std::vector<signed char> signs;
  std::vector<char> boundary;
  signs_and_boundary(m, values, signs, boundary);
  std::vector<Point> pts;
  std::vector<Triangle> tris;
  internal::marching_tetrahedra(m.points, m.tets, values, pts, tris);
  CHECK(check_surface(pts, tris).euler == euler_before, name << ": the input has Euler characteristic "
                                                            << check_surface(pts, tris).euler << ", not " << euler_before);
  const std::size_t joined = internal::join_islands(Tet_mesh_leaves{m}, m.points, boundary, signs, values, 1e-9, among_points);
  for(std::size_t v = 0; v < values.size(); ++v)
    CHECK((values[v] < 0) == (signs[v] < 0), name << ": value and sign of vertex " << v << " disagree");
  internal::marching_tetrahedra(m.points, m.tets, values, pts, tris);
  const Surface_check c = check_surface(pts, tris);
  CHECK(c.closed_manifold, name << ": not a closed 2-manifold after joining: " << c.error);
  CHECK(c.euler == euler_after && joined == joins, name << ": " << joined << " joins, Euler characteristic " << c.euler
                                                        << "; expected " << joins << " and " << euler_after);
  std::cout << "  " << name << ": " << joined << " joins, chi " << euler_before << " -> " << c.euler << std::endl;
}

void join_islands_test(const Tet_mesh& grid)
{
  for(int gap = 1; gap <= 3; ++gap)
  {
    // inside vertices of the left box up to x = -0.05, of the right one from 0.05 (gap - 1)
    const auto two_boxes = [gap](const Point& p) {
      return (std::min)(box_value(p, -0.475, -0.025), box_value(p, 0.025 + 0.05 * (gap - 1), 0.475));
    };
    join_islands_case(grid, two_boxes, "two boxes " + std::to_string(gap) + " vertex layers apart", 4,
                      gap <= 2 ? 2 : 4, gap <= 2 ? 1 : 0);
  }
  // the same, but no vertex between them lies among the points: two objects, not a neck
  const auto touching_boxes = [](const Point& p) {
    return (std::min)(box_value(p, -0.475, -0.025), box_value(p, 0.025, 0.475));
  };
  join_islands_case(grid, touching_boxes, "two boxes 1 vertex layer apart, the bridge not among the points", 4, 4, 0,
                    [](const Point&) { return false; });
  // the bridge vertices among the points, the middles of their edges not (the points only at
  // the grid's vertices): the edges cross open space, as between two objects far apart
  const auto at_a_grid_vertex = [](const Point& p) {
    for(int k = 0; k < 3; ++k)
      if(std::abs(p[k] / 0.05 - std::round(p[k] / 0.05)) > 0.01) return false;
    return true;
  };
  join_islands_case(grid, touching_boxes, "two boxes 1 vertex layer apart, the bridge's edges not among the points", 4,
                    4, 0, at_a_grid_vertex);
  join_islands_case(grid, touching_boxes, "two boxes 1 vertex layer apart, the bridge among the points", 4, 2, 1,
                    [](const Point&) { return true; });
  join_islands_case(grid, cut_ring_value, "a ring cut in two arcs", 4, 2, 1);
  join_islands_case(grid, torus_value, "a torus (one cluster)", 0, 0, 0);
}

int main()
{
  std::cout << "Ising annealing" << std::endl;
  ferromagnet_test(48, 48, 1, "2D ferromagnet 48x48");
  ferromagnet_test(16, 16, 16, "3D ferromagnet 16^3");
  planted_test();
  energy_test();
  determinism_test();
  degenerate_annealing_test();
  point_normals_test();

  std::cout << "Marching tetrahedra" << std::endl;
  const double pi = 3.14159265358979323846;
  const Tet_mesh grid = kuhn_grid(40, false);
  marching_test(grid, sphere_value, "sphere", 2, 4. / 3. * pi * std::pow(sphere_radius, 3));
  marching_test(grid, torus_value, "torus", 0, 2. * pi * pi * torus_R * torus_r * torus_r);
  marching_test(grid, two_spheres_value, "two spheres", 4,
                4. / 3. * pi * (std::pow(0.35, 3) + std::pow(0.3, 3)));
  const Tet_mesh shuffled = kuhn_grid(24, true);
  marching_test(shuffled, sphere_value, "sphere (shuffled even corner orders)", 2,
                4. / 3. * pi * std::pow(sphere_radius, 3));
  {
    std::vector<Point> pts(1);
    std::vector<Triangle> tris(1);
    internal::marching_tetrahedra(grid.points, {}, std::vector<double>(grid.points.size(), 1.), pts, tris);
    CHECK(pts.empty() && tris.empty(), "marching tetrahedra: no tets must give an empty output");
  }

  std::cout << "Thin handles" << std::endl;
  thin_handle_test(grid, drilled_sphere_value, "sphere drilled by a thin hole", 0, 2);
  thin_handle_test(grid, torus_value, "torus with a thick tube", 0, 0);
  thin_handle_test(grid, drilled_sphere_distance, "sphere drilled by a thin hole, true distances", 0, 2);
  // the local size: every Kuhn tet's longest edge is h sqrt(3), the median, so the smallest
  // leaf at a vertex over 0.88 is 1.14 times it; at relative depth 0.32 the median alone
  // gives 0.0277 < 0.03, the hole's depth (it stays), the local size 0.0315 (it is filled)
  thin_handle_test(grid, drilled_sphere_value, "thin hole below the median depth", 0, 0, 0.32, false);
  thin_handle_test(grid, drilled_sphere_value, "thin hole within the local leaves' depth", 0, 2, 0.32, true);
  ring_restore_test(true);
  ring_restore_test(false);

  std::cout << "Distance estimate" << std::endl;
  disk_distance_test();

  std::cout << "Bulk extent" << std::endl;
  bulk_extent_test();

  std::cout << "Tangent-plane signs" << std::endl;
  tangent_plane_test();

  std::cout << "Orientation propagation" << std::endl;
  propagation_test();

  std::cout << "Escape rays" << std::endl;
  escape_rays_test(kuhn_grid(40, false));

  std::cout << "Joined islands" << std::endl;
  join_islands_test(grid);

  std::cout << "Winding number" << std::endl;
  winding_number_test(kuhn_grid(40, false));

  std::cout << "Misfit leaves" << std::endl;
  misfit_leaves_test();

  std::cout << "Point smoothing" << std::endl;
  point_smoothing_test();

  std::cout << "Jet crossings" << std::endl;
  jet_crossing_test(grid);

  std::cout << "Taubin smoothing" << std::endl;
  taubin_test(grid);

  if(number_of_failures != 0)
  {
    std::cerr << number_of_failures << " check(s) FAILED" << std::endl;
    return 1;
  }
  std::cout << "all internal algorithm tests passed" << std::endl;
  return 0;
}
