#!/usr/bin/python3
"""Sweeps the sampling density on one mesh for ISM and Poisson and writes density.md.

The benchmark (run_benchmark.py) compares methods at the paper's sizes and the survey
(run_survey.py) runs ISM on many shapes at one size; this sweep asks how few points each
method needs: one closed mesh of libcgal-demo's data (default bunny00), sampled by N
area-weighted points without normals for several N and seeds, reconstructed by ISM
(package defaults) and by Poisson with jet normals oriented by an MST (the usual
unoriented-input route in CGAL), scored by benchmark_reconstruction (one process per run).

  /usr/bin/python3 run_density.py --build <cmake build dir> [--tarball data.tar.gz]
                                  [--out DIR] [--mesh bunny00] [--points 4000,8000,...]
                                  [--seeds 1,2,3] [--methods ism,poisson_jet_mst]
                                  [--noise F] [--nonuniform R] [--name density]

--noise adds gaussian noise of F times the diagonal to the samples: with one size and many
seeds it measures how often a noise level gives the right surface (the robustness tests
run one sampling per case). --nonuniform R keeps all samples on one half of the surface (x
above the median) and every R-th on the other, as the robustness test `nonuniform` does
(--points 65454 --nonuniform 10: its 36k points).

Outputs in --out (default: the benchmark/ directory): NAME.md, NAME.jsonl.
"""

import argparse
import json
import os
import sys
import tempfile
import time

from run_benchmark import run_case  # one process per run, killed with its group on timeout
from run_survey import benchmark_executable, extract, pct

HERE = os.path.dirname(os.path.abspath(__file__))
LABELS = {"ism": "ISM (defaults)", "poisson_jet_mst": "Poisson + jet + MST"}


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", help="CMake build directory (with the benchmark built)")
    ap.add_argument("--tarball", default="/usr/share/doc/libcgal-dev/data.tar.gz")
    ap.add_argument("--out", default=os.path.dirname(HERE), help="output directory (default: benchmark/)")
    ap.add_argument("--mesh", default="bunny00")
    ap.add_argument("--points", default="4000,6000,8000,12000,20000,36000")
    ap.add_argument("--seeds", default="1,2,3")
    ap.add_argument("--methods", default="ism,poisson_jet_mst")
    ap.add_argument("--timeout", type=float, default=300)
    ap.add_argument("--noise", type=float, default=0.0, help="gaussian noise, as a fraction of the diagonal")
    ap.add_argument("--nonuniform", type=int, default=1,
                    help="keep every R-th sample on the half x < median: that half R times sparser (1: uniform)")
    ap.add_argument("--name", default="density", help="base name of the outputs")
    ap.add_argument("--replot", action="store_true", help="rewrite NAME.md from NAME.jsonl without running")
    args = ap.parse_args()
    if not args.replot and not args.build:
        ap.error("--build is required (or --replot)")
    return args


def main():
    args = parse_args()
    sizes = [int(n) for n in args.points.split(",")]
    seeds = [int(s) for s in args.seeds.split(",")]
    methods = args.methods.split(",")
    started = time.strftime("%Y-%m-%d %H:%M")
    rows = []
    jsonl = os.path.join(args.out, args.name + ".jsonl")
    if args.replot:
        with open(jsonl) as f:
            rows = [json.loads(line) for line in f if line.strip()]
        write_markdown(args, rows, started + ", replotted")
        return
    exe = benchmark_executable(args.build, "run_density.py")
    with tempfile.TemporaryDirectory(prefix="ism_density_") as work:
        extract(args.tarball, [args.mesh], work)
        mesh = os.path.join(work, args.mesh + ".off")
        for n in sizes:
            for m in methods:
                for s in seeds:
                    cmd = [exe, "--method", m, "--mesh", mesh, "--points", str(n), "--seed", str(s), "--case", args.mesh,
                           "--noise", repr(args.noise), "--nonuniform", str(args.nonuniform)]
                    r = run_case(cmd, args.timeout, {"method": m, "case": args.mesh, "n_points": n, "seed": s,
                                                     "noise": args.noise, "nonuniform": args.nonuniform})
                    rows.append(r)
                    print("%-16s %6d seed %d %s" % (m, n, s, {k: r.get(k) for k in ("status", "genus", "inout_far")}),
                          flush=True)
    os.makedirs(args.out, exist_ok=True)
    with open(jsonl, "w") as f:
        for r in rows:
            f.write(json.dumps(r) + "\n")
    write_markdown(args, rows, started)


