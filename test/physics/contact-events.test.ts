/**
 * contactEvents(world): one function for the contact events of 2D and 3D worlds. A box dropped from
 * rest onto a static ground must give one begin (and hit) event naming its body and the ground's, with
 * the normal pointing up and an impulse equal to the momentum the contact took from the box in that
 * step (momentum balance: J = m (v_after - v_before) + m g dt, velocities read from the body); lifting
 * it off gives one end event.
 *
 * The contact is speculative (Catto, GDC 2013): it begins the step before the faces meet, and its
 * impulse then only slows the box to land exactly; the next step stops it. So the begin event's
 * impulse is not the whole m v of the impact; the begin step's plus the next step's momentum change
 * is, which the test checks too (the approach speed is the impact's speed).
 */
import { describe, expect, it } from 'vitest';
import {
  addBody,
  addBox,
  addShape3D,
  contactEvents,
  contactEvents3D,
  createPhysicsWorld,
  type PhysicsWorld,
  setPosition,
  setVelocity,
  slotOf,
  step,
} from '../../packages/physics/src/index.js';

const G = 9.81;

/**
 * Steps until the first begin event (at most `max` steps); returns the body's downward speed before
 * and after that step, m/s, and the steps taken.
 */
function dropUntilBegin(world: PhysicsWorld, box: number, max: number): { before: number; after: number; steps: number } {
  const vy = world.components.Velocity.y;
  for (let i = 1; i <= max; i++) {
    const before = -vy[slotOf(box)]!;
    step(world);
    if (contactEvents(world).begin.count > 0) return { before, after: -vy[slotOf(box)]!, steps: i };
  }
  throw new Error(`no begin event in ${max} steps`);
}

/**
 * Tolerance of the begin step's impulse against the momentum balance, relative: the impulse is the
 * solver's own sum and the velocities are the same step's, so they agree to rounding (1e-9 leaves
 * room for the sums of a few hundred operations).
 */
const BALANCE_TOLERANCE = 1e-9;

/**
 * Tolerance of the impact's whole impulse (begin step plus the next) against m v + 2 m g dt: the box
 * ends the second step at rest up to the soft contact's residual speed (< 1 mm/s against ~5 m/s), so
 * 1 % is generous; a missing or doubled step's impulse is off by 25 % or more.
 */
const IMPACT_TOLERANCE = 0.01;

/**
 * The begin step's impulse against the momentum balance, then the next step's momentum change added:
 * the impact's whole impulse, m v_impact + 2 m g dt (the weight during both steps).
 */
function expectImpulse(world: PhysicsWorld, box: number, mass: number, impulse: number, before: number, after: number): void {
  const gdt = G * world.dt;
  const balance = mass * (before - after + gdt);
  expect(Math.abs(impulse - balance) / balance).toBeLessThan(BALANCE_TOLERANCE);
  step(world);
  const rest = -world.components.Velocity.y[slotOf(box)]!;
  const next = mass * (after - rest + gdt);
  const impact = mass * (before + 2 * gdt);
  expect(Math.abs(impulse + next - impact) / impact).toBeLessThan(IMPACT_TOLERANCE);
}

