// One reconstruction method on one case, scored against the ground-truth mesh; prints one
// JSON line. run_benchmark.py runs one process per (method, case) so that wall time and
// peak memory belong to one method, and collects the lines into benchmark/results.md.
//
//   benchmark_reconstruction --method M --mesh truth.off --points N [--noise F] [--seed S]
//                            [--case NAME] [--samples K] [--queries Q] [--close-holes]
//                            [--output out.off]
//
// method: ism | ism_paper | poisson_jet_mst | poisson_jet_ism | poisson_oracle | advancing_front
//         | scale_space | alpha_wrap
// The input is N area-weighted samples of the truth mesh (ISM_eval::sample_points, seed S),
// displaced by an isotropic gaussian of sigma = F * diagonal per axis: the same for every
// method. Only the coordinates are given to the methods, except poisson_oracle which gets
// the true face normals of the sampler. poisson_jet_mst and poisson_jet_ism differ only in
// the orientation of the jet normals: mst_orient_normals or ism_orient_normals.
// Scores: in/out agreement with the truth on Q uniform queries in the truth's bounding box
// scaled by 1.1 (overall, and "far": queries farther than 1 % of that box's diagonal from
// the truth), only when the output is closed (else null); symmetric mean / max surface
// distance (K samples on each mesh) relative to the truth's bounding-box diagonal; topology
// of the output; for closed outputs, |enclosed volume| / truth's volume. "peak_mb" is the process's peak resident memory (VmHWM) right after the
// method ran, before any scoring; "base_mb" is the resident memory before it started
// (truth mesh and input points). time_total is the method's wall time; for the methods that
// output a triangle soup (advancing_front, scale_space) it excludes this program's conversion
// of the soup to a Surface_mesh (stage "to_mesh", reported apart). Like ism_reconstruct,
// the program restarts itself with glibc's large blocks backed by transparent huge pages
// (internal/huge_pages.h): the same for every method.

#include "ism_evaluation.h"

#include <CGAL/ism_surface_reconstruction.h>
#include <CGAL/ism_orient_normals.h>
#include <CGAL/ISM_reconstruction_3/internal/huge_pages.h>

#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Scale_space_surface_reconstruction_3.h>
#include <CGAL/alpha_wrap_3.h>
#include <CGAL/poisson_surface_reconstruction.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/property_map.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <tuple>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

typedef ISM_eval::K K;
typedef ISM_eval::Point_3 Point_3;
typedef ISM_eval::Vector_3 Vector_3;
typedef ISM_eval::Mesh Mesh;
typedef std::pair<Point_3, Vector_3> Pwn;
typedef CGAL::First_of_pair_property_map<Pwn> Point_map;
typedef CGAL::Second_of_pair_property_map<Pwn> Normal_map;
namespace PMP = CGAL::Polygon_mesh_processing;

// Memory of this process from /proc/self/status (kB fields), in MB; -1 if unavailable.
double proc_status_mb(const char* field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::string key = std::string(field) + ":";
  while (std::getline(in, line))
    if (line.compare(0, key.size(), key) == 0) return std::atof(line.c_str() + key.size()) / 1024.0;
  return -1;
}

// A JSON object written in insertion order; non-finite numbers become null.
class Json {
public:
  void num(const std::string& k, double v) {
    std::ostringstream os;
    if (std::isfinite(v)) os << std::setprecision(9) << v; else os << "null";
    add(k, os.str());
  }
  void integer(const std::string& k, long long v) { add(k, std::to_string(v)); }
  void boolean(const std::string& k, bool v) { add(k, v ? "true" : "false"); }
  void null(const std::string& k) { add(k, "null"); }
  void str(const std::string& k, const std::string& v) {
    std::string e = "\"";
    for (char c : v) {
      if (c == '"' || c == '\\') { e += '\\'; e += c; }
      else if (c == '\n') e += "\\n";
      else if (static_cast<unsigned char>(c) < 0x20) e += ' ';
      else e += c;
    }
    add(k, e + "\"");
  }
  void object(const std::string& k, const Json& j) { add(k, j.text()); }
  std::string text() const {
    std::string s = "{";
    for (std::size_t i = 0; i < items_.size(); ++i) s += (i ? ", \"" : "\"") + items_[i].first + "\": " + items_[i].second;
    return s + "}";
  }

private:
  void add(const std::string& k, const std::string& v) { items_.emplace_back(k, v); }
  std::vector<std::pair<std::string, std::string>> items_;
};

