// The frame-time benchmark (index.html?bench; tests/e2e/bench.mjs runs it), loaded by
// boot.js with import() only when the query asks for it.
import * as sk from '../pkg/spherekit_wasm.js';

export async function bench() {
  // 20 keys on S³ (a deterministic tumbling sequence), 4 000 samples, 800 × 800. Each frame
  // moves key 7 (the handle rebuilds the curve), renders and draws the frame, and samples the
  // rebuilt curve at 4 000 parameters.
  const keys = [];
  for (let k = 0; k < 20; k++) {
    const axis = [Math.cos(1.3 * k), Math.sin(1.3 * k), 0.5 * Math.cos(0.4 * k)];
    keys.push(Array.from(sk.axis_angle_to_key(40 * k, ...axis)));
  }
  const method = 'bspline-kim'; // C², three exponentials per sample
  const scene = { space: 'S3', method, points: keys, samples: 4000 };
  const pg = new sk.Playground(JSON.stringify(scene));
  const canvas = document.createElement('canvas');
  const times = [];       // rebuild + render + 4 000 samples
  const renderTimes = []; // rebuild + render
  const rebuildTimes = []; // set_point alone
  const sampleTimes = []; // the 4 000 samples alone
  for (let f = 0; f < 110; f++) {
    const key = keys[7].slice();
    key[1] += 0.01 * Math.sin(f);
    const t0 = performance.now();
    pg.set_point(0, 7, new Float64Array(key)); // rebuilds the curve
    const tb = performance.now();
    pg.draw(canvas, 800);                       // renders and draws one frame
    const t1 = performance.now();
    pg.sample_array(0, 'points'); // 4 000 samples of the curve
    const t2 = performance.now();
    if (f >= 10) {
      times.push(t2 - t0);
      renderTimes.push(t1 - t0);
      rebuildTimes.push(tb - t0);
      sampleTimes.push(t2 - t1);
    }
    await new Promise((r) => setTimeout(r, 0));
  }
  const median = (xs) => xs.slice().sort((a, b) => a - b)[xs.length >> 1];
  const result = {
    method,
    keys: 20,
    samples: 4000,
    size: 800,
    frames: times.length,
    medianMs: median(times),
    maxMs: Math.max(...times),
    medianRenderMs: median(renderTimes),
    medianRebuildMs: median(rebuildTimes),
    medianSampleMs: median(sampleTimes),
    builds: pg.builds(),
  };
  pg.free();
  window.spherekitBench = result;
  console.log('spherekit bench', JSON.stringify(result));
}
