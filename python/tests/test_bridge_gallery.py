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
RED = (0.85, 0.25, 0.2)


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


def test_axlim_clip_leaves_out_what_lies_outside_the_limits(tmp_path):
    fig, ax = axes()
    x = np.linspace(-1.4, 1.4, 29)
    ax.plot(x, 0 * x, 0 * x, color=BLUE, lw=4, axlim_clip=True)
    ax.plot(x, 0 * x + 0.5, 0 * x, color=BLUE, lw=4)  # not clipped
    ax.scatter([0, 0], [0, 0], [0.5, 1.6], color=BLUE, s=200, axlim_clip=True)
    mine, theirs = both(fig, tmp_path)
    white = (1.0, 1.0, 1.0)
    for p, want in [
        ((0.5, 0.0, 0.0), BLUE),  # the clipped line inside the limits
        ((1.25, 0.0, 0.0), white),  # and outside
        ((1.25, 0.5, 0.0), BLUE),  # the other line outside the limits
        ((0.0, 0.0, 0.5), BLUE),  # the point inside
        ((0.0, 0.0, 1.6), white),  # the point outside
    ]:
        assert near(colour_at(fig, ax, theirs, p), want), p  # matplotlib's own picture
        assert near(colour_at(fig, ax, mine, p), want), (p, colour_at(fig, ax, mine, p))
    plt.close(fig)


def test_log_scaled_data_are_drawn_where_matplotlib_draws_them(tmp_path):
    # z on a log axis from 1 to 100: a square at z = 10 lies halfway up (log10 z = 1),
    # a line at z = 3 below it; a point at z = 0 is outside the scale and not drawn.
    fig, ax = axes()
    ax.set_zscale("log")
    ax.set_zlim(1, 100)
    x, y = np.meshgrid([-0.5, 0.5], [-0.5, 0.5])
    ax.plot_surface(x, y, 10 + 0 * x, color=BLUE, shade=False, linewidth=0)
    ax.plot([-0.9, 0.9], [-0.8, -0.8], [3, 3], color=RED, lw=4)
    ax.scatter([0.8], [0.8], [0.0], color=RED, s=200)
    mine, theirs = both(fig, tmp_path)
    # Probes in scaled coordinates (what the axes project).
    for p, want in [((0.2, 0.2, 1.0), BLUE), ((0.0, -0.8, np.log10(3)), RED)]:
        assert near(colour_at(fig, ax, theirs, p), want), p
        assert near(colour_at(fig, ax, mine, p), want), (p, colour_at(fig, ax, mine, p))
    plt.close(fig)


def test_a_colorbar_is_matplotlibs_own_drawing(tmp_path):
    fig = plt.figure(figsize=(4, 3))
    ax = fig.add_subplot(projection="3d")
    x, y = np.meshgrid(np.linspace(-1, 1, 6), np.linspace(-1, 1, 6))
    s = ax.plot_surface(x, y, x * y, cmap="viridis", linewidth=0)
    cb = fig.colorbar(s, ax=ax)
    mine, theirs = both(fig, tmp_path)
    # The colour bar's pixels, as matplotlib's own export rasterises them (abutting
    # rectangles would show seams and edges where the image shows none).
    fig.canvas.draw()
    x0, y0, x1, y1 = cb.ax.get_window_extent().extents
    h = mine.shape[0]
    zoom = mine.shape[1] / fig.canvas.get_width_height()[0]
    rows = slice(int(h - y1 * zoom) + 2, int(h - y0 * zoom) - 2)
    cols = slice(int(x0 * zoom) + 2, int(x1 * zoom) - 2)
    diff = np.abs(mine[rows, cols, :3] - theirs[rows, cols, :3]).max()
    assert diff < 0.02, diff
    plt.close(fig)


def test_contour_lines_are_hidden_where_a_surface_lies_in_front(tmp_path):
    # Contour lines x = -0.5, 0, 0.5 drawn at z = 0 and the sheet z = y crossing them:
    # where y < 0 the lines lie over the sheet, where y > 0 under it.
    fig, ax = axes()
    x, y = np.meshgrid(np.linspace(-1, 1, 21), np.linspace(-1, 1, 21))
    ax.plot_surface(x, y, y, color=BLUE, shade=False, linewidth=0)
    ax.contour(x, y, x, levels=[-0.5, 0.5], colors=[RED], offset=0, zdir="z", linewidths=6)
    mine, _ = both(fig, tmp_path)
    for p, want in [((0.5, -0.5, 0.0), RED), ((-0.5, -0.6, 0.0), RED)]:
        assert near(colour_at(fig, ax, mine, p), want, 0.1), (p, colour_at(fig, ax, mine, p))
    for p in [(0.5, 0.5, 0.0), (-0.5, 0.6, 0.0)]:  # the lines' parts under the sheet
        assert near(colour_at(fig, ax, mine, p), BLUE), (p, colour_at(fig, ax, mine, p))
    plt.close(fig)


