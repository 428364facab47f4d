// orikin studio: the page. It holds no geometry of its own: every edit, check, fold and state
// comes from the server (liborikin); the page draws, picks and keeps the user's choices (the
// tool, the fold specification, the folds of the sequence, the time T).
import { Api, ApiError } from './api.js';
import { FrameReplay } from './frames.js';
import { ASSIGNMENT_NAMES, faceLabel, fmt, isCrease, parseDocument } from './document.js';
import { createExport, download } from './export.js';
import { createFiles } from './files.js';
import { createWholeFold } from './whole.js';
import { createVerify } from './verify.js';
import { createAxiomTool } from './axiom.js';
import { createCollide } from './collide.js';
import { createTree } from './tree.js';
import { createFoldPanel } from './foldpanel.js';
import { createSequence } from './sequence.js';
import { createMessages } from './messages.js';
import { createStore } from './store.js';
import { Plot } from './plot.js';
import { View2D } from './view2d.js';
import { View3D } from './view3d.js';

const $ = (id) => document.getElementById(id);

const COLLECTION_LABELS = { 'diagonal-left': 'DiagonalL', 'diagonal-right': 'DiagonalR', 'middle-h': 'MiddleH',
  'middle-v': 'MiddleV', cross: 'Cross', diagonals: 'Diagonals' };

const store = createStore({
  session: null,
  doc: null,
  version: -1,
  tool: 'select',
  selectedFace: -1,
  spec: { fix: -1, drive: -1, drives: [], locks: new Set() },
  bones: null,
  axiom: { picks: [], solutions: null, lines: null },
  move: { edge: -1, points: [] },
  check: null,
  fold: null,
  compliant: null,
  foldFrames: new Map(),
  foldK: 0,
  sequence: null,
  folds: [],
  grid: 0,
  t: 0,
  shownT: null,
  targetT: null,
  inflight: false,
  playing: false,
  foldPlaying: false,
  shown: 'flat',
  contactOf: null,   // the contact state shown: 'fold' or 'sequence'
  collide: null,     // the last collide check of a state
  regularize: null,  // the last regularize answer
  seqLimit: 0,       // the sequence's clean time: its duration, or the first contact
  composites: [],
  work: 0,
  lastError: '',
  stats: { states: 0, latency: [], since: performance.now() },
});
const state = store.state;

// --- messages and progress ----------------------------------------------------------------

// (a module script runs once the page is parsed: the elements exist)
const messages = createMessages($('messages'), (t) => { state.lastError = t; });
function message(text, error = false) {
  messages.add(text, error);
}

// A new document (New, Open, a drop): the errors, the verdict and the fold of the old one go.
function forgetDocument() {
  messages.clearErrors();
  state.folds = [];
  store.set({ sequence: null });
  state.spec = { fix: -1, drive: -1, drives: [], locks: new Set() };
  clearFold();
  $('collide-summary').replaceChildren();
  $('regularize-summary').replaceChildren();
  wholeFold.reset();
}

const progress = {
  show(text) { $('progress-text').textContent = text; $('progress').hidden = false; },
  hide() { $('progress').hidden = true; },
};

let api = null;

async function action(fn) {
  try {
    return await fn();
  } catch (e) {
    message(e instanceof ApiError || e instanceof Error ? e.message : String(e), true);
    return undefined;
  }
}

// --- the feature modules: files, export, the whole pattern's slider, verification, axioms ------

