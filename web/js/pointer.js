// Pointer, wheel and keyboard: pick and drag a point or a key's axis tip, turn the view,
// double-click to add a point (a single click on empty sphere only deselects), click or drag on
// the plot to move t, wheel or pinch to zoom, hover feedback, Ctrl+Z / Ctrl+Shift+Z; with the
// sphere focused, Tab through the points, arrow keys to move the selected one or turn the view,
// Delete, Escape, + and −. Picking, drags and rotations are Rust's; edits of a key go to every
// curve that shares it (keys.js).
//
// The pointer-move handler only records where the pointer is: the edit and the render happen
// once per animation frame (view.redraw's task), at reduced resolution while the drag lasts
// (state.quick); the URL, the JSON box and the table follow when the drag ends.
import { $, state, attempt, commit } from './state.js';
import { redraw, drawOverlay, plotAt, timeAt, pointOnCanvas, keyAxisOnScreen } from './view.js';
import { changed, renderPanels, deleteSelected, setTime, stepHistory, linkSoon } from './panels.js';
import { sharing, moveKeyTo, dragKey, addKeyAt } from './keys.js';
import { holdSearchedLambda } from './fit.js';

/** Durations (ms) of the last pointer-move handler runs (the bench reads them). */
export const moveTimes = [];

function devicePoint(ev) {
  const r = $('overlay').getBoundingClientRect();
  const sx = $('overlay').width / r.width;
  return [(ev.clientX - r.left) * sx, (ev.clientY - r.top) * sx];
}

let drag = null;
let still = 0;
const pointers = new Map(); // pointerId → [clientX, clientY], for pinch
let pinch = null;

/** Ends reduced-resolution drawing soon after the last zoom step or when a drag ends. */
let settle = 0;
function quickFor(ms) {
  state.quick = true;
  clearTimeout(settle);
  settle = setTimeout(() => {
    if (drag || pinch) return;
    state.quick = false;
    redraw();
  }, ms);
}

function setZoom(z) {
  state.zoom = Math.min(2.5, Math.max(0.5, z));
  quickFor(180);
  redraw();
  linkSoon();
}

function onDown(ev) {
  pointers.set(ev.pointerId, [ev.clientX, ev.clientY]);
  try {
    $('overlay').setPointerCapture(ev.pointerId);
  } catch {
    // A pointer the browser does not know as active (a synthetic one) cannot be captured.
  }
  if (pointers.size === 2) {
    // A second finger: pinch to zoom (the drag in progress stops where it is).
    const [a, b] = [...pointers.values()];
    releaseHold(drag);
    if (drag?.before !== undefined) commit(drag.before);
    drag = null;
    pinch = { d0: Math.hypot(a[0] - b[0], a[1] - b[1]) || 1, zoom0: state.zoom };
    return;
  }
  const [x, y] = devicePoint(ev);
  const plot = plotAt(x, y);
  if (plot) {
    drag = { kind: 'scrub', plot };
    setTime(timeAt(plot, x));
    return;
  }
  if (y > state.size) return; // below the sphere, outside the plots: the legend
  const before = state.pg.scene_json();
  const hit = state.pg.pick(x, y, state.size, 12 * Math.max(1, state.size / 512));
  if (hit) {
    const [c, i] = hit;
    state.selected = [c, i];
    state.activeCurve = c;
    attempt(() => state.pg.pin_camera(), { record: false });
    drag = { kind: 'point', c, i, x0: x, y0: y, key0: state.pg.point(c, i), moved: false, before, linked: sharing(c) };
    renderPanels();
  } else {
    drag = { kind: 'view', x0: x, y0: y, camera0: state.pg.camera(), moved: false, before };
  }
  $('overlay').classList.add('dragging');
  redraw();
}

function onMove(ev) {
  const start = performance.now();
  if (pointers.has(ev.pointerId)) pointers.set(ev.pointerId, [ev.clientX, ev.clientY]);
  if (pinch && pointers.size === 2) {
    const [a, b] = [...pointers.values()];
    const z = pinch.zoom0 * (Math.hypot(a[0] - b[0], a[1] - b[1]) / pinch.d0);
    redraw(() => setZoom(z));
  } else if (drag) {
    const [x, y] = devicePoint(ev);
    if (drag.kind === 'scrub') {
      drag.x = x;
      redraw(scrubStep);
    } else if (drag.moved || Math.hypot(x - drag.x0, y - drag.y0) >= 3) {
      if (!drag.moved && drag.kind === 'point') {
        const d = drag;
        attempt(() => { d.release = holdSearchedLambda(state.pg, d.linked); }, { record: false });
      }
      drag.moved = true;
      drag.x = x;
      drag.y = y;
      state.quick = true;
      redraw(dragStep);
      // The pointer held still: the full-resolution frame, until it moves again.
      clearTimeout(still);
      still = setTimeout(() => {
        if (!drag?.moved) return;
        state.quick = false;
        redraw();
      }, 150);
    }
  } else {
    hover(ev);
  }
  moveTimes.push(performance.now() - start);
  if (moveTimes.length > 2000) moveTimes.splice(0, 1000);
}

