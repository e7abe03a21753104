"""What the bridge reads from a 3D axes' artists: polygons with their colours, lines,
scatter points and texts, with what matplotlib needs to draw each visible piece in the
artist's own style.

Coordinates are the axes' scaled coordinates, those mplot3d projects with ``ax.M``: data
coordinates through each axis' scale transform (``set_zscale("log")``: log10 of z), as
matplotlib 3.11 transforms them before projecting. A point outside its scales' domain (z
<= 0 on a log axis), or outside the axes' view limits on an artist drawn with
``axlim_clip=True``, is left out as mplot3d leaves it out: a line breaks there, a scatter
point or text is not drawn, a polygon loses that corner.

The private mplot3d attributes read here (``_faces``, ``_invalid_vertices``,
``_facecolor3d``, ``_edgecolor3d``, ``_segments3d``, ``_offsets3d``, ``_sizes3d``) are
those of matplotlib 3.11.
"""

from __future__ import annotations

from typing import Any, List, NamedTuple, Tuple

import numpy as np

from ._axes_box import Pane, behind
from ._depth_shading import depth_shaded, scatter_depth_shading
from ._regions import outlines, region_faces


def _left_out(artist: Any, pts: np.ndarray) -> np.ndarray:
    """Which points (N, 3) in data coordinates mplot3d leaves out of ``artist``'s
    drawing: outside a scale's domain, or outside the view limits when the artist is
    clipped to them (``axlim_clip``)."""
    ax = artist.axes
    out = np.zeros(len(pts), dtype=bool)
    for i, axis in enumerate((ax.xaxis, ax.yaxis, ax.zaxis)):
        in_range = getattr(axis._scale, "val_in_range", None)
        if in_range is not None:
            out |= ~np.broadcast_to(np.asarray(in_range(pts[:, i]), dtype=bool), out.shape)
    if getattr(artist, "_axlim_clip", False):
        for i, lim in enumerate((ax.get_xlim3d(), ax.get_ylim3d(), ax.get_zlim3d())):
            lo, hi = min(lim), max(lim)
            with np.errstate(invalid="ignore"):
                out |= (pts[:, i] < lo) | (pts[:, i] > hi)
    return out


def scaled(ax: Any, pts: np.ndarray) -> np.ndarray:
    """Points (N, 3) in data coordinates in the axes' scaled coordinates (each axis'
    scale transform, identity for linear axes); NaN where that is not finite."""
    pts = np.asarray(pts, dtype=float).reshape(-1, 3)
    out = np.empty_like(pts)
    with np.errstate(all="ignore"):
        for i, axis in enumerate((ax.xaxis, ax.yaxis, ax.zaxis)):
            out[:, i] = axis.get_transform().transform(pts[:, i])
    out[~np.isfinite(out).all(axis=1)] = np.nan
    return out


def shown(artist: Any, pts: Any) -> np.ndarray:
    """``artist``'s points (N, 3) in data coordinates as the axes' scaled coordinates, NaN
    where mplot3d leaves them out (see the module docs)."""
    pts = np.asarray(pts, dtype=float).reshape(-1, 3)
    out = scaled(artist.axes, pts)
    out[_left_out(artist, pts)] = np.nan
    return out


def collection_polygons(coll: Any) -> Tuple[List[np.ndarray], np.ndarray, np.ndarray, np.ndarray]:
    """The collection's polygons in scaled coordinates, with face colours (colormapped),
    edge colours and line widths per polygon."""
    coll.do_3d_projection()  # also maps the colours
    faces = np.asarray(coll._faces, dtype=float)
    invalid = np.asarray(coll._invalid_vertices)
    n = len(faces)
    polys: List[np.ndarray] = []
    if n:
        # Every corner at once; only polygons that lose corners are picked apart.
        k = faces.shape[1]
        every = shown(coll, faces.reshape(-1, 3)).reshape(n, k, 3)
        keep = np.isfinite(every).all(axis=2)
        if invalid.ndim == 2:
            keep &= ~invalid
        whole = keep.all(axis=1)
        polys = [every[i] if whole[i] else every[i][keep[i]] for i in range(n)]
    rep = lambda c: (  # noqa: E731
        np.zeros((n, 4)) if len(c) == 0 else (np.repeat(c, n, axis=0) if len(c) != n else c)
    )
    fc = rep(np.asarray(coll._facecolor3d, dtype=float).reshape(-1, 4))
    # No edge colour ("none", the default of a collection without one) is no stroke, as
    # mplot3d draws it; "face" edges are already the face colours here.
    ec = rep(np.asarray(coll._edgecolor3d, dtype=float).reshape(-1, 4))
    lw = np.asarray(coll.get_linewidths(), dtype=float).reshape(-1)
    lw = np.zeros(n) if len(lw) == 0 else (np.repeat(lw, n) if len(lw) != n else lw)
    if n > 1:
        # Nearest first, the reverse of mplot3d's painting order: where limn's exact order
        # leaves a choice (polygons that do not overlap, such as the cells of a plane),
        # it paints the last given first, so edge strokes overlap their neighbours as
        # matplotlib's do.
        order = _painting_order(coll, faces)[::-1]
        polys = [polys[i] for i in order]
        fc, ec, lw = fc[order], ec[order], lw[order]
    return polys, fc, ec, lw


