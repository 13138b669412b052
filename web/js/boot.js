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
import { $, state, query, showError, attempt, commit, controlOf, methodOf } from './state.js';
import { redraw, drawNow, pointOnCanvas, keyAxisOnScreen, plotX, frameTimes } from './view.js';
import { changed, compareWith, pageLink, pretty, renderPanels } from './panels.js';
import { installPointer, moveTimes } from './pointer.js';
import { installAnimation, setPlaying } from './animation.js';
import { FIRST, exampleGroups } from './examples.js';

/** Shows scene `text` (a new scene: t goes back to the start of its time axis, or to `t`, and
 * the zoom to 1, or to `zoom`, from a shared link). A failure shows its message beside
 * `anchor` (or over the stage) and keeps the last good scene. The new frame is drawn before
 * this returns, so the figure's layout is final at once (a click right after lands where it
 * aims). */
function loadScene(text, { anchor = null, t = null, zoom = 1 } = {}) {
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
    state.zoom = Math.min(2.5, Math.max(0.5, Number.isFinite(zoom) ? zoom : 1));
    setPlaying(false);
    state.axis = Array.from(state.pg.time_axis());
    state.t = Number.isFinite(t) ? Math.min(state.axis[1], Math.max(state.axis[0], t)) : state.axis[0];
    changed();
    drawNow();
  } else if (state.pg) {
    redraw();
  }
  return ok;
}

/** The link's fragment, `#t=…&zoom=…&scene=…` (t and zoom optional, the scene last):
 * `{ scene, t, zoom }`, or null without a scene. */
function linkFromHash() {
  const m = location.hash.match(/^#((?:[a-z]+=[^&]*&)*)scene=(.*)$/s);
  if (!m) return null;
  const opts = Object.fromEntries(m[1].split('&').filter(Boolean).map((kv) => kv.split('=')));
  let scene;
  try {
    scene = decodeURIComponent(m[2]);
  } catch {
    scene = m[2];
  }
  return { scene, t: opts.t === undefined ? null : Number(opts.t), zoom: opts.zoom === undefined ? 1 : Number(opts.zoom) };
}

/**
 * A new scene of the current space with the active curve's method: the fewest points it takes
 * (two at least), a quarter turn apart along a great circle (S³: turns about the z axis).
 */
function newScene() {
  const pg = state.pg;
  const space = pg.space();
  const curve = JSON.parse(pg.curve_json(Math.min(state.activeCurve, pg.curve_count() - 1)));
  const method = methodOf(curve.method);
  const n = Math.max(2, method?.min_points ?? 2);
  const points = [];
  for (let k = 0; k < n; k++) {
    const a = (k * Math.PI) / 4;
    if (space === 'S3') points.push([Math.cos(a / 2), 0, 0, Math.sin(a / 2)].map((x) => Number(x.toFixed(4))));
    else {
      const dim = curve.points[0].length;
      const p = new Array(dim).fill(0);
      p[0] = Number(Math.cos(a).toFixed(4));
      p[1] = Number(Math.sin(a).toFixed(4));
      points.push(p);
    }
  }
  return JSON.stringify({ space, method: curve.method, points });
}

/** The example menu: one group per method, readable names, the description on hover and below. */
function fillPresets() {
  const preset = $('preset');
  const custom = document.createElement('option');
  custom.value = '';
  custom.textContent = 'Your scene';
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
    const link = linkFromHash();
    if (link && link.scene !== state.pg.scene_json()) loadScene(link.scene, link);
  });
  $('new-scene').addEventListener('click', () => {
    const before = state.pg.scene_json();
    if (loadScene(newScene(), { anchor: $('new-scene').closest('.row') })) {
      commit(before);
      changed();
    }
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
      await navigator.clipboard.writeText(new URL(pageLink(), location.href).href);
      $('copy-link').textContent = 'Copied';
    } catch {
      $('copy-link').textContent = 'Link is in the address bar';
    }
    setTimeout(() => { $('copy-link').textContent = 'Copy link'; }, 1500);
  });
  $('add-curve').addEventListener('click', () => compareWith($('new-method').value));
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
  // The frame of ω is the scene's (view.omega_frame): the plot, the readout and the link follow.
  for (const radio of document.querySelectorAll('input[name=frame]')) {
    radio.addEventListener('change', () => {
      const value = radio.value === 'body' ? '"body"' : 'null';
      if (attempt(() => state.pg.set_view('omega_frame', value), { anchor: $('frame-choice') })) changed();
      else renderPanels();
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
  const link = linkFromHash();
  const fromHash = link?.scene;
  if (!fromHash || !loadScene(fromHash, link)) {
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
