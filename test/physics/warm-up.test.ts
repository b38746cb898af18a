/**
 * `warmUp(dimensions)` (packages/physics/src/warm-up.ts): its scene exercises what it claims to (ball
 * and shape contacts in every step: if its layout broke, the JavaScript engine would compile less before
 * a user's first steps), it leaves no trace in a world made after it (the same state to the bit, with
 * or without it), it runs once a dimension (its ball pile too), and its arguments are checked. Whether it speeds the first
 * steps is measured in the bench (`--warm-up`), not here.
 */
import {
  ContactKind,
  createPhysicsWorld,
  forEachContact,
  type PhysicsWorld,
  query,
  SCENES,
  stateHash,
  step,
  WARM_UP_PILE_BALLS,
  WARM_UP_STEPS,
  warmUp,
} from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import { DENSE_MIN_BODIES } from '../../packages/physics/src/collision/broadphase/grid.js';
import { ballPile, warmUpScene } from '../../packages/physics/src/warm-up.js';

/** A scene of `name` and `count` built in a fresh world, stepped `steps` times; its state hash. */
function hashAfter(name: string, count: number, steps: number): string {
  const scene = SCENES[name]!;
  const world = createPhysicsWorld(scene.worldOptions({ count }));
  scene.build(world, { count });
  for (let i = 0; i < steps; i++) step(world);
  return stateHash(world);
}

/** Contact points of a world after its last step: between two balls, and of shapes' manifolds. */
function activity(world: PhysicsWorld): { balls: number; shapes: number } {
  const a = { balls: 0, shapes: 0 };
  forEachContact(world, (c) => {
    if (c.kind === ContactKind.Ball) a.balls++;
    else if (c.kind === ContactKind.Shape) a.shapes++;
  });
  return a;
}

describe('warmUp', () => {
  it.each([2, 3] as const)('the %iD scene has ball and shape contacts through its steps, and stays finite', (d) => {
    const world = warmUpScene(d);
    let fewestBalls = Infinity,
      fewestShapes = Infinity,
      breaks = 0,
      rows = 0;
    for (let i = 0; i < WARM_UP_STEPS; i++) {
      step(world);
      const a = activity(world);
      fewestBalls = Math.min(fewestBalls, a.balls);
      fewestShapes = Math.min(fewestShapes, a.shapes);
      breaks += world.joints.breaks.count;
      rows = Math.max(rows, world.joints.stats.rows);
    }
    // Every step had balls touching balls and shapes touching shapes (the stages the scene is there to run).
    expect(fewestBalls).toBeGreaterThan(5);
    expect(fewestShapes).toBeGreaterThan(100 / d);
    // 2D: the joint grid's 180 rows and the chain's and welds' were solved, and the falling weight broke a weld.
    if (d === 2) {
      expect(rows).toBeGreaterThanOrEqual(187);
      expect(breaks).toBeGreaterThan(0);
    }
    const P = world.components.Position;
    for (let e = 1; e < world.capacity + 1; e++) expect(Number.isFinite(P.y[e]!)).toBe(true);
  });

  it('leaves no trace: scenes made before and after its scene step to the same state', () => {
    const scenes = (): string[] => [hashAfter('pyramid', 8, 60), hashAfter('balls-in-box', 300, 60), hashAfter('box-pile-3d', 60, 60)];
    const before = scenes();
    for (const d of [2, 3] as const) {
      const world = warmUpScene(d);
      for (let i = 0; i < WARM_UP_STEPS; i++) step(world);
    }
    expect(scenes()).toEqual(before);
  });

  it('runs once a dimension; its argument must be 2 or 3, named in the error', () => {
    expect(() => warmUp(4 as 2)).toThrow(/^warmUp: dimensions must be 2 or 3, got 4$/);
    const first = warmUp(3);
    expect(warmUp(3)).toBe(false);
    expect(typeof first).toBe('boolean');
  });

  it.each([2, 3] as const)('the %iD ball pile is over the dense grid threshold, and it settles onto itself', (d) => {
    const world = ballPile(d);
    expect(WARM_UP_PILE_BALLS).toBeGreaterThanOrEqual(DENSE_MIN_BODIES);
    expect(query(world, [world.components.Ball]).length).toBe(WARM_UP_PILE_BALLS);
    step(world);
    // Dense: the grid's table is laid out over the pile's cells (spanX > 0), not hashed (spanX = 0).
    expect(world.collision.grid.spanX).toBeGreaterThan(0);
    for (let i = 0; i < 5; i++) step(world);
    // Touching from the start (rows 0.32 m apart, radius 0.15, half a ball shifted): the stages the
    // pile is there to compile all ran.
    expect(activity(world).balls).toBeGreaterThan(WARM_UP_PILE_BALLS);
  });

  it('runs the ball pile once a dimension, also after a plain warm-up; options are checked', () => {
    expect(() => warmUp(2, { ball: true } as never)).toThrow(/^warmUp: unknown option "ball"; known options are balls$/);
    expect(() => warmUp(2, { balls: 1 } as never)).toThrow(/^warmUp: balls must be a boolean, got 1$/);
    expect(() => warmUp(2, null as never)).toThrow(/^warmUp: options must be an object, got null$/);
    warmUp(3);
    expect(warmUp(3, { balls: true })).toBe(true);
    expect(warmUp(3, { balls: true })).toBe(false);
    expect(warmUp(3)).toBe(false);
  });
});
