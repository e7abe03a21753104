"""Drawing what limn painted through matplotlib's renderer: polygons, line pieces,
markers and texts in the style of the artists they come from, in display units."""

from __future__ import annotations

from typing import Any, List, Tuple

import numpy as np

from ._content import Line, Point


def draw_line(renderer: Any, line: Line, disp: np.ndarray, mk: dict, p2p: float) -> None:
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


def draw_marker(renderer: Any, point: Point, xy: Tuple[float, float]) -> None:
    """One visible scatter point or line marker: matplotlib's marker path, size and
    colours at its projected anchor."""
    from matplotlib.transforms import Affine2D

    path = marker_path(point.path)
    gc = renderer.new_gc()
    gc.set_clip_rectangle(point.clip)
    gc.set_foreground(tuple(point.edge), isRGBA=True)
    gc.set_linewidth(point.edge_width if point.edge[3] > 0 else 0)
    t = Affine2D().scale(point.scale).translate(*xy)
    face = point.face
    renderer.draw_path(gc, path, t, tuple(face) if face[3] > 0 else None)
    gc.restore()


def same_marker_run(a: Point, b: Point) -> bool:
    """Whether markers ``a`` and ``b`` can be drawn in one collection: the same path
    and clip, fills both shown or both not, edges both shown or both not."""
    return (
        a.path is b.path
        and a.clip is b.clip
        and (a.face[3] > 0) == (b.face[3] > 0)
        and (a.edge[3] > 0) == (b.edge[3] > 0)
    )


def draw_markers(renderer: Any, points: List[Point], xys: List[Tuple[float, float]]) -> None:
    """A run of visible markers painted one after another (``same_marker_run`` holds for
    each with the first), drawn as matplotlib draws a scatter: one path collection, so
    the backend may write the marker's path once and place it at every anchor (SVG
    ``<use>``, a PDF form). Each marker keeps its own size, colours and edge width."""
    from matplotlib.transforms import Affine2D, IdentityTransform

    if len(points) == 1:
        draw_marker(renderer, points[0], xys[0])
        return
    first = points[0]
    scales = np.array([p.scale for p in points], dtype=float)
    if (scales == scales[0]).all():
        transforms = Affine2D().scale(scales[0]).get_matrix()[None]
    else:
        transforms = np.array([Affine2D().scale(s).get_matrix() for s in scales])
    faces = np.array([p.face for p in points], dtype=float) if first.face[3] > 0 else []
    shown = first.edge[3] > 0
    edges = np.array([p.edge for p in points], dtype=float) if shown else []
    widths = [p.edge_width if shown else 0.0 for p in points]
    gc = renderer.new_gc()
    gc.set_clip_rectangle(first.clip)
    renderer.draw_path_collection(
        gc,
        IdentityTransform(),
        [marker_path(first.path)],
        transforms,
        np.asarray(xys, dtype=float),
        IdentityTransform(),
        faces,
        edges,
        widths,
        [(0, None)],
        [True],
        [None],
        "screen",
    )
    gc.restore()


def marker_path(path: Any) -> Any:
    from matplotlib.markers import MarkerStyle

    return MarkerStyle("o").get_path() if path is None else path


def marker_reach(path: Any) -> float:
    """How far a marker's path reaches from its anchor, in units of its scale."""
    vs = np.asarray(marker_path(path).vertices, dtype=float)
    return float(np.abs(vs).max()) if vs.size else 0.0


_CODES: dict = {}


def _closed_codes(n: int) -> np.ndarray:
    """Path codes of a closed outline of n corners (MOVETO, LINETO..., CLOSEPOLY)."""
    c = _CODES.get(n)
    if c is None:
        from matplotlib.path import Path

        c = np.full(n + 1, Path.LINETO, dtype=Path.code_type)
        c[0], c[-1] = Path.MOVETO, Path.CLOSEPOLY
        c.flags.writeable = False
        _CODES[n] = c
    return c


