// Which collisions bouncing balls plays a knock for (games/bouncing-balls/knocks.ts): the limiter
// against hand-worked cases, and a throw into the settled pile of the scene, whose impacts (a sound
// each before: 257 in 2.5 s in a playtest) come down to a few knocks a second.
import { forEachImpact } from '@bitphysics/game-kit';
import { createPhysicsWorld, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import { createKnockLimiter, KNOCK_LIMITS } from '../../games/bouncing-balls/knocks';
import { bouncingBallsWorldOptions, buildBouncingBalls, spawnBall } from '../../games/bouncing-balls/scene';

const limits = { minImpulse: 1, perStep: 2, cooldown: 0.1, perSecond: 10, burst: 3 };

describe('knock limiter', () => {
  it('keeps the loudest of a step above the minimum, silences a body for its cooldown, and spends a budget that refills', () => {
    const k = createKnockLimiter(limits);
    k.offer(1, 2, 0.9); // too quiet
    k.offer(3, 0, 5);
    k.offer(4, -1, 2);
    k.offer(5, 6, 3);
    // The two loudest: 5 N s and 3 N s.
    expect(k.take(0).map((x) => x.impulse)).toEqual([5, 3]);
    // Body 3 is in its cooldown 0.05 s later; body 4 is not (it was not heard); the budget has 1 left (3 - 2 + 0.5).
    k.offer(3, 7, 9);
    k.offer(4, 0, 2);
    k.offer(8, 0, 2);
    expect(k.take(0.05).map((x) => x.a)).toEqual([4]);
    // Budget spent (0.5 left): nothing until it refills to 1 (0.05 s later).
    k.offer(9, 0, 4);
    expect(k.take(0.06)).toEqual([]);
    k.offer(9, 0, 4);
    expect(k.take(0.11).map((x) => x.a)).toEqual([9]);
    // The walls (handle 0) are never silenced: two knocks on the wall in one step.
    k.offer(10, 0, 4);
    k.offer(11, 0, 4);
    expect(k.take(1).length).toBe(2);
  });
  it('starts afresh when time goes back (a new world), and rejects bad limits naming them', () => {
    const k = createKnockLimiter(limits);
    for (let i = 0; i < 3; i++) k.offer(1 + i, 0, 5);
    k.take(5);
    k.offer(1, 0, 5);
    expect(k.take(0).length).toBe(1);
    expect(() => createKnockLimiter({ ...limits, perStep: 0 })).toThrow(/perStep/);
    expect(() => createKnockLimiter({ ...limits, minImpulse: 0 })).toThrow(/minImpulse/);
    expect(() => k.take(Number.NaN)).toThrow(/time/);
  });
  it('a throw into the falling pile of 40 balls: over 40 impacts; the game plays at most 10 knocks a second and 4 at once', () => {
    const options = { count: 40, seed: 1 };
    const world = createPhysicsWorld(bouncingBallsWorldOptions(options));
    const h = buildBouncingBalls(world, options);
    for (let i = 0; i < 45; i++) step(world);
    const knocks = createKnockLimiter(KNOCK_LIMITS);
    // Thrown hard into the pile from the left, as a playtester did.
    spawnBall(world, h, 2, 4, 12, -6, 0.4);
    let before = 0,
      after = 0;
    const perSecond: number[] = [0, 0];
    for (let i = 0; i < 90; i++) {
      step(world);
      // Before: a knock for every impact over the old 0.5 N s threshold.
      forEachImpact(world, (a, b, impulse) => {
        if (impulse > 0.5) before++;
        knocks.offer(a, b, impulse);
      });
      const n = knocks.take(world.time).length;
      // Measured: 281 impacts and 28 knocks over 2.5 s after 2 s of settling.
      after += n;
      perSecond[Math.floor(i / 60)]! += n;
    }
    expect(before).toBeGreaterThan(40);
    // 1.5 s at 10 a second with a burst of 4 to start: at most 19.
    expect(after).toBeLessThanOrEqual(19);
    expect(after).toBeGreaterThan(0);
    for (const n of perSecond) expect(n).toBeLessThanOrEqual(14);
  });
});
