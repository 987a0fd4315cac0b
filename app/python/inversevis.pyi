# Type hints of the inversevis module (app/python/module.cpp holds the docstrings).
import os
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

class InputError(ValueError):
    """A file or input the engine cannot use: one line naming it and the problem."""

class Mesh:
    def __init__(
        self,
        vertices: Union[npt.NDArray[np.floating], Sequence[Sequence[float]]],
        faces: Union[npt.NDArray[np.integer], Sequence[Sequence[int]]],
        point_data: Optional[Mapping[str, npt.NDArray[Any]]] = None,
        cell_data: Optional[Mapping[str, npt.NDArray[Any]]] = None,
    ) -> None: ...
    @staticmethod
    def read(path: Union[str, os.PathLike]) -> "Mesh": ...
    @property
    def source(self) -> str: ...
    @property
    def vertices(self) -> npt.NDArray[np.float32]: ...
    @property
    def faces(self) -> npt.NDArray[np.int64]: ...
    @property
    def point_data(self) -> Dict[str, npt.NDArray[np.float64]]: ...
    @property
    def cell_data(self) -> Dict[str, npt.NDArray[np.float64]]: ...
    @property
    def arrays(self) -> List[Dict[str, Any]]: ...

class Picture:
    @property
    def rgba(self) -> npt.NDArray[np.uint8]: ...
    @property
    def layers(self) -> Dict[str, npt.NDArray[np.float32]]: ...
    @property
    def camera(self) -> Dict[str, Any]: ...
    @property
    def method(self) -> Dict[str, Any]: ...
    @property
    def measures(self) -> Dict[str, Any]: ...
    @property
    def optimization(self) -> Optional[Dict[str, Any]]: ...
    @property
    def views(self) -> List["Picture"]: ...
    def probe(self, x: int, y: int) -> Dict[str, Any]: ...
    def tear_map(self) -> npt.NDArray[np.uint8]: ...
    def unseen_map(self) -> npt.NDArray[np.uint8]: ...
    def save(self, path: Union[str, os.PathLike]) -> None: ...
    def save_view(self, path: Union[str, os.PathLike]) -> None: ...
    def save_views(self, path: Union[str, os.PathLike]) -> None: ...
    def _repr_png_(self) -> bytes: ...

def render(
    mesh: Mesh,
    method: str = "inversevis-wrap",
    *,
    scalar: Optional[str] = None,
    cell_to_point: bool = False,
    hotspots: int = 0,
    cap_holes: bool = False,
    theta: Optional[float] = None,
    phi: Optional[float] = None,
    fov: Optional[float] = None,
    ortho: bool = False,
    camera: Optional[Dict[str, Any]] = None,
    size: Tuple[int, int] = (1000, 1000),
    colormap: str = "viridis",
    range: Optional[Tuple[float, float]] = None,
    range_percentile: Optional[Tuple[float, float]] = None,
    symmetric: bool = False,
    log: bool = False,
    invert: bool = False,
    units: str = "",
    volume_resolution: int = 200,
    min_coherence: float = 0.99,
    full_trace: bool = False,
    legend: bool = True,
    legend_side: str = "right",
    outline: bool = True,
    shadows: bool = True,
    shade_indirect: bool = True,
    transparent: bool = False,
    spp: int = 1,
    measure: bool = False,
    progress: Optional[Callable[[str, int], None]] = None,
    **parameters: Union[float, Sequence[float]],
) -> Picture: ...

def optimize(
    mesh: Mesh,
    method: str = "inversevis-wrap",
    *,
    scalar: Optional[str] = None,
    cell_to_point: bool = False,
    hotspots: int = 0,
    cap_holes: bool = False,
    energy: str = "visibility",
    gamma: Optional[float] = None,
    opt_res: int = 100,
    ascent_res: int = 0,
    steps: int = 20,
    seed: int = 1,
    finalists: int = 5,
    hot_spot_views: Optional[int] = None,
    start: Optional[Tuple[float, float]] = None,
    views: int = 1,
    size: Tuple[int, int] = (1000, 1000),
    colormap: str = "viridis",
    range: Optional[Tuple[float, float]] = None,
    range_percentile: Optional[Tuple[float, float]] = None,
    symmetric: bool = False,
    log: bool = False,
    invert: bool = False,
    units: str = "",
    volume_resolution: int = 200,
    min_coherence: float = 0.99,
    legend: bool = True,
    legend_side: str = "right",
    outline: bool = True,
    shadows: bool = True,
    shade_indirect: bool = True,
    transparent: bool = False,
    spp: int = 1,
    progress: Optional[Callable[[str, int], None]] = None,
    **parameters: Union[float, Sequence[float]],
) -> Picture: ...

def read_view(path: Union[str, os.PathLike]) -> Dict[str, Any]: ...

def methods() -> List[str]: ...
