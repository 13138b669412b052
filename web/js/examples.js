// The example menu: the golden scenes (pkg/presets.json) grouped by method, with readable names and
// one-line descriptions. A scene missing from EXAMPLES (a new golden) still appears, under its
// method with its file name and the method's registry summary, so adding a method needs no edit
// here.

/** The scene the page opens on: an S² scene with a plot, the easiest to read. */
export const FIRST = 'cubic_s2';

/** name → [readable name, what it shows]. */
const EXAMPLES = {
  catmull_rom_s2: ['Catmull–Rom through seven points', 'A smooth curve through points on the globe; its speed is plotted below.'],
  catmull_rom_s3: ['Catmull–Rom through six orientations', 'A body turning smoothly through six key orientations (traced by its axis tips).'],
  geodesic_s2: ['Great-circle arcs (S²)', 'The shortest path between consecutive points: corners at the points, constant speed on each arc.'],
  geodesic_s3: ['Slerp between orientations', 'Piecewise slerp: constant angular speed on each piece, jumps of ω at the keys.'],
  geodesic_s1_equator: ['Arcs on the circle (S¹)', 'Points on the equator joined by arcs of the circle.'],
  nlerp_s2: ['Normalised linear interpolation (S²)', 'Straight chords pushed onto the sphere: the path of slerp, but the speed sags mid-arc.'],
  nlerp_s3_no_canonicalize: ['Nlerp without hemisphere fix (S³)', 'Keys left on opposite hemispheres: the long way round between some of them.'],
  compare_geodesic_nlerp_s2: ['Slerp and nlerp compared', 'Same path, different speed: the plot shows nlerp speeding up near the points.'],
  bezier_s2_cubic: ['Cubic Bézier by de Casteljau (S²)', 'One spherical Bézier curve; the control polygon is drawn thin.'],
  bezier_s3: ['Bézier of orientations', 'Spherical de Casteljau on unit quaternions.'],
  bezier_kim_s3: ['Kim’s Bézier of orientations', 'The Kim–Kim–Shin cumulative-basis Bézier curve on S³.'],
  bspline_kim_s3: ['Kim’s cubic B-spline of orientations', 'A C² approximating curve: it passes near, not through, the keys.'],
  squad_s3: ['Squad', 'Shoemake’s spherical quadrangle interpolation through six keys.'],
  squad_s3_nonuniform: ['Squad with uneven key times', 'The same keys at uneven times; body frames show the turning.'],
  beta_s2_example1: ['Beta spline, β₁ = 1 (S²)', 'Move the β₁ bias: most values have no interpolating Beta spline, and the page says so.'],
  beta_s2_example2_bias: ['Beta spline, three biases', 'One set of points, three β₁ settings side by side.'],
  beta_s2_tension_jacobi: ['Beta spline with tension 4', 'β₂ = 4 pulls the curve towards its control polygon (Jacobi solver).'],
  beta_s3: ['Beta spline of orientations', 'The Beta spline on unit quaternions.'],
  gamma_example1: ['Gamma spline', 'Boehm’s Gamma spline on S³ with γ = 1.'],
  gamma_example2_both_readings: ['Gamma spline, two readings of the last edge', 'The default reading of the last edge and the paper’s example, drawn together.'],
  arc_blend_s2_fig_8_3: ['Pobegailo’s arc blend (S²)', 'Circle arcs through consecutive triples of points, blended into one smooth curve.'],
  arc_blend_s3: ['Blended arcs of orientations', 'The arc blend on S³, smoothness 3 (C³), with body frames.'],
  corner_blend_s2_fig_8_5: ['Pobegailo’s corner blend (S²)', 'Great-circle arcs with their corners rounded off (smoothness 2: C²).'],
  corner_blend_s3: ['Corner blend of orientations', 'Slerp with rounded corners at the keys.'],
  cubic_s2: ['Cubic spline (S²)', 'A C² spline through five points, each reached at its own time (the knots).'],
  cubic_s3: ['Cubic rotation spline (scipy ends)', 'The C² rotation spline with scipy’s RotationSpline end conditions.'],
  cubic_s3_closed: ['Closed cubic rotation spline', 'A periodic C² loop through four tilts of the body: its z axis circles round, turning at a steady rate. (A traced axis tip may turn sharply where the body spins about that axis, although the rotation itself is C².)'],
  closed_loops_s2: ['Closed loops (S²)', 'Great-circle arcs, Catmull–Rom and a Beta spline through the same five points, each closed into a loop.'],
  closed_loops_s3: ['Closed loops of orientations', 'Squad, Kim’s B-spline and the Gamma spline, each a loop through the same four keys.'],
  compare_catmull_rom_nlerp_s2: ['Catmull–Rom by slerps and normalised (S²)', 'The same points: the slerp pyramid keeps an even pace, the normalised Euclidean one speeds up and slows down; great-circle arcs for reference.'],
  compare_catmull_rom_nlerp_s3: ['Catmull–Rom by slerps and normalised (S³)', 'The same keys on S³: compare the speed plots of the two Catmull–Rom constructions.'],
  corner_blend_s2_fig_8_1_small_circles: ['Corner blend on small circles', 'Legs along small circles (bend), two blend orders and cut-backs, as in Pobegailo’s figure 8.1.'],
  corner_blend_s2_fig_8_4_cuts: ['Corner blend with uneven cuts', 'Each corner cut back by its own amount on each side, after a slow start.'],
  figure_arclength_s2: ['Constant speed (S²)', 'A Catmull–Rom curve and the same curve at unit speed: the plot shows the difference.'],
  figure_arclength_s3: ['Constant angular speed', 'Squad and the same squad reparametrised by arc length (|ω| = 1).'],
  cubic_s3_orbit: ['A 360° camera orbit', 'Eight keys 45° of yaw apart with a pitch wobble, closed: one full turn is a loop of rotations (its quaternions end at −q₀, the same rotation), turning at a steady rate all the way round.'],
  compare_s3_squad_catmull_bspline_arcblend: ['Four S³ methods compared', 'Squad, Catmull–Rom, Kim’s B-spline and the arc blend through the same keys.'],
  figure_legend_labels_s2: ['Curve labels in the legend', 'Three methods through the same points, labelled.'],
  figure_omega_s2: ['Velocity components (S²)', 'The plot shows p′ in x, y and z as well as the speed.'],
  figure_omega_s3: ['Angular velocity components', 'The plot shows ω in x, y and z (space frame) and |ω|.'],
  figure_plot_time_normalized: ['Normalised time axis', 'Two curves with different domains plotted against u = t normalised per curve.'],
  figure_s3_axes_legend: ['Tracing chosen body axes', 'Only the body x and z axes are traced.'],
  figure_shared_time_axis: ['Shared time axis', 'Two curves with different domains on one t axis.'],
  figure_title: ['A figure with a title', 'view.title above the sphere.'],
  fit_noisy_s2: ['Smoothing spline of noisy directions (S²)', 'Eighty samples of a smooth track with 1° of noise: the C² cubic fitted to them passes near the samples (rings) through its own keys (dots). Slide λ or press GCV; the lower plot shows each sample’s residual.'],
  fit_noisy_s3: ['Smoothing spline of noisy rotations', 'Sixty-four noisy orientations, a quarter of them given as −q (the same rotation): the fitted rotation spline and each sample’s residual angle. Slide λ, press GCV or give a target rms.'],
};

