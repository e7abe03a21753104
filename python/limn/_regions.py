"""Filled paths in 3D as limn faces: the regions of a filled contour set (``contourf``,
``tricontourf``, with or without ``zdir``/``offset``) and of a ``PathPatch3D`` (a
circle, the glyphs of a ``TextPath``).

mplot3d projects such a path's vertices (curve control points included) and fills the
projected path as a 2D path with the nonzero rule: one level of a filled contour set is
one path of several outlines, some of them holes, and a glyph's outline has holes too.
A path of mplot3d lies in one plane (a level's plane, or the plane ``zdir`` and ``z``
give a patch), so the bridge fills it in that plane: curves are flattened (a few
degrees of arc per chord) and the outlines nested by containment. A region of nonzero
winding number without holes is one face (limn takes simple non-convex polygons); a
region with holes is one face too, its holes joined to the outline by cuts run both ways
(limn fills such an outline by its winding number: the cuts are inside), where each cut
can be shown in floating point to meet no edge. Otherwise, and for the fill of outlines
that cross each other (a filled contour set of a folded mesh), the region is cut into
trapezoids between the heights of its corners and crossings. Cuts, tops and bottoms of
trapezoids are not edges of the path: only the outlines' own edges are stroked.
"""

from __future__ import annotations

from typing import List, Tuple

import numpy as np

_MOVETO, _LINETO, _CURVE3, _CURVE4, _CLOSEPOLY = 1, 2, 3, 4, 79
_STEPS = {_CURVE3: 8, _CURVE4: 12}
"""Chords per quadratic and cubic segment (a quarter circle drawn as one cubic: under
1e-3 of its radius off the curve)."""


def outlines(verts: np.ndarray, codes) -> List[np.ndarray]:
    """The closed outlines (each (n, 3)) a path of 3D vertices and matplotlib path codes
    fills, curves flattened; ``codes`` ``None`` is one outline through every vertex.
    Vertices of ``CLOSEPOLY`` and ``STOP`` codes are not corners (matplotlib ignores
    them)."""
    verts = np.asarray(verts, dtype=float).reshape(-1, 3)
    if codes is None:
        return [verts]
    codes = np.asarray(codes)
    if not ((codes == _CURVE3) | (codes == _CURVE4)).any():
        keep = (codes == _MOVETO) | (codes == _LINETO)
        starts = np.nonzero(codes[keep] == _MOVETO)[0]
        parts = np.split(verts[keep], starts)
        return [p for p in parts if len(p)]
    rings: List[np.ndarray] = []
    ring: List[np.ndarray] = []
    i, n = 0, len(codes)
    while i < n:
        c = codes[i]
        if c == _MOVETO:
            if ring:
                rings.append(np.array(ring))
            ring = [verts[i]]
            i += 1
        elif c == _LINETO:
            ring.append(verts[i])
            i += 1
        elif c in (_CURVE3, _CURVE4):
            k = 2 if c == _CURVE3 else 3
            ctrl = np.vstack([ring[-1:] or [verts[i]], verts[i : i + k]])
            ring.extend(_bezier(ctrl)[1:])
            i += k
        else:  # CLOSEPOLY, STOP
            if ring:
                rings.append(np.array(ring))
            ring = []
            i += 1
    if ring:
        rings.append(np.array(ring))
    return rings


def _bernstein(steps: int, degree: int) -> np.ndarray:
    """The Bernstein weights (steps + 1, degree + 1) of a Bézier curve of ``degree`` at
    ``steps + 1`` evenly spaced parameters from 0 to 1."""
    t = np.linspace(0.0, 1.0, steps + 1)[:, None]
    k = np.arange(degree + 1)[None, :]
    binom = np.array([1, 2, 1]) if degree == 2 else np.array([1, 3, 3, 1])
    return binom[None, :] * t**k * (1 - t) ** (degree - k)


_WEIGHTS = {3: _bernstein(_STEPS[_CURVE3], 2), 4: _bernstein(_STEPS[_CURVE4], 3)}
"""Per number of control points, the weights of the points ``_bezier`` takes."""


def _bezier(ctrl: np.ndarray) -> np.ndarray:
    """Points along the Bézier curve of control points ``ctrl`` (three or four), from its
    start to its end: ``_STEPS`` chords."""
    return _WEIGHTS[len(ctrl)] @ ctrl


