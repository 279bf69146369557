#!/usr/bin/env bash
# End-to-end tests of the command-line tool ism_reconstruct (registered by tool_tests.cmake).
#
#   test_tool.sh ISM_RECONSTRUCT SAMPLE_MESH_POINTS MESH_DIR WORK_DIR
#
# - a small reconstruction (5,000 points sampled on MESH_DIR/sphere.off) succeeds, writes
#   the surface in every format and the tets, and its summary says 1 component, genus 0,
#   closed, manifold;
# - missing, empty, garbage, NaN/inf-holding, truncated and degenerate inputs exit 1 with
#   a message naming the file (and the line for text formats), leaving no output file;
# - a byte-order mark, extra columns, more records than a header announces (a warning) and a
#   long output name are accepted;
# - an output that is a directory or the input, or a stdout that cannot be written, exits 1;
# - unknown options, missing or malformed values and out-of-range parameters exit 2;
# - --help exits 0 and lists every option with its default; the tool's manual names each.
# - a run ended by a signal (HUP, INT, QUIT, TERM, PIPE) leaves no output and no temporary file.
set -u
tool=$1 sampler=$2 meshes=$3 work=$4
tool_doc=$(cd "$(dirname "$0")/../../doc/ISM_reconstruction_3" && pwd)/tool_and_examples.md
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1

failures=0 block_failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# "ok" only when no check failed since the last run
pass() { [ "$failures" -eq "$block_failures" ] && echo "ok:   $*"; }

# run NAME EXPECTED_CODE ARGS... : runs the tool, keeps stdout/stderr in NAME.out/.err
run() {
  local name=$1 expected=$2
  shift 2
  block_failures=$failures
  "$tool" "$@" >"$name.out" 2>"$name.err"
  local code=$?
  if [ "$code" -ne "$expected" ]; then
    fail "$name: exit code $code, expected $expected; stderr: $(head -c 300 "$name.err")"
    return 1
  fi
  return 0
}
# no temporary file may be left behind in the working directory
no_leftovers() {
  local left
  left=$(find . -maxdepth 2 -name '*.tmp[0-9]*' | head -3)
  [ -z "$left" ] || fail "$1: temporary files left: $left"
}
summary_has() {  # summary_has NAME KEY VALUE
  grep -Eq "^$2: +$3\$" "$1.out" || fail "$1: summary lacks '$2: $3' ($(grep "^$2:" "$1.out"))"
}

# ---------------------------------------------------------------------------------------
# 1. a small case that must work
# ---------------------------------------------------------------------------------------
"$sampler" --seed 3 "$meshes/sphere.off" 5000 sphere.xyz >/dev/null || { echo "FAIL: sampler"; exit 1; }
if run e2e 0 sphere.xyz sphere.off --tets sphere_tets.vtu; then
  [ -s sphere.off ] || fail "e2e: sphere.off missing or empty"
  [ -s sphere_tets.vtu ] || fail "e2e: sphere_tets.vtu missing or empty"
  head -1 sphere.off | grep -q OFF || fail "e2e: sphere.off is not an OFF file"
  grep -q 'Name="sign"' sphere_tets.vtu && grep -q 'Name="distance"' sphere_tets.vtu ||
    fail "e2e: the .vtu lacks the sign or distance field"
  summary_has e2e components 1
  summary_has e2e genus 0
  summary_has e2e closed yes
  summary_has e2e manifold yes
  grep -q "^input: .*(5000 points)" e2e.out || fail "e2e: summary lacks the number of points"
  for stage in refinement topology distance marching smoothing total; do
    grep -Eq "^(time \(s\):)? +$stage +[0-9.]+\$" e2e.out || fail "e2e: summary lacks the $stage time"
  done
  [ -s e2e.err ] && fail "e2e: stderr not empty although it is not a terminal: $(head -c 200 e2e.err)"
  no_leftovers e2e
  pass "5,000 sphere points: $(grep -E '^(components|genus|closed|manifold):' e2e.out | tr -s ' ' | tr '\n' ' ')"
fi

# the other output formats, the .mesh tets (+ .sol), the paper's settings, --quiet
if run formats 0 --quiet --paper --seed 2 sphere.xyz sphere.ply --tets sphere_tets.mesh; then
  [ -s sphere.ply ] && head -1 sphere.ply | grep -q ply || fail "formats: sphere.ply missing or not PLY"
  [ -s sphere_tets.mesh ] && [ -s sphere_tets.sol ] || fail "formats: sphere_tets.mesh or .sol missing"
  [ -s formats.out ] && fail "formats: --quiet printed a summary"
  no_leftovers formats
  pass "--paper, .ply output, .mesh/.sol tets, --quiet"
