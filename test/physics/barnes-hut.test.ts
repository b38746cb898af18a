import {
  addBody,
  buildTree,
  createPhysicsWorld,
  directField,
  enableMutualGravity,
  fieldErrorStats,
  forceErrorMedian,
  type GravityTree,
  galaxy,
  gravityFieldError,
  gravityMomentumRate,
  linearMomentum,
  mutualGravitySystem,
  type PhysicsWorld,
  Rng,
  sampleIndices,
  setGravitation,
  step,
  treeField,
  treeFields,
  worldTree,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/**
 * Barnes-Hut mutual gravity (packages/physics/src/forces/barnes-hut/tree.ts) against the direct sum.
 * Errors are relative field errors |a_tree - a_direct| / |a_direct| per body, summarised over an
 * evenly spaced sample of bodies (fractions: 0.01 = 1%).
 */

interface Bodies {
  n: number;
  x: Float64Array;
  y: Float64Array;
  z: Float64Array;
  m: Float64Array;
}

function bodies(n: number): Bodies {
  return { n, x: new Float64Array(n), y: new Float64Array(n), z: new Float64Array(n), m: new Float64Array(n) };
}

/** Uniform in the square [-50, 50]^2 (3D: the cube), masses uniform in [0.5, 1.5] kg. */
function uniform(n: number, dims: 2 | 3, seed: number): Bodies {
  const rng = new Rng(seed),
    b = bodies(n);
  for (let i = 0; i < n; i++) {
    b.x[i] = rng.range(-50, 50);
    b.y[i] = rng.range(-50, 50);
    b.z[i] = dims === 3 ? rng.range(-50, 50) : 0;
    b.m[i] = rng.range(0.5, 1.5);
  }
  return b;
}

/**
 * Galaxy-like 2D: 70% of the bodies in an exponential disc (scale 5 m, cut at 40 m), 30% in 8 tight
 * Gaussian clumps (sigma 0.5 m) scattered over the disc, and a nucleus of 5% of the mass at the centre.
 */
function clustered2D(n: number, seed: number): Bodies {
  const rng = new Rng(seed),
    b = bodies(n);
  const cx: number[] = [],
    cy: number[] = [];
  for (let k = 0; k < 8; k++) {
    const r = rng.range(3, 25),
      a = rng.range(0, 2 * Math.PI);
    cx.push(r * Math.cos(a));
    cy.push(r * Math.sin(a));
  }
  for (let i = 1; i < n; i++) {
    if (rng.next() < 0.7) {
      let r: number;
      do {
        r = -5 * Math.log(rng.next() * rng.next() + 1e-300);
      } while (r > 40);
      const a = rng.range(0, 2 * Math.PI);
      b.x[i] = r * Math.cos(a);
      b.y[i] = r * Math.sin(a);
    } else {
      const k = Math.floor(rng.next() * 8);
      b.x[i] = cx[k]! + 0.5 * rng.normal();
      b.y[i] = cy[k]! + 0.5 * rng.normal();
    }
    b.m[i] = rng.range(0.5, 1.5);
  }
  b.m[0] = 0.05 * n;
  return b;
}

/** Plummer sphere of scale 1 m (3D, clustered: half the mass within 1.3 m), cut at 30 m; equal masses. */
function plummer3D(n: number, seed: number): Bodies {
  const rng = new Rng(seed),
    b = bodies(n);
  for (let i = 0; i < n; i++) {
    let r: number;
    do {
      r = 1 / Math.sqrt(rng.range(1e-6, 1) ** (-2 / 3) - 1);
    } while (r > 30);
    const zc = rng.range(-1, 1),
      a = rng.range(0, 2 * Math.PI),
      s = Math.sqrt(1 - zc * zc);
    b.x[i] = r * s * Math.cos(a);
    b.y[i] = r * s * Math.sin(a);
    b.z[i] = r * zc;
    b.m[i] = 1;
  }
  return b;
}

function newTree(dims: 2 | 3): GravityTree {
  return worldTree(createPhysicsWorld({ dimensions: dims }));
}

/** Tree field at every body (input order). */
function treeFieldOf(b: Bodies, dims: 2 | 3, eps: number, theta: number, t = newTree(dims)) {
  buildTree(t, b.n, b.x, b.y, b.z, b.m);
  const ax = new Float64Array(b.n),
    ay = new Float64Array(b.n),
    az = new Float64Array(b.n);
  treeFields(t, 1, eps * eps, theta, ax, ay, az);
  return { t, ax, ay, az };
}

/** Error summary of the tree field against the direct sum over `sample` bodies. */
function treeError(b: Bodies, dims: 2 | 3, eps: number, theta: number, sample = 400) {
  const { ax, ay, az } = treeFieldOf(b, dims, eps, theta);
  const targets = sampleIndices(b.n, sample);
  const exact = directField(b.n, b.x, b.y, b.z, b.m, 1, eps * eps, targets);
  const approx = new Float64Array(exact.length);
  targets.forEach((i, k) => {
    approx[3 * k] = ax[i]!;
    approx[3 * k + 1] = ay[i]!;
    approx[3 * k + 2] = az[i]!;
  });
  return fieldErrorStats(approx, exact);
}

const cases: [string, 2 | 3, () => Bodies, number][] = [
  ['2D uniform square, N = 10,000', 2, () => uniform(10_000, 2, 1), 0.1],
  ['2D clustered (disc + clumps + nucleus), N = 10,000', 2, () => clustered2D(10_000, 2), 0.05],
  ['3D uniform cube, N = 5,000', 3, () => uniform(5_000, 3, 3), 0.1],
  ['3D Plummer sphere, N = 5,000', 3, () => plummer3D(5_000, 4), 0.01],
];

describe('accuracy against the direct sum', () => {
  // The target: median relative error below 1% at theta = 0.5 on random and clustered
  // distributions. Measured: 0.07% for each of the four (2D: fourth-order expansions, 3D: third
  // order). The second bound, 0.3%, is a regression guard: 4x above those, and below what a lost
  // expansion term gives (the third-order 2D expansion measured 0.5% on this uniform square).
  test.each(cases)('%s: median < 1% at theta = 0.5', (_name, dims, make, eps) => {
    const s = treeError(make(), dims, eps, 0.5);
    expect(s.median).toBeLessThan(0.01);
    expect(s.median).toBeLessThan(0.003);
    expect(Number.isFinite(s.max)).toBe(true);
  });

  // Convergence: the expansion error falls as a power of theta (theta^4 in 2D, theta^3 in 3D, for
  // pairs at the opening limit), so each smaller theta must be more accurate, and halving theta from
  // 0.5 to 0.25 must cut the median error at least 4-fold (2^2, half the weakest predicted order,
  // leaving room for sampling noise; measured 19-23-fold).
  test.each([cases[0]!, cases[1]!, cases[2]!])('%s: error decreases with theta', (_name, dims, make, eps) => {
    const b = make();
    const thetas = [0.9, 0.7, 0.5, 0.35, 0.25];
    const medians = thetas.map((theta) => treeError(b, dims, eps, theta, 200).median);
    for (let i = 1; i < medians.length; i++) expect(medians[i]!).toBeLessThan(medians[i - 1]!);
    expect(medians[4]!).toBeLessThan(medians[2]! / 4);
  });

  // With theta tiny no two cells are far enough apart, so every pair is summed directly (or by an
  // expansion of point-like cells, which is exact): the tree reproduces the direct sum to rounding.
  // 1e-9 relative leaves room for the different summation order (measured worst 6e-14).
  test.each([
    [2, 3000],
    [3, 2000],
  ] as const)('%iD, N = %i: theta = 1e-3 reproduces the direct sum to 1e-9', (dims, n) => {
    const b = dims === 2 ? clustered2D(n, 5) : plummer3D(n, 6);
    const eps = 0.02;
    const { ax, ay, az } = treeFieldOf(b, dims, eps, 1e-3);
    const all = sampleIndices(n, n);
    const exact = directField(n, b.x, b.y, b.z, b.m, 1, eps * eps, all);
    let worst = 0;
    for (let i = 0; i < n; i++) {
      const e = Math.hypot(exact[3 * i]!, exact[3 * i + 1]!, exact[3 * i + 2]!);
      worst = Math.max(worst, Math.hypot(ax[i]! - exact[3 * i]!, ay[i]! - exact[3 * i + 1]!, az[i]! - exact[3 * i + 2]!) / e);
    }
    expect(worst).toBeLessThan(1e-9);
  });

  // The single-body walk (treeField, a classic quadrupole Barnes-Hut walk) has the same accuracy
  // target, 1% median at theta = 0.5 (measured 0.4%).
  test('treeField for single bodies agrees with the direct sum', () => {
    const b = clustered2D(5000, 7),
      eps = 0.05;
    const t = newTree(2);
    buildTree(t, b.n, b.x, b.y, b.z, b.m);
    const targets = sampleIndices(b.n, 200);
    const exact = directField(b.n, b.x, b.y, b.z, b.m, 1, eps * eps, targets);
    const approx = new Float64Array(exact.length),
      out = new Float64Array(3);
    targets.forEach((i, k) => {
      treeField(t, i, 1, eps * eps, 0.5, out);
      approx.set(out, 3 * k);
    });
    expect(fieldErrorStats(approx, exact).median).toBeLessThan(0.01);
  });
});

describe('degenerate inputs', () => {
  const finite = (a: Float64Array) => a.every((v) => Number.isFinite(v));

  test('no bodies, one body, two bodies', () => {
    for (const dims of [2, 3] as const) {
      const t = newTree(dims);
      const out = new Float64Array(3);
      buildTree(t, 0, [], [], [], []);
      treeFields(t, 1, 0, 0.5, out, out, out);
      buildTree(t, 1, [3], [4], [5], [2]);
      treeFields(t, 1, 0, 0.5, out.subarray(0, 1), out.subarray(1, 2), out.subarray(2, 3));
      expect(Array.from(out)).toEqual([0, 0, 0]); // nothing else pulls it
      // Two bodies 3-4-5 apart (5 m), masses 2 and 3 kg, G = 1, no softening: |a_0| = 3 / 25.
      const b = { n: 2, x: new Float64Array([0, 3]), y: new Float64Array([0, 4]), z: new Float64Array(2), m: new Float64Array([2, 3]) };
      const f = treeFieldOf(b, dims, 0, 0.5);
      expect(f.ax[0]).toBeCloseTo((3 / 25) * 0.6, 14);
      expect(f.ay[0]).toBeCloseTo((3 / 25) * 0.8, 14);
      expect(f.ax[1]).toBeCloseTo((-2 / 25) * 0.6, 14);
    }
  });

  // Coincident bodies cannot be separated by splitting; the cell-size floor (1e-9 of the root) makes
  // them one leaf. Softened, a coincident pair pulls with zero force (d = 0); unsoftened, the pair is
  // skipped as in the direct sum. Either way: finite, and equal to the direct sum.
  test.each([
    [2, 0.05],
    [2, 0],
    [3, 0.05],
    [3, 0],
  ] as const)('%iD, eps = %f: coincident bodies', (dims, eps) => {
    const n = 400;
    const b = uniform(n, dims, 8);
    for (let i = 0; i < 200; i++) {
      b.x[i] = 1.5;
      b.y[i] = -2.5;
      b.z[i] = dims === 3 ? 0.5 : 0;
    }
    for (let i = 200; i < 230; i++) {
      b.x[i] = 1.5 + 1e-13 * i;
      b.y[i] = -2.5;
      b.z[i] = 0;
    } // closer than the cell floor
    for (const theta of [1e-3, 0.5]) {
      const { ax, ay, az } = treeFieldOf(b, dims, eps, theta);
      expect(finite(ax) && finite(ay) && finite(az)).toBe(true);
      const all = sampleIndices(n, n);
      const exact = directField(n, b.x, b.y, b.z, b.m, 1, eps * eps, all);
      const approx = new Float64Array(3 * n);
      for (let i = 0; i < n; i++) {
        approx[3 * i] = ax[i]!;
        approx[3 * i + 1] = ay[i]!;
        approx[3 * i + 2] = az[i]!;
      }
      // Tiny theta: the direct sum to rounding, as above (measured <= 1e-15 median). Theta 0.5: the
      // accuracy target (measured <= 0.5%).
      expect(fieldErrorStats(approx, exact).median).toBeLessThan(theta < 0.01 ? 1e-9 : 0.01);
    }
  });

  // A NaN or infinite position would put every body in one leaf (an O(N^2) sum); instead the build
  // stops and every field is NaN, which the integrator then reports as NonFiniteStateError.
  test('a non-finite position gives NaN fields without building a tree', () => {
    for (const bad of [NaN, Infinity]) {
      const b = uniform(20_000, 2, 10);
      b.x[123] = bad;
      const { t, ax } = treeFieldOf(b, 2, 0.1, 0.5);
      expect(t.nodeCount).toBe(0);
      expect(ax.every((v) => Number.isNaN(v))).toBe(true);
    }
    const world = discWorld(100, 'barnes-hut');
    world.components.Position.x[5] = NaN;
    expect(() => step(world)).toThrow(RangeError);
  });

  test('all bodies at one point: zero field, no NaN', () => {
    const n = 1000;
    const b = bodies(n);
    b.x.fill(7);
    b.y.fill(7);
    b.m.fill(1);
    const { ax, ay } = treeFieldOf(b, 2, 0.1, 0.5);
    expect(ax.every((v) => v === 0) && ay.every((v) => v === 0)).toBe(true);
  });
});

/** A 2D world of n bodies in a rotating uniform disc of radius 20 m, G = 1, mutual gravity. */
function discWorld(n: number, method: 'direct' | 'barnes-hut', seed = 9): PhysicsWorld {
  const world = createPhysicsWorld({ dimensions: 2, gravity: [0, 0], dt: 1e-3, capacity: n + 8 });
  setGravitation(world, { constant: 1, softening: 0.2, method, openingAngle: 0.6 });
  const rng = new Rng(seed);
  for (let i = 0; i < n; i++) {
    const r = 20 * Math.sqrt(rng.next()),
      a = rng.range(0, 2 * Math.PI);
    const e = addBody(world, {
      position: [r * Math.cos(a), r * Math.sin(a)],
      velocity: [-0.3 * r * Math.sin(a) + rng.normal(), 0.3 * r * Math.cos(a) + rng.normal()],
      mass: rng.range(0.5, 1.5),
    });
    enableMutualGravity(world, e);
  }
  return world;
}

describe('in a world', () => {
  // The forces each body gets from the Barnes-Hut path (gather, tree, scatter back to the entity)
  // against the direct path: the same accuracy target per entity, so a body mixed up with another
  // would show errors of order 100%. Measured median 0.1%.
  test('mutualGravitySystem: barnes-hut forces match direct forces per entity', () => {
    const n = 3000;
    const world = discWorld(n, 'direct');
    const F = world.components.Force;
    const force = () => {
      F.x.fill(0);
      F.y.fill(0);
      F.z.fill(0);
      mutualGravitySystem(world);
      return [F.x.slice(), F.y.slice()];
    };
    const [dx, dy] = force();
    setGravitation(world, { method: 'barnes-hut', openingAngle: 0.5 });
    const [bx, by] = force();
    const errs: number[] = [];
    for (let e = 0; e < dx!.length; e++) {
      const d = Math.hypot(dx![e]!, dy![e]!);
      if (d > 0) errs.push(Math.hypot(bx![e]! - dx![e]!, by![e]! - dy![e]!) / d);
    }
    errs.sort((a, b) => a - b);
    expect(errs.length).toBe(n);
    expect(errs[errs.length >> 1]!).toBeLessThan(0.01);
  });

  // Momentum. Every direct pair adds equal and opposite forces, and every cell-cell expansion adds
  // field polynomials whose total forces on the two cells are equal and opposite (they are expanded
  // about the centres of mass with the same kernel tensors), so sum_i F_i = 0 up to rounding. The
  // bound: per step the net force is at most 1e-12 of sum |F_i| (the rounding of the ~1e5 terms
  // summed into the forces; measured 3e-17), and the momentum update itself rounds by ~1e-16 of
  // sum m |v| per step (1e-15 allowed); so over N steps of h,
  //   |P(T) - P(0)| <= sum over steps of (h 1e-12 sum |F_i| + 1e-15 sum m |v|)
  // (here 2e-9 kg m/s; measured drift 3e-13, against a total |P| of 46 kg m/s).
  test('barnes-hut keeps total momentum to rounding over 200 steps', () => {
    const world = discWorld(1000, 'barnes-hut');
    const steps = 200,
      h = world.h;
    const p0 = Float64Array.from(linearMomentum(world));
    const rate0 = gravityMomentumRate(world);
    expect(rate0.relative).toBeLessThan(1e-12);
    let bound = 0;
    const c = world.components;
    for (let s = 0; s < steps; s++) {
      const r = gravityMomentumRate(world);
      let mv = 0;
      for (let e = 0; e < c.Mass.value.length; e++) mv += c.Mass.value[e]! * Math.hypot(c.Velocity.x[e]!, c.Velocity.y[e]!);
      bound += h * 1e-12 * r.total + 1e-15 * mv;
      step(world);
    }
    const p1 = linearMomentum(world);
    const drift = Math.hypot(p1[0]! - p0[0]!, p1[1]! - p0[1]!);
    expect(drift).toBeLessThan(bound);
    expect(gravityMomentumRate(world).relative).toBeLessThan(1e-12);
  });

  // The scene the bench runs, scaled down: the world-level error diagnostic against the direct sum.
  // Measured median: 0.02% (theta 0.5), 0.07% (theta 0.7).
  test('galaxy scene: forceErrorMedian below 1% at theta = 0.5 and 0.7', () => {
    for (const openingAngle of [0.5, 0.7]) {
      const world = createPhysicsWorld(galaxy.worldOptions({ count: 5000 }));
      galaxy.build(world, { count: 5000, openingAngle });
      expect(forceErrorMedian(world, 300)).toBeLessThan(0.01);
      const s = gravityFieldError(world, 300);
      expect(s.sample).toBe(300);
      // Tail sanity: measured p99 0.9% (theta 0.5) and 3% (0.7); a broken expansion gives ~100%.
      expect(s.p99).toBeLessThan(0.1);
    }
  });
});

describe('setGravitation bad input', () => {
  const world = createPhysicsWorld();
  test.each([
    ['negative constant', { constant: -1 }, RangeError, /constant must be >= 0, got -1/],
    ['NaN constant', { constant: NaN }, RangeError, /constant must be finite/],
    ['negative softening', { softening: -0.1 }, RangeError, /softening must be >= 0, got -0.1/],
    ['zero opening angle', { openingAngle: 0 }, RangeError, /openingAngle must be > 0, got 0/],
    ['negative opening angle', { openingAngle: -0.5 }, RangeError, /openingAngle must be > 0/],
    ['infinite opening angle', { openingAngle: Infinity }, RangeError, /openingAngle must be finite/],
    ['string opening angle', { openingAngle: '0.5' }, TypeError, /openingAngle must be a number/],
    ['unknown method', { method: 'fmm' }, RangeError, /method must be one of 'direct', 'barnes-hut', got "fmm"/],
    ['unknown option', { theta: 0.5 }, TypeError, /unknown option "theta"/],
  ])('%s', (_name, options, type, message) => {
    const run = () => setGravitation(world, options as never);
    expect(run).toThrow(type);
    expect(run).toThrow(message);
  });

  test('a rejected call leaves the settings as they were', () => {
    setGravitation(world, { method: 'barnes-hut', openingAngle: 0.7 });
    expect(() => setGravitation(world, { openingAngle: -1 })).toThrow(RangeError);
    expect(world.laws.openingAngle).toBe(0.7);
    expect(world.laws.gravityMethod).toBe('barnes-hut');
  });
});
