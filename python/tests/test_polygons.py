"""Faces of any number of corners: the numpy API's three ways of giving them, its
errors, and polygons that are not convex drawn as they are, by ``render_mesh`` and
``Scene`` and by the matplotlib bridge (checked on the rasterised files)."""

import numpy as np
import pytest

import limn

RED = (0.85, 0.25, 0.2)
BLUE = (0.2, 0.4, 0.85)

# An L-shaped hexagon in the plane z = 0, listed from a corner that does not see the
# whole outline: the fan from its first corner covers the notch (the triangle (0, 0.8),
# (0.8, 0), (0, 0) lies in it).
L_SHAPE = np.array([(0, 0.8), (-0.8, 0.8), (-0.8, -0.8), (0.8, -0.8), (0.8, 0), (0, 0)])
NOTCH = (0.25, 0.25)  # in the fan's triangle, outside the L
ARMS = [(-0.4, 0.4), (-0.4, -0.4), (0.4, -0.4), (0.6, -0.15), (-0.15, 0.6)]


def l_shape_3d(z=0.0):
    return np.c_[L_SHAPE, np.full(len(L_SHAPE), z)]


def mixed_mesh():
    """A triangle, the L-shaped hexagon, a non-planar quad and a star (a non-convex
    decagon): vertices, the faces as a ragged list, and one colour per face."""
    tri = [(1.0, -0.8, 0.1), (1.8, -0.8, 0.1), (1.4, -0.1, 0.1)]
    skew = [(1.0, 0.1, 0.0), (1.8, 0.1, 0.3), (1.8, 0.9, 0.0), (1.0, 0.9, 0.3)]
    a = np.arange(10) * np.pi / 5
    r = np.where(np.arange(10) % 2, 0.3, 0.7)
    star = np.c_[-1.9 + r * np.cos(a), r * np.sin(a), np.full(10, -0.2)]
    parts = [np.array(tri), l_shape_3d(), np.array(skew), star]
    v = np.concatenate(parts)
    faces, start = [], 0
    for p in parts:
        faces.append(list(range(start, start + len(p))))
        start += len(p)
    colors = np.array([BLUE, RED, BLUE, RED])
    return v, faces, colors


def test_ragged_faces_and_counted_faces_draw_the_same_picture(tmp_path):
    v, faces, colors = mixed_mesh()
    counts = [len(f) for f in faces]
    flat = np.concatenate(faces)
    ways = {
        "ragged": dict(faces=faces),
        "ragged arrays": dict(faces=[np.array(f, dtype=np.int32) for f in faces]),
        "counts": dict(faces=flat, counts=counts),
        "counts arrays": dict(faces=np.array(flat, np.uint16), counts=np.array(counts)),
    }
    pictures = {}
    for name, kw in ways.items():
        stats = limn.render_mesh(v, path=tmp_path / f"{name}.svg", colors=colors, **kw)
        assert stats["faces_in"] == len(faces), name
        pictures[name] = (tmp_path / f"{name}.svg").read_bytes()
    assert len(set(pictures.values())) == 1
    # Scene.add_mesh takes them the same ways, faces numbered across meshes.
    s = limn.Scene()
    assert s.add_mesh(v, faces, colors=colors) == 0
    assert s.add_mesh(v + 3, flat, counts=counts, colors=colors) == len(faces)
    assert s.face_count == 2 * len(faces)
    s.set_camera(eye=(0.5, -2.0, 6.0), size=(240, 160))
    assert s.check(against="raycast")["mismatches_outside_band"] == 0
    assert {p[0] for p in s.paint()} == set(range(2 * len(faces)))


def test_equal_sized_faces_as_an_array_a_list_or_counts_are_the_same_mesh(tmp_path):
    # Pentagons: an (M, 5) array is faces of five corners, not a special case.
    a = np.arange(5) * 2 * np.pi / 5
    ring = np.c_[np.cos(a), np.sin(a), np.zeros(5)]
    v = np.concatenate([ring, ring * 0.5 + [2.5, 0, 0.3]])
    f = np.array([[0, 1, 2, 3, 4], [5, 6, 7, 8, 9]])
    outs = []
    ways = [dict(faces=f), dict(faces=f.tolist()), dict(faces=f.ravel(), counts=[5, 5])]
    for i, kw in enumerate(ways):
        limn.render_mesh(v, path=tmp_path / f"{i}.svg", **kw)
        outs.append((tmp_path / f"{i}.svg").read_bytes())
    assert outs[0] == outs[1] == outs[2]


