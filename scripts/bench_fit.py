#!/usr/bin/env python3
# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""The fitting benchmark: smoothing noisy samples on S³ (rotations) and S² (directions), with
scipy and spherekit baselines, in one run.

    bash scripts/setup-python.sh python scripts/bench_fit.py     # or: ./run bench-fit

Three parts, each printed as a markdown table:

1. Recovery of a known motion. 501 samples (100 Hz over 5 s) of a smooth motion with 1° of
   noise; each method fits them, and its curve is compared with the truth at the sample times:
   RMS orientation (S³) or direction (S²) error in degrees, RMS angular-rate error in rad/s,
   RMS angular-acceleration error in rad/s². Figures are the mean over 10 seeds (and their
   standard deviation across the seeds).

   - S³ truth: R(t) = Exp(v(t)) R₀ with the rotation vector
     v(t) = (0.6 sin 2π·0.3t + 0.2 sin(2π·1.1t + 0.5), 0.5 cos 2π·0.45t − 0.3,
     1.5t − 3 + 0.3 sin 2π·0.7t) rad and R₀ the rotation of Euler angles xyz (20°, −30°, 50°):
     a turn of 7.5 rad about roughly z, so that |v| passes π (where scipy's rotation vectors
     wrap) and 2π. Rate and acceleration are the body-frame ω = 2 q̄ q̇ and α = 2 q̄ q̈ (q the
     unit quaternion, ω̇ = α in the body frame), from the closed form of the derivatives of
     q = exp(v/2) in `exp_jet` (independent of spherekit; checked against central differences
     at start-up).
   - S² truth: a loxodrome with a wobble, p = (cos φ cos λ, cos φ sin λ, sin φ) with latitude
     φ(t) = −1 + 0.4t + 0.1 sin 2π·0.5t and longitude λ = 3 gd⁻¹(φ) = 3 asinh(tan φ) (without
     the wobble, a rhumb line crossing the meridians at a constant angle); derivatives by the
     chain rule. Rate error is |ṗ − ṗ_true| (ambient velocities, rad/s), acceleration error
     |p̈ − p̈_true| (ambient second derivatives).
   - Noise, with an RMS angular error of exactly σ = 1° per sample: on S³,
     R_noisy = R Exp(e) with e ~ N(0, (σ/√3)² I₃) in the body frame (the error angle is |e|,
     E|e|² = σ²); on S², p_noisy = cos|e| p + sin|e| e/|e| with e an isotropic Gaussian in the
     tangent plane of p, N(0, (σ/√2)² I₂) (E|e|² = σ²).
   - Methods on S³: (a) scipy's `RotationSpline` through all samples; (b) a centred 15-sample
     windowed mean (quaternions sign-aligned to the window's centre, averaged and normalised:
     the chordal mean; the window shrinks symmetrically at the ends) and `RotationSpline`
     through the means; (c) `scipy.interpolate.make_smoothing_spline` (λ by GCV) of each
     component of the rotation vectors v_i = log(R̄⁻¹ R_i), unwrapped along the track, with R̄
     the chordal mean of all samples (`Rotation.mean()`), mapped back as R̄ Exp(v(t)). On S²:
     spherekit's `cubic` through all samples; the 15-sample windowed mean, normalised, then
     `cubic`; per-coordinate `make_smoothing_spline`, normalised (derivatives of u/|u| by the
     quotient rule). S² once more with the motion turned by a random rotation per seed
     (`Rotation.random(random_state=1000 + seed)`): the per-coordinate baseline depends on the
     frame (each coordinate gets its own λ), the spherical fit does not. spherekit's `cubic` uses its default natural ends.
   - Then spherekit's smoothing spline, `fit={"smoothing": "gcv"}` (`fit_spherekit_gcv`).

2. Speed: `make_smoothing_spline(t, x)` (λ by GCV) on the three rotation-vector components of
   10⁴ and 10⁵ noisy samples (100 Hz over 100 s and 1 000 s of the wobble of part 1 without
   its turn, 1° of noise), wall clock of the three fits: best of 3 for 10⁴, one run for 10⁵
   (about a minute per component on a 2-core machine; `--repeat-large 3` for a best of 3,
   `--repeat-large 0` to skip it). Then spherekit's fit on the same samples with GCV and with λ given (the λ its GCV
   chose), timed the same way.