const ctx = {
  state, store, $, action, message, shownStateRef: () => shownStateRef(),
  runSequence: (folds, label) => runSequence(folds, label), setupTimeline: () => setupTimeline(),
  clearCollision: () => clearCollision(), showContact: (of) => showContact(of), collideOptions: () => collideOptions(),
  renderTree: () => renderTree(), clearFold: () => clearFold(), foldBody: () => foldBody(),
  renderCollection, forgetDocument, refresh,
  clearErrors: () => messages.clearErrors(),
  get api() { return api; },
  get v2() { return v2; },
  get v3() { return v3; },
  get plot() { return plot; },
  get replay() { return replay; },
};
const exporter = createExport(ctx);
const files = createFiles(ctx);
const wholeFold = createWholeFold(ctx);
const exportParams = exporter.params;
const exportAs = exporter.exportAs;
const renderExportMenu = exporter.renderMenu;
const openFile = files.open;
const openTexture = files.openTexture;
const { runCheck, regularize, maybeDof } = createVerify(ctx);
const { axiomStatus, axiomClick } = createAxiomTool(ctx);
const { collideOptions, clearCollision, showCollision, showContact, shownStateRef, collideShown } = createCollide(ctx);
const { renderTree, selectFace } = createTree(ctx);
const { renderSpec, loadBones, foldBody, clearFold, compute, showFoldFrame, playFold } = createFoldPanel(ctx);
const { sequenceJson, runSequence, setupTimeline, sliderSteps, lastCleanT, showTime, addFold, togglePlay } = createSequence(ctx);

// --- document ----------------------------------------------------------------------------

async function refresh(force = false) {
  const session = await api.get('session');
  store.set({ session });
  $('file-name').textContent = session.file;
  $('file-name').title = session.file;
  $('undo').disabled = session.undo === 0;
  $('redo').disabled = session.redo === 0;
  $('save-back').hidden = !session.save_path;
  $('save-back').title = session.save_path ? 'Write the document back to ' + session.save_path : '';
  $('save-seq').hidden = !session.sequence_path;
  $('save-back').textContent = session.unsaved ? 'Save*' : 'Save';
  $('recovery').hidden = !session.recovery;
  if (session.recovery) {
    const when = session.recovery.modified ? new Date(session.recovery.modified * 1000).toLocaleString() : 'earlier';
    $('recovery-text').textContent = `Unsaved edits of ${session.file} from a session that ended without saving (${when}) are kept in ${session.recovery.path}.`;
  }
  if (session.version !== state.version || force) {
    const changed = state.version !== -1;
    state.version = session.version;
    const fold = JSON.parse(await api.text('document'));
    const doc = parseDocument(fold);
    await replay.load(doc.frames);
    loadDocument(doc, changed);
    await Promise.all([runCheck(), maybeDof()]);
  }
  state.grid = session.sequence ? session.sequence.grid : 0;
}

function loadDocument(doc, changed) {
  const old = state.doc;
  state.doc = doc;
  v2.setDocument(doc, old && old.box.size === doc.box.size);
  v3.setDocument(doc);
  $('edges-toggle').checked = v3.linesVisible !== false;
  state.shown = 'flat';
  clearCollision();
  $('state3d').textContent = doc.is3d ? 'frame 0 (3D)' : 'flat sheet';
  // keep the choices that still name something
  if (state.selectedFace >= doc.faces.length) state.selectedFace = -1;
  const E = doc.edges.length;
  if (state.spec.fix >= doc.faces.length) state.spec.fix = -1;
  if (state.spec.drive >= E) state.spec.drive = -1;
  for (const e of [...state.spec.locks]) if (e >= E) state.spec.locks.delete(e);
  if (changed) {
    // results of the old document are gone (the server dropped them)
    clearFold();
    store.set({ sequence: null });
    state.bones = null;
    setupTimeline();
  }
  state.axiom = { picks: [], solutions: null, lines: null };
  state.move = { edge: -1, points: [] };
  // a document with folded frames: a fold may start from any of them
  const sf = $('start-frame');
  sf.replaceChildren();
  for (let k = 0; k < doc.frames; k++) {
    const o = document.createElement('option');
    o.value = k;
    o.textContent = k === 0 ? 'frame 0 (flat)' : `frame ${k}`;
    sf.appendChild(o);
  }
  $('start-frame-label').hidden = doc.frames < 2;
  renderTree();
  renderSpec();
  if (state.spec.fix >= 0) loadBones();
}

// --- the crease collection -----------------------------------------------------------------

