#!/usr/bin/python3
"""Renders the input points beside the reconstructed surface into a PNG, headless.

    /usr/bin/python3 scripts/render_result.py POINTS.xyz SURFACE.off OUT.png
        [--title TEXT] [--size W H] [--azimuth DEG] [--elevation DEG]
        [--up X Y Z] [--front X Y Z] [--backend auto|vtk|matplotlib]

Two panes, one viewpoint: the points (coloured by height) and the shaded surface.

Backends. `vtk` renders with VTK offscreen (vtkRenderWindow.SetOffScreenRendering(1)).
Debian's python3-vtk9 (9.1) is built for X only (no EGL, no OSMesa), so offscreen VTK
still needs an X server: a display, or a virtual one (xvfb-run). `matplotlib` renders
with the Agg backend and needs nothing. `auto` (default) uses VTK when it can open a
context (DISPLAY is set, or VTK has an EGL/OSMesa window) and matplotlib otherwise.
Debian's VTK and matplotlib load only with the system interpreter: run /usr/bin/python3.
The surface is read with meshio (.off, .ply, .obj).
"""
import argparse
import os
import sys

import numpy as np


def read_points(path):
    """x y z per line ('#' comments, an optional count on the first line, extra columns ignored)."""
    rows = []
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            t = line.split("#", 1)[0].split()
            if len(t) >= 3:
                rows.append((float(t[0]), float(t[1]), float(t[2])))
    if not rows:
        raise ValueError(f"{path}: no point")
    return np.asarray(rows, dtype=float)


def read_surface(path):
    import meshio
    m = meshio.read(path)
    tris = [c.data for c in m.cells if c.type == "triangle"]
    if not tris:
        raise ValueError(f"{path}: no triangle")
    return np.asarray(m.points[:, :3], dtype=float), np.concatenate(tris).astype(np.int64)


def unit(v):
    v = np.asarray(v, dtype=float)
    n = np.linalg.norm(v)
    if n == 0:
        raise ValueError("zero vector")
    return v / n


def rotate(v, axis, degrees):
    """Rodrigues rotation of v around the unit vector axis."""
    a = np.radians(degrees)
    return v * np.cos(a) + np.cross(axis, v) * np.sin(a) + axis * (axis @ v) * (1 - np.cos(a))


def view_frame(up, front, azimuth, elevation):
    """(d, u, r): unit vectors towards the camera, up on screen, right on screen."""
    u = unit(up)
    d = unit(np.asarray(front, float) - (np.asarray(front, float) @ u) * u)
    d = rotate(d, u, azimuth)
    side = unit(np.cross(d, u))
    d = unit(rotate(d, side, -elevation))  # towards u
    r = unit(np.cross(-d, u))
    u = unit(np.cross(r, -d))
    return d, u, r


def vtk_available():
    try:
        import vtk
    except ImportError:
        return False
    if os.environ.get("DISPLAY"):
        return True
    return hasattr(vtk, "vtkEGLRenderWindow") or hasattr(vtk, "vtkOSOpenGLRenderWindow")


def captions(npts, nverts, ntris):
    return (f"input: {npts:,} points (no normals)",
            f"reconstruction: {nverts:,} vertices, {ntris:,} triangles")


