// Pointer and keyboard: pick and drag a point or a key's axis tip, turn the view, click to add a
// point, Delete to remove the selected one. Picking, drags and rotations are Rust's.
import { $, state, attempt } from './state.js';
import { redraw } from './view.js';
import { changed, renderPanels, deleteSelected } from './panels.js';

function devicePoint(ev) {
  const r = $('overlay').getBoundingClientRect();
  const sx = $('overlay').width / r.width;
  return [(ev.clientX - r.left) * sx, (ev.clientY - r.top) * sx];
}

let drag = null;

function onDown(ev) {
  const [x, y] = devicePoint(ev);
  if (y > state.size) return; // the plot strip
  $('overlay').setPointerCapture(ev.pointerId);
  const hit = state.pg.pick(x, y, state.size, 12 * Math.max(1, state.size / 512));
  if (hit) {
    const [c, i] = hit;
    state.selected = [c, i];
    state.activeCurve = c;
    attempt(() => state.pg.pin_camera());
    drag = { kind: 'point', c, i, x0: x, y0: y, key0: state.pg.point(c, i), moved: false };
    renderPanels();
  } else {
    drag = { kind: 'view', x0: x, y0: y, camera0: state.pg.camera(), moved: false };
  }
  redraw();
}

function onMove(ev) {
  if (!drag) return;
  const [x, y] = devicePoint(ev);
  if (!drag.moved && Math.hypot(x - drag.x0, y - drag.y0) < 3) return;
  drag.moved = true;
  const pg = state.pg;
  let ok;
  if (drag.kind === 'view') {
    ok = attempt(() => pg.drag_view(new Float64Array(drag.camera0), drag.x0, drag.y0, x, y, state.size));
  } else if (drag.key0.length === 4) {
    ok = attempt(() => pg.drag_key(drag.c, drag.i, new Float64Array(drag.key0), drag.x0, drag.y0, x, y, state.size));
  } else {
    ok = attempt(() => pg.move_point_to(drag.c, drag.i, x, y, state.size));
  }
  if (ok) changed({ panels: false });
}

function onUp(ev) {
  if (!drag) return;
  const d = drag;
  drag = null;
  if (d.kind === 'point') {
    renderPanels();
    return;
  }
  if (!d.moved) {
    // A click on the sphere adds a point to the active curve.
    const [x, y] = devicePoint(ev);
    const c = Math.min(state.activeCurve, state.pg.curve_count() - 1);
    const r = 0.45 * state.size;
    if (Math.hypot(x - state.size / 2, y - state.size / 2) <= r && state.pg.space() !== 'S1') {
      const before = JSON.parse(state.pg.curve_json(c)).points.length;
      attempt(() => state.pg.pin_camera());
      if (attempt(() => state.pg.add_point_at(c, x, y, state.size))) {
        state.selected = [c, before];
        changed();
      }
    } else {
      state.selected = null;
      renderPanels();
      redraw();
    }
  }
}

/** Listens on the overlay canvas and for Delete / Backspace outside form fields. */
export function installPointer() {
  const overlay = $('overlay');
  overlay.addEventListener('pointerdown', onDown);
  overlay.addEventListener('pointermove', onMove);
  overlay.addEventListener('pointerup', onUp);
  overlay.addEventListener('pointercancel', () => { drag = null; });
  window.addEventListener('keydown', (ev) => {
    if ((ev.key === 'Delete' || ev.key === 'Backspace') && !['INPUT', 'TEXTAREA', 'SELECT'].includes(document.activeElement?.tagName)) {
      deleteSelected();
    }
  });
}
