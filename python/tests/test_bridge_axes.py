"""The matplotlib bridge and the axes around the data: panes, grid lines and axis lines
in limn's scene, 3D texts, depth-shaded scatter points and the other polygon plots,
each checked on the rasterised file against matplotlib's own export of the figure."""

import re

import matplotlib as mpl
import numpy as np
import pytest

mpl.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import limn.matplotlib as lm  # noqa: E402
from probes import colour_at, count_colour, near, raster  # noqa: E402

RED = (0.85, 0.25, 0.2)
BLUE = (0.2, 0.4, 0.85)
GREEN = (0.0, 0.5, 0.0)
PANE = (0.95, 0.85, 0.3)  # an opaque yellow pane


def both(fig, tmp_path, zoom=3.0):
    """matplotlib's own export of ``fig`` and the bridge's, rasterised."""
    fig.savefig(tmp_path / "mpl.svg")
    lm.savefig(fig, tmp_path / "limn.svg")
    return (
        raster((tmp_path / "limn.svg").read_bytes(), zoom),
        raster((tmp_path / "mpl.svg").read_bytes(), zoom),
    )


def box_axes(**rc):
    """A 3D axes with limits [-1, 1] on every axis, seen from elev 20, azim -60: the
    panes are the walls x = -1, y = 1 and the floor z = -1."""
    with mpl.rc_context(rc):
        fig = plt.figure(figsize=(4, 3))
        ax = fig.add_subplot(projection="3d")
    ax.set_xlim(-1, 1)
    ax.set_ylim(-1, 1)
    ax.set_zlim(-1, 1)
    ax.view_init(elev=20, azim=-60)
    return fig, ax


def sheet_through_the_back_wall(ax):
    """A flat red sheet at z = 0 reaching from inside the box out through the back wall
    y = 1 to y = 1.6, in cells 0.3 by 0.2 (probes sit at cell centres, off the seams)."""
    x, y = np.meshgrid(np.linspace(-0.6, 0.6, 5), np.linspace(-0.6, 1.6, 12))
    ax.plot_surface(x, y, 0 * x, color=RED, shade=False, linewidth=0)


@pytest.mark.parametrize("proj", ["persp", "ortho"])
def test_a_surface_crossing_a_pane_is_cut_by_it(tmp_path, proj):
    fig, ax = box_axes()
    ax.set_proj_type(proj)
    ax.grid(False)
    ax.yaxis.set_pane_color(PANE, alpha=1.0)
    sheet_through_the_back_wall(ax)
    mine, theirs = both(fig, tmp_path)
    # In front of the wall the sheet shows; the part behind the opaque wall does not,
    # the wall does. matplotlib draws the panes first, so its export shows the sheet
    # through the wall.
    for p, want, mpl_shows in [
        ((0.15, 0.3, 0.0), RED, RED),
        ((0.45, -0.5, 0.0), RED, RED),
        ((0.15, 1.3, 0.0), PANE, RED),
        ((-0.45, 1.5, 0.0), PANE, RED),
        ((0.5, 1.0, 0.7), PANE, PANE),  # on the wall, above the sheet
    ]:
        assert near(colour_at(fig, ax, mine, p), want), (p, colour_at(fig, ax, mine, p))
        assert near(colour_at(fig, ax, theirs, p), mpl_shows), p
    plt.close(fig)