def top_view(scene, size=200):
    """An orthographic camera looking down the z axis at the square [-1, 1]²: the point
    (x, y) is at pixel column (x + 1) size / 2, row (1 - y) size / 2."""
    m = np.diag([1.0, 1.0, 0.5, 1.0])
    scene.set_camera(matrix=m, size=(size, size))


def pixel(img, xy):
    h, w = img.shape[:2]
    return img[int((1 - xy[1]) * h / 2), int((xy[0] + 1) * w / 2), :3]


def test_a_non_convex_face_is_drawn_without_its_notch(tmp_path):
    pytest.importorskip("resvg_py")
    pytest.importorskip("matplotlib")
    from probes import near, raster

    s = limn.Scene()
    s.add_mesh(l_shape_3d(), [range(6)], colors=[RED])
    top_view(s)
    assert s.check(against="raycast")["mismatches_outside_band"] == 0
    s.render(tmp_path / "l.svg")
    img = raster((tmp_path / "l.svg").read_bytes(), 1.0)
    assert near(pixel(img, NOTCH), (1, 1, 1)), pixel(img, NOTCH)
    for p in ARMS:
        assert near(pixel(img, p), RED), (p, pixel(img, p))


@pytest.mark.parametrize(
    "faces, counts, colors, message",
    [
        ([[0, 1, 2], [0, 1]], None, None, r"faces\[1\] has 2 corners; at least 3"),
        ([[0, 1, 2], []], None, None, r"faces\[1\] has 0 corners"),
        ([[0, 1, 2], [0, 1, 2, 9]], None, None, r"faces\[1\] refers to vertex 9, outside 0\.\.4"),
        ([[0, 1, 2, 3], [3, -1, 2]], None, None, r"faces\[1\] refers to vertex -1"),
        ([[0, 1, 2], [0, 1.5, 2, 3]], None, None, r"faces\[1\] must hold integers"),
        ([[0, 1, 2], [[0, 1, 2]]], None, None, r"faces\[1\] must be a sequence"),
        ([0, 1, 2, 3], None, None, "counts="),
        (7, None, None, "sequence of index sequences"),
        ([0, 1, 2, 0, 2, 3], [3, 2], None, r"faces\[1\] has 2 corners"),
        ([0, 1, 2, 0, 2, 3], [3, 4], None, "add up to 7 corners, but faces holds 6"),
        ([0, 1, 2, 0, 2, 3], [3, 3, 3], None, "add up to 9"),
        ([0, 1, 2, 0, 2, 3], [[3, 3]], None, r"counts must have shape \(M,\)"),
        ([0, 1, 2, 0, 2, 3], [3.0, 3.0], None, "counts must hold integers"),
        ([[0, 1, 2, 0, 2, 3]], [6], None, r"faces must have shape \(K,\)"),
        ([0, 1, 2, 0, 2, 4], [3, 3], None, r"faces\[1\] refers to vertex 4"),
        ([[0, 1, 2], [0, 2, 3, 1]], None, [RED], r"colors must have shape \(2, 3\)"),
        ([0, 1, 2, 0, 2, 3], [3, 3], [RED] * 3, r"colors must have shape \(2, 3\)"),
    ],
)
def test_bad_faces_raise_value_error_naming_the_face(tmp_path, faces, counts, colors, message):
    v = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], float)
    with pytest.raises(ValueError, match=message):
        limn.render_mesh(v, faces, tmp_path / "x.svg", counts=counts, colors=colors)
    assert list(tmp_path.iterdir()) == []
    s = limn.Scene()
    s.add_mesh(v, [[0, 1, 2]])
    with pytest.raises(ValueError, match=message):
        s.add_mesh(v, faces, counts=counts, colors=colors)
    assert s.face_count == 1  # the scene as it was


