import { addBody, addPlane, addShape3D, createPhysicsWorld, isSleeping, type PhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/**
 * A sleeping box wakes when a moving body can reach it within the step, not when one merely passes
 * within the speculative distance (0.1 m): a box sliding by 0.05 m away (1 m/s along the gap,
 * frictionless, closing nothing) leaves it asleep, while the same box heading at it at 1 m/s wakes it
 * before it arrives (the 0.05 m gap takes 3 steps) and the pair then conserves x momentum on the
 * frictionless floor (1 kg x -1 m/s, to 1e-9 N s: a woken body moved as static geometry would gain none).
 */
function sleepingBox(): { world: PhysicsWorld; sleeper: number } {
  const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -10, 0] });
  addPlane(world, { normal: [0, 1, 0], friction: 0 });
  const sleeper = addBody(world, { position: [0, 0.5, 0] });
  addShape3D(world, sleeper, { type: 'box', halfExtents: [0.5, 0.5, 0.5], friction: 0 });
  for (let s = 0; s < 120 && !isSleeping(world, sleeper); s++) step(world);
  expect(isSleeping(world, sleeper)).toBe(true);
  return { world, sleeper };
}

function mover(world: PhysicsWorld, velocity: number[]): number {
  const b = addBody(world, { position: [1.05, 0.5, -0.5], velocity });
  addShape3D(world, b, { type: 'box', halfExtents: [0.5, 0.5, 0.5], friction: 0 });
  return b;
}

describe('3D sleeping islands wake on reach, not on proximity', () => {
  test('a box sliding past 0.05 m away leaves a sleeping box asleep', () => {
    const { world, sleeper } = sleepingBox();
    const m = mover(world, [0, 0, 1]);
    for (let s = 0; s < 60; s++) {
      step(world);
      expect(isSleeping(world, sleeper)).toBe(true);
    }
    // It slid on by 1 m (frictionless), never touching.
    expect(world.components.Position.z[slotOf(m)]!).toBeGreaterThan(0.45);
  });

  test('a box heading at a sleeping box wakes it and pushes it without sinking in', () => {
    const { world, sleeper } = sleepingBox();
    const m = mover(world, [-1, 0, 0]);
    const P = world.components.Position,
      V = world.components.Velocity,
      a = slotOf(sleeper),
      b = slotOf(m);
    let wokeAt = -1;
    for (let s = 0; s < 30; s++) {
      step(world);
      if (wokeAt < 0 && !isSleeping(world, sleeper)) wokeAt = s;
    }
    expect(wokeAt).toBeGreaterThanOrEqual(0);
    expect(wokeAt).toBeLessThanOrEqual(2);
    expect(Math.abs(V.x[a]! + V.x[b]! + 1)).toBeLessThan(1e-9);
    expect(P.x[a]!).toBeLessThan(-0.05);
  });
});