// What a method produced.
struct Run {
  Mesh mesh;
  std::vector<std::pair<std::string, double>> stages;  // seconds, in order
  bool soup_was_manifold = true;  // false if the method's triangle soup had to be split to become a mesh
  double flip_rate = -1;          // normal methods: share of oriented normals opposed to the true one
  long long unoriented = -1;      // normal methods: points the orientation step could not orient (removed, as in CGAL's example)
  double glue_time = 0;            // this benchmark's soup-to-mesh conversion: in `stages`, not in time_total
  std::string note;
};

// A triangle soup on `points` as a Surface_mesh. Triangles output twice (the same three
// points, in either orientation: the scale-space alpha-shape mesher gives both sides of a
// facet) are kept once. If the soup is then not a valid 2-manifold polygon mesh,
// orient_polygon_soup duplicates what it must (non-manifold vertices and edges become
// borders) and the run is marked non-manifold. Its time is the run's glue time, recorded
// as the stage "to_mesh" and not counted in the method's time.
void soup_to_mesh(std::vector<Point_3> points, std::vector<std::array<std::size_t, 3>> faces, Run& run) {
  CGAL::Real_timer t;
  t.start();
  const std::size_t duplicates = PMP::merge_duplicate_polygons_in_polygon_soup(points, faces);
  if (duplicates > 0) run.note = std::to_string(duplicates) + " duplicate triangles merged";
  run.soup_was_manifold = PMP::is_polygon_soup_a_polygon_mesh(faces);
  if (!run.soup_was_manifold) PMP::orient_polygon_soup(points, faces);
  PMP::polygon_soup_to_polygon_mesh(points, faces, run.mesh);
  PMP::remove_isolated_vertices(run.mesh);
  run.mesh.collect_garbage();
  run.glue_time = t.time();
  run.stages.emplace_back("to_mesh", run.glue_time);
}

// The positions of the input, the only thing the methods without normals are given.
std::vector<Point_3> positions(const std::vector<Pwn>& input) {
  std::vector<Point_3> pts;
  pts.reserve(input.size());
  for (const Pwn& p : input) pts.push_back(p.first);
  return pts;
}

Run run_ism(const std::vector<Pwn>& input, bool paper) {
  Run run;
  CGAL::Real_timer t;
  t.start();
  std::vector<Point_3> pts = positions(input);
  CGAL::ISM_reconstruction_function<K> f(pts);
  const CGAL::ISM_reconstruction_3::Settings s =
      paper ? CGAL::ISM_reconstruction_3::Settings::paper() : CGAL::ISM_reconstruction_3::Settings();
  const double t_input = t.time();
  f.compute_implicit_function_with_settings(s);
  const auto ex = CGAL::ISM_reconstruction_3::extract_surface(f, run.mesh, s.smoothing_iterations, s.smoothing_lambda,
                                                               s.smoothing_mu, s.crossing_neighbors);
  const auto& st = f.statistics();
  run.stages = {{"input", t_input},
                {"refinement", st.refinement_time},
                {"topology", st.topology_time},
                {"distance", st.distance_time},
                {"marching", ex.marching_time},
                {"smoothing", ex.smoothing_time}};
  run.note = "leaves=" + std::to_string(st.number_of_leaves) + " depth=" + std::to_string(st.deepest_level);
  return run;
}

// Poisson as CGAL's poisson_surface_reconstruction_delaunay() (same defaults: sm_angle 20,
// sm_radius 30, sm_distance 0.375, Manifold_with_boundary_tag), written out to time the
// solve and the meshing separately.
bool poisson(const std::vector<Pwn>& pwn, double spacing, Run& run) {
  typedef CGAL::Poisson_reconstruction_function<K> Function;
  typedef CGAL::Surface_mesher::Surface_mesh_default_triangulation_3_generator<K>::Type STr;
  typedef CGAL::Surface_mesh_complex_2_in_triangulation_3<STr> C2t3;
  typedef CGAL::Implicit_surface_3<K, Function> Surface_3;
  const double sm_angle = 20.0, sm_radius = 30.0, sm_distance = 0.375;
  CGAL::Real_timer t;
  t.start();
  Function function(pwn.begin(), pwn.end(), Point_map(), Normal_map());
  if (!function.compute_implicit_function()) return false;
  run.stages.emplace_back("poisson_solve", t.time());
  t.reset();
  const Point_3 inner_point = function.get_inner_point();
  const K::Sphere_3 bsphere = function.bounding_sphere();
  const double radius = std::sqrt(CGAL::to_double(bsphere.squared_radius()));
  const double sm_sphere_radius = 5.0 * radius;
  const double sm_dichotomy_error = sm_distance * spacing / 1000.0;
  Surface_3 surface(function, K::Sphere_3(inner_point, sm_sphere_radius * sm_sphere_radius),
                    sm_dichotomy_error / sm_sphere_radius);
  CGAL::Surface_mesh_default_criteria_3<STr> criteria(sm_angle, sm_radius * spacing, sm_distance * spacing);
  STr tr;
  C2t3 c2t3(tr);
  CGAL::make_surface_mesh(c2t3, surface, criteria, CGAL::Manifold_with_boundary_tag());
  if (tr.number_of_vertices() == 0) return false;
  CGAL::facets_in_complex_2_to_triangle_mesh(c2t3, run.mesh);
  run.stages.emplace_back("poisson_mesh", t.time());
  return true;
}

