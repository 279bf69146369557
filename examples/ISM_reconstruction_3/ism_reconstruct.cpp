// ism_reconstruct: reconstructs a closed surface from points without normals with
// ISM_reconstruction_3 (the in/out function of points on a binary multitriangulation).
//
//   ism_reconstruct [options] INPUT OUTPUT
//
// INPUT: .xyz/.pwn, .ply, .off (a mesh file's vertices are the points), .las when CGAL is
// linked with LASlib. OUTPUT: .off, .ply, .obj or .stl. `--tets FILE` also writes the leaves of
// the triangulation (.vtu or .mesh) with the per-vertex fields "sign" and "distance".
// read_point_file.h reads and checks the input, naming the line of what is wrong.
// `--help` lists every parameter with its default.
//
// Exit codes: 0 success; 1 bad input (missing, empty, unreadable or malformed file, points
// that cannot bound a volume, no inside found) or an output that cannot be written;
// 2 usage error (unknown option, missing or malformed value, parameter out of range).
// A summary that cannot be written to stdout also exits 1. Warnings (a file holding more
// records than its header announces, far outliers) go to stderr, also with --quiet.
// Outputs are written to temporary files beside them and renamed at the end, so a failed
// or interrupted run leaves no (half-written) output file.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>

#include <CGAL/ism_surface_reconstruction.h>
#include <CGAL/ISM_reconstruction_function.h>
#include <CGAL/ISM_reconstruction_3/IO/tet_mesh_io.h>
#include <CGAL/ISM_reconstruction_3/internal/huge_pages.h>

#include "read_point_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::ISM_reconstruction_function<Kernel> Function;
typedef CGAL::ISM_reconstruction_3::Settings Settings;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

enum Exit_code { SUCCESS = 0, BAD_INPUT = 1, USAGE_ERROR = 2 };

// An error with the exit code it leads to.
struct Failure
{
  int code;
  std::string message;
};

[[noreturn]] void usage_error(const std::string& message) { throw Failure{USAGE_ERROR, message}; }
[[noreturn]] void input_error(const std::string& message) { throw Failure{BAD_INPUT, message}; }

std::string format_double(double v)
{
  std::ostringstream os;
  os << v;
  return os.str();
}

// ---------------------------------------------------------------------------------------
// Temporary output files: removed at exit or on a signal that ends the run (SIGINT, SIGTERM,
// SIGHUP when the terminal closes, SIGQUIT, SIGPIPE) unless renamed into place.
// ---------------------------------------------------------------------------------------

const int max_temporaries = 4;
char g_temporaries[max_temporaries][4096];
volatile std::sig_atomic_t g_number_of_temporaries = 0;

void remove_temporaries()
{
  for(int i = 0; i < g_number_of_temporaries; ++i)
    if(g_temporaries[i][0] != '\0') ::unlink(g_temporaries[i]);
  g_number_of_temporaries = 0;
}

