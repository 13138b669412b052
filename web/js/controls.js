// The parameter controls of one curve, generated from its method's registry entry
// (sk.methods(): the schema the scene format validates with). Nothing here knows a method:
// a number or integer gets a slider over the schema's range, a choice a select, a bool a
// checkbox, a per-joint parameter a "per joint" toggle, a method with `knots: {skip}` a knots
// field. Solver settings (`advanced`) and parameters of other spheres get no control; every
// parameter stays editable in the "params as JSON" box.
import { inSpaces } from './state.js';

/**
 * The controls of curve `c` (its scene description `curve`, on `space`) for registry entry
 * `method`. `edit.param(name, value, { live })` sets a parameter (null removes it; `live` while
 * a slider moves), `edit.field(name, value)` a curve field (`knots`, `params`, `closed`,
 * `parametrization`, `extrapolate`; null
 * removes it), `edit.fields({ name: value, … })` several at once,
 * `edit.error(message)` reports text the page could not read.
 */
export function curveControls(c, curve, space, method, edit) {
  const controls = [];
  const params = curve.params ?? {};
  const n = curve.points.length;
  for (const spec of method?.params ?? []) {
    if (spec.advanced || !inSpaces(spec.spaces, space)) continue;
    const value = params[spec.name] ?? spec.default;
    if (spec.type === 'choice') controls.push(choiceControl(spec, value, edit));
    else if (spec.type === 'bool') controls.push(boolControl(spec, value, edit));
    else if (spec.type === 'vector') controls.push(vectorControl(spec, value, edit));
    else controls.push(...numberControls(spec, value, n, Boolean(curve.closed), edit));
  }
  if (method?.closes) controls.push(closedToggle(curve, edit));
  controls.push(...timingControls(c, curve, edit));
  if (method?.knots?.skip !== undefined) {
    // A closed curve has a knot at every point (each is a key of the loop) and one more: the
    // time it returns to the first point (the registry's KnotRule::count_for).
    const count = curve.closed ? n + 1 : n - 2 * method.knots.skip;
    controls.push(knotsField(c, curve, count, edit));
  }
  controls.push(paramsJson(c, params, edit));
  return controls;
}

/** "closed": the curve returns to its first point (methods whose entry says `closes`). */
function closedToggle(curve, edit) {
  const label = document.createElement('label');
  label.className = 'check';
  const box = document.createElement('input');
  box.type = 'checkbox';
  box.checked = Boolean(curve.closed);
  // The knots of an open curve do not fit a closed one (one more): they go, and so does
  // `extrapolate: "cycle"` when the loop opens.
  const cycle = () => (!box.checked && curve.extrapolate === 'cycle' ? { extrapolate: null } : {});
  box.addEventListener('change', () => edit.fields({ closed: box.checked ? true : null, knots: null, ...cycle() }));
  label.append(box, ' closed loop');
  return label;
}

/**
 * The curve's timing, the same for every method: "constant speed" (`parametrization:
 * "arclength"`, the curve at unit speed over [0, L]) and what it is outside its domain
 * (`extrapolate`; `cycle` for closed curves). The scene format checks the choice: a policy the
 * curve has no value for (`segment` off the open cubic) comes back as its message.
 */
function timingControls(c, curve, edit) {
  const speed = document.createElement('label');
  speed.className = 'check';
  const box = document.createElement('input');
  box.type = 'checkbox';
  box.checked = curve.parametrization === 'arclength';
  box.setAttribute('aria-label', `Constant speed of curve ${c}`);
  box.addEventListener('change', () => edit.field('parametrization', box.checked ? 'arclength' : null));
  speed.append(box, ' constant speed');
  const outside = document.createElement('label');
  outside.className = 'row slider';
  outside.title = 'what the curve is outside its domain: hold the end at rest, extend along the end geodesic, cycle a closed loop, refuse (error), or continue the end segment (the cubic, as scipy)';
  const select = document.createElement('select');
  select.setAttribute('aria-label', `Extrapolation of curve ${c}`);
  const policies = ['hold', 'extend', ...(curve.closed ? ['cycle'] : []), 'error', 'segment'];
  for (const p of policies) select.append(new Option(p, p));
  select.value = curve.extrapolate ?? 'hold';
  select.addEventListener('change', () => edit.field('extrapolate', select.value === 'hold' ? null : select.value));
  outside.append('outside ', select);
  return [speed, outside];
}

