"""limn from Python: the numpy API against the command, bad input, and the matplotlib
bridge against matplotlib's own export."""

import os
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

import limn
from test_polygons import mixed_mesh

ROOT = Path(__file__).resolve().parents[2]


def limn_command():
    exe = os.environ.get("LIMN_BIN")
    if exe:
        return exe
    for d in (os.environ.get("CARGO_TARGET_DIR"), str(ROOT / "target")):
        if d and Path(d, "release", "limn").exists():
            return str(Path(d, "release", "limn"))
    return shutil.which("limn")


def strips_and_boxes():
    """The demo's cyclic strips and two interpenetrating boxes, with one colour a face."""
    verts, faces, colors = [], [], []
    centre = np.array([-3.6, 0.0, 0.0])
    r, ln, h, w = 1.0, 2.4, 0.45, 0.55
    for k, c in enumerate([[0.85, 0.25, 0.2], [0.2, 0.6, 0.3], [0.2, 0.4, 0.85]]):
        th = k * 2 * np.pi / 3 + 0.3
        d = np.array([np.cos(th), np.sin(th), 0.0])
        n = np.array([np.sin(th), -np.cos(th), 0.0])
        at = lambda t, s: centre + n * r + d * t + n * (s * w / 2) + np.array([0, 0, -h * t / ln])
        base = len(verts)
        verts += [at(-ln, -1), at(ln, -1), at(ln, 1), at(-ln, 1)]
        faces.append([base, base + 1, base + 2, base + 3])
        colors.append(c)

    def box(lo, size, rot, colour):
        base = len(verts)
        for i in range(8):
            corner = np.array([(i >> 0) & 1, (i >> 1) & 1, (i >> 2) & 1], float) * size
            verts.append(lo + rot @ corner)
        for q in ([0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]):
            faces.append([base + j for j in q])
            colors.append(colour)

    box(np.array([-1.0, -1, -1]), np.array([0.6, 0.6, 0.6]) * 2, np.eye(3), [0.9, 0.3, 0.25])
    a, b = 0.6, 0.45
    ry = np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])
    rx = np.array([[1, 0, 0], [0, np.cos(b), -np.sin(b)], [0, np.sin(b), np.cos(b)]])
    box(np.array([-0.4, -0.5, -0.4]), np.array([1.0, 0.9, 1.0]) * 1.6, ry @ rx, [0.25, 0.45, 0.9])
    return np.array(verts), np.array(faces), np.array(colors)


def write_obj(path, v, f, c):
    names = {}
    with open(path.with_suffix(".mtl"), "w") as m:
        for col in c:
            key = tuple(col)
            if key not in names:
                names[key] = f"mesh{len(names)}"
                kd = " ".join(repr(float(x)) for x in col)
                m.write(f"newmtl {names[key]}\nKd {kd}\nillum 0\n")
    with open(path, "w") as o:
        o.write(f"mtllib {path.with_suffix('.mtl').name}\no mesh\n")
        for p in v:
            o.write("v " + " ".join(repr(float(x)) for x in p) + "\n")
        for q, col in zip(f, c):
            o.write(f"usemtl {names[tuple(col)]}\nf " + " ".join(str(i + 1) for i in q) + "\n")


@pytest.mark.parametrize("eye", [None, (2.0, 3.0, 9.0)])
def test_render_mesh_equals_the_command(tmp_path, eye):
    exe = limn_command()
    if exe is None:
        pytest.skip("the limn command is not built (cargo build --release)")
    v, f, c = strips_and_boxes()
    stats = limn.render_mesh(v, f, tmp_path / "py.svg", colors=c, eye=eye, size=(640, 480))
    write_obj(tmp_path / "s.obj", v, f, c)
    args = [exe, "render", "s.obj", "-o", "cmd.svg", "--size", "640x480", "--quiet"]
    if eye:
        args += ["--eye", ",".join(map(repr, eye))]
    out = subprocess.run(args + ["--stats", "-"], cwd=tmp_path, capture_output=True, check=True)
    import json

    want = json.loads(out.stdout)
    assert (tmp_path / "py.svg").read_bytes() == (tmp_path / "cmd.svg").read_bytes()
    assert set(stats) == set(want)
    for k in ("faces_in", "splits", "fragments_out", "paths_out", "bytes_out", "sort", "arith"):
        assert stats[k] == want[k], k
    assert stats["splits"] > 0  # the strips overlap cyclically: no order of whole faces


