#!/usr/bin/python3
"""Runs benchmark_reconstruction over methods x cases and writes results.md and results.png.

One process per (method, case): wall time and peak memory belong to one method. Each run
has a time limit; a run that hangs is killed and reported as a "timeout" row. Every run of
a case samples the same input (same mesh, size, noise and seed).

  /usr/bin/python3 run_benchmark.py --build <cmake build dir> [--out DIR] [--quick]
                                    [--methods ism,poisson_jet_mst] [--cases bunny,knot]
                                    [--timeout S] [--queries Q] [--samples K]
  /usr/bin/python3 run_benchmark.py --replot results.jsonl [--out DIR] [--methods ...] [--cases ...]

--quick: bunny and eight at 5,000 points, every method, 120 s limit per run; exits with a
non-zero status if any method did not run or produced no scores (a CTest test).
Outputs in --out (default: the benchmark/ directory): results.md, results.png (if
matplotlib is there), results.jsonl (one JSON line per run, as printed by the program).
--replot: runs nothing; rewrites results.md and results.png in --out from the runs saved in a
results.jsonl (copy it elsewhere first if --out is its own directory: it is not rewritten).
Give it the --quick, --timeout, --queries and --samples of the run that wrote the file, which
the tables' text quotes.
"""

import argparse
import json
import math
import os
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))

METHODS = ["ism", "ism_paper", "poisson_jet_mst", "poisson_jet_ism", "poisson_oracle", "advancing_front",
           "scale_space", "alpha_wrap"]

METHOD_LABEL = {
    "ism": "ISM (package defaults)",
    "ism_paper": "ISM (paper settings)",
    "poisson_jet_mst": "Poisson + jet + MST",
    "poisson_jet_ism": "Poisson + jet + ISM orientation",
    "poisson_oracle": "Poisson, true normals",
    "advancing_front": "Advancing front",
    "scale_space": "Scale space",
    "alpha_wrap": "Alpha wrap",
}

# name, mesh file, number of points, gaussian noise (fraction of the diagonal), close holes,
# description
FULL_CASES = [
    ("bunny", "bunny00.off", 35947, 0.0, False, "bunny00.off"),
    ("knot", "knot1.off", 100000, 0.0, False, "knot1.off"),
    ("dragon", "ChineseDragon-10kv.off", 437645, 0.0, True,
     "ChineseDragon-10kv.off, holes filled for the ground truth"),
    ("bunny_noise_0.25", "bunny00.off", 35947, 0.0025, False, "bunny00.off, gaussian noise sigma = 0.25 % of the diagonal"),
    ("bunny_noise_0.5", "bunny00.off", 35947, 0.005, False, "bunny00.off, gaussian noise sigma = 0.5 % of the diagonal"),
    ("eight", "eight.off", 50000, 0.0, False, "eight.off (genus 2)"),
    ("3torus", "3torus.off", 50000, 0.0, False, "3torus.off (genus 3)"),
]

QUICK_CASES = [
    ("bunny_5k", "bunny00.off", 5000, 0.0, False, "bunny00.off"),
    ("eight_5k", "eight.off", 5000, 0.0, False, "eight.off (genus 2)"),
]


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", help="CMake build directory (required unless --replot)")
    ap.add_argument("--exe", help="benchmark_reconstruction (default: <build>/benchmark/ISM_reconstruction_3/...)")
    ap.add_argument("--data", help="directory of the meshes (default: <build>/data/meshes)")
    ap.add_argument("--out", default=os.path.dirname(HERE), help="output directory (default: benchmark/)")
    ap.add_argument("--quick", action="store_true", help="small sizes, fails if a method gives no scores")
    ap.add_argument("--methods", help="comma-separated subset of " + ",".join(METHODS))
    ap.add_argument("--cases", help="comma-separated subset of the case names")
    ap.add_argument("--timeout", type=float, help="seconds per run (default 600, quick 120)")
    ap.add_argument("--queries", type=int, help="in/out queries per run (default 30000, quick 20000)")
    ap.add_argument("--samples", type=int, help="distance samples per mesh (default 100000, quick 20000)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--replot", metavar="JSONL",
                    help="run nothing: rewrite results.md and results.png from a saved results.jsonl")
    args = ap.parse_args()
    if not args.build and not args.replot:
        ap.error("--build is required (unless --replot)")
    return args