extern "C" void on_signal(int sig)
{
  for(int i = 0; i < g_number_of_temporaries; ++i)  // unlink is async-signal-safe
    if(g_temporaries[i][0] != '\0') ::unlink(g_temporaries[i]);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

// `dir/name.ext` -> `dir/.name.tmp<pid>.ext` (same directory, so that rename is atomic;
// same extension, so that the writers choose the same format). `name` is cut so that the
// temporary's name stays within the 255 bytes a file name may have: a legal output name of
// 250 bytes failed ("File name too long").
std::string temporary_name(const std::string& path, const std::string& ext)
{
  const std::size_t slash = path.find_last_of('/');
  const std::string dir = (slash == std::string::npos) ? "" : path.substr(0, slash + 1);
  std::string name = (slash == std::string::npos) ? path : path.substr(slash + 1);
  name = name.substr(0, name.size() - ext.size() - 1);
  const std::string tail = ".tmp" + std::to_string(::getpid()) + "." + ext;
  const std::size_t room = 255 - 1 - tail.size();  // 1 for the leading '.'
  if(name.size() > room)
  {
    std::size_t size = room;
    while(size > 0 && (static_cast<unsigned char>(name[size]) & 0xC0) == 0x80) --size;  // not inside a UTF-8 character
    name.resize(size);
  }
  return dir + "." + name + tail;
}

void register_temporary(const std::string& path)
{
  if(g_number_of_temporaries >= max_temporaries || path.size() >= sizeof(g_temporaries[0]))
    throw Failure{BAD_INPUT, "internal error: too many temporary files"};
  std::strcpy(g_temporaries[g_number_of_temporaries], path.c_str());
  g_number_of_temporaries = g_number_of_temporaries + 1;
}

// An output that cannot be renamed into place (a directory of that name, a name too long)
// is reported before the reconstruction runs rather than after. lstat, as rename replaces
// a symbolic link rather than what it points to. An output that is the input would replace
// the points by the surface: refused too (it had been done without a word).
void check_output_name(const std::string& final_name, const std::string& input)
{
  struct stat st, in;
  if(::lstat(final_name.c_str(), &st) == 0)
  {
    if(S_ISDIR(st.st_mode)) input_error("cannot write '" + final_name + "': it is a directory");
    if(::lstat(input.c_str(), &in) == 0 && st.st_dev == in.st_dev && st.st_ino == in.st_ino)
      input_error("cannot write '" + final_name + "': it is the input file");
  }
  else if(errno != ENOENT)
    input_error("cannot write '" + final_name + "': " + std::strerror(errno));
}

// the .sol file of the fields beside `name`.mesh
std::string sol_name(const std::string& mesh_name) { return mesh_name.substr(0, mesh_name.size() - 4) + "sol"; }

// Creates (empty) the temporary file, so that an unwritable directory is reported before
// the reconstruction runs rather than after.
void create_temporary(const std::string& temporary, const std::string& final_name, const std::string& input)
{
  check_output_name(final_name, input);
  register_temporary(temporary);
  std::ofstream os(temporary);
  if(!os)
    input_error("cannot write '" + final_name + "': " + std::strerror(errno));
}

// CGAL's OFF writer formats every coordinate through an ostream at precision 17: on the
// dragon's 261k output vertices that took 1.1 s of a 10 s run. std::to_chars writes the
// shortest decimal that reads back to the same double, so the file is as exact and written
// in 0.13-0.19 s; .ply, .obj and .stl keep CGAL's writers.
bool write_off(const std::string& file, const Mesh& mesh)
{
  std::ofstream os(file, std::ios::binary);
  if(!os) return false;
  std::vector<std::uint32_t> index(mesh.number_of_vertices() + mesh.number_of_removed_vertices(), 0);
  std::string buffer = "OFF\n" + std::to_string(mesh.number_of_vertices()) + " " +
                       std::to_string(mesh.number_of_faces()) + " 0\n";
  buffer.reserve(1 << 20);
  char number[64];
  std::uint32_t next = 0;
  auto flush = [&]() {
    os.write(buffer.data(), std::streamsize(buffer.size()));
    buffer.clear();
  };
  auto flush_if_full = [&]() { if(buffer.size() > (1 << 20) - 256) flush(); };
  auto append = [&](auto x) {
    const std::to_chars_result r = std::to_chars(number, number + sizeof(number), x);
    buffer.append(number, r.ptr);
  };
  for(Mesh::Vertex_index v : mesh.vertices())
  {
    index[v] = next++;
    const Point& p = mesh.point(v);
    for(int d = 0; d < 3; ++d)
    {
      append(CGAL::to_double(p[d]));
      buffer.push_back(d < 2 ? ' ' : '\n');
    }
    flush_if_full();
  }
  for(Mesh::Face_index f : mesh.faces())
  {
    append(std::size_t(CGAL::degree(f, mesh)));
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    {
      buffer.push_back(' ');
      append(index[v]);
    }
    buffer.push_back('\n');
    flush_if_full();
  }
  flush();
  return bool(os.flush());
}

void rename_into_place(const std::string& temporary, const std::string& final_name)
{
  if(std::rename(temporary.c_str(), final_name.c_str()) != 0)
    input_error("cannot write '" + final_name + "': " + std::strerror(errno));
}

// Output lost on a full disk or a closed stdout must not pass for success (`> /dev/full`
// exited 0).
void write_stdout(const std::string& text, const std::string& what, const std::string& note = "")
{
  errno = 0;
  if(!(std::cout << text << std::flush))
    input_error("cannot write " + what + " to stdout" + (errno != 0 ? std::string(": ") + std::strerror(errno) : std::string()) + note);
}

// ---------------------------------------------------------------------------------------
// Options: one table drives parsing, --help (defaults read from Settings) and the names
// in range errors, so that none of them can drift from the library.
// ---------------------------------------------------------------------------------------

const char* distance_name(CGAL::ISM_reconstruction_3::Distance_estimate d)
{
  switch(d)
  {
  case CGAL::ISM_reconstruction_3::NEAREST_POINT_SQUARED_DISTANCE: return "nearest-squared";
  case CGAL::ISM_reconstruction_3::NEAREST_POINT_DISTANCE: return "nearest";
  default: return "plane";
  }
}

template <class Integer>
Integer parse_integer(const std::string& flag, const std::string& value)
{
  const char* s = value.c_str();
  char* end = nullptr;
  errno = 0;
  if constexpr(std::is_unsigned<Integer>::value)
  {
    if(value.find('-') != std::string::npos)
      usage_error(flag + ": '" + value + "' is out of range (it must not be negative)");
    const unsigned long long v = std::strtoull(s, &end, 10);
    if(end == s || *end != '\0') usage_error(flag + ": '" + value + "' is not an integer");
    if(errno == ERANGE || v > (std::numeric_limits<Integer>::max)())
      usage_error(flag + ": '" + value + "' is out of range");
    return Integer(v);
  }
  else
  {
    const long long v = std::strtoll(s, &end, 10);
    if(end == s || *end != '\0') usage_error(flag + ": '" + value + "' is not an integer");
    if(errno == ERANGE || v > (std::numeric_limits<Integer>::max)() || v < (std::numeric_limits<Integer>::min)())
      usage_error(flag + ": '" + value + "' is out of range");
    return Integer(v);
  }
}

double parse_real(const std::string& flag, const std::string& value)
{
  const char* s = value.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s, &end);
  if(end == s || *end != '\0') usage_error(flag + ": '" + value + "' is not a number");
  // ERANGE on underflow comes with a tiny value (1e-308) or 0, which Settings::check() judges
  // like any other; on overflow with HUGE_VAL
  if(!std::isfinite(v) || (errno == ERANGE && std::fabs(v) > 1)) usage_error(flag + ": '" + value + "' is out of range");
  return v;
}

struct Option
{
  const char* flag;
  const char* field;     // the Settings member, as named in Settings::check() messages
  const char* argument;  // nullptr for a switch
  const char* help;
  std::function<void(Settings&, const std::string& flag, const std::string& value)> set;
  std::function<std::string(const Settings&)> show;
};

