// spherekit playground: the page around the wasm handle. No math here: picking, projection,
// rotations and rendering all happen in Rust (crates/spherekit-wasm).
import init, * as sk from './pkg/spherekit_wasm.js';
import { drawBodies } from './draw.js';

const $ = (id) => document.getElementById(id);
const params = new URLSearchParams(location.search);
/** A fixed render size (pixels) instead of fitting the window, e.g. ?size=384 for the golden. */
const fixedSize = params.has('size') ? Number(params.get('size')) : null;

const state = {
  pg: null,          // sk.Playground
  size: 0,           // render size in device pixels
  dpr: 1,
  selected: null,    // [curve, index]
  activeCurve: 0,    // the curve new points go to
  playing: false,
  u: 0,              // animation fraction of the domain
  methods: [],
  presets: [],
  frameMs: [],
};

function showError(message) {
  const el = $('error');
  el.textContent = message ? `error: ${message}` : '';
  el.hidden = !message;
}

/** Runs an edit of the handle; a failure shows its message and leaves the last good state. */
function attempt(edit) {
  try {
    edit();
    showError('');
    return true;
  } catch (e) {
    showError(e instanceof Error ? e.message : String(e));
    return false;
  }
}

// ---- sizing and drawing -------------------------------------------------------------------

function hasPlot() {
  const view = JSON.parse(state.pg.scene_json()).view ?? {};
  return view.plot ? view.plot === 'speed' : state.pg.space() === 'S3';
}

function fit() {
  const stage = $('stage');
  state.dpr = fixedSize ? 1 : window.devicePixelRatio || 1;
  if (fixedSize) {
    state.size = fixedSize;
    return;
  }
  const w = stage.clientWidth - 16;
  const h = window.innerHeight - stage.getBoundingClientRect().top - 24;
  const factor = hasPlot() ? 1.25 : 1;
  const css = Math.max(160, Math.min(w, h / factor));
  state.size = Math.min(4096, Math.floor(css * state.dpr));
}

let pending = false;
/** Redraws on the next animation frame (drags call this many times per frame). */
function redraw() {
  if (pending) return;
  pending = true;
  requestAnimationFrame(() => {
    pending = false;
    drawNow();
  });
}

function drawNow() {
  const canvas = $('scene');
  fit();
  try {
    state.pg.draw(canvas, state.size);
  } catch (e) {
    showError(e.message); // a drawing failure; a good draw leaves an edit's message alone
  }
  const css = (px) => `${px / state.dpr}px`;
  canvas.style.width = css(canvas.width);
  canvas.style.height = css(canvas.height);
  const overlay = $('overlay');
  overlay.width = canvas.width;
  overlay.height = canvas.height;
  overlay.style.width = canvas.style.width;
  overlay.style.height = canvas.style.height;
  drawOverlay();
}

/** The selection ring and the animated body or point, over the rendered image. */
function drawOverlay() {
  const ctx = $('overlay').getContext('2d');
  ctx.clearRect(0, 0, ctx.canvas.width, ctx.canvas.height);
  const pg = state.pg;
  const s = state.size;
  const k = s / 512;
  if (state.playing || state.u > 0) drawBodies(ctx, pg, state.u, s);
  const sel = selectedMarkers();
  for (const p of sel) {
    ctx.strokeStyle = '#e69f00';
    ctx.lineWidth = 3 * k;
    ctx.beginPath();
    ctx.arc(p[0], p[1], 11 * k, 0, 2 * Math.PI);
    ctx.stroke();
  }
}

/** Pixel positions of the selected point (S²) or of its key's axis tips (S³). */
function selectedMarkers() {
  if (!state.selected) return [];
  const [c, i] = state.selected;
  let p;
  try {
    p = state.pg.point(c, i);
  } catch {
    state.selected = null;
    return [];
  }
  const s = state.size;
  if (p.length === 4) {
    return [[1, 0, 0], [0, 1, 0], [0, 0, 1]].map((axis) => {
      const v = rotate(p, axis);
      return state.pg.project(v[0], v[1], v[2], s);
    });
  }
  const n = Math.hypot(...p) || 1;
  return [state.pg.project(p[0] / n, p[1] / n, (p[2] ?? 0) / n, s)];
}

function rotate(q, axis) {
  const v = sk.key_axes(new Float64Array(q));
  const a = axis[0] ? 0 : axis[1] ? 1 : 2;
  return [v[3 * a], v[3 * a + 1], v[3 * a + 2]];
}