def run_one(cmd, timeout):
    """Runs cmd in its own process group; returns (exit status or None on timeout, stdout,
    stderr, wall seconds, peak RSS in MB of that process from wait4)."""
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        t0 = time.monotonic()
        p = subprocess.Popen(cmd, stdout=out, stderr=err, start_new_session=True)
        timed_out = False
        while True:
            pid, status, ru = os.wait4(p.pid, os.WNOHANG)
            if pid != 0:
                break
            if time.monotonic() - t0 > timeout:
                timed_out = True
                os.killpg(p.pid, signal.SIGKILL)  # the group of the child we started
                pid, status, ru = os.wait4(p.pid, 0)
                break
            time.sleep(0.05)
        wall = time.monotonic() - t0
        code = os.waitstatus_to_exitcode(status)
        p.returncode = code  # reaped here: keep Popen from waiting again
        out.seek(0)
        err.seek(0)
        return (None if timed_out else code, out.read().decode(errors="replace"),
                err.read().decode(errors="replace"), wall, ru.ru_maxrss / 1024.0)


def run_case(cmd, timeout, identity):
    """Runs one benchmark_reconstruction command (run_one); returns its JSON line as a dict,
    or `identity` with a status of timeout, crash or failed, plus wall_process and rss_mb."""
    code, out, err, wall, rss = run_one(cmd, timeout)
    r = None
    for line in out.splitlines():
        line = line.strip()
        if line.startswith("{"):
            try:
                r = json.loads(line)
            except ValueError:
                pass
    if code is None:
        r = dict(identity, status="timeout")
    elif r is None:
        tail = err.strip().splitlines()[-1:] if err.strip() else []
        r = dict(identity, status="crash" if code < 0 else "failed",
                 error=("exit %d; " % code) + (tail[0] if tail else ""))
    elif code != 0 and r.get("status") == "ok":
        r["status"] = "failed"
        r["error"] = "exit %d" % code
    r["wall_process"] = wall
    r["rss_mb"] = rss
    return r


def has_scores(r):
    if r.get("status") != "ok":
        return False
    for k in ("dist_mean", "dist_max", "components", "genus"):
        v = r.get(k)
        if v is None or (isinstance(v, float) and not math.isfinite(v)):
            return False
    if r.get("closed") and r.get("inout") is None:
        return False
    return True


def fmt(v, scale=1.0, digits=3, pct=False):
    if v is None:
        return "—"
    x = v * scale
    if pct:
        return "%.*f" % (digits, x)
    return "%.*g" % (digits, x)


def fmt_time(r, timeout):
    if r.get("status") == "timeout":
        return "timeout (> %g s)" % timeout
    if r.get("status") != "ok":
        return r.get("status", "failed")
    return "%.2f" % r["time_total"]


