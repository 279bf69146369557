#!/usr/bin/env bash
# Regenerates every figure of the ISM_reconstruction_3 user manual into
# doc/ISM_reconstruction_3/fig/, with the package itself, from real data:
#   1. builds figures/make_figure_data.cpp (target ism_doc_figure_data, see figures.cmake)
#      unless ISM_FIGURE_DATA_EXE names an already built one (e.g. from the top-level build);
#   2. runs it on bunny00.off and knot1.off from libcgal-demo's data tarball;
#   3. renders the PNGs with figures/render_figures.py (/usr/bin/python3, matplotlib);
#   4. copies the benchmark chart benchmark/results.png when it exists.
# `make_figures.sh --chart-only` does step 4 alone (after a run of the benchmark).
# Environment: ISM_FIGURE_BUILD_DIR (scratch directory, default $TMPDIR/ism_doc_figures),
# ISM_DATA_TARBALL (default /usr/share/doc/libcgal-dev/data.tar.gz), ISM_FIGURE_DATA_EXE.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
work="${ISM_FIGURE_BUILD_DIR:-${TMPDIR:-/tmp}/ism_doc_figures}"
tarball="${ISM_DATA_TARBALL:-/usr/share/doc/libcgal-dev/data.tar.gz}"
python=/usr/bin/python3
mkdir -p "$work/data" "$work/out" "$here/fig"

copy_chart() {
  local chart="$root/benchmark/results.png"
  if [ -f "$chart" ]; then
    "$python" "$here/figures/render_figures.py" --copy-chart "$chart" "$here/fig/benchmark_results.png"
  else
    echo "note: $chart does not exist yet (run the benchmark); fig/benchmark_results.png not updated" >&2
  fi
}
if [ "${1:-}" = "--chart-only" ]; then
  copy_chart
  exit 0
fi

for m in bunny00.off knot1.off; do
  if [ ! -f "$work/data/meshes/$m" ]; then
    [ -f "$tarball" ] || { echo "error: $tarball not found (apt-get install libcgal-demo)" >&2; exit 1; }
    tar -xzf "$tarball" -C "$work/data" --strip-components=1 "data/meshes/$m"
  fi
done

exe="${ISM_FIGURE_DATA_EXE:-}"
if [ -z "$exe" ]; then
  cmake -S "$here/figures" -B "$work/build" -DCMAKE_BUILD_TYPE=Release >"$work/cmake.log"
  cmake --build "$work/build" --target ism_doc_figure_data -j"$(nproc)"
  exe="$work/build/ism_doc_figure_data"
fi

"$exe" "$work/data/meshes" "$work/out"
"$python" "$here/figures/render_figures.py" "$work/out" "$here/fig"
cp "$work/out/stats.txt" "$here/fig/figure_data_stats.txt"

copy_chart
echo "figures written to $here/fig"