3. Key reduction: noise-free tracks of 2 000 samples (the S² and S³ truths of part 1 over 5 s;
   an S³ camera move of eases and holds over 5 s, `eased_s3`; and a closed S³ loop: one turn
   about z in 4 s with a periodic wobble). For ε = 0.1°, 0.5°, 1°: the smallest number k of
   keys, taken from the samples at the indices round(linspace(0, N − 1, k)) (closed:
   round(linspace(0, N, k + 1)) without the last), whose interpolating spherekit `cubic`
   through them at their times stays within ε of every sample: with its default natural ends,
   and (open tracks) clamped at the track's own end velocities (central differences of the
   truth, step 1e-5 s), which a user subsampling a track does not have but which isolates the
   ends' share of the difference.
   The search is a bisection on k in [2, N] (closed: [3, N]) assuming the maximum error falls as
   k grows; a scan of every k from there to 2k checks it: the table gives the smallest k the scan finds below ε and
   how many k in (k, 2k] exceed ε. Then spherekit's own reduction, `fit={"max_error": ε}`, its
   `fit_info["keys"]`.

The parts print in the order 1, 3, 2: the speed part, the slow one, comes last. Deterministic
(fixed seeds); about four minutes on a 2-core machine, three of them scipy's fits of 10⁵ samples
(under a minute with `--repeat-large 0`).
"""

import argparse
import math
import platform
import time

import numpy as np
import scipy
from scipy.interpolate import make_smoothing_spline
from scipy.spatial.transform import Rotation, RotationSpline

import spherekit

SIGMA = math.radians(1.0)  # RMS angular error of one noisy sample
RATE_HZ = 100.0
DURATION = 5.0
N_SAMPLES = 501
SEEDS = range(20261201, 20261211)  # 10 seeds
WINDOW = 15  # samples in the windowed mean
EPSILONS_DEG = (0.1, 0.5, 1.0)
N_DENSE = 2000
LOOP_PERIOD = 4.0

# The spherekit smoothing spline (see `fit_spherekit`): the `fit=` argument of `Curve("cubic")`
# and its `fit_info` dict (lambda, rms, max, keys, key_times, iterations, edf).


# ---- quaternions, scalar last [x, y, z, w] as scipy ----------------------------------------


def qmul(a, b):
    """Hamilton products of (n, 4) quaternions [x, y, z, w]."""
    av, aw = a[..., :3], a[..., 3:]
    bv, bw = b[..., :3], b[..., 3:]
    v = aw * bv + bw * av + np.cross(av, bv)
    w = aw * bw - np.sum(av * bv, axis=-1, keepdims=True)
    return np.concatenate([v, w], axis=-1)


def qconj(q):
    return q * np.array([-1.0, -1.0, -1.0, 1.0])


def rotation_angle(q, p):
    """The angle of the rotation between unit quaternions q and p, either sign: 2 atan2(|v|, |w|)
    of q̄ p (accurate for small and large angles)."""
    d = qmul(qconj(q), p)
    return 2.0 * np.arctan2(np.linalg.norm(d[:, :3], axis=1), np.abs(d[:, 3]))


def direction_angle(p, q):
    """Great-circle angle between unit vectors: atan2(|p × q|, p·q)."""
    return np.arctan2(np.linalg.norm(np.cross(p, q), axis=1), np.sum(p * q, axis=1))


def body_rates(q, qd, qdd):
    """Body-frame angular velocity ω = 2 vec(q̄ q̇) and acceleration α = 2 vec(q̄ q̈) (the real
    part of q̄̇ q̇ is all the derivative of q̄ contributes, so α = ω̇)."""
    qc = qconj(q)
    return 2.0 * qmul(qc, qd)[:, :3], 2.0 * qmul(qc, qdd)[:, :3]


# ---- q = exp(v/2) and its time derivatives ---------------------------------------------------
#
# With s = |v|², q = (g(s) v, h(s)) where g(s) = sin(√s/2)/√s and h(s) = cos(√s/2), so
# h′ = −g/4, h″ = −g′/4, and by the chain rule with ṡ = 2 v·v̇, s̈ = 2(v̇·v̇ + v·v̈):
#   q̇ = (g′ṡ v + g v̇,  h′ṡ),   q̈ = ((g″ṡ² + g′s̈) v + 2g′ṡ v̇ + g v̈,  h″ṡ² + h′s̈).
# For s ≤ 1, g, g′, g″ come from the series g(s) = Σ (−1)ᵏ sᵏ / (2²ᵏ⁺¹ (2k + 1)!), whose closed
# forms cancel there; above, from the closed forms (r = √s):
#   g′ = cos(r/2)/(4r²) − sin(r/2)/(2r³),
#   g″ = −sin(r/2)/(16r³) − 3 cos(r/2)/(8r⁴) + 3 sin(r/2)/(4r⁵).

_G_SERIES = np.array([(-1.0) ** k / (2.0 ** (2 * k + 1) * math.factorial(2 * k + 1)) for k in range(12)])


def _g_and_derivatives(s):
    g, g1, g2 = np.empty_like(s), np.empty_like(s), np.empty_like(s)
    small = s <= 1.0
    x = s[small]
    k = np.arange(len(_G_SERIES))
    powers = x[:, None] ** k  # s^k
    g[small] = powers @ _G_SERIES
    g1[small] = powers[:, :-1] @ (k[1:] * _G_SERIES[1:])
    g2[small] = powers[:, :-2] @ (k[2:] * (k[2:] - 1) * _G_SERIES[2:])
    r = np.sqrt(s[~small])
    sn, cs = np.sin(r / 2), np.cos(r / 2)
    g[~small] = sn / r
    g1[~small] = cs / (4 * r**2) - sn / (2 * r**3)
    g2[~small] = -sn / (16 * r**3) - 3 * cs / (8 * r**4) + 3 * sn / (4 * r**5)
    return g, g1, g2


def exp_jet(v, vd, vdd):
    """q = exp(v/2) = Exp(v) as a quaternion, with q̇ and q̈, for rotation vectors v(t) given with
    their first and second time derivatives, all (n, 3)."""
    s = np.sum(v * v, axis=1)
    sd = 2 * np.sum(v * vd, axis=1)
    sdd = 2 * (np.sum(vd * vd, axis=1) + np.sum(v * vdd, axis=1))
    g, g1, g2 = _g_and_derivatives(s)
    h, h1, h2 = np.cos(np.sqrt(s) / 2), -g / 4, -g1 / 4
    col = lambda a: a[:, None]  # noqa: E731
    q = np.column_stack([col(g) * v, h])
    qd = np.column_stack([col(g1 * sd) * v + col(g) * vd, h1 * sd])
    qdd = np.column_stack([
        col(g2 * sd**2 + g1 * sdd) * v + col(2 * g1 * sd) * vd + col(g) * vdd,
        h2 * sd**2 + h1 * sdd,
    ])
    return q, qd, qdd


# ---- the known motions -------------------------------------------------------------------------

BASE = Rotation.from_euler("xyz", [20, -30, 50], degrees=True).as_quat()


def s3_rotvec(t, turn=True):
    """v(t), v̇(t), v̈(t) of the S³ truth (module docstring); `turn=False`: the wobble alone."""
    tau = 2 * np.pi
    terms = [  # per component: (amplitude, frequency in Hz, phase) sinusoids
        [(0.6, 0.3, 0.0), (0.2, 1.1, 0.5)],
        [(0.5, 0.45, np.pi / 2)],
        [(0.3, 0.7, 0.0)],
    ]
    v, vd, vdd = (np.zeros((len(t), 3)) for _ in range(3))
    for j, comp in enumerate(terms):
        for a, f, ph in comp:
            w = tau * f
            v[:, j] += a * np.sin(w * t + ph)
            vd[:, j] += a * w * np.cos(w * t + ph)
            vdd[:, j] -= a * w * w * np.sin(w * t + ph)
    v[:, 1] -= 0.3
    if turn:
        v[:, 2] += 1.5 * t - 3.0
        vd[:, 2] += 1.5
    return v, vd, vdd


def truth_s3(t, turn=True):
    """Quaternions [x, y, z, w] of R(t) = Exp(v(t)) R₀, body ω and α: (n, 4), (n, 3), (n, 3)."""
    e, ed, edd = exp_jet(*s3_rotvec(t, turn))
    base = np.broadcast_to(BASE, e.shape)
    q, qd, qdd = qmul(e, base), qmul(ed, base), qmul(edd, base)
    return (q, *body_rates(q, qd, qdd))


def truth_s2(t):
    """Points, velocities and accelerations of the S² truth (module docstring), each (n, 3)."""
    w = 2 * np.pi * 0.5
    phi = -1.0 + 0.4 * t + 0.1 * np.sin(w * t)
    phid = 0.4 + 0.1 * w * np.cos(w * t)
    phidd = -0.1 * w * w * np.sin(w * t)
    k = 3.0  # λ = k asinh(tan φ), dλ/dφ = k sec φ
    sec = 1 / np.cos(phi)
    lam = k * np.arcsinh(np.tan(phi))
    lamd = k * sec * phid
    lamdd = k * (sec * np.tan(phi) * phid**2 + sec * phidd)
    cp, sp, cl, sl = np.cos(phi), np.sin(phi), np.cos(lam), np.sin(lam)
    p = np.column_stack([cp * cl, cp * sl, sp])
    p_phi = np.column_stack([-sp * cl, -sp * sl, cp])
    p_lam = np.column_stack([-cp * sl, cp * cl, np.zeros_like(t)])
    p_phiphi = -p
    p_philam = np.column_stack([sp * sl, -sp * cl, np.zeros_like(t)])
    p_lamlam = np.column_stack([-cp * cl, -cp * sl, np.zeros_like(t)])
    c = lambda a: a[:, None]  # noqa: E731
    pd = p_phi * c(phid) + p_lam * c(lamd)
    pdd = (p_phiphi * c(phid**2) + 2 * p_philam * c(phid * lamd) + p_lamlam * c(lamd**2)
           + p_phi * c(phidd) + p_lam * c(lamdd))
    return p, pd, pdd


def _smootherstep(x):
    x = np.clip(x, 0.0, 1.0)
    return x**3 * (10 - 15 * x + 6 * x * x)


def eased_s3(t):
    """Part 3's camera move: a pan of 100° eased in and out over 0–1.6 s, a hold, a pan back of
    40° with a tilt of 30° over 2.4–4.2 s, a hold (smootherstep eases): Rz(pan) Rx(tilt)."""
    a, b = _smootherstep(t / 1.6), _smootherstep((t - 2.4) / 1.8)
    pan = np.radians(100.0) * a - np.radians(40.0) * b
    tilt = np.radians(30.0) * b
    z = Rotation.from_rotvec(np.outer(pan, [0, 0, 1]))
    x = Rotation.from_rotvec(np.outer(tilt, [1, 0, 0]))
    return (z * x).as_quat()


def loop_s3(t):
    """The closed S³ loop of part 3: one turn about z per LOOP_PERIOD, then a periodic wobble
    Exp(w(t)) (w of period LOOP_PERIOD / 1 and / 2), so R(LOOP_PERIOD) = R(0)."""
    tau = 2 * np.pi / LOOP_PERIOD
    turn = Rotation.from_rotvec(np.outer(tau * t, [0, 0, 1])).as_quat()
    w = np.column_stack([0.4 * np.sin(tau * t), 0.3 * np.cos(2 * tau * t), 0.2 * np.sin(2 * tau * t + 1)])
    return qmul(turn, Rotation.from_rotvec(w).as_quat())


def check_truth():
    """The truths' analytic derivatives against central differences (h = 1e-4): a failure here
    means a wrong formula, not a slow benchmark."""
    t = np.linspace(0.0, DURATION, 97)
    h = 1e-4

    def fd(f):
        a, b, c = f(t - h), f(t), f(t + h)
        return b, (c - a) / (2 * h), (c - 2 * b + a) / h**2

    q, w, a = truth_s3(t)
    qs = fd(lambda x: truth_s3(x)[0])
    w_fd, a_fd = body_rates(*qs)
    assert np.abs(w - w_fd).max() < 1e-6 and np.abs(a - a_fd).max() < 1e-4, "S3 truth derivatives"
    # exp_jet on both branches of its series switch: a path through v = 0.
    v = lambda x: np.column_stack([x, 0.5 * x**2, 0.3 * x - 0.2 * x**3])  # noqa: E731
    x = np.linspace(-1.5, 1.5, 61)
    q, qd, qdd = exp_jet(v(x), np.column_stack([np.ones_like(x), x, 0.3 - 0.6 * x**2]),
                         np.column_stack([np.zeros_like(x), np.ones_like(x), -1.2 * x]))
    assert np.abs(q - Rotation.from_rotvec(v(x)).as_quat()).max() < 1e-14, "exp_jet points"
    e0, e1, e2 = (Rotation.from_rotvec(v(y)).as_quat() for y in (x - h, x, x + h))
    assert np.abs(qd - (e2 - e0) / (2 * h)).max() < 1e-7, "exp_jet first derivative"
    assert np.abs(qdd - (e2 - 2 * e1 + e0) / h**2).max() < 1e-5, "exp_jet second derivative"
    p, pd, pdd = truth_s2(t)
    ps = fd(lambda x: truth_s2(x)[0])
    assert np.abs(pd - ps[1]).max() < 1e-6 and np.abs(pdd - ps[2]).max() < 1e-4, "S2 truth derivatives"


# ---- noise -------------------------------------------------------------------------------------


def noisy_s3(q, rng):
    e = rng.normal(scale=SIGMA / math.sqrt(3), size=(len(q), 3))
    return qmul(q, Rotation.from_rotvec(e).as_quat())


def noisy_s2(p, rng):
    g = rng.normal(scale=SIGMA / math.sqrt(2), size=p.shape)
    e = g - np.sum(g * p, axis=1, keepdims=True) * p  # isotropic in the tangent plane
    a = np.linalg.norm(e, axis=1, keepdims=True)
    return np.cos(a) * p + np.sinc(a / np.pi) * e  # sin|e| e/|e|


# ---- fitted curves: one evaluation interface -------------------------------------------------
#
# A track is (point, rate, accel), three functions of an array of times: on S³ quaternions
# [x, y, z, w] and the body-frame ω and α; on S² the points, velocities and accelerations.


def curve_track(curve):
    """A spherekit `Curve` (its exact derivatives)."""
    if curve.space == "S3":
        return (curve, lambda t: curve.angular_velocity(t, frame="body"),
                lambda t: curve.angular_acceleration(t, frame="body"))
    return (curve, lambda t: curve(t, 1), lambda t: curve(t, 2))


def rotation_spline_track(spline):
    """scipy's `RotationSpline`: its order 1 and 2 are the body-frame ω and α."""
    return (lambda t: spline(t).as_quat(), lambda t: spline(t, 1), lambda t: spline(t, 2))


