// Frame-time benchmark of the playground in Debian's headless Chromium: opens index.html?bench
// (20 keys on S³, 4 000 samples, 800 × 800; see web/js/bench.js) and prints what the page
// reports. Needs `just web` first; run with `just bench-web`. Figures go to BENCHMARKS.md.
import { createServer } from 'node:http';
import { readFile } from 'node:fs/promises';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const webDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../web');
const MIME = { '.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css', '.wasm': 'application/wasm' };

const server = createServer(async (req, res) => {
  const rel = new URL(req.url, 'http://x').pathname;
  const file = path.join(webDir, path.normalize(rel === '/' ? '/index.html' : rel));
  try {
    const body = await readFile(file);
    res.writeHead(200, { 'content-type': MIME[path.extname(file)] ?? 'application/octet-stream' });
    res.end(body);
  } catch {
    res.writeHead(404).end();
  }
});
await new Promise((r) => server.listen(0, '127.0.0.1', r));
const userDataDir = mkdtempSync(path.join(tmpdir(), 'spherekit-bench-'));
const browser = await chromium.launchPersistentContext(userDataDir, {
  executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
  headless: true,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});
try {
  const page = await browser.newPage();
  await page.goto(`http://127.0.0.1:${server.address().port}/index.html?bench`);
  await page.waitForFunction(() => window.spherekitBench, null, { timeout: 300000 });
  console.log(JSON.stringify(await page.evaluate(() => window.spherekitBench), null, 2));
} finally {
  await browser.close();
  server.close();
  rmSync(userDataDir, { recursive: true, force: true });
}