def draw_polygon(
    renderer: Any,
    disp: np.ndarray,
    fill: tuple,
    edges: Any,
    edge: tuple,
    width: float,
    clip: Any,
    whole: bool = False,
) -> None:
    """A painted polygon (display units): its fill, then the edge segments ``edges``
    ((s, 2, 2) display units, or ``None``) in the edge colour and width (points);
    ``whole``: the segments are all of its edges, drawn with the fill as its outline in
    one path, as matplotlib draws a polygon (round joins where segments have round
    caps)."""
    from matplotlib.path import Path
    from matplotlib.transforms import IdentityTransform

    path = Path(np.concatenate([disp, disp[:1]]), _closed_codes(len(disp)))
    gc = renderer.new_gc()
    gc.set_clip_rectangle(clip)
    if whole and edges is not None and len(edges) == len(disp):
        gc.set_foreground(edge, isRGBA=True)
        gc.set_linewidth(renderer.points_to_pixels(width))
        gc.set_joinstyle("round")
        renderer.draw_path(gc, path, IdentityTransform(), fill)
        gc.restore()
        return
    _fill_then_stroke(renderer, gc, path, fill, edges, edge, width, clip)


def draw_polygons(
    renderer: Any,
    groups: List[List[np.ndarray]],
    fill: tuple,
    edges: Any,
    edge: tuple,
    width: float,
    clip: Any,
) -> None:
    """Fragments painted one after another in one fill (display units), each a group of
    rings (a polygon, or the outlines and holes of joined pieces, holes turned against
    their outlines), as one path: each group turned so that its rings' signed areas sum
    to a positive area, so that the nonzero rule fills every point any group fills
    (viewers anti-alias a path as a whole: no seam shows between them). Then the edge
    segments ``edges`` ((s, 2, 2) display units, or ``None``) in the edge colour and
    width (points), in one path."""
    from matplotlib.path import Path

    disps = [r for g in groups for r in g]
    lens = np.fromiter((len(d) for d in disps), dtype=np.intp, count=len(disps))
    group_of = np.repeat(np.arange(len(groups)), [len(g) for g in groups])
    pts = np.concatenate(disps)
    starts = np.cumsum(lens) - lens
    # Each ring's corner after each corner, and twice each group's signed area.
    local = np.arange(len(pts)) - np.repeat(starts, lens)
    after = np.where(local + 1 == np.repeat(lens, lens), 0, local + 1) + np.repeat(starts, lens)
    cross = pts[:, 0] * pts[after, 1] - pts[after, 0] * pts[:, 1]
    area = np.bincount(group_of, weights=np.add.reduceat(cross, starts), minlength=len(groups))
    backwards = np.repeat((area < 0)[group_of], lens)
    # Corners of a group turning the other way taken in reverse, then each ring closed.
    order = np.repeat(starts, lens) + np.where(backwards, np.repeat(lens, lens) - 1 - local, local)
    closed = np.insert(order, starts + lens, order[starts])
    codes = np.full(len(closed), Path.LINETO, dtype=Path.code_type)
    first = starts + np.arange(len(lens))
    codes[first] = Path.MOVETO
    codes[first + lens] = Path.CLOSEPOLY
    path = Path(pts[closed], codes)
    gc = renderer.new_gc()
    gc.set_clip_rectangle(clip)
    _fill_then_stroke(renderer, gc, path, fill, edges, edge, width, clip)


def _fill_then_stroke(
    renderer: Any, gc: Any, path: Any, fill: tuple, edges: Any, edge: tuple, width: float, clip: Any
) -> None:
    """Fills ``path`` with ``gc`` (no stroke), then strokes the segments ``edges``
    ((s, 2, 2) display units, or ``None``) in the edge colour and width (points), in one
    path with round caps."""
    from matplotlib.path import Path
    from matplotlib.transforms import IdentityTransform

    gc.set_linewidth(0)
    gc.set_foreground((0, 0, 0, 0), isRGBA=True)
    renderer.draw_path(gc, path, IdentityTransform(), fill)
    gc.restore()
    if edges is not None and len(edges):
        codes = np.tile(np.array([Path.MOVETO, Path.LINETO], dtype=Path.code_type), len(edges))
        gc = renderer.new_gc()
        gc.set_clip_rectangle(clip)
        gc.set_foreground(edge, isRGBA=True)
        gc.set_linewidth(renderer.points_to_pixels(width))
        gc.set_capstyle("round")
        renderer.draw_path(gc, Path(edges.reshape(-1, 2), codes), IdentityTransform())
        gc.restore()


def draw_text(renderer: Any, text: Any) -> None:
    """A visible ``Text3D`` drawn by matplotlib itself (its font, size, colour,
    alignment and direction)."""
    text.set_visible(True)
    try:
        type(text).draw(text, renderer)
    finally:
        text.set_visible(False)
