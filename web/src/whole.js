// The whole pattern's fold slider (the first control): every crease P % of the way toward the
// file's target angles, as `orikin fold --percent P` (the server's default fixed face unless one
// is chosen). Each position is one sequence of one fold toward the targets, shown at its end:
// the state is the CLI's exactly. Requests never pile up: while one runs only the latest P waits.
// With "compliant" ticked the slider runs the bar-and-hinge model instead (POST /api/compliant,
// the CLI's `fold --compliant --percent P --json` plus the positions): every pattern folds,
// bending its panels where it must, and the label says how far and how much the sheet strains.
// ctx: {state, $, v3, api, action, runSequence}.
import { faceLabel } from './document.js';

export function createWholeFold(ctx) {
  const { state, $ } = ctx;
  const whole = { want: null, running: false, percent: null };
  async function fold(p) {
    whole.want = p;
    $('whole-value').textContent = `${p} %`;
    if (whole.running) return;
    whole.running = true;
    try {
      while (whole.want !== null) {
        const want = whole.want;
        whole.want = null;
        if (want === 0 && !state.sequence && !$('whole-compliant').checked) continue;
        if ($('whole-compliant').checked) {
          await ctx.action(() => compliant(want));
          continue;
        }
        const f = { name: 'the whole pattern', percent: want };
        if (state.spec.fix >= 0) f.fix = state.spec.fix;
        await ctx.action(async () => {
          await ctx.runSequence(want === 0 ? [] : [f], 'fold');
          // back to the rigid model: a fold that showed no state of its own shows the sheet
          if (want === 0 || state.shown === 'compliant') {
            ctx.v3.setPositions(Float64Array.from(state.doc.vertices.flat()));
            state.shown = 'flat';
            state.shownAngles = null;
            $('state3d').textContent = state.doc.is3d ? 'frame 0 (3D)' : 'flat sheet';
          }
          whole.percent = want;
          const r = state.sequence;
          const fix = r && r.folds && r.folds[0] ? r.folds[0].fix : null;
          const face = fix !== null && fix !== undefined ? `, fixed ${faceLabel(state.doc, fix)}${state.spec.fix >= 0 ? '' : ' (default)'}` : '';
          $('whole-label').textContent = !r ? 'flat' : r.valid ? `${want} % of the way toward the targets${face}`
            : `${r.verdict}: ${r.reason} (tick "compliant" to fold it with bending panels)`;
          $('whole-label').title = $('whole-label').textContent;
        });
      }
    } finally {
      whole.running = false;
    }
  }
  // The compliant fold at p %: the bent sheet in the 3D view, its figures in the label.
  async function compliant(p) {
    const body = { percent: p };
    if (state.spec.fix >= 0) body.fix = state.spec.fix;
    const r = await ctx.api.compute('compliant fold', () => ctx.api.post('compliant', body));
    ctx.store.set({ compliant: r }); // (the Export menu offers its motion)
    ctx.v3.setPositions(Float64Array.from(r.positions.flat()));
    ctx.v3.setFaceColors(r.strain_colors.faces); // as orikin render --color strain paints them
    state.shown = 'compliant';
    state.shownAngles = Float64Array.from(r.fold_angles_deg); // degrees, as the sequence states
    whole.percent = p;
    const bar = r.strain_colors;
    const strain = `max strain ${(100 * r.max_strain).toPrecision(3)} % (faces coloured by strain, ${bar.ticks[0]} to ${bar.ticks[bar.ticks.length - 1]}: blue to yellow)`;
    const text = r.reached
      ? `compliant: ${p} % of the way toward the targets, ${strain}`
      : `compliant: stopped at ${(100 * r.reached_fraction).toPrecision(4)} % (${r.reason}), ${strain}`;
    $('whole-label').textContent = text;
    $('whole-label').title = text;
    $('state3d').textContent = `compliant fold, ${p} %`;
  }
  // A new document: the slider back at 0.
  function reset() {
    $('whole-slider').value = '0';
    $('whole-value').textContent = '0 %';
    $('whole-label').textContent = '';
    ctx.store.set({ compliant: null });
  }
  return { fold, reset, running: () => whole.running, percent: () => whole.percent };
}