def test_grid_lines_are_hidden_behind_a_surface_and_drawn_over_what_lies_behind_their_pane(
    tmp_path,
):
    fig, ax = box_axes(**{"grid.color": GREEN, "grid.linewidth": 2.0})
    sheet_through_the_back_wall(ax)
    mine, theirs = both(fig, tmp_path)
    # The grid line x = 0 on the back wall y = 1. Below the sheet (z < 0) the sheet in
    # front of the wall hides it; just above the sheet it runs in front of the part of
    # the sheet behind the wall, where matplotlib's export paints the sheet over it.
    for z in (-0.25, -0.2, -0.15):
        assert near(colour_at(fig, ax, mine, (0.0, 1.0, z)), RED), z
        assert near(colour_at(fig, ax, theirs, (0.0, 1.0, z)), RED), z
    for z in (0.1, 0.15, 0.2):
        assert near(colour_at(fig, ax, mine, (0.0, 1.0, z)), GREEN), z
        assert near(colour_at(fig, ax, theirs, (0.0, 1.0, z)), RED), z
    # Away from the sheet it is drawn as matplotlib draws it.
    for z in (0.7, 0.8):
        assert near(colour_at(fig, ax, mine, (0.0, 1.0, z)), GREEN), z
        assert near(colour_at(fig, ax, theirs, (0.0, 1.0, z)), GREEN), z
    plt.close(fig)


def scatter_in_a_box(**kwargs):
    """25 overlapping, colormapped scatter points inside the box, with axis labels and a
    title: nothing intersects, so the bridge's picture should be matplotlib's."""
    fig, ax = box_axes()
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    ax.set_title("points")
    rng = np.random.default_rng(3)
    pts = rng.uniform(-0.9, 0.9, (25, 3))
    sc = ax.scatter(*pts.T, s=60, c=rng.random(25), cmap="viridis", **kwargs)
    return fig, ax, pts, sc


def test_depth_shaded_scatter_and_the_axes_register_with_matplotlibs_own_export(tmp_path):
    fig, ax, pts, _ = scatter_in_a_box()  # depthshade=True, matplotlib's default
    mine, theirs = both(fig, tmp_path)
    # At every point's centre the colour (its alpha by depth over the panes and grid)
    # is matplotlib's.
    for p in pts:
        assert near(colour_at(fig, ax, mine, p), colour_at(fig, ax, theirs, p), 0.03), p
    # And so is the rest: panes, grid, axis lines, ticks, tick labels, axis labels and
    # title land on the same pixels.
    diff = np.abs(mine[:, :, :3] - theirs[:, :, :3]).max(axis=2)
    assert (diff > 0.1).sum() < 0.0005 * diff.size, (diff > 0.1).sum()
    # The shading matters: without it the points' colours differ (so the check above
    # can fail).
    plain, _, _, _ = scatter_in_a_box(depthshade=False)
    lm.savefig(plain, tmp_path / "plain.svg")
    flat = raster((tmp_path / "plain.svg").read_bytes(), 3.0)
    faded = sum(
        not near(colour_at(fig, ax, flat, p), colour_at(fig, ax, mine, p), 0.05) for p in pts
    )
    assert faded > 10, faded
    plt.close(fig)
    plt.close(plain)


@pytest.mark.parametrize("alpha", [None, 0.6])
def test_depth_shaded_alphas_are_mplot3ds(alpha):
    from matplotlib.collections import PathCollection

    from limn._depth_shading import depth_shaded

    fig, ax, pts, sc = scatter_in_a_box(alpha=alpha)
    fig.canvas.draw()
    # mplot3d's colours come sorted far to near; put them back in input order.
    theirs = np.empty((len(pts), 4))
    theirs[sc._z_markers_idx] = sc.get_facecolor()
    plain = PathCollection.get_facecolor(sc)
    mine = depth_shaded(plain, pts, ax.M, sc._depthshade_minalpha, alpha)
    assert np.allclose(mine, theirs, rtol=0, atol=1e-12)
    assert np.ptp(mine[:, 3]) > 0.1  # the alphas do vary with depth
    plt.close(fig)


