// The page's shared state, the error notice, and undo/redo. Every other module reads and
// writes `state`; nothing else is shared between them.

export const $ = (id) => document.getElementById(id);

/** The page's query: `?size=384` (a fixed render size, for the goldens), `?bench`. */
export const query = new URLSearchParams(location.search);

/** A fixed render size (pixels) instead of fitting the window, e.g. ?size=384 for the golden. */
export const fixedSize = query.has('size') ? Number(query.get('size')) : null;

export const state = {
  pg: null,          // sk.Playground
  size: 0,           // render size of a still frame, device pixels (zoom included)
  dpr: 1,
  zoom: 1,           // the view's magnification (1: the sphere fits the stage)
  selected: null,    // [curve, index]
  hover: null,       // [curve, index] under the pointer
  activeCurve: 0,    // the curve new points go to
  playing: false,
  t: 0,              // the time on the scene's time axis (the curves' own t), one for the whole page
  axis: [0, 1, 0],   // pg.time_axis(): [t0, t1, normalized]
  methods: [],       // the registry, as sk.methods() gives it
  presets: [],
  undo: [],          // scene JSON texts before each edit
  redo: [],
};

/** The notice element, kept here: while the panel is redrawn it may be outside the document
 * for a moment, where getElementById would not find it. */
let noticeElement = null;
const noticeBox = () => (noticeElement ??= $('notice'));

/** The last edit's failure: its message, and where it is shown. */
let notice = { anchor: null, key: null };

/**
 * Shows `message` (empty: hides it) where the action was: beside `anchor` (a control; it is
 * marked as failed) or, without one, over the stage. Inside the viewport either way. `lead` is
 * the plain explanation shown first (by default one for the message's kind, if any), the
 * library's message follows; `offer` is an optional `{ label, run }` button.
 */
export function showError(message, { anchor = null, lead = plainLead(message), offer = null } = {}) {
  const box = noticeBox();
  for (const el of document.querySelectorAll('[aria-invalid="true"]')) el.removeAttribute('aria-invalid');
  $('error').textContent = message ? `error: ${message}` : '';
  $('error-lead').textContent = lead;
  $('error-lead').hidden = !lead;
  const button = $('error-offer');
  button.hidden = !offer;
  button.onclick = offer ? () => offer.run() : null;
  if (offer) button.textContent = offer.label;
  box.hidden = !message;
  notice = { anchor: message ? anchor : null, key: message ? anchor?.dataset.key ?? null : null };
  placeNotice();
}

/** The plain words that open the message of a scene text that is not JSON (the parser's
 * words follow), or ''. */
function plainLead(message) {
  if (/^invalid scene JSON: /.test(message ?? '')) return 'The scene text is not valid JSON, so nothing changed. Where the parser stopped:';
  return '';
}

/** Puts the notice beside its control (found again by its key after the panel was redrawn)
 * or over the stage, and scrolls it into view. */
export function placeNotice() {
  const box = noticeBox();
  if (box.hidden) return;
  let anchor = notice.anchor;
  if (anchor && !anchor.isConnected && notice.key) anchor = document.querySelector(`[data-key="${notice.key}"]`);
  if (anchor?.isConnected) {
    anchor.setAttribute('aria-invalid', 'true');
    box.className = 'beside';
    anchor.after(box);
  } else {
    box.className = 'over-stage';
    $('canvas-wrap').after(box);
  }
  box.scrollIntoView({ block: 'nearest' });
}

/** Takes the notice out of the side panel before a part of it is redrawn (it is put back
 * beside the redrawn control by placeNotice). */
export function parkNotice() {
  const box = noticeBox();
  if (box.parentElement !== $('stage')) $('stage').append(box);
}

/** The control an event in the side panel came from (for the notice), or null. */
export function controlOf(el) {
  return el?.closest?.('#panel [data-key], #panel label, #panel .row') ?? null;
}

/**
 * Runs an edit of the handle. A failure shows its message where the action was (`anchor`:
 * the control, or null for the stage), explains a solver that gave up, and leaves the last good
 * state; a success clears the message. The edit is undoable unless `record` is false (a live
 * slider or drag records once at its end with `commit`).
 */
export function attempt(edit, { anchor = null, record = true } = {}) {
  const before = state.pg?.scene_json();
  try {
    edit();
  } catch (e) {
    const message = e instanceof Error ? e.message : String(e);
    showError(message, { anchor, ...explain(edit, anchor) });
    return false;
  }
  if (!noticeBox().hidden) showError('');
  if (record && before !== undefined) commit(before);
  return true;
}

/** Records an edit that started from scene text `before` (no entry if nothing changed). */
export function commit(before) {
  if (before === state.pg.scene_json()) return;
  state.undo.push(before);
  if (state.undo.length > 200) state.undo.shift();
  state.redo.length = 0;
  updateHistoryButtons();
}

export function updateHistoryButtons() {
  $('undo').disabled = state.undo.length === 0;
  $('redo').disabled = state.redo.length === 0;
}

/** What the page does after an edit made outside the panels' own handlers (panels.js sets it). */
export const hooks = { changed: () => {} };

/** The words for a failed `edit` whose solver gave up (Rust's `failure()`): the Beta spline's
 * interpolation, with the miss distance, and on offer the same edit with the approximating
 * spline (the method's `interpolate` switch off). */
function explain(edit, anchor) {
  const f = JSON.parse(state.pg?.failure() ?? 'null');
  if (!f) return {};
  const curve = f.curve ?? 0;
  const spec = JSON.parse(state.pg.curve_json(curve));
  const method = methodOf(spec.method);
  const deg = (f.residual * 180) / Math.PI;
  const miss = Number.isFinite(f.residual)
    ? `the nearest one found misses a point by ${f.residual.toPrecision(2)} rad (${deg.toPrecision(2)}°)`
    : 'the solver found none';
  const shape = method?.params.some((p) => p.name === 'beta1') ? 'Beta spline with these β' : `${spec.method} curve with these parameters`;
  const lead = `No ${shape} passes through the points: ${miss} after ${f.iterations} iterations. The picture keeps the last curve that worked.`;
  // Methods whose schema has an `interpolate` switch can show their approximating curve.
  const canApproximate = method?.params.some((p) => p.name === 'interpolate' && p.type === 'bool');
  return {
    lead,
    offer: canApproximate ? { label: 'Show the approximating spline', run: () => approximate(curve, edit, anchor) } : null,
  };
}

/** `edit` again with curve `curve` approximating instead of interpolating, as one undoable edit. */
function approximate(curve, edit, anchor) {
  const before = state.pg.scene_json();
  try {
    state.pg.set_param(curve, 'interpolate', 'false');
    edit();
  } catch (e) {
    state.pg.set_scene(before);
    showError(e instanceof Error ? e.message : String(e), { anchor });
    return;
  }
  showError('');
  commit(before);
  hooks.changed();
}

/** Whether a registry `spaces` list (["S2", "S3", "S<m>"] or ["S3"]) includes the scene's space. */
export function inSpaces(spaces, space) {
  return spaces.includes(space) || (spaces.includes('S<m>') && space !== 'S2' && space !== 'S3');
}

/** The registry entry of a method id (undefined for an unknown one). */
export function methodOf(id) {
  return state.methods.find((m) => m.id === id);
}
