// Self-collision in the page: the options of folds and sequences (check folds, clearance), the
// colliding faces and witness in both views, the first contact of a motion, the collide check of
// the state shown, and what the 3D view shows as the API names a state. ctx: {state, $, api,
// v2, v3, plot, replay}.
import { decodeState } from './api.js';
import { fmt } from './document.js';

export function createCollide(ctx) {
  const { state, $ } = ctx;
  // How folds and sequences are checked (as --no-collisions and --clearance).
  function collideOptions() {
    const o = {};
    if (!$('check-collisions').checked) o.no_collisions = true;
    const c = +$('clearance').value;
    if (c > 0) o.clearance = c;
    return o;
  }

  function clearCollision() {
    if (ctx.v3) ctx.v3.setHighlight([], null);
    if (ctx.v2) ctx.v2.setFaceClass('colliding', []);
  }

  // Colliding faces in 2D and 3D, and the witness point in 3D.
  function showCollision(faces, point) {
    ctx.v3.setHighlight(faces, point);
    ctx.v2.setFaceClass('colliding', faces);
  }

  // The state at the first contact of the fold or the sequence, its faces and witness shown.
  async function showContact(of) {
    const st = decodeState(await ctx.api.binary('contact', { of, binary: 1 }));
    const col = of === 'fold' ? state.fold.collision : state.sequence.collision;
    ctx.v3.setPositions(st.positions);
    state.shown = 'contact';
    state.contactOf = of;
    showCollision(col.faces, col.point);
    const at = of === 'sequence' ? `T = ${fmt(st.t, 6)}, fold ${st.fold}, ` : '';
    const where = col.progress !== undefined ? `progress ${fmt(col.progress, 6)}` : `drive ${fmt(st.drive_deg, 6)}°`;
    const label = `first contact of the ${of}: ${at}${where}, faces ${col.faces.join(' and ')}`;
    $('state3d').textContent = label;
    if (of === 'sequence') {
      $('t-label').textContent = label;
      ctx.plot.setCursor(st.t, st.angles);
    }
  }

  // What the 3D view shows, as the API names a state.
  function shownStateRef() {
    if (state.shown === 'fold') return { k: state.foldK };
    if (state.shown === 'sequence' && state.shownT !== null) return { t: state.shownT };
    if (state.shown === 'contact') return { contact: state.contactOf };
    if (state.shown === 'compliant') return { compliant: 1 };
    if (state.shown === 'frames') return ctx.replay.stateRef();
    return { frame: 0 };
  }

  // Check the state shown for self-collision (orikin collide).
  async function collideShown() {
    const body = shownStateRef();
    const c = +$('clearance').value;
    if (c > 0) body.clearance = c;
    const r = await ctx.api.compute('collide', () => ctx.api.post('collide', body));
    state.collide = r;
    const box = $('collide-summary');
    box.replaceChildren();
    const d = document.createElement('div');
    d.className = r.collides ? 'bad' : 'ok';
    d.dataset.collides = r.collides;
    const clear = r.min_clearance !== null ? `least clearance ${fmt(r.min_clearance, 6)} (faces ${r.clearance_faces.join(' and ')})` : 'every face pair shares a vertex';
    d.textContent = r.collides
      ? `${r.state}: collision: faces ${r.pairs.map((p) => p.join(' and ')).join('; ')} (${r.touching.length} touching pairs)`
      : `${r.state}: clean, ${r.touching.length} touching pairs, ${clear}`;
    box.appendChild(d);
    const faces = [...new Set(r.pairs.flat())];
    showCollision(faces, r.collides ? r.witness : null);
  }

  return { collideOptions, clearCollision, showCollision, showContact, shownStateRef, collideShown };
}