function renderCollection() {
  const box = $('collection');
  box.querySelectorAll('button').forEach((b) => b.remove());
  const add = (label, title, pattern) => {
    const b = document.createElement('button');
    b.textContent = label;
    b.title = title;
    b.dataset.pattern = typeof pattern === 'string' ? pattern : label;
    b.onclick = () => applyPattern(pattern, label);
    box.insertBefore(b, $('collection-assign'));
  };
  for (const c of state.session.collection) add(COLLECTION_LABELS[c.name] || c.name, c.summary, c.name);
  for (const c of state.composites) add(c.name, 'composite ' + c.name, c.pattern);
}

async function applyPattern(pattern, label) {
  if (state.selectedFace < 0) {
    message(`${label}: select a face first (in the tree, or click it with the select tool)`, true);
    return;
  }
  await action(async () => {
    const r = await api.compute(label, () => api.post('apply', { pattern, face: state.selectedFace, assign: $('collection-assign').value }));
    message(`${label} on ${r.applied_to}: new faces ${r.new_faces.map((f) => f.name).join(', ')}`);
    state.selectedFace = -1;
    await refresh();
  });
}

// --- tools in the 2D view ------------------------------------------------------------------

function setTool(tool) {
  state.tool = tool;
  for (const b of document.querySelectorAll('[data-tool]')) b.classList.toggle('on', b.dataset.tool === tool);
  state.axiom = { picks: [], solutions: null, lines: null };
  state.move = { edge: -1, points: [] };
  v2.setAxiomOverlay([], null);
  $('axiom-solutions').replaceChildren();
  axiomStatus();
  const hints = {
    select: 'click a face to select it, hover anything to see its FOLD index',
    fix: 'click the face held to the ground',
    drive: 'click the driven crease',
    lock: 'click creases to lock or unlock them',
    flip: 'click a crease to flip it (mountain ↔ valley)',
    move: 'click the crease to move, then the two points of its new line',
    remove: 'click a crease to remove it',
    axiom: 'click the inputs of the axiom: vertices for points, creases for lines',
  };
  if (hints[tool]) $('state3d').dataset.hint = hints[tool];
  // vertices are picked only where they are inputs (and for inspection): elsewhere a click near a
  // vertex of a dense pattern still reaches the face or crease under it
  v2.pickVertices = tool === 'select' || tool === 'axiom' || tool === 'move';
  v2.svg.style.cursor = tool === 'select' ? 'default' : 'crosshair';
}

function needCrease(hit, what) {
  if (hit.kind !== 'edge' || !isCrease(state.doc.assignment[hit.index])) {
    message(`${what}: click a crease`, true);
    return false;
  }
  return true;
}