def _painting_order(coll: Any, faces: np.ndarray) -> np.ndarray:
    """The order in which mplot3d paints the collection's polygons: far to near by its
    sort depth (``zsort``) of the projected corners, as ``do_3d_projection`` sorts them."""
    from mpl_toolkits.mplot3d import proj3d

    with np.errstate(invalid="ignore", divide="ignore"):
        pzs = proj3d._scale_proj_transform_vectors(faces, coll.axes)[..., 2]
    invalid = np.asarray(coll._invalid_vertices)
    if invalid.ndim == 2 and invalid.any():
        pzs = np.ma.MaskedArray(pzs, mask=invalid)
    face_z = coll._zsortfunc(pzs, axis=-1)
    face_z = np.ma.getdata(face_z)
    return np.argsort(face_z, axis=-1)[::-1]


def _lines(artist: Any) -> List[np.ndarray]:
    """A ``Line3D``'s runs of finite points (matplotlib breaks lines at NaN)."""
    xyz = (np.asarray(np.ma.filled(c, np.nan), dtype=float) for c in artist.get_data_3d())
    return _runs(shown(artist, np.c_[tuple(a.ravel() for a in np.broadcast_arrays(*xyz))]))


def _runs(pts: np.ndarray) -> List[np.ndarray]:
    """The runs of consecutive finite rows of ``pts``."""
    ok = np.isfinite(pts).all(axis=1)
    runs, start = [], None
    for i, good in enumerate(list(ok) + [False]):
        if good and start is None:
            start = i
        elif not good and start is not None:
            runs.append(pts[start:i])
            start = None
    return runs


class Line(NamedTuple):
    """One limn line of the bridge and how matplotlib draws its visible pieces."""

    points: np.ndarray
    rgba: np.ndarray
    width: float
    """Width in points."""
    dash: Any
    """``(offset, sequence)`` in points, or ``None`` for solid."""
    background: bool = False
    """A grid line or a pane's outline (painted under the axes' lines)."""
    cap: str = "butt"
    clip: Any = None
    """The clip box of the artist it comes from (``None``: not clipped)."""


class Point(NamedTuple):
    """One limn point of the bridge (a scatter point or a line's marker) and how
    matplotlib draws it."""

    at: np.ndarray
    face: Tuple[float, ...]
    edge: Tuple[float, ...]
    edge_width: float
    """In points."""
    path: Any
    """The marker's path (``None``: a circle)."""
    scale: float
    """Display units per unit of the path."""
    clip: Any = None


def clip_of(artist: Any) -> Any:
    """The clip box matplotlib gives ``artist``'s drawing (``None`` when it is not
    clipped)."""
    return artist.get_clip_box() if artist.get_clip_on() else None


