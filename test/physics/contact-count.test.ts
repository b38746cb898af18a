import { addBody, addBox, contactCount, createPhysicsWorld, step } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

// contactCount(world) is "the number of contacts the solver handled in the last step". A 2D world of
// shapes alone reported 0 whatever touched (only the balls' narrowphase wrote the count), so the bench
// printed "contacts 0" for a pyramid of 820 resting boxes. The counts below are the contact points of
// the geometry: a box resting flat on a box touches along an edge clipped to 2 points; a ball touches
// at 1.
describe('contactCount in 2D', () => {
  test('boxes resting on a static box count 2 points each, every step, not a running sum', () => {
    const world = createPhysicsWorld({ dimensions: 2, gravity: [0, -10] });
    addBox(world, { position: [0, -0.5], halfExtents: [20, 0.5], static: true });
    for (let i = 0; i < 5; i++) addBox(world, { position: [-8 + 4 * i, 0.5], halfExtents: [0.5, 0.5] });
    step(world);
    expect(contactCount(world)).toBe(10);
    step(world);
    expect(contactCount(world)).toBe(10);
  });

  test('balls on a static box count one point each, with the ball-ball contacts', () => {
    const world = createPhysicsWorld({ dimensions: 2, gravity: [0, -10] });
    addBox(world, { position: [0, -0.5], halfExtents: [20, 0.5], static: true });
    // Three balls on the floor, 2 m apart, and one resting on nothing but the middle one (touching it).
    for (let i = 0; i < 3; i++) addBody(world, { position: [-2 + 2 * i, 0.5], radius: 0.5 });
    step(world);
    expect(contactCount(world)).toBe(3);
    addBody(world, { position: [0, 1.5], radius: 0.5 });
    step(world);
    expect(contactCount(world)).toBe(4);
  });

  test('nothing touching counts 0', () => {
    const world = createPhysicsWorld({ dimensions: 2, gravity: [0, -10] });
    addBox(world, { position: [0, -0.5], halfExtents: [20, 0.5], static: true });
    addBox(world, { position: [0, 5], halfExtents: [0.5, 0.5] });
    step(world);
    expect(contactCount(world)).toBe(0);
  });
});
