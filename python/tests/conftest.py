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


@pytest.fixture(scope="session")
def cli():
    """The `spherekit` CLI of this checkout (`cargo build --release -p spherekit-cli`, incremental
    after the module's own build), to compare the module's output with. The suite runs where the
    module is built, so cargo is there: its absence is a failure, not a skip."""
    import json
    import shutil
    import subprocess

    cargo = shutil.which("cargo")
    assert cargo is not None, "cargo is not on PATH: no CLI to compare the module with"
    build = subprocess.run(
        [cargo, "build", "--release", "--locked", "--quiet", "-p", "spherekit-cli", "--bin", "spherekit",
         "--message-format=json"],
        cwd=REPO, capture_output=True, text=True, check=True,
    )
    for line in build.stdout.splitlines():
        message = json.loads(line)
        if message.get("reason") == "compiler-artifact" and message.get("executable"):
            return message["executable"]
    raise AssertionError("cargo built no spherekit executable")
