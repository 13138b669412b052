// The side panel: the view toggles, one card per curve (method, generated parameter controls),
// the point editor, the readout at t, the continuity table; `changed()`, which every
// successful edit calls; undo and redo.
import * as sk from '../pkg/spherekit_wasm.js';
import { $, state, attempt, commit, controlOf, hooks, parkNotice, placeNotice, showError, inSpaces, methodOf, updateHistoryButtons } from './state.js';
import { viewOptions, redraw, drawOverlay } from './view.js';
import { curveControls } from './controls.js';
import { aboutExample } from './examples.js';

/**
 * After any successful change: the time axis, the panels, URL fragment, JSON box, table and
 * image. `light` (while dragging or sliding) skips the URL, the JSON box and the table, which
 * follow when the gesture ends.
 */
export function changed({ panels = true, light = false } = {}) {
  syncTime();
  if (!light) {
    const text = state.pg.scene_json();
    history.replaceState(null, '', `${location.pathname}${location.search}#scene=${encodeURIComponent(text)}`);
    if (document.activeElement !== $('json')) $('json').value = pretty(text);
    const preset = state.presets.find((p) => p.scene.trim() === text || sameScene(p.scene, text));
    $('preset').value = preset ? preset.name : '';
    $('preset-about').textContent = preset ? aboutExample(state.groups, preset.name) : 'Your own scene (edited).';
    renderContinuity();
  }
  if (panels) renderPanels();
  if (light) readoutSoon();
  else renderReadout();
  updateHistoryButtons();
  redraw();
}

/** The readout while dragging: at most five times a second. */
let readoutTimer = 0;
function readoutSoon() {
  if (readoutTimer) return;
  readoutTimer = setTimeout(() => {
    readoutTimer = 0;
    renderReadout();
  }, 200);
}
hooks.changed = () => changed();

/** The scene's time axis after an edit (knots move it); t stays on it. */
function syncTime() {
  state.axis = Array.from(state.pg.time_axis());
  const [t0, t1] = state.axis;
  state.t = Math.min(t1, Math.max(t0, state.t));
  const slider = $('t');
  slider.min = String(t0);
  slider.max = String(t1);
  slider.value = String(state.t);
  $('t-out').textContent = `${state.axis[2] ? 'u' : 't'} = ${state.t.toFixed(3)}`;
}

/** Moves the page's one t: slider, readout, table row, plot cursor, moving bodies. */
export function setTime(t) {
  const [t0, t1] = state.axis;
  state.t = Math.min(t1, Math.max(t0, t));
  $('t').value = String(state.t);
  $('t-out').textContent = `${state.axis[2] ? 'u' : 't'} = ${state.t.toFixed(3)}`;
  renderReadout();
  drawOverlay();
}

/** Undo (`-1`) or redo (`+1`): the scene text before or after the edit, exactly. */
export function stepHistory(direction) {
  const from = direction < 0 ? state.undo : state.redo;
  const to = direction < 0 ? state.redo : state.undo;
  if (!from.length) return;
  const now = state.pg.scene_json();
  const text = from.pop();
  try {
    state.pg.set_scene(text);
  } catch (e) {
    showError(e.message);
    return;
  }
  to.push(now);
  showError('');
  if (state.selected) {
    try {
      state.pg.point(...state.selected);
    } catch {
      state.selected = null;
    }
  }
  changed();
}