// ---- scene changes --------------------------------------------------------------------------

/** After any successful change: panels, URL fragment, image. */
function changed({ panels = true } = {}) {
  const text = state.pg.scene_json();
  history.replaceState(null, '', `${location.pathname}${location.search}#scene=${encodeURIComponent(text)}`);
  if (document.activeElement !== $('json')) $('json').value = pretty(text);
  const preset = state.presets.find((p) => p.scene.trim() === text || sameScene(p.scene, text));
  $('preset').value = preset ? preset.name : '';
  if (panels) renderPanels();
  renderContinuity();
  redraw();
}

/** Indented JSON with each list of numbers on one line. */
function pretty(text) {
  return JSON.stringify(JSON.parse(text), null, 2)
    .replace(/\[\s*(-?[\d.e+-]+(?:,\s*-?[\d.e+-]+)*)\s*\]/g, (_, xs) => `[${xs.split(/,\s*/).join(', ')}]`);
}

function sameScene(a, b) {
  try {
    return JSON.stringify(JSON.parse(a)) === JSON.stringify(JSON.parse(b));
  } catch {
    return false;
  }
}

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

function renderPanels() {
  const pg = state.pg;
  const scene = JSON.parse(pg.scene_json());
  const space = pg.space();
  $('plot').checked = hasPlot();
  $('frames').checked = Boolean(scene.view?.frames);
  $('frames').disabled = space !== 'S3';
  // The renderer traces x, y and z for one S³ curve and x alone for several.
  const axes = scene.view?.axes ?? (pg.curve_count() > 1 ? ['x'] : ['x', 'y', 'z']);
  $('axes').hidden = space !== 'S3';
  for (const box of $('axes').querySelectorAll('input')) box.checked = axes.includes(box.value);

  const colors = JSON.parse(pg.colors());
  const box = $('curves');
  box.replaceChildren();
  for (let c = 0; c < pg.curve_count(); c++) {
    const curve = JSON.parse(pg.curve_json(c));
    const card = document.createElement('div');
    card.className = 'curve' + (c === state.activeCurve ? ' active' : '');
    const head = document.createElement('div');
    head.className = 'row';
    const swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = colors[c];
    swatch.title = `curve ${c}`;
    const select = methodSelect(space, curve.method);
    select.setAttribute('aria-label', `Method of curve ${c}`);
    select.addEventListener('change', () => {
      const fields = { ...curve, method: select.value };
      delete fields.points;
      delete fields.params; // parameters belong to the old method
      // Knots stay only where the new method takes as many (Catmull-Rom and Gamma take n − 2).
      const n = curve.points.length;
      if (KNOT_COUNT[select.value]?.(n) !== KNOT_COUNT[curve.method]?.(n)) delete fields.knots;
      if (attempt(() => pg.set_curve(c, JSON.stringify(fields)))) changed();
      else renderPanels();
    });
    head.append(swatch, select);
    if (pg.curve_count() > 1) {
      const remove = document.createElement('button');
      remove.type = 'button';
      remove.textContent = '✕';
      remove.title = `Remove curve ${c}`;
      remove.addEventListener('click', () => {
        if (attempt(() => pg.remove_curve(c))) {
          state.activeCurve = 0;
          state.selected = null;
          changed();
        }
      });
      head.append(remove);
    }
    card.append(head);
    card.addEventListener('pointerdown', () => {
      if (state.activeCurve !== c) {
        state.activeCurve = c;
        for (const el of box.children) el.classList.remove('active');
        card.classList.add('active');
      }
    });
    const summary = state.methods.find((m) => m.id === curve.method)?.summary ?? '';
    const p = document.createElement('p');
    p.className = 'muted';
    p.textContent = summary;
    card.append(p);
    card.append(...curveControls(c, curve, space));
    box.append(card);
  }
  const adder = $('new-method');
  const chosen = adder.value;
  adder.replaceWith(methodSelect(space, chosen || null, 'new-method'));
  $('new-method').setAttribute('aria-label', 'Method of the new curve');
  renderPointEditor();
}

