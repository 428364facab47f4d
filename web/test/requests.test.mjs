import assert from 'node:assert/strict';
import test from 'node:test';
import { exportGroups, exportParams, foldBody, foldMotionExportable, sequenceFold } from '../src/requests.js';

test('a fold body: the fixed face is left out when none is chosen (the CLI default)', () => {
  const b = foldBody({ fix: -1, drive: 12, locks: new Set([11, 3]) }, { to: '90', step: '10', from: '', frame: 0 });
  assert.deepEqual(b, { drive: 12, to: 90, step: 10, lock: [3, 11] });
  const c = foldBody({ fix: 4, drive: 12, locks: new Set() }, { to: '-45', step: '5', from: ' 10 ', frame: 2 });
  assert.deepEqual(c, { fix: 4, drive: 12, to: -45, step: 5, lock: [], from: 10, frame: 2 });
});

test('several drives, lock auto, symmetric, percent', () => {
  assert.deepEqual(foldBody({ fix: 0, drive: -1, drives: [3, 7], lockAuto: true, symmetric: true }, { to: 60, step: 10 }),
    { fix: 0, drive: [3, 7], to: [60, 60], step: 10, lock: 'auto', symmetric: true });
  assert.deepEqual(foldBody({ fix: -1, drive: 3, drives: [3, 7], locks: [] }, { to: '90, -45', step: '' }).to, [90, -45]);
  assert.throws(() => foldBody({ fix: -1, drive: 3, drives: [3, 7, 9], locks: [] }, { to: '90,45' }), /3 drives take 3 target angles/);
  assert.deepEqual(foldBody({ fix: -1, drive: -1, locks: [] }, { percent: 50, from: '20' }), { percent: 50, lock: [] });
  assert.throws(() => foldBody({ fix: 0, drive: -1, locks: [] }, { to: 90 }), /driven crease/);
});

test('the folding manager keeps what the request said', () => {
  assert.deepEqual(sequenceFold({ fix: 4, drive: 12, to: 90, step: 10, lock: [11] }, 'fold 1'),
    { name: 'fold 1', fix: 4, drive: 12, to: 90, step: 10, lock: [11] });
  assert.deepEqual(sequenceFold({ drive: 12, to: 90, lock: [] }, 'fold 2'), { name: 'fold 2', drive: 12, to: 90, lock: [] });
});

const FORMATS = [
  { format: 'fold', label: 'FOLD', kind: 'document', motion: false },
  { format: 'png', label: 'PNG picture', kind: 'picture', motion: false },
  { format: 'obj', label: 'OBJ mesh', kind: 'mesh', motion: false },
  { format: 'gltf', label: 'glTF mesh', kind: 'mesh', motion: true },
  { format: 'glb', label: 'GLB mesh', kind: 'mesh', motion: true },
  { format: 'gif', label: 'GIF animation', kind: 'animation', motion: true },
];

test('the export menu lists glTF once without a motion, and the motions only when they exist', () => {
  const count = (groups, f) => groups.flatMap((g) => g.options).filter((o) => o.value.split(':')[0] === f).length;
  const plain = exportGroups(FORMATS, {});
  assert.equal(count(plain, 'gltf'), 1);
  assert.deepEqual(plain.map((g) => g.label), ['crease pattern', 'picture of the state shown', 'mesh of the state shown']);
  const seq = exportGroups(FORMATS, { sequence: true });
  assert.deepEqual(seq[3].options.map((o) => o.value), ['gltf:sequence', 'glb:sequence', 'gif:sequence']);
  assert.equal(seq[3].options[0].label, 'glTF animation');
  assert.equal(exportGroups(FORMATS, { sequence: true, fold: true }).length, 5);
  const bent = exportGroups(FORMATS, { compliant: true });
  assert.deepEqual(bent[3].options.map((o) => o.value), ['gltf:compliant', 'glb:compliant', 'gif:compliant'],
    'a compliant fold moves as a glTF (morphing) or a GIF');
});

test('a fold is offered as a motion when the server exports it', () => {
  const frames = [{}, {}, {}];
  assert.equal(foldMotionExportable(null), false);
  assert.equal(foldMotionExportable({ valid: true, verdict: 'valid', frames }), true);
  assert.equal(foldMotionExportable({ valid: false, verdict: 'blocked', frames }), false);
  assert.equal(foldMotionExportable({ mode: 'targets', valid: true, verdict: 'reached', frames }), true);
  assert.equal(foldMotionExportable({ mode: 'targets', valid: false, verdict: 'stationary', frames }), true);
  assert.equal(foldMotionExportable({ mode: 'targets', valid: false, verdict: 'stationary', frames: [{}] }), false);
  assert.equal(foldMotionExportable({ mode: 'drives', valid: false, verdict: 'invalid assignment', frames }), false);
  assert.equal(foldMotionExportable({ mode: 'drives', valid: true, verdict: 'reached', frames: [] }), false);
});

test('export parameters: a document has none, a picture of a state the camera, a mesh the colours', () => {
  const common = { view: { eye: [1, 2, 3.0000000000001], up: [0, 0, 1] }, canvas: { width: 300, height: 200 },
    colors: { front: '#e8833a', back: '#f4efe6' }, grid: true, stateRef: { t: 1.5 }, flat: false };
  assert.deepEqual(exportParams({ ...common, format: 'fold', kind: 'document' }), { format: 'fold' });
  assert.deepEqual(exportParams({ ...common, format: 'png', kind: 'picture' }),
    { format: 'png', t: 1.5, eye: '1,2,3', up: '0,0,1', perspective: 1, front: '#e8833a', back: '#f4efe6', grid: 1, size: '600x400' });
  assert.deepEqual(exportParams({ ...common, format: 'png', kind: 'picture', flat: true, stateRef: { frame: 0 } }), { format: 'png', frame: 0 });
  assert.deepEqual(exportParams({ ...common, format: 'obj', kind: 'mesh', stateRef: { k: 3 } }), { format: 'obj', k: 3, front: '#e8833a', back: '#f4efe6' });
  const shot = exportParams({ ...common, format: 'png', kind: 'picture', stateRef: { compliant: 1 } });
  assert.equal(shot.compliant, 1);
  assert.equal(shot.color, 'strain', 'the compliant state is drawn coloured by strain, as the page shows it');
  assert.equal(exportParams({ ...common, format: 'glb', kind: 'mesh', stateRef: { compliant: 1 } }).color, undefined);
  assert.equal(exportParams({ ...common, format: 'gif', kind: 'animation', of: 'compliant' }).color, 'strain');
  const gif = exportParams({ ...common, format: 'gif', kind: 'animation', of: 'fold', canvas: { width: 1000, height: 500 } });
  assert.equal(gif.of, 'fold');
  assert.equal(gif.t, undefined);
  assert.equal(gif.size, '800x400');
});
