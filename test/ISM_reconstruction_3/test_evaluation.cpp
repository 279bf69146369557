// Tests of the evaluation utilities (common/ism_evaluation.h) themselves: analytic ground
// truths, sampler, topology, in/out accuracy, distances, and the real meshes of the data
// tarball. Usage: test_evaluation [directory holding bunny00.off knot1.off eight.off ...]
#include "ism_evaluation.h"

#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

using namespace ISM_eval;

static int failures = 0;

#define CHECK(cond)                                                                        \
  do {                                                                                     \
    if (!(cond)) {                                                                         \
      std::cerr << "FAILED: " #cond " (" << __FILE__ << ":" << __LINE__ << ")" << std::endl; \
      ++failures;                                                                          \
    }                                                                                      \
  } while (0)

#define CHECK_MSG(cond, msg)                                                               \
  do {                                                                                     \
    if (!(cond)) {                                                                         \
      std::cerr << "FAILED: " #cond " [" << msg << "] (" << __FILE__ << ":" << __LINE__ << ")" \
                << std::endl;                                                              \
      ++failures;                                                                          \
    }                                                                                      \
  } while (0)

// Topology, orientation, self-intersection, and sampler checks common to analytic meshes.
static void check_analytic(const std::string& name, const Mesh& m, std::size_t comps, int genus, long euler) {
  const Topology t = topology(m);
  std::cout << name << ": V=" << m.number_of_vertices() << " F=" << m.number_of_faces() << " " << t << std::endl;
  CHECK_MSG(t.components == comps, name);
  CHECK_MSG(t.genus == genus, name);
  CHECK_MSG(t.euler == euler, name);
  CHECK_MSG(t.closed, name);
  CHECK_MSG(t.manifold, name);
  CHECK_MSG(t.self_consistent, name);
  CHECK_MSG(t.boundary_cycles == 0, name);
  CHECK_MSG(CGAL::is_triangle_mesh(m), name);
  CHECK_MSG(is_outward_oriented(m), name);
  CHECK_MSG(!PMP::does_self_intersect(m), name);

  // Sampler: points on the mesh, normals outward (p + eps n outside, p - eps n inside).
  const double diag = diagonal(bbox(m));
  const auto samples = sample_points(m, 2000, 7);
  CHECK_MSG(samples.size() == 2000, name);
  Face_tree tree(faces(m).first, faces(m).second, m);
  tree.accelerate_distance_queries();
  const Inside_oracle inside = inside_oracle(m);
  double max_d = 0;
  std::size_t bad_normals = 0;
  const double eps = 1e-4 * diag;
  for (const auto& s : samples) {
    max_d = (std::max)(max_d, std::sqrt(CGAL::to_double(tree.squared_distance(s.first))));
    CHECK_MSG(std::abs(std::sqrt(CGAL::to_double(s.second.squared_length())) - 1) < 1e-12, name);
    if (inside(s.first + eps * s.second) || !inside(s.first - eps * s.second)) ++bad_normals;
  }
  CHECK_MSG(max_d < 1e-12 * diag, name << " max sample distance " << max_d);
  CHECK_MSG(bad_normals == 0, name << " " << bad_normals << " normals not outward");

  // In/out accuracy of the truth against itself and against its complement.
  const CGAL::Bbox_3 box = scaled_bbox(bbox(m), 1.2);
  const Inout_score self = inout_accuracy(m, box, inside, 20000, 0.01, 3);
  const Inout_score compl_ = inout_accuracy(
      m, box, [&](const Point_3& p) { return !inside(p); }, 20000, 0.01, 3);
  std::cout << "  inout self: overall=" << self.overall << " far=" << self.far << " n_far=" << self.n_far
            << "/" << self.n << "; complement: overall=" << compl_.overall << " far=" << compl_.far
            << std::endl;
  CHECK_MSG(self.overall == 1.0 && self.far == 1.0, name);
  CHECK_MSG(self.n == 20000 && self.n_far > 15000 && self.n_far < 20000, name);
  CHECK_MSG(compl_.overall < 1e-3 && compl_.far == 0.0, name);
}

