"""Which of limn's painted items go under the axes' ticks and labels.

matplotlib draws a 3D axes' panes, then its grid, then its axis lines, ticks and tick
labels, then the data. With the panes, the grid and the axis lines in limn's scene,
limn's paint order mixes them with the data (a surface that pokes out of the box behind
a pane is painted before the pane, a visible grid line comes after everything it is
drawn over). The bridge keeps matplotlib's layering where the picture allows: it paints
the box's items and every item that must come before one of them, then lets matplotlib
draw the ticks and labels, then paints the rest. Moving an item past another one whose
drawing it does not overlap leaves the picture unchanged, so the split is exact when
overlaps are judged conservatively.

Overlap is judged on convex parts (a polygon, one segment of a line piece, a marker's
anchor) widened by a pad (half a stroke, a marker's reach): two parts overlap unless an
axis separates them (an edge's normal of either part, or a segment's direction), which
never misses a real overlap. Parts that only touch do not overlap: the fills of two faces sharing an
edge may change places, which changes no boundary of the picture, only the blending
order of the antialiased pixels along that edge (otherwise the rule would pull every
face of a surface under the ticks, one neighbour after another).
"""

from __future__ import annotations

from typing import List, Optional

import numpy as np

Parts = Optional[List[np.ndarray]]
"""An item's convex parts, each (k, 2) in display units; ``None`` reaches everywhere."""

_FAR = 1e12
_MAX_CORNERS = 8
"""Parts of more corners are replaced by their bounding octagon (the tests' cost grows
with the square of the largest part's corner count)."""


def _octagon(p: np.ndarray) -> np.ndarray:
    """The convex octagon (8, 2) bounding the points (k, 2) between their extremes in x,
    y, x + y and x - y (corners repeat where it has fewer sides)."""
    x0, y0 = p.min(axis=0)
    x1, y1 = p.max(axis=0)
    s, d = p[:, 0] + p[:, 1], p[:, 0] - p[:, 1]
    s0, s1, d0, d1 = s.min(), s.max(), d.min(), d.max()
    # Counter-clockwise from the bottom edge's left end; each corner where two of the
    # eight supporting lines meet.
    return np.array(
        [
            (s0 - y0, y0),
            (d1 + y0, y0),
            (x1, x1 - d1),
            (x1, s1 - x1),
            (s1 - y1, y1),
            (d0 + y1, y1),
            (x0, x0 - d0),
            (x0, s0 - x0),
        ]
    )


def _table(parts: List[Parts], pads: np.ndarray):
    """The parts of all items as one padded table: owner, vertices (P, K, 2), pad and
    box (P, 4) including the pad."""
    owner, polys, pad = [], [], []
    for i, ps in enumerate(parts):
        if ps is None:
            ps = [np.array([[-_FAR, -_FAR], [_FAR, -_FAR], [_FAR, _FAR], [-_FAR, _FAR]])]
        for p in ps:
            p = np.asarray(p, dtype=float).reshape(-1, 2)
            if len(p) > _MAX_CORNERS:
                p = _octagon(p)
            if len(p):
                owner.append(i)
                polys.append(p)
                pad.append(pads[i])
    k = max((len(p) for p in polys), default=1)
    verts = np.empty((len(polys), k, 2))
    for j, p in enumerate(polys):
        verts[j, : len(p)] = p
        verts[j, len(p) :] = p[-1]
    pad = np.asarray(pad, dtype=float)
    lo, hi = verts.min(axis=1), verts.max(axis=1)
    box = np.c_[lo - pad[:, None], hi + pad[:, None]]
    return np.asarray(owner, dtype=int), verts, pad, box


