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

Lines (``Line3D`` from ``plot``, ``Line3DCollection`` from ``plot_wireframe``) and
scatter points (``Path3DCollection``) go into the same limn scene as the polygons, so
they are hidden exactly by the surfaces in front of them (a line on a surface's own
polygon is drawn over it); their visible pieces and markers are drawn by matplotlib's
renderer in matplotlib's own style (colour, width, dashes, marker path, size), at their
place in limn's paint order. Scatter points are drawn in their colours without
matplotlib's depth shading (limn decides what is in front).

The axes' panes and grid lines stay matplotlib's own, drawn first (behind the data) as
matplotlib draws them. Scales must be linear.
"""

from __future__ import annotations

from typing import Any, List, Tuple

import numpy as np

from . import Scene

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


class _Lines:
    """The bridge's lines and points: what limn gets, and how matplotlib draws each."""

    def __init__(self) -> None:
        # Per limn line: (points, rgba, width in points, dash (offset, seq) in points).
        self.lines: List[Tuple[np.ndarray, np.ndarray, float, Any]] = []
        # Per limn point: (position, face rgba, edge rgba, edge width, path, scale).
        self.points: List[Tuple[np.ndarray, Any, Any, float, Any, float]] = []

    def add_line3d(self, line: Any, p2p: float) -> None:
        from matplotlib.colors import to_rgba
        from matplotlib.markers import MarkerStyle

        rgba = np.array(to_rgba(line.get_color(), line.get_alpha()))
        dash = line._dash_pattern if line.get_linestyle() not in ("-", "solid") else None
        runs = _lines(line)
        if line.get_linestyle() not in ("None", "none", " ", ""):
            for r in runs:
                if len(r) >= 2:
                    self.lines.append((r, rgba, float(line.get_linewidth()), dash))
        ms = MarkerStyle(line.get_marker())
        if ms.get_marker() not in ("None", "none", " ", "", None):
            path = ms.get_path().transformed(ms.get_transform())
            scale = float(line.get_markersize()) * p2p
            fc = to_rgba(line.get_markerfacecolor(), line.get_alpha())
            ec = to_rgba(line.get_markeredgecolor(), line.get_alpha())
            for r in runs:
                for q in r:
                    self.points.append((q, fc, ec, float(line.get_markeredgewidth()), path, scale))

    def add_line_collection(self, coll: Any) -> None:
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
                if len(r) >= 2:
                    self.lines.append((r, c, w, dash))

    def add_scatter(self, coll: Any, p2p: float) -> None:
        from matplotlib.collections import PathCollection

        coll.update_scalarmappable()
        xs, ys, zs = (np.asarray(np.ma.filled(c, np.nan), dtype=float).ravel() for c in coll._offsets3d)
        pts = np.c_[xs, ys, zs]
        n = len(pts)
        fc = np.asarray(PathCollection.get_facecolor(coll), dtype=float).reshape(-1, 4)
        # In input order: mplot3d's own getters return colours and widths sorted by
        # depth (and "face" edges through them).
        if isinstance(coll._edgecolors, str) and coll._edgecolors == "face":
            ec = fc
        else:
            ec = np.asarray(PathCollection.get_edgecolor(coll), dtype=float).reshape(-1, 4)
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
                (
                    pts[i],
                    tuple(pick(fc, i, (0, 0, 0, 0))),
                    tuple(pick(ec, i, (0, 0, 0, 0))),
                    float(pick(lw, i, 0.0)),
                    pick(paths, i, None),
                    np.sqrt(max(s, 0.0)) * p2p,
                )
            )

    def vertices(self) -> List[np.ndarray]:
        return [r for r, *_ in self.lines] + [np.asarray([q[0] for q in self.points]).reshape(-1, 3)]


