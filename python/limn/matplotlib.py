"""The matplotlib bridge: ``savefig`` with every 3D axes' surfaces ordered exactly by limn.

matplotlib's mplot3d sorts whole polygons by one depth each, so intersecting surfaces
and cyclic overlaps come out wrong in its own export. ``savefig`` draws each 3D axes'
``Poly3DCollection`` content (plot_surface, plot_trisurf, bar3d, voxels,
add_collection3d) through limn instead: the same polygons, the face colours after
colormapping, alpha, edge colours and line widths, seen through the axes' own projection
(``get_proj()``: perspective with its focal length, or orthographic), so the picture
registers with the axes, ticks, labels, titles and colorbars matplotlib draws around it.
limn's polygons are drawn through matplotlib's renderer at the place the collections
would take, so the file is one vector file of the format the extension names (SVG, PDF,
...), with no raster embedded (colorbars, which rasterise their solids of 50 colours or
more, are kept as vectors too).

Lines (``Line3D`` from ``plot``, ``Line3DCollection`` from ``plot_wireframe`` and
``quiver``) and scatter points (``Path3DCollection``) go into the same limn scene as the
polygons, so they are hidden exactly by the surfaces in front of them (a line on a
surface's own polygon is drawn over it); their visible pieces and markers are drawn by
matplotlib's renderer in matplotlib's own style (colour, width, dashes, marker path,
size), at their place in limn's paint order, markers far to near as mplot3d paints them.
Scatter points keep mplot3d's depth shading (``depthshade``; see ``_depth_shading``).
3D texts (``Text3D`` from ``ax.text``) are limn labels: shown only where their anchor
is visible, drawn by matplotlib itself.

When data leave the axes' box, the box is scene content as well (``_axes_box``): the
panes with their colours and outlines, the grid lines on them and the axis lines along
the box's edges, so that data poking out of the box are seen through or behind the panes
and grid or axis lines behind data are hidden. mplot3d draws the box before the data,
then the ticks and labels; the bridge keeps that layering where the picture allows
(``_layers``): panes, grid, axis lines and every item that must be painted before one
of them come first, then matplotlib's ticks, tick labels and axis labels, then the rest
of the data. While every vertex, point and text anchor lies inside the box, the box is
behind all of them and mplot3d's own drawing of it is the exact picture, so the bridge
leaves it to mplot3d (``box="auto"``). ``ax.grid(False)``, ``ax.set_axis_off()``, pane
colours and ``pane.fill`` are respected. Each drawing is clipped as matplotlib clips the
artist it comes from, and the file is written whole or not at all. Scales must be
linear; the private mplot3d attributes read are those of matplotlib 3.11.
"""

from __future__ import annotations

import contextlib
import io
import os
import secrets
from functools import partial
from typing import Any, Callable, List, NamedTuple, Optional, Tuple

import numpy as np

from . import Scene
from ._depth_shading import depth_shaded, scatter_depth_shading
from ._layers import under_axes
from ._axes_box import Pane, axis_lines, grid_lines, inside_box, panes

__all__ = ["savefig"]


def _is_3d(ax: Any) -> bool:
    return getattr(ax, "name", "") == "3d"


def _polys(coll: Any) -> Tuple[List[np.ndarray], np.ndarray, np.ndarray, np.ndarray]:
    """The collection's polygons in data coordinates, with face colours (colormapped),
    edge colours and line widths per polygon."""
    coll.do_3d_projection()  # also maps the colours
    faces = np.asarray(coll._faces)
    invalid = np.asarray(coll._invalid_vertices)
    n = len(faces)
    polys = []
    for i in range(n):
        keep = ~invalid[i] if invalid.ndim == 2 else np.ones(faces.shape[1], bool)
        polys.append(np.asarray(faces[i][keep], dtype=float))
    rep = lambda c: (  # noqa: E731
        np.zeros((n, 4)) if len(c) == 0 else (np.repeat(c, n, axis=0) if len(c) != n else c)
    )
    fc = rep(np.asarray(coll._facecolor3d, dtype=float).reshape(-1, 4))
    ec = np.asarray(coll._edgecolor3d, dtype=float).reshape(-1, 4)
    ec = fc if len(ec) == 0 else rep(ec)
    lw = np.asarray(coll.get_linewidths(), dtype=float).reshape(-1)
    lw = np.zeros(n) if len(lw) == 0 else (np.repeat(lw, n) if len(lw) != n else lw)
    return polys, fc, ec, lw


