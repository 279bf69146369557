// Robustness tests of CGAL::ism_surface_reconstruction() (project issue 8).
//
// Usage: test_robustness <meshes dir> <scratch dir> <section> [case name filter]
//   section: corpus | noise_clean | noise_gauss_0.25 | noise_gauss_0.5 | outliers_1 |
//            outliers_far | nonuniform | nonuniform_dense | determinism | memory | all
//
// Every case runs in a forked child process (alarm() in the child, SIGKILL from the parent
// after a grace period, a resident-memory cap watched by the parent), so that a crash, a
// hang or a runaway allocation is reported as a FAILURE with the case name instead of
// killing the harness. The parent never calls the package (nor TBB): it only forks, waits
// and compares files.
//
// corpus       generated bad and degenerate inputs (points made in the child, files written
//              into the scratch dir and read back with CGAL::IO::read_points) and absurd
//              parameters. A case passes with a std::exception carrying a non-empty message
//              (or a read failure), or with a closed 2-manifold triangle mesh; cases marked
//              "error" must be refused (documented limits), cases marked "mesh" must give a
//              mesh (sphere scaled to 1e30 and 1e-30).
// noise_*, outliers_1, outliers_far, nonuniform, nonuniform_dense
//              the bunny sampled at 36k points: gaussian noise 0.25 % and 0.5 % of the
//              diagonal, 1 % uniform outliers in the box, 1 % outliers 1 to 2 diagonals
//              away (not in the issue; a scanner's stray returns), one half (x > median) ten times
//              denser than the other; nonuniform_dense: the 36k bunny's density on one
//              half, ten times that on the other (198k points). The output must be closed,
//              2-manifold, one component, genus 0, and right in/out on 100 % of the
//              queries farther than 1 % of the diagonal from the true surface. noise_clean is the same without noise (a
//              reference for the others). These are not loosened when they fail. The
//              environment variable ISM_ROBUSTNESS_SEED=s takes sampling s instead of 1 (how
//              often the bar is met over samplings: README, "Measured"); ISM_ROBUSTNESS_DUMP=dir
//              writes the points (.xyz) and the output (.off) there, to trace a miss.
// determinism  same input, parameters and seed: byte-identical .off over two runs and over
//              1 and 2 threads (tbb::global_control, when CGAL_LINKED_WITH_TBB).
// memory       inputs whose refinement needs more memory than the process may use must be
//              refused with a clear error (not std::bad_alloc, not the OOM killer). The
//              budget of the child is set with setrlimit(RLIMIT_AS), so the package's guard
//              has to take RLIMIT_AS (and cgroup limits) into account, not only
//              sysconf(_SC_PHYS_PAGES).
//
// Environment: ISM_ROBUSTNESS_TIME_SCALE multiplies every time limit (default 1, or 3 in a
// sanitizer build: ASan+UBSan measured 2-3 times slower on these cases).

#include "ism_evaluation.h"

#include <CGAL/ism_surface_reconstruction.h>
#include <CGAL/ISM_reconstruction_3/parameters.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <cxxabi.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#if defined(__SANITIZE_ADDRESS__)
#define ISM_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ISM_UNDER_ASAN 1
#endif
#endif

using namespace ISM_eval;
namespace params = CGAL::parameters;
namespace ISM = CGAL::ISM_reconstruction_3;

namespace {

const double NaN = std::numeric_limits<double>::quiet_NaN();
const double Inf = std::numeric_limits<double>::infinity();

std::string g_meshes_dir, g_tmp_dir;

// ---------------------------------------------------------------------------------------
// Results
// ---------------------------------------------------------------------------------------

enum Kind {
  MESH_OK,            // closed 2-manifold triangle mesh
  MESH_INVALID,       // returned true but the mesh is empty, open, non-manifold or not finite
  EXCEPTION,          // std::exception with a non-empty message
  READ_FAIL,          // CGAL::IO::read_points returned false or threw
  CANCELLED,          // returned false (callback)
  CHECK_FAILED,       // a quality check of a noise/determinism/memory case failed
  BAD_ALLOC,          // std::bad_alloc: memory was exhausted, no guard refused first
  EMPTY_MESSAGE,      // std::exception with an empty what()
  UNKNOWN_EXCEPTION,  // not a std::exception
  // set by the parent
  CRASH,              // killed by a signal
  TIMEOUT,            // alarm() or the parent's SIGKILL
  MEMORY_CAP,         // resident memory went over the cap, killed by the parent
  BAD_EXIT,           // nonzero exit status (sanitizer report, exit() in the package...)
  NO_RESULT           // exited 0 without reporting
};

const char* kind_name(int k)
{
  static const char* names[] = {"mesh",      "INVALID MESH", "exception", "read failure", "cancelled",
                                "CHECK FAILED", "BAD_ALLOC", "EMPTY MESSAGE", "NON-STD EXCEPTION", "CRASH",
                                "TIMEOUT",   "MEMORY CAP",   "BAD EXIT",  "NO RESULT"};
  return (k >= 0 && k <= NO_RESULT) ? names[k] : "?";
}

struct Result
{
  int kind = NO_RESULT;
  std::string detail;
};

enum Expect {
  ANY,    // a clear exception, a read failure or a valid mesh
  MESH,   // a valid mesh
  ERROR,  // a clear exception or a read failure (documented refusal)
  CANCEL  // the callback cancels: returns false
};

const char* expect_name(Expect e)
{
  switch(e)
  {
    case ANY: return "any";
    case MESH: return "mesh";
    case ERROR: return "error";
    case CANCEL: return "cancel";
  }
  return "?";
}

bool acceptable(Expect e, int kind)
{
  switch(kind)
  {
    case MESH_OK: return e == ANY || e == MESH;
    case EXCEPTION:
    case READ_FAIL: return e == ANY || e == ERROR;
    case CANCELLED: return e == CANCEL;
    default: return false;
  }
}

std::string demangle(const char* name)
{
  int status = 0;
  char* s = abi::__cxa_demangle(name, nullptr, nullptr, &status);
  std::string r = (status == 0 && s) ? s : name;
  std::free(s);
  return r;
}

std::string one_line(std::string s, std::size_t max = 160)
{
  std::replace(s.begin(), s.end(), '\n', ' ');
  std::replace(s.begin(), s.end(), '\t', ' ');
  if(s.size() > max) s = s.substr(0, max - 3) + "...";
  return s;
}

// ---------------------------------------------------------------------------------------
// Checking a mesh
// ---------------------------------------------------------------------------------------

struct Mesh_report
{
  bool valid = false;
  Topology topology;
  std::string text;
};

Mesh_report check_mesh(const Mesh& m)
{
  Mesh_report r;
  std::ostringstream os;
  os << "V=" << m.number_of_vertices() << " F=" << m.number_of_faces();
  bool ok = m.number_of_faces() > 0;
  if(!ok) os << " (empty mesh)";
  bool finite = true;
  for(vertex_descriptor v : vertices(m))
  {
    const Point_3& p = m.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) finite = false;
  }
  if(!finite) { os << " NON-FINITE VERTEX"; ok = false; }
  if(m.number_of_faces() > 0)
  {
    const bool valid = CGAL::is_valid_polygon_mesh(m);
    const bool triangles = valid && CGAL::is_triangle_mesh(m);
    const bool closed = valid && CGAL::is_closed(m);
    std::vector<halfedge_descriptor> nm;
    if(valid) PMP::non_manifold_vertices(m, std::back_inserter(nm));
    r.topology = topology(m);
    os << " comps=" << r.topology.components << " genus=" << r.topology.genus;
    if(!valid) { os << " NOT A VALID POLYGON MESH"; ok = false; }
    if(valid && !triangles) { os << " NOT TRIANGLES"; ok = false; }
    if(valid && !closed) { os << " OPEN (" << r.topology.boundary_cycles << " boundary cycles)"; ok = false; }
    if(!nm.empty()) { os << " " << nm.size() << " NON-MANIFOLD VERTICES"; ok = false; }
    if(r.topology.isolated_vertices > 0) { os << " " << r.topology.isolated_vertices << " ISOLATED VERTICES"; ok = false; }
  }
  r.valid = ok;
  r.text = os.str();
  return r;
}

// Runs the reconstruction and classifies what happened.
template <class NP>
Result reconstruct(const std::vector<Point_3>& points, const NP& np, Mesh* out = nullptr)
{
  Result r;
  Mesh m;
  try
  {
    const bool done = CGAL::ism_surface_reconstruction(points, m, np);
    if(!done)
    {
      r.kind = CANCELLED;
      r.detail = "returned false; mesh has " + std::to_string(m.number_of_faces()) + " faces";
      return r;
    }
  }
  catch(const std::bad_alloc& e)
  {
    r.kind = BAD_ALLOC;
    r.detail = demangle(typeid(e).name()) + ": " + e.what();
    return r;
  }
  catch(const std::exception& e)
  {
    const std::string what = e.what() ? e.what() : "";
    r.kind = what.empty() ? EMPTY_MESSAGE : EXCEPTION;
    r.detail = demangle(typeid(e).name()) + ": " + what;
    return r;
  }
  catch(...)
  {
    r.kind = UNKNOWN_EXCEPTION;
    r.detail = "exception not derived from std::exception";
    return r;
  }
  const Mesh_report mr = check_mesh(m);
  r.kind = mr.valid ? MESH_OK : MESH_INVALID;
  r.detail = mr.text;
  if(out) *out = std::move(m);
  return r;
}

Result reconstruct(const std::vector<Point_3>& points) { return reconstruct(points, params::default_values()); }

