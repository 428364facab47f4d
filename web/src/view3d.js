// The 3D view (three.js): the sheet at any state with two-sided colours or a texture on the
// front, its creases, a ground grid; orbit, zoom and pan with the mouse, roll/pitch/yaw
// buttons, preset views; the collision overlay (colliding faces and the witness point). The sheet lies in z = 0 before folding, so z is up here. Positions
// arrive as float64 (exact, kept for inspection) and are drawn as float32.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

// A software renderer (no GPU: SwiftShader, llvmpipe) draws every multisample: leave
// antialiasing to GPUs.
function softwareGl() {
  try {
    const gl = document.createElement('canvas').getContext('webgl');
    const info = gl && gl.getExtension('WEBGL_debug_renderer_info');
    const name = info ? String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL)) : '';
    return /swiftshader|llvmpipe|software/i.test(name);
  } catch (e) {
    return false;
  }
}

// One double-sided material: the front colour (and texture) on the side the sheet's faces are
// counter-clockwise from, the back colour on the other (the two sides of the paper).
function sheetMaterial() {
  const m = new THREE.MeshLambertMaterial({ color: 0xe8833a, side: THREE.DoubleSide, flatShading: true,
    polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 });
  m.userData.back = { value: new THREE.Color(0xf4efe6) };
  m.onBeforeCompile = (shader) => {
    shader.uniforms.backColor = m.userData.back;
    shader.fragmentShader = 'uniform vec3 backColor;\n' + shader.fragmentShader
      .replace('vec4 diffuseColor = vec4( diffuse, opacity );', 'vec4 diffuseColor = vec4( gl_FrontFacing ? diffuse : backColor, opacity );')
      .replace('#include <map_fragment>', '#ifdef USE_MAP\n if ( gl_FrontFacing ) diffuseColor *= texture2D( map, vMapUv );\n#endif');
  };
  return m;
}

// Faces folded flat onto each other are drawn this far apart (a fraction of the sheet's size):
// many depth-buffer steps at any zoom, far below a pixel at the fitted view.
const STACK_GAP = 1e-3;

// The faces' tree over their creases, from face 0 (breadth first): per face its parent face and
// the side of the parent it folds onto (+1 the front: a valley, -1 the back: a mountain), as
// the render module stacks faces folded flat without a faceOrders (by the fold tree).
function stackTree(doc) {
  const F = doc.faces.length;
  const byEdge = new Map();
  doc.faces.forEach((f, k) => f.forEach((a, i) => {
    const b = f[(i + 1) % f.length];
    const key = a < b ? `${a},${b}` : `${b},${a}`;
    (byEdge.get(key) || byEdge.set(key, []).get(key)).push(k);
  }));
  const side = new Map();
  doc.edges.forEach(([a, b], e) => {
    const as = doc.assignment[e];
    const s = as === 'V' ? 1 : as === 'M' ? -1 : (doc.foldAngle[e] || 0) < 0 ? -1 : 1;
    if (as !== 'B' && as !== 'C') side.set(a < b ? `${a},${b}` : `${b},${a}`, s);
  });
  const parent = new Int32Array(F).fill(-1), sign = new Int8Array(F), order = [];
  const seen = new Uint8Array(F);
  const adj = doc.faces.map(() => []);
  for (const [key, fs] of byEdge) if (fs.length === 2 && side.has(key)) {
    adj[fs[0]].push([fs[1], side.get(key)]);
    adj[fs[1]].push([fs[0], side.get(key)]);
  }
  for (let r = 0; r < F; r++) {
    if (seen[r]) continue;
    seen[r] = 1;
    order.push(r);
    for (let q = order.length - 1; q < order.length; q++) {
      const f = order[q];
      for (const [g, s] of adj[f]) if (!seen[g]) { seen[g] = 1; parent[g] = f; sign[g] = s; order.push(g); }
    }
  }
  return { parent, sign, order };
}

