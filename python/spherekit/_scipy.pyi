# Type stubs of the scipy drop-ins.
from typing import Any, Literal, Optional, Union, overload

import numpy as np
import numpy.typing as npt

_Times = Union[float, npt.ArrayLike]

class RotationSpline:
    times: npt.NDArray[np.float64]
    @property
    def rotations(self) -> Any: ...
    def __init__(
        self,
        times: npt.ArrayLike,
        rotations: Any,
        *,
        end: Optional[Literal["scipy", "natural", "clamped"]] = None,
        closed: bool = False,
        start_velocity: Optional[npt.ArrayLike] = None,
        end_velocity: Optional[npt.ArrayLike] = None,
        scalar_first: bool = False,
    ) -> None: ...
    @overload
    def __call__(self, times: _Times) -> Any: ...
    @overload
    def __call__(self, times: _Times, order: Literal[0]) -> Any: ...
    @overload
    def __call__(self, times: _Times, order: Literal[1, 2]) -> npt.NDArray[np.float64]: ...

class Slerp:
    times: npt.NDArray[np.float64]
    timedelta: npt.NDArray[np.float64]
    @property
    def rotations(self) -> Any: ...
    @property
    def rotvecs(self) -> npt.NDArray[np.float64]: ...
    def __init__(self, times: npt.ArrayLike, rotations: Any, *, scalar_first: bool = False) -> None: ...
    def __call__(self, times: _Times) -> Any: ...
