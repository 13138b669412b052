// Sizing, drawing and the overlay (the moving body or point at t, the plot cursor, hover and
// selection rings). The image itself is rendered in Rust (Playground.draw); the overlay only
// marks positions Rust projects. While a drag or a zoom is under way the frame is rendered at
// reduced resolution (state.quick) and shown at the same size; the still frame afterwards is
// the full-resolution one, the same pixels as the golden at ?size=.
import * as sk from '../pkg/spherekit_wasm.js';
import { drawBodies } from '../pkg/draw.js';
import { $, state, fixedSize, showError } from './state.js';

/** The view options with the renderer's defaults filled in (Rust's `view_options`). */
export function viewOptions() {
  return JSON.parse(state.pg.view_options()) ?? { plot: 'none', legend: false, axes: ['x'], frames: 0 };
}

/** The frame drawn while dragging: this fraction of the CSS width in pixels, at most QUICK_MAX
 * wide (measured: BENCHMARKS.md, section 6). */
const QUICK_SCALE = 0.7;
const QUICK_MAX = 640;

/** The smallest text of the figure (plot and legend), CSS pixels per em. */
export const MIN_TEXT = 11;

function fit() {
  state.dpr = fixedSize ? 1 : window.devicePixelRatio || 1;
  if (fixedSize) {
    state.size = fixedSize;
    state.base = fixedSize;
    return;
  }
  const stage = $('stage');
  const narrow = matchMedia('(max-width: 800px)').matches;
  const w = stage.clientWidth - 12;
  const h = narrow
    ? window.innerHeight - 56
    : stage.clientHeight - stage.querySelector('.toolbar').offsetHeight - 16;
  // The frame's height per width: the last still frame's if it had the same layout (plots,
  // the legend and a title make it taller than wide), or a guess that drawNow corrects.
  const view = viewOptions();
  const key = `${JSON.stringify(view)} ${state.pg.curve_count()} ${state.pg.scene_json().includes('"title"')}`;
  const factor = state.aspect?.key === key ? state.aspect.value : view.plot === 'omega' ? 1.9 : view.plot !== 'none' ? 1.45 : 1.08;
  const css = Math.max(160, Math.min(w, h / factor));
  state.base = Math.floor(css);
  state.size = Math.min(4096, Math.floor(css * state.dpr * state.zoom));
  state.aspectKey = key;
  state.fitFactor = factor;
}

let pending = false;
const tasks = [];
/** Durations (ms) of the last frames' work: queued edits, render and overlay (the bench reads them). */
export const frameTimes = [];
/** Redraws on the next animation frame, after running `task` (drags queue their edit here, so
 * that many pointer moves in one frame make one edit and one render). */
export function redraw(task = null) {
  if (task) tasks.push(task);
  if (pending) return;
  pending = true;
  requestAnimationFrame(() => {
    const start = performance.now();
    // Redraws asked for by the tasks are this frame's (`pending` is still set).
    for (const t of tasks.splice(0)) t();
    drawNow();
    pending = false;
    frameTimes.push(performance.now() - start);
    if (frameTimes.length > 2000) frameTimes.splice(0, 1000);
    if (tasks.length) redraw();
  });
}

/** Draws the frame now. A frame whose height per width differs from the one `fit` assumed
 * (a new layout) is fitted and drawn again, so that the figure fits the stage: a few times at
 * most, as the text floor makes a smaller figure relatively taller. */
export function drawNow(refits = 4) {
  const canvas = $('scene');
  fit();
  const quick = state.quick && !fixedSize;
  const drawSize = quick
    ? Math.min(state.size, Math.max(160, Math.round(Math.min(QUICK_MAX, (QUICK_SCALE * state.size) / state.dpr))))
    : state.size;
  // Text of at least MIN_TEXT CSS pixels (zoomed with the figure); none at a fixed size (the
  // golden's pixels).
  state.pg.set_min_text(fixedSize ? 0 : (MIN_TEXT * state.dpr * state.zoom * drawSize) / state.size);
  try {
    state.pg.draw(canvas, drawSize);
  } catch (e) {
    showError(e.message); // a drawing failure; a good draw leaves an edit's message alone
  }
  const k = state.size / canvas.width;
  state.plots = JSON.parse(state.pg.plot_axes()).map((p) => ({
    left: p.left * k, right: p.right * k, top: p.top * k, bottom: p.bottom * k, t0: p.t0, t1: p.t1,
  }));
  const aspect = canvas.height / canvas.width;
  if (!quick && state.zoom === 1) {
    state.aspect = { key: state.aspectKey, value: aspect };
    if (refits > 0 && !fixedSize && Math.abs(aspect - state.fitFactor) > 0.002) {
      // The frame is not the shape fit assumed: fit again with its real height.
      drawNow(refits - 1);
      return;
    }
  }
  const frameAspect = state.aspect?.value ?? aspect;
  // The frame at the current zoom, placed so that the sphere's centre stays at the centre of
  // the unzoomed sphere square; the wrapper clips it.
  const cssW = state.size / state.dpr;
  const offset = state.zoom === 1 ? 0 : (state.base - cssW) / 2;
  const wrap = $('canvas-wrap');
  setStyle(wrap, 'width', `${state.base}px`);
  setStyle(wrap, 'height', `${Math.round(state.base * frameAspect)}px`);
  const overlay = $('overlay');
  const oh = Math.round(state.size * aspect);
  if (overlay.width !== state.size || overlay.height !== oh) {
    overlay.width = state.size;
    overlay.height = oh;
  }
  for (const c of [canvas, overlay]) {
    setStyle(c, 'width', `${cssW}px`);
    setStyle(c, 'height', `${cssW * aspect}px`);
    setStyle(c, 'left', `${offset}px`);
    setStyle(c, 'top', `${offset}px`);
  }
  const zoom = `zoom ${Math.round(state.zoom * 100)}%`;
  if ($('zoom-out').textContent !== zoom) $('zoom-out').textContent = zoom;
  drawOverlay();
}

