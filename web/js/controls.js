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
 * `parametrization`, `extrapolate`; null removes it), `edit.fields({ name: value, … }, note)`
 * several at once (`note`: what the page says about the result), `edit.params({ name: value,
 * … })` several parameters at once (null removes one), `edit.error(message, lead)` reports
 * text the page could not read (`lead`: the plain explanation).
 *
 * A parameter that `requires` a choice (the cubic's end velocities with `end: "clamped"`) is
 * set and cleared with that choice and disabled, with the reason, while the choice differs;
 * parameters about the ends (`open_only`) give way to a note on a closed loop; a curve fitted
 * to its points (`fit`, fit.js) takes natural ends only, so its parameter controls are disabled.
 */
export function curveControls(c, curve, space, method, edit) {
  const controls = [];
  const params = curve.params ?? {};
  const n = curve.points.length;
  const closed = Boolean(curve.closed);
  let ends = false;
  for (const spec of method?.params ?? []) {
    if (spec.advanced || !inSpaces(spec.spaces, space)) continue;
    if (closed && spec.open_only) {
      ends = true;
      continue;
    }
    const value = params[spec.name] ?? spec.default;
    const off = spec.requires && (params[spec.requires.param] ?? defaultOf(method, spec.requires.param)) !== spec.requires.value
      ? `applies with ${spec.requires.param} “${spec.requires.value}”`
      : null;
    let control;
    if (spec.type === 'choice') control = [choiceControl(spec, value, dependentsOf(method, spec, space, curve, edit), edit)];
    else if (spec.type === 'bool') control = [boolControl(spec, value, edit)];
    else if (spec.type === 'vector') control = [vectorControl(spec, value, edit)];
    else control = numberControls(spec, value, n, closed, edit);
    // A curve fitted to its points (the scene's `fit`) takes the ends the fit sets.
    const why = curve.fit ? 'a fit sets its ends' : off;
    if (why) for (const el of control) disable(el, why);
    controls.push(...control);
  }
  if (ends) {
    const note = document.createElement('p');
    note.className = 'muted';
    note.textContent = 'A closed loop has no ends: its end conditions do not apply.';
    controls.push(note);
  }
  if (method?.closes) controls.push(closedToggle(curve, method, edit));
  controls.push(...timingControls(c, curve, edit));
  if (method?.knots?.skip !== undefined) {
    // A closed curve has a knot at every point (each is a key of the loop) and one more: the
    // time it returns to the first point (the registry's KnotRule::count_for).
    const count = closed ? n + 1 : n - 2 * method.knots.skip;
    controls.push(knotsField(c, curve, count, edit));
  } else if (method) {
    const note = document.createElement('p');
    note.className = 'muted';
    note.textContent = method.knots === 'computed'
      ? 'Its times are computed from the points (it takes no knots).'
      : 'It runs over t from 0 to 1 (it takes no knots).';
    controls.push(note);
  }
  controls.push(paramsJson(c, params, edit));
  return controls;
}

/** A registry entry's default for parameter `name`. */
function defaultOf(method, name) {
  return method?.params.find((p) => p.name === name)?.default;
}

/** Greys out a control and says why. */
function disable(el, why) {
  for (const input of el.querySelectorAll('input, select')) input.disabled = true;
  el.classList.add('disabled');
  el.title = why;
  const note = document.createElement('span');
  note.className = 'why';
  note.textContent = ` (${why})`;
  el.append(note);
}

/**
 * For choice `spec`, the edit of its dependents for a new value: the parameters that
 * `require` that value and have no default (vectors) are set to zero vectors (on S³ an angular
 * velocity [x, y, z], elsewhere a tangent vector of the points' dimension); every dependent is
 * removed when the choice moves away.
 */
function dependentsOf(method, spec, space, curve, edit) {
  const deps = (method?.params ?? []).filter((p) => p.requires?.param === spec.name);
  if (!deps.length) return null;
  const dim = space === 'S3' ? 3 : curve.points[0]?.length ?? 3;
  const params = curve.params ?? {};
  return (value) => {
    const changes = {};
    for (const d of deps) {
      if (d.requires.value !== value) changes[d.name] = null;
      else if (params[d.name] === undefined && d.default === null) changes[d.name] = new Array(dim).fill(0);
    }
    return changes;
  };
}

/**
 * Per-point times of an open curve's knots (`skip` points at each end have none: their times
 * continue the neighbouring spacing), or null without knots.
 */
function pointTimes(knots, n, skip) {
  if (!Array.isArray(knots) || knots.length !== n - 2 * skip || knots.length === 0) return null;
  const step = knots.length > 1 ? knots[1] - knots[0] : 1;
  const last = knots.length > 1 ? knots.at(-1) - knots.at(-2) : 1;
  const times = [];
  for (let i = 0; i < skip; i++) times.push(knots[0] - (skip - i) * step);
  times.push(...knots);
  for (let i = 1; i <= skip; i++) times.push(knots.at(-1) + i * last);
  return times;
}

/**
 * The knots a curve of `n` points with `knots` keeps when it opens or closes: closing, every
 * point keeps its time and the loop returns to the first point one mean spacing after the
 * last; opening, the return time goes (and `skip` end points lose theirs). Null: uniform.
 */
export function knotsWhen(closing, knots, n, skip) {
  if (!Array.isArray(knots)) return null;
  if (closing) {
    const times = pointTimes(knots, n, skip);
    if (!times) return null;
    const spacing = n > 1 ? (times[n - 1] - times[0]) / (n - 1) : 1;
    return [...times, times[n - 1] + spacing];
  }
  return knots.length === n + 1 ? knots.slice(skip, n - skip) : null;
}

/** Curve knots for another method on the same points (per-point times kept): null when
 * the method takes none. */
export function knotsFor(method, fromSkip, knots, n, closed) {
  const skip = method?.knots?.skip;
  if (skip === undefined || !Array.isArray(knots)) return null;
  if (closed) return knots.length === n + 1 ? knots : null;
  const times = pointTimes(knots, n, fromSkip);
  return times ? times.slice(skip, n - skip) : null;
}

/**
 * "closed loop": the curve returns to its first point (methods whose entry says `closes`).
 * Closing keeps every point's time (knots gain the return time, a mean spacing after the
 * last); the parameters about the ends go; opening drops the return time and `extrapolate:
 * "cycle"`. The card says what became of the knots.
 */
function closedToggle(curve, method, edit) {
  const label = document.createElement('label');
  label.className = 'check';
  const box = document.createElement('input');
  box.type = 'checkbox';
  box.checked = Boolean(curve.closed);
  box.addEventListener('change', () => {
    const closing = box.checked;
    const n = curve.points.length;
    const skip = method.knots?.skip ?? 0;
    const knots = knotsWhen(closing, curve.knots, n, skip);
    const changes = { closed: closing ? true : null, knots };
    if (!closing && curve.extrapolate === 'cycle') changes.extrapolate = null;
    if (closing && curve.params) {
      const params = { ...curve.params };
      for (const p of method.params) if (p.open_only) delete params[p.name];
      changes.params = Object.keys(params).length ? params : null;
    }
    const note = curve.knots === undefined ? null
      : closing ? `Closed: every point keeps its time; the loop returns to the first point at t = ${fmt(knots.at(-1))} (one mean spacing after the last).`
        : 'Opened: the return time of the loop is dropped from the knots.';
    edit.fields(changes, note);
  });
  label.append(box, ' closed loop');
  return label;
}

const fmt = (x) => String(Math.round(x * 1000) / 1000);

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
  box.setAttribute('aria-label', `Constant speed of curve ${c + 1}`);
  box.addEventListener('change', () => edit.field('parametrization', box.checked ? 'arclength' : null));
  speed.append(box, ' constant speed');
  const outside = document.createElement('label');
  outside.className = 'row slider';
  outside.title = 'what the curve is outside its domain: hold the end at rest, extend along the end geodesic, cycle a closed loop, refuse (error), or continue the end segment (the cubic, as scipy)';
  const select = document.createElement('select');
  select.setAttribute('aria-label', `Extrapolation of curve ${c + 1}`);
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

/** A select; `dependents(value)`, when given, are the parameters that change with it. */
function choiceControl(spec, value, dependents, edit) {
  const label = document.createElement('label');
  label.className = 'row slider';
  label.title = spec.summary;
  const select = document.createElement('select');
  select.setAttribute('aria-label', spec.label);
  for (const ch of spec.choices) select.append(new Option(ch, ch));
  select.value = value;
  select.addEventListener('change', () => {
    const v = select.value === spec.default ? null : select.value;
    if (dependents) edit.params({ [spec.name]: v, ...dependents(select.value) });
    else edit.param(spec.name, v);
  });
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
  label.textContent = curve.closed
    ? `knots (${count}: one time per point, then the return to the first; empty = 0, 1, 2, …) `
    : `knots (${count}, increasing; empty = 0, 1, 2, …) `;
  const input = document.createElement('input');
  input.className = 'params';
  input.spellcheck = false;
  input.value = (curve.knots ?? []).join(', ');
  input.placeholder = 'uniform';
  input.setAttribute('aria-label', `Knots of curve ${c + 1}`);
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
  input.setAttribute('aria-label', `Parameters of curve ${c + 1} (JSON)`);
  input.addEventListener('change', () => {
    let obj;
    try {
      obj = JSON.parse(input.value || '{}');
    } catch (e) {
      edit.error(`params: ${e.message}`, 'The parameters are not valid JSON.');
      return;
    }
    edit.field('params', obj && typeof obj === 'object' && Object.keys(obj).length ? obj : null);
  });
  details.append(summary, input);
  return details;
}
