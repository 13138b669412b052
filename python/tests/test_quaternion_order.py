# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""One quaternion order in Python: scalar last ([x, y, z, w], scipy's `as_quat()`) by default
in `Curve`, the drop-ins and scene dicts given to `sample`/`render`/`render_png`, scalar first
with `scalar_first=True`; JSON text and files are the CLI's format ([w, x, y, z]); a scene's own
`quaternion_order` wins."""

import json

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import spherekit
from conftest import random_times, walk

WXYZ = [3, 0, 1, 2]  # scalar last -> scalar first


def keys_with_random_signs(rng, n):
    q = walk(rng, n, 1.2).as_quat()
    return q * rng.choice([-1.0, 1.0], size=(n, 1))


def cubic_scene(points, knots, t, **extra):
    return {
        "space": "S3",
        "method": "cubic",
        "points": points.tolist(),
        "knots": list(knots),
        "params": {"end": "scipy"},
        "eval_at": list(t),
        **extra,
    }


def test_scene_dict_from_as_quat_gives_the_angular_velocity_of_curve(rng):
    q = keys_with_random_signs(rng, 7)  # Rotation.as_quat(): scalar last
    knots = random_times(rng, 7)
    curve = spherekit.Curve("cubic", q, knots=knots, end="scipy")
    t = np.linspace(knots[0], knots[-1], 57)
    for frame in ("space", "body"):
        out = spherekit.sample(cubic_scene(q, knots, t), deriv=True, frame=frame)
        np.testing.assert_allclose(out["angular_velocity"], curve.angular_velocity(t, frame), rtol=0, atol=1e-12)
        np.testing.assert_allclose(out["angular_acceleration"], curve.angular_acceleration(t, frame), rtol=0, atol=1e-11)
    # The output's quaternions are in the dict's order too.
    out = spherekit.sample(cubic_scene(q, knots, t), deriv=True)
    np.testing.assert_allclose(out["points"], curve(t), rtol=0, atol=1e-15)
    np.testing.assert_allclose(out["velocity"], curve(t, 1), rtol=0, atol=1e-12)


def test_the_old_misread_is_gone(rng):
    """The same scipy keys read scalar first (the old default for dicts) are other rotations:
    the dict's default is not that reading."""
    q = keys_with_random_signs(rng, 5)
    knots = np.arange(5.0)
    t = np.linspace(0, 4, 21)
    ours = spherekit.sample(cubic_scene(q, knots, t), deriv=True)["angular_velocity"]
    misread = spherekit.sample(cubic_scene(q, knots, t), deriv=True, scalar_first=True)["angular_velocity"]
    want = spherekit.Curve("cubic", q, knots=knots, end="scipy").angular_velocity(t)
    assert np.abs(np.asarray(ours) - want).max() < 1e-12
    assert np.abs(np.asarray(misread) - want).max() > 0.1


def test_scalar_first_dicts_and_the_scenes_own_order(rng):
    q = keys_with_random_signs(rng, 6)
    knots = random_times(rng, 6)
    t = np.linspace(knots[0], knots[-1], 31)
    last = spherekit.sample(cubic_scene(q, knots, t), deriv=True)
    first = spherekit.sample(cubic_scene(q[:, WXYZ], knots, t), deriv=True, scalar_first=True)
    # The same curve; the quaternions come out in the order they went in.
    assert first["angular_velocity"] == last["angular_velocity"]
    np.testing.assert_array_equal(np.asarray(first["points"]), np.asarray(last["points"])[:, WXYZ])
    np.testing.assert_array_equal(np.asarray(first["velocity"]), np.asarray(last["velocity"])[:, WXYZ])
    # An explicit quaternion_order wins over the default and over scalar_first.
    said_first = cubic_scene(q[:, WXYZ], knots, t, quaternion_order="wxyz")
    said_last = cubic_scene(q, knots, t, quaternion_order="xyzw")
    for scalar_first in (None, False, True):
        assert spherekit.sample(said_first, deriv=True, scalar_first=scalar_first) == first
        assert spherekit.sample(said_last, deriv=True, scalar_first=scalar_first) == last


def test_text_bytes_and_paths_are_the_cli_format(rng, tmp_path):
    q = keys_with_random_signs(rng, 5)
    knots = random_times(rng, 5)
    t = np.linspace(knots[0], knots[-1], 17)
    want_first = spherekit.sample(cubic_scene(q[:, WXYZ], knots, t), deriv=True, scalar_first=True)
    want_last = spherekit.sample(cubic_scene(q, knots, t), deriv=True)
    text_first = json.dumps(cubic_scene(q[:, WXYZ], knots, t))  # as a CLI scene file: w first
    path = tmp_path / "scene.json"
    path.write_text(text_first)
    for scene in (text_first, text_first.encode(), path):
        assert spherekit.sample(scene, deriv=True) == want_first
        assert spherekit.sample(scene, deriv=True, scalar_first=True) == want_first
    # scalar_first=False reads a text scalar last (the output is then scalar last too).
    text_last = "  \n" + json.dumps(cubic_scene(q, knots, t))
    assert spherekit.sample(text_last, deriv=True, scalar_first=False) == want_last
    # ... unless the text says its order.
    said = json.dumps(cubic_scene(q[:, WXYZ], knots, t, quaternion_order="wxyz"))
    assert spherekit.sample(said, deriv=True, scalar_first=False) == want_first