def write_markdown(path, results, cases, methods, args, timeout, started, finished, loads, total_wall):
    by = {(r["case"], r["method"]): r for r in results}
    lines = ["# ISM_reconstruction_3 benchmark", ""]
    lines += summary_paragraph(by, cases, timeout)
    lines += [""]
    lines += [
        "Machine: %d cores, load average %s before and %s after the run; %s to %s, %.1f minutes in all "
        "(scoring included)%s. One process per method and case; the timings are wall-clock seconds of "
        "the method alone (sampling and scoring excluded), \"peak MB\" is the process's peak resident "
        "memory right after the method ran (before scoring; the input points and the ground-truth "
        "mesh it includes are a few MB). Per-run time limit: %g s."
        % (os.cpu_count() or 0, loads[0], loads[1], started, finished, total_wall / 60.0,
           " (quick set)" if args.quick else "", timeout),
        "",
        "Input: points sampled uniformly by area on the ground-truth mesh (seed %d, identical for every "
        "method), optionally moved by isotropic gaussian noise; only the coordinates are given to the "
        "methods, except *Poisson, true normals* which gets the sampler's exact face normals. "
        "*Poisson + jet + MST*: CGAL::jet_estimate_normals (k = 18) + CGAL::mst_orient_normals (k = 18; "
        "unoriented points removed as in CGAL's examples) + Poisson_reconstruction_function meshed as "
        "poisson_surface_reconstruction_delaunay does (spacing: compute_average_spacing, k = 6; "
        "sm_angle 20, sm_radius 30, sm_distance 0.375); jet and spacing use Parallel_if_available_tag. "
        "*Poisson + jet + ISM orientation*: the same, except that the jet normals are oriented by "
        "CGAL::ism_orient_normals (this package's in/out function, default parameters; the points it "
        "could not orient removed) instead of mst_orient_normals. "
        "*Advancing front*: advancing_front_surface_reconstruction defaults. *Scale space*: "
        "Scale_space_surface_reconstruction_3 defaults, increase_scale(4) as CGAL's example, mesh on "
        "the smoothed points. *Alpha wrap*: alpha_wrap_3 on the points, alpha = diagonal/100, "
        "offset = diagonal/3000. For Advancing front and Scale space, which output a triangle soup, the "
        "benchmark's own conversion of the soup into a Surface_mesh (stage \"to_mesh\" in results.jsonl) "
        "is not counted in their time; ISM's time includes its conversion." % args.seed,
        "",
        "Scores: *in/out* = share of %s uniform queries in the ground truth's bounding box (scaled by "
        "1.1) on the same side of the output as of the ground truth (only for closed outputs, else —); "
        "*far* = the same over queries farther than 1 %% of that box's diagonal from the ground truth; "
        "*mean/max dist* = symmetric surface distance (%s area-weighted samples on each mesh) in %% of "
        "the ground truth's bounding-box diagonal; components and genus of the output (for open "
        "outputs genus counts boundary cycles); *closed/manifold*: no border edge / valid 2-manifold "
        "(a triangle soup that needed splitting into a mesh counts as non-manifold); *flip* = share of "
        "oriented normals pointing against the true normal." % (fmt_int(args.queries), fmt_int(args.samples)),
        "",
    ]
    for (name, mesh, n, noise, close, desc) in cases:
        r0 = next((by[(name, m)] for m in methods if (name, m) in by and "truth_genus" in by[(name, m)]), None)
        truth = ""
        if r0:
            truth = " — ground truth: %d component(s), genus %d" % (r0["truth_components"], r0["truth_genus"])
        lines += ["## %s: %s, %s points%s" % (name, desc, fmt_int(n), truth), ""]
        lines += ["| method | time (s) | peak MB | in/out % | far % | mean dist % | max dist % | components "
                  "| genus | closed / manifold | flip % | speed-up vs Poisson+jet+MST |",
                  "|---|---|---|---|---|---|---|---|---|---|---|---|"]
        ref = by.get((name, "poisson_jet_mst"))
        for m in methods:
            r = by.get((name, m))
            if r is None:
                continue
            ok = r.get("status") == "ok"
            speed = "—"
            if ok and ref and ref.get("status") == "ok" and r["time_total"] > 0:
                sp = ref["time_total"] / r["time_total"]
                speed = ("%.1f×" if abs(sp - 10) >= 0.05 else "%.2f×") % sp
            elif ok and ref and ref.get("status") == "timeout":
                speed = "> %.1f×" % (timeout / r["time_total"])
            if ok:
                cm = "%s / %s" % ("yes" if r["closed"] else "no", "yes" if r["manifold"] else "no")
                lines.append("| %s | %s | %s | %s | %s | %s | %s | %d | %d | %s | %s | %s |" % (
                    METHOD_LABEL.get(m, m), fmt_time(r, timeout), "%.0f" % r["peak_mb"],
                    fmt(r.get("inout"), 100, 2, True), fmt(r.get("inout_far"), 100, 2, True),
                    fmt(r.get("dist_mean"), 100, 4, True), fmt(r.get("dist_max"), 100, 3, True),
                    r["components"], r["genus"], cm, fmt(r.get("flip_rate"), 100, 2, True), speed))
            else:
                why = r.get("error", "")
                lines.append("| %s | %s | %s | — | — | — | — | — | — | — | — | — |%s" % (
                    METHOD_LABEL.get(m, m), fmt_time(r, timeout),
                    "%.0f" % r["rss_mb"] if r.get("rss_mb") else "—",
                    (" " + why.replace("|", "/")) if why else ""))
        lines.append("")
    with open(path, "w") as f:
        f.write("\n".join(lines))