async function onClick(hit, ev) {
  const doc = state.doc;
  switch (state.tool) {
    case 'select':
      if (hit.kind === 'face') selectFace(hit.index);
      else if (hit.kind === 'check') message(`vertex ${hit.index}: ${v2.layers.marks.querySelector(`[data-bad-vertex="${hit.index}"]`).dataset.reason}`);
      return;
    case 'flip':
      if (needCrease(hit, 'flip')) await edit({ op: 'flip', edge: hit.index });
      return;
    case 'assign-M': case 'assign-V': case 'assign-U':
      if (needCrease(hit, 'assign')) await edit({ op: 'assign', edge: hit.index, to: state.tool.slice(-1) });
      return;
    case 'remove':
      if (needCrease(hit, 'remove')) await edit({ op: 'remove', edge: hit.index });
      return;
    case 'move': {
      const m = state.move;
      if (m.edge < 0) {
        if (needCrease(hit, 'move')) { m.edge = hit.index; message(`moving crease ${hit.index}: click the two points of its new line`); }
        return;
      }
      m.points.push(hit.kind === 'vertex' ? doc.flat[hit.index] : hit.point);
      v2.setMovePicks(m.points);
      if (m.points.length === 2) {
        const [[x1, y1], [x2, y2]] = m.points;
        const edge = m.edge;
        state.move = { edge: -1, points: [] };
        v2.setMovePicks([]);
        await edit({ op: 'move', edge, segment: [x1, y1, x2, y2] });
      }
      return;
    }
    case 'axiom':
      return axiomClick(hit);
    case 'fix':
      if (hit.kind !== 'face') { message('fix: click a face', true); return; }
      if (state.fold) clearFold(); // the result was for another specification
      state.spec.fix = hit.index;
      renderSpec();
      renderTree();
      await action(loadBones);
      return;
    case 'drive': {
      if (!needCrease(hit, 'drive')) return;
      if (state.fold) clearFold();
      const sp = state.spec;
      if (ev && ev.shiftKey) {
        // several drives: shift-click adds a crease (or removes it)
        if (!sp.drives.length && sp.drive >= 0) sp.drives = [sp.drive];
        sp.drives = sp.drives.includes(hit.index) ? sp.drives.filter((e) => e !== hit.index) : sp.drives.concat([hit.index]);
        sp.drive = sp.drives.length ? sp.drives[0] : -1;
      } else {
        sp.drives = [];
        sp.drive = hit.index;
      }
      state.spec.locks.delete(hit.index);
      // the target's sign follows the crease's assignment (valley > 0, mountain < 0)
      const to = $('spec-to');
      const a = doc.assignment[hit.index];
      if ((a === 'M' && +to.value > 0) || (a === 'V' && +to.value < 0)) to.value = String(-to.value);
      renderSpec();
      return;
    }
    case 'lock':
      if (!needCrease(hit, 'lock')) return;
      if (state.fold) clearFold();
      if (state.spec.locks.has(hit.index)) state.spec.locks.delete(hit.index);
      else state.spec.locks.add(hit.index);
      if (state.spec.drive === hit.index) state.spec.drive = -1;
      renderSpec();
      maybeDof();
      return;
  }
}

async function edit(op) {
  await action(async () => {
    const r = await api.compute(op.op, () => api.post('edit', { ops: [op] }));
    for (const line of r.log) message(line);
    await refresh();
  });
}

function onHover(hit, ev) {
  const tip = $('tooltip');
  const info = $('hover-info');
  if (!hit || hit.kind === 'none') {
    tip.hidden = true;
    return;
  }
  const doc = state.doc;
  let text = '';
  if (hit.kind === 'vertex') {
    const [x, y] = doc.flat[hit.index];
    text = `vertex ${hit.index} (${fmt(x)}, ${fmt(y)})`;
  } else if (hit.kind === 'edge') {
    const a = doc.assignment[hit.index];
    text = `crease ${hit.index}: ${ASSIGNMENT_NAMES[a] || a}`;
    if (a !== 'B') text += `, ${fmt(doc.foldAngle[hit.index] || 0, 4)}°`;
    const off = state.fold && state.fold.offending_edges.find((o) => o.edge === hit.index);
    if (off) text += ` — would fold to ${fmt(off.angle_deg, 4)}° against its assignment (${state.fold.verdict})`;
    if (hit.index === state.spec.drive) text += ' · driven';
    if (state.spec.locks.has(hit.index)) text += ' · locked';
    const sp = state.fold && state.fold.split;
    if (sp) {
      if (state.fold.frame_a.includes(hit.index)) text += ' · Frame A';
      if (state.fold.frame_b.includes(hit.index)) text += ' · Frame B';
      if (state.fold.surrounding.includes(hit.index)) text += ' · surrounding';
    }
  } else if (hit.kind === 'face') {
    text = faceLabel(doc, hit.index) + (hit.index === state.spec.fix ? ' · fixed to the ground' : '');
  } else if (hit.kind === 'check') {
    text = `vertex ${hit.index}: ` + v2.layers.marks.querySelector(`[data-bad-vertex="${hit.index}"]`).dataset.reason;
  } else if (hit.kind === 'solution') {
    text = `solution ${hit.index + 1}: click to crease it`;
  }
  info.textContent = text;
  tip.textContent = text;
  tip.hidden = false;
  if (ev) {
    tip.style.left = ev.clientX + 14 + 'px';
    tip.style.top = ev.clientY + 12 + 'px';
  }
}

