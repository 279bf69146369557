// Tests the tet-mesh writers of <CGAL/ISM_reconstruction_3/IO/tet_mesh_io.h>.
//
// Usage: test_tet_mesh_io <output_dir>
// Writes a cube split into 6 tetrahedra with two vertex fields in every format, reads the
// MEDIT (.mesh/.sol) and TetGen (.node/.ele) files back and compares them bit for bit with
// the input; the .vtu files are checked by check_vtu.py against <output_dir>/cube_expected.json.

#include <CGAL/ISM_reconstruction_3/IO/tet_mesh_io.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef std::array<int, 4> Tet;
using CGAL::IO::Tet_mesh_vertex_field;

int failures = 0;

#define CHECK(cond)                                                                 \
  do {                                                                              \
    if(!(cond)) {                                                                   \
      std::cerr << "FAILED line " << __LINE__ << ": " << #cond << std::endl;        \
      ++failures;                                                                   \
    }                                                                               \
  } while(false)

struct Mesh
{
  std::vector<Point> points;
  std::vector<Tet> tets;
  std::vector<Tet_mesh_vertex_field> fields;
};

bool is_positive(const std::vector<Point>& points, const Tet& t)
{
  return CGAL::orientation(points[std::size_t(t[0])], points[std::size_t(t[1])],
                           points[std::size_t(t[2])], points[std::size_t(t[3])]) == CGAL::POSITIVE;
}

// A cube with coordinates that are not short decimals (thirds), so that any loss of
// precision in the text formats shows up as a mismatch.
Mesh make_cube()
{
  Mesh m;
  for(int i = 0; i < 8; ++i)
    m.points.emplace_back(0.1 + (i & 1) / 3.0, -2.0 + ((i >> 1) & 1) * 1.1, 1e3 + ((i >> 2) & 1) / 7.0);

  // Kuhn split around the diagonal 0-7: one tet per order in which the axes are crossed.
  const int axes[6][3] = { {0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0} };
  for(const auto& a : axes) {
    const int v1 = 1 << a[0];
    const int v2 = v1 | (1 << a[1]);
    Tet t = {{ 0, v1, v2, 7 }};
    if(!is_positive(m.points, t))
      std::swap(t[2], t[3]);
    m.tets.push_back(t);
  }

  std::vector<double> sign, distance;
  for(int i = 0; i < 8; ++i) {
    sign.push_back((i % 3 == 0) ? -1.0 : 1.0);
    distance.push_back(std::sqrt(2.0 + i) / 3.0 - 0.5);
  }
  m.fields.emplace_back("sign", sign);
  m.fields.emplace_back("distance", distance);
  return m;
}

std::string join(const std::string& dir, const std::string& name)
{
  return (std::filesystem::path(dir) / name).string();
}

bool same_point(const Point& p, double x, double y, double z)
{
  return p.x() == x && p.y() == y && p.z() == z;
}

// Minimal MEDIT reader: enough for the files this package writes.
void check_medit(const std::string& mesh_file, const std::string& sol_file, const Mesh& m)
{
  std::ifstream is(mesh_file);
  CHECK(is.good());
  std::string kw;
  int version = 0, dim = 0;
  is >> kw >> version;
  CHECK(kw == "MeshVersionFormatted" && version == 2);
  is >> kw >> dim;
  CHECK(kw == "Dimension" && dim == 3);
  std::size_t n = 0;
  is >> kw >> n;
  CHECK(kw == "Vertices" && n == m.points.size());
  for(std::size_t i = 0; i < n && is; ++i) {
    double x, y, z;
    int ref;
    is >> x >> y >> z >> ref;
    CHECK(same_point(m.points[i], x, y, z));
  }
  is >> kw >> n;
  CHECK(kw == "Tetrahedra" && n == m.tets.size());
  for(std::size_t i = 0; i < n && is; ++i) {
    int a, b, c, d, ref;
    is >> a >> b >> c >> d >> ref;
    CHECK((Tet{{ a - 1, b - 1, c - 1, d - 1 }} == m.tets[i]));
  }
  is >> kw;
  CHECK(kw == "End");
  CHECK(!is.fail());

  std::ifstream sol(sol_file);
  CHECK(sol.good());
  sol >> kw >> version;
  CHECK(kw == "MeshVersionFormatted" && version == 2);
  sol >> kw >> dim;
  CHECK(kw == "Dimension" && dim == 3);
  std::size_t nb_types = 0;
  sol >> kw >> n >> nb_types;
  CHECK(kw == "SolAtVertices" && n == m.points.size() && nb_types == m.fields.size());
  for(std::size_t j = 0; j < nb_types; ++j) {
    int type = 0;
    sol >> type;
    CHECK(type == 1);
  }
  for(std::size_t i = 0; i < n && sol; ++i)
    for(std::size_t j = 0; j < nb_types; ++j) {
      double v;
      sol >> v;
      CHECK(v == m.fields[j].second[i]);
    }
  sol >> kw;
  CHECK(kw == "End");
  CHECK(!sol.fail());
}

