"""The bridge on what matplotlib's 3D gallery uses: edge strokes, ``axlim_clip``, axis
scales and colorbars, each checked on the rasterised file against matplotlib's own
export of a small figure."""

import matplotlib as mpl
import numpy as np

mpl.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

import limn.matplotlib as lm  # noqa: E402
from probes import colour_at, near, raster  # noqa: E402

BLUE = (0.2, 0.4, 0.85)


def both(fig, tmp_path, zoom=3.0):
    """The bridge's export of ``fig`` and matplotlib's own, rasterised."""
    fig.savefig(tmp_path / "mpl.svg")
    lm.savefig(fig, tmp_path / "limn.svg")
    return (
        raster((tmp_path / "limn.svg").read_bytes(), zoom),
        raster((tmp_path / "mpl.svg").read_bytes(), zoom),
    )


def axes():
    fig = plt.figure(figsize=(4, 3))
    ax = fig.add_subplot(projection="3d")
    ax.set_xlim(-1, 1)
    ax.set_ylim(-1, 1)
    ax.set_zlim(-1, 1)
    ax.view_init(elev=20, azim=-60)
    ax.set_axis_off()
    return fig, ax


def test_a_collection_without_edge_colour_has_no_edge_stroke(tmp_path):
    # A translucent square of two triangles, no edge colour, thick lines: matplotlib
    # strokes nothing (neither the outline nor the shared diagonal).
    fig, ax = axes()
    sq = [(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0), (-0.5, 0.5, 0)]
    tris = [[sq[0], sq[1], sq[2]], [sq[0], sq[2], sq[3]]]
    ax.add_collection3d(Poly3DCollection(tris, facecolors=BLUE + (0.3,), linewidths=6))
    mine, theirs = both(fig, tmp_path)
    for p in [(0.0, 0.0, 0.0), (0.2, -0.2, 0.0), (-0.2, 0.2, 0.0), (0.0, -0.56, 0.0)]:
        c, want = colour_at(fig, ax, mine, p), colour_at(fig, ax, theirs, p)
        assert near(c, want, 0.04), (p, c, want)
    plt.close(fig)