static void test_rng() {
  Rng a(42), b(42), c(43);
  bool same = true, differ = false;
  for (int i = 0; i < 100; ++i) {
    const double x = a.uniform(), y = b.uniform(), z = c.uniform();
    same = same && (x == y);
    differ = differ || (x != z);
    CHECK(x >= 0 && x < 1);
  }
  CHECK(same && differ);
  // mt19937_64: the 10000th output of a default-constructed engine is specified by the standard.
  std::mt19937_64 e;
  e.discard(9999);
  CHECK(e() == 9981545732273789042ull);
  // Gaussian moments.
  Rng g(1);
  const int n = 200000;
  double s1 = 0, s2 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = g.gaussian();
    s1 += x;
    s2 += x * x;
  }
  const double mean = s1 / n, var = s2 / n - mean * mean;
  std::cout << "gaussian: mean=" << mean << " var=" << var << std::endl;
  CHECK(std::abs(mean) < 0.01 && std::abs(var - 1) < 0.02);
  std::size_t counts[5] = {0, 0, 0, 0, 0};
  Rng u(5);
  for (int i = 0; i < 50000; ++i) ++counts[u.uniform_index(5)];
  for (std::size_t k : counts) CHECK(k > 9500 && k < 10500);
}

static void test_analytic() {
  const Point_3 o(0, 0, 0);
  const Mesh sphere = make_sphere(o, 1.0, 24);
  check_analytic("sphere", sphere, 1, 0, 2);
  CHECK(sphere.number_of_vertices() == 2 + 23 * 48 && sphere.number_of_faces() == 4 * 24 * 23);

  const Mesh torus = make_torus(Point_3(1, 2, 3), 2.0, 0.6, 48, 24);
  check_analytic("torus", torus, 1, 1, 0);

  const Mesh two = make_two_spheres(Point_3(-2, 0, 0), 1.0, Point_3(2, 0.5, 0), 0.7, 20);
  check_analytic("two_spheres", two, 2, 0, 4);

  const Mesh nested = make_nested_spheres(o, 2.0, 1.0, 24);
  check_analytic("nested_spheres", nested, 2, 0, 4);
  {
    // in/out/in along a ray: hollow (out), shell (in), exterior (out); and the solid volume.
    const Inside_oracle in = inside_oracle(nested);
    CHECK(!in(Point_3(0, 0, 0)) && !in(Point_3(0.5, 0.3, -0.2)));
    CHECK(in(Point_3(1.5, 0, 0)) && in(Point_3(0, -1.5, 0.1)) && in(Point_3(0.8, 0.8, 0.8)));
    CHECK(!in(Point_3(2.5, 0, 0)) && !in(Point_3(1.5, 1.5, 1.5)));
    const double v = signed_volume(nested), expected = 4.0 / 3.0 * 3.14159265358979 * (8.0 - 1.0);
    std::cout << "  nested signed volume " << v << " (continuous " << expected << ")" << std::endl;
    CHECK(v > 0.97 * expected && v < expected);
    // same two spheres, inner one outward: not a consistently oriented shell
    Mesh bad = make_sphere(o, 2.0, 24);
    bad.join(make_sphere(o, 1.0, 24));
    CHECK(!is_outward_oriented(bad));
    Mesh rev = make_sphere(o, 1.0, 24);
    PMP::reverse_face_orientations(rev);
    CHECK(!is_outward_oriented(rev) && signed_volume(rev) < 0);
  }

  const Mesh trefoil = make_trefoil_tube(Point_3(0.5, 0, 0), 1.0);
  check_analytic("trefoil", trefoil, 1, 1, 0);

  // Sampler: determinism, noise level.
  {
    const auto s1 = sample_points(torus, 1000, 11), s2 = sample_points(torus, 1000, 11),
               s3 = sample_points(torus, 1000, 12);
    bool same = true, differ = false;
    for (std::size_t i = 0; i < s1.size(); ++i) {
      same = same && s1[i].first == s2[i].first && s1[i].second == s2[i].second;
      differ = differ || s1[i].first != s3[i].first;
    }
    CHECK(same && differ);
    const double sigma = 0.01;
    const auto noisy = sample_points(sphere, 20000, 5, sigma);
    double sum = 0, sum2 = 0;
    for (const auto& s : noisy) {
      const double d = std::sqrt(CGAL::to_double(s.first.x() * s.first.x() + s.first.y() * s.first.y() +
                                                 s.first.z() * s.first.z())) - 1.0;
      sum += d;
      sum2 += d * d;
    }
    const double rms = std::sqrt(sum2 / noisy.size());
    std::cout << "  noise sigma=" << sigma << ": mean radial offset " << sum / noisy.size() << " rms " << rms
              << std::endl;
    CHECK(std::abs(rms - sigma) < 0.05 * sigma);
    // Area weighting: on a sphere, fraction of samples with z > 0.5 is (1 - 0.5)/2 = 0.25.
    const auto uni = sample_points(make_sphere(o, 1.0, 64), 40000, 9);
    std::size_t cap = 0;
    for (const auto& s : uni)
      if (s.first.z() > 0.5) ++cap;
    std::cout << "  cap fraction " << double(cap) / uni.size() << " (0.25)" << std::endl;
    CHECK(std::abs(double(cap) / uni.size() - 0.25) < 0.01);
  }

  // Distances: sphere vs. sphere scaled by 1.01 about its center.
  {
    Mesh big = sphere;
    PMP::transform(K::Aff_transformation_3(CGAL::SCALING, 1.01), big);
    const Distance_score d = symmetric_distance(sphere, big, 20000, 1);
    std::cout << "  sphere vs 1.01 sphere: mean=" << d.mean << " max=" << d.max << " (0.01)" << std::endl;
    CHECK(d.mean > 0.0095 && d.mean < 0.0101 && d.max > 0.0095 && d.max < 0.0102);
    const Distance_score z = symmetric_distance(sphere, sphere, 5000, 1);
    CHECK(z.mean < 1e-12 && z.max < 1e-12);
    // Distance from a sphere to the two-sphere mesh is dominated by the missing component.
    const Distance_score t = symmetric_distance(make_sphere(Point_3(-2, 0, 0), 1.0, 20), two, 5000, 2);
    std::cout << "  one sphere vs two spheres: mean=" << t.mean << " max=" << t.max << std::endl;
    CHECK(t.max > 2.0 && t.mean > 0.3);
  }

  // Topology of open and degenerate inputs.
  {
    Mesh open = sphere;
    CGAL::Euler::remove_face(halfedge(*faces(open).begin(), open), open);
    const Topology t = topology(open);
    std::cout << "  sphere minus one face: " << t << std::endl;
    CHECK(!t.closed && t.euler == 1 && t.boundary_cycles == 1 && t.genus == 0 && t.components == 1 && !t.self_consistent);
    Mesh empty;
    const Topology e = topology(empty);
    CHECK(e.components == 0 && e.euler == 0);
    CHECK(!inside_oracle(empty)(o));
  }
}