def _camera(ax: Any, renderer: Any, points: np.ndarray) -> Tuple[np.ndarray, float, float]:
    """limn's view-projection matrix for the axes at draw time: matplotlib's ``M``, then
    the axes' 2D data transform to display units, then to limn's clip coordinates; the
    depth rescaled so the content lies between limn's near and far planes."""
    M = np.asarray(ax.M, dtype=float)
    W, H = renderer.get_canvas_width_height()
    t = ax.transData
    o, x, y = t.transform(np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]))
    a, d = x - o  # d(display)/d(xp)
    b, e = y - o  # d(display)/d(yp)
    c, f = o
    m = np.empty((4, 4))
    m[0] = (2 * a / W) * M[0] + (2 * b / W) * M[1] + (2 * c / W - 1) * M[3]
    m[1] = (2 * d / H) * M[0] + (2 * e / H) * M[1] + (2 * f / H - 1) * M[3]
    hom = np.c_[points, np.ones(len(points))]
    z = (hom @ M[2]) / (hom @ M[3])
    zmin, zmax = float(np.min(z)), float(np.max(z))
    s = 1.8 / (zmax - zmin) if zmax > zmin else 1.0
    m[2] = s * M[2] + (-0.9 - s * zmin) * M[3]
    m[3] = M[3]
    return m, W, H


def _lines(artist: Any) -> List[np.ndarray]:
    """A ``Line3D``'s runs of finite points (matplotlib breaks lines at NaN)."""
    xyz = (np.asarray(np.ma.filled(c, np.nan), dtype=float) for c in artist.get_data_3d())
    return _runs(np.c_[tuple(a.ravel() for a in np.broadcast_arrays(*xyz))])


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


class _Line(NamedTuple):
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


class _Point(NamedTuple):
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


def _clip_of(artist: Any) -> Any:
    """The clip box matplotlib gives ``artist``'s drawing (``None`` when it is not
    clipped)."""
    return artist.get_clip_box() if artist.get_clip_on() else None


class _Lines:
    """The bridge's lines, points and texts: what limn gets, and how matplotlib draws
    each."""

    def __init__(self) -> None:
        self.lines: List[_Line] = []
        self.points: List[_Point] = []
        # Per limn label: the Text3D it shows.
        self.texts: List[Any] = []

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
                    self.lines.append(_Line(r, rgba, w, dash, clip=_clip_of(line)))
        ms = MarkerStyle(line.get_marker())
        if ms.get_marker() not in ("None", "none", " ", "", None):
            path = ms.get_path().transformed(ms.get_transform())
            scale = float(line.get_markersize()) * p2p
            fc = to_rgba(line.get_markerfacecolor(), line.get_alpha())
            ec = to_rgba(line.get_markeredgecolor(), line.get_alpha())
            for r in runs:
                for q in r:
                    ew = float(line.get_markeredgewidth())
                    self.points.append(_Point(q, fc, ec, ew, path, scale, _clip_of(line)))

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
            for r in _runs(np.asarray(seg, dtype=float).reshape(-1, 3)):
                if len(r) >= 2 and c[3] > 0 and w > 0:
                    clip = None if background else _clip_of(coll)
                    self.lines.append(_Line(r, c, w, dash, background, clip=clip))

    def add_pane_outline(self, pane: Pane) -> None:
        if pane.width > 0:
            loop = np.vstack([pane.corners, pane.corners[:1]])
            self.lines.append(_Line(loop, pane.edge, pane.width, None, True, "projecting"))

    def add_scatter(self, coll: Any, p2p: float, M: np.ndarray) -> None:
        from matplotlib.collections import PathCollection

        coll.update_scalarmappable()
        xs, ys, zs = (np.asarray(np.ma.filled(c, np.nan), dtype=float).ravel() for c in coll._offsets3d)
        pts = np.c_[xs, ys, zs]
        n = len(pts)
        # In input order: mplot3d's own getters return colours and widths sorted by
        # depth (and "face" edges through them).
        fc = np.asarray(PathCollection.get_facecolor(coll), dtype=float).reshape(-1, 4)
        face_edges = isinstance(coll._edgecolors, str) and coll._edgecolors == "face"
        ec = fc if face_edges else np.asarray(PathCollection.get_edgecolor(coll), dtype=float)
        ec = ec.reshape(-1, 4)
        shaded, min_alpha, alpha = scatter_depth_shading(coll)
        if shaded and n:
            fc = depth_shaded(np.broadcast_to(fc, (n, 4)) if len(fc) else fc, pts, M, min_alpha, alpha)
            ec = fc if face_edges else (
                depth_shaded(np.broadcast_to(ec, (n, 4)), pts, M, min_alpha, alpha) if len(ec) else ec
            )
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
                _Point(
                    pts[i],
                    tuple(pick(fc, i, (0, 0, 0, 0))),
                    tuple(pick(ec, i, (0, 0, 0, 0))),
                    float(pick(lw, i, 0.0)),
                    pick(paths, i, None),
                    np.sqrt(max(s, 0.0)) * p2p,
                    _clip_of(coll),
                )
            )

    def add_text(self, text: Any) -> None:
        """A ``Text3D`` (``ax.text``): shown where its anchor is visible."""
        if text.get_text() and np.isfinite(np.asarray(text.get_position_3d(), float)).all():
            self.texts.append(text)

    def vertices(self) -> List[np.ndarray]:
        anchors = [q.at for q in self.points] + [t.get_position_3d() for t in self.texts]
        return [ln.points for ln in self.lines] + [np.asarray(anchors, dtype=float).reshape(-1, 3)]


