import {
  addBody,
  createPhysicsWorld,
  disposeWorld,
  enableThreads,
  type PhysicsWorld,
  setBoundary,
  stateHash,
  stepMany,
} from '@bitphysics/physics';
import { afterEach, expect, test } from 'vitest';
import { Rng } from '../../packages/physics/src/math/rng.js';
import { lastColorCount } from '../../packages/physics/src/solver/coloring.js';
import { stageThreading } from '../../packages/physics/src/solver/stages-threads.js';
import { BALANCE_MIN_PER_THREAD, RangeBalance } from '../../packages/physics/src/threads/balance.js';

// Worlds with threads > 1 need the thread pool (step/enable-threads.ts).
enableThreads();

// A pool cuts a loop into ranges by shares it learns from when each thread finished (threads/balance.ts).
// Two promises: the shares settle where every thread finishes at once (checked against a model of
// threads of different speeds and a wake-up delay, whose balance is known in closed form), and which
// thread runs which range never changes a result (stateHash, every bit: tolerance zero).

/** Runs one modelled loop of n elements: thread i takes latency[i] + share_i n perElement[i] ms. */
function simulate(b: RangeBalance, kernel: number, n: number, perElement: number[], latency: number[]): number[] {
  const t = perElement.length,
    bounds = new Int32Array(t + 1);
  b.bounds(kernel, n, bounds, 0);
  const times = perElement.map((p, i) => latency[i]! + (bounds[i + 1]! - bounds[i]!) * p);
  const finished = new Float64Array(t);
  for (let i = 1; i < t; i++) finished[i] = 1000 + times[i]!;
  b.record(kernel, n, 1000, 1000 + times[0]!, finished);
  return times;
}

test('shares settle where the threads finish together: 2 and 3 threads of different speeds, with a wake-up delay', () => {
  for (const [perElement, latency] of [
    [
      [1e-4, 1.6e-4],
      [0, 0.2],
    ],
    [
      [1e-4, 1.5e-4, 2e-4],
      [0, 0.1, 0.3],
    ],
  ] as const) {
    const t = perElement.length,
      n = 20_000,
      b = new RangeBalance(t);
    const bounds = new Int32Array(t + 1);
    b.bounds(3, n, bounds, 0);
    // Equal ranges (to the element) before anything is learnt.
    for (let i = 0; i <= t; i++) expect(Math.abs(bounds[i]! - (n * i) / t)).toBeLessThanOrEqual(1);
    let times: number[] = [];
    for (let run = 0; run < 60; run++) times = simulate(b, 3, n, [...perElement], [...latency]);
    // The balance in closed form: every thread ends at T with sum_i (T - latency_i) / perElement_i = n.
    let a = 0,
      c = 0;
    for (let i = 0; i < t; i++) {
      a += 1 / perElement[i]!;
      c += latency[i]! / perElement[i]!;
    }
    const T = (n + c) / a;
    // Within 1 % of T: the ranges are whole elements and the shares move a quarter of the way a run.
    for (const time of times) expect(Math.abs(time - T) / T).toBeLessThan(0.01);
    b.bounds(3, n, bounds, 0);
    expect(bounds[0]).toBe(0);
    expect(bounds[t]).toBe(n);
    for (let i = 0; i < t; i++) expect(bounds[i + 1]!).toBeGreaterThanOrEqual(bounds[i]!);
    // Another kernel, and a loop too short to balance, stay equal.
    b.bounds(4, n, bounds, 0);
    expect(Math.abs(bounds[1]! - n / t)).toBeLessThanOrEqual(1);
    const short = BALANCE_MIN_PER_THREAD * t - 1;
    b.bounds(3, short, bounds, 0);
    expect(bounds[1]).toBe(Math.floor(short / t));
  }
});

test('hold: fixed shares, checked; null learns again from equal shares', () => {
  const b = new RangeBalance(2),
    bounds = new Int32Array(3);
  b.hold([0.9, 0.1]);
  b.bounds(0, 10_000, bounds, 0);
  expect([...bounds]).toEqual([0, 9000, 10_000]);
  simulate(b, 0, 10_000, [1e-4, 1e-3], [0, 0]);
  expect(b.share(0, 0)).toBe(0.9); // held: nothing learnt
  expect(() => b.hold([0.5, 0.6])).toThrow(/RangeBalance.hold: shares must be 2 numbers .* summing to 1, got 2 summing to 1.1/);
  expect(() => b.hold([1])).toThrow(/got 1 summing to 1/);
  expect(() => b.hold([1.5, -0.5])).toThrow(/finite and >= 0, got -0.5 at 1/);
  b.hold(null);
  expect(b.share(0, 0)).toBe(0.5);
  simulate(b, 0, 10_000, [1e-4, 1e-3], [0, 0]);
  expect(b.share(0, 0)).toBeGreaterThan(0.5);
});

const worlds: PhysicsWorld[] = [];
const savedMin = stageThreading.minPerThread;
afterEach(() => {
  for (const w of worlds.splice(0)) disposeWorld(w);
  stageThreading.minPerThread = savedMin;
});

/**
 * 6,000 balls in a box, in rows 0.02 diameters apart with random sideways speeds: contacts from the
 * first step, and every threaded loop of a 2D pile on the threads (the solver stages and the coloured
 * solve from 1,024 rows on, not the default 16,384).
 */
function pile(shares: number[] | null): PhysicsWorld {
  const world = createPhysicsWorld({ dimensions: 2, capacity: 6000, gravity: [0, -10], threads: shares?.length ?? 2 });
  worlds.push(world);
  world.threadPool!.adaptive = false;
  world.collision.settings.coloredSolveMinRows = 1024;
  stageThreading.minPerThread = 1024;
  if (shares !== null) world.threadPool!.balance.hold(shares);
  setBoundary(world, { min: [0, 0], max: [60, 200] });
  const rng = new Rng(5);
  for (let i = 0; i < 6000; i++) {
    addBody(world, {
      position: [0.5 + 1.0001 * (i % 59), 0.5 + 1.02 * Math.floor(i / 59)],
      radius: 0.5,
      velocity: [rng.range(-1, 1), rng.range(-0.2, 0.2)],
    });
  }
  return world;
}

test('the state does not depend on the shares: a pile on 2 threads with learnt, 90/10 and 10/90 ranges, and 3 threads at 20/30/50', () => {
  const hashes = [null, [0.9, 0.1], [0.1, 0.9], [0.2, 0.3, 0.5]].map((shares) => {
    const world = pile(shares);
    stepMany(world, 40);
    // At least six loops a step on the threads (pairs, contacts, preparation, the coloured solve, ...).
    expect(world.threadPool!.runs).toBeGreaterThanOrEqual(6 * 40);
    expect(lastColorCount(world)).toBeGreaterThan(0);
    return stateHash(world);
  });
  expect(hashes[1]).toBe(hashes[0]);
  expect(hashes[2]).toBe(hashes[0]);
  expect(hashes[3]).toBe(hashes[0]);
}, 60_000);
