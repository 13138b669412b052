// spherekit docs widget: a small interactive view of one scene (drag to turn, play to animate,
// optionally a link that opens the same scene in a playground). Part of the npm package
// (`import { mount } from 'spherekit/widget'`, or this file from a CDN); the project's pages load
// it from web/pkg/, the same package.
//
//   <script type="module" src="widget.js"></script>
//   <spherekit-view scene='{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]]}'></spherekit-view>
//
// or from a module: import { mount } from './widget.js'; mount(element, sceneJsonText).
// The view fills the width of its element (at most `size` CSS pixels when given) and follows
// it when the page is resized; its plot and legend text is at least 11 CSS pixels. A bad scene
// shows the CLI's message as text in place of the view.
import init, * as sk from './spherekit_wasm.js';
import { drawBodies } from './draw.js';

let loading = null;
/** Loads the wasm module once for all widgets on the page. */
function ready() {
  loading ??= init({ module_or_path: new URL('./spherekit_wasm_bg.wasm', import.meta.url) });
  return loading;
}

/** The smallest text of the figure by default, CSS pixels per em (as the playground's); 0 draws
 * the figure as the CLI renders it at the view's size (the golden images). */
const MIN_TEXT = 11;

const STYLE = `
spherekit-view { display: block; min-width: 0; }
.skv { display: flex; flex-direction: column; gap: 4px; font: 14px system-ui, sans-serif; max-width: 100%; }
.skv-stage { position: relative; line-height: 0; }
.skv-stage canvas { display: block; }
.skv-overlay { position: absolute; left: 0; top: 0; cursor: grab; touch-action: none; }
.skv-bar { display: flex; gap: 6px; align-items: center; }
.skv-bar button { font: inherit; padding: 1px 8px; border: 1px solid #ccd; border-radius: 4px; background: #fff; cursor: pointer; }
.skv-bar input { flex: 1; min-width: 0; }
.skv-bar a { color: #0072b2; white-space: nowrap; }
.skv-error { color: #b3261e; font-family: ui-monospace, monospace; white-space: pre-wrap; max-width: 100%; margin: 0; }
`;

function injectStyle() {
  if (document.getElementById('spherekit-view-style')) return;
  const style = document.createElement('style');
  style.id = 'spherekit-view-style';
  style.textContent = STYLE;
  document.head.append(style);
}

/**
 * Shows `scene` (JSON text) in `element`: the rendered sphere, as wide as the element (at most
 * `size` CSS pixels when given), drag to turn it, a play button that animates t and, when
 * `playground` (a URL, relative to the page) is given, a link that opens the scene there
 * (`<playground>#scene=…`). Its plot and legend text is at least `minText` CSS pixels (11; 0
 * draws the CLI's picture at that size exactly). Resolves to a handle `{ pg, redraw, destroy }`, or null for a bad
 * scene (whose message is shown as text). `element.dataset.state` becomes "ready" or "error".
 */