class Marks:
    """An axes' lines, points and texts: what limn gets (in the order of limn's line,
    point and label indices), and how matplotlib draws each."""

    def __init__(self) -> None:
        self.lines: List[Line] = []
        self.points: List[Point] = []
        # Per limn label: the Text3D it shows and its anchor in scaled coordinates.
        self.texts: List[Any] = []
        self.anchors: List[np.ndarray] = []

    def add_line3d(self, line: Any, p2p: float) -> None:
        from matplotlib.colors import to_rgba
        from matplotlib.markers import MarkerStyle

        rgba = np.array(to_rgba(line.get_color(), line.get_alpha()))
        dash = line._dash_pattern if line.get_linestyle() not in ("-", "solid") else None
        runs = _lines(line)
        if line.get_linestyle() not in ("None", "none", " ", ""):
            for r in runs:
                if len(r) >= 2:
                    w = float(line.get_linewidth())
                    self.lines.append(Line(r, rgba, w, dash, clip=clip_of(line)))
        ms = MarkerStyle(line.get_marker())
        if ms.get_marker() not in ("None", "none", " ", "", None):
            path = ms.get_path().transformed(ms.get_transform())
            scale = float(line.get_markersize()) * p2p
            fc = to_rgba(line.get_markerfacecolor(), line.get_alpha())
            ec = to_rgba(line.get_markeredgecolor(), line.get_alpha())
            for r in runs:
                for q in r:
                    ew = float(line.get_markeredgewidth())
                    self.points.append(Point(q, fc, ec, ew, path, scale, clip_of(line)))

    def add_line_collection(self, coll: Any, background: bool = False) -> None:
        """A ``Line3DCollection`` (``plot_wireframe``, ``quiver``, the axes' grid)."""
        segs = coll._segments3d
        col = np.asarray(coll.get_colors(), dtype=float).reshape(-1, 4)
        lw = np.asarray(coll.get_linewidths(), dtype=float).reshape(-1)
        ls = coll.get_linestyles()
        for i, seg in enumerate(segs):
            c = col[i % len(col)] if len(col) else np.array([0, 0, 0, 1.0])
            w = float(lw[i % len(lw)]) if len(lw) else 1.0
            off, seq = ls[i % len(ls)] if ls else (0, None)
            dash = (off, seq) if seq else None
            pts = shown(coll, np.ma.filled(np.asarray(seg, dtype=float), np.nan))
            if background:
                pts = behind(coll.axes, pts)  # a grid line stays under data on its pane
            for r in _runs(pts):
                if len(r) >= 2 and c[3] > 0 and w > 0:
                    clip = None if background else clip_of(coll)
                    self.lines.append(Line(r, c, w, dash, background, clip=clip))

    def add_contour_lines(self, cset: Any) -> None:
        """A contour set's lines (``ax.contour``, a ``Collection3D`` of one path per
        level): each run between moves is a line in its level's colour, width and dash
        pattern (``CLOSEPOLY`` closes a run back to its start)."""
        from matplotlib.path import Path

        cset.update_scalarmappable()
        col = np.asarray(cset.get_edgecolor(), dtype=float).reshape(-1, 4)
        lw = np.asarray(cset.get_linewidths(), dtype=float).reshape(-1)
        ls = cset.get_linestyles()
        clip = clip_of(cset)
        for i, (verts, codes) in enumerate(cset._3dverts_codes):
            c = col[i % len(col)] if len(col) else np.array([0, 0, 0, 1.0])
            w = float(lw[i % len(lw)]) if len(lw) else 1.0
            off, seq = ls[i % len(ls)] if ls else (0, None)
            dash = (off, seq) if seq else None
            if c[3] <= 0 or w <= 0:
                continue
            pts = shown(cset, verts)
            codes = np.full(len(pts), Path.LINETO) if codes is None else np.asarray(codes)
            starts = np.nonzero(codes == Path.MOVETO)[0].tolist()
            for a, b in zip([0] + starts, starts + [len(pts)]):
                if b <= a:
                    continue
                run, kinds = pts[a:b], codes[a:b]
                if kinds[-1] == Path.CLOSEPOLY:
                    run = np.vstack([run[:-1], run[:1]])
                for r in _runs(run):
                    if len(r) >= 2:
                        self.lines.append(Line(r, c, w, dash, clip=clip))

    def add_pane_outline(self, pane: Pane) -> None:
        if pane.width > 0:
            loop = np.vstack([pane.corners, pane.corners[:1]])
            self.lines.append(Line(loop, pane.edge, pane.width, None, True, "projecting"))

    def add_scatter(self, coll: Any, p2p: float, M: np.ndarray) -> None:
        from matplotlib.collections import PathCollection

        coll.update_scalarmappable()
        xs, ys, zs = (
            np.asarray(np.ma.filled(c, np.nan), dtype=float).ravel() for c in coll._offsets3d
        )
        pts = shown(coll, np.c_[xs, ys, zs])
        n = len(pts)
        # In input order: mplot3d's own getters return colours and widths sorted by
        # depth (and "face" edges through them).
        fc = np.asarray(PathCollection.get_facecolor(coll), dtype=float).reshape(-1, 4)
        face_edges = isinstance(coll._edgecolors, str) and coll._edgecolors == "face"
        ec = fc if face_edges else np.asarray(PathCollection.get_edgecolor(coll), dtype=float)
        ec = ec.reshape(-1, 4)
        shaded, min_alpha, alpha = scatter_depth_shading(coll)
        if shaded and n:
            fc = depth_shaded(fc, pts, M, min_alpha, alpha)
            ec = fc if face_edges else depth_shaded(ec, pts, M, min_alpha, alpha)
        lw = np.asarray(getattr(coll, "_linewidths3d", coll.get_linewidths()), dtype=float)
        lw = lw.reshape(-1)
        sizes = np.asarray(coll._sizes3d, dtype=float).reshape(-1)
        paths = coll.get_paths()
        pick = lambda a, i, d: a[i % len(a)] if len(a) else d  # noqa: E731
        for i in range(n):
            if not np.isfinite(pts[i]).all():
                continue
            s = float(pick(sizes, i, 36.0))
            self.points.append(
                Point(
                    pts[i],
                    tuple(pick(fc, i, (0, 0, 0, 0))),
                    tuple(pick(ec, i, (0, 0, 0, 0))),
                    float(pick(lw, i, 0.0)),
                    pick(paths, i, None),
                    np.sqrt(max(s, 0.0)) * p2p,
                    clip_of(coll),
                )
            )

    def add_text(self, text: Any) -> None:
        """A ``Text3D`` (``ax.text``): shown where its anchor is visible."""
        at = shown(text, text.get_position_3d())[0]
        if text.get_text() and np.isfinite(at).all():
            self.texts.append(text)
            self.anchors.append(at)

    def vertices(self) -> List[np.ndarray]:
        anchors = [q.at for q in self.points] + self.anchors
        return [ln.points for ln in self.lines] + [np.asarray(anchors, dtype=float).reshape(-1, 3)]