// (point, estimated normal, index of the input point): the orientation steps reorder the
// range, the index finds the true normal for the flip rate.
typedef std::tuple<Point_3, Vector_3, std::size_t> Tagged;
typedef CGAL::Nth_of_tuple_property_map<0, Tagged> TP_map;
typedef CGAL::Nth_of_tuple_property_map<1, Tagged> TN_map;

// Poisson after jet normals (k = 18) oriented by `orient` (a callable on the range of
// Tagged that orients the normals in place and returns the first unoriented point, as
// mst_orient_normals and ism_orient_normals do); `orient_stage` names its stage.
template <class Orient>
Run run_poisson_jet(const std::vector<Pwn>& input, const char* orient_stage, Orient orient) {
  Run run;
  std::vector<Tagged> tagged;
  tagged.reserve(input.size());
  for (std::size_t i = 0; i < input.size(); ++i) tagged.emplace_back(input[i].first, CGAL::NULL_VECTOR, i);
  CGAL::Real_timer t;
  t.start();
  CGAL::jet_estimate_normals<CGAL::Parallel_if_available_tag>(
      tagged, 18, CGAL::parameters::point_map(TP_map()).normal_map(TN_map()));
  run.stages.emplace_back("jet_normals", t.time());
  t.reset();
  const auto unoriented_begin = orient(tagged);
  run.stages.emplace_back(orient_stage, t.time());
  t.reset();
  // As CGAL's examples: the points the orientation step could not orient are removed.
  const std::size_t n_oriented = std::size_t(unoriented_begin - tagged.begin());
  run.unoriented = (long long)(tagged.size() - n_oriented);
  if (n_oriented == 0) throw std::runtime_error(std::string(orient_stage) + ": no normal could be oriented");
  std::size_t flipped = 0;
  std::vector<Pwn> pwn;
  pwn.reserve(n_oriented);
  for (std::size_t i = 0; i < n_oriented; ++i) {
    const Vector_3& n = std::get<1>(tagged[i]);
    if (CGAL::to_double(CGAL::scalar_product(n, input[std::get<2>(tagged[i])].second)) < 0) ++flipped;
    pwn.emplace_back(std::get<0>(tagged[i]), n);
  }
  run.flip_rate = double(flipped) / double(n_oriented);
  std::vector<Tagged>().swap(tagged);
  const double spacing = CGAL::compute_average_spacing<CGAL::Parallel_if_available_tag>(
      pwn, 6, CGAL::parameters::point_map(Point_map()));
  run.stages.emplace_back("spacing", t.time());
  if (!poisson(pwn, spacing, run)) throw std::runtime_error("Poisson reconstruction failed");
  return run;
}

// Jet normals oriented by a minimum spanning tree (k = 18), as CGAL's tutorial does.
Run run_poisson_jet_mst(const std::vector<Pwn>& input) {
  return run_poisson_jet(input, "mst_orient", [](std::vector<Tagged>& tagged) {
    return CGAL::mst_orient_normals(tagged, 18, CGAL::parameters::point_map(TP_map()).normal_map(TN_map()));
  });
}

// Jet normals oriented by this package's in/out function (ism_orient_normals, defaults).
Run run_poisson_jet_ism(const std::vector<Pwn>& input) {
  return run_poisson_jet(input, "ism_orient", [](std::vector<Tagged>& tagged) {
    return CGAL::ism_orient_normals(tagged, CGAL::parameters::point_map(TP_map()).normal_map(TN_map()));
  });
}

