// Tests of CGAL::Bisection_triangulation_3: conformity (checked by our own face matching,
// by TetGen and by CGAL's Triangulation_3 built from the tet soup), shape regularity,
// point location, the three kernels, and bad input.
//
// usage: test_bisection_triangulation <mesh.off>   (a closed mesh, e.g. bunny00.off)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Bisection_triangulation_3.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Random.h>

#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_3/tet_soup_to_c3t3.h>

#define TETLIBRARY
#include <tetgen.h>

#include <cmath>
#include <stdexcept>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel EPICK;
typedef CGAL::Exact_predicates_exact_constructions_kernel EPECK;
typedef CGAL::Simple_cartesian<double> SC;

static int failures = 0;
#define CHECK(cond, what)                                                          \
  do { if(!(cond)) { ++failures; std::cerr << "FAILED: " << what << "  (" #cond ")\n"; } } while(0)

// ---------------------------------------------------------------------------
// Our own, independent conformity check: match faces by sorted vertex triples.
struct Conformity
{
  bool faces_matched = true;       // every face shared by 2 leaves or lying on the box boundary
  bool neighbors_agree = true;     // the triangulation's neighbor() equals the face matching
  bool positive = true;            // every leaf positively oriented
  double volume = 0;               // sum of leaf volumes
  std::size_t interior_faces = 0, boundary_faces = 0;
};

template <class K>
std::array<double, 3> to_d(const typename K::Point_3& p)
{ return {{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }}; }

static double signed_volume(const std::array<double, 3>& a, const std::array<double, 3>& b,
                            const std::array<double, 3>& c, const std::array<double, 3>& d)
{
  double u[3], v[3], w[3];
  for(int i = 0; i < 3; ++i) { u[i] = b[i] - a[i]; v[i] = c[i] - a[i]; w[i] = d[i] - a[i]; }
  return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
          u[2] * (v[0] * w[1] - v[1] * w[0])) / 6.;
}

// on_box_boundary(p): true when p lies on the boundary of the (axis-aligned) box
template <class K, class OnBoundary>
Conformity check_conformity(const CGAL::Bisection_triangulation_3<K>& bt, OnBoundary on_box_boundary)
{
  typedef CGAL::Bisection_triangulation_3<K> BT;
  Conformity r;
  std::map<std::array<int, 3>, std::vector<std::pair<int, int> > > faces;  // face -> (leaf, local index)
  for(typename BT::Cell_index c : bt.leaves())
  {
    const auto v = bt.positive_vertices(c);
    const double vol = signed_volume(to_d<K>(bt.point(v[0])), to_d<K>(bt.point(v[1])),
                                     to_d<K>(bt.point(v[2])), to_d<K>(bt.point(v[3])));
    if(!(vol > 0)) r.positive = false;
    r.volume += vol;
    for(int i = 0; i < 4; ++i)
    {
      std::array<int, 3> f;
      int n = 0;
      for(int l = 0; l < 4; ++l)
        if(l != i) f[n++] = bt.vertex(c, l);
      std::sort(f.begin(), f.end());
      faces[f].push_back(std::make_pair(c, i));
    }
  }
  for(const auto& f : faces)
  {
    if(f.second.size() == 2)
    {
      ++r.interior_faces;
      const auto& a = f.second[0];
      const auto& b = f.second[1];
      if(bt.neighbor(a.first, a.second) != b.first || bt.neighbor(b.first, b.second) != a.first)
        r.neighbors_agree = false;
    }
    else if(f.second.size() == 1)
    {
      ++r.boundary_faces;
      const auto& a = f.second[0];
      if(bt.neighbor(a.first, a.second) != -1) r.neighbors_agree = false;
      bool all_on_one_side = false;
      // a boundary face must lie on one face of the box
      for(int axis = 0; axis < 3 && !all_on_one_side; ++axis)
        for(int side = 0; side < 2 && !all_on_one_side; ++side)
        {
          bool ok = true;
          for(int v : f.first) ok = ok && on_box_boundary(to_d<K>(bt.point(v)), axis, side);
          all_on_one_side = ok;
        }
      if(!all_on_one_side) r.faces_matched = false;
    }
    else
      r.faces_matched = false;
  }
  return r;
}

static auto unit_box_boundary(double lo, double hi)
{
  return [lo, hi](const std::array<double, 3>& p, int axis, int side) {
    return std::abs(p[axis] - (side ? hi : lo)) < 1e-12 * (hi - lo);
  };
}

// ---------------------------------------------------------------------------
// Cross-check 1: TetGen reconstructs the given tets ("r") and reports neighbours ("n").
// Returns the number of leaves whose TetGen neighbours differ from ours, or -1 if a face
// TetGen calls boundary is not on the box (a hanging vertex, which TetGen does not flag).
template <class K, class OnBoundary>
long tetgen_mismatches(const CGAL::Bisection_triangulation_3<K>& bt, OnBoundary on_box_boundary)
{
  typedef CGAL::Bisection_triangulation_3<K> BT;
  const std::vector<typename BT::Cell_index> leaves = bt.leaves();
  std::vector<int> leaf_of_cell(bt.number_of_cells(), -1);
  for(std::size_t i = 0; i < leaves.size(); ++i) leaf_of_cell[leaves[i]] = int(i);
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = int(bt.number_of_vertices());
  in.pointlist = new REAL[3 * in.numberofpoints];
  for(int v = 0; v < in.numberofpoints; ++v)
  {
    const auto p = to_d<K>(bt.point(v));
    for(int d = 0; d < 3; ++d) in.pointlist[3 * v + d] = p[d];
  }
  in.numberoftetrahedra = int(leaves.size());
  in.numberofcorners = 4;
  in.tetrahedronlist = new int[4 * leaves.size()];
  for(std::size_t i = 0; i < leaves.size(); ++i)
  {
    const auto v = bt.positive_vertices(leaves[i]);
    for(int l = 0; l < 4; ++l) in.tetrahedronlist[4 * i + l] = v[l];
  }
  char switches[] = "rnQ";
  try { tetrahedralize(switches, &in, &out); }
  catch(...) { return -2; }
  if(out.numberoftetrahedra != int(leaves.size()) || out.neighborlist == nullptr) return -2;
  long mismatches = 0;
  for(std::size_t i = 0; i < leaves.size(); ++i)
    for(int k = 0; k < 4; ++k)
    {
      const int opposite = out.tetrahedronlist[4 * i + k];
      const int theirs = out.neighborlist[4 * i + k];
      int local = -1;
      for(int l = 0; l < 4; ++l)
        if(bt.vertex(leaves[i], l) == opposite) local = l;
      if(local < 0) { ++mismatches; continue; }
      const int ours_cell = bt.neighbor(leaves[i], local);
      const int ours = ours_cell < 0 ? -1 : leaf_of_cell[ours_cell];
      if(theirs == -1)
      {
        bool on_box = false;
        for(int axis = 0; axis < 3 && !on_box; ++axis)
          for(int side = 0; side < 2 && !on_box; ++side)
          {
            bool ok = true;
            for(int l = 0; l < 4; ++l)
              if(l != k) ok = ok && on_box_boundary(to_d<K>(bt.point(out.tetrahedronlist[4 * i + l])), axis, side);
            on_box = ok;
          }
        if(!on_box) return -1;
      }
      if(theirs != ours) ++mismatches;
    }
  return mismatches;
}

// ---------------------------------------------------------------------------
// Cross-check 2: CGAL's triangulation data structure built from the same soup.
// Returns -1 if CGAL refuses the soup (is_valid() false), else the number of mismatches.
template <class K>
long cgal_mismatches(const CGAL::Bisection_triangulation_3<K>& bt)
{
  typedef CGAL::Bisection_triangulation_3<K> BT;
  typedef CGAL::Labeled_mesh_domain_3<EPICK> Domain;
  typedef typename CGAL::Mesh_triangulation_3<Domain>::type Tr;
  typedef typename Tr::Point WPoint;
  typedef typename Tr::Vertex_handle Vertex_handle;
  const std::vector<typename BT::Cell_index> leaves = bt.leaves();
  std::vector<WPoint> points;
  for(std::size_t v = 0; v < bt.number_of_vertices(); ++v)
  {
    const auto p = to_d<K>(bt.point(int(v)));
    points.push_back(WPoint(EPICK::Point_3(p[0], p[1], p[2])));
  }
  std::vector<std::array<int, 5> > tets;
  for(auto c : leaves)
  {
    const auto v = bt.positive_vertices(c);
    tets.push_back({{v[0], v[1], v[2], v[3], 1}});
  }
  Tr tr;
  std::map<std::array<int, 3>, typename Tr::Cell::Surface_patch_index> patches;
  std::vector<Vertex_handle> handles(points.size());
  const bool ok = CGAL::build_triangulation<Tr, false>(tr, points, tets, patches, handles, false);
  if(!ok || !tr.Tr::Tr_Base::is_valid()) return -1;
  std::map<Vertex_handle, int> index;
  // handles[0] is the infinite vertex; point i has handle i+1
  for(std::size_t i = 1; i < handles.size(); ++i) index[handles[i]] = int(i) - 1;
  std::map<std::array<int, 4>, int> leaf_of;
  for(auto c : leaves)
  {
    auto v = bt.vertices(c);
    std::sort(v.begin(), v.end());
    leaf_of[{{v[0], v[1], v[2], v[3]}}] = c;
  }
  auto key = [&](typename Tr::Cell_handle ch) {
    std::array<int, 4> k;
    for(int l = 0; l < 4; ++l) k[l] = index.at(ch->vertex(l));
    std::sort(k.begin(), k.end());
    return k;
  };
  long mismatches = 0;
  std::size_t finite = 0;
  for(auto ch : tr.finite_cell_handles())
  {
    ++finite;
    const auto it = leaf_of.find(key(ch));
    if(it == leaf_of.end()) { ++mismatches; continue; }
    const int c = it->second;
    for(int l = 0; l < 4; ++l)
    {
      const int opposite = index.at(ch->vertex(l));
      int local = -1;
      for(int m = 0; m < 4; ++m)
        if(bt.vertex(c, m) == opposite) local = m;
      const auto nh = ch->neighbor(l);
      const int theirs = tr.is_infinite(nh) ? -1 : leaf_of.at(key(nh));
      if(local < 0 || bt.neighbor(c, local) != theirs) ++mismatches;
    }
  }
  if(finite != leaves.size()) ++mismatches;
  return mismatches;
}

// ---------------------------------------------------------------------------
// Adaptive refinement around points: refine every leaf holding a point up to max_level.
template <class K>
void refine_around(CGAL::Bisection_triangulation_3<K>& bt, const std::vector<typename K::Point_3>& pts,
                   int max_level)
{
  typedef CGAL::Bisection_triangulation_3<K> BT;
  std::vector<std::vector<int> > in_cell(bt.number_of_cells());
  for(int i = 0; i < int(pts.size()); ++i) in_cell[bt.locate(pts[i])].push_back(i);
  bt.refine([&](typename BT::Cell_index c) { return !in_cell[c].empty(); }, max_level,
            [&](typename BT::Cell_index p, typename BT::Cell_index c0, typename BT::Cell_index) {
              in_cell.resize(bt.number_of_cells());
              for(int i : in_cell[p]) in_cell[c0 + bt.child_side(p, pts[i])].push_back(i);
              std::vector<int>().swap(in_cell[p]);
            });
}

// ---------------------------------------------------------------------------
template <class K>
void test_kernel(const std::string& name)
{
  typedef CGAL::Bisection_triangulation_3<K> BT;
  typedef typename K::Point_3 P;
  typename K::Iso_cuboid_3 box(P(-1, -1, -1), P(1, 1, 1));
  auto bnd = unit_box_boundary(-1, 1);
  for(int level : {0, 1, 2, 3, 5, 8})
  {
    BT bt(box);
    bt.refine_uniformly(level);
    const Conformity r = check_conformity(bt, bnd);
    const std::string what = name + " uniform level " + std::to_string(level);
    CHECK(bt.number_of_leaves() == (std::size_t(6) << level), what + ": leaf count");
    CHECK(r.faces_matched, what + ": faces matched");
    CHECK(r.neighbors_agree, what + ": neighbors agree with face matching");
    CHECK(r.positive, what + ": all leaves positive");
    CHECK(std::abs(r.volume - 8.) < 1e-9, what + ": volumes sum to the box volume");
    for(auto c : bt.leaves()) CHECK(bt.level(c) == level, what + ": every leaf at that level");
  }
  // adaptive around a sphere
  CGAL::Random rnd(7);
  std::vector<P> pts;
  for(int i = 0; i < 300; ++i)
  {
    double x = rnd.get_double(-1, 1), y = rnd.get_double(-1, 1), z = rnd.get_double(-1, 1);
    const double n = std::sqrt(x * x + y * y + z * z);
    pts.push_back(P(0.6 * x / n, 0.6 * y / n, 0.6 * z / n));
  }
  BT bt(box);
  refine_around(bt, pts, 15);
  const Conformity r = check_conformity(bt, bnd);
  CHECK(r.faces_matched && r.neighbors_agree && r.positive && std::abs(r.volume - 8.) < 1e-9,
        name + " adaptive sphere: conforming, positive, volume");
  std::cout << name << ": adaptive sphere level 15, " << bt.number_of_leaves() << " leaves, conforming="
            << (r.faces_matched && r.neighbors_agree) << "\n";
}

// similarity class of a tet: its 6 squared edge lengths sorted and divided by the largest
static std::array<long, 5> similarity_class(const std::array<std::array<double, 3>, 4>& p)
{
  std::array<double, 6> l;
  int n = 0;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j)
    {
      double s = 0;
      for(int d = 0; d < 3; ++d) s += (p[i][d] - p[j][d]) * (p[i][d] - p[j][d]);
      l[n++] = s;
    }
  std::sort(l.begin(), l.end());
  std::array<long, 5> k;
  for(int i = 0; i < 5; ++i) k[i] = std::lround(l[i] / l[5] * 1e6);
  return k;
}

