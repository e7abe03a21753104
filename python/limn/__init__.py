"""limn: 3D polygon scenes drawn as vector pictures with hidden surfaces removed exactly.

>>> import numpy as np, limn
>>> v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], float)
>>> stats = limn.render_mesh(v, [[0, 1, 2]], "tri.svg")   # doctest: +SKIP

``render_mesh`` draws one mesh; ``Scene`` holds several meshes, lights and a camera
(perspective, orthographic, or a 4x4 view-projection matrix); ``limn.matplotlib.savefig``
writes a matplotlib figure whose 3D axes are ordered exactly by limn.
"""

from __future__ import annotations

from typing import Any, Dict, Optional, Sequence, Tuple

import numpy as np

from . import _limn

__all__ = ["render_mesh", "Scene", "__version__"]
__version__ = _limn.__version__


def _vertices(vertices: Any) -> np.ndarray:
    # Copies only when the dtype or layout requires it.
    v = np.ascontiguousarray(vertices, dtype=np.float64)
    if v.ndim != 2 or v.shape[1] != 3:
        raise ValueError(f"vertices must have shape (N, 3), not {v.shape}")
    return v


def _faces(faces: Any) -> np.ndarray:
    f = np.asarray(faces)
    if f.ndim != 2 or f.shape[1] not in (3, 4):
        raise ValueError(f"faces must have shape (M, 3) or (M, 4), not {f.shape}")
    if f.size and not np.issubdtype(f.dtype, np.integer):
        raise ValueError(f"faces must hold integers, not {f.dtype}")
    return np.ascontiguousarray(f, dtype=np.int64)


def _colors(colors: Any) -> Optional[np.ndarray]:
    if colors is None:
        return None
    c = np.ascontiguousarray(colors, dtype=np.float64)
    if c.ndim != 2 or c.shape[1] not in (3, 4):
        raise ValueError(f"colors must have shape (M, 3) or (M, 4), not {c.shape}")
    return c


def render_mesh(
    vertices: Any,
    faces: Any,
    path: Any,
    *,
    colors: Any = None,
    opacity: Optional[float] = None,
    eye: Optional[Sequence[float]] = None,
    target: Optional[Sequence[float]] = None,
    up: Sequence[float] = (0, 1, 0),
    fov: float = 45.0,
    size: Tuple[int, int] = (800, 600),
    sort: str = "adaptive",
    arith: str = "exact",
    format: Optional[str] = None,
) -> Dict[str, Any]:
    """Render one mesh to ``path`` and return the statistics ``limn --stats`` prints.

    vertices: ``(N, 3)`` floats. faces: ``(M, 3)`` or ``(M, 4)`` vertex indices.
    colors: per face ``(M, 3)`` or ``(M, 4)`` in 0..1, drawn exactly (unlit); without
    colours faces are grey, lit by a headlight. opacity: 0..1 for the whole mesh.
    eye, target, up, fov: the camera; without ``eye`` the scene is framed as the
    command frames it (from the right, above and in front). size: (width, height) in
    pixels. sort: adaptive, bsp, newell or simple. arith: exact or float. format: svg,
    pdf, eps, png or tikz (default: from the extension).

    Raises ValueError for wrong shapes, NaN, indices out of range and bad options;
    OSError when the file cannot be written. Nothing is written on error.
    """
    t = lambda x: None if x is None else tuple(float(c) for c in x)  # noqa: E731
    return _limn.render_mesh(
        _vertices(vertices),
        _faces(faces),
        str(path),
        colors=_colors(colors),
        opacity=opacity,
        eye=t(eye),
        target=t(target),
        up=t(up),
        fov=float(fov),
        size=(int(size[0]), int(size[1])),
        sort=sort,
        arith=arith,
        format=format,
    )


