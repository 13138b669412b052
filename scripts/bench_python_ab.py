#!/usr/bin/env python3
# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""Times several builds of the extension against each other, interleaved in one process.

    bash scripts/setup-python.sh python scripts/bench_python_ab.py DIR [DIR ...]

Each DIR holds one build's `_spherekit.abi3.so` (copy `target/release/lib_spherekit.so` there
after `cargo build --release -p spherekit-py`). On a loaded machine two runs of
bench_python.py can differ by 2x; taking turns in one process (the best of R rounds, R from
the environment, default 20) compares builds under the same conditions. The curves and times
are bench_python.py's; evaluation is on one thread (SPHEREKIT_THREADS=1) unless set.
"""

import importlib.util
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
from bench_python import walk  # noqa: E402

os.environ.setdefault("SPHEREKIT_THREADS", "1")


def load(directory):
    spec = importlib.util.spec_from_file_location("_spherekit", os.path.join(directory, "_spherekit.abi3.so"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def main():
    rng = np.random.default_rng(20261201)
    keys = walk(rng, 20, 1.0).as_quat()
    times = np.concatenate([[0.0], rng.uniform(0.3, 2.0, 19)]).cumsum()
    t = np.linspace(times[0], times[-1], 200_000)
    big = walk(rng, 1000, 1.0).as_quat()
    big_times = np.concatenate([[0.0], rng.uniform(0.3, 2.0, 999)]).cumsum()
    builds = [load(d) for d in sys.argv[1:]]
    rows = ["(t), (t, 1), (t, 2)", "(t)", "(t, 1)", "(t, 2)", "Slerp (t)",
            "RotationSpline construction, 1 000 keys", "Slerp construction, 1 000 keys"]
    best = {}
    for _ in range(int(os.environ.get("R", "20"))):
        for k, m in enumerate(builds):
            s, sl = m._CubicRotations(times, keys), m._SlerpRotations(times, keys)
            calls = [lambda: (s(t, 0), s(t, 1), s(t, 2)), lambda: s(t, 0), lambda: s(t, 1),
                     lambda: s(t, 2), lambda: sl(t), lambda: m._CubicRotations(big_times, big),
                     lambda: m._SlerpRotations(big_times, big)]
            for row, call in zip(rows, calls):
                n = 10 if "construction" in row else 1
                t0 = time.perf_counter()
                for _ in range(n):
                    call()
                best[k, row] = min(best.get((k, row), np.inf), (time.perf_counter() - t0) / n)
    print("| what | " + " | ".join(sys.argv[1:]) + " |")
    print("|---|" + "---:|" * len(builds))
    for row in rows:
        print(f"| {row} | " + " | ".join(f"{best[k, row] * 1e3:.3f} ms" for k in range(len(builds))) + " |")


if __name__ == "__main__":
    main()