def _clean(ring: np.ndarray) -> np.ndarray:
    """The ring without repeated consecutive corners (nor a last corner repeating the
    first), nor corners exactly on the straight line through their neighbours (a filled
    contour's outline along the data's border has one at every grid point): the same
    outline, fewer corners."""
    if len(ring) < 2:
        return ring
    nxt = np.concatenate([ring[1:], ring[:1]])
    same = (ring == nxt).all(axis=1)
    ring = ring[~same] if not same.all() else ring[:1]
    if len(ring) < 4:
        return ring
    nxt = np.concatenate([ring[1:], ring[:1]])
    into = ring - np.concatenate([ring[-1:], ring[:-1]])
    out = nxt - ring
    # Exactly straight on: the cross product of the steps in and out is zero.
    cross = np.stack(
        [
            into[:, 1] * out[:, 2] - into[:, 2] * out[:, 1],
            into[:, 2] * out[:, 0] - into[:, 0] * out[:, 2],
            into[:, 0] * out[:, 1] - into[:, 1] * out[:, 0],
        ],
        axis=1,
    )
    straight = (cross == 0).all(axis=1) & ((into * out).sum(axis=1) > 0)
    return ring[~straight] if (~straight).sum() >= 3 else ring


def _area(q: np.ndarray) -> float:
    return 0.5 * float(np.sum(q[:, 0] * np.roll(q[:, 1], -1) - np.roll(q[:, 0], -1) * q[:, 1]))


def _plane_axes(rings: List[np.ndarray]) -> Tuple[int, int]:
    """The two coordinate axes to fill the rings in: the axes of the plane the largest
    ring's normal (Newell's) is least inclined to (without area, the two the corners
    spread most along)."""
    best, normal = -1.0, np.array([0.0, 0.0, 1.0])
    for p in rings:
        nxt = np.roll(p, -1, axis=0)
        n = np.array(
            [
                np.sum((p[:, 1] - nxt[:, 1]) * (p[:, 2] + nxt[:, 2])),
                np.sum((p[:, 2] - nxt[:, 2]) * (p[:, 0] + nxt[:, 0])),
                np.sum((p[:, 0] - nxt[:, 0]) * (p[:, 1] + nxt[:, 1])),
            ]
        )
        size = float(np.abs(n).sum())
        if np.isfinite(size) and size > best:
            best, normal = size, n
    if (np.abs(normal) > 0).any():
        drop = int(np.argmax(np.abs(normal)))
    else:  # no area (a bow-tie's lobes cancel): the axis the corners spread least along
        drop = int(np.argmin(np.ptp(np.concatenate(rings), axis=0)))
    return tuple(a for a in range(3) if a != drop)  # type: ignore[return-value]


def region_faces(rings: List[np.ndarray]) -> List[Tuple[np.ndarray, np.ndarray]]:
    """The faces (n, 3) filling the outlines ``rings`` (each (k, 3), closed implicitly,
    in one plane) by the nonzero rule, with per face which of its edges (edge i from
    corner i to i + 1) are edges of an outline (the others are cuts).

    Outlines that cross (a filled contour set of a folded mesh, ``contourf(...,
    zdir="x")`` of a surface that is not a function of y and z) are first smoothed at
    their crossings into outlines that only touch there (``_uncrossed``: the same
    winding numbers). Then each region without holes is one face (touching at corners
    is fine), a region with holes one face with cuts to its holes (``_keyhole``) or,
    where no cut can be shown clear, trapezoids (``_slabs``); trapezoids fill all the
    outlines together where the rounded crossing points still leave a crossing.
    Degenerate outlines (fewer than three corners, no area) are left out."""
    rings = [_clean(r) for r in rings]
    rings = [r for r in rings if len(r) >= 3 and np.isfinite(r).all()]
    if not rings:
        return []
    u, v = _plane_axes(rings)
    rings, _ = _uncrossed(rings, [r[:, [u, v]] for r in rings])
    rings = [c for c in (_clean(r) for r in rings) if len(c) >= 3]
    flat = [r[:, [u, v]] for r in rings]
    if _crossing(flat):
        return _slabs(rings, flat)
    area = np.array([_area(q) for q in flat])
    good = area != 0
    rings = [r for r, g in zip(rings, good) if g]
    flat = [q for q, g in zip(flat, good) if g]
    area = area[good]
    n = len(rings)
    if n == 0:
        return []
    parent = _parents(flat, np.abs(area))
    sign = np.sign(area).astype(int)
    winding = sign.copy()
    for i in range(n):
        j = parent[i]
        while j >= 0:
            winding[i] += sign[j]
            j = parent[j]
    children: List[List[int]] = [[] for _ in range(n)]
    for i in range(n):
        if parent[i] >= 0:
            children[parent[i]].append(i)
    out: List[Tuple[np.ndarray, np.ndarray]] = []
    for i in range(n):
        # A region: an outline of nonzero winding number right inside one of winding
        # zero (or nothing), less the outlines of winding zero within it. Outlines of
        # nonzero winding within it are filled either way (nested outlines turned the
        # same way, outlines touching where crossings were smoothed): not holes.
        if winding[i] == 0 or (parent[i] >= 0 and winding[parent[i]] != 0):
            continue
        holes: List[int] = []
        within = list(children[i])
        while within:
            c = within.pop()
            if winding[c] == 0:
                holes.append(c)
            else:
                within += children[c]
        if not holes:
            out.append((rings[i], np.ones(len(rings[i]), dtype=bool)))
            continue
        # The outline counter-clockwise, its holes clockwise: winding one in the region.
        ccw = lambda k, want: (rings[k], flat[k]) if (area[k] > 0) == want else (  # noqa: E731
            rings[k][::-1],
            flat[k][::-1],
        )
        parts = [ccw(i, True)] + [ccw(h, False) for h in sorted(holes)]
        face = _keyhole([r for r, _ in parts], [q for _, q in parts])
        if face is not None:
            out.append(face)
        else:
            out += _slabs([r for r, _ in parts], [q for _, q in parts])
    return out