def test_render_reads_dicts_scalar_last_and_files_scalar_first(tmp_path):
    keys = Rotation.from_euler("xyz", [[0, 0, 0], [30, 10, 0], [60, 40, 20], [10, 80, 40]], degrees=True)
    q = keys.as_quat()
    dict_last = {"space": "S3", "method": "squad", "points": q.tolist()}
    dict_first = {"space": "S3", "method": "squad", "points": q[:, WXYZ].tolist()}
    file_first = tmp_path / "scene.json"
    file_first.write_text(json.dumps(dict_first))
    image = spherekit.render(dict_last, size=96)
    np.testing.assert_array_equal(spherekit.render(dict_first, size=96, scalar_first=True), image)
    np.testing.assert_array_equal(spherekit.render(file_first, size=96), image)
    np.testing.assert_array_equal(spherekit.render(json.dumps(dict_last), size=96, scalar_first=False), image)
    # Read in the other order, the same numbers are other rotations: another picture.
    assert not np.array_equal(spherekit.render(dict_last, size=96, scalar_first=True), image)
    pngs = []
    for scene, kwargs in ((dict_last, {}), (dict_first, {"scalar_first": True}), (file_first, {})):
        out = tmp_path / f"{len(pngs)}.png"
        spherekit.render_png(scene, out, size=96, **kwargs)
        pngs.append(out.read_bytes())
    assert pngs[0] == pngs[1] == pngs[2]


def test_other_spheres_take_no_order():
    scene = {"space": "S2", "method": "geodesic", "points": [[1, 0, 0], [0, 1, 0]], "samples": 3}
    want = spherekit.sample(scene)
    assert spherekit.sample(scene, scalar_first=True) == spherekit.sample(scene, scalar_first=False) == want
    assert spherekit.sample(json.dumps(scene), scalar_first=False) == want


@pytest.mark.parametrize(
    "scene, message",
    [
        ({"space": "S3", "method": "squad", "points": [[0, 0, 0, 1], [0, 0, 1, 0]], "quaternion_order": "zyxw"},
         "quaternion_order"),
        ({"space": "S2", "method": "geodesic", "points": [[1, 0, 0], [0, 1, 0]], "quaternion_order": "xyzw"},
         "quaternion_order: applies to S3"),
        ({"space": "S3", "method": "squad", "points": [[0, 0, 0, 1], [0, 0, 0, 0]]}, "points[1]"),
    ],
)
def test_bad_orders_and_keys_are_one_line_value_errors(scene, message):
    for call in (lambda: spherekit.sample(scene), lambda: spherekit.render(scene, size=16),
                 lambda: spherekit.sample(json.dumps(scene), scalar_first=False)):
        with pytest.raises(ValueError) as e:
            call()
        assert message in str(e.value) and "\n" not in str(e.value)


def test_a_text_that_is_not_a_scene_keeps_the_parsers_message():
    for bad in ('{"space": "S3", "points": [[0, 0, 0, 1]', "[1, 2]"):
        with pytest.raises(ValueError) as plain:
            spherekit.sample(bad)
        with pytest.raises(ValueError) as ordered:
            spherekit.sample(bad, scalar_first=False)
        assert str(plain.value) == str(ordered.value) and "\n" not in str(plain.value)


def test_curve_scalar_first_reads_and_writes_w_first(rng):
    q = keys_with_random_signs(rng, 6)
    knots = random_times(rng, 6)
    t = np.linspace(knots[0] - 0.5, knots[-1] + 0.5, 41)
    for method, kwargs in (("cubic", {"end": "natural"}), ("squad", {}), ("geodesic", {})):
        last = spherekit.Curve(method, q, knots=knots, **kwargs)
        first = spherekit.Curve(method, q[:, WXYZ], knots=knots, scalar_first=True, **kwargs)
        for order in (0, 1, 2):
            np.testing.assert_array_equal(first(t, order), last(t, order)[:, WXYZ])
        np.testing.assert_array_equal(first.points, last.points[:, WXYZ])
        np.testing.assert_array_equal(first.angular_velocity(t), last.angular_velocity(t))


def test_drop_ins_take_scalar_first_arrays(rng):
    q = keys_with_random_signs(rng, 6)
    times = random_times(rng, 6)
    t = np.linspace(times[0], times[-1], 37)
    for cls, calls in (
        (spherekit.RotationSpline, lambda s: [s(t).as_quat(), s(t, 1), s(t, 2)]),
        (spherekit.Slerp, lambda s: [s(t).as_quat()]),
    ):
        last, first = cls(times, q), cls(times, q[:, WXYZ], scalar_first=True)
        for a, b in zip(calls(last), calls(first)):
            np.testing.assert_array_equal(a, b)
        keys = Rotation.from_quat(q) if cls is spherekit.RotationSpline else Rotation.from_quat(q)[:-1]
        np.testing.assert_array_equal(first.rotations.as_quat(), keys.as_quat())
    # A Rotation has no order: scalar_first changes nothing for it.
    keys = Rotation.from_quat(q)
    np.testing.assert_array_equal(
        spherekit.RotationSpline(times, keys, scalar_first=True)(t).as_quat(),
        spherekit.RotationSpline(times, keys)(t).as_quat(),
    )


def test_drop_ins_without_scipy_return_arrays_in_the_order_given(rng, monkeypatch):
    from spherekit import _scipy

    q = keys_with_random_signs(rng, 5)
    times = random_times(rng, 5)
    t = np.linspace(times[0], times[-1], 23)
    want = {cls: cls(times, q)(t).as_quat() for cls in (spherekit.RotationSpline, spherekit.Slerp)}
    monkeypatch.setattr(_scipy, "_Rotation", None)
    for cls, quats in want.items():
        np.testing.assert_array_equal(cls(times, q)(t), quats)
        np.testing.assert_array_equal(cls(times, q[:, WXYZ], scalar_first=True)(t), quats[:, WXYZ])
