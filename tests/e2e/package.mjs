// The npm package as a user installs it: `npm pack` of web/pkg (`just web`), the tarball
// installed with npm into a scratch directory outside the repository, and the code blocks of
// docs/web.md and of the package's README run there: the `sh` block is the install command (run
// with the tarball in place of the registry), each `html` block a page served from the scratch
// directory and opened in Debian's headless Chromium, each `js` block a module run by node. A
// widget whose scene is a golden scene, at the golden size, must draw the golden pixels.
//
//   node tests/e2e/package.mjs          (just test-package)
//
// Screenshots of the pages go to tests/e2e/out/ (git-ignored).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFile, readdir, mkdir, writeFile } from 'node:fs/promises';
import { mkdtempSync, rmSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { PNG } from 'pngjs';
import { serve } from './serve.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, '../..');
const pkgDir = path.join(root, 'web/pkg');
const goldenDir = path.join(root, 'tests/golden');
const outDir = path.join(here, 'out');
const GUIDES = ['docs/web.md', 'crates/spherekit-wasm/README.md'];
const GOLDEN_SIZE = 384;

/** The fenced code blocks of a Markdown file: `{ lang, code, line }`. */
function codeBlocks(text) {
  const blocks = [];
  const lines = text.split('\n');
  for (let i = 0; i < lines.length; i++) {
    const open = lines[i].match(/^```(\w*)\s*$/);
    if (!open) continue;
    const start = i;
    const body = [];
    for (i++; i < lines.length && lines[i] !== '```'; i++) body.push(lines[i]);
    assert.ok(i < lines.length, `line ${start + 1}: unclosed code block`);
    blocks.push({ lang: open[1], code: `${body.join('\n')}\n`, line: start + 1 });
  }
  return blocks;
}

let scratch;
let installed;
let server;
let origin;
let browser;
const blocks = [];
const externalRequests = [];

before(async () => {
  assert.ok(existsSync(path.join(pkgDir, 'package.json')), 'web/pkg/package.json exists (just web)');
  scratch = mkdtempSync(path.join(tmpdir(), 'spherekit-scratch-'));
  assert.ok(!path.relative(root, scratch).match(/^[^.]/), 'the scratch directory is outside the repository');
  const tarball = execFileSync('npm', ['pack', '--silent', '--pack-destination', scratch], { cwd: pkgDir, encoding: 'utf8' }).trim();
  await writeFile(path.join(scratch, 'package.json'), '{ "name": "scratch", "private": true, "type": "module" }\n');
  for (const guide of GUIDES) {
    for (const b of codeBlocks(await readFile(path.join(root, guide), 'utf8'))) blocks.push({ ...b, guide });
  }
  const installs = blocks.filter((b) => b.lang === 'sh');
  assert.ok(installs.length > 0, 'the guides say how to install the package');
  for (const b of installs) assert.equal(b.code, 'npm install spherekit\n', `${b.guide}:${b.line}: the install command`);
  // What `npm install spherekit` does, from the tarball instead of the registry.
  execFileSync('npm', ['install', '--offline', '--no-audit', '--no-fund', '--silent', path.join(scratch, tarball)], { cwd: scratch });
  installed = path.join(scratch, 'node_modules/spherekit');

  ({ server, origin } = await serve(scratch));
  browser = await chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    headless: true,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking', '--disable-component-update'],
  });
  await mkdir(outDir, { recursive: true });
});

after(async () => {
  await browser?.close();
  server?.close();
  if (scratch) rmSync(scratch, { recursive: true, force: true });
});

test('the tarball holds the package and nothing else', async () => {
  const manifest = JSON.parse(await readFile(path.join(installed, 'package.json'), 'utf8'));
  assert.equal(manifest.name, 'spherekit');
  assert.equal(manifest.type, 'module');
  assert.match(manifest.license, /MIT/);
  const files = (await readdir(installed)).sort();
  assert.deepEqual(files, [...manifest.files, 'package.json'].sort(), 'the installed files are the file list');
  for (const [entry, target] of Object.entries(manifest.exports)) {
    for (const file of typeof target === 'string' ? [target] : Object.values(target)) {
      assert.ok(existsSync(path.join(installed, file)), `exports["${entry}"]: ${file} is in the package`);
    }
  }
  assert.ok(!files.includes('presets.json'), "the playground's example menu stays out of the package");
});

