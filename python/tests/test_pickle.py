# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""`Curve`, `RotationSpline` and `Slerp` pickle (every protocol) and deep-copy: rebuilt from their
constructor arguments, they give the same samples bit for bit."""

import copy
import pickle

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import spherekit
from conftest import random_times, walk


def copies(obj):
    """The object through every pickle protocol and through `copy.deepcopy` and `copy.copy`."""
    for protocol in range(pickle.HIGHEST_PROTOCOL + 1):
        yield f"pickle protocol {protocol}", pickle.loads(pickle.dumps(obj, protocol=protocol))
    yield "deepcopy", copy.deepcopy(obj)
    yield "copy", copy.copy(obj)


def curves(rng):
    keys = walk(rng, 6, 1.0).as_quat() * rng.choice([-1.0, 1.0], size=(6, 1))
    knots = random_times(rng, 6)
    loop = walk(rng, 5, 0.8).as_quat()
    return [
        spherekit.Curve("geodesic", [[1, 0, 0], [0, 1, 0], [0, 0.6, 0.8]]),
        spherekit.Curve("beta", [[1, 0, 0], [0.8, 0.6, 0], [0, 1, 0], [0, 0.6, 0.8], [0, 0, 1]], beta1=1.5, beta2=[0.0, 1.0, 2.0, 0.5, 0.0]),
        spherekit.Curve("catmull-rom", rng.normal(size=(5, 3)), parametrization="arclength", extrapolate="extend"),
        spherekit.Curve("cubic", keys, knots=knots, end="scipy", extrapolate="segment"),
        spherekit.Curve("cubic", keys[:, [3, 0, 1, 2]], knots=knots, scalar_first=True, end="natural"),
        spherekit.Curve("squad", keys, canonicalize=False),
        spherekit.Curve("cubic", loop, closed=True, knots=np.arange(6.0), extrapolate="cycle"),
        spherekit.Curve("geodesic", rng.normal(size=(4, 6)), space="S5", knots=[0, 1, 3, 4], extrapolate="error"),
    ]


def test_curves_pickle_and_deep_copy_to_the_same_samples(rng):
    for curve in curves(rng):
        t0, t1 = curve.domain
        # Outside the domain too, but for the curve that refuses it.
        t = np.linspace(t0, t1, 101) if curve.space == "S5" else np.linspace(t0 - 1, t1 + 1, 101)
        want = [curve(t, order) for order in (0, 1, 2)]
        for how, again in copies(curve):
            assert type(again) is spherekit.Curve and again is not curve, how
            assert (again.method, again.space, again.domain) == (curve.method, curve.space, curve.domain), how
            for order, values in enumerate(want):
                assert np.array_equal(again(t, order), values), (how, curve, order)
            np.testing.assert_array_equal(again.points, curve.points)
            if curve.space == "S3":
                np.testing.assert_array_equal(again.angular_velocity(t, "body"), curve.angular_velocity(t, "body"))


def test_a_pickled_curve_does_not_follow_the_callers_array(rng):
    points = rng.normal(size=(4, 3))
    curve = spherekit.Curve("catmull-rom", points)
    t = np.linspace(*curve.domain, 11)
    want = curve(t)
    data = pickle.dumps(curve)
    points[:] = 0.0
    assert np.array_equal(pickle.loads(data)(t), want)


def splines(rng):
    keys = walk(rng, 6, 1.2)
    q = keys.as_quat() * rng.choice([-1.0, 1.0], size=(6, 1))
    times = random_times(rng, 6)
    loop_times = np.append(times, times[-1] + 1.0)
    return [
        (spherekit.RotationSpline(times, keys), times),
        (spherekit.RotationSpline(times, q[:, [3, 0, 1, 2]], scalar_first=True), times),
        (spherekit.RotationSpline(times, q, end="clamped", start_velocity=[0.1, 0.2, 0.3], end_velocity=np.zeros(3)), times),
        (spherekit.RotationSpline(loop_times, Rotation.from_quat(q), closed=True), loop_times),
        (spherekit.Slerp(times, keys), times),
        (spherekit.Slerp(times, q[:, [3, 0, 1, 2]], scalar_first=True), times),
    ]


def test_drop_ins_pickle_and_deep_copy_to_the_same_samples(rng):
    for spline, times in splines(rng):
        slerp = isinstance(spline, spherekit.Slerp)
        t = np.linspace(times[0], times[-1], 201) if slerp else np.linspace(times[0] - 1, times[-1] + 1, 201)
        orders = (0,) if slerp else (0, 1, 2)
        want = [spline(t) if order == 0 else spline(t, order) for order in orders]
        for how, again in copies(spline):
            assert type(again) is type(spline) and again is not spline, how
            assert again._native is not spline._native, how
            np.testing.assert_array_equal(again.times, spline.times)
            np.testing.assert_array_equal(again.rotations.as_quat(), spline.rotations.as_quat())
            for order, values in zip(orders, want):
                got = again(t) if order == 0 else again(t, order)
                if order == 0:
                    got, values = got.as_quat(), values.as_quat()
                assert np.array_equal(got, values), (how, spline, order)


def test_copies_are_independent_of_the_callers_array(rng):
    q, times = walk(rng, 5, 1.0).as_quat(), random_times(rng, 5)
    spline = spherekit.RotationSpline(times, q)
    t = np.linspace(times[0], times[-1], 21)
    want = spline(t).as_quat()
    q[:] = [0.0, 0.0, 0.0, 1.0]
    times[:] = np.arange(5.0)
    for how, again in copies(spline):
        assert np.array_equal(again(t).as_quat(), want), how


@pytest.mark.parametrize("cls", [spherekit.RotationSpline, spherekit.Slerp])
def test_pickles_name_the_public_classes(rng, cls):
    spline = cls(random_times(rng, 3), walk(rng, 3, 1.0))
    data = pickle.dumps(spline)
    assert b"spherekit._scipy" in data and cls.__name__.encode() in data and b"_CubicRotations" not in data
    curve = spherekit.Curve("geodesic", [[1, 0, 0], [0, 1, 0]])
    assert b"spherekit._curve" in pickle.dumps(curve) and b"Curve" in pickle.dumps(curve)
