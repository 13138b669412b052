// Completes the npm package that `wasm-pack build` wrote (the wasm, its JS glue and their
// TypeScript declarations, package.json, the crate's README): adds the docs widget
// (crates/spherekit-wasm/js: widget.js, draw.js, widget.d.ts) and the licence texts, and gives
// package.json the npm name, the file list and the `exports` map. The justfile's `web` runs it.
//
//   node scripts/npm_package.mjs web/pkg
import { copyFileSync, existsSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const out = path.resolve(process.argv[2] ?? path.join(root, 'web/pkg'));
const manifest = path.join(out, 'package.json');
if (!existsSync(manifest)) throw new Error(`${manifest}: missing (run wasm-pack build first)`);
const generated = JSON.parse(readFileSync(manifest, 'utf8'));

const copies = [
  ['crates/spherekit-wasm/js/widget.js', 'widget.js'],
  ['crates/spherekit-wasm/js/widget.d.ts', 'widget.d.ts'],
  ['crates/spherekit-wasm/js/draw.js', 'draw.js'],
  ['LICENSE-APACHE', 'LICENSE-APACHE'],
  ['LICENSE-MIT', 'LICENSE-MIT'],
];
for (const [from, to] of copies) copyFileSync(path.join(root, from), path.join(out, to));

const glue = 'spherekit_wasm';
const files = [
  `${glue}_bg.wasm`, `${glue}_bg.wasm.d.ts`, `${glue}.js`, `${glue}.d.ts`,
  'widget.js', 'widget.d.ts', 'draw.js', 'README.md', 'LICENSE-APACHE', 'LICENSE-MIT',
];
for (const f of files) if (!existsSync(path.join(out, f))) throw new Error(`${path.join(out, f)}: missing`);

const pkg = {
  name: 'spherekit',
  version: generated.version,
  description: 'Spline curves on spheres in WebAssembly: the <spherekit-view> widget, and scenes sampled, checked and rendered in the browser.',
  license: generated.license,
  repository: generated.repository,
  homepage: 'https://github.com/spherekit/spherekit/blob/main/docs/web.md',
  keywords: ['spline', 'sphere', 'quaternion', 'rotation', 'slerp', 'webassembly', 'web-component'],
  type: 'module',
  files,
  main: `${glue}.js`,
  types: `${glue}.d.ts`,
  exports: {
    '.': { types: `./${glue}.d.ts`, default: `./${glue}.js` },
    './widget': { types: './widget.d.ts', default: './widget.js' },
    './widget.js': { types: './widget.d.ts', default: './widget.js' },
    [`./${glue}_bg.wasm`]: `./${glue}_bg.wasm`,
    './package.json': './package.json',
  },
  // widget.js defines the custom element when imported.
  sideEffects: ['./widget.js'],
};
writeFileSync(manifest, `${JSON.stringify(pkg, null, 2)}\n`);
console.log(`npm package ${pkg.name}@${pkg.version} in ${path.relative(root, out) || '.'}: ${files.length} files`);
