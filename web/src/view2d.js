// The 2D crease view (SVG): the crease pattern in the thesis' line styles (mountain dash-dot,
// valley dashed, colours by assignment), every vertex, crease and face hoverable (its FOLD
// index) and clickable, and the overlays of the other panels: selected and fixed faces, the
// bone structure, driven and locked creases, Frame A / Frame B / surrounding, failing vertices
// and those within the check's tolerance, offending creases, colliding faces, axiom inputs and
// solutions. Pan by dragging, zoom with the wheel.

const SVGNS = 'http://www.w3.org/2000/svg';
// Above this many edges the wide invisible hit lines are left out (the lines themselves take
// the pointer) and vertex dots are not drawn, to keep big patterns light.
const HIT_LINES_MAX = 6000;
const VERTEX_DOTS_MAX = 3000;
// Pointer distance (CSS pixels) within which a vertex is hit.
const VERTEX_PICK_PX = 8;

function svg(tag, attrs, parent) {
  const e = document.createElementNS(SVGNS, tag);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
  if (parent) parent.appendChild(e);
  return e;
}

export class View2D {
  constructor(svgEl, { onHover, onClick }) {
    this.svg = svgEl;
    this.onHover = onHover;
    this.onClick = onClick;
    this.doc = null;
    this.view = null; // {x, y, w, h} viewBox in SVG units (y flipped)
    this.layers = {};
    for (const name of ['faces', 'bones', 'halos', 'edges', 'hits', 'vertices', 'marks', 'overlay', 'labels'])
      this.layers[name] = svg('g', { class: name }, this.svg);
    this.layers.bones.setAttribute('pointer-events', 'none');
    this.layers.halos.setAttribute('pointer-events', 'none');
    this.layers.labels.setAttribute('pointer-events', 'none');
    this.hover = null;
    this.pickVertices = true; // false while a tool wants only faces and creases
    this.faceClass = new Map(); // face -> Set of classes
    this.markScale = [];
    this.installPointer();
    new ResizeObserver(() => this.applyView()).observe(this.svg);
  }

  setDocument(doc, keepView) {
    const sameFrame = keepView && this.doc && this.view;
    this.doc = doc;
    for (const g of ['faces', 'edges', 'hits', 'vertices']) this.layers[g].replaceChildren();
    this.clearOverlays();
    const P = (i) => doc.flat[i];
    // faces are picked by their polygons (faceAt); only faces with a class (hover, selected,
    // fixed) are drawn, so a pattern of ten thousand faces adds no elements
    this.faceBoxes = doc.faces.map((f) => {
      let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
      for (const v of f) { x0 = Math.min(x0, P(v)[0]); x1 = Math.max(x1, P(v)[0]); y0 = Math.min(y0, P(v)[1]); y1 = Math.max(y1, P(v)[1]); }
      return [x0, y0, x1, y1];
    });
    const edgeFrag = document.createDocumentFragment(), hitFrag = document.createDocumentFragment();
    const hits = doc.edges.length <= HIT_LINES_MAX;
    doc.edges.forEach(([a, b], i) => {
      const attrs = { x1: P(a)[0], y1: -P(a)[1], x2: P(b)[0], y2: -P(b)[1], 'data-edge': i };
      svg('line', { ...attrs, class: 'edge ' + doc.assignment[i] }, edgeFrag);
      if (hits) svg('line', { ...attrs, class: 'hit' }, hitFrag);
    });
    this.layers.edges.appendChild(edgeFrag);
    this.layers.hits.appendChild(hitFrag);
    this.layers.edges.style.pointerEvents = hits ? 'none' : 'auto';
    if (doc.flat.length <= VERTEX_DOTS_MAX) {
      const vf = document.createDocumentFragment();
      doc.flat.forEach(([x, y], i) => svg('circle', { class: 'vertex', 'data-vertex': i, cx: x, cy: -y, r: 1 }, vf));
      this.layers.vertices.appendChild(vf);
    }
    if (!sameFrame) this.fit();
    else this.applyView();
  }

  // --- view transform ---------------------------------------------------------------------

