"""Non-planar polygons cut into triangles as matplotlib shows them.

matplotlib fills a polygon of a ``Poly3DCollection`` as the outline its corners project
to, whatever its shape in 3D. A polygon that is not planar (a ``plot_surface`` patch of
several grid cells when a stride is above one, a cell of a curved height field) has no
one surface; limn gives such a face triangles of its own choice, which can differ from
the projected outline where the polygon folds (a patch across a sharp valley bridged by
a triangle over the valley's floor). The bridge therefore cuts each non-planar polygon
whose projected outline is simple into triangles of that outline (ear clipping in the
view), so that the triangles cover exactly what matplotlib fills; their corners are the
polygon's own, so each triangle is flat and in place in 3D. Which triangle edges are the
polygon's own edges is kept, so that only those are stroked. A quadrilateral whose
outline crosses itself (a bow-tie: a twisted strip of ``fill_between`` seen edge-on)
is filled by matplotlib as its two lobes, once each; it goes to limn as those two
triangles, meeting where the outline crosses itself.
"""

from __future__ import annotations

from typing import List, Optional, Tuple

import numpy as np


def planar(p: np.ndarray, rel: float = 1e-9) -> bool:
    """Whether the polygon's corners (n, 3) lie in one plane (within ``rel`` of its
    size)."""
    if len(p) <= 3:
        return True
    c = p.mean(axis=0)
    q = p - c
    nxt = np.roll(p, -1, axis=0)
    normal = np.array(
        [
            np.sum((p[:, 1] - nxt[:, 1]) * (p[:, 2] + nxt[:, 2])),
            np.sum((p[:, 2] - nxt[:, 2]) * (p[:, 0] + nxt[:, 0])),
            np.sum((p[:, 0] - nxt[:, 0]) * (p[:, 1] + nxt[:, 1])),
        ]
    )
    size = float(np.abs(q).max())
    length = float(np.linalg.norm(normal))
    if not (np.isfinite(length) and np.isfinite(size)) or length == 0 or size == 0:
        return True  # whole to limn (which refuses what it cannot take)
    return float(np.abs(q @ (normal / length)).max()) <= rel * size


_FAN_MAX = 64
"""Outlines of more corners are not tried for a fan (the test costs n² per outline)."""


def planar_all(p: np.ndarray, rel: float = 1e-9) -> np.ndarray:
    """``planar`` of each polygon of ``p`` (m, n, 3), all at once."""
    c = p.mean(axis=1, keepdims=True)
    q = p - c
    nxt = np.roll(p, -1, axis=1)
    normal = np.stack(
        [
            np.sum((p[..., 1] - nxt[..., 1]) * (p[..., 2] + nxt[..., 2]), axis=1),
            np.sum((p[..., 2] - nxt[..., 2]) * (p[..., 0] + nxt[..., 0]), axis=1),
            np.sum((p[..., 0] - nxt[..., 0]) * (p[..., 1] + nxt[..., 1]), axis=1),
        ],
        axis=1,
    )
    with np.errstate(all="ignore"):
        size = np.abs(q).max(axis=(1, 2))
        length = np.linalg.norm(normal, axis=1)
        unit = normal / length[:, None]
        dev = np.abs(np.einsum("mnk,mk->mn", q, unit)).max(axis=1)
        whole = ~(np.isfinite(length) & np.isfinite(size)) | (length == 0) | (size == 0)
        return whole | (dev <= rel * size)


