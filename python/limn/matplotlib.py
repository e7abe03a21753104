"""The matplotlib bridge: ``savefig`` with every 3D axes' surfaces ordered exactly by limn.

matplotlib's mplot3d sorts whole polygons by one depth each, so intersecting surfaces
and cyclic overlaps come out wrong in its own export. ``savefig`` draws each 3D axes'
``Poly3DCollection`` content (plot_surface, plot_trisurf, bar3d, voxels,
add_collection3d), its filled patches (``ax.bar``, ``PathPatch3D``: circles, glyphs) and
its filled contour sets (``contourf``, ``tricontourf``, with ``zdir`` and ``offset``)
through limn instead: the same polygons (a non-planar one as the triangles of the
outline matplotlib fills, see ``_triangulate``; a filled path as the regions matplotlib
fills, see ``_regions``), the face colours after colormapping, alpha, edge colours and line
widths, seen through the axes' own projection (``get_proj()``: perspective with its
focal length, or orthographic), so the picture registers with the axes, ticks, labels,
titles and colorbars matplotlib draws around it. limn's polygons are drawn through
matplotlib's renderer at the place the collections would take, so the 3D content is
vector drawing in the file of the format the extension names (SVG, PDF, ...). Everything
else is matplotlib's own drawing, unchanged: 2D axes, titles, legends and colorbars
(whose colour solids of 50 colours or more matplotlib embeds as one image, as in its own
export).

Lines (``Line3D`` from ``plot``, ``Line3DCollection`` from ``plot_wireframe`` and
``quiver``, the contour lines of ``ax.contour``) and scatter points
(``Path3DCollection``) go into the same limn scene as the polygons, so they are hidden
exactly by the surfaces in front of them (a line on a surface's own polygon is drawn
over it); their visible pieces and markers are drawn by matplotlib's renderer in
matplotlib's own style (colour, width, dashes, marker path, size), at their place in
limn's paint order, markers far to near as mplot3d paints them. Scatter points keep
mplot3d's depth shading (``depthshade``; see ``_depth_shading``). 3D texts (``Text3D``
from ``ax.text``) are limn labels: shown only where their anchor is visible, drawn by
matplotlib itself.

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
artist it comes from, and the file is written whole or not at all.

Axis scales (``set_zscale("log")``, ``"symlog"``, ...) are applied as mplot3d applies
them: limn gets every coordinate through its axis' scale transform, so a log axis' data
are straight in log space; a point outside a scale's domain is left out, as is a point
outside the view limits of an artist drawn with ``axlim_clip=True`` (see ``_content``).
The private mplot3d attributes read are those of matplotlib 3.11.
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
from ._axes_box import axis_lines, grid_lines, inside_box, panes
from ._content import Line, Marks, Point, Polygons
from ._drawing import (
    draw_line,
    draw_marker,
    draw_markers,
    draw_polygon,
    draw_polygons,
    draw_text,
    marker_reach,
    same_marker_run,
)
from ._layers import under_axes

__all__ = ["savefig"]


def _is_3d(ax: Any) -> bool:
    return getattr(ax, "name", "") == "3d"


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


class _Item(NamedTuple):
    """One thing limn painted, ready for matplotlib to draw."""

    parts: Optional[List[np.ndarray]]
    """Convex parts covering where its drawing may put ink once widened by ``pad``, in
    display units (``None``: anywhere)."""
    pad: float
    background: bool
    """Part of the axes' box: a pane, its outline, a grid line or an axis line."""
    draw: Callable[[Any], None]
    marker: Optional[Tuple[Point, Tuple[float, float]]] = None
    """A marker's point and display anchor (drawn with the markers next to it)."""