// read_mesh: quads are triangulated; a non-manifold vertex (two tetrahedra sharing a vertex)
// is rejected by the strict reader and repaired by the PMP reader (vertex duplicated).
static void test_read() {
  {
    std::ofstream os("ism_eval_cube_quads.off");
    os << "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
          "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
  }
  Mesh cube;
  CHECK(read_mesh("ism_eval_cube_quads.off", cube));
  const Topology tc = topology(cube);
  std::cout << "cube of quads: V=" << cube.number_of_vertices() << " F=" << cube.number_of_faces() << " " << tc
            << std::endl;
  CHECK(CGAL::is_triangle_mesh(cube) && cube.number_of_faces() == 12 && tc.genus == 0 && tc.closed);
  CHECK(is_outward_oriented(cube) && std::abs(signed_volume(cube) - 1) < 1e-12);
  {
    std::ofstream os("ism_eval_bowtie.off");
    os << "OFF\n7 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n-1 0 0\n0 -1 0\n0 0 -1\n"
          "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
          "3 0 5 4\n3 0 4 6\n3 0 6 5\n3 4 5 6\n";
  }
  Mesh bowtie;
  CHECK(read_mesh("ism_eval_bowtie.off", bowtie));
  const Topology tb = topology(bowtie);
  std::cout << "two tetrahedra sharing a vertex: V=" << bowtie.number_of_vertices() << " " << tb << std::endl;
  CHECK(tb.components == 2 && tb.closed && tb.manifold && tb.genus == 0 && bowtie.number_of_vertices() == 8);
  std::remove("ism_eval_cube_quads.off");
  std::remove("ism_eval_bowtie.off");
  Mesh none;
  CHECK(!read_mesh("ism_eval_does_not_exist.off", none));
}

struct Real_expect {
  const char* file;
  int genus;  // -1: report only
};