export async function mount(element, scene, { size = Infinity, playground = null, minText = MIN_TEXT } = {}) {
  await ready();
  injectStyle();
  element.replaceChildren();
  const root = document.createElement('div');
  root.className = 'skv';
  element.append(root);
  let pg;
  try {
    pg = new sk.Playground(scene);
  } catch (e) {
    const p = document.createElement('p');
    p.className = 'skv-error';
    p.textContent = `error: ${e instanceof Error ? e.message : String(e)}`;
    root.append(p);
    element.dataset.state = 'error';
    return null;
  }
  const dpr = window.devicePixelRatio || 1;
  pg.set_min_text(minText * dpr);
  let px = 0;
  /** The render width for the element's current width. */
  const fit = () => {
    const css = Math.min(size, element.getBoundingClientRect().width || 260);
    return Math.max(64, Math.min(2048, Math.round(css * dpr)));
  };
  px = fit();
  const stage = document.createElement('div');
  stage.className = 'skv-stage';
  const canvas = document.createElement('canvas');
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', 'spherekit scene');
  const overlay = document.createElement('canvas');
  overlay.className = 'skv-overlay';
  stage.append(canvas, overlay);
  const bar = document.createElement('div');
  bar.className = 'skv-bar';
  const play = document.createElement('button');
  play.type = 'button';
  play.textContent = '▶';
  play.title = 'Play';
  // t in the curves' own units, over the scene's time axis (as in the playground).
  const [t0, t1] = Array.from(pg.time_axis());
  const slider = document.createElement('input');
  slider.type = 'range';
  slider.min = String(t0);
  slider.max = String(t1);
  slider.step = 'any';
  slider.value = String(t0);
  slider.setAttribute('aria-label', 'Parameter t');
  bar.append(play, slider);
  if (playground) {
    const open = document.createElement('a');
    open.href = `${new URL(playground, document.baseURI).href}#scene=${encodeURIComponent(pg.scene_json())}`;
    open.textContent = 'Playground ↗';
    open.title = 'Open this scene in the playground';
    open.className = 'skv-open';
    bar.append(open);
  }
  const error = document.createElement('p');
  error.className = 'skv-error';
  error.hidden = true;
  root.append(stage, bar, error);

  let t = t0;
  let playing = false;
  const drawOverlay = () => {
    const ctx = overlay.getContext('2d');
    ctx.clearRect(0, 0, overlay.width, overlay.height);
    if (playing || t > t0) drawBodies(ctx, pg, t, px);
  };
  const redraw = () => {
    try {
      pg.draw(canvas, px);
      error.hidden = true;
    } catch (e) {
      error.textContent = `error: ${e.message}`;
      error.hidden = false;
    }
    for (const c of [canvas, overlay]) {
      c.style.width = `${canvas.width / dpr}px`;
      c.style.height = `${canvas.height / dpr}px`;
    }
    overlay.width = canvas.width;
    overlay.height = canvas.height;
    drawOverlay();
  };

  let drag = null;
  const at = (ev) => {
    const r = overlay.getBoundingClientRect();
    return [(ev.clientX - r.left) * (overlay.width / r.width), (ev.clientY - r.top) * (overlay.width / r.width)];
  };
  overlay.addEventListener('pointerdown', (ev) => {
    overlay.setPointerCapture(ev.pointerId);
    const [x, y] = at(ev);
    drag = { x, y, camera: pg.camera() };
  });
  overlay.addEventListener('pointermove', (ev) => {
    if (!drag) return;
    const [x, y] = at(ev);
    try {
      pg.drag_view(new Float64Array(drag.camera), drag.x, drag.y, x, y, px);
      redraw();
    } catch { /* the view keeps its last camera */ }
  });
  const end = () => { drag = null; };
  overlay.addEventListener('pointerup', end);
  overlay.addEventListener('pointercancel', end);

  let last = 0;
  const tick = (now) => {
    if (!playing || !element.isConnected) return;
    // Four seconds for the whole time axis.
    t += last ? ((now - last) / 4000) * (t1 - t0) : 0;
    if (t > t1) t = t0 + ((t - t0) % (t1 - t0 || 1));
    last = now;
    slider.value = String(t);
    drawOverlay();
    requestAnimationFrame(tick);
  };
  play.addEventListener('click', () => {
    playing = !playing;
    play.textContent = playing ? '■' : '▶';
    play.title = playing ? 'Pause' : 'Play';
    last = 0;
    if (playing) requestAnimationFrame(tick);
  });
  slider.addEventListener('input', () => {
    t = Number(slider.value);
    drawOverlay();
  });

  redraw();
  // The column's width changes with the window: render at the new width.
  const resized = new ResizeObserver(() => {
    const next = fit();
    if (next !== px) {
      px = next;
      redraw();
    }
  });
  resized.observe(element);
  element.dataset.state = 'ready';
  return {
    pg,
    redraw,
    destroy() {
      playing = false;
      resized.disconnect();
      element.replaceChildren();
      pg.free();
    },
  };
}

/** `<spherekit-view scene="…" size="…" playground="…" min-text="…">`: the widget as a custom
 * element (`size`: the largest width, CSS pixels; without it the view fills the element's width;
 * `min-text`: the smallest text, CSS pixels, 11 by default). */
class SpherekitView extends HTMLElement {
  connectedCallback() {
    if (this.started) return;
    this.started = true;
    const size = Number(this.getAttribute('size')) || Infinity;
    const playground = this.getAttribute('playground');
    const minAttr = this.getAttribute('min-text');
    const minText = minAttr === null ? MIN_TEXT : Math.max(0, Number(minAttr) || 0);
    mount(this, this.getAttribute('scene') ?? '', { size, playground, minText }).catch((e) => {
      this.textContent = `error: ${e.message}`;
      this.dataset.state = 'error';
    });
  }
}

if (!customElements.get('spherekit-view')) customElements.define('spherekit-view', SpherekitView);