// The controls of each method's parameters. The scene format (crates/spherekit/src/scene.rs)
// validates every value; this table only gives the controls' ranges and defaults.
// `perPoint(n)`: how many values a per-joint list has for n points; `first`: the index of its
// first entry in the sources' numbering (the Gamma paper's γ₁ … γₗ₋₁).
const PARAMS = {
  'catmull-rom': [{ name: 'tangent', choices: ['quaternion', 'intrinsic'], spaces: ['S3'] }],
  gamma: [
    { name: 'gamma', label: 'γ', min: 0.05, max: 4, value: 1, perPoint: (n) => n - 4, first: 1 },
    { name: 'last_edge', choices: ['formula', 'paper-example'] },
  ],
  beta: [
    { name: 'beta1', label: 'β₁ bias', min: 0.1, max: 4, value: 1, perPoint: (n) => n },
    { name: 'beta2', label: 'β₂ tension', min: 0, max: 20, value: 0, perPoint: (n) => n },
    { name: 'interpolate', bool: true, value: true },
    { name: 'solver', choices: ['newton', 'jacobi'] },
  ],
  'arc-blend': [{ name: 'order', label: 'order n', min: 1, max: 10, step: 1, value: 2 }],
  'corner-blend': [
    { name: 'order', label: 'order n', min: 1, max: 10, step: 1, value: 2 },
    { name: 'fraction', label: 'fraction', min: 0.02, max: 0.5, value: 0.25 },
  ],
};
/** Methods that take `knots`, and how many for n points. */
const KNOT_COUNT = { geodesic: (n) => n, nlerp: (n) => n, squad: (n) => n, 'catmull-rom': (n) => n - 2, gamma: (n) => n - 2 };

/** Sets a parameter (null removes it) and redraws; the panels follow unless `live`. */
function setParam(c, name, value, { live = false } = {}) {
  if (attempt(() => state.pg.set_param(c, name, JSON.stringify(value)))) changed({ panels: !live });
  else if (!live) renderPanels();
}

/** Replaces one field of curve `c` (null removes it), keeping its points and other fields. */
function setCurveField(c, curve, name, value) {
  const fields = { ...curve };
  delete fields.points;
  if (value === null) delete fields[name];
  else fields[name] = value;
  if (attempt(() => state.pg.set_curve(c, JSON.stringify(fields)))) changed();
}

/** The parameter controls of curve `c`: one per parameter of its method, knots, raw JSON. */
function curveControls(c, curve, space) {
  const controls = [];
  const params = curve.params ?? {};
  const n = curve.points.length;
  for (const spec of PARAMS[curve.method] ?? []) {
    if (spec.spaces && !spec.spaces.includes(space)) continue;
    const value = params[spec.name] ?? spec.value;
    if (spec.choices) {
      const label = document.createElement('label');
      label.className = 'row slider';
      const select = document.createElement('select');
      for (const ch of spec.choices) select.append(new Option(ch, ch));
      select.value = value ?? spec.choices[0];
      select.addEventListener('change', () => setParam(c, spec.name, select.value === spec.choices[0] ? null : select.value));
      label.append(`${spec.label ?? spec.name} `, select);
      controls.push(label);
    } else if (spec.bool) {
      const label = document.createElement('label');
      label.className = 'check';
      const box = document.createElement('input');
      box.type = 'checkbox';
      box.checked = value;
      box.addEventListener('change', () => setParam(c, spec.name, box.checked === spec.value ? null : box.checked));
      label.append(box, ` ${spec.name}`);
      controls.push(label);
    } else {
      const joints = spec.perPoint ? spec.perPoint(n) : 0;
      const list = Array.isArray(value) ? value : null;
      if (list) {
        list.forEach((v, k) => controls.push(slider(spec, `${spec.label} [${k + (spec.first ?? 0)}]`, v, (x, live) => {
          const next = list.slice();
          next[k] = x;
          setParam(c, spec.name, next, { live });
        })));
      } else {
        controls.push(slider(spec, spec.label, value, (x, live) => setParam(c, spec.name, x, { live })));
      }
      if (joints > 1 || list) {
        const label = document.createElement('label');
        label.className = 'check muted';
        const box = document.createElement('input');
        box.type = 'checkbox';
        box.checked = Boolean(list);
        box.addEventListener('change', () => setParam(c, spec.name, box.checked ? new Array(joints).fill(value) : list[0]));
        label.append(box, ` ${spec.label} per joint`);
        controls.push(label);
      }
    }
  }
  const knotCount = KNOT_COUNT[curve.method];
  if (knotCount) {
    const label = document.createElement('label');
    label.textContent = `knots (${knotCount(n)}, increasing; empty = 0, 1, 2, …) `;
    const input = document.createElement('input');
    input.className = 'params';
    input.spellcheck = false;
    input.value = (curve.knots ?? []).join(', ');
    input.placeholder = 'uniform';
    input.setAttribute('aria-label', `Knots of curve ${c}`);
    input.addEventListener('change', () => {
      const text = input.value.trim();
      setCurveField(c, curve, 'knots', text ? text.split(/[\s,]+/).filter(Boolean).map(Number) : null);
    });
    label.append(input);
    controls.push(label);
  }
  // Every parameter (solver tolerances too) as JSON.
  const details = document.createElement('details');
  const summary = document.createElement('summary');
  summary.className = 'muted';
  summary.textContent = 'params as JSON';
  const input = document.createElement('input');
  input.className = 'params';
  input.spellcheck = false;
  input.value = JSON.stringify(params);
  input.setAttribute('aria-label', `Parameters of curve ${c} (JSON)`);
  input.addEventListener('change', () => {
    let obj;
    try {
      obj = JSON.parse(input.value || '{}');
    } catch (e) {
      showError(`params: ${e.message}`);
      return;
    }
    setCurveField(c, curve, 'params', obj && typeof obj === 'object' && Object.keys(obj).length ? obj : null);
  });
  details.append(summary, input);
  controls.push(details);
  return controls;
}