def write_markdown(args, rows, started):
    """NAME.md: one row per size and method, over the seeds found in `rows`."""
    sizes = sorted({r["n_points"] for r in rows})
    methods = [m for m in args.methods.split(",") if any(r["method"] == m for r in rows)]
    seeds = sorted({r["seed"] for r in rows})
    level = args.noise or (rows[0].get("noise") or 0 if rows else 0)
    noise = (", gaussian noise of %g %% of the diagonal" % (100 * level)) if level > 0 else ""
    thin = (rows[0].get("nonuniform") or 1) if rows else args.nonuniform
    if thin > 1:
        noise += (", then one half of them (x below the median) thinned to one sample in %d, the other half kept: "
                  "N - N/2 + N/%d points in all" % (thin, 2 * thin))
    title = ("how often each method is right at %g %% noise" % (100 * level)) if level > 0 \
        else ("how often each method is right on one half %d times sparser" % thin) if thin > 1 \
        else "how few points each method needs"
    kind = "noise" if level > 0 else "non-uniform" if thin > 1 else "density"
    md = ["# ISM_reconstruction_3 %s sweep: %s" % (kind, title), "",
          "`%s.off` (libcgal-demo's data tarball) sampled by N area-weighted points without normals%s, seeds %s, "
          "reconstructed by each method and scored by `benchmark_reconstruction` "
          "(`benchmark/ISM_reconstruction_3/run_density.py`, %s). Poisson gets the normals CGAL users would give "
          "it for unoriented points: jet-estimated, oriented by a minimum spanning tree." %
          (args.mesh, noise, compact(seeds), started), "",
          "*right topology*: runs with the components and genus of the truth; *genus*: per seed; *far %*: share of "
          "the uniform queries farther than 1 % of the diagonal from the truth that are on the truth's side, worst "
          "and mean over the seeds; *mean dist*: symmetric surface distance in % of the diagonal (mean over the "
          "seeds); *all far right*: runs with the right topology and every far query on the truth's side (what "
          "the robustness tests ask of one sampling); time: the reconstruction alone (2 cores), mean.", "",
          "| points | method | right topology | all far right | genus | far % worst / mean | mean dist % | time (s) |",
          "|---|---|---|---|---|---|---|---|"]
    for n in sizes:
        for m in methods:
            runs = [r for r in rows if r["n_points"] == n and r["method"] == m]
            ok = [r for r in runs if r.get("status") == "ok"]
            if not ok:
                md.append("| %s | %s | 0 of %d | 0 | | | | |" % ("{:,}".format(n), LABELS.get(m, m), len(runs)))
                continue
            right = [r for r in ok if r["genus"] == r["truth_genus"] and r["components"] == r["truth_components"]]
            # an open output (Poisson, now and then) has no inside: no in/out score
            far = [r["inout_far"] for r in ok if r.get("inout_far") is not None]
            perfect = [r for r in right if r.get("inout_far") == 1.0]
            md.append("| %s | %s | %d of %d | %d | %s | %s / %s | %.3f | %.2f |" % (
                "{:,}".format(n), LABELS.get(m, m), len(right), len(runs), len(perfect),
                ", ".join(str(r["genus"]) if r.get("status") == "ok" else r.get("status") for r in runs),
                pct(min(far) if far else None, 3), pct(sum(far) / len(far) if far else None, 3),
                mean_pct([r.get("dist_mean") for r in ok]), sum(r["time_total"] for r in ok) / len(ok)))
    with open(os.path.join(args.out, args.name + ".md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("wrote %s" % os.path.join(args.out, args.name + ".md"))


def mean_pct(values):
    values = [v for v in values if v is not None]
    return 100.0 * sum(values) / len(values) if values else float("nan")


def compact(seeds):
    """1, 2, ..., 30 as "1-30" when consecutive: the title stays short for many seeds."""
    if len(seeds) > 3 and seeds == list(range(seeds[0], seeds[0] + len(seeds))):
        return "%d-%d" % (seeds[0], seeds[-1])
    return ", ".join(map(str, seeds))


if __name__ == "__main__":
    main()
