import {
  addBody,
  addParticle,
  addSegment,
  addSystem,
  applyImpulse,
  ballsInBox,
  createEntity,
  createFixedStepLoop,
  createPhysicsWorld,
  NonFiniteStateError,
  Rng,
  removeBody,
  setAngularVelocity,
  setBoundary,
  setMass,
  setMaterial,
  setOrientation,
  setRadius,
  setTimeStep,
  slotOf,
  step,
  stepMany,
} from '@bitphysics/physics';
import { addEntity } from 'bitecs';
import fc from 'fast-check';
import { describe, expect, test } from 'vitest';

describe('bad input is refused at the boundary, naming the parameter and the value', () => {
  const world = createPhysicsWorld({ capacity: 10 });
  const cases: Array<[string, () => unknown, ErrorConstructor, RegExp]> = [
    ['negative mass', () => addBody(world, { mass: -1 }), RangeError, /mass must be > 0, got -1/],
    ['NaN mass', () => addBody(world, { mass: NaN }), RangeError, /mass must be finite, got NaN/],
    ['zero mass', () => addBody(world, { mass: 0 }), RangeError, /mass must be > 0, got 0/],
    ['radius 0', () => addBody(world, { radius: 0 }), RangeError, /radius must be > 0, got 0/],
    ['negative radius', () => addBody(world, { radius: -0.5 }), RangeError, /radius must be > 0, got -0.5/],
    ['restitution above 1', () => addBody(world, { radius: 1, restitution: 1.5 }), RangeError, /restitution must be in \[0, 1\], got 1.5/],
    [
      'restitution below 0',
      () => addBody(world, { radius: 1, restitution: -0.1 }),
      RangeError,
      /restitution must be in \[0, 1\], got -0.1/,
    ],
    ['negative friction', () => addBody(world, { radius: 1, friction: -1 }), RangeError, /friction must be >= 0, got -1/],
    ['unknown body option', () => addBody(world, { restituion: 0.5 } as never), TypeError, /unknown option "restituion"/],
    ['position of the wrong length', () => addBody(world, { position: [1, 2, 3] }), TypeError, /position must be an array of 2 numbers/],
    ['NaN in a position', () => addBody(world, { position: [0, NaN] }), RangeError, /position\[1\] must be finite, got NaN/],
    ['dt = 0', () => createPhysicsWorld({ dt: 0 }), RangeError, /dt must be > 0, got 0/],
    ['dt < 0', () => createPhysicsWorld({ dt: -0.01 }), RangeError, /dt must be > 0, got -0.01/],
    ['dt infinite', () => createPhysicsWorld({ dt: Infinity }), RangeError, /dt must be finite, got Infinity/],
    ['dt NaN', () => createPhysicsWorld({ dt: NaN }), RangeError, /dt must be finite, got NaN/],
    ['unknown world option', () => createPhysicsWorld({ gravty: [0, -9.81] } as never), TypeError, /unknown option "gravty"/],
    [
      'unknown integrator',
      () => createPhysicsWorld({ integrator: 'verlet' as never }),
      RangeError,
      /integrator must be one of .*got "verlet"/,
    ],
    ['dimensions 4', () => createPhysicsWorld({ dimensions: 4 as never }), RangeError, /dimensions must be 2 or 3, got 4/],
    ['capacity 0', () => createPhysicsWorld({ capacity: 0 }), RangeError, /capacity must be an integer in \[1, 16777216\], got 0/],
    ['fractional substeps', () => createPhysicsWorld({ substeps: 1.5 }), RangeError, /substeps must be an integer, got 1.5/],
    [
      'gravity of the wrong dimension',
      () => createPhysicsWorld({ dimensions: 3, gravity: [0, -9.81] }),
      TypeError,
      /gravity must be an array of 3 numbers/,
    ],
    ['setMass negative', () => setMass(world, addParticle(world), -2), RangeError, /mass must be > 0, got -2/],
    ['setRadius zero', () => setRadius(world, addParticle(world), 0), RangeError, /radius must be > 0, got 0/],
    [
      'setMaterial restitution 2',
      () => setMaterial(world, addParticle(world), { restitution: 2 }),
      RangeError,
      /restitution must be in \[0, 1\], got 2/,
    ],
    ['boundary with max below min', () => setBoundary(world, { min: [0, 0], max: [-1, 5] }), RangeError, /max\[0\] must be > min\[0\]/],
    ['segment with a NaN end', () => addSegment(world, { a: [0, 0], b: [NaN, 1] }), RangeError, /b\[0\] must be finite, got NaN/],
    ['removing a missing entity', () => removeBody(world, 999), RangeError, /removeBody: entity must be an entity of this world .*got 999/],
    [
      'impulse on a missing entity',
      () => applyImpulse(world, 998, [1, 0]),
      RangeError,
      /applyImpulse: entity must be an entity of this world .*got 998/,
    ],
    ['loop with dt 0', () => createFixedStepLoop({ dt: 0, step: () => {} }), RangeError, /dt must be > 0, got 0/],
  ];
  for (const [name, run, type, message] of cases) {
    test(name, () => {
      expect(run).toThrow(type);
      expect(run).toThrow(message);
    });
  }

  test('adding past capacity throws a RangeError that says so, and nothing is lost', () => {
    const small = createPhysicsWorld({ capacity: 3 });
    for (let i = 0; i < 3; i++) addBody(small, { position: [i, 0] });
    expect(() => addBody(small, { position: [9, 9] })).toThrow(RangeError);
    expect(() => addBody(small, { position: [9, 9] })).toThrow(/full \(capacity 3 entities\)/);
    expect(() => createEntity(small)).toThrow(/capacity 3/);
    // The three bodies are intact and the world still steps.
    step(small);
    expect(small.components.Position.x[3]).toBe(2);
  });

  test("entities made with bitecs' own addEntity past capacity are caught before their data is lost", () => {
    const small = createPhysicsWorld({ capacity: 2 });
    addEntity(small);
    addEntity(small);
    addEntity(small);
    expect(() => step(small)).toThrow(/entity id 3 exceeds the world's capacity 2/);
  });
});

describe('a NaN never spreads silently', () => {
  test('a NaN written into a velocity stops the step, naming the entity and field, before it reaches other bodies', () => {
    const world = createPhysicsWorld({ capacity: 100 });
    setBoundary(world, { min: [0, 0], max: [10, 10] });
    const ids = [1, 2, 3].map((i) => addBody(world, { position: [i * 1.01 + 2, 1], radius: 0.5 }));
    stepMany(world, 10);
    world.components.Velocity.y[ids[1]!] = NaN;
    let error: unknown;
    try {
      step(world);
    } catch (e) {
      error = e;
    }
    expect(error).toBeInstanceOf(NonFiniteStateError);
    expect(error).toBeInstanceOf(RangeError);
    expect((error as NonFiniteStateError).entity).toBe(ids[1]);
    expect((error as NonFiniteStateError).field).toBe('Velocity.y');
    expect(String((error as Error).message)).toMatch(/entity \d+ has a non-finite Velocity.y \(NaN\) after stage 'integrate'/);
    // The neighbours it touches are untouched by the NaN.
    for (const id of [ids[0]!, ids[2]!]) {
      expect(Number.isFinite(world.components.Position.y[id]!)).toBe(true);
      expect(Number.isFinite(world.components.Velocity.y[id]!)).toBe(true);
    }
  });

  test('a force law that returns NaN is caught at the same step', () => {
    const world = createPhysicsWorld();
    const body = addBody(world, { position: [0, 1] });
    addSystem(world, 'forces', (w) => {
      w.components.Force.x[body] = 0 / 0;
    });
    expect(() => step(world)).toThrow(NonFiniteStateError);
  });
});

describe('entities', () => {
  test('a recycled id starts from rest: nothing carries over from the removed body', () => {
    const world = createPhysicsWorld({ capacity: 4 });
    const a = addBody(world, { position: [0, 5], velocity: [3, 4], radius: 0.5, angularVelocity: 2 });
    stepMany(world, 5);
    removeBody(world, a);
    const b = addBody(world, { position: [1, 1] });
    // Same slot (bitecs recycles at once), new handle (the slot's second life).
    expect(slotOf(b)).toBe(slotOf(a));
    expect(b).not.toBe(a);
    const s = slotOf(b),
      c = world.components;
    expect([c.Velocity.x[s], c.Velocity.y[s], c.AngularVelocity.z[s], c.Force.x[s], c.Force.y[s]]).toEqual([0, 0, 0, 0, 0]);
    expect(c.PreviousPosition.x[s]).toBe(1);
  });

  test('the same seed and inputs give bit-identical results (determinism)', () => {
    const run = () => {
      const world = createPhysicsWorld(ballsInBox.worldOptions({ count: 300 }));
      const { balls } = ballsInBox.build(world, { count: 300, seed: 42 });
      stepMany(world, 200);
      const P = world.components.Position;
      let hash = 0;
      for (const e of balls) hash = ((Math.imul(hash, 31) + P.x[e]! * 1e9) | 0) ^ ((P.y[e]! * 1e9) | 0);
      return hash;
    };
    expect(run()).toBe(run());
  });
});

describe('previous position', () => {
  test('after a step with substeps, PreviousPosition is where bodies were when the step began (renderers interpolate from it)', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], substeps: 4 });
    const b = addBody(world, { position: [0, 0], velocity: [1, 0] });
    step(world);
    expect(world.components.PreviousPosition.x[b]).toBe(0);
    expect(world.components.Position.x[b]).toBeCloseTo(1 / 60, 12);
    step(world);
    expect(world.components.PreviousPosition.x[b]).toBeCloseTo(1 / 60, 12);
  });
});

