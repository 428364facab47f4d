// Verification in the inspector: the check of the pattern (its marks in the 2D view, the
// tolerance of rounded drawings), regularize, and the degrees of freedom. ctx: {state, $, api, v2,
// message, action, refresh}.
import { fmt } from './document.js';

// DOF is computed automatically for patterns up to this many interior vertices (dense SVD,
// milliseconds); larger ones get a button (the sparse method may take seconds).
const DOF_AUTO_MAX_INTERIOR = 300;

export function createVerify(ctx) {
  const { state, $, message, action } = ctx;
  async function runCheck() {
    const tol = $('check-tolerance').value.trim();
    const c = await ctx.api.get('check', tol === '' ? undefined : { tolerance_deg: tol });
    state.check = c;
    const bad = [], within = [];
    const reasons = new Map();
    for (const v of c.violations) reasons.set(v.vertex, (reasons.get(v.vertex) || []).concat(`${v.rule}: ${v.detail}`));
    for (const v of c.vertices) {
      if (v.within_tolerance) within.push({ vertex: v.vertex, reason: `within tolerance: flat-foldable once its sectors move by ${fmt(v.deviation_deg, 6)}°` });
      else if (!v.flat_foldable) bad.push({ vertex: v.vertex, reason: (reasons.get(v.vertex) || ['not flat-foldable']).join('; ') });
    }
    ctx.v2.setCheckMarks(bad, within);
    const box = $('check-summary');
    box.replaceChildren();
    const head = document.createElement('div');
    if (c.interior_vertices === 0) {
      head.textContent = 'no interior vertices: nothing to check locally';
    } else {
      head.className = c.locally_flat_foldable ? 'ok' : 'bad';
      head.textContent = c.locally_flat_foldable
        ? `locally flat-foldable (${c.interior_vertices} interior vert${c.interior_vertices === 1 ? 'ex' : 'ices'})`
        : `not locally flat-foldable: ${c.failed_vertices} of ${c.interior_vertices} interior vert${c.interior_vertices === 1 ? 'ex fails' : 'ices fail'}`;
    }
    box.appendChild(head);
    if (c.within_tolerance_vertices > 0) {
      const w = document.createElement('div');
      w.className = 'within';
      w.textContent = `${c.within_tolerance_vertices} within ${fmt(c.tolerance_deg, 6)}° (largest deviation ${fmt(c.max_deviation_deg, 6)}°)`;
      box.appendChild(w);
    }
    if (c.violations.length) {
      const ul = document.createElement('ul');
      for (const v of c.violations.slice(0, 12)) {
        const li = document.createElement('li');
        li.textContent = `vertex ${v.vertex}: ${v.rule}: ${v.detail}`;
        ul.appendChild(li);
      }
      if (c.violations.length > 12) {
        const li = document.createElement('li');
        li.textContent = `… ${c.violations.length - 12} more (hover the marked vertices)`;
        ul.appendChild(li);
      }
      box.appendChild(ul);
    }
    if (c.hint) {
      const h = document.createElement('div');
      h.className = 'hint';
      h.textContent = c.hint;
      box.appendChild(h);
    }
  }

  // Regularize (orikin regularize): the nearest exact pattern replaces the document (undo
  // restores the drawing); the displacement is reported.
  async function regularize() {
    const rigid = $('regularize-rigid').checked;
    const r = await ctx.api.compute('regularize', () => ctx.api.post('regularize', { rigid }));
    state.regularize = r;
    const box = $('regularize-summary');
    box.replaceChildren();
    const d = document.createElement('div');
    if (r.replaced) {
      d.className = 'ok';
      d.textContent = r.max_move_vertex === null
        ? 'regularized: no vertex moved (the pattern is exact already)'
        : `regularized${rigid ? ' (rigid)' : ''}: ${r.moved_vertices} vertices moved, the largest by ${r.max_move_rel.toExponential(2)} of the sheet (vertex ${r.max_move_vertex}), RMS ${r.rms_move_rel.toExponential(2)}; Kawasaki ${r.kawasaki_before_deg.toExponential(2)}° → ${r.kawasaki_after_deg.toExponential(2)}°`;
      message(d.textContent + ' (undo restores the drawing)');
    } else {
      d.className = 'bad';
      d.textContent = 'regularize refused: ' + r.reason;
      message(d.textContent, true);
    }
    d.dataset.replaced = r.replaced;
    box.appendChild(d);
    await ctx.refresh();
  }

  async function maybeDof(force = false) {
    const box = $('dof-summary');
    const n = state.session ? state.session.interior_vertices : 0;
    if (!force && n > DOF_AUTO_MAX_INTERIOR) {
      box.replaceChildren();
      const b = document.createElement('button');
      b.className = 'small';
      b.textContent = 'compute the DOF';
      b.title = `${n} interior vertices: the sparse rank may take a while`;
      b.onclick = () => action(() => maybeDof(true));
      box.appendChild(b);
      return;
    }
    let d;
    try {
      d = await ctx.api.compute('degrees of freedom', () => ctx.api.post('dof', { lock: [...state.spec.locks] }));
    } catch (e) {
      box.textContent = 'DOF: ' + e.message;
      return;
    }
    const locks = state.spec.locks.size ? ` with ${state.spec.locks.size} locked` : '';
    box.textContent = `DOF ${d.dof} at this state${locks}` + (d.generic_dof !== null && d.generic_dof !== d.dof ? ` (${d.generic_dof} nearby)` : '') +
      ` · Grübler–Kutzbach ${d.grubler} · rank ${d.rank} of ${d.unknowns} unknowns`;
    box.dataset.dof = d.dof;
  }

  return { runCheck, regularize, maybeDof };
}