def fmt_int(n):
    return "{:,}".format(n) if n is not None else "?"


def summary_paragraph(by, cases, timeout):
    """Where ISM (defaults) meets the targets and where it does not, with the figures."""
    speed, acc, topo, orc, bullets = [], [], [], [], []
    for (name, mesh, n, noise, close, desc) in cases:
        i, p, o = by.get((name, "ism")), by.get((name, "poisson_jet_mst")), by.get((name, "poisson_oracle"))
        if not i or i.get("status") != "ok":
            bullets.append("- **%s**: ISM did not run (%s)." % (name, i.get("status") if i else "missing"))
            speed.append((name, False)); acc.append((name, False)); topo.append((name, False)); orc.append((name, False))
            continue
        parts = []
        right_topo = i["genus"] == i["truth_genus"] and i["components"] == i["truth_components"]
        topo.append((name, right_topo))
        parts.append("genus %d / %d component(s) (truth %d / %d)%s" % (
            i["genus"], i["components"], i["truth_genus"], i["truth_components"], "" if right_topo else " ✗"))
        if p and p.get("status") == "ok":
            s = p["time_total"] / i["time_total"]
            speed.append((name, s >= 10))
            parts.insert(0, "%.2f× faster than Poisson+jet+MST (%.2f s vs %.2f s)%s" % (
                s, i["time_total"], p["time_total"], "" if s >= 10 else " ✗"))
            better_d = i["dist_mean"] <= p["dist_mean"]
            better_io = (p.get("inout") is None) or (i.get("inout") is not None and i["inout"] >= p["inout"])
            acc.append((name, better_d and better_io))
            parts.append("mean distance %.4f %% vs %.4f %%%s, in/out %s %% vs %s %%%s" % (
                100 * i["dist_mean"], 100 * p["dist_mean"], "" if better_d else " ✗",
                fmt(i.get("inout"), 100, 2, True), fmt(p.get("inout"), 100, 2, True), "" if better_io else " ✗"))
        elif p:
            speed.append((name, True))
            acc.append((name, True))
            parts.insert(0, "Poisson+jet+MST %s (ISM %.2f s)" % (
                "timed out after %g s" % timeout if p.get("status") == "timeout" else "failed", i["time_total"]))
        if o and o.get("status") == "ok" and o["dist_mean"] > 0:
            ratio = i["dist_mean"] / o["dist_mean"]
            orc.append((name, ratio <= 1.2))
            parts.append("mean distance %.2f× the oracle Poisson's%s" % (ratio, "" if ratio <= 1.2 else " ✗"))
        bullets.append("- **%s**: %s." % (name, "; ".join(parts)))

    def tally(lst):
        good = [n for n, ok in lst if ok]
        bad = [n for n, ok in lst if not ok]
        return "%d of %d%s" % (len(good), len(lst), (" (falls short on: %s)" % ", ".join(bad)) if bad else "")

    # the paper's settings, in one sentence
    sp, tp, dr = [], [], []
    for (name, mesh, n, noise, close, desc) in cases:
        i, p = by.get((name, "ism_paper")), by.get((name, "poisson_jet_mst"))
        if i and i.get("status") == "ok":
            tp.append(i["genus"] == i["truth_genus"] and i["components"] == i["truth_components"])
            if p and p.get("status") == "ok":
                sp.append(p["time_total"] / i["time_total"])
                dr.append(i["dist_mean"] / p["dist_mean"])
    paper = ""
    if tp:
        paper = (" With the paper's settings (Settings::paper()) ISM is %s faster than Poisson+jet+MST, has the "
                 "right topology on %d of %d cases, and its mean distance is %s that of Poisson+jet+MST." % (
                     ("%.1f× to %.1f×" % (min(sp), max(sp))) if sp else "?", sum(tp), len(tp),
                     ("%.2f× to %.2f×" % (min(dr), max(dr))) if dr else "?"))
    text = ("**Summary (generated from the figures below).** Targets for ISM with the package defaults: "
            "≥ 10× faster than Poisson + jet normals + MST orientation — met on %s; equal or better accuracy "
            "(mean distance and in/out) than that Poisson — met on %s; right genus and number of components — "
            "met on %s; mean distance within 1.2× of Poisson with the true normals — met on %s. "
            "Per case (✗ marks a missed target):" % (tally(speed), tally(acc), tally(topo), tally(orc)))
    return [text, ""] + bullets + ([""] + [paper.strip()] if paper else []) + notes(by, cases)


