// The side panel: the view toggles, one card per curve (method, generated parameter controls),
// the point editor, the readout at t, the continuity table; `changed()`, which every
// successful edit calls; undo and redo.
import * as sk from '../pkg/spherekit_wasm.js';
import { $, state, attempt, commit, controlOf, hooks, parkNotice, placeNotice, showError, inSpaces, methodOf, updateHistoryButtons } from './state.js';
import { viewOptions, redraw, drawOverlay } from './view.js';
import { curveControls, knotsFor } from './controls.js';
import { aboutExample } from './examples.js';
import { sharing, setKey, removeKey } from './keys.js';
import { fitControls, updateFitReadouts } from './fit.js';

/** A note a curve card shows after an edit (what became of the knots), until the next edit. */
let cardNote = null;

/** The page's address for the current scene, t and zoom (`#t=…&zoom=…&scene=…`; the scene
 * last, as boot.js reads it). */
export function pageLink() {
  const t = state.t === state.axis[0] ? '' : `t=${Number(state.t.toPrecision(6))}&`;
  const zoom = state.zoom === 1 ? '' : `zoom=${Number(state.zoom.toPrecision(4))}&`;
  return `${location.pathname}${location.search}#${t}${zoom}scene=${encodeURIComponent(state.pg.scene_json())}`;
}

/** Puts t and zoom into the address soon (not on every animation frame). */
let linkTimer = 0;
export function linkSoon() {
  clearTimeout(linkTimer);
  linkTimer = setTimeout(() => history.replaceState(null, '', pageLink()), 300);
}

/**
 * After any successful change: the time axis, the panels, URL fragment, JSON box, table and
 * image. `light` (while dragging or sliding) skips the URL, the JSON box and the table, which
 * follow when the gesture ends.
 */
export function changed({ panels = true, light = false } = {}) {
  syncTime();
  if (!light) {
    const text = state.pg.scene_json();
    history.replaceState(null, '', pageLink());
    if (document.activeElement !== $('json')) $('json').value = pretty(text);
    const preset = state.presets.find((p) => p.scene.trim() === text || sameScene(p.scene, text));
    $('preset').value = preset ? preset.name : '';
    $('preset-about').textContent = preset ? aboutExample(state.groups, preset.name) : 'Your own scene: an edited example, a shared link or a pasted scene.';
    renderContinuity();
  }
  if (panels) renderPanels();
  else updateFitReadouts(state.pg);
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
  if (!state.playing) linkSoon();
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

/** Whether the panels are being redrawn (a control removed while it has focus may fire its
 * change event again, in the middle of the redraw: that redraw is this one). */
let rendering = false;

export function renderPanels() {
  if (rendering) return;
  rendering = true;
  try {
    drawPanels();
  } finally {
    rendering = false;
  }
}

function drawPanels() {
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
  cardNote = null;
  const adder = $('new-method');
  const chosen = adder.value;
  adder.replaceWith(methodSelect(space, chosen || null, 'new-method'));
  $('new-method').setAttribute('aria-label', 'Method to compare with');
  $('frame-choice').hidden = space !== 'S3';
  for (const radio of document.querySelectorAll('input[name=frame]')) radio.checked = radio.value === view.omega_frame;
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
  swatch.title = `curve ${c + 1}`;
  const select = methodSelect(space, curve.method);
  select.setAttribute('aria-label', `Method of curve ${c + 1}`);
  head.dataset.key = `c${c}-method`;
  select.addEventListener('change', () => {
    // Rust keeps the parameters and knots the new method can take; a legend label that was
    // the old method's name follows the method.
    const relabel = curve.label !== undefined && curve.label === method?.name;
    if (attempt(() => {
      pg.set_method(c, select.value);
      if (relabel) {
        const fields = JSON.parse(pg.curve_json(c));
        delete fields.points;
        fields.label = methodOf(select.value)?.name ?? select.value;
        pg.set_curve(c, JSON.stringify(fields));
      }
    }, { anchor: head })) changed();
    else renderPanels();
  });
  head.append(swatch, select);
  if (pg.curve_count() > 1) {
    const remove = document.createElement('button');
    remove.type = 'button';
    remove.textContent = '✕';
    remove.title = `Remove curve ${c + 1}`;
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
      drawOverlay(); // its ω arrow
    }
  });
  const p = document.createElement('p');
  p.className = 'muted';
  p.textContent = method?.summary ?? '';
  card.append(p);
  const shared = sharing(c).length - 1;
  if (shared) {
    const q = document.createElement('p');
    q.className = 'muted';
    q.textContent = `Shares its keys with ${shared === 1 ? 'another curve' : `${shared} other curves`}: moving, adding or deleting a key changes them all.`;
    card.append(q);
  }
  const fitting = fitControls(pg, c, curve, method, {
    fit: (fit, opts) => setFit(c, curve, fit, opts),
    fields: (changes, note) => setCurveField(c, curve, changes, note),
  });
  fitting.forEach((el, k) => { el.dataset.key = `c${c}-fit${k}`; });
  if (fitting.length) {
    const box = document.createElement('div');
    box.className = 'fit';
    box.append(...fitting);
    card.append(box);
  }
  const controls = curveControls(c, curve, space, method, {
    param: (name, value, opts) => setParam(c, name, value, opts),
    field: (name, value) => setCurveField(c, curve, { [name]: value }),
    fields: (changes, note) => setCurveField(c, curve, changes, note),
    params: (changes) => {
      const params = { ...(curve.params ?? {}) };
      for (const [name, value] of Object.entries(changes)) {
        if (value === null) delete params[name];
        else params[name] = value;
      }
      setCurveField(c, curve, { params: Object.keys(params).length ? params : null });
    },
    error: (message, lead) => showError(message, { anchor: eventControl(), lead }),
  });
  // Keys find a control again after the panel is redrawn (the notice goes back beside it).
  controls.forEach((el, k) => { el.dataset.key = `c${c}-${k}`; });
  card.append(...controls);
  if (cardNote?.curve === c) {
    const note = document.createElement('p');
    note.className = 'note';
    note.textContent = cardNote.text;
    card.append(note);
  }
  return card;
}

