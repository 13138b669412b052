# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""Keys with rates: the cubic's `velocities` (one per key) through `spherekit.Curve`."""
import pickle

import numpy as np
import pytest

import spherekit
from conftest import random_times, walk


def same_rotations(a, b):
    """The largest difference of two quaternion arrays up to the sign of each row."""
    sign = np.sign(np.sum(a * b, axis=1))[:, None]
    return np.abs(a - sign * b).max()


def test_keys_and_body_rates_are_interpolated(rng):
    keys = walk(rng, 6, 1.0)
    times = random_times(rng, 6)
    rates = rng.normal(size=(6, 3))
    c = spherekit.Curve("cubic", keys.as_quat(), knots=times, velocities=rates, frame="body")
    assert same_rotations(c(times), keys.as_quat()) < 1e-12
    np.testing.assert_allclose(c.angular_velocity(times, frame="body"), rates, rtol=0, atol=1e-12)
    # The same rates in the space frame (ω = R ω_body) give the same curve.
    space = spherekit.Curve("cubic", keys.as_quat(), knots=times, velocities=keys.apply(rates))
    t = np.linspace(times[0], times[-1], 101)
    assert same_rotations(space(t), c(t)) < 1e-12
    np.testing.assert_allclose(space.angular_velocity(times), keys.apply(rates), rtol=0, atol=1e-12)
    assert c.info["iterations"] == 0
    again = pickle.loads(pickle.dumps(c))
    np.testing.assert_array_equal(again(t), c(t))


def test_tangent_velocities_on_s2_and_a_closed_loop(rng):
    keys = np.array([[1.0, 0, 0], [0, 1, 0], [0, 0.6, 0.8], [0.6, 0, 0.8]])
    raw = rng.normal(size=keys.shape)
    velocities = raw - np.sum(raw * keys, axis=1)[:, None] * keys
    for closed, knots in [(False, [0, 1, 2.5, 3]), (True, [0, 1, 2.5, 3, 4])]:
        c = spherekit.Curve("cubic", keys, knots=knots, closed=closed, velocities=velocities)
        np.testing.assert_allclose(c(knots[:4]), keys, rtol=0, atol=1e-12)
        np.testing.assert_allclose(c(knots[:4], 1), velocities, rtol=0, atol=1e-12)


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"velocities": np.zeros((2, 3))}, "params.velocities: must have one velocity per point: expected 3, got 2"),
        ({"velocities": [[0, 0, 1], [0, np.nan, 1], [0, 0, 1]]}, "params.velocities[1]: must be a list of finite numbers"),
        ({"velocities": np.zeros((3, 4))}, "params.velocities[0]: must be an angular velocity [x, y, z], got 4 numbers"),
        ({"velocities": np.zeros((3, 3)), "end": "clamped", "start_velocity": [0, 0, 1], "end_velocity": [0, 0, 1]},
         "params.velocities: gives the velocity at every key"),
    ],
)
def test_bad_rates_are_a_value_error(kwargs, message):
    keys = [[0, 0, 0, 1], [0, 0, 0.6, 0.8], [0.6, 0, 0, 0.8]]
    with pytest.raises(ValueError) as e:
        spherekit.Curve("cubic", keys, **kwargs)
    assert message in str(e.value) and "\n" not in str(e.value)
