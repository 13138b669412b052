# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
import os

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def walk(rng, n, max_angle):
    """Keys of a random walk on SO(3), steps of 0.1 to `max_angle` rad (as the core's scipy
    fixture, scripts/scipy_rotation_spline_fixture.py)."""
    rots = [Rotation.random(random_state=rng)]
    for _ in range(n - 1):
        axis = rng.normal(size=3)
        axis /= np.linalg.norm(axis)
        rots.append(rots[-1] * Rotation.from_rotvec(axis * rng.uniform(0.1, max_angle)))
    return Rotation.concatenate(rots)


def random_times(rng, n):
    return np.concatenate([[rng.uniform(-1, 1)], rng.uniform(0.3, 2.0, n - 1)]).cumsum()


@pytest.fixture
def rng():
    return np.random.default_rng(20261201)