def test_render_mesh_of_polygons_of_any_shape_equals_the_command(tmp_path):
    # One face conversion for both: the numpy API hands each polygon over whole, as
    # the OBJ loader does.
    exe = limn_command()
    if exe is None:
        pytest.skip("the limn command is not built (cargo build --release)")
    v, f, c = mixed_mesh()  # a triangle, an L, a non-planar quad, a star
    eye = (0.5, -2.0, 6.0)
    stats = limn.render_mesh(v, f, tmp_path / "py.svg", colors=c, eye=eye, size=(320, 240))
    write_obj(tmp_path / "s.obj", v, f, c)
    args = [exe, "render", "s.obj", "-o", "cmd.svg", "--size", "320x240", "--quiet"]
    args += ["--eye", ",".join(map(repr, eye))]
    subprocess.run(args, cwd=tmp_path, capture_output=True, check=True)
    assert (tmp_path / "py.svg").read_bytes() == (tmp_path / "cmd.svg").read_bytes()
    assert stats["faces_in"] == len(f)


def test_scene_checks_exactly_under_every_projection(tmp_path):
    v, f, c = strips_and_boxes()
    s = limn.Scene()
    s.add_mesh(v, f, colors=c)
    for cam in (
        dict(),
        dict(eye=(2, 3, 9), projection="orthographic"),
        dict(eye=(-3, 2, 8), projection="orthographic", height=6.0),
    ):
        s.set_camera(size=(200, 150), **cam)
        r = s.check(against="raycast")
        assert r["mismatches_outside_band"] == 0, (cam, r)
    wrong = s.check(against="raycast", sort="simple")
    assert wrong["mismatches_outside_band"] > 0  # one depth per face is wrong here
    st = s.render(tmp_path / "o.pdf")
    assert (tmp_path / "o.pdf").read_bytes().startswith(b"%PDF")
    assert st["faces_in"] == len(f)


def test_a_matrix_camera_matches_its_look_at_twin():
    v, f, c = strips_and_boxes()
    s = limn.Scene()
    s.add_mesh(v, f, colors=c)
    eye, target = np.array([2.0, 3, 9]), np.zeros(3)
    fwd = (target - eye) / np.linalg.norm(target - eye)
    side = np.cross(fwd, [0, 1, 0])
    side /= np.linalg.norm(side)
    up = np.cross(side, fwd)
    view = np.eye(4)
    view[0, :3], view[1, :3], view[2, :3] = side, up, -fwd
    view[:3, 3] = -view[:3, :3] @ eye
    n, fa, t = 2.0, 20.0, np.tan(np.radians(22.5))
    proj = np.array(
        [[1 / (t * 4 / 3), 0, 0, 0], [0, 1 / t, 0, 0], [0, 0, (fa + n) / (n - fa), 2 * fa * n / (n - fa)], [0, 0, -1, 0]]
    )
    s.set_camera(matrix=proj @ view, size=(200, 150))
    assert s.check()["mismatches_outside_band"] == 0
    a = s.paint()
    s.set_camera(eye=tuple(eye), target=(0, 0, 0), size=(200, 150))
    b = s.paint()
    assert [x[0] for x in a] == [x[0] for x in b]


