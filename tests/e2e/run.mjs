// End-to-end test of the playground (web/index.html) and the docs widget page (web/docs.html)
// in Debian's headless Chromium through playwright-core. Needs `just web` first (web/pkg).
//
//   node tests/e2e/run.mjs          (just test-e2e)
//
// Screenshots go to tests/e2e/out/ (git-ignored).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFile, readdir, mkdir } from 'node:fs/promises';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { PNG } from 'pngjs';
import { serve } from './serve.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, '../..');
const webDir = path.join(root, 'web');
const goldenDir = path.join(root, 'tests/golden');
const badDir = path.join(root, 'tests/robustness/bad');
const outDir = path.join(here, 'out');
const GOLDEN_SIZE = 384;

let server;
let origin;
let browser;
let userDataDir;

before(async () => {
  await mkdir(outDir, { recursive: true });
  ({ server, origin } = await serve(webDir, { index: 'index.html' }));
  userDataDir = mkdtempSync(path.join(tmpdir(), 'spherekit-chromium-'));
  // A fresh profile each run (playwright passes it as --user-data-dir).
  browser = await chromium.launchPersistentContext(userDataDir, {
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    headless: true,
    args: [
      '--headless', '--no-sandbox', '--disable-gpu', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
    ],
    viewport: { width: 1280, height: 860 },
    deviceScaleFactor: 1,
  });
});

after(async () => {
  await browser?.close();
  server?.close();
  if (userDataDir) rmSync(userDataDir, { recursive: true, force: true });
});

async function newPage(viewport = { width: 1280, height: 860 }) {
  const page = await browser.newPage();
  await page.setViewportSize(viewport);
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.errors = errors;
  return page;
}

const sceneUrl = (text, query = '') => `${origin}/index.html${query}#scene=${encodeURIComponent(text)}`;