def rotvec_spline_track(splines, ref):
    """R(t) = ref Exp(v(t)) for a rotation vector v(t) of three scalar splines: its body rates
    are those of Exp(v(t)), from `exp_jet`."""

    def jet(t):
        v, vd, vdd = (np.column_stack([s(t, nu) for s in splines]) for nu in (0, 1, 2))
        return exp_jet(v, vd, vdd)

    def rates(t):
        return body_rates(*jet(t))

    return (lambda t: qmul(np.broadcast_to(ref, (len(t), 4)), jet(t)[0]),
            lambda t: rates(t)[0], lambda t: rates(t)[1])


def normalised_track(splines):
    """p = u/|u| for u(t) of three scalar splines; with r = |u|, ṙ = p·u̇, r̈ = ṗ·u̇ + p·ü:
    ṗ = (u̇ − ṙ p)/r and p̈ = (ü − r̈ p − 2ṙ ṗ)/r."""

    def jet(t):
        u, ud, udd = (np.column_stack([s(t, nu) for s in splines]) for nu in (0, 1, 2))
        r = np.linalg.norm(u, axis=1, keepdims=True)
        p = u / r
        rd = np.sum(p * ud, axis=1, keepdims=True)
        pd = (ud - rd * p) / r
        rdd = np.sum(pd * ud, axis=1, keepdims=True) + np.sum(p * udd, axis=1, keepdims=True)
        return p, pd, (udd - rdd * p - 2 * rd * pd) / r

    return (lambda t: jet(t)[0], lambda t: jet(t)[1], lambda t: jet(t)[2])