fi
run obj 0 --distance=nearest --smoothing-iterations 0 sphere.xyz sphere.obj && {
  grep -q '^f ' sphere.obj || fail "obj: sphere.obj has no face"
  summary_has obj closed yes
  pass ".obj output, --flag=value"
}
# binary STL: an 80-byte header, the triangle count, 50 bytes per triangle; as many
# triangles as the .off written above from the same points and flags
run stl 0 --distance=nearest --smoothing-iterations 0 sphere.xyz sphere.stl && {
  triangles=$(od -An -t u4 -j 80 -N 4 sphere.stl | tr -d ' ')
  [ "$(stat -c %s sphere.stl)" = "$((84 + 50 * triangles))" ] || fail "stl: sphere.stl is not a binary STL of $triangles triangles"
  [ "$triangles" = "$(grep -c '^f ' sphere.obj)" ] || fail "stl: $triangles triangles, the .obj has $(grep -c '^f ' sphere.obj)"
  summary_has stl closed yes
  pass ".stl output ($triangles triangles)"
}
# a mesh file's vertices are points: reconstruct from the .off written above
run off_input 0 sphere.off sphere_again.off && {
  summary_has off_input closed yes
  [ -s off_input.err ] && fail "off_input: a mesh with faces gave a message: $(head -c 200 off_input.err)"
  pass ".off input"
}
run ply_input 0 sphere.ply sphere_again2.off && { summary_has ply_input closed yes; pass "binary .ply input"; }
# OFF variants CGAL 5.5's reader refuses ("malformed or truncated"): the tool reads their
# points itself; exact coordinates give the .xyz run's surface, binary floats a closed one
n=$(wc -l <sphere.xyz)
{ echo COFF; echo "$n 0 0"; awk '{ print $0, 0.5, 0.25, 1, 1 }' sphere.xyz; } >colours.off
{ echo 4OFF; echo "$n 0 0"; awk '{ printf "%.17g %.17g %.17g 2\n", 2 * $1, 2 * $2, 2 * $3 }' sphere.xyz; } >homogeneous.off
{ echo "OFF $n 0 0"; cat sphere.xyz; } >header_counts.off
{ echo "nOFF # dimension next"; echo 3; echo "$n 0 0"; cat sphere.xyz; } >dimension.off
want=$(grep '^output:' e2e.out | grep -o '([0-9]* vertices')
for variant in colours homogeneous header_counts dimension; do
  run "off_$variant" 0 "$variant.off" "off_$variant.out.off" && {
    got=$(grep '^output:' "off_$variant.out" | grep -o '([0-9]* vertices')
    [ "$got" = "$want" ] || fail "off_$variant: $got, from the .xyz $want"
    pass ".off input, $(head -c 8 "$variant.off" | head -1): the .xyz run's $got"
  }
done
perl -ne 'BEGIN { @p = () } push @p, split; END { print "OFF BINARY\n", pack("N3", @p / 3, 0, 0), pack("f>*", @p) }' \
  sphere.xyz >binary.off
run off_binary 0 binary.off off_binary.out.off && {
  summary_has off_binary closed yes
  summary_has off_binary genus 0
  pass "binary .off input"
}
# far from unit size the points are reconstructed scaled by a power of two and the surface
# scaled back (normalization.h): the same surface as at unit size (a sphere at 1e150 found no
# inside, the bunny at 1e40 came out other)
for scale in 1e200 1e-200; do
  awk -v s=$scale '{ printf "%.17g %.17g %.17g\n", $1 * s, $2 * s, $3 * s }' sphere.xyz >scaled.xyz
  run "scaled_$scale" 0 scaled.xyz "scaled_$scale.off" && {
    summary_has "scaled_$scale" closed yes
    want=$(grep '^output:' e2e.out | grep -o '([0-9]* vertices') got=$(grep '^output:' "scaled_$scale.out" | grep -o '([0-9]* vertices')
    [ "$got" = "$want" ] || fail "scaled_$scale: $got, at unit size $want"
    pass "points scaled by $scale: the surface of unit size $got"
  }
