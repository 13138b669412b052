// The play button and the t slider: the animated body (S³) or point (S²) on the overlay.
import { $, state } from './state.js';
import { drawOverlay } from './view.js';

let lastTick = 0;
function tick(now) {
  if (!state.playing) return;
  const dt = lastTick ? (now - lastTick) / 1000 : 0;
  lastTick = now;
  state.u = (state.u + dt / 4) % 1;
  $('t').value = String(state.u);
  $('t-out').textContent = state.u.toFixed(3);
  drawOverlay();
  requestAnimationFrame(tick);
}

function setPlaying(on) {
  state.playing = on;
  $('play').textContent = on ? '■ Pause' : '▶ Play';
  lastTick = 0;
  if (on) requestAnimationFrame(tick);
}

export function installAnimation() {
  $('play').addEventListener('click', () => setPlaying(!state.playing));
  $('t').addEventListener('input', () => {
    state.u = Number($('t').value);
    $('t-out').textContent = state.u.toFixed(3);
    drawOverlay();
  });
}
