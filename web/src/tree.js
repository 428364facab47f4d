// The face tree ("folding elements", thesis fig. 9-2): the crease history Obj1 → Obj11, Obj12 →
// …, its leaves the faces (selected, fixed, hovered with the 2D view). ctx: {state, $, v2, message}.
import { faceLabel } from './document.js';

export function createTree(ctx) {
  const { state, $, message } = ctx;
  // The tree lists at most this many faces (a generated tessellation has thousands; pick those
  // in the view).
  const TREE_FACES_MAX = 500;

  function renderTree() {
    const doc = state.doc;
    const root = $('tree');
    root.replaceChildren();
    const faceOf = new Map();
    doc.names.forEach((n, f) => { if (n) faceOf.set(n, f); });
    const node = (label, face, inner) => {
      const li = document.createElement('li');
      const d = document.createElement('div');
      d.className = 'node ' + (face >= 0 ? 'leaf' : 'inner');
      if (face >= 0) {
        d.dataset.face = face;
        if (face === state.selectedFace) d.classList.add('selected');
        if (face === state.spec.fix) d.classList.add('fixed');
        d.onclick = () => selectFace(face);
        d.onmouseenter = () => ctx.v2.toggleFaceClass(face, 'hover', true);
        d.onmouseleave = () => ctx.v2.toggleFaceClass(face, 'hover', false);
      }
      d.innerHTML = '';
      const name = document.createElement('span');
      name.textContent = label;
      d.appendChild(name);
      if (face >= 0) {
        const s = document.createElement('small');
        s.textContent = label === 'face ' + face ? '' : 'face ' + face;
        d.appendChild(s);
      }
      li.appendChild(d);
      if (inner) li.appendChild(inner);
      return li;
    };
    const ul = document.createElement('ul');
    if (doc.tree.length) {
      const children = doc.tree.map(() => []);
      const roots = [];
      doc.tree.forEach((n, i) => (n.parent >= 0 && n.parent < doc.tree.length ? children[n.parent].push(i) : roots.push(i)));
      const build = (i) => {
        const sub = children[i].length ? document.createElement('ul') : null;
        for (const c of children[i]) sub.appendChild(build(c));
        const face = faceOf.has(doc.tree[i].name) ? faceOf.get(doc.tree[i].name) : -1;
        return node(doc.tree[i].name, face, sub);
      };
      for (const r of roots) ul.appendChild(build(r));
      // faces outside the tree
      const inTree = new Set(doc.tree.map((n) => n.name));
      doc.faces.forEach((_, f) => {
        if (!doc.names[f] || !inTree.has(doc.names[f])) ul.appendChild(node(doc.names[f] || 'face ' + f, f, null));
      });
    } else {
      for (let f = 0; f < Math.min(doc.faces.length, TREE_FACES_MAX); f++) ul.appendChild(node(doc.names[f] || `face ${f}`, f, null));
      if (doc.faces.length > TREE_FACES_MAX) {
        const li = document.createElement('li');
        li.className = 'hint';
        li.textContent = `… ${doc.faces.length - TREE_FACES_MAX} more faces: pick them in the crease view`;
        ul.appendChild(li);
      }
    }
    root.appendChild(ul);
  }

  function selectFace(f) {
    state.selectedFace = state.selectedFace === f ? -1 : f;
    ctx.v2.setFaceClass('selected', state.selectedFace >= 0 ? [state.selectedFace] : []);
    for (const el of document.querySelectorAll('#tree .node')) el.classList.toggle('selected', +el.dataset.face === state.selectedFace && el.dataset.face !== undefined);
    if (state.selectedFace >= 0) message(`selected ${faceLabel(state.doc, state.selectedFace)}: the collection and the axiom tool apply to it`);
  }

  return { renderTree, selectFace };
}
