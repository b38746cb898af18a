import {
  addBody,
  addDistanceJoint3D,
  addShape3D,
  createPhysicsWorld,
  isSleeping,
  removeBody,
  removeJoint3D,
  slotOf,
  step,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

const G = 9.81;

/** A 0.1 m ball hanging at rest 1 m below `anchor` on a rigid distance joint, asleep after 4 s. */
function sleepingBob(withBody: boolean) {
  const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -G, 0] });
  // The holder: a static body (so it never moves) or the world.
  const holder = withBody ? addBody(world, { position: [0, 0, 0], static: true }) : null;
  if (holder !== null) addShape3D(world, holder, { type: 'box', halfExtents: [0.1, 0.1, 0.1] });
  const bob = addBody(world, { position: [0, -1, 0] });
  addShape3D(world, bob, { type: 'sphere', radius: 0.1 });
  const joint = addDistanceJoint3D(world, { a: holder, b: bob, anchorA: [0, 0, 0] });
  for (let i = 0; i < 240; i++) step(world);
  expect(isSleeping(world, bob)).toBe(true);
  return { world, holder, bob, joint };
}

describe('removing a 3D joint wakes what it held', () => {
  test('a sleeping bob falls freely once its joint is removed, or the body it hangs from (y drop = g t^2 / 2, 1e-9 m)', () => {
    // Before, the bob stayed asleep in mid-air: removeJoint3D did not wake its bodies (2D joints did).
    // The drop after n steps of free fall from rest, nothing touching it: the integrator's exact
    // g t^2 / 2 (t = n h), checked to 1e-9 m (rounding).
    for (const how of ['removeJoint3D', 'removeBody holder'] as const) {
      const { world, holder, bob, joint } = sleepingBob(how === 'removeBody holder');
      const c = world.components,
        e = slotOf(bob),
        y0 = c.Position.y[e]!;
      if (how === 'removeJoint3D') removeJoint3D(world, joint);
      else removeBody(world, holder!);
      expect(isSleeping(world, bob)).toBe(false);
      const n = 30;
      for (let i = 0; i < n; i++) step(world);
      const t = n * world.dt;
      expect(Math.abs(y0 - c.Position.y[e]! - 0.5 * G * t * t)).toBeLessThan(1e-9);
    }
  });
});
