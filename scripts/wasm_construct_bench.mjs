// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT
//
// The .wasm's construction time: `node scripts/wasm_construct_bench.mjs web/pkg` loads a
// `just web` build (any directory holding spherekit_wasm.js and spherekit_wasm_bg.wasm) and
// times the `sample` export (parse, build, 2 samples, JSON out) of 20-key scenes on S2 and S3,
// the fastest of 15 runs of 40 calls each, in microseconds per call (BENCHMARKS.md, section 6).
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
const dir = process.argv[2];
const mod = await import(pathToFileURL(path.join(dir, 'spherekit_wasm.js')).href);
await mod.default({ module_or_path: fs.readFileSync(path.join(dir, 'spherekit_wasm_bg.wasm')) });
function keys(space, n) {
  const out = [];
  for (let i = 0; i < n; i++) {
    const a = 0.4 * i, b = 0.3 * Math.sin(1.7 * i);
    out.push(space === 'S2' ? [Math.cos(a), Math.sin(a), b] : [Math.cos(a / 2), Math.sin(a / 2) * 0.6, 0.5 * b, 0.3]);
  }
  return out;
}
const res = {};
for (const method of ['arc-blend', 'beta', 'catmull-rom', 'geodesic', 'catmull-rom-nlerp', 'corner-blend']) {
  for (const space of ['S2', 'S3']) {
    const scene = JSON.stringify({ space, method, points: keys(space, 20), samples: 2 });
    mod.sample(scene, false);
    const times = [];
    for (let r = 0; r < 15; r++) {
      const t0 = performance.now();
      for (let k = 0; k < 40; k++) mod.sample(scene, false);
      times.push((performance.now() - t0) / 40 * 1000);
    }
    times.sort((x, y) => x - y);
    res[`${method} ${space}`] = +times[0].toFixed(1);
  }
}
console.log(JSON.stringify(res));