def _axes(verts: np.ndarray) -> np.ndarray:
    """Unit normals of the edges of each part, (P, K, 2); where an edge has zero length
    (the padding of short parts), the direction of the part's first edge instead, which
    gives a segment both its normal and its direction. Zero for a single point."""
    d = np.roll(verts, -1, axis=-2) - verts
    n = np.stack([-d[..., 1], d[..., 0]], axis=-1)
    a = np.where((n == 0).all(axis=-1, keepdims=True), d[..., :1, :], n)
    length = np.linalg.norm(a, axis=-1, keepdims=True)
    return np.divide(a, length, out=np.zeros_like(a), where=length > 0)


def _separated(a: np.ndarray, b: np.ndarray, axes: np.ndarray, gap: np.ndarray) -> np.ndarray:
    """Whether some axis separates each part of ``a`` (N, K, 2) from the part of ``b``
    (N, K, 2) in the same row by ``gap`` (N,) or more; ``axes`` (N, M, 2). Parts that
    only touch (gap 0) are separated."""
    ax, ay = axes[:, :, None, 0], axes[:, :, None, 1]
    pa = a[:, None, :, 0] * ax + a[:, None, :, 1] * ay  # (N, M, K)
    pb = b[:, None, :, 0] * ax + b[:, None, :, 1] * ay
    g = gap[:, None]
    apart = (pb.min(axis=2) - pa.max(axis=2) >= g) | (pa.min(axis=2) - pb.max(axis=2) >= g)
    real = (axes != 0).any(axis=2)  # a zero axis separates nothing
    return (apart & real).any(axis=1)


def under_axes(parts: List[Parts], pads: np.ndarray, background: np.ndarray) -> np.ndarray:
    """The items to paint before matplotlib's ticks and labels: every ``background`` item
    and every item painted before one of those items that overlaps it, and so on.

    parts: per item in paint order, its convex parts (or ``None``: everywhere); pads: (N,)
    display units each part is widened by; background: (N,) bool. Painting the returned
    items in their order, then the others in theirs, gives the same picture as the paint
    order: no two overlapping items change places.

    Computed in rounds: the parts of the items chosen last are tested against every
    earlier part not chosen yet whose box meets theirs, all pairs at once.
    """
    under = np.array(background, dtype=bool).copy()
    if not under.any():
        return under
    owner, verts, pad, box = _table(parts, np.asarray(pads, dtype=float))
    own_axes = _axes(verts)
    frontier = np.nonzero(under[owner])[0]
    while len(frontier):
        found = []
        # Chunks of nearby parts (sorted by left edge), each against the parts in the
        # slab of x it spans.
        frontier = frontier[np.argsort(box[frontier, 0], kind="stable")]
        for chunk in np.array_split(frontier, max(1, len(frontier) // 64)):
            f = box[chunk]
            slab = np.nonzero(
                (box[:, 0] <= f[:, 2].max())
                & (box[:, 2] >= f[:, 0].min())
                & (owner < owner[chunk].max())
                & ~under[owner]
            )[0]
            b = box[slab]
            meets = (
                (owner[slab][:, None] < owner[chunk][None, :])
                & (b[:, 0:1] <= f[None, :, 2])
                & (b[:, 2:3] >= f[None, :, 0])
                & (b[:, 1:2] <= f[None, :, 3])
                & (b[:, 3:4] >= f[None, :, 1])
            )
            p, q = np.nonzero(meets)
            if len(p) == 0:
                continue
            p, q = slab[p], chunk[q]
            # The chosen part's own axes first (a line's normal separates most pairs),
            # then the other part's axes for the pairs left.
            gap = pad[p] + pad[q]
            keep = ~_separated(verts[p], verts[q], own_axes[q], gap)
            p, q, gap = p[keep], q[keep], gap[keep]
            keep = ~_separated(verts[p], verts[q], own_axes[p], gap)
            found.append(owner[p[keep]])
        new = np.unique(np.concatenate(found)) if found else np.zeros(0, int)
        new = new[~under[new]]
        under[new] = True
        frontier = np.nonzero(np.isin(owner, new))[0]
    return under