  fit() {
    if (!this.doc) return;
    const { x0, y0, x1, y1, size } = this.doc.box;
    const m = 0.06 * size;
    this.view = { x: x0 - m, y: -y1 - m, w: x1 - x0 + 2 * m, h: y1 - y0 + 2 * m };
    this.applyView();
  }

  applyView() {
    if (!this.view) return;
    const r = this.svg.getBoundingClientRect();
    if (r.width === 0 || r.height === 0) return;
    // keep the aspect of the element: grow the view box to it
    let { x, y, w, h } = this.view;
    const aspect = r.width / r.height;
    if (w / h < aspect) { const nw = h * aspect; x -= (nw - w) / 2; w = nw; }
    else { const nh = w / aspect; y -= (nh - h) / 2; h = nh; }
    this.view = { x, y, w, h };
    this.svg.setAttribute('viewBox', `${x} ${y} ${w} ${h}`);
    this.unitsPerPx = w / r.width;
    this.refreshScale();
  }

  // Sizes given in pixels follow the zoom.
  refreshScale() {
    const u = this.unitsPerPx || 1;
    for (const c of this.layers.vertices.children) c.setAttribute('r', 2.2 * u);
    for (const [el, px, attr] of this.markScale) el.setAttribute(attr, px * u);
  }

  toSheet(clientX, clientY) {
    const pt = this.svg.createSVGPoint();
    pt.x = clientX; pt.y = clientY;
    const m = this.svg.getScreenCTM();
    if (!m) return [0, 0];
    const p = pt.matrixTransform(m.inverse());
    return [p.x, -p.y];
  }

  // Client (CSS pixel) coordinates of a sheet point: what a click there uses.
  clientOf(x, y) {
    const pt = this.svg.createSVGPoint();
    pt.x = x; pt.y = -y;
    const p = pt.matrixTransform(this.svg.getScreenCTM());
    return [p.x, p.y];
  }

  nearestVertex(x, y) {
    if (!this.doc) return -1;
    const r = VERTEX_PICK_PX * (this.unitsPerPx || 1);
    let best = -1, bd = r * r;
    this.doc.flat.forEach(([vx, vy], i) => {
      const d = (vx - x) ** 2 + (vy - y) ** 2;
      if (d <= bd) { bd = d; best = i; }
    });
    return best;
  }

