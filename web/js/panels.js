// The side panel: the view toggles, one card per curve (method, generated parameter controls),
// the point editor, the continuity table; and `changed()`, which every successful edit calls.
import * as sk from '../pkg/spherekit_wasm.js';
import { $, state, attempt, showError, inSpaces, methodOf } from './state.js';
import { hasPlot, redraw } from './view.js';
import { curveControls } from './controls.js';

/** After any successful change: panels, URL fragment, image. */
export function changed({ panels = true } = {}) {
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
  for (let c = 0; c < pg.curve_count(); c++) box.append(curveCard(c, colors[c], space));
  const adder = $('new-method');
  const chosen = adder.value;
  adder.replaceWith(methodSelect(space, chosen || null, 'new-method'));
  $('new-method').setAttribute('aria-label', 'Method of the new curve');
  renderPointEditor();
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
  select.addEventListener('change', () => {
    // Rust keeps the parameters and knots the new method can take.
    if (attempt(() => pg.set_method(c, select.value))) changed();
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
      for (const el of $('curves').children) el.classList.remove('active');
      card.classList.add('active');
    }
  });
  const p = document.createElement('p');
  p.className = 'muted';
  p.textContent = method?.summary ?? '';
  card.append(p);
  card.append(...curveControls(c, curve, space, method, {
    param: (name, value, opts) => setParam(c, name, value, opts),
    field: (name, value) => setCurveField(c, curve, { [name]: value }),
    fields: (changes) => setCurveField(c, curve, changes),
    error: showError,
  }));
  return card;
}

/** Sets a parameter (null removes it) and redraws; the panels follow unless `live`. */
function setParam(c, name, value, { live = false } = {}) {
  if (attempt(() => state.pg.set_param(c, name, JSON.stringify(value)))) changed({ panels: !live });
  else if (!live) renderPanels();
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
  if (attempt(() => state.pg.set_curve(c, JSON.stringify(fields)))) changed();
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

export function renderPointEditor() {
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

export function deleteSelected() {
  if (!state.selected) return;
  const [c, i] = state.selected;
  if (attempt(() => state.pg.remove_point(c, i))) {
    state.selected = null;
    changed();
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