// Reads a point file, then reconstructs from what was read.
Result read_and_reconstruct(const std::string& file)
{
  std::vector<Point_3> points;
  bool ok = false;
  try
  {
    ok = CGAL::IO::read_points(file, std::back_inserter(points));
  }
  catch(const std::bad_alloc& e)
  {
    // the reader (CGAL's, not the package's) reserved what a corrupt header announced
    return Result{READ_FAIL, std::string("reader threw std::bad_alloc (corrupt header size)")};
  }
  catch(const std::exception& e)
  {
    return Result{READ_FAIL, "reader threw " + demangle(typeid(e).name()) + ": " + e.what()};
  }
  if(!ok) return Result{READ_FAIL, "read_points returned false (" + std::to_string(points.size()) + " points read)"};
  Result r = reconstruct(points);
  r.detail = std::to_string(points.size()) + " points read; " + r.detail;
  return r;
}

// ---------------------------------------------------------------------------------------
// Point generators (deterministic: ISM_eval::Rng)
// ---------------------------------------------------------------------------------------

std::vector<Point_3> random_cube(std::size_t n, std::uint64_t seed, double half = 1.)
{
  Rng rng(seed);
  std::vector<Point_3> v;
  v.reserve(n);
  for(std::size_t i = 0; i < n; ++i) v.push_back(rng.uniform_point(CGAL::Bbox_3(-half, -half, -half, half, half, half)));
  return v;
}

// points on the sphere of centre c and radius r (normalised gaussian vectors)
std::vector<Point_3> sphere_points(std::size_t n, std::uint64_t seed, double r = 1., const Point_3& c = Point_3(0, 0, 0))
{
  Rng rng(seed);
  std::vector<Point_3> v;
  v.reserve(n);
  while(v.size() < n)
  {
    const double x = rng.gaussian(), y = rng.gaussian(), z = rng.gaussian();
    const double l = std::sqrt(x * x + y * y + z * z);
    if(l < 1e-9) continue;
    v.emplace_back(c.x() + r * (x / l), c.y() + r * (y / l), c.z() + r * (z / l));
  }
  return v;
}

std::vector<Point_3> mesh_points(const Mesh& m, std::size_t n, unsigned seed, double sigma = 0)
{
  std::vector<Point_3> v;
  v.reserve(n);
  for(const auto& s : sample_points(m, n, seed, sigma)) v.push_back(s.first);
  return v;
}

Mesh shape(const std::string& name)
{
  if(name == "sphere") return make_sphere(Point_3(0, 0, 0), 1., 32);
  if(name == "torus") return make_torus(Point_3(0, 0, 0), 1., 0.35);
  if(name == "two_spheres") return make_two_spheres(Point_3(-1.2, 0, 0), 1., Point_3(1.3, 0, 0), 0.8);
  if(name == "nested_spheres") return make_nested_spheres(Point_3(0, 0, 0), 1., 0.5);
  if(name == "trefoil") return make_trefoil_tube();
  Mesh m;
  if(!read_mesh(g_meshes_dir + "/" + name + ".off", m)) throw std::runtime_error("test: cannot read " + name);
  return m;
}

std::vector<Point_3> repeat(const std::vector<Point_3>& v, std::size_t copies)
{
  std::vector<Point_3> r;
  r.reserve(v.size() * copies);
  for(std::size_t c = 0; c < copies; ++c) r.insert(r.end(), v.begin(), v.end());
  return r;
}

// ---------------------------------------------------------------------------------------
// Files
// ---------------------------------------------------------------------------------------

std::string tmp_file(const std::string& name) { return g_tmp_dir + "/" + name; }

void write_text(const std::string& file, const std::string& text)
{
  std::ofstream os(file, std::ios::binary);
  os << text;
}

std::string xyz_text(const std::vector<Point_3>& v)
{
  std::ostringstream os;
  os << std::setprecision(17);
  for(const Point_3& p : v) os << p.x() << " " << p.y() << " " << p.z() << "\n";
  return os.str();
}

std::string off_text(const std::vector<Point_3>& v, long declared_vertices, const std::string& header = "OFF")
{
  std::ostringstream os;
  os << std::setprecision(17) << header << "\n" << declared_vertices << " 0 0\n";
  for(const Point_3& p : v) os << p.x() << " " << p.y() << " " << p.z() << "\n";
  return os.str();
}

std::string ply_binary(const std::vector<Point_3>& v, const std::string& declared, const std::string& type = "double",
                       bool big_endian = false)
{
  std::ostringstream os;
  os << "ply\nformat " << (big_endian ? "binary_big_endian" : "binary_little_endian") << " 1.0\n"
     << "element vertex " << declared << "\nproperty " << type << " x\nproperty " << type << " y\nproperty " << type
     << " z\nend_header\n";
  for(const Point_3& p : v)
  {
    const double c[3] = {p.x(), p.y(), p.z()};
    for(double d : c)
    {
      char bytes[8];
      std::size_t n;
      if(type == "float") { const float f = float(d); std::memcpy(bytes, &f, 4); n = 4; }
      else { std::memcpy(bytes, &d, 8); n = 8; }
      if(big_endian) std::reverse(bytes, bytes + n);
      os.write(bytes, std::streamsize(n));
    }
  }
  return os.str();
}

std::size_t ply_header_size(const std::string& ply) { return ply.find("end_header\n") + 11; }

std::string random_bytes(std::size_t n, std::uint64_t seed)
{
  Rng rng(seed);
  std::string s(n, '\0');
  for(char& c : s) c = char(rng.uniform_index(256));
  return s;
}

// ---------------------------------------------------------------------------------------
// The fork harness
// ---------------------------------------------------------------------------------------

double time_scale()
{
  if(const char* s = std::getenv("ISM_ROBUSTNESS_TIME_SCALE")) return (std::max)(0.1, std::atof(s));
#ifdef ISM_UNDER_ASAN
  return 3.;
#else
  return 1.;
#endif
}

struct Case
{
  std::string group, name;
  Expect expect = ANY;
  std::function<Result()> run;
  int time_limit = 60;           // seconds, before scaling
  std::size_t address_space_mb = 4096;  // RLIMIT_AS of the child (not under ASan)
  std::size_t rss_cap_mb = 6144;        // the parent kills the child above this resident size
};

struct Outcome
{
  Result result;
  bool pass = false;
  double seconds = 0;
  long peak_rss_mb = 0;
};

long resident_mb(pid_t pid)
{
  std::ifstream is("/proc/" + std::to_string(pid) + "/statm");
  long size = 0, resident = 0;
  if(!(is >> size >> resident)) return 0;
  return long(resident * (sysconf(_SC_PAGESIZE) / 1024) / 1024);
}

void set_address_space_limit(std::size_t mb)
{
#ifndef ISM_UNDER_ASAN  // ASan reserves terabytes of shadow address space
  struct rlimit rl;
  rl.rlim_cur = rl.rlim_max = rlim_t(mb) * 1024 * 1024;
  setrlimit(RLIMIT_AS, &rl);
#else
  (void)mb;
#endif
}

Outcome run_in_child(const Case& c)
{
  Outcome o;
  std::cout.flush();
  std::cerr.flush();
  int fd[2];
  if(pipe(fd) != 0) { o.result = Result{NO_RESULT, "pipe() failed"}; return o; }
  const int limit = (std::max)(1, int(c.time_limit * time_scale()));
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if(pid < 0) { o.result = Result{NO_RESULT, "fork() failed"}; return o; }
  if(pid == 0)
  {
    close(fd[0]);
    set_address_space_limit(c.address_space_mb);
    alarm(unsigned(limit));
    Result r;
    try { r = c.run(); }
    catch(const std::bad_alloc& e) { r = Result{BAD_ALLOC, std::string("outside the package: ") + e.what()}; }
    catch(const std::exception& e) { r = Result{CHECK_FAILED, std::string("test code threw: ") + e.what()}; }
    const std::string msg = std::to_string(r.kind) + "\n" + r.detail;
    std::size_t off = 0;
    while(off < msg.size())
    {
      const ssize_t w = write(fd[1], msg.data() + off, msg.size() - off);
      if(w <= 0) break;
      off += std::size_t(w);
    }
    close(fd[1]);
    // a normal exit, so that LeakSanitizer checks the child (it exits 23 on a leak)
    std::exit(0);
  }
  close(fd[1]);
  fcntl(fd[0], F_SETFL, O_NONBLOCK);
  std::string data;
  int status = 0;
  struct rusage ru;
  std::memset(&ru, 0, sizeof(ru));
  int killed_for = -1;  // TIMEOUT or MEMORY_CAP when the parent killed it
  long peak_seen = 0;
  for(;;)
  {
    char buf[4096];
    ssize_t n;
    while((n = read(fd[0], buf, sizeof buf)) > 0) data.append(buf, std::size_t(n));
    const pid_t w = wait4(pid, &status, WNOHANG, &ru);
    if(w == pid) break;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const long rss = resident_mb(pid);
    peak_seen = (std::max)(peak_seen, rss);
    if(killed_for < 0 && rss > long(c.rss_cap_mb))
    {
      killed_for = MEMORY_CAP;
      kill(pid, SIGKILL);
    }
    if(killed_for < 0 && elapsed > limit + 15)
    {
      killed_for = TIMEOUT;
      kill(pid, SIGKILL);
    }
    usleep(elapsed < 1 ? 2000 : 20000);
  }
  {
    char buf[4096];
    ssize_t n;
    while((n = read(fd[0], buf, sizeof buf)) > 0) data.append(buf, std::size_t(n));
  }
  close(fd[0]);
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  o.peak_rss_mb = (std::max)(long(ru.ru_maxrss / 1024), peak_seen);

  Result reported;
  const std::size_t nl = data.find('\n');
  if(nl != std::string::npos)
  {
    reported.kind = std::atoi(data.substr(0, nl).c_str());
    reported.detail = data.substr(nl + 1);
  }
  if(killed_for == MEMORY_CAP)
    o.result = Result{MEMORY_CAP, "resident memory over " + std::to_string(c.rss_cap_mb) + " MB, killed"};
  else if(killed_for == TIMEOUT)
    o.result = Result{TIMEOUT, "no answer after " + std::to_string(limit + 15) + " s, killed"};
  else if(WIFSIGNALED(status))
  {
    const int sig = WTERMSIG(status);
    if(sig == SIGALRM)
      o.result = Result{TIMEOUT, "no answer after " + std::to_string(limit) + " s (alarm)"};
    else
      o.result = Result{CRASH, std::string("killed by signal ") + std::to_string(sig) + " (" + strsignal(sig) + ")" +
                                   (sig == SIGKILL ? " - the OOM killer?" : "")};
  }
  else if(WIFEXITED(status) && WEXITSTATUS(status) != 0)
    o.result = Result{BAD_EXIT, "exit status " + std::to_string(WEXITSTATUS(status)) +
                                    " (a sanitizer report on stderr?); it had reported: " +
                                    (nl == std::string::npos ? std::string("nothing")
                                                             : std::string(kind_name(reported.kind)) + " " + reported.detail)};
  else if(nl == std::string::npos)
    o.result = Result{NO_RESULT, "the child exited without a result"};
  else
    o.result = reported;
  o.pass = acceptable(c.expect, o.result.kind);
  return o;
}