@pytest.mark.parametrize(
    "vertices, faces, colors, message",
    [
        (np.zeros((4, 2)), [[0, 1, 2]], None, "shape"),
        (np.zeros((4, 3)), [[0, 1]], None, "at least 3"),
        (np.array([[0, 0, 0], [1, 0, 0], [np.nan, 1, 0]]), [[0, 1, 2]], None, "not finite"),
        (np.eye(3), [[0, 1, 3]], None, "outside"),
        (np.eye(3), [[0, 1, -1]], None, "outside"),
        (np.eye(3), [[0, 1, 2]], [[1, 0, 0], [0, 1, 0]], "colors"),
        (np.eye(3), [[0, 1, 2]], [[2, 0, 0]], "outside 0..1"),
        (np.eye(3), [[0.5, 1, 2]], None, "integers"),
    ],
)
def test_bad_input_raises_value_error_and_writes_nothing(tmp_path, vertices, faces, colors, message):
    out = tmp_path / "x.svg"
    with pytest.raises(ValueError, match=message):
        limn.render_mesh(vertices, faces, out, colors=colors)
    assert list(tmp_path.iterdir()) == []


def test_bad_options_and_files(tmp_path):
    v, f = np.eye(3), [[0, 1, 2]]
    with pytest.raises(ValueError, match="sort"):
        limn.render_mesh(v, f, tmp_path / "a.svg", sort="fast")
    with pytest.raises(ValueError, match="extension"):
        limn.render_mesh(v, f, tmp_path / "a.doc")
    with pytest.raises(OSError):
        limn.render_mesh(v, f, tmp_path / "missing" / "a.svg")
    s = limn.Scene()
    with pytest.raises(ValueError, match="projection"):
        s.set_camera(projection="fisheye")
    with pytest.raises(ValueError, match="matrix"):
        s.set_camera(matrix=np.zeros((4, 4)))
        s.add_mesh(v, f)
        s.render(tmp_path / "b.svg")
    assert list(tmp_path.iterdir()) == []


# --- the matplotlib bridge ---------------------------------------------------------

mpl = pytest.importorskip("matplotlib")
mpl.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import limn.matplotlib as lm  # noqa: E402
from probes import colour_at, count_colour, near, raster  # noqa: E402

HEIGHT_COLOUR = (0.85, 0.25, 0.2)
PLANE_COLOUR = (0.2, 0.4, 0.85)


def crossing_surfaces(size=(4, 3)):
    """A height field and a tilted plane crossing it, in two flat colours."""
    fig = plt.figure(figsize=size)
    ax = fig.add_subplot(projection="3d")
    x, y = np.meshgrid(np.linspace(-1, 1, 12), np.linspace(-1, 1, 12))
    z1 = 0.6 * np.exp(-2 * (x**2 + y**2))
    z2 = 0.35 * x + 0.1
    ax.plot_surface(x, y, z1, color=HEIGHT_COLOUR, shade=False, linewidth=0)
    ax.plot_surface(x, y, z2, color=PLANE_COLOUR, shade=False, linewidth=0)
    ax.view_init(elev=25, azim=-60)
    return fig, ax, lambda px, py: (0.6 * np.exp(-2 * (px**2 + py**2)), 0.35 * px + 0.1)


def probe_points(surf):
    """Points on the visible surface at the centres of grid cells (away from the quads'
    edges and from the silhouette), where the height field and the plane lie at clearly
    different heights: the higher one is the one seen from above."""
    centre = lambda k: -1 + (2 * k + 1) / 11  # noqa: E731
    pts = []
    for i, j in [(0, 5), (0, 8), (1, 4), (5, 1), (2, 2), (9, 9), (3, 8)]:
        px, py = centre(i), centre(j)
        z1, z2 = surf(px, py)
        assert abs(z1 - z2) > 0.05
        pts.append(((px, py, max(z1, z2)), HEIGHT_COLOUR if z1 > z2 else PLANE_COLOUR))
    return pts


