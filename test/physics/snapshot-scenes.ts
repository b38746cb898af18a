import {
  addBody,
  addBox,
  addDistanceJoint,
  addEmitter,
  addRevoluteJoint,
  addSegment,
  addSpring,
  createCloth,
  createPhysicsWorld,
  type PhysicsWorld,
  SCENES,
  setBoundary,
} from '@bitphysics/physics';

/**
 * Scenes for the snapshot and determinism tests (also bundled into a child process by the determinism
 * test, so this file imports only the package).
 */

/** A 2D world with every kind of state: balls, boxes (shapes), springs, joints, a cloth and emitters with death bursts. */
export function mixedScene(): PhysicsWorld {
  const world = createPhysicsWorld({ dimensions: 2, capacity: 3000, seed: 7, gravity: [0, -9.81] });
  setBoundary(world, { min: [-12, -1], max: [12, 30], restitution: 0.3 });
  addSegment(world, { a: [-12, 0], b: [12, 0] });
  for (let i = 0; i < 6; i++) addBox(world, { position: [-6, 0.5 + 1.05 * i], halfExtents: [0.5, 0.5], friction: 0.6 });
  for (let i = 0; i < 24; i++)
    addBody(world, {
      position: [2 + (i % 6) * 1.1, 3 + Math.floor(i / 6) * 1.1],
      radius: 0.4,
      restitution: 0.5,
      velocity: [(i % 3) - 1, 0],
    });
  // A chain of springs from a fixed anchor.
  let prev = addBody(world, { position: [8, 20], radius: 0.2 });
  addSpring(world, { anchor: [8, 22], b: prev, stiffness: 200, damping: 0.5, restLength: 1.5 });
  for (let i = 1; i < 5; i++) {
    const next = addBody(world, { position: [8 + i * 0.5, 20 - i], radius: 0.2 });
    addSpring(world, { a: prev, b: next, stiffness: 200, damping: 0.5, restLength: 1.2 });
    prev = next;
  }
  // A pendulum of boxes on revolute joints and a rod.
  let link = addBox(world, { position: [-9, 18], halfExtents: [0.6, 0.15] });
  addRevoluteJoint(world, { b: link, anchor: [-9.6, 18] });
  for (let i = 1; i < 4; i++) {
    const next = addBox(world, { position: [-9 + 1.2 * i, 18], halfExtents: [0.6, 0.15] });
    addRevoluteJoint(world, { a: link, b: next, anchor: [-9.6 + 1.2 * i, 18] });
    link = next;
  }
  const bob = addBody(world, { position: [0, 15], radius: 0.3 });
  addDistanceJoint(world, { b: bob, anchorA: [-2, 18] });
  createCloth(world, { origin: [3, 25], width: 3, height: 2, columns: 4, rows: 4, pinned: 'corners' });
  // Emitters: a fountain whose drops burst into mist.
  const mist = addEmitter(world, {
    speed: [0.5, 2],
    lifetime: [0.2, 0.6],
    policy: 'recycle-oldest',
    particle: { mass: 0.001, quadraticDrag: 1e-5 },
  });
  addEmitter(world, {
    position: [0, 1],
    rate: 60,
    direction: [0, 1],
    spread: 0.4,
    speed: [6, 10],
    lifetime: [0.5, 1.2],
    policy: 'recycle-oldest',
    particle: { mass: 0.01, linearDrag: 0.002, colorStart: 0x88ccff },
    onDeath: { emitter: mist, count: 3, maxGeneration: 1 },
  });
  return world;
}

/** The scenes the snapshot tests step: name, and a builder with small counts (the unit suite must stay fast). */
export const SNAPSHOT_SCENES: ReadonlyArray<{ name: string; build: () => PhysicsWorld }> = [
  { name: 'balls-in-box', build: () => scene('balls-in-box', 150) },
  { name: 'galaxy', build: () => scene('galaxy', 300) },
  { name: 'fireworks', build: () => scene('fireworks', 500) },
  { name: 'mixed (boxes, springs, joints, cloth, emitters)', build: mixedScene },
];

function scene(name: string, count: number): PhysicsWorld {
  const def = SCENES[name]!;
  const world = createPhysicsWorld(def.worldOptions({ count }));
  def.build(world, { count });
  return world;
}
