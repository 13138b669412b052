# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""Drop-ins for ``scipy.spatial.transform.RotationSpline`` and ``Slerp``, and
``SmoothRotationSpline``, the smoothing spline of noisy rotations called as they are.

The argument checks and their ``ValueError`` messages are scipy's (1.17); the curves are the
Rust ``CubicSpline`` (with scipy's end condition, or fitted to samples) and
``GeodesicSpline``, evaluated in batches with the interpreter lock released.
"""

from __future__ import annotations

import functools

import numpy as np

from . import _spherekit
from ._curve import Curve

try:  # scipy is optional: without it, rotations are (n, 4) scalar-last quaternion arrays.
    from scipy.spatial.transform import Rotation as _Rotation
except ImportError:  # pragma: no cover - exercised only without scipy
    _Rotation = None


def _quats(rotations, who):
    """The keys as an (n, 4) array (scalar last from a ``Rotation``, else as given) and whether
    they came as an array, with scipy's messages for the bad shapes."""
    if hasattr(rotations, "as_quat") and hasattr(rotations, "single"):
        if rotations.single:
            raise ValueError(
                "`rotations` must be a sequence of at least 2 rotations."
                if who == "Slerp"
                else "`rotations` must be a sequence of rotations."
            )
        q = np.asarray(rotations.as_quat(), dtype=float)
        array = False
    else:
        if who == "Slerp" and _Rotation is not None and not isinstance(rotations, np.ndarray):
            raise TypeError("`rotations` must be a `Rotation` instance.")
        q = np.asarray(rotations, dtype=float)
        array = True
        if q.ndim == 1:
            raise ValueError(
                "`rotations` must be a sequence of at least 2 rotations."
                if who == "Slerp"
                else "`rotations` must be a sequence of rotations."
            )
    if q.ndim > 2:
        raise ValueError("Rotations with more than 1 leading dimension are not supported.")
    if q.shape[-1] != 4:
        raise ValueError(f"Expected `rotations` as quaternions of shape (n, 4), got {q.shape}.")
    return q, array


def _checked_times(times, n, closed):
    """``times`` as a float array, with scipy's ``RotationSpline`` messages for a wrong shape,
    count (closed: one more than the rotations, the return time) or order."""
    times = np.asarray(times, dtype=float)
    if times.ndim != 1:
        raise ValueError("`times` must be 1-dimensional.")
    if len(times) != (n + 1 if closed else n):
        if closed:
            raise ValueError(
                "Expected one more timestamp than rotations for a closed spline "
                "(the time it is back at the first rotation), "
                f"got {n} rotations and {len(times)} timestamps."
            )
        raise ValueError(
            "Expected number of rotations to be equal to number of timestamps given, "
            f"got {n} rotations and {len(times)} timestamps."
        )
    if (np.diff(times) <= 0).any():
        raise ValueError("Values in `times` must be in a strictly increasing order.")
    return times


def _renamed(name, value, old_name, old_value):
    """The value of keyword ``name``, also accepted under its earlier name ``old_name``."""
    if old_value is None:
        return value
    if value is not None:
        raise ValueError(f"`{old_name}` is the earlier name of `{name}`: give one of them.")
    return old_value


def _as_given(rotations, q, array):
    """The keys to keep for pickling: a ``Rotation`` as it is (it pickles), an array copied (the
    caller may change theirs)."""
    return q.copy() if array else rotations


def _key_rotations(kept, array, scalar_first):
    """The keys as scipy keeps them, from what ``_as_given`` kept: the ``Rotation`` given, or
    one made from the quaternion array (the array itself without scipy)."""
    if not array or _Rotation is None:
        return kept
    return _Rotation.from_quat(kept, scalar_first=scalar_first)


def _rotations(q):
    """Quaternions (scalar last when scipy is importable) as a scipy ``Rotation``, or as they are
    without scipy.

    The spline's quaternions are unit to rounding, so scipy's normalisation (most of the cost
    of ``Rotation.from_quat`` on large batches) is skipped where scipy's constructor offers it
    (``normalize=False, copy=False``, scipy 1.10 and later).
    """
    if _Rotation is None:
        return q
    try:
        return _Rotation(q, normalize=False, copy=False)
    except TypeError:  # pragma: no cover - scipy without the keywords
        return _Rotation.from_quat(q)


class _Keyed:
    """What the drop-ins share: they pickle as their arguments (``_args``: the times, the
    rotations as given and the keywords), and the splines give back their keys or samples."""

    def _keep(self, times, rotations, q, array, scalar_first, kwargs):
        self._args = (times.copy(), _as_given(rotations, q, array), kwargs)
        self._array_keys = array
        self._scalar_first = scalar_first
        self.times = times

    @functools.cached_property
    def rotations(self):
        """The keys (samples) as given: the ``Rotation`` (one made from the quaternion array;
        the array without scipy)."""
        return _key_rotations(self._args[1], self._array_keys, self._scalar_first)

    def __getstate__(self):
        return self._args

    def __setstate__(self, state):
        times, rotations, kwargs = state
        self.__init__(times, rotations, **kwargs)


class RotationSpline(_Keyed):
    """Interpolates rotations with continuous angular rate and acceleration.

    A drop-in for ``scipy.spatial.transform.RotationSpline``: the same constructor (a scipy
    ``Rotation``, or an ``(n, 4)`` quaternion array, scalar last ``[x, y, z, w]`` or scalar
    first with ``scalar_first=True`` as scipy's ``Rotation.from_quat``), the same call
    ``spline(times, order=0|1|2)`` returning a ``Rotation`` (an ``(m, 4)`` array in the order
    of ``scalar_first`` without scipy), the body-frame angular rate, or the body-frame angular
    acceleration; the same ``ValueError`` messages, and the attributes ``times`` and
    ``rotations`` (the keys as given, a ``Rotation``). Outside the key times the end segments'
    cubics are extrapolated, as scipy does (a closed spline is periodic instead). A NaN time
    is a ``ValueError``.

    The quaternions are scipy's, sign included: the key as given at each key time, composed
    with the rotation from it between and outside the key times. The curve does not depend on
    the keys' signs (``q`` and ``-q`` are the same key). A spline pickles and deep-copies
    (rebuilt from its arguments: the same values, bit for bit).

    The curve is the Rust ``CubicSpline`` on S3, which is scipy's construction solved to a
    relative residual of 1e-14 (it agrees with scipy to about 1e-11).

    Beyond scipy:

    - ``end="scipy"`` (the default for open splines: the end rates are the end segments' mean
      rates), ``"natural"``
      (zero angular acceleration at the ends) or ``"clamped"`` (the body-frame angular
      velocities ``start_velocity`` and ``end_velocity`` at the first and last key);
    - ``closed=True``: a C2 loop through the keys; ``times`` then has one more entry than
      ``rotations``, the time at which the spline is back at the first key (no ends: ``end``
      must be left out or ``"natural"``). Its quaternions repeat with the period.

    >>> import numpy as np
    >>> from spherekit import RotationSpline
    >>> from scipy.spatial.transform import Rotation
    >>> keys = Rotation.from_euler("xyz", [[0, 0, 0], [10, 20, 30], [40, 10, 0], [0, 40, 40]], degrees=True)
    >>> spline = RotationSpline([0, 1, 2, 4], keys)
    >>> spline([0.5, 3.0]).as_quat().shape
    (2, 4)
    >>> rate = spline([0.5, 3.0], 1)          # body-frame angular rate, rad per time unit
    >>> import scipy.spatial.transform as sst
    >>> bool(np.allclose(rate, sst.RotationSpline([0, 1, 2, 4], keys)([0.5, 3.0], 1), atol=1e-10))
    True
    >>> import pickle
    >>> bool((pickle.loads(pickle.dumps(spline))(3.0).as_quat() == spline(3.0).as_quat()).all())
    True
    """

    def __init__(
        self,
        times,
        rotations,
        *,
        end=None,
        closed=False,
        start_velocity=None,
        end_velocity=None,
        scalar_first=False,
        start_rate=None,
        end_rate=None,
    ):
        # `start_rate`/`end_rate`: the earlier names of `start_velocity`/`end_velocity`.
        start_velocity = _renamed("start_velocity", start_velocity, "start_rate", start_rate)
        end_velocity = _renamed("end_velocity", end_velocity, "end_rate", end_rate)
        q, array = _quats(rotations, "RotationSpline")
        if len(q) == 1:
            raise ValueError("`rotations` must contain at least 2 rotations.")
        times = _checked_times(times, len(q), closed)
        scalar_first = bool(scalar_first)
        native_end = ("natural" if closed else "scipy") if end is None else end
        self._native = _spherekit._CubicRotations(
            times,
            q,
            end=native_end,
            closed=closed,
            start_velocity=start_velocity,
            end_velocity=end_velocity,
            scalar_first=scalar_first and array,
        )
        self._keep(times, rotations, q, array, scalar_first, dict(
            end=end, closed=closed, start_velocity=start_velocity, end_velocity=end_velocity,
            scalar_first=scalar_first))

    def __call__(self, times, order=0):
        """The interpolated rotations (``order=0``), body-frame angular rates (1, rad per time
        unit) or angular accelerations (2) at ``times`` (a number or a 1-D array; NaN is a
        ``ValueError``)."""
        out = self._native(times, order, scalar_first=self._scalar_first and _Rotation is None)
        return _rotations(out) if order == 0 else out



class SmoothRotationSpline(_Keyed):
    """The smoothing spline of noisy rotations, called as ``RotationSpline`` is.

    ``SmoothRotationSpline(times, rotations, smoothing="gcv", weights=None)`` fits the cubic
    spline of ``RotationSpline``'s family (natural ends) to rotations measured at ``times``
    (a scipy ``Rotation``, or an ``(n, 4)`` quaternion array, scalar last or with
    ``scalar_first=True`` scalar first): the curve minimising
    ``Σ wᵢ·θᵢ² + λ·∫|v″|²``, with ``θᵢ`` the rotation angle between the curve at ``tᵢ`` and
    sample ``i`` (``q`` and ``-q`` are the same sample) and ``v`` the curve in the tangent
    space of its keys. About a single axis this is scipy's
    ``make_smoothing_spline(times, angle, weights, lam)`` of the rotation angle.

    - ``smoothing``: λ ≥ 0 (a number), ``"gcv"`` (generalised cross-validation, the default)
      or ``{"rms": σ}`` (the λ whose weighted RMS residual is σ radians);
    - ``weights``: one positive number per sample (default 1);
    - ``max_error`` (radians) or ``keys`` (a count): keys at fewer sample times, the fewest
      within ``max_error`` of every sample or that many (λ then defaults to 0; not with
      ``"gcv"``).

    ``spline(times, order=0|1|2)`` returns a ``Rotation`` (an ``(m, 4)`` array without scipy),
    the body-frame angular rate or the body-frame angular acceleration, as
    ``RotationSpline``; outside the sample times the end segments' cubics continue. The
    attributes ``times`` and ``rotations`` are the samples as given, ``fit_info`` the fit
    (``lambda``, ``rms``, ``max``, ``keys``, ``key_times``, ``iterations``, ``edf``,
    ``residuals``). Bad input raises ``ValueError`` naming the option (``fit.smoothing: …``,
    ``fit.weights[3]: …``). A spline pickles and deep-copies.

    >>> import numpy as np
    >>> from scipy.spatial.transform import Rotation
    >>> from spherekit import SmoothRotationSpline
    >>> t = np.arange(40) * 0.1
    >>> noise = 0.01 * np.sin(7.3 * np.arange(40))
    >>> samples = Rotation.from_rotvec(np.outer(0.5 * t + noise, [0, 0, 1]))
    >>> spline = SmoothRotationSpline(t, samples, smoothing=0.01)
    >>> spline([1.0, 2.0]).as_rotvec().shape
    (2, 3)
    >>> bool(spline.fit_info["rms"] < 0.01)
    True
    """

    def __init__(
        self,
        times,
        rotations,
        smoothing="gcv",
        weights=None,
        *,
        max_error=None,
        keys=None,
        scalar_first=False,
    ):
        q, array = _quats(rotations, "RotationSpline")
        if len(q) == 1:
            raise ValueError("`rotations` must contain at least 2 rotations.")
        times = _checked_times(times, len(q), False)
        scalar_first = bool(scalar_first)
        fit = {"smoothing": smoothing}
        if weights is not None:
            fit["weights"] = np.asarray(weights, dtype=float).tolist()
        if max_error is not None:
            fit["max_error"] = max_error
        if keys is not None:
            fit["keys"] = keys
        self._curve = Curve(
            "cubic",
            q,
            knots=times,
            fit=fit,
            extrapolate="segment",
            scalar_first=scalar_first and array,
        )
        self._keep(times, rotations, q, array, scalar_first, dict(
            smoothing=smoothing, weights=weights, max_error=max_error, keys=keys,
            scalar_first=scalar_first))

    @property
    def fit_info(self):
        """The fit: a dict of ``lambda``, ``rms``, ``max`` (radians), ``keys``, ``key_times``,
        ``iterations``, ``edf`` and ``residuals`` (each sample's rotation angle from the
        curve)."""
        return self._curve.fit_info

    def __call__(self, times, order=0):
        """The rotations (``order=0``), body-frame angular rates (1, rad per time unit) or
        angular accelerations (2) at ``times`` (a number or a 1-D array; NaN is a
        ``ValueError``)."""
        if order == 0:
            out = self._curve(times)
            if _Rotation is not None and self._scalar_first and self._array_keys:
                out = np.roll(out, -1, axis=-1)  # [w, x, y, z] as given -> scipy's [x, y, z, w]
            return _rotations(out)
        if order == 1:
            return self._curve.angular_velocity(times, frame="body")
        if order == 2:
            return self._curve.angular_acceleration(times, frame="body")
        raise ValueError("`order` must be 0, 1 or 2.")



class Slerp(_Keyed):
    """Spherical linear interpolation of rotations.

    A drop-in for ``scipy.spatial.transform.Slerp``: the same constructor (a scipy
    ``Rotation``; an ``(n, 4)`` quaternion array is accepted too, scalar last ``[x, y, z, w]``
    or scalar first with ``scalar_first=True``), the same call returning a ``Rotation`` (an
    ``(m, 4)`` array in the order of ``scalar_first`` without scipy), the same errors,
    including the ``ValueError`` for times outside the key times (NaN included), and scipy's
    attributes ``times``, ``timedelta``, ``rotations`` (the keys but the last, as scipy keeps
    them) and ``rotvecs`` (the rotation vectors between consecutive keys). Consecutive keys are
    joined by the shortest rotation, as in scipy. The curve is the Rust ``GeodesicSpline`` on
    S3; its quaternions are scipy's, sign included (the key starting the segment composed with
    the rotation from it; at a key time, the segment ending there). A ``Slerp`` pickles and
    deep-copies (rebuilt from its arguments: the same values, bit for bit).

    >>> from spherekit import Slerp
    >>> from scipy.spatial.transform import Rotation
    >>> slerp = Slerp([0, 2], Rotation.from_euler("z", [[0], [90]], degrees=True))
    >>> round(float(slerp(1.0).as_euler("xyz", degrees=True)[2]), 9)
    45.0
    >>> slerp(3.0)
    Traceback (most recent call last):
        ...
    ValueError: Interpolation times must be within the range [0.0, 2.0], both inclusive.
    """

    def __init__(self, times, rotations, *, scalar_first=False):
        q, array = _quats(rotations, "Slerp")
        if len(q) <= 1:
            raise ValueError("`rotations` must be a sequence of at least 2 rotations.")
        times = np.asarray(times, dtype=float)
        if times.ndim != 1:
            raise ValueError(
                "Expected times to be specified in a 1 dimensional array, got "
                f"{times.ndim} dimensions."
            )
        if times.shape[0] != len(q):
            raise ValueError(
                "Expected number of rotations to be equal to number of timestamps "
                f"given, got {len(q)} rotations and {times.shape[0]} timestamps."
            )
        timedelta = np.diff(times)
        if (timedelta <= 0).any():
            raise ValueError("Times must be in strictly increasing order.")
        scalar_first = bool(scalar_first)
        self._native = _spherekit._SlerpRotations(times, q, scalar_first=scalar_first and array)
        self._keep(times, rotations, q, array, scalar_first, dict(scalar_first=scalar_first))
        self.timedelta = timedelta

    @functools.cached_property
    def _keys(self):
        return _key_rotations(self._args[1], self._array_keys, self._scalar_first)

    @functools.cached_property
    def rotations(self):
        """The keys but the last (as scipy's ``Slerp.rotations``): a ``Rotation`` (an array
        without scipy)."""
        return self._keys[:-1]

    @functools.cached_property
    def rotvecs(self):
        """The rotation vectors from each key to the next, ``(n - 1, 3)`` (scipy's
        ``Slerp.rotvecs``; needs scipy)."""
        if _Rotation is None:  # pragma: no cover - exercised only without scipy
            raise AttributeError("Slerp.rotvecs needs scipy")
        return (self._keys[:-1].inv() * self._keys[1:]).as_rotvec()

    def __call__(self, times):
        """The interpolated rotations at ``times`` (a number or a 1-D array within the key
        times)."""
        return _rotations(self._native(times, scalar_first=self._scalar_first and _Rotation is None))