def test_savefig_orders_intersecting_surfaces_where_matplotlib_does_not(tmp_path):
    fig, ax, surf = crossing_surfaces()
    fig.savefig(tmp_path / "mpl.svg")
    lm.savefig(fig, tmp_path / "limn.svg")
    mine = raster((tmp_path / "limn.svg").read_bytes(), 2.0)
    theirs = raster((tmp_path / "mpl.svg").read_bytes(), 2.0)
    mpl_wrong = 0
    for p, want in probe_points(surf):
        # Seen from above, the higher surface is the visible one at every probe.
        assert near(colour_at(fig, ax, mine, p), want), (p, colour_at(fig, ax, mine, p))
        other = PLANE_COLOUR if want == HEIGHT_COLOUR else HEIGHT_COLOUR
        mpl_wrong += near(colour_at(fig, ax, theirs, p), other)
    assert mpl_wrong > 0  # matplotlib shows the other surface there: what the bridge fixes
    plt.close(fig)


@pytest.mark.parametrize("box", ["auto", "limn"])
@pytest.mark.parametrize("ext", ["svg", "pdf"])
def test_output_is_vector_but_for_matplotlibs_own_images(tmp_path, ext, box):
    fig, ax, _ = crossing_surfaces()
    ax.set_title("two surfaces")
    x, y = np.meshgrid(np.linspace(-1, 1, 8), np.linspace(-1, 1, 8))
    s = ax.plot_surface(x, y, x * y - 0.5, cmap="viridis", linewidth=0.3, edgecolor="k")
    fig.colorbar(s, ax=ax)  # matplotlib embeds a colorbar's solids as an image
    ax.scatter([0.0, 0.5], [0.0, -0.5], [0.8, 0.2], c=[0.1, 0.9], cmap="plasma")
    ax.text(0.0, 0.0, 0.9, "peak")
    lm.savefig(fig, tmp_path / f"f.{ext}", box=box)  # the axes' box by matplotlib or limn
    fig.savefig(tmp_path / f"mpl.{ext}")
    data = (tmp_path / f"f.{ext}").read_bytes()
    theirs = (tmp_path / f"mpl.{ext}").read_bytes()
    # The 3D content is vector drawing; the only image is the colorbar's, matplotlib's.
    image = b"<image" if ext == "svg" else b"/Subtype /Image"
    assert data.count(image) == theirs.count(image) == 1
    if ext == "svg":
        assert b"<path" in data
        assert b"two surfaces" in data or b"<use" in data
    else:
        assert data.startswith(b"%PDF")
    # The figure is restored: matplotlib's own export still shows its collections.
    assert all(c.get_visible() for c in ax.collections)
    plt.close(fig)


def test_figures_without_3d_axes_are_saved_unchanged(tmp_path):
    plt.rcParams["svg.hashsalt"] = "limn"  # ids the same in both files
    fig, ax = plt.subplots(figsize=(3, 2))
    ax.plot([0, 1], [1, 0])
    fig.savefig(tmp_path / "a.svg", metadata={"Date": None})
    lm.savefig(fig, tmp_path / "b.svg", metadata={"Date": None})
    assert (tmp_path / "a.svg").read_bytes() == (tmp_path / "b.svg").read_bytes()
    plt.close(fig)


# --- lines, points and labels ------------------------------------------------------


def square_with_marks():
    """A unit square in the plane z = 0 seen from +z, a line passing behind it and in
    front of it, one point behind its middle and one in front of it."""
    s = limn.Scene()
    s.add_mesh(
        np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], float),
        [[0, 1, 2, 3]],
        colors=[[0.2, 0.4, 0.85]],
    )
    s.add_line([[-3, 0.5, -1], [3, 0.5, -1]], color=(1, 0, 0), width=2.0, dash=[6, 3])
    s.add_line([[-3, -0.5, 1], [3, -0.5, 1]], color=(0, 0.6, 0), head=True)
    s.add_points([[0, 0, -1], [0.3, 0.3, 1]], marker="circle", size=[6, 8], color=(0, 0, 0))
    s.add_label((0.3, 0.3, 1), "front", anchor="south", offset=(0, -4))
    s.add_label((0, 0, -1), "behind")
    s.set_camera(eye=(0, 0, 6), target=(0, 0, 0), size=(200, 200))
    return s


