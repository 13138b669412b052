# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""Whole scenes: the malformed-scene catalogue, `render`, `render_png`, `methods`."""

import glob
import json
import os
import pathlib

import numpy as np
import pytest

import spherekit
from conftest import REPO

BAD = sorted(glob.glob(os.path.join(REPO, "tests", "robustness", "bad", "*.json")))


def test_the_catalogue_is_there():
    assert len(BAD) >= 80


@pytest.mark.parametrize("path", BAD, ids=os.path.basename)
def test_every_bad_scene_is_a_value_error(path):
    data = open(path, "rb").read()
    want = open(path[: -len(".json")] + ".txt").read().strip()
    # `view` is read by the renderer only (files named render_*), as in the CLI's test.
    calls = [lambda: spherekit.render(data, size=16)]
    if not os.path.basename(path).startswith("render_"):
        calls.append(lambda: spherekit.sample(data, deriv=True))
    for call in calls:
        with pytest.raises(ValueError) as e:
            call()
        message = str(e.value)
        assert want in message and "\n" not in message, (message, want)


def test_sample_takes_dicts_text_and_paths(tmp_path):
    scene = {"space": "S2", "method": "geodesic", "points": [[1, 0, 0], [0, 1, 0]], "samples": 5}
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(scene))
    a = spherekit.sample(scene)
    assert a == spherekit.sample(json.dumps(scene)) == spherekit.sample(path)
    assert a["t"] == [0.0, 0.25, 0.5, 0.75, 1.0] and a["method"] == "geodesic"
    assert spherekit.sample(scene, samples=3)["t"] == [0.0, 0.5, 1.0]
    out = spherekit.sample(dict(scene, space="S3", points=[[1, 0, 0, 0], [0, 1, 0, 0]]), deriv=True, frame="body")
    assert len(out["angular_velocity"]) == 5
    with pytest.raises(ValueError, match="cannot read scene file"):
        spherekit.sample(pathlib.Path(tmp_path / "missing.json"))
    with pytest.raises(ValueError, match="samples"):
        spherekit.sample(scene, samples=1)


def test_render_and_png(tmp_path):
    scene = os.path.join(REPO, "tests", "golden", "squad_s3.json")
    img = spherekit.render(pathlib.Path(scene), size=96)
    assert img.dtype == np.uint8 and img.ndim == 3 and img.shape[1:] == (96, 4)
    assert img[..., 3].min() == 255 and img[..., :3].std() > 0
    out = tmp_path / "squad.png"
    spherekit.render_png(pathlib.Path(scene), out, size=96)
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(ValueError, match="size"):
        spherekit.render(pathlib.Path(scene), size=-1)


@pytest.mark.parametrize("name", ["squad_s3", "bezier_s2_cubic", "figure_legend_labels_s2"])
def test_render_png_writes_the_bytes_of_the_cli(tmp_path, name):
    """The golden PNGs are the CLI's output at 384 px; the module encodes with the same encoder."""
    golden = pathlib.Path(REPO, "tests", "golden")
    out = tmp_path / f"{name}.png"
    spherekit.render_png(golden / f"{name}.json", out, size=384)
    assert out.read_bytes() == (golden / f"{name}.png").read_bytes()


# Golden scenes whose samples all differed from the CLI's in the last bits while the module was
# built without the core's `libm` feature (42 of the 44 goldens did): curves of S², S³, closed,
# arc-length and several-curve scenes.
SAME_BITS_AS_CLI = [
    "cubic_s2",
    "squad_s3",
    "beta_s2_example1",
    "arc_blend_s3",
    "cubic_s3_orbit",
    "figure_arclength_s3",
    "compare_s3_squad_catmull_bspline_arcblend",
]


def bits(out):
    """The sample output as text: `repr` of a float is the shortest text that reads back to the
    same bits (−0.0 included), so equal texts are equal bits."""
    return json.dumps(out, sort_keys=True)


@pytest.mark.parametrize("name", SAME_BITS_AS_CLI)
def test_samples_are_the_bits_of_the_cli(cli, name):
    """The module is built with the core's `libm` feature, as the CLI and the browser are."""
    import subprocess

    scene = pathlib.Path(REPO, "tests", "golden", f"{name}.json")
    for flags, options in [
        (["--deriv", "--continuity"], dict(deriv=True, continuity=True)),
        (["--deriv", "--frame", "body", "--samples", "257"], dict(deriv=True, frame="body", samples=257)),
    ]:
        out = subprocess.run([cli, "sample", str(scene), *flags], capture_output=True, text=True, check=True)
        assert bits(spherekit.sample(scene, **options)) == bits(json.loads(out.stdout)), flags


@pytest.mark.parametrize("name", SAME_BITS_AS_CLI[:4])
def test_render_png_is_the_cli_png_at_any_size(cli, tmp_path, name):
    import subprocess

    scene = pathlib.Path(REPO, "tests", "golden", f"{name}.json")
    for size in (257, 600):
        want, got = tmp_path / f"cli{size}.png", tmp_path / f"py{size}.png"
        subprocess.run([cli, "render", str(scene), "-o", str(want), "--size", str(size)], check=True)
        spherekit.render_png(scene, got, size=size)
        assert got.read_bytes() == want.read_bytes(), size


def test_methods_is_the_registry():
    methods = spherekit.methods()
    ids = [m["id"] for m in methods]
    assert "cubic" in ids and "squad" in ids and len(ids) == len(set(ids))
    assert all({"id", "spaces", "min_points", "params"} <= m.keys() for m in methods)
