#!/usr/bin/env python3
# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""Times the `spherekit` Python module against scipy on the same curves, in one run.

    bash scripts/setup-python.sh python scripts/bench_python.py

Rows: numpy arrays in, numpy arrays out (order 0 returns a scipy `Rotation` for both), 20 keys
and 200 000 times for evaluation; 1 000 keys for construction. Each figure is the best of
several repetitions (wall clock: 10 for evaluation, 100 for construction). spherekit splits large batches over the available cores;
the "1 thread" column is the same call with SPHEREKIT_THREADS=1.

After the table: the constructors' native part alone (the Rust class the drop-in calls, given
the (n, 4) array), and the 1 000 keys written to target/bench_python_keys.txt for timing the
core alone on them (`cargo run --release -p spherekit-py --example core_construction`).
"""

import os
import platform
import time

import numpy as np
import scipy
from scipy.spatial.transform import Rotation, RotationSpline as ScipySpline, Slerp as ScipySlerp

import spherekit


def walk(rng, n, max_angle):
    """Keys of a random walk on SO(3): steps of 0.1 to `max_angle` rad about random axes."""
    axes = rng.normal(size=(n, 3))
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    steps = Rotation.from_rotvec(axes * rng.uniform(0.1, max_angle, (n, 1)))
    rots = [Rotation.random(random_state=rng)]
    for k in range(1, n):
        rots.append(rots[-1] * steps[k])
    return Rotation.concatenate(rots)


def best(f, repeat):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return min(times)


def main():
    rng = np.random.default_rng(20261201)
    keys = walk(rng, 20, 1.0)
    times = np.concatenate([[0.0], rng.uniform(0.3, 2.0, 19)]).cumsum()
    t = np.linspace(times[0], times[-1], 200_000)
    ours, theirs = spherekit.RotationSpline(times, keys), ScipySpline(times, keys)
    ours_slerp, theirs_slerp = spherekit.Slerp(times, keys), ScipySlerp(times, keys)
    big = walk(rng, 1000, 1.0)
    big_times = np.concatenate([[0.0], rng.uniform(0.3, 2.0, 999)]).cumsum()
    big_quat = big.as_quat()
    keys_file = os.path.join(os.path.dirname(__file__), "..", "target", "bench_python_keys.txt")
    os.makedirs(os.path.dirname(keys_file), exist_ok=True)
    np.savetxt(keys_file, np.column_stack([big_times, big_quat]), fmt="%.17g")

    def all_orders(s):
        return lambda: (s(t), s(t, 1), s(t, 2))

    rows = [
        ("RotationSpline, 20 keys: (t), (t, 1), (t, 2) at 200 000 times",
         all_orders(ours), all_orders(theirs), 10),
        ("RotationSpline, 20 keys: (t) at 200 000 times", lambda: ours(t), lambda: theirs(t), 10),
        ("RotationSpline, 20 keys: (t, 1) at 200 000 times", lambda: ours(t, 1), lambda: theirs(t, 1), 10),
        ("RotationSpline, 20 keys: (t, 2) at 200 000 times", lambda: ours(t, 2), lambda: theirs(t, 2), 10),
        ("Slerp, 20 keys: (t) at 200 000 times", lambda: ours_slerp(t), lambda: theirs_slerp(t), 10),
        ("RotationSpline construction, 1 000 keys",
         lambda: spherekit.RotationSpline(big_times, big), lambda: ScipySpline(big_times, big), 100),
        ("Slerp construction, 1 000 keys",
         lambda: spherekit.Slerp(big_times, big), lambda: ScipySlerp(big_times, big), 100),
    ]
    # The same curve: agreement on the timed parameters.
    angle = (ours(t).inv() * theirs(t)).magnitude().max()
    rate = np.abs(ours(t, 1) - theirs(t, 1)).max() / np.abs(theirs(t, 1)).max()
    slerp = (ours_slerp(t).inv() * theirs_slerp(t)).magnitude().max()

    print(f"python {platform.python_version()}, numpy {np.__version__}, scipy {scipy.__version__}, "
          f"{platform.machine()}")
    print(f"agreement on the timed curve: RotationSpline angle {angle:.1e} rad, rate {rate:.1e} "
          f"relative; Slerp angle {slerp:.1e} rad")
    print()
    print(f"threads: {os.cpu_count()} available (spherekit splits batches of ≥ 32 768 parameters "
          "over them; SPHEREKIT_THREADS=1 keeps one)")
    print()
    print("| what | spherekit | spherekit, 1 thread | scipy | speed-up | speed-up, 1 thread |")
    print("|---|---:|---:|---:|---:|---:|")
    for label, a, b, repeat in rows:
        os.environ.pop("SPHEREKIT_THREADS", None)
        ta = best(a, repeat)
        os.environ["SPHEREKIT_THREADS"] = "1"
        ta1 = best(a, repeat)
        os.environ.pop("SPHEREKIT_THREADS", None)
        tb = best(b, repeat)
        print(f"| {label} | {ta * 1e3:.2f} ms | {ta1 * 1e3:.2f} ms | {tb * 1e3:.2f} ms "
              f"| {tb / ta:.1f}× | {tb / ta1:.1f}× |")
    native = spherekit._spherekit
    print()
    print("native part of the constructors, 1 000 keys, (n, 4) array in (best of 200): "
          f"RotationSpline {best(lambda: native._CubicRotations(big_times, big_quat), 200) * 1e6:.1f} µs, "
          f"Slerp {best(lambda: native._SlerpRotations(big_times, big_quat), 200) * 1e6:.1f} µs; "
          "the core alone on the same keys: cargo run --release -p spherekit-py --example "
          "core_construction")


if __name__ == "__main__":
    main()
