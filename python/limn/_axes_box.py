"""A 3D axes' box as scene content: its panes, grid lines and axis lines, where they are in
the axes' scaled coordinates (data coordinates through the axis scales) and how
matplotlib styles them.

mplot3d draws three panes (the walls of the axes' box on the far side from the viewer),
on them the grid lines at the major ticks, then the axis lines along the box's edges,
all before the data. The bridge puts them into the limn scene instead, so a surface
poking out of the box is cut by the pane exactly, a grid line passes behind a surface
exactly, and an axis line is hidden where data lie in front of it. Ticks, tick labels
and axis labels stay matplotlib's 2D drawing.
"""

from __future__ import annotations

from typing import Any, List, NamedTuple, Optional

import numpy as np


class Pane(NamedTuple):
    """One pane: its corners in scaled coordinates and its matplotlib style."""

    corners: np.ndarray
    """(4, 3): the rectangle on the face of the axes' box."""
    fill: Optional[np.ndarray]
    """RGBA of its face, ``None`` when the pane is not filled (``pane.fill = False``)."""
    edge: np.ndarray
    """RGBA of its outline."""
    width: float
    """Width of its outline in points (0 draws none)."""


def _box_corners(ax: Any) -> np.ndarray:
    """The eight corners of the axes' box in scaled coordinates (each axis' bounds through
    its scale transform, as ``_get_coord_info`` places panes and axis lines), numbered as
    mplot3d numbers them (x fastest around the bottom face, then the top face)."""
    (x0, x1), (y0, y1), (z0, z1) = (
        sorted(float(v) for v in axis.get_transform().transform(np.asarray(bound, float)))
        for axis, bound in (
            (ax.xaxis, ax.get_xbound()),
            (ax.yaxis, ax.get_ybound()),
            (ax.zaxis, ax.get_zbound()),
        )
    )
    return np.array(
        [
            (x0, y0, z0),
            (x1, y0, z0),
            (x1, y1, z0),
            (x0, y1, z0),
            (x0, y0, z1),
            (x1, y0, z1),
            (x1, y1, z1),
            (x0, y1, z1),
        ],
        dtype=float,
    )


_BEHIND = 1e-6
"""How far (of the box's size along each axis) the box's panes, grid and axis lines are
moved out of the box in the scene."""


def behind(ax: Any, points: np.ndarray) -> np.ndarray:
    """Points of the box's drawing (N, 3, scaled coordinates) moved outward by a
    millionth of the box's size along each axis where they lie on a face of the box:
    mplot3d draws the box under the data, so data lying on a pane (a filled contour set
    at ``offset`` on the axes' limit, a patch on a wall) stay in front of that pane and
    of its grid in limn's order, as they are in matplotlib's."""
    pts = np.array(points, dtype=float).reshape(-1, 3)
    corners = _box_corners(ax)
    lo, hi = corners[0], corners[6]
    step = _BEHIND * (hi - lo)
    pts = np.where(pts <= lo, pts - step, pts)
    return np.where(pts >= hi, pts + step, pts)


def inside_box(ax: Any, points: np.ndarray) -> bool:
    """Whether every finite point of ``points`` (N, 3, scaled coordinates) lies in the
    axes' closed box (exact comparisons with the axes' scaled bounds)."""
    pts = np.asarray(points, dtype=float).reshape(-1, 3)
    pts = pts[np.isfinite(pts).all(axis=1)]
    corners = _box_corners(ax)
    return bool(((pts >= corners[0]) & (pts <= corners[6])).all())


def panes(ax: Any) -> List[Pane]:
    """The panes matplotlib would draw for the 3D axes ``ax`` (none when its axes are off;
    a pane that is hidden, or neither filled nor outlined, is left out). Each is the
    face of the box mplot3d chooses for it (``Axis.active_pane``: the far one of the two
    parallel faces)."""
    from matplotlib.colors import to_rgba

    if not getattr(ax, "_axis3don", True):
        return []
    corners = _box_corners(ax)
    out = []
    for axis in ax._axis_map.values():
        pane = axis.pane
        if not pane.get_visible():
            continue
        i = axis._axinfo["i"]
        _, _, _, highs = axis._get_coord_info()
        plane = axis._PLANES[2 * i + (1 if highs[i] else 0)]
        fill = np.array(to_rgba(pane.get_facecolor())) if pane.get_fill() else None
        if fill is not None and fill[3] <= 0:
            fill = None
        edge = np.array(to_rgba(pane.get_edgecolor()))
        width = float(pane.get_linewidth()) if edge[3] > 0 else 0.0
        if fill is None and width <= 0:
            continue
        out.append(Pane(behind(ax, corners[list(plane)]), fill, edge, width))
    return out


def grid_lines(ax: Any) -> List[Any]:
    """The axes' grid lines as ``Line3DCollection``s with their segments, colours, widths
    and styles up to date (mplot3d's own ``Axis.draw_grid`` computes them, with its
    drawing switched off); empty when the grid or the axes are off."""
    from matplotlib.backend_bases import RendererBase

    if not getattr(ax, "_axis3don", True) or not getattr(ax, "_draw_grid", True):
        return []
    out = []
    for axis in ax._axis_map.values():
        lines = axis.gridlines
        was = lines.get_visible()
        lines.set_visible(False)
        lines.set_segments([])  # no ticks, no grid: nothing left from an earlier draw
        try:
            type(axis).draw_grid(axis, RendererBase())
        finally:
            lines.set_visible(was)
        if was and len(lines._segments3d):
            out.append(lines)
    return out


class AxisLine(NamedTuple):
    """One axis line: its ends in scaled coordinates and its style."""

    ends: np.ndarray
    """(2, 3): two corners of the axes' box."""
    rgba: np.ndarray
    width: float
    """In points."""
    cap: str
    """matplotlib's cap style of the line (``projecting`` by default)."""


def axis_lines(ax: Any) -> List[AxisLine]:
    """The axis lines matplotlib would draw for the 3D axes ``ax``, at the box edges
    mplot3d chooses for them (``Axis._get_all_axis_line_edge_points``, one per tick
    position: two when ticks are on both sides); none when the axes are off."""
    from matplotlib.colors import to_rgba

    if not getattr(ax, "_axis3don", True):
        return []
    out = []
    for axis in ax._axis_map.values():
        line = axis.line
        if not line.get_visible():
            continue
        mins, maxs, _, highs = axis._get_coord_info()
        minmax = np.where(highs, maxs, mins)
        maxmin = np.where(~highs, maxs, mins)
        rgba = np.array(to_rgba(line.get_color(), line.get_alpha()))
        width = float(line.get_linewidth())
        if rgba[3] <= 0 or width <= 0:
            continue
        p1s, p2s, _ = axis._get_all_axis_line_edge_points(minmax, maxmin, axis._tick_position)
        for p1, p2 in zip(p1s, p2s):
            ends = behind(ax, np.array([p1, p2], dtype=float))
            out.append(AxisLine(ends, rgba, width, str(line.get_solid_capstyle())))
    return out
