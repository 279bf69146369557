// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_MEMORY_BUDGET_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_MEMORY_BUDGET_H

// The memory guard (project issue 8): a depth or an input size whose memory would exceed
// what this process may use is refused with std::length_error before the allocation,
// instead of std::bad_alloc, or the OOM killer, in the middle of the run.

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

#if defined(__linux__)
#include <sys/resource.h>
#include <unistd.h>
#endif

#if defined(__GLIBC__)
#include <malloc.h>  // malloc_trim
#endif

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

inline std::string format_bytes(double bytes)
{
  std::ostringstream os;
  os.setf(std::ios::fixed);
  if(bytes >= double(1ull << 30)) os << std::setprecision(2) << bytes / double(1ull << 30) << " GiB";
  else os << std::setprecision(1) << bytes / double(1ull << 20) << " MiB";
  return os.str();
}

// What this process may still allocate, and which limit says so.
struct Memory_budget
{
  std::size_t bytes = (std::numeric_limits<std::size_t>::max)();  // max: no known limit
  std::string limited_by;

  bool limited() const { return bytes != (std::numeric_limits<std::size_t>::max)(); }
  void consider(double available, const std::string& why)
  {
    const double b = (std::max)(0., available);
    if(b < double(bytes))
    {
      bytes = b >= double((std::numeric_limits<std::size_t>::max)()) ? bytes : std::size_t(b);
      limited_by = why;
    }
  }
};

#if defined(__linux__)
// the first number in a file (false if missing, or not a number as cgroup v2's "max")
inline bool read_number(const std::string& file, double& value)
{
  std::ifstream is(file);
  return bool(is >> value);
}

// the value of `key` in a "key value" file (memory.stat)
inline double read_stat(const std::string& file, const std::string& key)
{
  std::ifstream is(file);
  std::string k;
  double v;
  while(is >> k >> v)
    if(k == key) return v;
  return 0;
}

// The tightest memory limit of the cgroups (v2 and v1) holding this process and of their
// ancestors: limit - usage, the usage without the inactive page cache (which the kernel
// reclaims before it kills).
inline void consider_cgroups(Memory_budget& budget)
{
  std::ifstream is("/proc/self/cgroup");
  std::string line;
  while(std::getline(is, line))
  {
    // "hierarchy-ID:controllers:path": "0::/path" (v2) or "4:memory:/path" (v1)
    const std::size_t a = line.find(':'), b = a == std::string::npos ? a : line.find(':', a + 1);
    if(b == std::string::npos) continue;
    const std::string controllers = line.substr(a + 1, b - a - 1);
    std::string path = line.substr(b + 1);
    const bool v2 = controllers.empty();
    if(!v2 && ("," + controllers + ",").find(",memory,") == std::string::npos) continue;
    const std::string mount = v2 ? "/sys/fs/cgroup" : "/sys/fs/cgroup/memory";
    const char* limit_file = v2 ? "/memory.max" : "/memory.limit_in_bytes";
    const char* usage_file = v2 ? "/memory.current" : "/memory.usage_in_bytes";
    const char* inactive = v2 ? "inactive_file" : "total_inactive_file";
    for(;;)
    {
      const std::string dir = mount + (path == "/" ? "" : path);
      double limit, usage;
      if(read_number(dir + limit_file, limit) && limit < 1e18 && read_number(dir + usage_file, usage))
      {
        usage = (std::max)(0., usage - read_stat(dir + "/memory.stat", inactive));
        budget.consider(limit - usage, "the memory limit of the cgroup " + dir + ": " + format_bytes(limit) + ", " +
                                           format_bytes(usage) + " of it in use");
      }
      if(path.empty() || path == "/") break;
      const std::size_t slash = path.find_last_of('/');
      path = slash == 0 || slash == std::string::npos ? "/" : path.substr(0, slash);
    }
  }
}
#endif