_ORIENT_BOUND = (3.0 + 16.0 * 2.0**-53) * 2.0**-53
"""Shewchuk's bound on the error of ``(a - o) × (p - o)`` computed in doubles, relative
to the sum of the magnitudes of its two products: a value larger than the bound has
the exact value's sign."""


def _certain_side(o: np.ndarray, a: np.ndarray, p: np.ndarray) -> np.ndarray:
    """Per row, the sign of the orientation of ``o, a, p`` (points (k, 2)) where floating
    point proves it, 0 where it does not (including where it is exactly 0)."""
    left = (a[:, 0] - o[:, 0]) * (p[:, 1] - o[:, 1])
    right = (a[:, 1] - o[:, 1]) * (p[:, 0] - o[:, 0])
    det = left - right
    bound = _ORIENT_BOUND * (np.abs(left) + np.abs(right))
    return np.where(det > bound, 1, np.where(-det > bound, -1, 0))


def _clear_cut(m: np.ndarray, p: np.ndarray, a: np.ndarray, b: np.ndarray) -> bool:
    """Whether the segment ``m``–``p`` provably meets no edge ``a``–``b`` (each (E, 2))
    except at ``m`` and ``p`` themselves, by an end of an edge that leaves them off the
    segment's line. Edges whose boxes miss the segment's are clear (exact comparisons);
    an edge is clear when both its ends lie strictly on one side of the segment's line,
    or both ends of the segment strictly on one side of the edge's line."""
    lo, hi = np.minimum(m, p), np.maximum(m, p)
    near = ~(
        (np.maximum(a[:, 0], b[:, 0]) < lo[0])
        | (np.minimum(a[:, 0], b[:, 0]) > hi[0])
        | (np.maximum(a[:, 1], b[:, 1]) < lo[1])
        | (np.minimum(a[:, 1], b[:, 1]) > hi[1])
    )
    a, b = a[near], b[near]
    if not len(a):
        return True
    mm = np.broadcast_to(m, a.shape)
    pp = np.broadcast_to(p, a.shape)
    at_end_a = (a == m).all(axis=1) | (a == p).all(axis=1)
    at_end_b = (b == m).all(axis=1) | (b == p).all(axis=1)
    sa, sb = _certain_side(mm, pp, a), _certain_side(mm, pp, b)
    # An edge from an end of the segment: clear when its other end is off the line.
    from_end = at_end_a | at_end_b
    other = np.where(at_end_a[:, None], b, a)
    so = _certain_side(mm, pp, other)
    clear_from_end = from_end & ~(at_end_a & at_end_b) & (so != 0)
    # Both ends of the segment repeated by an edge: the segment is an edge (never cut).
    same_side = (sa * sb) > 0
    sm, sp = _certain_side(a, b, mm), _certain_side(a, b, pp)
    apart = (sm * sp) > 0
    clear = np.where(from_end, clear_from_end, same_side | apart)
    return bool(clear.all())