// Skips '#' comment lines, as TetGen does.
std::string next_data_line(std::istream& is)
{
  std::string line;
  while(std::getline(is, line))
    if(!line.empty() && line[0] != '#')
      return line;
  return std::string();
}

void check_tetgen(const std::string& node_file, const std::string& ele_file, const Mesh& m)
{
  std::ifstream is(node_file);
  CHECK(is.good());
  std::string first;
  std::getline(is, first);
  CHECK(first == "# attributes: sign distance");
  is.seekg(0);
  std::istringstream header(next_data_line(is));
  std::size_t n = 0, dim = 0, nb_attr = 0, nb_markers = 0;
  header >> n >> dim >> nb_attr >> nb_markers;
  CHECK(n == m.points.size() && dim == 3 && nb_attr == m.fields.size() && nb_markers == 0);
  for(std::size_t i = 0; i < n && is; ++i) {
    std::size_t id;
    double x, y, z;
    is >> id >> x >> y >> z;
    CHECK(id == i);
    CHECK(same_point(m.points[i], x, y, z));
    for(std::size_t j = 0; j < nb_attr; ++j) {
      double v;
      is >> v;
      CHECK(v == m.fields[j].second[i]);
    }
  }
  CHECK(!is.fail());
  std::string rest;
  is >> rest;
  CHECK(is.eof() && rest.empty());

  std::ifstream es(ele_file);
  CHECK(es.good());
  std::istringstream eheader(next_data_line(es));
  std::size_t nt = 0, corners = 0, region = 0;
  eheader >> nt >> corners >> region;
  CHECK(nt == m.tets.size() && corners == 4 && region == 0);
  for(std::size_t i = 0; i < nt && es; ++i) {
    std::size_t id;
    Tet t;
    es >> id >> t[0] >> t[1] >> t[2] >> t[3];
    CHECK(id == i && t == m.tets[i]);
  }
  CHECK(!es.fail());
}

// The JSON the Python checker compares the .vtu files against.
bool write_expected_json(const std::string& file, const Mesh& m)
{
  std::ofstream os(file);
  os << std::setprecision(17);
  os << "{\n  \"number_of_points\": " << m.points.size()
     << ",\n  \"number_of_cells\": " << m.tets.size() << ",\n  \"points\": [";
  for(std::size_t i = 0; i < m.points.size(); ++i)
    os << (i ? ", " : "") << "[" << m.points[i].x() << ", " << m.points[i].y() << ", " << m.points[i].z() << "]";
  os << "],\n  \"tets\": [";
  for(std::size_t i = 0; i < m.tets.size(); ++i)
    os << (i ? ", " : "") << "[" << m.tets[i][0] << ", " << m.tets[i][1] << ", " << m.tets[i][2] << ", " << m.tets[i][3] << "]";
  os << "],\n  \"fields\": {";
  for(std::size_t j = 0; j < m.fields.size(); ++j) {
    os << (j ? ", " : "") << "\n    \"" << m.fields[j].first << "\": [";
    for(std::size_t i = 0; i < m.fields[j].second.size(); ++i)
      os << (i ? ", " : "") << m.fields[j].second[i];
    os << "]";
  }
  os << "\n  }\n}\n";
  return bool(os);
}