#define ISM_INTEGER_OPTION(FLAG, FIELD, HELP)                                                        \
  Option{FLAG, #FIELD, "N", HELP,                                                                  \
         [](Settings& s, const std::string& f, const std::string& v) {                             \
           s.FIELD = parse_integer<decltype(s.FIELD)>(f, v);                                       \
         },                                                                                        \
         [](const Settings& s) { return std::to_string(s.FIELD); }}
#define ISM_REAL_OPTION(FLAG, FIELD, HELP)                                                           \
  Option{FLAG, #FIELD, "X", HELP,                                                                  \
         [](Settings& s, const std::string& f, const std::string& v) { s.FIELD = parse_real(f, v); }, \
         [](const Settings& s) { return format_double(s.FIELD); }}

const std::vector<Option>& options()
{
  static const std::vector<Option> table = {
    ISM_INTEGER_OPTION("--maximum-depth", maximum_depth,
                       "deepest level of a cell of the triangulation (the paper's maximum level; "
                       "far outliers and parts far apart add 3 levels per doubling of the points' extent over "
                       "that of their bulk, up to 48)"),
    ISM_INTEGER_OPTION("--min-points-per-cell", min_points_per_cell,
                       "a cell is fitted and subdivided only with at least this many points"),
    Option{"--inherit-sparse-cell-planes", "sparse_cell_planes", nullptr,
           "a cell with fewer than --min-points-per-cell points inherits its parent's plane (the "
           "paper) instead of taking the plane of that many points nearest its own",
           [](Settings& s, const std::string&, const std::string&) { s.sparse_cell_planes = false; },
           [](const Settings& s) { return std::string(s.sparse_cell_planes ? "off" : "on"); }},
    ISM_INTEGER_OPTION("--coarser-refinements", coarser_refinements,
                       "if the in/out signs see (almost) no inside and the later steps make it in pieces "
                       "(too few points for the leaves), compute again with twice --min-points-per-cell, "
                       "up to this many times; 0: never"),
    ISM_REAL_OPTION("--coplanarity-threshold", coplanarity_threshold,
                    "a cell whose coplanarity error l0/(l0+l1+l2) is below this is not subdivided"),
    ISM_REAL_OPTION("--empty-cell-error", empty_cell_error,
                    "error given to empty cells (eps_empty), as a fraction of [eps_min, eps_max]"),
    ISM_REAL_OPTION("--initial-temperature", initial_temperature,
                    "annealing start temperature, in units of the mean |H_e|"),
    ISM_REAL_OPTION("--warm-start-temperature", warm_start_temperature,
                    "annealing start temperature when starting from the previous signs (passes during "
                    "refinement and the final one after them), in units of the mean |H_e|"),
    ISM_REAL_OPTION("--cooling-factor", cooling_factor, "temperature ratio between two annealing sweeps"),
    ISM_INTEGER_OPTION("--sweeps", number_of_sweeps, "sweeps of the final annealing"),
    ISM_INTEGER_OPTION("--warm-start-interval", warm_start_interval,
                       "bisections between topology passes during refinement; 0: whenever the number "
                       "of leaves doubled; -1: none (the final annealing alone, from scratch: a sphere of 3000 "
                       "points came out in 29 parts)"),
    ISM_INTEGER_OPTION("--seed", random_seed, "random seed of the annealing (a run is deterministic)"),
    ISM_INTEGER_OPTION("--crossing-neighbors", crossing_neighbors,
                       "each surface vertex moves along its leaf edge onto the quadric fitted to this "
                       "many nearest points (6-64); 0: the linear zero crossing of F"),
    ISM_INTEGER_OPTION("--smoothing-iterations", smoothing_iterations,
                       "Taubin lambda/mu iterations on the output surface (0: none)"),
    ISM_REAL_OPTION("--smoothing-lambda", smoothing_lambda, "Taubin smoothing factor lambda"),
    ISM_REAL_OPTION("--smoothing-mu", smoothing_mu, "Taubin inflation factor mu"),
    Option{"--no-clamp", "clamp_box_boundary", nullptr,
           "do not hold the box boundary vertices outside while annealing (fix the global sign afterwards)",
           [](Settings& s, const std::string&, const std::string&) { s.clamp_box_boundary = false; },
           [](const Settings& s) { return std::string(s.clamp_box_boundary ? "clamped" : "not clamped"); }},
    Option{"--distance", "distance_estimate", "nearest-squared|nearest|plane",
           "value at a vertex: squared distance to the nearest point (the paper), distance to it, or "
           "distance to the plane fitted to the nearest points",
           [](Settings& s, const std::string& f, const std::string& v) {
             if(v == "nearest-squared") s.distance_estimate = CGAL::ISM_reconstruction_3::NEAREST_POINT_SQUARED_DISTANCE;
             else if(v == "nearest") s.distance_estimate = CGAL::ISM_reconstruction_3::NEAREST_POINT_DISTANCE;
             else if(v == "plane") s.distance_estimate = CGAL::ISM_reconstruction_3::LOCAL_PLANE_DISTANCE;
             else usage_error(f + ": '" + v + "' is not one of nearest-squared, nearest, plane");
           },
           [](const Settings& s) { return std::string(distance_name(s.distance_estimate)); }},
    ISM_REAL_OPTION("--box-margin", box_margin,
                    "margin of the box around the points, as a fraction of their largest extent"),
    ISM_REAL_OPTION("--minimum-island-fraction", minimum_island_fraction,
                    "inside (or enclosed outside) clusters of fewer vertices than this fraction of the "
                    "largest inside cluster are flipped; 0: keep all"),
    ISM_REAL_OPTION("--thin-handle-depth", thin_handle_depth,
                    "a handle held open only by vertices nearer to the surface than this many times the "
                    "size of the leaves it crosses (the median, or the local one where larger) is removed (tunnel filled, else bridge cut); "
                    "0: keep all"),
    Option{"--no-tangent-planes", "tangent_plane_signs", nullptr,
           "keep the Ising sign of every vertex (the paper) instead of giving the vertices near the "
           "points the side of their tangent planes, oriented by the in/out function",
           [](Settings& s, const std::string&, const std::string&) { s.tangent_plane_signs = false; },
           [](const Settings& s) { return std::string(s.tangent_plane_signs ? "tangent planes" : "Ising signs"); }},
    ISM_INTEGER_OPTION("--surface-refinement-passes", surface_refinement_passes,
                       "after the signs, bisect the leaves in which the function misses a point by more "
                       "than --surface-refinement-tolerance times their longest edge (and the noise), up "
                       "to this many times, then as many times those larger than 1.5 times the median "
                       "(sparser parts); 0: none"),
    ISM_REAL_OPTION("--surface-refinement-tolerance", surface_refinement_tolerance,
                    "miss of the function at a point, relative to its leaf's longest edge, above which "
                    "the leaf is bisected"),
    ISM_INTEGER_OPTION("--escape-rays", escape_rays,
                       "turn outside an inside vertex of the surface's leaves away from the points if "
                       "this many rays from it, pointing away from its nearest point, all leave the box "
                       "without meeting a point; 0: never"),
    Option{"--no-winding-number", "winding_number_signs", nullptr,
           "do not re-sign, last, the vertices of the surface's leaves away from the points by the "
           "winding number of the points (their normals oriented by the in/out function)",
           [](Settings& s, const std::string&, const std::string&) { s.winding_number_signs = false; },
           [](const Settings& s) { return std::string(s.winding_number_signs ? "on" : "off"); }},
    Option{"--no-join-islands", "join_islands", nullptr,
           "do not join, last, an inside cluster but the largest to another across one or two "
           "outside vertices (a part cut off at a neck too thin for the leaves)",
           [](Settings& s, const std::string&, const std::string&) { s.join_islands = false; },
           [](const Settings& s) { return std::string(s.join_islands ? "on" : "off"); }},
    Option{"--keep-point-clusters", "merge_point_clusters", nullptr,
           "do not replace, first of all, the clusters of copies of the points by their centroids where most "
           "points have a few copies far closer to them than the next points (several scans along the same "
           "beams, points written again with rounding)",
           [](Settings& s, const std::string&, const std::string&) { s.merge_point_clusters = false; },
           [](const Settings& s) { return std::string(s.merge_point_clusters ? "merged" : "kept"); }},
    Option{"--keep-isolated-points", "remove_isolated_points", nullptr,
           "do not leave out, first, the points whose 12 nearest points spread more than 20 times "
           "farther than the median point's (stray returns far from the surface)",
           [](Settings& s, const std::string&, const std::string&) { s.remove_isolated_points = false; },
           [](const Settings& s) { return std::string(s.remove_isolated_points ? "left out" : "kept"); }},
    ISM_INTEGER_OPTION("--point-smoothing-iterations", point_smoothing_iterations,
                       "before the refinement, move noisy points onto a quadric fitted to their nearest "
                       "points (jet smoothing) this many times where they are dense for their noise, "
                       "else once (more passes flatten thin parts); 0: never"),
    ISM_INTEGER_OPTION("--point-smoothing-neighbors", point_smoothing_neighbors,
                       "nearest points a point's quadric is fitted to; more, up to 64, where the points "
                       "are dense for their noise"),
    ISM_REAL_OPTION("--point-smoothing-noise", point_smoothing_noise,
                    "smooth the points only if the median coplanarity error of their 12 nearest points "
                    "exceeds this; 0: always"),
    ISM_INTEGER_OPTION("--memory-limit", memory_limit,
                       "bytes the reconstruction may use on top of the input; 0: what the machine allows "
                       "(physical memory, ulimit -v and -d, cgroup limit). Beyond it the run stops with an "
                       "error before allocating"),
  };
  return table;
}

