// The play button and the t slider, in the curves' own parameter units (the scene's time axis,
// pg.time_axis()); the slider, the readout, the table and the plot cursor share state.t.
import { $, state } from './state.js';
import { setTime } from './panels.js';

let lastTick = 0;
function tick(now) {
  if (!state.playing) return;
  const dt = lastTick ? (now - lastTick) / 1000 : 0;
  lastTick = now;
  const [t0, t1] = state.axis;
  const span = t1 - t0;
  // Four seconds for the whole axis.
  let t = state.t + (dt * span) / 4;
  if (t > t1) t = t0 + ((t - t0) % (span || 1));
  setTime(t);
  requestAnimationFrame(tick);
}

export function setPlaying(on) {
  state.playing = on;
  $('play').textContent = on ? '■ Pause' : '▶ Play';
  lastTick = 0;
  if (on) requestAnimationFrame(tick);
}

export function installAnimation() {
  $('play').addEventListener('click', () => setPlaying(!state.playing));
  $('t').addEventListener('input', () => setTime(Number($('t').value)));
}
