// The smoothing controls of a curve fitted to its points (the scene's `fit` field, cubic only):
// λ on a log scale (slider and number), the GCV button, a target rms, and the readout of the
// fit (λ, rms and largest residual in degrees, keys, effective degrees of freedom) from Rust's
// `info.fit`. The fit itself runs in Rust on every rebuild; nothing here computes it.
//
// The points of a fitted curve are its samples: the picture marks them as rings and the fitted
// keys as dots; dragging a sample (or typing its coordinates, adding or deleting one) moves the
// sample and the curve is fitted again (with λ held while a sample is dragged when λ is
// searched for, see holdSearchedLambda).

/** The slider's range of log₁₀ λ (widened to take a λ outside it). */
const LOG_RANGE = [-8, 3];

const deg = (rad) => (rad * 180) / Math.PI;

/** λ for the number box: four significant digits. */
const showLambda = (x) => (Number.isFinite(x) ? Number(x.toPrecision(4)).toString() : '');

/** The fit report of curve `c` (`info.fit` of `pg.sample_at` at one time: lambda, rms, max,
 * keys, key_times, iterations, edf when there is one, residuals), or null for a curve without
 * a fit. */
export function fitInfo(pg, c) {
  const [t0] = Array.from(pg.time_axis());
  const json = JSON.parse(pg.sample_at(new Float64Array([t0]), false, null));
  return (json.curves ?? [json])[c]?.info?.fit ?? null;
}

/**
 * While a sample is dragged, each curve of `curves` whose λ is searched for (`"gcv"` or a
 * target rms: a search fits many times, about a second and a half for 80 samples in the
 * browser) keeps the λ it last chose, so that the curve follows the pointer; the function
 * returned puts the search back (one search, when the drag ends). Null when no curve
 * searches.
 */
export function holdSearchedLambda(pg, curves) {
  const held = [];
  for (const c of curves) {
    const spec = JSON.parse(pg.curve_json(c));
    if (!spec.fit || typeof spec.fit.smoothing === 'number') continue;
    const info = fitInfo(pg, c);
    if (!info) continue;
    held.push({ c, fit: spec.fit });
    setFitOf(pg, c, { ...spec.fit, smoothing: info.lambda });
  }
  if (!held.length) return null;
  return () => {
    for (const { c, fit } of held) setFitOf(pg, c, fit);
  };
}

/** Sets curve `c`'s fit object, keeping its other fields. */
function setFitOf(pg, c, fit) {
  const fields = JSON.parse(pg.curve_json(c));
  delete fields.points;
  fields.fit = fit;
  pg.set_curve(c, JSON.stringify(fields));
}

/** The readout's text for a report. */
function readoutText(info) {
  const edf = info.edf === undefined ? '' : ` · edf ${info.edf.toFixed(1)}`;
  return `λ = ${showLambda(info.lambda)} · rms ${deg(info.rms).toFixed(3)}° · max ${deg(info.max).toFixed(3)}° · ${info.keys} keys${edf}`;
}

/** Refreshes every fitted curve's readout (after an edit, also while a slider moves or a sample
 * is dragged: the panels are not redrawn then). */
export function updateFitReadouts(pg) {
  for (const el of document.querySelectorAll('[data-fit-readout]')) {
    const c = Number(el.dataset.fitReadout);
    let info = null;
    try {
      info = fitInfo(pg, c);
    } catch {
      info = null;
    }
    if (info) el.textContent = readoutText(info);
  }
}

/**
 * The fit controls of curve `c` (scene description `curve`, registry entry `method`): for a
 * method that takes a fit, the "fitted to its points" switch, and with a fit the smoothing
 * controls and the readout. `edit.fit(fit, { live, anchor })` sets the fit object (null removes it;
 * `live` while the slider moves; `anchor`: the control a failure is shown beside, by default
 * the one of the event being handled), `edit.fields(changes, note)` several curve fields at once.
 */
export function fitControls(pg, c, curve, method, edit) {
  const keys = (method?.fit ?? []).map((k) => k.name);
  if (!keys.includes('smoothing')) return [];
  const summary = (name) => method.fit.find((k) => k.name === name)?.summary ?? '';
  const controls = [fitToggle(c, curve, edit)];
  const fit = curve.fit;
  if (!fit) return controls;
  const info = fitInfo(pg, c);
  const lambda = info?.lambda ?? (typeof fit.smoothing === 'number' ? fit.smoothing : 1e-3);
  controls.push(lambdaControl(c, fit, lambda, summary('smoothing'), edit));
  controls.push(searchControls(c, fit, info, edit));
  const readout = document.createElement('p');
  readout.className = 'fit-readout';
  readout.dataset.fitReadout = String(c);
  readout.setAttribute('aria-live', 'polite');
  readout.textContent = info ? readoutText(info) : '';
  const how = document.createElement('p');
  how.className = 'muted';
  how.textContent = 'Rings are the samples (the points), dots the fitted keys; the lower plot shows each sample’s residual. Drag a sample to move it: the curve is fitted again. Other fit options (weights, max_error, keys) in the scene’s JSON.';
  controls.push(readout, how);
  return controls;
}