static void test_real(const std::string& dir) {
  const Real_expect expected[] = {{"bunny00.off", 0},
                                  {"knot1.off", 1},
                                  {"eight.off", 2},
                                  {"knot2.off", -1},
                                  {"double-torus-example.off", -1},
                                  {"3torus.off", -1},
                                  {"sphere.off", -1},
                                  {"ChineseDragon-10kv.off", -1}};
  for (const Real_expect& e : expected) {
    const std::string file = dir + "/" + e.file;
    CGAL::Real_timer file_timer;
    file_timer.start();
    Mesh m;
    const bool ok = read_mesh(file, m);
    if (!ok) {
      std::cout << e.file << ": cannot read" << std::endl;
      CHECK_MSG(e.genus < 0, "cannot read " << file);
      continue;
    }
    const Topology t = topology(m);
    const CGAL::Bbox_3 b = bbox(m);
    const bool closed = t.closed;
    const bool si = PMP::does_self_intersect(m);
    std::cout << e.file << ": V=" << m.number_of_vertices() << " F=" << m.number_of_faces() << " diag=" << diagonal(b)
              << " " << t << " self_intersect=" << si
              << " outward=" << (closed ? (is_outward_oriented(m) ? "yes" : "no") : "n/a") << std::endl;
    if (e.genus >= 0) {
      CHECK_MSG(t.closed && t.manifold && t.self_consistent, e.file);
      CHECK_MSG(t.components == 1, e.file);
      CHECK_MSG(t.genus == e.genus, e.file << " genus " << t.genus);
      CHECK_MSG(is_outward_oriented(m), e.file);
      // sampler on real data: on the surface, normals outward
      const auto s = sample_points(m, 2000, 1);
      const Inside_oracle in = inside_oracle(m);
      Face_tree tree(faces(m).first, faces(m).second, m);
      double md = 0;
      std::size_t outward = 0;
      const double eps = 1e-5 * diagonal(b);
      for (const auto& p : s) {
        md = (std::max)(md, std::sqrt(CGAL::to_double(tree.squared_distance(p.first))));
        if (!in(p.first + eps * p.second) && in(p.first - eps * p.second)) ++outward;
      }
      std::cout << "  samples: max distance " << md << ", outward normals " << outward << "/" << s.size()
                << std::endl;
      CHECK_MSG(md < 1e-9 * diagonal(b), e.file);
      // thin features can make p - eps n cross another sheet: allow a tiny share
      CHECK_MSG(outward >= s.size() * 995 / 1000, e.file);
      const Inout_score self = inout_accuracy(m, scaled_bbox(b, 1.1), in, 20000, 0.01, 4);
      CHECK_MSG(self.overall == 1.0, e.file);
    }
    if (!closed) {
      Mesh filled = m;
      CGAL::Real_timer timer;
      timer.start();
      const bool closed_now = close_holes(filled);
      const Topology tf = topology(filled);
      std::cout << "  close_holes: " << (closed_now ? "closed" : "NOT closed") << " in " << timer.time()
                << " s: V=" << filled.number_of_vertices() << " F=" << filled.number_of_faces() << " " << tf
                << " self_intersect=" << PMP::does_self_intersect(filled)
                << " outward=" << (closed_now ? (is_outward_oriented(filled) ? "yes" : "no") : "n/a")
                << std::endl;
      if (std::string(e.file) == "ChineseDragon-10kv.off") {
        CHECK_MSG(closed_now && tf.closed && tf.manifold && tf.components == 1, "dragon hole filling");
        const Distance_score d = symmetric_distance(m, filled, 20000, 1);
        std::cout << "  filled vs original: mean=" << d.mean / diagonal(b) << " max=" << d.max / diagonal(b)
                  << " (relative to diagonal)" << std::endl;
      }
    }
    std::cout << "  [" << file_timer.time() << " s]" << std::endl;
  }
}

int main(int argc, char** argv) {
  CGAL::Real_timer total;
  total.start();
  CGAL::Real_timer t;
  t.start();
  test_rng();
  std::cout << "[rng " << t.time() << " s]" << std::endl;
  t.reset();
  test_read();
  test_analytic();
  std::cout << "[read + analytic " << t.time() << " s]" << std::endl;
  if (argc > 1) {
    t.reset();
    test_real(argv[1]);
    std::cout << "[real data " << t.time() << " s]" << std::endl;
  } else {
    std::cout << "no data directory given: real-data checks skipped" << std::endl;
  }
  std::cout << "[total " << total.time() << " s]" << std::endl;
  if (failures) {
    std::cerr << failures << " check(s) failed" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "all checks passed" << std::endl;
  return EXIT_SUCCESS;
}
