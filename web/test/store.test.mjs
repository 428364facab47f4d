import assert from 'node:assert/strict';
import test from 'node:test';
import { createStore } from '../src/store.js';

test('set merges and tells only the listeners of the keys that changed value', () => {
  const s = createStore({ a: 1, b: 2 });
  const heard = [];
  s.subscribe('a', (st, keys) => heard.push(['a', st.a, keys.join()]));
  s.subscribe(['b'], (st) => heard.push(['b', st.b]));
  assert.deepEqual(s.set({ a: 1 }), []);
  assert.deepEqual(heard, []);
  assert.deepEqual(s.set({ a: 3, b: 2 }), ['a']);
  assert.deepEqual(heard, [['a', 3, 'a']]);
  assert.equal(s.state.a, 3);
});

test('emit tells in-place changes; a listener of several keys is called once; unsubscribe', () => {
  const s = createStore({ list: [], n: 0 });
  let calls = 0, all = 0;
  const off = s.subscribe(['list', 'n'], () => calls++);
  s.subscribe('*', () => all++);
  s.state.list.push(1);
  s.emit('list', 'n');
  assert.equal(calls, 1);
  assert.equal(all, 1);
  off();
  s.set({ n: 5 });
  assert.equal(calls, 1);
  assert.equal(all, 2);
});