done
# harmless in a file, and once refused: a UTF-8 byte-order mark (Windows editors) in every
# text format, `x y z intensity` (scanners) and 5 columns; the same points, the same surface
{ printf '\xef\xbb\xbf'; cat sphere.xyz; } >bom.xyz
{ printf '\xef\xbb\xbf'; cat header_counts.off; } >bom.off
{ printf '\xef\xbb\xbfply\nformat ascii 1.0\nelement vertex %d\n' "$n"
  printf 'property double %s\n' x y z; echo end_header; cat sphere.xyz; } >bom.ply
awk '{ print $0, 0.5 }' sphere.xyz >columns4.xyz
awk '{ print $0, 0.5, 7 }' sphere.xyz >columns5.xyz
want=$(grep '^output:' e2e.out | grep -o '([0-9]* vertices')
for file in bom.xyz bom.off bom.ply columns4.xyz columns5.xyz; do
  run "$file" 0 "$file" "$file.out.off" && {
    got=$(grep '^output:' "$file.out" | grep -o '([0-9]* vertices')
    [ "$got" = "$want" ] || fail "$file: $got, from the .xyz $want"
    pass "$file: the .xyz run's $got"
  }
done
# more vertex records than the header announces: the header decides (the format), with a
# warning on stderr, also with --quiet (as the tool's other warning)
{ echo OFF; echo "4000 0 0"; cat sphere.xyz; } >more_vertices.off
{ printf 'ply\nformat ascii 1.0\nelement vertex 4000\n'; printf 'property double %s\n' x y z; echo end_header
  cat sphere.xyz; } >more_vertices.ply
for file in more_vertices.off more_vertices.ply; do
  run "$file" 0 --quiet "$file" "$file.out.off" && {
    grep -q "warning: '$file', line [0-9]*: more .* than the .*header announces" "$file.err" ||
      fail "$file: no warning on stderr: $(head -c 300 "$file.err")"
    pass "$file: $(head -1 "$file.err")"
  }
done
# an underflowing value is a tiny one, for Settings::check() to judge (strtod's ERANGE
# refused it as out of range)
run underflow 0 --quiet --thin-handle-depth 1e-308 sphere.xyz underflow.off && pass "--thin-handle-depth 1e-308"
# the temporary .NAME.tmpPID.EXT of a legal 254-byte name went over 255 bytes
long=$(printf 'x%.0s' {1..250}).off
run long_name 0 --quiet sphere.xyz "$long" && {
  [ -s "$long" ] || fail "long_name: the 254-byte output is missing"
  no_leftovers long_name
  pass "a 254-byte output name"
}
# beyond 255 bytes it is refused before the work (the temporary's name is shortened)
if run name_too_long 1 sphere.xyz "x$long.off"; then
  grep -q "File name too long" name_too_long.err || fail "name_too_long: $(cat name_too_long.err)"
  pass "name_too_long: $(head -c 60 name_too_long.err)..."
fi

# unclamped (the paper's way), a box boundary vertex could stay inside after the global
# flip: 300 points on an open cylinder came out open with --no-clamp and with --paper
awk 'BEGIN { for (i = 0; i < 20; ++i) for (j = 0; j < 15; ++j) { a = 6.283185307 * (i + 0.5 * (j % 2)) / 20
             printf "%.9f %.9f %.9f\n", cos(a), sin(a), 2 * j / 14 - 1 } }' >cylinder.xyz
for flag in --no-clamp --paper; do
  run "unclamped$flag" 0 "$flag" cylinder.xyz "unclamped$flag.off" && {
    summary_has "unclamped$flag" closed yes
    pass "$flag on an open cylinder's points: a closed surface"
  }
done

# a pancake (ellipsoid of axes 1, 1, 0.02 or 0.01) whose sides are closer than about two
# point spacings: the surface misses most random points on it, or falls into pieces along
# evenly spread ones; either way a warning, also with --quiet (a thin plate's points came
# out in 125 pieces without a word)
awk 'BEGIN { srand(11); for (i = 0; i < 10000; ++i) { do { x = 2 * rand() - 1; y = 2 * rand() - 1; z = 2 * rand() - 1
               r = x * x + y * y + z * z } while (r > 1 || r < 1e-6)
             r = sqrt(r); printf "%.9f %.9f %.9f\n", x / r, y / r, 0.02 * z / r } }' >pancake_random.xyz
