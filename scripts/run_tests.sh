#!/usr/bin/env bash
# Installs what is missing, builds everything with the tests in Release and runs CTest, then
# the same test suite built with AddressSanitizer + UndefinedBehaviorSanitizer in its own
# build directory (scripts/run_sanitizers.sh). The script fails if either run fails; both
# always run. Extra arguments go to both ctest runs (e.g. -R robustness).
#
# Measured on the 2-core development machine, other jobs keeping the load average at 2 to 4:
# Release build + CTest about 13 min; sanitizer build 690 s (11.5 min, ISM_JOBS=2, at most
# 4.7 GB resident for one compiler) + its CTest 363 s (6 min): about 31 min in all, within
# CI's 90 minutes on 2 cores.
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