/**
 * "Compare with…": a curve of `method` on the same keys as the active curve (shared: a drag
 * moves both), with its times (the knots, as far as the method takes knots) and its loop
 * setting; each curve labelled with its method's name for the legend. The new curve has no
 * fit: compared with a fitted curve, it is the curve of `method` through the samples (with
 * the cubic, the interpolating spline that the fit smooths).
 */
export function compareWith(id) {
  const pg = state.pg;
  const c = Math.min(state.activeCurve, pg.curve_count() - 1);
  const base = JSON.parse(pg.curve_json(c));
  const from = methodOf(base.method);
  const to = methodOf(id);
  const n = base.points.length;
  const closed = Boolean(base.closed) && Boolean(to?.closes);
  const knots = knotsFor(to, from?.knots?.skip ?? 0, base.knots, n, closed);
  const anchor = $('add-curve').closest('.row');
  const ok = attempt(() => {
    const before = pg.scene_json();
    try {
      if (base.label === undefined && pg.curve_count() === 1) {
        const name = from?.name ?? base.method;
        const fields = { ...base, label: base.fit ? `${name}, fitted` : name };
        delete fields.points;
        pg.set_curve(c, JSON.stringify(fields));
      }
      pg.add_curve(id);
      const k = pg.curve_count() - 1;
      // add_curve takes curve 1's points; the active curve's replace them.
      const points = JSON.parse(pg.curve_json(k)).points;
      if (JSON.stringify(points) !== JSON.stringify(base.points)) {
        for (let i = 0; i < n; i++) {
          const p = new Float64Array(pg.point(c, i));
          if (i < points.length) pg.set_point(k, i, p);
          else pg.insert_point(k, i, p);
        }
        for (let i = points.length - 1; i >= n; i--) pg.remove_point(k, i);
      }
      // A fitted curve's points are samples: the other curve passes through them (for the
      // cubic, the interpolating spline the fit smooths).
      const name = to?.name ?? id;
      const fields = { method: id, label: base.fit ? `${name} through the samples` : name };
      if (closed) fields.closed = true;
      if (knots) fields.knots = knots;
      pg.set_curve(k, JSON.stringify(fields));
    } catch (e) {
      pg.set_scene(before);
      throw e;
    }
  }, { anchor });
  if (ok) {
    state.activeCurve = pg.curve_count() - 1;
    const lost = [];
    if (base.knots && !knots) lost.push(to?.knots === 'computed' ? 'it computes its own times, so the keys’ times are not used' : 'it takes no knots');
    if (base.closed && !closed) lost.push('it has no closed form, so it is open');
    if (lost.length) cardNote = { curve: state.activeCurve, text: `${to?.name ?? id}: ${lost.join('; ')}.` };
    changed();
  }
}

/** The panel control of the event being handled (the one the user acted on), or null. */
function eventControl() {
  return controlOf(window.event?.target ?? document.activeElement);
}

/** The scene before a live slider move began (recorded for undo when it is released). */
let liveBefore = null;

/** Sets a parameter (null removes it) and redraws; the panels follow unless `live`. A value
 * the curve cannot take is marked while the slider moves; on release the control goes back
 * to the scene's value, with the message beside it. */
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
  else if (!live) {
    changed(); // the scene as it was before the slider moved, and every control with it
  }
}

