import { addBody, addPlane, addShape3D, createPhysicsWorld, isSleeping, removeBody, slotOf, step, stepMany } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

describe('3D shape bodies sleep in islands', () => {
  test('a stack of boxes falls asleep and stays put; a box dropped on it wakes the stack, which holds it and sleeps again', () => {
    const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -9.81, 0] });
    addPlane(world, { normal: [0, 1, 0] });
    const stack: number[] = [];
    for (let i = 0; i < 3; i++) {
      const b = addBody(world, { position: [0, 0.5 + i, 0] });
      addShape3D(world, b, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
      stack.push(b);
    }
    const c = world.components,
      top = slotOf(stack[2]!);
    let asleepAt = -1;
    for (let s = 0; s < 240 && asleepAt < 0; s++) {
      step(world);
      if (stack.every((b) => isSleeping(world, b))) asleepAt = s;
    }
    // Rest for the sleep time (0.5 s) after settling: asleep well within 4 s.
    expect(asleepAt).toBeGreaterThan(0);
    const y = c.Position.y[top]!;
    for (let s = 0; s < 30; s++) step(world);
    // Asleep, nothing moves at all (the solver skips the island).
    expect(c.Position.y[top]!).toBe(y);
    expect(stack.every((b) => isSleeping(world, b))).toBe(true);
    // A box falls onto the sleeping stack: the stack wakes when it arrives ...
    const drop = addBody(world, { position: [0.2, 4.5, 0] });
    addShape3D(world, drop, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
    let woke = false;
    for (let s = 0; s < 60; s++) {
      step(world);
      if (!isSleeping(world, stack[0]!)) woke = true;
    }
    expect(woke).toBe(true);
    // ... holds it (the dropped box rests on the top one: centre 1 m above it, within 2 cm) ...
    expect(Math.abs(c.Position.y[slotOf(drop)]! - c.Position.y[top]! - 1)).toBeLessThan(0.02);
    expect(Math.abs(c.Position.y[top]! - y)).toBeLessThan(0.02);
    // ... and everything sleeps again.
    for (let s = 0; s < 240; s++) step(world);
    expect([...stack, drop].every((b) => isSleeping(world, b))).toBe(true);
  });

  test('removing an awake box that leaned on a sleeping box wakes it, which stays where it was', () => {
    const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -10, 0] });
    addPlane(world, { normal: [0, 1, 0] });
    const b = addBody(world, { position: [0, 0.5, 0] });
    addShape3D(world, b, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
    stepMany(world, 120);
    expect(isSleeping(world, b)).toBe(true);
    // A box against its side that counts as resting (rest time > 0) leaves the sleeper asleep; the rest
    // time is set here, as a box that settled there would have it.
    const a = addBody(world, { position: [1, 0.5, 0] });
    addShape3D(world, a, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
    world.collision.sleep.restTime[slotOf(a)] = 0.1;
    step(world);
    expect(isSleeping(world, b) && !isSleeping(world, a)).toBe(true);
    const c = world.components,
      s = slotOf(b),
      y = c.Position.y[s];
    removeBody(world, a);
    expect(isSleeping(world, b)).toBe(false);
    // Woken between steps: no velocity or position is written (exactly; not the step's gravity, v = g h).
    expect([c.Velocity.x[s], c.Velocity.y[s], c.Velocity.z[s], c.Position.y[s]]).toEqual([0, 0, 0, y]);
  });
});