def test_lines_points_and_labels_are_hidden_by_the_faces_in_front(tmp_path):
    s = square_with_marks()
    assert s.mark_counts == (2, 2, 2)
    polys, marks = s.paint_with_marks()
    kinds = {(m["kind"], m["index"]) for m in marks}
    # The point and the label behind the square are hidden; those in front are shown.
    assert ("marker", 1) in kinds and ("marker", 0) not in kinds
    assert ("label", 0) in kinds and ("label", 1) not in kinds
    # The line behind shows only left and right of the square; the one in front whole.
    behind = [m for m in marks if m["kind"] == "line" and m["index"] == 0]
    front = [m for m in marks if m["kind"] == "line" and m["index"] == 1]
    assert len(behind) == 2 and len(front) == 1
    # The square's left edge at x = -1 projects to where the hidden part starts.
    xs = sorted(float(m["points"][:, 0].max()) for m in behind)
    left = 100 - (1 / 6) * 100 / np.tan(np.radians(22.5))
    assert abs(xs[0] - left) < 1e-6, (xs, left)
    # Marks in front are painted after the square.
    assert all(m["before"] == len(polys) for m in marks)
    assert any(m["kind"] == "head" for m in marks)
    out = tmp_path / "m.svg"
    stats = s.render(out)
    data = out.read_bytes()
    assert b"front" in data and b"behind" not in data and stats["paths_out"] > 0
    assert (stats["lines"]["markers"], stats["lines"]["markers_shown"]) == (2, 1)
    assert (stats["lines"]["labels"], stats["lines"]["labels_shown"]) == (2, 1)


def test_marks_are_hidden_exactly_through_orthographic_and_matrix_cameras():
    s = square_with_marks()
    s.set_camera(eye=(0, 0, 6), target=(0, 0, 0), size=(200, 200), projection="orthographic")
    _, marks = s.paint_with_marks()
    kinds = {(m["kind"], m["index"]) for m in marks}
    assert ("marker", 1) in kinds and ("marker", 0) not in kinds
    # Seen along parallel rays, the hidden stretch of the line behind is exactly the
    # square's width: its pieces end where the square's edges project.
    behind = sorted(
        (m["points"] for m in marks if m["kind"] == "line" and m["index"] == 0),
        key=lambda p: p[0, 0],
    )
    front = [m["points"] for m in marks if m["kind"] == "line" and m["index"] == 1][0]
    sq = [p for _, p, _, _ in s.paint(seams=0)][0]
    assert abs(behind[0][:, 0].max() - sq[:, 0].min()) < 1e-9
    assert abs(behind[1][:, 0].min() - sq[:, 0].max()) < 1e-9
    assert front[:, 0].max() - front[:, 0].min() > 150
    # A 4x4 orthographic matrix looking down -z: the same decisions.
    m = np.diag([0.25, 0.25, -0.1, 1.0])
    s.set_camera(matrix=m, size=(200, 200))
    _, marks2 = s.paint_with_marks()
    assert {(m["kind"], m["index"]) for m in marks2} == kinds


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda s: s.add_line(np.zeros((3, 2))), "shape"),
        (lambda s: s.add_line(np.zeros((1, 3))), "at least 2"),
        (lambda s: s.add_line([[0, 0, 0], [np.nan, 0, 0]]), "not finite"),
        (lambda s: s.add_line(np.eye(3), color=(2, 0, 0)), "outside 0..1"),
        (lambda s: s.add_line(np.eye(3), width=0), "positive"),
        (lambda s: s.add_line(np.eye(3), dash=[0, 0]), "dash"),
        (lambda s: s.add_points(np.zeros((2, 2))), "shape"),
        (lambda s: s.add_points([[0, 0, 0], [0, np.inf, 0]]), "not finite"),
        (lambda s: s.add_points(np.eye(3), marker="star"), "unknown marker"),
        (lambda s: s.add_points(np.eye(3), size=[1, 2]), "one per point"),
        (lambda s: s.add_points(np.eye(3), size=[1, -2, 1]), "positive"),
        (lambda s: s.add_points(np.eye(3), color=np.ones((2, 3))), "one per point"),
        (lambda s: s.add_label((0, np.nan, 0), "x"), "not finite"),
        (lambda s: s.add_label((0, 0, 0), "a\nb"), "one line"),
        (lambda s: s.add_label((0, 0, 0), "x", anchor="up"), "unknown anchor"),
        (lambda s: s.add_label((0, 0, 0), "x", size=0), "positive"),
    ],
)
def test_bad_marks_raise_value_error_and_change_nothing(tmp_path, call, message):
    s = limn.Scene()
    s.add_mesh(np.eye(3), [[0, 1, 2]])
    with pytest.raises(ValueError, match=message):
        call(s)
    assert s.mark_counts == (0, 0, 0)
    s.render(tmp_path / "a.svg")  # the scene is still whole
    assert [p.name for p in tmp_path.iterdir()] == ["a.svg"]