// Per face, its offset (3F) in the state pos: its parent's plus STACK_GAP along the parent's front
// normal (valley) or back normal (mountain). Faces not flat onto each other move imperceptibly.
function stackOffsets(doc, tree, pos, faceCorners, cornerVertex) {
  const F = faceCorners.length;
  const off = new Float64Array(3 * F);
  const gap = STACK_GAP * doc.box.size;
  const normal = (f) => {
    // Newell's normal of the face's polygon in this state (the front side's)
    const [c0, n] = faceCorners[f];
    let nx = 0, ny = 0, nz = 0;
    for (let i = 0; i < n; i++) {
      const a = 3 * cornerVertex[c0 + i], b = 3 * cornerVertex[c0 + (i + 1) % n];
      nx += (pos[a + 1] - pos[b + 1]) * (pos[a + 2] + pos[b + 2]);
      ny += (pos[a + 2] - pos[b + 2]) * (pos[a] + pos[b]);
      nz += (pos[a] - pos[b]) * (pos[a + 1] + pos[b + 1]);
    }
    const l = Math.hypot(nx, ny, nz) || 1;
    return [nx / l, ny / l, nz / l];
  };
  // the front of a face is the side its flat polygon is counter-clockwise from (as the material)
  const flatSign = doc.faces.map((f) => {
    let a = 0;
    for (let i = 0; i < f.length; i++) {
      const [x0, y0] = doc.flat[f[i]], [x1, y1] = doc.flat[f[(i + 1) % f.length]];
      a += x0 * y1 - x1 * y0;
    }
    return a < 0 ? -1 : 1;
  });
  for (const f of tree.order) {
    const p = tree.parent[f];
    if (p < 0) continue;
    const n = normal(p);
    const s = tree.sign[f] * flatSign[p] * gap;
    for (let k = 0; k < 3; k++) off[3 * f + k] = off[3 * p + k] + s * n[k];
  }
  return off;
}

const CREASE_COLORS = { M: 0xd7263d, V: 0x1b6ef3, B: 0x22262b, F: 0x9a9a9a, U: 0x6f6f6f, C: 0x000000, J: 0xcccccc };
// Crease lines are drawn in 3D by default for patterns up to this many edges.
const CREASE_LINES_AUTO_MAX = 5000;
// Roll/pitch/yaw buttons turn the model by this much (radians).
const ROTATE_STEP = Math.PI / 12;

