// Sizing, drawing and the overlay (selection rings, the animated body). The image itself is
// rendered in Rust (Playground.draw); the overlay only marks positions Rust projects.
import * as sk from '../pkg/spherekit_wasm.js';
import { drawBodies } from '../draw.js';
import { $, state, fixedSize, showError } from './state.js';

/** Whether the scene shows a plot under the sphere (speed, or speed and omega; the renderer's default on S³). */
export function hasPlot() {
  const view = JSON.parse(state.pg.scene_json()).view ?? {};
  return view.plot ? view.plot !== 'none' : state.pg.space() === 'S3';
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
  // The frame's height per width: the last frame's if it had the same plot strip (plots and
  // the legend make it taller than wide), or a guess.
  const plot = hasPlot();
  const factor = state.aspect?.plot === plot ? state.aspect.value : plot ? 1.4 : 1;
  const css = Math.max(160, Math.min(w, h / factor));
  state.size = Math.min(4096, Math.floor(css * state.dpr));
}

let pending = false;
/** Redraws on the next animation frame (drags call this many times per frame). */
export function redraw() {
  if (pending) return;
  pending = true;
  requestAnimationFrame(() => {
    pending = false;
    drawNow();
  });
}

export function drawNow() {
  const canvas = $('scene');
  fit();
  try {
    state.pg.draw(canvas, state.size);
  } catch (e) {
    showError(e.message); // a drawing failure; a good draw leaves an edit's message alone
  }
  state.aspect = { plot: hasPlot(), value: canvas.height / canvas.width };
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
export function drawOverlay() {
  const ctx = $('overlay').getContext('2d');
  ctx.clearRect(0, 0, ctx.canvas.width, ctx.canvas.height);
  const pg = state.pg;
  const s = state.size;
  const k = s / 512;
  if (state.playing || state.u > 0) drawBodies(ctx, pg, state.u, s);
  for (const p of selectedMarkers()) {
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