def errors(track, t, truth, space):
    """RMS angle (degrees), rate (rad/s) and acceleration (rad/s²) errors at the times t."""
    point, rate, accel = track
    angle = rotation_angle if space == "S3" else direction_angle
    rms = lambda a: math.sqrt(np.mean(a**2))  # noqa: E731
    return (math.degrees(rms(angle(point(t), truth[0]))),
            rms(np.linalg.norm(rate(t) - truth[1], axis=1)),
            rms(np.linalg.norm(accel(t) - truth[2], axis=1)))


# ---- the methods -------------------------------------------------------------------------------


def windowed_mean(samples, space):
    """Centred WINDOW-sample means, the window shrunk symmetrically at the ends; on S³ each
    window's quaternions are sign-aligned to its centre first. Normalised (the chordal mean)."""
    n, half = len(samples), WINDOW // 2
    out = np.empty_like(samples)
    for i in range(n):
        h = min(half, i, n - 1 - i)
        w = samples[i - h:i + h + 1]
        if space == "S3":
            w = w * np.sign(w @ samples[i])[:, None]
        m = w.sum(axis=0)
        out[i] = m / np.linalg.norm(m)
    return out


def unwrap_rotvecs(rotvecs):
    """Rotation vectors made continuous along a track: each v = θ a (θ ≤ π) is replaced by the
    equivalent a (θ + 2πk), k an integer, nearest the previous one."""
    out = np.empty_like(rotvecs)
    prev = rotvecs[0]
    for i, v in enumerate(rotvecs):
        theta = float(np.linalg.norm(v))
        axis = v / theta if theta > 1e-12 else prev / max(float(np.linalg.norm(prev)), 1e-300)
        cands = [axis * (theta + 2 * math.pi * k) for k in range(-3, 4)]
        prev = min(cands, key=lambda c: float(np.sum((c - prev) ** 2)))
        out[i] = prev
    return out