/*
  The bytes this process may still allocate: the minimum of
  - physical memory minus what this process holds resident (sysconf);
  - the soft RLIMIT_AS (ulimit -v) minus the address space already mapped, and minus what
    threads not started yet will reserve (a glibc malloc arena of 64 MiB and a stack of 8 MiB
    per hardware thread);
  - the soft RLIMIT_DATA (ulimit -d) minus the data already mapped;
  - the limits of the cgroups (v2 memory.max, v1 memory.limit_in_bytes) minus their usage;
  - `memory_limit`, if not 0.
  Linux only; elsewhere only `memory_limit` (no limit if it is 0).
*/
inline Memory_budget available_memory(std::size_t memory_limit = 0)
{
  Memory_budget budget;
#if defined(__linux__)
  const double page = double(sysconf(_SC_PAGESIZE));
  double size = 0, resident = 0, shared = 0, text = 0, lib = 0, data = 0;  // pages
  {
    std::ifstream statm("/proc/self/statm");
    statm >> size >> resident >> shared >> text >> lib >> data;
  }
  const long physical_pages = sysconf(_SC_PHYS_PAGES);
  if(physical_pages > 0 && page > 0)
    budget.consider(double(physical_pages) * page - resident * page,
                    "physical memory: " + format_bytes(double(physical_pages) * page) + ", " +
                        format_bytes(resident * page) + " of it held by this process");
  struct rlimit rl;
  if(getrlimit(RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY)
  {
    const double threads = (std::max)(1u, std::thread::hardware_concurrency());
    budget.consider(double(rl.rlim_cur) - size * page - threads * double(72ull << 20),
                    "the address-space limit RLIMIT_AS (ulimit -v): " + format_bytes(double(rl.rlim_cur)) + ", " +
                        format_bytes(size * page) + " of it already mapped, " + format_bytes(threads * double(72ull << 20)) +
                        " kept for the stacks and malloc arenas of " + std::to_string(int(threads)) + " threads");
  }
  if(getrlimit(RLIMIT_DATA, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY)
    budget.consider(double(rl.rlim_cur) - data * page,
                    "the data limit RLIMIT_DATA (ulimit -d): " + format_bytes(double(rl.rlim_cur)) + ", " +
                        format_bytes(data * page) + " of it in use");
  consider_cgroups(budget);
#endif
  if(memory_limit > 0)
    budget.consider(double(memory_limit), "the parameter memory_limit = " + std::to_string(memory_limit) + " bytes");
  return budget;
}

/*
  Refuses a reconstruction whose estimated memory exceeds the budget of the process, read
  once at construction (refine() builds one before it allocates anything proportional to the
  points).

  The estimate, of the memory the reconstruction adds to what the process already holds:
    fixed_bytes + bytes_per_point * points + bytes_per_cell * cells,
  up front with the cells of the 6 roots, then every time the triangulation grew by 1/8:
  with 9/8 of its current number of cells (the next check), so that the peak until the next
  check is covered.

  Measured (issue 8; Release, 2-core Linux, with m_range and m_fit as Block_arrays, float
  coupling weights; the growth of /proc/self/status VmPeak (address space) and VmHWM
  (resident) over CGAL::ISM_reconstruction_function + extract_surface(): the whole pipeline,
  refinement, annealing passes with their coupling graph, distances with the kd-tree, marching
  tetrahedra), whole peak per cell:
    input, maximum_depth                       cells        address space   resident
    ChineseDragon, 1M points, 24               3,926,682    149 B/cell      122 B/cell
    ChineseDragon, 1M points, 36               4,709,766    141 B/cell      118 B/cell
    ChineseDragon, 300k points, 24             1,388,666    182 B/cell      121 B/cell
    sphere, 20k points x 6 copies 1e-12 apart, 30  16,232,362  107 B/cell   100 B/cell
  and with few cells (maximum_depth 3, 90 cells), 3M points on a sphere: 134 B/point of
  address space, 118 B/point resident (the copy of the points, index arrays, the kd-tree of
  the distances). Without the per-point part (134 B/point) and glibc's 64 MiB arena per
  thread (fixed_bytes), a cell costs 103 to 113 B at the peak; bytes_per_cell adds the capacity
  the std::vectors that grow by doubling may hold unused (the priority queue, the vertex
  arrays), bytes_per_point some margin. Re-measure them when what a cell or a point costs
  changes (read VmPeak before and after a run, divide by number_of_cells()).
*/
class Memory_guard
{
public:
  static constexpr double bytes_per_cell = 160;
  static constexpr double bytes_per_point = 160;
  static constexpr double fixed_bytes = double(64ull << 20);

  /// reads the budget and checks the cost of `number_of_points` up front
  /// \throws std::length_error if it does not fit
  Memory_guard(std::size_t memory_limit, std::size_t number_of_points, int maximum_depth)
    : m_budget(available_memory(memory_limit)), m_points(number_of_points), m_depth(maximum_depth)
  {
    if(estimate(6) > double(m_budget.bytes))
      refuse(estimate(6), "the reconstruction from " + std::to_string(m_points) +
                              " points (their copies, index arrays and kd-tree, before any refinement)",
             false);
  }

  /// call after each bisection: cheap unless the number of cells grew by 1/8 since the last check
  /// \throws std::length_error if 9/8 of `number_of_cells` would not fit
  void check(std::size_t number_of_cells)
  {
    if(number_of_cells < m_next_check) return;
    const std::size_t next = number_of_cells + number_of_cells / 8;
    const double needed = estimate(next);
    if(needed > double(m_budget.bytes))
      refuse(needed, "the refinement of " + std::to_string(m_points) + " points at maximum_depth " +
                         std::to_string(m_depth) + ", at " + std::to_string(number_of_cells) +
                         " cells and still refining (about " + std::to_string(int(bytes_per_cell)) + " bytes per cell),");
    m_next_check = next;
  }

  /// \throws std::length_error if the copy of `number_of_points` points (24 bytes each,
  /// made by the constructor of `ISM_reconstruction_function`) does not fit
  static void check_point_copy(std::size_t memory_limit, std::size_t number_of_points)
  {
    const double needed = 24. * double(number_of_points);
    if(needed > double(std::size_t(1) << 24))  // 16 MiB: not worth reading /proc below that
    {
      Memory_guard guard(memory_limit);
      if(needed > double(guard.m_budget.bytes))
        guard.refuse(needed, "the copy of " + std::to_string(number_of_points) + " points", false);
    }
  }

  const Memory_budget& budget() const { return m_budget; }
  double estimate(std::size_t cells) const
  {
    return fixed_bytes + bytes_per_point * double(m_points) + bytes_per_cell * double(cells);
  }

private:
  explicit Memory_guard(std::size_t memory_limit) : m_budget(available_memory(memory_limit)), m_points(0), m_depth(0) {}

  [[noreturn]] void refuse(double needed, const std::string& what, bool lower_depth = true) const
  {
    throw std::length_error("ISM reconstruction: not enough memory: " + what + " needs about " +
                            format_bytes(needed) + " more, but this process may use only " +
                            format_bytes(double(m_budget.bytes)) + " more (limited by " + m_budget.limited_by +
                            "). " +
                            (lower_depth && m_depth > 0 ? "Lower maximum_depth (now " + std::to_string(m_depth) + "), reconstruct"
                                         : std::string("Reconstruct")) +
                            " from fewer points, or " +
                            (m_budget.limited_by.compare(0, 27, "the parameter memory_limit ") == 0
                                 ? std::string("raise memory_limit (0: what the machine allows).")
                                 : std::string("give the process more memory (memory_limit, 0 by default, can only "
                                               "lower the limit).")));
  }

  Memory_budget m_budget;
  std::size_t m_points;
  int m_depth;
  std::size_t m_next_check = std::size_t(1) << 15;  // 5 MiB of cells: below, fixed_bytes covers them
};

// Returns to the system the heap memory glibc keeps after a free: blocks under the mmap
// threshold (the per-cell blocks, the per-chunk graph rows) lie between blocks still in
// use, and stay resident under the next large arrays, which then set a higher peak.
// Nothing to do elsewhere.
inline void return_free_heap_memory()
{
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_MEMORY_BUDGET_H