def _draw_items(renderer: Any, items: List[_Item]) -> None:
    """Draws ``items`` in order; a run of markers that can share a path collection
    (``same_marker_run``) is drawn as one, as matplotlib draws a scatter."""
    i = 0
    while i < len(items):
        it = items[i]
        if it.marker is None:
            it.draw(renderer)
            i += 1
            continue
        j = i + 1
        while (
            j < len(items)
            and items[j].marker is not None
            and same_marker_run(it.marker[0], items[j].marker[0])
        ):
            j += 1
        run = [items[k].marker for k in range(i, j)]
        draw_markers(renderer, [m[0] for m in run], [m[1] for m in run])
        i = j


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

    def draw_back(self, renderer: Any) -> None:
        if _measuring(renderer):
            # matplotlib's measuring pass (``bbox_inches="tight"``) draws nothing: the
            # axes update their state as mplot3d's own drawing would, limn is not run.
            self.later = []
            if self.draws_axes:
                for axis in self.ax._axis_map.values():
                    type(axis).draw(axis, renderer)
            return
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
            return
        under = under_axes(
            [it.parts for it in items],
            np.array([it.pad for it in items], dtype=float),
            np.array([it.background for it in items], dtype=bool),
        )
        _draw_items(renderer, [it for it, u in zip(items, under) if u])
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

    def draw_front(self, renderer: Any) -> None:
        _draw_items(renderer, self.later)
        self.later = []

    def _content(self, p2p: float, M: np.ndarray) -> Tuple[Polygons, Marks]:
        """The axes' polygons and marks, with its box when that goes into the scene
        (first, in matplotlib's order: panes, their outlines, grid lines, axis lines)."""
        from mpl_toolkits.mplot3d.art3d import (
            Line3DCollection,
            Patch3D,
            Path3DCollection,
            PathPatch3D,
        )

        polys = Polygons()
        for coll in self.colls:
            if isinstance(coll, PathPatch3D):
                polys.add_path_patch(coll)
            elif isinstance(coll, Patch3D):
                polys.add_patch(coll)
            elif _is_contour_fill(coll):
                polys.add_contour_fill(coll)
            else:
                polys.add_collection(coll)
        data = Marks()
        for art in self.marks:
            if isinstance(art, Path3DCollection):
                data.add_scatter(art, p2p, M)
            elif isinstance(art, Line3DCollection):
                data.add_line_collection(art)
            elif _is_contour_lines(art):
                data.add_contour_lines(art)
            else:
                data.add_line3d(art, p2p)
        for text in self.texts:
            data.add_text(text)
        # With every vertex, point and anchor inside the axes' box, the panes, the grid
        # and the axis lines lie behind all of them (or in their plane): mplot3d's own
        # drawing of the box, before the data, is then the exact picture, and the box
        # stays out of the scene.
        everything = np.concatenate([np.zeros((0, 3))] + polys.corners + data.vertices())
        self.box_in_limn = self.draws_axes and (
            self.box == "limn" or self.box == "auto" and not inside_box(self.ax, everything)
        )
        marks = Marks()
        if self.box_in_limn:
            walls = panes(self.ax)
            for w in walls:
                if w.fill is not None:
                    polys.add_pane(w)
            for w in walls:
                marks.add_pane_outline(w)
            for grid in grid_lines(self.ax):
                marks.add_line_collection(grid, background=True)
            for a in axis_lines(self.ax):
                marks.lines.append(Line(a.ends, a.rgba, a.width, None, True, a.cap))
        marks.lines += data.lines
        marks.points, marks.texts, marks.anchors = data.points, data.texts, data.anchors
        return polys, marks

    def _paint(self, renderer: Any) -> List[_Item]:
        """The scene of the axes ordered by limn: its painted polygons and visible marks as
        items in paint order."""
        p2p = float(renderer.points_to_pixels(1.0))
        M = np.asarray(self.ax.M, dtype=float)
        polys, extra = self._content(p2p, M)
        fc, ec, lw = polys.styles()
        corners = [p for p in polys.corners if len(p) >= 3]
        if not corners and not extra.lines and not extra.points and not extra.texts:
            return []
        m, W, H = _camera(self.ax, renderer, np.concatenate(corners + extra.vertices()))
        v, faces, counts, owner, own = polys.mesh(partial(_project, m=m))
        wl, hl = max(1, int(round(W))), max(1, int(round(H)))
        scene = Scene()
        if len(counts):
            scene.add_mesh(v, faces, counts=counts, colors=np.clip(fc[owner], 0, 1))
        for ln in extra.lines:
            scene.add_line(ln.points, color=np.clip(ln.rgba, 0, 1))
        if extra.points:
            scene.add_points(np.asarray([q.at for q in extra.points]), size=1.0)
        for at in extra.anchors:
            scene.add_label(tuple(float(c) for c in at), "x")
        scene.set_camera(matrix=m, size=(wl, hl))
        sx, sy = W / wl, H / hl
        # Fragments of unstroked faces of one tiling (a polygon's triangles, the faces
        # filling one region) painted one after another come joined: the outline of
        # their union, not one subpath per piece.
        stroked = (lw > 0) & (ec[:, 3] > 0) if len(lw) else np.zeros(0, dtype=bool)
        tiling = np.asarray(polys.tiling, dtype=np.int64)
        join = (
            np.where(stroked[owner], -1, tiling[owner]) if len(owner) else np.zeros(0, np.int64)
        )
        # Per face: whether every edge of it is its polygon's own (one reduction).
        if len(own):
            firsts = np.cumsum([0] + [len(o) for o in own[:-1]])
            own_all = np.logical_and.reduceat(np.concatenate(own).astype(bool), firsts)
        else:
            own_all = np.zeros(0, dtype=bool)
        # Faces whose every edge matplotlib strokes, opaque and at least a seam flap wide
        # (one of limn's pixels), right after the fill (a surface edged in its own
        # colour): the stroke covers the seam, so those edges get no flap.
        covering = stroked & (ec[:, 3] >= 1) & (lw * p2p >= max(sx, sy))
        closed = covering[owner] & own_all if len(owner) else np.zeros(0, dtype=bool)
        polygons, marks = scene.paint_with_marks(
            sort=self.sort, arith=self.arith, join=join, stroked=closed
        )
        disp_of = lambda pts: np.c_[pts[:, 0] * sx, H - pts[:, 1] * sy]  # noqa: E731
        # Markers and texts between the same two polygons are painted far to near, as
        # mplot3d paints a scatter (limn's picture keeps them in input order).
        anchors = [q.at for q in extra.points] + extra.anchors
        depth = _depths(M, np.asarray(anchors, dtype=float).reshape(-1, 3))
        first_text = len(extra.points)
        by_place: dict = {}
        for mk in marks:
            by_place.setdefault(mk["before"], []).append(mk)
        for run in by_place.values():
            run.sort(key=partial(_paint_key, depth=depth, first_text=first_text))
        items: List[_Item] = []

        # Fragments painted one after another in the same paint, drawn as one path
        # (see ``_Run``).
        run: List[_Run] = []

        def flush() -> None:
            if run:
                items.append(run.pop().item())

        def add_marks(place: int) -> None:
            if place in by_place:
                flush()
            for mk in by_place.get(place, ()):
                if mk["kind"] == "line":
                    ln = extra.lines[mk["index"]]
                    disp = disp_of(mk["points"])
                    items.append(
                        _Item(
                            _segments(disp),
                            0.75 * ln.width * p2p,  # projecting caps included
                            ln.background,
                            partial(draw_line, line=ln, disp=disp, mk=mk, p2p=p2p),
                        )
                    )
                elif mk["kind"] == "marker" and mk["index"] is not None:
                    x, y = mk["at"]
                    pt = extra.points[mk["index"]]
                    xy = (x * sx, H - y * sy)
                    reach = marker_reach(pt.path) * pt.scale + pt.edge_width * p2p
                    items.append(
                        _Item(
                            [np.array([xy])],
                            reach,
                            False,
                            partial(draw_marker, point=pt, xy=xy),
                            (pt, xy),
                        )
                    )
                elif mk["kind"] == "label" and mk["index"] is not None:
                    text = extra.texts[mk["index"]]
                    items.append(_Item(None, 0.0, False, partial(draw_text, text=text)))

        first = np.concatenate([[0], np.cumsum(counts)])
        seen = _project(v, m)  # the faces' corners in limn's normalised coordinates
        # Every fragment's points in display units at once (a joined entry's rings one
        # after another).
        joined = [isinstance(p[1], list) for p in polygons]
        ends = np.cumsum(
            [0] + [sum(map(len, p[1])) if j else len(p[1]) for p, j in zip(polygons, joined)]
        )
        every = [r for p, j in zip(polygons, joined) for r in (p[1] if j else (p[1],))]
        pts_all = np.concatenate(every) if every else np.zeros((0, 2))
        disp_all = np.column_stack([pts_all[:, 0] * sx, H - pts_all[:, 1] * sy])
        lead, skip = _whole_runs(polygons, owner, by_place, fc, ec, lw, len(polys.corners))
        # Which edges of the fragments of triangles of polygons cut in the view lie on
        # the polygon's own edges, all at once.
        cut = [
            i
            for i, (face, _, _, orig) in enumerate(polygons)
            if not skip[i]
            and lead[i] < 0
            and stroked[owner[face]]
            and any(orig)
            and not own_all[face]
        ]
        own_edges = _polygon_edges(
            [disp_all[ends[i] : ends[i + 1]] for i in cut],
            [polygons[i][3] for i in cut],
            [polygons[i][0] for i in cut],
            seen,
            first,
            own,
            W,
            H,
        )
        own_edges_of = dict(zip(cut, own_edges))
        # The polygons drawn whole, projected at once.
        wholes = sorted({int(owner[polygons[i][0]]) for i in np.nonzero(lead >= 0)[0]})
        whole_disp = {}
        if wholes:
            c = _project(np.concatenate([polys.corners[k] for k in wholes]), m)
            d = np.column_stack([(c[:, 0] + 1) / 2 * wl * sx, H - (1 - c[:, 1]) / 2 * hl * sy])
            cuts = np.cumsum([len(polys.corners[k]) for k in wholes])[:-1]
            whole_disp = dict(zip(wholes, np.split(d, cuts)))
        # Per polygon: what a run of its fragments must share besides the fill.
        style_of: dict = {}
        for i, (face, pts, fill, orig) in enumerate(polygons):
            add_marks(i)
            k = int(owner[face])
            if skip[i]:
                continue
            if lead[i] >= 0:
                flush()
                # Every fragment of this polygon, one after another: the polygon itself.
                disp = whole_disp[k]
                parts = [disp_all[ends[j] : ends[j + 1]] for j in range(i, lead[i] + 1)]
                edged = lw[k] > 0 and ec[k][3] > 0
                items.append(
                    _Item(
                        parts,
                        0.5 * lw[k] * p2p if edged else 0.0,
                        polys.background[k],
                        partial(
                            draw_polygon,
                            disp=disp,
                            fill=tuple(fill),
                            edges=_outline(disp) if edged else None,
                            edge=tuple(ec[k]),
                            width=float(lw[k]),
                            clip=polys.clip[k],
                            whole=edged,
                        ),
                    )
                )
                continue
            disp = disp_all[ends[i] : ends[i + 1]]
            edged = lw[k] > 0 and ec[k][3] > 0 and any(orig)
            if edged and i in own_edges_of:
                # A triangle of a polygon cut in the view: only the polygon's own edges.
                orig = own_edges_of[i]
                edged = any(orig)
            edges, whole = None, False
            if edged:
                flags = np.asarray(orig, dtype=bool)
                whole = bool(flags.all())
                if whole:
                    edges = _outline(disp)
                else:
                    j = np.nonzero(flags)[0]
                    edges = np.empty((len(j), 2, 2))
                    edges[:, 0], edges[:, 1] = disp[j], disp[(j + 1) % len(disp)]
            # Only fragments of one tiling join (of one polygon, or of the faces filling
            # one path): they do not overlap (a translucent one is not blended twice),
            # an edge keeps its place between the fills of other polygons, and the
            # outlines limn joins with their seam flaps overlap only where flaps of one
            # tiling meet.
            style = style_of.get(k)
            if style is None:
                style = (polys.tiling[k], polys.background[k], tuple(ec[k]), float(lw[k]))
                style_of[k] = style
            key = (tuple(fill), *style)
            if run and (run[0].key != key or run[0].clip is not polys.clip[k]):
                flush()
            if not run:
                run.append(_Run(key, polys.clip[k], 0.5 * lw[k] * p2p))
            if joined[i]:
                rings, at, parts = polygons[i][1], 0, []
                for r in rings:
                    parts.append(disp[at : at + len(r)])
                    at += len(r)
                run[0].add(parts, edges, edged, whole)
            else:
                run[0].add([disp], edges, edged, whole)
        flush()
        add_marks(len(polygons))
        return items


