// What a thrown ball touched, by kind (touches.ts), from the physics world's contact events: the
// backboard and rim are the hoop's (a bank shot is a plain basket, not a trick shot), a hard lob
// into the box's top is the ceiling however far the ball has bounced back by the step's end, and
// the sides, the floor and the ramps are what they are.
import { createPhysicsWorld, type PhysicsWorld, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import { addHoop, hoopSpots } from '../../games/bouncing-balls/hoop';
import { bouncingBallsWorldOptions, buildBouncingBalls, removeBall, spawnBall } from '../../games/bouncing-balls/scene';
import { forEachTouch, type TouchKind } from '../../games/bouncing-balls/touches';

/** An empty wide box with the first hoop (13, 6), its backboard on the right at x 14.08 m. */
function court(): {
  world: PhysicsWorld;
  ramps: number[];
  hoop: number[];
  spawn: (x: number, y: number, vx: number, vy: number) => number;
} {
  const options = { count: 1, tall: false };
  const world = createPhysicsWorld(bouncingBallsWorldOptions(options));
  const h = buildBouncingBalls(world, options);
  for (const e of [...h.balls]) removeBall(world, h, e);
  const hoop = addHoop(world, hoopSpots(false)[0]!, 0.8, 0.3);
  return { world, ramps: h.segments, hoop, spawn: (x, y, vx, vy) => spawnBall(world, h, x, y, vx, vy, 0.4) };
}

/** The kinds ball `e` touches in `steps` steps, in order. */
function touches(c: ReturnType<typeof court>, e: number, steps: number): TouchKind[] {
  const out: TouchKind[] = [];
  for (let i = 0; i < steps; i++) {
    step(c.world);
    forEachTouch(c.world, c.ramps, c.hoop, (b, _other, kind) => {
      if (b === e) out.push(kind);
    });
  }
  return out;
}

describe('bouncing-balls touches', () => {
  it('a ball thrown into the backboard touches the hoop first, not a wall (a bank shot is no trick shot)', () => {
    const c = court();
    // From (12.6, 7) m straight right at 4 m/s: it meets the board's face (x 14 m less its 0.4 m) in about 0.15 s.
    const e = c.spawn(12.6, 7, 4, 0);
    const kinds = touches(c, e, 30);
    expect(kinds[0]).toBe('hoop');
  });

  it('a ball dropped onto the front rim touches the hoop', () => {
    const c = court();
    // The front rim runs from x 11.92 to 11.67 m at y 6 m: a ball over it falls onto it.
    const e = c.spawn(11.8, 7, 0, 0);
    expect(touches(c, e, 40)[0]).toBe('hoop');
  });

  // From (4, 2) m, clear of the ramps (x 0 to 1.6 m and 6.6 to 8.6 m), up to the box's top (10 m):
  // met at about 7, 11 and 13 m/s. The hardest one's step ends 0.14 m back down from it (the rule
  // that looked for the ball's top within 0.1 m of the top after the step called that a wall).
  for (const vy of [14, 16, 18]) {
    it(`a lob at ${vy} m/s into the box's top touches the ceiling (not a wall), however hard`, () => {
      const c = court();
      const e = c.spawn(4, 2, 0, vy);
      expect(touches(c, e, 60)[0]).toBe('ceiling');
    });
  }

  it('a side of the box, the floor and a ramp are what they are', () => {
    const c = court();
    const side = c.spawn(1.5, 3, -6, 0);
    expect(touches(c, side, 20)[0]).toBe('wall');
    const floor = c.spawn(4, 1, 0, -3);
    expect(touches(c, floor, 20)[0]).toBe('wall');
    // Under the floating ramp from (6.6, 8.4) to (8.6, 8.8) m, thrown up into it.
    const ramp = c.spawn(7.6, 6.5, 0, 6);
    expect(touches(c, ramp, 30)[0]).toBe('ramp');
  });
});
