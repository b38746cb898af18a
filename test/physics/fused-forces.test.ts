import {
  addBody,
  addEmitter,
  addSpring,
  addSystem,
  createPhysicsWorld,
  disposeWorld,
  enableThreads,
  NonFiniteStateError,
  type PhysicsWorld,
  SCENES,
  setAttractor,
  setWind,
  stateHash,
  step,
} from '@bitphysics/physics';
import { hasComponent, query } from 'bitecs';
import { describe, expect, test } from 'vitest';
import { fusedForcesAllowed } from '../../packages/physics/src/integrators/fused-gate.js';

// Worlds with threads > 1 need the thread pool (step/enable-threads.ts).
enableThreads();

// The fused force-and-integrate pass (integrators/fused-gate.ts, semi-implicit-euler.ts fusedForced2)
// must leave exactly the state the separate stages leave (clear, drag laws, forces check, integrator).
// The independent reference is the separate path itself: a no-op user system in the forces stage turns
// the pass off (the gate refuses any system it does not know), so the same scene stepped both ways must
// hash the same, every bit of every body (stateHash) including the Force accumulators. Exact equality:
// the pass performs the same floating-point operations in the same order per body.

const noop = (): void => {};

/** A world of particles of every kind the pass handles, stiff and not, and plain bodies with drag. */
function mixedWorld(substeps: number, dimensions: 2 | 3 = 2): PhysicsWorld {
  const world = createPhysicsWorld({
    dimensions,
    capacity: 6000,
    gravity: dimensions === 2 ? [0, -9.81] : [0, -9.81, 0],
    seed: 3,
    substeps,
  });
  const v = (x: number, y: number): number[] => (dimensions === 2 ? [x, y] : [x, y, 0.5 * x]);
  // Quadratic drag: k |v| h / m from ~0.004 (5 m/s) to ~0.3 at 40 m/s, so some steps are stiff.
  const quad = addEmitter(world, {
    position: v(0, 0),
    rate: 3000,
    speed: [5, 40],
    lifetime: [0.3, 0.9],
    particle: { mass: 0.002, quadraticDrag: 1e-3 },
  });
  void quad;
  // Linear drag: k h / m = 0.5 (stiff) for one emitter, 0.05 for the other.
  addEmitter(world, { position: v(3, 0), rate: 1500, speed: [2, 6], lifetime: [0.2, 0.6], particle: { mass: 0.01, linearDrag: 0.3 } });
  addEmitter(world, { position: v(-3, 0), rate: 1500, speed: [2, 6], lifetime: [0.2, 0.6], particle: { mass: 0.01, linearDrag: 0.03 } });
  // Mass only (a force accumulator, no law): exact free fall; bursts into quadratic-drag sparks.
  const sparks = addEmitter(world, { speed: [1, 3], lifetime: [0.2, 0.4], particle: { mass: 0.001, quadraticDrag: 2e-5 } });
  addEmitter(world, {
    position: v(0, 1),
    rate: 120,
    speed: [8, 12],
    lifetime: [0.2, 0.5],
    particle: { mass: 0.1 },
    onDeath: { emitter: sparks, count: 10, maxGeneration: 1 },
  });
  // Ordinary bodies with drag beside the particles.
  addBody(world, { position: v(10, 5), velocity: v(3, 1), mass: 2, quadraticDrag: 0.05 });
  addBody(world, { position: v(-10, 5), velocity: v(-3, 1), mass: 2, linearDrag: 0.5 });
  return world;
}