// --- start ---------------------------------------------------------------------------------------

let v2, v3, plot;
// the document's frames replayed as a motion while no sequence holds the timeline (frames.js)
let replay = null;

function token() {
  const q = new URLSearchParams(location.search).get('token');
  if (q) {
    sessionStorage.setItem('orikin-token', q);
    history.replaceState(null, '', location.pathname);
    return q;
  }
  return sessionStorage.getItem('orikin-token');
}

function wire() {
  $('new-sheet').onclick = () => $('new-dialog').showModal();
  $('new-ok').addEventListener('click', (ev) => {
    ev.preventDefault();
    $('new-dialog').close('ok');
    const kind = document.querySelector('input[name=kind]:checked').value;
    const body = kind === 'square' ? { square: +$('new-side').value } : { rect: [+$('new-w').value, +$('new-h').value] };
    action(async () => {
      await api.post('new', body);
      forgetDocument();
      await refresh();
      setupTimeline();
      v3.fit();
    });
  });
  $('open-file').onchange = (ev) => { if (ev.target.files[0]) openFile(ev.target.files[0]); ev.target.value = ''; };
  $('download-fold').onclick = () => exportAs('fold');
  $('export-format').onchange = (ev) => {
    const [format, of] = ev.target.value.split(':');
    if (format) exportAs(format, of);
    ev.target.value = '';
  };
  // Save-back: a file changed on disk since the studio read it is overwritten only when asked.
  const saveBack = async (what, path) => {
    if (!confirm(`Write the ${what} to ${path}?`)) return;
    let r;
    try {
      r = await api.post('save', { what });
    } catch (e) {
      if (!(e instanceof ApiError && e.body && e.body.conflict)) throw e;
      if (!confirm(`${e.message}.\n\nOverwrite it anyway?`)) { message('not saved: ' + e.message, true); return; }
      r = await api.post('save', { what, overwrite: true });
    }
    message('saved ' + r.saved);
    await refresh();
  };
  $('save-back').onclick = () => action(() => saveBack('document', state.session.save_path));
  $('save-seq').onclick = () => action(() => saveBack('sequence', state.session.sequence_path));
  $('recover').onclick = () => action(async () => {
    await api.post('recover', { action: 'recover' });
    message('recovered the unsaved edits of an earlier session (Undo goes back to the file)');
    await refresh();
  });
  $('discard-recovery').onclick = () => action(async () => {
    if (!confirm('Delete the unsaved edits of the earlier session for good?')) return;
    await api.post('recover', { action: 'discard' });
    message('discarded the autosave');
    await refresh();
  });
  $('download-seq').onclick = () => {
    if (!state.folds.length) { message('no folds to download', true); return; }
    download('sequence.seq.json', new Blob([JSON.stringify(sequenceJson(state.folds), null, 2) + '\n'], { type: 'application/json' }));
  };
  $('undo').onclick = () => action(async () => { await api.compute('undo', () => api.post('undo')); await refresh(); });
  $('redo').onclick = () => action(async () => { await api.compute('redo', () => api.post('redo')); await refresh(); });
  for (const b of document.querySelectorAll('[data-layout]'))
    b.onclick = () => {
      $('main').className = 'layout-' + b.dataset.layout;
      for (const o of document.querySelectorAll('[data-layout]')) o.classList.toggle('on', o === b);
    };
  for (const b of document.querySelectorAll('[data-tool]')) b.onclick = () => setTool(b.dataset.tool === state.tool ? 'select' : b.dataset.tool);
  $('axiom-number').onchange = () => { setTool('axiom'); };
  $('clear-spec').onclick = () => { state.spec = { fix: -1, drive: -1, drives: [], locks: new Set() }; clearFold(); renderSpec(); renderTree(); maybeDof(); };
  $('compute').onclick = compute;
  $('whole-slider').oninput = (ev) => wholeFold.fold(+ev.target.value);
  $('whole-compliant').onchange = () => wholeFold.fold(+$('whole-slider').value);
  $('check-tolerance').onchange = () => action(runCheck);
  $('regularize').onclick = () => action(regularize);
  $('collide').onclick = () => action(collideShown);
  $('show-seq-contact').onclick = () => action(() => showContact('sequence'));
  $('fold-slider').oninput = (ev) => action(() => showFoldFrame(+ev.target.value));
  $('play-fold').onclick = playFold;
  $('add-fold').onclick = addFold;
  $('run-seq').onclick = () => action(() => runSequence(state.folds, 'sequence'));
  $('play').onclick = togglePlay;
  $('t-slider').oninput = (ev) => (replay.on ? replay.slide(+ev.target.value) : showTime(+ev.target.value / sliderSteps()));
  $('t-value').onchange = (ev) => {
    if (replay.on) { replay.stop(); if (isFinite(+ev.target.value)) replay.show(+ev.target.value); return; }
    const t = Math.min(Math.max(+ev.target.value, 0), lastCleanT());
    if (isFinite(t)) showTime(t);
  };
  for (const b of document.querySelectorAll('[data-rot]')) b.onclick = () => { const [k, s] = b.dataset.rot.split(','); v3.rotate(k, +s); };
  for (const b of document.querySelectorAll('[data-zoom]')) b.onclick = () => v3.zoom(+b.dataset.zoom);
  $('fit3d').onclick = () => v3.fit();
  $('preset').onchange = (ev) => { v3.preset(ev.target.value); ev.target.value = ''; };
  $('grid-toggle').onchange = (ev) => v3.setGrid(ev.target.checked);
  $('edges-toggle').onchange = (ev) => v3.setCreasesVisible(ev.target.checked);
  $('color-front').oninput = (ev) => v3.setColors(ev.target.value, null);
  $('color-back').oninput = (ev) => v3.setColors(null, ev.target.value);
  $('texture-file').onchange = (ev) => { if (ev.target.files[0]) openTexture(ev.target.files[0]); ev.target.value = ''; };
  $('texture-clear').onclick = () => { v3.setTexture(null); v3.setColors($('color-front').value, null); $('texture-clear').hidden = true; };
  // drag and drop anywhere
  let depth = 0;
  window.addEventListener('dragenter', (ev) => { ev.preventDefault(); depth++; $('drop-overlay').hidden = false; });
  window.addEventListener('dragleave', () => { if (--depth <= 0) { depth = 0; $('drop-overlay').hidden = true; } });
  window.addEventListener('dragover', (ev) => ev.preventDefault());
  window.addEventListener('drop', (ev) => {
    ev.preventDefault();
    depth = 0;
    $('drop-overlay').hidden = true;
    const f = ev.dataTransfer && ev.dataTransfer.files[0];
    if (f) openFile(f);
  });
  window.addEventListener('keydown', (ev) => {
    if (ev.target instanceof HTMLInputElement || ev.target instanceof HTMLSelectElement) return;
    if ((ev.ctrlKey || ev.metaKey) && ev.key.toLowerCase() === 'z') { ev.preventDefault(); $(ev.shiftKey ? 'redo' : 'undo').click(); }
    else if ((ev.ctrlKey || ev.metaKey) && ev.key.toLowerCase() === 'y') { ev.preventDefault(); $('redo').click(); }
    else if (ev.key === 'Escape') setTool('select');
  });
  // the legend of line styles
  const legend = $('legend2d');
  for (const [a, label] of [['M', 'mountain'], ['V', 'valley'], ['U', 'unassigned'], ['B', 'boundary']]) {
    const span = document.createElement('span');
    span.innerHTML = `<svg width="26" height="8"><line class="edge ${a}" x1="1" y1="4" x2="25" y2="4"></line></svg> ${label}`;
    legend.appendChild(span);
  }
}