def test_a_text_behind_a_surface_is_hidden(tmp_path):
    fig, ax = box_axes()
    ax.grid(False)
    sheet_through_the_back_wall(ax)
    ax.text(0.0, 0.2, -0.4, "under", color=BLUE, fontsize=14, ha="center")
    ax.text(0.0, 0.2, 0.3, "over", color=GREEN, fontsize=14, ha="center")
    mine, theirs = both(fig, tmp_path)
    # matplotlib draws both texts over the sheet; the bridge only the one above it.
    assert count_colour(theirs, BLUE, 0.15) > 50
    assert count_colour(mine, BLUE, 0.15) == 0
    assert count_colour(mine, GREEN, 0.15) > 50
    # The shown text is matplotlib's own: same glyphs at the same place.
    assert abs(count_colour(mine, GREEN, 0.15) - count_colour(theirs, GREEN, 0.15)) < 10
    plt.close(fig)


def test_interpenetrating_bars_are_ordered_exactly(tmp_path):
    fig, ax = box_axes()
    ax.grid(False)
    # A wide slab and a post through it, in one bar3d collection.
    ax.bar3d(
        [-0.8, -0.15],
        [-0.8, -0.15],
        [0.0, -0.9],
        [1.6, 0.3],
        [1.6, 0.3],
        [0.2, 1.8],
        color=[RED, BLUE],
        shade=False,
    )
    mine, theirs = both(fig, tmp_path)
    probes = [
        ((0.15, 0.0, 0.45), BLUE),  # the post's right face above the slab
        ((0.0, -0.15, 0.3), BLUE),  # the post's front face above the slab
        ((0.0, -0.3, 0.2), RED),  # the slab's top in front of the post
        ((0.0, -0.15, -0.6), BLUE),  # the post under the slab, seen past its front edge
    ]
    mpl_wrong = 0
    for p, want in probes:
        assert near(colour_at(fig, ax, mine, p), want), (p, colour_at(fig, ax, mine, p))
        mpl_wrong += not near(colour_at(fig, ax, theirs, p), want)
    # One depth per face cannot draw a post through a slab: matplotlib paints the slab
    # over the post's side and the post over the slab's top.
    assert mpl_wrong >= 2
    plt.close(fig)


PANES = {"x": (0.9, 0.6, 0.6), "y": (0.6, 0.9, 0.6), "z": (0.6, 0.6, 0.9)}


@pytest.mark.parametrize("variant", ["default", "grid off", "axis off", "x pane unfilled"])
@pytest.mark.parametrize("point", [(0.0, 0.0, 0.0), (0.0, 0.0, -1.3)], ids=["inside", "below"])
def test_the_axes_own_settings_are_respected(tmp_path, variant, point):
    # With the point inside the box, matplotlib draws the box (behind everything, which
    # is exact); with the point below the floor, the box is limn scene content and the
    # floor hides the point.
    fig, ax = box_axes(**{"grid.color": GREEN})
    for name, colour in PANES.items():
        getattr(ax, f"{name}axis").set_pane_color(colour, alpha=1.0)
    ax.scatter(*([c] for c in point), color=RED, s=20)
    if variant == "grid off":
        ax.grid(False)
    elif variant == "axis off":
        ax.set_axis_off()
    elif variant == "x pane unfilled":
        ax.xaxis.pane.fill = False
    mine, theirs = both(fig, tmp_path, zoom=2.0)
    counts = {}
    for name, colour in list(PANES.items()) + [("grid", GREEN)]:
        a, b = count_colour(mine, colour, 0.05), count_colour(theirs, colour, 0.05)
        assert abs(a - b) <= max(0.02 * b, 20), (name, a, b)
        counts[name] = a
    if variant == "default":
        assert min(counts.values()) > 1000, counts
    elif variant == "grid off":
        assert counts["grid"] == 0 and counts["x"] > 1000
    elif variant == "axis off":
        assert sum(counts.values()) < 20, counts  # the point's antialiased rim at most
    else:  # the x pane's outline is left, under the grid's edge lines
        assert counts["x"] < 50 and counts["y"] > 1000, counts
    # matplotlib draws the point over the floor; the bridge hides it behind the floor
    # (there is no floor with the axes off).
    assert count_colour(theirs, RED) > 20
    hidden = point[2] < -1 and variant != "axis off"
    assert (count_colour(mine, RED) == 0) == hidden
    plt.close(fig)


