# Type stubs of the scipy drop-ins. Rotations are scipy's `Rotation` (without scipy installed,
# the drop-ins return (n, 4) quaternion arrays instead; the stubs describe the usual case).
from typing import Any, Literal, Optional, Union, overload

import numpy as np
import numpy.typing as npt
from scipy.spatial.transform import Rotation

_Times = Union[float, npt.ArrayLike]
# A Rotation, or quaternions [x, y, z, w] ([w, x, y, z] with scalar_first=True), shape (n, 4).
_Rotations = Union[Rotation, npt.ArrayLike]

class _Keyed:
    """What the drop-ins share: their times and their keys (samples) as given."""
    times: npt.NDArray[np.float64]
    @property
    def rotations(self) -> Rotation: ...

class RotationSpline(_Keyed):
    def __init__(
        self,
        times: npt.ArrayLike,
        rotations: _Rotations,
        *,
        end: Optional[Literal["scipy", "natural", "clamped"]] = None,
        closed: bool = False,
        start_velocity: Optional[npt.ArrayLike] = None,
        end_velocity: Optional[npt.ArrayLike] = None,
        scalar_first: bool = False,
    ) -> None: ...
    @overload
    def __call__(self, times: _Times) -> Rotation: ...
    @overload
    def __call__(self, times: _Times, order: Literal[0]) -> Rotation: ...
    @overload
    def __call__(self, times: _Times, order: Literal[1, 2]) -> npt.NDArray[np.float64]: ...

class SmoothRotationSpline(_Keyed):
    @property
    def fit_info(self) -> dict[str, Any]: ...
    def __init__(
        self,
        times: npt.ArrayLike,
        rotations: _Rotations,
        smoothing: Union[float, Literal["gcv"], dict[str, float]] = "gcv",
        weights: Optional[npt.ArrayLike] = None,
        *,
        max_error: Optional[float] = None,
        keys: Optional[int] = None,
        scalar_first: bool = False,
    ) -> None: ...
    @overload
    def __call__(self, times: _Times) -> Rotation: ...
    @overload
    def __call__(self, times: _Times, order: Literal[0]) -> Rotation: ...
    @overload
    def __call__(self, times: _Times, order: Literal[1, 2]) -> npt.NDArray[np.float64]: ...

class Slerp(_Keyed):
    timedelta: npt.NDArray[np.float64]
    @property
    def rotvecs(self) -> npt.NDArray[np.float64]: ...
    def __init__(self, times: npt.ArrayLike, rotations: _Rotations, *, scalar_first: bool = False) -> None: ...
    def __call__(self, times: _Times) -> Rotation: ...