def fan_corner_all(q: np.ndarray) -> np.ndarray:
    """Per outline of ``q`` (m, n, 2), a corner whose fan of triangles covers the outline
    exactly (-1: none): every triangle (c, c + i, c + i + 1) turning the way the outline
    winds and their angles at c adding up to less than a full turn, so the triangles
    follow each other around c without overlapping (a convex outline, or one
    star-shaped from c)."""
    m, n, _ = q.shape
    area = 0.5 * np.sum(q[..., 0] * np.roll(q[..., 1], -1, axis=1)
                        - np.roll(q[..., 0], -1, axis=1) * q[..., 1], axis=1)
    sign = np.sign(area)[:, None]
    best = np.full(m, -1)
    with np.errstate(invalid="ignore"):
        for c in range(n):
            # Only the outlines without a corner yet (most have one at corner 0).
            rows = np.nonzero(best < 0)[0]
            if not len(rows):
                break
            o = q[rows, c : c + 1, :]
            a = q[rows][:, (c + np.arange(1, n - 1)) % n, :] - o
            b = q[rows][:, (c + np.arange(2, n)) % n, :] - o
            cr = a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]
            dot = (a * b).sum(axis=2)
            fine = (cr * sign[rows] > 0).all(axis=1)
            fine &= np.abs(np.arctan2(cr, dot).sum(axis=1)) < 2 * np.pi - 1e-9
            best[rows[fine]] = c
    return best