awk 'BEGIN { for (i = 0; i < 10000; ++i) { z = 1 - 2 * (i + 0.5) / 10000; r = sqrt(1 - z * z); a = 2.399963 * i
             printf "%.9f %.9f %.9f\n", r * cos(a), r * sin(a), 0.01 * z } }' >pancake_even.xyz
for case in "pancake_random % of the points lie in leaves the surface does not reach" \
            "pancake_even the surface fell into [0-9]* pieces"; do
  name=${case%% *} words=${case#* }
  run "$name" 0 --quiet "$name.xyz" "$name.off" && {
    grep -q "warning: [0-9]* \?$words.*: the points may be too sparse.*thinner than about two point spacings" "$name.err" ||
      fail "$name: no warning of a part too thin: $(head -c 300 "$name.err")"
    pass "$name: $(head -c 100 "$name.err")..."
  }
done

# ---------------------------------------------------------------------------------------
# 2. bad input: exit 1, the file (and the line) named, no output left
# ---------------------------------------------------------------------------------------
bad_input() {  # bad_input NAME FILE [LINE]: the tool must refuse FILE
  local name=$1 file=$2 line=${3:-}
  rm -f "$name.off" "$name.vtu"
  if run "$name" 1 "$file" "$name.off" --tets "$name.vtu"; then
    grep -qF "$file" "$name.err" || fail "$name: the message does not name $file: $(cat "$name.err")"
    if [ -n "$line" ]; then
      grep -q "line $line\b" "$name.err" || fail "$name: the message does not name line $line: $(cat "$name.err")"
    fi
    [ -e "$name.off" ] || [ -e "$name.vtu" ] && fail "$name: an output file was left behind"
    no_leftovers "$name"
    pass "$name: $(head -1 "$name.err")"
  fi
}

says() {  # says NAME WORD: the message of the bad input NAME holds WORD
  grep -qF -- "$2" "$1.err" || fail "$1: the message does not say '$2': $(cat "$1.err")"
}

bad_input missing does_not_exist.xyz
: >empty.xyz
bad_input empty_xyz empty.xyz
: >empty.off
bad_input empty_off empty.off
head -c 3000 /dev/urandom | tr -d '\n' >garbage.xyz; printf '\n' >>garbage.xyz
bad_input garbage_xyz garbage.xyz 1
printf 'this is not\na mesh\n' >garbage.off
bad_input garbage_off garbage.off 1
head -c 3000 /dev/urandom >garbage.ply
bad_input garbage_ply garbage.ply
{ head -n 4 sphere.xyz; echo "0.1 nan 0.2"; tail -n +5 sphere.xyz; } >nan.xyz
bad_input nan_xyz nan.xyz 5
{ head -n 9 sphere.xyz; echo "0.1 0.2 -inf"; tail -n +10 sphere.xyz; } >inf.xyz
bad_input inf_xyz inf.xyz 10
{ head -n 6 sphere.xyz; echo "0.1 0.2 zero"; tail -n +7 sphere.xyz; } >word.xyz
bad_input word_xyz word.xyz 7
# OFF (the data file, not the tool's output): header on line 1, counts on line 2,
# vertex k on line k + 3
cp "$meshes/sphere.off" mesh.off
awk 'NR == 10 { $2 = "nan" } { print }' mesh.off >nan.off
bad_input nan_off nan.off 10
# truncated: in the middle of a coordinate line, in the vertex list, in the face list
head -c $(($(stat -c %s sphere.xyz) - 25)) sphere.xyz >truncated.xyz
bad_input truncated_xyz truncated.xyz "$(wc -l <truncated.xyz | awk '{print $1 + 1}')"
{ echo 5000; cat sphere.xyz; } | head -n 2000 >counted.xyz
bad_input truncated_counted_xyz counted.xyz 1
head -n 100 mesh.off >truncated_vertices.off
bad_input truncated_off_vertices truncated_vertices.off 100
nv=$(sed -n 2p mesh.off | awk '{print $1}')
head -n $((nv + 2 + 50)) mesh.off >truncated_faces.off
bad_input truncated_off_faces truncated_faces.off $((nv + 52))
printf 'nOFF\n2\n3 0 0\n0 0\n1 0\n0 1\n' >plane.off
bad_input off_dimension_2 plane.off 2 && says off_dimension_2 "dimension 2"
{ echo 4OFF; echo "$n 0 0"; awk 'NR == 7 { print $0, 0; next } { print $0, 1 }' sphere.xyz; } >infinity.off
bad_input off_at_infinity infinity.off 9 && says off_at_infinity "at infinity"
printf 'OFF\n1000000000 0 0\n0 0 0\n' >announces.off
bad_input off_count_beyond_file announces.off 2 && says off_count_beyond_file "more than the file can hold"
printf 'OFF\n1000000000000 0 0\n0 0 0\n' >announces_1e12.off
bad_input off_count_1e12 announces_1e12.off 2 && says off_count_1e12 "more than the file can hold"
printf 'OFF\n3 10000000000 0\n0 0 0\n' >faces_1e10.off
bad_input off_face_count_1e10 faces_1e10.off 2 && says off_face_count_1e10 "too large"
# more vertex lines than announced, and faces: the first face is not one
{ echo OFF; echo "4000 1 0"; cat sphere.xyz; echo "3 0 1 2"; } >more_vertices_faces.off
bad_input off_more_vertices_faces more_vertices_faces.off 4003 &&
  says off_more_vertices_faces "more vertices than the 4000 the header announces?"
head -c 5000 binary.off >truncated_binary.off
bad_input off_binary_truncated truncated_binary.off && says off_binary_truncated "truncated"
if [ -s sphere.ply ]; then  # the binary PLY written above, cut in half
  head -c $(($(stat -c %s sphere.ply) / 2)) sphere.ply >truncated.ply
  bad_input truncated_ply truncated.ply
else
  fail "truncated_ply: no sphere.ply to truncate"
fi
# PLY headers CGAL 5.5's reader crashes on (integer or list coordinates, a property before
# any element) or trusts (a list count of 4e9 in a 100-byte file: 3.9 GB and a minute),
# and a property of unknown type, which it drops and then misreads the rest
ply_head='ply\nformat ascii 1.0\nelement vertex 3\n'
printf "${ply_head}property int x\nproperty int y\nproperty int z\nend_header\n0 0 0\n1 0 0\n0 1 0\n" >int.ply
bad_input ply_integer_coordinates int.ply && says ply_integer_coordinates "'x' is an integer"
printf "${ply_head}property list uchar float x\nproperty float y\nproperty float z\nend_header\n1 0 0 0\n1 1 0 0\n1 0 1 0\n" >list.ply
bad_input ply_list_coordinate list.ply && says ply_list_coordinate "'x' is a list"
printf 'ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\nend_header\n0\n' >property_first.ply
bad_input ply_property_before_element property_first.ply 3 && says ply_property_before_element "before any element"
printf "${ply_head}property float x\nproperty float y\nproperty int64 z\nend_header\n0 0 0\n1 0 0\n0 1 0\n" >int64.ply
bad_input ply_unknown_type int64.ply 6 && says ply_unknown_type "'int64'"
printf 'ply\nformat ascii 1.0\nelement vertex 1e16\nproperty float x\nend_header\n' >count_1e16.ply
bad_input ply_count_1e16 count_1e16.ply 3 && says ply_count_1e16 "more than any file holds"
# CGAL's reader fails on NaN in ASCII without saying where: vertex k on line k + 8
{ printf 'ply\nformat ascii 1.0\nelement vertex %d\n' "$n"; printf 'property double %s\n' x y z; echo end_header
  awk 'NR == 4 { $2 = "nan" } { print }' sphere.xyz; } >nan_ascii.ply
bad_input ply_ascii_nan nan_ascii.ply 11 && says ply_ascii_nan "NaN or infinite"
printf 'ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty list uint float w\nproperty float x\nproperty float y\nproperty float z\nend_header\n\x00\x28\x6b\xee\x00\x00\x00\x00' >list_count.ply
bad_input ply_list_count_4e9 list_count.ply && says ply_list_count_4e9 "4000000000 items"
# a named pipe: the scan and CGAL's reader each open the file, and a second open waits
# for a writer that has gone (it hung)
if mkfifo pipe.off 2>/dev/null; then
  bad_input pipe_input pipe.off && says pipe_input "not a regular file"
fi
# points that cannot bound a volume, and an unknown format
head -n 5 sphere.xyz >few.xyz
bad_input too_few_points few.xyz
awk '{ print $1, $2, 0 }' sphere.xyz >flat.xyz
bad_input coplanar_points flat.xyz
cp sphere.xyz points.foo
bad_input unknown_format points.foo
# the library's refusals name its parameters as C++ does; the tool's message names the flags
awk 'BEGIN { for (i = 0; i < 2000; ++i) print i / 2000, 0, 0; srand(28)
             for (i = 0; i < 20; ++i) print 10 * rand() - 5, 10 * rand() - 5, 10 * rand() - 5 }' >segment.xyz
