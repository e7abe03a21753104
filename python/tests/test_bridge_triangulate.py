"""The bridge's all-at-once polygon tests against their one-polygon references: planarity,
and the fan from a corner that sees the whole projected outline against ear clipping."""

import numpy as np
import pytest

from limn._triangulate import (
    _area,
    ear_clip,
    fan_corner_all,
    planar,
    planar_all,
    view_triangles,
)


def wobbly(rng, m, n, bump):
    """m polygons of n corners around a circle, radii and heights jittered."""
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    r = 1 + bump * rng.uniform(-1, 1, (m, n))
    z = bump * rng.uniform(-1, 1, (m, n))
    return np.stack([r * np.cos(t), r * np.sin(t), z], axis=2)


@pytest.mark.parametrize("bump", [0.0, 1e-12, 0.05, 0.6])
def test_planar_all_is_planar_polygon_by_polygon(bump):
    rng = np.random.default_rng(3)
    polys = wobbly(rng, 200, 7, bump)
    assert planar_all(polys).tolist() == [planar(p) for p in polys]


@pytest.mark.parametrize("n", [5, 8, 12])
def test_a_fan_corner_gives_triangles_covering_the_outline_exactly(n):
    rng = np.random.default_rng(n)
    q = wobbly(rng, 300, n, 0.45)[..., :2]
    q[::2] = q[::2, ::-1]  # both windings
    # A comb seen from none of its corners whole, then the jittered outlines.
    comb = np.array([(0, 0), (3, 0), (3, 1), (1, 1), (1, 2), (3, 2), (3, 3), (1, 3),
                     (1, 4), (3, 4), (3, 5), (0, 5)], dtype=float)
    if n == 12:
        q = np.concatenate([comb[None], q])
    corner = fan_corner_all(q)
    assert (corner >= 0).any()
    if n == 12:
        assert corner[0] == -1
    for poly, c in zip(q, corner):
        if c < 0:
            continue
        tris = [poly[[c, (c + i) % n, (c + i + 1) % n]] for i in range(1, n - 1)]
        areas = np.array([_area(t) for t in tris])
        # Every triangle turns the way the outline winds, and together they have its
        # area: they cover it without overlapping.
        assert (np.sign(areas) == np.sign(_area(poly))).all()
        assert areas.sum() == pytest.approx(_area(poly), rel=1e-12)
        # Ear clipping covers the same area.
        clipped = ear_clip(poly)
        assert sum(abs(_area(poly[list(t)])) for t in clipped) == pytest.approx(abs(_area(poly)))


def test_view_triangles_cut_a_non_planar_polygon_into_its_outline_either_way():
    rng = np.random.default_rng(7)
    polys = list(wobbly(rng, 50, 8, 0.3))
    faces, owner, own = view_triangles(polys, lambda p: np.asarray(p)[:, :2])
    for k, p in enumerate(polys):
        mine = [f for f, o in zip(faces, owner) if o == k]
        got = sum(abs(_area(f[:, :2])) for f in mine)
        if len(mine) > 1:
            assert got == pytest.approx(abs(_area(p[:, :2])), rel=1e-9), k
    # Each polygon edge is stroked exactly once over its pieces.
    for k, p in enumerate(polys):
        count = sum(int(np.sum(e)) for e, o in zip(own, owner) if o == k)
        assert count == len(p)