def test_quiver_arrows_are_hidden_where_they_pass_under_a_surface(tmp_path):
    fig, ax = box_axes()
    ax.grid(False)
    sheet_through_the_back_wall(ax)
    # One arrow up through the sheet: its shaft and head are a Line3DCollection.
    ax.quiver(0.15, 0.3, -0.6, 0, 0, 1.2, color=GREEN, linewidth=3, arrow_length_ratio=0.2)
    mine, theirs = both(fig, tmp_path)
    below, above = (0.15, 0.3, -0.2), (0.15, 0.3, 0.3)
    assert near(colour_at(fig, ax, mine, below), RED)
    assert near(colour_at(fig, ax, mine, above), GREEN)
    # matplotlib gives the arrow one depth and paints the sheet over all of it.
    assert near(colour_at(fig, ax, theirs, below), RED)
    assert near(colour_at(fig, ax, theirs, above), RED)
    plt.close(fig)


def test_the_box_drawn_by_limn_is_the_box_matplotlib_draws(tmp_path):
    # With the data inside the box, "auto" leaves the box to matplotlib; "limn" makes it
    # scene content. The two pictures agree but for antialiasing.
    fig, ax, pts, _ = scatter_in_a_box()
    lm.savefig(fig, tmp_path / "auto.svg")
    lm.savefig(fig, tmp_path / "limn.svg", box="limn")
    a = raster((tmp_path / "auto.svg").read_bytes(), 3.0)
    b = raster((tmp_path / "limn.svg").read_bytes(), 3.0)
    diff = np.abs(a[:, :, :3] - b[:, :, :3]).max(axis=2)
    assert (diff > 0.1).sum() < 0.0005 * diff.size, (diff > 0.1).sum()
    # "matplotlib" always leaves the box to matplotlib: the sheet through the back wall
    # is then drawn over the wall, as in matplotlib's own export.
    fig2, ax2 = box_axes()
    ax2.grid(False)
    ax2.yaxis.set_pane_color(PANE, alpha=1.0)
    sheet_through_the_back_wall(ax2)
    lm.savefig(fig2, tmp_path / "mpl_box.svg", box="matplotlib")
    img = raster((tmp_path / "mpl_box.svg").read_bytes(), 3.0)
    assert near(colour_at(fig2, ax2, img, (0.15, 1.3, 0.0)), RED)
    plt.close(fig)
    plt.close(fig2)


@pytest.mark.filterwarnings("ignore:overflow:RuntimeWarning")
def test_bad_input_raises_and_leaves_no_file(tmp_path):
    fig = plt.figure(figsize=(4, 3))
    ax = fig.add_subplot(projection="3d")  # limits from the data: no usable projection
    x, y = np.meshgrid([0.0, 1.0], [0.0, 1.0])
    ax.plot_surface(x, y, np.array([[0.0, 1e300], [0.0, 1e308]]))
    with pytest.raises(ValueError):
        lm.savefig(fig, tmp_path / "huge.svg")
    with pytest.raises(ValueError, match="box"):
        lm.savefig(fig, tmp_path / "box.svg", box="pane")
    with pytest.raises(OSError, match="no folder"):
        lm.savefig(fig, tmp_path / "missing" / "f.svg")
    assert list(tmp_path.iterdir()) == []
    plt.close(fig)