describe('the fused force-and-integrate pass', () => {
  test("gives the separate stages' state to the bit (particles with quadratic, linear and no drag, stiff and not; 1 and 2 substeps; 2D and 3D)", () => {
    for (const [substeps, dimensions] of [
      [1, 2],
      [2, 2],
      [1, 3],
    ] as const) {
      const fused = mixedWorld(substeps, dimensions),
        separate = mixedWorld(substeps, dimensions);
      addSystem(separate, 'forces', noop);
      let fusedSteps = 0;
      for (let i = 0; i < 120; i++) {
        if (fusedForcesAllowed(fused)) fusedSteps++;
        expect(fusedForcesAllowed(separate)).toBe(false);
        step(fused);
        step(separate);
      }
      // The pass really ran (all but the first step, before any particle had a force accumulator).
      expect(fusedSteps, `${dimensions}D substeps ${substeps}`).toBeGreaterThanOrEqual(119);
      expect(stateHash(fused), `${dimensions}D substeps ${substeps}`).toBe(stateHash(separate));
    }
  });

  test("gives the separate stages' state to the bit on the fireworks scene (300 steps)", () => {
    const make = () => {
      const def = SCENES.fireworks!;
      const world = createPhysicsWorld(def.worldOptions({ count: 3000 }));
      def.build(world, { count: 3000 });
      return world;
    };
    const fused = make(),
      separate = make();
    addSystem(separate, 'forces', noop);
    for (let i = 0; i < 300; i++) {
      step(fused);
      step(separate);
    }
    expect(fusedForcesAllowed(fused)).toBe(true);
    expect(stateHash(fused)).toBe(stateHash(separate));
  });

  test('a user force law on particles still applies (the pass turns off): v1 = v0 + (F / m + g) h, drag included', () => {
    const world = createPhysicsWorld({ dimensions: 2, gravity: [0, -9.81], capacity: 200 });
    addEmitter(world, { position: [0, 0], rate: 600, speed: [2, 4], lifetime: 5, particle: { mass: 0.5 } });
    addEmitter(world, { position: [0, 0], rate: 600, speed: [2, 4], lifetime: 5, particle: { mass: 0.5, quadraticDrag: 0.01 } });
    for (let i = 0; i < 3; i++) step(world);
    expect(fusedForcesAllowed(world)).toBe(true);
    const c = world.components;
    const F = 2; // N along +x on every particle
    addSystem(world, 'forces', (w) => {
      for (const e of query(w as never, [c.Particle, c.Force])) c.Force.x[e] = c.Force.x[e]! + F;
    });
    expect(fusedForcesAllowed(world)).toBe(false);
    const ents = Array.from(query(world as never, [c.Particle, c.Force]));
    expect(ents.length).toBeGreaterThan(20);
    const v0 = ents.map((e) => [c.Velocity.x[e]!, c.Velocity.y[e]!]);
    step(world);
    const h = world.dt,
      m = 0.5;
    ents.forEach((e, i) => {
      const [u, v] = v0[i]!;
      // Quadratic drag -k |v| v where the particle has it (k |v| h / m <= 0.01 * 5 / 60 / 0.5: never stiff).
      const k = hasComponent(world as never, e, c.QuadraticDrag) ? 0.01 : 0;
      const s = Math.hypot(u, v);
      const ax = (F - k * s * u) / m,
        ay = (-k * s * v) / m - 9.81;
      // Relative 1e-12: the same formula in a different order of operations.
      expect(c.Velocity.x[e]).toBeCloseTo(u + ax * h, 12);
      expect(c.Velocity.y[e]).toBeCloseTo(v + ay * h, 12);
    });
  });

  test("runs in a world with worker threads too (on its calling thread); the state is the one-thread world's to the bit", () => {
    const make = (threads: number) => {
      const def = SCENES.fireworks!;
      const world = createPhysicsWorld({ ...def.worldOptions({ count: 3000 }), threads });
      def.build(world, { count: 3000 });
      return world;
    };
    const one = make(1),
      two = make(2);
    try {
      let fusedOne = 0,
        fusedTwo = 0;
      for (let i = 0; i < 120; i++) {
        if (fusedForcesAllowed(one)) fusedOne++;
        if (fusedForcesAllowed(two)) fusedTwo++;
        step(one);
        step(two);
      }
      // The same steps fuse as on one thread (those with sparks in the air); before, a world with
      // threads never fused (its step ran the five separate passes, slower).
      expect(fusedOne).toBeGreaterThan(60);
      expect(fusedTwo).toBe(fusedOne);
      expect(stateHash(two)).toBe(stateHash(one));
    } finally {
      disposeWorld(two);
    }
  });

  test('turns off for anything that could touch a force accumulator, and on again without it', () => {
    const make = (): PhysicsWorld => {
      const world = createPhysicsWorld({ dimensions: 2, gravity: [0, -9.81], capacity: 100 });
      addBody(world, { position: [0, 5], mass: 1, quadraticDrag: 0.1 });
      return world;
    };
    expect(fusedForcesAllowed(make())).toBe(true);
    // Another integrator.
    expect(fusedForcesAllowed(createPhysicsWorld({ dimensions: 2, integrator: 'rk4' }))).toBe(false);
    let w = make();
    setWind(w, { velocity: [1, 0] });
    expect(fusedForcesAllowed(w)).toBe(false);
    w = make();
    setAttractor(w, addBody(w, { position: [0, 0], static: true }), { mass: 1e10 });
    expect(fusedForcesAllowed(w)).toBe(false);
    w = make();
    addSpring(w, { anchor: [0, 10], b: addBody(w, { position: [0, 8], mass: 1 }), stiffness: 10 });
    expect(fusedForcesAllowed(w)).toBe(false);
    // A body with both drags (not a fused kind): off.
    w = make();
    addBody(w, { mass: 1, linearDrag: 0.1, quadraticDrag: 0.1 });
    expect(fusedForcesAllowed(w)).toBe(false);
    // A static body with a force accumulator: off (the pass writes movers only).
    w = make();
    addBody(w, { mass: 1, quadraticDrag: 0.1, static: true });
    expect(fusedForcesAllowed(w)).toBe(false);
  });

  test('a drag force that overflows is reported as the forces stage reports it (Force.x, stage forces, the body), before the body moves', () => {
    // k = 1e200 kg/m at 1e60 m/s on 1e300 kg: k |v| h / m = 1e-40 (not stiff), F = k v^2 = 1e320 = Infinity.
    // The offending body must keep its position and velocity to the bit (the throw comes before it is
    // written, as the separate forces stage throws before the integrator runs); a body listed after it
    // (added later: the pass runs each list in entity order) must not move either.
    const errorOf = (separate: boolean, dimensions: 2 | 3, drag: 'quadratic' | 'linear'): NonFiniteStateError => {
      const world = createPhysicsWorld({ dimensions, gravity: dimensions === 2 ? [0, -9.81] : [0, -9.81, 0] });
      const vec = (x: number, y: number): number[] => (dimensions === 2 ? [x, y] : [x, y, 0.25 * y]);
      // Linear drag: k = 1e300 kg/s at 1e30 m/s on 1e300 kg is not stiff (k h / m = 1/60) and F = 1e330.
      const b =
        drag === 'quadratic'
          ? addBody(world, { mass: 1e300, quadraticDrag: 1e200, position: vec(1.5, 2), velocity: vec(1e60, 3) })
          : addBody(world, { mass: 1e300, linearDrag: 1e300, position: vec(1.5, 2), velocity: vec(1e30, 3) });
      // In the same drag list as b (the lists run bare, quadratic, linear).
      const after = addBody(world, {
        mass: 2,
        [drag === 'quadratic' ? 'quadraticDrag' : 'linearDrag']: 0.01,
        position: vec(-1, 4),
        velocity: vec(2, 1),
      });
      if (separate) addSystem(world, 'forces', noop);
      expect(fusedForcesAllowed(world)).toBe(!separate);
      const c = world.components;
      const motion = (e: number): number[] => [
        c.Position.x[e]!,
        c.Position.y[e]!,
        c.Position.z[e]!,
        c.Velocity.x[e]!,
        c.Velocity.y[e]!,
        c.Velocity.z[e]!,
      ];
      const before = [motion(b), motion(after)];
      let caught: unknown;
      try {
        step(world);
      } catch (e) {
        caught = e;
      }
      expect(caught).toBeInstanceOf(NonFiniteStateError);
      expect((caught as NonFiniteStateError).entity).toBe(b);
      // Exact equality: no arithmetic may have touched them (Object.is also tells -0 from 0).
      for (const m of [motion(b), motion(after)]) for (const v of m) expect(Number.isFinite(v)).toBe(true);
      expect(motion(b)).toEqual(before[0]);
      expect(motion(after)).toEqual(before[1]);
      return caught as NonFiniteStateError;
    };
    for (const dimensions of [2, 3] as const) {
      for (const drag of ['quadratic', 'linear'] as const) {
        const a = errorOf(false, dimensions, drag),
          b = errorOf(true, dimensions, drag);
        expect([a.field, a.stage]).toEqual(['Force.x', 'forces']);
        expect([a.field, a.stage]).toEqual([b.field, b.stage]);
        expect(a.message).toContain('(-Infinity)');
      }
    }
  });
  test('a NaN velocity written by hand on a body with drag is reported as its force (Force.x, stage forces) before any position turns NaN', () => {
    // F = -k |v| v with v = (NaN, 1) is NaN; the separate stages throw at the forces check before the
    // integrator. With the pass, no position may become NaN either: the body's own, and the next body's in its list.
    for (const separate of [false, true]) {
      const world = createPhysicsWorld({ dimensions: 2, gravity: [0, -9.81] });
      const b = addBody(world, { mass: 1, quadraticDrag: 0.1, position: [0.5, 1] });
      const next = addBody(world, { mass: 1, quadraticDrag: 0.1, position: [2, 3], velocity: [1, 1] });
      if (separate) addSystem(world, 'forces', noop);
      expect(fusedForcesAllowed(world)).toBe(!separate);
      const c = world.components;
      c.Velocity.x[b] = NaN;
      let caught: unknown;
      try {
        step(world);
      } catch (e) {
        caught = e;
      }
      expect(caught).toBeInstanceOf(NonFiniteStateError);
      const err = caught as NonFiniteStateError;
      expect([err.entity, err.field, err.stage]).toEqual([b, 'Force.x', 'forces']);
      expect([c.Position.x[b], c.Position.y[b], c.Velocity.y[b]]).toEqual([0.5, 1, 0]);
      expect([c.Position.x[next], c.Position.y[next], c.Velocity.x[next], c.Velocity.y[next]]).toEqual([2, 3, 1, 1]);
    }
  });
});
