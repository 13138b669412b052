# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""Closed rotation splines on full-turn orbits: closed in SO(3), not on S3. Keys a full turn of
yaw round end on the far side of the first key's quaternion; the loop goes on to -q0 (the same
rotation) rather than turning back the long way (before the core's `RotationLoop`, 8 keys 45°
apart turned forward to 315° and back: peak |ω| 6.65 rad/s instead of 0.785)."""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import spherekit

CASES = [(n, 1) for n in (3, 4, 8, 16, 32)] + [(8, 2), (16, 2), (32, 2)]


def orbit(n, laps=1, direction=1, wobble_deg=0.0, rng=None):
    """`n` keys evenly spaced over `laps` full turns of yaw (`direction` ±1), each tilted by a
    random pitch and roll of at most `wobble_deg`."""
    yaw = direction * 2 * np.pi * laps * np.arange(n) / n
    tilt = np.zeros((n, 2)) if rng is None else np.radians(rng.uniform(-wobble_deg, wobble_deg, size=(n, 2)))
    return Rotation.from_euler("ZYX", np.column_stack([yaw, tilt]))


def angle(a, b):
    return (a.inv() * b).magnitude().max()


@pytest.mark.parametrize("n, laps", CASES)
@pytest.mark.parametrize("direction", [1, -1])
def test_closed_rotation_spline_on_an_even_orbit_turns_at_constant_speed(n, laps, direction):
    period = 2.0 * n  # two time units per key
    times = np.linspace(0, period, n + 1)
    spline = spherekit.RotationSpline(times, orbit(n, laps, direction), closed=True)
    t = np.linspace(0, period, 4001)
    speed = np.linalg.norm(spline(t, 1), axis=1)
    nominal = 2 * np.pi * laps / period
    # Within 1 % of 2π·laps/T everywhere (measured: within 1e-14).
    assert np.abs(speed / nominal - 1).max() < 0.01
    # About the vertical, in the orbit's direction.
    rates = spline(t, 1)
    assert np.abs(rates[:, :2]).max() < 1e-9 and (np.sign(rates[:, 2]) == direction).all()
    # The rotation at T is the rotation at 0 (approached from inside the period), the rate too.
    assert angle(spline(period - 1e-9), spline(0.0)) < 1e-8
    assert np.abs(spline(period - 1e-9, 1) - spline(0.0, 1)).max() < 1e-7
    # And the loop goes on: a period later, the same rotations.
    assert angle(spline(t + period), spline(t)) < 1e-12


@pytest.mark.parametrize("n, laps", CASES)
@pytest.mark.parametrize("direction", [1, -1])
def test_closed_rotation_spline_on_a_wobbling_orbit_closes_the_short_way(rng, n, laps, direction):
    period = float(n)
    times = np.linspace(0, period, n + 1)
    keys = orbit(n, laps, direction, wobble_deg=5.0, rng=rng)
    spline = spherekit.RotationSpline(times, keys, closed=True)
    t = np.linspace(0, period, 4001)
    speed = np.linalg.norm(spline(t, 1), axis=1)
    # No turning back the long way on the last segment: the peak speed is of the order of the
    # steps between neighbouring keys (the seam's included), where turning back would take
    # the last segment through most of a turn (8 keys: 8.5 times the step).
    steps = (keys.inv() * keys[np.r_[1:n, 0]]).magnitude() / np.diff(times)
    assert speed.max() < 1.6 * steps.max()
    yaw_rate = spline(t, 1) @ np.array([0.0, 0.0, 1.0])
    assert (np.sign(yaw_rate) == direction).all()
    # Through every key, and back at the first one.
    assert angle(spline(times[:-1]), keys) < 1e-12
    assert angle(spline(period - 1e-9), keys[0]) < 1e-8
    assert np.abs(spline(period - 1e-9, 1) - spline(0.0, 1)).max() < 1e-6
    # The quaternions at the key times are the keys as given, in every lap.
    q = keys.as_quat()
    for lap in (0, 1, -2):
        np.testing.assert_allclose(spline(times[:-1] + lap * period).as_quat(), q, rtol=0, atol=1e-15)


@pytest.mark.parametrize("n, laps", [(3, 1), (8, 1), (32, 1), (16, 2)])
def test_closed_cubic_curve_on_an_orbit_turns_at_constant_speed(n, laps):
    """The same orbit through `spherekit.Curve` (the scene crate's closed cubic)."""
    period = float(n)
    keys = orbit(n, laps).as_quat()
    curve = spherekit.Curve("cubic", keys, closed=True, knots=np.linspace(0, period, n + 1))
    t = np.linspace(0, period, 2001)
    speed = np.linalg.norm(curve.angular_velocity(t), axis=1)
    nominal = 2 * np.pi * laps / period
    assert np.abs(speed / nominal - 1).max() < 0.01
    end = Rotation.from_quat(curve(period))
    assert angle(end, Rotation.from_quat(curve(0.0))) < 1e-12