def test_a_tight_bounding_box_is_matplotlibs_and_limn_orders_once(tmp_path, monkeypatch):
    import re

    import limn

    calls = []
    paint = limn.Scene.paint_with_marks
    monkeypatch.setattr(
        limn.Scene, "paint_with_marks", lambda s, **k: calls.append(1) or paint(s, **k)
    )
    fig, ax = box_axes()
    sheet_through_the_back_wall(ax)
    fig.savefig(tmp_path / "mpl.svg", bbox_inches="tight")
    lm.savefig(fig, tmp_path / "limn.svg", bbox_inches="tight")
    # matplotlib's measuring pass draws nothing: limn orders the scene once.
    assert len(calls) == 1
    size = lambda f: re.search(rb'width="[^"]+" height="[^"]+"', f.read_bytes()).group(0)  # noqa
    assert size(tmp_path / "limn.svg") == size(tmp_path / "mpl.svg")
    plt.close(fig)


@pytest.mark.parametrize(
    "style",
    [
        dict(facecolors="none", edgecolors="r"),
        dict(c="b", edgecolors="k", linewidths=2),
        dict(c=np.linspace(0, 1, 20), alpha=0.5),
        dict(s=np.linspace(5, 80, 20), marker="^"),
        dict(c="g", depthshade=False),
    ],
    ids=["hollow", "edged", "alpha", "sizes", "flat"],
)
def test_scatter_styles_are_drawn_as_matplotlib_draws_them(tmp_path, style):
    fig = plt.figure(figsize=(4, 3))
    ax = fig.add_subplot(projection="3d")
    ax.scatter(*np.random.default_rng(0).uniform(-1, 1, (3, 20)), **style)
    mine, theirs = both(fig, tmp_path, zoom=2.0)
    diff = np.abs(mine[:, :, :3] - theirs[:, :, :3]).max(axis=2)
    assert (diff > 0.1).sum() < 0.0005 * diff.size, (diff > 0.1).sum()
    plt.close(fig)


def test_a_scatter_is_written_as_matplotlib_writes_it_its_marker_once(tmp_path):
    # Markers painted one after another go to the backend as one path collection: the
    # SVG holds the marker's path once and places it at every point, as matplotlib's own
    # export does, with each point's own depth-shaded colour.
    fig = plt.figure(figsize=(4, 3))
    ax = fig.add_subplot(projection="3d")
    ax.scatter(*np.random.default_rng(1).uniform(-1, 1, (3, 40)), s=30)
    fig.savefig(tmp_path / "mpl.svg")
    lm.savefig(fig, tmp_path / "limn.svg")
    mine, theirs = (tmp_path / "limn.svg").read_text(), (tmp_path / "mpl.svg").read_text()
    uses = lambda svg: len(re.findall(r'<use xlink:href="#C', svg))  # noqa: E731
    assert uses(mine) == uses(theirs) == 40
    assert len(mine) < 1.2 * len(theirs), (len(mine), len(theirs))
    opacities = set(re.findall(r"fill-opacity: ([0-9.]+)", mine))
    assert len(opacities) > 10  # depth shading kept per point
    plt.close(fig)


def test_a_surface_edged_in_its_own_colours_gets_no_seam_flaps(tmp_path):
    # plot_surface with face colours strokes each quad in its own colour: the strokes
    # cover the seams, so the bridge writes the quads as matplotlib does, without flaps
    # (which doubled the file), and the picture stays matplotlib's.
    fig = plt.figure(figsize=(4, 3))
    ax = fig.add_subplot(projection="3d")
    x, y = np.meshgrid(np.linspace(-1, 1, 25), np.linspace(-1, 1, 25))
    colours = plt.cm.viridis((x + y + 2) / 4)
    ax.plot_surface(x, y, 0.3 * x - 0.2 * y, facecolors=colours, shade=False)
    mine, theirs = both(fig, tmp_path, zoom=2.0)
    diff = np.abs(mine[:, :, :3] - theirs[:, :, :3]).max(axis=2)
    assert (diff > 0.1).sum() < 0.002 * diff.size, (diff > 0.1).sum()
    size = lambda name: (tmp_path / name).stat().st_size  # noqa: E731
    assert size("limn.svg") < 1.1 * size("mpl.svg"), (size("limn.svg"), size("mpl.svg"))
    plt.close(fig)