class _Run:
    """Fragments painted one after another with the same fill, edge style, clip and layer,
    drawn as one item: one path when there are several (no seam shows between them in a
    viewer, and a figure of thousands of triangles of a few polygons is a few paths).
    Each fragment is a list of rings: one, or the outlines and holes of a joined run."""

    def __init__(self, key: tuple, clip: Any, pad: float) -> None:
        self.key, self.clip, self.pad = key, clip, pad
        self.groups: List[List[np.ndarray]] = []
        self.edges: List[np.ndarray] = []
        self.edged = False
        self.whole = False

    def add(self, rings: List[np.ndarray], edges: Any, edged: bool, whole: bool) -> None:
        self.groups.append(rings)
        if edges is not None:
            self.edges.append(edges)
        self.edged |= edged
        self.whole = whole

    def item(self) -> _Item:
        fill, _, background, edge, width = self.key
        pad = self.pad if self.edged else 0.0
        parts = [r for g in self.groups for r in g]
        if len(parts) == 1:
            draw = partial(
                draw_polygon,
                disp=parts[0],
                fill=fill,
                edges=self.edges[0] if self.edges else None,
                edge=edge,
                width=width,
                clip=self.clip,
                whole=self.whole,
            )
        else:
            draw = partial(
                draw_polygons,
                groups=self.groups,
                fill=fill,
                edges=np.concatenate(self.edges) if self.edges else None,
                edge=edge,
                width=width,
                clip=self.clip,
            )
        return _Item(parts, pad, background, draw)


