// End-to-end test of the playground (web/index.html) and the docs widget page (web/docs.html)
// in Debian's headless Chromium through playwright-core. Needs `just web` first (web/pkg).
//
//   node tests/e2e/run.mjs          (just test-e2e)
//
// Screenshots go to tests/e2e/out/ (git-ignored).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { createServer } from 'node:http';
import { readFile, readdir, mkdir } from 'node:fs/promises';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { PNG } from 'pngjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, '../..');
const webDir = path.join(root, 'web');
const goldenDir = path.join(root, 'tests/golden');
const outDir = path.join(here, 'out');
const GOLDEN_SIZE = 384;

const MIME = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.wasm': 'application/wasm',
  '.json': 'application/json',
};

let server;
let origin;
let browser;
let userDataDir;
const externalRequests = [];

before(async () => {
  await mkdir(outDir, { recursive: true });
  server = createServer(async (req, res) => {
    const url = new URL(req.url, 'http://x');
    const rel = decodeURIComponent(url.pathname === '/' ? '/index.html' : url.pathname);
    const file = path.join(webDir, path.normalize(rel));
    if (!file.startsWith(webDir)) {
      res.writeHead(403).end();
      return;
    }
    try {
      const body = await readFile(file);
      res.writeHead(200, { 'content-type': MIME[path.extname(file)] ?? 'application/octet-stream' });
      res.end(body);
    } catch {
      res.writeHead(404).end('not found');
    }
  });
  await new Promise((r) => server.listen(0, '127.0.0.1', r));
  origin = `http://127.0.0.1:${server.address().port}`;
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
  page.on('request', (r) => { if (!r.url().startsWith(origin) && !r.url().startsWith('data:') && !r.url().startsWith('blob:')) externalRequests.push(r.url()); });
  page.errors = errors;
  return page;
}

const sceneUrl = (text, query = '') => `${origin}/index.html${query}#scene=${encodeURIComponent(text)}`;

async function openPlayground(page, url) {
  await page.goto(url);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

/** The scene canvas's pixels, straight RGBA. */
async function canvasPixels(page) {
  return page.evaluate(() => {
    const c = document.getElementById('scene');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height);
    return { width: c.width, height: c.height, data: Array.from(d.data) };
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

test('the docs page renders a widget for every implemented method', async () => {
  const page = await newPage({ width: 1100, height: 900 });
  await page.goto(`${origin}/docs.html`);
  await page.waitForFunction(() => [...document.querySelectorAll('spherekit-view')].every((w) => w.dataset.state));
  const widgets = await page.evaluate(async () => {
    const sk = await import('./pkg/spherekit_wasm.js');
    const implemented = new Set(JSON.parse(sk.methods()).filter((m) => m.implemented !== false).map((m) => m.id));
    return [...document.querySelectorAll('section.method')].map((s) => {
      const w = s.querySelector('spherekit-view');
      const canvas = w.querySelector('canvas');
      let inked = 0;
      if (canvas) {
        const d = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
          for (let i = 0; i < d.length; i += 4) if (d[i] + d[i + 1] + d[i + 2] < 600) inked++;
      }
      return { method: s.dataset.method, implemented: implemented.has(s.dataset.method), state: w.dataset.state, inked, text: w.textContent };
    });
  });
  const methods = await page.evaluate(async () => JSON.parse((await import('./pkg/spherekit_wasm.js')).methods()).map((m) => m.id));
  assert.deepEqual(widgets.map((w) => w.method).sort(), methods.slice().sort(), 'one widget per method');
  for (const w of widgets) {
    if (w.implemented) {
      assert.equal(w.state, 'ready', `${w.method}: rendered`);
      assert.ok(w.inked > 500, `${w.method}: the canvas shows the scene (${w.inked} dark pixels)`);
    } else {
      assert.equal(w.state, 'error', `${w.method}: not implemented`);
      assert.match(w.text, /is not implemented yet/);
    }
  }
  console.log(`docs widgets: ${widgets.filter((w) => w.state === 'ready').length} rendered, ${widgets.filter((w) => w.state !== 'ready').length} not implemented yet (${widgets.filter((w) => w.state !== 'ready').map((w) => w.method).join(', ')})`);
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
  await first.locator('button').click();
  await page.waitForTimeout(400);
  await page.screenshot({ path: path.join(outDir, 'docs.png'), fullPage: true });
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
  await page.click('#play');
  await page.waitForTimeout(700);
  await page.screenshot({ path: path.join(outDir, 'playground-s3-playing.png') });
  await page.click('#play');
  // Select a key by clicking an axis tip.
  const [x, y] = await page.evaluate(() => {
    const h = window.spherekitPage.handle();
    const key = Array.from(h.point(0, 2));
    return window.spherekitPage.keyTipOnScreen ? window.spherekitPage.keyTipOnScreen(0, 2) : [0, 0, key];
  });
  if (x) {
    await page.mouse.click(x, y);
    await page.screenshot({ path: path.join(outDir, 'playground-s3-key.png') });
  }
  assert.deepEqual(page.errors, [], 'no page errors');
  await page.close();
});

test('the playground loads nothing from other origins', () => {
  assert.deepEqual(externalRequests, []);
});