class _Item(NamedTuple):
    """One thing limn painted, ready for matplotlib to draw."""

    parts: Optional[List[np.ndarray]]
    """Convex parts covering where its drawing may put ink once widened by ``pad``, in
    display units (``None``: anywhere)."""
    pad: float
    background: bool
    """A pane, a grid line or a pane's outline."""
    draw: Callable[[Any], None]


def _segments(disp: np.ndarray) -> List[np.ndarray]:
    """A polyline's segments as convex parts."""
    return [disp[i : i + 2] for i in range(len(disp) - 1)]


class _Limn3D:
    """Draws one 3D axes' content through limn in two artists: one under everything else
    in the axes (the panes, the grid, what lies behind them, then matplotlib's axis lines,
    ticks and labels when the bridge draws them) and one in the place of the
    collections (the rest of the data)."""

    def __init__(
        self,
        ax: Any,
        colls: List[Any],
        marks: List[Any],
        texts: List[Any],
        sort: str,
        arith: str,
        draws_axes: bool,
        box: str,
    ) -> None:
        from matplotlib.artist import Artist

        class _Art(Artist):
            def __init__(inner, draw: Callable[[Any], None]) -> None:  # noqa: N805
                super().__init__()
                inner._draw = draw

            def draw(inner, renderer):  # noqa: N805
                inner._draw(renderer)

        self.ax, self.colls, self.marks, self.texts = ax, colls, marks, texts
        self.sort, self.arith, self.draws_axes, self.box = sort, arith, draws_axes, box
        self.back = _Art(self.draw_back)
        self.front = _Art(self.draw_front)
        lowest = min([a.get_zorder() for a in ax.get_children()] + [0.0])
        self.back.set_zorder(lowest - 1)
        self.front.set_zorder(max(axis.get_zorder() for axis in ax._axis_map.values()) + 1)
        self.later: List[_Item] = []
        self.box_in_limn = False
        self.seconds = 0.0

    def draw_back(self, renderer: Any) -> None:
        import time

        t0 = time.perf_counter()
        items = self._paint(renderer)
        if self.draws_axes and not self.box_in_limn:
            # mplot3d's own order: panes, grid, then axis lines, ticks and labels.
            axes = list(self.ax._axis_map.values())
            for axis in axes:
                type(axis).draw_pane(axis, renderer)
            for axis in axes:
                type(axis).draw_grid(axis, renderer)
            for axis in axes:
                type(axis).draw(axis, renderer)
            self.later = items
            self.seconds += time.perf_counter() - t0
            return
        under = under_axes(
            [it.parts for it in items],
            np.array([it.pad for it in items], dtype=float),
            np.array([it.background for it in items], dtype=bool),
        )
        for it, u in zip(items, under):
            if u:
                it.draw(renderer)
        if self.draws_axes:
            # Ticks, tick labels and axis labels; the axis lines are limn's.
            for axis in self.ax._axis_map.values():
                shown = axis.line.get_visible()
                axis.line.set_visible(False)
                try:
                    type(axis).draw(axis, renderer)
                finally:
                    axis.line.set_visible(shown)
        self.later = [it for it, u in zip(items, under) if not u]
        self.seconds += time.perf_counter() - t0

    def draw_front(self, renderer: Any) -> None:
        for it in self.later:
            it.draw(renderer)
        self.later = []

    def _paint(self, renderer: Any) -> List[_Item]:
        """The scene of the axes ordered by limn: its painted polygons and visible marks as
        items in paint order."""
        from mpl_toolkits.mplot3d.art3d import Line3DCollection, Path3DCollection

        p2p = float(renderer.points_to_pixels(1.0))
        M = np.asarray(self.ax.M, dtype=float)
        polys, fcs, ecs, lws, clips = [], [], [], [], []
        for coll in self.colls:
            p, fc, ec, lw = _polys(coll)
            clips += [_clip_of(coll)] * len(p)
            polys += p
            fcs.append(fc)
            ecs.append(ec)
            lws.append(lw)
        data = _Lines()
        for art in self.marks:
            if isinstance(art, Path3DCollection):
                data.add_scatter(art, p2p, M)
            elif isinstance(art, Line3DCollection):
                data.add_line_collection(art)
            else:
                data.add_line3d(art, p2p)
        for text in self.texts:
            data.add_text(text)
        # With every vertex, point and anchor inside the axes' box, the panes, the grid
        # and the axis lines lie behind all of them (or in their plane): mplot3d's own
        # drawing of the box, before the data, is then the exact picture, and the box
        # stays out of the scene.
        self.box_in_limn = self.draws_axes and (
            self.box == "limn"
            or self.box == "auto"
            and not inside_box(self.ax, np.concatenate([np.zeros((0, 3))] + polys + data.vertices()))
        )
        extra = _Lines()
        background = np.zeros(len(polys), bool)
        if self.box_in_limn:
            walls = panes(self.ax)
            filled = [w for w in walls if w.fill is not None]
            polys += [w.corners for w in filled]
            clips += [None] * len(filled)
            fcs.append(np.array([w.fill for w in filled]).reshape(-1, 4))
            ecs.append(np.zeros((len(filled), 4)))
            lws.append(np.zeros(len(filled)))
            background = np.r_[background, np.ones(len(filled), bool)]
            # In matplotlib's order: outlines of the panes, grid lines, axis lines.
            for w in walls:
                extra.add_pane_outline(w)
            for grid in grid_lines(self.ax):
                extra.add_line_collection(grid, background=True)
            for a in axis_lines(self.ax):
                extra.lines.append(_Line(a.ends, a.rgba, a.width, None, True, a.cap))
        extra.lines += data.lines
        extra.points, extra.texts = data.points, data.texts
        fc = np.concatenate(fcs) if fcs else np.zeros((0, 4))
        ec = np.concatenate(ecs) if ecs else np.zeros((0, 4))
        lw = np.concatenate(lws) if lws else np.zeros(0)
        # Polygons of 3 and 4 corners as they are; longer ones as fans (matplotlib's
        # polygons are convex in practice: quads of surfaces, bars, voxels).
        verts, tris, quads = [], [], []
        owner_t, owner_q = [], []
        base = 0
        for k, p in enumerate(polys):
            if len(p) < 3:
                continue
            verts.append(p)
            idx = base + np.arange(len(p))
            base += len(p)
            if len(p) == 4:
                quads.append(idx)
                owner_q.append(k)
            else:
                for j in range(1, len(p) - 1):
                    tris.append([idx[0], idx[j], idx[j + 1]])
                    owner_t.append(k)
        if not verts and not extra.lines and not extra.points and not extra.texts:
            return []
        v = np.concatenate(verts) if verts else np.zeros((0, 3))
        m, W, H = _camera(self.ax, renderer, np.concatenate([v] + extra.vertices()))
        wl, hl = max(1, int(round(W))), max(1, int(round(H)))
        scene = Scene()
        owner = []
        for faces, own in ((tris, owner_t), (quads, owner_q)):
            if faces:
                own = np.asarray(own)
                scene.add_mesh(v, np.asarray(faces), colors=np.clip(fc[own], 0, 1))
                owner += list(own)
        for ln in extra.lines:
            scene.add_line(ln.points, color=np.clip(ln.rgba, 0, 1))
        if extra.points:
            scene.add_points(np.asarray([q.at for q in extra.points]), size=1.0)
        for text in extra.texts:
            scene.add_label(tuple(float(c) for c in text.get_position_3d()), "x")
        scene.set_camera(matrix=m, size=(wl, hl))
        sx, sy = W / wl, H / hl
        polygons, marks = scene.paint_with_marks(sort=self.sort, arith=self.arith)
        disp_of = lambda pts: np.c_[pts[:, 0] * sx, H - pts[:, 1] * sy]  # noqa: E731
        # Markers and texts between the same two polygons are painted far to near, as
        # mplot3d paints a scatter (limn's picture keeps them in input order).
        anchors = [q.at for q in extra.points] + [t.get_position_3d() for t in extra.texts]
        depth = _depths(M, np.asarray(anchors, dtype=float).reshape(-1, 3))
        first_text = len(extra.points)
        by_place: dict = {}
        for mk in marks:
            by_place.setdefault(mk["before"], []).append(mk)
        for run in by_place.values():
            run.sort(key=partial(_paint_key, depth=depth, first_text=first_text))
        items: List[_Item] = []

        def add_marks(place: int) -> None:
            for mk in by_place.get(place, ()):
                if mk["kind"] == "line":
                    ln = extra.lines[mk["index"]]
                    disp = disp_of(mk["points"])
                    items.append(
                        _Item(
                            _segments(disp),
                            0.75 * ln.width * p2p,  # projecting caps included
                            ln.background,
                            partial(self._draw_line, line=ln, disp=disp, mk=mk, p2p=p2p),
                        )
                    )
                elif mk["kind"] == "marker" and mk["index"] is not None:
                    x, y = mk["at"]
                    pt = extra.points[mk["index"]]
                    xy = (x * sx, H - y * sy)
                    reach = _marker_reach(pt.path) * pt.scale + pt.edge_width * p2p
                    items.append(
                        _Item(
                            [np.array([xy])],
                            reach,
                            False,
                            partial(self._draw_marker, point=pt, xy=xy),
                        )
                    )
                elif mk["kind"] == "label" and mk["index"] is not None:
                    text = extra.texts[mk["index"]]
                    items.append(_Item(None, 0.0, False, partial(_draw_text, text=text)))

        for i, (face, pts, fill, orig) in enumerate(polygons):
            add_marks(i)
            k = owner[face]
            disp = disp_of(pts)
            edged = lw[k] > 0 and ec[k][3] > 0 and any(orig)
            pad = 0.5 * lw[k] * p2p if edged else 0.0
            items.append(
                _Item(
                    [disp],
                    pad,
                    bool(background[k]) if k < len(background) else False,
                    partial(
                        _draw_polygon,
                        disp=disp,
                        fill=tuple(fill),
                        edges=orig if edged else None,
                        edge=tuple(ec[k]),
                        width=float(lw[k]),
                        clip=clips[k],
                    ),
                )
            )
        add_marks(len(polygons))
        return items

    @staticmethod
    def _draw_line(renderer: Any, line: _Line, disp: np.ndarray, mk: dict, p2p: float) -> None:
        """One visible piece of a line in its matplotlib style (width and dashes in
        points; the dash pattern continues from where the piece starts on the line)."""
        from matplotlib.path import Path
        from matplotlib.transforms import IdentityTransform

        gc = renderer.new_gc()
        gc.set_clip_rectangle(line.clip)
        gc.set_foreground(tuple(line.rgba), isRGBA=True)
        gc.set_linewidth(line.width)
        gc.set_capstyle(line.cap)
        gc.set_joinstyle("round")
        if line.dash is not None and line.dash[1]:
            off = (line.dash[0] or 0.0) + mk["dash_offset"] / p2p
            gc.set_dashes(off, list(line.dash[1]))
        renderer.draw_path(gc, Path(disp), IdentityTransform())
        gc.restore()

    @staticmethod
    def _draw_marker(renderer: Any, point: _Point, xy: Tuple[float, float]) -> None:
        """One visible scatter point or line marker: matplotlib's marker path, size and
        colours at its projected anchor."""
        from matplotlib.transforms import Affine2D

        path = _marker_path(point.path)
        gc = renderer.new_gc()
        gc.set_clip_rectangle(point.clip)
        gc.set_foreground(tuple(point.edge), isRGBA=True)
        gc.set_linewidth(point.edge_width if point.edge[3] > 0 else 0)
        t = Affine2D().scale(point.scale).translate(*xy)
        face = point.face
        renderer.draw_path(gc, path, t, tuple(face) if face[3] > 0 else None)
        gc.restore()