function scrubStep() {
  if (drag?.kind === 'scrub' && drag.x !== undefined) setTime(timeAt(drag.plot, drag.x));
}

/** A fitted curve whose λ is searched for (GCV, a target rms) keeps the λ last chosen while
 * one of its samples is dragged (fit.js); when the drag ends, the search runs once more. */
function releaseHold(d) {
  if (!d?.release) return;
  const release = d.release;
  d.release = null;
  attempt(release, { record: false });
}

/** The drag's edit, once per frame, from the latest pointer position. */
function dragStep(d = drag) {
  if (!d || d.x === undefined || d.done === d.x + d.y * 1e6) return;
  d.done = d.x + d.y * 1e6;
  const pg = state.pg;
  const [x, y] = [d.x, d.y];
  let ok;
  if (d.kind === 'view') {
    ok = attempt(() => pg.drag_view(new Float64Array(d.camera0), d.x0, d.y0, x, y, state.size), { record: false });
  } else if (d.key0.length === 4) {
    ok = attempt(() => dragKey(d.linked, d.i, d.key0, d.x0, d.y0, x, y, state.size), { record: false });
  } else {
    ok = attempt(() => moveKeyTo(d.linked, d.i, x, y, state.size), { record: false });
  }
  if (ok) changed({ panels: false, light: true });
}

/** Hover: the pointer cursor and a ring over a draggable point, a column cursor over a plot. */
function hover(ev) {
  const [x, y] = devicePoint(ev);
  const overlay = $('overlay');
  const onPlot = Boolean(plotAt(x, y));
  const hit = !onPlot && y <= state.size ? state.pg.pick(x, y, state.size, 12 * Math.max(1, state.size / 512)) : null;
  const key = hit ? [hit[0], hit[1]] : null;
  overlay.classList.toggle('over-point', Boolean(key));
  overlay.classList.toggle('over-plot', onPlot);
  const same = (a, b) => (a === b) || (a && b && a[0] === b[0] && a[1] === b[1]);
  if (!same(key, state.hover)) {
    state.hover = key;
    drawOverlay(); // only the overlay changes
  }
}

function onUp(ev) {
  pointers.delete(ev.pointerId);
  if (pinch) {
    if (pointers.size < 2) {
      pinch = null;
      quickFor(0);
    }
    return;
  }
  $('overlay').classList.remove('dragging');
  if (!drag) return;
  const d = drag;
  drag = null;
  if (d.kind === 'scrub') return;
  state.quick = false;
  if (d.moved) {
    dragStep(d); // the last position, if its frame has not run yet
    releaseHold(d);
    commit(d.before);
    changed();
    return;
  }
  if (d.kind === 'point') {
    changed(); // selected (the camera pinned), nothing moved
    return;
  }
  // A click (no drag) on empty space deselects (a double-click adds a point: onDoubleClick).
  if (state.selected) {
    state.selected = null;
    renderPanels();
    redraw();
  }
}

/** A double-click on empty sphere appends the point there to the active curve (and to the
 * curves sharing its keys), selected; one undoable edit. */
function onDoubleClick(ev) {
  const [x, y] = devicePoint(ev);
  if (plotAt(x, y) || y > state.size) return;
  if (Math.hypot(x - state.size / 2, y - state.size / 2) > 0.45 * state.size) return;
  if (state.pg.pick(x, y, state.size, 12 * Math.max(1, state.size / 512))) return;
  const before = state.pg.scene_json();
  const c = Math.min(state.activeCurve, state.pg.curve_count() - 1);
  const count = JSON.parse(state.pg.curve_json(c)).points.length;
  const linked = sharing(c);
  if (attempt(() => {
    state.pg.pin_camera();
    addKeyAt(linked, x, y, state.size);
  }, { record: false })) {
    commit(before);
    state.selected = [c, count];
    changed();
  }
}

function onCancel(ev) {
  pointers.delete(ev.pointerId);
  pinch = null;
  releaseHold(drag);
  if (drag?.before !== undefined) commit(drag.before);
  drag = null;
  state.quick = false;
  $('overlay').classList.remove('dragging');
  changed();
}

function onWheel(ev) {
  ev.preventDefault();
  setZoom(state.zoom * Math.exp(-ev.deltaY * 0.0015));
}

const typing = () => ['INPUT', 'TEXTAREA', 'SELECT'].includes(document.activeElement?.tagName);

/** Every pickable point as [curve, index], curve by curve (Tab's order). Keys shared by
 * several curves are listed once, under the first. */
