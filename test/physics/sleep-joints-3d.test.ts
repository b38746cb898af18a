import { addBallJoint3D, addBody, addPlane, addShape3D, createPhysicsWorld, isSleeping, slotOf, step } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/**
 * 3D joints in the sleeping islands: bodies joined by a 3D joint sleep and wake together, as 2D joints
 * do (Box2D v3's islands). A 1 m box rests on the floor; a 0.1 m box hangs from its side on a ball joint
 * (anchor 0.3 m out from the box's side) and swings. Without the join the resting box fell asleep after
 * its 0.5 s of rest (step 31 at 60 Hz) and then held the swinging bob like a fixed anchor: the bob swung
 * on forever, its island asleep. The undamped bob never stops, so the base must stay awake while the
 * bob moves faster than the sleep threshold (0.1 m/s).
 */
describe('3D joints and sleeping islands', () => {
  const build = () => {
    const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -9.81, 0] });
    addPlane(world, { normal: [0, 1, 0], point: [0, 0, 0] });
    const base = addBody(world, { position: [0, 0.5, 0] });
    addShape3D(world, base, { type: 'box', halfExtents: [0.5, 0.5, 0.5], density: 1000 });
    const bob = addBody(world, { position: [0.8, 0.2, 0] });
    addShape3D(world, bob, { type: 'box', halfExtents: [0.05, 0.05, 0.05], density: 1000 });
    addBallJoint3D(world, { a: base, b: bob, anchor: [0.8, 0.9, 0] });
    return { world, base: slotOf(base), bob: slotOf(bob), bobHandle: bob };
  };

  test('a box with a swinging bob jointed to it stays awake while the bob moves', () => {
    const { world, base, bob } = build();
    const V = world.components.Velocity;
    world.components.Velocity.z[bob] = 1; // swings across the box's side, touching nothing
    let fastAndBaseAsleep = 0,
      fastSteps = 0;
    for (let i = 0; i < 240; i++) {
      step(world);
      const speed = Math.hypot(V.x[bob]!, V.y[bob]!, V.z[bob]!);
      if (speed > 0.1) {
        fastSteps++;
        if (isSleeping(world, base)) fastAndBaseAsleep++;
      }
    }
    expect(fastSteps).toBeGreaterThan(100);
    expect(fastAndBaseAsleep).toBe(0);
    expect(isSleeping(world, bob)).toBe(false);
  });

  test('a resting box and its hanging bob sleep together and a push on the bob wakes both', () => {
    const { world, base, bob } = build();
    let both = -1;
    for (let i = 0; i < 600 && both < 0; i++) {
      step(world);
      const a = isSleeping(world, base),
        b = isSleeping(world, bob);
      // One island: neither sleeps without the other.
      expect(a).toBe(b);
      if (a && b) both = i;
    }
    expect(both).toBeGreaterThan(0);
    world.components.Velocity.z[bob] = 1; // a velocity written into a sleeper wakes its island
    step(world);
    expect(isSleeping(world, bob)).toBe(false);
    expect(isSleeping(world, base)).toBe(false);
  });
});
