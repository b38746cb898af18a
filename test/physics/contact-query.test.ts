/**
 * forEachContact(world, fn): one read path for every contact point of the last step, balls and shapes,
 * 2D and 3D. Checked against geometry (a box resting flat on the ground touches it at its two bottom
 * corners in 2D, four in 3D, on the ground's top face) and against the momentum balance: the normal
 * impulses of a body's contacts over a step equal m (v_after - v_before) + m g dt, read from the body.
 */
import { describe, expect, it } from 'vitest';
import {
  addBody,
  addBox,
  addShape3D,
  ContactKind,
  type ContactView,
  createPhysicsWorld,
  forEachContact,
  type PhysicsWorld,
  slotOf,
  step,
} from '../../packages/physics/src/index.js';

const G = 9.81;

/** Copies of the views `forEachContact` hands out (it reuses one object). */
function contacts(world: PhysicsWorld): ContactView[] {
  const out: ContactView[] = [];
  const n = forEachContact(world, (c) => out.push({ ...c }));
  expect(n).toBe(out.length);
  return out;
}

/**
 * Tolerance of a step's summed normal impulse against the momentum balance, relative: both are the same
 * step's sums of the solver's own numbers, so they agree to rounding over a few hundred operations.
 */
const BALANCE = 1e-9;

describe('forEachContact', () => {
  it('2D: a box resting on the ground gives its two bottom corners, kind Shape, with the impulse that holds it', () => {
    const world = createPhysicsWorld({ dimensions: 2, capacity: 16, gravity: [0, -G], sleep: false });
    const ground = slotOf(addBox(world, { position: [0, -0.5], halfExtents: [5, 0.5], static: true }));
    const box = slotOf(addBox(world, { position: [0, 0.5], halfExtents: [0.5, 0.5], density: 2 }));
    for (let i = 0; i < 60; i++) step(world);
    const m = world.components.Mass.value[box]!;
    const vy = world.components.Velocity.y;
    const before = vy[box]!;
    step(world);
    const seen = contacts(world);
    expect(seen).toHaveLength(2);
    let impulse = 0;
    for (const c of seen) {
      expect(c.kind).toBe(ContactKind.Shape);
      expect([c.bodyA, c.bodyB].sort()).toEqual([ground, box].sort());
      expect([c.a, c.b]).toEqual([c.bodyA, c.bodyB]);
      const up = c.bodyB === box ? 1 : -1;
      expect(up * c.ny).toBeCloseTo(1, 9);
      expect(c.nz).toBe(0);
      // On the ground's top face (within the solver's slop) at a bottom corner of the box.
      expect(Math.abs(c.y)).toBeLessThan(0.02);
      expect(Math.abs(Math.abs(c.x) - 0.5)).toBeLessThan(1e-6);
      impulse += c.impulse;
    }
    const balance = m * (vy[box]! - before + G * world.dt);
    expect(Math.abs(impulse - balance) / balance).toBeLessThan(BALANCE);
  });

  it('2D: a ball body resting on a box is one point of a shape contact, the ball its own shape', () => {
    const world = createPhysicsWorld({ dimensions: 2, capacity: 16, gravity: [0, -G], sleep: false });
    const ground = slotOf(addBox(world, { position: [0, -0.5], halfExtents: [5, 0.5], static: true }));
    const ball = slotOf(addBody(world, { position: [1, 0.3], radius: 0.3 }));
    for (let i = 0; i < 60; i++) step(world);
    const seen = contacts(world);
    expect(seen).toHaveLength(1);
    const c = seen[0]!;
    expect(c.kind).toBe(ContactKind.Shape);
    expect([c.shapeA, c.shapeB].sort()).toEqual([ground, ball].sort());
    expect(c.x).toBeCloseTo(1, 6);
    expect(Math.abs(c.y)).toBeLessThan(0.02);
    expect(c.impulse).toBeGreaterThan(0);
  });

  it('2D: ball contacts keep their kinds and fields (ball on the boundary floor)', () => {
    const world = createPhysicsWorld({ dimensions: 2, capacity: 16, gravity: [0, -G], sleep: false });
    world.collision.boundary.enabled = true;
    world.collision.boundary.min.set([-2, 0, 0]);
    world.collision.boundary.max.set([2, 4, 0]);
    const ball = slotOf(addBody(world, { position: [0, 0.25], radius: 0.25 }));
    for (let i = 0; i < 30; i++) step(world);
    const seen = contacts(world).filter((c) => c.kind === ContactKind.Boundary && c.ny > 0.5);
    expect(seen).toHaveLength(1);
    const c = seen[0]!;
    expect([c.a, c.bodyA, c.shapeA, c.b, c.bodyB, c.shapeB]).toEqual([0, 0, -3, ball, ball, ball]);
    expect(c.y).toBeCloseTo(0, 3);
  });

  it('3D: a cube resting on a box gives four points on its bottom face, kind Shape', () => {
    const world = createPhysicsWorld({ dimensions: 3, capacity: 16, gravity: [0, -G, 0], sleep: false });
    const ground = addBody(world, { position: [0, -0.5, 0], static: true });
    addShape3D(world, ground, { type: 'box', halfExtents: [5, 0.5, 5] });
    const cube = addBody(world, { position: [0, 0.5, 0] });
    addShape3D(world, cube, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
    for (let i = 0; i < 60; i++) step(world);
    const seen = contacts(world);
    expect(seen).toHaveLength(4);
    const corners = new Set<string>();
    for (const c of seen) {
      expect(c.kind).toBe(ContactKind.Shape);
      expect([c.bodyA, c.bodyB].sort()).toEqual([slotOf(ground), slotOf(cube)].sort());
      expect(Math.abs(c.ny)).toBeCloseTo(1, 6);
      expect(Math.abs(c.y)).toBeLessThan(0.02);
      corners.add(`${Math.sign(c.x)},${Math.sign(c.z)}`);
      expect(Math.abs(Math.abs(c.x) - 0.5)).toBeLessThan(1e-3);
      expect(Math.abs(Math.abs(c.z) - 0.5)).toBeLessThan(1e-3);
      expect(c.impulse).toBeGreaterThan(0);
    }
    expect(corners.size).toBe(4);
  });
});