describe('fixed-step loop', () => {
  test('runs whole steps, keeps the remainder as alpha, clamps the backlog', () => {
    let steps = 0;
    const loop = createFixedStepLoop({
      dt: 0.01,
      step: () => {
        steps++;
      },
      maxFrameTime: 0.1,
      maxStepsPerFrame: 5,
    });
    let r = loop.advance(0.035);
    expect(r.steps).toBe(3);
    expect(r.alpha).toBeCloseTo(0.5, 9);
    r = loop.advance(0.005);
    expect(r.steps).toBe(1);
    expect(r.alpha).toBeCloseTo(0, 9);
    // A 2 s hitch: clamped to 0.1 s, and at most 5 steps run; the rest is dropped, not queued.
    r = loop.advance(2);
    expect(r.steps).toBe(5);
    expect(r.dropped).toBeGreaterThan(1.9);
    expect(loop.accumulator).toBeLessThan(0.01);
    expect(steps).toBe(9);
    expect(() => loop.advance(-1)).toThrow(RangeError);
  });
});

describe('broadphase', () => {
  /**
   * Completeness against brute force: every pair of balls that overlaps (or is about to, within the
   * speculative margin) must become a contact. Random sizes (0.05 to 2 m, so some bodies take the
   * oversized path) and positions.
   */
  test('finds every touching pair that all-pairs testing finds', () => {
    fc.assert(
      fc.property(fc.integer({ min: 1, max: 1_000_000 }), fc.constantFrom(2, 3), (seed, dims) => {
        const world = createPhysicsWorld({ dimensions: dims as 2 | 3, gravity: dims === 2 ? [0, 0] : [0, 0, 0], capacity: 400 });
        const rng = new Rng(seed);
        const ids: number[] = [];
        for (let i = 0; i < 300; i++) {
          const r = i % 17 === 0 ? rng.range(1, 2) : rng.range(0.05, 0.4);
          const p = dims === 2 ? [rng.range(0, 12), rng.range(0, 12)] : [rng.range(0, 6), rng.range(0, 6), rng.range(0, 6)];
          ids.push(addBody(world, { position: p, radius: r }));
        }
        step(world);
        const rows = world.collision.cache.rows;
        const found = new Set<string>();
        for (let i = 0; i < rows.count; i++) found.add(`${Math.min(rows.a[i]!, rows.b[i]!)}-${Math.max(rows.a[i]!, rows.b[i]!)}`);
        const O = world.components.PreviousPosition,
          R = world.components.Ball.radius;
        for (let i = 0; i < ids.length; i++)
          for (let j = i + 1; j < ids.length; j++) {
            const a = ids[i]!,
              b = ids[j]!;
            const d = Math.hypot(O.x[b]! - O.x[a]!, O.y[b]! - O.y[a]!, O.z[b]! - O.z[a]!);
            if (d < R[a]! + R[b]!) expect(found.has(`${a}-${b}`)).toBe(true);
          }
      }),
      { numRuns: 12, seed: 1 },
    );
  });
});

