#!/usr/bin/python3
"""Renders the figures of the ISM_reconstruction_3 user manual.

    render_figures.py <data dir> <fig dir>
    render_figures.py --copy-chart <png> <output png>


<data dir> holds what make_figure_data wrote (see make_figure_data.cpp); the PNGs go to
<fig dir>. Matplotlib only (Agg backend, no display): meshes are drawn by a small
painter's-algorithm renderer (orthographic view, faces sorted by depth, Lambert shading).
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection, PolyCollection  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

DPI = 90
MAX_BYTES = 300 * 1024
TOO_LARGE = []


def read_slice(path, with_values=False):
    """Lines 'level n x1 y1 [f1] ...' -> levels, list of (n,2) polygons, list of (n,) values."""
    levels, polys, values = [], [], []
    k = 3 if with_values else 2
    with open(path) as f:
        for line in f:
            a = line.split()
            if not a:
                continue
            n = int(a[1])
            c = np.array(a[2:2 + k * n], dtype=float).reshape(n, k)
            levels.append(int(a[0]))
            polys.append(c[:, :2])
            if with_values:
                values.append(c[:, 2])
    return np.array(levels), polys, values


def read_off(path):
    with open(path) as f:
        words = []
        for line in f:
            line = line.split("#")[0]
            words.extend(line.split())
    assert words[0].endswith("OFF")
    nv, nf = int(words[1]), int(words[2])
    i = 4
    v = np.array(words[i:i + 3 * nv], dtype=float).reshape(nv, 3)
    i += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(words[i])
        faces.append([int(x) for x in words[i + 1:i + 1 + n]])
        i += 1 + n
    return v, np.array(faces, dtype=int)


def rotation(azimuth, elevation):
    """Camera rotation: world -> view (x right, y up, z towards the viewer)."""
    a, e = np.radians(azimuth), np.radians(elevation)
    ry = np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])
    rx = np.array([[1, 0, 0], [0, np.cos(e), -np.sin(e)], [0, np.sin(e), np.cos(e)]])
    return rx @ ry


def draw_mesh(ax, v, f, rot, color=(0.80, 0.68, 0.45)):
    p = v @ rot.T
    tri = p[f]
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    n /= np.linalg.norm(n, axis=1)[:, None] + 1e-300
    light = np.array([0.35, 0.45, 0.82])
    light /= np.linalg.norm(light)
    lambert = np.abs(n @ light)  # two-sided: the output's orientation does not matter here
    shade = 0.25 + 0.75 * lambert
    depth = tri[:, :, 2].mean(axis=1)
    order = np.argsort(depth)  # far first
    colors = np.clip(np.outer(shade, color), 0, 1)[order]
    pc = PolyCollection(tri[order][:, :, :2], facecolors=colors, edgecolors=colors, linewidths=0.15,
                        antialiaseds=False)
    ax.add_collection(pc)
    set_limits(ax, p[:, :2])


def draw_points(ax, pts, rot, size=0.15):
    p = pts @ rot.T
    order = np.argsort(p[:, 2])
    z = p[order, 2]
    # near points dark, far ones light
    ax.scatter(p[order, 0], p[order, 1], s=size, c=z, cmap="Greys", vmin=z.min() - 0.3 * np.ptp(z),
               vmax=z.max(), linewidths=0)
    set_limits(ax, p[:, :2])


def set_limits(ax, xy, pad=0.03):
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    c, r = 0.5 * (lo + hi), 0.5 * (hi - lo).max() * (1 + pad)
    ax.set_xlim(c[0] - r, c[0] + r)
    ax.set_ylim(c[1] - r, c[1] + r)
    ax.set_aspect("equal")
    ax.axis("off")


def save(fig, path):
    fig.savefig(path, dpi=DPI, facecolor="white")
    plt.close(fig)
    size = os.path.getsize(path)
    print("%s: %d KB" % (path, size // 1024))
    if size > MAX_BYTES:
        TOO_LARGE.append(path)


def level_collection(polys, levels, cmap, norm, lw=0.25):
    return PolyCollection(polys, array=levels, cmap=cmap, norm=norm, edgecolors="k", linewidths=lw)


def figure_kuhn(data, out):
    fig = plt.figure(figsize=(9.6, 4.2))
    grid = fig.add_gridspec(2, 5, width_ratios=[1, 1, 1, 0.15, 3.3], wspace=0.0, hspace=0.05)
    roots = np.loadtxt(os.path.join(data, "kuhn_roots.txt")).reshape(-1, 4, 3)
    colors = plt.cm.tab10(np.arange(6))
    cube_edges = [(a, b) for a in range(8) for b in range(a + 1, 8) if bin(a ^ b).count("1") == 1]
    corner = np.array([[(i >> 0) & 1, (i >> 1) & 1, (i >> 2) & 1] for i in range(8)], dtype=float)
    for r, (t, col) in enumerate(zip(roots, colors)):
        ax = fig.add_subplot(grid[r // 3, r % 3], projection="3d")
        for a, b in cube_edges:
            ax.plot(*zip(corner[a], corner[b]), color="0.6", lw=0.6)
        faces = [t[[0, 1, 2]], t[[0, 1, 3]], t[[0, 2, 3]], t[[1, 2, 3]]]
        ax.add_collection3d(Poly3DCollection(faces, facecolors=col, edgecolors="k", linewidths=0.6, alpha=0.6))
        ax.plot([0, 1], [0, 1], [0, 1], "k--", lw=0.8)
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
        ax.set_zlim(0, 1)
        ax.view_init(elev=20, azim=-60)
        ax.set_axis_off()
        ax.set_box_aspect((1, 1, 1), zoom=0.95)
    fig.text(0.23, 0.94, "(a) the 6 Kuhn tetrahedra of the box, around its diagonal", ha="center", fontsize=10)

    ax = fig.add_subplot(grid[:, 4])
    levels, polys, _ = read_slice(os.path.join(data, "conforming_slice.txt"))
    cmap = plt.cm.viridis
    norm = matplotlib.colors.Normalize(levels.min(), levels.max())
    ax.add_collection(level_collection(polys, levels, cmap, norm, lw=0.3))
    ax.plot([0.3], [0.62], "r+", ms=9, mew=1.5)
    set_limits(ax, np.vstack(polys), pad=0.01)
    cb = fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, fraction=0.046, pad=0.02)
    cb.set_label("level", fontsize=9)
    ax.set_title("(b) conforming bisection towards +: leaves cut by z = 0.42", fontsize=10)
    fig.subplots_adjust(left=0.0, right=0.97, top=0.9, bottom=0.03)
    save(fig, os.path.join(out, "kuhn_bisection.png"))


def figure_levels(data, out):
    depths = [12, 15, 18]
    fig, axes = plt.subplots(1, 3, figsize=(11.4, 4.1))
    pts = np.loadtxt(os.path.join(data, "slice_points.txt"))
    slices = [read_slice(os.path.join(data, "levels_%d.txt" % d)) for d in depths]
    lmin = min(s[0].min() for s in slices)
    lmax = max(s[0].max() for s in slices)
    cmap = plt.cm.viridis
    norm = matplotlib.colors.Normalize(lmin, lmax)
    for ax, d, (levels, polys, _) in zip(axes, depths, slices):
        ax.add_collection(level_collection(polys, levels, cmap, norm, lw=0.1))
        ax.scatter(pts[:, 0], pts[:, 1], s=0.25, c="r", linewidths=0)
        set_limits(ax, np.vstack(polys), pad=0.0)
        ax.set_title("maximum_depth(%d): %d leaves cut" % (d, len(polys)), fontsize=10)
    fig.subplots_adjust(left=0.01, right=0.92, bottom=0.02, top=0.93, wspace=0.03)
    cax = fig.add_axes([0.93, 0.1, 0.012, 0.75])
    cb = fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cmap), cax=cax)
    cb.set_label("level of the leaf", fontsize=9)
    save(fig, os.path.join(out, "bmt_levels.png"))


def clip(poly, f, keep_negative):
    """Part of a convex polygon where the linear function f (given at the corners) is < 0 (or >= 0)."""
    s = -f if keep_negative else f
    res = []
    n = len(poly)
    for i in range(n):
        j = (i + 1) % n
        a_in, b_in = s[i] >= 0, s[j] >= 0
        if a_in:
            res.append(poly[i])
        if a_in != b_in:
            t = s[i] / (s[i] - s[j])
            res.append(poly[i] + t * (poly[j] - poly[i]))
    return np.array(res) if len(res) >= 3 else None


def figure_signs(data, out):
    levels, polys, values = read_slice(os.path.join(data, "sign_slice.txt"), with_values=True)
    pts = np.loadtxt(os.path.join(data, "slice_points.txt"))
    inside, outside, zero = [], [], []
    for p, f in zip(polys, values):
        if (f < 0).all():
            inside.append(p)
        elif (f >= 0).all():
            outside.append(p)
        else:
            a, b = clip(p, f, True), clip(p, f, False)
            if a is not None:
                inside.append(a)
            if b is not None:
                outside.append(b)
            # the zero segment: the corners of the clipped part on both sides
            z = []
            for i in range(len(p)):
                j = (i + 1) % len(p)
                if (f[i] < 0) != (f[j] < 0):
                    t = f[i] / (f[i] - f[j])
                    z.append(p[i] + t * (p[j] - p[i]))
            if len(z) == 2:
                zero.append(np.array(z))
    fig, axes = plt.subplots(1, 2, figsize=(10.0, 4.6))
    allxy = np.vstack(polys)
    for k, ax in enumerate(axes):
        ax.add_collection(PolyCollection(outside, facecolors="#f4d9b0", edgecolors="none"))
        ax.add_collection(PolyCollection(inside, facecolors="#5b8fc9", edgecolors="none"))
        ax.add_collection(PolyCollection(polys, facecolors="none", edgecolors="k", linewidths=0.12 if k == 0 else 0.3))
        ax.add_collection(LineCollection(zero, colors="k", linewidths=1.2 if k == 0 else 2.0))
        if k == 1:
            ax.scatter(pts[:, 0], pts[:, 1], s=5, c="r", linewidths=0, zorder=3)
    set_limits(axes[0], allxy, pad=0.0)
    axes[0].set_title("(a) sign of F on the slice: inside (blue), outside", fontsize=10)
    # zoom on the ear/head region: a window around the point of the slice with the largest y
    top = pts[np.argmax(pts[:, 1])]
    w = 0.09
    axes[1].set_xlim(top[0] - w, top[0] + w)
    axes[1].set_ylim(top[1] - 1.6 * w, top[1] + 0.4 * w)
    axes[1].set_aspect("equal")
    axes[1].set_xticks([])
    axes[1].set_yticks([])
    axes[1].set_title("(b) zoom: leaves, F = 0 (black) and the points near the slice (red)", fontsize=10)
    axes[0].add_patch(matplotlib.patches.Rectangle((top[0] - w, top[1] - 1.6 * w), 2 * w, 2 * w, fill=False,
                                                   edgecolor="r", lw=1))
    fig.tight_layout()
    save(fig, os.path.join(out, "inout_slice.png"))


def segment_distances(points, segments):
    """Distance from each of `points` (n, 2) to the nearest of `segments` (m, 4: x1 y1 x2 y2)."""
    a = segments[:, :2]
    d = segments[:, 2:] - a
    dd = (d * d).sum(1)
    dd[dd == 0] = 1
    out = np.empty(len(points))
    for i in range(0, len(points), 256):
        p = points[i:i + 256, None, :]
        t = np.clip(((p - a) * d).sum(2) / dd, 0, 1)
        out[i:i + 256] = np.sqrt(((p - (a + t[..., None] * d)) ** 2).sum(2)).min(1)
    return out


def figure_crossings(data, out):
    """The slice of the surface through F's linear crossings and through the quadric crossings,
    zoomed where the two differ most against the truth."""
    truth = np.loadtxt(os.path.join(data, "truth_slice.txt"))
    linear = np.loadtxt(os.path.join(data, "crossing_slice_0.txt"))
    quadric = np.loadtxt(os.path.join(data, "crossing_slice_12.txt"))
    _, polys, _ = read_slice(os.path.join(data, "sign_slice.txt"), with_values=True)
    pts = np.loadtxt(os.path.join(data, "slice_points.txt"))
    mid_l = (linear[:, :2] + linear[:, 2:]) / 2
    mid_q = (quadric[:, :2] + quadric[:, 2:]) / 2
    err_l, err_q = segment_distances(mid_l, truth), segment_distances(mid_q, truth)
    # the window (half width w) where the linear crossings miss the truth most, on average,
    # more than the quadric ones
    w, best, centre = 0.025, -1.0, mid_l[0]
    for c in mid_l[::3]:
        il, iq = np.abs(mid_l - c).max(1) < w, np.abs(mid_q - c).max(1) < w
        if il.sum() >= 5 and iq.sum() >= 5 and err_l[il].mean() - err_q[iq].mean() > best:
            best, centre = err_l[il].mean() - err_q[iq].mean(), c
    fig, axes = plt.subplots(1, 2, figsize=(10.0, 5.0))
    for ax, segs, err, color, title in (
            (axes[0], linear, err_l, "#1f5fbf", "(a) F's linear zero crossings (the paper)"),
            (axes[1], quadric, err_q, "#c0392b", "(b) moved along their edges onto the points' quadric")):
        ax.add_collection(PolyCollection(polys, facecolors="none", edgecolors="#b0b0b0", linewidths=0.4))
        ax.add_collection(LineCollection(truth.reshape(-1, 2, 2), colors="#8a8a8a", linewidths=5.0, alpha=0.45))
        ax.add_collection(LineCollection(segs.reshape(-1, 2, 2), colors=color, linewidths=1.8))
        ax.scatter(pts[:, 0], pts[:, 1], s=9, c="k", linewidths=0, zorder=3)
        ax.set_xlim(centre[0] - w, centre[0] + w)
        ax.set_ylim(centre[1] - w, centre[1] + w)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        inside = np.abs(((segs[:, :2] + segs[:, 2:]) / 2) - centre).max(1) < w
        ax.set_title("%s\nmean distance to the truth in the window: %.2g" % (title, err[inside].mean()), fontsize=10)
    fig.suptitle("bunny slice: truth (grey band), leaves (grey lines), points near the slice (black)", fontsize=10)
    fig.tight_layout()
    save(fig, os.path.join(out, "crossings.png"))


def figure_reconstruction(data, out, name, rot, title):
    pts = np.loadtxt(os.path.join(data, name + "_points.xyz"))
    v, f = read_off(os.path.join(data, name + "_reconstruction.off"))
    fig, axes = plt.subplots(1, 2, figsize=(8.4, 4.3))
    draw_points(axes[0], pts, rot)
    axes[0].set_title("%d input points, no normals" % len(pts), fontsize=10)
    draw_mesh(axes[1], v, f, rot)
    axes[1].set_title("ism_surface_reconstruction(): %d triangles" % len(f), fontsize=10)
    fig.suptitle(title, fontsize=11)
    fig.tight_layout()
    save(fig, os.path.join(out, name + "_reconstruction.png"))


def copy_chart(src, dst):
    """Copies a PNG chart (the benchmark's), shrinking it until it is below MAX_BYTES."""
    if os.path.getsize(src) <= MAX_BYTES:
        with open(src, "rb") as i, open(dst, "wb") as o:
            o.write(i.read())
        print("%s: copied" % dst)
        return
    img = plt.imread(src)
    h, w = img.shape[:2]
    for width in (1200, 1000, 800, 640, 480):
        if width >= w:
            continue
        fig = plt.figure(figsize=(width / DPI, width * h / w / DPI), dpi=DPI)
        ax = fig.add_axes([0, 0, 1, 1])
        ax.imshow(img, interpolation="antialiased")
        ax.axis("off")
        fig.savefig(dst, dpi=DPI)
        plt.close(fig)
        if os.path.getsize(dst) <= MAX_BYTES:
            print("%s: %d px wide, %d KB" % (dst, width, os.path.getsize(dst) // 1024))
            return
    sys.exit("could not bring %s below %d KB" % (src, MAX_BYTES // 1024))


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "--copy-chart":
        copy_chart(sys.argv[2], sys.argv[3])
        return
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    data, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    figure_kuhn(data, out)
    figure_levels(data, out)
    figure_signs(data, out)
    figure_crossings(data, out)
    figure_reconstruction(data, out, "bunny", rotation(20, 10), "Stanford bunny (bunny00.off), default parameters")
    figure_reconstruction(data, out, "knot", rotation(0, -35), "Knot (knot1.off), default parameters")
    if TOO_LARGE:
        sys.exit("larger than %d KB: %s" % (MAX_BYTES // 1024, " ".join(TOO_LARGE)))


if __name__ == "__main__":
    main()