def render_vtk(pts, verts, tris, args, frame):
    import vtk
    from vtk.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray

    d, u, _ = frame

    def polydata(points, cells, npc):
        pd = vtk.vtkPolyData()
        vp = vtk.vtkPoints()
        vp.SetData(numpy_to_vtk(np.ascontiguousarray(points), deep=True))
        pd.SetPoints(vp)
        c = np.empty((len(cells), npc + 1), dtype=np.int64)
        c[:, 0] = npc
        c[:, 1:] = cells.reshape(len(cells), npc)
        ca = vtk.vtkCellArray()
        ca.SetCells(len(cells), numpy_to_vtkIdTypeArray(c.ravel(), deep=True))
        return pd, ca

    cloud, verts_ca = polydata(pts, np.arange(len(pts)), 1)
    cloud.SetVerts(verts_ca)
    height = pts @ u
    scalars = numpy_to_vtk(np.ascontiguousarray(height), deep=True)
    scalars.SetName("height")
    cloud.GetPointData().SetScalars(scalars)
    cloud_mapper = vtk.vtkPolyDataMapper()
    cloud_mapper.SetInputData(cloud)
    cloud_mapper.SetScalarRange(float(height.min()), float(height.max()))
    lut = vtk.vtkLookupTable()
    lut.SetHueRange(0.65, 0.0)
    lut.Build()
    cloud_mapper.SetLookupTable(lut)
    cloud_actor = vtk.vtkActor()
    cloud_actor.SetMapper(cloud_mapper)
    cloud_actor.GetProperty().SetPointSize(2.0)

    mesh, polys = polydata(verts, tris, 3)
    mesh.SetPolys(polys)
    normals = vtk.vtkPolyDataNormals()
    normals.SetInputData(mesh)
    normals.SplittingOff()
    surf_mapper = vtk.vtkPolyDataMapper()
    surf_mapper.SetInputConnection(normals.GetOutputPort())
    surf_mapper.ScalarVisibilityOff()
    surf_actor = vtk.vtkActor()
    surf_actor.SetMapper(surf_mapper)
    prop = surf_actor.GetProperty()
    prop.SetColor(0.85, 0.78, 0.62)
    prop.SetAmbient(0.12)
    prop.SetDiffuse(0.8)
    prop.SetSpecular(0.25)
    prop.SetSpecularPower(30)

    w, h = args.size
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetSize(w, h)
    left, right = vtk.vtkRenderer(), vtk.vtkRenderer()
    left.SetViewport(0.0, 0.0, 0.5, 1.0)
    right.SetViewport(0.5, 0.0, 1.0, 1.0)
    for r, actor in ((left, cloud_actor), (right, surf_actor)):
        r.AddActor(actor)
        r.SetBackground(1.0, 1.0, 1.0)
        win.AddRenderer(r)

    lo, hi = pts.min(axis=0), pts.max(axis=0)
    center = 0.5 * (lo + hi)
    radius = 0.5 * np.linalg.norm(hi - lo)
    cam = vtk.vtkCamera()
    cam.SetFocalPoint(*center)
    cam.SetPosition(*(center + 4.0 * radius * d))
    cam.SetViewUp(*u)
    cam.SetViewAngle(30.0)
    left.SetActiveCamera(cam)
    right.SetActiveCamera(cam)
    left.ResetCamera()
    cam.Zoom(1.2)
    left.ResetCameraClippingRange()
    right.ResetCameraClippingRange()

    for renderer, text in zip((left, right), captions(len(pts), len(verts), len(tris))):
        t = vtk.vtkTextActor()
        t.SetInput(text)
        t.GetTextProperty().SetFontSize(max(14, h // 32))
        t.GetTextProperty().SetColor(0.1, 0.1, 0.1)
        t.SetPosition(12, 12)
        renderer.AddActor2D(t)
    if args.title:  # on an overlay spanning both panes, so that it is not clipped
        win.SetNumberOfLayers(2)
        overlay = vtk.vtkRenderer()
        overlay.SetLayer(1)
        overlay.SetViewport(0.0, 0.0, 1.0, 1.0)
        overlay.InteractiveOff()
        t = vtk.vtkTextActor()
        t.SetInput(args.title)
        p = t.GetTextProperty()
        p.SetFontSize(max(16, h // 30))
        p.SetColor(0.1, 0.1, 0.1)
        t.SetPosition(12, h - 12 - max(16, h // 30))
        overlay.AddActor2D(t)
        win.AddRenderer(overlay)

    win.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(args.png)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def render_matplotlib(pts, verts, tris, args, frame):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib import cm
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    d, u, r = frame
    # Coordinates in the view frame, laid out for matplotlib's default camera at
    # elev=0, azim=-90 (looking along +y, x right, z up): x = right, y = away, z = up.
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    center = 0.5 * (lo + hi)

    def to_view(p):
        q = p - center
        return np.stack([q @ r, -(q @ d), q @ u], axis=1)

    P, V = to_view(pts), to_view(verts)
    ext = np.abs(np.concatenate([P, V])).max(axis=0) * 1.02

    # Lambert + Blinn-Phong, two-sided, light from the upper left of the viewer, on
    # area-weighted vertex normals averaged per face (smoother than flat shading).
    a, b, c = V[tris[:, 0]], V[tris[:, 1]], V[tris[:, 2]]
    fn = np.cross(b - a, c - a)
    vn = np.zeros_like(V)
    for k in range(3):
        np.add.at(vn, tris[:, k], fn)
    vn /= np.maximum(np.linalg.norm(vn, axis=1, keepdims=True), 1e-300)
    to_eye = np.array([0.0, -1.0, 0.0])
    light = unit([-0.45, -1.0, 0.55])
    half = unit(light + to_eye)
    facing = np.sign(fn @ to_eye)[:, None]  # two-sided: flip normals of faces seen from behind
    n = vn[tris] * facing[:, :, None]
    diffuse = np.clip(n @ light, 0, 1).mean(axis=1)
    specular = (np.clip(n @ half, 0, 1) ** 40).mean(axis=1)
    base = np.array([0.86, 0.78, 0.60])
    rgb = np.clip(base * (0.28 + 0.72 * diffuse[:, None]) + 0.25 * specular[:, None], 0, 1)

    w, h = args.size
    dpi = 100
    fig = plt.figure(figsize=(w / dpi, h / dpi), dpi=dpi)
    fig.patch.set_facecolor("white")
    texts = captions(len(pts), len(verts), len(tris))
    for k in range(2):
        ax = fig.add_axes([0.5 * k, 0.0, 0.5, 1.0], projection="3d")
        ax.set_proj_type("ortho")
        ax.view_init(elev=0, azim=-90)
        ax.set_xlim(-ext[0], ext[0])
        ax.set_ylim(-ext[1], ext[1])
        ax.set_zlim(-ext[2], ext[2])
        try:
            ax.set_box_aspect(tuple(ext), zoom=1.3)  # matplotlib >= 3.6
        except TypeError:
            ax.set_box_aspect(tuple(ext))
        ax.set_axis_off()
        if k == 0:
            height = P[:, 2]
            ax.scatter(P[:, 0], P[:, 1], P[:, 2], s=1.2, c=height, cmap=cm.jet, depthshade=False,
                       linewidths=0, marker="o", alpha=0.9)
        else:
            # edges in the face colour hide the antialiasing seams between triangles
            coll = Poly3DCollection(V[tris], facecolors=rgb, edgecolors=rgb, linewidths=0.15)
            ax.add_collection3d(coll)
        fig.text(0.5 * k + 0.01, 0.02, texts[k], fontsize=max(9, h // 55), color="0.1")
    if args.title:
        fig.text(0.01, 0.96, args.title, fontsize=max(11, h // 45), color="0.1", va="top")
    fig.savefig(args.png, dpi=dpi, facecolor="white")
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("points")
    ap.add_argument("surface")
    ap.add_argument("png")
    ap.add_argument("--title", default="")
    ap.add_argument("--size", type=int, nargs=2, default=(1600, 800), metavar=("W", "H"))
    ap.add_argument("--azimuth", type=float, default=-25.0, help="degrees around the up axis")
    ap.add_argument("--elevation", type=float, default=15.0, help="degrees above the horizon")
    ap.add_argument("--up", type=float, nargs=3, default=(0.0, 1.0, 0.0), metavar=("X", "Y", "Z"))
    ap.add_argument("--front", type=float, nargs=3, default=(0.0, 0.0, 1.0), metavar=("X", "Y", "Z"),
                    help="direction towards the camera before azimuth and elevation")
    ap.add_argument("--backend", choices=("auto", "vtk", "matplotlib"), default="auto")
    args = ap.parse_args(argv)

    pts = read_points(args.points)
    verts, tris = read_surface(args.surface)
    frame = view_frame(args.up, args.front, args.azimuth, args.elevation)
    backend = args.backend
    if backend == "auto":
        backend = "vtk" if vtk_available() else "matplotlib"
    if backend == "vtk":
        render_vtk(pts, verts, tris, args, frame)
    else:
        render_matplotlib(pts, verts, tris, args, frame)
    if not os.path.isfile(args.png) or os.path.getsize(args.png) == 0:
        raise OSError(f"{args.png} was not written")
    print(f"rendered {args.png} ({args.size[0]}x{args.size[1]}, {backend})")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (OSError, ValueError) as e:
        print(f"render_result.py: error: {e}", file=sys.stderr)
        sys.exit(1)