def rotvecs_about_mean(t, quats):
    """(R̄, v): R̄ the chordal mean of the samples, v_i = log(R̄⁻¹ R_i) unwrapped along the track."""
    rots = Rotation.from_quat(quats)
    ref = rots.mean()
    return ref.as_quat(), unwrap_rotvecs((ref.inv() * rots).as_rotvec())


def fit_interpolating(t, samples, space):
    if space == "S3":
        return rotation_spline_track(RotationSpline(t, Rotation.from_quat(samples)))
    return curve_track(spherekit.Curve("cubic", samples, knots=t))


def fit_windowed(t, samples, space):
    return fit_interpolating(t, windowed_mean(samples, space), space)


def fit_euclidean_gcv(t, samples, space):
    if space == "S3":
        ref, v = rotvecs_about_mean(t, samples)
        return rotvec_spline_track([make_smoothing_spline(t, v[:, j]) for j in range(3)], ref)
    return normalised_track([make_smoothing_spline(t, samples[:, j]) for j in range(3)])


def fit_spherekit(knots, samples, fit, closed=False):
    """spherekit's smoothing spline, `Curve("cubic", samples, knots=knots, fit=fit)` (closed: one
    knot more than samples, the time of the return to the first)."""
    return spherekit.Curve("cubic", samples, knots=knots, closed=closed, fit=fit)