def test_a_non_planar_polygon_covers_its_projected_outline(tmp_path):
    # plot_surface with a stride of 2: polygons of 8 corners round 2×2 cells of a height
    # field with sharp valleys. matplotlib fills each polygon's projected outline, which
    # dips into the valleys; triangles across a valley would cover what lies beyond it.
    fig, ax = axes()
    ax.view_init(elev=30, azim=-60)
    x, y = np.mgrid[0 : 6 * np.pi : 0.25, 0 : 4 * np.pi : 0.25]
    z = np.sqrt(np.abs(np.cos(x) + np.cos(y)))
    ax.set(xlim=(0, 6 * np.pi), ylim=(0, 4 * np.pi), zlim=(0, 2))
    ax.plot_surface(x, y, z, color=BLUE, shade=False, rstride=2, cstride=2, linewidth=0)
    mine, theirs = both(fig, tmp_path, zoom=2.0)
    bg = lambda img: (img[:, :, :3] > 0.97).all(axis=2)  # noqa: E731
    # Pixels covered beyond matplotlib's: antialiasing, and the polygons whose projected
    # outline crosses itself (limn's own triangles; 2.5 % of the surface's pixels when
    # every polygon is).
    extra = int((~bg(mine) & bg(theirs)).sum())
    assert extra < 0.015 * int((~bg(theirs)).sum()), (extra, int((~bg(theirs)).sum()))
    plt.close(fig)


def test_only_a_cut_polygons_own_edges_are_stroked(tmp_path):
    # A non-planar hexagon (cut into four triangles in the view) with thick black edges:
    # its middle, crossed by the cuts, stays the face colour.
    fig, ax = axes()
    t = np.linspace(0, 2 * np.pi, 7)[:-1]
    hexagon = np.c_[0.8 * np.cos(t), 0.8 * np.sin(t), 0.1 * np.cos(3 * t)]
    ax.add_collection3d(
        Poly3DCollection([hexagon], facecolors=[BLUE], edgecolors="k", linewidths=4)
    )
    mine, theirs = both(fig, tmp_path)
    for p in [(0.0, 0.0, 0.0), (0.3, 0.1, 0.0), (-0.2, -0.3, 0.0), (0.1, 0.4, 0.0)]:
        c, want = colour_at(fig, ax, mine, p), colour_at(fig, ax, theirs, p)
        assert near(want, BLUE) and near(c, BLUE), (p, c, want)
    edge = (*hexagon[0, :2], hexagon[0, 2])
    assert near(colour_at(fig, ax, mine, edge), (0, 0, 0), 0.2)
    plt.close(fig)


def test_bars_of_ax_bar_are_ordered_with_the_surfaces(tmp_path):
    # ax.bar in the plane y = -0.5 (zdir="y"), in front of the sheet z = 0 that it
    # pokes through: the bar's upper part in front, its lower part under the sheet.
    fig, ax = axes()
    x, y = np.meshgrid(np.linspace(-1, 1, 5), np.linspace(-1, 1, 5))
    ax.plot_surface(x, y, 0 * x, color=BLUE, shade=False, linewidth=0)
    ax.bar([0.0], [0.8], width=0.6, bottom=-0.4, zs=-0.5, zdir="y", color=RED)
    mine, _ = both(fig, tmp_path)
    assert near(colour_at(fig, ax, mine, (0.0, -0.5, 0.2)), RED)  # above the sheet
    assert near(colour_at(fig, ax, mine, (0.0, -0.5, -0.2)), BLUE)  # under it
    plt.close(fig)


def test_a_quad_seen_as_a_bow_tie_is_filled_as_matplotlib_fills_it(tmp_path):
    # A twisted translucent quad (fill_between's strips): two opposite edges cross in
    # the view, and matplotlib fills the two lobes of the bow-tie once each.
    fig, ax = axes()
    ax.view_init(elev=0, azim=-90)  # seen along y
    quad = np.array([(-0.6, -0.5, -0.5), (0.6, 0.5, 0.5), (0.6, -0.5, -0.5), (-0.6, 0.5, 0.5)])
    ax.add_collection3d(Poly3DCollection([quad], facecolors=[BLUE + (0.5,)]))
    mine, theirs = both(fig, tmp_path)
    bg = lambda img: (img[:, :, :3] > 0.97).all(axis=2)  # noqa: E731
    differ = (np.abs(mine[:, :, :3] - theirs[:, :, :3]) > 0.1).any(axis=2)
    assert int((~bg(theirs)).sum()) > 1000
    # Antialiasing along the crossing edges apart (limn's triangles cover a lobe where
    # the quad's own two triangles would overlap or leave half of it out).
    assert differ.sum() < 0.1 * int((~bg(theirs)).sum()), int(differ.sum())
    plt.close(fig)


def test_abutting_cells_overlap_their_strokes_in_matplotlibs_order(tmp_path):
    # Two coplanar cells with thick strokes in their face colours (plot_surface's
    # default, as imshow3d in the gallery draws): nothing orders them, and the stroke of
    # the one mplot3d paints last covers the shared edge. Listed either way round.
    for cells in ((BLUE, RED), (RED, BLUE)):
        fig, ax = axes()
        squares = [
            [(-0.6, -0.3, 0), (0, -0.3, 0), (0, 0.3, 0), (-0.6, 0.3, 0)],
            [(0, -0.3, 0), (0.6, -0.3, 0), (0.6, 0.3, 0), (0, 0.3, 0)],
        ]
        colours = [c + (1.0,) for c in cells]
        ax.add_collection3d(
            Poly3DCollection(squares, facecolors=colours, edgecolors=colours, linewidths=8)
        )
        mine, theirs = both(fig, tmp_path)
        for p in [(-0.03, 0.0, 0.0), (0.03, 0.0, 0.0), (-0.03, 0.2, 0.0), (0.03, -0.2, 0.0)]:
            c, want = colour_at(fig, ax, mine, p), colour_at(fig, ax, theirs, p)
            assert near(c, want, 0.1), (cells, p, c, want)
        plt.close(fig)
