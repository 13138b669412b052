#!/usr/bin/env python3
# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""Writes crates/spherekit/tests/data/rotation_spline_scipy.json: scipy's RotationSpline on a few
random key sets with non-uniform times, for the `scipy_agreement` test of tests/it/cubic.rs.

    python3 -m venv .tools/pyvenv && .tools/pyvenv/bin/pip install scipy==1.17.1 numpy==2.4.6
    .tools/pyvenv/bin/python scripts/scipy_rotation_spline_fixture.py

Each case: times, keys (scalar first, w x y z, as given to scipy), ~50 parameters across the
domain (including the key times), scipy's rotations there (w x y z, sign as scipy returns
them), body-frame angular rates `rs(t, 1)` and accelerations `rs(t, 2)`. `converged_to` is the
largest change of scipy's angular rates when its fixed-point iteration (10 steps, stopping at
1e-9) is continued to 200 steps: how far scipy's own answer is from the solution of its
equations.
"""

import json
import os

import numpy as np
import scipy
from scipy.spatial.transform import Rotation, RotationSpline

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "crates", "spherekit", "tests", "data", "rotation_spline_scipy.json")


def case(rng, n, max_angle, name):
    dt = rng.uniform(0.3, 2.0, n - 1)
    times = np.concatenate([[rng.uniform(-1, 1)], dt]).cumsum()
    rot = [Rotation.random(random_state=rng)]
    for _ in range(n - 1):
        axis = rng.normal(size=3)
        axis /= np.linalg.norm(axis)
        angle = rng.uniform(0.1, max_angle)
        rot.append(rot[-1] * Rotation.from_rotvec(axis * angle))
    rots = Rotation.concatenate(rot)
    spline = RotationSpline(times, rots)
    ts = np.sort(np.concatenate([np.linspace(times[0], times[-1], 50 - n), times]))
    q = spline(ts).as_quat()[:, [3, 0, 1, 2]]
    rate = spline(ts, 1)
    acc = spline(ts, 2)

    class Long(RotationSpline):
        MAX_ITER = 200
        TOL = 1e-15

    long = Long(times, rots)
    converged_to = float(np.abs(long(ts, 1) - rate).max())
    return {
        "name": name,
        "times": times.tolist(),
        "keys": rots.as_quat()[:, [3, 0, 1, 2]].tolist(),
        "ts": ts.tolist(),
        "quats": q.tolist(),
        "rates": rate.tolist(),
        "accelerations": acc.tolist(),
        "converged_to": converged_to,
    }


def main():
    rng = np.random.default_rng(20261201)
    cases = [
        case(rng, 4, 1.0, "4 keys, steps up to 1 rad"),
        case(rng, 7, 1.5, "7 keys, steps up to 1.5 rad"),
        case(rng, 20, 1.0, "20 keys, steps up to 1 rad"),
        case(rng, 20, 2.0, "20 keys, steps up to 2 rad"),
    ]
    data = {
        "generator": "scripts/scipy_rotation_spline_fixture.py",
        "scipy": scipy.__version__,
        "numpy": np.__version__,
        "cases": cases,
    }
    with open(OUT, "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")
    for c in cases:
        print(c["name"], "scipy converged_to", c["converged_to"])


if __name__ == "__main__":
    main()
