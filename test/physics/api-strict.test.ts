import {
  addBody,
  addElectricField,
  addEmitter,
  addFluidRegion,
  addMagneticField,
  addParticle,
  addSpring,
  createEntity,
  createPhysicsWorld,
  handleOf,
  isAlive,
  query,
  removeBody,
  SLOT_RANGE,
  setVelocity,
  slotOf,
  step,
  stepMany,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';
import { buildCases, classify, makeFixture, snapshot } from './api-strict-cases.js';

/**
 * Every exported function of @bitphysics/physics that takes an entity or an options object, given a
 * removed entity (its slot reused), a non-entity, an entity of the wrong kind, a missing or null
 * options object, null option values, non-boolean booleans and unknown keys (the table is in
 * api-strict-cases.ts). Each must throw a TypeError or RangeError whose message starts with the
 * function the user called, and leave the world exactly as it was (every store of every live
 * entity, the component sets, the live count, the spawn stamps, gravity, the boundary, the laws).
 */
describe('every public function refuses bad calls with a clear error and changes nothing', () => {
  const cases = buildCases();
  test('the table covers the API (more than 700 calls over more than 50 functions)', () => {
    expect(cases.length).toBeGreaterThan(700);
    expect(new Set(cases.map((c) => c.expectFrom)).size).toBeGreaterThan(50);
  });
  for (const c of cases) {
    test(c.label, () => {
      const fx = makeFixture();
      const before = snapshot(fx.world);
      let error: unknown;
      try {
        c.run(fx);
      } catch (e) {
        error = e;
      }
      expect(classify(c, error), String(error)).toBe('clear');
      if (c.pattern) expect((error as Error).message).toMatch(c.pattern);
      expect(snapshot(fx.world)).toBe(before);
    });
  }
});

describe('generational handles', () => {
  test("a removed body's handle does not move the body that reuses its slot", () => {
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 8 });
    const old = addBody(world, { position: [0, 0], radius: 0.5 });
    removeBody(world, old);
    const fresh = addBody(world, { position: [5, 5], radius: 0.5 });
    expect(slotOf(fresh)).toBe(slotOf(old));
    expect(fresh).toBe(old + SLOT_RANGE); // second life of the slot
    expect(() => setVelocity(world, old, [1, 0])).toThrow(
      /setVelocity: entity refers to a removed entity \(id \d+, slot \d+ now holds handle \d+\)/,
    );
    stepMany(world, 10);
    const P = world.components.Position;
    expect([P.x[slotOf(fresh)], P.y[slotOf(fresh)]]).toEqual([5, 5]); // untouched: nothing moved it
    expect(isAlive(world, old)).toBe(false);
    expect(isAlive(world, fresh)).toBe(true);
  });

  test("a stale handle cannot turn a field into a ball (the issue's setRadius case)", () => {
    const world = createPhysicsWorld({ capacity: 8 });
    const ball = addBody(world, { radius: 0.5 });
    removeBody(world, ball);
    const field = addMagneticField(world, { field: 1 });
    expect(slotOf(field)).toBe(slotOf(ball));
    expect(() => removeBody(world, ball)).toThrow(/removed entity/);
    expect(query(world, [world.components.Ball]).length).toBe(0);
    expect(query(world, [world.components.MagneticField]).length).toBe(1);
  });

  test('handleOf turns a query() slot into the handle the API accepts; every creating function returns a handle', () => {
    const world = createPhysicsWorld({ capacity: 4 });
    for (let round = 0; round < 3; round++) {
      const made = [addBody(world, {}), addParticle(world), createEntity(world), addEmitter(world, {})];
      for (const h of made) {
        expect(isAlive(world, h)).toBe(true);
        expect(handleOf(world, slotOf(h))).toBe(h);
        expect(slotOf(h)).toBeGreaterThanOrEqual(1);
        expect(slotOf(h)).toBeLessThanOrEqual(4);
      }
      // After the first round every slot is in a later life: handles differ from slots.
      if (round > 0) for (const h of made) expect(h).toBeGreaterThan(SLOT_RANGE);
      for (const h of made) removeBody(world, h);
    }
    expect(() => handleOf(world, 1)).toThrow(/handleOf: slot must be the slot of a live entity/);
  });

  test('a spring to a removed body is refused even though the slot holds a new body', () => {
    const world = createPhysicsWorld({ capacity: 8 });
    const a = addBody(world, {}),
      b = addBody(world, { position: [1, 0] });
    removeBody(world, b);
    addBody(world, { position: [2, 0] });
    expect(() => addSpring(world, { a, b, stiffness: 1 })).toThrow(/addSpring: b refers to a removed entity/);
  });
});

describe('atomic creation: a refused call leaves nothing behind', () => {
  test('four refused addBody calls on a world of capacity 4 leave room for 4 bodies', () => {
    const world = createPhysicsWorld({ capacity: 4 });
    const before = snapshot(world);
    const bad = [
      () => addBody(world, { radius: 1, inertia: -1 }),
      () => addBody(world, { radius: 1, inertia: [1, 2, 3] }),
      () => addBody(world, { static: 'yes' as never }),
      () => addBody(world, { position: [0, 0], rotates: false, angularVelocity: 2 }),
    ];
    for (const run of bad) {
      expect(run).toThrow(/^addBody: /);
      expect(snapshot(world)).toBe(before);
    }
    for (let i = 0; i < 4; i++) addBody(world, { position: [i, 0], radius: 0.4 });
    expect(world.entityIndex.aliveCount).toBe(4);
    step(world);
  });

  test('a full world refuses every creating function by its own name, and nothing changes', () => {
    const world = createPhysicsWorld({ capacity: 2 });
    const a = addBody(world, {}),
      b = addBody(world, { position: [1, 0] });
    const before = snapshot(world);
    const calls: Array<[string, () => unknown]> = [
      ['addBody', () => addBody(world, {})],
      ['addParticle', () => addParticle(world)],
      ['createEntity', () => createEntity(world)],
      ['addElectricField', () => addElectricField(world, { field: [1, 0] })],
      ['addFluidRegion', () => addFluidRegion(world, { surface: 0, density: 1000 })],
      ['addEmitter', () => addEmitter(world, {})],
      ['addSpring', () => addSpring(world, { a, b, stiffness: 1 })],
    ];
    for (const [name, run] of calls) {
      expect(run).toThrow(new RegExp(`^${name}: the world is full \\(capacity 2 entities\\)`));
      // addSpring would have given both bodies a force accumulator: it must not have.
      expect(snapshot(world)).toBe(before);
    }
  });
});
