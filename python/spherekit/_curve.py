# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""`Curve`: the native class, with a `__call__` whose signature `help()` and Jupyter can show.

A native class's `__call__` is a slot, which CPython describes as `(*args, **kwargs)` whatever
its Rust signature; this subclass only forwards the call, so the parameters are visible.
"""

from . import _spherekit


class Curve(_spherekit.Curve):
    __doc__ = _spherekit.Curve.__doc__
    __slots__ = ()

    def __call__(self, t, order=0):
        """The points (``order=0``), velocities (1) or accelerations (2) at the parameters ``t``:
        an ``(m, d)`` array for ``m`` parameters (``(d,)`` for a scalar ``t``)."""
        return super().__call__(t, order)
