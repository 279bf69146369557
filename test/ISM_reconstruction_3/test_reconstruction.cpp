// End-to-end tests of the reconstruction on inputs with a known answer: analytic shapes
// (sphere, torus, two spheres, nested spheres, trefoil tube) and real meshes from
// libcgal-demo, sampled area-weighted with a fixed seed, without normals.
// For each: closed and 2-manifold, components and genus of the truth, in/out agreement
// (F and the output mesh) >= 99.5 % overall and 100 % farther than 1 % of the diagonal,
// symmetric mean distance <= 0.5 % of the diagonal. Plus the API: named parameters,
// Polyhedron_3 output, the paper's settings, cancellation, determinism, other kernels and
// Point_set_3, the unit of the coordinates, bad input.
//
// usage: test_reconstruction <directory holding bunny00.off, knot1.off, eight.off, ChineseDragon-10kv.off>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Random.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/ism_surface_reconstruction.h>
#include <CGAL/property_map.h>
#include "ism_evaluation.h"

#include <forward_list>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <type_traits>

using namespace ISM_eval;
static int failures = 0;
#define CHECK(cond, what)                                                          \
  do { if(!(cond)) { ++failures; std::cerr << "FAILED: " << what << "\n"; } } while(0)

// `overall`: the share of all queries on the right side required (sparse samplings round
// off more of the surface's detail than 0.5 %)
static void check_case(const std::string& name, const Mesh& truth, std::size_t n, double overall = 0.995)
{
  const auto samples = sample_points(truth, n, 42, 0);
  std::vector<Point_3> points;
  for(const auto& s : samples) points.push_back(s.first);
  CGAL::ISM_reconstruction_function<K> function(points);
  const CGAL::ISM_reconstruction_3::Settings settings;
  function.compute_implicit_function_with_settings(settings);
  Mesh out;
  CGAL::ISM_reconstruction_3::extract_surface(function, out, settings.smoothing_iterations, settings.smoothing_lambda,
                                              settings.smoothing_mu, settings.crossing_neighbors);
  const Topology t = topology(truth), o = topology(out);
  const CGAL::Bbox_3 bb = bbox(truth);
  const double diag = diagonal(bb);
  const Inout_score f = inout_accuracy(truth, scaled_bbox(bb, 1.2), [&](const Point_3& p) { return function(p) < 0; },
                                       20000, 0.01, 7);
  const Inout_score m = inout_accuracy(truth, scaled_bbox(bb, 1.2), inside_oracle(out), 20000, 0.01, 7);
  const Distance_score d = symmetric_distance(truth, out, 20000, 3);
  std::cout << "| " << name << " | " << n << " | " << function.statistics().number_of_leaves << " | "
            << o.components << " (" << t.components << ") | " << o.genus << " (" << t.genus << ") | "
            << (o.closed && o.manifold) << " | " << 100 * f.overall << " / " << 100 * f.far << " | "
            << 100 * m.overall << " / " << 100 * m.far << " | " << 100 * d.mean / diag << " | " << 100 * d.max / diag
            << " |" << std::endl;
  CHECK(o.closed && o.manifold, name + ": output closed and 2-manifold");
  CHECK(o.components == t.components, name + ": number of components");
  CHECK(o.genus == t.genus, name + ": genus");
  CHECK(f.overall >= overall && m.overall >= overall, name + ": in/out >= " + std::to_string(100 * overall) + " %");
  CHECK(f.far == 1. && m.far == 1., name + ": in/out 100 % farther than 1 % of the diagonal");
  CHECK(d.mean <= 0.005 * diag, name + ": mean distance <= 0.5 % of the diagonal");
}

