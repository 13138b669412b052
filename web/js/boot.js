// spherekit playground: the page's one module entry. Loads the wasm, the method registry and
// the example scenes, loads the scene of the URL fragment (or an example), wires the scene
// panel's buttons, and with ?bench loads and runs the benchmark. No math on the page: picking,
// projection, rotations and rendering all happen in Rust (crates/spherekit-wasm).
//
//   state.js      the shared state, error display, registry look-ups
//   view.js       sizing, drawing, the overlay
//   panels.js     curve cards, point editor, continuity table; changed() after every edit
//   controls.js   the parameter controls, generated from the registry
//   pointer.js    drag, pick, click to add, Delete
//   animation.js  play and the t slider
//   bench.js      ?bench only
import init, * as sk from '../pkg/spherekit_wasm.js';
import { $, state, query, showError, attempt } from './state.js';
import { redraw, drawNow, pointOnCanvas, keyAxisOnScreen } from './view.js';
import { changed, pretty, renderPanels } from './panels.js';
import { installPointer } from './pointer.js';
import { installAnimation } from './animation.js';

function loadScene(text, { keepOnError = true } = {}) {
  let ok;
  if (!state.pg) {
    try {
      state.pg = new sk.Playground(text);
      ok = true;
      showError('');
    } catch (e) {
      showError(e.message);
      ok = false;
    }
  } else {
    ok = attempt(() => state.pg.set_scene(text));
  }
  if (ok) {
    state.selected = null;
    state.activeCurve = 0;
    state.u = 0;
    changed();
  } else if (keepOnError && state.pg) {
    redraw();
  }
  return ok;
}

function sceneFromHash() {
  const m = location.hash.match(/^#scene=(.*)$/s);
  if (!m) return null;
  try {
    return decodeURIComponent(m[1]);
  } catch {
    return m[1];
  }
}

/** A golden scene's file name as a menu label: `arc_blend_s2_fig_8_3` → `arc blend on S² (fig. 8.3)`. */
function presetLabel(name) {
  return name
    .replace(/_s([123])(?=_|$)/g, (_, d) => ` on S${'¹²³'[d - 1]}`)
    .replace(/_fig_(\d+)_(\d+)/, ' (fig. $1.$2)')
    .replace(/example(\d)/, 'example $1')
    .replaceAll('_', ' ');
}

function fillPresets() {
  const preset = $('preset');
  const custom = document.createElement('option');
  custom.value = '';
  custom.textContent = '(your scene)';
  custom.disabled = true;
  preset.append(custom);
  for (const p of state.presets) {
    const opt = document.createElement('option');
    opt.value = p.name;
    opt.textContent = presetLabel(p.name);
    preset.append(opt);
  }
  preset.addEventListener('change', () => {
    const p = state.presets.find((x) => x.name === preset.value);
    if (p) loadScene(p.scene);
  });
}

/** The Scene section: JSON box, download, link, view toggles, the curve adder. */
function installScenePanel() {
  window.addEventListener('hashchange', () => {
    const text = sceneFromHash();
    if (text && text !== state.pg.scene_json()) loadScene(text);
  });
  $('apply-json').addEventListener('click', () => loadScene($('json').value));
  $('download').addEventListener('click', () => {
    const blob = new Blob([pretty(state.pg.scene_json()) + '\n'], { type: 'application/json' });
    const a = document.createElement('a');
    a.href = URL.createObjectURL(blob);
    a.download = 'scene.json';
    a.click();
    URL.revokeObjectURL(a.href);
  });
  $('copy-link').addEventListener('click', async () => {
    try {
      await navigator.clipboard.writeText(location.href);
      $('copy-link').textContent = 'Copied';
    } catch {
      $('copy-link').textContent = 'Link is in the address bar';
    }
    setTimeout(() => { $('copy-link').textContent = 'Copy link'; }, 1500);
  });
  $('add-curve').addEventListener('click', () => {
    if (attempt(() => state.pg.add_curve($('new-method').value))) {
      state.activeCurve = state.pg.curve_count() - 1;
      changed();
    }
  });
  $('plot').addEventListener('change', () => {
    if (attempt(() => state.pg.set_view('plot', JSON.stringify($('plot').checked ? 'speed' : 'none')))) changed();
  });
  $('axes').addEventListener('change', () => {
    const axes = [...$('axes').querySelectorAll('input:checked')].map((b) => b.value);
    if (axes.length === 0) {
      renderPanels(); // at least one axis
      return;
    }
    if (attempt(() => state.pg.set_view('axes', JSON.stringify(axes)))) changed();
  });
  $('frames').addEventListener('change', () => {
    if (attempt(() => state.pg.set_view('frames', $('frames').checked ? '7' : 'null'))) changed();
  });
  window.addEventListener('resize', redraw);
}

/** CSS-pixel position (relative to the viewport) of a device-pixel position on the canvas. */
function toViewport(q) {
  const r = $('scene').getBoundingClientRect();
  return [r.left + q[0] / state.dpr, r.top + q[1] / state.dpr];
}

async function main() {
  await init();
  state.methods = JSON.parse(sk.methods());
  state.presets = JSON.parse(sk.presets());
  fillPresets();
  const fallback = state.presets.find((p) => p.name === 'geodesic_s3') ?? state.presets[0];
  const fromHash = sceneFromHash();
  if (!fromHash || !loadScene(fromHash)) {
    const error = $('error').textContent;
    loadScene(fallback.scene);
    if (fromHash) showError(error.replace(/^error: /, ''));
  }
  installScenePanel();
  installAnimation();
  installPointer();

  // A small API for tests and the console.
  window.spherekitPage = {
    handle: () => state.pg,
    /** CSS-pixel position (relative to the viewport) of a point's marker (S²). */
    pointOnScreen: (c, i) => toViewport(pointOnCanvas(state.pg.point(c, i))),
    /** CSS-pixel position of the tip of key (c, i)'s rotated z axis (S³). */
    keyTipOnScreen: (c, i) => toViewport(keyAxisOnScreen(state.pg.point(c, i), 2)),
    size: () => state.size,
  };
  drawNow();
  document.body.dataset.ready = 'true';
  if (query.has('bench')) await (await import('./bench.js')).bench();
}

main().catch((e) => {
  showError(e instanceof Error ? e.message : String(e));
  console.error(e);
});
