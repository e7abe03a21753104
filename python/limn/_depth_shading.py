"""Scatter colours faded by depth, as matplotlib's mplot3d fades them (``depthshade``).

mplot3d draws a scatter with ``depthshade=True`` (its default) with each point's alpha
scaled by its depth: the nearest point keeps its alpha, deeper ones fade linearly over
the scatter's extent down to ``depthshade_minalpha``. The bridge draws each visible
point itself, so it computes the same alphas here, in the input order of the points.
"""

from __future__ import annotations

from typing import Any, Optional

import numpy as np


def depth_shaded(
    rgba: np.ndarray, xyz: np.ndarray, M: np.ndarray, min_alpha: float, alpha: Optional[float]
) -> np.ndarray:
    """``rgba`` (N, 4) or one colour (1, 4) for the points ``xyz`` (N, 3), with the alpha
    mplot3d gives each point when the axes project through ``M``: (N, 4), or (0, 4) when
    ``rgba`` is empty.

    Mirrors matplotlib 3.11's ``mpl_toolkits.mplot3d.art3d._zalpha`` with the scale of
    ``art3d._get_data_scale`` and the alpha handling of
    ``Path3DCollection._maybe_depth_shade_and_sort_colors``:

    - the depth of a point is the third coordinate of its projection by ``M`` (after the
      division by w), larger is farther;
    - the scale is the length of the diagonal of the projected points' bounding box
      (x, y and depth ranges), over the finite points only;
    - the factor is ``1 - (depth - nearest depth) / scale`` clipped to
      ``[min_alpha, 1]`` (1 for every point when the scale is 0), and it multiplies the
      colour's alpha;
    - when the collection has its own ``alpha``, mplot3d multiplies the result by it once
      more (the colours already carry it), and so does this function.

    Points that are not finite keep their colour (they are not drawn).
    """
    rgba = np.array(rgba, dtype=float).reshape(-1, 4)
    xyz = np.asarray(xyz, dtype=float).reshape(-1, 3)
    ok = np.isfinite(xyz).all(axis=1)
    if len(rgba) == 0 or not ok.any():
        return rgba  # no colours ("none"): nothing to shade
    rgba = np.array(np.broadcast_to(rgba, (len(xyz), 4)))
    hom = np.c_[xyz[ok], np.ones(int(ok.sum()))] @ np.asarray(M, dtype=float).T
    proj = hom[:, :3] / hom[:, 3:4]
    scale = float(np.sqrt((np.ptp(proj, axis=0) ** 2).sum()))
    m = float(np.clip(min_alpha, 0.0, 1.0))
    factor = np.ones(len(xyz))
    if scale != 0 and np.isfinite(scale):
        depth = proj[:, 2]
        factor[ok] = np.clip(1.0 - (depth - depth.min()) / scale, m, 1.0)
    rgba[:, 3] *= factor
    if alpha is not None:
        rgba[:, 3] *= float(alpha)
    return rgba


def scatter_depth_shading(coll: Any) -> tuple:
    """Whether the scatter ``coll`` is depth shaded, with its minimum alpha and its own
    alpha (``(False, 1.0, None)`` for versions without depth shading)."""
    on = bool(getattr(coll, "_depthshade", False))
    return on, float(getattr(coll, "_depthshade_minalpha", 0.3)), getattr(coll, "_alpha", None)
