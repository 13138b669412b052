// Drawing over the rendered image, shared by the playground and the docs widget: the body
// rotating by an S³ curve (its axis triad and its angular velocity ω) or a point moving along an
// S² curve at time t on the scene's time axis (pg.time_axis(): the curves' own t). Positions,
// vectors and colours come from the wasm handle (eval, readout, project, axis_colors); no math
// here beyond scaling a vector to the sphere.

/** Draws every curve's moving body or point at time `t` (each curve clamped to its domain) on a
 * 2D context, with the ω arrow of S³ curve `omega` (default: every S³ curve). */
export function drawBodies(ctx, pg, t, size, omega = null) {
  const k = size / 512;
  const colors = JSON.parse(pg.colors());
  const axisColors = JSON.parse(pg.axis_colors());
  const several = pg.curve_count() > 1;
  for (let c = 0; c < pg.curve_count(); c++) {
    const v = pg.eval(c, t);
    if (v.length === 13) {
      // S³: a rigid body, its axis triad from the centre to the rotated tips (far ones first).
      const o = pg.project(0, 0, 0, size);
      const tips = [0, 1, 2].map((a) => ({ a, p: pg.project(v[4 + 3 * a], v[5 + 3 * a], v[6 + 3 * a], size) }));
      tips.sort((x, y) => x.p[2] - y.p[2]);
      for (const { a, p } of tips) {
        ctx.globalAlpha = p[2] < 0 ? 0.5 : 1;
        ctx.strokeStyle = several ? colors[c] : axisColors[a];
        ctx.lineWidth = (a === 2 ? 7 : 4) * k;
        ctx.lineCap = 'round';
        ctx.beginPath();
        ctx.moveTo(o[0], o[1]);
        ctx.lineTo(p[0], p[1]);
        ctx.stroke();
        ctx.fillStyle = axisColors[a];
        ctx.beginPath();
        ctx.arc(p[0], p[1], (a === 2 ? 8 : 6) * k, 0, 2 * Math.PI);
        ctx.fill();
      }
      ctx.globalAlpha = 1;
      if (omega === null || omega === c) drawOmega(ctx, pg, c, t, size, o, several ? colors[c] : '#1f2328');
    } else {
      const p = v.length === 2 ? pg.project(v[0], v[1], 0, size) : pg.project(v[0], v[1], v[2], size);
      ctx.globalAlpha = p[2] < 0 ? 0.5 : 1;
      ctx.fillStyle = colors[c];
      ctx.strokeStyle = '#fff';
      ctx.lineWidth = 2.5 * k;
      ctx.beginPath();
      ctx.arc(p[0], p[1], 9 * k, 0, 2 * Math.PI);
      ctx.fill();
      ctx.stroke();
    }
    ctx.globalAlpha = 1;
  }
}

/**
 * Curve `c`'s angular velocity ω at t as an arrow from the sphere's centre `o` along ω's axis
 * to the sphere (the physical vector: the same arrow whichever frame the readout uses),
 * labelled ω; dashed when it points away from the viewer. Nothing while the body is at rest.
 */
function drawOmega(ctx, pg, c, t, size, o, color) {
  const w = JSON.parse(pg.readout(c, t, 'space')).omega;
  const n = Math.hypot(...w);
  if (!(n > 1e-9)) return;
  const k = size / 512;
  const tip = pg.project(w[0] / n, w[1] / n, w[2] / n, size);
  const [dx, dy] = [tip[0] - o[0], tip[1] - o[1]];
  const len = Math.hypot(dx, dy);
  ctx.save();
  ctx.strokeStyle = color;
  ctx.fillStyle = color;
  ctx.lineWidth = 2.5 * k;
  ctx.setLineDash(tip[2] < 0 ? [6 * k, 4 * k] : []);
  ctx.beginPath();
  ctx.moveTo(o[0], o[1]);
  ctx.lineTo(tip[0], tip[1]);
  ctx.stroke();
  ctx.setLineDash([]);
  if (len > 12 * k) {
    const [ux, uy] = [dx / len, dy / len];
    const head = 14 * k;
    ctx.beginPath();
    ctx.moveTo(tip[0], tip[1]);
    ctx.lineTo(tip[0] - head * ux - 0.5 * head * uy, tip[1] - head * uy + 0.5 * head * ux);
    ctx.lineTo(tip[0] - head * ux + 0.5 * head * uy, tip[1] - head * uy - 0.5 * head * ux);
    ctx.closePath();
    ctx.fill();
  }
  ctx.font = `italic ${Math.round(18 * k)}px system-ui, sans-serif`;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.lineWidth = 3 * k;
  ctx.strokeStyle = '#fff';
  const [lx, ly] = [tip[0] + (len > 0 ? (dx / len) * 14 * k : 14 * k), tip[1] + (len > 0 ? (dy / len) * 14 * k : 0)];
  ctx.strokeText('ω', lx, ly);
  ctx.fillText('ω', lx, ly);
  ctx.restore();
}
