import assert from 'node:assert/strict';
import test from 'node:test';
import { fmt } from '../src/document.js';
import { foldItemText, foldStateText, foldVerdictText } from '../src/format.js';

test('fmt trims trailing zeros and keeps non-finite values', () => {
  assert.equal(fmt(90), '90');
  assert.equal(fmt(0.1 + 0.2), '0.3');
  assert.equal(fmt(1.23456789, 3), '1.235');
  assert.equal(fmt(-0.0000001), '-0');
  assert.equal(fmt(NaN), 'NaN');
});

test('a hand-written fold without a step shows the default step, never "undefined"', () => {
  const t = foldItemText({ fix: 4, drive: 12, to: 180 });
  assert.equal(t, 'fix 4, drive 12 to 180°, step 10°');
  assert.ok(!/undefined|NaN/.test(foldItemText({ drive: 3, to: -90 })));
  assert.equal(foldItemText({ drive: 3, to: -90 }), 'default fixed face, drive 3 to -90°, step 10°');
});

test('folds toward the targets, locks, from and names', () => {
  assert.equal(foldItemText({ name: 'part way', percent: 60, step: 20 }), 'part way: default fixed face, 60 % of the way toward the targets, step 20°');
  assert.equal(foldItemText({ fix: 0, drive: 1, to: 90, step: 5, lock: [2, 7], from: 10 }), 'fix 0, drive 1 to 90°, step 5°, lock 2,7, from 10°');
  assert.equal(foldItemText({ fix: 0, percent: 100, step: 10, lock: 'auto' }), 'fix 0, 100 % of the way toward the targets, step 10°, lock auto');
});

test('fold states are counted as the verdict counts them', () => {
  const r = { valid: true, solver: 'newton', frames: new Array(19).fill({}) };
  assert.equal(foldVerdictText(r), 'valid: 19 states, newton');
  assert.equal(foldStateText(18, 19, 180), 'fold: state 19 of 19, drive 180°');
  assert.equal(foldStateText(0, 19, 0), 'fold: state 1 of 19, drive 0°');
  assert.equal(foldStateText(3, 5, NaN), 'fold: state 4 of 5');
  assert.equal(foldVerdictText({ valid: false, verdict: 'blocked', frames: new Array(7).fill({}) }), 'blocked: 7 states up to the stop');
  assert.equal(foldVerdictText({ valid: false, verdict: 'invalid assignment', frames: [] }), 'invalid assignment');
});