def _keyhole(
    rings: List[np.ndarray], flat: List[np.ndarray]
) -> "Tuple[np.ndarray, np.ndarray] | None":
    """A region with holes as one face: the outline ``rings[0]`` (counter-clockwise in
    ``flat``) with each hole (clockwise) joined to it by a cut run both ways, from the
    hole's corner of largest first coordinate to the nearest corner of what is joined so
    far that it provably sees (no edge of any outline meets the cut: see
    ``_clear_cut``). The corners are the outlines' own; the cuts are not edges of the
    path. ``None`` when some hole finds no such corner among its nearest few (the region
    is then cut into trapezoids)."""
    ring3, ring2 = rings[0], flat[0]
    own = np.ones(len(ring3), dtype=bool)
    holes = sorted(range(1, len(rings)), key=lambda k: -flat[k][:, 0].max())
    for done, k in enumerate(holes):
        h2, h3 = flat[k], rings[k]
        mi = int(np.argmax(h2[:, 0]))
        m = h2[mi]
        # Every edge of every outline: what is joined so far and the holes not yet.
        others = [ring2] + [flat[j] for j in holes[done:]]
        a, b = _edges(others)
        corners = np.concatenate(others)
        if (corners == m).all(axis=1).sum() > 1:
            return None  # the hole touches an outline at M: no unambiguous cut
        ahead = np.nonzero(ring2[:, 0] >= m[0])[0]
        if not len(ahead):
            return None
        d = np.hypot(*(ring2[ahead] - m).T)
        chosen = None
        for pi in ahead[np.argsort(d, kind="stable")][:16]:
            # A corner met twice (an end of an earlier cut, outlines touching) has two
            # sides to join at: left alone.
            if (corners == ring2[pi]).all(axis=1).sum() > 1:
                continue
            if _clear_cut(m, ring2[pi], a, b):
                chosen = int(pi)
                break
        if chosen is None:
            return None
        # ... → P, M, the hole round from M back to M, P → ...
        hole_order = np.r_[np.arange(mi, len(h2)), np.arange(0, mi + 1)]
        ring2 = np.concatenate([ring2[: chosen + 1], h2[hole_order], ring2[chosen:]])
        ring3 = np.concatenate([ring3[: chosen + 1], h3[hole_order], ring3[chosen:]])
        # Edge i runs from corner i: P → M is a cut, the hole's edges are its own, the
        # last hole corner (M again) → P is the cut back.
        own = np.concatenate(
            [own[:chosen], [False], np.ones(len(h2), dtype=bool), [False], own[chosen:]]
        )
    return ring3, own


def _parents(flat: List[np.ndarray], size: np.ndarray) -> np.ndarray:
    """Per ring, the smallest ring containing it (-1: none). A ring is inside another
    when most of its corners are (a few corners where rings touch do not decide)."""
    from matplotlib.path import Path

    n = len(flat)
    lo = np.array([q.min(axis=0) for q in flat])
    hi = np.array([q.max(axis=0) for q in flat])
    parent = np.full(n, -1)
    if n == 1:
        return parent
    # Candidate pairs (j inside i): j's box inside i's, i larger.
    within = (
        (lo[None, :, :] >= lo[:, None, :]).all(axis=2)
        & (hi[None, :, :] <= hi[:, None, :]).all(axis=2)
        & (size[:, None] > size[None, :])
    )
    best = np.full(n, np.inf)
    for i in np.nonzero(within.any(axis=1))[0]:
        path = Path(flat[i])
        for j in np.nonzero(within[i])[0]:
            if size[i] >= best[j]:
                continue
            q = flat[j]
            if 2 * int(path.contains_points(q).sum()) > len(q):
                parent[j], best[j] = i, size[i]
    return parent


def _edges(flat: List[np.ndarray]) -> Tuple[np.ndarray, np.ndarray]:
    """Every outline's edges as start and end points (E, 2) each."""
    a = np.concatenate(flat)
    b = np.concatenate([np.roll(q, -1, axis=0) for q in flat])
    return a, b