let lastOverlay = '';

/** Sets an inline style only when it changes (an unchanged write still costs a style pass). */
function setStyle(el, name, value) {
  if (el.style[name] !== value) el.style[name] = value;
}

/** The moving bodies at t, the plot cursor, the hover and selection rings, over the image. */
export function drawOverlay() {
  const overlay = $('overlay');
  const pg = state.pg;
  const bodies = state.playing || state.t > state.axis[0];
  // The same marks as last time (turning the view with nothing on the sphere's overlay moves
  // only the plot-free image): leave the overlay alone, so the compositor has less to do.
  const onSphere = bodies || state.selected || state.hover;
  const key = [state.t, bodies, state.selected, state.hover, state.activeCurve, overlay.width, overlay.height, pg.builds(), pg.curve_count(),
    onSphere ? pg.camera().join() : '', JSON.stringify(state.plots)].join('|');
  if (key === lastOverlay) return;
  lastOverlay = key;
  const ctx = overlay.getContext('2d');
  ctx.clearRect(0, 0, overlay.width, overlay.height);
  const s = state.size;
  const k = s / 512;
  // ω of the active curve only: one arrow per curve would crowd a comparison.
  if (bodies) drawBodies(ctx, pg, state.t, s, Math.min(state.activeCurve, pg.curve_count() - 1));
  for (const p of state.plots ?? []) {
    const x = plotX(p, state.t);
    ctx.strokeStyle = '#b3261e';
    ctx.lineWidth = Math.max(1, 1.5 * k);
    ctx.beginPath();
    ctx.moveTo(x, p.top);
    ctx.lineTo(x, p.bottom);
    ctx.stroke();
    // The head hangs inside the axes, from their top edge: above it is the plot's title.
    ctx.fillStyle = '#b3261e';
    ctx.beginPath();
    ctx.moveTo(x - 5 * k, p.top);
    ctx.lineTo(x + 5 * k, p.top);
    ctx.lineTo(x, p.top + 6 * k);
    ctx.fill();
  }
  if (state.hover && !sameKey(state.hover, state.selected)) {
    for (const p of markers(state.hover)) ring(ctx, p, '#5b6470', 2.5 * k, 12 * k);
  }
  for (const p of markers(state.selected)) ring(ctx, p, '#1f2328', 3 * k, 11 * k);
}

function ring(ctx, p, color, width, radius) {
  ctx.strokeStyle = color;
  ctx.lineWidth = width;
  ctx.beginPath();
  ctx.arc(p[0], p[1], radius, 0, 2 * Math.PI);
  ctx.stroke();
}

const sameKey = (a, b) => Boolean(a && b && a[0] === b[0] && a[1] === b[1]);

/** The x (device pixels of a still frame) of time `t` in plot `p`. */
export function plotX(p, t) {
  const f = p.t1 > p.t0 ? (t - p.t0) / (p.t1 - p.t0) : 0;
  return p.left + Math.min(1, Math.max(0, f)) * (p.right - p.left);
}

/** The plot under device pixel (x, y) (with a margin for its tick numbers), or null. */
export function plotAt(x, y) {
  const m = 8 * (state.size / 512);
  return (state.plots ?? []).find((p) => x >= p.left - m && x <= p.right + m && y >= p.top - 2 * m && y <= p.bottom + 3 * m) ?? null;
}

/** The time at device x in plot `p`. */
export function timeAt(p, x) {
  const f = Math.min(1, Math.max(0, (x - p.left) / (p.right - p.left)));
  return p.t0 + f * (p.t1 - p.t0);
}

/** Pixel positions of point (S²) or key axis tips (S³) `[c, i]`. */
function markers(key) {
  if (!key) return [];
  const [c, i] = key;
  let p;
  try {
    p = state.pg.point(c, i);
  } catch {
    return [];
  }
  const s = state.size;
  if (p.length === 4) return [0, 1, 2].map((a) => keyAxisOnScreen(p, a, s));
  return [pointOnCanvas(p, s)];
}

/** Device-pixel position of a point (normalised onto the sphere) in an image `s` wide. */
export function pointOnCanvas(p, s = state.size) {
  const n = Math.hypot(...p) || 1;
  return state.pg.project(p[0] / n, p[1] / n, (p[2] ?? 0) / n, s);
}

/** Device-pixel position of the tip of key `q`'s rotated axis `a` (0 = x, 1 = y, 2 = z). */
export function keyAxisOnScreen(q, a, s = state.size) {
  const v = sk.key_axes(new Float64Array(q));
  return state.pg.project(v[3 * a], v[3 * a + 1], v[3 * a + 2], s);
}