/** Sets curve `c`'s fit object (null removes it) and redraws; as `setParam`, the panels follow
 * unless `live`, and a live slider is recorded for undo once, on release. */
function setFit(c, curve, fit, { live = false, anchor = eventControl() } = {}) {
  if (liveBefore === null) liveBefore = state.pg.scene_json();
  const before = liveBefore;
  const fields = { ...curve };
  delete fields.points;
  if (fit === null) delete fields.fit;
  else fields.fit = fit;
  const ok = attempt(() => state.pg.set_curve(c, JSON.stringify(fields)), { anchor, record: false });
  if (!live) {
    liveBefore = null;
    commit(before);
  }
  if (ok) changed({ panels: !live, light: live });
  else if (!live) changed();
}

/** Replaces fields of curve `c` (`{ name: value }`, null removes one), keeping its points and
 * other fields; `note` is shown on the card afterwards. A refused change puts the controls
 * back to the scene's values, the message beside the control. */
function setCurveField(c, curve, changes, note = null) {
  const fields = { ...curve };
  delete fields.points;
  for (const [name, value] of Object.entries(changes)) {
    if (value === null) delete fields[name];
    else fields[name] = value;
  }
  if (attempt(() => state.pg.set_curve(c, JSON.stringify(fields)), { anchor: eventControl() })) {
    cardNote = note ? { curve: c, text: note } : null;
    changed();
  } else {
    renderPanels();
  }
}

/** A select of every method, those the space cannot take disabled. */
function methodSelect(space, value, id) {
  const select = document.createElement('select');
  if (id) select.id = id;
  for (const m of state.methods) {
    const opt = document.createElement('option');
    opt.value = m.id;
    opt.textContent = m.name;
    opt.disabled = !inSpaces(m.spaces, space);
    opt.title = `${m.summary} — ${m.spaces.join(', ')} (id "${m.id}")`;
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
      ? 'Click an axis tip of a key (or Tab to it on the sphere) to select it; drag it, or use the arrow keys, to turn it.'
      : 'Click a point (or Tab to it on the sphere) to select it; drag it, or use the arrow keys, to move it.';
    box.append(p);
    $('point-section').classList.remove('selected');
    return;
  }
  $('point-section').classList.add('selected');
  const [c, i] = state.selected;
  const q = state.pg.point(c, i);
  const linked = sharing(c);
  const title = document.createElement('p');
  title.textContent = `curve ${c + 1}, point ${i + 1}`;
  if (linked.length > 1) title.textContent += ` (shared by curves ${linked.map((k) => k + 1).sort((a, b) => a - b).join(', ')})`;
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
    if (attempt(() => setKey(linked, i, new Float64Array(coords)), { anchor: eventControl() })) changed({ panels: false });
    else renderPointEditor(); // the coordinates go back to the scene's
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
      if (attempt(() => setKey(linked, i, sk.axis_angle_to_key(deg, x, y, z)), { anchor: eventControl() })) changed();
      else renderPointEditor();
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
  // In reach: a bottom sheet on a phone (CSS), scrolled into the side panel's view elsewhere.
  if (!matchMedia('(max-width: 800px)').matches) $('point-section').scrollIntoView({ block: 'nearest' });
}

export function deleteSelected() {
  if (!state.selected) return;
  const [c, i] = state.selected;
  // From the keyboard or the button: the message goes beside the point editor's button.
  if (attempt(() => removeKey(sharing(c), i), { anchor: $('point-editor').querySelector('button') })) {
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
  const frame = s3 ? viewOptions().omega_frame : 'space';
  const box = $('readout');
  box.replaceChildren();
  state.readouts = [];
  let same = s3;
  for (let c = 0; c < pg.curve_count(); c++) {
    const r = JSON.parse(pg.readout(c, state.t, frame));
    state.readouts.push(r);
    if (s3) {
      // Whether ω has the same components in the other frame (at the identity, or with ω
      // along the rotation's axis): then the switch changes nothing at this t.
      const other = JSON.parse(pg.readout(c, state.t, frame === 'body' ? 'space' : 'body')).omega;
      if (Math.hypot(...other.map((x, k) => x - r.omega[k])) > 1e-9 * (1 + r.speed)) same = false;
    }
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
      line(`ω ${frame}`, vec(r.omega));
      line(`α ${frame}`, vec(r.alpha));
    }
    box.append(block);
  }
  const note = $('frame-note');
  note.hidden = !same;
  note.textContent = same
    ? 'At this t the body and space frames coincide (the body is in its rest orientation, or turns about its own rotation axis): ω reads the same in both.'
    : '';
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