def _crossing_pairs(a: np.ndarray, b: np.ndarray) -> Tuple[np.ndarray, np.ndarray]:
    """The pairs ``i < j`` of edges ``a[i]``–``b[i]`` and ``a[j]``–``b[j]`` (each (E, 2))
    that cross properly (each one's ends strictly on both sides of the other)."""
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    order = np.argsort(lo[:, 0], kind="stable")
    sa, sb, slo, shi = a[order], b[order], lo[order], hi[order]
    e = len(a)
    step = max(1, 4_000_000 // max(e, 1))
    found_i: List[np.ndarray] = []
    found_j: List[np.ndarray] = []
    for s in range(0, e, step):
        i = np.arange(s, min(e, s + step))
        # Pairs j > i whose boxes meet (boxes sorted by left side: j's left side
        # before i's right side).
        last = np.searchsorted(slo[:, 0], shi[i, 0], side="right")
        counts = np.maximum(last - i - 1, 0)
        if not counts.any():
            continue
        ii = np.repeat(i, counts)
        jj = np.arange(len(ii)) - np.repeat(np.cumsum(counts) - counts, counts) + ii + 1
        meet = (slo[jj, 1] <= shi[ii, 1]) & (shi[jj, 1] >= slo[ii, 1])
        ii, jj = ii[meet], jj[meet]
        d1 = _side(sa[ii], sb[ii], sa[jj])
        d2 = _side(sa[ii], sb[ii], sb[jj])
        d3 = _side(sa[jj], sb[jj], sa[ii])
        d4 = _side(sa[jj], sb[jj], sb[ii])
        x = (d1 * d2 < 0) & (d3 * d4 < 0)
        found_i.append(order[ii[x]])
        found_j.append(order[jj[x]])
    if not found_i:
        return np.zeros(0, np.intp), np.zeros(0, np.intp)
    fi, fj = np.concatenate(found_i), np.concatenate(found_j)
    return np.minimum(fi, fj), np.maximum(fi, fj)


def _crossing(flat: List[np.ndarray]) -> bool:
    """Whether two edges of the outlines cross properly."""
    return len(_crossing_pairs(*_edges(flat))[0]) > 0


def _where_crossing(
    a: np.ndarray, b: np.ndarray, ii: np.ndarray, jj: np.ndarray
) -> Tuple[np.ndarray, np.ndarray]:
    """Where the crossing edges ``ii`` and ``jj`` meet: the fraction of the way along
    each (from ``a`` to ``b``)."""
    p, r = a[ii], b[ii] - a[ii]
    q, sv = a[jj], b[jj] - a[jj]
    den = r[:, 0] * sv[:, 1] - r[:, 1] * sv[:, 0]
    t = ((q[:, 0] - p[:, 0]) * sv[:, 1] - (q[:, 1] - p[:, 1]) * sv[:, 0]) / den
    u = ((q[:, 0] - p[:, 0]) * r[:, 1] - (q[:, 1] - p[:, 1]) * r[:, 0]) / den
    return np.clip(t, 0.0, 1.0), np.clip(u, 0.0, 1.0)


def _uncrossed(
    rings: List[np.ndarray], flat: List[np.ndarray]
) -> Tuple[List[np.ndarray], List[np.ndarray]]:
    """Outlines with the same winding number everywhere off them as ``rings``, none of
    which crosses another or itself: at each crossing, the outline arriving along one
    edge leaves along the other (the crossing is smoothed the way both run, so every
    point keeps its winding number). Smoothing a crossing of an outline with itself
    splits it in two, of two outlines joins them; the new outlines touch at the
    crossings. Their edges are pieces of the given ones."""
    a, b = _edges(flat)
    ii, jj = _crossing_pairs(a, b)
    if not len(ii):
        return rings, flat
    t, u = _where_crossing(a, b, ii, jj)
    a3 = np.concatenate(rings)
    b3 = np.concatenate([np.roll(r, -1, axis=0) for r in rings])
    x3 = a3[ii] + t[:, None] * (b3[ii] - a3[ii])
    x2 = a[ii] + t[:, None] * (b[ii] - a[ii])
    # The nodes of the walk along every outline: each corner, then the crossings on its
    # edge in order along it, as (corner, -1) or (crossing, which of its two edges).
    on_edge: dict = {}
    for c in range(len(ii)):
        on_edge.setdefault(int(ii[c]), []).append((float(t[c]), c, 0))
        on_edge.setdefault(int(jj[c]), []).append((float(u[c]), c, 1))
    seq: List[Tuple[int, int]] = []
    after: List[int] = []  # the next node along the same outline
    e = 0
    for q in flat:
        begin = len(seq)
        for _ in range(len(q)):
            seq.append((e, -1))
            seq += [(c, side) for _, c, side in sorted(on_edge.get(e, ()))]
            e += 1
        after += list(range(begin + 1, len(seq))) + [begin]
    visit = {node: k for k, node in enumerate(seq) if node[1] >= 0}
    # Arriving at a crossing along one edge, the walk leaves along the other: the
    # successor of each of its two visits is that of the other (a permutation still).
    succ = list(after)
    for c in range(len(ii)):
        k0, k1 = visit[(c, 0)], visit[(c, 1)]
        succ[k0], succ[k1] = after[k1], after[k0]
    used = [False] * len(seq)
    out3: List[np.ndarray] = []
    out2: List[np.ndarray] = []
    for k0 in range(len(seq)):
        k, pts3, pts2 = k0, [], []
        while not used[k]:
            used[k] = True
            node, side = seq[k]
            pts3.append(a3[node] if side < 0 else x3[node])
            pts2.append(a[node] if side < 0 else x2[node])
            k = succ[k]
        if pts3:
            out3.append(np.array(pts3))
            out2.append(np.array(pts2))
    return out3, out2


def _side(o: np.ndarray, a: np.ndarray, p: np.ndarray) -> np.ndarray:
    return np.sign((a[:, 0] - o[:, 0]) * (p[:, 1] - o[:, 1]) - (a[:, 1] - o[:, 1]) * (p[:, 0] - o[:, 0]))


def _slabs(rings: List[np.ndarray], flat: List[np.ndarray]) -> List[Tuple[np.ndarray, np.ndarray]]:
    """The nonzero fill of outlines that may cross, as trapezoids: the plane cut at the
    height of every corner and every crossing into slabs, in each slab the spans between
    edges where the winding number is not zero; a span bounded by the same two edges in
    consecutive slabs is one trapezoid. Corners in 3D are on the outlines' edges (the
    outlines lie in one plane); the trapezoids' sides on edges are the outline's own,
    their tops and bottoms are not."""
    a, b = _edges(flat)
    a3 = np.concatenate(rings)
    b3 = np.concatenate([np.roll(r, -1, axis=0) for r in rings])
    dy = b[:, 1] - a[:, 1]
    keep = dy != 0
    a, b, a3, b3, dy = a[keep], b[keep], a3[keep], b3[keep], dy[keep]
    up = np.where(dy > 0, 1, -1)
    ylo, yhi = np.minimum(a[:, 1], b[:, 1]), np.maximum(a[:, 1], b[:, 1])
    ys = np.unique(np.r_[a[:, 1], b[:, 1], _crossing_heights(a, b)])

    def at(e: np.ndarray, y: float) -> Tuple[np.ndarray, np.ndarray]:
        t = (y - a[e, 1]) / dy[e]
        return a[e, 0] + t * (b[e, 0] - a[e, 0]), a3[e] + t[:, None] * (b3[e] - a3[e])

    out: List[Tuple[np.ndarray, np.ndarray]] = []
    open_: dict = {}  # (left edge, right edge) -> bottom corners (2, 3)

    def close(key, y: float, store: dict) -> None:
        bottom = store.pop(key)
        _, top = at(np.array(key), y)
        quad = np.array([bottom[0], bottom[1], top[1], top[0]])
        own = np.array([False, True, False, True])
        same = (quad == np.roll(quad, -1, axis=0)).all(axis=1)
        if (~same).sum() >= 3:
            out.append((quad[~same], own[~same]))

    for y0, y1 in zip(ys[:-1], ys[1:]):
        e = np.nonzero((ylo <= y0) & (yhi >= y1))[0]
        mid = 0.5 * (y0 + y1)
        x, _ = at(e, mid)
        e = e[np.argsort(x, kind="stable")]
        w = np.cumsum(up[e])
        spans = []
        start = None
        for k in range(len(e)):
            before = w[k - 1] if k else 0
            if before == 0 and w[k] != 0:
                start = int(e[k])
            elif before != 0 and w[k] == 0 and start is not None:
                spans.append((start, int(e[k])))
        now = set(spans)
        for key in [key for key in open_ if key not in now]:
            close(key, y0, open_)
        for key in spans:
            if key not in open_:
                _, bottom = at(np.array(key), y0)
                open_[key] = bottom
    for key in list(open_):
        close(key, ys[-1], open_)
    return out


def _crossing_heights(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The heights (y) where two edges cross properly."""
    ii, jj = _crossing_pairs(a, b)
    t, _ = _where_crossing(a, b, ii, jj)
    return a[ii, 1] + t * (b[ii, 1] - a[ii, 1])