def _depths(M: np.ndarray, xyz: np.ndarray) -> np.ndarray:
    """mplot3d's depth of each point (the third projected coordinate; larger is
    farther)."""
    hom = np.c_[xyz, np.ones(len(xyz))] @ M.T
    return hom[:, 2] / hom[:, 3]


def _paint_key(mk: dict, depth: np.ndarray, first_text: int) -> Tuple[int, float]:
    """Order of the marks painted between the same two polygons: line pieces and heads
    first (in limn's order), then markers far to near, then texts far to near."""
    kind, index = mk["kind"], mk["index"]
    if kind == "marker" and index is not None:
        return (1, -float(depth[index]))
    if kind == "label" and index is not None:
        return (2, -float(depth[first_text + index]))
    return (0, 0.0)


def _marker_path(path: Any) -> Any:
    from matplotlib.markers import MarkerStyle

    return MarkerStyle("o").get_path() if path is None else path


def _marker_reach(path: Any) -> float:
    """How far a marker's path reaches from its anchor, in units of its scale."""
    vs = np.asarray(_marker_path(path).vertices, dtype=float)
    return float(np.abs(vs).max()) if vs.size else 0.0


def _draw_polygon(
    renderer: Any, disp: np.ndarray, fill: tuple, edges: Any, edge: tuple, width: float, clip: Any
) -> None:
    """A painted polygon: its fill, then its original edges in the face's edge colour
    and width (points)."""
    from matplotlib.path import Path
    from matplotlib.transforms import IdentityTransform

    gc = renderer.new_gc()
    gc.set_clip_rectangle(clip)
    gc.set_linewidth(0)
    gc.set_foreground((0, 0, 0, 0), isRGBA=True)
    path = Path(np.vstack([disp, disp[:1]]), closed=True)
    renderer.draw_path(gc, path, IdentityTransform(), fill)
    gc.restore()
    if edges is not None:
        n = len(disp)
        segs = [(disp[i], disp[(i + 1) % n]) for i in range(n) if edges[i]]
        codes = [Path.MOVETO, Path.LINETO] * len(segs)
        gc = renderer.new_gc()
        gc.set_clip_rectangle(clip)
        gc.set_foreground(edge, isRGBA=True)
        gc.set_linewidth(renderer.points_to_pixels(width))
        gc.set_capstyle("round")
        renderer.draw_path(gc, Path(np.array([q for s in segs for q in s]), codes), IdentityTransform())
        gc.restore()