def _cross(o: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return (a[..., 0] - o[..., 0]) * (b[..., 1] - o[..., 1]) - (a[..., 1] - o[..., 1]) * (
        b[..., 0] - o[..., 0]
    )


def simple(q: np.ndarray) -> bool:
    """Whether the closed outline through the points (n, 2) is simple: no two edges that
    are not neighbours meet (touching counts as meeting), no zero-length edge."""
    n = len(q)
    a, b = q, np.roll(q, -1, axis=0)
    if (np.abs(b - a).max(axis=1) == 0).any():
        return False
    i, j = np.triu_indices(n, k=2)
    keep = ~((i == 0) & (j == n - 1))
    i, j = i[keep], j[keep]
    d1 = _cross(a[i], b[i], a[j])
    d2 = _cross(a[i], b[i], b[j])
    d3 = _cross(a[j], b[j], a[i])
    d4 = _cross(a[j], b[j], b[i])
    cross = (d1 * d2 <= 0) & (d3 * d4 <= 0)
    return not cross.any()


def _area(q: np.ndarray) -> float:
    """Signed area of the outline (n, 2), positive counter-clockwise."""
    return 0.5 * float(np.sum(q[:, 0] * np.roll(q[:, 1], -1) - np.roll(q[:, 0], -1) * q[:, 1]))


def ear_clip(q: np.ndarray) -> List[Tuple[int, int, int]]:
    """Triangles (corner indices, counter-clockwise) covering the simple polygon (n, 2)
    exactly."""
    n = len(q)
    idx = list(range(n)) if _area(q) > 0 else list(range(n))[::-1]
    tris: List[Tuple[int, int, int]] = []
    guard = 0
    while len(idx) > 3 and guard < 4 * n * n:
        guard += 1
        m = len(idx)
        for k in range(m):
            a, b, c = idx[k - 1], idx[k], idx[(k + 1) % m]
            if _cross(q[a], q[b], q[c]) <= 0:
                continue  # reflex or flat corner
            others = [o for o in idx if o not in (a, b, c)]
            if others:
                p = q[others]
                inside = (
                    (_cross(q[a], q[b], p) >= 0)
                    & (_cross(q[b], q[c], p) >= 0)
                    & (_cross(q[c], q[a], p) >= 0)
                )
                if inside.any():
                    continue
            tris.append((a, b, c))
            del idx[k]
            break
        else:
            return []  # no ear (should not happen for a simple outline)
    if len(idx) == 3:
        tris.append((idx[0], idx[1], idx[2]))
    return tris


def _darts(corners: List[np.ndarray], project) -> Tuple[np.ndarray, np.ndarray]:
    """Per polygon, the reflex corner of a quadrilateral whose projected outline is a dart
    (simple, one reflex corner), -1 for every other polygon, and whether it is a
    quadrilateral whose outline is a bow-tie (two edges crossing); all quadrilaterals at
    once. Either diagonal cuts a convex quad into triangles covering its outline, so
    convex quads (most cells of a curved surface) go to limn whole, as do quads with a
    straight or doubled corner; a dart is cut from its reflex corner, a bow-tie into its
    two lobes (matplotlib fills both)."""
    reflex = np.full(len(corners), -1)
    bowtie = np.zeros(len(corners), dtype=bool)
    quads = np.array([k for k, p in enumerate(corners) if len(p) == 4], dtype=int)
    if not len(quads):
        return reflex, bowtie
    q = project(np.concatenate([corners[k] for k in quads])).reshape(-1, 4, 2)
    turn = _cross(np.roll(q, 1, axis=1), q, np.roll(q, -1, axis=1))  # at each corner
    with np.errstate(invalid="ignore"):
        pos, neg = (turn > 0).sum(axis=1), (turn < 0).sum(axis=1)
        area = 0.5 * np.sum(q[..., 0] * np.roll(q[..., 1], -1, axis=1)
                            - np.roll(q[..., 0], -1, axis=1) * q[..., 1], axis=1)
    # A dart: three corners turn the way the outline winds, one the other way (a
    # bow-tie turns two and two, and its area's sign does not say which is reflex).
    dart = ((pos == 3) & (neg == 1) & (area > 0)) | ((neg == 3) & (pos == 1) & (area < 0))
    odd = np.where(area[:, None] > 0, turn < 0, turn > 0)
    reflex[quads[dart]] = np.argmax(odd[dart], axis=1)
    bowtie[quads[(pos == 2) & (neg == 2)]] = True
    return reflex, bowtie


def _lobes(p: np.ndarray, q: np.ndarray):
    """The two triangles of a quadrilateral (4, 3) whose projected outline (4, 2) is a
    bow-tie: each lobe's corner where the outline crosses itself is the middle of the two
    crossing edges' points that project there (the same point in the view). ``None``
    when no two opposite edges cross properly."""
    if not np.isfinite(q).all():
        return None
    for i in (0, 1):
        a, b, c, d = (q[(i + j) % 4] for j in range(4))
        den = (b[0] - a[0]) * (d[1] - c[1]) - (b[1] - a[1]) * (d[0] - c[0])
        if den == 0:
            continue
        s = ((c[0] - a[0]) * (d[1] - c[1]) - (c[1] - a[1]) * (d[0] - c[0])) / den
        u = ((c[0] - a[0]) * (b[1] - a[1]) - (c[1] - a[1]) * (b[0] - a[0])) / den
        if 0 < s < 1 and 0 < u < 1:
            P = [p[(i + j) % 4] for j in range(4)]
            x = ((P[0] + s * (P[1] - P[0])) + (P[2] + u * (P[3] - P[2]))) / 2
            return [np.array([x, P[1], P[2]]), np.array([x, P[3], P[0]])]
    return None


def view_triangles(
    corners: List[np.ndarray], project, fixed: Optional[List[Optional[np.ndarray]]] = None
) -> Tuple[List[np.ndarray], np.ndarray, List[np.ndarray]]:
    """Each polygon (n, 3) as it goes to limn: planar ones, and those whose projected
    outline is not simple, whole; the others as the triangles of their projected outline.
    A polygon with its own edges given in ``fixed`` (not ``None``: a filled region with
    bridges to its holes, see ``_regions``) goes whole, with those edges.

    ``project`` maps points (k, 3) to the view's 2D coordinates (k, 2), NaN where a point
    cannot be projected. Returns the faces, the polygon each face comes from, and per face
    which of its edges (edge i from corner i to i + 1) are edges of its polygon."""
    faces: List[np.ndarray] = []
    owner: List[int] = []
    own: List[np.ndarray] = []
    reflex, bowtie = _darts(corners, project)
    sizes = np.array([len(p) for p in corners], dtype=np.int64)
    # Every corner projected at once; planarity and convex projected outlines tested per
    # corner count, all polygons of a count at once.
    seen = project(np.concatenate(corners)) if len(corners) else np.zeros((0, 2))
    starts = np.concatenate([[0], np.cumsum(sizes)])
    flat = np.ones(len(corners), dtype=bool)
    fan = np.full(len(corners), -1)
    fan_tris: dict = {}
    for n in np.unique(sizes[sizes >= 4]):
        ks = np.nonzero(sizes == n)[0]
        group = np.stack([corners[k] for k in ks])
        flat[ks] = planar_all(group)
        # A fan only for polygons that do not go whole (planar ones do).
        bent = ks[~flat[ks]]
        if 5 <= n <= _FAN_MAX and len(bent):
            rows = starts[bent][:, None] + np.arange(n)[None, :]
            fan[bent] = fan_corner_all(seen[rows])
            # Each fanned polygon's triangles (n - 2, 3, 3), for all of them at once.
            fanned = bent[fan[bent] >= 0]
            if len(fanned):
                tri = np.array([[0, i, i + 1] for i in range(1, n - 1)])
                at = (fan[fanned][:, None, None] + tri[None]) % n
                polys = group[np.searchsorted(ks, fanned)]
                tris = polys[np.arange(len(fanned))[:, None, None], at]
                fan_tris.update(zip(fanned.tolist(), tris))
    fan_edges = {}
    # Polygons that go whole with all their edges (most): no test per polygon below.
    plain = ~(bowtie | ((reflex >= 0) & ~flat) | ((sizes >= 5) & ~flat))
    if fixed is not None:
        plain &= np.array([f is None for f in fixed], dtype=bool)
    all_own = {}  # one read-only all-true array per corner count
    for k, p in enumerate(corners):
        n = len(p)
        if plain[k]:
            mine = all_own.get(n)
            if mine is None:
                mine = all_own[n] = np.ones(n, dtype=bool)
                mine.flags.writeable = False
            faces.append(p)
            owner.append(k)
            own.append(mine)
            continue
        if fixed is not None and fixed[k] is not None:
            faces.append(p)
            owner.append(k)
            own.append(fixed[k])
            continue
        if bowtie[k]:
            lobes = _lobes(p, seen[starts[k] : starts[k + 1]])
            if lobes is not None:
                for t in lobes:
                    faces.append(t)
                    owner.append(k)
                    own.append(np.ones(3, dtype=bool))
                continue
        if reflex[k] >= 0 and not flat[k]:
            r = int(reflex[k])
            cuts = ((r, r + 1, r + 2), (r, r + 2, r + 3))
            for t, e in zip(cuts, ((True, True, False), (False, True, True))):
                faces.append(p[[i % 4 for i in t]])
                owner.append(k)
                own.append(np.array(e))
            continue
        if n >= 5 and not flat[k] and fan[k] >= 0:
            # The fan from that corner covers the outline exactly, in the polygon's own
            # winding.
            if n not in fan_edges:
                fan_edges[n] = [np.array([i == 1, True, i == n - 2]) for i in range(1, n - 1)]
            faces.extend(fan_tris[k])
            owner.extend([k] * (n - 2))
            own.extend(fan_edges[n])
            continue
        if n >= 5 and not flat[k]:
            q = seen[starts[k] : starts[k + 1]]
            if np.isfinite(q).all() and simple(q):
                tris = ear_clip(q)
                if len(tris) == n - 2:
                    if _area(q) < 0:  # the polygon's own winding, as its neighbours have it
                        tris = [(c, b, a) for a, b, c in tris]
                    for t in tris:
                        faces.append(p[list(t)])
                        owner.append(k)
                        own.append(
                            np.array(
                                [(t[(e + 1) % 3] - t[e]) % n in (1, n - 1) for e in range(3)]
                            )
                        )
                    continue
        faces.append(p)
        owner.append(k)
        own.append(np.ones(n, dtype=bool))
    return faces, np.asarray(owner, dtype=np.int64), own
