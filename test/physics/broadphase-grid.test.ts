import { addBody, addSegment, createPhysicsWorld, disposeWorld, type PhysicsWorld, stepMany } from '@bitphysics/physics';
import { afterEach, expect, test } from 'vitest';
import { broadphaseSystem, DENSE_MIN_BODIES, PairKind } from '../../packages/physics/src/collision/broadphase/grid.js';
import { Rng } from '../../packages/physics/src/math/rng.js';

// The broadphase's two grids (collision/broadphase/grid.ts): a dense grid in space order for a large,
// compact world, the spatial hash otherwise. Whichever runs, the pairs must be exactly those a brute-
// force test of every pair of balls finds (within reach: radius + margin each, at the start-of-step
// positions; tolerance zero, the same comparison), each once; oversized balls (found by range
// queries) and segments too.

const worlds: PhysicsWorld[] = [];
afterEach(() => {
  for (const w of worlds.splice(0)) disposeWorld(w);
});

/**
 * 1,200 balls (radius 0.5 m, 0.02 diameters apart, small random velocities, no gravity) in a block of
 * 40 x 30, or in two blocks `apart` metres apart; one ball 20 times larger sits in the first block
 * (oversized: queried by range) and a static segment crosses it.
 */
function blocks(apart: number): PhysicsWorld {
  const world = createPhysicsWorld({ dimensions: 2, capacity: 1300, gravity: [0, 0] });
  worlds.push(world);
  const rng = new Rng(5);
  for (let k = 0; k < 1200; k++) {
    const i = k % 40,
      j = Math.floor(k / 40);
    const shift = apart > 0 && k >= 600 ? apart : 0;
    const y = apart > 0 && k >= 600 ? 1.02 * (j - 15) : 1.02 * j;
    addBody(world, { position: [1.02 * i + shift, y], velocity: [rng.range(-0.1, 0.1), rng.range(-0.1, 0.1)], radius: 0.5 });
  }
  addBody(world, { position: [20, 7], radius: 10 });
  addSegment(world, { a: [-2, 3.3], b: [45, 9.1] });
  return world;
}

/** Runs the broadphase on `world`'s current state and checks its ball pairs against brute force; returns the pair count. */
function checkPairs(world: PhysicsWorld, skip = -1): number {
  broadphaseSystem(world);
  const c = world.components,
    cs = world.collision;
  const n = c.Ball.radius.length - 1;
  const found = new Set<number>();
  let ballPairs = 0;
  for (let i = 0; i < cs.pairCount; i++) {
    if (cs.pairKind[i] !== PairKind.BallBall) continue;
    ballPairs++;
    found.add(cs.pairA[i]! * (n + 1) + cs.pairB[i]!);
  }
  expect(found.size).toBe(ballPairs); // no pair twice
  let brute = 0;
  const ox = c.PreviousPosition.x,
    oy = c.PreviousPosition.y,
    R = c.Ball.radius;
  for (let e = 1; e <= n; e++) {
    if (!(R[e]! > 0) || e === skip) continue;
    for (let f = e + 1; f <= n; f++) {
      if (!(R[f]! > 0) || f === skip) continue;
      const rr = R[e]! + cs.margin[e]! + R[f]! + cs.margin[f]!;
      const dx = ox[f]! - ox[e]!,
        dy = oy[f]! - oy[e]!;
      if (dx * dx + dy * dy < rr * rr) {
        brute++;
        if (!found.has(e * (n + 1) + f)) throw new Error(`pair ${e} ${f} missed`);
      }
    }
  }
  expect(ballPairs).toBe(brute);
  return brute;
}

test('dense grid (a compact world of 1,200 balls): the brute-force pairs, with an oversized ball and a segment', () => {
  expect(1200).toBeGreaterThanOrEqual(DENSE_MIN_BODIES);
  const world = blocks(0);
  stepMany(world, 2);
  const pairs = checkPairs(world);
  const g = world.collision.grid;
  expect(g.spanX).toBeGreaterThan(0);
  // The lattice's neighbours and the big ball's: far more pairs than balls.
  expect(pairs).toBeGreaterThan(2000);
  // The segment is paired with every ball that touches its line between the end points (and no ball twice).
  const cs = world.collision,
    c = world.components;
  const withSegment = new Set<number>();
  for (let i = 0; i < cs.pairCount; i++) if (cs.pairKind[i] === PairKind.SegmentBall) withSegment.add(cs.pairB[i]!);
  let touching = 0;
  for (let e = 1; e <= 1200; e++) {
    const px = c.PreviousPosition.x[e]! + 2,
      py = c.PreviousPosition.y[e]! - 3.3;
    const ex = 47,
      ey = 5.8;
    const u = Math.min(1, Math.max(0, (px * ex + py * ey) / (ex * ex + ey * ey)));
    if (Math.hypot(px - u * ex, py - u * ey) < 0.5) {
      touching++;
      expect(withSegment.has(e)).toBe(true);
    }
  }
  expect(touching).toBeGreaterThan(20);
});

test('the hash (two blocks 100 km apart: too many cells for a dense grid) finds the same brute-force pairs', () => {
  const world = blocks(1e5);
  stepMany(world, 2);
  checkPairs(world);
  expect(world.collision.grid.spanX).toBe(0);
});

test('a ball at a NaN position leaves the dense grid usable: every other pair is found', () => {
  const world = blocks(0);
  stepMany(world, 1);
  world.components.PreviousPosition.x[600] = NaN;
  world.components.PreviousPosition.y[600] = NaN;
  world.components.Position.x[600] = NaN;
  world.components.Position.y[600] = NaN;
  checkPairs(world, 600);
  expect(world.collision.grid.spanX).toBeGreaterThan(0);
});
