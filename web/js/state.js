// The page's shared state and its two error helpers. Every other module reads and writes
// `state`; nothing else is shared between them.

export const $ = (id) => document.getElementById(id);

/** The page's query: `?size=384` (a fixed render size, for the goldens), `?bench`. */
export const query = new URLSearchParams(location.search);

/** A fixed render size (pixels) instead of fitting the window, e.g. ?size=384 for the golden. */
export const fixedSize = query.has('size') ? Number(query.get('size')) : null;

export const state = {
  pg: null,          // sk.Playground
  size: 0,           // render size in device pixels
  dpr: 1,
  selected: null,    // [curve, index]
  activeCurve: 0,    // the curve new points go to
  playing: false,
  u: 0,              // animation fraction of the domain
  methods: [],       // the registry, as sk.methods() gives it
  presets: [],
};

export function showError(message) {
  const el = $('error');
  el.textContent = message ? `error: ${message}` : '';
  el.hidden = !message;
}

/** Runs an edit of the handle; a failure shows its message and leaves the last good state. */
export function attempt(edit) {
  try {
    edit();
    showError('');
    return true;
  } catch (e) {
    showError(e instanceof Error ? e.message : String(e));
    return false;
  }
}

/** Whether a registry `spaces` string ("S2, S3, S<m>" or "S3") includes the scene's space. */
export function inSpaces(spaces, space) {
  const list = spaces.split(', ');
  return list.includes(space) || (list.includes('S<m>') && space !== 'S2' && space !== 'S3');
}

/** The registry entry of a method id (undefined for an unknown one). */
export function methodOf(id) {
  return state.methods.find((m) => m.id === id);
}
