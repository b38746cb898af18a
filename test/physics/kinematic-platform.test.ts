import { addBody, addBox, addShape3D, createPhysicsWorld, type PhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';
import { KERNEL_HELPERS } from '../../packages/physics/src/solver/kernel-helpers.js';
import { rigidPartner } from '../../packages/physics/src/solver/rigid-partner.js';

/**
 * A body resting on a kinematic platform sinks into it as deep as into a static one of the same shape:
 * neither takes the contact's impulse (inverse mass 0), so the contact is a spring on the resting body
 * alone and every contact row family gives it the stiffer softness (solver/rigid-partner.ts). At rest
 * the soft contact's spring holds the weight, so the overlap is its static deflection g / omega^2 with
 * omega = 2 pi f, f twice the family's contact frequency (Box2D's soft step: the warm-started impulse
 * m g h_s balances the bias rate times the overlap when m h_s omega^2 s = m g h_s). Shapes (2D and 3D
 * manifolds): f = min(contactHertz, SHAPE_HERTZ_FRACTION / h_s) (solver/contact-scale.ts); balls:
 * f = contactHertz sqrt(1 m / r) for the smallest ball's radius r. The soft rule (partner treated as
 * moving) gives half the frequency, a quarter of the stiffness: four times the overlap, which is what
 * a 3D box on a kinematic platform had (2.76e-4 m against 6.90e-5 m).
 */

const G = 9.81;
/** Steps of 1/60 s before the overlap is read: the soft contact settles within 0.5 s (overdamped, zeta 10). */
const STEPS = 120;
/** Relative tolerance of every depth: the settled overlaps agree to 1e-9 of themselves. */
const TOL = 0.01;

type Platform = 'static' | 'kinematic' | 'rising';
/** The platform's options: static, kinematic at rest, or kinematic rising at 0.5 m/s (in its frame, the same contact). */
function platformOptions(p: Platform, dimensions: 2 | 3): object {
  if (p === 'static') return { static: true };
  if (p === 'kinematic') return { kinematic: true };
  return { kinematic: true, velocity: dimensions === 2 ? [0, 0.5] : [0, 0.5, 0] };
}

/** How far (m) `body` has sunk into `platform`: their centres' vertical distance at touching, `gap`, less the one now. */
function depth(world: PhysicsWorld, platform: number, body: number, gap: number): number {
  const P = world.components.Position;
  return gap - (P.y[body]! - P.y[platform]!);
}

/** A 1 m box on a 4 m by 1 m platform (2D shapes), settled; returns its overlap (m) and the shapes' frequency f (Hz). */
function box2D(p: Platform): { depth: number; hertz: number } {
  const world = createPhysicsWorld({ gravity: [0, -G], sleep: false });
  const platform = slotOf(addBox(world, { position: [0, 0], halfExtents: [2, 0.5], ...platformOptions(p, 2) }));
  const box = slotOf(addBox(world, { position: [0, 1], halfExtents: [0.5, 0.5] }));
  for (let i = 0; i < STEPS; i++) step(world);
  return { depth: depth(world, platform, box, 1), hertz: shapeHertz(world) };
}

/** A 1 m cube on a 4 m by 1 m by 4 m platform (3D shapes), settled; overlap (m) and f (Hz). */
function box3D(p: Platform): { depth: number; hertz: number } {
  const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -G, 0], sleep: false });
  const platform = addBody(world, { position: [0, 0, 0], ...platformOptions(p, 3) });
  addShape3D(world, platform, { type: 'box', halfExtents: [2, 0.5, 2] });
  const box = addBody(world, { position: [0, 1, 0], rotates: true });
  addShape3D(world, box, { type: 'box', halfExtents: [0.5, 0.5, 0.5], density: 1 });
  for (let i = 0; i < STEPS; i++) step(world);
  return { depth: depth(world, slotOf(platform), slotOf(box), 1), hertz: shapeHertz(world) };
}

/** A ball of radius 0.5 m on top of a ball of radius 5 m (the ball rows, 2D or 3D), settled; overlap (m) and f (Hz). */
function ballOnBall(dimensions: 2 | 3, p: Platform): { depth: number; hertz: number } {
  const world = createPhysicsWorld({ dimensions, gravity: dimensions === 2 ? [0, -G] : [0, -G, 0], sleep: false });
  const z = dimensions === 2 ? [] : [0];
  const platform = slotOf(addBody(world, { position: [0, -5, ...z], radius: 5, ...platformOptions(p, dimensions) }));
  const ball = slotOf(addBody(world, { position: [0, 0.5, ...z], radius: 0.5, mass: 1 }));
  for (let i = 0; i < STEPS; i++) step(world);
  return { depth: depth(world, platform, ball, 5.5), hertz: world.collision.settings.contactHertz * Math.sqrt(1 / 0.5) };
}

/** The shape contacts' frequency, Hz: contactHertz capped at an eighth of the substep rate (SHAPE_HERTZ_FRACTION). */
function shapeHertz(world: PhysicsWorld): number {
  const s = world.collision.settings;
  return Math.min(s.contactHertz, (0.125 * s.solverSubsteps) / world.h);
}

/** The static deflection g / omega^2 (m) of the stiffer contact spring, omega = 2 pi (2 f). */
function deflection(hertz: number): number {
  const omega = 2 * Math.PI * 2 * hertz;
  return G / (omega * omega);
}

const cases: [string, (p: Platform) => { depth: number; hertz: number }][] = [
  ['2D box (2D manifolds)', box2D],
  ['3D box (3D manifolds)', box3D],
  ['2D ball (ball rows)', (p) => ballOnBall(2, p)],
  ['3D ball (ball rows)', (p) => ballOnBall(3, p)],
];

describe('a body on a kinematic platform sinks in as on a static one, in every contact row family', () => {
  for (const [name, scene] of cases) {
    test(`${name}: the stiffer softness against static, kinematic and rising kinematic platforms`, () => {
      const still = scene('static');
      // The static platform's overlap is the stiffer spring's deflection (not the soft one's, 4 times it).
      const expected = deflection(still.hertz);
      expect(Math.abs(still.depth - expected)).toBeLessThan(TOL * expected);
      for (const p of ['kinematic', 'rising'] as const) {
        const moving = scene(p);
        expect(Math.abs(moving.depth - still.depth), p).toBeLessThan(TOL * still.depth);
      }
    });
  }
});

describe('rigidPartner, the one rule', () => {
  test('a row is against an infinite-mass partner when either inverse mass is 0', () => {
    expect([rigidPartner(0, 1), rigidPartner(2, 0), rigidPartner(0, 0), rigidPartner(1, 0.5)]).toEqual([1, 1, 1, 0]);
  });
  test('the ball rows reach it as KERNEL_HELPERS 19 (the workers run the same function)', () => {
    expect(KERNEL_HELPERS[19]).toBe(rigidPartner);
  });
});