/** Indented JSON with each list of numbers on one line. */
export function pretty(text) {
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

export function renderPanels() {
  parkNotice();
  const pg = state.pg;
  const space = pg.space();
  // The view as the renderer draws it, its defaults filled in.
  const view = viewOptions();
  $('plot').checked = view.plot !== 'none';
  $('frames').checked = view.frames > 0;
  $('legend').checked = view.legend;
  $('frames').disabled = space !== 'S3';
  const { axes } = view;
  $('axes').hidden = space !== 'S3';
  for (const box of $('axes').querySelectorAll('input')) box.checked = axes.includes(box.value);

  const colors = JSON.parse(pg.colors());
  const box = $('curves');
  box.replaceChildren();
  for (let c = 0; c < pg.curve_count(); c++) box.append(curveCard(c, colors[c], space));
  const adder = $('new-method');
  const chosen = adder.value;
  adder.replaceWith(methodSelect(space, chosen || null, 'new-method'));
  $('new-method').setAttribute('aria-label', 'Method of the new curve');
  $('frame-choice').hidden = space !== 'S3';
  renderPointEditor();
  placeNotice(); // a failed control's message goes back beside the redrawn control
}

function curveCard(c, color, space) {
  const pg = state.pg;
  const curve = JSON.parse(pg.curve_json(c));
  const method = methodOf(curve.method);
  const card = document.createElement('div');
  card.className = 'curve' + (c === state.activeCurve ? ' active' : '');
  const head = document.createElement('div');
  head.className = 'row';
  const swatch = document.createElement('span');
  swatch.className = 'swatch';
  swatch.style.background = color;
  swatch.title = `curve ${c}`;
  const select = methodSelect(space, curve.method);
  select.setAttribute('aria-label', `Method of curve ${c}`);
  head.dataset.key = `c${c}-method`;
  select.addEventListener('change', () => {
    // Rust keeps the parameters and knots the new method can take.
    if (attempt(() => pg.set_method(c, select.value), { anchor: head })) changed();
    else renderPanels();
  });
  head.append(swatch, select);
  if (pg.curve_count() > 1) {
    const remove = document.createElement('button');
    remove.type = 'button';
    remove.textContent = '✕';
    remove.title = `Remove curve ${c}`;
    remove.addEventListener('click', () => {
      if (attempt(() => pg.remove_curve(c), { anchor: head })) {
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
      for (const el of $('curves').children) el.classList.remove('active');
      card.classList.add('active');
    }
  });
  const p = document.createElement('p');
  p.className = 'muted';
  p.textContent = method?.summary ?? '';
  card.append(p);
  const controls = curveControls(c, curve, space, method, {
    param: (name, value, opts) => setParam(c, name, value, opts),
    field: (name, value) => setCurveField(c, curve, { [name]: value }),
    fields: (changes) => setCurveField(c, curve, changes),
    error: (message) => showError(message, { anchor: eventControl() }),
  });
  // Keys find a control again after the panel is redrawn (the notice goes back beside it).
  controls.forEach((el, k) => { el.dataset.key = `c${c}-${k}`; });
  card.append(...controls);
  return card;
}

/** The panel control of the event being handled (the one the user acted on), or null. */
function eventControl() {
  return controlOf(window.event?.target ?? document.activeElement);
}

/** The scene before a live slider move began (recorded for undo when it is released). */
let liveBefore = null;

/** Sets a parameter (null removes it) and redraws; the panels follow unless `live`. A value
 * the curve cannot take leaves the control where it is, marked, with the message beside it. */
function setParam(c, name, value, { live = false } = {}) {
  const anchor = eventControl();
  if (liveBefore === null) liveBefore = state.pg.scene_json();
  const before = liveBefore;
  const ok = attempt(() => state.pg.set_param(c, name, JSON.stringify(value)), { anchor, record: false });
  if (!live) {
    liveBefore = null;
    commit(before);
  }
  if (ok) changed({ panels: !live, light: live });
}

/** Replaces fields of curve `c` (`{ name: value }`, null removes one), keeping its points and
 * other fields. */
function setCurveField(c, curve, changes) {
  const fields = { ...curve };
  delete fields.points;
  for (const [name, value] of Object.entries(changes)) {
    if (value === null) delete fields[name];
    else fields[name] = value;
  }
  if (attempt(() => state.pg.set_curve(c, JSON.stringify(fields)), { anchor: eventControl() })) changed();
}

/** A select of every method, those the space cannot take disabled. */
function methodSelect(space, value, id) {
  const select = document.createElement('select');
  if (id) select.id = id;
  for (const m of state.methods) {
    const opt = document.createElement('option');
    opt.value = m.id;
    opt.textContent = m.id;
    opt.disabled = !inSpaces(m.spaces, space);
    opt.title = `${m.summary} — ${m.spaces.join(', ')}`;
    select.append(opt);
  }
  if (value) select.value = value;
  else {
    const first = [...select.options].find((o) => !o.disabled);
    if (first) select.value = first.value;
  }
  return select;
}

export function renderPointEditor() {
  parkNotice();
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
    if (attempt(() => state.pg.set_point(c, i, new Float64Array(coords)), { anchor: eventControl() })) changed({ panels: false });
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
      if (attempt(() => state.pg.set_point(c, i, sk.axis_angle_to_key(deg, x, y, z)), { anchor: eventControl() })) changed();
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

export function deleteSelected() {
  if (!state.selected) return;
  const [c, i] = state.selected;
  // From the keyboard or the button: the message goes beside the point editor's button.
  if (attempt(() => state.pg.remove_point(c, i), { anchor: $('point-editor').querySelector('button') })) {
    state.selected = null;
    changed();
  }
}

/** The readout at the page's t: per curve its own t, the point or quaternion, the speed, and
 * on S³ ω and α in the chosen frame (Rust's `readout`). */
export function renderReadout() {
  const pg = state.pg;
  const colors = JSON.parse(pg.colors());
  const s3 = pg.space() === 'S3';
  const box = $('readout');
  box.replaceChildren();
  state.readouts = [];
  for (let c = 0; c < pg.curve_count(); c++) {
    const r = JSON.parse(pg.readout(c, state.t, state.frame));
    state.readouts.push(r);
    const block = document.createElement('div');
    block.className = 'curve-at';
    const sw = document.createElement('span');
    sw.className = 'swatch';
    sw.style.background = colors[c];
    const head = document.createElement('b');
    head.textContent = `t = ${r.t.toFixed(3)}`;
    block.append(sw, head);
    const line = (name, value) => {
      const k = document.createElement('span');
      k.textContent = name;
      const v = document.createElement('span');
      v.className = 'num';
      v.textContent = value;
      block.append(k, v);
    };
    line(s3 ? 'q (w,x,y,z)' : 'point', vec(r.point));
    line(s3 ? '|ω| rad/t' : 'speed', num(r.speed));
    if (r.omega) {
      line(`ω ${state.frame}`, vec(r.omega));
      line(`α ${state.frame}`, vec(r.alpha));
    }
    box.append(block);
  }
  markJointRows();
}

const num = (x) => (Number.isFinite(x) ? (x < 0 ? '' : ' ') + x.toFixed(3) : String(x));
const vec = (v) => `(${Array.from(v, num).join(', ')})`;

/** Marks the continuity table's rows at the current t of their curve. */
function markJointRows() {
  const span = state.axis[1] - state.axis[0] || 1;
  for (const row of $('continuity').querySelectorAll('tbody tr')) {
    const r = state.readouts?.[Number(row.dataset.curve)];
    row.classList.toggle('now', Boolean(r) && Math.abs(Number(row.dataset.t) - r.t) <= 0.005 * span);
  }
}

/** The continuity report per joint; the class is Rust's (`C⁰`, `G¹`, `C¹`, … `Cⁿ`, `broken`). */
export function renderContinuity() {
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
      row.dataset.curve = String(c);
      row.dataset.t = String(j.t);
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
    markJointRows();
  }
}

function fmt(x) {
  if (x === 0) return '0';
  return Math.abs(x) < 1e-3 || Math.abs(x) >= 1e4 ? x.toExponential(1) : x.toFixed(3);
}
