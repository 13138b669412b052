# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""Spline curves on spheres from numpy: S2, unit quaternions (S3) and S^m.

Every curve is built and evaluated by the Rust crates of spherekit; this package is a thin
layer over them.

- :class:`Curve` — any registered method (``spherekit.methods()``) on any sphere.
- :class:`RotationSpline`, :class:`Slerp` — drop-ins for ``scipy.spatial.transform``'s
  classes of the same names, quaternions and all (scipy is optional: without it, rotations are
  ``(n, 4)`` quaternion arrays); :class:`SmoothRotationSpline` — the smoothing spline of noisy
  rotations, called as ``RotationSpline``.
- :func:`sample`, :func:`render`, :func:`render_png` — whole JSON scenes, as the
  ``spherekit`` CLI takes them; :func:`methods` — the method registry.

Quaternions are scalar last, ``[x, y, z, w]`` as scipy's ``Rotation.as_quat()``, in and out,
or ``[w, x, y, z]`` with ``scalar_first=True``: in ``Curve``, the drop-ins, and scenes given to
``sample``/``render``/``render_png`` as dicts. A scene given as JSON text or a file path is the
CLI's format, ``[w, x, y, z]`` (``scalar_first=False`` reads it scalar last); a scene's own
``"quaternion_order"`` wins. Bad input, a NaN time included, raises ``ValueError`` with a
one-line message (the CLI's for scenes).

>>> import numpy as np, spherekit
>>> c = spherekit.Curve("squad", [[0, 0, 0, 1], [0, 0, 0.3826834, 0.9238795], [0.5, 0.5, 0, 0.7071068]])
>>> c.space, c.domain
('S3', (0.0, 2.0))
>>> c.angular_velocity([0.5, 1.5], frame="body").shape
(2, 3)
"""

from ._curve import Curve
from ._spherekit import __version__ as __version__
from ._spherekit import methods, render, render_png, sample
from ._scipy import RotationSpline, Slerp, SmoothRotationSpline

__all__ = [
    "Curve",
    "RotationSpline",
    "Slerp",
    "SmoothRotationSpline",
    "methods",
    "render",
    "render_png",
    "sample",
]