def _draw_text(renderer: Any, text: Any) -> None:
    """A visible ``Text3D`` drawn by matplotlib itself (its font, size, colour,
    alignment and direction)."""
    text.set_visible(True)
    try:
        type(text).draw(text, renderer)
    finally:
        text.set_visible(False)


def savefig(
    fig: Any,
    path: Any,
    *,
    sort: str = "adaptive",
    arith: str = "exact",
    box: str = "auto",
    **kwargs: Any,
) -> None:
    """Save ``fig`` like ``fig.savefig(path, **kwargs)``, with the content of every 3D
    axes ordered exactly by limn (see the module docs): its polygon collections, lines,
    scatter points, 3D texts, panes, grid lines and axis lines. Figures without 3D axes
    are saved unchanged. ``sort`` and ``arith`` choose limn's ordering (adaptive and
    exact by default).

    ``box`` says who draws an axes' panes, grid lines and axis lines: ``"auto"`` (the
    default, exact) leaves them to matplotlib when every vertex, point and text anchor
    lies inside the axes' box (they are then behind all the data, and matplotlib's
    drawing is the exact picture) and makes them limn scene content when something
    leaves the box; ``"limn"`` always makes them scene content; ``"matplotlib"`` always
    leaves them to matplotlib, which is faster but wrong where data leave the box (a
    surface behind a pane is drawn over it).

    Raises what ``fig.savefig`` raises, and ValueError for geometry limn refuses (such
    as NaN vertices) or an unknown ``box``; nothing is written then."""
    from mpl_toolkits.mplot3d.art3d import (
        Line3D,
        Line3DCollection,
        Path3DCollection,
        Poly3DCollection,
        Text3D,
    )

    if box not in ("auto", "limn", "matplotlib"):
        raise ValueError(f"box must be 'auto', 'limn' or 'matplotlib', not {box!r}")
    swaps = []
    taken = []  # axes whose panes, grid and axis drawing the bridge does
    # Colorbars rasterise their colour solids on their own (50 colours or more); here
    # they stay vectors, so that the file holds no raster.
    rasterized = [
        cb.solids
        for cb in (getattr(ax, "_colorbar", None) for ax in fig.axes)
        if cb is not None and cb.solids is not None and cb.solids.get_rasterized()
    ]
    if not any(_is_3d(ax) for ax in fig.axes):
        rasterized = []
    try:
        for solids in rasterized:
            solids.set_rasterized(False)
        for ax in fig.axes:
            if not _is_3d(ax):
                continue
            colls = [
                c for c in ax.collections if isinstance(c, Poly3DCollection) and c.get_visible()
            ]
            marks = [
                c
                for c in ax.collections
                if isinstance(c, (Line3DCollection, Path3DCollection)) and c.get_visible()
            ] + [ln for ln in ax.lines if isinstance(ln, Line3D) and ln.get_visible()]
            texts = [t for t in ax.texts if isinstance(t, Text3D) and t.get_visible()]
            if not colls and not marks and not texts:
                continue
            draws_axes = bool(getattr(ax, "_axis3don", False)) and box != "matplotlib"
            for c in colls + marks + texts:
                c.set_visible(False)
            if draws_axes:
                # mplot3d draws panes, grid and axes before the axes' children; the
                # bridge's first artist draws them instead, in limn's order.
                for axis in ax._axis_map.values():
                    for name in ("draw_pane", "draw_grid", "draw"):
                        setattr(axis, name, _draw_nothing)
                taken.append(ax)
            bridge = _Limn3D(ax, colls, marks, texts, sort, arith, draws_axes, box)
            ax.add_artist(bridge.back)
            ax.add_artist(bridge.front)
            swaps.append((colls + marks + texts, bridge))
        _save_whole(fig, path, kwargs)
    finally:
        for solids in rasterized:
            solids.set_rasterized(True)
        for ax in taken:
            for axis in ax._axis_map.values():
                for name in ("draw_pane", "draw_grid", "draw"):
                    vars(axis).pop(name, None)
        for colls, bridge in swaps:
            bridge.back.remove()
            bridge.front.remove()
            for c in colls:
                c.set_visible(True)


