import {
  addBody,
  createPhysicsWorld,
  disposeWorld,
  enableThreads,
  type PhysicsWorld,
  setBoundary,
  stateHash,
  step,
  stepMany,
} from '@bitphysics/physics';
import { afterEach, expect, test } from 'vitest';
import { broadphaseSystem } from '../../packages/physics/src/collision/broadphase/grid.js';
import { PAIRS_MIN_PER_THREAD } from '../../packages/physics/src/collision/broadphase/grid-pairs.js';
import { ballPairs } from '../../packages/physics/src/collision/broadphase/grid-pairs-kernel.js';
import { Rng } from '../../packages/physics/src/math/rng.js';
import { query } from '../../packages/physics/src/world/query.js';

// Worlds with threads > 1 need the thread pool (step/enable-threads.ts).
enableThreads();

// The broadphase's cell pass and the narrowphase's ball-ball contacts on the world's threads: each
// thread handles a range (of the grid, of the pairs), and the ranges are appended in order, so the
// pairs, the contacts and the whole state are identical to the bit to one thread (stateHash hashes
// every bit; tolerance zero). Independent check: the pairs are exactly those a brute-force test of
// every pair of balls finds.

const worlds: PhysicsWorld[] = [];
afterEach(() => {
  for (const w of worlds.splice(0)) disposeWorld(w);
});

/** A lattice of nearly touching balls (gaps of 0.02 diameters) with small random velocities: dense contacts from the first step. */
function lattice(dims: 2 | 3, threads: number, side = dims === 2 ? [65, 64, 1] : [16, 16, 16]): PhysicsWorld {
  const n = side[0]! * side[1]! * side[2]!;
  const world = createPhysicsWorld({ dimensions: dims, capacity: n, gravity: dims === 2 ? [0, 0] : [0, 0, 0], threads });
  worlds.push(world);
  if (world.threadPool !== null) world.threadPool.adaptive = false;
  const rng = new Rng(17);
  for (let k = 0; k < side[2]!; k++) {
    for (let j = 0; j < side[1]!; j++) {
      for (let i = 0; i < side[0]!; i++) {
        const v = [rng.range(-0.1, 0.1), rng.range(-0.1, 0.1), rng.range(-0.1, 0.1)];
        addBody(
          world,
          dims === 2
            ? { position: [1.02 * i, 1.02 * j], velocity: [v[0]!, v[1]!], radius: 0.5 }
            : { position: [1.02 * i, 1.02 * j, 1.02 * k], velocity: v, radius: 0.5 },
        );
      }
    }
  }
  return world;
}

for (const dims of [2, 3] as const) {
  test(`${dims}D touching balls: pairs and contacts on 2 threads give the one-thread state; the pairs are the brute-force ones`, () => {
    const steps = 2;
    const run = (threads: number): [string, PhysicsWorld] => {
      const world = lattice(dims, threads);
      stepMany(world, steps);
      return [stateHash(world), world];
    };
    const [one] = run(1);
    const [two, world] = run(2);
    expect(world.collision.pairCount).toBeGreaterThan(2 * PAIRS_MIN_PER_THREAD);
    // The cell pass and the contacts each ran on the threads every step.
    expect(world.threadPool!.runs).toBeGreaterThanOrEqual(2 * steps);
    expect(two).toBe(one);
    // Brute force over every pair of balls: within reach (radius + margin each) at the start-of-step positions.
    const runs = world.threadPool!.runs;
    broadphaseSystem(world);
    expect(world.threadPool!.runs).toBe(runs + 1);
    const c = world.components,
      cs = world.collision;
    const n = c.Ball.radius.length - 1;
    const found = new Set<number>();
    for (let i = 0; i < cs.pairCount; i++) found.add(cs.pairA[i]! * (n + 1) + cs.pairB[i]!);
    expect(found.size).toBe(cs.pairCount);
    let brute = 0;
    const ox = c.PreviousPosition.x,
      oy = c.PreviousPosition.y,
      oz = c.PreviousPosition.z;
    for (let e = 1; e <= n; e++) {
      for (let f = e + 1; f <= n; f++) {
        const rr = c.Ball.radius[e]! + cs.margin[e]! + c.Ball.radius[f]! + cs.margin[f]!;
        const dx = ox[f]! - ox[e]!,
          dy = oy[f]! - oy[e]!;
        if (dx * dx + dy * dy >= rr * rr) continue;
        const dz = oz[f]! - oz[e]!;
        if (dx * dx + dy * dy + dz * dz < rr * rr) {
          brute++;
          if (!found.has(e * (n + 1) + f)) throw new Error(`pair ${e} ${f} missed`);
        }
      }
    }
    expect(cs.pairCount).toBe(brute);
  }, 60_000);
}

