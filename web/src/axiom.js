// The axiom tool (Huzita–Hatori 1–7): the inputs picked in the 2D view in order, the solutions
// drawn and creased on the selected face or the whole sheet. ctx: {state, $, api, v2, message,
// action, refresh}.
import { fmt } from './document.js';

// Inputs of each axiom, in the order they are picked.
const AXIOM_INPUTS = { 1: ['p1', 'p2'], 2: ['p1', 'p2'], 3: ['l1', 'l2'], 4: ['p1', 'l1'], 5: ['p1', 'p2', 'l1'],
  6: ['p1', 'l1', 'p2', 'l2'], 7: ['p1', 'l1', 'l2'] };

export function createAxiomTool(ctx) {
  const { state, $, message, action } = ctx;
  function axiomStatus() {
    const n = +$('axiom-number').value;
    const need = AXIOM_INPUTS[n];
    const k = state.axiom.picks.length;
    $('axiom-status').textContent = state.tool !== 'axiom' ? '' : k < need.length
      ? `pick ${need[k]} (${need[k][0] === 'p' ? 'a vertex or a point' : 'a crease'})`
      : `${state.axiom.lines ? state.axiom.lines.length : 0} solution(s)`;
  }

  async function axiomClick(hit) {
    const doc = state.doc;
    const n = +$('axiom-number').value;
    const need = AXIOM_INPUTS[n];
    const ax = state.axiom;
    if (hit.kind === 'solution' && ax.lines) return creaseSolution(hit.index);
    if (ax.picks.length >= need.length) ax.picks = [];
    const want = need[ax.picks.length];
    if (want[0] === 'p') {
      const [x, y] = hit.kind === 'vertex' ? doc.flat[hit.index] : hit.point;
      ax.picks.push({ type: 'point', name: want, x, y });
    } else {
      if (hit.kind !== 'edge') { message(`axiom ${n}: ${want} is a line: click a crease or a side`, true); return; }
      const [a, b] = doc.edges[hit.index];
      const [x0, y0] = doc.flat[a], [x1, y1] = doc.flat[b];
      ax.picks.push({ type: 'line', name: want, edge: hit.index, line: [x0, y0, x1 - x0, y1 - y0] });
    }
    ax.solutions = null;
    ax.lines = null;
    ctx.v2.setAxiomOverlay(ax.picks, null);
    $('axiom-solutions').replaceChildren();
    if (ax.picks.length === need.length) {
      await action(async () => {
        const r = await ctx.api.post('axiom', axiomBody(n));
        ax.lines = r.lines;
        ax.solutions = r.segments;
        ctx.v2.setAxiomOverlay(ax.picks, r.segments);
        const box = $('axiom-solutions');
        box.replaceChildren();
        if (!r.lines.length) message(`axiom ${n}: no solution for these inputs`, true);
        r.lines.forEach((l, k) => {
          const b = document.createElement('button');
          b.textContent = `crease solution ${k + 1}`;
          b.dataset.solution = k;
          b.title = `through (${fmt(l.point[0])}, ${fmt(l.point[1])}), direction (${fmt(l.dir[0])}, ${fmt(l.dir[1])})`;
          b.onclick = () => creaseSolution(k);
          box.appendChild(b);
        });
      });
    }
    axiomStatus();
  }

  function axiomBody(n) {
    const body = { axiom: n };
    for (const p of state.axiom.picks) body[p.name] = p.type === 'point' ? [p.x, p.y] : p.line;
    if (state.selectedFace >= 0) body.face = state.selectedFace;
    return body;
  }

  async function creaseSolution(k) {
    const n = +$('axiom-number').value;
    const body = axiomBody(n);
    body.solution = k + 1;
    body.assign = $('collection-assign').value;
    if (state.selectedFace < 0) body.all = true;
    await action(async () => {
      const r = await ctx.api.compute(`axiom ${n}`, () => ctx.api.post('crease', body));
      message(`axiom ${n} solution ${k + 1} on ${r.applied_to}: ${r.faces_split} face(s) split`);
      state.axiom = { picks: [], solutions: null, lines: null };
      $('axiom-solutions').replaceChildren();
      ctx.v2.setAxiomOverlay([], null);
      state.selectedFace = -1;
      await ctx.refresh();
    });
    axiomStatus();
  }

  return { axiomStatus, axiomClick };
}
