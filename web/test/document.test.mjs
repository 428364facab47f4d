import assert from 'node:assert/strict';
import test from 'node:test';
import { centroid, faceLabel, isCrease, parseDocument } from '../src/document.js';

const SQUARE = {
  vertices_coords: [[0, 0], [2, 0], [2, 1], [0, 1], [1, 0], [1, 1]],
  edges_vertices: [[0, 4], [4, 1], [1, 2], [2, 5], [5, 3], [3, 0], [4, 5]],
  edges_assignment: ['B', 'B', 'B', 'B', 'B', 'B', 'v'],
  faces_vertices: [[0, 4, 5, 3], [4, 1, 2, 5]],
  'orikin:faces_name': ['Obj11', null],
  file_frames: [{ vertices_coords: [] }],
};

test('a document: frames, box, assignments upper-cased, centroids, names', () => {
  const d = parseDocument(SQUARE);
  assert.equal(d.frames, 2);
  assert.deepEqual(d.box, { x0: 0, y0: 0, x1: 2, y1: 1, size: 2 });
  assert.equal(d.assignment[6], 'V');
  assert.deepEqual(d.foldAngle, [0, 0, 0, 0, 0, 0, 0]);
  assert.equal(d.is3d, false);
  assert.deepEqual(d.faceCentroid, [[0.5, 0.5], [1.5, 0.5]]);
  assert.equal(faceLabel(d, 0), 'Obj11 (face 0)');
  assert.equal(faceLabel(d, 1), 'face 1');
});

test('an empty document has a unit box; a 3D one is known', () => {
  const e = parseDocument({});
  assert.deepEqual(e.box, { x0: 0, y0: 0, x1: 1, y1: 1, size: 1 });
  assert.equal(parseDocument({ vertices_coords: [[0, 0, 0], [1, 0, 0.5]] }).is3d, true);
});

test('centroids of polygons (area-weighted) and degenerate ones (vertex mean)', () => {
  const [cx, cy] = centroid([[0, 0], [4, 0], [0, 3]]);
  assert.ok(Math.abs(cx - 4 / 3) < 1e-15 && Math.abs(cy - 1) < 1e-15);
  assert.deepEqual(centroid([[0, 0], [1, 1], [2, 2]]), [1, 1]);
  assert.ok(isCrease('M') && isCrease('F') && !isCrease('B') && !isCrease('C'));
});
