#!/usr/bin/env bash
# Builds the HTML documentation of ISM_reconstruction_3 (user and reference manual) with
# doxygen and FAILS (exit 1) on any doxygen warning or error.
#
#   scripts/build_doc.sh [OUTPUT_DIR]
#
# The HTML goes to OUTPUT_DIR/html, OUTPUT_DIR being the argument, else $ISM_DOC_OUTPUT_DIR,
# else doc/ISM_reconstruction_3 (i.e. doc/ISM_reconstruction_3/html). The warnings are
# written to OUTPUT_DIR/doxygen_warnings.log and printed. $DOXYGEN names the doxygen
# executable (default: doxygen from PATH).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
doc="$root/doc/ISM_reconstruction_3"
out="${1:-${ISM_DOC_OUTPUT_DIR:-$doc}}"
doxygen="${DOXYGEN:-doxygen}"
command -v "$doxygen" >/dev/null 2>&1 || {
  echo "error: doxygen not found (apt-get install -y doxygen graphviz)" >&2; exit 1; }
mkdir -p "$out"
out="$(cd "$out" && pwd)"
log="$out/doxygen_warnings.log"
rm -f "$log"
rm -rf "$out/html"

# the benchmark chart is a required figure of the manual (doc/ISM_reconstruction_3/make_figures.sh
# --chart-only copies it from benchmark/results.png): a missing file fails the build below
sections=""
if [ ! -f "$doc/fig/benchmark_results.png" ]; then
  echo "error: $doc/fig/benchmark_results.png is missing (run the benchmark, then" \
       "doc/ISM_reconstruction_3/make_figures.sh --chart-only)" >&2
fi

# the Doxyfile reads these variables; its relative paths are relative to $doc
status=0
(cd "$doc" && ISM_DOC_OUTPUT_DIR="$out" ISM_DOC_WARN_LOG="$log" ISM_DOC_SECTIONS="$sections" \
   "$doxygen" Doxyfile) || status=$?

# WARN_AS_ERROR = FAIL_ON_WARNINGS makes doxygen exit non-zero on a warning; the log is
# checked too, so that no warning passes whatever the doxygen version does.
count=0
if [ -s "$log" ]; then
  count=$(grep -c -i -E 'warning|error' "$log" || true)
  [ "$count" -gt 0 ] || count=$(wc -l <"$log")
fi
if [ "$status" -ne 0 ] || [ "$count" -gt 0 ]; then
  [ -s "$log" ] && cat "$log" >&2
  echo "error: doxygen failed (exit status $status, $count warning(s)); see $log" >&2
  exit 1
fi
if [ ! -f "$out/html/index.html" ]; then
  echo "error: $out/html/index.html was not produced" >&2
  exit 1
fi
echo "documentation built without warnings: $out/html/index.html"