def _outline(disp: np.ndarray) -> np.ndarray:
    """A polygon's edges as segments (n, 2, 2)."""
    edges = np.empty((len(disp), 2, 2))
    edges[:, 0] = disp
    edges[:, 1, :][:-1] = disp[1:]
    edges[-1, 1] = disp[0]
    return edges


def _whole_runs(
    polygons: list,
    owner: np.ndarray,
    marks_at: dict,
    fc: np.ndarray,
    ec: np.ndarray,
    lw: np.ndarray,
    n_polys: int,
) -> Tuple[np.ndarray, np.ndarray]:
    """Polygons to draw whole, as matplotlib draws them, in place of their fragments: the
    fragments of a polygon (the triangles it was cut into, limn's pieces of a face and
    its cover) painted one after another with nothing else in between fill exactly the
    polygon's outline there. Only for polygons whose seams limn's flaps need not close:
    translucent ones (limn gives them no flaps) and those whose every edge is stroked
    (the stroke covers the seams).

    Returns per fragment the index of the last fragment of its polygon's run where it
    leads one (-1 elsewhere), and whether it is drawn by such a lead."""
    n = len(polygons)
    lead = np.full(n, -1)
    skip = np.zeros(n, dtype=bool)
    if n == 0:
        return lead, skip
    face = np.fromiter((p[0] for p in polygons), dtype=np.int64, count=n)
    fo = owner[face]
    idx = np.arange(n)
    lo = np.full(n_polys, n)
    hi = np.full(n_polys, -1)
    np.minimum.at(lo, fo, idx)
    np.maximum.at(hi, fo, idx)
    count = np.bincount(fo, minlength=n_polys)
    faces_all = np.bincount(owner, minlength=n_polys)
    faces_seen = np.bincount(owner[np.unique(face)], minlength=n_polys)
    places = np.array(sorted(p for p in marks_at if 0 < p < n), dtype=np.int64)
    inner = np.searchsorted(places, hi, side="right") - np.searchsorted(places, lo, side="right")
    alpha = np.clip(fc[:, 3], 0, 1) if len(fc) else np.zeros(0)
    stroked = (lw > 0) & (ec[:, 3] > 0)
    ok = (
        (count > 1)
        & (hi - lo + 1 == count)
        & (inner == 0)
        & (faces_seen == faces_all)
        & ((alpha < 1) | stroked)
    )
    for k in np.nonzero(ok)[0]:
        lead[lo[k]] = hi[k]
        skip[lo[k] + 1 : hi[k] + 1] = True
    return lead, skip


