"""limn: 3D polygon scenes drawn as vector pictures with hidden surfaces removed exactly.

>>> import numpy as np, limn
>>> v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], float)
>>> stats = limn.render_mesh(v, [[0, 1, 2]], "tri.svg")   # doctest: +SKIP

``render_mesh`` draws one mesh; ``load`` reads a mesh or scene file (OBJ, STL, PLY,
glTF, GLB, TOML) as the command reads it; ``Scene`` holds several meshes, lines, point
markers, labels, lights and a camera
(perspective, orthographic, or a 4x4 view-projection matrix), and renders with every
option of ``limn render`` (same names, ``-`` as ``_``, same defaults, same file safety);
``limn.matplotlib.savefig``
writes a matplotlib figure whose 3D axes are ordered exactly by limn (surfaces, bars,
lines, scatter points, 3D texts and, when data leave it, the axes' box).
"""

from __future__ import annotations

import warnings
from typing import Any, Dict, Optional, Sequence, Tuple

import numpy as np

from . import _limn

__all__ = ["load", "render_mesh", "Scene", "__version__"]
__version__ = _limn.__version__


def _vertices(vertices: Any) -> np.ndarray:
    # Copies only when the dtype or layout requires it.
    v = np.ascontiguousarray(vertices, dtype=np.float64)
    if v.ndim != 2 or v.shape[1] != 3:
        raise ValueError(f"vertices must have shape (N, 3), not {v.shape}")
    return v


def _indices(what: str, a: Any, ndim: int, shape: str) -> np.ndarray:
    """``a`` as a contiguous int64 array of ``ndim`` dimensions (``shape`` names them in
    the message), integers only."""
    x = np.asarray(a)
    if x.ndim != ndim:
        raise ValueError(f"{what} must have shape {shape}, not {x.shape}")
    if x.size and not np.issubdtype(x.dtype, np.integer):
        raise ValueError(f"{what} must hold integers, not {x.dtype}")
    return np.ascontiguousarray(x, dtype=np.int64)


def _faces(faces: Any, counts: Any = None) -> Tuple[np.ndarray, Optional[np.ndarray]]:
    """The faces as the native module takes them: an ``(M, k)`` array and no counts, or
    the flat ``(K,)`` indices of every face one after another and the ``(M,)`` counts."""
    if counts is not None:
        return _indices("faces", faces, 1, "(K,)"), _indices("counts", counts, 1, "(M,)")
    if isinstance(faces, np.ndarray) and faces.dtype != object:
        if faces.ndim == 1 and faces.size:
            raise ValueError("faces is flat: give each face's corner count with counts=")
        return _indices("faces", faces, 2, "(M, k)"), None
    try:
        rows = list(faces)
    except TypeError:
        raise ValueError(
            f"faces must be an (M, k) array or a sequence of index sequences, not {faces!r}"
        ) from None
    if not rows:
        return np.zeros((0, 3), dtype=np.int64), None
    with warnings.catch_warnings():
        # Faces of different corner counts: numpy >= 1.24 refuses them, older ones warn.
        warnings.simplefilter("error")
        try:
            f = np.asarray(rows)
        except (ValueError, Warning):
            f = None
    if f is not None and f.dtype != object:
        if f.ndim == 2:
            return _indices("faces", f, 2, "(M, k)"), None
        if f.ndim == 1:
            raise ValueError("faces is flat: give each face's corner count with counts=")
    ragged = []
    for j, face in enumerate(rows):
        r = np.asarray(face)
        if r.ndim != 1:
            raise ValueError(f"faces[{j}] must be a sequence of vertex indices, not {face!r}")
        if r.size and not np.issubdtype(r.dtype, np.integer):
            raise ValueError(f"faces[{j}] must hold integers, not {r.dtype}")
        ragged.append(r.astype(np.int64, copy=False))
    n = np.fromiter((len(r) for r in ragged), dtype=np.int64, count=len(ragged))
    return np.ascontiguousarray(np.concatenate(ragged), dtype=np.int64), n