class _Limn3D:
    """Draws one 3D axes' polygon collections, lines and scatter points through limn, in
    the collections' place."""

    def __init__(
        self, ax: Any, colls: List[Any], marks: List[Any], sort: str, arith: str
    ) -> None:
        from matplotlib.artist import Artist

        class _Art(Artist):
            def draw(inner, renderer):  # noqa: N805
                self.draw(renderer)

        self.ax, self.colls, self.sort, self.arith = ax, colls, sort, arith
        self.marks = marks
        self.artist = _Art()
        zorder = max(axis.get_zorder() for axis in ax._axis_map.values()) + 1
        self.artist.set_zorder(zorder)
        self.seconds = 0.0

    def draw(self, renderer: Any) -> None:
        import time

        from matplotlib.path import Path
        from matplotlib.transforms import IdentityTransform

        t0 = time.perf_counter()
        from mpl_toolkits.mplot3d.art3d import Line3DCollection, Path3DCollection

        p2p = float(renderer.points_to_pixels(1.0))
        polys, fcs, ecs, lws = [], [], [], []
        for coll in self.colls:
            p, fc, ec, lw = _polys(coll)
            polys += p
            fcs.append(fc)
            ecs.append(ec)
            lws.append(lw)
        extra = _Lines()
        for art in self.marks:
            if isinstance(art, Path3DCollection):
                extra.add_scatter(art, p2p)
            elif isinstance(art, Line3DCollection):
                extra.add_line_collection(art)
            else:
                extra.add_line3d(art, p2p)
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
        if not verts and not extra.lines and not extra.points:
            return
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
        for pts, rgba, _, _ in extra.lines:
            scene.add_line(pts, color=np.clip(rgba, 0, 1))
        if extra.points:
            scene.add_points(np.asarray([q[0] for q in extra.points]), size=1.0)
        scene.set_camera(matrix=m, size=(wl, hl))
        sx, sy = W / wl, H / hl
        polygons, marks = scene.paint_with_marks(sort=self.sort, arith=self.arith)
        disp_of = lambda pts: np.c_[pts[:, 0] * sx, H - pts[:, 1] * sy]  # noqa: E731
        by_place: dict = {}
        for mk in marks:
            by_place.setdefault(mk["before"], []).append(mk)

        def draw_marks(place: int) -> None:
            for mk in by_place.get(place, ()):
                if mk["kind"] == "line":
                    self._draw_line(renderer, extra.lines[mk["index"]], disp_of(mk["points"]), mk, p2p)
                elif mk["kind"] == "marker" and mk["index"] is not None:
                    x, y = mk["at"]
                    self._draw_marker(renderer, extra.points[mk["index"]], (x * sx, H - y * sy), p2p)

        for i, (face, pts, fill, orig) in enumerate(polygons):
            draw_marks(i)
            k = owner[face]
            disp = disp_of(pts)
            gc = renderer.new_gc()
            gc.set_linewidth(0)
            gc.set_foreground((0, 0, 0, 0), isRGBA=True)
            path = Path(np.vstack([disp, disp[:1]]), closed=True)
            renderer.draw_path(gc, path, IdentityTransform(), tuple(fill))
            gc.restore()
            if lw[k] > 0 and ec[k][3] > 0 and any(orig):
                segs = [(disp[i], disp[(i + 1) % len(disp)]) for i in range(len(disp)) if orig[i]]
                codes = [Path.MOVETO, Path.LINETO] * len(segs)
                gc = renderer.new_gc()
                gc.set_foreground(tuple(ec[k]), isRGBA=True)
                gc.set_linewidth(renderer.points_to_pixels(lw[k]))
                gc.set_capstyle("round")
                renderer.draw_path(
                    gc, Path(np.array([q for s in segs for q in s]), codes), IdentityTransform()
                )
                gc.restore()
        draw_marks(len(polygons))
        self.seconds += time.perf_counter() - t0

    @staticmethod
    def _draw_line(renderer: Any, line: Any, disp: np.ndarray, mk: dict, p2p: float) -> None:
        """One visible piece of a line in its matplotlib style (width and dashes in
        points; the dash pattern continues from where the piece starts on the line)."""
        from matplotlib.path import Path
        from matplotlib.transforms import IdentityTransform

        _, rgba, width, dash = line
        gc = renderer.new_gc()
        gc.set_foreground(tuple(rgba), isRGBA=True)
        gc.set_linewidth(width)
        gc.set_capstyle("butt")
        gc.set_joinstyle("round")
        if dash is not None and dash[1]:
            off = (dash[0] or 0.0) + mk["dash_offset"] / p2p
            gc.set_dashes(off, list(dash[1]))
        renderer.draw_path(gc, Path(disp), IdentityTransform())
        gc.restore()

    @staticmethod
    def _draw_marker(renderer: Any, point: Any, xy: Tuple[float, float], p2p: float) -> None:
        """One visible scatter point or line marker: matplotlib's marker path, size and
        colours at its projected anchor."""
        from matplotlib.markers import MarkerStyle
        from matplotlib.transforms import Affine2D

        _, face, edge, ew, path, scale = point
        if path is None:
            path = MarkerStyle("o").get_path()
        gc = renderer.new_gc()
        gc.set_foreground(tuple(edge), isRGBA=True)
        gc.set_linewidth(ew if edge[3] > 0 else 0)
        t = Affine2D().scale(scale).translate(*xy)
        renderer.draw_path(gc, path, t, tuple(face) if face[3] > 0 else None)
        gc.restore()


def savefig(fig: Any, path: Any, *, sort: str = "adaptive", arith: str = "exact", **kwargs: Any) -> None:
    """Save ``fig`` like ``fig.savefig(path, **kwargs)``, with the polygons of every 3D
    axes ordered exactly by limn (see the module docs). Figures without 3D axes are saved
    unchanged. ``sort`` and ``arith`` choose limn's ordering (adaptive and exact by
    default). Raises what ``fig.savefig`` raises, and ValueError for geometry limn
    refuses (such as NaN vertices)."""
    from mpl_toolkits.mplot3d.art3d import (
        Line3D,
        Line3DCollection,
        Path3DCollection,
        Poly3DCollection,
    )

    swaps = []
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
            if not colls and not marks:
                continue
            for c in colls + marks:
                c.set_visible(False)
            bridge = _Limn3D(ax, colls, marks, sort, arith)
            ax.add_artist(bridge.artist)
            swaps.append((colls + marks, bridge))
        fig.savefig(path, **kwargs)
    finally:
        for solids in rasterized:
            solids.set_rasterized(True)
        for colls, bridge in swaps:
            bridge.artist.remove()
            for c in colls:
                c.set_visible(True)
