// Drawing over the rendered image, shared by the playground and the docs widget: the body
// rotating by an S³ curve (its axis triad) or a point moving along an S² curve at time t on
// the scene's time axis (pg.time_axis(): the curves' own t). Positions come from the wasm
// handle (eval, project); no math here.

const AXIS_COLORS = ['#d55e00', '#009e73', '#0072b2'];

/** Draws every curve's moving body or point at time `t` (each curve clamped to its domain) on a 2D context. */
export function drawBodies(ctx, pg, t, size) {
  const k = size / 512;
  const colors = JSON.parse(pg.colors());
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
        ctx.strokeStyle = several ? colors[c] : AXIS_COLORS[a];
        ctx.lineWidth = (a === 2 ? 7 : 4) * k;
        ctx.lineCap = 'round';
        ctx.beginPath();
        ctx.moveTo(o[0], o[1]);
        ctx.lineTo(p[0], p[1]);
        ctx.stroke();
        ctx.fillStyle = AXIS_COLORS[a];
        ctx.beginPath();
        ctx.arc(p[0], p[1], (a === 2 ? 8 : 6) * k, 0, 2 * Math.PI);
        ctx.fill();
      }
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