def fit_spherekit_gcv(t, samples, space):
    return curve_track(fit_spherekit(t, samples, {"smoothing": "gcv"}))


METHODS = {
    "S3": [
        ("scipy RotationSpline through all samples", fit_interpolating),
        (f"{WINDOW}-sample windowed mean, then scipy RotationSpline", fit_windowed),
        ("scipy make_smoothing_spline (GCV) of unwrapped rotation vectors about the mean",
         fit_euclidean_gcv),
        ('spherekit cubic, fit={"smoothing": "gcv"}', fit_spherekit_gcv),
    ],
    "S2": [
        ("spherekit cubic through all samples", fit_interpolating),
        (f"{WINDOW}-sample windowed mean, normalised, then spherekit cubic", fit_windowed),
        ("scipy make_smoothing_spline (GCV) per coordinate, normalised", fit_euclidean_gcv),
        ('spherekit cubic, fit={"smoothing": "gcv"}', fit_spherekit_gcv),
    ],
}


def recovery():
    t = np.arange(N_SAMPLES) / RATE_HZ
    truths = {"S3": truth_s3(t), "S2": truth_s2(t)}
    noisy = {"S3": noisy_s3, "S2": noisy_s2}
    angle = {"S3": rotation_angle, "S2": direction_angle}
    print(f"## 1. Recovery of a known motion: {N_SAMPLES} samples at {RATE_HZ:g} Hz, "
          f"{math.degrees(SIGMA):g}° RMS noise, mean (sd) over {len(SEEDS)} seeds")
    print()
    print("| space | method | RMS angle error (°) | RMS rate error (rad/s) | RMS acceleration error (rad/s²) |")
    print("|---|---|---:|---:|---:|")
    infos = []
    # S², and the same motion turned by a random rotation per seed (the per-coordinate
    # Euclidean baseline depends on the frame; the spherical fit does not).
    for row, space, turned in (("S3", "S3", False), ("S2", "S2", False),
                               ("S2, random frame", "S2", True)):
        truths_seeds = [
            tuple(x @ Rotation.random(random_state=1000 + seed).as_matrix().T for x in truths[space])
            if turned else truths[space]
            for seed in SEEDS
        ]
        data = [noisy[space](truth[0], np.random.default_rng(seed)) for seed, truth in zip(SEEDS, truths_seeds)]
        noise = [math.degrees(math.sqrt(np.mean(angle[space](d, truth[0]) ** 2)))
                 for d, truth in zip(data, truths_seeds)]
        print(f"| {row} | the noisy samples themselves | {np.mean(noise):.3g} ({np.std(noise):.2g}) | | |")
        for label, fit in METHODS[space]:
            runs = np.array([errors(fit(t, d, space), t, truth, space) for d, truth in zip(data, truths_seeds)])
            cells = " | ".join(f"{m:.3g} ({s:.2g})" for m, s in zip(runs.mean(axis=0), runs.std(axis=0)))
            print(f"| {row} | {label} | {cells} |")
        if not turned:
            info = fit_spherekit(t, data[0], {"smoothing": "gcv"}).fit_info
            infos.append(f"{space}: " + ", ".join(f"{k} {info[k]:.4g}" for k in ("lambda", "rms", "max", "keys", "iterations", "edf")))
    print()
    for info in infos:
        print(f"spherekit fit_info, first seed, {info}")
    if infos:
        print()