// Runs the cases, prints one line per case as it goes and a summary table; returns the
// number of failures.
int run_cases(const std::string& title, const std::vector<Case>& cases, const std::string& filter)
{
  std::vector<std::pair<const Case*, Outcome> > done;
  for(const Case& c : cases)
  {
    if(!filter.empty() && (c.group + "/" + c.name).find(filter) == std::string::npos) continue;
    const Outcome o = run_in_child(c);
    done.emplace_back(&c, o);
    std::cout << (o.pass ? "ok      " : "FAILURE ") << c.group << "/" << c.name << " [expect " << expect_name(c.expect)
              << "]: " << kind_name(o.result.kind) << " - " << one_line(o.result.detail, 400) << " (" << std::fixed
              << std::setprecision(2) << o.seconds << " s, " << o.peak_rss_mb << " MB)" << std::defaultfloat
              << std::endl;
  }
  // summary
  std::size_t failures = 0;
  std::map<std::string, std::size_t> by_kind;
  std::map<std::string, std::array<std::size_t, 2> > by_group;
  for(const auto& d : done)
  {
    ++by_kind[kind_name(d.second.result.kind)];
    ++by_group[d.first->group][d.second.pass ? 0 : 1];
    if(!d.second.pass) ++failures;
  }
  std::cout << "\n==== " << title << ": " << done.size() << " cases, " << done.size() - failures << " passed, " << failures
            << " failed ====\n";
  std::cout << std::left << std::setw(5) << "#" << std::setw(12) << "group" << std::setw(36) << "case" << std::setw(7)
            << "expect" << std::setw(19) << "outcome" << std::right << std::setw(9) << "time s" << std::setw(8) << "MB"
            << "  verdict  detail\n";
  std::size_t i = 0;
  for(const auto& d : done)
  {
    const Outcome& o = d.second;
    std::ostringstream t;
    t << std::fixed << std::setprecision(2) << o.seconds;
    std::cout << std::left << std::setw(5) << ++i << std::setw(12) << d.first->group << std::setw(36) << d.first->name
              << std::setw(7) << expect_name(d.first->expect) << std::setw(19) << kind_name(o.result.kind) << std::right
              << std::setw(9) << t.str() << std::setw(8) << o.peak_rss_mb << "  " << (o.pass ? "ok     " : "FAILURE")
              << "  " << one_line(o.result.detail, 110) << "\n";
  }
  std::cout << "\noutcomes:";
  for(const auto& k : by_kind) std::cout << "  " << k.first << "=" << k.second;
  std::cout << "\ngroups (passed/failed):";
  for(const auto& g : by_group) std::cout << "  " << g.first << "=" << g.second[0] << "/" << g.second[1];
  std::cout << "\n";
  if(failures)
  {
    std::cout << "failed cases:";
    for(const auto& d : done)
      if(!d.second.pass) std::cout << " " << d.first->group << "/" << d.first->name;
    std::cout << "\n";
  }
  std::cout << std::endl;
  return int(failures);
}

// ---------------------------------------------------------------------------------------
// 1. The corpus of bad and degenerate inputs
// ---------------------------------------------------------------------------------------

// the input of the parameter cases: a sphere sample that reconstructs with the defaults
std::vector<Point_3> base_points() { return sphere_points(3000, 11); }
std::vector<Point_3> small_points() { return sphere_points(500, 12); }

// the mesh must be the spheres of centres `centres` and radius s: every vertex within 10 % of
// s from its nearest centre, and (a coarse sphere is not the sphere) at least
// `minimum_vertices` vertices on each
void check_spheres(const Mesh& m, const std::vector<std::array<double, 3> >& centres, double s,
                   std::size_t minimum_vertices, Result& r)
{
  if(r.kind != MESH_OK) return;
  double lo = Inf, hi = 0;
  std::vector<std::size_t> count(centres.size(), 0);
  for(vertex_descriptor vd : vertices(m))
  {
    const Point_3& p = m.point(vd);
    double d = Inf;
    std::size_t nearest = 0;
    for(std::size_t i = 0; i < centres.size(); ++i)
    {
      // divide first: at 1e-30 the squares would lose precision, at 1e200 they would overflow
      const double dx = (p.x() - centres[i][0]) / s, dy = (p.y() - centres[i][1]) / s, dz = (p.z() - centres[i][2]) / s;
      const double di = std::sqrt(dx * dx + dy * dy + dz * dz);
      if(di < d) { d = di; nearest = i; }
    }
    lo = (std::min)(lo, d);
    hi = (std::max)(hi, d);
    ++count[nearest];
  }
  std::ostringstream os;
  os << r.detail << "; |v - c| / r in [" << lo << ", " << hi << "]";
  if(centres.size() > 1)
  {
    os << ", vertices per sphere";
    for(std::size_t c : count) os << " " << c;
  }
  r.detail = os.str();
  if(!(lo > 0.9 && hi < 1.1) || *std::min_element(count.begin(), count.end()) < minimum_vertices)
  {
    r.kind = MESH_INVALID;
    r.detail += centres.size() > 1 ? " NOT THE SPHERES" : " NOT THE SPHERE";
  }
}

// a sphere at scale s (centred at offset * s) must give a mesh of the same size
Result scaled_sphere(double s, double offset, bool check_size)
{
  std::vector<Point_3> v = sphere_points(5000, 21);
  for(Point_3& p : v) p = Point_3(s * (p.x() + offset), s * (p.y() - 0.5 * offset), s * (p.z() + 0.25 * offset));
  Mesh m;
  Result r = reconstruct(v, params::default_values(), &m);
  if(check_size) check_spheres(m, {{{ s * offset, -0.5 * s * offset, 0.25 * s * offset }}}, s, 0, r);
  return r;
}

// one stray point `distance` radii away: the box grows that much, yet the sphere must come
// out as fine as without it (its 5000 points give about 2,000 vertices; 146 when the
// levels the box cost were not given back)
Result sphere_with_far_outlier(double distance)
{
  std::vector<Point_3> v = sphere_points(5000, 22);
  v.emplace_back(distance, distance, distance);
  Mesh m;
  Result r = reconstruct(v, params::default_values(), &m);
  check_spheres(m, {{{ 0., 0., 0. }}}, 1, 1000, r);
  return r;
}

// two spheres `distance` radii apart: the box is as large as with a far outlier, but half
// the points are out there. Each sphere must come out as fine as alone (its 5000 points give
// about 2,400 vertices; with the bulk counted as 98 % of the points, which span both
// spheres, 500 at 100 radii and no mesh at all at 1000).
Result two_spheres(double distance)
{
  std::vector<Point_3> v = sphere_points(5000, 23), far = sphere_points(5000, 24, 1., Point_3(distance, 0, 0));
  v.insert(v.end(), far.begin(), far.end());
  Mesh m;
  Result r = reconstruct(v, params::default_values(), &m);
  check_spheres(m, {{{ 0., 0., 0. }}, {{ distance, 0., 0. }}}, 1, 1000, r);
  return r;
}

// A refusal must say why: an exception whose message lacks `phrase` fails the case.
Result expect_message(Result r, const std::string& phrase, const std::string& missing)
{
  if(r.kind == EXCEPTION && r.detail.find(phrase) == std::string::npos)
  {
    r.kind = CHECK_FAILED;
    r.detail += " (the message does not " + missing + ")";
  }
  return r;
}