describe('tunnelling', () => {
  test('a ball at 200 m/s does not pass through a thin segment or out of the boundary', () => {
    const world = createPhysicsWorld({ gravity: [0, 0] });
    setBoundary(world, { min: [-50, -50], max: [50, 50], restitution: 1, friction: 0 });
    addSegment(world, { a: [10, -50], b: [10, 50], restitution: 1, friction: 0 });
    const ball = addBody(world, { position: [0, 0], velocity: [200, 37], radius: 0.1, restitution: 1, friction: 0 });
    const P = world.components.Position;
    for (let i = 0; i < 600; i++) {
      step(world);
      // Left of the wall at x = 10 (within its radius), inside the box.
      expect(P.x[ball]!).toBeLessThan(10 - 0.1 + 1e-6);
      expect(Math.abs(P.y[ball]!)).toBeLessThan(50 - 0.1 + 1e-6);
      expect(P.x[ball]!).toBeGreaterThan(-50 + 0.1 - 1e-6);
    }
  });
});

describe('setters', () => {
  test('setTimeStep changes dt and substeps; bad values are refused', () => {
    const world = createPhysicsWorld();
    setTimeStep(world, 0.01, 2);
    expect([world.dt, world.substeps, world.h]).toEqual([0.01, 2, 0.005]);
    expect(() => setTimeStep(world, 0)).toThrow(/dt must be > 0, got 0/);
    expect(() => setTimeStep(world, 0.01, 0)).toThrow(/substeps must be an integer in \[1, 64\], got 0/);
  });
  test('setAngularVelocity and setOrientation write the stores (normalising quaternions)', () => {
    const world = createPhysicsWorld({ dimensions: 3 });
    const b = addBody(world, { radius: 1 });
    setAngularVelocity(world, b, [1, 2, 3]);
    setOrientation(world, b, [0, 0, 2, 0]);
    const c = world.components;
    expect([c.AngularVelocity.x[b], c.AngularVelocity.y[b], c.AngularVelocity.z[b]]).toEqual([1, 2, 3]);
    expect([c.Orientation.x[b], c.Orientation.y[b], c.Orientation.z[b], c.Orientation.w[b]]).toEqual([0, 0, 1, 0]);
    expect(() => setOrientation(world, b, [0, 0, 0, 0])).toThrow(/zero quaternion/);
    expect(() => setAngularVelocity(world, b, 3)).toThrow(TypeError);
  });
});