#undef ISM_INTEGER_OPTION
#undef ISM_REAL_OPTION

// The library's messages name its parameters as a C++ caller writes them
// (`remove_isolated_points(false)`, `maximum_depth`); a person at the shell needs the flags.
std::string with_flags(std::string message)
{
  const auto identifier = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for(const Option& o : options())
  {
    // a switch only ever turns its parameter off
    const std::string name = std::string(o.field) + (o.argument == nullptr ? "(false)" : "");
    for(std::size_t at = message.find(name); at != std::string::npos; at = message.find(name, at))
    {
      const std::size_t end = at + name.size();
      if((at > 0 && identifier(message[at - 1])) || (end < message.size() && identifier(message[end])))
      {
        at = end;
        continue;
      }
      message.replace(at, name.size(), o.flag);
      at += std::strlen(o.flag);
    }
  }
  return message;
}

const Option* find_option(const std::string& flag)
{
  for(const Option& o : options())
    if(flag == o.flag) return &o;
  return nullptr;
}

void print_help(std::ostream& os)
{
  const Settings defaults, paper = Settings::paper();
  os << "Usage: ism_reconstruct [options] INPUT OUTPUT\n\n"
        "Reconstructs a closed, 2-manifold surface from points WITHOUT normals (ISM_reconstruction_3:\n"
        "an in/out function on a binary multitriangulation, signs by an Ising model).\n\n"
        "  INPUT   points: .xyz/.pwn (x y z per line, more columns ignored), .ply, .off (its vertices)";
#ifdef CGAL_LINKED_WITH_LASLIB
  os << ", .las";
#endif
  os << "\n  OUTPUT  the surface: .off, .ply, .obj or .stl (binary; for printing)\n\n"
        "Options (default value in brackets; 'paper:' when --paper changes it):\n";
  // "  --flag ARG   help text, wrapped at 100 columns under itself"
  auto line = [&os](const std::string& left, const std::string& help) {
    const std::size_t column = 30, width = 100;
    std::string text = "  " + left;
    if(text.size() + 1 > column) { os << text << "\n"; text.clear(); }
    text.resize(column, ' ');
    std::istringstream words(help);
    std::string word;
    bool first = true;
    while(words >> word)
    {
      if(!first && text.size() + 1 + word.size() > width)
      {
        os << text << "\n";
        text.assign(column, ' ');
        first = true;
      }
      text += (first ? "" : " ") + word;
      first = false;
    }
    os << text << "\n";
  };
  for(const Option& o : options())
  {
    std::string help = std::string(o.help) + " [" + o.show(defaults);
    if(o.show(paper) != o.show(defaults)) help += "; paper: " + o.show(paper);
    help += "]";
    line(std::string(o.flag) + (o.argument ? std::string(" ") + o.argument : std::string()), help);
  }
  line("--paper", "start from the paper's settings (Settings::paper()); other options override them [off]");
  line("--tets FILE", "also write the triangulation leaves with per-vertex 'sign' and 'distance' (.vtu or .mesh) [none]");
  line("--quiet", "no progress and no summary; errors only [off]");
  line("-h, --help", "print this help and exit");
  os << "\nValues are given as '--flag VALUE' or '--flag=VALUE'.\n"
        "Progress goes to stderr when it is a terminal; the summary goes to stdout.\n"
        "Exit codes: 0 success, 1 bad input or unwritable output, 2 usage error.\n"
        "Outputs are written to temporary files and renamed at the end: a failed run leaves none.\n";
}

