/**
 * contactEvents(world): one function for the contact events of 2D and 3D worlds, of shapes and of
 * balls (ball bodies against each other, segments and the boundary box) alike. A box dropped from
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
  addSegment,
  addShape3D,
  contactEvents,
  contactEvents3D,
  createPhysicsWorld,
  isSleeping,
  type PhysicsWorld,
  removeBody,
  setBoundary,
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

/**
 * Two equal balls meet head-on at 2 m/s each with restitution 1 and no gravity: the impact stage
 * bounces them exactly (an elastic exchange), so the one begin event's approach speed is 4 m/s and
 * its impulse the momentum one ball lost, m (v_before - v_after) = 4 m, both to rounding
 * (BALANCE_TOLERANCE); they part within a few steps, which gives one end event.
 */
function headOn(dimensions: 2 | 3): void {
  const world = createPhysicsWorld({ dimensions, capacity: 16, gravity: [0, 0, 0].slice(0, dimensions) });
  const along = dimensions === 3 ? 2 : 0; // the line of centres: z in 3D, x in 2D
  const at = (u: number): number[] => [0, 0, 0].map((_, k) => (k === along ? u : 0)).slice(0, dimensions);
  const a = addBody(world, { position: at(-1), velocity: at(2), radius: 0.25, mass: 1.5, restitution: 1 });
  const b = addBody(world, { position: at(1), velocity: at(-2), radius: 0.25, mass: 1.5, restitution: 1 });
  const V = [world.components.Velocity.x, world.components.Velocity.y, world.components.Velocity.z][along]!;
  let begins = 0,
    ends = 0,
    hits = 0;
  for (let i = 0; i < 60; i++) {
    const before = V[slotOf(a)]!;
    step(world);
    const { begin, end, hit } = contactEvents(world);
    hits += hit.count;
    ends += end.count;
    if (end.count > 0) expect([end.shapeA[0], end.shapeB[0]].sort()).toEqual([a, b].sort());
    if (begin.count === 0) continue;
    begins += begin.count;
    // A ball is its own shape and body; the lower slot is A, the normal points from A to B.
    expect([begin.shapeA[0], begin.shapeB[0]]).toEqual([a, b]);
    expect([begin.bodyA[0], begin.bodyB[0]]).toEqual([a, b]);
    const n = [begin.nx[0]!, begin.ny[0]!, begin.nz[0]!];
    expect(n[along]).toBeCloseTo(1, 12);
    expect(Math.hypot(...n)).toBeCloseTo(1, 12);
    expect(begin.approachSpeed[0]).toBeCloseTo(4, 9);
    const lost = 1.5 * (before - V[slotOf(a)]!);
    expect(Math.abs(begin.impulse[0]! - lost) / lost).toBeLessThan(BALANCE_TOLERANCE);
    expect(begin.impulse[0]).toBeCloseTo(6, 9);
    // The point lies between the centres, on the line of centres.
    const p = [begin.px[0]!, begin.py[0]!, begin.pz[0]!];
    expect(Math.abs(p[along]!)).toBeLessThan(0.25);
  }
  expect(begins).toBe(1);
  expect(hits).toBe(1);
  expect(ends).toBe(1);
}

describe('contactEvents of balls', () => {
  it('two balls meeting head-on in 2D give one begin (a hit) with the elastic impulse, then one end', () => headOn(2));

  it('two spheres meeting head-on in 3D give one begin (a hit) with the elastic impulse, then one end', () => headOn(3));

  it('a ball dropped on a segment begins once, naming the segment and the static world, and rests without more events', () => {
    const world = createPhysicsWorld({ dimensions: 2, capacity: 16, gravity: [0, -G] });
    const floor = addSegment(world, { a: [-5, 0], b: [5, 0] });
    const ball = addBody(world, { position: [0, 2], radius: 0.25 });
    const vy = world.components.Velocity.y;
    let before = 0;
    for (let i = 0; i < 120 && contactEvents(world).begin.count === 0; i++) {
      before = -vy[slotOf(ball)]!;
      step(world);
    }
    const { begin, hit } = contactEvents(world);
    expect(begin.count).toBe(1);
    expect([begin.shapeA[0], begin.bodyA[0], begin.shapeB[0], begin.bodyB[0]]).toEqual([floor, 0, ball, ball]);
    expect(begin.ny[0]).toBeCloseTo(1, 9);
    // Fell 1.75 m: sqrt(2 g h) = 5.86 m/s; the approach speed is the speed at impact, at least the
    // step's start speed and at most what the rest of the step's fall adds (g dt = 0.16 m/s).
    expect(begin.approachSpeed[0]).toBeGreaterThanOrEqual(before - 1e-9);
    expect(begin.approachSpeed[0]).toBeLessThan(before + G * world.dt + 1e-9);
    expect(hit.count).toBe(1);
    // Resting, then asleep (0.5 s on): no new begin or end events.
    for (let i = 0; i < 120; i++) {
      step(world);
      expect(contactEvents(world).begin.count).toBe(0);
      expect(contactEvents(world).end.count).toBe(0);
    }
  });

  it("a ball landing on the boundary box's floor names the face as shape -1 - face and the static world as body", () => {
    const world = createPhysicsWorld({ dimensions: 2, capacity: 16, gravity: [0, -G] });
    setBoundary(world, { min: [-2, 0], max: [2, 4] });
    const ball = addBody(world, { position: [0, 1], radius: 0.25 });
    let found = false;
    for (let i = 0; i < 120 && !found; i++) {
      step(world);
      const { begin } = contactEvents(world);
      if (begin.count === 0) continue;
      found = true;
      expect(begin.count).toBe(1);
      // Faces 0 -x, 1 +x, 2 -y, 3 +y: the floor is face 2, shape -3.
      expect([begin.shapeA[0], begin.bodyA[0], begin.shapeB[0]]).toEqual([-3, 0, ball]);
      expect(begin.ny[0]).toBeCloseTo(1, 9);
    }
    expect(found).toBe(true);
  });
});