describe('contactEvents in 2D', () => {
  function scene(): { world: PhysicsWorld; ground: number; box: number; mass: number } {
    const world = createPhysicsWorld({ dimensions: 2, capacity: 16, gravity: [0, -G] });
    const ground = addBox(world, { position: [0, -0.5], halfExtents: [5, 0.5], static: true });
    // 1 m x 1 m at density 2 kg/m^2: 2 kg.
    const box = addBox(world, { position: [0, 2], halfExtents: [0.5, 0.5], density: 2 });
    return { world, ground, box, mass: world.components.Mass.value[slotOf(box)]! };
  }

  it('a box dropped on the ground gives one begin event with its bodies, an upward normal and the impulse of the impact', () => {
    const { world, ground, box, mass } = scene();
    expect(mass).toBeCloseTo(2, 12);
    const { before, after } = dropUntilBegin(world, box, 120);
    // Fell about 1.5 m: v = sqrt(2 g h) ~ 5.4 m/s.
    expect(before).toBeGreaterThan(4);
    const { begin, hit } = contactEvents(world);
    expect(begin.count).toBe(1);
    const bodies = [begin.bodyA[0], begin.bodyB[0]];
    expect(bodies).toContain(box);
    expect(bodies).toContain(ground);
    // Normal from A to B; pointing up means from the ground to the box.
    const up = begin.bodyB[0] === box ? 1 : -1;
    expect(up * begin.ny[0]!).toBeCloseTo(1, 6);
    expect(begin.nx[0]).toBeCloseTo(0, 6);
    expect(begin.nz[0]).toBe(0);
    // The contact point lies on the ground's top face (y = 0) within the speculative gap.
    expect(Math.abs(begin.py[0]!)).toBeLessThan(0.2);
    expect(begin.approachSpeed[0]).toBeCloseTo(before, 6);
    // The same event is a hit (faster than 1 m/s).
    expect(hit.count).toBe(1);
    expect(hit.impulse[0]).toBe(begin.impulse[0]);
    expectImpulse(world, box, mass, begin.impulse[0]!, before, after);
    // Events are per step: the step after that, resting, has none.
    step(world);
    expect(contactEvents(world).begin.count).toBe(0);
    expect(contactEvents(world).end.count).toBe(0);
  });

  it('lifting the box off the ground gives one end event', () => {
    const { world, ground, box } = scene();
    dropUntilBegin(world, box, 120);
    for (let i = 0; i < 30; i++) step(world);
    setPosition(world, box, [0, 3]);
    setVelocity(world, box, [0, 0]);
    step(world);
    const { end, begin } = contactEvents(world);
    expect(begin.count).toBe(0);
    expect(end.count).toBe(1);
    expect([end.bodyA[0], end.bodyB[0]].sort()).toEqual([box, ground].sort());
  });

  it('a box set down slowly begins touching without a hit', () => {
    const { world, box } = scene();
    setPosition(world, box, [0, 0.52]);
    const { steps } = dropUntilBegin(world, box, 60);
    expect(steps).toBeLessThan(60);
    const { begin, hit } = contactEvents(world);
    expect(begin.count).toBe(1);
    expect(begin.approachSpeed[0]).toBeLessThan(1);
    expect(hit.count).toBe(0);
  });

  it('refuses a negative hit speed', () => {
    const { world } = scene();
    expect(() => contactEvents(world, -1)).toThrow(/contactEvents: hitSpeed must be/);
  });
});

describe('contactEvents in 3D', () => {
  function scene(): { world: PhysicsWorld; ground: number; box: number; mass: number } {
    const world = createPhysicsWorld({ dimensions: 3, capacity: 16, gravity: [0, -G, 0] });
    const ground = addBody(world, { position: [0, -0.5, 0], static: true });
    addShape3D(world, ground, { type: 'box', halfExtents: [5, 0.5, 5] });
    const box = addBody(world, { position: [0, 2, 0] });
    // 1 m cube at 2 kg/m^3: 2 kg.
    addShape3D(world, box, { type: 'box', halfExtents: [0.5, 0.5, 0.5], density: 2 });
    return { world, ground, box, mass: world.components.Mass.value[slotOf(box)]! };
  }

  it('a box dropped on the ground gives one begin event with its bodies, an upward normal and the impulse of the impact', () => {
    const { world, ground, box, mass } = scene();
    expect(mass).toBeCloseTo(2, 12);
    const { before, after } = dropUntilBegin(world, box, 120);
    expect(before).toBeGreaterThan(4);
    const { begin, hit } = contactEvents(world);
    expect(begin.count).toBe(1);
    const bodies = [begin.bodyA[0], begin.bodyB[0]];
    expect(bodies).toContain(box);
    expect(bodies).toContain(ground);
    const up = begin.bodyB[0] === box ? 1 : -1;
    expect(up * begin.ny[0]!).toBeCloseTo(1, 6);
    expect(begin.approachSpeed[0]).toBeCloseTo(before, 6);
    expect(hit.count).toBe(1);
    // contactEvents3D still gives the same begin event.
    expect(contactEvents3D(world).begin.count).toBe(1);
    expect(contactEvents3D(world).begin.bodyB[0]).toBe(begin.bodyB[0]);
    expectImpulse(world, box, mass, begin.impulse[0]!, before, after);
  });

  it('lifting the box off the ground gives one end event', () => {
    const { world, ground, box } = scene();
    dropUntilBegin(world, box, 120);
    for (let i = 0; i < 30; i++) step(world);
    setPosition(world, box, [0, 3, 0]);
    setVelocity(world, box, [0, 0, 0]);
    step(world);
    const { end } = contactEvents(world);
    expect(end.count).toBe(1);
    expect([end.bodyA[0], end.bodyB[0]].sort()).toEqual([box, ground].sort());
  });
});