Run run_poisson_oracle(const std::vector<Pwn>& input) {
  Run run;
  CGAL::Real_timer t;
  t.start();
  const double spacing = CGAL::compute_average_spacing<CGAL::Parallel_if_available_tag>(
      input, 6, CGAL::parameters::point_map(Point_map()));
  run.stages.emplace_back("spacing", t.time());
  run.flip_rate = 0;
  if (!poisson(input, spacing, run)) throw std::runtime_error("Poisson reconstruction failed");
  return run;
}

Run run_advancing_front(const std::vector<Pwn>& input) {
  Run run;
  CGAL::Real_timer t;
  t.start();
  std::vector<Point_3> pts = positions(input);
  std::vector<std::array<std::size_t, 3>> faces;
  CGAL::advancing_front_surface_reconstruction(pts.begin(), pts.end(), std::back_inserter(faces));
  run.stages.emplace_back("reconstruction", t.time());
  soup_to_mesh(std::move(pts), std::move(faces), run);
  return run;
}

// As CGAL's scale_space.cpp example: default Weighted_PCA_smoother, increase_scale(4),
// default Alpha_shape_mesher; the mesh is on the points at the final scale.
Run run_scale_space(const std::vector<Pwn>& input) {
  typedef CGAL::Scale_space_surface_reconstruction_3<K> Reconstruction;
  Run run;
  CGAL::Real_timer t;
  t.start();
  std::vector<Point_3> pts = positions(input);
  Reconstruction r(pts.begin(), pts.end());
  r.increase_scale(4);
  run.stages.emplace_back("smoothing", t.time());
  t.reset();
  r.reconstruct_surface();
  run.stages.emplace_back("meshing", t.time());
  t.reset();
  std::vector<Point_3> out_pts(r.points_begin(), r.points_end());
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(r.number_of_facets());
  for (auto it = r.facets_begin(); it != r.facets_end(); ++it) faces.push_back({{(*it)[0], (*it)[1], (*it)[2]}});
  soup_to_mesh(std::move(out_pts), std::move(faces), run);
  return run;
}

Run run_alpha_wrap(const std::vector<Pwn>& input) {
  Run run;
  CGAL::Real_timer t;
  t.start();
  std::vector<Point_3> pts = positions(input);
  const CGAL::Bbox_3 b = CGAL::bbox_3(pts.begin(), pts.end());
  const double diag = ISM_eval::diagonal(b);
  CGAL::alpha_wrap_3(pts, diag / 100.0, diag / 3000.0, run.mesh);
  run.stages.emplace_back("wrap", t.time());
  return run;
}