def test_non_finite_vertices_of_a_polygon_raise_value_error(tmp_path):
    v = l_shape_3d()
    v[4, 2] = np.inf
    with pytest.raises(ValueError, match=r"vertices\[4\].*not finite"):
        limn.render_mesh(v, [range(6)], tmp_path / "x.svg")
    assert list(tmp_path.iterdir()) == []


# --- the matplotlib bridge ---------------------------------------------------------


def test_an_l_shaped_poly3dcollection_polygon_keeps_its_notch(tmp_path):
    pytest.importorskip("resvg_py")
    mpl = pytest.importorskip("matplotlib")
    mpl.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    import limn.matplotlib as lm
    from probes import colour_at, near, raster

    fig = plt.figure(figsize=(4, 3))
    ax = fig.add_subplot(projection="3d")
    ax.set_xlim(-1, 1)
    ax.set_ylim(-1, 1)
    ax.set_zlim(-1, 1)
    ax.view_init(elev=50, azim=-60)
    ax.grid(False)
    # The L and a blue triangle in its plane beyond the notch: the polygons go to limn as
    # one mesh of a hexagon and a triangle, each in its own colour.
    tri = [(0.55, 0.55, 0.0), (0.8, 0.55, 0.0), (0.8, 0.8, 0.0)]
    ax.add_collection3d(
        Poly3DCollection([l_shape_3d(), tri], facecolors=[RED, BLUE], linewidths=0)
    )
    fig.savefig(tmp_path / "mpl.svg")
    lm.savefig(fig, tmp_path / "limn.svg")
    mine = raster((tmp_path / "limn.svg").read_bytes(), 3.0)
    theirs = raster((tmp_path / "mpl.svg").read_bytes(), 3.0)
    notch = (*NOTCH, 0.0)
    # matplotlib fills the outline as it is: its export shows the pane behind the notch.
    assert not near(colour_at(fig, ax, theirs, notch), RED)
    assert near(colour_at(fig, ax, mine, notch), colour_at(fig, ax, theirs, notch)), (
        colour_at(fig, ax, mine, notch)
    )
    for p in ARMS[:3]:
        assert near(colour_at(fig, ax, mine, (*p, 0.0)), RED), p
    assert near(colour_at(fig, ax, mine, (0.72, 0.62, 0.0)), BLUE)
    plt.close(fig)


def test_the_bridge_hands_each_polygon_over_whole_with_its_owner():
    from limn._content import Polygons

    polys = Polygons()
    tri = np.array([(0, 0, 0), (1, 0, 0), (0, 1, 0)], float)
    polys.corners = [tri, tri[:2], l_shape_3d(), np.zeros((0, 3)), tri + 1]
    v, faces, counts, owner, own = polys.mesh()
    assert counts.tolist() == [3, 6, 3]  # the hexagon one face, not a fan of four
    assert owner.tolist() == [0, 2, 4]  # what is too small to draw is skipped
    assert all(o.all() for o in own)  # every edge of each face is its polygon's
    starts = np.r_[0, np.cumsum(counts)]
    for j, k in enumerate(owner):
        assert np.array_equal(v[faces[starts[j] : starts[j + 1]]], polys.corners[k])


