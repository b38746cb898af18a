import {
  addBody,
  addBox,
  ballsInBox,
  createPhysicsWorld,
  isSleeping,
  removeBody,
  setBoundary,
  setGravity,
  setVelocity,
  slotOf,
  step,
  stepMany,
} from '@bitphysics/physics';
import { query } from 'bitecs';
import { describe, expect, test } from 'vitest';
import { maxPairOverlap } from './helpers';

const asleep = (world: ReturnType<typeof createPhysicsWorld>) => query(world, [world.components.Sleeping]).length;

describe('sleeping islands', () => {
  test('a settled pile falls asleep: no contacts are solved and nothing moves', () => {
    const world = createPhysicsWorld(ballsInBox.worldOptions({ count: 300 }));
    const { balls } = ballsInBox.build(world, { count: 300 });
    stepMany(world, 900);
    expect(asleep(world)).toBe(300);
    const P = world.components.Position;
    const before = Array.from(balls, (e) => [P.x[e], P.y[e]]);
    stepMany(world, 60);
    expect(Array.from(balls, (e) => [P.x[e], P.y[e]])).toEqual(before);
    expect(world.collision.stats.contacts).toBe(0);
  });

  test('a ball dropped on a sleeping pile wakes it, and the pile settles again without overlaps', () => {
    const world = createPhysicsWorld(ballsInBox.worldOptions({ count: 300 }));
    const { balls, layout } = ballsInBox.build(world, { count: 300 });
    stepMany(world, 900);
    expect(asleep(world)).toBe(300);
    const drop = addBody(world, {
      position: [layout.max[0] / 2, layout.max[1] - 1],
      velocity: [0, -15],
      radius: 0.5,
      restitution: 0.5,
      friction: 0.1,
    });
    let minAsleep = 301;
    for (let i = 0; i < 120; i++) {
      step(world);
      minAsleep = Math.min(minAsleep, asleep(world));
    }
    expect(minAsleep).toBeLessThan(300);
    stepMany(world, 900);
    expect(maxPairOverlap(world, [...balls, drop])).toBeLessThan(0.025);
    expect(world.components.Position.y[drop]!).toBeGreaterThan(0.5 - 0.025);
  });

  test('a slow body in free flight never sleeps: it drifts exactly x = x0 + v t', () => {
    // Sleep needs support; a free body below the sleep speed (0.01 < 0.05 m/s) must keep moving.
    const world = createPhysicsWorld({ gravity: [0, 0] });
    setBoundary(world, { min: [-50, -50], max: [50, 50] });
    const a = addBody(world, { position: [0, 0], velocity: [0.01, 0], radius: 0.5 });
    stepMany(world, 600);
    expect(isSleeping(world, a)).toBe(false);
    // Exact to rounding: no force acts, so every scheme translates uniformly.
    expect(world.components.Position.x[a]!).toBeCloseTo(0.01 * world.time, 12);
  });

  test('writing a velocity wakes a sleeping body; setVelocity does too', () => {
    const world = createPhysicsWorld({ gravity: [0, -10] });
    setBoundary(world, { min: [-5, 0], max: [5, 10] });
    const a = addBody(world, { position: [-2, 0.5], radius: 0.5 });
    const b = addBody(world, { position: [2, 0.5], radius: 0.5 });
    stepMany(world, 120);
    expect(isSleeping(world, a) && isSleeping(world, b)).toBe(true);
    world.components.Velocity.x[a] = 3;
    setVelocity(world, b, [0, 5]);
    step(world);
    expect(isSleeping(world, a)).toBe(false);
    expect(isSleeping(world, b)).toBe(false);
    expect(world.components.Position.x[a]!).toBeGreaterThan(-2);
    expect(world.components.Position.y[b]!).toBeGreaterThan(0.5);
  });

  test('removing the ball underneath wakes the one resting on it, which falls', () => {
    const world = createPhysicsWorld({ gravity: [0, -10] });
    setBoundary(world, { min: [-5, 0], max: [5, 10] });
    const under = addBody(world, { position: [0, 0.5], radius: 0.5 });
    const top = addBody(world, { position: [0, 1.5], radius: 0.5, rotates: false });
    stepMany(world, 180);
    expect(isSleeping(world, top)).toBe(true);
    removeBody(world, under);
    stepMany(world, 60);
    expect(world.components.Position.y[top]!).toBeLessThan(0.6);
  });

  test('removing an awake box that leaned on a sleeping box wakes it, which stays where it was', () => {
    const world = createPhysicsWorld({ gravity: [0, -10] });
    addBox(world, { position: [0, -0.5], halfExtents: [50, 0.5], static: true });
    const b = addBox(world, { position: [0, 0.5], halfExtents: [0.5, 0.5] });
    stepMany(world, 120);
    expect(isSleeping(world, b)).toBe(true);
    // A box against its side that counts as resting (rest time > 0) meets the sleeper as geometry and
    // leaves it asleep; the rest time is set here, as a box that settled there would have it.
    const a = addBox(world, { position: [1, 0.5], halfExtents: [0.5, 0.5] });
    world.collision.sleep.restTime[slotOf(a)] = 0.1;
    step(world);
    expect(isSleeping(world, b) && !isSleeping(world, a)).toBe(true);
    const P = world.components.Position,
      s = slotOf(b),
      y = P.y[s];
    removeBody(world, a);
    expect(isSleeping(world, b)).toBe(false);
    // Woken between steps: no velocity or position is written (exactly).
    expect([world.components.Velocity.x[s], world.components.Velocity.y[s], P.y[s]]).toEqual([0, 0, y]);
  });

  test('changing gravity wakes everything', () => {
    const world = createPhysicsWorld({ gravity: [0, -10] });
    setBoundary(world, { min: [-5, 0], max: [5, 10] });
    const b = addBody(world, { position: [0, 0.5], radius: 0.5 });
    stepMany(world, 120);
    expect(isSleeping(world, b)).toBe(true);
    setGravity(world, [5, -10]);
    stepMany(world, 30);
    expect(world.components.Position.x[b]!).toBeGreaterThan(0.05);
  });

  test('sleep: false keeps every body awake', () => {
    const world = createPhysicsWorld({ ...ballsInBox.worldOptions({ count: 50 }), sleep: false });
    ballsInBox.build(world, { count: 50 });
    stepMany(world, 900);
    expect(asleep(world)).toBe(0);
  });
});
