// Shared keys: curves with the same points (a comparison of methods, "Compare with…") are
// edited together, so a drag, a typed coordinate, an added or a deleted point moves every
// one of them. The scene format has no link between curves: curves share their keys while
// their point lists are equal, which undo, shared links and pasted scenes keep. Each edit
// goes to the curve acted on first (Rust computes the point), then the same point to the
// others; if any curve refuses it, the scene is put back as it was and the error is raised.
import { state } from './state.js';

/** The curves whose points equal curve `c`'s (`c` first). */
export function sharing(c) {
  const pg = state.pg;
  const mine = JSON.stringify(JSON.parse(pg.curve_json(c)).points);
  const out = [c];
  for (let k = 0; k < pg.curve_count(); k++) {
    if (k !== c && JSON.stringify(JSON.parse(pg.curve_json(k)).points) === mine) out.push(k);
  }
  return out;
}

/** Runs `edit` as one change of the scene: a failure part-way puts the scene back. */
function together(edit) {
  const before = state.pg.scene_json();
  try {
    edit();
  } catch (e) {
    state.pg.set_scene(before);
    throw e;
  }
}

/** Gives point `i` of every curve in `linked` but the first the first curve's point `i`. */
function follow(linked, i) {
  const p = new Float64Array(state.pg.point(linked[0], i));
  for (const k of linked.slice(1)) state.pg.set_point(k, i, p);
}

/** Sets point `i` of the curves `linked` to `coords`. */
export function setKey(linked, i, coords) {
  together(() => {
    state.pg.set_point(linked[0], i, coords);
    follow(linked, i);
  });
}

/** Moves S² point `i` of the curves `linked` to the sphere point under pixel (x, y). */
export function moveKeyTo(linked, i, x, y, size) {
  together(() => {
    state.pg.move_point_to(linked[0], i, x, y, size);
    follow(linked, i);
  });
}

/** Turns S³ key `i` of the curves `linked` (`key0` at the start of the drag) by a drag. */
export function dragKey(linked, i, key0, x0, y0, x1, y1, size) {
  together(() => {
    state.pg.drag_key(linked[0], i, new Float64Array(key0), x0, y0, x1, y1, size);
    follow(linked, i);
  });
}

/** Appends the point under pixel (x, y) to the curves `linked` (see Playground.add_point_at). */
export function addKeyAt(linked, x, y, size) {
  together(() => {
    state.pg.add_point_at(linked[0], x, y, size);
    const n = JSON.parse(state.pg.curve_json(linked[0])).points.length;
    const p = new Float64Array(state.pg.point(linked[0], n - 1));
    for (const k of linked.slice(1)) state.pg.insert_point(k, n - 1, p);
  });
}

/** Removes point `i` of the curves `linked`. */
export function removeKey(linked, i) {
  together(() => {
    for (const k of linked) state.pg.remove_point(k, i);
  });
}
