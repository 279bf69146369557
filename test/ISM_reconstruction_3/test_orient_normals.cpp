// Tests of CGAL::ism_orient_normals(): on points sampled from closed meshes with known
// outward normals, unoriented normals from jet_estimate_normals (k = 18) are oriented by
// ism_orient_normals() and by mst_orient_normals() (k = 18); the share of points whose
// normal agrees with the truth is compared case by case (smooth shapes, thin parts and
// handles, noise, outliers, several components).
// Usage: test_orient_normals [directory holding knot1.off eight.off bunny00.off]
#include "ism_evaluation.h"

#include <CGAL/ism_orient_normals.h>

#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/property_map.h>
#include <CGAL/Real_timer.h>
#include <CGAL/tags.h>

#include <cstdio>
#include <iostream>
#include <string>
#include <tuple>
#include <vector>

using namespace ISM_eval;

namespace {

int failures = 0;

#define CHECK_MSG(cond, msg)                                                                   \
  do {                                                                                         \
    if(!(cond)) {                                                                              \
      std::cerr << "FAILED: " #cond " [" << msg << "] (" << __FILE__ << ":" << __LINE__ << ")" \
                << std::endl;                                                                  \
      ++failures;                                                                              \
    }                                                                                          \
  } while(0)

// point, normal to orient, index of the sample (its true normal; outliers have none)
typedef std::tuple<Point_3, Vector_3, std::size_t> Item;
typedef CGAL::Nth_of_tuple_property_map<0, Item> Point_map;
typedef CGAL::Nth_of_tuple_property_map<1, Item> Normal_map;

struct Case
{
  std::string name;
  std::vector<std::pair<Point_3, Vector_3> > samples;  // inliers with their true normals
  std::vector<Point_3> outliers;
  bool hard = false;                                    // ism must beat mst here
};

struct Score
{
  double agreement = 0;                 // share of inliers whose oriented normal agrees with the truth
  std::size_t unoriented = 0;           // inliers left unoriented (counted as disagreeing)
  std::size_t unoriented_outliers = 0;
  double seconds = 0;
};

Score score(const std::vector<Item>& items, std::vector<Item>::const_iterator first_unoriented,
            const std::vector<std::pair<Point_3, Vector_3> >& truth)
{
  Score s;
  std::size_t good = 0;
  for(auto it = items.begin(); it != items.end(); ++it)
  {
    const std::size_t i = std::get<2>(*it);
    if(i >= truth.size())  // an outlier
    {
      if(it >= first_unoriented) ++s.unoriented_outliers;
      continue;
    }
    if(it >= first_unoriented) { ++s.unoriented; continue; }
    if(CGAL::scalar_product(std::get<1>(*it), truth[i].second) > 0) ++good;
  }
  s.agreement = double(good) / double(truth.size());
  return s;
}

// a closed box [x0,x1]x[y0,y1]x[z0,z1], outward
Mesh make_box(double x0, double y0, double z0, double x1, double y1, double z1)
{
  const std::vector<Point_3> p = { Point_3(x0, y0, z0), Point_3(x1, y0, z0), Point_3(x1, y1, z0), Point_3(x0, y1, z0),
                                   Point_3(x0, y0, z1), Point_3(x1, y0, z1), Point_3(x1, y1, z1), Point_3(x0, y1, z1) };
  const std::vector<std::array<std::size_t, 3> > t = { {0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                                                       {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7} };
  Mesh m;
  ISM_eval::internal::build_mesh(p, t, m);
  ISM_eval::internal::orient_outward_single(m);
  return m;
}

std::vector<Point_3> uniform_outliers(const Mesh& m, std::size_t n, unsigned seed)
{
  const CGAL::Bbox_3 b = bbox(m);
  Rng rng(seed);
  std::vector<Point_3> out;
  for(std::size_t i = 0; i < n; ++i)
    out.push_back(rng.uniform_point(b));
  return out;
}

void run(const Case& c)
{
  std::vector<Item> items;
  for(std::size_t i = 0; i < c.samples.size(); ++i) items.emplace_back(c.samples[i].first, CGAL::NULL_VECTOR, i);
  for(std::size_t i = 0; i < c.outliers.size(); ++i)
    items.emplace_back(c.outliers[i], CGAL::NULL_VECTOR, c.samples.size() + i);
  const auto np = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());

  CGAL::Real_timer timer;
  timer.start();
  CGAL::jet_estimate_normals<CGAL::Parallel_if_available_tag>(items, 18, np);
  const double jet_time = timer.time();

  std::vector<Item> by_mst = items;
  timer.reset();
  const auto mst_end = CGAL::mst_orient_normals(by_mst, 18, np);
  Score mst = score(by_mst, mst_end, c.samples);
  mst.seconds = timer.time();

  std::vector<Item> by_ism = items;
  timer.reset();
  const auto ism_end = CGAL::ism_orient_normals(by_ism, np);
  Score ism = score(by_ism, ism_end, c.samples);
  ism.seconds = timer.time();

  std::printf("| %-32s | %6zu | %8.3f %% | %5zu | %6.2f s | %8.3f %% | %5zu | %6.2f s | %5.2f s |", c.name.c_str(),
              items.size(), 100 * ism.agreement, ism.unoriented, ism.seconds, 100 * mst.agreement, mst.unoriented,
              mst.seconds, jet_time);
  if(!c.outliers.empty())
    std::printf(" outliers left unoriented: ism %zu, mst %zu of %zu", ism.unoriented_outliers, mst.unoriented_outliers,
                c.outliers.size());
  std::printf("\n");
  std::fflush(stdout);
  CHECK_MSG(ism.agreement >= mst.agreement - 0.001, c.name);
  if(c.hard) CHECK_MSG(ism.agreement > mst.agreement, c.name);
}

// The interface: Point_set_3, estimate_normals (both spellings), reconstruction parameters
// passed through, the callback, an empty range.
void api_checks()
{
  const Mesh torus = make_torus(Point_3(0, 0, 0), 1., 0.4);
  const std::vector<std::pair<Point_3, Vector_3> > samples = sample_points(torus, 5000, 3);

  // Point_set_3 with its own maps; unoriented normals estimated inside (PCA, k = 18)
  CGAL::Point_set_3<Point_3> point_set;
  point_set.add_normal_map();
  auto truth = point_set.add_property_map<Vector_3>("truth", CGAL::NULL_VECTOR).first;
  for(const auto& s : samples) truth[*point_set.insert(s.first, CGAL::NULL_VECTOR)] = s.second;
  auto first = CGAL::ism_orient_normals(point_set, CGAL::parameters::estimate_normals(true, point_set.parameters()));
  std::size_t good = 0, oriented = 0;
  for(auto it = point_set.begin(); it != first; ++it, ++oriented)
    if(CGAL::scalar_product(point_set.normal(*it), truth[*it]) > 0.5) ++good;
  std::printf("Point_set_3 + estimate_normals(true): %zu of %zu oriented, %zu agree with the truth\n", oriented,
              point_set.size(), good);
  CHECK_MSG(double(good) >= 0.999 * double(point_set.size()), "Point_set_3 + estimate_normals");

  // pairs, estimate_normals chained the other way, reconstruction parameters passed through
  typedef std::pair<Point_3, Vector_3> Pwn;
  std::vector<Pwn> pwn;
  for(const auto& s : samples) pwn.push_back(Pwn(s.first, Vector_3(1, 0, 0)));
  const auto pwn_np = CGAL::parameters::estimate_normals(true)
                          .point_map(CGAL::First_of_pair_property_map<Pwn>())
                          .normal_map(CGAL::Second_of_pair_property_map<Pwn>());
  auto pwn_first = CGAL::ism_orient_normals(pwn, CGAL::parameters::maximum_depth(22, pwn_np.random_seed(5)));
  CHECK_MSG(pwn_first == pwn.end(), "pairs: every normal oriented");
  // outward on the torus scaled by `scale` around z: away from the core circle of radius `scale`
  auto outward_share = [](const std::vector<Pwn>& with_normals, double scale) {
    std::size_t outward = 0;
    for(const Pwn& q : with_normals)
    {
      const double x = q.first.x() / scale, y = q.first.y() / scale, rho = std::sqrt(x * x + y * y);
      const Vector_3 away(x - x / rho, y - y / rho, q.first.z() / scale);
      if(CGAL::scalar_product(q.second, away) > 0) ++outward;
    }
    return double(outward) / double(with_normals.size());
  };
  CHECK_MSG(outward_share(pwn, 1.) >= 0.999, "pairs: outward normals");

  // points far from unit size, beyond the spans ISM_reconstruction_function takes (1e+-32):
  // oriented as ism_surface_reconstruction() reconstructs them, scaled by a power of two
  for(const double scale : { 0x1p120, 0x1p-120 })
  {
    std::vector<Pwn> far;
    for(const auto& s : samples)
      far.push_back(Pwn(Point_3(scale * s.first.x(), scale * s.first.y(), scale * s.first.z()), Vector_3(1, 0, 0)));
    try
    {
      CHECK_MSG(CGAL::ism_orient_normals(far, pwn_np) == far.end(), "torus at scale 2^+-120: every normal oriented");
      const double share = outward_share(far, scale);
      std::printf("torus at scale %g: %.2f %% of the normals outward\n", scale, 100 * share);
      CHECK_MSG(share >= 0.999, "torus at scale 2^+-120: outward normals");
    }
    catch(const std::exception& e)
    {
      CHECK_MSG(false, std::string("torus at scale 2^+-120: ") + e.what());
    }
  }

  // a cancelled run orients nothing and leaves the normals alone
  std::vector<Pwn> cancelled = pwn;
  auto none = CGAL::ism_orient_normals(
      cancelled, CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Pwn>())
                     .normal_map(CGAL::Second_of_pair_property_map<Pwn>())
                     .callback([](double) { return false; }));
  CHECK_MSG(none == cancelled.begin(), "cancelled: nothing oriented");
  CHECK_MSG(cancelled == pwn, "cancelled: normals untouched");
  // also those it was asked to estimate (they were estimated before the function was computed)
  auto none_estimated = CGAL::ism_orient_normals(cancelled, pwn_np.callback([](double) { return false; }));
  CHECK_MSG(none_estimated == cancelled.begin() && cancelled == pwn, "cancelled with estimate_normals(true): normals untouched");