def notes(by, cases):
    """Remarks on the other methods' rows, generated from the figures."""
    out = []
    aw = [(c[0], by[(c[0], "alpha_wrap")]) for c in cases if by.get((c[0], "alpha_wrap"), {}).get("status") == "ok"]
    bad = [(n, r) for n, r in aw if r.get("inout") is not None and r["inout"] < 0.95 and r.get("volume_ratio") is not None]
    if bad:
        out.append("- *Alpha wrap* (alpha = diagonal/100) on %s: closed, but it encloses only %s of the true volume: "
                   "it got inside the shape through gaps of the sampling and wrapped the points from inside "
                   "too (a thin shell around the points; the passages are its handles), so its in/out counts the "
                   "inside as outside." % (", ".join(n for n, r in bad),
                                           ", ".join("%.1f %%" % (100 * r["volume_ratio"]) for n, r in bad)))
    ss = [c[0] for c in cases if by.get((c[0], "scale_space"), {}).get("status") == "ok"
          and not by[(c[0], "scale_space")]["manifold"]]
    if ss:
        out.append("- *Scale space*: CGAL's default alpha-shape mesher returns a triangle soup that is not a "
                   "2-manifold (%s); facets given twice are kept once, and turning the rest into a Surface_mesh "
                   "splits it at its non-manifold edges and vertices, so its *components* and *genus* columns "
                   "count those pieces, not the surface's topology; its distances are valid." % ", ".join(ss))
    for m, label, step in (("poisson_jet_mst", "Poisson + jet + MST", "MST orientation"),
                           ("poisson_jet_ism", "Poisson + jet + ISM orientation", "ism_orient_normals")):
        fl = [(c[0], by[(c[0], m)]["flip_rate"]) for c in cases
              if by.get((c[0], m), {}).get("status") == "ok" and (by[(c[0], m)].get("flip_rate") or 0) > 0.01]
        if fl:
            out.append("- *%s*: %s left %s of the normals opposed to the truth on %s." % (
                label, step, " / ".join("%.1f %%" % (100 * f) for n, f in fl), ", ".join(n for n, f in fl)))
    af = [c[0] for c in cases if by.get((c[0], "advancing_front"), {}).get("status") == "ok"
          and not by[(c[0], "advancing_front")]["closed"]]
    if af:
        out.append("- *Advancing front* interpolates the points (hence its small distances) but leaves boundaries "
                   "on %s: no in/out score there; for open outputs the genus column uses the boundary cycles." % ", ".join(af))
    return (["", "Notes on the other methods:", ""] + out) if out else []


