#!/usr/bin/env bash
# The main job: reconstructs the Stanford bunny from 36,000 points WITHOUT normals.
#
#   bash scripts/run_main.sh [extra ism_reconstruct options, e.g. --paper or --seed 2]
#
# 1. installs the missing Debian packages (scripts/install_deps.sh);
# 2. configures a Release build in build/ (which extracts the meshes into build/data/meshes)
#    and builds only ism_reconstruct and sample_mesh_points (target ism_tools, in parallel);
# 3. samples 36,000 points on bunny00.off (area-weighted, seed 1, no normals) into
#    out/bunny_points.xyz;
# 4. runs ism_reconstruct: out/bunny.off (the surface) and out/bunny_tets.vtu (the leaves of
#    the triangulation with per-vertex sign and distance, for ParaView);
# 5. renders out/bunny.png: the points beside the reconstructed surface (VTK offscreen
#    under xvfb-run when it is installed and there is no display, matplotlib otherwise);
# 6. prints where the results are and the tool's summary (also kept in out/summary.txt).
#
# Environment: ISM_BUILD_DIR (default build/), ISM_OUT_DIR (default out/),
# ISM_JOBS (parallel compile jobs, default nproc), ISM_POINTS (default 36000).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${ISM_BUILD_DIR:-$root/build}"
out="${ISM_OUT_DIR:-$root/out}"
jobs="${ISM_JOBS:-$(nproc)}"
npoints="${ISM_POINTS:-36000}"
now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'; }

echo "== dependencies"
bash "$root/scripts/install_deps.sh"

echo "== build (Release, $build)"
t=$(now)
mkdir -p "$build"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >"$build/configure.log" 2>&1 ||
  { cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j"$jobs" --target ism_tools  # ism_reconstruct and sample_mesh_points
build_time=$(elapsed "$t")
bin="$build/examples/ISM_reconstruction_3"
mesh="$build/data/meshes/bunny00.off"
[ -s "$mesh" ] || { echo "error: $mesh is missing (libcgal-demo's data tarball)"; exit 1; }

echo "== sample $npoints points on bunny00.off"
mkdir -p "$out"
"$bin/sample_mesh_points" --seed 1 "$mesh" "$npoints" "$out/bunny_points.xyz"

echo "== reconstruct"
t=$(now)
"$bin/ism_reconstruct" "$out/bunny_points.xyz" "$out/bunny.off" --tets "$out/bunny_tets.vtu" "$@" \
  >"$out/summary.txt"
run_time=$(elapsed "$t")

echo "== render"
t=$(now)
render=(/usr/bin/python3 "$root/scripts/render_result.py" "$out/bunny_points.xyz" "$out/bunny.off"
        "$out/bunny.png" --title "ism_reconstruct: bunny00.off, $npoints points without normals")
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
  # Debian's VTK is built for X only: a virtual X server gives it an offscreen context
  xvfb-run -a "${render[@]}" --backend vtk 2>"$out/render.log" || "${render[@]}" --backend matplotlib
else
  "${render[@]}"
fi
render_time=$(elapsed "$t")

echo
echo "== results"
echo "points:          $out/bunny_points.xyz"
echo "surface:         $out/bunny.off"
echo "tetrahedra:      $out/bunny_tets.vtu (per-vertex fields sign and distance; open in ParaView)"
echo "picture:         $out/bunny.png"
echo "summary:         $out/summary.txt"
echo "build: ${build_time} s, ism_reconstruct (whole process): ${run_time} s, render: ${render_time} s"
echo
cat "$out/summary.txt"
