import { Rng } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';
import { sortByKey } from '../../packages/physics/src/solver/sort-by-key.js';

/**
 * The impact stage orders its seeds with sortByKey, which replaced
 * order.subarray(0, n).sort((x, y) => key[x] - key[y]) (impacts.ts). The state hashes of every scene
 * depend on that order, ties and non-finite keys included, so the reference here is the engine's own
 * typed-array sort with that comparator: the permutation must be the same element for element (no
 * tolerance: these are indices).
 */
describe('impact order (sortByKey)', () => {
  test('same permutation as the typed-array sort with the key comparator: ties, NaN, Infinity, 0 to 3,000 rows', () => {
    const rng = new Rng(7);
    for (let it = 0; it < 400; it++) {
      const n = it < 300 ? Math.floor(rng.range(0, 40)) : Math.floor(rng.range(0, 3000));
      const spare = Math.floor(rng.range(0, 8));
      const key = new Float64Array(n + spare + 4);
      const mode = it % 4;
      for (let i = 0; i < key.length; i++) {
        const u = rng.range(0, 1);
        key[i] =
          mode === 0
            ? Math.floor(u * 5) // many ties
            : mode === 1
              ? u < 0.1
                ? NaN
                : u < 0.2
                  ? Infinity
                  : u < 0.3
                    ? -1
                    : u // non-finite keys
              : mode === 2
                ? u < 0.3
                  ? 0
                  : u * 1e-3 // touching rows (key 0) among impact times
                : u;
      }
      const order = new Int32Array(n + spare);
      for (let i = 0; i < order.length; i++) order[i] = Math.floor(rng.range(0, key.length));
      const expected = order.slice();
      expected.subarray(0, n).sort((x, y) => key[x]! - key[y]!);
      sortByKey(order, key, n);
      expect(Array.from(order)).toEqual(Array.from(expected));
    }
  });
});
