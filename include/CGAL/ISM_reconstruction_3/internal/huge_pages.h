// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_HUGE_PAGES_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_HUGE_PAGES_H

// For programs (the tool, the benchmark), not for the library: the method touches a few
// hundred MB of fresh memory on large inputs, and with 4 kB pages the page faults alone
// took 1 s of the 5.8 s of the 437,645-point dragon on the 2-core development VM (126k faults);
// with glibc backing its large blocks by transparent huge pages (glibc >= 2.35, tunable
// glibc.malloc.hugetlb=1) the run took 4.4 s (41k faults; peak memory +3 %). glibc reads
// tunables only at start-up, so the program restarts itself once with the tunable set.
// A library user gets the same by setting GLIBC_TUNABLES=glibc.malloc.hugetlb=1.

#if defined(__linux__) && defined(__GLIBC__)
#include <cstdlib>
#include <string>
#include <unistd.h>
#endif

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// Re-executes the running program with glibc.malloc.hugetlb=1 added to GLIBC_TUNABLES,
// unless it is already there, the environment variable ISM_NO_HUGE_PAGES is set, or this
// is not Linux with glibc >= 2.35. Returns only if it did not re-execute (also when exec
// failed: the program then simply runs with normal pages).
inline void restart_with_huge_pages(char** argv)
{
#if defined(__linux__) && defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 35))
  if(std::getenv("ISM_NO_HUGE_PAGES") != nullptr)
    return;
  const char* current = std::getenv("GLIBC_TUNABLES");
  std::string tunables = current ? current : "";
  if(tunables.find("glibc.malloc.hugetlb") != std::string::npos)
    return;  // set already, by the user or by the first start
  tunables += std::string(tunables.empty() ? "" : ":") + "glibc.malloc.hugetlb=1";
  if(setenv("GLIBC_TUNABLES", tunables.c_str(), 1) != 0)
    return;
  execv("/proc/self/exe", argv);
  // exec failed (no /proc?): go on in this process, without the tunable
  if(current) setenv("GLIBC_TUNABLES", current, 1);
  else unsetenv("GLIBC_TUNABLES");
#else
  (void)argv;
#endif
}

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_HUGE_PAGES_H