class Scene:
    """Several meshes, lights and a camera.

    >>> s = limn.Scene()                                   # doctest: +SKIP
    >>> s.add_mesh(v, f, colors=c)                         # doctest: +SKIP
    >>> s.set_camera(eye=(3, 2, 5), projection="orthographic")   # doctest: +SKIP
    >>> s.render("fig.pdf"); s.check(against="raycast")    # doctest: +SKIP
    """

    def __init__(self) -> None:
        self._s = _limn.Scene()

    @property
    def face_count(self) -> int:
        """Number of faces added so far."""
        return self._s.face_count

    def add_mesh(
        self,
        vertices: Any,
        faces: Any,
        *,
        colors: Any = None,
        opacity: Optional[float] = None,
        name: str = "mesh",
    ) -> int:
        """Add a mesh (arguments as in ``render_mesh``); return the id of its first face.

        Faces are numbered in the order they are added, over all meshes.
        """
        return self._s.add_mesh(
            _vertices(vertices), _faces(faces), colors=_colors(colors), opacity=opacity, name=name
        )

    def add_light(
        self,
        kind: str,
        vector: Optional[Sequence[float]] = None,
        color: Sequence[float] = (1.0, 1.0, 1.0),
    ) -> None:
        """Add a light: ``"ambient"``, ``"headlight"``, ``"directional"`` (``vector``
        points towards the light) or ``"point"`` (``vector`` is its position). Lights
        shade faces added without colours."""
        vec = None if vector is None else tuple(float(x) for x in vector)
        self._s.add_light(kind, vec, tuple(float(x) for x in color))

    def set_camera(
        self,
        *,
        eye: Optional[Sequence[float]] = None,
        target: Optional[Sequence[float]] = None,
        up: Sequence[float] = (0, 1, 0),
        fov: float = 45.0,
        size: Tuple[int, int] = (800, 600),
        projection: str = "perspective",
        height: Optional[float] = None,
        matrix: Any = None,
    ) -> None:
        """Set the camera.

        projection: ``"perspective"`` (``fov`` degrees vertically) or ``"orthographic"``
        (``height`` world units vertically; framed when omitted). matrix: a 4x4
        view-projection matrix (world to OpenGL clip coordinates, rows first) instead of
        eye/target/up/projection; its centre of projection is the eye. Without ``eye``
        the scene is framed as the command frames it.
        """
        t = lambda x: None if x is None else tuple(float(c) for c in x)  # noqa: E731
        m = None
        if matrix is not None:
            m = np.ascontiguousarray(matrix, dtype=np.float64)
            if m.shape != (4, 4):
                raise ValueError(f"matrix must have shape (4, 4), not {m.shape}")
            m = m.reshape(16)
        self._s.set_camera(
            eye=t(eye),
            target=t(target),
            up=t(up),
            fov=float(fov),
            size=(int(size[0]), int(size[1])),
            projection=projection,
            height=None if height is None else float(height),
            matrix=m,
        )

    def render(
        self,
        path: Any,
        *,
        format: Optional[str] = None,
        sort: str = "adaptive",
        arith: str = "exact",
        outline: Optional[Tuple[float, float, float, float]] = None,
        background: Optional[Tuple[float, float, float]] = None,
    ) -> Dict[str, Any]:
        """Render to ``path`` (format from the extension unless given); return the
        statistics ``limn --stats`` prints. outline: (r, g, b, width) strokes the model's
        edges; background: (r, g, b) paints the page."""
        return self._s.render(
            str(path), format=format, sort=sort, arith=arith, outline=outline, background=background
        )

    def check(
        self, against: str = "raycast", *, sort: str = "adaptive", arith: str = "exact"
    ) -> Dict[str, Any]:
        """Compare the painted order with an image-space reference (raycast, zbuffer,
        scanline, abuffer, warnock) at every pixel centre; ``mismatches_outside_band`` is
        0 when they agree outside the band of centres too close to an edge to call."""
        return self._s.check(against, sort=sort, arith=arith)

    def paint(
        self, *, sort: str = "adaptive", arith: str = "exact", seams: float = 0.5
    ) -> list:
        """The painted polygons, back to front: ``(face, points (n, 2) in pixels with y
        down, fill (r, g, b, a), original_edges)``; seam flaps included."""
        return self._s.paint(sort=sort, arith=arith, seams=seams)
