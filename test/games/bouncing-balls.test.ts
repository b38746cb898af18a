// The bouncing-balls scene's two layouts: the wide 16 x 10 m box and the tall 10 x 16 m one a phone
// held upright gets. Both hold the same balls with the same room (160 m^2), and neither lets a ball out.
import { createPhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import { bouncingBallsWorldOptions, buildBouncingBalls, layoutOf, meanRadiusFor } from '../../games/bouncing-balls/scene';

describe('bouncing-balls layouts', () => {
  for (const tall of [false, true]) {
    it(`${tall ? 'tall' : 'wide'}: 40 balls start inside the box, clear of the walls, and stay inside for 4 s`, () => {
      const options = { count: 40, tall };
      const world = createPhysicsWorld(bouncingBallsWorldOptions(options));
      const h = buildBouncingBalls(world, options);
      const { box } = layoutOf(tall);
      expect(world.collision.boundary.max[0]).toBe(box.max[0]);
      expect(world.collision.boundary.max[1]).toBe(box.max[1]);
      expect(h.balls.length).toBe(40);
      expect(h.meanRadius).toBe(meanRadiusFor(40));
      const P = world.components.Position,
        R = world.components.Ball;
      // A ball may sink into a wall by the solver's slop, a few mm; 1 cm is a ball outside.
      const inside = () =>
        h.balls.every((e) => {
          const s = slotOf(e),
            r = R.radius[s]!;
          return (
            P.x[s]! - r > box.min[0] - 0.01 &&
            P.x[s]! + r < box.max[0] + 0.01 &&
            P.y[s]! - r > box.min[1] - 0.01 &&
            P.y[s]! + r < box.max[1] + 0.01
          );
        });
      expect(inside()).toBe(true);
      for (let i = 0; i < 240; i++) step(world);
      expect(inside()).toBe(true);
    });
  }

  it('rejects a tall that is not a boolean, naming it', () => {
    expect(() => buildBouncingBalls(createPhysicsWorld(bouncingBallsWorldOptions()), { tall: 'yes' as unknown as boolean })).toThrow(
      /tall/,
    );
  });
});