def test_non_planar_polygons_are_cut_into_triangles_of_their_projected_outline():
    from limn._triangulate import view_triangles

    rng = np.random.default_rng(3)
    project = lambda p: p[:, :2]  # noqa: E731  (seen along z)

    def area(q):
        return 0.5 * np.sum(q[:, 0] * np.roll(q[:, 1], -1) - np.roll(q[:, 0], -1) * q[:, 1])

    kinds = {"dart": 0, "convex": 0, "hexagon": 0}
    for _ in range(300):
        n = int(rng.choice([4, 6]))
        t = np.sort(rng.uniform(0, 2 * np.pi, n))
        if np.diff(np.r_[t, t[0] + 2 * np.pi]).max() >= np.pi:
            continue  # keep the origin inside: the outline is star-shaped, so simple
        r = rng.uniform(0.2, 1.0, n)
        p = np.c_[r * np.cos(t), r * np.sin(t), rng.uniform(-1, 1, n)]
        faces, owner, own = view_triangles([p], project)
        assert (owner == 0).all()
        if len(faces) == 1:  # whole: a convex quad (either diagonal covers its outline)
            assert n == 4
            d = np.diff(np.r_[p[:, :2], p[:2, :2]], axis=0)
            turn = d[:-1, 0] * d[1:, 1] - d[:-1, 1] * d[1:, 0]
            assert (turn > 0).all() or (turn < 0).all()
            kinds["convex"] += 1
            continue
        kinds["dart" if n == 4 else "hexagon"] += 1
        # n - 2 triangles of the polygon's own corners, wound as the polygon, covering
        # its outline exactly: their areas add up to the outline's, none folds over.
        assert len(faces) == n - 2
        whole = area(p[:, :2])
        parts = [area(f[:, :2]) for f in faces]
        assert all(np.sign(a) == np.sign(whole) for a in parts)
        assert abs(sum(parts) - whole) < 1e-12
        # The polygon's own edges are flagged, the cuts are not; every edge once.
        edges = set()
        for f, o in zip(faces, own):
            idx = [int(np.nonzero((p == c).all(axis=1))[0][0]) for c in f]
            for e in range(3):
                a, b = idx[e], idx[(e + 1) % 3]
                assert bool(o[e]) == ((b - a) % n in (1, n - 1))
                if o[e]:
                    edges.add((a, b))
        assert edges == {(i, (i + 1) % n) for i in range(n)}
    assert min(kinds.values()) > 10, kinds


def test_the_triangles_of_a_polygon_are_one_path_in_the_bridge(tmp_path):
    """Two stars side by side (limn cuts each into eight triangles, none of which hides
    another): each star is painted as one path of its triangles, so that no seam shows
    between them in a viewer, and is drawn where matplotlib draws it."""
    pytest.importorskip("resvg_py")
    mpl = pytest.importorskip("matplotlib")
    mpl.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import to_hex
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    import limn.matplotlib as lm
    from probes import colour_at, near, raster

    a = np.arange(10) * np.pi / 5
    r = np.where(np.arange(10) % 2, 0.2, 0.45)
    star = np.c_[r * np.cos(a), r * np.sin(a), np.zeros(10)]
    left, right = star + (-0.5, 0, 0), star + (0.5, 0, 0)
    fig = plt.figure(figsize=(4, 3))
    ax = fig.add_subplot(projection="3d")
    ax.set_xlim(-1, 1)
    ax.set_ylim(-1, 1)
    ax.set_zlim(-1, 1)
    ax.view_init(elev=60, azim=-70)
    ax.add_collection3d(Poly3DCollection([left, right], facecolors=[RED, BLUE], linewidths=0))
    lm.savefig(fig, tmp_path / "limn.svg")
    svg = (tmp_path / "limn.svg").read_text()
    for colour in (RED, BLUE):
        assert svg.count(f"fill: {to_hex(colour)}") == 1, colour
    mine = raster(svg.encode(), 3.0)
    for centre, colour in (((-0.5, 0.0, 0.0), RED), ((0.5, 0.0, 0.0), BLUE)):
        for k in range(10):
            # Half-way out along each point and between points of the star.
            p = np.asarray(centre) + 0.6 * star[k] * (1.0 if k % 2 else 0.5)
            assert near(colour_at(fig, ax, mine, tuple(p)), colour), (centre, k)
    plt.close(fig)