function keyList() {
  const pg = state.pg;
  const out = [];
  const seen = new Set();
  for (let c = 0; c < pg.curve_count(); c++) {
    const group = sharing(c).sort((a, b) => a - b);
    if (seen.has(group[0])) continue;
    for (const k of group) seen.add(k);
    const n = JSON.parse(pg.curve_json(c)).points.length;
    for (let i = 0; i < n; i++) out.push([c, i]);
  }
  return out;
}

/** The step of an arrow key, device pixels. */
const STEP = 10;

/**
 * Keys on the focused sphere: Tab / Shift+Tab select the next / previous point (past the last
 * one, focus moves on as usual); arrows move the selected point, or turn the view when none
 * is selected; Escape deselects; + and − zoom. Each arrow press is one undoable edit.
 */
function onCanvasKey(ev) {
  const pg = state.pg;
  if (ev.key === 'Tab') {
    const keys = keyList();
    const at = state.selected ? keys.findIndex(([c, i]) => c === state.selected[0] && i === state.selected[1]) : -1;
    const next = at + (ev.shiftKey ? -1 : 1);
    if ((state.selected === null && ev.shiftKey) || next < 0 || next >= keys.length) {
      state.selected = null;
      renderPanels();
      redraw();
      return; // focus leaves the sphere
    }
    ev.preventDefault();
    state.selected = keys[next];
    state.activeCurve = keys[next][0];
    renderPanels();
    redraw();
    return;
  }
  if (ev.key === 'Escape') {
    if (state.selected) {
      state.selected = null;
      renderPanels();
      redraw();
    }
    return;
  }
  if (ev.key === '+' || ev.key === '=' || ev.key === '-' || ev.key === '−') {
    ev.preventDefault();
    setZoom(state.zoom * (ev.key === '-' || ev.key === '−' ? 1 / 1.15 : 1.15));
    return;
  }
  const arrows = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] };
  const dir = arrows[ev.key];
  if (!dir) return;
  ev.preventDefault();
  const step = STEP * state.dpr * (ev.shiftKey ? 4 : 1);
  const [dx, dy] = [dir[0] * step, dir[1] * step];
  const before = pg.scene_json();
  let ok;
  if (state.selected) {
    const [c, i] = state.selected;
    const linked = sharing(c);
    const key = pg.point(c, i);
    // The camera is pinned first (moving points must not move a default camera).
    if (key.length === 4) {
      // A key turns as if its z axis tip were dragged.
      const [x, y] = keyAxisOnScreen(key, 2);
      ok = attempt(() => {
        pg.pin_camera();
        dragKey(linked, i, key, x, y, x + dx, y + dy, state.size);
      }, { record: false });
    } else {
      const [x, y] = pointOnCanvas(key);
      ok = attempt(() => {
        pg.pin_camera();
        moveKeyTo(linked, i, x + dx, y + dy, state.size);
      }, { record: false });
    }
  } else {
    // The view turns as if the sphere's centre were dragged.
    const c = state.size / 2;
    ok = attempt(() => pg.drag_view(new Float64Array(pg.camera()), c, c, c + dx, c + dy, state.size), { record: false });
  }
  if (ok) {
    commit(before);
    changed();
  }
}

/** Listens on the overlay canvas, and for the keyboard outside form fields. */
export function installPointer() {
  const overlay = $('overlay');
  overlay.addEventListener('pointerdown', onDown);
  overlay.addEventListener('pointermove', onMove);
  overlay.addEventListener('pointerup', onUp);
  overlay.addEventListener('pointercancel', onCancel);
  overlay.addEventListener('pointerleave', () => {
    if (!drag && state.hover) {
      state.hover = null;
      drawOverlay();
    }
  });
  overlay.addEventListener('wheel', onWheel, { passive: false });
  overlay.addEventListener('keydown', onCanvasKey);
  overlay.addEventListener('dblclick', onDoubleClick);
  window.addEventListener('keydown', (ev) => {
    const mod = ev.ctrlKey || ev.metaKey;
    if (mod && !typing() && (ev.key === 'z' || ev.key === 'Z')) {
      ev.preventDefault();
      stepHistory(ev.shiftKey ? 1 : -1);
    } else if (mod && !typing() && ev.key === 'y') {
      ev.preventDefault();
      stepHistory(1);
    } else if ((ev.key === 'Delete' || ev.key === 'Backspace') && !typing()) {
      deleteSelected();
    }
  });
  $('undo').addEventListener('click', () => stepHistory(-1));
  $('redo').addEventListener('click', () => stepHistory(1));
  $('reset-view').addEventListener('click', () => {
    state.zoom = 1;
    if (attempt(() => state.pg.set_view('camera', 'null'))) changed();
  });
}