/** A golden file name as a label when EXAMPLES lacks it: `arc_blend_s2_x` → `arc blend on S² x`. */
function fileLabel(name) {
  return name
    .replace(/_s([123])(?=_|$)/g, (_, d) => ` on S${'¹²³'[d - 1]}`)
    .replace(/_fig_(\d+)_(\d+)/, ' (fig. $1.$2)')
    .replace(/example(\d)/, 'example $1')
    .replaceAll('_', ' ');
}

/**
 * The examples as menu groups `[{ group, items: [{ name, label, about, space }] }]`: one group
 * per method, named as the registry names it (a scene with several methods goes to
 * "Comparisons", the figure options to "Figure options", a curve fitted to samples to "Fitted to
 * samples"), S² scenes first within a group.
 */
export function exampleGroups(presets, methodOf) {
  const groups = new Map();
  for (const p of presets) {
    const scene = JSON.parse(p.scene);
    const methods = [...new Set((scene.curves ?? [scene]).map((c) => c.method ?? scene.method))];
    const fitted = (scene.curves ?? [scene]).some((c) => c.fit);
    const group = p.name.startsWith('figure_') ? 'Figure options' : methods.length > 1 ? 'Comparisons' : fitted ? 'Fitted to samples' : methodOf(methods[0])?.name ?? methods[0];
    const [label, about] = EXAMPLES[p.name] ?? [fileLabel(p.name), methodOf(methods[0])?.summary ?? ''];
    if (!groups.has(group)) groups.set(group, []);
    groups.get(group).push({ name: p.name, label, about, space: scene.space });
  }
  const order = (g) => (g === 'Comparisons' ? 1 : g === 'Figure options' ? 2 : 0);
  const rank = (s) => (s === 'S2' ? 0 : s === 'S3' ? 1 : 2);
  return [...groups.entries()]
    .sort((a, b) => order(a[0]) - order(b[0]))
    .map(([group, items]) => ({ group, items: items.sort((a, b) => rank(a.space) - rank(b.space)) }));
}

/** The description of example `name`, or ''. */
export function aboutExample(groups, name) {
  for (const g of groups) for (const it of g.items) if (it.name === name) return it.about;
  return '';
}