struct Command_line
{
  Settings settings;
  std::string input, output, tets;
  bool quiet = false;
  bool help = false;
};

Command_line parse_command_line(int argc, char** argv)
{
  Command_line cl;
  bool paper = false;
  std::vector<std::pair<const Option*, std::string> > assignments;  // applied after --paper
  std::vector<std::string> positional;
  bool options_ended = false;
  for(int i = 1; i < argc; ++i)
  {
    std::string arg = argv[i];
    if(options_ended || arg.size() < 2 || arg[0] != '-')
    {
      positional.push_back(arg);
      continue;
    }
    if(arg == "--") { options_ended = true; continue; }
    std::string value;
    bool has_value = false;
    const std::size_t eq = arg.find('=');
    if(arg.compare(0, 2, "--") == 0 && eq != std::string::npos)
    {
      value = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
      has_value = true;
    }
    auto take_value = [&]() -> std::string {
      if(has_value) return value;
      if(i + 1 >= argc) usage_error("option " + arg + " needs a value");
      return argv[++i];
    };
    auto no_value = [&]() {
      if(has_value) usage_error("option " + arg + " takes no value");
    };
    if(arg == "-h" || arg == "--help") { no_value(); cl.help = true; }
    else if(arg == "--quiet") { no_value(); cl.quiet = true; }
    else if(arg == "--paper") { no_value(); paper = true; }
    else if(arg == "--tets")
    {
      cl.tets = take_value();
      if(cl.tets.empty()) usage_error("--tets needs a file name");
    }
    else if(const Option* o = find_option(arg))
    {
      if(o->argument) assignments.emplace_back(o, take_value());
      else { no_value(); assignments.emplace_back(o, std::string()); }
    }
    else
      usage_error("unknown option '" + arg + "'");
  }
  if(cl.help) return cl;

  cl.settings = paper ? Settings::paper() : Settings();
  for(const auto& a : assignments) a.first->set(cl.settings, a.first->flag, a.second);
  try
  {
    cl.settings.check();
  }
  catch(const std::invalid_argument& e)
  {
    // name the flag rather than the C++ member
    std::string message = e.what();
    for(const Option& o : options())
      if(message.find(std::string(" ") + o.field + " ") != std::string::npos)
      {
        message = std::string(o.flag) + ": " + message;
        break;
      }
    usage_error(message);
  }

  if(positional.size() != 2)
    usage_error(positional.size() < 2 ? "an INPUT and an OUTPUT file are needed" : "too many arguments");
  cl.input = positional[0];
  cl.output = positional[1];
  const std::string out_ext = ism_tool::lowercase_extension(cl.output);
  if(out_ext != "off" && out_ext != "ply" && out_ext != "obj" && out_ext != "stl")
    usage_error("output '" + cl.output + "': the extension must be .off, .ply, .obj or .stl");
  if(!cl.tets.empty())
  {
    const std::string ext = ism_tool::lowercase_extension(cl.tets);
    if(ext != "vtu" && ext != "mesh")
      usage_error("--tets '" + cl.tets + "': the extension must be .vtu or .mesh");
  }
  return cl;
}

// ---------------------------------------------------------------------------------------
// Progress (stderr, terminals only) and topology of the result
// ---------------------------------------------------------------------------------------