def _project(p: np.ndarray, m: np.ndarray) -> np.ndarray:
    """Points (k, 3) through limn's camera matrix to its normalised 2D coordinates (x and
    y in [-1, 1] across the canvas, y up), NaN where w <= 0."""
    h = np.c_[np.asarray(p, dtype=float).reshape(-1, 3), np.ones(len(p))] @ m.T
    out = np.full((len(h), 2), np.nan)
    ok = h[:, 3] > 0
    out[ok] = h[ok, :2] / h[ok, 3:]
    return out


def _polygon_edges(
    disps: List[np.ndarray],
    origs: List[Any],
    faces: List[int],
    seen: np.ndarray,
    first: np.ndarray,
    own: List[np.ndarray],
    W: float,
    H: float,
) -> List[List[bool]]:
    """Per painted fragment (corners ``disps[i]`` in display units, its original edges
    ``origs[i]``, of face ``faces[i]``), which of its edges lie on an edge of its polygon:
    each edge limn marks original lies on one of the face's edges (face corners ``seen``
    in limn's normalised coordinates, those of face ``f`` from ``first[f]`` on), the one
    nearest to its midpoint, which is the polygon's own where ``own[f]`` says so.
    Fragments of faces of the same corner count are taken together."""
    out: List[List[bool]] = [[] for _ in disps]
    groups: dict = {}
    for i, f in enumerate(faces):
        groups.setdefault(int(first[f + 1] - first[f]), []).append(i)
    for n, members in groups.items():
        fs = np.array([faces[i] for i in members], dtype=np.int64)
        c = (seen[first[fs][:, None] + np.arange(n)] + 1) / 2 * np.array([W, H])  # (m, n, 2)
        d = np.roll(c, -1, axis=1) - c
        length = np.maximum(np.hypot(d[..., 0], d[..., 1]), 1e-300)
        owns = np.array([np.asarray(own[f], dtype=bool) for f in fs]).reshape(len(fs), n)
        pts = np.concatenate([disps[i] for i in members])
        lens = np.array([len(disps[i]) for i in members])
        starts = np.cumsum(lens) - lens
        member = np.repeat(np.arange(len(members)), lens)
        local = np.arange(len(pts)) - starts[member]
        after = starts[member] + (local + 1) % lens[member]
        flags = np.concatenate(
            [np.resize(np.asarray(origs[i], dtype=bool), len(disps[i])) for i in members]
        )
        j = np.nonzero(flags)[0]
        g = member[j]
        q = (pts[j] + pts[after[j]]) / 2
        a, dd = c[g], d[g]
        dist = np.abs(dd[..., 0] * (q[:, None, 1] - a[..., 1]) - dd[..., 1] * (q[:, None, 0] - a[..., 0]))
        res = np.zeros(len(pts), dtype=bool)
        res[j] = owns[g, np.argmin(dist / length[g], axis=1)]
        for m, i in enumerate(members):
            out[i] = res[starts[m] : starts[m] + lens[m]].tolist()
    return out


