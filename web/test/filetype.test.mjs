import assert from 'node:assert/strict';
import test from 'node:test';
import { extensionOf, fileKind, jsonKind } from '../src/filetype.js';

test('an SVG is a crease pattern even when the browser types it image/svg+xml', () => {
  assert.equal(fileKind('bird.svg', 'image/svg+xml'), 'pattern');
  assert.equal(fileKind('BIRD.SVG', ''), 'pattern');
  assert.equal(fileKind('noname', 'image/svg+xml'), 'pattern');
});

test('FOLD, OPX and CP are patterns whatever their type', () => {
  assert.equal(fileKind('a.fold', 'application/octet-stream'), 'pattern');
  assert.equal(fileKind('a.opx', 'application/xml'), 'pattern');
  assert.equal(fileKind('a.cp', ''), 'pattern');
});

test('raster images are images; JSON is JSON; the rest unknown', () => {
  assert.equal(fileKind('paper.png', 'image/png'), 'image');
  assert.equal(fileKind('paper.JPG', ''), 'image');
  assert.equal(fileKind('photo', 'image/jpeg'), 'image');
  assert.equal(fileKind('x.seq.json', 'application/json'), 'json');
  assert.equal(fileKind('notes.txt', 'text/plain'), 'unknown');
  // the name wins over the type: a .png typed as SVG is still an image, a .fold typed as PNG a pattern
  assert.equal(fileKind('x.png', 'image/svg+xml'), 'image');
  assert.equal(fileKind('x.fold', 'image/png'), 'pattern');
});

test('extensions and JSON kinds', () => {
  assert.equal(extensionOf('dir.v2/file'), '');
  assert.equal(extensionOf('a.b.SEQ.JSON'), '.json');
  assert.equal(jsonKind({ folds: [] }), 'sequence');
  assert.equal(jsonKind({ creases: [] }), 'composite');
  assert.equal(jsonKind({ hello: 1 }), null);
  assert.equal(jsonKind(null), null);
});
