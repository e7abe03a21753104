"""Type hints of the native module (the documented API is in ``limn/__init__.py``)."""

from typing import Any, Dict, List, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

# Faces (Scene.add_mesh): without counts, an (M, k) array of M faces of k >= 3 corners;
# with counts ((M,), each face's corner count, 3 or more), the flat (K,) indices of every
# face one face after another, K being the sum of the counts.
def load(path: str, allow_outside: bool = ...) -> "Scene": ...

class Scene:
    face_count: int
    def __init__(self) -> None: ...
    def add_mesh(
        self,
        vertices: npt.NDArray[np.float64],
        faces: npt.NDArray[np.int64],
        counts: Optional[npt.NDArray[np.int64]] = ...,
        colors: Optional[npt.NDArray[np.float64]] = ...,
        opacity: Optional[float] = ...,
        name: str = ...,
    ) -> int: ...
    mark_counts: Tuple[int, int, int]
    def add_line(
        self,
        points: npt.NDArray[np.float64],
        color: List[float],
        width: float,
        dash: List[float],
        head: bool,
        name: str = ...,
    ) -> int: ...
    def add_points(
        self,
        positions: npt.NDArray[np.float64],
        marker: str,
        sizes: npt.NDArray[np.float64],
        colors: npt.NDArray[np.float64],
        name: str = ...,
    ) -> int: ...
    def add_label(
        self,
        at: Tuple[float, float, float],
        text: str,
        size: float,
        color: List[float],
        anchor: str,
        offset: Tuple[float, float],
        name: str = ...,
    ) -> int: ...
    def add_light(
        self,
        kind: str,
        vector: Optional[Tuple[float, float, float]] = ...,
        color: Tuple[float, float, float] = ...,
        shadows: bool = ...,
    ) -> None: ...
    def set_camera(
        self,
        eye: Optional[Tuple[float, float, float]] = ...,
        target: Optional[Tuple[float, float, float]] = ...,
        up: Tuple[float, float, float] = ...,
        fov: float = ...,
        size: Tuple[int, int] = ...,
        projection: str = ...,
        height: Optional[float] = ...,
        matrix: Optional[npt.NDArray[np.float64]] = ...,
    ) -> None: ...
    def render(
        self,
        path: str,
        format: Optional[str] = ...,
        sort: Optional[str] = ...,
        arith: Optional[str] = ...,
        cull: Optional[str] = ...,
        outline: bool = ...,
        outline_color: Optional[Tuple[float, float, float]] = ...,
        outline_width: Optional[float] = ...,
        background: Any = ...,
        style: Optional[str] = ...,
        hidden: Optional[str] = ...,
        fill: Optional[str] = ...,
        crease: Optional[float] = ...,
        seams: float = ...,
        shading: Optional[str] = ...,
        shading_tolerance: float = ...,
        texture_samples: float = ...,
        method: str = ...,
        shadow_map_size: int = ...,
        shadow_bias: float = ...,
        standalone: bool = ...,
        max_fragments: Optional[int] = ...,
        visible: bool = ...,
        near: Optional[float] = ...,
        far: Optional[float] = ...,
        threads: Optional[int] = ...,
        stats: Optional[str] = ...,
    ) -> Dict[str, Any]: ...
    def check(
        self,
        against: str = ...,
        sort: Optional[str] = ...,
        arith: Optional[str] = ...,
        seams: float = ...,
        visible: bool = ...,
        diff: Optional[str] = ...,
        stats: Optional[str] = ...,
        threads: Optional[int] = ...,
    ) -> Dict[str, Any]: ...
    def paint(
        self, sort: Optional[str] = ..., arith: Optional[str] = ..., seams: float = ...
    ) -> List[Tuple[int, npt.NDArray[np.float64], Tuple[float, float, float, float], List[bool]]]: ...
    def paint_with_marks(
        self,
        sort: Optional[str] = ...,
        arith: Optional[str] = ...,
        seams: float = ...,
        join: Optional[npt.NDArray[np.int64]] = ...,
        stroked: Optional[npt.NDArray[np.bool_]] = ...,
    ) -> Tuple[
        List[
            Tuple[
                int,
                Union[npt.NDArray[np.float64], List[npt.NDArray[np.float64]]],
                Tuple[float, float, float, float],
                List[bool],
            ]
        ],
        List[Dict[str, Any]],
    ]: ...
