#!/usr/bin/env python3
# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""Times spherekit against its peers in one run and writes BENCHMARKS.md's comparison table.

Run with `just bench-compare` (it makes .venv/ with the pinned peers). The Rust side is the
`bench_json` example (the criterion benches' keys and parameters, best of 21 runs); the peers
run on the same keys and parameters: scipy (`Slerp`, `RotationSpline`), numpy-quaternion
(`squad`, `slerp`) and splines (`splines.quaternion`, pure Python, timed on fewer samples).
Where two libraries compute the same curve the largest difference is reported (quaternions
compared up to sign, since scipy canonicalises w >= 0).
"""

import datetime
import json
import os
import platform
import re
import subprocess
import sys
import time

import numpy as np
import quaternion
import scipy
import splines
import splines.quaternion as sq
from scipy.spatial.transform import RotationSpline, Rotation, Slerp

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REPS = 11
SLOW_SAMPLES = 2000  # pure-Python peers


def best(f, reps=REPS):
    """The best wall time of `reps` calls of f, in ns."""
    out = None
    t = float("inf")
    for _ in range(reps):
        start = time.perf_counter_ns()
        out = f()
        t = min(t, time.perf_counter_ns() - start)
    return t, out


def params(domain, count):
    """data::params: midpoints of `count` equal cells of the domain, same float operations."""
    t0, t1 = domain
    return t0 + (t1 - t0) * (np.arange(count, dtype=np.float64) + 0.5) / count


def updown(a, b):
    """Largest difference of quaternion arrays (n, 4) up to sign, per row."""
    d1 = np.abs(a - b).max(axis=1)
    d2 = np.abs(a + b).max(axis=1)
    return float(np.minimum(d1, d2).max())


def rust():
    cmd = ["cargo", "run", "--quiet", "--release", "-p", "spherekit", "--example", "bench_json"]
    out = subprocess.run(cmd, cwd=ROOT, check=True, capture_output=True, text=True).stdout
    return json.loads(out)


# The paired rounds: (name, request of `bench_json paired`, rounds, turns per round, peer runs
# per turn). Each turn times the peer, then spherekit (one untimed run, then `N` timed ones, the
# request's `N`); a round's timing on each side is its best over the round's turns. "build" and
# "rates" interleave the two sides one run at a time, so that both sides' best is taken over the
# same stretch of time (this machine's speed changes in episodes longer than a 1 000-key
# construction: a spherekit best of 21 in a row came out at 275 µs or 410 µs, both often, with
# nothing else running); "build, consecutive" times 21 runs in a row on each side (each side's
# best is then taken over a different stretch of time; kept as a third line for comparison).
PAIRED = [
    ("build", "build 1", 15, 21, 1),
    ("rates", "rates 1", 9, 3, 1),
    ("build, consecutive", "build 21", 15, 1, 21),
]


def paired_rounds(peers):
    """The cubic against scipy's `RotationSpline` in rounds that alternate the two, so that both
    sides of a round's ratio see the same load ([`PAIRED`]); the Rust side answers from one
    process that stays up, as the Python one does. `peers` maps a request kind (`build`: the
    1 000-key construction; `rates`: point, rate and acceleration per sample) to a function of a
    run count giving scipy's best time of that many runs. Returns {name: [(scipy, spherekit)]}."""
    cmd = ["cargo", "run", "--quiet", "--release", "-p", "spherekit", "--example", "bench_json",
           "--", "paired"]
    rounds = {}
    with subprocess.Popen(cmd, cwd=ROOT, stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True) as own:
        for name, request, count, turns, peer_runs in PAIRED:
            peer = peers[request.split()[0]]
            rounds[name] = []
            for i in range(count + 1):
                theirs = ours = float("inf")
                for _ in range(turns):
                    theirs = min(theirs, peer(peer_runs))
                    own.stdin.write(request + "\n")
                    own.stdin.flush()
                    ours = min(ours, float(own.stdout.readline()))
                if i > 0:  # the first round warms both sides up
                    rounds[name].append((theirs, ours))
        own.stdin.close()
    return rounds


def paired_line(what, rounds, unit, scale):
    ratios = sorted(p / o for p, o in rounds)
    med = ratios[len(ratios) // 2]
    peer_med = sorted(p for p, _ in rounds)[len(rounds) // 2]
    own_med = sorted(o for _, o in rounds)[len(rounds) // 2]
    return (f"- {what}: ratio median **{med:.1f}×**, range {ratios[0]:.1f}–{ratios[-1]:.1f}× "
            f"({len(rounds)} rounds; medians {fmt(peer_med / scale, 1)} and {fmt(own_med / scale, 1)} {unit})")


def main():
    uptime_before = subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()
    r = rust()
    n = r["samples"]
    keys = np.array(r["keys"])  # w, x, y, z
    keys1000 = np.array(r["keys_1000"])
    methods = {m["name"]: m for m in r["methods"]}
    every = r["check_every"]
    times = np.arange(len(keys), dtype=np.float64)
    times1000 = np.arange(len(keys1000), dtype=np.float64)
    xyzw = keys[:, [1, 2, 3, 0]]
    xyzw1000 = keys1000[:, [1, 2, 3, 0]]
    ts = params(methods["geodesic"]["domain"], n)
    peers = []  # (peer, spherekit method, ns/sample, max diff or None, note[, spherekit ns])

    # scipy Slerp vs geodesic.
    rot = Rotation.from_quat(xyzw)
    slerp = Slerp(times, rot)
    t, out = best(lambda: slerp(ts))
    q = out.as_quat()[::every][:, [3, 0, 1, 2]]
    diff = updown(q, np.array(r["values"]["geodesic"]))
    peers.append(("scipy Slerp", "geodesic", t / n, diff, "same curve"))

    # numpy-quaternion slerp (vectorised over the samples, segment lookup in numpy).
    R = quaternion.as_quat_array(keys)

    def nq_slerp():
        i = np.minimum(np.searchsorted(times, ts, side="right") - 1, len(keys) - 2)
        return quaternion.slerp(R[i], R[i + 1], times[i], times[i + 1], ts)

    t, out = best(nq_slerp)
    diff = updown(quaternion.as_float_array(out)[::every], np.array(r["values"]["geodesic"]))
    peers.append(("numpy-quaternion slerp", "geodesic", t / n, diff, "same curve"))

    # numpy-quaternion squad vs squad (uniform knots: the same inner points and end conditions).
    t, out = best(lambda: quaternion.squad(R, times, ts))
    diff = updown(quaternion.as_float_array(out)[::every], np.array(r["values"]["squad"]))
    peers.append(("numpy-quaternion squad", "squad", t / n, diff, "same curve"))

    # scipy RotationSpline vs cubic (scipy ends): the same curve. scipy is timed for the point,
    # the body-frame rate and the acceleration (rs(t), rs(t, 1), rs(t, 2)), spherekit for
    # jet_many plus the conversion of each jet to body-frame rate and acceleration.
    spline = RotationSpline(times, rot)
    t3, (sq_, sr_, sa_) = best(lambda: (spline(ts), spline(ts, 1), spline(ts, 2)))
    cv = r["cubic"]["values"]
    qdiff = updown(sq_.as_quat()[::every][:, [3, 0, 1, 2]], np.array(cv["quats"]))
    rdiff = float(np.abs(sr_[::every] - np.array(cv["rates"])).max() / np.abs(sr_).max())
    adiff = float(np.abs(sa_[::every] - np.array(cv["accelerations"])).max() / np.abs(sa_).max())
    peers.append(("scipy RotationSpline, rotation + rate + acceleration", "cubic", t3 / n, qdiff,
                  f"same curve (scipy ends); rates {rdiff:.1e}, accelerations {adiff:.1e} relative; "
                  "spherekit: `jet_many` + body rates", r["cubic"]["rates_ns"]))
    # RotationSpline (C², interpolating) vs the other C²-or-smoother spherekit curves: different
    # constructions, compared for speed only (rotations alone, `rs(t)`).
    t, _ = best(lambda: spline(ts))
    peers.append(("scipy RotationSpline, rotation", "cubic", t / n, None, "same curve, point only"))
    peers.append(("scipy RotationSpline, rotation", "bspline-kim", t / n, None,
                  "different construction: C², keys are B-spline control points (no interpolation)"))
    peers.append(("scipy RotationSpline, rotation", "arc-blend", t / n, None,
                  "different construction: C² (order 2), interpolating"))
    peers.append(("scipy RotationSpline, rotation", "beta", t / n, None,
                  "different construction: G¹ only (acceleration jumps 0.06–0.82 at joints)"))
    build20, _ = best(lambda: RotationSpline(times, rot), reps=50)
    rot1000 = Rotation.from_quat(xyzw1000)
    # Best of 21, as many runs as spherekit's 1 000-key builds get in bench_json.
    build1000, _ = best(lambda: RotationSpline(times1000, rot1000), reps=21)
    paired = paired_rounds({
        "build": lambda reps: best(lambda: RotationSpline(times1000, rot1000), reps=reps)[0],
        "rates": lambda reps: best(lambda: (spline(ts), spline(ts, 1), spline(ts, 2)), reps=reps)[0] / n,
    })

    # splines (pure Python), on SLOW_SAMPLES parameters.
    uq = [sq.UnitQuaternion.from_unit_xyzw(v) for v in xyzw]
    ts_slow = params(methods["geodesic"]["domain"], SLOW_SAMPLES)

    def per_sample(curve, tt):
        t, out = best(lambda: [curve.evaluate(x) for x in tt], reps=3)
        return t / len(tt), out

    def as_wxyz(qs):
        return np.array([[q.scalar, *q.vector] for q in qs])

    pw = sq.PiecewiseSlerp(uq, grid=list(times))
    t, out = per_sample(pw, ts_slow)
    peers.append(("splines PiecewiseSlerp", "geodesic", t, None, f"{SLOW_SAMPLES} samples"))
    closed_grid = [*times, times[-1] + 1.0]  # splines' Squad is always a closed curve
    t, _ = per_sample(sq.Squad(uq, grid=closed_grid), ts_slow)
    peers.append(("splines Squad", "squad", t, None, f"{SLOW_SAMPLES} samples; closed curve"))
    t, _ = per_sample(sq.CatmullRom(uq, grid=list(times)), ts_slow)
    peers.append(("splines CatmullRom", "catmull-rom", t, None, f"{SLOW_SAMPLES} samples"))
    # The cubic Bezier of the first 4 keys on [0, 1]: the same de Casteljau curve.
    bez = sq.DeCasteljau([uq[:4]])
    ts_bez = params(methods["bezier"]["domain"], n)[::every]
    t, out = per_sample(bez, ts_bez)
    diff = updown(as_wxyz(out), np.array(r["values"]["bezier"]))
    peers.append(("splines DeCasteljau", "bezier", t, diff, f"{len(ts_bez)} samples; same curve"))

    uptime_after = subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()
    write(r, peers, build20, build1000, paired, uptime_before, uptime_after)


def fmt(x, digits=1):
    if x is None:
        return "–"
    if x >= 1e5:
        return f"{x:,.0f}"
    return f"{x:.{digits}f}"


def write(r, peers, build20, build1000, paired, up0, up1):
    methods = {m["name"]: m for m in r["methods"]}
    slerp = r["glam_slerp_ns"]
    lines = []
    lines.append("<!-- generated by scripts/bench_compare.py (`just bench-compare`); edit the script -->")
    lines.append("### Per sample: spherekit and the floor")
    lines.append("")
    lines.append(
        f"20 keys on S³ (Bézier methods: one cubic, the first 4 keys), {r['samples']:,} increasing "
        f"parameters, best of 21 runs (peers: best of {REPS}). Floor: k slerps × glam `DQuat::slerp` "
        f"= k × {slerp:.1f} ns. Construction: one `try_new`."
    )
    lines.append("")
    lines.append(
        "| method | `eval` ns/sample | `eval_many` ns/sample | `jet_many` ns/sample | k slerps | "
        "k × slerp ns | eval_many / floor | build 20 keys µs | build 1 000 keys µs |"
    )
    lines.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for m in r["methods"]:
        floor = m["slerps"] * slerp
        ratio = f"{m['eval_many_ns'] / floor:.2f}" if floor > 0 else "–"
        b1000 = m["build_1000_ns"]
        lines.append(
            f"| {m['name']} | {fmt(m['eval_ns'])} | {fmt(m['eval_many_ns'])} | "
            f"{fmt(m['jet_many_ns'])} | {m['slerps']} | {fmt(floor)} | {ratio} | "
            f"{fmt(m['build_20_ns'] / 1e3, 2)} | {fmt(None if b1000 is None else b1000 / 1e3, 1)} |"
        )
    lines.append(f"| glam `DQuat::slerp` | {fmt(slerp)} | | | 1 | {fmt(slerp)} | | | |")
    lines.append("")
    lines.append("### Peers, same keys and parameters")
    lines.append("")
    lines.append(
        "Ratio = peer ns / spherekit `eval_many` ns (higher: spherekit faster; for the cubic row with "
        "rate and acceleration: / `jet_many` plus body-rate conversion). Max diff: largest "
        "coordinate difference of the quaternions (up to sign) where both compute the same curve."
    )
    lines.append("")
    lines.append("| peer | spherekit method | peer ns/sample | spherekit ns/sample | ratio | max diff | note |")
    lines.append("|---|---|---:|---:|---:|---:|---|")
    for peer, name, ns, diff, note, *own in peers:
        mine = own[0] if own else methods[name]["eval_many_ns"]
        d = "–" if diff is None else f"{diff:.1e}"
        lines.append(f"| {peer} | {name} | {fmt(ns)} | {fmt(mine)} | {ns / mine:.1f}× | {d} | {note} |")
    lines.append("")
    lines.append("Construction against scipy `RotationSpline` (C², interpolating). `cubic` is the same "
                 "curve (scipy ends); the others are different constructions: bspline-kim C² "
                 "(keys as control points), arc-blend C² (interpolating), beta G¹ (interpolating, "
                 "Newton solve). Best of 21 runs on both sides for 1 000 keys; 20 keys: best of 50 "
                 "(scipy) and 200 (spherekit).")
    lines.append("")
    lines.append("| keys | RotationSpline µs | method | spherekit µs | ratio |")
    lines.append("|---:|---:|---|---:|---:|")
    for name in ("cubic", "bspline-kim", "arc-blend", "beta"):
        m = methods[name]
        lines.append(f"| 20 | {fmt(build20 / 1e3, 1)} | {name} | {fmt(m['build_20_ns'] / 1e3, 2)} | "
                     f"{build20 / m['build_20_ns']:.1f}× |")
        lines.append(f"| 1 000 | {fmt(build1000 / 1e3, 1)} | {name} | {fmt(m['build_1000_ns'] / 1e3, 1)} | "
                     f"{build1000 / m['build_1000_ns']:.1f}× |")
    lines.append("")
    lines.append(
        "Paired rounds, `cubic` against `RotationSpline` on the same keys, so that both sides of a "
        "ratio see the same load. Interleaved: one scipy run, then one spherekit run (after an untimed "
        "one), 21 times a round for the construction and 3 for the evaluation, the best of each side "
        "per round; consecutive: scipy's best of 21 constructions, then "
        "spherekit's best of 21:"
    )
    lines.append("")
    lines.append(paired_line("construction, 1 000 keys, interleaved", paired["build"], "µs", 1e3))
    lines.append(paired_line("rotation + rate + acceleration per sample, 20 keys, 200 000 parameters, "
                             "interleaved", paired["rates"], "ns", 1))
    lines.append(paired_line("construction, 1 000 keys, consecutive", paired["build, consecutive"],
                             "µs", 1e3))
    lines.append("")
    lines.append(
        f"Date {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC; "
        f"{platform.processor() or platform.machine()}, Python {platform.python_version()}, "
        f"scipy {scipy.__version__}, numpy {np.__version__}, numpy-quaternion {quaternion.__version__}, "
        f"splines {splines.__version__}. Load before: `{up0}`; after: `{up1}`."
    )
    table = "\n".join(lines) + "\n"
    path = os.path.join(ROOT, "BENCHMARKS.md")
    begin, end = "<!-- compare:begin -->", "<!-- compare:end -->"
    text = open(path).read() if os.path.exists(path) else f"# Benchmarks\n\n{begin}\n{end}\n"
    if begin not in text:
        text += f"\n{begin}\n{end}\n"
    text = re.sub(re.escape(begin) + ".*?" + re.escape(end), lambda _: f"{begin}\n{table}{end}", text,
                  flags=re.S)
    with open(path, "w") as f:
        f.write(text)
    print(table)


if __name__ == "__main__":
    sys.exit(main())