/** "fitted to its points": on, the curve becomes the smoothing spline of its points at their
 * times (GCV; times 0, 1, 2, … when it has no knots; natural ends, as a fit takes); off, the
 * interpolating cubic through them again. */
function fitToggle(c, curve, edit) {
  const label = document.createElement('label');
  label.className = 'check';
  label.title = 'the points are noisy samples: fit a smoothing spline to them instead of passing through them';
  const box = document.createElement('input');
  box.type = 'checkbox';
  box.checked = Boolean(curve.fit);
  box.setAttribute('aria-label', `Curve ${c + 1} fitted to its points`);
  box.addEventListener('change', () => {
    if (!box.checked) {
      edit.fields({ fit: null }, 'The curve passes through its points again.');
      return;
    }
    const changes = { fit: { smoothing: 'gcv' } };
    const notes = ['Fitted to its points (λ by GCV).'];
    if (!Array.isArray(curve.knots)) {
      changes.knots = curve.points.map((_, i) => i);
      notes.push('The points are samples at t = 0, 1, 2, ….');
    }
    const params = { ...(curve.params ?? {}) };
    const end = params.end;
    for (const name of Object.keys(params)) if (name !== 'end' || end !== 'natural') delete params[name];
    if (Object.keys(params).length !== Object.keys(curve.params ?? {}).length) {
      changes.params = Object.keys(params).length ? params : null;
      notes.push('A fit has natural ends: the end conditions were dropped.');
    }
    edit.fields(changes, notes.join(' '));
  });
  label.append(box, ' fitted to its points (smoothing spline)');
  return label;
}

/** λ on a log scale: a slider over log₁₀ λ and a number box. With λ chosen by GCV or a target
 * rms, both show the λ chosen, and moving either gives that λ from there on. */
function lambdaControl(c, fit, lambda, summary, edit) {
  const row = document.createElement('div');
  row.className = 'row slider fit-lambda';
  row.title = summary;
  const range = document.createElement('input');
  range.type = 'range';
  const log = Math.log10(Math.max(lambda, 1e-300));
  range.min = String(Math.min(LOG_RANGE[0], Math.floor(log)));
  range.max = String(Math.max(LOG_RANGE[1], Math.ceil(log)));
  range.step = 'any';
  range.value = String(log);
  range.setAttribute('aria-label', `Smoothing λ of curve ${c + 1} (log scale)`);
  const number = document.createElement('input');
  number.type = 'number';
  number.className = 'fit-number';
  number.min = '0';
  number.step = 'any';
  number.value = showLambda(lambda);
  number.setAttribute('aria-label', `Smoothing λ of curve ${c + 1}`);
  const set = (value, live) => edit.fit({ ...fit, smoothing: value }, { live });
  range.addEventListener('input', () => {
    const value = Number((10 ** Number(range.value)).toPrecision(4));
    number.value = showLambda(value);
    set(value, true);
  });
  range.addEventListener('change', () => set(Number((10 ** Number(range.value)).toPrecision(4)), false));
  number.addEventListener('change', () => set(Number(number.value), false));
  const how = typeof fit.smoothing === 'number' ? '' : fit.smoothing === 'gcv' ? ' (GCV)' : ' (rms)';
  row.append(`λ${how} `, range, number);
  return row;
}

/** The GCV button and the target rms (degrees): λ chosen by generalised cross-validation, or
 * the λ whose rms residual is the target. */
function searchControls(c, fit, info, edit) {
  const row = document.createElement('div');
  row.className = 'row slider';
  const gcv = document.createElement('button');
  gcv.type = 'button';
  gcv.className = 'fit-gcv';
  gcv.textContent = 'GCV';
  gcv.title = 'choose λ by generalised cross-validation (needs a key at every sample)';
  gcv.setAttribute('aria-pressed', String(fit.smoothing === 'gcv'));
  gcv.addEventListener('click', () => {
    // The search takes a moment (many fits): say so before it runs.
    gcv.disabled = true;
    gcv.textContent = 'GCV…';
    const anchor = row;
    requestAnimationFrame(() => setTimeout(() => edit.fit({ ...fit, smoothing: 'gcv' }, { anchor }), 0));
  });
  const target = document.createElement('input');
  target.type = 'number';
  target.className = 'fit-number fit-rms';
  target.min = '0';
  target.step = 'any';
  target.placeholder = info ? deg(info.rms).toFixed(3) : '';
  const rms = fit.smoothing?.rms;
  target.value = rms === undefined ? '' : String(Number(deg(rms).toPrecision(4)));
  target.setAttribute('aria-label', `Target rms residual of curve ${c + 1} (degrees)`);
  target.title = 'the λ whose rms residual is this many degrees';
  target.addEventListener('change', () => {
    const d = Number(target.value);
    if (target.value.trim() === '') return;
    edit.fit({ ...fit, smoothing: { rms: (d * Math.PI) / 180 } });
  });
  const label = document.createElement('label');
  label.className = 'inline';
  label.append('target rms° ', target);
  row.append(gcv, label);
  return row;
}