def _colors(colors: Any) -> Optional[np.ndarray]:
    if colors is None:
        return None
    c = np.ascontiguousarray(colors, dtype=np.float64)
    if c.ndim != 2 or c.shape[1] not in (3, 4):
        raise ValueError(f"colors must have shape (M, 3) or (M, 4), not {c.shape}")
    return c


def _points(what: str, points: Any) -> np.ndarray:
    p = np.ascontiguousarray(points, dtype=np.float64)
    if p.ndim != 2 or p.shape[1] != 3:
        raise ValueError(f"{what} must have shape (N, 3), not {p.shape}")
    return p


def render_mesh(
    vertices: Any,
    faces: Any,
    path: Any,
    *,
    counts: Any = None,
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
    **options: Any,
) -> Dict[str, Any]:
    """Render one mesh to ``path`` and return the statistics ``limn --stats`` prints.

    vertices: ``(N, 3)`` floats. faces: polygons of any number of corners from three
    up, given as vertex indices in one of three ways: an ``(M, k)`` array (``M`` faces
    of ``k`` corners each, e.g. triangles or quads); a sequence of index sequences, one
    per face, of any lengths (``[[0, 1, 2], [0, 2, 3, 4, 5]]``); or, with ``counts``
    (``(M,)``, each face's corner count), the flat ``(K,)`` array of every face's
    indices one face after another (``faces=[0, 1, 2, 0, 2, 3, 4, 5], counts=[3, 5]``).
    A face need not be convex or planar: it is drawn as the polygon it is (limn
    triangulates it when it must). colors: per face ``(M, 3)`` or ``(M, 4)`` in 0..1,
    drawn exactly (unlit); without
    colours faces are grey, lit by a headlight. opacity: 0..1 for the whole mesh.
    eye, target, up, fov: the camera; without ``eye`` the scene is framed as the
    command frames it (from the right, above and in front). size: (width, height) in
    pixels. sort: adaptive, bsp, newell or simple. arith: exact or float. format: svg,
    pdf, eps, png or tikz (default: from the extension). Any other keyword is an option
    of ``Scene.render``.

    Raises ValueError for wrong shapes, NaN, indices out of range, faces of fewer than
    three corners, counts that do not add up to the number of indices, and bad options
    (the message names the face); OSError when the file cannot be written. Nothing is
    written on error.
    """
    s = Scene()
    s.add_mesh(vertices, faces, counts=counts, colors=colors, opacity=opacity)
    s.set_camera(eye=eye, target=target, up=up, fov=fov, size=size)
    return s.render(path, format=format, sort=sort, arith=arith, **options)