async function start() {
  const tok = token();
  v2 = new View2D($('cp'), { onHover, onClick: (hit, ev) => onClick(hit, ev) });
  v3 = new View3D($('gl'));
  plot = new Plot($('plot'));
  wire();
  if (!tok) {
    message('this page needs the session token: open the URL that orikin view printed', true);
    return;
  }
  api = new Api(tok, progress);
  replay = new FrameReplay(api, $, { show: (pos, label) => {
    v3.setPositions(pos);
    if (state.shown === 'contact') clearCollision();
    state.shown = 'frames';
    $('state3d').textContent = label;
  } });
  await action(async () => {
    // the Export menu follows what there is to export (store.js)
    store.subscribe(['session', 'fold', 'sequence', 'compliant'], () => renderExportMenu());
    await refresh(true);
    renderExportMenu();
    renderCollection();
    if (state.session.sequence) {
      const r = await api.get('sequence');
      store.set({ sequence: r });
      state.folds = r.folds.map((f) => {
        // a fold toward the targets ("percent") has no drive
        const o = f.percent !== undefined && f.percent !== null
          ? { fix: f.fix, percent: f.percent, step: f.step_deg, lock: f.lock }
          : { fix: f.fix, drive: f.drive, to: f.to_deg, step: f.step_deg, lock: f.lock };
        if (f.name) o.name = f.name;
        if (f.from_deg !== null) o.from = f.from_deg;
        return o;
      });
      setupTimeline();
      if (r.frames.length) await showTime(0);
      if (r.collision) message(`collision: ${r.reason} (the sequence stops before it; "contact" shows it)`, true);
    } else {
      setupTimeline();
    }
  });
  setTool('select');
  window.studio.ready = true;
}