/** A labelled range input; `set(value, live)` runs while dragging (live) and on release. */
function slider(spec, name, value, set) {
  const row = document.createElement('label');
  row.className = 'row slider';
  const range = document.createElement('input');
  range.type = 'range';
  range.min = String(Math.min(spec.min, value));
  range.max = String(Math.max(spec.max, value));
  range.step = String(spec.step ?? 'any');
  range.value = String(value);
  const out = document.createElement('output');
  const show = (v) => (spec.step === 1 ? String(v) : v.toFixed(3));
  out.textContent = show(value);
  range.addEventListener('input', () => {
    out.textContent = show(Number(range.value));
    set(Number(range.value), true);
  });
  range.addEventListener('change', () => set(Number(range.value), false));
  row.append(`${name} `, range, out);
  return row;
}

function methodSelect(space, value, id) {
  const select = document.createElement('select');
  if (id) select.id = id;
  for (const m of state.methods) {
    const opt = document.createElement('option');
    opt.value = m.id;
    const fits = m.spaces.split(', ').includes(space) || (m.spaces.includes('S<m>') && space !== 'S3' && space !== 'S2');
    opt.textContent = m.id;
    opt.disabled = !fits;
    opt.title = `${m.summary} — ${m.spaces}`;
    select.append(opt);
  }
  if (value) select.value = value;
  else {
    const first = [...select.options].find((o) => !o.disabled);
    if (first) select.value = first.value;
  }
  return select;
}

function renderPointEditor() {
  const box = $('point-editor');
  box.replaceChildren();
  if (!state.selected) {
    const p = document.createElement('p');
    p.className = 'muted';
    p.textContent = state.pg.space() === 'S3'
      ? 'Click an axis tip of a key to select it; drag to rotate it.'
      : 'Click a point to select it; drag to move it.';
    box.append(p);
    return;
  }
  const [c, i] = state.selected;
  const q = state.pg.point(c, i);
  const title = document.createElement('p');
  title.textContent = `curve ${c}, point ${i}`;
  box.append(title);
  const names = q.length === 4 ? ['w', 'x', 'y', 'z'] : q.length === 3 ? ['x', 'y', 'z'] : q.map((_, k) => `x${k}`);
  const inputs = names.map((n, k) => {
    const label = document.createElement('label');
    label.className = 'coord';
    const input = document.createElement('input');
    input.type = 'number';
    input.step = '0.01';
    input.value = String(Math.round(q[k] * 1e6) / 1e6);
    label.append(`${n} `, input);
    box.append(label);
    return input;
  });
  const apply = () => {
    const coords = inputs.map((el) => Number(el.value));
    if (attempt(() => state.pg.set_point(c, i, new Float64Array(coords)))) changed({ panels: false });
  };
  for (const el of inputs) el.addEventListener('change', apply);
  if (q.length === 4) {
    // Axis–angle editing of a key: angle in degrees about an axis.
    const aa = Array.from(sk.key_to_axis_angle(new Float64Array(q)));
    const row = document.createElement('div');
    row.className = 'axis-angle';
    const fields = ['angle°', 'ax', 'ay', 'az'].map((label, k) => {
      const l = document.createElement('label');
      l.className = 'coord';
      const input = document.createElement('input');
      input.type = 'number';
      input.step = k === 0 ? '1' : '0.05';
      input.value = String(Math.round(aa[k] * 1e4) / 1e4);
      l.append(`${label} `, input);
      row.append(l);
      return input;
    });
    const applyAA = () => {
      const [deg, x, y, z] = fields.map((el) => Number(el.value));
      if (attempt(() => state.pg.set_point(c, i, sk.axis_angle_to_key(deg, x, y, z)))) changed();
    };
    for (const el of fields) el.addEventListener('change', applyAA);
    const note = document.createElement('p');
    note.className = 'muted';
    note.textContent = 'Axis–angle (degrees):';
    box.append(note, row);
  }
  const del = document.createElement('button');
  del.type = 'button';
  del.textContent = 'Delete point';
  del.addEventListener('click', deleteSelected);
  box.append(del);
}