export class View3D {
  constructor(canvas) {
    this.canvas = canvas;
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: !softwareGl() });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0xeef0f3);
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.enableDamping = false;
    this.controls.addEventListener('change', () => this.render());
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x8a8f99, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.4);
    sun.position.set(3, -4, 6);
    this.scene.add(sun);
    const fill = new THREE.DirectionalLight(0xffffff, 0.5);
    fill.position.set(-4, 3, -5);
    this.scene.add(fill);
    this.model = new THREE.Group(); // roll/pitch/yaw turn this
    this.scene.add(this.model);
    this.grid = null;
    this.material = sheetMaterial();
    this.lineMaterial = new THREE.LineBasicMaterial({ vertexColors: true });
    // colliding faces: drawn over the sheet (pulled towards the viewer), both sides
    this.highlightMaterial = new THREE.MeshBasicMaterial({ color: 0xd7263d, side: THREE.DoubleSide, transparent: true,
      opacity: 0.6, polygonOffset: true, polygonOffsetFactor: -1, polygonOffsetUnits: -4, depthWrite: false });
    // the witness point: always visible
    this.markerMaterial = new THREE.MeshBasicMaterial({ color: 0x111111, depthTest: false });
    this.highlighted = { faces: [], point: null };
    this.positions = null; // Float64Array 3V: the state shown
    this.frameCount = 0;
    this.pending = false;
    new ResizeObserver(() => this.resize()).observe(canvas);
  }

  // Build the mesh of a document: faces triangulated in the flat sheet (they stay rigid).
  setDocument(doc) {
    this.doc = doc;
    for (const o of [this.mesh, this.lines]) if (o) { this.model.remove(o); o.geometry.dispose(); }
    const index = [];
    // Every face has its own corners (cornerVertex: the vertex of each corner), so that faces
    // folded flat onto each other can be stacked apart (stackOffsets) instead of fighting.
    this.faceTris = []; // per face: [first index, index count] in the sheet's index
    this.faceCorners = []; // per face: [first corner, corner count]
    const cornerVertex = [];
    for (const f of doc.faces) {
      const contour = f.map((i) => new THREE.Vector2(doc.flat[i][0], doc.flat[i][1]));
      const tris = f.length === 3 ? [[0, 1, 2]] : THREE.ShapeUtils.triangulateShape(contour, []);
      const c0 = cornerVertex.length;
      for (const i of f) cornerVertex.push(i);
      this.faceCorners.push([c0, f.length]);
      const first = index.length;
      for (const t of tris) index.push(c0 + t[0], c0 + t[1], c0 + t[2]);
      this.faceTris.push([first, index.length - first]);
    }
    this.cornerVertex = Int32Array.from(cornerVertex);
    this.stackTree = stackTree(doc);
    this.sheetIndex = index;
    const C = cornerVertex.length;
    this.geometry = new THREE.BufferGeometry();
    this.posAttr = new THREE.BufferAttribute(new Float32Array(3 * C), 3);
    this.posAttr.setUsage(THREE.DynamicDrawUsage);
    this.geometry.setAttribute('position', this.posAttr);
    const { x0, y0, size } = doc.box;
    const uv = new Float32Array(2 * C);
    cornerVertex.forEach((i, c) => { uv[2 * c] = (doc.flat[i][0] - x0) / size; uv[2 * c + 1] = (doc.flat[i][1] - y0) / size; });
    this.geometry.setAttribute('uv', new THREE.BufferAttribute(uv, 2));
    this.geometry.setIndex(C > 65535 ? new THREE.Uint32BufferAttribute(index, 1) : new THREE.Uint16BufferAttribute(index, 1));
    this.mesh = new THREE.Mesh(this.geometry, this.material);
    this.model.add(this.mesh);
    // creases as line segments sharing the vertex positions
    const E = doc.edges.length;
    const lineGeom = new THREE.BufferGeometry();
    this.linePos = new THREE.BufferAttribute(new Float32Array(6 * E), 3);
    this.linePos.setUsage(THREE.DynamicDrawUsage);
    const col = new Float32Array(6 * E);
    const c = new THREE.Color();
    doc.edges.forEach((_, i) => {
      c.setHex(CREASE_COLORS[doc.assignment[i]] ?? 0x444444);
      col.set([c.r, c.g, c.b, c.r, c.g, c.b], 6 * i);
    });
    lineGeom.setAttribute('position', this.linePos);
    lineGeom.setAttribute('color', new THREE.BufferAttribute(col, 3));
    this.lines = new THREE.LineSegments(lineGeom, this.lineMaterial);
    // Thousands of crease lines cost a software renderer more than the sheet itself; the flat
    // shading shows the folds anyway. Shown by default up to CREASE_LINES_AUTO_MAX edges.
    if (this.linesChosen === undefined) this.linesVisible = E <= CREASE_LINES_AUTO_MAX;
    this.lines.visible = this.linesVisible !== false;
    this.model.add(this.lines);
    this.setHighlight([], null);
    this.setPositions(Float64Array.from(doc.vertices.flat()));
    this.setGrid(this.gridVisible !== false);
    this.fit();
  }

  // The collision overlay: these faces drawn in red over the sheet (sharing its vertex
  // positions, so they follow every state) and the witness point marked; [] and null clear it.
  setHighlight(faces, point) {
    if (this.highlight) { this.model.remove(this.highlight); this.highlight.geometry.dispose(); this.highlight = null; }
    if (this.marker) { this.model.remove(this.marker); this.marker.geometry.dispose(); this.marker = null; }
    this.highlighted = { faces: [...faces], point: point ? [...point] : null };
    if (!this.doc) return;
    const index = [];
    for (const f of faces) {
      if (!(f >= 0 && f < this.faceTris.length)) continue;
      const [first, n] = this.faceTris[f];
      for (let i = first; i < first + n; i++) index.push(this.sheetIndex[i]);
    }
    if (index.length) {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', this.posAttr);
      g.setIndex(index);
      this.highlight = new THREE.Mesh(g, this.highlightMaterial);
      this.highlight.renderOrder = 1;
      this.model.add(this.highlight);
    }
    if (point) {
      const r = 0.025 * this.doc.box.size;
      this.marker = new THREE.Mesh(new THREE.SphereGeometry(r, 16, 12), this.markerMaterial);
      this.marker.position.set(point[0], point[1], point[2]);
      this.marker.renderOrder = 2;
      this.model.add(this.marker);
    }
    this.render();
  }

  // Show a state: 3V coordinates (float64, kept as given).
  // Paint each face its own colour (colors: [r, g, b] per face, sRGB 0 … 1; both sides), or
  // null for the sheet's colours again. A new state (setPositions) clears them.
  setFaceColors(colors) {
    this.faceColors = colors ? colors.map((c) => [...c]) : null;
    if (!colors) {
      if (this.geometry.getAttribute('color')) this.geometry.deleteAttribute('color');
      if (this.material.vertexColors) {
        this.material.vertexColors = false;
        this.material.color.copy(this.sheetColor || this.material.color);
        this.material.needsUpdate = true;
      }
      this.render();
      return;
    }
    const C = this.cornerVertex.length, col = new Float32Array(3 * C), k = new THREE.Color();
    for (let f = 0; f < this.faceCorners.length; f++) {
      const [c0, n] = this.faceCorners[f];
      k.setRGB(colors[f][0], colors[f][1], colors[f][2], THREE.SRGBColorSpace);
      for (let c = c0; c < c0 + n; c++) col.set([k.r, k.g, k.b], 3 * c);
    }
    this.geometry.setAttribute('color', new THREE.BufferAttribute(col, 3));
    if (!this.material.vertexColors) {
      this.sheetColor = this.material.color.clone();
      this.material.vertexColors = true;
      this.material.color.set(0xffffff);
      this.material.needsUpdate = true;
    }
    this.render();
  }

  setPositions(pos, keepColors = false) {
    if (this.faceColors && !keepColors) this.setFaceColors(null);
    this.positions = Float64Array.from(pos);
    const p = this.posAttr.array;
    const off = stackOffsets(this.doc, this.stackTree, pos, this.faceCorners, this.cornerVertex);
    for (let f = 0; f < this.faceCorners.length; f++) {
      const [c0, n] = this.faceCorners[f];
      for (let c = c0; c < c0 + n; c++) {
        const v = 3 * this.cornerVertex[c];
        p[3 * c] = pos[v] + off[3 * f]; p[3 * c + 1] = pos[v + 1] + off[3 * f + 1]; p[3 * c + 2] = pos[v + 2] + off[3 * f + 2];
      }
    }
    this.posAttr.needsUpdate = true;
    const lp = this.linePos.array;
    const edges = this.doc.edges;
    for (let i = 0; i < edges.length; i++) {
      const a = 3 * edges[i][0], b = 3 * edges[i][1];
      lp[6 * i] = pos[a]; lp[6 * i + 1] = pos[a + 1]; lp[6 * i + 2] = pos[a + 2];
      lp[6 * i + 3] = pos[b]; lp[6 * i + 4] = pos[b + 1]; lp[6 * i + 5] = pos[b + 2];
    }
    this.linePos.needsUpdate = true;
    this.geometry.computeBoundingSphere();
    this.lines.geometry.computeBoundingSphere();
    this.render();
  }

  setGrid(on) {
    this.gridVisible = on;
    if (this.grid) { this.scene.remove(this.grid); this.grid.geometry.dispose(); this.grid = null; }
    if (!on || !this.doc) { this.render(); return; }
    const { x0, y0, x1, y1, size } = this.doc.box;
    const span = 3 * size;
    const divisions = 12;
    this.grid = new THREE.GridHelper(span, divisions, 0x9aa0a8, 0xc9ccd1);
    this.grid.rotation.x = Math.PI / 2; // onto the plane z = 0
    this.grid.position.set((x0 + x1) / 2, (y0 + y1) / 2, 0);
    // the ground is drawn first and never hides anything: the sheet lies on it
    this.grid.material.depthWrite = false;
    this.grid.renderOrder = -1;
    this.scene.add(this.grid);
    this.render();
  }

  setCreasesVisible(on) {
    this.linesChosen = true;
    this.linesVisible = on;
    if (this.lines) this.lines.visible = on;
    this.render();
  }

  setColors(front, back) {
    if (front) this.material.color.set(front);
    if (back) this.material.userData.back.value.set(back);
    this.render();
  }

  setTexture(url) {
    if (this.material.map) { this.material.map.dispose(); this.material.map = null; }
    if (!url) {
      this.material.needsUpdate = true;
      this.render();
      return Promise.resolve();
    }
    return new Promise((resolve, reject) => {
      new THREE.TextureLoader().load(url, (tex) => {
        tex.colorSpace = THREE.SRGBColorSpace;
        this.material.map = tex;
        this.material.color.set(0xffffff);
        this.material.needsUpdate = true;
        this.render();
        resolve();
      }, undefined, () => reject(new Error('the image could not be read')));
    });
  }

  // The view as the render module's camera takes it (model coordinates, the roll/pitch/yaw
  // buttons undone): the direction from the target towards the eye, and the image's up.
  viewAxes() {
    const inv = this.model.quaternion.clone().invert();
    const eye = this.camera.position.clone().sub(this.controls.target).applyQuaternion(inv);
    const up = new THREE.Vector3(0, 1, 0).applyQuaternion(this.camera.quaternion).applyQuaternion(inv);
    return { eye: eye.toArray(), up: up.toArray() };
  }

  center() {
    const b = new THREE.Box3().setFromObject(this.mesh || this.model);
    const c = b.getCenter(new THREE.Vector3());
    const r = Math.max(b.getSize(new THREE.Vector3()).length() / 2, 1e-9);
    return { c, r };
  }

  fit(direction) {
    if (!this.mesh) return;
    const { c, r } = this.center();
    const dir = (direction || this.camera.position.clone().sub(this.controls.target)).clone();
    if (dir.lengthSq() < 1e-20 || !direction && this.fitted === undefined) dir.set(0.9, -1.6, 1.4);
    dir.normalize();
    // the sphere around the model within the narrower of the two fields of view
    const vfov = (this.camera.fov * Math.PI) / 180;
    const hfov = 2 * Math.atan(Math.tan(vfov / 2) * (this.camera.aspect || 1));
    const dist = r / Math.sin(Math.min(vfov, hfov) / 2) * 1.15;
    this.controls.target.copy(c);
    this.camera.position.copy(c).addScaledVector(dir, dist);
    this.camera.near = dist / 100;
    this.camera.far = dist * 100;
    this.camera.updateProjectionMatrix();
    this.fitted = true;
    this.controls.update();
    this.render();
  }

  // How far the state shown reaches on screen: the largest |x| and |y| of its vertices in
  // normalised device coordinates (within 1: the whole model is in view).
  extent() {
    if (!this.positions) return null;
    this.model.updateMatrixWorld();
    this.camera.updateMatrixWorld();
    const v = new THREE.Vector3();
    let m = 0;
    for (let i = 0; i < this.positions.length; i += 3) {
      v.set(this.positions[i], this.positions[i + 1], this.positions[i + 2]).applyMatrix4(this.model.matrixWorld).project(this.camera);
      m = Math.max(m, Math.abs(v.x), Math.abs(v.y));
    }
    return m;
  }

  preset(name) {
    const d = { iso: [0.9, -1.6, 1.4], top: [0, -1e-4, 1], bottom: [0, 1e-4, -1], front: [0, -1, 0], back: [0, 1, 0],
      left: [-1, 0, 0], right: [1, 0, 0] }[name];
    if (!d) return;
    this.model.quaternion.identity();
    this.fit(new THREE.Vector3(...d));
  }

  // Turn the model about the view's axes: roll about the line of sight, pitch about the
  // screen's horizontal, yaw about its vertical.
  rotate(kind, sign) {
    const view = new THREE.Vector3().subVectors(this.controls.target, this.camera.position).normalize();
    const up = new THREE.Vector3(0, 1, 0).applyQuaternion(this.camera.quaternion);
    const right = new THREE.Vector3().crossVectors(view, up).normalize();
    const axis = kind === 'roll' ? view : kind === 'pitch' ? right : up;
    const q = new THREE.Quaternion().setFromAxisAngle(axis, sign * ROTATE_STEP);
    // about the model's centre
    const { c } = this.center();
    this.model.position.sub(c).applyQuaternion(q).add(c);
    this.model.quaternion.premultiply(q);
    this.render();
  }

  zoom(sign) {
    const f = sign > 0 ? 0.8 : 1.25;
    const off = this.camera.position.clone().sub(this.controls.target).multiplyScalar(f);
    this.camera.position.copy(this.controls.target).add(off);
    this.controls.update();
    this.render();
  }

  resize() {
    const w = this.canvas.clientWidth, h = this.canvas.clientHeight;
    if (w === 0 || h === 0) return;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  // Mean time of one synchronous draw (ms), for the performance figures.
  timeRender(n) {
    const gl = this.renderer.getContext();
    const t0 = performance.now();
    for (let i = 0; i < n; i++) {
      this.renderer.render(this.scene, this.camera);
      gl.finish();
    }
    return (performance.now() - t0) / n;
  }

  // Draw on the next animation frame (several changes in one frame draw once).
  render() {
    if (this.pending) return;
    this.pending = true;
    requestAnimationFrame(() => {
      this.pending = false;
      this.renderer.render(this.scene, this.camera);
      this.frameCount++;
    });
  }
}