void check_bad_input(const std::string& dir, const Mesh& m)
{
  using namespace CGAL::IO;
  std::ostringstream os;

  // index out of range, negative index
  std::vector<Tet> bad_tets = m.tets;
  bad_tets.back()[2] = int(m.points.size());
  CHECK(!write_tet_mesh_VTU(os, m.points, bad_tets));
  CHECK(!write_tet_mesh_MEDIT(os, m.points, bad_tets));
  bad_tets.back()[2] = -1;
  CHECK(!write_tet_mesh_VTU(os, m.points, bad_tets, {}, false));
  std::ostringstream node_os, ele_os;
  CHECK(!write_tet_mesh_TetGen(node_os, ele_os, m.points, bad_tets));
  CHECK(os.str().empty() && node_os.str().empty() && ele_os.str().empty());

  // a field of the wrong size
  std::vector<Tet_mesh_vertex_field> bad_fields = m.fields;
  bad_fields[1].second.pop_back();
  CHECK(!write_tet_mesh_VTU(os, m.points, m.tets, bad_fields));
  CHECK(!write_tet_mesh_MEDIT_sol(os, m.points.size(), bad_fields));
  CHECK(!write_tet_mesh_TetGen(node_os, ele_os, m.points, m.tets, bad_fields));
  CHECK(!write_tet_mesh_MEDIT_sol(os, m.points.size(), {}));
  CHECK(os.str().empty() && node_os.str().empty() && ele_os.str().empty());

  // no file must be created for bad input nor for an unknown extension
  const std::string bad_file = join(dir, "bad.vtu");
  std::filesystem::remove(bad_file);
  CHECK(!write_tet_mesh(bad_file, m.points, m.tets, bad_fields));
  CHECK(!std::filesystem::exists(bad_file));
  CHECK(!write_tet_mesh(join(dir, "cube.off"), m.points, m.tets));
  CHECK(!write_tet_mesh(join(dir, "cube"), m.points, m.tets));
  CHECK(!write_tet_mesh(join(dir, "no_such_dir/cube.vtu"), m.points, m.tets));

  // a failed stream
  std::ostringstream failed;
  failed.setstate(std::ios::failbit);
  CHECK(!write_tet_mesh_VTU(failed, m.points, m.tets, m.fields));
  CHECK(!write_tet_mesh_MEDIT(failed, m.points, m.tets));
}

// Other kernels and index types must compile and give the same bytes.
void check_genericity(const Mesh& m)
{
  using namespace CGAL::IO;
  typedef CGAL::Exact_predicates_exact_constructions_kernel::Point_3 Exact_point;
  typedef CGAL::Simple_cartesian<float>::Point_3 Float_point;
  std::vector<Exact_point> exact_points;
  std::vector<Float_point> float_points;
  for(const Point& p : m.points) {
    exact_points.emplace_back(p.x(), p.y(), p.z());
    float_points.emplace_back(float(p.x()), float(p.y()), float(p.z()));
  }
  std::vector<std::array<std::size_t, 4> > size_t_tets;
  for(const Tet& t : m.tets)
    size_t_tets.push_back({{ std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2]), std::size_t(t[3]) }});

  for(bool binary : { true, false }) {
    std::ostringstream a, b;
    CHECK(write_tet_mesh_VTU(a, m.points, m.tets, m.fields, binary));
    CHECK(write_tet_mesh_VTU(b, exact_points, size_t_tets, m.fields, binary));
    CHECK(a.str() == b.str());
    std::ostringstream f;
    CHECK(write_tet_mesh_VTU(f, float_points, size_t_tets, m.fields, binary));
  }
  std::ostringstream a, b;
  CHECK(write_tet_mesh_MEDIT(a, m.points, m.tets));
  CHECK(write_tet_mesh_MEDIT(b, exact_points, size_t_tets));
  CHECK(a.str() == b.str());

  // an empty mesh is valid
  std::ostringstream e;
  CHECK(write_tet_mesh_VTU(e, std::vector<Point>(), std::vector<Tet>()));
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2) {
    std::cerr << "usage: " << argv[0] << " <output_dir>" << std::endl;
    return 2;
  }
  const std::string dir = argv[1];
  std::filesystem::create_directories(dir);

  const Mesh m = make_cube();
  for(const Tet& t : m.tets)
    CHECK(is_positive(m.points, t));

  CHECK(CGAL::IO::write_tet_mesh(join(dir, "cube.vtu"), m.points, m.tets, m.fields));
  {
    std::ofstream os(join(dir, "cube_ascii.vtu"), std::ios::binary);
    CHECK(CGAL::IO::write_tet_mesh_VTU(os, m.points, m.tets, m.fields, false));
  }
  CHECK(write_expected_json(join(dir, "cube_expected.json"), m));

  CHECK(CGAL::IO::write_tet_mesh(join(dir, "cube.MESH"), m.points, m.tets, m.fields));
  check_medit(join(dir, "cube.MESH"), join(dir, "cube.sol"), m);

  CHECK(CGAL::IO::write_tet_mesh(join(dir, "cube.ele"), m.points, m.tets, m.fields));
  check_tetgen(join(dir, "cube.node"), join(dir, "cube.ele"), m);

  check_bad_input(dir, m);
  check_genericity(m);

  if(failures != 0) {
    std::cerr << failures << " check(s) failed" << std::endl;
    return 1;
  }
  std::cout << "test_tet_mesh_io: all checks passed" << std::endl;
  return 0;
}