/** A vector (a velocity) as comma-separated numbers; empty removes it. */
function vectorControl(spec, value, edit) {
  const label = document.createElement('label');
  label.className = 'row';
  label.title = spec.summary;
  const input = document.createElement('input');
  input.className = 'params';
  input.spellcheck = false;
  input.value = Array.isArray(value) ? value.join(', ') : '';
  input.placeholder = 'x, y, z';
  input.setAttribute('aria-label', spec.label);
  input.addEventListener('change', () => {
    const text = input.value.trim();
    edit.param(spec.name, text ? text.split(/[\s,]+/).filter(Boolean).map(Number) : null);
  });
  label.append(`${spec.label} `, input);
  return label;
}

function choiceControl(spec, value, edit) {
  const label = document.createElement('label');
  label.className = 'row slider';
  const select = document.createElement('select');
  for (const ch of spec.choices) select.append(new Option(ch, ch));
  select.value = value;
  select.addEventListener('change', () => edit.param(spec.name, select.value === spec.default ? null : select.value));
  label.append(`${spec.label} `, select);
  return label;
}

function boolControl(spec, value, edit) {
  const label = document.createElement('label');
  label.className = 'check';
  const box = document.createElement('input');
  box.type = 'checkbox';
  box.checked = Boolean(value);
  box.addEventListener('change', () => edit.param(spec.name, box.checked === spec.default ? null : box.checked));
  label.append(box, ` ${spec.label}`);
  return label;
}

/**
 * One slider, or one per entry of a per-joint list, and the "per joint" toggle. A loop has an
 * entry at every point (the registry's PerJoint::count_for).
 */
function numberControls(spec, value, n, closed, edit) {
  const controls = [];
  const joints = spec.per_joint ? (closed ? n : n - 2 * spec.per_joint.skip) : 0;
  const first = closed ? 0 : (spec.per_joint?.first ?? 0);
  const list = Array.isArray(value) ? value : null;
  if (list) {
    list.forEach((v, k) => controls.push(slider(spec, `${spec.label} [${k + first}]`, v, (x, live) => {
      const next = list.slice();
      next[k] = x;
      edit.param(spec.name, next, { live });
    })));
  } else {
    controls.push(slider(spec, spec.label, value, (x, live) => edit.param(spec.name, x, { live })));
  }
  if (joints > 1 || list) {
    const label = document.createElement('label');
    label.className = 'check muted';
    const box = document.createElement('input');
    box.type = 'checkbox';
    box.checked = Boolean(list);
    box.addEventListener('change', () => edit.param(spec.name, box.checked ? new Array(joints).fill(value) : list[0]));
    label.append(box, ` ${spec.label} per joint`);
    controls.push(label);
  }
  return controls;
}

/** A labelled range input; `set(value, live)` runs while dragging (live) and on release. */
function slider(spec, name, value, set) {
  const integer = spec.type === 'integer';
  const row = document.createElement('label');
  row.className = 'row slider';
  const range = document.createElement('input');
  range.type = 'range';
  range.min = String(Math.min(spec.min, value));
  range.max = String(Math.max(spec.max, value));
  range.step = integer ? '1' : 'any';
  range.value = String(value);
  const out = document.createElement('output');
  const show = (v) => (integer ? String(v) : v.toFixed(3));
  out.textContent = show(value);
  range.addEventListener('input', () => {
    out.textContent = show(Number(range.value));
    set(Number(range.value), true);
  });
  range.addEventListener('change', () => set(Number(range.value), false));
  row.append(`${name} `, range, out);
  return row;
}

function knotsField(c, curve, count, edit) {
  const label = document.createElement('label');
  label.textContent = `knots (${count}, increasing; empty = 0, 1, 2, …) `;
  const input = document.createElement('input');
  input.className = 'params';
  input.spellcheck = false;
  input.value = (curve.knots ?? []).join(', ');
  input.placeholder = 'uniform';
  input.setAttribute('aria-label', `Knots of curve ${c}`);
  input.addEventListener('change', () => {
    const text = input.value.trim();
    edit.field('knots', text ? text.split(/[\s,]+/).filter(Boolean).map(Number) : null);
  });
  label.append(input);
  return label;
}

/** Every parameter (solver settings too) as JSON. */
function paramsJson(c, params, edit) {
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
      edit.error(`params: ${e.message}`);
      return;
    }
    edit.field('params', obj && typeof obj === 'object' && Object.keys(obj).length ? obj : null);
  });
  details.append(summary, input);
  return details;
}
