// The gold ball stays one that can score (hoop.ts underHoop, goldChoices): a ball that comes to rest
// under the hoop, by the wall behind its backboard, has no clean basket (reach.ts findBasket), so it
// is never made the gold one, even when it is the only ball with nothing on top of it.
import { createPhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import {
  addHoop,
  FRONT_RIM_LENGTH,
  goldChoices,
  HOOP_HALF_WIDTH,
  HOOP_RADIUS,
  hoopSpots,
  underHoop,
} from '../../games/bouncing-balls/hoop';
import { findBasket } from '../../games/bouncing-balls/reach';
import { bouncingBallsWorldOptions, buildBouncingBalls, layoutOf, removeBall, spawnBall } from '../../games/bouncing-balls/scene';

describe('bouncing-balls gold ball', () => {
  it('no clean basket from under any hoop of either layout (where underHoop says a ball is)', () => {
    for (const tall of [false, true]) {
      const wall = layoutOf(tall).box;
      for (const spot of hoopSpots(tall)) {
        // From just past the front rim's outer end to 0.5 m from the wall behind the board, at heap heights.
        const near = spot.x - spot.side * (HOOP_HALF_WIDTH + HOOP_RADIUS + FRONT_RIM_LENGTH - 0.1);
        const far = spot.side > 0 ? wall.max[0] - 0.5 : wall.min[0] + 0.5;
        for (const t of [0, 0.5, 1])
          for (const y of [0.5, 1.5, 2.5]) {
            const x = near + t * (far - near);
            expect(underHoop(spot, x, y), `${tall ? 'tall' : 'wide'} (${x}, ${y})`).toBe(true);
            expect(findBasket(spot, tall, x, y), `${tall ? 'tall' : 'wide'} spot ${spot.x},${spot.y} from (${x}, ${y})`).toBeNull();
          }
      }
    }
  });

  it('a ball that drops behind the backboard rests under the hoop, and the gold goes to a ball the player can score with', () => {
    const options = { count: 1, tall: false };
    const world = createPhysicsWorld(bouncingBallsWorldOptions(options));
    const h = buildBouncingBalls(world, options);
    for (const e of [...h.balls]) removeBall(world, h, e);
    const spot = hoopSpots(false)[0]!;
    addHoop(world, spot, 0.8, 0.3);
    // Between the backboard (x 14.08 m) and the right wall (16 m), and two balls stacked at x 5 m.
    const behind = spawnBall(world, h, 15, 0.5, 0, 0, 0.4);
    const low = spawnBall(world, h, 5, 0.4, 0, 0, 0.4);
    const high = spawnBall(world, h, 5, 1.2, 0, 0, 0.4);
    for (let i = 0; i < 120; i++) step(world);
    const P = world.components.Position,
      V = world.components.Velocity;
    const at = [behind, low, high].map((e) => [P.x[slotOf(e)]!, P.y[slotOf(e)]!, 0.4] as const);
    // At rest under the hoop (under 2 cm/s after 2 s), on the floor behind the board.
    expect(Math.hypot(V.x[slotOf(behind)]!, V.y[slotOf(behind)]!)).toBeLessThan(0.02);
    expect(underHoop(spot, at[0]![0], at[0]![1])).toBe(true);
    expect(underHoop(spot, at[2]![0], at[2]![1])).toBe(false);
    // The free ones are `behind` and `high` (nothing on top); of them only `high` can score.
    expect(goldChoices(spot, at)).toEqual([2]);
    // Only balls under the hoop: they are all there is.
    expect(goldChoices(spot, [at[0]!])).toEqual([0]);
    // Stacked balls: the top one free.
    expect(goldChoices(spot, [at[0]!, at[1]!, [5.1, 1.2, 0.4], [4.9, 2, 0.4]])).toEqual([3]);
    // The only free ball is under the hoop (x 11.8 m, past the front rim's end at 11.67 m), on one
    // that is not: that one, though a ball lies on it.
    expect(
      goldChoices(spot, [
        [11.3, 0.4, 0.4],
        [11.8, 1.2, 0.4],
      ]),
    ).toEqual([0]);
  });
});