static double min_dihedral_angle(const std::array<std::array<double, 3>, 4>& p)
{
  auto sub = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::array<double, 3>{{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
  };
  auto cross = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::array<double, 3>{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
  };
  auto dot = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  };
  double best = 10;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j)
    {
      int o[2], n = 0;
      for(int l = 0; l < 4; ++l)
        if(l != i && l != j) o[n++] = l;
      // dihedral angle at edge (o0,o1) between faces (o0,o1,i) and (o0,o1,j)
      const auto e = sub(p[o[1]], p[o[0]]);
      const auto n1 = cross(e, sub(p[i], p[o[0]]));
      const auto n2 = cross(e, sub(p[j], p[o[0]]));
      const double c = dot(n1, n2) / std::sqrt(dot(n1, n1) * dot(n2, n2));
      best = (std::min)(best, std::acos((std::max)(-1., (std::min)(1., c))));
    }
  return best;
}

// A box turned by angles whose sines are not dyadic (the reconstruction's boxes follow the
// points' principal axes): the midpoints of its edges are rounded, so vertices on its
// boundary lie off it by an ulp; with an inexact kernel the predicates round too, and a
// point on a face shared by two roots (the main diagonal) tested outside both (an API
// black-box run: 117 vertices of Simple_cartesian<double>'s triangulation not located).
// Every vertex and every point of the main diagonal is located all the same.
template <class K>
void test_location_in_turned_box(const std::string& name)
{
  typedef typename K::Point_3 P;
  typedef typename K::Vector_3 V;
  const double c = std::cos(0.3), s = std::sin(0.3), c2 = std::cos(1.1), s2 = std::sin(1.1);
  const V a(c * c2, s * c2, s2), b(-s, c, 0), d(-c * s2, -s * s2, c2);
  CGAL::Bisection_triangulation_3<K> bt(P(-0.7, 0.3, -1.9), 2.3 * a, 1.7 * b, 1.1 * d);
  bt.refine_uniformly(6);
  long unlocated = 0;
  for(int v = 0; v < int(bt.number_of_vertices()); ++v)
  {
    try { bt.locate(bt.point(v)); }
    catch(const std::out_of_range&) { ++unlocated; }
  }
  const P o = bt.point(0), e = bt.point(7);
  for(int i = 0; i <= 1000; ++i)
  {
    const double t = i / 1000.;
    const P q(CGAL::to_double(o.x()) + t * CGAL::to_double(e.x() - o.x()),
              CGAL::to_double(o.y()) + t * CGAL::to_double(e.y() - o.y()),
              CGAL::to_double(o.z()) + t * CGAL::to_double(e.z() - o.z()));
    if(bt.locate_root(q) < 0) ++unlocated;
  }
  CHECK(unlocated == 0, name + ": vertices and main-diagonal points of a turned box located (" +
                            std::to_string(unlocated) + " not)");
  CHECK(bt.locate_root(bt.point(0) + 1e-6 * (bt.point(0) - bt.point(7))) < 0,
        name + ": a point just beyond a corner is outside");
}