  // The face containing the sheet point (x, y), or -1 (crossing number; faces do not overlap).
  faceAt(x, y) {
    const doc = this.doc;
    if (!doc) return -1;
    for (let f = 0; f < doc.faces.length; f++) {
      const b = this.faceBoxes[f];
      if (x < b[0] || x > b[2] || y < b[1] || y > b[3]) continue;
      const poly = doc.faces[f];
      let inside = false;
      for (let i = 0, j = poly.length - 1; i < poly.length; j = i++) {
        const [xi, yi] = doc.flat[poly[i]], [xj, yj] = doc.flat[poly[j]];
        if ((yi > y) !== (yj > y) && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
      }
      if (inside) return f;
    }
    return -1;
  }

  // What is under the pointer: a vertex (within a few pixels), else a crease, else a face.
  pick(ev) {
    const [x, y] = this.toSheet(ev.clientX, ev.clientY);
    const v = this.pickVertices ? this.nearestVertex(x, y) : -1;
    if (v >= 0) return { kind: 'vertex', index: v, point: [x, y] };
    const t = ev.target;
    if (t && t.dataset && t.dataset.solution !== undefined) return { kind: 'solution', index: +t.dataset.solution, point: [x, y] };
    if (t && t.dataset && t.dataset.edge !== undefined) return { kind: 'edge', index: +t.dataset.edge, point: [x, y] };
    if (t && t.dataset && t.dataset.badVertex !== undefined) return { kind: 'check', index: +t.dataset.badVertex, point: [x, y] };
    const f = this.faceAt(x, y);
    if (f >= 0) return { kind: 'face', index: f, point: [x, y] };
    return { kind: 'none', index: -1, point: [x, y] };
  }

  installPointer() {
    let drag = null;
    this.svg.addEventListener('pointerdown', (ev) => {
      drag = { x: ev.clientX, y: ev.clientY, view: { ...this.view }, moved: false, id: ev.pointerId };
    });
    this.svg.addEventListener('pointermove', (ev) => {
      if (drag && (ev.buttons & 7)) {
        const dx = ev.clientX - drag.x, dy = ev.clientY - drag.y;
        if (!drag.moved && Math.hypot(dx, dy) > 4) {
          drag.moved = true;
          this.svg.setPointerCapture(drag.id);
        }
        if (drag.moved) {
          const u = this.unitsPerPx || 1;
          this.view = { ...drag.view, x: drag.view.x - dx * u, y: drag.view.y - dy * u };
          this.applyView();
          return;
        }
      }
      this.setHover(this.pick(ev), ev);
    });
    this.svg.addEventListener('pointerup', (ev) => {
      const d = drag;
      drag = null;
      if (d && d.moved) { this.svg.releasePointerCapture(d.id); return; }
      if (ev.button !== 0) return;
      this.onClick(this.pick(ev), ev);
    });
    this.svg.addEventListener('pointerleave', () => this.setHover(null, null));
    this.svg.addEventListener('wheel', (ev) => {
      ev.preventDefault();
      if (!this.view) return;
      const f = Math.exp(ev.deltaY * 0.0015);
      const [x, y] = this.toSheet(ev.clientX, ev.clientY);
      const sx = x, sy = -y;
      this.view = { x: sx - (sx - this.view.x) * f, y: sy - (sy - this.view.y) * f, w: this.view.w * f, h: this.view.h * f };
      this.applyView();
    }, { passive: false });
    this.svg.addEventListener('dblclick', () => this.fit());
  }

  setHover(hit, ev) {
    const key = hit ? hit.kind + hit.index : '';
    if (key !== (this.hover ? this.hover.key : '')) {
      this.layers.overlay.querySelectorAll('.hover').forEach((e) => e.classList.remove('hover'));
      this.layers.halos.querySelectorAll('.halo.hover').forEach((e) => e.remove());
      this.layers.vertices.querySelectorAll('.hover').forEach((e) => e.classList.remove('hover'));
      if (this.hover && this.hover.kind === 'face') this.toggleFaceClass(this.hover.index, 'hover', false);
      if (hit && hit.kind === 'edge') this.halo(hit.index, 'hover');
      if (hit && hit.kind === 'face') this.toggleFaceClass(hit.index, 'hover', true);
      if (hit && hit.kind === 'vertex') {
        const c = this.layers.vertices.querySelector(`[data-vertex="${hit.index}"]`);
        if (c) c.classList.add('hover');
      }
      if (hit && hit.kind === 'solution') {
        this.layers.overlay.querySelectorAll(`[data-solution="${hit.index}"]`).forEach((e) => e.classList.add('hover'));
      }
      this.hover = hit ? { ...hit, key } : null;
    }
    this.onHover(hit, ev);
  }

  // --- overlays ---------------------------------------------------------------------------

  clearOverlays() {
    for (const g of ['bones', 'halos', 'marks', 'overlay', 'labels']) this.layers[g].replaceChildren();
    this.markScale = [];
    this.faceClass.clear();
  }

  halo(edge, cls, title) {
    const [a, b] = this.doc.edges[edge];
    const P = this.doc.flat;
    const l = svg('line', { class: 'halo ' + cls, x1: P[a][0], y1: -P[a][1], x2: P[b][0], y2: -P[b][1], 'data-halo': edge }, this.layers.halos);
    if (title) l.dataset.title = title;
    return l;
  }

  // Replace the halos of a group (drive, lock, frame-a, …) by these edges.
  setHalos(cls, edges) {
    this.layers.halos.querySelectorAll('.halo.' + cls).forEach((e) => e.remove());
    for (const e of edges) if (e >= 0 && e < this.doc.edges.length) this.halo(e, cls);
  }

  toggleFaceClass(face, cls, on) {
    if (!this.doc || face < 0 || face >= this.doc.faces.length) return;
    let set = this.faceClass.get(face);
    if (!set) this.faceClass.set(face, (set = new Set()));
    if (on) set.add(cls); else set.delete(cls);
    let el = this.layers.faces.querySelector(`[data-face="${face}"]`);
    if (!set.size) {
      if (el) el.remove();
      this.faceClass.delete(face);
      return;
    }
    if (!el) {
      const P = this.doc.flat;
      el = svg('polygon', { 'data-face': face, points: this.doc.faces[face].map((v) => `${P[v][0]},${-P[v][1]}`).join(' ') },
        this.layers.faces);
      el.setAttribute('pointer-events', 'none');
    }
    el.setAttribute('class', 'face ' + [...set].join(' '));
  }

  setFaceClass(cls, faces) {
    for (const [f, set] of this.faceClass) if (set.has(cls)) this.toggleFaceClass(f, cls, false);
    for (const f of faces) this.toggleFaceClass(f, cls, true);
  }

  // Bones: face centroid to crease midpoint (thesis fig. 9-7).
  setBones(bones) {
    const g = this.layers.bones;
    g.replaceChildren();
    this.markScale = this.markScale.filter(([el]) => el.isConnected);
    const seen = new Set();
    for (const b of bones || []) {
      svg('line', { class: 'bone', x1: b.from[0], y1: -b.from[1], x2: b.to[0], y2: -b.to[1] }, g);
      if (!seen.has(b.face)) {
        seen.add(b.face);
        const c = svg('circle', { class: 'bone-node', cx: b.from[0], cy: -b.from[1], r: 3 }, g);
        this.markScale.push([c, 3, 'r']);
      }
    }
    this.refreshScale();
  }

  // Vertices of the check with their reasons (shown on hover): failing ones, and those that pass
  // only within the check's tolerance.
  setCheckMarks(bad, within = []) {
    const g = this.layers.marks;
    g.replaceChildren();
    this.markScale = this.markScale.filter(([el]) => el.isConnected);
    for (const [list, cls] of [[bad, 'bad-vertex'], [within, 'within-vertex']])
      for (const { vertex, reason } of list) {
        const [x, y] = this.doc.flat[vertex];
        const c = svg('circle', { class: cls, cx: x, cy: -y, r: 9, 'data-bad-vertex': vertex }, g);
        c.dataset.reason = reason;
        this.markScale.push([c, 9, 'r']);
      }
    this.refreshScale();
  }

  setLabels(labels) {
    const g = this.layers.labels;
    g.replaceChildren();
    this.markScale = this.markScale.filter(([el]) => el.isConnected);
    for (const { x, y, text } of labels) {
      const t = svg('text', { class: 'label', x, y: -y, 'text-anchor': 'middle' }, g);
      t.textContent = text;
      this.markScale.push([t, 11, 'font-size']);
    }
    this.refreshScale();
  }

  // Axiom tool: picked inputs and the solution lines (clickable).
  setAxiomOverlay(picks, solutions) {
    const g = this.layers.overlay;
    g.replaceChildren();
    this.markScale = this.markScale.filter(([el]) => el.isConnected);
    for (const p of picks) {
      if (p.type === 'point') {
        const c = svg('circle', { class: 'axiom-pick', cx: p.x, cy: -p.y, r: 5 }, g);
        this.markScale.push([c, 5, 'r']);
      } else {
        const [a, b] = this.doc.edges[p.edge];
        const P = this.doc.flat;
        svg('line', { class: 'axiom-pick-line', x1: P[a][0], y1: -P[a][1], x2: P[b][0], y2: -P[b][1] }, g);
      }
    }
    (solutions || []).forEach((segs, k) => {
      for (const s of segs) svg('line', { class: 'axiom-line', x1: s[0], y1: -s[1], x2: s[2], y2: -s[3], 'data-solution': k }, g);
    });
    this.refreshScale();
  }

  setMovePicks(points) {
    const g = this.layers.overlay;
    g.replaceChildren();
    for (const [x, y] of points) {
      const c = svg('circle', { class: 'move-pick', cx: x, cy: -y, r: 5 }, g);
      this.markScale.push([c, 5, 'r']);
    }
    this.refreshScale();
  }
}