  std::vector<Pwn> empty;
  CHECK_MSG(CGAL::ism_orient_normals(empty, pwn_np) == empty.end(), "empty range");
}

} // namespace

int main(int argc, char** argv)
{
  const std::string dir = argc > 1 ? argv[1] : "data/meshes";
  CGAL::Real_timer total;
  total.start();
  const std::size_t n = 12000;
  std::vector<Case> cases;
  auto add = [&](const std::string& name, const Mesh& m, std::size_t count, double noise, double outliers, bool hard) {
    Case c;
    c.name = name;
    c.hard = hard;
    c.samples = sample_points(m, count, 7, noise * diagonal(bbox(m)));
    if(outliers > 0) c.outliers = uniform_outliers(m, std::size_t(outliers * double(count)), 11);
    cases.push_back(c);
  };
  auto read = [&](const std::string& file, Mesh& m) {
    const bool ok = read_mesh(dir + "/" + file, m) && is_outward_oriented(m);
    CHECK_MSG(ok, dir + "/" + file);
    return ok;
  };

  // smooth shapes
  add("sphere", make_sphere(Point_3(0, 0, 0), 1.), n, 0, 0, false);
  add("torus R=1 r=0.4", make_torus(Point_3(0, 0, 0), 1., 0.4), n, 0, 0, false);
  // thin parts and handles
  Mesh knot1, eight, bunny;
  if(read("knot1.off", knot1)) add("knot1.off", knot1, n, 0, 0, false);
  if(read("eight.off", eight)) add("eight.off", eight, n, 0, 0, false);
  add("trefoil tube", make_trefoil_tube(), n, 0, 0, false);
  add("thin torus R=1 r=0.05", make_torus(Point_3(0, 0, 0), 1., 0.05, 96, 16), n, 0, 0, false);
  {
    // 1 x 1 plates 0.15 thick, 0.05 apart: the k nearest neighbours span the gap
    Mesh plates = make_box(-0.5, -0.5, -0.175, 0.5, 0.5, -0.025);
    ISM_eval::internal::append(plates, make_box(-0.5, -0.5, 0.025, 0.5, 0.5, 0.175));
    add("two plates t=0.15 gap=0.05", plates, 20000, 0, 0, true);
  }
  if(read("bunny00.off", bunny))
  {
    add("bunny00.off", bunny, n, 0, 0, true);
    // noise and outliers
    add("bunny noise 0.5% diag", bunny, n, 0.005, 0, true);
    add("bunny 1% outliers", bunny, n, 0, 0.01, true);
  }
  add("torus noise 0.5% diag", make_torus(Point_3(0, 0, 0), 1., 0.4), n, 0.005, 0, false);
  add("torus 1% outliers", make_torus(Point_3(0, 0, 0), 1., 0.4), n, 0, 0.01, false);
  // several components
  add("two spheres gap=0.05", make_two_spheres(Point_3(-1.025, 0, 0), 1., Point_3(1.025, 0, 0), 1.), n, 0, 0, true);
  add("spheres r=1, 0.3 gap=0.05",
      make_two_spheres(Point_3(-1.025, 0, 0), 1., Point_3(0.325, 0, 0), 0.3), n, 0, 0, true);
  add("nested spheres 1 / 0.8", make_nested_spheres(Point_3(0, 0, 0), 1., 0.8), n, 0, 0, true);

  std::printf("| %-32s | %6s | %10s | %5s | %8s | %10s | %5s | %8s | %7s |\n", "case", "points", "ism agree",
              "unor.", "ism time", "mst agree", "unor.", "mst time", "jet");
  std::printf("|%s|\n", std::string(115, '-').c_str());
  for(const Case& c : cases) run(c);
  api_checks();
  std::printf("total %.1f s, %d failure(s)\n", total.time(), failures);
  return failures == 0 ? 0 : 1;
}