class Progress
{
public:
  explicit Progress(bool enabled) : m_enabled(enabled) { m_timer.start(); }
  void stage(const std::string& name, double fraction)
  {
    if(!m_enabled) return;
    const double now = m_timer.time();
    if(name == m_stage && fraction < 1 && now - m_last < 0.1) return;
    m_stage = name;
    m_last = now;
    std::cerr << "\r\033[K" << std::setw(3) << int(100 * fraction + 1e-9) << "%  " << std::left << std::setw(11) << name
              << std::right << std::fixed << std::setprecision(1) << std::setw(7) << now << " s" << std::flush;
    std::cerr.unsetf(std::ios::floatfield);
  }
  void done()
  {
    if(m_enabled) std::cerr << "\r\033[K" << std::flush;
  }
  // the library reports 0-0.7 during refinement, 0.75 then 0.9 at the ends of
  // refinement and topology, 1 at the end of distance estimation
  bool report(double p)
  {
    stage(p < 0.75 ? "refinement" : (p < 0.9 ? "topology" : (p < 1 ? "distance" : "extraction")), 0.9 * p);
    return true;
  }

private:
  bool m_enabled;
  CGAL::Real_timer m_timer;
  std::string m_stage;
  double m_last = -1;
};

struct Topology
{
  std::size_t components = 0, boundary_cycles = 0;
  std::size_t largest_component_faces = 0;
  long euler = 0;
  long genus = 0;
  bool closed = false, manifold = false;
};

Topology topology(Mesh& mesh)
{
  Topology t;
  t.closed = CGAL::is_closed(mesh);
  std::size_t isolated = 0;
  for(auto v : vertices(mesh))
    if(mesh.is_isolated(v)) ++isolated;
  std::vector<Mesh::Halfedge_index> non_manifold;
  PMP::non_manifold_vertices(mesh, std::back_inserter(non_manifold));
  t.manifold = CGAL::is_valid_polygon_mesh(mesh) && non_manifold.empty() && isolated == 0;
  t.euler = long(num_vertices(mesh) - isolated) - long(num_edges(mesh)) + long(num_faces(mesh));
  auto fcc = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:ism_cc", 0).first;
  t.components = PMP::connected_components(mesh, fcc);
  std::vector<std::size_t> faces_of(t.components, 0);
  for(auto f : faces(mesh)) ++faces_of[fcc[f]];
  if(!faces_of.empty()) t.largest_component_faces = *std::max_element(faces_of.begin(), faces_of.end());
  std::vector<Mesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  t.boundary_cycles = cycles.size();
  // chi = sum over components of (2 - 2 g_i - b_i)
  t.genus = (2 * long(t.components) - long(t.boundary_cycles) - t.euler) / 2;
  mesh.remove_property_map(fcc);
  return t;
}