def write_chart(path, results, cases, methods):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import numpy as np
    except ImportError as e:
        print("no chart: %s" % e, file=sys.stderr)
        return False
    ok = [r for r in results if r.get("status") == "ok"]
    case_names = [c[0] for c in cases]
    fig, axes = plt.subplots(1, 3, figsize=(19, 6))
    markers = "os^vD<>ph"
    # 1. time vs number of points (noise-free cases joined by a line)
    ax = axes[0]
    for k, m in enumerate(methods):
        rs = [r for r in ok if r["method"] == m]
        if not rs:
            continue
        clean = [r for r in rs if r.get("noise", 0) == 0]
        noisy = [r for r in rs if r.get("noise", 0) != 0]
        # markers: every noise-free case; line: geometric mean of the cases of each size
        sizes = sorted(set(r["n_points"] for r in clean))
        gm = [math.exp(sum(math.log(max(r["time_total"], 1e-6)) for r in clean if r["n_points"] == n)
                       / sum(1 for r in clean if r["n_points"] == n)) for n in sizes]
        line, = ax.plot(sizes, gm, label=METHOD_LABEL.get(m, m))
        ax.plot([r["n_points"] for r in clean], [r["time_total"] for r in clean], linestyle="none",
                marker=markers[k % len(markers)], color=line.get_color())
        if noisy:
            ax.plot([r["n_points"] for r in noisy], [r["time_total"] for r in noisy], linestyle="none",
                    marker=markers[k % len(markers)], color=line.get_color(), mfc="none")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("number of points")
    ax.set_ylabel("time (s)")
    ax.set_title("Method time vs number of points (hollow: noisy inputs)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    # 2. mean distance per case; 3. in/out error per case (grouped bars)
    width = 0.8 / max(1, len(methods))
    x = np.arange(len(case_names))
    for ax, key, title, f in (
            (axes[1], "dist_mean", "Mean symmetric distance (% of diagonal)", lambda v: 100 * v),
            (axes[2], "inout", "In/out error (% of queries; closed outputs only)", lambda v: max(100 * (1 - v), 1e-3))):
        for k, m in enumerate(methods):
            vals = []
            for c in case_names:
                r = next((r for r in ok if r["method"] == m and r["case"] == c), None)
                v = r.get(key) if r else None
                vals.append(f(v) if v is not None else np.nan)
            ax.bar(x - 0.4 + width * (k + 0.5), vals, width, label=METHOD_LABEL.get(m, m))
        ax.set_yscale("log")
        ax.set_xticks(x)
        ax.set_xticklabels(case_names, rotation=30, ha="right")
        ax.set_title(title)
        ax.grid(True, axis="y", which="both", alpha=0.3)
    axes[1].legend(fontsize=7)
    axes[2].text(0.01, 0.99, "missing bar: open output, failure or timeout", transform=axes[2].transAxes,
                 va="top", fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return True


def replot(args, cases, methods):
    """Rewrites results.md and results.png from the runs saved in args.replot."""
    with open(args.replot) as f:
        saved = [json.loads(line) for line in f if line.strip().startswith("{")]
    names = set(r.get("case") for r in saved)
    if not args.cases:  # the cases of the file, in the order of the lists above
        seen = set()
        cases = [c for c in FULL_CASES + QUICK_CASES if c[0] in names and not (c[0] in seen or seen.add(c[0]))]
    wanted_c, wanted_m = set(c[0] for c in cases), set(methods)
    results = [r for r in saved if r.get("case") in wanted_c and r.get("method") in wanted_m]
    if not results:
        sys.exit("no run of the selected methods and cases in %s" % args.replot)
    methods = [m for m in methods if any(r["method"] == m for r in results)]
    timeout = args.timeout or (120.0 if args.quick else 600.0)
    loads = ["%.2f" % r["load_before"] if r.get("load_before") is not None else "?" for r in (results[0], results[-1])]
    finished = time.strftime("%Y-%m-%d %H:%M", time.localtime(os.path.getmtime(args.replot)))
    total_wall = sum(r.get("wall_process", 0) for r in results)
    os.makedirs(args.out, exist_ok=True)
    md = os.path.join(args.out, "results.md")
    write_markdown(md, results, cases, methods, args, timeout, "?", finished, loads, total_wall)
    chart = write_chart(os.path.join(args.out, "results.png"), results, cases, methods)
    print("re-rendered %d runs (%s; %s) from %s: wrote %s%s" % (
        len(results), ", ".join(c[0] for c in cases), ", ".join(methods), args.replot, md,
        " and results.png" if chart else ""))
    return 0


def main():
    args = parse_args()
    cases = QUICK_CASES if args.quick else FULL_CASES
    if args.cases:
        wanted = args.cases.split(",")
        allc = {c[0]: c for c in FULL_CASES + QUICK_CASES}
        unknown = [w for w in wanted if w not in allc]
        if unknown:
            sys.exit("unknown case(s): %s" % ", ".join(unknown))
        cases = [allc[w] for w in wanted]
    methods = args.methods.split(",") if args.methods else METHODS
    unknown = [m for m in methods if m not in METHODS]
    if unknown:
        sys.exit("unknown method(s): %s" % ", ".join(unknown))
    timeout = args.timeout or (120.0 if args.quick else 600.0)
    args.queries = args.queries or (20000 if args.quick else 30000)
    args.samples = args.samples or (20000 if args.quick else 100000)
    if args.replot:
        return replot(args, cases, methods)
    exe = args.exe or os.path.join(args.build, "benchmark", "ISM_reconstruction_3", "benchmark_reconstruction")
    data = args.data or os.path.join(args.build, "data", "meshes")
    if not os.access(exe, os.X_OK):
        sys.exit("not an executable: %s (build the benchmark_reconstruction target)" % exe)
    os.makedirs(args.out, exist_ok=True)

    results = []
    started = time.strftime("%Y-%m-%d %H:%M")
    load0 = "%.2f" % os.getloadavg()[0]
    t_all = time.monotonic()
    jsonl = open(os.path.join(args.out, "results.jsonl"), "w")
    for (name, mesh, n, noise, close, desc) in cases:
        mesh_path = os.path.join(data, mesh)
        for m in methods:
            cmd = [exe, "--method", m, "--mesh", mesh_path, "--points", str(n), "--noise", repr(noise),
                   "--seed", str(args.seed), "--case", name, "--samples", str(args.samples),
                   "--queries", str(args.queries)]
            if close:
                cmd.append("--close-holes")
            load = os.getloadavg()[0]
            r = run_case(cmd, timeout, {"method": m, "case": name, "n_points": n, "noise": noise})
            wall = r["wall_process"]
            r["load_before"] = load
            results.append(r)
            jsonl.write(json.dumps(r) + "\n")
            jsonl.flush()
            if r.get("status") == "ok":
                print("%-16s %-16s %8.2f s %7.0f MB  inout %s  dist %.4f%%  genus %d  comps %d  (process %.1f s, load %.1f)"
                      % (name, m, r["time_total"], r["peak_mb"], fmt(r.get("inout"), 100, 2, True),
                         100 * r["dist_mean"], r["genus"], r["components"], wall, load), flush=True)
            else:
                print("%-16s %-16s %s %s (process %.1f s)" % (name, m, r["status"], r.get("error", ""), wall),
                      flush=True)
    jsonl.close()
    total_wall = time.monotonic() - t_all
    finished = time.strftime("%Y-%m-%d %H:%M")
    load1 = "%.2f" % os.getloadavg()[0]
    write_markdown(os.path.join(args.out, "results.md"), results, cases, methods, args, timeout, started,
                   finished, (load0, load1), total_wall)
    write_chart(os.path.join(args.out, "results.png"), results, cases, methods)
    print("total %.1f min; wrote %s" % (total_wall / 60.0, os.path.join(args.out, "results.md")))

    if args.quick:
        bad = [(r["case"], r["method"], r.get("status")) for r in results if not has_scores(r)]
        if bad:
            for c, m, s in bad:
                print("FAILED: %s on %s: %s" % (m, c, s), file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