test('the JavaScript blocks of the guides run under node against the installed package', async () => {
  const js = blocks.filter((b) => b.lang === 'js');
  assert.ok(js.length > 0, 'the guides have JavaScript blocks');
  for (const [k, b] of js.entries()) {
    const file = path.join(scratch, `block-${k}.mjs`);
    await writeFile(file, b.code);
    try {
      execFileSync(process.execPath, [file], { cwd: scratch, encoding: 'utf8', stdio: 'pipe' });
    } catch (e) {
      assert.fail(`${b.guide}:${b.line}: the block fails under node:\n${e.stderr}`);
    }
  }
});

test('the HTML blocks of the guides work as pages, and a widget draws the golden pixels', async () => {
  const html = blocks.filter((b) => b.lang === 'html');
  assert.ok(html.length > 0, 'the guides have HTML blocks');
  const goldens = new Map();
  for (const name of (await readdir(goldenDir)).filter((n) => n.endsWith('.json'))) {
    goldens.set(JSON.stringify(JSON.parse(await readFile(path.join(goldenDir, name), 'utf8'))), name.replace('.json', ''));
  }
  const report = [];
  for (const [k, b] of html.entries()) {
    const where = `${b.guide}:${b.line}`;
    // A snippet without <!doctype> is a fragment of a page: it goes into an empty one.
    const page = /^<!doctype html>/i.test(b.code) ? b.code : `<!doctype html>\n<meta charset="utf-8">\n${b.code}`;
    const name = `page-${k}.html`;
    await writeFile(path.join(scratch, name), page);
    const tab = await browser.newPage({ viewport: { width: 900, height: 800 }, deviceScaleFactor: 1 });
    const errors = [];
    tab.on('pageerror', (e) => errors.push(String(e)));
    tab.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
    tab.on('request', (r) => { if (!r.url().startsWith(origin)) externalRequests.push(r.url()); });
    await tab.goto(`${origin}/${name}`);
    // Every widget of the page (an element or a mount call) has drawn or shown its error.
    const expected = (b.code.match(/<spherekit-view/g) ?? []).length + (b.code.match(/\bmount\(/g) ?? []).length;
    assert.ok(expected > 0, `${where}: the page has a widget`);
    await tab.waitForFunction((n) => document.querySelectorAll('[data-state]').length >= n, expected, { timeout: 30000 });
    await tab.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const states = await tab.$$eval('[data-state]', (els) => els.map((e) => e.dataset.state));
    assert.deepEqual(states, Array(expected).fill('ready'), `${where}: every widget is ready`);
    assert.deepEqual(errors, [], `${where}: no page errors`);
    await tab.screenshot({ path: path.join(outDir, `package-${name.replace('.html', '.png')}`) });

    const views = await tab.$$eval('spherekit-view', (els) => els.map((e, i) => ({ i, scene: e.getAttribute('scene'), size: Number(e.getAttribute('size')) })));
    for (const v of views) {
      const golden = goldens.get(JSON.stringify(JSON.parse(v.scene)));
      if (!golden || v.size !== GOLDEN_SIZE) continue;
      const { width, height, base64 } = await tab.evaluate((i) => {
        const c = document.querySelectorAll('spherekit-view')[i].querySelector('.skv-stage canvas');
        const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
        let bytes = '';
        for (let j = 0; j < d.length; j += 0x8000) bytes += String.fromCharCode(...d.subarray(j, j + 0x8000));
        return { width: c.width, height: c.height, base64: btoa(bytes) };
      }, v.i);
      const png = PNG.sync.read(await readFile(path.join(goldenDir, `${golden}.png`)));
      assert.equal(width, png.width, `${where}: ${golden}: width`);
      assert.equal(height, png.height, `${where}: ${golden}: height`);
      const got = Buffer.from(base64, 'base64');
      let max = 0;
      for (let j = 0; j < got.length; j++) max = Math.max(max, Math.abs(got[j] - png.data[j]));
      assert.equal(max, 0, `${where}: ${golden}: the widget's pixels equal the golden PNG`);
      report.push(`${where}: ${golden} (${width}×${height}): the golden pixels`);
    }
    await tab.close();
  }
  assert.ok(report.length > 0, 'a guide page shows a golden scene at the golden size');
  console.log(report.join('\n'));
  assert.deepEqual(externalRequests, [], 'nothing is loaded from elsewhere');
});
