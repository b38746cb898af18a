import {
  addBody,
  addBox,
  addSystem,
  contactSolverSystem,
  createPhysicsWorld,
  NonFiniteStateError,
  type PhysicsWorld,
  setBoundary,
  slotOf,
  step,
  stepMany,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/**
 * A NaN written into one body's state in the middle of the collide stage (by a system hooked in before
 * the contact solver) must stop the step before the solver spreads it through the contacts to the
 * bodies touching it: the error names that body and field, and every other body keeps a finite state,
 * the one it had before the step's collide stage (README: "before it reaches any other body").
 */
function pile2D(world: PhysicsWorld, shapes: boolean): number[] {
  setBoundary(world, { min: [0, 0], max: [20, 40] });
  const out: number[] = [];
  for (let j = 0; j < 10; j++)
    for (let i = 0; i < 12; i++) {
      const position = [0.5 + i + (j % 2) * 0.25, 0.5 + j];
      out.push(
        shapes ? addBox(world, { position, halfExtents: [0.49, 0.49], density: 1 }) : addBody(world, { position, radius: 0.5, mass: 1 }),
      );
    }
  return out;
}

function pile3D(world: PhysicsWorld): number[] {
  setBoundary(world, { min: [0, 0, 0], max: [6, 40, 6] });
  const out: number[] = [];
  for (let j = 0; j < 4; j++)
    for (let i = 0; i < 6; i++)
      for (let k = 0; k < 6; k++) out.push(addBody(world, { position: [0.5 + i, 0.5 + j, 0.5 + k], radius: 0.5, mass: 1 }));
  return out;
}

function nonFinite(world: PhysicsWorld, bodies: number[]): number {
  const c = world.components;
  let n = 0;
  for (const h of bodies) {
    const e = slotOf(h);
    const v = [
      c.Position.x[e]!,
      c.Position.y[e]!,
      c.Position.z[e]!,
      c.Velocity.x[e]!,
      c.Velocity.y[e]!,
      c.Velocity.z[e]!,
      c.AngularVelocity.z[e] ?? 0,
    ];
    if (!v.every(Number.isFinite)) n++;
  }
  return n;
}

describe('a NaN made in the collide stage stops the step before it reaches another body', () => {
  const cases: [string, () => { world: PhysicsWorld; bodies: number[] }][] = [
    [
      '2D balls',
      () => {
        const world = createPhysicsWorld({ gravity: [0, -9.81] });
        return { world, bodies: pile2D(world, false) };
      },
    ],
    [
      '2D boxes',
      () => {
        const world = createPhysicsWorld({ gravity: [0, -9.81] });
        return { world, bodies: pile2D(world, true) };
      },
    ],
    [
      '3D balls',
      () => {
        const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -9.81, 0] });
        return { world, bodies: pile3D(world) };
      },
    ],
  ];
  for (const [name, make] of cases) {
    test(`${name}: a NaN velocity written before the contact solver`, () => {
      const { world, bodies } = make();
      stepMany(world, 30);
      const victim = bodies[50]!;
      let armed = true;
      addSystem(
        world,
        'collide',
        () => {
          if (!armed) return;
          armed = false;
          world.components.Velocity.x[slotOf(victim)] = NaN;
        },
        { before: contactSolverSystem },
      );
      let caught: unknown;
      try {
        step(world);
      } catch (e) {
        caught = e;
      }
      expect(caught).toBeInstanceOf(NonFiniteStateError);
      expect((caught as NonFiniteStateError).entity).toBe(victim);
      expect((caught as NonFiniteStateError).field).toBe('Velocity.x');
      expect((caught as NonFiniteStateError).stage).toBe('collide');
      expect(nonFinite(world, bodies)).toBe(1);
    });
  }
});