async function openPlayground(page, url) {
  await page.goto(url);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

/** The scene canvas's pixels, straight RGBA (sent as base64: an array of numbers is slow). */
async function canvasPixels(page) {
  const { width, height, base64 } = await page.evaluate(() => {
    const c = document.getElementById('scene');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let bytes = '';
    for (let i = 0; i < d.length; i += 0x8000) bytes += String.fromCharCode(...d.subarray(i, i + 0x8000));
    return { width: c.width, height: c.height, base64: btoa(bytes) };
  });
  return { width, height, data: Buffer.from(base64, 'base64') };
}

/** SHA-256 of the scene canvas's pixels after the next frames, computed in the page (fast). */
async function canvasHash(page) {
  return page.evaluate(async () => {
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    const c = document.getElementById('scene');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const digest = await crypto.subtle.digest('SHA-256', d);
    return `${c.width}x${c.height} ${Array.from(new Uint8Array(digest), (b) => b.toString(16).padStart(2, '0')).join('')}`;
  });
}

function maxDiff(a, b) {
  let max = 0;
  let count = 0;
  for (let i = 0; i < a.length; i++) {
    const d = Math.abs(a[i] - b[i]);
    if (d > max) max = d;
    if (d > 0) count++;
  }
  return { max, count };
}

test('the playground draws every golden scene with the golden pixels', async () => {
  const names = (await readdir(goldenDir)).filter((n) => n.endsWith('.json')).sort();
  assert.ok(names.length > 0, 'golden scenes exist');
  const page = await newPage();
  const report = [];
  for (const name of names) {
    const text = await readFile(path.join(goldenDir, name), 'utf8');
    await openPlayground(page, sceneUrl(text, `?size=${GOLDEN_SIZE}`));
    const errorText = await page.textContent('#error');
    assert.equal(errorText, '', `${name}: no error shown`);
    const got = await canvasPixels(page);
    const png = PNG.sync.read(await readFile(path.join(goldenDir, name.replace('.json', '.png'))));
    assert.equal(got.width, png.width, `${name}: width`);
    assert.equal(got.height, png.height, `${name}: height`);
    const { max, count } = maxDiff(got.data, png.data);
    report.push(`${name.replace('.json', '')}: max channel difference ${max}, ${count} differing channels`);
    assert.equal(max, 0, `${name}: canvas pixels equal the golden PNG`);
  }
  console.log(`golden pixels (${GOLDEN_SIZE} px):\n  ${report.join('\n  ')}`);
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('dragging a point changes the curve and the scene', async () => {
  const page = await newPage();
  const text = await readFile(path.join(goldenDir, 'geodesic_s2.json'), 'utf8');
  await openPlayground(page, sceneUrl(text, `?size=${GOLDEN_SIZE}`));
  const before = await canvasPixels(page);
  const pointBefore = await page.evaluate(() => Array.from(window.spherekitPage.handle().point(0, 2)));
  const [x, y] = await page.evaluate(() => window.spherekitPage.pointOnScreen(0, 2));
  await page.mouse.move(x, y);
  await page.mouse.down();
  for (let k = 1; k <= 10; k++) await page.mouse.move(x + 4 * k, y + 3 * k);
  await page.mouse.up();
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const after = await canvasPixels(page);
  const pointAfter = await page.evaluate(() => Array.from(window.spherekitPage.handle().point(0, 2)));
  assert.notDeepEqual(pointAfter, pointBefore, 'the point moved');
  const { count } = maxDiff(before.data, after.data);
  assert.ok(count > 100, `the image changed (${count} channels)`);
  const hash = await page.evaluate(() => decodeURIComponent(location.hash.slice('#scene='.length)));
  assert.deepEqual(JSON.parse(hash).points[2], pointAfter, 'the URL fragment holds the new scene');
  // Only the dragged curve was rebuilt: the camera drag below re-renders without building.
  const builds = await page.evaluate(() => window.spherekitPage.handle().builds());
  const box = await page.locator('#overlay').boundingBox();
  await page.mouse.move(box.x + 30, box.y + box.height * 0.4);
  await page.mouse.down();
  await page.mouse.move(box.x + 80, box.y + box.height * 0.45);
  await page.mouse.up();
  assert.equal(await page.evaluate(() => window.spherekitPage.handle().builds()), builds, 'turning the view builds nothing');
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('a malformed scene shows its message and keeps the last good scene', async () => {
  const page = await newPage();
  const good = await readFile(path.join(goldenDir, 'geodesic_s3.json'), 'utf8');
  await openPlayground(page, sceneUrl(good, `?size=${GOLDEN_SIZE}`));
  const before = await canvasPixels(page);
  // A hand-edited URL with a point of zero length: the CLI's message, as text.
  const bad = '{"space":"S2","method":"geodesic","points":[[1,0,0],[0,0,0]]}';
  await page.evaluate((h) => { location.hash = h; }, `#scene=${encodeURIComponent(bad)}`);
  await page.waitForFunction(() => document.getElementById('error').textContent !== '');
  assert.equal(await page.textContent('#error'), 'error: points[1] has zero length and cannot be normalised');
  const after = await canvasPixels(page);
  assert.equal(maxDiff(before.data, after.data).max, 0, 'the previous scene stays on screen');
  // Markup in a message is shown as text, never inserted as HTML.
  await page.fill('#json', '{"space":"<img src=x onerror=alert(1)>"}');
  await page.click('#apply-json');
  const shown = await page.textContent('#error');
  assert.match(shown, /^error: space: "<img src=x onerror=alert\(1\)>" is not a sphere/);
  assert.equal(await page.locator('#error img').count(), 0, 'no element was created from the message');
  // Text that is not JSON.
  await page.fill('#json', '{"space": "S2", ');
  await page.click('#apply-json');
  assert.match(await page.textContent('#error'), /^error: invalid scene JSON: /);
  // The page keeps working: a preset loads and clears the error.
  await page.selectOption('#preset', 'nlerp_s2');
  assert.equal(await page.textContent('#error'), '');
  const nlerp = await canvasPixels(page);
  assert.ok(maxDiff(before.data, nlerp.data).count > 100, 'the new scene is drawn');
  // A broken fragment on first load: the message and a fallback scene.
  const fresh = await newPage();
  await openPlayground(fresh, `${origin}/index.html#scene=${encodeURIComponent('{"space":"S2","method":"nope","points":[]}')}`);
  assert.match(await fresh.textContent('#error'), /^error: method: unknown method "nope"; known: geodesic, nlerp/);
  const fallback = await canvasPixels(fresh);
  assert.ok(fallback.data.some((v, i) => i % 4 !== 3 && v < 200), 'a fallback scene is drawn');
  assert.deepEqual(page.errors, [], 'no page errors');
  await fresh.close();
  await page.close();
});

test('every malformed scene of tests/robustness/bad is refused by the wasm API and by the page', async () => {
  const t0 = performance.now();
  const names = (await readdir(badDir)).filter((n) => n.endsWith('.json')).sort();
  assert.ok(names.length >= 40, `only ${names.length} bad scenes`);
  // The bytes as the page would receive them as text: invalid UTF-8 becomes U+FFFD and a BOM is
  // kept (as String::from_utf8_lossy does in crates/spherekit-cli/tests/it/robustness.rs).
  // As there, the .txt is the CLI's message for a file it cannot read as UTF-8 text, so such a
  // scene must only be refused here.
  const cases = await Promise.all(names.map(async (name) => {
    const bytes = await readFile(path.join(badDir, name));
    let utf8 = true;
    try {
      new TextDecoder('utf-8', { fatal: true }).decode(bytes);
    } catch {
      utf8 = false;
    }
    const text = new TextDecoder('utf-8', { ignoreBOM: true }).decode(bytes);
    const want = (await readFile(path.join(badDir, name.replace(/\.json$/, '.txt')), 'utf8')).replace(/\n+$/, '');
    return { name, text, want, utf8 };
  }));
  const page = await newPage();
  const good = await readFile(path.join(goldenDir, 'geodesic_s3.json'), 'utf8');
  await openPlayground(page, sceneUrl(good, `?size=${GOLDEN_SIZE}`));
  assert.equal(await page.textContent('#error'), '', 'the good scene loads');
  const problems = [];
  const bad = (c, what) => problems.push(`${c.name}: ${what}`);
  const fine = (c, message) => (c.utf8 ? message.includes(c.want) : true)
    && !message.includes('\n') && !/panicked|unreachable|RuntimeError/.test(message);

  // 1. The wasm API, from the module web/js/boot.js initialised.
  const api = await page.evaluate(async (cases) => {
    const sk = await import('./pkg/spherekit_wasm.js');
    const shared = window.spherekitPage.handle() instanceof sk.Playground;
    const outcome = (f) => {
      try {
        const v = f();
        v?.free?.();
        return { threw: false };
      } catch (e) {
        return { threw: true, error: e instanceof Error, kind: e?.constructor?.name, message: e instanceof Error ? e.message : String(e) };
      }
    };
    const results = cases.map((c) => ({ validate: outcome(() => sk.validate(c.text)), playground: outcome(() => new sk.Playground(c.text)) }));
    return { shared, results };
  }, cases);
  assert.ok(api.shared, 'import() inside the page gives the module instance web/main.js initialised');
  api.results.forEach((r, i) => {
    const c = cases[i];
    for (const [fn, o] of Object.entries(r)) {
      if (!o.threw) bad(c, `${fn} accepted the scene`);
      else if (!o.error || !fine(c, o.message)) bad(c, `${fn} threw ${o.kind} ${JSON.stringify(o.message)}, expected one line containing ${JSON.stringify(c.want)}`);
    }
    if (r.validate.threw && r.playground.threw && r.validate.message !== r.playground.message) {
      bad(c, `validate says ${JSON.stringify(r.validate.message)} but new Playground says ${JSON.stringify(r.playground.message)}`);
    }
  });

  // 2. The page: each scene into the Scene JSON box, Apply; the message is shown and the last
  // good scene stays (the same scene, URL and pixels once the page has redrawn).
  const ui = await page.evaluate(async ({ cases, good }) => {
    const frames = () => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    const $ = (id) => document.getElementById(id);
    const pixels = () => {
      const c = $('scene');
      return c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    };
    const apply = (text) => {
      $('json').value = text;
      $('apply-json').dispatchEvent(new MouseEvent('click', { bubbles: true }));
    };
    const state = () => ({ scene: window.spherekitPage.handle().scene_json(), hash: location.hash });
    const base = state();
    const before = pixels();
    const results = [];
    for (const c of cases) {
      apply(c.text);
      const error = $('error').textContent;
      const hidden = $('error').hidden;
      await frames();
      const after = pixels();
      let changed = after.length === before.length ? 0 : -1;
      for (let i = 0; changed >= 0 && i < after.length; i++) if (after[i] !== before[i]) changed++;
      const now = state();
      results.push({ error, hidden, changed, sameScene: now.scene === base.scene, sameHash: now.hash === base.hash });
      if (error === '' || now.scene !== base.scene) {
        apply(good); // accepted: put the good scene back for the next case
        await frames();
      }
    }
    return results;
  }, { cases: cases.map(({ text }) => ({ text })), good });
  ui.forEach((r, i) => {
    const c = cases[i];
    if (r.error === '') {
      bad(c, 'the page accepted the scene');
      return;
    }
    const shown = r.error.replace(/^error: /, '');
    if (!r.error.startsWith('error: ') || r.hidden || !fine(c, shown)) bad(c, `the page shows ${JSON.stringify(r.error)}${r.hidden ? ' (hidden)' : ''}, expected one line containing ${JSON.stringify(c.want)}`);
    const made = api.results[i].playground;
    if (made.threw && shown !== made.message) bad(c, `the page shows ${JSON.stringify(r.error)} but the wasm API says ${JSON.stringify(made.message)}`);
    if (!r.sameScene || !r.sameHash) bad(c, 'the last good scene was replaced');
    if (r.changed !== 0) bad(c, `the canvas changed (${r.changed} channels)`);
  });
  assert.deepEqual(problems, [], `${problems.length} problems with ${cases.length} bad scenes:\n${problems.join('\n')}`);

  // The page still works: a preset clears the error and draws; Apply takes a good scene again.
  const goodHash = await canvasHash(page);
  await page.selectOption('#preset', 'nlerp_s2');
  assert.equal(await page.textContent('#error'), '', 'a preset clears the error');
  assert.notEqual(await canvasHash(page), goodHash, 'the preset is drawn');
  await page.fill('#json', good);
  await page.click('#apply-json');
  assert.equal(await page.textContent('#error'), '', 'Apply takes a good scene');
  assert.equal(await canvasHash(page), goodHash, 'the good scene is drawn as before');
  console.log(`malformed scenes: ${cases.length} refused by validate, new Playground and the page in ${((performance.now() - t0) / 1000).toFixed(1)} s`);
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('the docs page renders a widget for every method', async () => {
  const page = await newPage({ width: 1100, height: 900 });
  await page.goto(`${origin}/docs.html`);
  await page.waitForFunction(() => [...document.querySelectorAll('spherekit-view')].every((w) => w.dataset.state));
  const widgets = await page.evaluate(async () => {
    return [...document.querySelectorAll('section.method')].map((s) => {
      const w = s.querySelector('spherekit-view');
      const canvas = w.querySelector('canvas');
      let inked = 0;
      if (canvas) {
        const d = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
          for (let i = 0; i < d.length; i += 4) if (d[i] + d[i + 1] + d[i + 2] < 600) inked++;
      }
      return { method: s.dataset.method, state: w.dataset.state, inked, text: w.textContent };
    });
  });
  const methods = await page.evaluate(async () => JSON.parse((await import('./pkg/spherekit_wasm.js')).methods()).map((m) => m.id));
  assert.deepEqual(widgets.map((w) => w.method).sort(), methods.slice().sort(), 'one widget per method');
  for (const w of widgets) {
    assert.equal(w.state, 'ready', `${w.method}: rendered (${w.text})`);
    assert.ok(w.inked > 500, `${w.method}: the canvas shows the scene (${w.inked} dark pixels)`);
  }
  console.log(`docs widgets: ${widgets.length} rendered`);
  // Turn one widget and play it.
  const first = page.locator('spherekit-view').first();
  const canvas = first.locator('canvas').first();
  const box = await canvas.boundingBox();
  const before = await canvas.screenshot();
  await page.mouse.move(box.x + box.width * 0.3, box.y + box.height * 0.5);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width * 0.6, box.y + box.height * 0.4, { steps: 5 });
  await page.mouse.up();
  assert.notDeepEqual(await canvas.screenshot(), before, 'dragging turns the widget');
  const slider = first.locator('input[type=range]');
  const start = Number(await slider.inputValue());
  await first.locator('button').click();
  await page.waitForFunction((el) => Number(el.value) > Number(el.min) + 0.05 * (Number(el.max) - Number(el.min)), await slider.elementHandle());
  assert.ok(Number(await slider.inputValue()) > start, 'playing moves t');
  // Each widget is as wide as its column, so its text can be read.
  const fits = await page.$$eval('section.method', (sections) => sections.map((s) => {
    const column = s.querySelector('spherekit-view').getBoundingClientRect().width;
    const canvas = s.querySelector('spherekit-view canvas').getBoundingClientRect().width;
    return { method: s.dataset.method, column, canvas };
  }));
  for (const f of fits) {
    assert.ok(Math.abs(f.canvas - f.column) <= 2, `${f.method}: the view fills its column (${f.canvas} of ${f.column} px)`);
    assert.ok(f.canvas >= 400, `${f.method}: the view is ${f.canvas} px wide at 1100 px`);
  }
  await page.screenshot({ path: path.join(outDir, 'docs.png'), fullPage: true });
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('the parameter controls edit the scene', async () => {
  const page = await newPage({ width: 1280, height: 860 });
  const beta = {
    space: 'S2', method: 'beta',
    points: [[1, 0, 0], [0.6, 0.8, 0], [0, 0.6, 0.8], [-0.6, 0, 0.8], [-0.8, -0.6, 0]],
    params: { beta1: [1, 0.5, 2, 1, 1] },
  };
  await openPlayground(page, sceneUrl(JSON.stringify(beta)));
  await page.screenshot({ path: path.join(outDir, 'playground-beta-controls.png') });
  // β₁ ≠ 1 at points 1 and 2: direction continuous, speed not; β₁ = 1 at point 3: C¹.
  const classes = await page.$$eval('#continuity tbody tr', (rows) => rows.map((r) => r.cells[5].textContent));
  assert.deepEqual(classes, ['G¹', 'G¹', 'C¹']);
  const params = () => page.evaluate(() => JSON.parse(window.spherekitPage.handle().curve_json(0)).params ?? {});
  const sliders = page.locator('#curves input[type=range]');
  assert.equal(await sliders.count(), 6, 'five β₁ sliders (one per point) and one β₂');
  // Move β₁ at point 1 and release: the scene follows and the picture changes.
  const before = await canvasHash(page);
  await sliders.nth(1).evaluate((el) => {
    el.value = '1.5';
    el.dispatchEvent(new Event('input', { bubbles: true }));
    el.dispatchEvent(new Event('change', { bubbles: true }));
  });
  assert.deepEqual((await params()).beta1, [1, 1.5, 2, 1, 1]);
  assert.notEqual(await canvasHash(page), before, 'redrawn');
  // One β₂ for every joint, then one per joint.
  await page.getByLabel('β₂ tension per joint').check();
  assert.deepEqual((await params()).beta2, [0, 0, 0, 0, 0]);
  await page.getByLabel('β₁ bias per joint').uncheck();
  assert.equal((await params()).beta1, 1, 'back to one value (the first)');
  // A method with knots: typed in, checked by the scene format.
  await page.locator('#curves select').first().selectOption('catmull-rom');
  const knots = page.getByLabel('Knots of curve 1');
  await knots.fill('0, 1, 4');
  await knots.dispatchEvent('change');
  assert.equal(await page.textContent('#error'), '');
  assert.deepEqual(JSON.parse(await page.evaluate(() => window.spherekitPage.handle().curve_json(0))).knots, [0, 1, 4]);
  await knots.fill('0, 2, 1');
  await knots.dispatchEvent('change');
  assert.match(await page.textContent('#error'), /^error: knots/);
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('the constant-speed toggle and the extrapolation choice edit the scene', async () => {
  const page = await newPage({ width: 1280, height: 860 });
  const scene = {
    space: 'S2', method: 'geodesic', points: [[1, 0, 0], [0, 1, 0], [0, 0.6, 0.8]], knots: [0, 1, 5],
    view: { plot: 'speed' },
  };
  await openPlayground(page, sceneUrl(JSON.stringify(scene)));
  const curve = async () => JSON.parse(await page.evaluate(() => window.spherekitPage.handle().curve_json(0)));
  const before = await canvasHash(page);
  await page.getByLabel('Constant speed of curve 1').check();
  assert.equal((await curve()).parametrization, 'arclength');
  const domain = await page.evaluate(() => Array.from(window.spherekitPage.handle().sample_array(0, 'domain')));
  // Two great-circle arcs: a quarter turn and atan2(0.8, 0.6).
  assert.ok(Math.abs(domain[1] - (Math.PI / 2 + Math.atan2(0.8, 0.6))) < 1e-9, `the domain is [0, L]: ${domain}`);
  assert.notEqual(await canvasHash(page), before, 'the speed plot is redrawn');
  await page.getByLabel('Extrapolation of curve 1').selectOption('extend');
  assert.equal((await curve()).extrapolate, 'extend');
  // A policy this curve has no value for: the scene format's message, the scene unchanged.
  await page.getByLabel('Extrapolation of curve 1').selectOption('segment');
  assert.match(await page.textContent('#error'), /^error: extrapolate: "segment"/);
  assert.equal((await curve()).extrapolate, 'extend');
  await page.getByLabel('Constant speed of curve 1').uncheck();
  assert.equal((await curve()).parametrization, undefined);
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('screenshots of the playground', async () => {
  const page = await newPage({ width: 1280, height: 860 });
  const s2 = await readFile(path.join(goldenDir, 'compare_geodesic_nlerp_s2.json'), 'utf8');
  await openPlayground(page, sceneUrl(s2));
  await page.screenshot({ path: path.join(outDir, 'playground-s2.png') });
  const s3 = await readFile(path.join(goldenDir, 'geodesic_s3.json'), 'utf8');
  await openPlayground(page, sceneUrl(s3));
  const [t0, t1] = await page.evaluate(() => window.spherekitPage.axis());
  await page.click('#play');
  await page.waitForFunction((t) => window.spherekitPage.t() > t, t0 + 0.1 * (t1 - t0));
  await page.screenshot({ path: path.join(outDir, 'playground-s3-playing.png') });
  await page.click('#play');
  assert.equal(await page.textContent('#play'), '▶ Play', 'paused');
  // Select a key by clicking an axis tip: the point editor shows it.
  const [x, y] = await page.evaluate(() => window.spherekitPage.keyTipOnScreen(0, 2));
  await page.mouse.click(x, y);
  assert.equal(await page.textContent('#point-editor p'), 'curve 1, point 3', 'the key is selected');
  await page.screenshot({ path: path.join(outDir, 'playground-s3-key.png') });
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('Chromium parses and draws every SVG golden (spherekit render -o x.svg)', async () => {
  const svgDir = path.join(goldenDir, 'svg');
  const names = (await readdir(svgDir)).filter((n) => n.endsWith('.svg') && !n.endsWith('.new.svg')).sort();
  assert.ok(names.length > 0, 'SVG goldens exist');
  const page = await newPage();
  await page.goto(`${origin}/index.html`);
  for (const name of names) {
    const text = await readFile(path.join(svgDir, name), 'utf8');
    const result = await page.evaluate(async (svg) => {
      const doc = new DOMParser().parseFromString(svg, 'image/svg+xml');
      const error = doc.querySelector('parsererror')?.textContent ?? null;
      const texts = [...doc.querySelectorAll('text')].map((t) => t.textContent);
      const img = new Image();
      img.src = URL.createObjectURL(new Blob([svg], { type: 'image/svg+xml' }));
      await img.decode();
      // Draw it: some pixels must be neither white nor transparent.
      const c = document.createElement('canvas');
      c.width = img.naturalWidth;
      c.height = img.naturalHeight;
      const ctx = c.getContext('2d');
      ctx.drawImage(img, 0, 0);
      const d = ctx.getImageData(0, 0, c.width, c.height).data;
      let inked = 0;
      for (let i = 0; i < d.length; i += 4) if (d[i + 3] > 0 && (d[i] < 200 || d[i + 1] < 200 || d[i + 2] < 200)) inked++;
      return { error, texts: texts.length, width: img.naturalWidth, height: img.naturalHeight, inked };
    }, text);
    assert.equal(result.error, null, `${name} parses as SVG`);
    assert.equal(result.width, GOLDEN_SIZE, `${name} width`);
    assert.ok(result.texts >= 4, `${name} has its legend (and axes) as <text>`);
    assert.ok(result.inked > 1000, `${name} draws something (${result.inked} inked pixels)`);
  }
  assert.deepEqual(page.errors, []);
  await page.close();
});


const SIZES = [{ width: 1400, height: 900 }, { width: 1024, height: 700 }, { width: 390, height: 844 }];

/** Whether element `selector` is shown and lies inside the viewport. */
async function visibleInViewport(page, selector) {
  return page.evaluate((sel) => {
    const el = document.querySelector(sel);
    if (!el || el.hidden) return { ok: false, why: 'hidden' };
    const r = el.getBoundingClientRect();
    const ok = r.width > 0 && r.height > 0 && r.left >= 0 && r.top >= 0 && r.right <= innerWidth && r.bottom <= innerHeight;
    return { ok, why: JSON.stringify({ left: r.left, top: r.top, right: r.right, bottom: r.bottom, w: innerWidth, h: innerHeight }) };
  }, selector);
}

const frames = (page) => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

test('every failing action shows its message inside the viewport, where the action was', async () => {
  const beta = await readFile(path.join(goldenDir, 'beta_s2_example1.json'), 'utf8');
  for (const vp of SIZES) {
    const page = await newPage(vp);
    const where = `${vp.width}x${vp.height}`;
    // 1. A broken scene in the JSON box: the message beside the Apply button.
    await openPlayground(page, sceneUrl(beta));
    await page.locator('#json').scrollIntoViewIfNeeded();
    await page.fill('#json', '{"space": "S2", ');
    await page.click('#apply-json');
    assert.match(await page.textContent('#error'), /^error: invalid scene JSON: /, where);
    let v = await visibleInViewport(page, '#notice');
    assert.ok(v.ok, `${where} apply: the message is inside the viewport ${v.why}`);
    assert.ok(await page.evaluate(() => document.getElementById('json-actions').nextElementSibling?.id === 'notice'), `${where}: beside the Apply button`);
    // 2. A β₁ the points cannot take: the slider stays, marked; the words and the miss distance.
    const slider = page.locator('#curves input[type=range]').first();
    await slider.scrollIntoViewIfNeeded();
    await slider.evaluate((el) => {
      el.value = '1.5';
      el.dispatchEvent(new Event('input', { bubbles: true }));
      el.dispatchEvent(new Event('change', { bubbles: true }));
    });
    assert.match(await page.textContent('#error'), /did not converge/, where);
    const help = await page.textContent('#error-lead');
    assert.match(help, /^No Beta spline with these β passes through the points: the nearest one found misses a point by \d\.\d+ rad \(\d+°\)/, `${where}: ${help}`);
    v = await visibleInViewport(page, '#notice');
    assert.ok(v.ok, `${where} slider: the message is inside the viewport ${v.why}`);
    assert.equal(await slider.evaluate((el) => el.closest('[aria-invalid="true"]') !== null), true, `${where}: the slider is marked`);
    assert.equal(Number(await slider.inputValue()), 1, `${where}: the slider goes back to the scene's β₁`);
    assert.ok(await page.evaluate(() => Boolean(document.getElementById('error-lead').compareDocumentPosition(document.getElementById('error')) & Node.DOCUMENT_POSITION_FOLLOWING)), `${where}: the plain words come first`);
    assert.equal(JSON.parse(await page.evaluate(() => window.spherekitPage.handle().curve_json(0))).params.beta1, 1, 'the scene keeps its last good β₁');
    // The offer: the approximating spline with the β₁ asked for.
    await page.click('#error-offer');
    assert.equal(await page.locator('#notice').isHidden(), true, `${where}: the message goes once the edit succeeds`);
    const params = JSON.parse(await page.evaluate(() => window.spherekitPage.handle().curve_json(0))).params;
    assert.deepEqual([params.beta1, params.interpolate], [1.5, false], `${where}: approximating with β₁ = 1.5`);
    assert.equal(await page.locator('[aria-invalid="true"]').count(), 0, 'no control is marked any more');
    // 3. Deleting below the minimum (two points): the message beside the point editor.
    await openPlayground(page, sceneUrl('{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]]}'));
    await page.evaluate(() => window.scrollTo(0, 0));
    const [x, y] = await page.evaluate(() => window.spherekitPage.pointOnScreen(0, 1));
    await page.mouse.click(x, y);
    assert.equal(await page.textContent('#point-editor p'), 'curve 1, point 2', `${where}: the point is selected`);
    v = await visibleInViewport(page, '#point-section');
    assert.ok(v.ok, `${where}: the point editor is in reach ${v.why}`);
    await page.keyboard.press('Delete');
    assert.match(await page.textContent('#error'), /^error: /, `${where}: deleting below the minimum is refused`);
    v = await visibleInViewport(page, '#notice');
    assert.ok(v.ok, `${where} delete: the message is inside the viewport ${v.why}`);
    // 4. A broken URL fragment: over the stage.
    await page.evaluate(() => { location.hash = `#scene=${encodeURIComponent('{"space":"S2","method":"geodesic","points":[[1,0,0],[0,0,0]]}')}`; });
    await page.waitForFunction(() => document.getElementById('error').textContent.includes('zero length'));
    v = await visibleInViewport(page, '#notice');
    assert.ok(v.ok, `${where} fragment: the message is inside the viewport ${v.why}`);
    assert.equal(await page.evaluate(() => document.getElementById('notice').className), 'over-stage');
    await page.screenshot({ path: path.join(outDir, `playground-error-${where}.png`) });
    assert.deepEqual(page.errors, [], 'no page errors');
    await page.close();
  }
});

test('the layout: the sphere fills a phone, a small laptop screen does not scroll', async () => {
  const phone = await newPage({ width: 390, height: 844 });
  await openPlayground(phone, `${origin}/index.html`);
  const width = await phone.evaluate(() => document.getElementById('scene').getBoundingClientRect().width);
  assert.ok(width >= 330, `the sphere is ${width} px wide at 390 px`);
  // After a resize too.
  await phone.setViewportSize({ width: 600, height: 844 });
  await frames(phone);
  const wider = await phone.evaluate(() => document.getElementById('scene').getBoundingClientRect().width);
  assert.ok(wider >= 520, `the sphere is ${wider} px wide at 600 px`);
  await phone.close();
  const laptop = await newPage({ width: 1024, height: 700 });
  for (const name of ['cubic_s2', 'compare_s3_squad_catmull_bspline_arcblend', 'figure_omega_s3']) {
    const text = await readFile(path.join(goldenDir, `${name}.json`), 'utf8');
    await openPlayground(laptop, sceneUrl(text));
    const m = await laptop.evaluate(() => ({ h: document.documentElement.scrollHeight, w: document.documentElement.scrollWidth }));
    assert.ok(m.h <= 700 && m.w <= 1024, `${name}: the page does not scroll at 1024×700 (${m.w}×${m.h})`);
    const stage = await laptop.evaluate(() => document.getElementById('canvas-wrap').getBoundingClientRect().bottom);
    assert.ok(stage <= 700, `${name}: the figure is on screen (bottom ${stage})`);
  }
  assert.deepEqual(laptop.errors, [], 'no page errors');
  await laptop.close();
});

test('the first screen: an S² example, a sentence, three steps, examples grouped by method', async () => {
  const page = await newPage({ width: 1400, height: 900 });
  await openPlayground(page, `${origin}/index.html`);
  assert.equal(await page.evaluate(() => window.spherekitPage.handle().space()), 'S2');
  assert.ok((await page.textContent('#intro')).length > 40, 'one sentence on what the page is');
  assert.equal(await page.locator('#try li').count(), 4, 'four "try this" steps');
  const steps = await page.textContent('#try');
  assert.match(steps, /double-click/, 'the hints say how to add a point');
  assert.match(steps, /turn the view/, 'the hints say how to turn the view');
  assert.match(steps, /wheel/, 'the hints say how to zoom');
  const groups = await page.$$eval('#preset optgroup', (gs) => gs.map((g) => ({ label: g.label, items: [...g.children].map((o) => ({ text: o.textContent, title: o.title })) })));
  assert.ok(groups.length >= 10, `grouped (${groups.map((g) => g.label).join(', ')})`);
  for (const g of groups) {
    for (const it of g.items) {
      assert.doesNotMatch(it.text, /_|example\d/, `${g.label}: "${it.text}" is a readable name`);
      assert.ok(it.title.length > 10, `${g.label}: "${it.text}" has a description`);
    }
  }
  assert.ok(groups.some((g) => g.label === 'Beta spline') && groups.some((g) => g.label === 'Comparisons'), 'method groups (by name) and comparisons');
  for (const g of groups) assert.doesNotMatch(g.label, /^[a-z]+(-[a-z]+)+$/, `the group "${g.label}" has a readable name`);
  const methods = await page.$$eval('#new-method option', (os) => os.map((o) => o.textContent));
  assert.ok(methods.includes('Catmull–Rom') && !methods.includes('catmull-rom'), `the method picker shows names (${methods})`);
  assert.ok((await page.textContent('#preset-about')).length > 10, 'the example says what it shows');
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('undo restores the scene exactly after a drag; redo; reset view; zoom; hover', async () => {
  const page = await newPage({ width: 1280, height: 860 });
  const text = await readFile(path.join(goldenDir, 'geodesic_s2.json'), 'utf8');
  await openPlayground(page, sceneUrl(text));
  const scene = () => page.evaluate(() => window.spherekitPage.handle().scene_json());
  const original = await scene();
  assert.equal(await page.isDisabled('#undo'), true, 'nothing to undo at first');
  // Hover over a point: the pointer cursor and a ring.
  const [x, y] = await page.evaluate(() => window.spherekitPage.pointOnScreen(0, 2));
  await page.mouse.move(x + 40, y + 40);
  await page.mouse.move(x, y);
  assert.equal(await page.evaluate(() => getComputedStyle(document.getElementById('overlay')).cursor), 'pointer', 'pointer cursor over a point');
  await page.mouse.move(x + 60, y + 60);
  assert.equal(await page.evaluate(() => getComputedStyle(document.getElementById('overlay')).cursor), 'grab', 'grab elsewhere on the sphere');
  // Drag the point, then undo: the scene text is the original, byte for byte.
  await page.mouse.move(x, y);
  await page.mouse.down();
  for (let k = 1; k <= 10; k++) await page.mouse.move(x + 5 * k, y + 3 * k);
  await page.mouse.up();
  const dragged = await scene();
  assert.notEqual(dragged, original, 'the drag changed the scene');
  await page.click('#undo');
  assert.equal(await scene(), original, 'undo restores the scene exactly');
  await page.click('#redo');
  assert.equal(await scene(), dragged, 'redo brings the drag back');
  await page.locator('#overlay').focus();
  await page.evaluate(() => document.activeElement?.blur());
  await page.keyboard.press('Control+z');
  assert.equal(await scene(), original, 'Ctrl+Z undoes');
  await page.keyboard.press('Control+Shift+Z');
  assert.equal(await scene(), dragged, 'Ctrl+Shift+Z redoes');
  // A parameter edit and a method change are undoable too.
  await page.locator('#curves select').first().selectOption('catmull-rom');
  assert.equal(JSON.parse(await scene()).method, 'catmull-rom');
  await page.click('#undo');
  assert.equal(await scene(), dragged, 'undo of a method change');
  // Turn the view, zoom with the wheel, reset the view.
  const box = await page.locator('#overlay').boundingBox();
  const spot = await page.evaluate(() => window.spherekitPage.emptySpot());
  await page.mouse.move(...spot);
  await page.mouse.down();
  await page.mouse.move(spot[0] + 60, spot[1] + 20, { steps: 5 });
  await page.mouse.up();
  const turned = JSON.parse(await scene()).view.camera;
  assert.ok(turned, 'the camera is in the scene');
  await page.mouse.move(box.x + box.width / 2, box.y + box.width / 2);
  await page.mouse.wheel(0, -300);
  await page.waitForFunction(() => window.spherekitPage.zoom() > 1.3);
  const zoom = await page.evaluate(() => window.spherekitPage.zoom());
  assert.ok(zoom > 1.3, `the wheel zooms in (${zoom})`);
  assert.ok((await page.evaluate(() => window.spherekitPage.size())) > (await page.evaluate(() => document.getElementById('canvas-wrap').clientWidth)), 'drawn larger than the stage');
  await page.screenshot({ path: path.join(outDir, 'playground-zoomed.png') });
  // Pinch: two touch pointers moving apart zoom in further, moving together zoom out.
  const pinch = (spread0, spread1) => page.evaluate(async ([a, b]) => {
    const el = document.getElementById('overlay');
    const r = el.getBoundingClientRect();
    const [cx, cy] = [r.left + r.width / 2, r.top + r.width / 2];
    const send = (type, id, dx) => el.dispatchEvent(new PointerEvent(type, { pointerId: id, pointerType: 'touch', isPrimary: id === 11, clientX: cx + dx, clientY: cy, bubbles: true }));
    send('pointerdown', 11, -a);
    send('pointerdown', 12, a);
    for (let k = 1; k <= 5; k++) {
      const d = a + ((b - a) * k) / 5;
      send('pointermove', 11, -d);
      send('pointermove', 12, d);
      await new Promise((res) => requestAnimationFrame(res));
    }
    send('pointerup', 11, -b);
    send('pointerup', 12, b);
    await new Promise((res) => requestAnimationFrame(() => requestAnimationFrame(res)));
    return window.spherekitPage.zoom();
  }, [spread0, spread1]);
  const pinched = await pinch(40, 60);
  assert.ok(pinched > zoom * 1.3, `pinching out zooms in (${zoom} → ${pinched})`);
  const unpinched = await pinch(60, 30);
  assert.ok(unpinched < pinched * 0.6, `pinching in zooms out (${pinched} → ${unpinched})`);
  await page.click('#reset-view');
  assert.equal(await page.evaluate(() => window.spherekitPage.zoom()), 1, 'reset view: zoom 1');
  assert.equal(JSON.parse(await scene()).view.camera, undefined, 'reset view: the default camera');
  await page.click('#undo');
  assert.deepEqual(JSON.parse(await scene()).view.camera, turned, 'undo of reset view');
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('one t: the slider in curve units, the plot scrub, the readout, reset on a new scene', async () => {
  const page = await newPage({ width: 1400, height: 900 });
  const text = await readFile(path.join(goldenDir, 'squad_s3_nonuniform.json'), 'utf8');
  await openPlayground(page, sceneUrl(text));
  const axis = await page.evaluate(() => window.spherekitPage.axis());
  assert.ok(axis[1] > 1, `the time axis is in the curve's units (${axis})`);
  assert.equal(Number(await page.getAttribute('#t', 'max')), axis[1], 'the slider spans the time axis');
  // Click on the plot at t = 0.4 of the axis, then drag along it.
  const target = axis[0] + 0.4 * (axis[1] - axis[0]);
  const [px, py] = await page.evaluate((t) => window.spherekitPage.plotPointOnScreen(t), target);
  await page.mouse.click(px, py);
  const t1 = await page.evaluate(() => window.spherekitPage.t());
  assert.ok(Math.abs(t1 - target) < 0.02 * (axis[1] - axis[0]), `a click on the plot sets t (${t1} for ${target})`);
  assert.equal(Number(await page.inputValue('#t')).toFixed(6), t1.toFixed(6), 'the slider follows');
  const [qx, qy] = await page.evaluate((t) => window.spherekitPage.plotPointOnScreen(t), axis[0] + 0.8 * (axis[1] - axis[0]));
  await page.mouse.move(px, py);
  await page.mouse.down();
  await page.mouse.move(qx, qy, { steps: 6 });
  await page.mouse.up();
  const t2 = await page.evaluate(() => window.spherekitPage.t());
  assert.ok(t2 > t1 + 0.3 * (axis[1] - axis[0]), `dragging on the plot scrubs (${t1} → ${t2})`);
  // The readout at t: finite numbers, the same t; ω and α in the body frame on request.
  const readout = await page.evaluate(() => window.spherekitPage.readouts());
  assert.equal(readout.length, 1);
  const r = readout[0];
  assert.ok(Math.abs(r.t - t2) < 1e-9, 'the readout is at the page t');
  for (const v of [...r.point, r.speed, ...r.omega, ...r.alpha]) assert.ok(Number.isFinite(v), `finite: ${JSON.stringify(r)}`);
  assert.ok(Math.abs(Math.hypot(...r.omega) - r.speed) < 1e-9, '|ω| is the angular speed');
  const shown = await page.textContent('#readout');
  assert.match(shown, /ω space/);
  assert.doesNotMatch(shown, /NaN|undefined/);
  await page.check('input[name=frame][value=body]');
  const body = (await page.evaluate(() => window.spherekitPage.readouts()))[0];
  assert.match(await page.textContent('#readout'), /ω body/);
  assert.ok(Math.abs(Math.hypot(...body.omega) - r.speed) < 1e-9, 'the body frame has the same |ω|');
  // A new scene puts t back to the start of its axis.
  await page.selectOption('#preset', 'cubic_s2');
  const fresh = await page.evaluate(() => ({ t: window.spherekitPage.t(), axis: window.spherekitPage.axis() }));
  assert.equal(fresh.t, fresh.axis[0], 'reset on a new scene');
  assert.equal(await page.textContent('#t-out'), `t = ${fresh.axis[0].toFixed(3)}`);
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('the continuity class goes beyond C²', async () => {
  const page = await newPage();
  const scene = { space: 'S2', method: 'corner-blend', points: [[1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0.2, 0]], params: { order: 10 } };
  await openPlayground(page, sceneUrl(JSON.stringify(scene)));
  const classes = await page.$$eval('#continuity tbody tr', (rows) => rows.map((r) => r.cells[5].textContent));
  assert.ok(classes.length > 0, 'joints are listed');
  for (const c of classes) assert.doesNotMatch(c, /^C[⁰¹²]?$|^G/, `order 10 is reported beyond C² (${classes})`);
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('a gallery widget opens the same scene in the playground', async () => {
  const page = await newPage({ width: 1100, height: 900 });
  await page.goto(`${origin}/docs.html`);
  await page.waitForFunction(() => [...document.querySelectorAll('spherekit-view')].every((w) => w.dataset.state));
  const first = page.locator('spherekit-view').first();
  const scene = await first.getAttribute('scene');
  await first.locator('a.skv-open').click();
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
  const shown = await page.evaluate(() => window.spherekitPage.handle().scene_json());
  assert.deepEqual(JSON.parse(shown), JSON.parse(scene), 'the playground shows the widget scene');
  assert.equal(await page.textContent('#error'), '');
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('turning the view draws at reduced resolution, the still frame at full resolution', async () => {
  const b = await chromium.launch({ executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium', headless: true, args: ['--headless', '--no-sandbox', '--disable-gpu'] });
  const ctx = await b.newContext({ viewport: { width: 1400, height: 900 }, deviceScaleFactor: 2 });
  const page = await ctx.newPage();
  await openPlayground(page, `${origin}/index.html`);
  const full = await page.evaluate(() => window.spherekitPage.size());
  const hash = await canvasHash(page);
  const width = () => page.evaluate(() => document.getElementById('scene').width);
  const [x, y] = await page.evaluate(() => window.spherekitPage.emptySpot());
  await page.mouse.move(x, y);
  await page.mouse.down();
  for (let k = 1; k <= 8; k++) await page.mouse.move(x + 6 * k, y + 2 * k);
  const moving = await width();
  assert.ok(moving < full / 2, `reduced while moving (${moving} of ${full} px)`);
  await page.waitForFunction((w) => document.getElementById('scene').width === w, full);
  assert.equal(await width(), full, 'full resolution when the pointer holds still');
  // Back to the start and release: the still frame is the one before the drag, pixel for pixel.
  await page.mouse.move(x, y, { steps: 4 });
  await page.mouse.up();
  await page.click('#undo');
  assert.equal(await width(), full);
  assert.equal(await canvasHash(page), hash, 'the still frame after undo is the first one');
  await ctx.close();
  await b.close();
});

/** Where the figure is (the canvas wrapper, the canvas in it) and how far the page scrolls. */
function figureBox(page) {
  return page.evaluate(() => {
    const box = (el) => {
      const r = el.getBoundingClientRect();
      return { left: r.left, top: r.top, right: r.right, bottom: r.bottom, width: r.width, height: r.height };
    };
    const stage = document.getElementById('stage');
    return {
      wrap: box(document.getElementById('canvas-wrap')),
      canvas: box(document.getElementById('scene')),
      stage: box(stage),
      stageScroll: stage.scrollHeight - stage.clientHeight,
      pageBottom: document.scrollingElement.scrollHeight - scrollY,
      view: { w: innerWidth, h: innerHeight },
    };
  });
}

/** Clicks time `t` on the first plot (scrolled into the window first on a phone); the page's t. */
async function clickPlot(page, t) {
  let [x, y] = await page.evaluate((u) => window.spherekitPage.plotPointOnScreen(u), t);
  const h = await page.evaluate(() => innerHeight);
  if (y > h - 10) {
    await page.evaluate((dy) => window.scrollBy(0, dy), y - h / 2);
    [x, y] = await page.evaluate((u) => window.spherekitPage.plotPointOnScreen(u), t);
  }
  await page.mouse.click(x, y);
  return page.evaluate(() => window.spherekitPage.t());
}

test('every example fits: the whole figure at 1400×900, 1024×700 and 390×844, and a plot click lands at its t', async () => {
  const names = (await readdir(goldenDir)).filter((n) => n.endsWith('.json')).map((n) => n.replace('.json', '')).sort();
  for (const vp of SIZES) {
    const page = await newPage(vp);
    const where = `${vp.width}x${vp.height}`;
    await openPlayground(page, `${origin}/index.html`);
    const menu = await page.$$eval('#preset option', (os) => os.map((o) => o.value).filter(Boolean));
    assert.deepEqual(menu.slice().sort(), names, `${where}: the menu holds every example`);
    let plots = 0;
    for (const name of menu) {
      await page.evaluate(() => window.scrollTo(0, 0));
      await page.selectOption('#preset', name);
      const f = await figureBox(page);
      const at = `${where} ${name}: ${JSON.stringify(f)}`;
      // The canvas is not clipped by its wrapper, and the wrapper is reachable.
      assert.ok(f.canvas.height <= f.wrap.height + 1 && f.canvas.width <= f.wrap.width + 1, `${at}: the whole figure is in its frame`);
      assert.ok(f.wrap.left >= 0 && f.wrap.right <= f.view.w, `${at}: within the width`);
      if (vp.width > 800) {
        assert.ok(f.wrap.top >= 0 && f.wrap.bottom <= f.view.h, `${at}: inside the viewport`);
      } else {
        assert.ok(f.wrap.bottom <= f.pageBottom + 1, `${at}: inside the page's scrollable area`);
      }
      // A click on the plot right after choosing the example lands at the clicked t.
      const axis = await page.evaluate(() => window.spherekitPage.axis());
      const hasPlot = await page.evaluate(() => window.spherekitPage.plotPointOnScreen(0) !== null);
      const wantPlot = await page.evaluate(() => JSON.parse(window.spherekitPage.handle().view_options()).plot !== 'none');
      assert.equal(hasPlot, wantPlot, `${where} ${name}: the plot axes are known exactly when a plot is drawn`);
      if (hasPlot) {
        plots++;
        const target = axis[0] + 0.37 * (axis[1] - axis[0]);
        const t = await clickPlot(page, target);
        assert.ok(Math.abs(t - target) <= 0.015 * (axis[1] - axis[0]), `${where} ${name}: the click lands at t = ${t}, aimed at ${target}`);
      }
    }
    assert.ok(plots > 10, `${where}: ${plots} examples with a plot were clicked`);
    assert.deepEqual(page.errors, [], `${where}: no page errors`);
    await page.close();
  }
});

test('clamped ends from the form: the end condition and its velocities go together', async () => {
  const page = await newPage({ width: 1280, height: 860 });
  const scene = { space: 'S2', method: 'cubic', points: [[1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0.2]] };
  await openPlayground(page, sceneUrl(JSON.stringify(scene)));
  const params = async () => JSON.parse(await page.evaluate(() => window.spherekitPage.handle().curve_json(0))).params ?? {};
  const start = page.getByLabel('start velocity');
  // Before: the velocities are disabled, and say why.
  assert.equal(await start.isDisabled(), true, 'no velocity without clamped ends');
  assert.match(await start.evaluate((el) => el.closest('label').textContent), /applies with end “clamped”/);
  // Clamped: the velocities come with it (zero), the select shows what the scene has.
  await page.getByLabel('end', { exact: true }).selectOption('clamped');
  assert.equal(await page.textContent('#error'), '', 'no error');
  assert.deepEqual(await params(), { end: 'clamped', start_velocity: [0, 0, 0], end_velocity: [0, 0, 0] });
  assert.equal(await page.getByLabel('end', { exact: true }).inputValue(), 'clamped');
  // Then a velocity typed in (the other order is not offered: disabled until clamped).
  assert.equal(await start.isDisabled(), false, 'the velocities are enabled with clamped ends');
  await start.fill('0, 0.5, 0');
  await start.dispatchEvent('change');
  assert.equal(await page.textContent('#error'), '');
  assert.deepEqual((await params()).start_velocity, [0, 0.5, 0]);
  assert.equal((await params()).end, 'clamped');
  // Back to natural: the velocities go too.
  await page.getByLabel('end', { exact: true }).selectOption('natural');
  assert.deepEqual(await params(), {});
  assert.equal(await page.textContent('#error'), '');
  // A closed loop has no ends: the end controls give way to a note.
  await page.getByLabel('end', { exact: true }).selectOption('clamped');
  await page.locator('#curves label:has-text("closed loop") input').check();
  assert.equal(await page.textContent('#error'), '');
  assert.deepEqual(await params(), {}, 'closing drops the end conditions');
  assert.equal(await page.getByLabel('end', { exact: true }).count(), 0, 'no end control on a loop');
  assert.match(await page.textContent('#curves'), /A closed loop has no ends/);
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('the body frame: the ω plot, the readout, and a note where the frames coincide', async () => {
  const page = await newPage({ width: 1400, height: 900 });
  const text = await readFile(path.join(goldenDir, 'figure_omega_s3.json'), 'utf8');
  await openPlayground(page, sceneUrl(text));
  // At t₀ the body is at rest orientation: the note says the frames coincide.
  assert.equal(await page.isVisible('#frame-note'), true, 'a note at the identity');
  const [t0, t1] = await page.evaluate(() => window.spherekitPage.axis());
  await page.evaluate((t) => {
    const s = document.getElementById('t');
    s.value = String(t);
    s.dispatchEvent(new Event('input', { bubbles: true }));
  }, t0 + 0.4 * (t1 - t0));
  assert.equal(await page.isVisible('#frame-note'), false, 'no note where the frames differ');
  const space = (await page.evaluate(() => window.spherekitPage.readouts()))[0];
  /** The second plot's title band and its plotted values, as pixel sums per row. */
  const strip = () => page.evaluate(() => {
    const c = document.getElementById('scene');
    const p = JSON.parse(window.spherekitPage.handle().plot_axes())[1];
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const band = (y0, y1, x0, x1) => {
      let sum = 0;
      for (let y = Math.max(0, Math.floor(y0)); y < Math.min(c.height, y1); y++) for (let x = Math.floor(x0); x < x1; x++) sum += d[4 * (y * c.width + x)];
      return sum;
    };
    const h = p.bottom - p.top;
    return { title: band(p.top - 0.3 * h, p.top, 0, c.width), values: band(p.top, p.bottom, p.left + 1, p.right) };
  });
  const before = await strip();
  await page.check('input[name=frame][value=body]');
  assert.equal(await page.textContent('#error'), '');
  assert.equal(JSON.parse(await page.evaluate(() => window.spherekitPage.handle().scene_json())).view.omega_frame, 'body', 'the frame is the scene\'s');
  const after = await strip();
  const f = await figureBox(page);
  assert.ok(f.wrap.bottom <= f.view.h && f.canvas.height <= f.wrap.height + 1, `the figure still fits (${JSON.stringify(f)})`);
  assert.notEqual(after.title, before.title, 'the plot title changes (space frame → body frame)');
  assert.notEqual(after.values, before.values, 'the plotted components change');
  const body = (await page.evaluate(() => window.spherekitPage.readouts()))[0];
  assert.match(await page.textContent('#readout'), /ω body/);
  assert.ok(Math.abs(Math.hypot(...body.omega) - space.speed) < 1e-9, 'the same |ω|');
  assert.ok(Math.hypot(...body.omega.map((x, k) => x - space.omega[k])) > 1e-3, 'other components');
  // The link keeps the frame: a fresh load shows the body frame selected.
  const url = await page.evaluate(() => location.href);
  const fresh = await newPage({ width: 1400, height: 900 });
  await openPlayground(fresh, url);
  assert.equal(await fresh.isChecked('input[name=frame][value=body]'), true);
  await page.click('#undo');
  assert.equal(await page.isChecked('input[name=frame][value=space]'), true, 'undo of the frame switch');
  assert.deepEqual([...page.errors, ...fresh.errors], [], 'no page errors');
  await fresh.close();
  await page.close();
});

/** Whether some pixel within `r` device pixels of (x, y) on the scene canvas has colour `hex`. */
function hasColorNear(page, [x, y], hex, r = 10) {
  return page.evaluate(([x, y, hex, r]) => {
    const c = document.getElementById('scene');
    const b = c.getBoundingClientRect();
    const k = c.width / b.width;
    const [cx, cy] = [(x - b.left) * k, (y - b.top) * k];
    const want = [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
    const d = c.getContext('2d').getImageData(Math.round(cx - r), Math.round(cy - r), 2 * r, 2 * r).data;
    for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - want[0]) + Math.abs(d[i + 1] - want[1]) + Math.abs(d[i + 2] - want[2]) < 30) return true;
    return false;
  }, [x, y, hex, r]);
}

test('compare with another method: shared keys, the same times and loop, a key marker per curve', async () => {
  const page = await newPage({ width: 1280, height: 860 });
  const scene = { space: 'S2', method: 'cubic', points: [[1, 0, 0.2], [0.3, 1, 0.5], [-0.5, 0.3, 1], [-1, -0.6, 0.1], [-0.2, -1, -0.6]], knots: [0, 1, 3, 4, 6] };
  await openPlayground(page, sceneUrl(JSON.stringify(scene)));
  const curve = async (c) => JSON.parse(await page.evaluate((k) => window.spherekitPage.handle().curve_json(k), c));
  await page.selectOption('#new-method', 'catmull-rom');
  await page.click('#add-curve');
  assert.equal(await page.textContent('#error'), '');
  const [a, b] = [await curve(0), await curve(1)];
  assert.deepEqual(b.points, a.points, 'the same keys');
  assert.deepEqual(b.knots, [1, 3, 4], 'the inner keys keep their times (Catmull–Rom has no knots at its end points)');
  assert.deepEqual([a.label, b.label], ['Cubic spline', 'Catmull–Rom'], 'the legend says which is which');
  // Each curve's keys in its own colour: at a shared key both colours show.
  const colors = JSON.parse(await page.evaluate(() => window.spherekitPage.handle().colors()));
  const key = await page.evaluate(() => window.spherekitPage.pointOnScreen(0, 2));
  for (const c of colors) assert.ok(await hasColorNear(page, key, c), `a marker in ${c} at the shared key`);
  // A drag moves the key of both curves.
  const [x, y] = key;
  await page.mouse.move(x, y);
  await page.mouse.down();
  for (let k = 1; k <= 8; k++) await page.mouse.move(x + 4 * k, y + 3 * k);
  await page.mouse.up();
  const [a2, b2] = [await curve(0), await curve(1)];
  assert.notDeepEqual(a2.points[2], a.points[2], 'the key moved');
  assert.deepEqual(b2.points, a2.points, 'both curves moved together');
  await page.click('#undo');
  assert.deepEqual((await curve(1)).points, a.points, 'one undo puts both back');
  // A double-click on empty sphere adds a point to both; a single click adds nothing.
  const spot = await page.evaluate(() => window.spherekitPage.emptySpot());
  await page.mouse.click(...spot);
  assert.equal((await curve(0)).points.length, 5, 'a single click adds no point');
  await page.mouse.dblclick(...spot);
  assert.equal((await curve(0)).points.length, 6, 'a double-click adds a point');
  assert.deepEqual((await curve(1)).points, (await curve(0)).points, 'to both curves');
  await page.click('#undo');
  // Closing the cubic's loop keeps every key's time and says when it returns to the first.
  await page.locator('#curves .curve').first().locator('label:has-text("closed loop") input').check();
  assert.equal(await page.textContent('#error'), '');
  assert.deepEqual((await curve(0)).knots, [0, 1, 3, 4, 6, 7.5], 'the knots stay, and the return comes one mean spacing later');
  assert.match(await page.textContent('#curves .curve .note'), /keeps its time.*t = 7\.5/);
  // Comparing a closed curve gives a closed curve.
  // (Selecting the card by its top-left corner: its middle holds controls, such as the loop box.)
  await page.locator('#curves .curve').first().click({ position: { x: 4, y: 4 } });
  assert.equal(JSON.parse(await page.evaluate(() => window.spherekitPage.handle().curve_json(0))).closed, true, 'selecting the card changes nothing');
  await page.selectOption('#new-method', 'geodesic');
  await page.click('#add-curve');
  const g = await curve(2);
  assert.equal(g.closed, true, 'the loop setting is copied');
  assert.deepEqual(g.knots, [0, 1, 3, 4, 6, 7.5], 'and the times');
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('keyboard only: reach the sphere, select a point, move it, undo, turn the view, delete', async () => {
  const page = await newPage({ width: 1280, height: 860 });
  const text = await readFile(path.join(goldenDir, 'geodesic_s2.json'), 'utf8');
  await openPlayground(page, sceneUrl(text));
  const scene = () => page.evaluate(() => window.spherekitPage.handle().scene_json());
  const original = await scene();
  let reached = false;
  for (let k = 0; k < 40 && !reached; k++) {
    await page.keyboard.press('Tab');
    reached = await page.evaluate(() => document.activeElement?.id === 'overlay');
  }
  assert.ok(reached, 'Tab reaches the sphere');
  assert.notEqual(await page.evaluate(() => getComputedStyle(document.getElementById('canvas-wrap')).outlineStyle), 'none', 'a visible focus ring');
  assert.equal(await page.isVisible('#keys-hint'), true, 'the keys are explained while the sphere has focus');
  await page.keyboard.press('Tab');
  assert.equal(await page.textContent('#point-editor p'), 'curve 1, point 1', 'Tab selects the first point');
  await page.keyboard.press('Tab');
  assert.equal(await page.textContent('#point-editor p'), 'curve 1, point 2', 'and the next');
  assert.equal(await page.evaluate(() => document.activeElement?.id), 'overlay', 'focus stays on the sphere');
  const before = await page.evaluate(() => Array.from(window.spherekitPage.handle().point(0, 1)));
  for (let k = 0; k < 3; k++) await page.keyboard.press('ArrowRight');
  const moved = await page.evaluate(() => Array.from(window.spherekitPage.handle().point(0, 1)));
  assert.ok(Math.hypot(...moved.map((v, k) => v - before[k])) > 0.01, 'the arrows move the point');
  for (let k = 0; k < 3; k++) await page.keyboard.press('Control+z');
  assert.equal(await scene(), original, 'undo restores the scene exactly');
  await page.keyboard.press('Escape');
  assert.match(await page.textContent('#point-editor p'), /Click a point/, 'Escape deselects');
  await page.keyboard.press('ArrowLeft');
  const camera = JSON.parse(await scene()).view?.camera;
  assert.ok(Array.isArray(camera), 'an arrow without a selection turns the view');
  await page.keyboard.press('Tab');
  const count = JSON.parse(await scene()).points.length;
  await page.keyboard.press('Delete');
  assert.equal(JSON.parse(await scene()).points.length, count - 1, 'Delete removes the selected point');
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('a shared link keeps t and zoom', async () => {
  const page = await newPage({ width: 1280, height: 860 });
  const text = await readFile(path.join(goldenDir, 'cubic_s2.json'), 'utf8');
  await openPlayground(page, sceneUrl(text));
  const [t0, t1] = await page.evaluate(() => window.spherekitPage.axis());
  const t = t0 + 0.6 * (t1 - t0);
  await page.evaluate((u) => {
    const s = document.getElementById('t');
    s.value = String(u);
    s.dispatchEvent(new Event('input', { bubbles: true }));
  }, t);
  await page.focus('#overlay');
  await page.keyboard.press('+');
  await page.keyboard.press('+');
  const zoom = await page.evaluate(() => window.spherekitPage.zoom());
  assert.ok(zoom > 1.2, `zoomed in (${zoom})`);
  await page.waitForFunction(() => /^#t=[^&]+&zoom=[^&]+&scene=/.test(location.hash));
  const url = await page.evaluate(() => location.href);
  const fresh = await newPage({ width: 1280, height: 860 });
  await openPlayground(fresh, url);
  assert.ok(Math.abs((await fresh.evaluate(() => window.spherekitPage.t())) - t) < 1e-4, 'the same t');
  assert.ok(Math.abs((await fresh.evaluate(() => window.spherekitPage.zoom())) - zoom) < 1e-3, 'the same zoom');
  assert.equal(await fresh.evaluate(() => window.spherekitPage.handle().scene_json()), await page.evaluate(() => window.spherekitPage.handle().scene_json()), 'the same scene');
  assert.equal(await fresh.inputValue('#preset'), 'cubic_s2', 'the example is named, not "your scene"');
  assert.deepEqual([...page.errors, ...fresh.errors], [], 'no page errors');
  await fresh.close();
  await page.close();
});

test('"New" starts again from the fewest points of the method, undoably', async () => {
  const page = await newPage({ width: 1280, height: 860 });
  const text = await readFile(path.join(goldenDir, 'squad_s3.json'), 'utf8');
  await openPlayground(page, sceneUrl(text));
  const before = await page.evaluate(() => window.spherekitPage.handle().scene_json());
  await page.click('#new-scene');
  assert.equal(await page.textContent('#error'), '');
  const fresh = JSON.parse(await page.evaluate(() => window.spherekitPage.handle().scene_json()));
  const min = await page.evaluate(() => JSON.parse(window.spherekitPage.handle().curve_json(0)).points.length);
  assert.equal(fresh.space, 'S3');
  assert.equal(fresh.method, 'squad');
  const need = await page.evaluate(async () => {
    const sk = await import('./pkg/spherekit_wasm.js');
    return Math.max(2, JSON.parse(sk.methods()).find((m) => m.id === 'squad').min_points);
  });
  assert.equal(min, need, 'the fewest points squad takes');
  assert.ok(min >= 2 && min < JSON.parse(before).points.length, `${min} points`);
  await page.click('#undo');
  assert.equal(await page.evaluate(() => window.spherekitPage.handle().scene_json()), before, 'undo brings the scene back');
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

/** The fit readout of curve `c` and the report Rust gives for it (`info.fit`). */
async function fitState(page, c = 0) {
  return page.evaluate((c) => {
    const pg = window.spherekitPage.handle();
    const [t0] = Array.from(pg.time_axis());
    const json = JSON.parse(pg.sample_at(new Float64Array([t0]), false, null));
    return {
      readout: document.querySelector(`[data-fit-readout="${c}"]`)?.textContent ?? null,
      info: (json.curves ?? [json])[c].info.fit ?? null,
      fit: JSON.parse(pg.curve_json(c)).fit ?? null,
      lambdaBox: document.querySelector(`#curves .curve:nth-child(${c + 1}) .fit-lambda input[type=number]`)?.value ?? null,
      slider: document.querySelector(`#curves .curve:nth-child(${c + 1}) .fit-lambda input[type=range]`)?.value ?? null,
    };
  }, c);
}

/** Moves curve 0's λ slider to log₁₀ λ = `log` as a drag would: input events, then change. */
async function slideLambda(page, log) {
  await page.evaluate((log) => {
    const range = document.querySelector('#curves .curve .fit-lambda input[type=range]');
    const from = Number(range.value);
    for (let k = 1; k <= 4; k++) {
      range.value = String(from + ((log - from) * k) / 4);
      range.dispatchEvent(new Event('input', { bubbles: true }));
    }
    range.dispatchEvent(new Event('change', { bubbles: true }));
  }, log);
}

test('fitted examples: λ slider, GCV, target rms, a dragged sample, errors and compare', async () => {
  const page = await newPage({ width: 1280, height: 860 });
  await openPlayground(page, `${origin}/index.html`);
  const timings = [];
  for (const name of ['fit_noisy_s2', 'fit_noisy_s3']) {
    await page.selectOption('#preset', name);
    assert.equal(await page.textContent('#error'), '', `${name}: no error`);
    assert.match(await page.textContent('#preset-about'), /sample/, `${name}: described`);
    let s = await fitState(page);
    assert.equal(s.fit.smoothing, s.info.lambda, `${name}: the example's λ`);
    assert.match(s.readout, new RegExp(`^λ = ${s.info.lambda} · rms \\d\\.\\d{3}° · max \\d\\.\\d{3}° · \\d+ keys · edf \\d+\\.\\d$`), `${name}: ${s.readout}`);
    assert.ok(Math.abs(Number(s.slider) - Math.log10(s.info.lambda)) < 1e-9, `${name}: the slider at log λ`);
    // A rebuild of the example in the page, with its λ and with GCV (the fit runs in wasm).
    timings.push(await page.evaluate((name) => {
      const pg = window.spherekitPage.handle();
      const text = pg.scene_json();
      const scene = JSON.parse(text);
      const gcv = JSON.stringify({ ...scene, fit: { ...scene.fit, smoothing: 'gcv' } });
      // Each run moves the first sample a little, so that every set_scene rebuilds the fit.
      const time = (t, n) => {
        const runs = [];
        for (let k = 1; k <= n; k++) {
          const moved = JSON.parse(t);
          moved.points[0] = moved.points[0].map((x, i) => (i === 1 ? x + 1e-5 * k : x));
          const moveText = JSON.stringify(moved);
          const builds = pg.builds();
          const t0 = performance.now();
          pg.set_scene(moveText);
          runs.push(performance.now() - t0);
          if (pg.builds() === builds) throw new Error('set_scene did not rebuild');
        }
        runs.sort((a, b) => a - b);
        return runs[(n - 1) >> 1];
      };
      const given = time(text, 3);
      const chosen = time(gcv, 1); // a second and a half: once keeps the test quick
      pg.set_scene(text);
      return `${name}: rebuild with λ given ${given.toFixed(1)} ms (median of 3), with GCV ${chosen.toFixed(1)} ms`;
    }, name));
    const before = await canvasHash(page);
    await slideLambda(page, 0);
    s = await fitState(page);
    assert.equal(s.fit.smoothing, 1, `${name}: λ = 10⁰ from the slider`);
    assert.match(s.readout, /^λ = 1 · /, `${name}: the readout follows (${s.readout})`);
    assert.equal(s.lambdaBox, '1');
    assert.notEqual(await canvasHash(page), before, `${name}: the figure changes`);
    await page.click('#undo');
    assert.equal((await fitState(page)).fit.smoothing, JSON.parse((await page.evaluate(() => window.spherekitPage.handle().scene_json()))).fit.smoothing);
    // GCV: the λ it chose is the one shown, and the slider continues from it.
    await page.locator('#curves .fit-gcv').click();
    await page.waitForFunction(() => JSON.parse(window.spherekitPage.handle().curve_json(0)).fit.smoothing === 'gcv');
    s = await fitState(page);
    assert.equal(s.fit.smoothing, 'gcv', `${name}: GCV chosen`);
    assert.equal(await page.textContent('#error'), '', `${name}: GCV converged`);
    assert.ok(s.readout.startsWith(`λ = ${Number(s.info.lambda.toPrecision(4))} · `), `${name}: the λ GCV chose (${s.info.lambda}) is shown: ${s.readout}`);
    assert.equal(Number(s.lambdaBox), Number(s.info.lambda.toPrecision(4)), `${name}: the λ box`);
    assert.ok(Math.abs(Number(s.slider) - Math.log10(s.info.lambda)) < 1e-9, `${name}: the slider at GCV's λ`);
    await slideLambda(page, Number(s.slider) + 0.5);
    s = await fitState(page);
    assert.equal(typeof s.fit.smoothing, 'number', `${name}: the slider gives a λ again`);
    assert.ok(Math.abs(Math.log10(s.fit.smoothing) - Math.log10(s.info.lambda)) < 1e-9);
    // A target rms (degrees). (On S³ the core's rms search does not converge on these samples
    // yet: the page shows its error, as the next step checks for a bad λ.)
    if (name === 'fit_noisy_s2') {
      const rms = page.locator('#curves .fit-rms');
      await rms.fill('0.8');
      await rms.dispatchEvent('change');
      s = await fitState(page);
      assert.equal(await page.textContent('#error'), '', `${name}: the target is met`);
      assert.ok(Math.abs(s.fit.smoothing.rms - (0.8 * Math.PI) / 180) < 1e-12, `${name}: the target in radians`);
      assert.match(s.readout, /rms 0\.800°/, `${name}: the fit meets the target (${s.readout})`);
    }
    // A bad λ: the page says why beside the control and keeps the scene.
    const kept = await page.evaluate(() => window.spherekitPage.handle().scene_json());
    const box = page.locator('#curves .fit-lambda input[type=number]');
    await box.fill('-1');
    await box.dispatchEvent('change');
    assert.match(await page.textContent('#error'), /fit\.smoothing/, `${name}: the error names the field`);
    assert.equal(await page.evaluate(() => window.spherekitPage.handle().scene_json()), kept, `${name}: the scene is kept`);
  }
  console.log(`fit rebuilds in the page:\n  ${timings.join('\n  ')}`);
  // Dragging a sample moves it and fits again.
  await page.selectOption('#preset', 'fit_noisy_s2');
  const was = await fitState(page);
  const p0 = await page.evaluate(() => Array.from(window.spherekitPage.handle().point(0, 40)));
  const [x, y] = await page.evaluate(() => window.spherekitPage.pointOnScreen(0, 40));
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + 30, y - 30, { steps: 6 });
  await page.mouse.up();
  const p1 = await page.evaluate(() => Array.from(window.spherekitPage.handle().point(0, 40)));
  assert.ok(Math.hypot(...p1.map((v, k) => v - p0[k])) > 0.02, `the sample moved (${p0} → ${p1})`);
  const now = await fitState(page);
  assert.ok(now.info.residuals[40] > was.info.residuals[40], 'its residual grew');
  assert.notEqual(now.readout, was.readout, 'the readout follows the drag');
  // With GCV, λ is held while the sample moves and searched for again when it is let go.
  await page.locator('#curves .fit-gcv').click();
  await page.waitForFunction(() => JSON.parse(window.spherekitPage.handle().curve_json(0)).fit.smoothing === 'gcv');
  const g0 = await page.evaluate(() => Array.from(window.spherekitPage.handle().point(0, 20)));
  const [gx, gy] = await page.evaluate(() => window.spherekitPage.pointOnScreen(0, 20));
  await page.mouse.move(gx, gy);
  await page.mouse.down();
  await page.mouse.move(gx + 10, gy + 10, { steps: 2 });
  const held = await fitState(page);
  assert.equal(typeof held.fit.smoothing, 'number', 'λ held during the drag');
  await page.mouse.move(gx + 20, gy + 20, { steps: 2 });
  await page.mouse.up();
  const after = await fitState(page);
  assert.equal(after.fit.smoothing, 'gcv', 'GCV again after the drag');
  assert.equal(await page.textContent('#error'), '');
  await page.click('#undo');
  assert.equal((await fitState(page)).fit.smoothing, 'gcv', 'undo: before the drag, with GCV');
  assert.deepEqual(await page.evaluate(() => Array.from(window.spherekitPage.handle().point(0, 20))), g0, 'undo: the sample back');
  assert.notEqual(after.info.lambda, held.info.lambda, 'GCV searched again on the moved sample');
  // Compare with the cubic: the interpolating spline through the samples.
  await page.selectOption('#new-method', 'cubic');
  await page.click('#add-curve');
  assert.equal(await page.textContent('#error'), '');
  const curves = await page.evaluate(() => [0, 1].map((c) => JSON.parse(window.spherekitPage.handle().curve_json(c))));
  assert.equal(curves[0].label, 'Cubic spline, fitted');
  assert.equal(curves[1].label, 'Cubic spline through the samples');
  assert.equal(curves[1].fit, undefined, 'the second curve interpolates');
  assert.deepEqual(curves[1].points, curves[0].points, 'the same samples');
  assert.deepEqual(curves[1].knots, curves[0].knots, 'at the same times');
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('the fit switch turns a cubic into the smoothing spline of its points and back', async () => {
  const page = await newPage({ width: 1280, height: 860 });
  // The S³ example with scipy's ends instead of a fit: its 64 samples are interpolated.
  const example = JSON.parse(await readFile(path.join(goldenDir, 'fit_noisy_s3.json'), 'utf8'));
  delete example.fit;
  example.params = { end: 'scipy' };
  await openPlayground(page, sceneUrl(JSON.stringify(example)));
  assert.equal(await page.locator('[data-fit-readout]').count(), 0, 'no fit readout without a fit');
  await page.getByLabel('Curve 1 fitted to its points').click();
  assert.equal(await page.textContent('#error'), '');
  const curve = JSON.parse(await page.evaluate(() => window.spherekitPage.handle().curve_json(0)));
  assert.deepEqual(curve.fit, { smoothing: 'gcv' });
  assert.equal(curve.params, undefined, 'scipy ends dropped: a fit has natural ends');
  assert.match(await page.textContent('#curves .note'), /natural ends/);
  const s = await fitState(page);
  assert.ok(s.readout.startsWith(`λ = ${Number(s.info.lambda.toPrecision(4))} · `), s.readout);
  await page.getByLabel('Curve 1 fitted to its points').click();
  assert.equal(JSON.parse(await page.evaluate(() => window.spherekitPage.handle().curve_json(0))).fit, undefined);
  assert.equal(await page.locator('[data-fit-readout]').count(), 0, 'the fit controls go with the fit');
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('screenshots at 1400×900, 1024×700 and 390×844, device pixel ratio 1 and 2', async () => {
  const s3 = await readFile(path.join(goldenDir, 'compare_s3_squad_catmull_bspline_arcblend.json'), 'utf8');
  const b = await chromium.launch({ executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium', headless: true, args: ['--headless', '--no-sandbox', '--disable-gpu'] });
  for (const dpr of [1, 2]) {
    for (const vp of SIZES) {
      const where = `${vp.width}x${vp.height} DPR ${dpr}`;
      const ctx = await b.newContext({ viewport: vp, deviceScaleFactor: dpr });
      const page = await ctx.newPage();
      const errors = [];
      page.on('pageerror', (e) => errors.push(String(e)));
      await openPlayground(page, `${origin}/index.html`);
      const canvas = await page.evaluate(() => ({ w: document.getElementById('scene').width, css: document.getElementById('scene').getBoundingClientRect().width }));
      assert.ok(Math.abs(canvas.w - canvas.css * dpr) <= 2, `${where}: the canvas has ${dpr} device pixels per CSS pixel (${JSON.stringify(canvas)})`);
      await page.screenshot({ path: path.join(outDir, `playground-${vp.width}x${vp.height}-dpr${dpr}.png`) });
      await openPlayground(page, sceneUrl(s3));
      const f = await figureBox(page);
      if (vp.width > 800) assert.ok(f.wrap.bottom <= f.view.h, `${where}: the figure is inside the viewport (${f.wrap.bottom})`);
      const t = await clickPlot(page, 1.7);
      assert.ok(Math.abs(t - 1.7) < 0.2, `${where}: the plot click sets t (${t})`);
      await page.screenshot({ path: path.join(outDir, `playground-s3-${vp.width}x${vp.height}-dpr${dpr}.png`) });
      assert.deepEqual(errors, [], `no page errors at ${where}`);
      await ctx.close();
    }
  }
  await b.close();
});

test('the playground and the gallery load nothing from other origins', async () => {
  const page = await browser.newPage();
  const requests = [];
  page.on('request', (r) => requests.push(r.url()));
  await openPlayground(page, `${origin}/index.html`);
  await page.goto(`${origin}/docs.html`);
  await page.waitForFunction(() => [...document.querySelectorAll('spherekit-view')].every((w) => w.dataset.state === 'ready'));
  const own = requests.filter((u) => u.startsWith(`${origin}/`));
  assert.ok(own.some((u) => u.endsWith('.wasm')) && own.some((u) => u.endsWith('presets.json')), `the pages' own files were requested (${own.length})`);
  assert.deepEqual(requests.filter((u) => !u.startsWith(`${origin}/`) && !u.startsWith('data:') && !u.startsWith('blob:')), []);
  await page.close();
});
