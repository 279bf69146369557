#!/usr/bin/env bash
# Installs what is missing, builds everything with the tests in Release and runs CTest, then
# the same test suite built with AddressSanitizer + UndefinedBehaviorSanitizer in its own
# build directory (scripts/run_sanitizers.sh). The script fails if either run fails; both
# always run. Extra arguments go to both ctest runs (e.g. -R robustness).
#
# Measured from clean build directories on the 2-core development machine, while other jobs
# kept the load average at about 4: 48 min 29 s wall in all (50.6 min of CPU: 2744 s user,
# 294 s system; at most 4.7 GB resident, one sanitizer compiler): Release build + CTest
# (113 s) about 14 min, sanitizer build 1589 s + its CTest 479 s = 34.5 min. At a load
# average of 2 the sanitizer part took 17.5 min (build 690 s, CTest 363 s). Either way
# within CI's 90 minutes on 2 cores.
#
# Environment: ISM_TEST_BUILD_DIR (default build-tests); ISM_SANITIZERS=0 skips the
# sanitizer run (a quicker local check); see scripts/run_sanitizers.sh for its own.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/install_deps.sh"
build="${ISM_TEST_BUILD_DIR:-$root/build-tests}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON >/dev/null
cmake --build "$build" -j"$(nproc)"
status=0
(cd "$build" && ctest --output-on-failure -j"$(nproc)" "$@") || status=$?
if [ "${ISM_SANITIZERS:-1}" != 0 ]; then
  bash "$root/scripts/run_sanitizers.sh" "$@" || status=$?
fi
exit $status