bad_input segment_among_isolated_points segment.xyz && says segment_among_isolated_points "--keep-isolated-points keeps them"
if run memory_limit_small 1 sphere.xyz memory_limit_small.off --memory-limit 100000; then
  says memory_limit_small "raise --memory-limit"
  [ -e memory_limit_small.off ] && fail "memory_limit_small: an output file was left behind"
  pass "memory_limit_small: $(head -c 120 memory_limit_small.err)"
fi
for m in segment_among_isolated_points memory_limit_small; do
  grep -Eq 'remove_isolated_points|memory_limit' "$m.err" && fail "$m: the message names a C++ parameter: $(cat "$m.err")"
done
# an output that cannot be written is refused before the work
if run unwritable 1 sphere.xyz no_such_dir/out.off; then
  grep -q "no_such_dir/out.off" unwritable.err || fail "unwritable: the message does not name the output"
  pass "unwritable output: $(head -1 unwritable.err)"
fi
# an output that is a directory only failed at the final rename ("Is a directory"), after
# the work; the check before it says "it is a directory"
# (the .sol of a .mesh too)
mkdir -p directory.off directory.vtu directory.sol
for args in "sphere.xyz directory.off" "sphere.xyz dir_tets.off --tets directory.vtu" \
            "sphere.xyz dir_tets.off --tets directory.mesh"; do
  name=directory_${args##*.}
  if run "$name" 1 $args; then
    says "$name" "it is a directory"
    [ -e dir_tets.off ] && fail "$name: an output file was written"
    no_leftovers "$name"
    pass "$name: $(head -1 "$name.err")"
  fi
done
# an output that is the input replaced the points by the surface without a word
cp "$meshes/sphere.off" same.off
if run same_file 1 same.off same.off; then
  says same_file "it is the input file"
  cmp -s same.off "$meshes/sphere.off" || fail "same_file: the input was changed"
  no_leftovers same_file
  pass "same_file: $(head -1 same_file.err)"
fi
# a summary lost on a full disk exited 0
if [ -w /dev/full ]; then
  block_failures=$failures
  "$tool" sphere.xyz full.off >/dev/full 2>full.err
  code=$?
  [ "$code" -eq 1 ] || fail "stdout_full: exit code $code, expected 1"
  grep -q "cannot write the summary to stdout" full.err || fail "stdout_full: $(cat full.err)"
  pass "stdout_full: $(head -1 full.err)"
fi
# a parameter that stops the refinement is named, not only the points blamed; with the
# defaults (10 points) the message does not name any
run refinement_hint 1 --coplanarity-threshold 0.333 sphere.xyz hint.off && {
  says refinement_hint "no vertex was found inside"
  says refinement_hint "(--coplanarity-threshold 0.333)"
  pass "refinement_hint: ...$(grep -o '; the refinement.*' refinement_hint.err)"
}
head -n 10 sphere.xyz >ten.xyz
run no_refinement_hint 1 ten.xyz hint.off && {
  says no_refinement_hint "no vertex was found inside"
  grep -q "refinement parameters" no_refinement_hint.err && fail "no_refinement_hint: $(cat no_refinement_hint.err)"
  pass "no_refinement_hint: no parameter named with the defaults"
}

# ---------------------------------------------------------------------------------------
# 3. usage errors: exit 2, the option named
# ---------------------------------------------------------------------------------------
usage() {  # usage NAME WORD ARGS...: exit 2 and the message holds WORD
  local name=$1 word=$2
  shift 2
  rm -f usage.off
  if run "$name" 2 "$@"; then
    grep -qF -- "$word" "$name.err" || fail "$name: the message does not name '$word': $(cat "$name.err")"
    [ -e usage.off ] && fail "$name: an output file was left behind"
    no_leftovers "$name"
    pass "$name: $(head -1 "$name.err")"
  fi
}
usage unknown_flag --frobnicate --frobnicate sphere.xyz usage.off
usage missing_value --maximum-depth sphere.xyz usage.off --maximum-depth
usage not_a_number --maximum-depth --maximum-depth abc sphere.xyz usage.off
usage not_a_real --cooling-factor --cooling-factor 0.9x sphere.xyz usage.off
usage depth_out_of_range --maximum-depth --maximum-depth 0 sphere.xyz usage.off
usage cooling_out_of_range --cooling-factor --cooling-factor 2 sphere.xyz usage.off
usage margin_out_of_range --box-margin --box-margin=-1 sphere.xyz usage.off
usage negative_seed --seed --seed -1 sphere.xyz usage.off
usage huge_integer --sweeps --sweeps 99999999999999999999 sphere.xyz usage.off
usage nan_value --smoothing-lambda --smoothing-lambda nan sphere.xyz usage.off
usage real_overflow --thin-handle-depth --thin-handle-depth 1e400 sphere.xyz usage.off
usage bad_distance --distance --distance far sphere.xyz usage.off
usage switch_with_value --no-clamp --no-clamp=1 sphere.xyz usage.off
usage switch_with_value_2 --no-tangent-planes --no-tangent-planes=0 sphere.xyz usage.off
usage no_output OUTPUT sphere.xyz
usage bad_output_extension usage.step sphere.xyz usage.step
usage bad_tets_extension --tets sphere.xyz usage.off --tets usage.ele

# ---------------------------------------------------------------------------------------
# 4. --help: every option with its default
# ---------------------------------------------------------------------------------------
if run help 0 --help; then
  # one record per option: its line and the indented lines that continue it
  awk '/^  -/ { if (r != "") print r; r = $0; next } /^      / && r != "" { r = r " " $0; next }
       { if (r != "") print r; r = "" } END { if (r != "") print r }' help.out | tr -s ' ' >help.records
  for flag in --maximum-depth --min-points-per-cell --coplanarity-threshold --empty-cell-error \
              --initial-temperature --cooling-factor --sweeps --warm-start-interval --seed \
              --smoothing-iterations --smoothing-lambda --smoothing-mu --no-clamp --distance \
              --box-margin --minimum-island-fraction --thin-handle-depth --no-tangent-planes \
              --surface-refinement-passes --surface-refinement-tolerance --crossing-neighbors --coarser-refinements \
              --memory-limit --paper --tets --quiet; do
    grep -Eq -- "^ $flag\b.*\[[^]]+\]\$" help.records || fail "help: no entry for $flag ending with its [default]"
  done
  grep -Eq -- "^ -h, --help\b" help.records || fail "help: --help is not listed"
  grep -q "nearest-squared|nearest|plane" help.out || fail "help: the --distance choices are not listed"
  # the manual names every option (--keep-isolated-points had been left out of it)
  for flag in $(grep -Eo -- '^  --[a-z-]+' help.out); do
    grep -q -- "\`$flag" "$tool_doc" || fail "help: $flag is not in $tool_doc"
  done
  pass "--help lists every option with its default"
fi

# ---------------------------------------------------------------------------------------
# 5. a run ended by a signal leaves no output and no temporary file (SIGHUP, SIGQUIT and
#    SIGPIPE had left the empty temporaries of the outputs)
# ---------------------------------------------------------------------------------------
block_failures=$failures
# 50,000 points and 100,000 sweeps: far longer than the wait below, even on a fast machine
"$sampler" --seed 4 "$meshes/sphere.off" 50000 signal.xyz >/dev/null || fail "sampler: signal.xyz"
for sig in HUP INT QUIT TERM PIPE; do
  (ulimit -c 0; exec "$tool" --quiet --sweeps 100000 signal.xyz signal.off --tets signal.vtu) >signal.out 2>&1 &
  pid=$!
  # the run is under way once its temporaries exist (they are made first)
  for _ in $(seq 100); do
    [ -n "$(find . -maxdepth 1 -name '.signal.tmp*')" ] && break
    sleep 0.1
  done
  sleep 0.5
  kill -s "$sig" "$pid"
  wait "$pid" 2>/dev/null  # bash reports the signal itself otherwise
  code=$?
  [ "$code" -gt 128 ] || fail "signal $sig: exit code $code, expected the signal's"
  [ -e signal.off ] || [ -e signal.vtu ] && fail "signal $sig: an output was written"
  no_leftovers "signal $sig"
done
pass "a run ended by SIGHUP, SIGINT, SIGQUIT, SIGTERM or SIGPIPE leaves nothing behind"

echo
if [ "$failures" -ne 0 ]; then
  echo "$failures check(s) failed"
  exit 1
fi
echo "all tool checks passed"
