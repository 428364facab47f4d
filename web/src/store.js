// The page's store: one state object, changed through set() (or in place followed by emit()),
// with listeners per key. Pure (no DOM): the feature modules read store.state and subscribe to
// what they draw.

export function createStore(initial) {
  const state = { ...initial };
  const listeners = new Map(); // key -> Set of functions (key '*' hears every change)
  const emit = (keys) => {
    const called = new Set();
    for (const k of [...keys, '*']) {
      for (const fn of listeners.get(k) || []) {
        if (called.has(fn)) continue;
        called.add(fn);
        fn(state, keys);
      }
    }
  };
  return {
    state,
    // Merge these fields into the state and tell the listeners of the keys that changed value.
    set(patch) {
      const changed = Object.keys(patch).filter((k) => !Object.is(state[k], patch[k]));
      Object.assign(state, patch);
      if (changed.length) emit(changed);
      return changed;
    },
    // Tell the listeners of these keys that their (mutable) values changed in place.
    emit(...keys) { emit(keys); },
    // Call fn(state, keys) when one of these keys changes; returns the function that unsubscribes.
    subscribe(keys, fn) {
      for (const k of [].concat(keys)) {
        if (!listeners.has(k)) listeners.set(k, new Set());
        listeners.get(k).add(fn);
      }
      return () => { for (const k of [].concat(keys)) listeners.get(k).delete(fn); };
    },
  };
}