# --- lines and points through the matplotlib bridge ---------------------------------

BELOW = (0.9, 0.1, 0.1)
ABOVE = (0.1, 0.7, 0.2)


def scatter_around_a_plane(size=(4, 3)):
    """A flat blue square at z = 0 and one scatter of points: red ones under the square
    (hidden from above), green ones over it."""
    fig = plt.figure(figsize=size)
    ax = fig.add_subplot(projection="3d")
    x, y = np.meshgrid(np.linspace(-1, 1, 6), np.linspace(-1, 1, 6))
    ax.plot_surface(x, y, 0 * x, color=PLANE_COLOUR, shade=False, linewidth=0)
    g = np.linspace(-0.45, 0.45, 4)
    px, py = (a.ravel() for a in np.meshgrid(g, g))
    below = np.c_[px, py, np.full(px.shape, -0.15)]
    above = np.c_[px + 0.1, py + 0.1, np.full(px.shape, 0.25)]
    # One point above the plane's front corner, nearest the viewer: matplotlib draws
    # the whole scatter at the depth of its nearest point, so in front of the plane.
    above = np.r_[above, [[0.95, -0.95, 0.45]]]
    pts = np.r_[below, above]
    colours = [BELOW] * len(below) + [ABOVE] * len(above)
    ax.scatter(pts[:, 0], pts[:, 1], pts[:, 2], c=colours, s=40, depthshade=False)
    ax.set_zlim(-0.5, 0.5)
    ax.view_init(elev=40, azim=-60)
    return fig, ax, below, above


def test_scatter_points_behind_a_surface_are_hidden(tmp_path):
    fig, ax, below, above = scatter_around_a_plane()
    fig.savefig(tmp_path / "mpl.svg")
    lm.savefig(fig, tmp_path / "limn.svg")
    mine = raster((tmp_path / "limn.svg").read_bytes(), 2.0)
    theirs = raster((tmp_path / "mpl.svg").read_bytes(), 2.0)
    for p in below:
        # The plane, or a point above it, covers each point below.
        c = colour_at(fig, ax, mine, p)
        assert not near(c, BELOW), (p, c)
    for p in above:
        assert near(colour_at(fig, ax, mine, p), ABOVE), p
    # No pixel of a hidden point in the bridge's picture; matplotlib's export, which
    # gives the whole scatter one depth, shows them on top of the plane.
    assert count_colour(mine, BELOW) == 0
    assert count_colour(theirs, BELOW) > 100
    mpl_wrong = sum(near(colour_at(fig, ax, theirs, p), BELOW) for p in below)
    assert mpl_wrong > 0
    assert all(c.get_visible() for c in ax.collections)
    plt.close(fig)


