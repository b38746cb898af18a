import {
  addBody,
  addShape,
  buildTree,
  createPhysicsWorld,
  disposeWorld,
  enableMutualGravity,
  enableThreads,
  evaluateForces,
  galaxy,
  gravityFieldError,
  MIN_PARALLEL_PER_THREAD,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  setAngularDamping,
  setAttractor,
  setCentralForce,
  setDrag,
  setGravitation,
  stateHash,
  stepMany,
  treeFieldsSorted,
  worldTree,
} from '@bitphysics/physics';
import { afterEach, expect, test } from 'vitest';
import { BARNES_HUT_MIN_PER_THREAD } from '../../packages/physics/src/forces/barnes-hut/tree.js';
import { barnesHutWalk } from '../../packages/physics/src/forces/barnes-hut/walk-kernel.js';
import { Rng } from '../../packages/physics/src/math/rng.js';
import { LoopChooser } from '../../packages/physics/src/threads/adaptive.js';
import { stageNeedsCheck } from '../../packages/physics/src/world/trusted-systems.js';

// Worlds with threads > 1 need the thread pool (step/enable-threads.ts).
enableThreads();

// Force laws on the world's threads: Barnes-Hut's walk (each thread replays the walk for its own
// bodies, in the one-thread order), drag and angular damping (one body's arithmetic a thread). The
// promise is equality to the last bit with the one-thread run (stateHash hashes every bit), so the
// tolerance is zero; each test also checks the physics against something independent.

const worlds: PhysicsWorld[] = [];
afterEach(() => {
  for (const w of worlds.splice(0)) disposeWorld(w);
});

/** A world whose parallel loops always take the threads (not the adaptive choice), so the tests see them. */
function make(options: PhysicsWorldOptions): PhysicsWorld {
  const w = createPhysicsWorld(options);
  if (w.threadPool !== null) w.threadPool.adaptive = false;
  worlds.push(w);
  return w;
}

test('Barnes-Hut evaluated in parts: every field identical to the one-part walk wherever the parts are cut (2D and 3D)', () => {
  for (const dims of [2, 3] as const) {
    const n = 900;
    const t = worldTree(make({ dimensions: dims }));
    const rng = new Rng(11 + dims);
    const x = new Float64Array(n),
      y = new Float64Array(n),
      z = new Float64Array(n),
      m = new Float64Array(n);
    // A third of the bodies in a tight clump: deep cells and straddling pairs at every cut.
    for (let i = 0; i < n; i++) {
      const r = i % 3 === 0 ? 0.05 : 50;
      x[i] = rng.range(-r, r);
      y[i] = rng.range(-r, r);
      z[i] = dims === 3 ? rng.range(-r, r) : 0;
      m[i] = rng.range(0.5, 1.5);
    }
    buildTree(t, n, x, y, z, m);
    treeFieldsSorted(t, 1.3, 0.01, 0.6);
    const ref = [t.ax.slice(0, n), t.ay.slice(0, n), t.az.slice(0, n)];
    const counts = { ...t.stats };
    const leafStarts: number[] = [];
    for (let k = 0; k < t.nodeCount; k++) if (t.skip[k] === k + 1) leafStarts.push(t.start[k]!);
    for (const parts of [2, 3, 7]) {
      // Uneven cuts at leaf starts, the parts run one after the other on this thread.
      t.cut[0] = 0;
      for (let p = 1; p < parts; p++) t.cut[p] = leafStarts[Math.floor((leafStarts.length * p * p) / (parts * parts))]!;
      t.cut[parts] = n;
      const size = t.scratch[0]!.length;
      const arrays = [t.x, t.y, t.z, t.m, t.node, t.start, t.end, t.skip, t.ax, t.ay, t.az, t.cut, t.info];
      for (let p = 0; p < parts; p++) arrays.push(new Float64Array(size).fill(1e300));
      t.ax.fill(NaN);
      t.ay.fill(NaN);
      t.az.fill(NaN);
      barnesHutWalk(arrays, t.walkParams, null, 0, parts);
      for (let i = 0; i < n; i++) {
        if (!Object.is(t.ax[i], ref[0]![i]) || !Object.is(t.ay[i], ref[1]![i]) || !Object.is(t.az[i], ref[2]![i])) {
          throw new Error(`${dims}D, ${parts} parts: slot ${i} differs`);
        }
      }
      // Each interaction is counted by exactly one part: the counts add up to the one-part walk's.
      let cellPairs = 0,
        bodyPairs = 0;
      for (let p = 0; p < parts; p++) {
        cellPairs += t.info[4 * p]!;
        bodyPairs += t.info[4 * p + 1]!;
      }
      expect([cellPairs, bodyPairs]).toEqual([counts.cellPairs, counts.bodyPairs]);
    }
  }
});