std::vector<Case> corpus_cases()
{
  std::vector<Case> cases;
  auto add = [&](const std::string& group, const std::string& name, Expect e, std::function<Result()> f) {
    Case c;
    c.group = group;
    c.name = name;
    c.expect = e;
    c.run = std::move(f);
    cases.push_back(std::move(c));
    return &cases.back();
  };

  // --- tiny inputs
  add("tiny", "empty", ERROR, [] { return reconstruct(std::vector<Point_3>()); });
  for(int n = 1; n <= 9; ++n)
    add("tiny", "random_" + std::to_string(n), ERROR, [n] { return reconstruct(random_cube(std::size_t(n), 100 + n)); });
  for(int n : {10, 11, 12, 20, 50})
    add("tiny", "random_" + std::to_string(n), ANY, [n] { return reconstruct(random_cube(std::size_t(n), 100 + n)); });
  add("tiny", "cube_corners_8", ERROR, [] {
    std::vector<Point_3> v;
    for(int i = 0; i < 8; ++i) v.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    return reconstruct(v);
  });
  add("tiny", "cube_corners_8_plus_centre_and_top", ANY, [] {
    std::vector<Point_3> v;
    for(int i = 0; i < 8; ++i) v.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    v.emplace_back(0.5, 0.5, 0.5);
    v.emplace_back(0.5, 0.5, 1.5);
    return reconstruct(v);
  });
  add("tiny", "grid_3x3x3", ANY, [] {
    std::vector<Point_3> v;
    for(int i = 0; i < 27; ++i) v.emplace_back(i % 3, (i / 3) % 3, i / 9);
    return reconstruct(v);
  });

  // --- all points identical
  for(std::size_t n : {10, 1000, 100000})
  {
    add("identical", "origin_x" + std::to_string(n), ERROR, [n] { return reconstruct(std::vector<Point_3>(n, Point_3(0, 0, 0))); });
    add("identical", "far_1e30_x" + std::to_string(n), ERROR,
        [n] { return reconstruct(std::vector<Point_3>(n, Point_3(1e30, -2e30, 3e30))); });
  }
  add("identical", "nine_distinct_x1000", ERROR, [] { return reconstruct(repeat(random_cube(9, 5), 1000)); });

  // --- collinear
  for(std::size_t n : {10, 1000, 100000})
  {
    add("collinear", "x_axis_" + std::to_string(n), ERROR, [n] {
      Rng rng(n);
      std::vector<Point_3> v;
      for(std::size_t i = 0; i < n; ++i) v.emplace_back(rng.uniform(-1, 1), 0, 0);
      return reconstruct(v);
    });
    add("collinear", "diagonal_" + std::to_string(n), ERROR, [n] {
      Rng rng(n + 1);
      std::vector<Point_3> v;
      for(std::size_t i = 0; i < n; ++i) { const double t = rng.uniform(-1, 1); v.emplace_back(1 + t, 2 + 3 * t, -t); }
      return reconstruct(v);
    });
  }
  for(double jitter : {1e-12, 1e-7})
    add("collinear", "near_line_jitter_" + one_line(std::to_string(jitter)), ANY, [jitter] {
      Rng rng(7);
      std::vector<Point_3> v;
      for(int i = 0; i < 5000; ++i)
        v.emplace_back(rng.uniform(-1, 1), jitter * rng.gaussian(), jitter * rng.gaussian());
      return reconstruct(v);
    });
  add("collinear", "line_plus_one_point", ANY, [] {
    std::vector<Point_3> v;
    for(int i = 0; i < 1000; ++i) v.emplace_back(i * 1e-3, 0, 0);
    v.emplace_back(0.5, 0.5, 0.5);
    return reconstruct(v);
  });

  // --- coplanar
  for(std::size_t n : {10, 1000, 100000})
  {
    add("coplanar", "z0_" + std::to_string(n), ERROR, [n] {
      Rng rng(n + 2);
      std::vector<Point_3> v;
      for(std::size_t i = 0; i < n; ++i)
      {
        const double y = rng.uniform(-1, 1);  // drawn first, as in Rng::uniform_point
        v.emplace_back(rng.uniform(-1, 1), y, 0);
      }
      return reconstruct(v);
    });
    add("coplanar", "tilted_" + std::to_string(n), ERROR, [n] {
      Rng rng(n + 3);
      std::vector<Point_3> v;
      for(std::size_t i = 0; i < n; ++i)
      {
        const double a = rng.uniform(-1, 1), b = rng.uniform(-1, 1);
        v.emplace_back(3 + a + b, -1 + 2 * a - b, 5 + 0.5 * a + 3 * b);
      }
      return reconstruct(v);
    });
  }
  // within half their spacing of a plane: an open sheet, refused (with 1e-3, 10,000 points on
  // a disk came out as 12 blobs without a word: an independent black-box run, session 41)
  for(double jitter : {1e-12, 1e-6, 1e-3})
    add("coplanar", "near_plane_jitter_" + one_line(std::to_string(jitter)), ERROR, [jitter] {
      Rng rng(8);
      std::vector<Point_3> v;
      for(int i = 0; i < 5000; ++i)
      {
        const double z = jitter * rng.gaussian();  // drawn first, as in Rng::uniform_point
        const double y = rng.uniform(-1, 1);
        v.emplace_back(rng.uniform(-1, 1), y, z);
      }
      return reconstruct(v);
    });
  // one point off the plane made it no plane: a slab with a spike to that point
  add("coplanar", "plane_plus_one_point", ERROR, [] {
    Rng rng(10);
    std::vector<Point_3> v;
    for(int i = 0; i < 5000; ++i)
    {
      const double y = rng.uniform(-1, 1);  // drawn first, as in Rng::uniform_point
      v.emplace_back(rng.uniform(-1, 1), y, 0);
    }
    v.emplace_back(0.1, 0.2, 0.5);
    return reconstruct(v);
  });
  add("coplanar", "two_parallel_lines", ERROR, [] {
    std::vector<Point_3> v;
    for(int i = 0; i < 500; ++i) { v.emplace_back(i, 0, 0); v.emplace_back(i, 1, 0); }
    return reconstruct(v);
  });
  add("coplanar", "two_parallel_planes", ANY, [] {
    Rng rng(9);
    std::vector<Point_3> v;
    for(int i = 0; i < 4000; ++i)
    {
      const double y = rng.uniform(-1, 1);  // drawn first, as in Rng::uniform_point
      v.emplace_back(rng.uniform(-1, 1), y, i % 2 ? 0.1 : -0.1);
    }
    return reconstruct(v);
  });
  add("coplanar", "circle", ERROR, [] {
    std::vector<Point_3> v;
    for(int i = 0; i < 1000; ++i) v.emplace_back(std::cos(i * 0.00628), std::sin(i * 0.00628), 0);
    return reconstruct(v);
  });

  // --- NaN and infinite coordinates
  struct Bad { const char* name; std::size_t index; int coord; double value; };
  const Bad bads[] = {{"nan_first", 0, 0, NaN},    {"nan_middle_y", 1500, 1, NaN}, {"nan_last_z", 2999, 2, NaN},
                      {"inf_first", 0, 0, Inf},    {"minus_inf_middle", 1500, 1, -Inf},
                      {"dbl_max_one_point", 7, 2, std::numeric_limits<double>::max()},
                      {"dbl_lowest_one_point", 7, 0, std::numeric_limits<double>::lowest()},
                      {"1e300_one_point", 7, 1, 1e300}, {"1e154_one_point", 7, 1, 1e154}};
  for(const Bad& b : bads)
  {
    const bool finite = std::isfinite(b.value);
    add("nonfinite", b.name, finite ? ANY : ERROR, [b] {
      std::vector<Point_3> v = base_points();
      const Point_3 p = v[b.index];
      double c[3] = {p.x(), p.y(), p.z()};
      c[b.coord] = b.value;
      v[b.index] = Point_3(c[0], c[1], c[2]);
      return reconstruct(v);
    });
  }
  for(double distance : {30., 100., 1000.})
    add("outliers", "sphere_one_point_at_" + std::to_string(int(distance)), MESH,
        [distance] { return sphere_with_far_outlier(distance); });
  // so far that the sphere is a line to the principal axes: refused as "all points lie on a
  // line" before the isolated points were left out; now left out like the others
  for(double distance : {1e10, 1e30})
    add("outliers", "sphere_one_point_at_1e" + std::to_string(int(std::lround(std::log10(distance)))), MESH,
        [distance] { return sphere_with_far_outlier(distance); });
  for(double distance : {100., 1000.})
    add("outliers", "two_spheres_" + std::to_string(int(distance)) + "_apart", MESH,
        [distance] { return two_spheres(distance); });
  add("nonfinite", "all_nan", ERROR, [] { return reconstruct(std::vector<Point_3>(100, Point_3(NaN, NaN, NaN))); });
  // the same, the isolated points kept: the error must name the cause
  add("nonfinite", "far_outlier_1e10_kept", ERROR, [] {
    std::vector<Point_3> v = base_points();
    v.emplace_back(1e10, 1e10, 1e10);
    return expect_message(reconstruct(v, params::remove_isolated_points(false)), "remove the far outliers",
                          "name the far outlier");
  });

  // ten points 1e5 radii around: isolated (isolated_points.h), left out; the box they made
  // needed more levels than there are below the deepest, and the sphere came out as a blob
  add("outliers", "ten_points_at_1e5", MESH, [] {
    std::vector<Point_3> v = sphere_points(5000, 25);
    const double d = 1e5;
    for(const Point_3& p : {Point_3(d, 0, 0), Point_3(-d, 0, 0), Point_3(0, d, 0), Point_3(0, -d, 0), Point_3(0, 0, d),
                            Point_3(0, 0, -d), Point_3(d, d, d), Point_3(-d, d, -d), Point_3(d, -d, -d), Point_3(-d, -d, d)})
      v.push_back(p);
    Mesh m;
    Result r = reconstruct(v, params::default_values(), &m);
    check_spheres(m, {{{ 0., 0., 0. }}}, 1, 1000, r);
    return r;
  });
  // a dense segment among sparse points: the points bound a volume, what is left once the
  // isolated ones are left out does not; refused, saying so
  add("outliers", "segment_among_isolated_points", ERROR, [] {
    std::vector<Point_3> v;
    for(int i = 0; i < 2000; ++i) v.emplace_back(i / 2000., 0, 0);
    Rng rng(28);
    for(int i = 0; i < 20; ++i) v.push_back(rng.uniform_point(CGAL::Bbox_3(-5, -5, -5, 5, 5, 5)));
    return expect_message(reconstruct(v), "isolated points are left out", "say that isolated points were left out");
  });
  // two spheres 1e5 radii apart: not isolated points, but a box that leaves each sphere 21
  // levels short of what it needs; refused, naming the cause, rather than two blobs
  add("outliers", "two_spheres_1e5_apart", ERROR, [] {
    std::vector<Point_3> v = sphere_points(5000, 26), far = sphere_points(5000, 27, 1., Point_3(1e5, 0, 0));
    v.insert(v.end(), far.begin(), far.end());
    return expect_message(reconstruct(v), "remove the far outliers", "name the parts far apart");
  });

  // --- scale: the sphere must give the sphere at any scale: ism_surface_reconstruction()
  // scales points beyond [2^-32, 2^32) by a power of two (normalization.h); the function
  // alone refuses them beyond 1e+-32 (point_input.h)
  struct Scale { const char* name; double s, offset; Expect e; };
  const Scale scales[] = {{"1e30", 1e30, 0, MESH},          {"1e-30", 1e-30, 0, MESH},
                          {"1e30_offset", 1e30, 3, MESH},    {"1e-30_offset", 1e-30, 3, MESH},
                          {"1e15", 1e15, 0, MESH},           {"1e-15", 1e-15, 0, MESH},
                          {"1e100", 1e100, 0, MESH},         {"1e-100", 1e-100, 0, MESH},
                          {"1e200", 1e200, 0, MESH},         {"1e-200", 1e-200, 0, MESH},
                          {"1e300", 1e300, 0, MESH},         {"1e-300", 1e-300, 0, MESH},
                          {"1e-310_subnormal", 1e-310, 0, ANY}, {"unit_offset_1e6", 1, 1e6, ANY},
                          {"unit_offset_1e12", 1, 1e12, ANY}};
  for(const Scale& s : scales)
    add("scale", std::string("sphere_") + s.name, s.e, [s] { return scaled_sphere(s.s, s.offset, true); });

  // --- many copies of few points
  add("copies", "10_points_x1000000", ANY, [] { return reconstruct(repeat(random_cube(10, 31), 1000000)); });
  add("copies", "10_points_x100000", ANY, [] { return reconstruct(repeat(random_cube(10, 32), 100000)); });
  add("copies", "10_points_x100", ANY, [] { return reconstruct(repeat(random_cube(10, 33), 100)); });
  add("copies", "12_points_x100000_interleaved", ANY, [] {
    const std::vector<Point_3> ten = random_cube(12, 34);
    std::vector<Point_3> v;
    for(int i = 0; i < 1200000; ++i) v.push_back(ten[std::size_t(i) % 12]);
    return reconstruct(v);
  });

  // --- duplicate-heavy sets
  for(std::size_t copies : {2, 5, 6, 7, 20})
    add("duplicates", "sphere3000_x" + std::to_string(copies), ANY,
        [copies] { return reconstruct(repeat(sphere_points(3000, 41), copies)); });
  add("duplicates", "sphere10000_half_duplicated", ANY, [] {
    std::vector<Point_3> v = sphere_points(10000, 42);
    for(std::size_t i = 0; i < 5000; ++i) v[5000 + i] = v[i];
    return reconstruct(v);
  });
  add("duplicates", "sphere3000_x6_jitter_1e-12", ANY, [] {
    Rng rng(43);
    std::vector<Point_3> v;
    for(const Point_3& p : repeat(sphere_points(3000, 43), 6))
      v.emplace_back(p.x() + 1e-12 * rng.gaussian(), p.y() + 1e-12 * rng.gaussian(), p.z() + 1e-12 * rng.gaussian());
    return reconstruct(v);
  });
  add("duplicates", "sphere2000_one_point_x100000", ANY, [] {
    std::vector<Point_3> v = sphere_points(2000, 44);
    v.insert(v.end(), 100000, v[0]);
    return reconstruct(v);
  });

  // --- shapes and sizes (valid inputs, some too sparse to bound anything)
  const char* shapes[] = {"sphere", "torus", "two_spheres", "nested_spheres", "trefoil"};
  unsigned seed = 50;
  for(const char* s : shapes)
    for(std::size_t n : {100, 1000, 10000})
    {
      const std::string name = std::string(s);
      const unsigned sd = ++seed;
      add("shapes", name + "_" + std::to_string(n), ANY, [name, n, sd] { return reconstruct(mesh_points(shape(name), n, sd)); });
    }
  for(std::size_t n : {300, 3000})
    add("shapes", "bunny_" + std::to_string(n), ANY, [n] { return reconstruct(mesh_points(shape("bunny00"), n, 61)); });
  add("shapes", "uniform_cube_volume_5000", ANY, [] { return reconstruct(random_cube(5000, 62)); });

  // --- files
  auto add_file = [&](const std::string& name, std::function<std::string()> content) {
    add("files", name, ANY, [name, content] {
      const std::string f = tmp_file(name);
      write_text(f, content());
      return read_and_reconstruct(f);
    });
  };
  add_file("empty.xyz", [] { return std::string(); });
  add_file("empty.off", [] { return std::string(); });
  add_file("empty.ply", [] { return std::string(); });
  add_file("valid.xyz", [] { return xyz_text(sphere_points(2000, 70)); });
  add_file("crlf.xyz", [] {
    std::string s = xyz_text(sphere_points(2000, 71)), r;
    for(char c : s) { if(c == '\n') r += '\r'; r += c; }
    return r;
  });
  add_file("garbage_lines.xyz", [] {
    std::string s = xyz_text(sphere_points(2000, 72));
    std::string r;
    std::size_t line = 0;
    for(char c : s)
    {
      r += c;
      if(c == '\n' && ++line % 100 == 0) r += "this is not a point\n1 2\n# comment\n\n1 two 3\n";
    }
    return r;
  });
  add_file("garbage_only.xyz", [] { return std::string("hello world\nfoo bar baz\n"); });
  add_file("binary_garbage.xyz", [] { return random_bytes(20000, 73); });
  add_file("binary_garbage.off", [] { return random_bytes(20000, 74); });
  add_file("binary_garbage.ply", [] { return random_bytes(20000, 75); });
  add_file("nan_tokens.xyz", [] { return xyz_text(sphere_points(100, 76)) + "nan nan nan\ninf 1 2\n"; });
  add_file("overflow_tokens.xyz", [] { return xyz_text(sphere_points(100, 77)) + "1e999 1 2\n"; });
  add_file("long_line.xyz", [] { return xyz_text(sphere_points(100, 78)) + std::string(1 << 20, '7') + " 1 2\n"; });
  add_file("four_columns.xyz", [] {
    std::ostringstream os;
    for(const Point_3& p : sphere_points(1000, 79)) os << p.x() << " " << p.y() << " " << p.z() << " 1\n";
    return os.str();
  });
  add_file("off_valid.off", [] { return off_text(sphere_points(2000, 80), 2000); });
  add_file("off_count_too_big.off", [] { return off_text(sphere_points(500, 81), 1000); });
  add_file("off_count_too_small.off", [] { return off_text(sphere_points(2000, 82), 10); });
  add_file("off_count_zero.off", [] { return off_text(sphere_points(200, 83), 0); });
  add_file("off_count_negative.off", [] { return off_text(sphere_points(200, 84), -5); });
  add_file("off_count_huge.off", [] { return off_text(sphere_points(200, 85), 4000000000L); });
  add_file("off_header_only.off", [] { return std::string("OFF\n"); });
  add_file("off_no_header.off", [] { return xyz_text(sphere_points(200, 86)); });
  add_file("off_garbage_vertex.off", [] {
    std::string s = off_text(sphere_points(200, 87), 200);
    return s.substr(0, s.size() / 2) + "x y z\n" + s.substr(s.size() / 2);
  });
  add_file("off_nan_vertex.off", [] { return off_text(sphere_points(199, 88), 200) + "nan nan nan\n"; });
  add_file("off_faces_out_of_range.off", [] {
    std::string s = off_text(sphere_points(100, 89), 100);
    s.replace(s.find("100 0 0"), 7, "100 2 0");
    return s + "3 0 1 2000000\n3 -1 5 7\n";
  });
  add_file("ply_valid_double.ply", [] { return ply_binary(sphere_points(2000, 90), "2000"); });
  add_file("ply_valid_float_big_endian.ply", [] { return ply_binary(sphere_points(2000, 91), "2000", "float", true); });
  {
    // truncations of one binary PLY
    for(const char* where : {"header_only", "mid_header", "one_byte", "half", "last_byte_missing"})
    {
      const std::string w = where;
      add_file("ply_truncated_" + w + ".ply", [w] {
        const std::string ply = ply_binary(sphere_points(2000, 92), "2000");
        const std::size_t h = ply_header_size(ply);
        std::size_t keep = ply.size();
        if(w == "header_only") keep = h;
        else if(w == "mid_header") keep = h / 2;
        else if(w == "one_byte") keep = h + 1;
        else if(w == "half") keep = h + (ply.size() - h) / 2 + 3;
        else if(w == "last_byte_missing") keep = ply.size() - 1;
        return ply.substr(0, keep);
      });
    }
  }
  add_file("ply_count_too_big.ply", [] { return ply_binary(sphere_points(500, 93), "100000"); });
  add_file("ply_count_huge.ply", [] { return ply_binary(sphere_points(500, 94), "4000000000"); });
  add_file("ply_count_negative.ply", [] { return ply_binary(sphere_points(500, 95), "-3"); });
  add_file("ply_no_xyz.ply", [] {
    return std::string("ply\nformat ascii 1.0\nelement vertex 3\nproperty float a\nend_header\n1\n2\n3\n");
  });
  add_file("ply_ascii_garbage.ply", [] {
    std::string s = "ply\nformat ascii 1.0\nelement vertex 100\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
    return s + xyz_text(sphere_points(50, 96)) + "garbage here\n";
  });
  add_file("ply_unknown_format.ply", [] { return std::string("ply\nformat binary_middle_endian 1.0\nelement vertex 1\nend_header\n"); });
  add("files", "missing_file.xyz", ANY, [] { return read_and_reconstruct(tmp_file("does/not/exist.xyz")); });
  add("files", "directory.xyz", ANY, [] {
    const std::string d = tmp_file("a_directory.xyz");
    mkdir(d.c_str(), 0755);
    return read_and_reconstruct(d);
  });

  // --- absurd parameters, on a 3000-point sphere (500 for the slow ones)
#define ISM_PARAM_CASE(NAME, EXPECT, NP) add("parameters", NAME, EXPECT, [] { return reconstruct(base_points(), NP); })
#define ISM_SMALL_PARAM_CASE(NAME, EXPECT, NP) add("parameters", NAME, EXPECT, [] { return reconstruct(small_points(), NP); })
  ISM_PARAM_CASE("maximum_depth_0", ERROR, params::maximum_depth(0));
  ISM_PARAM_CASE("maximum_depth_-1", ERROR, params::maximum_depth(-1));
  ISM_PARAM_CASE("maximum_depth_1", ANY, params::maximum_depth(1));
  ISM_PARAM_CASE("maximum_depth_2", ANY, params::maximum_depth(2));
  ISM_PARAM_CASE("maximum_depth_5", ANY, params::maximum_depth(5));
  ISM_PARAM_CASE("maximum_depth_48", ANY, params::maximum_depth(48));
  ISM_PARAM_CASE("maximum_depth_49", ERROR, params::maximum_depth(49));
  ISM_PARAM_CASE("maximum_depth_60", ERROR, params::maximum_depth(60));
  ISM_PARAM_CASE("maximum_depth_INT_MAX", ERROR, params::maximum_depth(INT_MAX));
  ISM_PARAM_CASE("maximum_depth_INT_MIN", ERROR, params::maximum_depth(INT_MIN));
  ISM_PARAM_CASE("maximum_depth_size_t_max", ERROR, params::maximum_depth(std::size_t(-1)));
  ISM_PARAM_CASE("min_points_per_cell_0", ERROR, params::min_points_per_cell(0));
  ISM_PARAM_CASE("min_points_per_cell_1", ERROR, params::min_points_per_cell(1));
  ISM_PARAM_CASE("min_points_per_cell_2", ERROR, params::min_points_per_cell(2));
  ISM_PARAM_CASE("min_points_per_cell_3", ANY, params::min_points_per_cell(3));
  ISM_PARAM_CASE("min_points_per_cell_-5", ERROR, params::min_points_per_cell(-5));
  ISM_PARAM_CASE("min_points_per_cell_1000000", ANY, params::min_points_per_cell(1000000));
  ISM_PARAM_CASE("min_points_per_cell_1000001", ERROR, params::min_points_per_cell(1000001));
  ISM_PARAM_CASE("coplanarity_threshold_-1", ERROR, params::coplanarity_threshold(-1.));
  ISM_PARAM_CASE("coplanarity_threshold_-1e-300", ERROR, params::coplanarity_threshold(-1e-300));
  ISM_PARAM_CASE("coplanarity_threshold_nan", ERROR, params::coplanarity_threshold(NaN));
  ISM_PARAM_CASE("coplanarity_threshold_inf", ERROR, params::coplanarity_threshold(Inf));
  ISM_PARAM_CASE("coplanarity_threshold_1/3", ERROR, params::coplanarity_threshold(1. / 3));
  ISM_PARAM_CASE("coplanarity_threshold_0.3", ANY, params::coplanarity_threshold(0.3));
  ISM_PARAM_CASE("coplanarity_threshold_1e-300", ANY, params::coplanarity_threshold(1e-300));
  ISM_PARAM_CASE("empty_cell_error_-0.1", ERROR, params::empty_cell_error(-0.1));
  ISM_PARAM_CASE("empty_cell_error_nan", ERROR, params::empty_cell_error(NaN));
  ISM_PARAM_CASE("empty_cell_error_1.5", ERROR, params::empty_cell_error(1.5));
  ISM_PARAM_CASE("empty_cell_error_0", ANY, params::empty_cell_error(0.));
  ISM_PARAM_CASE("empty_cell_error_1", ANY, params::empty_cell_error(1.));
  ISM_PARAM_CASE("initial_temperature_0", ERROR, params::initial_temperature(0.));
  ISM_PARAM_CASE("initial_temperature_-1", ERROR, params::initial_temperature(-1.));
  ISM_PARAM_CASE("initial_temperature_nan", ERROR, params::initial_temperature(NaN));
  ISM_PARAM_CASE("initial_temperature_inf", ERROR, params::initial_temperature(Inf));
  ISM_PARAM_CASE("initial_temperature_1e6", ANY, params::initial_temperature(1e6));
  ISM_PARAM_CASE("initial_temperature_1e7", ERROR, params::initial_temperature(1e7));
  ISM_PARAM_CASE("initial_temperature_1e-300", ANY, params::initial_temperature(1e-300));
  ISM_PARAM_CASE("cooling_factor_0", ERROR, params::cooling_factor(0.));
  ISM_PARAM_CASE("cooling_factor_-0.5", ERROR, params::cooling_factor(-0.5));
  ISM_PARAM_CASE("cooling_factor_1", ANY, params::cooling_factor(1.));
  ISM_PARAM_CASE("cooling_factor_1.5", ERROR, params::cooling_factor(1.5));
  ISM_PARAM_CASE("cooling_factor_nan", ERROR, params::cooling_factor(NaN));
  ISM_PARAM_CASE("cooling_factor_inf", ERROR, params::cooling_factor(Inf));
  // its final temperature underflowed to 0: a failed precondition without NDEBUG
  ISM_PARAM_CASE("cooling_factor_1e-300", MESH, params::cooling_factor(1e-300));
  ISM_PARAM_CASE("number_of_sweeps_0", ERROR, params::number_of_sweeps(0));
  ISM_PARAM_CASE("number_of_sweeps_-1", ERROR, params::number_of_sweeps(-1));
  ISM_PARAM_CASE("number_of_sweeps_1", ANY, params::number_of_sweeps(1));
  ISM_SMALL_PARAM_CASE("number_of_sweeps_100000", ANY, params::number_of_sweeps(100000));
  ISM_PARAM_CASE("number_of_sweeps_100001", ERROR, params::number_of_sweeps(100001));
  ISM_PARAM_CASE("number_of_sweeps_INT_MAX", ERROR, params::number_of_sweeps(INT_MAX));
  ISM_PARAM_CASE("warm_start_interval_-2", ERROR, params::warm_start_interval(-2L));
  ISM_PARAM_CASE("warm_start_interval_-1", ANY, params::warm_start_interval(-1L));
  ISM_SMALL_PARAM_CASE("warm_start_interval_1", ANY, params::warm_start_interval(1L));
  ISM_PARAM_CASE("warm_start_interval_LONG_MAX", ANY, params::warm_start_interval(LONG_MAX));
  ISM_PARAM_CASE("crossing_neighbors_0", ANY, params::crossing_neighbors(0u));
  ISM_PARAM_CASE("crossing_neighbors_5", ERROR, params::crossing_neighbors(5u));
  ISM_PARAM_CASE("crossing_neighbors_64", ANY, params::crossing_neighbors(64u));
  ISM_PARAM_CASE("crossing_neighbors_65", ERROR, params::crossing_neighbors(65u));
  ISM_PARAM_CASE("crossing_neighbors_-1", ERROR, params::crossing_neighbors(-1));
  ISM_PARAM_CASE("smoothing_iterations_0", ANY, params::smoothing_iterations(0u));
  // the default filter peaks at 1.00085 per iteration: 112 iterations stay within 1.1
  ISM_PARAM_CASE("smoothing_iterations_112", ANY, params::smoothing_iterations(112u));
  ISM_PARAM_CASE("smoothing_iterations_113", ERROR, params::smoothing_iterations(113u));
  ISM_PARAM_CASE("smoothing_iterations_10000", ERROR, params::smoothing_iterations(10000u));
  ISM_PARAM_CASE("smoothing_iterations_10001", ERROR, params::smoothing_iterations(10001u));
  ISM_PARAM_CASE("smoothing_iterations_-1", ERROR, params::smoothing_iterations(-1));
  ISM_PARAM_CASE("smoothing_lambda_nan", ERROR, params::smoothing_lambda(NaN));
  ISM_PARAM_CASE("smoothing_lambda_2", ERROR, params::smoothing_lambda(2.));
  ISM_PARAM_CASE("smoothing_lambda_inf", ERROR, params::smoothing_lambda(Inf));
  ISM_PARAM_CASE("smoothing_lambda_-1", ANY, params::smoothing_lambda(-1.));
  ISM_PARAM_CASE("smoothing_mu_nan", ERROR, params::smoothing_mu(NaN));
  ISM_PARAM_CASE("smoothing_mu_-2", ERROR, params::smoothing_mu(-2.));
  ISM_PARAM_CASE("smoothing_mu_1", ANY, params::smoothing_mu(1.));
  // Laplacian steps without the inflating one, or with the sign of mu mistyped, shrink
  ISM_PARAM_CASE("smoothing_shrinking_1_1_x10000", ERROR,
                 params::smoothing_lambda(1., params::smoothing_mu(1., params::smoothing_iterations(10000u))));
  ISM_PARAM_CASE("smoothing_shrinking_0.5_0.53_x3", ERROR,
                 params::smoothing_mu(0.53, params::smoothing_iterations(3u)));
  ISM_PARAM_CASE("smoothing_shrinking_0.5_0_x3", ERROR,
                 params::smoothing_mu(0., params::smoothing_iterations(3u)));
  ISM_PARAM_CASE("smoothing_unstable_1_-1_x10000", ERROR,
                 params::smoothing_lambda(1., params::smoothing_mu(-1., params::smoothing_iterations(10000u))));
  ISM_PARAM_CASE("box_margin_0", ERROR, params::box_margin(0.));
  ISM_PARAM_CASE("box_margin_-1", ERROR, params::box_margin(-1.));
  ISM_PARAM_CASE("box_margin_nan", ERROR, params::box_margin(NaN));
  ISM_PARAM_CASE("box_margin_inf", ERROR, params::box_margin(Inf));
  ISM_PARAM_CASE("box_margin_10", ANY, params::box_margin(10.));
  ISM_PARAM_CASE("box_margin_11", ERROR, params::box_margin(11.));
  ISM_PARAM_CASE("box_margin_1e-300", ANY, params::box_margin(1e-300));
  ISM_PARAM_CASE("surface_refinement_passes_-1", ERROR, params::surface_refinement_passes(-1));
  ISM_PARAM_CASE("surface_refinement_passes_11", ERROR, params::surface_refinement_passes(11));
  ISM_PARAM_CASE("surface_refinement_passes_10", ANY, params::surface_refinement_passes(10));
  ISM_PARAM_CASE("escape_rays_-1", ERROR, params::escape_rays(-1));
  ISM_PARAM_CASE("escape_rays_65", ERROR, params::escape_rays(65));
  ISM_PARAM_CASE("escape_rays_1", ANY, params::escape_rays(1));
  ISM_PARAM_CASE("escape_rays_64", ANY, params::escape_rays(64));
  ISM_PARAM_CASE("winding_number_signs_false", ANY, params::winding_number_signs(false));
  ISM_PARAM_CASE("winding_number_signs_without_tangent_planes", ANY,
                 params::winding_number_signs(true, params::tangent_plane_signs(false, params::escape_rays(0))));
  ISM_PARAM_CASE("surface_refinement_tolerance_0", ERROR, params::surface_refinement_tolerance(0.));
  ISM_PARAM_CASE("surface_refinement_tolerance_nan", ERROR, params::surface_refinement_tolerance(NaN));
  ISM_PARAM_CASE("point_smoothing_iterations_-1", ERROR, params::point_smoothing_iterations(-1));
  ISM_PARAM_CASE("point_smoothing_neighbors_3", ERROR, params::point_smoothing_neighbors(3));
  ISM_PARAM_CASE("point_smoothing_noise_nan", ERROR, params::point_smoothing_noise(NaN));
  // smoothing forced on clean points, with the fewest neighbours
  ISM_PARAM_CASE("point_smoothing_always", MESH,
                 params::point_smoothing_noise(0., params::point_smoothing_neighbors(6)));
  ISM_PARAM_CASE("surface_refinement_tolerance_1e-9", ANY,
                 params::surface_refinement_tolerance(1e-9, params::surface_refinement_passes(3)));
  ISM_PARAM_CASE("random_seed_0", ANY, params::random_seed(0));
  ISM_PARAM_CASE("random_seed_max", ANY, params::random_seed(std::uint64_t(-1)));
  ISM_PARAM_CASE("distance_nearest_point_squared", ANY, params::distance_estimate(ISM::NEAREST_POINT_SQUARED_DISTANCE));
  ISM_PARAM_CASE("distance_nearest_point", ANY, params::distance_estimate(ISM::NEAREST_POINT_DISTANCE));
  ISM_PARAM_CASE("distance_local_plane", ANY, params::distance_estimate(ISM::LOCAL_PLANE_DISTANCE));
  // 3 is not an enumerator but is a valid value of the enum (its range is 0..3); 7 would be UB.
  // It ran as some estimate, unnamed (an independent black-box run, session 41)
  ISM_PARAM_CASE("distance_estimate_unnamed_value_3", ERROR, params::distance_estimate(static_cast<ISM::Distance_estimate>(3)));
  // integer parameters given as other types: a NaN (undefined to convert), a fraction, a
  // value that wrapped to a valid one (4294967320 -> 24, 4294967302 -> 6) are refused
  ISM_PARAM_CASE("maximum_depth_nan", ERROR, params::maximum_depth(NaN));
  ISM_PARAM_CASE("maximum_depth_2.7", ERROR, params::maximum_depth(2.7));
  ISM_PARAM_CASE("maximum_depth_12.0", MESH, params::maximum_depth(12.0));
  ISM_PARAM_CASE("maximum_depth_2^32+24", ERROR, params::maximum_depth(4294967320LL));
  ISM_PARAM_CASE("crossing_neighbors_2^32+6", ERROR, params::crossing_neighbors(4294967302LL));
  ISM_PARAM_CASE("number_of_sweeps_1e300", ERROR, params::number_of_sweeps(1e300));
  ISM_PARAM_CASE("random_seed_-1", ERROR, params::random_seed(-1));
  ISM_PARAM_CASE("paper_settings", ANY, params::paper_settings(true));
  ISM_PARAM_CASE("paper_settings_depth_0", ERROR, params::paper_settings(true, params::maximum_depth(0)));
  ISM_PARAM_CASE("clamp_box_boundary_false", ANY, params::clamp_box_boundary(false));
  ISM_PARAM_CASE("all_nan", ERROR,
                 params::coplanarity_threshold(NaN, params::empty_cell_error(NaN, params::initial_temperature(
                     NaN, params::cooling_factor(NaN, params::smoothing_lambda(NaN, params::smoothing_mu(NaN, params::box_margin(NaN))))))));
  ISM_PARAM_CASE("depth_1_min_points_3_sweeps_1", ANY,
                 params::maximum_depth(1, params::number_of_sweeps(1, params::min_points_per_cell(3))));
  // a double where an int is expected: converted by the package (NaN -> int is undefined;
  // x86 gives INT_MIN, so the range check refuses it)
  ISM_PARAM_CASE("maximum_depth_double_1e300", ANY, params::maximum_depth(1e300));
  ISM_PARAM_CASE("callback_cancels_at_once", CANCEL, params::callback(std::function<bool(double)>([](double) { return false; })));
  ISM_PARAM_CASE("callback_cancels_at_0.8", CANCEL,
                 params::callback(std::function<bool(double)>([](double p) { return p < 0.8; })));
  ISM_PARAM_CASE("callback_throws", ERROR, params::callback(std::function<bool(double)>([](double) -> bool {
                   throw std::runtime_error("callback threw");
                 })));
  ISM_PARAM_CASE("callback_nan_progress_check", ANY, params::callback(std::function<bool(double)>([](double p) {
                   if(!(p >= 0 && p <= 1)) throw std::logic_error("progress out of [0,1]");
                   return true;
                 })));
#undef ISM_PARAM_CASE
#undef ISM_SMALL_PARAM_CASE
  return cases;
}

