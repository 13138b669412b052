# Type stubs of the native module (crates/spherekit-py).
from os import PathLike
from typing import Any, Literal, Optional, Union

import numpy as np
import numpy.typing as npt

_Times = Union[float, npt.ArrayLike]
# A dict is Python's convention (quaternions [x, y, z, w] unless scalar_first=True); str, bytes
# and paths are the scene format as the CLI reads it ([w, x, y, z] unless scalar_first=False);
# a scene's own "quaternion_order" wins over both.
_Scene = Union[dict[str, Any], str, bytes, PathLike[str]]

class Curve:
    """A curve of any registered method on any sphere, evaluated from numpy arrays."""

    def __init__(
        self,
        method: str,
        points: npt.ArrayLike,
        *,
        space: Optional[str] = None,
        knots: Optional[npt.ArrayLike] = None,
        closed: bool = False,
        scalar_first: bool = False,
        canonicalize: Optional[bool] = None,
        parametrization: Optional[Literal["native", "arclength"]] = None,
        extrapolate: Optional[Literal["hold", "extend", "cycle", "error", "segment"]] = None,
        fit: Optional[dict[str, Any]] = None,
        **params: Any,
    ) -> None: ...
    def __call__(self, t: _Times, order: Literal[0, 1, 2] = 0) -> npt.NDArray[np.float64]: ...
    def __reduce__(self) -> tuple[Any, tuple[str, npt.NDArray[np.float64]]]: ...
    def angular_velocity(self, t: _Times, frame: Literal["space", "body"] = "space") -> npt.NDArray[np.float64]: ...
    def angular_acceleration(self, t: _Times, frame: Literal["space", "body"] = "space") -> npt.NDArray[np.float64]: ...
    def continuity(self) -> list[dict[str, Any]]: ...
    @property
    def domain(self) -> tuple[float, float]: ...
    @property
    def joints(self) -> npt.NDArray[np.float64]: ...
    @property
    def method(self) -> str: ...
    @property
    def space(self) -> str: ...
    @property
    def points(self) -> npt.NDArray[np.float64]: ...
    @property
    def controls(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def auxiliary(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def info(self) -> dict[str, Any]: ...
    @property
    def fit_info(self) -> Optional[dict[str, Any]]: ...

class _CubicRotations:
    def __init__(
        self,
        times: npt.ArrayLike,
        quats: npt.ArrayLike,
        end: Literal["scipy", "natural", "clamped"] = "scipy",
        closed: bool = False,
        start_velocity: Optional[npt.ArrayLike] = None,
        end_velocity: Optional[npt.ArrayLike] = None,
        scalar_first: bool = False,
    ) -> None: ...
    def __call__(self, t: _Times, order: Literal[0, 1, 2] = 0, scalar_first: bool = False) -> npt.NDArray[np.float64]: ...
    def _extrapolated(self, t: float, order: Literal[0, 1, 2] = 0) -> npt.NDArray[np.float64]: ...
    @property
    def solve_info(self) -> tuple[int, float]: ...
    @property
    def keys(self) -> npt.NDArray[np.float64]: ...

class _SlerpRotations:
    def __init__(self, times: npt.ArrayLike, quats: npt.ArrayLike, scalar_first: bool = False) -> None: ...
    def __call__(self, t: _Times, scalar_first: bool = False) -> npt.NDArray[np.float64]: ...

def sample(
    scene: _Scene,
    *,
    deriv: bool = False,
    continuity: bool = False,
    frame: Literal["space", "body"] = "space",
    samples: Optional[int] = None,
    scalar_first: Optional[bool] = None,
) -> dict[str, Any]: ...
def render(scene: _Scene, size: int = 512, *, scalar_first: Optional[bool] = None) -> npt.NDArray[np.uint8]: ...
def render_png(
    scene: _Scene, path: Union[str, PathLike[str]], size: int = 512, *, scalar_first: Optional[bool] = None
) -> None: ...
def methods() -> list[dict[str, Any]]: ...

__version__: str