// For people and tests: read-only views of what the page shows.
window.studio = {
  ready: false,
  positions: () => (v3 && v3.positions ? Array.from(v3.positions) : []),
  shownT: () => state.shownT,
  replayT: () => (replay && replay.shown ? replay.shown.t : null),
  shown: () => state.shown,
  version: () => state.version,
  lastError: () => state.lastError,
  busy: () => (api ? api.busy + api.pending : 0) + (state.inflight ? 1 : 0) + state.work + (wholeFold.running() ? 1 : 0),
  angles: () => (state.shownAngles ? Array.from(state.shownAngles) : []),
  wholePercent: () => wholeFold.percent(),
  compliant: () => state.compliant || null,
  faceColors: () => (v3 && v3.faceColors ? v3.faceColors : null),
  stats: () => ({
    states: state.stats.states,
    framesDrawn: v3 ? v3.frameCount : 0,
    latencyMs: state.stats.latency.length ? state.stats.latency.reduce((a, b) => a + b, 0) / state.stats.latency.length : null,
  }),
  clientOf: (x, y) => v2.clientOf(x, y),
  faceClient: (f) => v2.clientOf(...state.doc.faceCentroid[f]),
  edgeClient: (e) => {
    const [a, b] = state.doc.edges[e];
    const P = state.doc.flat;
    return v2.clientOf((P[a][0] + P[b][0]) / 2, (P[a][1] + P[b][1]) / 2);
  },
  vertexClient: (v) => v2.clientOf(...state.doc.flat[v]),
  renderMs: (n = 10) => v3.timeRender(n),
  setProgressDelay: (ms) => { api.progressDelay = ms; },
  fold: () => state.fold,
  sequence: () => state.sequence,
  check: () => state.check,
  collide: () => state.collide,
  regularizeResult: () => state.regularize,
  highlight: () => (v3 ? v3.highlighted : null),
  viewExtent: () => (v3 ? v3.extent() : null),
  exportOptions: () => [...document.querySelectorAll('#export-format option')].filter((o) => o.value).map((o) => o.value),
  errors: () => [...document.querySelectorAll('#messages .msg.error')].map((e) => e.textContent),
  exportParams: (format, of) => exportParams(format, of),
  spec: () => ({ fix: state.spec.fix, drive: state.spec.drive, drives: [...state.spec.drives], locks: [...state.spec.locks] }),
  foldRequest: () => foldBody(),
};

start();