test('galaxy on 1 and 2 threads: identical states; the threaded field matches the direct sum', () => {
  const count = 2 * BARNES_HUT_MIN_PER_THREAD + 100;
  const hashes = [1, 2].map((threads) => {
    const options = { count, seed: 5, openingAngle: 1 };
    const world = make({ ...galaxy.worldOptions(options), threads });
    galaxy.build(world, options);
    stepMany(world, 2);
    if (threads > 1) {
      expect(world.threadPool!.runs, `threads ${threads} used its workers`).toBeGreaterThan(0);
      expect(worldTree(world).parts, `threads ${threads}: the walk ran in parts`).toBe(threads);
    }
    // Independent check: the threaded tree field against the direct sum on 100 stars (median
    // relative error; the one-thread tree gives ~0.3% at theta 1, the bound leaves margin).
    if (threads === 2) expect(gravityFieldError(world, 100).median).toBeLessThan(0.01);
    return stateHash(world);
  });
  expect(hashes[1]).toBe(hashes[0]);
}, 60_000);

test('3D mutual gravity by Barnes-Hut on 2 threads: identical state; total momentum kept to rounding', () => {
  const n = 2 * BARNES_HUT_MIN_PER_THREAD + 50;
  const run = (threads: number): [string, PhysicsWorld] => {
    const world = make({ dimensions: 3, capacity: n, gravity: [0, 0, 0], threads });
    setGravitation(world, { constant: 1, softening: 0.1, method: 'barnes-hut', openingAngle: 1 });
    const rng = new Rng(9);
    for (let i = 0; i < n; i++) {
      const e = addBody(world, { position: [rng.range(-20, 20), rng.range(-20, 20), rng.range(-20, 20)], mass: rng.range(0.5, 1.5) });
      enableMutualGravity(world, e);
    }
    stepMany(world, 1);
    return [stateHash(world), world];
  };
  const [one] = run(1);
  const [two, world] = run(2);
  expect(worldTree(world).parts).toBe(2);
  expect(two).toBe(one);
  // The mutual expansions and direct pairs are exactly opposite both ways: from rest, the total
  // momentum stays zero up to rounding (|P| / sum m|v| < 1e-12).
  const c = world.components;
  let px = 0,
    py = 0,
    pz = 0,
    scale = 0;
  for (let e = 1; e <= n; e++) {
    const m = c.Mass.value[e]!;
    px += m * c.Velocity.x[e]!;
    py += m * c.Velocity.y[e]!;
    pz += m * c.Velocity.z[e]!;
    scale += m * Math.hypot(c.Velocity.x[e]!, c.Velocity.y[e]!, c.Velocity.z[e]!);
  }
  expect(Math.hypot(px, py, pz) / scale).toBeLessThan(1e-12);
}, 60_000);

test("drag, angular damping, central forces and an attractor on an adaptive 2-thread pool: the one-thread state and forces; a body's force is the sum of its laws", () => {
  // The adaptive choice runs each loop on the threads at its first three calls and on one thread at
  // the next two (threads/adaptive.ts): five steps take every loop both ways.
  const n = 2 * MIN_PARALLEL_PER_THREAD + 33;
  const run = (threads: number): [string, PhysicsWorld] => {
    const world = createPhysicsWorld({ dimensions: 2, capacity: n, gravity: [0, 0], threads });
    worlds.push(world);
    setGravitation(world, { constant: 1 });
    const rng = new Rng(21);
    for (let i = 0; i < n; i++) {
      const e = addBody(world, {
        position: [rng.range(-50, 50), rng.range(-50, 50)],
        velocity: [rng.range(-9, 9), rng.range(-9, 9)],
        mass: rng.range(0.5, 2),
      });
      // Every 1000th body's drag is stiff (k h / m far above the explicit limit): the exact decay path.
      if (i % 3 === 0) setDrag(world, e, { linear: i % 1000 === 0 ? 1e4 : rng.range(0, 2) });
      else if (i % 3 === 1) setDrag(world, e, { quadratic: i % 1000 === 1 ? 1e4 : rng.range(0, 0.5) });
      else {
        setDrag(world, e, { linear: rng.range(0, 1), quadratic: rng.range(0, 0.2) });
        world.components.AngularVelocity.z[e] = rng.range(-5, 5);
        setAngularDamping(world, e, rng.range(0, 0.3));
      }
      setCentralForce(world, e, { centre: [1, 2], k: -0.3, n: i % 2 === 0 ? 3 : 1 });
      if (i === 7) setAttractor(world, e, { mass: 50, softening: 2 });
    }
    stepMany(world, 5);
    evaluateForces(world);
    return [stateHash(world) + hashForces(world), world];
  };
  const [one] = run(1);
  const [two, world] = run(2);
  expect(world.threadPool!.runs).toBeGreaterThan(0);
  expect(two).toBe(one);
  // Independent check at the final state: body 16 (i = 15: linear drag, central force with n = 1)
  // feels -k v + k_c r^(n-2) (x - c) - G M m (x - x_a) / (|x - x_a|^2 + eps^2)^(3/2), to rounding (1e-12).
  const c = world.components,
    e = 16,
    a = 8;
  const x = c.Position.x[e]!,
    y = c.Position.y[e]!,
    m = c.Mass.value[e]!,
    k = c.LinearDrag.k[e]!;
  const cx = x - 1,
    cy = y - 2,
    r = Math.hypot(cx, cy);
  const ax = x - c.Position.x[a]!,
    ay = y - c.Position.y[a]!,
    d2 = ax * ax + ay * ay + 4;
  const g = (-50 * m) / (d2 * Math.sqrt(d2));
  const fx = -k * c.Velocity.x[e]! - (0.3 * cx) / r + g * ax,
    fy = -k * c.Velocity.y[e]! - (0.3 * cy) / r + g * ay;
  expect(c.Force.x[e]! / fx - 1).toBeCloseTo(0, 12);
  expect(c.Force.y[e]! / fy - 1).toBeCloseTo(0, 12);
}, 60_000);