def _is_polygon_patch(art: Any) -> bool:
    """Whether ``art`` is a filled 3D patch: a polygon (``ax.bar`` in a 3D axes,
    ``patch_2d_to_3d``) or a path of any outlines and curves (``PathPatch3D`` from
    ``pathpatch_2d_to_3d``: a circle, a text's glyphs). Unfilled patches stay
    matplotlib's drawing."""
    from mpl_toolkits.mplot3d.art3d import Patch3D

    return (
        isinstance(art, Patch3D)
        and art.get_fill()
        and len(getattr(art, "_segment3d", ())) >= 3
    )


def _is_contour_set(art: Any, filled: bool) -> bool:
    from matplotlib.contour import ContourSet
    from mpl_toolkits.mplot3d.art3d import Collection3D

    return (
        isinstance(art, Collection3D)
        and isinstance(art, ContourSet)
        and bool(art.filled) == filled
        and hasattr(art, "_3dverts_codes")
    )


def _is_contour_lines(art: Any) -> bool:
    """Whether ``art`` is a 3D axes' contour set of lines (``ax.contour``)."""
    return _is_contour_set(art, filled=False)


def _is_contour_fill(art: Any) -> bool:
    """Whether ``art`` is a 3D axes' filled contour set (``ax.contourf``,
    ``ax.tricontourf``, with or without ``zdir``/``offset``)."""
    return _is_contour_set(art, filled=True)


def _measuring(renderer: Any) -> bool:
    """Whether ``renderer`` is in matplotlib's measuring pass (``_draw_disabled``: its
    drawing methods replaced by no-ops on the instance, or on the vector renderer inside
    a mixed-mode renderer)."""
    inner = getattr(renderer, "_renderer", None)
    return any("draw_path" in getattr(r, "__dict__", {}) for r in (renderer, inner))


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
    try:
        for ax in fig.axes:
            if not _is_3d(ax):
                continue
            colls = [
                c
                for c in ax.collections
                if (isinstance(c, Poly3DCollection) or _is_contour_fill(c)) and c.get_visible()
            ] + [p for p in ax.patches if _is_polygon_patch(p) and p.get_visible()]
            marks = [
                c
                for c in ax.collections
                if (isinstance(c, (Line3DCollection, Path3DCollection)) or _is_contour_lines(c))
                and c.get_visible()
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
