/**
 * The warm-up `createPhysicsWorld({ warmUp: true })` runs (packages/physics/src/warm-up.ts): its
 * scene exercises what it claims to (polygon or box manifolds, ball rows, joints: if its layout broke,
 * the JavaScript engine would compile less before a user's first steps), it leaves no trace in a world
 * made after it (the same state to the bit, with or without it), and its option is checked like the
 * others. Whether it speeds the first steps is measured in the bench, not here.
 */
import { ContactKind, createPhysicsWorld, forEachContact, type PhysicsWorld, SCENES, stateHash, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import { WARM_UP_STEPS, warmUp, warmUpScene } from '../../packages/physics/src/warm-up.js';

/** A scene of `name` and `count` built in a world made without the warm-up, stepped `steps` times; its state hash. */
function hashAfter(name: string, count: number, steps: number): string {
  const scene = SCENES[name]!;
  const world = createPhysicsWorld({ ...scene.worldOptions({ count }), warmUp: false });
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

describe('warm-up', () => {
  it.each([2, 3] as const)('the %iD scene has ball and shape contacts through its steps, and stays finite', (d) => {
    const world = warmUpScene(d, createPhysicsWorld);
    let fewestBalls = Infinity,
      fewestShapes = Infinity;
    for (let i = 0; i < WARM_UP_STEPS; i++) {
      step(world);
      const a = activity(world);
      fewestBalls = Math.min(fewestBalls, a.balls);
      fewestShapes = Math.min(fewestShapes, a.shapes);
    }
    // Every step had balls touching balls and shapes touching shapes (the stages the scene is there to run).
    expect(fewestBalls).toBeGreaterThan(5);
    expect(fewestShapes).toBeGreaterThan(5);
    const P = world.components.Position;
    for (let e = 1; e < world.capacity + 1; e++) expect(Number.isFinite(P.y[e]!)).toBe(true);
  });

  it('leaves no trace: scenes made before and after it step to the same state', () => {
    const before = [hashAfter('pyramid', 8, 60), hashAfter('balls-in-box', 300, 60), hashAfter('box-pile-3d', 60, 60)];
    warmUp(2, createPhysicsWorld);
    warmUp(3, createPhysicsWorld);
    expect([hashAfter('pyramid', 8, 60), hashAfter('balls-in-box', 300, 60), hashAfter('box-pile-3d', 60, 60)]).toEqual(before);
  });

  it('its option must be a boolean, named in the error', () => {
    expect(() => createPhysicsWorld({ warmUp: 1 as unknown as boolean })).toThrow(/createPhysicsWorld.*warmUp.*1/);
    expect(() => createPhysicsWorld({ warmUp: false })).not.toThrow();
    expect(createPhysicsWorld({ dimensions: 3, warmUp: true }).dimensions).toBe(3);
  });
});