class Polygons:
    """An axes' polygons in scaled coordinates with their styles, in the order limn gets
    them (``owner`` indices of the painted fragments refer to this order)."""

    def __init__(self) -> None:
        self.corners: List[np.ndarray] = []
        self._fill: List[np.ndarray] = []
        self._edge: List[np.ndarray] = []
        self._width: List[np.ndarray] = []
        self.clip: List[Any] = []
        self.background: List[bool] = []
        # Per polygon, which of its edges are the artist's own (``None``: all; the
        # faces of filled paths have bridges to their holes, see ``_regions``).
        self.own: List[Any] = []
        # Per polygon, the tiling it belongs to: polygons of one tiling never overlap
        # (the faces filling one path: a contour level, a patch), so their fragments
        # painted one after another may be drawn as one path; every other polygon is a
        # tiling of its own.
        self.tiling: List[int] = []
        self._tilings = 0

    def _new_tiling(self, count: int = 1) -> int:
        """The first of ``count`` new tiling numbers."""
        self._tilings += count
        return self._tilings - count

    def add_collection(self, coll: Any) -> None:
        """A ``Poly3DCollection``'s polygons with their colours and edge widths."""
        p, fc, ec, lw = collection_polygons(coll)
        self.corners += p
        self._fill.append(fc)
        self._edge.append(ec)
        self._width.append(lw)
        self.clip += [clip_of(coll)] * len(p)
        self.background += [False] * len(p)
        self.own += [None] * len(p)
        start = self._new_tiling(len(p))
        self.tiling += range(start, start + len(p))

    def add_patch(self, patch: Any) -> None:
        """A filled ``Patch3D`` of one polygon (``ax.bar``): its outline, face and edge
        colour and line width."""
        from matplotlib.colors import to_rgba

        pts = shown(patch, np.asarray(patch._segment3d, dtype=float))
        if len(pts) > 1 and np.array_equal(pts[0], pts[-1], equal_nan=True):
            pts = pts[:-1]  # the closing corner
        self.corners.append(pts[np.isfinite(pts).all(axis=1)])
        self._fill.append(np.array(to_rgba(patch.get_facecolor()), dtype=float).reshape(1, 4))
        self._edge.append(np.array(to_rgba(patch.get_edgecolor()), dtype=float).reshape(1, 4))
        self._width.append(np.array([float(patch.get_linewidth())]))
        self.clip.append(clip_of(patch))
        self.background.append(False)
        self.own.append(None)
        self.tiling.append(self._new_tiling())

    def add_path_patch(self, patch: Any) -> None:
        """A filled ``PathPatch3D`` (``pathpatch_2d_to_3d``: a circle, a text's glyphs):
        the regions its path fills in its plane (see ``_regions``), in its face colour,
        its outlines in its edge colour and line width."""
        from matplotlib.colors import to_rgba

        pts = np.asarray(patch._segment3d, dtype=float).reshape(-1, 3)
        self._add_regions(
            [shown(patch, r) for r in outlines(pts, patch._code3d)],
            np.array(to_rgba(patch.get_facecolor()), dtype=float),
            np.array(to_rgba(patch.get_edgecolor()), dtype=float),
            float(patch.get_linewidth()),
            clip_of(patch),
        )

    def add_contour_fill(self, cset: Any) -> None:
        """A filled contour set in 3D (``contourf``/``tricontourf`` of a 3D axes, a
        ``Collection3D`` of one path per level): each level's regions in its colour."""
        cset.update_scalarmappable()
        fc = np.asarray(cset.get_facecolor(), dtype=float).reshape(-1, 4)
        ec = np.asarray(cset.get_edgecolor(), dtype=float).reshape(-1, 4)
        lw = np.asarray(cset.get_linewidths(), dtype=float).reshape(-1)
        clip = clip_of(cset)
        for i, (verts, codes) in enumerate(cset._3dverts_codes):
            pick = lambda a, d: a[i % len(a)] if len(a) else d  # noqa: E731
            self._add_regions(
                [shown(cset, r) for r in outlines(verts, codes)],
                pick(fc, np.zeros(4)),
                pick(ec, np.zeros(4)),
                float(pick(lw, 0.0)),
                clip,
            )

    def _add_regions(
        self, rings: List[np.ndarray], fill: np.ndarray, edge: np.ndarray, width: float, clip: Any
    ) -> None:
        # A corner mplot3d leaves out (NaN) is left out of its outline.
        rings = [r[np.isfinite(r).all(axis=1)] for r in rings]
        tiling = self._new_tiling()
        for face, own in region_faces(rings):
            self.corners.append(face)
            self._fill.append(np.asarray(fill, dtype=float).reshape(1, 4))
            self._edge.append(np.asarray(edge, dtype=float).reshape(1, 4))
            self._width.append(np.array([width]))
            self.clip.append(clip)
            self.background.append(False)
            self.own.append(own)
            self.tiling.append(tiling)

    def add_pane(self, pane: Pane) -> None:
        """A filled pane (its outline is a line of its own)."""
        self.corners.append(pane.corners)
        self._fill.append(np.asarray(pane.fill, dtype=float).reshape(1, 4))
        self._edge.append(np.zeros((1, 4)))
        self._width.append(np.zeros(1))
        self.clip.append(None)
        self.background.append(True)
        self.own.append(None)
        self.tiling.append(self._new_tiling())

    def styles(self) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Fill colours (N, 4), edge colours (N, 4) and edge widths (N,) in points."""
        cat = lambda parts, shape: np.concatenate(parts) if parts else np.zeros(shape)  # noqa: E731
        return cat(self._fill, (0, 4)), cat(self._edge, (0, 4)), cat(self._width, (0,))

    def mesh(
        self, project: Any = None
    ) -> Tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, List[np.ndarray]]:
        """Vertices, faces and corner counts for limn (``add_mesh(v, faces,
        counts=counts)``), the polygon each face comes from, and per face which of its
        edges are edges of that polygon. Every polygon of three corners or more is one
        face, whatever its shape (limn draws a non-convex polygon, an L-shaped polygon of a
        ``Poly3DCollection``, as it is), except that with ``project`` (points to the view's
        2D coordinates) a non-planar polygon is cut into the triangles of its projected
        outline (see ``_triangulate``)."""
        from ._triangulate import view_triangles

        kept = [k for k, p in enumerate(self.corners) if len(p) >= 3]
        polys = [self.corners[k] for k in kept]
        fixed = [self.own[k] if k < len(self.own) else None for k in kept]
        if project is None:
            faces, sub = polys, np.arange(len(polys))
            own = [np.ones(len(p), bool) if f is None else f for p, f in zip(polys, fixed)]
        else:
            faces, sub, own = view_triangles(polys, project, fixed)
        owner = np.asarray(kept, dtype=np.int64)[sub] if len(faces) else np.zeros(0, np.int64)
        counts = np.array([len(p) for p in faces], dtype=np.int64)
        v = np.concatenate(faces) if faces else np.zeros((0, 3))
        # Each face's corners are its own vertices, one face after another.
        return v, np.arange(len(v), dtype=np.int64), counts, owner, own