int main(int argc, char** argv)
{
  typedef CGAL::Bisection_triangulation_3<EPICK> BT;
  typedef EPICK::Point_3 P;

  test_kernel<EPICK>("EPICK");
  test_kernel<SC>("Simple_cartesian<double>");
  test_kernel<EPECK>("EPECK");
  test_location_in_turned_box<EPICK>("EPICK");
  test_location_in_turned_box<SC>("Simple_cartesian<double>");

  const EPICK::Iso_cuboid_3 cube(P(0, 0, 0), P(1, 1, 1));
  auto bnd = unit_box_boundary(0, 1);

  // --- a uniform level whose cells the machine cannot hold (level 27: 1.6 billion cells,
  // about 80 GiB) is refused before the allocation; it was left to std::bad_alloc or the
  // OOM killer. Skipped where the process may really use that much.
  {
    BT bt(cube);
    const double budget = double(CGAL::ISM_reconstruction_3::internal::available_memory().bytes);
    if(budget < 80. * double(1ull << 30))
    {
      std::string message;
      try { bt.refine_uniformly(27); }
      catch(const std::length_error& e) { message = e.what(); }
      CHECK(message.find("level 27 needs about") != std::string::npos && bt.number_of_leaves() == 6,
            "refine_uniformly(27): refused before the allocation (" + message + ")");
    }
  }

  // --- parallelepiped built from an origin and three axes
  {
    BT bt(P(1, 2, 3), EPICK::Vector_3(2, 0.5, 0), EPICK::Vector_3(-0.3, 1, 0.2), EPICK::Vector_3(0.1, 0.1, 1.5));
    bt.refine_uniformly(6);
    double vol = 0;
    bool positive = true;
    for(auto c : bt.leaves())
    {
      const auto v = bt.positive_vertices(c);
      const double s = signed_volume(to_d<EPICK>(bt.point(v[0])), to_d<EPICK>(bt.point(v[1])),
                                     to_d<EPICK>(bt.point(v[2])), to_d<EPICK>(bt.point(v[3])));
      positive = positive && s > 0;
      vol += s;
    }
    const double expected = std::abs(CGAL::determinant(EPICK::Vector_3(2, 0.5, 0), EPICK::Vector_3(-0.3, 1, 0.2),
                                                       EPICK::Vector_3(0.1, 0.1, 1.5)));
    CHECK(positive, "parallelepiped: all leaves positive");
    CHECK(std::abs(vol - expected) < 1e-9 * expected, "parallelepiped: volumes sum to the box volume");
  }

  // --- adaptive refinement around a real mesh's points up to level >= 20, cross-checked
  std::vector<P> mesh_points;
  if(argc > 1)
  {
    if(!CGAL::IO::read_points(argv[1], std::back_inserter(mesh_points)) || mesh_points.empty())
      CHECK(false, std::string("could not read points of ") + argv[1]);
  }
  else
    CHECK(false, "usage: test_bisection_triangulation <mesh.off>");
  if(!mesh_points.empty())
  {
    // normalise into the unit cube with a margin
    CGAL::Bbox_3 bb = CGAL::bbox_3(mesh_points.begin(), mesh_points.end());
    const double s = (std::max)({bb.xmax() - bb.xmin(), bb.ymax() - bb.ymin(), bb.zmax() - bb.zmin()});
    for(P& p : mesh_points)
      p = P(0.1 + 0.8 * (p.x() - bb.xmin()) / s, 0.1 + 0.8 * (p.y() - bb.ymin()) / s, 0.1 + 0.8 * (p.z() - bb.zmin()) / s);
    BT bt(cube);
    const int max_level = 21;
    refine_around(bt, mesh_points, max_level);
    int deepest = 0;
    for(auto c : bt.leaves()) deepest = (std::max)(deepest, bt.level(c));
    const Conformity r = check_conformity(bt, bnd);
    std::cout << "real mesh: " << mesh_points.size() << " points, " << bt.number_of_leaves() << " leaves, "
              << bt.number_of_vertices() << " vertices, deepest level " << deepest << "\n";
    CHECK(deepest >= 20, "real mesh: refinement reaches level 20");
    CHECK(r.faces_matched, "real mesh: faces matched");
    CHECK(r.neighbors_agree, "real mesh: neighbors agree");
    CHECK(r.positive, "real mesh: positive leaves");
    CHECK(std::abs(r.volume - 1.) < 1e-9, "real mesh: volume");
    const long tg = tetgen_mismatches(bt, bnd);
    std::cout << "real mesh: TetGen neighbour mismatches " << tg << "\n";
    CHECK(tg == 0, "real mesh: TetGen neighbours equal ours");
    const long cg = cgal_mismatches(bt);
    std::cout << "real mesh: CGAL triangulation neighbour mismatches " << cg << "\n";
    CHECK(cg == 0, "real mesh: CGAL Triangulation_3 neighbours equal ours");

    // shape regularity over >= 20 levels
    std::set<std::array<long, 5> > classes;
    double min_angle = 10, min_angle_root = 10;
    for(auto c : bt.leaves())
    {
      std::array<std::array<double, 3>, 4> p;
      for(int l = 0; l < 4; ++l) p[l] = to_d<EPICK>(bt.point(bt.vertex(c, l)));
      classes.insert(similarity_class(p));
      min_angle = (std::min)(min_angle, min_dihedral_angle(p));
    }
    for(int c = 0; c < 6; ++c)
    {
      std::array<std::array<double, 3>, 4> p;
      for(int l = 0; l < 4; ++l) p[l] = to_d<EPICK>(bt.point(bt.vertex(c, l)));
      min_angle_root = (std::min)(min_angle_root, min_dihedral_angle(p));
    }
    std::cout << "shape regularity: " << classes.size() << " similarity classes of leaves; smallest dihedral angle "
              << min_angle * 180 / M_PI << " deg (level 0: " << min_angle_root * 180 / M_PI << " deg)\n";
    CHECK(classes.size() <= 12, "shape regularity: bounded number of similarity classes");
    CHECK(min_angle >= min_angle_root - 1e-9, "shape regularity: no dihedral angle below level 0's");

    // point location against brute force, including points on faces and edges
    CGAL::Random rnd(3);
    std::vector<P> queries;
    for(int i = 0; i < 2000; ++i) queries.push_back(P(rnd.get_double(0, 1), rnd.get_double(0, 1), rnd.get_double(0, 1)));
    const auto leaves = bt.leaves();
    for(int i = 0; i < 500; ++i)
    {
      const auto c = leaves[rnd.get_int(0, int(leaves.size()))];
      const P& a = bt.point(bt.vertex(c, 0));
      const P& b = bt.point(bt.vertex(c, 1));
      const P& d = bt.point(bt.vertex(c, 2));
      queries.push_back(CGAL::midpoint(a, b));                                  // on an edge
      queries.push_back(CGAL::centroid(a, b, d));                               // on a face
      queries.push_back(a);                                                     // a vertex
    }
    long wrong = 0;
    for(const P& q : queries)
    {
      const auto c = bt.locate(q);
      if(!bt.is_leaf(c) || !bt.has_on(c, q)) ++wrong;
    }
    // brute force on a subset: locate returns one of the leaves whose closure holds q
    for(int i = 0; i < 200; ++i)
    {
      const P& q = queries[std::size_t(rnd.get_int(0, int(queries.size())))];
      std::vector<int> holders;
      for(auto c : leaves)
        if(bt.has_on(c, q)) holders.push_back(c);
      if(std::find(holders.begin(), holders.end(), bt.locate(q)) == holders.end()) ++wrong;
    }
    CHECK(wrong == 0, "point location agrees with brute force (" + std::to_string(wrong) + " wrong)");
    // the walk from a hint: from the leaf of a nearby point (a few steps) and from a random
    // leaf (long walks fall back to the descent); the leaf found holds the query either way
    long walked = 0, wrong_walk = 0;
    for(std::size_t i = 0; i < queries.size(); ++i)
    {
      const P& q = queries[i];
      const auto near_hint = bt.locate(queries[i > 0 ? i - 1 : i]);
      const auto far_hint = leaves[rnd.get_int(0, int(leaves.size()))];
      for(auto hint : { near_hint, far_hint })
      {
        const auto c = bt.locate(q, hint);
        if(!bt.is_leaf(c) || !bt.has_on(c, q)) ++wrong_walk;
        const auto w = bt.walk_to(q, hint);
        if(w >= 0 && (++walked, !bt.has_on(w, q))) ++wrong_walk;
      }
    }
    CHECK(wrong_walk == 0 && walked > 0, "point location by a walk from a hint (" + std::to_string(wrong_walk) +
                                             " wrong, " + std::to_string(walked) + " walks ended in a leaf)");
    CHECK(bt.walk_to(P(2, 0.5, 0.5), leaves[0]) < 0, "a walk towards a point outside the box ends with -1");

    // adjacency: leaves around an edge, around a vertex, edges
    {
      const auto c = leaves[leaves.size() / 2];
      std::vector<int> ring;
      bt.leaves_around_edge(c, 0, 1, std::back_inserter(ring));
      bool all_hold = true;
      for(int t : ring)
        all_hold = all_hold && std::count(bt.vertices(t).begin(), bt.vertices(t).end(), bt.vertex(c, 0)) &&
                   std::count(bt.vertices(t).begin(), bt.vertices(t).end(), bt.vertex(c, 1));
      std::size_t brute = 0;
      for(auto t : leaves)
        if(std::count(bt.vertices(t).begin(), bt.vertices(t).end(), bt.vertex(c, 0)) &&
           std::count(bt.vertices(t).begin(), bt.vertices(t).end(), bt.vertex(c, 1)))
          ++brute;
      CHECK(all_hold && ring.size() == brute, "leaves around an edge equal brute force");
      std::vector<std::size_t> off;
      std::vector<int> cells;
      bt.leaves_around_vertices(off, cells);
      std::size_t around = off[bt.vertex(c, 2) + 1] - off[bt.vertex(c, 2)], brute_v = 0;
      for(auto t : leaves)
        brute_v += std::count(bt.vertices(t).begin(), bt.vertices(t).end(), bt.vertex(c, 2));
      CHECK(around == brute_v, "leaves around a vertex equal brute force");
      // Euler: V - E + F - T = 1 for a ball
      const std::size_t E = bt.edges().size();
      const std::size_t F = r.interior_faces + r.boundary_faces;
      const long chi = long(bt.number_of_vertices()) - long(E) + long(F) - long(leaves.size());
      CHECK(chi == 1, "Euler characteristic of the leaf mesh is 1 (got " + std::to_string(chi) + ")");
    }
  }

  // --- a deliberately non-conforming mesh must be caught by all three checks
  {
    BT bt(cube);
    bt.refine_uniformly(4);
    // a leaf whose refinement edge is interior, so that it has neighbours around it
    BT::Cell_index victim = -1;
    for(auto c : bt.leaves())
    {
      std::vector<int> ring;
      bt.leaves_around_edge(c, 0, BT::refinement_index(bt.level(c)), std::back_inserter(ring));
      if(ring.size() > 2) { victim = c; break; }
    }
    bt.bisect_non_conforming_for_testing(victim);
    const Conformity r = check_conformity(bt, bnd);
    CHECK(!r.faces_matched, "non-conforming mesh caught by face matching");
    const long tg = tetgen_mismatches(bt, bnd);
    CHECK(tg != 0, "non-conforming mesh caught by TetGen (a boundary face inside the box)");
    CHECK(cgal_mismatches(bt) == -1, "non-conforming mesh refused by CGAL's build_triangulation");
  }

  // --- bad input
  auto throws = [](auto f) { try { f(); } catch(const std::exception& e) { std::cout << "  expected error: " << e.what() << "\n"; return true; } return false; };
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  CHECK(throws([&] { BT bt(EPICK::Iso_cuboid_3(P(0, 0, 0), P(1, 1, 0))); }), "flat box refused");
  CHECK(throws([&] { BT bt(EPICK::Iso_cuboid_3(P(0, 0, 0), P(1, nan, 1))); }), "NaN box refused");
  CHECK(throws([&] { BT bt(EPICK::Iso_cuboid_3(P(0, 0, 0), P(1, inf, 1))); }), "infinite box refused");
  CHECK(throws([&] { BT bt(P(0, 0, 0), EPICK::Vector_3(1, 0, 0), EPICK::Vector_3(0, 1, 0), EPICK::Vector_3(1, 1, 0)); }),
        "flat parallelepiped refused");
  CHECK(throws([&] { BT bt(cube); bt.refine_uniformly(40); }), "uniform level beyond the indices refused");
  CHECK(throws([&] { BT bt(cube); bt.refine_uniformly(-1); }), "negative level refused");
  CHECK(throws([&] { BT bt(cube); bt.locate(P(2, 0, 0)); }), "location outside the box refused");
  CHECK(throws([&] { BT bt(cube); bt.locate(P(nan, 0, 0)); }), "location of a NaN point refused");
  CHECK(throws([&] { BT bt(cube); bt.refine([](int) { return true; }, BT::maximum_level() + 1); }),
        "refinement beyond the maximum level refused");
  CHECK(throws([&] { BT bt(cube); bt.refine_uniformly(2); bt.bisect(0); }), "bisecting an inner cell refused");
  CHECK(throws([&] { BT bt(P(1e308, 0, 0), EPICK::Vector_3(1e308, 0, 0), EPICK::Vector_3(0, 1, 0), EPICK::Vector_3(0, 0, 1)); }),
        "a box whose corner overflows refused");
  {
    BT bt(cube);
    bt.refine_uniformly(3);
    CHECK(bt.walk_to(P(nan, 0, 0), bt.leaves()[0]) < 0, "a walk towards a NaN point ends with -1");
    CHECK(throws([&] { bt.locate(P(0.1, inf, 0), bt.leaves()[0]); }), "location of an infinite point from a hint refused");
  }

  // --- an on_bisect that throws leaves a conforming mesh, which refines on (it left stale
  // neighbour links, and the next bisection walked around an edge forever)
  for(int call = 1; call <= 9; ++call)
  {
    BT bt(cube);
    bt.refine_uniformly(3);
    int calls = 0;
    CHECK(throws([&] {
            bt.refine([](int) { return true; }, 5, [&](int, int, int) {
              if(++calls == call) throw std::runtime_error("from on_bisect");
            });
          }),
          "an exception of on_bisect reaches the caller");
    bt.refine_uniformly(5);
    const Conformity r = check_conformity(bt, unit_box_boundary(0, 1));
    CHECK(r.faces_matched && r.neighbors_agree && r.positive && std::abs(r.volume - 1.) < 1e-9 &&
              bt.number_of_leaves() == 6 * 32,
          "conforming after on_bisect threw at call " + std::to_string(call));
  }

  // --- cells too small for their coordinates: a unit box at 1e9 refined around a point to
  // level 96 (edges of 2^-32, the coordinates' ulp 1.2e-7) gave flat leaves that contained
  // the point, and refinement without end; refused now, the mesh still whole
  {
    const double o = 1e9;
    BT bt(EPICK::Iso_cuboid_3(P(o, o, o), P(o + 1, o + 1, o + 1)));
    const P target(o + 0.3, o + 0.6, o + 0.7);
    CHECK(throws([&] { bt.refine([&](int c) { return bt.has_on(c, target); }, BT::maximum_level()); }),
          "midpoints rounding onto their edge's ends refused");
    const Conformity r = check_conformity(bt, unit_box_boundary(o, o + 1));
    CHECK(r.faces_matched && r.neighbors_agree && r.positive, "the box at 1e9 stays conforming with positive leaves");
    CHECK(bt.number_of_leaves() < 50000, "the box at 1e9: refinement stopped (" + std::to_string(bt.number_of_leaves()) +
                                             " leaves; it made 31 million)");
  }

  // --- a point within rounding of a leaf face, in a box with decimal corners: locate() gave
  // the leaf beside its own (60 of 576 leaf-edge midpoints at level 4)
  {
    BT bt(EPICK::Iso_cuboid_3(P(0.1, 0.2, 0.3), P(0.3, 0.7, 1.1)));
    bt.refine_uniformly(4);
    int wrong = 0, tested = 0;
    for(int c : bt.leaves())
      for(int i = 0; i < 4; ++i)
        for(int j = i + 1; j < 4; ++j, ++tested)
          if(!bt.has_on(bt.locate(CGAL::midpoint(bt.point(bt.vertex(c, i)), bt.point(bt.vertex(c, j)))),
                        CGAL::midpoint(bt.point(bt.vertex(c, i)), bt.point(bt.vertex(c, j)))))
            ++wrong;
    CHECK(wrong == 0, "leaf-edge midpoints of a decimal box located in a leaf holding them (" + std::to_string(wrong) +
                          " of " + std::to_string(tested) + " not)");
  }

  if(failures == 0) std::cout << "all Bisection_triangulation_3 tests passed\n";
  return failures == 0 ? 0 : 1;
}
