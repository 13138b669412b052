#!/usr/bin/env python3
# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""Writes the playground's example menu, web/pkg/presets.json, from the golden scenes.

The golden-image scenes (tests/golden/*.json) are the one source; `just web` runs this after
the wasm build. The file is `[{"name", "scene"}, ...]` sorted by name, each scene as its JSON
text (the page loads it with fetch instead of the .wasm carrying 15 KB of scene text).
"""

import json
import pathlib
import sys

root = pathlib.Path(__file__).resolve().parent.parent
golden = root / "tests" / "golden"
out = root / "web" / "pkg" / "presets.json"
presets = [
    {"name": path.stem, "scene": path.read_text(encoding="utf-8")}
    for path in sorted(golden.glob("*.json"))
]
if not presets:
    sys.exit(f"web_presets: no scenes in {golden}")
out.parent.mkdir(parents=True, exist_ok=True)
out.write_text(json.dumps(presets, ensure_ascii=False) + "\n", encoding="utf-8")
