// Frame-time benchmarks of the playground in Debian's headless Chromium. Needs `just web`
// first; run with `just bench-web`. Figures go to BENCHMARKS.md (section 6).
//
// 1. index.html?bench (20 keys on S³, 4 000 samples, 800 × 800; see web/js/bench.js): the
//    rebuild + render + sample time per frame of the wasm handle.
// 2. Turning the view with the mouse at 1400 × 900, device pixel ratio 1 and 2, with the four
//    S³ curves of tests/golden/compare_s3_squad_catmull_bspline_arcblend.json: 150 mouse moves
//    over a second or more; per drag frame the work (the queued edit, the render and the
//    overlay, measured in the page's animation-frame callback) and the interval between
//    animation frames, and the time spent in each pointer-move handler; then the still frame.
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { serve } from './serve.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const webDir = path.resolve(here, '../../web');

const { server, origin } = await serve(webDir, { index: 'index.html' });
// A fresh temporary profile per run (chromium.launch), one browser context per pixel ratio.
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
  headless: true,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});

const stats = (xs) => {
  const s = xs.slice().sort((a, b) => a - b);
  const q = (f) => s[Math.min(s.length - 1, Math.floor(f * s.length))];
  const r = (x) => Math.round(x * 100) / 100;
  return { n: s.length, median: r(q(0.5)), p95: r(q(0.95)), max: r(s[s.length - 1]) };
};

async function dragBench(dpr) {
  const context = await browser.newContext({ viewport: { width: 1400, height: 900 }, deviceScaleFactor: dpr });
  const page = await context.newPage();
  const scene = await readFile(path.resolve(here, '../golden/compare_s3_squad_catmull_bspline_arcblend.json'), 'utf8');
  await page.goto(`${origin}/index.html#scene=${encodeURIComponent(scene)}`);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 60000 });
  const info = await page.evaluate(() => ({ dpr: devicePixelRatio, size: window.spherekitPage.size(), curves: window.spherekitPage.handle().curve_count() }));
  // A still frame, timed.
  const still = await page.evaluate(() => {
    const pg = window.spherekitPage.handle();
    const canvas = document.createElement('canvas');
    const times = [];
    for (let k = 0; k < 12; k++) {
      const t0 = performance.now();
      pg.draw(canvas, window.spherekitPage.size());
      times.push(performance.now() - t0);
    }
    return times.slice(2);
  });
  const [x, y] = await page.evaluate(() => window.spherekitPage.emptySpot());
  const frames0 = await page.evaluate(() => window.spherekitPage.frameTimes().length);
  const moves0 = await page.evaluate(() => window.spherekitPage.moveTimes().length);
  await page.evaluate(() => {
    window.benchStamps = [];
    const loop = (now) => {
      window.benchStamps.push(now);
      if (!window.benchStop) requestAnimationFrame(loop);
    };
    requestAnimationFrame(loop);
  });
  await page.mouse.move(x, y);
  await page.mouse.down();
  for (let k = 1; k <= 150; k++) {
    const a = (k / 150) * 2 * Math.PI;
    await page.mouse.move(x + 120 * Math.sin(a), y + 60 * (1 - Math.cos(a)));
  }
  await page.mouse.up();
  await page.waitForTimeout(100);
  const result = await page.evaluate(([f0, m0]) => {
    window.benchStop = true;
    const s = window.benchStamps;
    const intervals = s.slice(1).map((t, i) => t - s[i]);
    return {
      work: window.spherekitPage.frameTimes().slice(f0),
      moves: window.spherekitPage.moveTimes().slice(m0),
      intervals,
    };
  }, [frames0, moves0]);
  await context.close();
  // The last frame is the full-resolution still after the drag; the drag frames are before it.
  const drag = result.work.slice(0, -1);
  return {
    devicePixelRatio: info.dpr,
    canvasPx: info.size,
    curves: info.curves,
    stillFrameMs: stats(still),
    dragFrameWorkMs: stats(drag),
    frameIntervalMs: stats(result.intervals.slice(1, -6)),
    pointerMoveHandlerMs: stats(result.moves),
  };
}

try {
  const page = await browser.newPage();
  await page.goto(`${origin}/index.html?bench`);
  await page.waitForFunction(() => window.spherekitBench, null, { timeout: 300000 });
  console.log('handle (rebuild, render, sample):', JSON.stringify(await page.evaluate(() => window.spherekitBench), null, 2));
  await page.close();
  for (const dpr of [1, 2]) {
    console.log(`turning the view, 4 curves on S3, 1400x900, DPR ${dpr}:`, JSON.stringify(await dragBench(dpr), null, 2));
  }
} finally {
  await browser.close();
  server.close();
}
