// The fold panel (thesis ch. 9.4): the specification picked by clicks (fixed face, drives,
// locks; lock auto, symmetric; from, to, step), the bone structure, compute, the verdict with
// its reason, hint, contact, offending creases and the Frame A / Frame B split, and the fold's
// states on its own slider (a blocked fold's up to its stop). ctx: {state, store, $, api, v2,
// v3, message, action, refresh, clearCollision, showContact, collideOptions, renderTree}.
import { decodeState } from './api.js';
import { ASSIGNMENT_NAMES, faceLabel, fmt } from './document.js';
import { foldStateText, foldVerdictText } from './format.js';
import { foldBody as buildFoldBody } from './requests.js';

export function createFoldPanel(ctx) {
  const { state, $, message, action } = ctx;
  function renderSpec() {
    const s = state.spec;
    // no face chosen: the server fixes the CLI's default face (the face at the centre); once a
    // fold has run, the face it fixed is shown and marked
    const fixed = s.fix >= 0 ? s.fix : state.fold && state.fold.fixed_face >= 0 ? state.fold.fixed_face : -1;
    $('spec-fix').textContent = s.fix >= 0 ? faceLabel(state.doc, s.fix)
      : fixed >= 0 ? faceLabel(state.doc, fixed) + ' (default)' : 'default (the face at the centre)';
    $('spec-drive').textContent = s.drives.length > 1 ? 'creases ' + s.drives.join(', ') : s.drive >= 0 ? 'crease ' + s.drive : '–';
    $('spec-lock').textContent = s.locks.size ? [...s.locks].sort((a, b) => a - b).join(', ') : '–';
    ctx.v2.setFaceClass('fixed', fixed >= 0 ? [fixed] : []);
    ctx.v2.setHalos('drive', s.drives.length > 1 ? s.drives : s.drive >= 0 ? [s.drive] : []);
    ctx.v2.setHalos('lock', [...s.locks]);
    if (s.fix < 0) ctx.v2.setBones(null);
  }

  async function loadBones() {
    if (state.spec.fix < 0) return;
    try {
      const m = await ctx.api.get('mechanism', { fix: state.spec.fix });
      state.bones = m.bones;
      ctx.v2.setBones(m.bones);
    } catch (e) {
      ctx.v2.setBones(null);
      message('bone structure: ' + e.message, true);
    }
  }

  function foldBody() {
    const spec = { ...state.spec, lockAuto: $('spec-lock-auto').checked, symmetric: $('spec-symmetric').checked };
    return buildFoldBody(spec, { to: $('spec-to').value, step: $('spec-step').value, from: $('spec-from').value,
      frame: +$('start-frame').value });
  }

  function clearFold() {
    ctx.store.set({ fold: null });
    state.foldFrames.clear();
    state.foldPlaying = false;
    $('verdict').replaceChildren();
    $('split').replaceChildren();
    $('fold-slider').disabled = true;
    $('fold-slider').max = 0;
    $('play-fold').disabled = true;
    for (const c of ['frame-a', 'frame-b', 'surround', 'offending']) ctx.v2.setHalos(c, []);
    ctx.v2.setLabels([]);
    ctx.clearCollision();
    renderSpec();
  }

  async function compute() {
    await action(async () => {
      const body = Object.assign(foldBody(), ctx.collideOptions());
      if (state.sequence && state.sequence.valid && state.folds.length && !body.frame) body.after_sequence = true;
      clearFold();
      const r = await ctx.api.compute('fold', () => ctx.api.post('fold', body));
      ctx.store.set({ fold: r });
      showFold(r, body);
      renderSpec();
      if (r.frames.length) await showFoldFrame(r.frames.length - 1);
      await ctx.refresh();
      if (r.collision) await ctx.showContact('fold');
    });
  }

  function showFold(r, body) {
    const box = $('verdict');
    box.replaceChildren();
    const v = document.createElement('div');
    v.className = r.valid ? 'valid' : 'invalid';
    v.textContent = foldVerdictText(r);
    v.dataset.verdict = r.verdict;
    box.appendChild(v);
    if (r.reason) {
      const why = document.createElement('div');
      why.className = 'reason';
      why.textContent = r.reason;
      box.appendChild(why);
    }
    if (r.collision) {
      const c = document.createElement('div');
      c.className = 'contact';
      const stop = r.frames.length ? `the motion stops at state ${r.frames.length - 1}` : 'the start state collides';
      const at = r.collision.progress !== undefined ? `${fmt(100 * r.collision.progress, 4)} % of the way` : `drive ${fmt(r.collision.drive_deg, 6)}°`;
      c.textContent = `${stop}; first contact at ${at} (step ${r.collision.step}) `;
      const b = document.createElement('button');
      b.className = 'small';
      b.id = 'show-fold-contact';
      b.textContent = 'show contact';
      b.onclick = () => action(() => ctx.showContact('fold'));
      c.appendChild(b);
      box.appendChild(c);
    }
    if (r.hint) {
      const h = document.createElement('div');
      h.className = 'hint';
      h.textContent = r.hint;
      box.appendChild(h);
    }
    const meta = document.createElement('div');
    meta.className = 'hint';
    // a fold mode (percent, several drives, symmetric) answers as orikin fold does in that mode
    meta.textContent = r.mode
      ? `${r.mode === 'targets' ? 'toward the targets' : 'several drives'} · locked ${r.locked.length}` + (r.symmetry ? ` · ${r.symmetry.crease_groups} symmetric groups` : '')
      : `DOF at the last state ${r.dof} · Grübler–Kutzbach ${r.grubler}` + (body.after_sequence ? ' · after the sequence' : '');
    box.appendChild(meta);
    // the offending creases, named and marked
    const offending = r.offending_edges || [];
    ctx.v2.setHalos('offending', offending.map((o) => o.edge));
    ctx.v2.setLabels(offending.map((o) => {
      const [a, b] = state.doc.edges[o.edge];
      const P = state.doc.flat;
      return { x: (P[a][0] + P[b][0]) / 2, y: (P[a][1] + P[b][1]) / 2, text: `${o.edge}: ${o.assignment} → ${fmt(o.angle_deg, 2)}°` };
    }));
    for (const o of offending) message(`crease ${o.edge} (${ASSIGNMENT_NAMES[o.assignment]}) would fold to ${fmt(o.angle_deg, 6)}° at drive ${fmt(o.at_drive_deg, 4)}°`, true);
    // Frame A, Frame B, surrounding of a single vertex (thesis fig. 9-8)
    const sp = $('split');
    sp.replaceChildren();
    if (r.split) {
      ctx.v2.setHalos('frame-a', r.frame_a);
      ctx.v2.setHalos('frame-b', r.frame_b);
      ctx.v2.setHalos('surround', r.surrounding);
      sp.innerHTML = '';
      const part = (cls, label, edges) => {
        const s = document.createElement('span');
        s.className = cls;
        s.textContent = `${label} ${edges.join(', ') || 'none'}`;
        return s;
      };
      sp.append(`vertex ${r.split.vertex}: `, part('a', 'Frame A', r.frame_a), ' · ', part('b', 'Frame B', r.frame_b), ' · ',
        part('s', 'surrounding', r.surrounding));
    }
    const slider = $('fold-slider');
    slider.max = Math.max(0, r.frames.length - 1);
    slider.value = slider.max;
    slider.disabled = r.frames.length < 2;
    $('play-fold').disabled = r.frames.length < 2;
  }

  async function showFoldFrame(k) {
    state.foldK = k;
    let st = state.foldFrames.get(k);
    if (!st) {
      st = decodeState(await ctx.api.binary('fold/frame', { k, binary: 1 }));
      state.foldFrames.set(k, st);
    }
    if (state.foldK !== k) return;
    ctx.v3.setPositions(st.positions);
    if (state.shown === 'contact') ctx.clearCollision();
    state.shown = 'fold';
    $('state3d').textContent = foldStateText(k, state.fold.frames.length, st.drive_deg);
  }

  async function playFold() {
    if (!state.fold || state.fold.frames.length < 2) return;
    state.foldPlaying = !state.foldPlaying;
    $('play-fold').textContent = state.foldPlaying ? 'pause' : 'play';
    const slider = $('fold-slider');
    if (+slider.value >= +slider.max) slider.value = 0;
    while (state.foldPlaying && state.fold) {
      const k = +slider.value;
      await action(() => showFoldFrame(k));
      await new Promise((r) => setTimeout(r, 80));
      if (k >= +slider.max) break;
      slider.value = k + 1;
    }
    state.foldPlaying = false;
    $('play-fold').textContent = 'play';
  }

  return { renderSpec, loadBones, foldBody, clearFold, compute, showFoldFrame, playFold };
}
