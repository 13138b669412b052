#!/usr/bin/env python3
# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""Writes the two fitted-curve examples, examples/fit-noisy-s2.json and fit-noisy-s3.json.

Each is a smooth track sampled at equally spaced times (S²: 80 samples 0.05 apart; S³: 64
samples 0.0625 apart) with noise of 1° rms, seeded, so the files are the same on every run
(`python3 scripts/fit_examples.py`):

- S²: a direction whose longitude grows steadily while its latitude swings,
  p(t) = (cos b cos a, cos b sin a, sin b), a = −1.2 + 0.75 t, b = 0.1 + 0.35 sin 1.3 t;
  each sample is p plus a Gaussian tangent vector of 1°/√2 per component (1° rms angle),
  normalised.
- S³: a rotation by yaw, pitch and roll (z, y, x; intrinsic) ψ = 0.9 t, θ = 0.4 sin 1.1 t,
  φ = 0.3 cos 0.7 t, composed with a Gaussian rotation vector of 1°/√3 per component (1° rms
  angle); then about a quarter of the quaternions change sign (the same rotations, as sensors
  report them: the scene canonicalises them).

The smoothing λ is given (0.02 on S², 0.01 on S³: about what generalised cross-validation
chooses for these samples) rather than "gcv", so that the playground rebuilds the curve at
once while a sample is dragged; its GCV button runs the search.

tests/golden/fit_noisy_s2.json and fit_noisy_s3.json are links to these files (the golden
images and the playground's example menu read the golden scenes).
"""

import json
import math
import pathlib
import random

ROOT = pathlib.Path(__file__).resolve().parent.parent
NOISE = math.radians(1.0)


def qmul(a, b):
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return (
        aw * bw - ax * bx - ay * by - az * bz,
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
    )


def axis_angle(v):
    angle = math.sqrt(sum(x * x for x in v))
    if angle == 0.0:
        return (1.0, 0.0, 0.0, 0.0)
    s = math.sin(angle / 2) / angle
    return (math.cos(angle / 2), v[0] * s, v[1] * s, v[2] * s)


def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def rounded(v):
    return [round(x, 5) + 0.0 for x in v]


def s2_scene(rng, times):
    points = []
    for t in times:
        a, b = -1.2 + 0.75 * t, 0.1 + 0.35 * math.sin(1.3 * t)
        p = (math.cos(b) * math.cos(a), math.cos(b) * math.sin(a), math.sin(b))
        east = (-math.sin(a), math.cos(a), 0.0)
        north = (-math.sin(b) * math.cos(a), -math.sin(b) * math.sin(a), math.cos(b))
        g1, g2 = (rng.gauss(0.0, NOISE / math.sqrt(2)) for _ in range(2))
        points.append(rounded(unit([p[k] + g1 * east[k] + g2 * north[k] for k in range(3)])))
    return points


def s3_scene(rng, times):
    points = []
    for t in times:
        yaw, pitch, roll = 0.9 * t, 0.4 * math.sin(1.1 * t), 0.3 * math.cos(0.7 * t)
        q = qmul(
            qmul(axis_angle((0.0, 0.0, yaw)), axis_angle((0.0, pitch, 0.0))),
            axis_angle((roll, 0.0, 0.0)),
        )
        q = qmul(q, axis_angle([rng.gauss(0.0, NOISE / math.sqrt(3)) for _ in range(3)]))
        if rng.random() < 0.25:
            q = tuple(-x for x in q)
        points.append(rounded(unit(q)))
    return points


def write(name, scene):
    """The scene as the other scenes are written: one point per line, short lists on one line."""
    one = lambda v: json.dumps(v, separators=(", ", ": "))
    fields = []
    for key, value in scene.items():
        if key == "points":
            rows = ",\n".join(f"    {one(p)}" for p in value)
            fields.append(f'  "points": [\n{rows}\n  ]')
        else:
            fields.append(f"  {json.dumps(key)}: {one(value)}")
    text = "{\n" + ",\n".join(fields) + "\n}\n"
    (ROOT / "examples" / name).write_text(text, encoding="utf-8")


def main():
    s2_times = [round(i * 0.05, 10) for i in range(80)]
    s3_times = [i * 0.0625 for i in range(64)]
    write(
        "fit-noisy-s2.json",
        {
            "space": "S2",
            "method": "cubic",
            "points": s2_scene(random.Random(2026), s2_times),
            "knots": s2_times,
            "fit": {"smoothing": 0.02},
            "view": {"plot": "speed", "legend": True},
        },
    )
    write(
        "fit-noisy-s3.json",
        {
            "space": "S3",
            "method": "cubic",
            "points": s3_scene(random.Random(2027), s3_times),
            "knots": s3_times,
            "fit": {"smoothing": 0.01},
            "view": {"plot": "speed", "legend": True},
        },
    )


if __name__ == "__main__":
    main()