int usage() {
  std::cerr << "usage: benchmark_reconstruction --method M --mesh truth.off --points N [--noise F] [--nonuniform R]\n"
               "         [--seed S] [--case NAME] [--samples K] [--queries Q] [--close-holes] [--output out.off]\n"
               "  M: ism ism_paper poisson_jet_mst poisson_jet_ism poisson_oracle advancing_front scale_space\n"
               "     alpha_wrap\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  CGAL::ISM_reconstruction_3::internal::restart_with_huge_pages(argv);
  std::string method, mesh_file, case_name, output_file;
  std::size_t n_points = 0, samples = 100000, queries = 100000;
  double noise = 0;
  std::size_t nonuniform = 1;
  unsigned seed = 1;
  bool close = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) { std::cerr << "missing value after " << a << "\n"; std::exit(usage()); }
      return argv[++i];
    };
    if (a == "--method") method = next();
    else if (a == "--mesh") mesh_file = next();
    else if (a == "--points") n_points = std::stoul(next());
    else if (a == "--noise") noise = std::stod(next());
    else if (a == "--nonuniform") nonuniform = std::stoul(next());
    else if (a == "--seed") seed = unsigned(std::stoul(next()));
    else if (a == "--case") case_name = next();
    else if (a == "--samples") samples = std::stoul(next());
    else if (a == "--queries") queries = std::stoul(next());
    else if (a == "--close-holes") close = true;
    else if (a == "--output") output_file = next();
    else { std::cerr << "unknown argument " << a << "\n"; return usage(); }
  }
  if (method.empty() || mesh_file.empty() || n_points == 0 || nonuniform == 0) return usage();
  if (case_name.empty()) case_name = mesh_file;

  Json out;
  out.str("method", method);
  out.str("case", case_name);
  out.integer("n_points", (long long)n_points);
  out.num("noise", noise);
  out.integer("nonuniform", (long long)nonuniform);
  out.integer("seed", seed);
  try {
    Mesh truth;
    if (!ISM_eval::read_mesh(mesh_file, truth)) throw std::runtime_error("cannot read " + mesh_file);
    if (close && !CGAL::is_closed(truth) && !ISM_eval::close_holes(truth))
      throw std::runtime_error("could not close the holes of " + mesh_file);
    const ISM_eval::Topology tt = ISM_eval::topology(truth);
    const CGAL::Bbox_3 tb = ISM_eval::bbox(truth);
    const double diag = ISM_eval::diagonal(tb);
    std::vector<Pwn> input = ISM_eval::sample_points(truth, n_points, seed, noise * diag);
    if (nonuniform > 1) input = ISM_eval::thin_one_half(input, nonuniform);
    out.integer("n_input", (long long)input.size());
    out.integer("truth_components", (long long)tt.components);
    out.integer("truth_genus", tt.genus);
    out.boolean("truth_closed", tt.closed);
    const double base_mb = proc_status_mb("VmRSS");

    CGAL::Real_timer total;
    total.start();
    Run run;
    if (method == "ism") run = run_ism(input, false);
    else if (method == "ism_paper") run = run_ism(input, true);
    else if (method == "poisson_jet_mst") run = run_poisson_jet_mst(input);
    else if (method == "poisson_jet_ism") run = run_poisson_jet_ism(input);
    else if (method == "poisson_oracle") run = run_poisson_oracle(input);
    else if (method == "advancing_front") run = run_advancing_front(input);
    else if (method == "scale_space") run = run_scale_space(input);
    else if (method == "alpha_wrap") run = run_alpha_wrap(input);
    else { std::cerr << "unknown method " << method << "\n"; return usage(); }
    total.stop();
    const double peak_mb = proc_status_mb("VmHWM");

    out.num("time_total", total.time() - run.glue_time);
    Json st;
    for (const auto& s : run.stages) st.num(s.first, s.second);
    out.object("stages", st);
    out.num("peak_mb", peak_mb);
    out.num("base_mb", base_mb);
    out.integer("output_vertices", (long long)run.mesh.number_of_vertices());
    out.integer("output_faces", (long long)run.mesh.number_of_faces());

    if (!output_file.empty() && !CGAL::IO::write_polygon_mesh(output_file, run.mesh, CGAL::parameters::stream_precision(17)))
      throw std::runtime_error("cannot write " + output_file);

    // --- scores
    CGAL::Real_timer et;
    et.start();
    const ISM_eval::Topology ot = ISM_eval::topology(run.mesh);
    const bool closed = run.mesh.number_of_faces() > 0 && ot.closed;
    if (closed) {
      const ISM_eval::Inside_oracle inside(run.mesh);
      const ISM_eval::Inout_score s =
          ISM_eval::inout_accuracy(truth, ISM_eval::scaled_bbox(tb, 1.1), inside, queries, 0.01, seed + 100);
      out.num("inout", s.overall);
      out.num("inout_far", s.far);
      // enclosed volume over the truth's (orientation-free): ~1 for a right in/out partition
      out.num("volume_ratio", std::abs(ISM_eval::signed_volume(run.mesh) / ISM_eval::signed_volume(truth)));
    } else {
      out.null("inout");
      out.null("inout_far");
      out.null("volume_ratio");
    }
    const ISM_eval::Distance_score d = ISM_eval::symmetric_distance(run.mesh, truth, samples, seed + 200);
    out.num("dist_mean", d.mean / diag);
    out.num("dist_max", d.max / diag);
    out.integer("components", (long long)ot.components);
    out.integer("genus", ot.genus);
    out.boolean("closed", closed);
    out.boolean("manifold", ot.manifold && run.soup_was_manifold);
    if (run.flip_rate >= 0) out.num("flip_rate", run.flip_rate); else out.null("flip_rate");
    if (run.unoriented >= 0) out.integer("unoriented", run.unoriented);
    if (!run.note.empty()) out.str("note", run.note);
    out.num("eval_time", et.time());
    out.str("status", "ok");
    std::cout << out.text() << std::endl;
    return 0;
  } catch (const std::exception& e) {
    out.str("status", "error");
    out.str("error", e.what());
    std::cout << out.text() << std::endl;
    return 1;
  }
}
