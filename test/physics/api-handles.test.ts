import {
  addBody,
  addBox,
  addShape,
  createCloth,
  createPhysicsWorld,
  createRope,
  isAlive,
  isJoint,
  query,
  removeBody,
  SLOT_RANGE,
  setShapeFilter,
  shapesOf,
  slotOf,
  step,
  updateMassFromShapes,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/**
 * Generational handles in the 2D shape API, compounds, ropes and cloth (issue 33). The reference is the
 * handle contract of world/handles.ts: a live entity's handle is accepted whatever its slot's history, a removed
 * entity's handle is refused with "refers to a removed entity", and every entity the API reports is alive.
 */

/** Removes and re-adds a body in the same slot `n` times; returns the live handle (generation n). */
function recycle(world: ReturnType<typeof createPhysicsWorld>, n: number): { live: number; stale: number } {
  let h = addBody(world, { position: [0, 0] });
  let stale = h;
  for (let i = 0; i < n; i++) {
    removeBody(world, h);
    stale = h;
    h = addBody(world, { position: [0, 0] });
  }
  return { live: h, stale };
}

describe('the 2D shape API takes handles', () => {
  test('addShape, shapesOf, setShapeFilter and updateMassFromShapes accept a live body in a reused slot', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 16 });
    const { live, stale } = recycle(world, 3);
    expect(slotOf(live)).toBe(slotOf(stale));
    const s = addShape(world, live, { type: 'circle', radius: 0.5 });
    expect(s).toBe(live); // the first shape lives on the body's entity
    expect(shapesOf(world, live)).toEqual([live]);
    setShapeFilter(world, s, { category: 2 });
    expect(world.components.Shape.category[slotOf(live)]).toBe(2);
    updateMassFromShapes(world, live);
    expect(world.components.Mass.value[slotOf(live)]).toBeCloseTo(Math.PI * 0.25, 12); // density 1 x pi r^2
  });

  test("a removed body's handle is refused and does not reach the body in its slot", () => {
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 16 });
    const { live, stale } = recycle(world, 1);
    expect(() => addShape(world, stale, { type: 'circle', radius: 0.5 })).toThrow(/^addShape: body refers to a removed entity/);
    expect(() => shapesOf(world, stale)).toThrow(/^shapesOf: body refers to a removed entity/);
    expect(() => updateMassFromShapes(world, stale)).toThrow(/^updateMassFromShapes: body refers to a removed entity/);
    addShape(world, live, { type: 'circle', radius: 0.5 });
    const box = addBox(world, { halfExtents: [0.5, 0.5] });
    removeBody(world, box);
    const other = addBox(world, { halfExtents: [0.5, 0.5] });
    expect(slotOf(other)).toBe(slotOf(box));
    expect(() => setShapeFilter(world, box, { mask: 0 })).toThrow(/^setShapeFilter: shape refers to a removed entity/);
    expect(world.components.Shape.mask[slotOf(other)]).toBe(0xffffffff);
  });

  test('addBox returns a handle, not a slot', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 16 });
    const a = addBox(world, { halfExtents: [0.5, 0.5] });
    removeBody(world, a);
    const b = addBox(world, { halfExtents: [0.5, 0.5] });
    expect(b).toBe(a + SLOT_RANGE);
    expect(isAlive(world, b)).toBe(true);
  });

  test('updateMassFromShapes on an id above the capacity throws at once (it looped forever)', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 16 });
    addBox(world, { halfExtents: [0.5, 0.5] });
    expect(() => updateMassFromShapes(world, 17)).toThrow(/^updateMassFromShapes: body must be an entity of this world/);
    expect(() => updateMassFromShapes(world, 1e6)).toThrow(RangeError);
  });
});

describe('compounds keep their shape lists', () => {
  test("removing a compound's extra shape unlinks it; removing the compound later spares the slot's new body", () => {
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 16 });
    const body = addBody(world, { position: [0, 0] });
    addShape(world, body, { type: 'box', halfExtents: [0.5, 0.5] });
    const extra = addShape(world, body, { type: 'circle', radius: 0.5, offset: [1, 0] });
    expect(shapesOf(world, body)).toEqual([body, extra]);
    removeBody(world, extra);
    expect(shapesOf(world, body)).toEqual([body]);
    // The body's mass follows its one remaining shape: density 1 x 1 m^2.
    expect(world.components.Mass.value[slotOf(body)]).toBeCloseTo(1, 12);
    const bystander = addBody(world, { position: [5, 5], radius: 0.2 });
    expect(slotOf(bystander)).toBe(slotOf(extra));
    expect(shapesOf(world, body)).toEqual([body]);
    removeBody(world, body);
    expect(isAlive(world, bystander)).toBe(true);
    step(world);
    expect(world.components.Position.x[slotOf(bystander)]).toBe(5);
  });
});

describe('ropes and cloth keep handles of any generation', () => {
  /** A world whose first slots have been used 70 times (past 64 generations, where Int32 overflows). */
  function worn(capacity: number, used: number): ReturnType<typeof createPhysicsWorld> {
    const world = createPhysicsWorld({ gravity: [0, -9.81], capacity });
    for (let g = 0; g < 70; g++) {
      const hs: number[] = [];
      for (let i = 0; i < used; i++) hs.push(addBody(world));
      for (const h of hs) removeBody(world, h);
    }
    return world;
  }

  test('createRope after 70 lives of every slot returns live bodies and joints', () => {
    const world = worn(64, 30);
    const alive = world.entityIndex.aliveCount;
    const rope = createRope(world, { start: [0, 0], end: [5, 0], segments: 10 });
    expect(rope.bodies.length).toBe(10);
    for (const b of rope.bodies) expect(isAlive(world, b)).toBe(true);
    for (const j of rope.joints) expect(isJoint(world, j)).toBe(true);
    expect(query(world, [world.components.Joint]).length).toBe(10);
    expect(world.entityIndex.aliveCount).toBe(alive + 20); // 10 bodies and 10 joints, no orphans
  });

  test('createCloth after 70 lives of every slot returns live points and links', () => {
    const world = worn(64, 40);
    const cloth = createCloth(world, { columns: 3, rows: 3, shearCompliance: null, bendCompliance: null });
    for (const p of cloth.points) expect(isAlive(world, p)).toBe(true);
    for (const l of cloth.links) expect(isJoint(world, l)).toBe(true);
  });
});