int main(int argc, char** argv)
{
  const std::string dir = argc > 1 ? argv[1] : "data/meshes";
  std::cout << "| case | points | leaves | components (truth) | genus (truth) | closed+manifold | in/out F % (far) | "
               "in/out mesh % (far) | mean dist % | max dist % |\n|---|---|---|---|---|---|---|---|---|---|\n";
  check_case("sphere", make_sphere(Point_3(0, 0, 0), 1, 48), 20000);
  check_case("torus", make_torus(Point_3(0, 0, 0), 1, 0.35), 30000);
  check_case("two spheres", make_two_spheres(Point_3(0, 0, 0), 1, Point_3(2.5, 0, 0), 0.8), 30000);
  // 0.5 apart, about 9 point spacings: join_islands joined them across one vertex in the
  // gap's large leaves before a bridge had to lie among the points
  check_case("two spheres 0.5 apart, 8000 points", make_two_spheres(Point_3(0, 0, 0), 1, Point_3(2.5, 0, 0), 1), 8000);
  // five spheres 1.2 apart, 800 points each (about 7 point spacings): a bridge vertex beside
  // one sphere reached the next across a leaf edge as long as the gap (3 components)
  {
    Mesh row = make_sphere(Point_3(0, 0, 0), 1);
    for(int k = 1; k < 5; ++k) ISM_eval::internal::append(row, make_sphere(Point_3(3.2 * k, 0, 0), 1));
    check_case("five spheres 1.2 apart, 800 points each", row, 4000, 0.985);
  }
  check_case("nested spheres", make_nested_spheres(Point_3(0, 0, 0), 1, 0.5), 30000);
  check_case("trefoil tube", make_trefoil_tube(), 36000);
  for(const std::string file : {"bunny00.off", "knot1.off", "eight.off", "ChineseDragon-10kv.off"})
  {
    Mesh truth;
    if(!read_mesh(dir + "/" + file, truth)) { CHECK(false, "cannot read " + dir + "/" + file); continue; }
    if(!CGAL::is_closed(truth)) close_holes(truth);
    // the dragon has thin details: at 36k points they are undersampled (genus 2 measured), at
    // 150k and at the paper's 437k points they are resolved
    const std::size_t n = file == std::string("knot1.off") ? 100000 : file == std::string("ChineseDragon-10kv.off") ? 150000 : 36000;
    check_case(file, truth, n);
    if(file != std::string("bunny00.off")) continue;
    // 3,000 points on the bunny: the samplings on which the tip of an ear came out as a
    // second component, cut off at a neck too thin for the leaves (3 and 2 components on
    // seeds 4 and 8 with join_islands(false)), give one component of genus 0. Since the
    // sparse cells take the planes of their nearest points (sparse_cell_planes), seed 4
    // needs no joining: one of the two must still need it, or this tests nothing of it.
    bool joining_needed = false;
    for(unsigned int seed : { 4u, 8u })
    {
      std::vector<Point_3> sparse;
      for(const auto& s : sample_points(truth, 3000, seed, 0)) sparse.push_back(s.first);
      Mesh joined, apart;
      CGAL::ism_surface_reconstruction(sparse, joined);
      CGAL::ism_surface_reconstruction(sparse, apart, CGAL::parameters::join_islands(false));
      const Topology j = topology(joined), a = topology(apart);
      std::cout << "  bunny00 at 3000 points, seed " << seed << ": " << j.components << " component(s), genus " << j.genus
                << " (without join_islands: " << a.components << ")" << std::endl;
      CHECK(j.closed && j.manifold && j.components == 1 && j.genus == 0,
            "bunny00 at 3000 points, seed " + std::to_string(seed) + ": one component of genus 0");
      joining_needed = joining_needed || a.components > 1;
    }
    CHECK(joining_needed, "bunny00 at 3000 points, seed 4 or 8: more than one component without join_islands");
  }

  // --- API: named parameters (ours first, CGAL's chained after), a Polyhedron_3 output,
  // points held in pairs through a property map
  {
    const Mesh truth = make_torus(Point_3(0, 0, 0), 1, 0.4);
    std::vector<std::pair<Point_3, int> > items;
    for(const auto& s : sample_points(truth, 10000, 5, 0)) items.push_back(std::make_pair(s.first, 0));
    CGAL::Polyhedron_3<K> poly;
    const bool ok = CGAL::ism_surface_reconstruction(
        items, poly,
        CGAL::parameters::maximum_depth(20, CGAL::parameters::smoothing_iterations(2u))
            .point_map(CGAL::First_of_pair_property_map<std::pair<Point_3, int> >())
            .random_seed(7));
    CHECK(ok && CGAL::is_closed(poly) && poly.size_of_facets() > 100, "named parameters + Polyhedron_3 output");
    Mesh out;
    CHECK(CGAL::ism_surface_reconstruction(items, out,
                                           CGAL::parameters::paper_settings(true).point_map(
                                               CGAL::First_of_pair_property_map<std::pair<Point_3, int> >())),
          "the paper's settings run");
    CHECK(CGAL::is_closed(out) && topology(out).genus == 1, "the paper's settings give a closed torus");

    // cancellation through the callback
    std::vector<Point_3> pts;
    for(const auto& it : items) pts.push_back(it.first);
    Mesh cancelled;
    const bool finished = CGAL::ism_surface_reconstruction(
        pts, cancelled, CGAL::parameters::callback(std::function<bool(double)>([](double) { return false; })));
    CHECK(!finished && num_faces(cancelled) == 0, "the callback cancels and leaves the mesh empty");

    // determinism: same input and seed, same output
    Mesh a, b;
    CGAL::ism_surface_reconstruction(pts, a, CGAL::parameters::random_seed(11));
    CGAL::ism_surface_reconstruction(pts, b, CGAL::parameters::random_seed(11));
    std::ostringstream sa, sb;
    CGAL::IO::write_OFF(sa, a);
    CGAL::IO::write_OFF(sb, b);
    CHECK(sa.str() == sb.str(), "deterministic for a given seed");

    // implicit function concept: inside point negative, far point positive, sphere holds the points
    CGAL::ISM_reconstruction_function<K> f(pts);
    f.compute_implicit_function();
    CHECK(f(f.get_inner_point()) < 0, "get_inner_point() is inside");
    CHECK(f(Point_3(10, 10, 10)) > 0, "far away is outside");
    bool held = true;
    for(const Point_3& p : pts)
      held = held && CGAL::squared_distance(p, f.bounding_sphere().center()) <= f.bounding_sphere().squared_radius();
    CHECK(held, "bounding_sphere() holds the points");

    // copies share the computed function; a new computation of the original leaves them
    // unchanged (CGAL's Implicit_surface_3 holds a copy)
    std::vector<Point_3> probes;
    for(int i = 0; i < 200; ++i) probes.push_back(pts[std::size_t(i) * (pts.size() / 200)] + K::Vector_3(0.01 * (i % 7), 0, -0.01 * (i % 5)));
    std::vector<double> before;
    for(const Point_3& p : probes) before.push_back(CGAL::to_double(f(p)));
    CGAL::ISM_reconstruction_function<K> g(f), h(pts);
    h = f;
    bool same = g.statistics().number_of_leaves == f.statistics().number_of_leaves;
    for(std::size_t i = 0; i < probes.size(); ++i) same = same && g(probes[i]) == before[i] && h(probes[i]) == before[i];
    CHECK(same, "a copy evaluates as the original");
    f.compute_implicit_function(CGAL::parameters::maximum_depth(12));
    bool changed = f.statistics().number_of_leaves != g.statistics().number_of_leaves, kept = true;
    for(std::size_t i = 0; i < probes.size(); ++i) kept = kept && g(probes[i]) == before[i] && h(probes[i]) == before[i];
    CHECK(changed, "a new computation with another depth changes the original");
    CHECK(kept, "copies keep their function when the original is computed again");
    // a second computation gives what a fresh object gives (it once reused the vertex
    // positions of the first triangulation)
    CGAL::ISM_reconstruction_function<K> fresh(pts);
    fresh.compute_implicit_function(CGAL::parameters::maximum_depth(12));
    bool as_fresh = fresh.statistics().number_of_leaves == f.statistics().number_of_leaves;
    for(const Point_3& p : probes) as_fresh = as_fresh && fresh(p) == f(p);
    CHECK(as_fresh, "computing again gives the function of a fresh object");
    // the points times 1024 (exact in binary) give the function times 1024 (the paper's
    // squared distance: 1024^2) with each distance estimate. The steps after the signs
    // compared squared values with distances: the bunny times 1000 gave 41,067 output
    // vertices instead of 22,463 with the paper's estimate.
    namespace ISM = CGAL::ISM_reconstruction_3;
    for(ISM::Distance_estimate e : {ISM::NEAREST_POINT_SQUARED_DISTANCE, ISM::NEAREST_POINT_DISTANCE, ISM::LOCAL_PLANE_DISTANCE})
    {
      const double s = 1024, unit = e == ISM::NEAREST_POINT_SQUARED_DISTANCE ? s * s : s;
      std::vector<Point_3> scaled;
      for(const Point_3& p : pts) scaled.push_back(Point_3(s * p.x(), s * p.y(), s * p.z()));
      CGAL::ISM_reconstruction_function<K> unit_function(pts), scaled_function(scaled);
      unit_function.compute_implicit_function(CGAL::parameters::distance_estimate(e));
      scaled_function.compute_implicit_function(CGAL::parameters::distance_estimate(e));
      double worst = 0;  // relative deviation of F
      for(const Point_3& p : probes)
      {
        const double fa = CGAL::to_double(unit_function(p));
        const double fb = CGAL::to_double(scaled_function(Point_3(s * p.x(), s * p.y(), s * p.z())));
        worst = (std::max)(worst, std::abs(fb - unit * fa) / (unit * std::abs(fa)));
      }
      std::ostringstream what;  // std::to_string printed the deviations found, 1e-10, as 0.000000
      what << "distance estimate " << int(e) << ": the points times 1024 give F times "
           << (e == ISM::NEAREST_POINT_SQUARED_DISTANCE ? "1024^2" : "1024") << " (leaves "
           << unit_function.statistics().number_of_leaves << " and " << scaled_function.statistics().number_of_leaves
           << ", F off by " << worst
           << " relative)";
      CHECK(unit_function.statistics().number_of_leaves == scaled_function.statistics().number_of_leaves && worst <= 1e-9,
            what.str());
    }
    // a cancelled computation leaves no half-made function behind (+1 everywhere)
    const bool completed =
        f.compute_implicit_function(CGAL::parameters::callback(std::function<bool(double)>([](double) { return false; })));
    CHECK(!completed && f(fresh.get_inner_point()) == 1 && f(probes[0]) == 1, "cancelled: +1 everywhere");
    // ... and nothing that reads its values: extract_surface() read past them (a segfault, or
    // the old surface's leaves with garbage), get_inner_point() gave the old point
    auto throws_logic_error = [](auto run) {
      try { run(); } catch(const std::logic_error&) { return true; }
      return false;
    };
    CHECK(throws_logic_error([&] { Mesh m; ISM::extract_surface(f, m, 0, 0.5, -0.53); }),
          "cancelled: extract_surface() throws std::logic_error");
    CHECK(throws_logic_error([&] { f.get_inner_point(); }), "cancelled: get_inner_point() throws std::logic_error");
    // a run that throws after its values are filled (12 points on a sphere: no vertex
    // inside) is no function either: is_computed() was true, F read 0.80 and
    // extract_surface() gave an empty mesh (an independent black-box run, session 41)
    {
      std::vector<Point_3> twelve;
      for(int i = 0; i < 12; ++i)
      {
        const double z = -1 + (2 * i + 1) / 12., r = std::sqrt(1 - z * z), a = 2.4 * i;
        twelve.push_back(Point_3(r * std::cos(a), r * std::sin(a), z));
      }
      CGAL::ISM_reconstruction_function<K> thrown(twelve);
      bool threw = false;
      try { thrown.compute_implicit_function(); } catch(const std::runtime_error&) { threw = true; }
      CHECK(threw && !thrown.is_computed() && thrown(Point_3(0, 0, 0)) == 1 &&
                throws_logic_error([&] { Mesh m; ISM::extract_surface(thrown, m, 0, 0.5, -0.53); }),
            "thrown: not computed, +1 everywhere, extract_surface() throws std::logic_error");
    }
    // n random points on the unit sphere, z scaled by `flatness` (an ellipsoid)
    const auto random_sphere_points = [](std::mt19937& random, std::normal_distribution<double>& normal, int n,
                                         double flatness) {
      std::vector<Point_3> points;
      for(int i = 0; i < n; ++i)
      {
        const double x = normal(random), y = normal(random), z = normal(random);
        const double r = std::sqrt(x * x + y * y + z * z);
        points.push_back(Point_3(x / r, y / r, flatness * z / r));
      }
      return points;
    };
    // few points: random spheres of 250 points came out in 2 to 10 parts on 10 of 10
    // samplings (the Ising signs saw no inside, or one vertex, with leaves of 6 points); the
    // coarser refinements (leaves of 12, then 24 points) must give one closed sphere whose
    // inside the signs saw, and must have run
    {
      std::mt19937 random(42);
      std::normal_distribution<double> normal;
      std::size_t coarser = 0;
      for(int sampling = 0; sampling < 6; ++sampling)
      {
        const std::vector<Point_3> few = random_sphere_points(random, normal, 250, 1.);
        CGAL::ISM_reconstruction_function<K> g(few);
        g.compute_implicit_function();
        Mesh m;
        ISM::extract_surface(g, m, 0, 0.5, -0.53);
        const Topology t = topology(m);
        coarser += g.statistics().number_of_coarser_refinements;
        CHECK(t.closed && t.manifold && t.components == 1 && t.genus == 0 && g.statistics().number_of_ising_inside_vertices > 0,
              "250 random points on a sphere, sampling " + std::to_string(sampling) +
                  ": one closed sphere, an inside found by the Ising signs (components " + std::to_string(t.components) +
                  ", points per leaf " + std::to_string(g.settings().min_points_per_cell) + ")");
      }
      CHECK(coarser > 0, "250 random points on a sphere: the coarser refinements ran");
    }
    // the samplings of 500 and 400 random points (CGAL::Random, rejection in the cube) on
    // which the tangent planes made an inside shell of 3 to 6 pieces that the joining made
    // one: the surface came out hollow, the centre outside, because the coarser refinement's
    // test counted the pieces after the joining (500: seeds 15-30), or because a coarser
    // result that needed coarser leaves itself was judged worse (400: seed 17)
    const std::vector<std::pair<std::size_t, unsigned int> > hollow_samplings = {
        {500, 15}, {500, 21}, {500, 26}, {500, 27}, {500, 30}, {400, 17}};
    for(const auto& sampling : hollow_samplings)
    {
      const unsigned int seed = sampling.second;
      CGAL::Random random(seed);
      std::vector<Point_3> points;
      while(points.size() < sampling.first)
      {
        const double x = random.get_double(-1, 1), y = random.get_double(-1, 1), z = random.get_double(-1, 1);
        const double r2 = x * x + y * y + z * z;
        if(r2 > 1e-6 && r2 <= 1) points.push_back(Point_3(x, y, z) + (1 / std::sqrt(r2) - 1) * K::Vector_3(x, y, z));
      }
      CGAL::ISM_reconstruction_function<K> g(points);
      g.compute_implicit_function();
      Mesh m;
      ISM::extract_surface(g, m, 0, 0.5, -0.53);
      const Topology t = topology(m);
      CHECK(g(Point_3(0, 0, 0)) < 0 && t.closed && t.components == 1,
            std::to_string(sampling.first) + " random points on a sphere, seed " + std::to_string(seed) + ": the centre inside (F " +
                std::to_string(g(Point_3(0, 0, 0))) + "), one piece (" + std::to_string(t.components) + ")");
    }
    // points off the surface: on a pancake whose two sides are closer than about two point
    // spacings no cell fits between them, and the surface misses many of its points (the
    // tool warns); on a sphere of as many points it reaches them all
    {
      std::mt19937 random(7);
      std::normal_distribution<double> normal;
      double off_fraction[2] = {0, 0};
      for(int flat = 0; flat < 2; ++flat)
      {
        const std::vector<Point_3> points = random_sphere_points(random, normal, 10000, flat ? 0.02 : 1.);
        CGAL::ISM_reconstruction_function<K> g(points);
        g.compute_implicit_function();
        off_fraction[flat] = double(g.statistics().number_of_points_off_surface) / double(points.size());
        CHECK(g.statistics().number_of_merged_points == 0, "random points without copies: none merged");
      }
      std::cout << "points off the surface: sphere " << off_fraction[0] << ", pancake " << off_fraction[1] << "\n";
      CHECK(off_fraction[0] < 0.01 && off_fraction[1] > 0.1,
            "points off the surface: under 1 % on a sphere of 10,000 random points, over 10 % on an ellipsoid of axes "
            "1, 1, 0.02 (" + std::to_string(off_fraction[0]) + ", " + std::to_string(off_fraction[1]) + ")");
    }
    // clusters of copies (several scans along the same beams): 3,000 random directions on a
    // sphere, each 8 times with radial noise 1e-4, came out in hundreds of pieces before
    // merge_point_clusters; merged, one sphere, as the points taken once
    {
      std::mt19937 random(11);
      std::normal_distribution<double> normal;
      const std::vector<Point_3> directions = random_sphere_points(random, normal, 3000, 1.);
      std::vector<Point_3> copies;
      for(const Point_3& d : directions)
        for(int copy = 0; copy < 8; ++copy)
          copies.push_back(CGAL::ORIGIN + (1 + 1e-4 * normal(random)) * (d - CGAL::ORIGIN));
      CGAL::ISM_reconstruction_function<K> g(copies);
      g.compute_implicit_function();
      Mesh m;
      ISM::extract_surface(g, m, 0, 0.5, -0.53);
      const Topology t = topology(m);
      double worst = 0;
      for(auto v : vertices(m)) worst = (std::max)(worst, std::abs(std::sqrt((m.point(v) - CGAL::ORIGIN).squared_length()) - 1));
      const std::size_t merged = g.statistics().number_of_merged_points;
      CHECK(t.closed && t.manifold && t.components == 1 && t.genus == 0 && worst < 0.05 && merged >= 20000 && merged <= 21000,
            "3,000 points 8 times each with radial noise 1e-4: one sphere (components " + std::to_string(t.components) +
                ", genus " + std::to_string(t.genus) + ", farthest vertex " + std::to_string(worst) + " off the sphere, " +
                std::to_string(merged) + " points merged, 21,000 copies)");
    }
    // extract_surface()'s arguments are checked as the named parameters they mirror; the
    // defaults' Taubin filter, 1.00085 at its peak, inflated a sphere to 126 times its radius
    // in 10,000 iterations
    auto refused = [&](unsigned iterations, double lambda, double mu, unsigned neighbors) {
      try { Mesh m; ISM::extract_surface(fresh, m, iterations, lambda, mu, neighbors); }
      catch(const std::invalid_argument&) { return true; }
      return false;
    };
    CHECK(refused(0, 0.5, -0.53, 5) && refused(0, 0.5, -0.53, 65) && refused(3, 2, -3, 12) &&
              refused(1000, 0.5, -0.53, 12) && !refused(100, 0.5, -0.53, 12) && !refused(3, 0.5, -0.53, 0),
          "extract_surface(): crossing neighbours outside 0 or [6, 64], a diverging or inflating Taubin filter refused");
  }

  // --- other kernels: the method computes in double whatever the kernel, so points of
  // Simple_cartesian<double> and of the exact-constructions kernel (whose points PMP users
  // hold) give the surface that Epick gives (Epeck's exact constructions of the output
  // points round differently: up to 2e-15 measured)
  {
    const auto samples = sample_points(make_torus(Point_3(0, 0, 0), 1, 0.4), 8000, 9, 0);
    struct Surface { int genus = -1; std::vector<double> xyz; std::string faces; };
    auto reconstruct_with = [&](auto kernel_point) {
      typedef decltype(kernel_point) P;
      std::vector<P> points;
      for(const auto& s : samples) points.push_back(P(s.first.x(), s.first.y(), s.first.z()));
      CGAL::Surface_mesh<P> out;
      CGAL::ism_surface_reconstruction(points, out);
      Surface r;
      for(auto v : out.vertices())
        for(int d = 0; d < 3; ++d) r.xyz.push_back(CGAL::to_double(out.point(v)[d]));
      std::ostringstream faces;
      for(auto f : out.faces())
      {
        for(auto v : CGAL::vertices_around_face(out.halfedge(f), out)) faces << std::size_t(v) << " ";
        faces << "\n";
      }
      r.faces = faces.str();
      if constexpr(std::is_same<P, Point_3>::value) r.genus = topology(out).genus;
      return r;
    };
    auto same = [](const Surface& a, const Surface& b) {
      bool ok = a.faces == b.faces && a.xyz.size() == b.xyz.size();
      for(std::size_t i = 0; ok && i < a.xyz.size(); ++i) ok = std::abs(a.xyz[i] - b.xyz[i]) <= 1e-12;
      return ok;
    };
    const Surface epick = reconstruct_with(Point_3());
    CHECK(epick.genus == 1 && !epick.faces.empty(), "kernels: Epick gives the torus");
    CHECK(same(reconstruct_with(CGAL::Simple_cartesian<double>::Point_3()), epick),
          "kernels: Simple_cartesian<double> gives Epick's surface");
    CHECK(same(reconstruct_with(CGAL::Exact_predicates_exact_constructions_kernel::Point_3()), epick),
          "kernels: Epeck gives Epick's surface");
    // F at a vertex is its value with each kernel, and F is right along the box's main
    // diagonal, on the faces shared by the roots: with Simple_cartesian<double> those points
    // tested outside every root and took the outside value (1,739 of 196,150 wrong on a sphere)
    auto evaluation_of = [&](auto kernel_point) {
      typedef decltype(kernel_point) P;
      typedef typename CGAL::Kernel_traits<P>::Kernel Kernel;
      std::vector<P> points;
      for(const auto& s : sample_points(make_sphere(Point_3(0, 0, 0), 1), 5000, 5, 0))
        points.push_back(P(s.first.x(), s.first.y(), s.first.z()));
      CGAL::ISM_reconstruction_function<Kernel> function(points);
      function.compute_implicit_function();
      const auto& tr = function.triangulation();
      long off = 0, wrong = 0;
      for(int v = 0; v < int(tr.number_of_vertices()); ++v)
        off += std::abs(CGAL::to_double(function(tr.point(v))) - function.values()[std::size_t(v)]) >
               1e-9 * (1 + std::abs(function.values()[std::size_t(v)]));
      const P o = tr.point(0), e = tr.point(7);
      for(int i = 0; i < 20000; ++i)
      {
        const double t = (i + 0.5) / 20000;
        const P q(CGAL::to_double(o.x()) + t * CGAL::to_double(e.x() - o.x()),
                  CGAL::to_double(o.y()) + t * CGAL::to_double(e.y() - o.y()),
                  CGAL::to_double(o.z()) + t * CGAL::to_double(e.z() - o.z()));
        const double r = std::sqrt(CGAL::to_double(CGAL::squared_distance(q, P(0, 0, 0))));
        if(std::abs(r - 1) > 0.02) wrong += (CGAL::to_double(function(q)) < 0) != (r < 1);
      }
      const double nan = std::numeric_limits<double>::quiet_NaN();
      return std::to_string(off) + " vertices off, " + std::to_string(wrong) + " wrong on the diagonal, F(NaN) " +
             (CGAL::to_double(function(P(nan, 0, 0))) > 0 ? "> 0" : "not > 0");
    };
    for(const std::string& r : { evaluation_of(Point_3()), evaluation_of(CGAL::Simple_cartesian<double>::Point_3()) })
      CHECK(r == "0 vertices off, 0 wrong on the diagonal, F(NaN) > 0", "kernels: evaluation: " + r);
    // a Point_set_3, CGAL's point container, given alone (its point map is found) and with
    // its point map named
    CGAL::Point_set_3<Point_3> point_set;
    for(const auto& s : samples) point_set.insert(s.first);
    Mesh alone, named;
    CGAL::ism_surface_reconstruction(point_set, alone);
    CGAL::ism_surface_reconstruction(point_set, named, CGAL::parameters::point_map(point_set.point_map()));
    CHECK(num_vertices(alone) == epick.xyz.size() / 3 && num_vertices(named) == epick.xyz.size() / 3,
          "Point_set_3 input gives the surface of a vector of points");
    // a range without size() (a ConstRange need not have one)
    std::forward_list<Point_3> listed;
    for(auto it = samples.rbegin(); it != samples.rend(); ++it) listed.push_front(it->first);
    Mesh from_list;
    CGAL::ism_surface_reconstruction(listed, from_list);
    CHECK(num_vertices(from_list) == epick.xyz.size() / 3, "a std::forward_list gives the surface of a vector of points");
  }

  // --- bad input: clear exceptions (the robustness test covers many more cases)
  auto message = [](auto run) -> std::string {
    try { run(); } catch(const std::exception& e) { return e.what(); }
    return "";
  };
  std::vector<Point_3> none, line, plane;
  for(int i = 0; i < 100; ++i) { line.push_back(Point_3(i, 2 * i, 3 * i)); plane.push_back(Point_3(i % 10, i / 10, 0)); }
  Mesh out;
  const std::string e1 = message([&] { CGAL::ism_surface_reconstruction(none, out); });
  const std::string e2 = message([&] { CGAL::ism_surface_reconstruction(line, out); });
  const std::string e3 = message([&] { CGAL::ism_surface_reconstruction(plane, out); });
  std::vector<Point_3> sphere_pts;
  for(const auto& s : sample_points(make_sphere(Point_3(0, 0, 0), 1), 2000, 1, 0)) sphere_pts.push_back(s.first);
  const std::string e4 = message([&] { CGAL::ism_surface_reconstruction(sphere_pts, out, CGAL::parameters::maximum_depth(60)); });
  const std::string e5 = message([&] { CGAL::ism_surface_reconstruction(sphere_pts, out, CGAL::parameters::coplanarity_threshold(-1.)); });
  std::cout << "messages:\n  " << e1 << "\n  " << e2 << "\n  " << e3 << "\n  " << e4 << "\n  " << e5 << "\n";
  CHECK(e1.find("empty") != std::string::npos, "empty input refused");
  CHECK(e2.find("line") != std::string::npos, "collinear input refused");
  CHECK(e3.find("plane") != std::string::npos, "coplanar input refused");
  CHECK(e4.find("maximum_depth") != std::string::npos, "depth 60 refused");
  CHECK(e5.find("coplanarity_threshold") != std::string::npos, "negative threshold refused");
  CHECK(num_faces(out) == 0, "a refused input leaves the mesh untouched");

  if(failures == 0) std::cout << "all reconstruction tests passed\n";
  return failures == 0 ? 0 : 1;
}
