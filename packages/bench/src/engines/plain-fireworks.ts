import { Rng, SCENES } from '@bitphysics/physics';
import type { EngineInstance, SceneRunOptions } from './types.js';

const DT = 1 / 60;

/** One kind of particle of the fireworks scene: how it is born, how it moves and what it bursts into. */
interface Kind {
  speed: [number, number];
  life: [number, number];
  inherit: number;
  mass: number;
  drag: number;
  /** Burst on death: the kind (index) and count, or -1. */
  child: number;
  childCount: number;
}

// The fireworks scene's three emitters (packages/physics/src/scenes/fireworks.ts), as data: shells from a
// 60 m line at count / 1350 per second bursting into 200 sparks, each bursting into 7 embers.
const SHELL = 0,
  SPARK = 1,
  EMBER = 2;
const KINDS: Kind[] = [
  { speed: [28, 34], life: [0.9, 1.2], inherit: 0, mass: 0.1, drag: 0, child: SPARK, childCount: 200 },
  { speed: [4, 12], life: [1, 2], inherit: 1, mass: 0.002, drag: 4e-5, child: EMBER, childCount: 7 },
  { speed: [1, 3], life: [0.5, 1], inherit: 0, mass: 0.001, drag: 2e-5, child: -1, childCount: 0 },
];

/**
 * The fireworks scene as a bare structure-of-arrays engine with a free list: the same births (shells
 * at the scene's rate, death bursts of 200 sparks and 7 embers), deaths, gravity and quadratic drag,
 * semi-implicit Euler, over Float64Arrays of the world's capacity; a dead particle's slot goes on a
 * stack and the next birth takes it. What our churn costs is compared against this.
 */
export function createPlainFireworks(options: SceneRunOptions): EngineInstance {
  const count = options.count;
  const capacity = SCENES.fireworks!.worldOptions({ count }).capacity!;
  const rng = new Rng(options.seed);
  const n = capacity;
  const px = new Float64Array(n),
    py = new Float64Array(n),
    vx = new Float64Array(n),
    vy = new Float64Array(n);
  const age = new Float64Array(n),
    life = new Float64Array(n);
  const kind = new Uint8Array(n);
  const free = new Int32Array(n);
  let freeTop = 0;
  for (let i = n - 1; i >= 0; i--) free[freeTop++] = i;
  /** Live slots, packed (index into it kept per slot for O(1) removal). */
  const live = new Int32Array(n),
    where = new Int32Array(n);
  let liveCount = 0,
    spawned = 0,
    expired = 0;
  const dead = new Int32Array(n);
  const rate = count / 1350;
  let carry = 0;
  const g = -9.81;

  function spawn(k: number, x: number, y: number, bvx: number, bvy: number, dirAngle: number, spread: number): void {
    if (freeTop === 0) return;
    const s = free[--freeTop]!;
    const K = KINDS[k]!;
    const a = dirAngle + rng.range(-spread, spread);
    const sp = rng.range(K.speed[0], K.speed[1]);
    px[s] = x;
    py[s] = y;
    vx[s] = K.inherit * bvx + sp * Math.cos(a);
    vy[s] = K.inherit * bvy + sp * Math.sin(a);
    age[s] = 0;
    life[s] = rng.range(K.life[0], K.life[1]);
    kind[s] = k;
    where[s] = liveCount;
    live[liveCount++] = s;
    spawned++;
  }

  return {
    engine: 'plain-loop',
    notes: [
      'plain-loop: fireworks over Float64Arrays with a free list (shells, 200 sparks a shell, 7 embers a spark; gravity, quadratic drag F = -k |v| v, semi-implicit Euler, h = 1/60 s)',
    ],
    step(): void {
      spawned = 0;
      expired = 0;
      // Deaths (and their bursts, born after the pass).
      let nd = 0;
      for (let i = 0; i < liveCount; i++) {
        const s = live[i]!;
        age[s] = age[s]! + DT;
        if (age[s]! >= life[s]!) dead[nd++] = s;
      }
      for (let d = 0; d < nd; d++) {
        const s = dead[d]!;
        const j = where[s]!,
          last = live[--liveCount]!;
        live[j] = last;
        where[last] = j;
        free[freeTop++] = s;
        expired++;
        const K = KINDS[kind[s]!]!;
        for (let c = 0; c < K.childCount; c++) spawn(K.child, px[s]!, py[s]!, vx[s]!, vy[s]!, Math.PI / 2, Math.PI);
      }
      // Births from the line of shells.
      carry += rate * DT;
      while (carry >= 1) {
        carry -= 1;
        spawn(SHELL, rng.range(-30, 30), 0, 0, 0, Math.PI / 2, 0.15);
      }
      // Forces and semi-implicit Euler.
      for (let i = 0; i < liveCount; i++) {
        const s = live[i]!;
        const K = KINDS[kind[s]!]!;
        let ax = 0,
          ay = g;
        if (K.drag > 0) {
          const sp = Math.sqrt(vx[s]! * vx[s]! + vy[s]! * vy[s]!),
            c = (-K.drag * sp) / K.mass;
          ax += c * vx[s]!;
          ay += c * vy[s]!;
        }
        vx[s] = vx[s]! + ax * DT;
        vy[s] = vy[s]! + ay * DT;
        px[s] = px[s]! + vx[s]! * DT;
        py[s] = py[s]! + vy[s]! * DT;
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