int run(int argc, char** argv)
{
  CGAL::Real_timer total;
  total.start();
  const Command_line cl = parse_command_line(argc, argv);
  if(cl.help)
  {
    std::ostringstream help;
    print_help(help);
    write_stdout(help.str(), "the help");
    return SUCCESS;
  }

  // temporaries first: an unwritable output fails now, not after the reconstruction
  const std::string out_ext = ism_tool::lowercase_extension(cl.output);
  const std::string out_tmp = temporary_name(cl.output, out_ext);
  std::string tets_ext, tets_tmp;
  create_temporary(out_tmp, cl.output, cl.input);
  if(!cl.tets.empty())
  {
    tets_ext = ism_tool::lowercase_extension(cl.tets);
    tets_tmp = temporary_name(cl.tets, tets_ext);
    create_temporary(tets_tmp, cl.tets, cl.input);
    if(tets_ext == "mesh")  // the fields go to the .sol file beside the .mesh
    {
      check_output_name(sol_name(cl.tets), cl.input);
      register_temporary(sol_name(tets_tmp));
    }
  }

  CGAL::Real_timer timer;
  timer.start();
  std::vector<std::string> warnings;
  std::vector<Point> points = ism_tool::read_point_file<Point>(cl.input, warnings);
  for(const std::string& w : warnings) std::cerr << "ism_reconstruct: warning: " << w << "\n";
  const double read_time = timer.time();
  // points far from unit size are reconstructed scaled by 2^e, exactly, and the outputs
  // scaled back (normalization.h: some sizes are held in single precision)
  const int exponent = CGAL::ISM_reconstruction_3::internal::normalizing_exponent(points, CGAL::Identity_property_map<Point>());
  if(exponent != 0)
    for(Point& p : points) p = CGAL::ISM_reconstruction_3::internal::scaled_point(p, exponent);

  Progress progress(!cl.quiet && ::isatty(STDERR_FILENO));
  Settings settings = cl.settings;
  settings.callback = [&progress](double p) { return progress.report(p); };
  std::unique_ptr<Function> function;
  try
  {
    function.reset(new Function(points, CGAL::parameters::memory_limit(settings.memory_limit)));
    // the function holds its own copy: not keeping two lowers the peak memory
    std::vector<Point>().swap(points);
  }
  catch(const std::invalid_argument& e)
  {
    input_error("'" + cl.input + "': " + with_flags(e.what()));
  }
  catch(const std::length_error& e)  // the memory guard
  {
    input_error("'" + cl.input + "': " + with_flags(e.what()));
  }
  try
  {
    function->compute_implicit_function_with_settings(settings);
  }
  catch(const std::invalid_argument& e)
  {
    usage_error(e.what());
  }
  catch(const std::runtime_error& e)
  {
    std::string message = std::string("'") + cl.input + "': " + with_flags(e.what());
    // the library blames the points; a refinement parameter set away from its default can
    // as well stop the cells before one has a vertex inside (--coplanarity-threshold 0.333
    // on 5,000 sphere points that are fine by default)
    if(message.find("no vertex was found inside") != std::string::npos)
    {
      const Settings defaults;
      std::string given;
      for(const Option& o : options())
        if(std::strcmp(o.field, "maximum_depth") == 0 || std::strcmp(o.field, "min_points_per_cell") == 0 ||
           std::strcmp(o.field, "coplanarity_threshold") == 0)
          if(o.show(cl.settings) != o.show(defaults))
            given += std::string(given.empty() ? "" : ", ") + o.flag + " " + o.show(cl.settings);
      if(!given.empty())
        message += "; the refinement parameters set away from their defaults (" + given +
                   ") may also stop the refinement too early: try without them (--help lists the defaults)";
    }
    input_error(message);
  }
  catch(const std::length_error& e)  // the memory guard
  {
    input_error("'" + cl.input + "': " + with_flags(e.what()));
  }

  progress.stage("extraction", 0.9);
  Mesh mesh;
  const CGAL::ISM_reconstruction_3::Extraction_statistics extraction =
      CGAL::ISM_reconstruction_3::internal::extract_scaled_surface(*function, mesh, settings.smoothing_iterations,
                                                                   settings.smoothing_lambda, settings.smoothing_mu,
                                                                   settings.crossing_neighbors, -exponent);

  progress.stage("writing", 0.95);
  timer.reset();
  errno = 0;  // a full disk named its reason nowhere
  const bool written = out_ext == "off" ? write_off(out_tmp, mesh)
                                           : CGAL::IO::write_polygon_mesh(out_tmp, mesh, CGAL::parameters::stream_precision(17));
  if(!written)
    input_error("cannot write '" + cl.output + "'" + (errno != 0 ? std::string(": ") + std::strerror(errno) : std::string()));
  std::size_t number_of_tets = 0;
  if(!cl.tets.empty())
  {
    const auto& tr = function->triangulation();
    const std::vector<std::array<int, 4> > tets = tr.leaf_tetrahedra();
    number_of_tets = tets.size();
    std::vector<CGAL::IO::Tet_mesh_vertex_field> fields(2);
    fields[0].first = "sign";
    fields[0].second.assign(function->signs().begin(), function->signs().end());
    fields[1].first = "distance";
    fields[1].second = function->values();
    std::vector<Point> tet_points;
    if(exponent != 0)
    {
      // a squared distance scales twice
      const int value_exponent = settings.distance_estimate == CGAL::ISM_reconstruction_3::NEAREST_POINT_SQUARED_DISTANCE ? -2 * exponent : -exponent;
      for(double& x : fields[1].second) x = std::ldexp(x, value_exponent);
      tet_points.reserve(tr.points().size());
      for(const Point& p : tr.points()) tet_points.push_back(CGAL::ISM_reconstruction_3::internal::scaled_point(p, -exponent));
    }
    errno = 0;
    if(!CGAL::IO::write_tet_mesh(tets_tmp, exponent == 0 ? tr.points() : tet_points, tets, fields))
      input_error("cannot write '" + cl.tets + "'" + (errno != 0 ? std::string(": ") + std::strerror(errno) : std::string()));
  }
  // all written: move into place (the .sol of a .mesh first, the surface last)
  if(!cl.tets.empty())
  {
    if(tets_ext == "mesh")
    {
      rename_into_place(sol_name(tets_tmp), sol_name(cl.tets));
    }
    rename_into_place(tets_tmp, cl.tets);
  }
  rename_into_place(out_tmp, cl.output);
  g_number_of_temporaries = 0;
  const double write_time = timer.time();
  progress.done();

  const auto& stats = function->statistics();
  if(stats.added_levels > 0 && stats.deepest_level >= CGAL::ISM_reconstruction_3::Settings::deepest_level)
    std::cerr << "ism_reconstruct: warning: far outliers or parts far apart make the points' extent so much "
                 "larger than that of their bulk that the leaves reached the deepest level allowed ("
              << CGAL::ISM_reconstruction_3::Settings::deepest_level
              << "): the surface may be coarse; remove the far outliers, or reconstruct the parts one by one\n";
  // the surface then stands on the tangent planes alone: in parts, or lumpy (random points
  // on a sphere, 150-500 of them: 1 part where the model found an inside, 1-10 where not,
  // before the coarser refinements; after them, where even leaves of 24 points see none)
  if(stats.number_of_ising_inside_vertices == 0)
    std::cerr << "ism_reconstruct: warning: the in/out signs (Ising model) found no inside region for "
              << stats.number_of_points << " points, also with leaves of up to "
              << function->settings().min_points_per_cell
              << " points; the surface comes from the points' tangent planes alone and may be in parts or "
                 "lumpy: sample the surface more densely\n";
  // Both sides of a part thinner than about two point spacings fall in the same leaves, and
  // no vertex lies between them: the surface misses the part's points (random points on an
  // ellipsoid of axes 1, 1, 0.01: 58 % of them off the surface, in 35 pieces), or runs
  // along them in many small pieces (evenly spread points on it: 66-310 components, none
  // off). Measured over 30 closed meshes of libcgal-demo (36,000 points each), the bunny
  // with noise, outliers and one half sparser: at most 2.2 % off, one component except
  // knot2 (2); a thin plate's points had come out in 125 pieces without a word. Points on
  // 20 great circles of a sphere (scan lines far apart): 52 % off.
  const Topology topo = topology(mesh);
  const double off_surface = double(stats.number_of_points_off_surface) /
                             double(stats.number_of_points - stats.number_of_merged_points - stats.number_of_isolated_points);
  const bool missed = off_surface > 0.1;
  const bool in_pieces = topo.components >= 10 && 2 * topo.largest_component_faces < num_faces(mesh);
  if(missed || in_pieces)
  {
    std::ostringstream why;
    if(missed)
      why << std::lround(100 * off_surface) << " % of the points lie in leaves the surface does not reach";
    else
      why << "the surface fell into " << topo.components << " pieces, the largest with "
          << std::lround(100. * double(topo.largest_component_faces) / double(num_faces(mesh))) << " % of the faces";
    std::cerr << "ism_reconstruct: warning: " << why.str()
              << ": the points may be too sparse for the object (parts thinner than about two point "
                 "spacings, where no cell fits between their sides, or wide gaps between lines of points); "
                 "sample it more densely\n";
  }
  if(cl.quiet) return SUCCESS;
  auto yes = [](bool b) { return b ? "yes" : "no"; };
  std::ostringstream os;
  os << std::fixed << std::setprecision(3);
  os << "input:       " << cl.input << " (" << stats.number_of_points << " points"
     << (stats.number_of_merged_points > 0
             ? ", " + std::to_string(stats.number_of_merged_points) + " merged into the centroids of their clusters of copies"
             : std::string())
     << (stats.number_of_isolated_points > 0
             ? ", " + std::to_string(stats.number_of_isolated_points) + " isolated ones left out"
             : std::string())
     << ")\n"
     << (stats.number_of_flipped_islands > 0
             ? "islands:     " + std::to_string(stats.number_of_flipped_islands) +
                   " inside clusters smaller than --minimum-island-fraction of the largest set outside "
                   "(0 keeps them)\n"
             : std::string())
     << "leaves:      " << stats.number_of_leaves << " (" << stats.number_of_vertices << " vertices, "
     << stats.number_of_inside_vertices << " inside, deepest level " << stats.deepest_level
     << (stats.added_levels > 0 ? " (" + std::to_string(stats.added_levels) + " levels added for far outliers or parts far apart)" : std::string())
     << ", " << stats.number_of_topology_passes << " topology passes"
     << (stats.number_of_coarser_refinements > 0
             ? ", " + std::to_string(function->settings().min_points_per_cell) + " points per leaf after " +
                   std::to_string(stats.number_of_coarser_refinements) + " coarser refinement" +
                   (stats.number_of_coarser_refinements > 1 ? "s" : "")
             : std::string())
     << ")\n"
     << "time (s):    reading     " << std::setw(8) << read_time << "\n"
     << "             refinement  " << std::setw(8) << stats.refinement_time << "\n"
     << "             topology    " << std::setw(8) << stats.topology_time << "\n"
     << "             distance    " << std::setw(8) << stats.distance_time << "\n"
     << "             marching    " << std::setw(8) << extraction.marching_time << "\n"
     << "             smoothing   " << std::setw(8) << extraction.smoothing_time << "\n"
     << "             writing     " << std::setw(8) << write_time << "\n"
     << "             total       " << std::setw(8) << total.time() << "\n"
     << "output:      " << cl.output << " (" << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces)\n";
  if(!cl.tets.empty())
    os << "tets:        " << cl.tets << " (" << number_of_tets << " tetrahedra, fields sign and distance)\n";
  os << "components:  " << topo.components << "\n"
     << "genus:       " << topo.genus << "\n"
     << "euler:       " << topo.euler << "\n"
     << "closed:      " << yes(topo.closed) << "\n"
     << "manifold:    " << yes(topo.manifold) << "\n";
  write_stdout(os.str(), "the summary", " (the output files are written)");
  return SUCCESS;
}

} // namespace

