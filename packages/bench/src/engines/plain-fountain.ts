import { FOUNTAIN_MEAN_LIFETIME, Rng, SCENES } from '@bitphysics/physics';
import type { EngineInstance, SceneRunOptions } from './types.js';

const DT = 1 / 60;

/**
 * The fountain scene as a bare structure-of-arrays engine with a free list: drops born at the
 * scene's rate (count / (5/6 s)) on a 0.5 m disc, thrown within 0.35 rad of vertical at 9 to 13 m/s,
 * living 2/3 to 1 s; gravity (0, -9.81) with semi-implicit Euler and the exact free-fall drift
 * x += (v - g h / 2) h (as ours integrates bare particles), over Float64Arrays of the world's
 * capacity; a dead drop's slot goes on a stack and the next birth takes it. What our churn costs at a
 * million particles is compared against this.
 */
export function createPlainFountain(options: SceneRunOptions): EngineInstance {
  const count = options.count;
  const n = SCENES.fountain!.worldOptions({ count }).capacity!;
  const rng = new Rng(options.seed);
  const px = new Float64Array(n),
    py = new Float64Array(n),
    vx = new Float64Array(n),
    vy = new Float64Array(n);
  const age = new Float64Array(n),
    life = new Float64Array(n);
  const free = new Int32Array(n);
  let freeTop = 0;
  for (let i = n - 1; i >= 0; i--) free[freeTop++] = i;
  /** Live slots, packed (index into it kept per slot for O(1) removal). */
  const live = new Int32Array(n),
    where = new Int32Array(n);
  let liveCount = 0,
    spawned = 0,
    expired = 0;
  const rate = count / FOUNTAIN_MEAN_LIFETIME;
  let carry = 0;
  const g = -9.81,
    gh = g * DT,
    half = 0.5 * gh;

  return {
    engine: 'plain-loop',
    notes: [
      'plain-loop: fountain over Float64Arrays with a free list (disc of 0.5 m, 9-13 m/s within 0.35 rad of up, lifetimes 2/3-1 s; gravity, semi-implicit Euler with exact free fall, h = 1/60 s)',
    ],
    step(): void {
      spawned = 0;
      expired = 0;
      // Deaths.
      for (let i = 0; i < liveCount; i++) {
        const s = live[i]!;
        const a = age[s]! + DT;
        age[s] = a;
        if (a >= life[s]!) {
          const last = live[--liveCount]!;
          live[i] = last;
          where[last] = i;
          free[freeTop++] = s;
          expired++;
          i--;
        }
      }
      // Births.
      carry += rate * DT;
      const whole = Math.floor(carry);
      carry -= whole;
      for (let k = 0; k < whole && freeTop > 0; k++) {
        const s = free[--freeTop]!;
        const ang = rng.range(0, 2 * Math.PI),
          r = 0.5 * Math.sqrt(rng.next());
        px[s] = r * Math.cos(ang);
        py[s] = r * Math.sin(ang);
        const dir = Math.PI / 2 + rng.range(-0.35, 0.35),
          sp = rng.range(9, 13);
        vx[s] = sp * Math.cos(dir);
        vy[s] = sp * Math.sin(dir);
        age[s] = 0;
        life[s] = rng.range(2 / 3, 1);
        where[s] = liveCount;
        live[liveCount++] = s;
        spawned++;
      }
      // Gravity and semi-implicit Euler.
      for (let i = 0; i < liveCount; i++) {
        const s = live[i]!;
        const nvy = vy[s]! + gh;
        vy[s] = nvy;
        px[s] = px[s]! + vx[s]! * DT;
        py[s] = py[s]! + (nvy - half) * DT;
      }
    },
    stats() {
      return { bodies: liveCount, contacts: null, extra: { live: liveCount, spawnedPerStep: spawned, expiredPerStep: expired } };
    },
    snapshot() {
      const positions = new Float64Array(2 * liveCount);
      for (let i = 0; i < liveCount; i++) {
        const s = live[i]!;
        positions[2 * i] = px[s]!;
        positions[2 * i + 1] = py[s]!;
      }
      return { dimensions: 2, count: liveCount, positions };
    },
    dispose(): void {},
  };
}