/**
 * Contacts keep touching while their bodies sleep (Box2D v3's rule): falling asleep on the ground gives
 * no end event and waking up again no begin event; a pair that parts after the wake ends once, and
 * removing a sleeping body ends its contacts, with its old handle.
 */
describe('contact events across sleep', () => {
  function settle(world: PhysicsWorld, body: number): { begins: number; ends: number } {
    let begins = 0,
      ends = 0;
    for (let i = 0; i < 150; i++) {
      step(world);
      begins += contactEvents(world).begin.count;
      ends += contactEvents(world).end.count;
    }
    expect(isSleeping(world, body)).toBe(true);
    return { begins, ends };
  }

  for (const dimensions of [2, 3] as const) {
    it(`${dimensions}D: a box falls asleep on the ground and is hit awake without ending or beginning its ground contact; lifted off, it ends once`, () => {
      const g = dimensions === 2 ? [0, -G] : [0, -G, 0];
      const world = createPhysicsWorld({ dimensions, capacity: 16, gravity: g });
      const at = (x: number, y: number): number[] => (dimensions === 2 ? [x, y] : [x, y, 0]);
      const box = (y: number): number => {
        if (dimensions === 2) return addBox(world, { position: at(0, y), halfExtents: [0.5, 0.5] });
        const b = addBody(world, { position: at(0, y) });
        addShape3D(world, b, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
        return b;
      };
      let ground: number;
      if (dimensions === 2) ground = addBox(world, { position: [0, -0.5], halfExtents: [5, 0.5], static: true });
      else {
        ground = addBody(world, { position: [0, -0.5, 0], static: true });
        addShape3D(world, ground, { type: 'box', halfExtents: [5, 0.5, 5] });
      }
      const lower = box(0.5);
      expect(settle(world, lower)).toEqual({ begins: 1, ends: 0 });
      // A second box dropped on it wakes it: the only new pair is the two boxes.
      const upper = box(2.5);
      const pairs: number[][] = [];
      let ends = 0;
      for (let i = 0; i < 60; i++) {
        step(world);
        const { begin, end } = contactEvents(world);
        for (let k = 0; k < begin.count; k++) pairs.push([begin.bodyA[k]!, begin.bodyB[k]!].sort());
        ends += end.count;
      }
      expect(pairs).toEqual([[lower, upper].sort()]);
      expect(ends).toBe(0);
      // Lifted off the ground (a move wakes nothing by itself; the step sees the gap): one end event.
      setPosition(world, lower, at(3, 4));
      setVelocity(world, lower, at(0, 0));
      step(world);
      const { end } = contactEvents(world);
      const ended = Array.from({ length: end.count }, (_, k) => [end.bodyA[k]!, end.bodyB[k]!].sort());
      expect(ended).toContainEqual([ground, lower].sort());
      expect(ended.filter((p) => p.includes(ground))).toHaveLength(1);
    });
  }

  it('a sleeping ball removed from a segment ends its contact, naming its old handle', () => {
    const world = createPhysicsWorld({ dimensions: 2, capacity: 16, gravity: [0, -G] });
    const floor = addSegment(world, { a: [-5, 0], b: [5, 0] });
    const ball = addBody(world, { position: [0, 1], radius: 0.25 });
    expect(settle(world, ball)).toEqual({ begins: 1, ends: 0 });
    removeBody(world, ball);
    step(world);
    const { end } = contactEvents(world);
    expect(end.count).toBe(1);
    expect([end.shapeA[0], end.bodyA[0], end.shapeB[0], end.bodyB[0]]).toEqual([floor, 0, ball, ball]);
  });
});