def _shoelace(p):
    x, y = p[:, 0], p[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def test_joined_pieces_of_a_face_are_the_outline_of_their_union():
    # A translucent comb (one non-convex face: several convex pieces, painted as they
    # are) and a square beside it.
    comb = [(0, 0), (5, 0), (5, 3), (4, 3), (4, 1), (3, 1), (3, 3), (2, 3), (2, 1), (1, 1), (1, 3), (0, 3)]
    v = np.array([(x, y, 0.0) for x, y in comb] + [(6, 0, 0), (7, 0, 0), (7, 1, 0), (6, 1, 0)], float)
    counts = [len(comb), 4]
    s = limn.Scene()
    s.add_mesh(v, np.arange(len(v)), counts=counts, colors=np.array([[0.2, 0.4, 0.8, 0.5]] * 2))
    s.set_camera(eye=(3.5, 1.5, 20.0), target=(3.5, 1.5, 0.0), size=(320, 160))
    apart, _ = s.paint_with_marks(seams=0)
    pieces = [p for p in apart if p[0] == 0]
    assert len(pieces) > 1
    together, marks = s.paint_with_marks(seams=0, join=np.array([0, -1]))
    assert marks == []
    (entry,) = [p for p in together if p[0] == 0]
    rings = entry[1]
    assert isinstance(rings, list) and len(rings) == 1 and entry[3] == []
    # The comb's own outline: its twelve corners, each a corner of the pieces rounded to
    # a millionth of a pixel, enclosing the pieces' area.
    assert len(rings[0]) == len(comb)
    corners = np.concatenate([p[1] for p in pieces])
    gap = np.abs(corners[None, :, :] - rings[0][:, None, :]).max(axis=2).min(axis=1)
    assert gap.max() <= 0.5e-6
    want = sum(abs(_shoelace(p[1])) for p in pieces)
    assert abs(_shoelace(rings[0])) == pytest.approx(want, abs=1e-3)
    # The square is not flagged: it comes as it is.
    assert [type(p[1]) for p in together if p[0] == 1] == [np.ndarray]
    with pytest.raises(ValueError, match="join has 1 groups for 2 faces"):
        s.paint_with_marks(join=np.array([0]))


def test_joined_faces_of_one_group_are_the_outline_of_their_union():
    # A translucent square as two triangles (faces 0 and 1, one group), and a triangle
    # beside it in no group.
    v = np.array([(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (3, 0, 0), (4, 0, 0), (4, 1, 0)], float)
    faces = np.array([0, 1, 2, 0, 2, 3, 4, 5, 6])
    s = limn.Scene()
    s.add_mesh(v, faces, counts=[3, 3, 3], colors=np.array([[0.8, 0.3, 0.2, 0.5]] * 3))
    s.set_camera(eye=(2.0, 1.0, 20.0), target=(2.0, 1.0, 0.0), size=(320, 160))
    apart, _ = s.paint_with_marks(seams=0)
    assert sorted(p[0] for p in apart) == [0, 1, 2]
    together, _ = s.paint_with_marks(seams=0, join=np.array([7, 7, -1]))
    assert len(together) == 2
    (square,) = [p for p in together if isinstance(p[1], list)]
    assert square[0] in (0, 1) and len(square[1]) == 1 and len(square[1][0]) == 4


def test_edges_the_caller_strokes_get_no_seam_flap():
    # Two opaque squares of different colours sharing an edge, seen face on: the one
    # painted first gets a flap into the other (joined into its outline: six corners),
    # unless the caller strokes the edges of either.
    v = np.array([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (2, 0, 0), (2, 1, 0)], float)
    faces = np.array([0, 1, 2, 3, 1, 4, 5, 2])
    colors = np.array([[0.8, 0.3, 0.2, 1.0], [0.2, 0.3, 0.8, 1.0]])
    s = limn.Scene()
    s.add_mesh(v, faces, counts=[4, 4], colors=colors)
    s.set_camera(eye=(1.0, 0.5, 20.0), target=(1.0, 0.5, 0.0), size=(320, 160))
    corners = lambda drawn: sorted(len(p[1]) for p in drawn)  # noqa: E731
    assert corners(s.paint_with_marks()[0]) == [4, 6]
    assert corners(s.paint_with_marks(stroked=np.array([False, False]))[0]) == [4, 6]
    for stroked in ([True, False], [False, True], [True, True]):
        drawn, _ = s.paint_with_marks(stroked=np.array(stroked))
        assert corners(drawn) == [4, 4], stroked
    with pytest.raises(ValueError, match="stroked has 1 flags for 2 faces"):
        s.paint_with_marks(stroked=np.array([True]))
