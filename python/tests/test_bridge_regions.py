"""Filled paths in limn's scene: filled contour sets (``contourf`` with ``zdir`` and
``offset``) and ``PathPatch3D``s (circles, glyphs), filled as matplotlib fills them (the
nonzero rule, holes, crossing outlines) and ordered exactly with the surfaces around
them; checked against limn's ray casting and on the rasterised file."""

import matplotlib as mpl
import numpy as np
import pytest

mpl.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.path import Path  # noqa: E402

import limn  # noqa: E402
import limn.matplotlib as lm  # noqa: E402
from limn._regions import outlines, region_faces  # noqa: E402
from probes import colour_at, near, raster  # noqa: E402

RED = (0.85, 0.25, 0.2)
BLUE = (0.2, 0.4, 0.85)
GREEN = (0.1, 0.6, 0.3)


def square(a, b, z=0.0):
    return np.array([(a, a, z), (b, a, z), (b, b, z), (a, b, z)], dtype=float)


def area(p):
    x, y = p[:, 0], p[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def covered(faces, xy):
    """Whether the point (x, y) is inside one of the faces (in the plane z = const)."""
    return any(Path(f[:, :2]).contains_point(xy) for f, _ in faces)


def test_a_region_with_a_hole_is_filled_around_it():
    faces = region_faces([square(0, 4), square(1, 3)[::-1]])
    assert sum(abs(area(f)) for f, _ in faces) == pytest.approx(12.0)
    assert not covered(faces, (2, 2)) and covered(faces, (0.5, 2)) and covered(faces, (3.5, 2))
    # The cuts between the pieces are not edges of the path: never stroked.
    for f, own in faces:
        for i in np.nonzero(own)[0]:
            a, b = f[i, :2], f[(i + 1) % len(f), :2]
            on_outline = any(
                (a[k] == b[k] and a[k] in (0, 1, 3, 4)) for k in range(2)
            )
            assert on_outline, (a, b)


def test_a_region_without_holes_is_one_face_with_all_its_edges():
    l_shape = np.array([(0, 0, 0), (4, 0, 0), (4, 1, 0), (1, 1, 0), (1, 4, 0), (0, 4, 0)], float)
    ((face, own),) = region_faces([l_shape])
    assert len(face) == 6 and own.all()


@pytest.mark.parametrize(
    "rings, want, inside, outside",
    [
        # Two squares of one orientation overlapping: their union.
        ([square(0, 2), square(1, 3)], 7.0, [(0.5, 0.5), (1.5, 1.5), (2.5, 2.5)], [(2.5, 0.5)]),
        # The same orientation inside: nonzero fills the inner square too.
        ([square(0, 4), square(1, 3)], 16.0, [(2, 2), (0.5, 0.5)], []),
        # A bow-tie: both lobes (its signed area is zero).
        (
            [np.array([(0, 0, 0), (2, 2, 0), (2, 0, 0), (0, 2, 0)], float)],
            2.0,
            [(1.5, 1.0), (0.5, 1.0)],
            [(1.0, 0.5), (1.0, 1.5)],
        ),
    ],
)
def test_outlines_are_filled_by_the_nonzero_rule(rings, want, inside, outside):
    faces = region_faces(rings)
    assert sum(abs(area(f)) for f, _ in faces) == pytest.approx(want)
    for xy in inside:
        assert covered(faces, xy), xy
    for xy in outside:
        assert not covered(faces, xy), xy


def winding(rings, xy):
    """The winding number of the outlines ``rings`` around the point (x, y)."""
    total = 0
    for r in rings:
        a, b = r[:, :2], np.roll(r[:, :2], -1, axis=0)
        up = (a[:, 1] <= xy[1]) & (b[:, 1] > xy[1])
        down = (a[:, 1] > xy[1]) & (b[:, 1] <= xy[1])
        side = (b[:, 0] - a[:, 0]) * (xy[1] - a[:, 1]) - (xy[0] - a[:, 0]) * (b[:, 1] - a[:, 1])
        total += int(np.sum(up & (side > 0)) - np.sum(down & (side < 0)))
    return total


def band(n=120, shift=0.0):
    """One outline of two curves crossing twice, as a filled contour of a folded surface
    gives (``contourf(..., zdir="x")``): out along one curve, back along the other."""
    x = np.linspace(-3, 3, n)
    lower = np.c_[x, np.sin(x) * 2 - 0.5 + shift, np.zeros(n)]
    upper = np.c_[x, np.sin(x) + shift, np.zeros(n)][::-1]
    return np.vstack([lower, upper])


@pytest.mark.parametrize(
    "rings",
    [
        [band()],
        # Two rings crossing each other, one turned the other way: their overlap has
        # winding number zero.
        [square(0, 2), square(1, 3)[::-1]],
        # A band and a square over it.
        [band(), square(-1, 1)],
        # A ring winding twice round its middle.
        [np.array([(0, 0, 0), (4, 0, 0), (4, 4, 0), (1, 4, 0), (1, 1, 0), (3, 1, 0), (3, 3, 0), (0, 3, 0)], float)],
    ],
)
def test_crossing_outlines_are_uncrossed_not_cut_into_trapezoids(rings):
    faces = region_faces(rings)
    # Every face lies where the outlines' winding number is not zero, and every such
    # point is in exactly one face (probed on a grid that misses the outlines' corners).
    lo = np.concatenate(rings)[:, :2].min(axis=0) - 0.5
    hi = np.concatenate(rings)[:, :2].max(axis=0) + 0.5
    for x in np.linspace(lo[0], hi[0], 41) + 1e-3:
        for y in np.linspace(lo[1], hi[1], 37) + 2e-3:
            inside = sum(Path(f[:, :2]).contains_point((x, y)) for f, _ in faces)
            assert inside == (winding(rings, (x, y)) != 0), (x, y)
    # Pieces of the given outlines, not slabs: few faces, few new corners.
    corners = sum(len(r) for r in rings)
    assert len(faces) <= 6
    assert sum(len(f) for f, _ in faces) <= corners + 4 * len(faces) + 8


def test_glyph_outlines_keep_their_holes():
    from matplotlib.text import TextPath

    tp = TextPath((0, 0), "go", size=1)
    verts = np.c_[tp.vertices, np.zeros(len(tp.vertices))]
    rings = outlines(verts, tp.codes)
    faces = region_faces(rings)
    # The filled area is matplotlib's: the outlines' signed areas, holes subtracted.
    want = sum(abs(area(f)) for f, _ in [(r, None) for r in rings if area(r) < 0]) - sum(
        area(r) for r in rings if area(r) > 0
    )
    assert sum(abs(area(f)) for f, _ in faces) == pytest.approx(abs(want), rel=1e-9)
    # The middle of the o's counter is empty, its ring is not.
    o = [r for r in rings if r[:, 0].min() > 0.5]
    inner = min(o, key=lambda r: abs(area(r)))
    centre = tuple(inner[:, :2].mean(axis=0))
    assert not covered(faces, centre)
    assert covered(faces, (centre[0], inner[:, 1].min() - 0.02))


def test_curves_are_flattened_close_to_the_curve():
    circle = Path.circle((0, 0), 1.0)
    (ring,) = outlines(np.c_[circle.vertices, np.zeros(len(circle.vertices))], circle.codes)
    r = np.hypot(ring[:, 0], ring[:, 1])
    assert np.abs(r - 1).max() < 1e-3 and len(ring) > 64


def test_glyph_faces_crossed_by_a_plane_agree_with_ray_casting(tmp_path):
    from matplotlib.text import TextPath

    tp = TextPath((0, 0), "B8", size=2)
    verts = np.c_[tp.vertices - [1.2, 0.7], np.zeros(len(tp.vertices))]
    faces = region_faces(outlines(verts, tp.codes))
    s = limn.Scene()
    v = np.concatenate([f for f, _ in faces])
    counts = np.array([len(f) for f, _ in faces])
    s.add_mesh(v, np.arange(len(v)), counts=counts, colors=np.tile([0.1, 0.6, 0.3], (len(counts), 1)))
    plane = np.array([(-2, -1, -0.5), (2, -1, -0.5), (2, 1, 0.5), (-2, 1, 0.5)], float)
    s.add_mesh(plane, np.array([[0, 1, 2, 3]]), colors=np.array([[0.85, 0.25, 0.2]]))
    s.set_camera(eye=(0.5, -3.0, 4.0), target=(0, 0, 0), size=(240, 180))
    report = s.check(against="raycast")
    assert report["mismatches_outside_band"] == 0, report


def box_axes(elev=60, azim=-60):
    fig = plt.figure(figsize=(4, 3))
    ax = fig.add_subplot(projection="3d")
    ax.set_xlim(-1, 1)
    ax.set_ylim(-1, 1)
    ax.set_zlim(-1, 1)
    ax.view_init(elev=elev, azim=azim)
    ax.grid(False)
    return fig, ax


def both(fig, tmp_path, zoom=3.0):
    fig.savefig(tmp_path / "mpl.svg")
    lm.savefig(fig, tmp_path / "limn.svg")
    return (
        raster((tmp_path / "limn.svg").read_bytes(), zoom),
        raster((tmp_path / "mpl.svg").read_bytes(), zoom),
    )


def test_a_filled_contour_set_at_an_offset_is_ordered_with_a_surface_through_it(tmp_path):
    fig, ax = box_axes()
    x, y = np.meshgrid(np.linspace(-0.8, 0.8, 9), np.linspace(-0.8, 0.8, 9))
    # A ring (a region with a hole) on the plane z = 0, a tilted sheet through it.
    r = np.hypot(*np.meshgrid(np.linspace(-0.8, 0.8, 41), np.linspace(-0.8, 0.8, 41)))
    gx, gy = np.meshgrid(np.linspace(-0.8, 0.8, 41), np.linspace(-0.8, 0.8, 41))
    ax.contourf(gx, gy, r, levels=[0.35, 5.0], colors=[BLUE], zdir="z", offset=0.0)
    ax.plot_surface(x, y, 0.5 * x, color=RED, shade=False, linewidth=0)
    mine, theirs = both(fig, tmp_path)
    probes = [
        ((0.6, 0.6, 0.3), RED),  # the sheet above the ring
        ((-0.6, 0.6, 0.0), BLUE),  # the ring above the sheet
        ((-0.6, -0.6, 0.0), BLUE),
        ((-0.12, 0.0, -0.06), RED),  # the sheet seen through the ring's hole
    ]
    mpl_wrong = 0
    for p, want in probes:
        assert near(colour_at(fig, ax, mine, p), want), (p, colour_at(fig, ax, mine, p))
        mpl_wrong += not near(colour_at(fig, ax, theirs, p), want)
    assert mpl_wrong > 0  # matplotlib draws the whole set over or under the sheet
    plt.close(fig)


def test_a_filled_contour_set_on_a_pane_stays_in_front_of_it(tmp_path):
    # The data leave the box, so the panes are limn's; the set lies in the floor pane.
    fig, ax = box_axes(elev=30)
    ax.xaxis.set_pane_color((0.95, 0.85, 0.3), alpha=1.0)
    ax.yaxis.set_pane_color((0.95, 0.85, 0.3), alpha=1.0)
    ax.zaxis.set_pane_color((0.95, 0.85, 0.3), alpha=1.0)
    gx, gy = np.meshgrid(np.linspace(-1, 1, 21), np.linspace(-1, 1, 21))
    ax.contourf(gx, gy, gx, levels=[-2, 0, 2], colors=[BLUE, GREEN], zdir="z", offset=-1.0)
    ax.plot([0, 0], [0, 0], [0.5, 1.4], color="k")  # leaves the box
    mine, theirs = both(fig, tmp_path)
    for p, want in [((-0.5, 0.0, -1.0), BLUE), ((0.5, 0.0, -1.0), GREEN)]:
        assert near(colour_at(fig, ax, mine, p), want), (p, colour_at(fig, ax, mine, p))
        assert near(colour_at(fig, ax, theirs, p), want)
    plt.close(fig)


def test_a_path_patch_is_hidden_where_a_surface_passes_in_front(tmp_path):
    from matplotlib.patches import Circle
    import mpl_toolkits.mplot3d.art3d as art3d

    fig, ax = box_axes(elev=30)
    disc = Circle((0.0, 0.0), 0.6, color=GREEN)
    ax.add_patch(disc)
    art3d.pathpatch_2d_to_3d(disc, z=0.0, zdir="x")  # upright in the plane x = 0
    x, y = np.meshgrid(np.linspace(-0.9, 0.9, 7), np.linspace(-0.9, 0.9, 7))
    ax.plot_surface(x, y, 0 * x, color=RED, shade=False, linewidth=0)
    mine, theirs = both(fig, tmp_path)
    probes = [((0.0, 0.0, 0.4), GREEN), ((0.0, 0.1, -0.4), RED)]
    mpl_wrong = 0
    for p, want in probes:
        assert near(colour_at(fig, ax, mine, p), want), (p, colour_at(fig, ax, mine, p))
        mpl_wrong += not near(colour_at(fig, ax, theirs, p), want)
    assert mpl_wrong > 0
    plt.close(fig)


def shifted_square(x, y, size, z=0.0):
    return np.array(
        [(x, y, z), (x + size, y, z), (x + size, y + size, z), (x, y + size, z)], dtype=float
    )


def test_a_region_with_holes_is_one_face_its_holes_joined_by_cuts(tmp_path):
    # A 10 × 4 rectangle with three 1 × 1 holes side by side (given clockwise).
    holes = [shifted_square(x, 1.5, 1.0)[::-1] for x in (1.0, 4.5, 8.0)]
    ((face, own),) = region_faces([shifted_square(0, 0, 10) * (1, 0.4, 1)] + holes)
    # Every corner of the outlines, each hole's first corner and its cut's other end
    # twice; two cut edges per hole, every other edge the path's own.
    assert len(face) == 4 + 3 * (4 + 2)
    assert (~own).sum() == 6
    assert abs(area(face)) == pytest.approx(40.0 - 3.0)
    for i in np.nonzero(~own)[0]:
        a, b = face[i], face[(i + 1) % len(face)]
        # A cut runs between a hole and what was joined before, never along an outline.
        assert not (a[0] == b[0] and a[0] in (0, 10)) and not (a[1] == b[1])
    # limn draws it as the rectangle without its holes (the same frame: the same
    # bounds; pixels of the face's colour on white, counted).
    def painted(f, name):
        s = limn.Scene()
        s.add_mesh(f, [list(range(len(f)))], colors=[RED])
        s.render(tmp_path / f"{name}.png", background="#ffffff")
        img = plt.imread(tmp_path / f"{name}.png")[:, :, :3]
        return int((np.abs(img - RED).max(axis=2) < 0.1).sum())

    rectangle = painted(shifted_square(0, 0, 10) * (1, 0.4, 1), "rectangle")
    assert painted(face, "region") / rectangle == pytest.approx(37.0 / 40.0, abs=0.005)


def test_a_hole_touching_its_outline_is_filled_by_trapezoids():
    # The hole's rightmost corner touches the outline: no unambiguous cut from it.
    hole = np.array([(1, 1, 0), (1, 3, 0), (4, 2, 0)], dtype=float)
    faces = region_faces([square(0, 4), hole])
    assert len(faces) > 1
    assert sum(abs(area(f)) for f, _ in faces) == pytest.approx(16.0 - 3.0)