# ---- speed --------------------------------------------------------------------------------------


from bench_python import best as best_of  # noqa: E402 (the scripts' one timing helper)


def time_spherekit_fit(t, quats, repeat):
    """Wall clock of spherekit's fit of the samples: (GCV, λ given), λ the one its GCV chose."""
    fits = []
    gcv = best_of(lambda: fits.append(fit_spherekit(t, quats, {"smoothing": "gcv"})), repeat)
    lam = fits[-1].fit_info["lambda"]
    given = best_of(lambda: fit_spherekit(t, quats, {"smoothing": lam}), repeat)
    return gcv, given, lam


def speed(repeat_large):
    print("## 2. Speed: smoothing splines of n noisy S³ samples (100 Hz, the wobble without the turn)")
    print()
    print("| n | repeats (best of) | scipy make_smoothing_spline ×3 (GCV) | spherekit fit (GCV) | spherekit fit (λ given) |")
    print("|---:|---:|---:|---:|---:|")
    for n, repeat in ((10_000, 3), (100_000, repeat_large)):
        if repeat == 0:
            continue
        t = np.arange(n) / RATE_HZ
        q = noisy_s3(truth_s3(t, turn=False)[0], np.random.default_rng(n))
        _, v = rotvecs_about_mean(t, q)
        scipy_s = best_of(lambda: [make_smoothing_spline(t, v[:, j]) for j in range(3)], repeat)
        gcv, given, lam = time_spherekit_fit(t, q, repeat)
        ours = f"{gcv:.3f} s | {given:.3f} s (λ = {lam:.3g})"
        print(f"| {n:,} | {repeat} | {scipy_s:.2f} s | {ours} |")
    print()


# ---- key reduction ------------------------------------------------------------------------------


def reduction_tracks():
    t = np.linspace(0.0, DURATION, N_DENSE)
    tl = np.arange(N_DENSE) * LOOP_PERIOD / N_DENSE  # the sample at LOOP_PERIOD is the first
    return [
        ("S2, the loxodrome of part 1", t, lambda s: truth_s2(s)[0], False, direction_angle),
        ("S3, the motion of part 1", t, lambda s: truth_s3(s)[0], False, rotation_angle),
        ("S3, eases and holds", t, eased_s3, False, rotation_angle),
        ("S3, closed loop", tl, loop_s3, True, rotation_angle),
    ]