// ---------------------------------------------------------------------------------------
// 2. Noise, outliers, non-uniform sampling on the bunny
// ---------------------------------------------------------------------------------------

Result bunny_quality(const std::string& which)
{
  Mesh truth;
  if(!read_mesh(g_meshes_dir + "/bunny00.off", truth)) return Result{CHECK_FAILED, "cannot read bunny00.off"};
  const CGAL::Bbox_3 b = bbox(truth);
  const double diag = diagonal(b);
  std::vector<Point_3> pts;
  std::ostringstream in;
  // ISM_ROBUSTNESS_SEED: another sampling of the same case (1 in CTest), to measure how often the bar is met
  const char* seed_env = std::getenv("ISM_ROBUSTNESS_SEED");
  const unsigned seed = seed_env ? unsigned(std::strtoul(seed_env, nullptr, 10)) : 1u;
  if(seed != 1) in << "sampling seed " << seed << "; ";
  if(which == "noise_clean") pts = mesh_points(truth, 36000, seed);
  else if(which == "noise_gauss_0.25") pts = mesh_points(truth, 36000, seed, 0.0025 * diag);
  else if(which == "noise_gauss_0.5") pts = mesh_points(truth, 36000, seed, 0.005 * diag);
  else if(which == "outliers_1")
  {
    pts = mesh_points(truth, 36000, seed);
    const CGAL::Bbox_3 ob = scaled_bbox(b, 1.1);
    Rng rng(seed + 1);
    for(int i = 0; i < 360; ++i)
      pts.push_back(rng.uniform_point(ob));
    in << "36000 surface points + 360 uniform outliers in the bbox scaled by 1.1; ";
  }
  else if(which == "outliers_far")
  {
    // a scanner's stray returns: sparse, and far. The winding number once counted them as a
    // surface around the bunny and the output was their hull (1 of 3 samplings of 360)
    pts = mesh_points(truth, 36000, seed);
    Rng rng(seed + 1);
    const double c[3] = { 0.5 * (b.xmin() + b.xmax()), 0.5 * (b.ymin() + b.ymax()), 0.5 * (b.zmin() + b.zmax()) };
    for(int i = 0; i < 360; ++i)
    {
      double u[3] = { rng.gaussian(), rng.gaussian(), rng.gaussian() };
      const double r = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
      const double at = rng.uniform(1, 2) * diag / (r > 0 ? r : 1);
      pts.push_back(Point_3(c[0] + at * u[0], c[1] + at * u[1], c[2] + at * u[2]));
    }
    in << "36000 surface points + 360 outliers 1 to 2 diagonals from the bbox centre; ";
  }
  else if(which == "nonuniform" || which == "nonuniform_dense")
  {
    // one half of the surface (by area: x above the samples' median) 10 times denser.
    // nonuniform: 36000 points in all, 32727 on the dense half, 3273 on the other (5.5 times
    // sparser than the 36k bunny); nonuniform_dense: the 36k bunny's density on the sparse
    // half (18000 points), 10 times that on the other (180000)
    std::size_t dense = 0;
    for(const auto& s : thin_one_half(sample_points(truth, which == "nonuniform" ? 65454 : 360000, seed), 10, &dense))
      pts.push_back(s.first);
    in << dense << " points on x > median, " << pts.size() - dense << " on the other half; ";
  }
  else return Result{CHECK_FAILED, "unknown case " + which};

  Mesh m;
  const auto start = std::chrono::steady_clock::now();
  Result r = reconstruct(pts, params::default_values(), &m);
  // ISM_ROBUSTNESS_DUMP=dir keeps the points and the output, to trace a miss with the tool
  if(const char* dump = std::getenv("ISM_ROBUSTNESS_DUMP"))
  {
    const std::string base = std::string(dump) + "/" + which + "_" + std::to_string(seed);
    std::ofstream xyz(base + ".xyz");
    xyz << std::setprecision(17);
    for(const Point_3& p : pts) xyz << p << "\n";
    if(r.kind == MESH_OK) CGAL::IO::write_OFF(base + ".off", m, params::stream_precision(17));
  }
  const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if(r.kind != MESH_OK)
  {
    r.detail = in.str() + r.detail;
    return r;
  }
  const Topology tp = topology(m);
  // queries in the bbox scaled by 1.1; "far" = farther than 1 % of the bunny's diagonal
  const CGAL::Bbox_3 qb = scaled_bbox(b, 1.1);
  const double far_fraction = 0.01 * diag / diagonal(qb);
  const Inout_score s = inout_accuracy(truth, qb, inside_oracle(m), 50000, far_fraction, 5);
  const Distance_score d = symmetric_distance(truth, m, 20000, 6);
  std::ostringstream os;
  os << in.str() << pts.size() << " points, " << std::fixed << std::setprecision(2) << t << " s; " << std::defaultfloat
     << "V=" << m.number_of_vertices() << " F=" << m.number_of_faces() << " components=" << tp.components
     << " genus=" << tp.genus << " closed=" << tp.closed << " manifold=" << tp.manifold << "; in/out far (>1% diag) "
     << std::setprecision(6) << 100 * s.far << "% of " << s.n_far << ", all " << 100 * s.overall << "% of " << s.n
     << "; distance mean " << d.mean / diag << " max " << d.max / diag << " (x diag)";
  std::string failed;
  if(!tp.closed) failed += " not closed;";
  if(!tp.manifold) failed += " not 2-manifold;";
  if(tp.components != 1) failed += " " + std::to_string(tp.components) + " components (want 1);";
  if(tp.genus != 0) failed += " genus " + std::to_string(tp.genus) + " (want 0);";
  if(s.far < 1.0) failed += " in/out far " + std::to_string(s.n_far - std::size_t(std::llround(s.far * s.n_far))) + " wrong (want 0);";
  r.detail = os.str() + (failed.empty() ? "" : "; FAILED:" + failed);
  r.kind = failed.empty() ? MESH_OK : CHECK_FAILED;
  return r;
}

