import { addBody, addPlane, addShape3D, createPhysicsWorld, isSleeping, slotOf, step } from '@bitphysics/physics';
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
});
