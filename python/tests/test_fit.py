# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""Fitting noisy samples: `Curve(..., fit=...)` and `SmoothRotationSpline`, against scipy's
Euclidean smoothing spline of the angle on one rotation axis and on a great circle of S2."""

import pickle

import numpy as np
import pytest
from scipy.interpolate import make_smoothing_spline
from scipy.spatial.transform import Rotation

import spherekit

AXIS = np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8])


def noisy_angle(rng, n=60, dt=0.2):
    """Times ~`dt` apart (jittered) and an angle of a smooth motion plus noise, radians."""
    t = np.cumsum(np.concatenate([[0.0], rng.uniform(0.75 * dt, 1.25 * dt, n - 1)]))
    angle = 1.4 * np.sin(0.45 * t) + 0.3 * t + rng.normal(0, 0.05, n)
    return t, angle


def about_axis(angle):
    return Rotation.from_rotvec(np.outer(angle, AXIS))


def angle_about_axis(rotations, reference):
    """The angle of each rotation about AXIS, unwrapped, continuous from `reference[0]`."""
    q = rotations.as_quat()
    half = np.arctan2(q[:, :3] @ AXIS, q[:, 3])
    angle = np.unwrap(2 * half)
    return angle + 2 * np.pi * np.round((reference[0] - angle[0]) / (2 * np.pi))


def circle_points(angle):
    return np.column_stack([np.cos(angle), np.sin(angle), np.zeros_like(angle)])


def angle_on_circle(points, reference):
    angle = np.unwrap(np.arctan2(points[:, 1], points[:, 0]))
    return angle + 2 * np.pi * np.round((reference[0] - angle[0]) / (2 * np.pi))


def fine(t):
    return np.linspace(t[0], t[-1], 997)


def test_one_axis_equals_scipys_smoothing_spline_for_a_given_lambda(rng):
    t, angle = noisy_angle(rng)
    w = rng.uniform(0.5, 2.0, len(t))
    lam = 0.02
    spline = spherekit.SmoothRotationSpline(t, about_axis(angle), smoothing=lam, weights=w)
    reference = make_smoothing_spline(t, angle, w, lam=lam)
    s = fine(t)
    got = angle_about_axis(spline(s), reference(s))
    assert np.max(np.abs(got - reference(s))) < 1e-8
    # Body rates and accelerations: the angle's derivatives about the axis.
    rate, acceleration = spline(s, 1), spline(s, 2)
    assert np.max(np.abs(rate - np.outer(reference(s, 1), AXIS))) < 1e-7
    assert np.max(np.abs(acceleration - np.outer(reference(s, 2), AXIS))) < 1e-6
    info = spline.fit_info
    assert info["lambda"] == lam and info["keys"] == len(t)
    residuals = np.abs(reference(t) - angle)
    assert np.max(np.abs(info["residuals"] - residuals)) < 1e-8
    assert info["rms"] == pytest.approx(np.sqrt(np.sum(w * residuals**2) / np.sum(w)), rel=1e-7)


def test_one_axis_gcv_equals_scipys_choice(rng):
    # scipy's bounded search finds λ to an absolute 1e-5: samples 0.3 s apart make λ large
    # enough for that to be accurate.
    t, angle = noisy_angle(rng, n=80, dt=0.3)
    spline = spherekit.SmoothRotationSpline(t, about_axis(angle))
    reference = make_smoothing_spline(t, angle)
    s = fine(t)
    got = angle_about_axis(spline(s), reference(s))
    assert np.max(np.abs(got - reference(s))) < 1e-5
    assert spline.fit_info["edf"] > 3


def test_great_circle_equals_scipys_smoothing_spline(rng):
    t, angle = noisy_angle(rng, n=50, dt=0.25)
    w = rng.uniform(0.5, 2.0, len(t))
    lam = 0.05
    curve = spherekit.Curve("cubic", circle_points(angle), knots=t, fit={"smoothing": lam, "weights": w})
    reference = make_smoothing_spline(t, angle, w, lam=lam)
    s = fine(t)
    assert np.max(np.abs(angle_on_circle(curve(s), reference(s)) - reference(s))) < 1e-8
    assert curve.fit_info["lambda"] == lam
    t, angle = noisy_angle(rng, n=80, dt=0.3)
    gcv = spherekit.Curve("cubic", circle_points(angle), knots=t, fit={"smoothing": "gcv"})
    s = fine(t)
    reference = make_smoothing_spline(t, angle)
    assert np.max(np.abs(angle_on_circle(gcv(s), reference(s)) - reference(s))) < 1e-5
    # A numpy array of samples in, arrays out.
    assert isinstance(gcv.fit_info["residuals"], np.ndarray)
    assert gcv.fit_info["residuals"].shape == (len(t),)
    assert gcv.points.shape == (len(t), 3)


def test_a_target_rms_is_reached(rng):
    t, angle = noisy_angle(rng, n=40)
    w = rng.uniform(0.5, 2.0, len(t))
    for sigma in [0.02, 0.04]:
        spline = spherekit.SmoothRotationSpline(t, about_axis(angle), smoothing={"rms": sigma}, weights=w)
        circle = spherekit.Curve("cubic", circle_points(angle), knots=t, fit={"smoothing": {"rms": sigma}, "weights": w})
        for info in [spline.fit_info, circle.fit_info]:
            assert info["rms"] == pytest.approx(sigma, rel=1e-6)
            r = info["residuals"]
            assert np.sqrt(np.sum(w * r**2) / np.sum(w)) == pytest.approx(sigma, rel=1e-6)


def test_sign_flips_of_the_samples_change_nothing(rng):
    t, angle = noisy_angle(rng, n=40)
    rotations = about_axis(angle) * Rotation.from_rotvec([0.2, 0.1, -0.3])
    q = rotations.as_quat()
    flipped = q * np.where(rng.uniform(size=len(q)) < 0.5, -1.0, 1.0)[:, None]
    a = spherekit.SmoothRotationSpline(t, rotations, smoothing="gcv")
    b = spherekit.SmoothRotationSpline(t, flipped, smoothing="gcv")
    s = fine(t)
    assert np.max((a(s).inv() * b(s)).magnitude()) < 1e-9
    assert b.fit_info["lambda"] == pytest.approx(a.fit_info["lambda"], rel=1e-9)
    np.testing.assert_allclose(b(s, 1), a(s, 1), atol=1e-8)


def test_fewer_keys_and_pickling(rng):
    t, angle = noisy_angle(rng, n=50, dt=0.1)
    spline = spherekit.SmoothRotationSpline(t, about_axis(angle), smoothing=0, keys=8)
    assert spline.fit_info["keys"] == 8 and spline.fit_info["edf"] is None
    assert len(spline.fit_info["key_times"]) == 8
    again = pickle.loads(pickle.dumps(spline))
    assert (again(t).as_quat() == spline(t).as_quat()).all()
    curve = spherekit.Curve("cubic", circle_points(angle), knots=t, fit={"smoothing": 0.1, "weights": np.ones(len(t))})
    assert (pickle.loads(pickle.dumps(curve))(t) == curve(t)).all()
    assert spherekit.Curve("cubic", circle_points(angle), knots=t).fit_info is None


@pytest.mark.parametrize(
    "options, field",
    [
        (dict(smoothing=-1.0), "fit.smoothing: "),
        (dict(smoothing=float("nan")), "fit.smoothing: "),
        (dict(smoothing="auto"), "fit.smoothing: "),
        (dict(smoothing={"rms": 0}), "fit.smoothing: "),
        (dict(weights=[1.0] * 3), "fit.weights: "),
        (dict(weights=[1.0, 1.0, -1.0] + [1.0] * 17), "fit.weights[2]: "),
        (dict(weights=[1.0, float("nan")] + [1.0] * 18), "fit.weights[1]: "),
        (dict(smoothing=0, max_error=0.0), "fit.max_error: "),
        (dict(smoothing=0, keys=1), "fit.keys: "),
        (dict(smoothing=0, keys=21), "fit.keys: "),
        (dict(smoothing=0, keys=3, max_error=0.1), "fit: "),
        (dict(keys=3), "fit.smoothing: "),
    ],
)
def test_bad_fits_raise_value_errors_naming_the_field(rng, options, field):
    t, angle = noisy_angle(rng, n=20)
    with pytest.raises(ValueError) as e:
        spherekit.SmoothRotationSpline(t, about_axis(angle), **options)
    assert str(e.value).startswith(field), str(e.value)


def test_bad_curve_fits_raise_value_errors(rng):
    t, angle = noisy_angle(rng, n=20)
    with pytest.raises(ValueError, match=r"^fit\.lam: unknown fit option"):
        spherekit.Curve("cubic", circle_points(angle), knots=t, fit={"lam": 1})
    with pytest.raises(ValueError, match=r'^fit: method "geodesic" does not fit samples'):
        spherekit.Curve("geodesic", circle_points(angle), fit={})
    with pytest.raises(ValueError, match=r'^knots: are needed with "fit"'):
        spherekit.Curve("cubic", circle_points(angle), fit={})
    with pytest.raises(ValueError, match=r"Values in `times` must be in a strictly increasing order"):
        spherekit.SmoothRotationSpline(t[::-1], about_axis(angle))