def test_a_wireframe_on_its_surface_shows_and_lines_behind_it_do_not(tmp_path):
    fig = plt.figure(figsize=(4, 3))
    ax = fig.add_subplot(projection="3d")
    n = 7
    x, y = np.meshgrid(np.linspace(-1, 1, n), np.linspace(-1, 1, n))
    z = 0.1 * x - 0.05 * y  # planar, so every wireframe segment lies on a face
    ax.plot_surface(x, y, z, color=HEIGHT_COLOUR, shade=False, linewidth=0)
    ax.plot_wireframe(x, y, z, color="k", linewidth=1.5)
    # A dashed line just under the surface, hidden by it.
    lx = np.array([-0.5, 0.5])
    ax.plot(lx, [0.1, 0.1], 0.1 * lx - 0.005 - 0.1, color=ABOVE, linewidth=3, linestyle="--")
    ax.set_zlim(-0.5, 0.5)
    ax.view_init(elev=60, azim=-50)
    lm.savefig(fig, tmp_path / "w.svg")
    img = raster((tmp_path / "w.svg").read_bytes(), 3.0)
    shown = 0
    for i in range(n):
        for j in range(n - 1):
            # The middle of each wireframe segment along x, and one between rows (on the
            # surface only).
            px = (x[i, j] + x[i, j + 1]) / 2
            p = (px, y[i, j], 0.1 * px - 0.05 * y[i, j])
            c = colour_at(fig, ax, img, p)
            shown += near(c, (0, 0, 0))
            if i < n - 1:
                q = (px, (y[i, j] + y[i + 1, j]) / 2)
                c = colour_at(fig, ax, img, (q[0], q[1], 0.1 * q[0] - 0.05 * q[1]))
                assert near(c, HEIGHT_COLOUR), (q, c)
    assert shown == n * (n - 1), shown
    assert count_colour(img, ABOVE) == 0
    # Without the surface the line shows (so the check above can fail).
    ax.collections[0].set_visible(False)
    lm.savefig(fig, tmp_path / "bare.svg")
    assert count_colour(raster((tmp_path / "bare.svg").read_bytes(), 3.0), ABOVE) > 100
    plt.close(fig)


def floor_and_cube():
    """A 6 x 6 floor at y = 0 and a unit cube floating above it (no colours: lit)."""
    v = [[-3, 0, -3], [3, 0, -3], [3, 0, 3], [-3, 0, 3]]
    v += [[x, y, z] for z in (-0.5, 0.5) for y in (1.0, 2.0) for x in (-0.5, 0.5)]
    f = [[0, 3, 2, 1]]
    for q in ([0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]):
        f.append([4 + j for j in q])
    return np.array(v, float), np.array(f)


def test_lights_cast_exact_shadows_only_when_asked(tmp_path):
    v, f = floor_and_cube()
    fills = {}
    for shadows in (False, True):
        s = limn.Scene()
        s.add_mesh(v, f)
        s.add_light("ambient", color=(0.2, 0.2, 0.2))
        s.add_light("directional", (0.3, 1.0, 0.2), shadows=shadows)
        s.set_camera(eye=(4.0, 6.0, 9.0), target=(0.0, 0.5, 0.0), size=(320, 240))
        out = tmp_path / f"shadows-{shadows}.svg"
        st = s.render(out)
        assert ("shadows" in st["effects"]) == shadows, st["effects"]
        assert (st["fragments_in_shadow"] > 0) == shadows, st
        fills[shadows] = set(re.findall(r'fill="(#[0-9a-fA-F]{6})"', out.read_text()))
    # The floor's shadowed part is painted in a colour of its own.
    assert fills[True] - fills[False], fills
    s = limn.Scene()
    for kind in ("ambient", "headlight"):
        with pytest.raises(ValueError, match="cast shadows"):
            s.add_light(kind, shadows=True)
