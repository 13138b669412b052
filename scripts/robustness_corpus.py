#!/usr/bin/env python3
# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""Writes the degenerate-geometry corpus tests/robustness/degenerate/ (see ROBUSTNESS.md).

Each case is one scene file named after what it tests and its expected outcome:
`NAME.ok.json` (must build; every sample finite, unit norm) or `NAME.err.json` with
`NAME.err.txt` beside it holding a substring the one-line error must contain. The
expectations are the function expect_err below; every case not in it is expected to succeed.
The methods, their spheres, knot rules and minimum point counts come from the method
registry (`spherekit methods --json`), so a new method gets its cases without an edit here.

Run from the repository root (`just corpus` writes, `just corpus-check` compares):
    python3 scripts/robustness_corpus.py --registry REGISTRY.json [--check]
"""

import argparse
import filecmp
import json
import math
import os
import shutil
import sys
import tempfile

OUT = "tests/robustness/degenerate"

# Methods and the spaces they run on ("S<m>" stands for S5 here).
ALL_SPACES = ["S2", "S3", "S5"]
METHODS = {}      # id -> spaces
TAKES_KNOTS = set()
KNOTS_AT_INNER = set()  # knots at the inner points p₁ … p_{n−2} only
MIN_POINTS = {}
CLOSES = set()  # methods with a closed form ("closed": true)


REGISTRY = []
DICT = "fuzz/scene.dict"
# Scene keys and values of the format itself (the registry adds methods and parameters).
DICT_TOKENS = ["space", "method", "points", "knots", "params", "canonicalize", "closed",
               "parametrization", "native", "arclength", "extrapolate", "hold", "extend", "cycle",
               "error", "segment",
               "quaternion_order", "xyzw", "samples", "eval_at", "curves", "view", "color",
               "label", "fit", "gcv", "rms", "camera", "plot", "speed", "omega", "none", "plot_time", "normalized",
               "frames", "omega_frame", "body", "axes", "accuracy", "legend", "title", "S1", "S2",
               "S3", "S5"]
DICT_LITERALS = ["1e-9", "1e300", "-1e300", "1e-300", "0.999999999", "-1", "true", "false"]


def fuzz_dict():
    """The libFuzzer dictionary of the scene_bytes target: the format's keys and every
    registered method id, parameter name and choice."""
    words = list(DICT_TOKENS)
    for m in REGISTRY:
        words.append(m["id"])
        for p in m["params"]:
            words.append(p["name"])
            words += p.get("choices", [])
        words += [f["name"] for f in m.get("fit") or []]
    seen = []
    for w in words:
        if w not in seen:
            seen.append(w)
    lines = ["# Scene tokens for the scene_bytes target (libFuzzer -dict), written by",
             "# scripts/robustness_corpus.py from the method registry."]
    lines += ['"\\"' + w + '\\""' for w in seen]
    lines += ['"' + w + '"' for w in DICT_LITERALS]
    return "\n".join(lines) + "\n"


def load_registry(path):
    """Fills the tables above from `spherekit methods --json`."""
    with open(path) as f:
        registry = json.load(f)
    REGISTRY.extend(registry)
    for m in registry:
        METHODS[m["id"]] = ["S3"] if m["spaces"] == ["S3"] else ALL_SPACES
        knots = m["knots"]
        if isinstance(knots, dict):
            TAKES_KNOTS.add(m["id"])
            if knots["skip"] == 1:
                KNOTS_AT_INNER.add(m["id"])
        MIN_POINTS[m["id"]] = m["min_points"]
        if m["closes"]:
            CLOSES.add(m["id"])


# Wide parameter list: far outside, just outside, at, just inside each end of [0, 1] and [0, 3].
EDGE_PARAMS = [-1e300, -1.0, -1e-12, -0.0, 0.0, 1e-12, 0.5, 1.0 - 1e-12, 1.0, 1.0 + 1e-12,
               2.0, 3.0 - 1e-12, 3.0, 3.0 + 1e-12, 4.0, 1e300]


def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def rot(axis, angle):
    """Quaternion [w, x, y, z] of the rotation by `angle` about `axis`."""
    a = unit(axis)
    s = math.sin(angle / 2)
    return [math.cos(angle / 2), a[0] * s, a[1] * s, a[2] * s]


def on_circle(space, angle):
    """The point at `angle` along one fixed great circle of `space`."""
    c, s = math.cos(angle), math.sin(angle)
    if space == "S2":
        return unit([c, s * 0.6, s * 0.8])
    if space == "S3":
        return [c, s * 0.48, s * 0.6, s * 0.64]
    return [c, 0.0, s * 0.6, 0.0, s * 0.8, 0.0]


def generic(space, n, seed=1):
    """n well-spread points (about 0.7 rad apart) that wind around the sphere."""
    pts = []
    for i in range(n):
        a = 0.7 * i + 0.1 * seed
        b = 0.45 * math.sin(1.3 * i + seed)
        if space == "S2":
            p = [math.cos(a) * math.cos(b), math.sin(a) * math.cos(b), math.sin(b)]
        elif space == "S3":
            p = [math.cos(a / 2) * math.cos(b), math.sin(a / 2) * math.cos(b), math.sin(b) * 0.6, math.sin(b) * 0.8]
        else:
            p = [math.cos(a) * math.cos(b), math.sin(a) * math.cos(b), math.sin(b) * 0.6, 0.0, math.sin(b) * 0.8, 0.1]
        pts.append(unit(p))
    return pts


def ring(space, n):
    """n points around a loop (a small circle, and its analogues on S3 and S5)."""
    pts = []
    for i in range(n):
        a = 2 * math.pi * (i + 0.1 * (i % 2)) / n
        c, s = math.cos(a), math.sin(a)
        if space == "S2":
            p = [c, s, 1.1]
        elif space == "S3":
            p = [1.0, 0.4 * c, 0.4 * s, 0.3 * math.sin(2 * a)]
        else:
            p = [c, s, 1.0, 0.3 * math.sin(2 * a), 0.3, -0.2]
        pts.append(unit(p))
    return pts


def near(p, eps, space):
    """A point at angle eps from p (in a direction orthogonal to p)."""
    d = [0.0] * len(p)
    # Gram-Schmidt from a fixed vector.
    v = [0.3, -0.5, 0.7, 0.2, -0.1, 0.4][: len(p)]
    dot = sum(a * b for a, b in zip(v, p))
    d = unit([a - dot * b for a, b in zip(v, p)])
    return [math.cos(eps) * a + math.sin(eps) * b for a, b in zip(p, d)]


def scene(space, method, points, **extra):
    s = {"space": space, "method": method, "points": points}
    s.update(extra)
    return s


def cases():
    """Yields (name, scene)."""
    for method, spaces in METHODS.items():
        m = method.replace("-", "_")
        nmin = max(MIN_POINTS.get(method, 2), 4)
        for space in spaces:
            sp = space.lower()
            base = generic(space, nmin + 1)
            pre = f"{m}_{sp}"
            # Identical consecutive keys (in the middle of the sequence).
            pts = base[:2] + [base[1]] + base[2:]
            yield f"{pre}_identical_keys", scene(space, method, pts, samples=65)
            # All keys identical.
            yield f"{pre}_all_keys_identical", scene(space, method, [base[0]] * nmin, samples=17)
            # Keys 1e-9 apart.
            pts = base[:2] + [near(base[1], 1e-9, space)] + base[2:]
            yield f"{pre}_keys_1e-9_apart", scene(space, method, pts, samples=65)
            # Every key 1e-9 from the one before.
            pts = [near(base[0], 1e-9 * i, space) for i in range(nmin)]
            yield f"{pre}_all_keys_1e-9_apart", scene(space, method, pts, samples=17)
            # Neighbours at π − 1e-9 (nearly antipodal on the sphere).
            p = base[0]
            q = [-x for x in near(p, 1e-9, space)]
            pts = [p, q] + [near(q, 0.5 + 0.3 * i, space) for i in range(1, nmin - 1)]
            yield f"{pre}_near_antipodal_1e-9", scene(space, method, pts, samples=65)
            # Exactly antipodal neighbours.
            pts = [p, [-x for x in p]] + base[2:nmin]
            yield f"{pre}_antipodal", scene(space, method, pts, samples=17)
            # Three (or more) points on one great circle.
            pts = [on_circle(space, 0.4 * i) for i in range(nmin + 1)]
            yield f"{pre}_great_circle", scene(space, method, pts, samples=65)
            # Parameters at, just inside and just outside the domain.
            pts = base[: max(nmin, 4)]
            extra = {}
            if method in TAKES_KNOTS:
                n_knots = len(pts) - 2 if method in KNOTS_AT_INNER else len(pts)
                extra["knots"] = [3.0 * i / (n_knots - 1) for i in range(n_knots)]
            yield f"{pre}_params_edge", scene(space, method, pts, eval_at=EDGE_PARAMS, **extra)
            # The curve-level timing fields: every policy at the edge parameters, arc length on
            # degenerate keys (identical ones, all at one point, all 1e-9 apart).
            for policy in ("hold", "extend", "error", "segment"):
                yield f"{pre}_extrapolate_{policy}_params_edge", scene(
                    space, method, pts, eval_at=EDGE_PARAMS, extrapolate=policy, **extra)
            yield f"{pre}_arclength_params_edge", scene(
                space, method, pts, eval_at=EDGE_PARAMS, parametrization="arclength", **extra)
            yield f"{pre}_arclength_extend_params_edge", scene(
                space, method, pts, eval_at=EDGE_PARAMS, parametrization="arclength", extrapolate="extend")
            dup = base[:2] + [base[1]] + base[2:]
            yield f"{pre}_arclength_identical_keys", scene(space, method, dup, parametrization="arclength", samples=65)
            yield f"{pre}_arclength_all_keys_identical", scene(
                space, method, [base[0]] * nmin, parametrization="arclength", samples=17)
            yield f"{pre}_arclength_all_keys_1e-9_apart", scene(
                space, method, [near(base[0], 1e-9 * i, space) for i in range(nmin)],
                parametrization="arclength", samples=17)
            # 10 000 keys: generated by the test itself (robustness.rs), not stored (≈ 15 MB).
            # Huge and tiny knot spacings.
            if method in TAKES_KNOTS:
                pts = base[: max(nmin, 5)]
                n_knots = len(pts) - 2 if method in KNOTS_AT_INNER else len(pts)
                mixed = [0.0]
                for i in range(1, n_knots):
                    mixed.append(mixed[-1] + (1e-6 if i % 2 else 1e6))
                yield f"{pre}_knots_mixed_1e-6_1e6", scene(space, method, pts, knots=mixed, samples=257)
                yield f"{pre}_knots_tiny_1e-6", scene(space, method, pts,
                                                        knots=[1e-6 * i for i in range(n_knots)], samples=65)
                yield f"{pre}_knots_huge_1e6", scene(space, method, pts,
                                                       knots=[1e6 * i for i in range(n_knots)], samples=65)
                yield f"{pre}_knots_offset_1e9", scene(space, method, pts,
                                                         knots=[1e9 + i for i in range(n_knots)], samples=65)
        # Closed loops (the closing step is one more step of the sequence).
        for space in spaces if method in CLOSES else []:
            sp = space.lower()
            pre = f"{m}_{sp}_closed"
            n = max(nmin, 5)
            loop = ring(space, n)
            yield pre, scene(space, method, loop, closed=True, samples=65)
            extra = {"knots": [3.0 * i / n for i in range(n + 1)]} if method in TAKES_KNOTS else {}
            yield f"{pre}_params_edge", scene(space, method, loop, closed=True, eval_at=EDGE_PARAMS, **extra)
            # A loop repeats under "cycle" (the policy only closed curves take).
            yield f"{pre}_extrapolate_cycle_params_edge", scene(
                space, method, loop, closed=True, eval_at=EDGE_PARAMS, extrapolate="cycle", **extra)
            yield f"{pre}_minimum_points", scene(space, method, ring(space, 3), closed=True, samples=65)
            # The last point equal to the first (a zero-length closing step).
            yield f"{pre}_seam_identical", scene(space, method, loop + [loop[0]], closed=True, samples=65)
            # The last point 1e-9 from the first, and 1e-9 from antipodal to it.
            yield f"{pre}_seam_1e-9", scene(space, method, loop + [near(loop[0], 1e-9, space)], closed=True,
                                            samples=65)
            q = [-x for x in near(loop[0], 1e-9, space)]
            yield f"{pre}_seam_near_antipodal_1e-9", scene(space, method, loop[:3] + [q], closed=True,
                                                           samples=65)
            # The last point antipodal to the first (kept as given on S3).
            pts = loop[:3] + [[-x for x in loop[0]]]
            extra = {"canonicalize": False} if space == "S3" else {}
            yield f"{pre}_seam_antipodal", scene(space, method, pts, closed=True, samples=17, **extra)
            if space == "S3":
                # Camera orbits of one full turn in 3 and 4 keys: loops of rotations closed at −q₀,
                # also repeated under "cycle" past both ends.
                for k in (3, 4):
                    orbit = [rot([0.0, 0.0, 1.0], 2 * math.pi * i / k) for i in range(k)]
                    yield f"{pre}_full_turn_orbit_{k}", scene(space, method, orbit, closed=True, samples=65)
                yield f"{pre}_full_turn_orbit_cycle_params_edge", scene(
                    space, method, orbit, closed=True, eval_at=EDGE_PARAMS, extrapolate="cycle")
            if method in TAKES_KNOTS:
                mixed = [0.0]
                for i in range(1, n + 1):
                    mixed.append(mixed[-1] + (1e-6 if i % 2 else 1e6))
                yield f"{pre}_knots_mixed_1e-6_1e6", scene(space, method, loop, closed=True, knots=mixed,
                                                          samples=257)
        if "S3" in spaces:
            base = generic("S3", nmin + 1)
            pre = f"{m}_s3"
            # q and −q in one sequence, with and without canonicalisation.
            pts = base[:2] + [[-x for x in base[1]]] + base[2:]
            yield f"{pre}_q_and_minus_q", scene("S3", method, pts, samples=65)
            yield f"{pre}_q_and_minus_q_no_canonicalize", scene("S3", method, pts, canonicalize=False, samples=65)
            # Every other key negated.
            pts = [[-x for x in q] if i % 2 else q for i, q in enumerate(base)]
            yield f"{pre}_alternating_signs", scene("S3", method, pts, samples=65)
            yield f"{pre}_alternating_signs_no_canonicalize", scene("S3", method, pts, canonicalize=False, samples=65)
            # Rotations a half turn minus 1e-9 apart (quaternions π/2 − 5e-10 apart), and a half turn.
            pts = [rot([0, 0, 1], math.pi * k - 1e-9 * k) for k in range(nmin)]
            yield f"{pre}_half_turn_minus_1e-9", scene("S3", method, pts, samples=65)
            pts = [rot([1, 1, 0], math.pi * k) for k in range(nmin)]
            yield f"{pre}_half_turns", scene("S3", method, pts, samples=65)
            yield f"{pre}_half_turns_no_canonicalize", scene("S3", method, pts, canonicalize=False, samples=65)
            # Near-antipodal quaternions that canonicalisation turns into near-identical ones.
            p = base[0]
            q = [-x for x in near(p, 1e-9, "S3")]
            pts = [p, q] + base[2:nmin]
            yield f"{pre}_near_minus_q_canonicalized", scene("S3", method, pts, samples=65)

    # Shape parameters.
    for space in ALL_SPACES:
        sp = space.lower()
        pts = generic(space, 6)
        for name, params in [
            ("beta1_1e-9", {"beta1": 1e-9}),
            ("beta1_1e-300", {"beta1": 1e-300}),
            ("beta1_1e6", {"beta1": 1e6}),
            ("beta2_1e6", {"beta2": 1e6}),
            ("beta2_1e12", {"beta2": 1e12}),
            ("beta2_0", {"beta2": 0.0}),
            ("beta1_1e-9_beta2_1e6", {"beta1": 1e-9, "beta2": 1e6}),
            ("beta1_0", {"beta1": 0.0}),
            ("beta1_negative", {"beta1": -1.0}),
            ("beta2_negative", {"beta2": -1.0}),
            ("beta_approximating_beta1_1e-9", {"beta1": 1e-9, "interpolate": False}),
            ("beta_approximating_beta2_1e6", {"beta2": 1e6, "interpolate": False}),
            ("beta1_per_point_extreme", {"beta1": [1e-9, 1e6, 1.0, 1e-9, 1e6, 1.0]}),
            ("jacobi_beta2_1e6", {"beta2": 1e6, "solver": "jacobi"}),
        ]:
            yield f"beta_{sp}_{name}", scene(space, "beta", pts, params=params, samples=129)
        for label, frac in [("1e-12", 1e-12), ("1e-9", 1e-9), ("0.5", 0.5), ("0.5_plus_1e-12", 0.5 + 1e-12),
                            ("0", 0.0)]:
            yield f"corner_blend_{sp}_fraction_{label}", scene(
                space, "corner-blend", pts, params={"fraction": frac}, samples=129)
        # Cuts per corner and side, and the timing (6 points: 4 corners).
        for label, params in [
            ("cuts_per_corner", {"fraction": [0.1, 0.45, 0.3, 0.2]}),
            ("cuts_pairs_whole_edges", {"fraction": [0.1, 0.05, 0.3, 0.2], "fraction_out": [0.95, 0.7, 0.7, 0.95]}),
            ("cuts_pairs_1e-9", {"fraction": 1e-9, "fraction_out": 0.5}),
            ("cuts_overlap", {"fraction": [0.1, 0.6, 0.3, 0.2], "fraction_out": 0.5}),
            ("cuts_out_of_range", {"fraction": [0.1, 1.0, 0.3, 0.2]}),
            ("cuts_wrong_length", {"fraction": [0.1, 0.2]}),
            ("speed_1e-6", {"speed": 1e-6}),
            ("speed_1e6", {"speed": 1e6}),
            ("speed_0", {"speed": 0.0}),
            ("start_negative_1e6", {"start": -1e6}),
        ]:
            yield f"corner_blend_{sp}_{label}", scene(space, "corner-blend", pts, params=params, samples=129)
        for n in [1, 10]:
            yield f"arc_blend_{sp}_smoothness_{n}", scene(space, "arc-blend", pts, params={"smoothness": n}, samples=129)
            yield f"corner_blend_{sp}_smoothness_{n}", scene(space, "corner-blend", pts, params={"smoothness": n}, samples=129)
    # Small-circle legs (S2 only): one bend for all edges, one per edge, next to ±1.
    pts = generic("S2", 6)
    for label, bend in [("0.9", 0.9), ("per_edge", [0.5, -0.5, 0.9, -0.9, 0.0]),
                        ("1_minus_1e-12", 1.0 - 1e-12), ("1", 1.0), ("wrong_length", [0.1, 0.2])]:
        yield f"corner_blend_s2_bend_{label}", scene("S2", "corner-blend", pts, params={"bend": bend}, samples=129)
    pts = generic("S3", 7)
    for name, g in [("gamma_1e-9", 1e-9), ("gamma_1e-300", 1e-300), ("gamma_1e6", 1e6), ("gamma_1e12", 1e12),
                    ("gamma_0", 0.0), ("gamma_negative", -1.0), ("gamma_per_joint_extreme", [1e-9, 1e6, 1e-9])]:
        yield f"gamma_s3_{name}", scene("S3", "gamma", pts, params={"gamma": g}, samples=129)
        yield f"gamma_s3_{name}_paper_example", scene(
            "S3", "gamma", pts, params={"gamma": g, "last_edge": "paper-example"}, samples=129)
    # Keys with velocities (the cubic's params.velocities): ordinary, huge, tiny and zero rates,
    # on degenerate keys, open and closed; on S3 angular velocities in either frame.
    yield from hermite_cases()
    # Multi-curve scenes share the checks.
    yield "compare_s2_identical_keys_every_method", {
        "space": "S2",
        "curves": [{"method": m, "points": generic("S2", 5)[:2] + [generic("S2", 5)[1]] + generic("S2", 5)[2:]}
                   for m, sps in METHODS.items() if "S2" in sps],
        "samples": 33,
    }


def tangent_rates(space, pts, scale, seed=1):
    """A velocity at every point of `pts`: on S3 an angular velocity [x, y, z], elsewhere a
    tangent vector (a fixed vector with its component along the point removed), times `scale`."""
    out = []
    for i, p in enumerate(pts):
        a = 0.9 * i + seed
        if space == "S3":
            out.append([scale * math.cos(a), scale * 0.5 * math.sin(a), scale * 0.7])
            continue
        v = [math.cos(a + k) for k in range(len(p))]
        dot = sum(x * y for x, y in zip(v, p))
        out.append([scale * (x - dot * y) for x, y in zip(v, p)])
    return out


def hermite_cases():
    """Yields (name, scene) for the cubic with a velocity at every key."""
    for space in ALL_SPACES:
        sp = space.lower()
        pre = f"cubic_{sp}_velocities"
        base = generic(space, 5)
        frames = [{"frame": "space"}, {"frame": "body"}] if space == "S3" else [{}]
        for frame in frames:
            f = f"_{frame['frame']}" if frame else ""
            for label, scale in [("", 1.0), ("_1e6", 1e6), ("_1e-300", 1e-300), ("_zero", 0.0)]:
                params = {"velocities": tangent_rates(space, base, scale), **frame}
                yield f"{pre}{f}{label}", scene(space, "cubic", base, params=params, samples=65)
            params = {"velocities": tangent_rates(space, base, 1.0), **frame}
            yield f"{pre}{f}_params_edge", scene(space, "cubic", base, params=params, eval_at=EDGE_PARAMS,
                                                 knots=[3.0 * i / 4 for i in range(5)])
            pts = base[:2] + [base[1]] + base[2:]
            params = {"velocities": tangent_rates(space, pts, 1.0), **frame}
            yield f"{pre}{f}_identical_keys", scene(space, "cubic", pts, params=params, samples=65)
            p = base[0]
            q = [-x for x in near(p, 1e-9, space)]
            pts = [p, q] + base[2:]
            params = {"velocities": tangent_rates(space, pts, 1.0), **frame}
            yield f"{pre}{f}_near_antipodal_1e-9", scene(space, "cubic", pts, params=params, samples=65)
            loop = ring(space, 5)
            params = {"velocities": tangent_rates(space, loop, 1.0), **frame}
            yield f"{pre}{f}_closed", scene(space, "cubic", loop, params=params, closed=True,
                                            extrapolate="cycle", eval_at=EDGE_PARAMS)
            if space == "S3":
                # q and −q (canonicalised: the rate goes with the rotation), and a loop of one
                # full turn (closed at −q₀), with rates.
                pts = base[:2] + [[-x for x in base[1]]] + base[2:]
                params = {"velocities": tangent_rates(space, pts, 1.0), **frame}
                yield f"{pre}{f}_q_and_minus_q", scene(space, "cubic", pts, params=params, samples=65)
                orbit = [rot([0.0, 0.0, 1.0], 2 * math.pi * i / 3) for i in range(3)]
                params = {"velocities": [[0.0, 0.0, 2 * math.pi / 3]] * 3, **frame}
                yield f"{pre}{f}_full_turn_orbit_3", scene(space, "cubic", orbit, params=params, closed=True,
                                                          extrapolate="cycle", eval_at=EDGE_PARAMS)


# Methods that need distinct consecutive points (a circle through three points, a corner).
NEEDS_DISTINCT = ("arc_blend_", "beta_", "corner_blend_")
ANTIPODAL = "are antipodal: the geodesic between them is not unique"
COINCIDE = "coincide: this method needs distinct consecutive points"
NO_CONVERGENCE = "params.solver: the solver did not converge"


def expect_err(name):
    """The substring the error line must contain, or None when the case must succeed."""
    distinct = name.startswith(NEEDS_DISTINCT)
    # Closed loops: the closing pair of points is a pair of neighbours like the others.
    if "_closed_seam_antipodal" in name:
        return "closed: the last and the first point are antipodal"
    if "_closed_seam_identical" in name and distinct:
        return "closed: the last and the first point coincide"
    if name in ("cubic_s2_closed_seam_near_antipodal_1e-9", "cubic_s5_closed_seam_near_antipodal_1e-9"):
        return "points: the C² spline could not be solved"
    if name in ("catmull_rom_nlerp_s2_closed_seam_near_antipodal_1e-9",
                "catmull_rom_nlerp_s5_closed_seam_near_antipodal_1e-9"):
        return "points[3] to points[0]: the ambient curve of this segment may pass through the origin"
    if name == "beta_s3_closed_seam_near_antipodal_1e-9":
        # Canonicalisation flips the last key to 1e-9 from q₀: a short closing step, solved.
        return None
    if name.endswith("_q_and_minus_q_no_canonicalize"):
        return "points[1] and points[2] " + ANTIPODAL
    if name.endswith("_q_and_minus_q") and distinct:
        return "points[1] and points[2] " + COINCIDE
    if name.endswith("_antipodal"):
        # On S3 canonicalisation turns −q into q.
        if "_s3_" in name:
            return "points[0] and points[1] " + COINCIDE if distinct else None
        return "points[0] and points[1] " + ANTIPODAL
    # The timing fields (before the rules on the keys, which the same names end with).
    if "_extrapolate_error_params_edge" in name:
        return "eval_at[0]: -1e300 is outside the domain"
    if "_extrapolate_segment_" in name and not name.startswith("cubic_"):
        return 'extrapolate: "segment" continues the end segments'
    if "_extrapolate_segment_" in name:
        return "eval_at[0]: -1e300 is so far outside the domain of the curve that its continued end segment overflows"
    if "_arclength_" in name and name.endswith("_all_keys_identical"):
        return "points[0] and points[1] " + COINCIDE if distinct else "parametrization: the curve has zero length"
    if name.endswith("_all_keys_identical") and distinct:
        return "points[0] and points[1] " + COINCIDE
    if name.endswith("_identical_keys") and distinct:
        return "points[1] and points[2] " + COINCIDE
    # The Beta spline's interpolation solver (beta_solve.rs) does not converge for extreme β₁
    # or a near-antipodal step: a typed error, documented in ROBUSTNESS.md.
    if name.startswith("beta_") and "approximating" not in name and "_s3_near_antipodal" not in name and (
        name.endswith(("_beta1_1e-9", "_beta1_1e-300", "_beta1_1e6", "_beta1_per_point_extreme",
                       "_near_antipodal_1e-9"))
    ):
        return NO_CONVERGENCE
    # The cubic spline's C² equations are singular next to a near-antipodal step (dExp
    # degenerates at a half turn) and ill-conditioned for time spacings 1e12 apart: a typed
    # error, documented in ROBUSTNESS.md. (cubic_s2_near_antipodal_1e-9 converges since the
    # scene's numbers are read back exactly, serde_json's float_roundtrip.)
    if name in ("cubic_s2_knots_mixed_1e-6_1e6",
                "cubic_s3_knots_mixed_1e-6_1e6", "cubic_s5_knots_mixed_1e-6_1e6"):
        return "points: the C² spline could not be solved"
    if name.endswith(("_beta1_0", "_beta1_negative")):
        return "params.beta1: must be > 0"
    if name.endswith("_beta2_negative"):
        return "params.beta2: must be ≥ 0"
    if name.endswith(("_fraction_0", "_fraction_0.5_plus_1e-12")):
        return "params.fraction: must be in (0, 0.5]"
    if name.endswith("_cuts_pairs_1e-9"):
        # The speed grows ×5·10⁸ at each corner: the later pieces cannot be timed in f64.
        return "params.fraction: piece"
    if name.endswith("_cuts_overlap"):
        return "params.fraction: entries 0 and 1 overlap on the edge from point 1 to point 2"
    if name.endswith("_cuts_out_of_range"):
        return "params.fraction: entry 1 (the corner at point 2): the incoming cut must be in (0, 1)"
    if name.endswith("_cuts_wrong_length"):
        return "params.fraction: expected 4 entries (one per corner, the points 1 to 4), got 2"
    if name.endswith("_speed_0"):
        return "params.speed: must be a positive number"
    if name == "corner_blend_s2_bend_1":
        return "params.bend: entry 0 (the edge from point 0): must be in (−1, 1)"
    if name == "corner_blend_s2_bend_wrong_length":
        return "params.bend: expected 5 values (one per edge), got 2"
    if "_gamma_0" in name or "_gamma_negative" in name:
        return "params.gamma: must be finite and positive"
    if name == "compare_s2_identical_keys_every_method":
        return "curves[5].points[1] and points[2] " + COINCIDE
    return None


BAD = "tests/robustness/bad"
S2 = '"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0],[0,0,1]]'
S3 = '"space":"S3","method":"squad","points":[[1,0,0,0],[0,1,0,0],[0,0,1,0]]'
FIT = '"space":"S2","method":"cubic","points":[[1,0,0],[0.98,0.2,0],[0.92,0.39,0],[0.83,0.56,0],[0.7,0.72,0]],"knots":[0,0.1,0.2,0.3,0.4]'


def bad_cases():
    """(name, scene text, substring of the one-line error). Plain files, so that other front
    ends (the wasm crate) can run the same catalog."""
    deep = "[" * 200 + "]" * 200
    return [
        # Not JSON, or not a scene.
        ("empty_file", "", "invalid scene JSON"),
        ("whitespace_only", "  \n\t ", "invalid scene JSON"),
        ("truncated_object", "{" + S2[:40], "invalid scene JSON"),
        ("truncated_after_points", "{" + S2 + ",", "invalid scene JSON"),
        ("trailing_garbage", "{" + S2 + "} x", "invalid scene JSON"),
        ("two_objects", "{" + S2 + "}{" + S2 + "}", "invalid scene JSON"),
        ("top_level_array", "[" + "{" + S2 + "}]", "invalid scene JSON"),
        ("top_level_string", '"S2"', "invalid scene JSON"),
        ("top_level_null", "null", "invalid scene JSON"),
        ("not_utf8", b"{\"space\":\"S2\xff\"}", "valid UTF-8"),
        ("bom_prefix", "\ufeff{" + S2 + "}", "invalid scene JSON"),
        ("comment", "{" + S2 + " // three points\n}", "invalid scene JSON"),
        ("deeply_nested_points", '{"space":"S2","method":"geodesic","points":' + deep + "}", "points[0][0]: invalid type: sequence, expected f64"),
        ("deeply_nested_view", "{" + S2 + ',"view":' + deep + "}", "recursion limit"),
        ("deeply_nested_params", "{" + S2 + ',"params":{"a":' + deep + "}}", "recursion limit"),
        # Missing and unknown fields, wrong types.
        ("missing_space", '{"method":"geodesic","points":[[1,0,0],[0,1,0]]}', "missing field `space`"),
        ("missing_method", '{"space":"S2","points":[[1,0,0],[0,1,0]]}', "missing field `method`"),
        ("missing_points", '{"space":"S2","method":"geodesic"}', "missing field `points`"),
        ("unknown_field", "{" + S2 + ',"sample":5}', "unknown field `sample`"),
        ("unknown_method", '{"space":"S2","method":"bspline","points":[[1,0,0],[0,1,0]]}', 'method: unknown method "bspline"'),
        ("method_wrong_space", '{"space":"S2","method":"squad","points":[[1,0,0],[0,1,0]]}', 'method: "squad" works on S3, not S2'),
        ("unknown_space", '{"space":"R3","method":"geodesic","points":[[1,0,0],[0,1,0]]}', 'space: "R3" is not a sphere'),
        ("space_s0", '{"space":"S0","method":"geodesic","points":[[1],[1]]}', 'space: "S0" is not a sphere'),
        ("space_huge_dimension", '{"space":"S99999999999999999999","method":"geodesic","points":[[1],[1]]}', "is not a sphere"),
        ("space_number", '{"space":2,"method":"geodesic","points":[[1,0,0],[0,1,0]]}', "invalid type: integer `2`, expected a string"),
        ("points_not_list", '{"space":"S2","method":"geodesic","points":"[[1,0,0]]"}', "invalid type: string"),
        ("point_string_coordinate", '{"space":"S2","method":"geodesic","points":[[1,0,0],[0,"1",0]]}', "invalid type: string \"1\", expected f64"),
        ("point_null_coordinate", '{"space":"S2","method":"geodesic","points":[[1,0,0],[0,null,0]]}', "points[1][1]: invalid type: null, expected f64"),
        ("unknown_param", "{" + S2 + ',"params":{"tension":1}}', 'params.tension: unknown parameter for method "geodesic"'),
        ("params_not_object", "{" + S2 + ',"params":[1]}', "invalid type: sequence, expected a map"),
        ("canonicalize_on_s2", "{" + S2 + ',"canonicalize":false}', "canonicalize: applies to S3"),
        ("canonicalize_string", "{" + S3 + ',"canonicalize":"no"}', "invalid type: string \"no\", expected a boolean"),
        ("bad_color", "{" + S2 + ',"color":"red"}', 'color: "red" is not a colour'),
        ("curves_and_method", '{"space":"S2","method":"geodesic","curves":[{"method":"nlerp","points":[[1,0,0],[0,1,0]]}]}', "curves: give either"),
        ("curves_empty", '{"space":"S2","curves":[]}', "curves: must list at least one curve"),
        ("curves_bad_point", '{"space":"S2","curves":[{"method":"nlerp","points":[[1,0,0],[0,1,0]]},{"method":"geodesic","points":[[1,0,0],[0,0,0]]}]}', "curves[1].points[1] has zero length"),
        # `view` is read by the renderer only: `spherekit sample` ignores it (files named render_*).
        ("render_view_unknown_option", "{" + S2 + ',"view":{"zoom":2}}', "view.zoom: unknown view option"),
        # Control characters in quoted names (found by fuzzing: the message was two lines).
        ("unknown_field_with_newline", '{"space":"S2","method":"geodesic","poi\\nts":[[1,0,0],[0,1,0]]}', "unknown field `poi\\nts`"),
        ("unknown_method_with_newline", '{"space":"S2","method":"geo\\ndesic","points":[[1,0,0],[0,1,0]]}', 'unknown method "geo\\ndesic"'),
        ("unknown_param_with_control_chars", "{" + S2 + ',"params":{"a\\r\\n\\u001b":1}}', "params.a\\r\\n\\u{1b}: unknown parameter"),
        ("space_with_newline", '{"space":"S\\n2","method":"geodesic","points":[[1,0,0],[0,1,0]]}', 'space: "S\\n2" is not a sphere'),
        ("render_view_key_with_newline", "{" + S2 + ',"view":{"cam\\nera":1}}', "view.cam\\nera: unknown view option"),
        # Non-finite numbers.
        ("points_nan_literal", '{"space":"S2","method":"geodesic","points":[[1,0,0],[NaN,1,0]]}', "points[1][0]: expected value"),
        ("points_infinity_literal", '{"space":"S2","method":"geodesic","points":[[1,0,0],[Infinity,1,0]]}', "points[1][0]: expected value"),
        ("points_1e400", '{"space":"S2","method":"geodesic","points":[[1,0,0],[1e400,1,0]]}', "points[1][0]: number out of range"),
        ("knots_1e400", "{" + S2 + ',"knots":[0,1,1e400]}', "knots[2]: number out of range"),
        ("samples_1e400", "{" + S2 + ',"samples":1e400}', "samples: number out of range"),
        ("eval_at_1e400", "{" + S2 + ',"eval_at":[0,1e400]}', "eval_at[1]: number out of range"),
        ("param_nan_string", '{"space":"S2","method":"corner-blend","points":[[1,0,0],[0,1,0],[0,0,1]],"params":{"fraction":"NaN"}}', "params.fraction: must be a number or a list of numbers"),
        ("beta1_1e400", '{"space":"S2","method":"beta","points":[[1,0,0],[0,1,0],[0,0,1]],"params":{"beta1":1e400}}', "params.beta1: number out of range"),
        # Points.
        ("points_empty", '{"space":"S2","method":"geodesic","points":[]}', "needs at least 2 points, got 0"),
        ("points_one", '{"space":"S2","method":"geodesic","points":[[1,0,0]]}', "needs at least 2 points, got 1"),
        ("catmull_rom_three_points", '{"space":"S2","method":"catmull-rom","points":[[1,0,0],[0,1,0],[0,0,1]]}', "needs at least 4 points, got 3"),
        ("points_zero_vector", '{"space":"S2","method":"geodesic","points":[[1,0,0],[0,0,0]]}', "points[1] has zero length"),
        ("points_subnormal_vector", '{"space":"S2","method":"geodesic","points":[[1,0,0],[1e-320,0,0]]}', "points[1] has zero length"),
        ("point_too_short", '{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1]]}', "points[1]: has 2 coordinates, S2 points have 3"),
        ("point_too_long", '{"space":"S3","method":"squad","points":[[1,0,0,0],[0,1,0,0,0]]}', "points[1]: has 5 coordinates, S3 points have 4"),
        ("points_mixed_lengths", '{"space":"S5","method":"nlerp","points":[[1,0,0,0,0,0],[0,1,0,0,0],[0,0,1,0,0,0,0]]}', "points[1]: has 5 coordinates, S5 points have 6"),
        ("point_empty", '{"space":"S2","method":"geodesic","points":[[1,0,0],[]]}', "points[1]: has 0 coordinates"),
        ("antipodal_neighbours", '{"space":"S2","method":"geodesic","points":[[1,0,0],[-1,0,0]]}', "points[0] and points[1] are antipodal"),
        # Knots.
        ("knots_not_increasing", "{" + S2 + ',"knots":[0,2,1]}', "knots[2]"),
        ("knots_repeated", "{" + S2 + ',"knots":[0,1,1]}', "knots[2]"),
        ("knots_wrong_count", "{" + S2 + ',"knots":[0,1]}', "knots: expected 3 knots, got 2"),
        ("knots_for_bezier", '{"space":"S2","method":"bezier","points":[[1,0,0],[0,1,0]],"knots":[0,1]}', 'knots: method "bezier" takes no knots'),
        # Found by fuzzing (scene_bytes): 1e-96 spacing made |acceleration jumps| overflow.
        ("knots_spacing_1e-96", '{"space":"S2","method":"catmull-rom","points":[[0.9245181863860598,0.09276122906808075,0.36967753167214523],[0.6578469395012764,0.6773445735480922,0.32930492385288923],[0.06933930854407318,0.9777827086264879,-0.19782071428866735],[-0.5319188672180433,0.7307624041144873,-0.4278418252465374],[-0.9702795301900121,0.23908210989940434,-0.03738151976978039]],"knots":[0.0,1e-96,1000000.000001],"samples":257}', "knots[1] − knots[0] must be from 1e-50 to 1e50"),
        ("knots_spacing_subnormal", "{" + S2 + ',"knots":[0,5e-324,1]}', "knots[1] − knots[0] must be from 1e-50 to 1e50"),
        ("knots_spacing_overflows", "{" + S2 + ',"knots":[-1e308,1e308,1.7e308]}', "knots[1] − knots[0] must be from 1e-50 to 1e50"),
        ("knots_strings", "{" + S2 + ',"knots":["0","1","2"]}', "invalid type: string"),
        # Sampling.
        ("samples_zero", "{" + S2 + ',"samples":0}', "samples: must be a whole number from 2 to 1000000, got 0"),
        ("samples_one", "{" + S2 + ',"samples":1}', "samples: must be a whole number from 2 to 1000000, got 1"),
        ("samples_negative", "{" + S2 + ',"samples":-5}', "samples: must be a whole number from 2 to 1000000, got -5"),
        ("samples_fraction", "{" + S2 + ',"samples":2.5}', "samples: must be a whole number from 2 to 1000000, got 2.5"),
        ("samples_1e12", "{" + S2 + ',"samples":1e12}', "samples: must be a whole number from 2 to 1000000, got 1000000000000"),
        ("samples_above_limit", "{" + S2 + ',"samples":1000001}', "samples: must be a whole number from 2 to 1000000"),
        ("samples_times_curves_above_limit", '{"space":"S2","curves":[{"method":"geodesic","points":[[1,0,0],[0,1,0]]},{"method":"nlerp","points":[[1,0,0],[0,1,0]]}],"samples":600000}', "samples: 2 curves × 600000 parameters exceed the limit of 1000000 evaluations per scene"),
        ("samples_string", "{" + S2 + ',"samples":"10"}', "invalid type: string"),
        ("samples_and_eval_at", "{" + S2 + ',"samples":5,"eval_at":[0]}', "eval_at: give either samples or eval_at"),
        ("eval_at_empty", "{" + S2 + ',"eval_at":[]}', "eval_at: must have 1 to 1000000 parameters, got 0"),
        # Method parameters.
        ("smoothness_zero", '{"space":"S2","method":"arc-blend","points":[[1,0,0],[0,1,0],[0,0,1]],"params":{"smoothness":0}}', "params.smoothness: must be a whole number from 1 to 10, got 0"),
        ("smoothness_eleven", '{"space":"S3","method":"corner-blend","points":[[1,0,0,0],[0,1,0,0],[0,0,1,0]],"params":{"smoothness":11}}', "params.smoothness: must be a whole number from 1 to 10, got 11"),
        ("smoothness_huge", '{"space":"S2","method":"arc-blend","points":[[1,0,0],[0,1,0],[0,0,1]],"params":{"smoothness":1e12}}', "params.smoothness: must be a whole number"),
        ("smoothness_negative", '{"space":"S2","method":"corner-blend","points":[[1,0,0],[0,1,0],[0,0,1]],"params":{"smoothness":-1}}', "params.smoothness: must be a whole number"),
        # `order`, the earlier name of `smoothness`, is read as it (out of range here), but not beside it.
        ("order_zero", '{"space":"S2","method":"arc-blend","points":[[1,0,0],[0,1,0],[0,0,1]],"params":{"order":0}}', "params.smoothness: must be a whole number from 1 to 10, got 0"),
        ("order_and_smoothness", '{"space":"S2","method":"corner-blend","points":[[1,0,0],[0,1,0],[0,0,1]],"params":{"order":2,"smoothness":2}}', "params.order: is the earlier name of params.smoothness: give one of them"),
        ("fraction_above_half", '{"space":"S2","method":"corner-blend","points":[[1,0,0],[0,1,0],[0,0,1]],"params":{"fraction":0.75}}', "params.fraction: must be in (0, 0.5]"),
        ("gamma_list_wrong_length", '{"space":"S3","method":"gamma","points":[[1,0,0,0],[0.9,0.1,0,0],[0.8,0.2,0.1,0],[0.7,0.3,0.2,0.1],[0.6,0.4,0.3,0.1]],"params":{"gamma":[1,2,3,4]}}', "params.gamma: must have one value per interior knot (1), got 4"),
        ("gamma_string", '{"space":"S3","method":"gamma","points":[[1,0,0,0],[0.9,0.1,0,0],[0.8,0.2,0.1,0],[0.7,0.3,0.2,0.1]],"params":{"gamma":"1"}}', "params.gamma: must be a number or a list of numbers"),
        ("beta1_list_wrong_length", '{"space":"S2","method":"beta","points":[[1,0,0],[0,1,0],[0,0,1]],"params":{"beta1":[1,2]}}', "params.beta1: must be one number or a list of 3 numbers"),
        ("beta_tolerance_zero", '{"space":"S2","method":"beta","points":[[1,0,0],[0,1,0],[0,0,1]],"params":{"tolerance":0}}', "params.tolerance: must be a positive number"),
        ("beta_max_iterations_huge", '{"space":"S2","method":"beta","points":[[1,0,0],[0,1,0],[0,0,1]],"params":{"max_iterations":1e12}}', "params.max_iterations: must be a whole number from 1 to 1000000"),
        ("beta_unknown_solver", '{"space":"S2","method":"beta","points":[[1,0,0],[0,1,0],[0,0,1]],"params":{"solver":"gauss"}}', "params.solver: must be one of: newton, jacobi"),
        ("catmull_rom_bad_tangent", '{"space":"S3","method":"catmull-rom","points":[[1,0,0,0],[0.9,0.1,0,0],[0.8,0.2,0.1,0],[0.7,0.3,0.2,0.1]],"params":{"tangent":"chordal"}}', "params.tangent: must be one of: quaternion, intrinsic"),
        ("closed_bezier", '{"space":"S2","method":"bezier","closed":true,"points":[[1,0,0],[0,1,0],[0,0,1]]}', 'closed: method "bezier" has no closed form'),
        ("closed_geodesic_two_points", '{"space":"S2","method":"geodesic","closed":true,"points":[[1,0,0],[0,1,0]]}', "points: this method needs at least 3 points, got 2"),
        ("closed_catmull_rom_open_knot_count", '{"space":"S2","method":"catmull-rom","closed":true,"points":[[1,0,0],[0,1,0],[0,0,1],[-1,0.2,0.3]],"knots":[0,1]}', "knots: expected 5 knots, got 2"),
        ("closed_squad_knots_not_increasing", '{"space":"S3","method":"squad","closed":true,"points":[[1,0,0,0],[0.9,0.1,0,0],[0.8,0.2,0.1,0]],"knots":[0,1,1,2]}', "knots[2] is not greater than knots[1]"),
        ("closed_gamma_list_wrong_length", '{"space":"S3","method":"gamma","closed":true,"points":[[1,0,0,0],[0.9,0.1,0,0],[0.8,0.2,0.1,0],[0.7,0.3,0.2,0.1]],"params":{"gamma":[1,2]}}', "params.gamma: must have one value per knot but the last (4), got 2"),
        ("closed_arc_blend_book_does_not_close", '{"space":"S2","method":"arc-blend","closed":true,"params":{"timing":"book"},"points":[[1,0,0.3],[0.2,0.9,0.4],[-0.8,0.4,0.1],[-0.3,-0.9,0.5]]}', "params.timing: the book knots do not close the loop"),
        ("closed_arc_blend_no_circle_around", '{"space":"S2","method":"arc-blend","closed":true,"points":[[1,0,0.3],[0.2,0.9,0.4],[-0.8,0.4,0.1],[1,0,0.3],[0.1,-0.9,0.5]]}', "points[3] and points[0] coincide: no unique circle"),
        ("extrapolate_unknown", "{" + S2 + ',"extrapolate":"clamp"}', 'extrapolate: "clamp" is not an extrapolation policy'),
        ("extrapolate_not_string", "{" + S2 + ',"extrapolate":true}', "invalid type: boolean"),
        ("extrapolate_cycle_open", "{" + S2 + ',"extrapolate":"cycle"}', 'extrapolate: "cycle" repeats a closed curve, and this curve is open'),
        ("extrapolate_segment_geodesic", "{" + S2 + ',"extrapolate":"segment"}', 'extrapolate: "segment" continues the end segments'),
        ("extrapolate_segment_arclength", '{"space":"S2","method":"cubic","points":[[1,0,0],[0,1,0],[0,0,1]],"parametrization":"arclength","extrapolate":"segment"}', 'extrapolate: "segment" continues a method\'s own formula'),
        ("extrapolate_error_outside", "{" + S2 + ',"extrapolate":"error","eval_at":[0,2.5]}', 'eval_at[1]: 2.5 is outside the domain [0, 2] of the curve, whose "extrapolate" is "error"'),
        ("extrapolate_at_top_level_of_curves", '{"space":"S2","extrapolate":"hold","curves":[{"method":"geodesic","points":[[1,0,0],[0,1,0]]}]}', "curves: with \"curves\", give knots"),
        ("extrapolate_error_in_curves", '{"space":"S2","curves":[{"method":"geodesic","points":[[1,0,0],[0,1,0]]},{"method":"nlerp","extrapolate":"error","points":[[1,0,0],[0,1,0]]}],"eval_at":[-1]}', 'eval_at[0]: -1 is outside the domain [0, 1] of curves[1]'),
        ("parametrization_unknown", "{" + S2 + ',"parametrization":"time"}', 'parametrization: "time" is not a parametrization'),
        ("parametrization_zero_length", '{"space":"S2","method":"geodesic","points":[[1,0,0],[1,0,0]],"parametrization":"arclength"}', "parametrization: the curve has zero length"),
        ("closed_not_bool", '{"space":"S2","method":"cubic","closed":"yes","points":[[1,0,0],[0,1,0],[0,0,1]]}', "invalid type: string"),
        ("closed_cubic_knot_count", '{"space":"S3","method":"cubic","closed":true,"points":[[1,0,0,0],[0.9,0.1,0,0],[0.8,0.2,0.1,0]],"knots":[0,1,2]}', "knots: expected 4 knots, got 3"),
        ("closed_cubic_two_keys", '{"space":"S2","method":"cubic","closed":true,"points":[[1,0,0],[0,1,0]]}', "points: this method needs at least 3 points, got 2"),
        ("closed_cubic_antipodal_seam", '{"space":"S2","method":"cubic","closed":true,"points":[[1,0,0],[0,1,0],[-1,0,0]]}', "closed: the last and the first point are antipodal"),
        ("cubic_clamped_without_velocity", '{"space":"S2","method":"cubic","params":{"end":"clamped"},"points":[[1,0,0],[0,1,0]]}', 'params.start_velocity: is needed with "end": "clamped"'),
        ("cubic_velocity_not_tangent", '{"space":"S2","method":"cubic","params":{"end":"clamped","start_velocity":[1,0,0],"end_velocity":[0,0,1]},"points":[[1,0,0],[0,1,0]]}', "params.start_velocity: the start velocity is not tangent"),
        ("cubic_velocity_without_clamped", '{"space":"S2","method":"cubic","params":{"end_velocity":[0,0,1]},"points":[[1,0,0],[0,1,0]]}', 'params.end_velocity: applies with "end": "clamped" only'),
        ("cubic_velocity_nan", '{"space":"S3","method":"cubic","params":{"end":"clamped","start_velocity":[0,"x",0],"end_velocity":[0,0,1]},"points":[[1,0,0,0],[0.9,0.1,0,0]]}', "params.start_velocity: must be a list of finite numbers"),
        ("cubic_angular_velocity_length", '{"space":"S3","method":"cubic","params":{"end":"clamped","start_velocity":[0,0],"end_velocity":[0,0,1]},"points":[[1,0,0,0],[0.9,0.1,0,0]]}', "params.start_velocity: must be an angular velocity [x, y, z], got 2 numbers"),
        ("cubic_velocities_wrong_count", '{"space":"S2","method":"cubic","params":{"velocities":[[0,0,1],[0,0,1]]},"points":[[1,0,0],[0,1,0],[1,1,0]]}', "params.velocities: must have one velocity per point: expected 3, got 2"),
        ("cubic_velocities_nan_entry", '{"space":"S2","method":"cubic","params":{"velocities":[[0,0,1],[0,"NaN",1]]},"points":[[1,0,0],[0,1,0]]}', "params.velocities[1]: must be a list of finite numbers"),
        ("cubic_velocities_1e400_entry", '{"space":"S2","method":"cubic","params":{"velocities":[[0,0,1],[0,1e400,1]]},"points":[[1,0,0],[0,1,0]]}', "params.velocities[1][1]: number out of range"),
        ("cubic_velocities_not_a_list", '{"space":"S2","method":"cubic","params":{"velocities":1},"points":[[1,0,0],[0,1,0]]}', "params.velocities: must be a list of vectors, one per point"),
        ("cubic_velocities_not_tangent", '{"space":"S2","method":"cubic","params":{"velocities":[[0,0,1],[0,1,0]]},"points":[[1,0,0],[0,1,0]]}', "params.velocities[1]: is not tangent to its key"),
        ("cubic_velocities_wrong_dimension", '{"space":"S5","method":"cubic","params":{"velocities":[[0,1,0,0,0,0],[1,0,0]]},"points":[[1,0,0,0,0,0],[0,1,0,0,0,0]]}', "params.velocities[1]: has 3 numbers, not a vector of this sphere"),
        ("cubic_velocities_with_clamped", '{"space":"S2","method":"cubic","params":{"velocities":[[0,0,1],[0,0,1]],"end":"clamped","start_velocity":[0,0,1],"end_velocity":[0,0,1]},"points":[[1,0,0],[0,1,0]]}', 'params.velocities: gives the velocity at every key, the ends\' too: it takes no "end" other than natural'),
        ("cubic_velocities_with_end_velocity", '{"space":"S2","method":"cubic","params":{"velocities":[[0,0,1],[0,0,1]],"end_velocity":[0,0,1]},"points":[[1,0,0],[0,1,0]]}', "params.velocities: gives the velocity at every key"),
        ("cubic_velocities_s3_body_not_angular", '{"space":"S3","method":"cubic","params":{"velocities":[[0,0,1],[0,1,0,0]],"frame":"body"},"points":[[1,0,0,0],[0.9,0.1,0,0]]}', "params.velocities[1]: must be an angular velocity [x, y, z], got 4 numbers"),
        ("cubic_velocities_s3_space_nan", '{"space":"S3","method":"cubic","params":{"velocities":[[0,0,1],[0,null,1]],"frame":"space"},"points":[[1,0,0,0],[0.9,0.1,0,0]]}', "params.velocities[1]: must be a list of finite numbers"),
        ("cubic_velocities_s3_full_turn_wrong_count", '{"space":"S3","method":"cubic","closed":true,"params":{"velocities":[[0,0,1],[0,0,1]]},"points":[[1,0,0,0],[0.5,0,0,0.8660254037844386],[-0.5,0,0,0.8660254037844386]]}', "params.velocities: must have one velocity per point: expected 3, got 2"),
        ("cubic_frame_unknown", '{"space":"S3","method":"cubic","params":{"velocities":[[0,0,1],[0,0,1]],"frame":"world"},"points":[[1,0,0,0],[0.9,0.1,0,0]]}', "params.frame: must be one of: space, body"),
        ("cubic_knots_not_increasing", '{"space":"S2","method":"cubic","points":[[1,0,0],[0,1,0],[0,0,1]],"knots":[0,2,1]}', "knots[2] is not greater than knots[1]"),
        ("quaternion_order_unknown", '{"space":"S3","quaternion_order":"zyxw","method":"geodesic","points":[[1,0,0,0],[0,1,0,0]]}', 'quaternion_order: "zyxw" is not an order'),
        ("quaternion_order_on_s2", '{"space":"S2","quaternion_order":"xyzw","method":"geodesic","points":[[1,0,0],[0,1,0]]}', "quaternion_order: applies to S3 (quaternion) scenes only"),
        ("arc_blend_unknown_timing", '{"space":"S2","method":"arc-blend","params":{"timing":"fast"},"points":[[1,0,0],[0,1,0],[0,0,1]]}', "params.timing: must be one of: auto, book, arc-length, uniform"),
        ("gamma_last_edge_unknown", '{"space":"S3","method":"gamma","points":[[1,0,0,0],[0.9,0.1,0,0],[0.8,0.2,0.1,0],[0.7,0.3,0.2,0.1]],"params":{"last_edge":"paper"}}', "params.last_edge: must be one of: formula, paper-example"),
        # A cubic fitted to samples ("fit"): every option's bad values name the option.
        ("fit_weights_negative", '{' + FIT + ',"fit":{"weights":[1,1,-1,1,1]}}', "fit.weights[2]: must be a positive finite number, got -1"),
        ("fit_weights_zero", '{' + FIT + ',"fit":{"weights":[1,0,1,1,1]}}', "fit.weights[1]: must be a positive finite number, got 0"),
        ("fit_weights_string", '{' + FIT + ',"fit":{"weights":[1,1,1,"1",1]}}', 'fit.weights[3]: must be a positive finite number, got "1"'),
        ("fit_weights_count", '{' + FIT + ',"fit":{"weights":[1,1]}}', "fit.weights: must have one weight per sample: 5 points, got 2"),
        ("fit_weights_nan_literal", '{' + FIT + ',"fit":{"weights":[1,1,NaN,1,1]}}', "invalid scene JSON"),
        ("fit_lambda_negative", '{' + FIT + ',"fit":{"smoothing":-0.5}}', "fit.smoothing: λ must be a finite number ≥ 0, got -0.5"),
        ("fit_smoothing_unknown", '{' + FIT + ',"fit":{"smoothing":"auto"}}', 'fit.smoothing: must be a number λ ≥ 0, "gcv" or {"rms": σ}'),
        ("fit_rms_zero", '{' + FIT + ',"fit":{"smoothing":{"rms":0}}}', "fit.smoothing: the target rms must be a positive finite number of radians, got 0"),
        ("fit_rms_negative", '{' + FIT + ',"fit":{"smoothing":{"rms":-1}}}', "fit.smoothing: the target rms must be a positive finite number of radians, got -1"),
        ("fit_max_error_zero", '{' + FIT + ',"fit":{"max_error":0}}', "fit.max_error: must be a positive finite number of radians, got 0"),
        ("fit_max_error_negative", '{' + FIT + ',"fit":{"max_error":-1e-3}}', "fit.max_error: must be a positive finite number of radians"),
        ("fit_keys_too_few", '{' + FIT + ',"fit":{"keys":1}}', "fit.keys: must be between 2 and the number of samples, 5; got 1"),
        ("fit_keys_too_many", '{' + FIT + ',"fit":{"keys":6}}', "fit.keys: must be between 2 and the number of samples, 5; got 6"),
        ("fit_keys_negative", '{' + FIT + ',"fit":{"keys":-3}}', "fit.keys: must be a whole number of keys"),
        ("fit_keys_and_max_error", '{' + FIT + ',"fit":{"keys":3,"max_error":0.1}}', 'fit: give "keys" or "max_error", not both'),
        ("fit_gcv_with_keys", '{' + FIT + ',"fit":{"smoothing":"gcv","keys":3}}', 'fit.smoothing: "gcv" needs a key at every sample'),
        ("fit_unknown_key", '{' + FIT + ',"fit":{"lambda":1}}', "fit.lambda: unknown fit option; known: smoothing, weights, max_error, keys"),
        ("fit_not_object", '{' + FIT + ',"fit":true}', "fit: must be an object"),
        ("fit_on_geodesic", '{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]],"fit":{}}', 'fit: method "geodesic" does not fit samples: use "method": "cubic"'),
        ("fit_without_knots", '{"space":"S2","method":"cubic","points":[[1,0,0],[0,1,0]],"fit":{}}', 'knots: are needed with "fit"'),
        ("fit_knot_count", '{' + FIT.replace(',0.4]', ']') + ',"fit":{}}', "knots: expected 5 knots, got 4"),
        ("fit_clamped_end", '{' + FIT + ',"params":{"end":"clamped"},"fit":{}}', 'params.end: does not apply with "fit"'),
        ("fit_in_curves_list", '{"space":"S2","curves":[{' + FIT[13:] + ',"fit":{"keys":0}}]}', "curves[0].fit.keys: must be between 2"),
    ]


def write(root):
    bad_dir = os.path.join(root, "bad")
    out_dir = os.path.join(root, "degenerate")
    for d in (bad_dir, out_dir):
        if os.path.isdir(d):
            shutil.rmtree(d)
        os.makedirs(d)
    for name, text, want in bad_cases():
        data = text if isinstance(text, bytes) else text.encode()
        with open(f"{bad_dir}/{name}.json", "wb") as f:
            f.write(data)
        with open(f"{bad_dir}/{name}.txt", "w") as f:
            f.write(want + "\n")
    n_ok = n_err = 0
    for name, s in cases():
        err = expect_err(name)
        if err is None:
            path = f"{out_dir}/{name}.ok.json"
            n_ok += 1
        else:
            path = f"{out_dir}/{name}.err.json"
            with open(f"{out_dir}/{name}.err.txt", "w") as f:
                f.write(err + "\n")
            n_err += 1
        with open(path, "w") as f:
            json.dump(s, f, separators=(",", ":"))
            f.write("\n")
    return len(bad_cases()), n_ok, n_err


def differences(a, b):
    """Files that differ, or are in only one of the trees a and b."""
    out = []
    cmp = filecmp.dircmp(a, b)
    stack = [("", cmp)]
    while stack:
        prefix, c = stack.pop()
        out += [prefix + n for n in c.left_only + c.right_only]
        _, mismatch, errors = filecmp.cmpfiles(c.left, c.right, c.common_files, shallow=False)
        out += [prefix + n for n in mismatch + errors]
        stack += [(prefix + n + "/", sub) for n, sub in c.subdirs.items()]
    return sorted(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--registry", required=True, help="the output of `spherekit methods --json`")
    parser.add_argument("--check", action="store_true", help="compare with tests/robustness instead of writing")
    args = parser.parse_args()
    load_registry(args.registry)
    root = os.path.dirname(OUT)
    if args.check:
        with tempfile.TemporaryDirectory() as tmp:
            write(tmp)
            diff = differences(root, tmp)
        with open(DICT) as f:
            if f.read() != fuzz_dict():
                diff.append(DICT)
        if diff:
            print(f"tests/robustness is not what scripts/robustness_corpus.py writes ({len(diff)} files differ, "
                  f"e.g. {', '.join(diff[:5])}): run `just corpus` and commit", file=sys.stderr)
            sys.exit(1)
        print("tests/robustness matches the generator")
        return
    n_bad, n_ok, n_err = write(root)
    with open(DICT, "w") as f:
        f.write(fuzz_dict())
    print(f"{n_bad} bad scenes in {root}/bad; {n_ok} ok, {n_err} err cases in {OUT}")


if __name__ == "__main__":
    main()