test('sleeping balls: the cell pass stays on the threads, wakes the same balls in the same order and gives the one-thread state', () => {
  // A resting lattice of 4,096 balls (512 x 8) on the floor of a box falls asleep (all of it by step 40:
  // a low pile settles sooner than a tall one, 16 rows took until step ~175, with about as many pairs);
  // then a ball thrown in wakes the part of the pile it hits. Threads and one thread step side by side;
  // the solve of this pile (under 16,384 rows) is in the one-thread order, so the states are equal to the bit.
  const make = (threads: number): PhysicsWorld => {
    const world = createPhysicsWorld({ dimensions: 2, capacity: 5000, gravity: [0, -10], threads });
    worlds.push(world);
    if (world.threadPool !== null) world.threadPool.adaptive = false;
    setBoundary(world, { min: [0, 0], max: [512, 200] });
    for (let j = 0; j < 8; j++) for (let i = 0; i < 512; i++) addBody(world, { position: [0.5 + i, 0.5 + j], radius: 0.5 });
    return world;
  };
  const one = make(1),
    two = make(2);
  const asleep = (w: PhysicsWorld): number => query(w, [w.components.Ball, w.components.Sleeping]).length;
  const pool = two.threadPool!;
  let pairRunsAsleep = 0,
    sleptMost = 0,
    wokenAfterHit = 0;
  const run = pool.run.bind(pool);
  pool.run = (system, kernel, arrays, params, n, ids) => {
    if (kernel === ballPairs && asleep(two) > 0) pairRunsAsleep++;
    return run(system, kernel, arrays, params, n, ids);
  };
  for (let s = 0; s < 90; s++) {
    if (s === 60) {
      sleptMost = asleep(two);
      for (const w of [one, two]) addBody(w, { position: [100.3, 10], velocity: [3, -20], radius: 0.5 });
    }
    step(one);
    step(two);
    if (s === 75) wokenAfterHit = sleptMost - asleep(two);
    if (s % 10 === 0 || s >= 59) expect(stateHash(two), `step ${s}`).toBe(stateHash(one));
  }
  expect(sleptMost).toBe(4096); // the lattice was asleep before the hit
  expect(wokenAfterHit).toBeGreaterThan(0); // and the hit woke some of it
  expect(pairRunsAsleep).toBeGreaterThan(20); // the cell pass ran on the threads with sleeping balls
}, 60_000);

test('2D touching balls on 3 and 4 threads: the narrowphase takes every range, and the state is the one-thread state', () => {
  // Regression: with 4 threads the narrowphase handed its kernel 51 arrays and the pool, which took at
  // most 48, threw; a world of 4 threads could not step a crowded box. The reference is the same scene
  // on one thread, to the bit (tolerance zero, as above).
  const steps = 2;
  const run = (threads: number): string => {
    const world = lattice(2, threads, [100, 100, 1]);
    stepMany(world, steps);
    if (threads > 1) expect(world.collision.pairCount).toBeGreaterThan(2048 * threads);
    return stateHash(world);
  };
  const one = run(1);
  for (const threads of [3, 4]) expect(run(threads)).toBe(one);
}, 60_000);