int run_quality(const std::string& which)
{
  Case c;
  c.group = "quality";
  c.name = which;
  c.expect = MESH;
  c.time_limit = 300;
  c.run = [which] { return bunny_quality(which); };
  return run_cases("noise/outliers/non-uniform: " + which, {c}, "");
}

// ---------------------------------------------------------------------------------------
// 3. Determinism
// ---------------------------------------------------------------------------------------

Result write_reconstruction(const std::string& file, int threads, const std::string& input)
{
#ifdef CGAL_LINKED_WITH_TBB
  tbb::global_control gc(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
#else
  (void)threads;
#endif
  Mesh truth;
  std::vector<Point_3> pts;
  if(input == "bunny_noise")
  {
    if(!read_mesh(g_meshes_dir + "/bunny00.off", truth)) return Result{CHECK_FAILED, "cannot read bunny00.off"};
    pts = mesh_points(truth, 36000, 3, 0.0025 * diagonal(bbox(truth)));
  }
  else
    pts = mesh_points(shape("torus"), 20000, 4);
  Mesh m;
  Result r = reconstruct(pts, params::random_seed(12345), &m);
  if(r.kind != MESH_OK) return r;
  std::ofstream os(file, std::ios::binary);
  if(!CGAL::IO::write_OFF(os, m, params::stream_precision(17)))
    return Result{CHECK_FAILED, "cannot write " + file};
  return r;
}

std::string file_bytes(const std::string& f)
{
  std::ifstream is(f, std::ios::binary);
  std::ostringstream os;
  os << is.rdbuf();
  return os.str();
}

int run_determinism()
{
  int failures = 0;
#ifdef CGAL_LINKED_WITH_TBB
  std::cout << "TBB: runs with 1, 1 and 2 threads\n";
#else
  std::cout << "no TBB: the thread-count comparison is the same single-threaded code\n";
#endif
  for(const std::string input : {"bunny_noise", "torus"})
  {
    std::vector<Case> cases;
    const int threads[] = {1, 1, 2};
    std::vector<std::string> files;
    for(int i = 0; i < 3; ++i)
    {
      Case c;
      c.group = "determinism";
      c.name = input + "_run" + std::to_string(i + 1) + "_threads" + std::to_string(threads[i]);
      c.expect = MESH;
      c.time_limit = 300;
      const std::string f = tmp_file(c.name + ".off");
      std::remove(f.c_str());
      files.push_back(f);
      const int t = threads[i];
      c.run = [f, t, input] { return write_reconstruction(f, t, input); };
      cases.push_back(c);
    }
    failures += run_cases("determinism: " + input, cases, "");
    const std::string a = file_bytes(files[0]), b = file_bytes(files[1]), c = file_bytes(files[2]);
    const bool same_runs = !a.empty() && a == b, same_threads = !a.empty() && a == c;
    std::cout << (same_runs ? "ok      " : "FAILURE ") << input << ": run 1 and run 2 (1 thread) "
              << (same_runs ? "byte-identical" : "DIFFER") << " (" << a.size() << " and " << b.size() << " bytes)\n";
    std::cout << (same_threads ? "ok      " : "FAILURE ") << input << ": 1 thread and 2 threads "
              << (same_threads ? "byte-identical" : "DIFFER") << " (" << a.size() << " and " << c.size() << " bytes)\n\n";
    failures += !same_runs + !same_threads;
  }
  return failures;
}

// ---------------------------------------------------------------------------------------
// 4. Memory
// ---------------------------------------------------------------------------------------

// A clear refusal: an exception that is not bad_alloc, with a message. A mesh is fine too
// if the run stayed within the budget (the test's RLIMIT_AS enforces that).
int run_memory()
{
  const std::size_t budget_mb = 2048;
  std::cout << "memory budget of each child: RLIMIT_AS = " << budget_mb << " MB";
#ifdef ISM_UNDER_ASAN
  std::cout << " (NOT set under AddressSanitizer; only the parent's resident-size cap applies)";
#endif
  std::cout << "; physical memory " << (double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE)) / (1024. * 1024.)) << " MB\n";
  std::vector<Case> cases;
  auto add = [&](const std::string& name, Expect e, int time_limit, std::function<Result()> f) {
    Case c;
    c.group = "memory";
    c.name = name;
    c.expect = e;
    c.time_limit = time_limit;
    c.address_space_mb = budget_mb;
    c.rss_cap_mb = budget_mb + 512;
    c.run = std::move(f);
    cases.push_back(std::move(c));
  };
  // 100k distinct points, each 6 times (= min_points_per_cell): every cluster kept its
  // cells subdivisible down to maximum_depth (> 12 GB after 10 min) until exact duplicates
  // were removed on input.
  add("sphere100k_x6_depth48", ANY, 240,
      [] { return reconstruct(repeat(sphere_points(100000, 201), 6), params::maximum_depth(48)); });
  // the same with the copies jittered by 1e-12 (distinct, so not removed as duplicates):
  // the clusters still refine down to maximum_depth
  add("sphere100k_x6_jitter1e-12_depth48", ANY, 240, [] {
    Rng rng(205);
    std::vector<Point_3> v;
    for(const Point_3& p : repeat(sphere_points(100000, 201), 6))
      v.emplace_back(p.x() + 1e-12 * rng.gaussian(), p.y() + 1e-12 * rng.gaussian(), p.z() + 1e-12 * rng.gaussian());
    return reconstruct(v, params::maximum_depth(48));
  });
  // the issue's example: 10M distinct points at depth 48 (about 49M cells, 7 GB by a
  // 1M-point measurement: 4.9M cells, 660 MB, deepest level 30)
  add("sphere10M_depth48", ANY, 240, [] { return reconstruct(sphere_points(10000000, 202), params::maximum_depth(48)); });
  // the guard must not refuse what fits: the bunny at depth 48 within the same budget
  add("bunny36k_depth48_fits", MESH, 240,
      [] { return reconstruct(mesh_points(shape("bunny00"), 36000, 203), params::maximum_depth(48)); });
  return run_cases("memory", cases, "");
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 4)
  {
    std::cerr << "usage: " << argv[0] << " <meshes dir> <scratch dir> <section> [case filter]\n"
              << "sections: corpus noise_clean noise_gauss_0.25 noise_gauss_0.5 outliers_1 outliers_far nonuniform nonuniform_dense determinism memory all\n";
    return 2;
  }
  g_meshes_dir = argv[1];
  g_tmp_dir = argv[2];
  const std::string section = argv[3];
  const std::string filter = argc > 4 ? argv[4] : "";
  {
    // mkdir -p
    std::string path;
    std::istringstream is(g_tmp_dir);
    std::string part;
    if(!g_tmp_dir.empty() && g_tmp_dir[0] == '/') path = "/";
    while(std::getline(is, part, '/'))
    {
      if(part.empty()) continue;
      path += part + "/";
      mkdir(path.c_str(), 0755);
    }
  }
  std::cout << "time limits scaled by " << time_scale() << std::endl;
  int failures = 0;
  const bool all = section == "all";
  if(all || section == "corpus")
  {
    const std::vector<Case> cases = corpus_cases();
    std::cout << "corpus: " << cases.size() << " cases" << std::endl;
    failures += run_cases("corpus", cases, filter);
  }
  for(const char* q : {"noise_clean", "noise_gauss_0.25", "noise_gauss_0.5", "outliers_1", "outliers_far", "nonuniform",
                       "nonuniform_dense"})
    if(all || section == q) failures += run_quality(q);
  if(all || section == "determinism") failures += run_determinism();
  if(all || section == "memory") failures += run_memory();
  std::cout << (failures ? "FAILED: " : "passed: ") << failures << " failure(s) in section " << section << std::endl;
  return failures ? 1 : 0;
}