/** Every bit of the force accumulators, as text (the state hash does not cover forces). */
function hashForces(world: PhysicsWorld): string {
  const f = world.components.Force;
  let h = 0;
  const bits = new Uint32Array(new Float64Array([0]).buffer);
  const one = new Float64Array(bits.buffer);
  for (let e = 0; e < f.x.length; e++) {
    for (const v of [f.x[e]!, f.y[e]!]) {
      one[0] = v;
      h = (Math.imul(h ^ bits[0]!, 0x01000193) ^ bits[1]!) >>> 0;
    }
  }
  return ` forces ${h.toString(16)}`;
}

test('a world with nothing to collide does not check its bodies again after the collide stage', () => {
  for (const dimensions of [2, 3] as const) {
    const world = make({ dimensions });
    addBody(world, { position: dimensions === 2 ? [0, 1] : [0, 1, 0] });
    stepMany(world, 1);
    expect(stageNeedsCheck(world, 'collide', world.stages.collide), `${dimensions}D, no shapes`).toBe(0);
  }
  // A shape makes the 2D shape collision write body state: the stage is checked again.
  const world = make({ dimensions: 2 });
  const e = addBody(world, { position: [0, 1] });
  addShape(world, e, { type: 'circle', radius: 0.5 });
  stepMany(world, 1);
  expect(stageNeedsCheck(world, 'collide', world.stages.collide)).toBe(2);
});

test('the adaptive choice: threads first, then one thread, then the faster by its estimate, probing the other less and less often', () => {
  const c = new LoopChooser();
  const site = 'loop';
  const ran: boolean[] = [];
  // The threads take 2 ms, one thread 1 ms, for 1000 elements.
  for (let i = 0; i < 60; i++) {
    const parallel = c.choose(site);
    ran.push(parallel);
    c.record(site, parallel, parallel ? 2 : 1, 1000);
  }
  expect(ran.slice(0, 5)).toEqual([true, true, true, false, false]);
  expect(c.preference(site)).toBe(false);
  // After the first five calls only the probes take the threads, 4 and 16 calls apart (threads/adaptive.ts).
  expect(ran.map((p, i) => (p && i >= 5 ? i : -1)).filter((i) => i >= 0)).toEqual([8, 24]);
  // When the threads become faster (0.4 ms), the estimate follows and they are preferred.
  for (let i = 0; i < 60; i++) {
    const parallel = c.choose(site);
    c.record(site, parallel, parallel ? 0.4 : 1, 1000);
  }
  expect(c.preference(site)).toBe(true);
});

test('galaxy of 33,000 stars on an adaptive pool: the state of one thread while its loops switch between threads and one thread', () => {
  // The choice runs each loop on the threads at its first three calls and on one thread at the next
  // two (threads/adaptive.ts), so four steps take every Barnes-Hut loop (gather with bounding box,
  // keys, key sort, order, leaf moments, walk, forces) both ways.
  const options = { count: 2 * MIN_PARALLEL_PER_THREAD + 200, seed: 8, openingAngle: 1.5 };
  const run = (threads: number): string => {
    const world = createPhysicsWorld({ ...galaxy.worldOptions(options), threads });
    worlds.push(world);
    galaxy.build(world, options);
    stepMany(world, 4);
    return stateHash(world);
  };
  expect(run(2)).toBe(run(1));
}, 60_000);