def _save_whole(fig: Any, path: Any, kwargs: dict) -> None:
    """``fig.savefig(path, **kwargs)``, with a file name written whole or not at all: the
    figure is saved into memory first (a drawing that fails leaves no partial file), then
    written to a new file in the target's folder and renamed over the target. The format
    comes from ``format`` or the extension, as ``fig.savefig`` takes it (the canvas's
    default format, appended to a name without extension). File objects are passed to
    ``fig.savefig`` as they are."""
    if not isinstance(path, (str, os.PathLike)):
        fig.savefig(path, **kwargs)
        return
    target = os.fspath(path)
    kwargs = dict(kwargs)
    fmt = kwargs.pop("format", None)
    if fmt is None:
        fmt = os.path.splitext(target)[1][1:]
        if not fmt:
            fmt = fig.canvas.get_default_filetype()
            target = target.rstrip(".") + "." + fmt
    folder, name = os.path.split(os.path.abspath(target))
    if not os.path.isdir(folder):
        raise FileNotFoundError(f"cannot write {target}: no folder {folder}")
    buf = io.BytesIO()
    fig.savefig(buf, format=fmt, **kwargs)
    tmp = os.path.join(folder, f".{name}.{secrets.token_hex(6)}.part")
    try:
        with open(tmp, "xb") as f:
            f.write(buf.getvalue())
        os.replace(tmp, target)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def _draw_nothing(*_: Any, **__: Any) -> None:
    """Stands in for an axis' own drawing while the bridge draws it."""
