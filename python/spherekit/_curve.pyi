# Type stubs of `Curve` (the native class of _spherekit.pyi, with a Python `__call__`).
from typing import Literal

import numpy as np
import numpy.typing as npt

from . import _spherekit
from ._spherekit import _Times

class Curve(_spherekit.Curve):
    def __call__(self, t: _Times, order: Literal[0, 1, 2] = 0) -> npt.NDArray[np.float64]: ...
