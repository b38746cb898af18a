import { addBody, addPlane, addShape3D, createPhysicsWorld, isSleeping, slotOf, step } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

// The collide stage keeps a sleeping collider's pose from its last pass (collision/colliders-3d.ts
// keptPose): these check it is posed again whenever that pose would be stale.
describe('sleeping 3D colliders keep their pose only while it holds', () => {
  test('a sleeping box moved by writing its pose (without waking it) is collided where it now is', () => {
    const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -10, 0] });
    addPlane(world, { normal: [0, 1, 0] });
    const sleeper = addBody(world, { position: [0, 0.5, 0] });
    addShape3D(world, sleeper, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
    for (let s = 0; s < 240 && !isSleeping(world, sleeper); s++) step(world);
    expect(isSleeping(world, sleeper)).toBe(true);
    // A box to fall where the sleeper will be; a step posed the sleeper where it rests now.
    const drop = addBody(world, { position: [5, 2, 0] });
    addShape3D(world, drop, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
    step(world);
    expect(isSleeping(world, sleeper)).toBe(true);
    const c = world.components,
      e = slotOf(sleeper);
    for (const P of [c.Position, c.PreviousPosition]) P.x[e] = 5;
    for (let s = 0; s < 120; s++) step(world);
    // The dropped box rests on the moved one (centre 1.5 m up), not on the floor through it (0.5 m).
    expect(c.Position.y[slotOf(drop)]!).toBeGreaterThan(1.45);
    expect(c.Position.y[slotOf(drop)]!).toBeLessThan(1.55);
    expect(Math.abs(c.Position.x[e]! - 5)).toBeLessThan(0.05);
  });

  test('a world does not keep the pose another world gave the same collider slot (same body pose, other box)', () => {
    // Two worlds alike but for the sleeper's size, each with a box falling from high up: the sleepers are
    // collider 0 of their worlds, asleep at exactly the same pose.
    const make = (half: [number, number, number], dropX: number, dropY: number) => {
      const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -10, 0] });
      addPlane(world, { normal: [0, 1, 0] });
      const sleeper = addBody(world, { position: [0, 0.5, 0] });
      addShape3D(world, sleeper, { type: 'box', halfExtents: half });
      const drop = addBody(world, { position: [dropX, dropY, 0] });
      addShape3D(world, drop, { type: 'box', halfExtents: [0.25, 0.25, 0.25] });
      return { world, sleeper, drop };
    };
    const narrow = make([0.5, 0.5, 0.5], 20, 60),
      wide = make([1.5, 0.5, 1.5], 1.2, 30);
    const both = [narrow, wide];
    for (let s = 0; s < 60; s++) for (const { world } of both) step(world);
    for (const { world, sleeper } of both) {
      expect(isSleeping(world, sleeper)).toBe(true);
      const c = world.components,
        e = slotOf(sleeper);
      for (const P of [c.Position, c.PreviousPosition]) {
        P.x[e] = 0;
        P.y[e] = 0.5;
        P.z[e] = 0;
      }
      c.Orientation.x[e] = 0;
      c.Orientation.y[e] = 0;
      c.Orientation.z[e] = 0;
      c.Orientation.w[e] = 1;
    }
    // The worlds step in turn while the wide one's box falls onto its sleeper, 1.2 m off centre: within
    // the wide box (1.5 m), beyond the narrow one's (0.5 m).
    for (let s = 0; s < 180; s++) for (const { world } of both) step(world);
    const y = wide.world.components.Position.y[slotOf(wide.drop)]!;
    expect(y).toBeGreaterThan(1.2);
    expect(y).toBeLessThan(1.3);
  });
});
