import { assertFinite, assertInteger } from '../validation/validate.js';

/**
 * Seeded pseudo-random numbers for deterministic scenes, emitters and turbulence.
 *
 * Generator: SFC32 (Chris Doty-Humphrey's Small Fast Counting generator, from PractRand),
 * 128 bits of state, period at least 2^32, passes PractRand to 2^40+ bytes. Its state is
 * seeded from one 32-bit seed by SplitMix32 (Steele, Lea and Flood, "Fast splittable
 * pseudorandom number generators", OOPSLA 2014) and warmed up by 12 outputs.
 *
 * The same seed gives the same sequence on every platform (only 32-bit integer arithmetic).
 * @category Utilities
 */
export class Rng {
  private a = 0;
  private b = 0;
  private c = 0;
  private d = 0;
  /** The seed this generator was created or last reset with. */
  seed = 0;

  /** @param seed any finite number; it is truncated to 32 bits. @throws RangeError if not finite. */
  constructor(seed = 1) {
    this.reset(seed);
  }

  /** Restarts the sequence from `seed`. @throws TypeError | RangeError if `seed` is not a finite number. */
  reset(seed: number): void {
    assertFinite('Rng.reset', 'seed', seed);
    this.seed = seed;
    let s = seed >>> 0;
    const splitmix = (): number => {
      s = (s + 0x9e3779b9) | 0;
      let z = s;
      z = Math.imul(z ^ (z >>> 16), 0x85ebca6b);
      z = Math.imul(z ^ (z >>> 13), 0xc2b2ae35);
      return (z ^ (z >>> 16)) >>> 0;
    };
    this.a = splitmix();
    this.b = splitmix();
    this.c = splitmix();
    this.d = splitmix();
    for (let i = 0; i < 12; i++) this.nextUint32();
  }

  /** Next unsigned 32-bit integer, uniform on [0, 2^32). */
  nextUint32(): number {
    const a = this.a,
      b = this.b,
      c = this.c,
      d = this.d;
    const t = (((a + b) | 0) + d) | 0;
    this.d = (d + 1) | 0;
    this.a = b ^ (b >>> 9);
    this.b = (c + (c << 3)) | 0;
    const r = (c << 21) | (c >>> 11);
    this.c = (r + t) | 0;
    return t >>> 0;
  }

  /** Uniform float on [0, 1) with 32 bits of resolution. */
  next(): number {
    return this.nextUint32() / 4294967296;
  }

  /** Uniform float on [min, max). */
  range(min: number, max: number): number {
    return min + (max - min) * this.next();
  }

  /** Uniform integer on [min, max] inclusive. @throws RangeError unless min <= max are integers. */
  int(min: number, max: number): number {
    assertInteger('Rng.int', 'min', min, Number.MIN_SAFE_INTEGER, Number.MAX_SAFE_INTEGER);
    assertInteger('Rng.int', 'max', max, min, Number.MAX_SAFE_INTEGER);
    return min + Math.floor(this.next() * (max - min + 1));
  }

  /**
   * Standard normal deviate (mean 0, standard deviation 1) by the Box-Muller transform
   * (Box and Muller, Ann. Math. Statist. 29, 1958). One value per call; the pair's second is discarded
   * so the stream stays simple to reason about.
   */
  normal(): number {
    let u = this.next();
    if (u < 1e-300) u = 1e-300;
    const v = this.next();
    return Math.sqrt(-2 * Math.log(u)) * Math.cos(2 * Math.PI * v);
  }
}