function deleteSelected() {
  if (!state.selected) return;
  const [c, i] = state.selected;
  if (attempt(() => state.pg.remove_point(c, i))) {
    state.selected = null;
    changed();
  }
}

function renderContinuity() {
  const box = $('continuity');
  box.replaceChildren();
  const report = JSON.parse(state.pg.continuity());
  const colors = JSON.parse(state.pg.colors());
  const table = document.createElement('table');
  const head = table.createTHead().insertRow();
  for (const h of ['', 't', '|ΔC⁰|', '|ΔC¹|', '|ΔC²|', 'class']) {
    const th = document.createElement('th');
    th.textContent = h;
    head.append(th);
  }
  const body = table.createTBody();
  report.forEach((joints, c) => {
    for (const j of joints) {
      const row = body.insertRow();
      const sw = document.createElement('span');
      sw.className = 'swatch';
      sw.style.background = colors[c];
      row.insertCell().append(sw);
      row.insertCell().textContent = fmt(j.t);
      row.insertCell().textContent = fmt(j.c0);
      row.insertCell().textContent = fmt(j.c1);
      row.insertCell().textContent = fmt(j.c2);
      row.insertCell().textContent = j.class;
    }
  });
  if (!body.rows.length) {
    const p = document.createElement('p');
    p.className = 'muted';
    p.textContent = 'No interior joints.';
    box.append(p);
  } else {
    box.append(table);
  }
}

function fmt(x) {
  if (x === 0) return '0';
  return Math.abs(x) < 1e-3 || Math.abs(x) >= 1e4 ? x.toExponential(1) : x.toFixed(3);
}

// ---- pointer interaction -----------------------------------------------------------------

function devicePoint(ev) {
  const r = $('overlay').getBoundingClientRect();
  const sx = $('overlay').width / r.width;
  return [(ev.clientX - r.left) * sx, (ev.clientY - r.top) * sx];
}

let drag = null;

function onDown(ev) {
  const [x, y] = devicePoint(ev);
  if (y > state.size) return; // the plot strip
  $('overlay').setPointerCapture(ev.pointerId);
  const hit = state.pg.pick(x, y, state.size, 12 * Math.max(1, state.size / 512));
  if (hit) {
    const [c, i] = hit;
    state.selected = [c, i];
    state.activeCurve = c;
    attempt(() => state.pg.pin_camera());
    drag = { kind: 'point', c, i, x0: x, y0: y, key0: state.pg.point(c, i), moved: false };
    renderPanels();
  } else {
    drag = { kind: 'view', x0: x, y0: y, camera0: state.pg.camera(), moved: false };
  }
  redraw();
}

function onMove(ev) {
  if (!drag) return;
  const [x, y] = devicePoint(ev);
  if (!drag.moved && Math.hypot(x - drag.x0, y - drag.y0) < 3) return;
  drag.moved = true;
  const pg = state.pg;
  let ok;
  if (drag.kind === 'view') {
    ok = attempt(() => pg.drag_view(new Float64Array(drag.camera0), drag.x0, drag.y0, x, y, state.size));
  } else if (drag.key0.length === 4) {
    ok = attempt(() => pg.drag_key(drag.c, drag.i, new Float64Array(drag.key0), drag.x0, drag.y0, x, y, state.size));
  } else {
    ok = attempt(() => pg.move_point_to(drag.c, drag.i, x, y, state.size));
  }
  if (ok) changed({ panels: false });
}

