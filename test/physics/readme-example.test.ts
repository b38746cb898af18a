import { addBody, addMagneticField, addSegment, createPhysicsWorld, setBoundary, setCharge, slotOf, step } from '@bitphysics/physics';
import { expect, test } from 'vitest';

/** Drag, a charge in a magnetic field, a wall and the boundary composed on one ball (the README's first example until it became a guide): the ball stays in its box and moves. */
test('the README example runs and the ball stays in its box', () => {
  const world = createPhysicsWorld({ dimensions: 2, capacity: 1000, gravity: [0, -9.81] });
  setBoundary(world, { min: [0, 0], max: [20, 12], restitution: 0.8 });
  addSegment(world, { a: [2, 6], b: [10, 3], friction: 0.3 });
  const ball = addBody(world, { position: [3, 10], radius: 0.4, mass: 2, restitution: 0.7, quadraticDrag: 0.05 });
  setCharge(world, ball, 0.5);
  addMagneticField(world, { field: 2 });
  for (let i = 0; i < 600; i++) step(world);
  const at = slotOf(ball);
  const x = world.components.Position.x[at]!,
    y = world.components.Position.y[at]!;
  expect(x).toBeGreaterThan(0.4 - 0.02);
  expect(x).toBeLessThan(20 - 0.4 + 0.02);
  expect(y).toBeGreaterThan(0.4 - 0.02);
  expect(y).toBeLessThan(12 - 0.4 + 0.02);
  expect(Math.hypot(x - 3, y - 10)).toBeGreaterThan(1);
});
