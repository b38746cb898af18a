/**
 * seededRandom(seed): a small seeded generator of numbers in [0, 1) for a game's scenery and level
 * layouts, so a picture or a level is the same on every load. The generator is mulberry32 (Tommy
 * Ettinger's 32-bit generator: a Weyl sequence step of 0x6d2b79f5 and an xorshift-multiply mix;
 * period 2^32), small and fast, enough for placing things; the physics' own `Rng` (SFC32) is the one
 * for simulations.
 */

/**
 * A seeded generator: each call of the returned function gives the next number, uniform in [0, 1)
 * with 32 bits of resolution. The same seed gives the same sequence on every platform (32-bit integer
 * arithmetic only).
 * @param seed any finite number; it is truncated to 32 bits (a seed of 0 stands for 0x9e3779b9, so
 *   that 0 is not a weak start).
 * @throws RangeError naming `seededRandom` if `seed` is not a finite number.
 */
export function seededRandom(seed: number): () => number {
  if (typeof seed !== 'number' || !Number.isFinite(seed)) {
    throw new RangeError(`seededRandom: seed must be a finite number, got ${String(seed)}`);
  }
  let a = seed >>> 0 || 0x9e3779b9;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
