#!/usr/bin/env python3
"""Draws a limn-projected scene with matplotlib's mplot3d and writes its SVG.

Usage: python3 mpl_driver.py IN.txt OUT.svg

IN.txt is the exchange format described in README.md (``limn-projected 1``;
x = pixel column from the left, y = pixel row from the top, z in [-1, 1],
smaller = nearer).  The polygons go, in input order, into one
``Poly3DCollection`` (flat face colours, no edges, no shading, no
anti-aliasing, ``zsort`` and ``sort_zpos`` left at their defaults) on a 3D
Axes with an orthographic projection looking straight down the z axis.
mplot3d then does what it always does: it sorts the polygons by the mean
projected depth of their vertices and paints them back to front.  That
order is what the benchmark measures.

Placement: the figure is W x H points at 72 dpi (1 pt = 1 px), without any
margin; the data is fed as (x, H - y, -z) so that mplot3d's y-up, z-towards-
the-eye axes give y down and smaller z nearer.  mplot3d keeps its 2D Axes
square and puts the projected unit box inside it with a margin of its own,
so the driver does not rely on those internals: it measures where three
reference points land, sets the x/y limits so that data x lands at picture
column x and data y at picture row y, measures again, and stops with an
error if any polygon vertex is off by more than 1e-6 px.

The SVG is matplotlib's, with only the root's width/height rewritten from
``Wpt``/``Hpt`` to ``W``/``H`` (the viewBox is already ``0 0 W H``).  No
background is drawn (figure and Axes patches are off), so uncovered pixels
stay transparent.  Prints ``primitives N``: the number of polygons drawn.
"""
import re
import sys

import matplotlib

matplotlib.use("svg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

TOL = 1e-6  # largest allowed placement error, in pixels


def fail(msg):
    print(f"mpl_driver: {msg}", file=sys.stderr)
    sys.exit(1)


def read_scene(path):
    try:
        with open(path) as f:
            tokens = f.read().split()
    except OSError as e:
        fail(f"cannot read {path}: {e}")
    if tokens[:2] != ["limn-projected", "1"]:
        fail(f"{path}: not a 'limn-projected 1' file")
    try:
        w, h, n = int(tokens[2]), int(tokens[3]), int(tokens[4])
        pos = 5
        polys = []
        for _ in range(n):
            r, g, b, k = (int(t) for t in tokens[pos:pos + 4])
            pos += 4
            if not all(0 <= c <= 255 for c in (r, g, b)) or k < 3:
                fail(f"{path}: bad colour or vertex count")
            xyz = np.array(tokens[pos:pos + 3 * k], dtype=float).reshape(k, 3)
            pos += 3 * k
            polys.append(((r, g, b), xyz))
    except (IndexError, ValueError):
        fail(f"{path}: truncated or malformed")
    if w <= 0 or h <= 0:
        fail(f"{path}: bad picture size")
    return w, h, polys


def display_xy(ax, pts):
    """Where data points (x, y, z) land in the SVG picture (y down)."""
    from mpl_toolkits.mplot3d import proj3d
    xs, ys, _ = proj3d.proj_transform(pts[:, 0], pts[:, 1], pts[:, 2], ax.get_proj())
    d = ax.transData.transform(np.column_stack([xs, ys]))
    fig_h = ax.figure.bbox.height
    return np.column_stack([d[:, 0], fig_h - d[:, 1]])


def main():
    if len(sys.argv) != 3:
        print("usage: python3 mpl_driver.py IN.txt OUT.svg", file=sys.stderr)
        sys.exit(1)
    src, out = sys.argv[1], sys.argv[2]
    w, h, polys = read_scene(src)

    plt.rcParams["svg.fonttype"] = "none"
    plt.rcParams["svg.hashsalt"] = "limn"  # deterministic ids
    plt.rcParams["svg.id"] = None
    fig = plt.figure(figsize=(w / 72.0, h / 72.0), dpi=72)
    fig.patch.set_visible(False)
    ax = fig.add_axes((0, 0, 1, 1), projection="3d", proj_type="ortho")
    ax.view_init(elev=90, azim=-90, roll=0)
    ax.set_axis_off()
    ax.patch.set_visible(False)
    depth = float(min(w, h))
    ax.set_box_aspect((w, h, depth))
    ax.set_xlim(0, w)
    ax.set_ylim(0, h)
    ax.set_zlim(-1, 1)

    # data coordinates: (x, H - y, -z)
    verts = [np.column_stack([p[:, 0], h - p[:, 1], -p[:, 2]]) for _, p in polys]
    colours = [(r / 255.0, g / 255.0, b / 255.0, 1.0) for (r, g, b), _ in polys]
    col = Poly3DCollection(verts, facecolors=colours, edgecolors="none",
                           linewidths=0, antialiaseds=False)
    col.set_clip_on(False)  # the picture itself is the clip, as for gl2ps
    ax.add_collection3d(col)

    # Calibrate x/y limits so that data (x, y') lands at picture (x, H - y').
    fig.canvas.draw()
    ref = np.array([[0.0, 0.0, 0.0], [w, 0.0, 0.0], [0.0, h, 0.0]])
    for _ in range(3):
        (lo_x, hi_x), (lo_y, hi_y) = ax.get_xlim(), ax.get_ylim()
        d = display_xy(ax, np.array([[lo_x, lo_y, 0.0], [hi_x, lo_y, 0.0], [lo_x, hi_y, 0.0]]))
        if abs(d[1, 1] - d[0, 1]) > TOL or abs(d[2, 0] - d[0, 0]) > TOL:
            fail("the view is not axis-aligned (check view_init)")
        # d[0] is where (lo_x, lo_y) lands, d[1] (hi_x, lo_y), d[2] (lo_x, hi_y).
        # These picture positions belong to the ends of the axis ranges, not to
        # the values: give the ends the values that should land there
        # (column = x, row = H - y').
        ax.set_xlim(d[0, 0], d[1, 0])
        ax.set_ylim(h - d[0, 1], h - d[2, 1])
        fig.canvas.draw()
        got = display_xy(ax, ref)
        want = np.array([[0.0, h], [w, h], [0.0, 0.0]])
        if np.abs(got - want).max() <= TOL:
            break
    else:
        fail(f"could not place the picture (error {np.abs(got - want).max():g} px)")

    # The drawn paths must be the input polygons, each at its own place.
    paths = col.get_paths()
    if len(paths) != len(polys):
        fail(f"{len(paths)} paths drawn for {len(polys)} polygons")
    if polys:
        allv = np.vstack([p for _, p in polys])
        flat = np.column_stack([allv[:, 0], h - allv[:, 1], np.zeros(len(allv))])
        err = np.abs(display_xy(ax, flat) - allv[:, :2]).max()
        if err > TOL:
            fail(f"vertices misplaced by {err:g} px")

    try:
        fig.savefig(out + ".tmp", format="svg", dpi=72)
        with open(out + ".tmp") as f:
            svg = f.read()
        svg, n = re.subn(r'width="([0-9.]+)pt" height="([0-9.]+)pt"',
                         lambda m: f'width="{m.group(1)}" height="{m.group(2)}"', svg, count=1)
        if n != 1 or f'viewBox="0 0 {w} {h}"' not in svg:
            fail("matplotlib's SVG header is not the expected one")
        with open(out, "w") as f:
            f.write(svg)
    except OSError as e:
        fail(f"cannot write {out}: {e}")
    finally:
        import os
        if os.path.exists(out + ".tmp"):
            os.remove(out + ".tmp")
    print(f"primitives {len(paths)}")


if __name__ == "__main__":
    main()
