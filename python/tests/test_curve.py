# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""`spherekit.Curve` for every registered method and sphere, against the scene layer (the
CLI's `sample`), numpy-quaternion's squad, and the scalar orders."""

import glob
import json
import os

import numpy as np
import pytest
import quaternion

import spherekit
from conftest import REPO, walk

GOLDEN = sorted(glob.glob(os.path.join(REPO, "tests", "golden", "*.json")))


def curves_of(scene):
    """The single-curve scenes a golden file holds (its `curves` list split up)."""
    if "curves" not in scene:
        yield scene
        return
    for c in scene["curves"]:
        yield {"space": scene["space"], **c}


def curve_args(scene):
    kwargs = dict(scene.get("params", {}))
    for key in ("knots", "closed", "canonicalize", "parametrization", "extrapolate", "fit"):
        if key in scene:
            kwargs[key] = scene[key]
    return scene["method"], np.array(scene["points"], dtype=float), dict(space=scene["space"], scalar_first=True, **kwargs)


def test_every_method_has_a_golden_scene():
    methods = {m["id"] for m in spherekit.methods()}
    seen = {c["method"] for path in GOLDEN for c in curves_of(json.load(open(path)))}
    assert methods <= seen, methods - seen


@pytest.mark.parametrize("path", GOLDEN, ids=os.path.basename)
def test_curve_equals_the_scene_layer(path):
    for scene in curves_of(json.load(open(path))):
        method, points, kwargs = curve_args(scene)
        curve = spherekit.Curve(method, points, **kwargs)
        t0, t1 = curve.domain
        t = np.linspace(t0, t1, 37)
        scene = {k: v for k, v in scene.items() if k not in ("color", "view", "samples")}
        # The golden scenes are the CLI's format: quaternions scalar first.
        out = spherekit.sample({**scene, "eval_at": t.tolist()}, deriv=True, scalar_first=True)
        # The same library on both sides; the scene's parameters pass through JSON text, whose
        # parsing may round the last bit, so the values agree to rounding rather than exactly.
        same = lambda a, b: np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-12)  # noqa: E731
        assert out["domain"] == [t0, t1]
        same(curve(t), out["points"])
        same(curve(t, 1), out["velocity"])
        same(curve(t, 2), out["acceleration"])
        if scene["space"] == "S3":
            same(curve.angular_velocity(t), out["angular_velocity"])
            same(curve.angular_acceleration(t), out["angular_acceleration"])
        if "controls" in out:
            np.testing.assert_array_equal(curve.controls, out["controls"])
        assert curve.info == out.get("info", {})
        joints = curve.joints
        assert joints[0] == t0 and joints[-1] == t1
        report = curve.continuity()
        assert len(report) == max(len(joints) - 2, 0) or all("class" in j for j in report)


def test_space_is_inferred_from_the_width(rng):
    assert spherekit.Curve("geodesic", rng.normal(size=(3, 3))).space == "S2"
    assert spherekit.Curve("geodesic", rng.normal(size=(3, 4))).space == "S3"
    assert spherekit.Curve("geodesic", rng.normal(size=(3, 6))).space == "S5"
    assert spherekit.Curve("geodesic", rng.normal(size=(3, 2))).space == "S1"


def test_scalar_orders_round_trip(rng):
    keys = walk(rng, 6, 1.0).as_quat()  # scalar last
    last = spherekit.Curve("cubic", keys, end="scipy")
    first = spherekit.Curve("cubic", keys[:, [3, 0, 1, 2]], scalar_first=True, end="scipy")
    t = np.linspace(*last.domain, 101)
    for order in (0, 1, 2):
        np.testing.assert_array_equal(last(t, order)[:, [3, 0, 1, 2]], first(t, order))
    np.testing.assert_array_equal(last.points[:, [3, 0, 1, 2]], first.points)
    np.testing.assert_array_equal(last.angular_velocity(t, "body"), first.angular_velocity(t, "body"))
    # The keys come back as given (already canonical, unit): the round trip is exact.
    canonical = last.points
    again = spherekit.Curve("cubic", canonical, end="scipy").points
    np.testing.assert_allclose(again, canonical, rtol=0, atol=1e-15)


def test_squad_equals_numpy_quaternion(rng):
    keys = walk(rng, 20, 1.0).as_quat()[:, [3, 0, 1, 2]]  # w x y z
    for k in range(1, len(keys)):  # canonical keys: numpy-quaternion's squad does not flip
        if np.dot(keys[k - 1], keys[k]) < 0:
            keys[k] = -keys[k]
    times = np.arange(len(keys), dtype=float)
    t = np.linspace(0, len(keys) - 1, 2001)
    ours = spherekit.Curve("squad", keys, scalar_first=True)(t)
    theirs = quaternion.as_float_array(quaternion.squad(quaternion.as_quat_array(keys), times, t))
    # Up to the sign of the whole quaternion (the same rotation).
    sign = np.sign(np.sum(ours * theirs, axis=1))[:, None]
    assert np.abs(ours - sign * theirs).max() < 1e-12


def test_angular_rates_frames_and_spheres(rng):
    keys = walk(rng, 5, 1.0)
    c = spherekit.Curve("cubic", keys.as_quat(), knots=[0, 1, 2, 3, 5], end="scipy")
    t = np.linspace(0, 5, 11)
    q = keys.__class__.from_quat(c(t))
    body, space = c.angular_velocity(t, frame="body"), c.angular_velocity(t)
    np.testing.assert_allclose(q.apply(body), space, atol=1e-13)
    with pytest.raises(ValueError, match="frame"):
        c.angular_velocity(t, frame="world")
    with pytest.raises(ValueError, match="S3"):
        spherekit.Curve("geodesic", np.eye(3)).angular_velocity(t)


def test_outside_the_domain_is_clamped_and_nan_raises():
    c = spherekit.Curve("geodesic", [[1, 0, 0], [0, 1, 0]], knots=[0, 2])
    np.testing.assert_array_equal(c([-1.0, 3.0]), c([0.0, 2.0]))
    s3 = spherekit.Curve("squad", [[0, 0, 0, 1], [0, 0, 0.6, 0.8], [0.6, 0, 0, 0.8]])
    calls = [
        (lambda: c([1.0, np.nan]), r"^t\[1\]: NaN is not a parameter$"),
        (lambda: c(np.nan, 1), r"^t: NaN is not a parameter$"),
        (lambda: s3.angular_velocity([0.5, np.nan, np.nan]), r"^t\[1\]: NaN"),
        (lambda: s3.angular_acceleration(np.array([np.nan])), r"^t\[0\]: NaN"),
        (lambda: spherekit.Curve("geodesic", [[1, 0, 0], [0, 1, 0]], extrapolate="error")(np.nan), "^t: NaN"),
    ]
    for call, message in calls:
        with pytest.raises(ValueError, match=message):
            call()


@pytest.mark.parametrize(
    "args, kwargs, message",
    [
        (("geodesic", [[1, 0, 0], [-1, 0, 0]]), {}, "points[0] and points[1] are antipodal"),
        (("geodesic", [[1, 0, 0], [0, 0, 0]]), {}, "points[1] has zero length"),
        (("nope", [[1, 0, 0], [0, 1, 0]]), {}, 'unknown method "nope"'),
        (("squad", [[1, 0, 0], [0, 1, 0]]), {}, '"squad" works on S3'),
        (("geodesic", [[1, 0, 0], [0, 1, 0]]), {"knots": [0, 0]}, "knots"),
        (("beta", [[1, 0, 0], [0, 1, 0], [0, 0, 1]]), {"beta9": 1}, "beta9"),
        (("geodesic", "points"), {}, "(n, d) array"),
        (("geodesic", [[1, 0, 0], [0, 1, 0]]), {"space": "S7"}, "points[0]: has 3 coordinates"),
        (("geodesic", [[1, 0, 0], [0, 1, 0]]), {"gamma": object()}, "cannot pass"),
    ],
)
def test_bad_input_is_a_value_error(args, kwargs, message):
    with pytest.raises(ValueError) as e:
        spherekit.Curve(*args, **kwargs)
    assert message in str(e.value) and "\n" not in str(e.value)


def test_bad_evaluation_arguments():
    c = spherekit.Curve("geodesic", [[1, 0, 0], [0, 1, 0]])
    for call in (lambda: c([[0.5]]), lambda: c(0.5, 3), lambda: c("x")):
        with pytest.raises(ValueError):
            call()


def test_arclength_and_extrapolate_options():
    keys = [[1, 0, 0], [0, 1, 0], [0, 0.6, 0.8], [0.6, 0, 0.8]]
    c = spherekit.Curve("catmull-rom", keys, parametrization="arclength", extrapolate="extend")
    a, b = c.domain
    assert a == 0.0 and b > 0.5
    speed = np.linalg.norm(c(np.linspace(a, b, 50), 1), axis=1)
    np.testing.assert_allclose(speed, 1.0, atol=1e-9)
    # Extended past the end at the end's unit speed, along the end geodesic.
    end = c(b)
    assert abs(np.arccos(np.clip(np.dot(c(b + 0.5), end), -1, 1)) - 0.5) < 1e-9
    held = spherekit.Curve("catmull-rom", keys)
    np.testing.assert_array_equal(held([held.domain[1] + 1], 1), [[0.0, 0.0, 0.0]])
    strict = spherekit.Curve("geodesic", keys[:2], extrapolate="error")
    assert strict(0.5).shape == (3,)
    with pytest.raises(ValueError, match=r"eval_at\[1\]: 2 is outside the domain \[0, 1\]"):
        strict([0.5, 2.0])
    with pytest.raises(ValueError, match='extrapolate: "cycle" repeats a closed curve'):
        spherekit.Curve("geodesic", keys, extrapolate="cycle")


def test_batches_split_over_threads_agree_bit_for_bit(rng, monkeypatch):
    c = spherekit.Curve("squad", walk(rng, 5, 1.0).as_quat())
    t = np.linspace(-0.5, 4.5, 40_000)
    calls = [lambda: c(t), lambda: c(t, 1), lambda: c(t, 2), lambda: c.angular_velocity(t, "body"),
             lambda: c.angular_acceleration(t)]
    for call in calls:
        monkeypatch.setenv("SPHEREKIT_THREADS", "1")
        one = call()
        monkeypatch.setenv("SPHEREKIT_THREADS", "2")
        assert np.array_equal(one, call()) and not np.isnan(one).any()


def test_smoothness_and_derivative_order_are_different_keywords():
    """`smoothness=n` is the blends' Cⁿ order; `curve(t, order)` the derivative order, as scipy's.
    The earlier spellings, `order=n` for the smoothness and a snake_case method id, still give
    the same curve."""
    pts = [[1, 0, 0.3], [0.6, 0.8, 0.4], [-0.2, 1, 0.1], [-0.9, 0.3, -0.2]]
    for method in ["arc-blend", "corner-blend"]:
        c = spherekit.Curve(method, pts, smoothness=3)
        old = spherekit.Curve(method.replace("-", "_"), pts, order=3)
        t = np.linspace(*c.domain, 401)
        for derivative in (0, 1, 2):
            assert (old(t, order=derivative) == c(t, order=derivative)).all(), (method, derivative)
        assert (spherekit.Curve(method, pts)(t, 2) != c(t, 2)).any(), method
        with pytest.raises(ValueError, match="earlier name of params.smoothness"):
            spherekit.Curve(method, pts, order=3, smoothness=3)
    names = {p["name"] for m in spherekit.methods() for p in m["params"]}
    assert "smoothness" in names and "order" not in names
