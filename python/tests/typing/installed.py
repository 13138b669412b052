# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""Checked by `mypy --strict` against the installed wheel (scripts/test-wheel.sh): the types a
user's checker sees. `assert_type` fails the check when a stub says otherwise."""

from typing import Any, Optional

import numpy as np
import numpy.typing as npt
from scipy.spatial.transform import Rotation
from typing_extensions import assert_type

import spherekit

keys = Rotation.from_euler("z", [[0], [90], [180]], degrees=True)
spline = spherekit.RotationSpline([0, 1, 2], keys)
assert_type(spline(0.5), Rotation)
assert_type(spline([0.5, 1.0], 0), Rotation)
assert_type(spline([0.5, 1.0], 1), npt.NDArray[np.float64])
assert_type(spline.rotations, Rotation)
assert_type(spherekit.Slerp([0, 1, 2], keys)(0.5), Rotation)
assert_type(spherekit.Slerp([0, 1, 2], keys).rotations, Rotation)

curve = spherekit.Curve("squad", keys.as_quat())
assert_type(curve(np.linspace(0, 1, 3)), npt.NDArray[np.float64])
assert_type(curve(0.5, 2), npt.NDArray[np.float64])
assert_type(curve.angular_velocity([0.5], frame="body"), npt.NDArray[np.float64])
assert_type(curve.domain, tuple[float, float])
assert_type(spherekit.sample({"space": "S2", "method": "geodesic", "points": [[1, 0, 0], [0, 1, 0]]}), dict[str, Any])
assert_type(spherekit.__version__, str)

smooth = spherekit.SmoothRotationSpline([0, 1, 2], keys, smoothing={"rms": 0.01}, weights=[1, 2, 1])
assert_type(smooth(0.5), Rotation)
assert_type(smooth([0.5], 2), npt.NDArray[np.float64])
assert_type(smooth.fit_info, dict[str, Any])
fitted = spherekit.Curve("cubic", keys.as_quat(), knots=[0, 1, 2], fit={"smoothing": 0.1})
assert_type(fitted.fit_info, Optional[dict[str, Any]])