function onUp(ev) {
  if (!drag) return;
  const d = drag;
  drag = null;
  if (d.kind === 'point') {
    renderPanels();
    return;
  }
  if (!d.moved) {
    // A click on the sphere adds a point to the active curve.
    const [x, y] = devicePoint(ev);
    const c = Math.min(state.activeCurve, state.pg.curve_count() - 1);
    const r = 0.45 * state.size;
    if (Math.hypot(x - state.size / 2, y - state.size / 2) <= r && state.pg.space() !== 'S1') {
      const before = JSON.parse(state.pg.curve_json(c)).points.length;
      attempt(() => state.pg.pin_camera());
      if (attempt(() => state.pg.add_point_at(c, x, y, state.size))) {
        state.selected = [c, before];
        changed();
      }
    } else {
      state.selected = null;
      renderPanels();
      redraw();
    }
  }
}

// ---- animation -------------------------------------------------------------------------------

let lastTick = 0;
function tick(now) {
  if (!state.playing) return;
  const dt = lastTick ? (now - lastTick) / 1000 : 0;
  lastTick = now;
  state.u = (state.u + dt / 4) % 1;
  $('t').value = String(state.u);
  $('t-out').textContent = state.u.toFixed(3);
  drawOverlay();
  requestAnimationFrame(tick);
}

function setPlaying(on) {
  state.playing = on;
  $('play').textContent = on ? '■ Pause' : '▶ Play';
  lastTick = 0;
  if (on) requestAnimationFrame(tick);
}

// ---- benchmark (?bench) -----------------------------------------------------------------------

async function bench() {
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

// ---- start -----------------------------------------------------------------------------------

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

async function main() {
  await init();
  state.methods = JSON.parse(sk.methods());
  state.presets = JSON.parse(sk.presets());
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
  const fallback = state.presets.find((p) => p.name === 'geodesic_s3') ?? state.presets[0];

  const fromHash = sceneFromHash();
  if (!fromHash || !loadScene(fromHash)) {
    const error = $('error').textContent;
    loadScene(fallback.scene);
    if (fromHash) showError(error.replace(/^error: /, ''));
  }

  preset.addEventListener('change', () => {
    const p = state.presets.find((x) => x.name === preset.value);
    if (p) loadScene(p.scene);
  });
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
  $('play').addEventListener('click', () => setPlaying(!state.playing));
  $('t').addEventListener('input', () => {
    state.u = Number($('t').value);
    $('t-out').textContent = state.u.toFixed(3);
    drawOverlay();
  });
  const overlay = $('overlay');
  overlay.addEventListener('pointerdown', onDown);
  overlay.addEventListener('pointermove', onMove);
  overlay.addEventListener('pointerup', onUp);
  overlay.addEventListener('pointercancel', () => { drag = null; });
  window.addEventListener('keydown', (ev) => {
    if ((ev.key === 'Delete' || ev.key === 'Backspace') && !['INPUT', 'TEXTAREA', 'SELECT'].includes(document.activeElement?.tagName)) {
      deleteSelected();
    }
  });
  window.addEventListener('resize', redraw);

  // A small API for tests and the console.
  window.spherekitPage = {
    handle: () => state.pg,
    /** CSS-pixel position (relative to the viewport) of a point's marker (S²). */
    pointOnScreen(c, i) {
      const p = state.pg.point(c, i);
      const n = Math.hypot(...p);
      const q = state.pg.project(p[0] / n, p[1] / n, (p[2] ?? 0) / n, state.size);
      const r = $('scene').getBoundingClientRect();
      return [r.left + q[0] / state.dpr, r.top + q[1] / state.dpr];
    },
    /** CSS-pixel position of the tip of key (c, i)'s rotated z axis (S³). */
    keyTipOnScreen(c, i) {
      const v = sk.key_axes(new Float64Array(state.pg.point(c, i)));
      const q = state.pg.project(v[6], v[7], v[8], state.size);
      const r = $('scene').getBoundingClientRect();
      return [r.left + q[0] / state.dpr, r.top + q[1] / state.dpr];
    },
    size: () => state.size,
  };
  drawNow();
  document.body.dataset.ready = 'true';
  if (params.has('bench')) await bench();
}

main().catch((e) => {
  showError(e instanceof Error ? e.message : String(e));
  console.error(e);
});