int main(int argc, char** argv)
{
  CGAL::ISM_reconstruction_3::internal::restart_with_huge_pages(argv);
#if defined(__GLIBC__)
  // glibc raises its mmap threshold up to 32 MB each time a large block is freed; the
  // arrays of each topology pass (tens of MB) then come from the heap and leave holes in
  // it that are never returned. A fixed threshold keeps them mapped and unmapped on free.
  // Measured on 437,645 points: peak resident memory 240 MB -> 212 MB (128 kB:
  // 209 MB, 4 MB: 234 MB), user time unchanged within the noise.
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
  for(int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE}) std::signal(sig, on_signal);
  int code = SUCCESS;
  try
  {
    code = run(argc, argv);
  }
  catch(const Failure& f)
  {
    if(::isatty(STDERR_FILENO)) std::cerr << "\r\033[K";  // clear a progress line
    std::cerr << "ism_reconstruct: error: " << f.message << "\n";
    if(f.code == USAGE_ERROR) std::cerr << "(ism_reconstruct --help lists the options)\n";
    code = f.code;
  }
  catch(const std::bad_alloc&)
  {
    // the memory guard refuses what it can foresee; reading a file that does not fit
    // ends here (it printed only "std::bad_alloc")
    std::cerr << "ism_reconstruct: error: out of memory (the input, or the refinement at this depth, needs more "
                 "than this process may allocate): use fewer points or a smaller --maximum-depth\n";
    code = BAD_INPUT;
  }
  catch(const std::exception& e)
  {
    std::cerr << "ism_reconstruct: error: " << e.what() << "\n";
    code = BAD_INPUT;
  }
  remove_temporaries();
  return code;
}
