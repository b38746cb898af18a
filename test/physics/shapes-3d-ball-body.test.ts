import { addBody, addShape3D, createPhysicsWorld, setRadius, shapes3DOfBody, slotOf, stateHash, step } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

describe('3D ball bodies and shapes do not mix', () => {
  test('addShape3D on a body made with a radius throws naming the function, parameter and radius, and changes nothing', () => {
    // A ball body is a sphere of the ball narrowphase with addBody's mass; a box shape on it used to
    // replace that mass with the box's (1,000 kg for a 1 m cube, whatever mass was given) while the
    // ball kept colliding and its scalar inertia (0.4 m r^2 of the old mass) went stale.
    const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -9.81, 0] });
    const ball = addBody(world, { position: [0, 2, 0], radius: 0.5, mass: 3 });
    step(world);
    const before = stateHash(world);
    expect(() => addShape3D(world, ball, { type: 'box', halfExtents: [0.5, 0.5, 0.5], density: 1000 })).toThrow(
      /^addShape3D: body must be a body without a ball radius .*got body \d+ with radius 0\.5$/,
    );
    expect(stateHash(world)).toBe(before);
    expect(shapes3DOfBody(world, ball)).toEqual([]);
    expect(world.components.Mass.value[slotOf(ball)]).toBe(3);
    // A body without a radius takes the sphere as a shape: the mass is the sphere's, rho 4/3 pi r^3.
    const sphere = addBody(world, { position: [3, 2, 0] });
    addShape3D(world, sphere, { type: 'sphere', radius: 0.5, density: 1000 });
    expect(world.components.Mass.value[slotOf(sphere)]).toBeCloseTo((1000 * 4 * Math.PI * 0.125) / 3, 9);
  });

  test('setRadius on a body with 3D shapes throws and changes nothing', () => {
    const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -9.81, 0] });
    const box = addBody(world, { position: [0, 2, 0] });
    addShape3D(world, box, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
    const before = stateHash(world);
    expect(() => setRadius(world, box, 0.5)).toThrow(/^setRadius: eid must be a body without 3D shapes .*got body \d+$/);
    expect(stateHash(world)).toBe(before);
    expect(world.components.Mass.value[slotOf(box)]).toBe(1000);
  });
});
