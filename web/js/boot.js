// spherekit playground: the page's one module entry. Loads the wasm, the method registry and
// the example scenes, loads the scene of the URL fragment (or an example), wires the scene
// panel's buttons, and with ?bench loads and runs the benchmark. No math on the page: picking,
// projection, rotations and rendering all happen in Rust (crates/spherekit-wasm).
//
//   state.js      the shared state, the error notice, undo records, registry look-ups
//   view.js       sizing, drawing (reduced resolution while dragging), the overlay
//   panels.js     curve cards, point editor, readout, continuity table; changed() after
//                 every edit; undo and redo
//   controls.js   the parameter controls, generated from the registry
//   examples.js   the example menu: groups, names, descriptions
//   pointer.js    drag, pick, hover, click to add, plot scrubbing, zoom, keyboard
//   animation.js  play and the t slider
//   bench.js      ?bench only
import init, * as sk from '../pkg/spherekit_wasm.js';
import { $, state, query, showError, attempt, controlOf, methodOf } from './state.js';
import { redraw, drawNow, pointOnCanvas, keyAxisOnScreen, plotX, frameTimes } from './view.js';
import { changed, pretty, renderPanels, setTime } from './panels.js';
import { installPointer, moveTimes } from './pointer.js';
import { installAnimation, setPlaying } from './animation.js';
import { FIRST, exampleGroups } from './examples.js';

/** Shows scene `text` (a new scene: t goes back to the start of its time axis). A failure
 * shows its message beside `anchor` (or over the stage) and keeps the last good scene. */
function loadScene(text, { anchor = null } = {}) {
  let ok;
  if (!state.pg) {
    try {
      state.pg = new sk.Playground(text);
      ok = true;
      showError('');
    } catch (e) {
      showError(e.message, { anchor });
      ok = false;
    }
  } else {
    ok = attempt(() => state.pg.set_scene(text), { anchor });
  }
  if (ok) {
    state.selected = null;
    state.hover = null;
    state.activeCurve = 0;
    state.zoom = 1;
    setPlaying(false);
    state.axis = Array.from(state.pg.time_axis());
    state.t = state.axis[0];
    changed();
  } else if (state.pg) {
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

/** The example menu: one group per method, readable names, the description on hover and below. */
function fillPresets() {
  const preset = $('preset');
  const custom = document.createElement('option');
  custom.value = '';
  custom.textContent = '(your scene)';
  custom.disabled = true;
  preset.append(custom);
  state.groups = exampleGroups(state.presets, methodOf);
  for (const g of state.groups) {
    const group = document.createElement('optgroup');
    group.label = g.group;
    for (const it of g.items) {
      const opt = new Option(it.label, it.name);
      opt.title = it.about;
      group.append(opt);
    }
    preset.append(group);
  }
  preset.addEventListener('change', () => {
    const p = state.presets.find((x) => x.name === preset.value);
    if (p) loadScene(p.scene, { anchor: preset.closest('label') });
  });
}

/** The Scene section: JSON box, download, link, view toggles, the curve adder. */
function installScenePanel() {
  window.addEventListener('hashchange', () => {
    const text = sceneFromHash();
    if (text && text !== state.pg.scene_json()) loadScene(text);
  });
  $('apply-json').addEventListener('click', () => loadScene($('json').value, { anchor: $('json-actions') }));
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
    if (attempt(() => state.pg.add_curve($('new-method').value), { anchor: $('add-curve').closest('.row') })) {
      state.activeCurve = state.pg.curve_count() - 1;
      changed();
    }
  });
  $('plot').addEventListener('change', () => {
    if (attempt(() => state.pg.set_view('plot', JSON.stringify($('plot').checked ? 'speed' : 'none')), { anchor: controlOf($('plot')) })) changed();
  });
  $('legend').addEventListener('change', () => {
    if (attempt(() => state.pg.set_view('legend', JSON.stringify($('legend').checked)), { anchor: controlOf($('legend')) })) changed();
  });
  $('axes').addEventListener('change', () => {
    const axes = [...$('axes').querySelectorAll('input:checked')].map((b) => b.value);
    if (axes.length === 0) {
      renderPanels(); // at least one axis
      return;
    }
    if (attempt(() => state.pg.set_view('axes', JSON.stringify(axes)), { anchor: $('axes') })) changed();
  });
  $('frames').addEventListener('change', () => {
    if (attempt(() => state.pg.set_view('frames', $('frames').checked ? '7' : 'null'), { anchor: controlOf($('frames')) })) changed();
  });
  for (const radio of document.querySelectorAll('input[name=frame]')) {
    radio.addEventListener('change', () => {
      state.frame = radio.value;
      setTime(state.t);
    });
  }
  window.addEventListener('resize', () => redraw());
}

/** CSS-pixel position (relative to the viewport) of a device-pixel position on the canvas. */
function toViewport(q) {
  const overlay = $('overlay');
  const r = overlay.getBoundingClientRect();
  const k = r.width / overlay.width;
  return [r.left + q[0] * k, r.top + q[1] * k];
}

async function main() {
  await init();
  state.methods = JSON.parse(sk.methods());
  // The golden scenes, written next to the wasm package by `just web` (scripts/web_presets.py).
  const presets = await fetch(new URL('../pkg/presets.json', import.meta.url));
  if (!presets.ok) throw new Error(`pkg/presets.json: HTTP ${presets.status} (run \`just web\`)`);
  state.presets = await presets.json();
  fillPresets();
  const fallback = state.presets.find((p) => p.name === FIRST) ?? state.presets[0];
  const fromHash = sceneFromHash();
  if (!fromHash || !loadScene(fromHash)) {
    const error = $('error').textContent;
    loadScene(fallback.scene);
    if (fromHash) showError(error.replace(/^error: /, ''));
  }
  state.undo.length = 0; // the first scene is where history starts
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
    /** CSS-pixel position of time `t` on plot `k`'s time axis (its vertical middle), or null. */
    plotPointOnScreen: (t, k = 0) => {
      const p = state.plots?.[k];
      return p ? toViewport([plotX(p, t), (p.top + p.bottom) / 2]) : null;
    },
    size: () => state.size,
    t: () => state.t,
    axis: () => state.axis.slice(),
    zoom: () => state.zoom,
    readouts: () => state.readouts,
    moveTimes: () => moveTimes.slice(),
    frameTimes: () => frameTimes.slice(),
    /** A CSS-pixel position on the sphere where no point or key can be picked (to turn the view). */
    emptySpot: () => {
      const s = state.size;
      for (let k = 0; k < 400; k++) {
        const a = k * 2.399;
        const r = 0.05 + 0.3 * ((k * 0.618) % 1);
        const x = s / 2 + r * s * Math.cos(a);
        const y = s / 2 + r * s * Math.sin(a);
        if (!state.pg.pick(x, y, s, 40 * Math.max(1, s / 512))) return toViewport([x, y]);
      }
      return toViewport([s / 2, s / 2]);
    },
  };
  drawNow();
  document.body.dataset.ready = 'true';
  if (query.has('bench')) await (await import('./bench.js')).bench();
}

main().catch((e) => {
  showError(e instanceof Error ? e.message : String(e));
  console.error(e);
});
