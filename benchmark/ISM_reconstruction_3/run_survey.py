#!/usr/bin/python3
"""Surveys ISM (package defaults) over the closed meshes of CGAL's data and writes survey.md.

Where the benchmark (run_benchmark.py) compares methods on a few cases, the survey runs one
method on many shapes, to show where the method fails: 30 closed meshes of libcgal-demo's
data tarball (data/meshes), each sampled by 36,000 area-weighted points without normals
(seed 1), reconstructed and scored by benchmark_reconstruction (one process per mesh).

  /usr/bin/python3 run_survey.py --build <cmake build dir> [--tarball data.tar.gz]
                                 [--out DIR] [--points N] [--meshes a,b,c]

Outputs in --out (default: the benchmark/ directory): survey.md, survey.jsonl.
"""

import argparse
import json
import os
import sys
import tarfile
import tempfile
import time

from run_benchmark import run_case  # one process per run, killed with its group on timeout

HERE = os.path.dirname(os.path.abspath(__file__))

# The closed meshes of data/meshes with at least 500 faces (3torus and the double torus,
# smaller, for their genus), one of each model (no refined or shuffled copies).
MESHES = ["3torus", "double-torus-example", "eight", "anchor", "rotor", "cactus", "spool", "pinion",
          "cube-meshed", "hand", "elk", "couplingdown", "blobby", "knot", "bones", "elephant", "cow", "knot1",
          "femur", "dino", "homer", "knot2", "bull", "fandisk", "cheese", "turbine", "camel", "man",
          "armadillo", "bunny00"]


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", required=True, help="CMake build directory (with the benchmark built)")
    ap.add_argument("--tarball", default="/usr/share/doc/libcgal-dev/data.tar.gz")
    ap.add_argument("--out", default=os.path.dirname(HERE), help="output directory (default: benchmark/)")
    ap.add_argument("--points", type=int, default=36000)
    ap.add_argument("--meshes", help="comma-separated subset of " + ",".join(MESHES))
    ap.add_argument("--timeout", type=float, default=300)
    return ap.parse_args()


def extract(tarball, names, into):
    wanted = {"data/meshes/%s.off" % n for n in names}
    with tarfile.open(tarball) as t:
        for m in t.getmembers():
            if m.name in wanted:
                m.name = os.path.basename(m.name)
                t.extract(m, into)
    missing = [n for n in names if not os.path.exists(os.path.join(into, n + ".off"))]
    if missing:
        sys.exit("run_survey.py: not in %s: %s" % (tarball, ", ".join(missing)))


def benchmark_executable(build, script):
    """benchmark_reconstruction in the CMake build directory `build`; exits naming `script` if absent."""
    exe = os.path.join(build, "benchmark", "ISM_reconstruction_3", "benchmark_reconstruction")
    if not os.path.exists(exe):
        sys.exit("%s: %s not found (build the target benchmark_reconstruction)" % (script, exe))
    return exe


def pct(x, digits=2):
    return "—" if x is None else ("%." + str(digits) + "f") % (100.0 * x)


def main():
    args = parse_args()
    names = args.meshes.split(",") if args.meshes else MESHES
    exe = benchmark_executable(args.build, "run_survey.py")
    started = time.strftime("%Y-%m-%d %H:%M")
    rows = []
    with tempfile.TemporaryDirectory(prefix="ism_survey_") as work:
        extract(args.tarball, names, work)
        for n in names:
            cmd = [exe, "--method", "ism", "--mesh", os.path.join(work, n + ".off"), "--points", str(args.points),
                   "--seed", "1", "--case", n]
            r = run_case(cmd, args.timeout, {"method": "ism", "case": n, "n_points": args.points, "noise": 0})
            rows.append(r)
            print("%-22s %s" % (n, {k: r.get(k) for k in ("status", "genus", "components", "inout_far", "time_total")}),
                  flush=True)
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "survey.jsonl"), "w") as f:
        for r in rows:
            f.write(json.dumps(r) + "\n")
    right = [r for r in rows if r.get("status") == "ok" and r.get("genus") == r.get("truth_genus")
             and r.get("components") == r.get("truth_components")]
    far_ok = [r for r in rows if r.get("status") == "ok" and r.get("inout_far") == 1]
    closed = [r for r in rows if r.get("closed") and r.get("manifold")]
    md = ["# ISM_reconstruction_3 survey: package defaults on %d closed meshes of CGAL's data" % len(rows), "",
          "Each mesh of `data/meshes` (libcgal-demo's data tarball) sampled by %s area-weighted points without "
          "normals (seed 1), reconstructed with the package defaults and scored by `benchmark_reconstruction` "
          "(`benchmark/ISM_reconstruction_3/run_survey.py`, %s). " % ("{:,}".format(args.points), started) +
          "Closed and 2-manifold: %d of %d; components and genus of the truth: %d of %d; every query farther than "
          "1 %% of the diagonal on the right side: %d of %d. A truth that intersects itself (bones, cow, elk, man, "
          "bull, camel) has a genus and an inside that are only approximately defined." %
          (len(closed), len(rows), len(right), len(rows), len(far_ok), len(rows)), "",
          "*in/out*: share of uniform queries in the truth's bounding box scaled by 1.1 on the truth's side; *far*: "
          "the same over the queries farther than 1 % of that box's diagonal from the truth; *mean dist*: symmetric "
          "surface distance in % of the truth's bounding-box diagonal; time: the reconstruction alone (2 cores).", "",
          "| mesh | truth components / genus | output components / genus | closed / manifold | in/out % | far % "
          "| mean dist % | time (s) | peak MB |",
          "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if r.get("status") != "ok":
            md.append("| %s | | | %s | | | | | |" % (r["case"], r.get("status")))
            continue
        wrong = r["genus"] != r["truth_genus"] or r["components"] != r["truth_components"] or r["inout_far"] != 1
        md.append("| %s%s | %d / %d | %d / %d | %s / %s | %s | %s | %.3f | %.2f | %.0f |" % (
            r["case"], " ✗" if wrong else "", r["truth_components"], r["truth_genus"], r["components"], r["genus"],
            "yes" if r["closed"] else "no", "yes" if r["manifold"] else "no", pct(r["inout"]),
            pct(r["inout_far"], 3), 100.0 * r["dist_mean"], r["time_total"], r["peak_mb"]))
    with open(os.path.join(args.out, "survey.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("wrote %s" % os.path.join(args.out, "survey.md"))


if __name__ == "__main__":
    main()
