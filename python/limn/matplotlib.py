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

The axes' panes and grid lines stay matplotlib's own, drawn first (behind the data) as
matplotlib draws them. Scales must be linear. Line3D, Line3DCollection and scatter
points are left to matplotlib.
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


class _Limn3D:
    """Draws one 3D axes' polygon collections through limn, in the collections' place."""

    def __init__(self, ax: Any, colls: List[Any], sort: str, arith: str) -> None:
        from matplotlib.artist import Artist

        class _Art(Artist):
            def draw(inner, renderer):  # noqa: N805
                self.draw(renderer)

        self.ax, self.colls, self.sort, self.arith = ax, colls, sort, arith
        self.artist = _Art()
        zorder = max(axis.get_zorder() for axis in ax._axis_map.values()) + 1
        self.artist.set_zorder(zorder)
        self.seconds = 0.0

    def draw(self, renderer: Any) -> None:
        import time

        from matplotlib.path import Path
        from matplotlib.transforms import IdentityTransform

        t0 = time.perf_counter()
        polys, fcs, ecs, lws = [], [], [], []
        for coll in self.colls:
            p, fc, ec, lw = _polys(coll)
            polys += p
            fcs.append(fc)
            ecs.append(ec)
            lws.append(lw)
        if not polys:
            return
        fc, ec, lw = np.concatenate(fcs), np.concatenate(ecs), np.concatenate(lws)
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
        if not verts:
            return
        v = np.concatenate(verts)
        m, W, H = _camera(self.ax, renderer, v)
        wl, hl = max(1, int(round(W))), max(1, int(round(H)))
        scene = Scene()
        owner = []
        for faces, own in ((tris, owner_t), (quads, owner_q)):
            if faces:
                own = np.asarray(own)
                scene.add_mesh(v, np.asarray(faces), colors=np.clip(fc[own], 0, 1))
                owner += list(own)
        scene.set_camera(matrix=m, size=(wl, hl))
        sx, sy = W / wl, H / hl
        for face, pts, fill, orig in scene.paint(sort=self.sort, arith=self.arith):
            k = owner[face]
            disp = np.c_[pts[:, 0] * sx, H - pts[:, 1] * sy]
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
        self.seconds += time.perf_counter() - t0


def savefig(fig: Any, path: Any, *, sort: str = "adaptive", arith: str = "exact", **kwargs: Any) -> None:
    """Save ``fig`` like ``fig.savefig(path, **kwargs)``, with the polygons of every 3D
    axes ordered exactly by limn (see the module docs). Figures without 3D axes are saved
    unchanged. ``sort`` and ``arith`` choose limn's ordering (adaptive and exact by
    default). Raises what ``fig.savefig`` raises, and ValueError for geometry limn
    refuses (such as NaN vertices)."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

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
            if not colls:
                continue
            for c in colls:
                c.set_visible(False)
            bridge = _Limn3D(ax, colls, sort, arith)
            ax.add_artist(bridge.artist)
            swaps.append((colls, bridge))
        fig.savefig(path, **kwargs)
    finally:
        for solids in rasterized:
            solids.set_rasterized(True)
        for colls, bridge in swaps:
            bridge.artist.remove()
            for c in colls:
                c.set_visible(True)