def end_velocities(track, t0, t1, angle):
    """The track's velocities at t0 and t1 as the scene's clamped ends take them (S³: body
    angular velocities with params.frame "body"; S²: tangent vectors), by central differences."""
    h = 1e-5
    out = []
    for s in (t0, t1):
        a, b, c = track(np.array([s - h, s, s + h]))
        if angle is rotation_angle:
            r = Rotation.from_quat(b).inv()
            w = ((r * Rotation.from_quat(c)).as_rotvec() - (r * Rotation.from_quat(a)).as_rotvec()) / (2 * h)
        else:
            w = (c - a) / (2 * h)
            w = w - b * np.dot(b, w)
        out.append([float(x) for x in w])
    return out


def max_error(k, t, samples, closed, angle, ends=None):
    """Largest angle between the samples and spherekit's cubic through k of them (natural ends,
    or clamped at the velocities `ends`)."""
    n = len(t)
    if closed:
        idx = np.unique(np.round(np.linspace(0, n, k + 1)).astype(int)[:-1])
        knots = np.append(t[idx], n * (t[1] - t[0]))
    else:
        idx = np.unique(np.round(np.linspace(0, n - 1, k)).astype(int))
        knots = t[idx]
    params = {}
    if ends is not None:
        params = {"end": "clamped", "start_velocity": ends[0], "end_velocity": ends[1]}
        if angle is rotation_angle:
            params["frame"] = "body"
    curve = spherekit.Curve("cubic", samples[idx], knots=knots, closed=closed, **params)
    return float(angle(curve(t), samples).max())


def smallest_keys(err, eps, lo, n):
    """Bisection for the smallest k in [lo, n] with err(k) ≤ eps (err(n) = 0: every sample a key)."""
    hi = n
    while lo < hi:
        mid = (lo + hi) // 2
        if err(mid) <= eps:
            hi = mid
        else:
            lo = mid + 1
    return lo


def key_reduction():
    print(f"## 3. Key reduction: uniform keys of spherekit's interpolating cubic within ε of {N_DENSE} samples")
    print()
    print("| track | ε | keys (bisection) | max error there (°) | smallest k ≤ ε (scan) | k in (k, 2k] above ε | clamped at the true end velocities | spherekit fit(max_error=ε) keys |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for label, t, track, closed, angle in reduction_tracks():
        samples = track(t)
        ends = None if closed else end_velocities(track, t[0], t[-1], angle)
        cache, clamped_cache = {}, {}

        def err(k):
            if k not in cache:
                cache[k] = max_error(k, t, samples, closed, angle)
            return cache[k]

        def clamped_err(k):
            if k not in clamped_cache:
                clamped_cache[k] = max_error(k, t, samples, closed, angle, ends)
            return clamped_cache[k]

        for eps_deg in EPSILONS_DEG:
            eps = math.radians(eps_deg)
            lo = 3 if closed else 2  # the fewest keys of an open and a closed cubic
            k = smallest_keys(err, eps, lo, len(t))
            scan = range(lo, min(len(t), 2 * k) + 1)
            first = next(j for j in scan if err(j) <= eps)
            above = sum(1 for j in scan if j > k and err(j) > eps)
            knots = np.append(t, len(t) * (t[1] - t[0])) if closed else t
            clamped = "" if closed else str(smallest_keys(clamped_err, eps, lo, len(t)))
            ours = str(fit_spherekit(knots, samples, {"max_error": eps}, closed=closed).fit_info["keys"])
            print(f"| {label} | {eps_deg:g}° | {k} | {math.degrees(err(k)):.3f} | {first} | {above} | {clamped} | {ours} |")
    print()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeat-large", type=int, default=1,
                        help="repetitions of the 10⁵-sample timing (best of; default 1, 0 skips it)")
    args = parser.parse_args()
    check_truth()
    print(f"python {platform.python_version()}, numpy {np.__version__}, scipy {scipy.__version__}, "
          f"spherekit {spherekit.__version__}, {platform.machine()}")
    print()
    start = time.perf_counter()
    recovery()
    key_reduction()
    speed(args.repeat_large)
    print(f"total {time.perf_counter() - start:.0f} s")


if __name__ == "__main__":
    main()