def load(path: Any, *, allow_outside: bool = False) -> "Scene":
    """Read a mesh or scene file as ``limn render`` reads it: OBJ (with MTL materials and
    textures), STL, PLY, glTF/GLB, or a TOML scene file (meshes, lights, camera, lines,
    points, labels and render settings, which ``render`` then uses as the command does).

    allow_outside: follow references (material libraries, buffers, textures, meshes)
    outside the file's folder. The file's warnings are issued as ``UserWarning`` (text
    starting ``limn: ``). Raises ``OSError`` when the file cannot be read and
    ``ValueError`` (naming file and line) when it is not valid.
    """
    s = Scene.__new__(Scene)
    s._s = _limn.load(str(path), allow_outside=bool(allow_outside))
    return s


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
        counts: Any = None,
        colors: Any = None,
        opacity: Optional[float] = None,
        name: str = "mesh",
    ) -> int:
        """Add a mesh (arguments as in ``render_mesh``: faces of any number of corners,
        as an ``(M, k)`` array, a sequence of index sequences, or flat indices with
        ``counts``); return the id of its first face.

        Faces are numbered in the order they are added, over all meshes. Raises
        ``ValueError`` (and leaves the scene unchanged) on bad input.
        """
        f, n = _faces(faces, counts)
        return self._s.add_mesh(
            _vertices(vertices), f, counts=n, colors=_colors(colors), opacity=opacity, name=name
        )

    def add_line(
        self,
        points: Any,
        *,
        color: Sequence[float] = (0.0, 0.0, 0.0),
        width: float = 1.0,
        dash: Optional[Sequence[float]] = None,
        head: bool = False,
        name: str = "line",
    ) -> int:
        """Add a polyline through ``points`` ``(N, 3)`` (N >= 2); return its index.

        It is drawn only where visible: hidden exactly by the faces in front of it, drawn
        over a face whose plane holds it (a wireframe on its own surface shows).
        color: (r, g, b) or (r, g, b, a) in 0..1; width: pixels; dash: lengths in pixels
        (dash, gap, ...), ``None`` for solid; head: an arrow head at the last point when
        that point is visible. Raises ``ValueError`` (and leaves the scene unchanged) on
        a bad shape, a non-finite point, a colour outside 0..1 or a width that is not
        positive.
        """
        p = _points("points", points)
        return self._s.add_line(
            p,
            [float(c) for c in color],
            float(width),
            [] if dash is None else [float(d) for d in dash],
            bool(head),
            name=name,
        )

    def add_points(
        self,
        positions: Any,
        *,
        marker: str = "dot",
        size: Any = 4.0,
        color: Any = (0.0, 0.0, 0.0),
        name: str = "points",
    ) -> int:
        """Add point markers at ``positions`` ``(N, 3)``; return the index of the first.

        A marker is drawn whole where its anchor is visible and not at all where a face
        hides it. marker: ``dot``, ``circle``, ``square``, ``triangle``, ``cross`` or
        ``plus``; size: diameter in pixels, one number or one per point ``(N,)``; color:
        one (r, g, b[, a]) or one per point ``(N, 3)`` / ``(N, 4)``, in 0..1. Raises
        ``ValueError`` (scene unchanged) on bad shapes, non-finite values or an unknown
        marker.
        """
        p = _points("positions", positions)
        n = p.shape[0]
        sizes = np.asarray(size, dtype=np.float64)
        if sizes.ndim == 0:
            sizes = np.full(n, float(sizes))
        colors = np.asarray(color, dtype=np.float64)
        if colors.ndim == 1:
            colors = np.broadcast_to(colors, (n, colors.shape[0]))
        if sizes.ndim != 1:
            raise ValueError(f"size must be one number or shape ({n},), not {sizes.shape}")
        if colors.ndim != 2:
            raise ValueError(f"color must be one colour or shape ({n}, 3|4), not {colors.shape}")
        return self._s.add_points(
            p,
            str(marker),
            np.ascontiguousarray(sizes),
            np.ascontiguousarray(colors),
            name=name,
        )

    def add_label(
        self,
        at: Sequence[float],
        text: str,
        *,
        size: float = 10.0,
        color: Sequence[float] = (0.0, 0.0, 0.0),
        anchor: str = "center",
        offset: Tuple[float, float] = (0.0, 0.0),
        name: str = "label",
    ) -> int:
        """Add a one-line text label at the 3D point ``at``; return its index.

        Shown where ``at`` is visible. size: font size in points (pixels of the picture);
        anchor: which point of the text box sits at the projected point plus ``offset``
        (TikZ names: ``center``, ``north``, ``south east``, ...; ``south`` puts the text
        above the point); offset: pixels, x right, y down. Raises ``ValueError`` on a
        non-finite position, a text with a line break or an unknown anchor.
        """
        a = tuple(float(x) for x in at)
        if len(a) != 3:
            raise ValueError(f"at must be a 3D point, not {at!r}")
        o = tuple(float(x) for x in offset)
        if len(o) != 2:
            raise ValueError(f"offset must be (x, y), not {offset!r}")
        return self._s.add_label(
            a, str(text), float(size), [float(c) for c in color], str(anchor), o, name=name
        )

    @property
    def mark_counts(self) -> Tuple[int, int, int]:
        """Numbers of lines, point markers and labels added so far."""
        return self._s.mark_counts

    def add_light(
        self,
        kind: str,
        vector: Optional[Sequence[float]] = None,
        color: Sequence[float] = (1.0, 1.0, 1.0),
        shadows: bool = False,
    ) -> None:
        """Add a light: ``"ambient"``, ``"headlight"``, ``"directional"`` (``vector``
        points towards the light) or ``"point"`` (``vector`` is its position). Lights
        shade faces added without colours. ``shadows=True`` makes a directional or point
        light cast shadows, exact in vector output (faces split along the shadows'
        edges); ambient lights and headlights cannot (``ValueError``)."""
        vec = None if vector is None else tuple(float(x) for x in vector)
        self._s.add_light(kind, vec, tuple(float(x) for x in color), bool(shadows))

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
        sort: Optional[str] = None,
        arith: Optional[str] = None,
        cull: Optional[str] = None,
        outline: Any = False,
        background: Any = None,
        style: Optional[str] = None,
        hidden: Optional[str] = None,
        fill: Optional[str] = None,
        crease: Optional[float] = None,
        seams: float = 1.0,
        shading: Optional[str] = None,
        shading_tolerance: float = 1.0 / 255.0,
        texture_samples: float = 2.0,
        method: str = "painter",
        shadow_map_size: int = 2048,
        shadow_bias: float = 1e-3,
        standalone: bool = False,
        max_fragments: Optional[int] = None,
        visible: bool = False,
        near: Optional[float] = None,
        far: Optional[float] = None,
        threads: Optional[int] = None,
        stats: Any = None,
    ) -> Dict[str, Any]:
        """Render to ``path`` with the options of ``limn render`` (the same names with
        ``_`` for ``-``, the same defaults; unset ones fall back to a loaded scene file's
        settings); return the statistics ``limn --stats`` prints (for ``method`` other
        than ``"painter"``: ``{"method", "warnings"}``).

        format: svg, pdf, eps, png or tikz (default: the extension). sort: adaptive, bsp,
        newell, simple. arith: exact, float. cull: auto, on, off. outline: ``True``
        strokes every model edge; ``(r, g, b, width)`` in that colour and width.
        background: ``(r, g, b)``, ``"#rrggbb"`` or ``"none"``. style: filled,
        hidden-line; hidden: omit, dashed; fill: background, none; crease: degrees.
        seams: seam flap width in pixels (0 to 10). shading: flat, gouraud, phong;
        shading_tolerance: per channel (0, 1]. texture_samples: SVG and PDF draw opaque
        textured faces from one image of the page sampled this many times per pixel each
        way (0 to 16; 0: each face's texture under its own maps). method: painter, zbuffer, scanline,
        abuffer, warnock, raycast (a PNG). standalone: a TikZ file that compiles alone.
        max_fragments: give up beyond. visible: draw only the visible map (each face split
        exactly along what hides it, the hidden parts left out; also a scene file's
        ``visible = true``). near, far: clipping distances. threads: worker
        threads (the picture is the same for every count). stats: also write the
        statistics as JSON to this path.

        Writes safely: a temporary file renamed into place (nothing left on error), a
        symbolic link written through, a device or FIFO written directly; a folder, a
        read-only file and the files the scene was read from are refused (``OSError``).
        Warnings are issued as ``UserWarning`` (text starting ``limn: ``) and listed in
        the statistics. Raises ``ValueError`` for bad options and scenes.
        """
        colour = width = None
        if isinstance(outline, (tuple, list)):
            if len(outline) != 4:
                raise ValueError("outline must be True, False or (r, g, b, width)")
            colour = tuple(float(c) for c in outline[:3])
            width = float(outline[3])
            outline = True
        if isinstance(background, (tuple, list)):
            background = tuple(float(c) for c in background)
        return self._s.render(
            str(path),
            format=format,
            sort=sort,
            arith=arith,
            cull=cull,
            outline=bool(outline),
            outline_color=colour,
            outline_width=width,
            background=background,
            style=style,
            hidden=hidden,
            fill=fill,
            crease=None if crease is None else float(crease),
            seams=float(seams),
            shading=shading,
            shading_tolerance=float(shading_tolerance),
            texture_samples=float(texture_samples),
            method=method,
            shadow_map_size=int(shadow_map_size),
            shadow_bias=float(shadow_bias),
            standalone=bool(standalone),
            max_fragments=max_fragments,
            visible=bool(visible),
            near=near,
            far=far,
            threads=threads,
            stats=None if stats is None else str(stats),
        )

    def check(
        self,
        against: str = "raycast",
        *,
        sort: Optional[str] = None,
        arith: Optional[str] = None,
        seams: float = 1.0,
        visible: bool = False,
        diff: Any = None,
        stats: Any = None,
        threads: Optional[int] = None,
    ) -> Dict[str, Any]:
        """Compare the picture ``render`` draws (seam flaps ``seams`` pixels wide
        included) with an image-space reference (raycast, zbuffer, scanline, warnock) at
        every pixel centre, as ``limn check`` does; return its report, with ``agrees``
        (no pixel outside the band of centres too close to an edge to call disagrees, nor
        any shadow or line pixel) and ``failures`` (why not). visible: check the visible
        map ``render(visible=True)`` draws (also that no pixel centre is covered by two
        of its opaque regions). diff: write a PNG of the disagreeing pixels; stats:
        write the report as JSON."""
        return self._s.check(
            against,
            sort=sort,
            arith=arith,
            seams=float(seams),
            visible=bool(visible),
            diff=None if diff is None else str(diff),
            stats=None if stats is None else str(stats),
            threads=threads,
        )

    def paint(
        self, *, sort: Optional[str] = None, arith: Optional[str] = None, seams: float = 1.0
    ) -> list:
        """The painted polygons, back to front: ``(face, points (n, 2) in pixels with y
        down, fill (r, g, b, a), original_edges)``; seam flaps included."""
        return self._s.paint(sort=sort, arith=arith, seams=seams)

    def paint_with_marks(
        self,
        *,
        sort: Optional[str] = None,
        arith: Optional[str] = None,
        seams: float = 1.0,
        join: Any = None,
        stroked: Any = None,
    ) -> Tuple[list, list]:
        """``paint()``'s polygons and the visible lines, markers, labels and arrow heads
        as dicts in paint order. Each has ``before`` (paint it before that polygon; the
        polygons' count means after all) and ``kind``: ``"line"`` (``points (n, 2)``,
        ``color``, ``width``, ``dash``, ``dash_offset``), ``"marker"`` (``at``,
        ``shape``, ``size``, ``color``, ``stroke``), ``"label"`` (``at``, ``offset``,
        ``anchor``, ``text``, ``size``, ``color``) or ``"head"`` (``points (3, 2)``,
        ``color``); ``index`` is the input line, point (over all ``add_points`` calls) or
        label it shows, ``None`` for heads. Pixels, y down.

        ``join``: a group number per face (an array of ``face_count`` integers; negative:
        none), for faces that do not overlap (a polygon's triangles, the faces filling
        one region). The flat fragments of faces of one group painted one after another
        in one fill, with no mark between them, then come as one polygon whose points
        are a list of rings (each (k, 2)): the outline of their union (what they fill
        together under the nonzero rule, on a grid of a millionth of a pixel), outer
        rings turned one way and holes the other, with no original edges; its face is
        the first fragment's.

        ``stroked``: a flag per face (an array of ``face_count`` booleans) for faces whose
        every original edge the caller strokes, opaque and at least ``seams`` pixels wide,
        right after the face's fill: those edges get no seam flap, as the stroke covers
        the seam."""
        if join is not None:
            join = np.ascontiguousarray(join, dtype=np.int64).reshape(-1)
        if stroked is not None:
            stroked = np.ascontiguousarray(stroked, dtype=bool).reshape(-1)
        return self._s.paint_with_marks(
            sort=sort, arith=arith, seams=seams, join=join, stroked=stroked
        )
