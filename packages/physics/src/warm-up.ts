/**
 * The warm-up (`createPhysicsWorld({ warmUp: true })`): before a program's first world of a dimension
 * that asks for it is made, a small scene of that dimension is built, stepped and thrown away, so that
 * the JavaScript engine has compiled the physics code the scene runs before the program's own scene
 * runs it.
 *
 * Why: V8 (Node, Chrome) runs a function in its interpreter until the function has run enough, then
 * compiles it on a background thread and keeps interpreting while it compiles. A scene's first steps
 * run every stage's loops over all its bodies and contacts in the interpreter, many times slower than
 * the compiled code, and the bigger the scene the more of its first step is interpreted: a pyramid of
 * 820 boxes took about 130 ms of main-thread CPU for its first step against about 10 ms for a later
 * one, and several steps more before all of its code was compiled, although only 9 compiled functions
 * were thrown away again. A small scene reaches the compile thresholds of the same functions in far
 * fewer operations, so most of the stall moves out of the first steps into the making of the first
 * world, where a game loads. In all it costs a little more CPU than it saves, so it is asked for, not
 * the default.
 *
 * The scene covers the common paths of the dimension: boxes stacked on a static ground (polygon
 * manifolds, friction, islands, sleep), ball bodies (the ball rows), a circle or sphere shape, and a
 * chain of joints. It touches no state outside the world it makes, so a world's trajectory is the same
 * with and without it.
 */
import { addBody, setBoundary } from './bodies/api.js';
import { addBox, addShape } from './bodies/shapes-2d.js';
import { addShape3D } from './bodies/shapes-3d.js';
import { addHingeJoint3D } from './joints/hinge-joint-3d.js';
import { addRevoluteJoint } from './joints/revolute-joint.js';
import { step } from './step/step.js';
import type { PhysicsWorld, PhysicsWorldOptions } from './world/options.js';

/** Steps the warm-up scene runs: about 1.3 s of simulated time at 60 Hz, enough for its loops to be compiled. */
export const WARM_UP_STEPS = 80;

/** Dimensions (2, 3) whose warm-up ran in this program. */
const warmed = new Set<number>();

/**
 * Runs the warm-up scene of `dimensions` once per program: a second call for the same dimension does
 * nothing. `make` makes the scene's world (createPhysicsWorld; passed in because this module sits
 * below create-world.ts).
 */
export function warmUpOnce(dimensions: 2 | 3, make: (options: PhysicsWorldOptions) => PhysicsWorld): void {
  if (warmed.has(dimensions)) return;
  warmed.add(dimensions);
  warmUp(dimensions, make);
}

/** Builds the warm-up scene of `dimensions` with `make` and steps it WARM_UP_STEPS times; returns the world. */
export function warmUp(dimensions: 2 | 3, make: (options: PhysicsWorldOptions) => PhysicsWorld): PhysicsWorld {
  const world = warmUpScene(dimensions, make);
  for (let i = 0; i < WARM_UP_STEPS; i++) step(world);
  return world;
}

/** The warm-up scene of `dimensions`, built in a world made by `make` (without a warm-up of its own), not stepped. */
export function warmUpScene(dimensions: 2 | 3, make: (options: PhysicsWorldOptions) => PhysicsWorld): PhysicsWorld {
  const world = make({ dimensions, capacity: 96, gravity: dimensions === 2 ? [0, -10] : [0, -10, 0], warmUp: false });
  if (dimensions === 2) build2D(world);
  else build3D(world);
  return world;
}

/** 2D: a pyramid of 21 boxes, 32 balls falling beside it, a disc and a chain of 4 hinged boxes, in a walled box. */
function build2D(world: PhysicsWorld): void {
  setBoundary(world, { min: [-8, -1], max: [8, 30] });
  addBox(world, { position: [0, -0.5], halfExtents: [8, 0.5], static: true });
  for (let row = 0; row < 6; row++) {
    for (let i = 0; i < 6 - row; i++) {
      addBox(world, { position: [(i - (5 - row) / 2) * 1.05 - 3, 0.5 + row], halfExtents: [0.5, 0.5], density: 1, friction: 0.6 });
    }
  }
  // Rows offset by half a ball, so the balls land on each other and pile up.
  for (let i = 0; i < 32; i++) {
    const row = Math.floor(i / 8);
    addBody(world, { position: [2 + (i % 8) * 0.32 + (row % 2) * 0.16, 1 + row * 0.4], radius: 0.15, mass: 1 });
  }
  addShape(world, addBody(world, { position: [-6, 3] }), { type: 'circle', radius: 0.4, density: 1 });
  let previous = addBox(world, { position: [5, 8], halfExtents: [0.4, 0.1], static: true });
  for (let k = 0; k < 4; k++) {
    const link = addBox(world, { position: [5.8 + k * 0.8, 8], halfExtents: [0.4, 0.1], density: 1 });
    addRevoluteJoint(world, { a: previous, b: link, anchor: [5.4 + k * 0.8, 8] });
    previous = link;
  }
}

/** 3D: a stack of 20 boxes on a static slab, 24 balls falling beside it, a sphere shape and a chain of 3 hinged boxes. */
function build3D(world: PhysicsWorld): void {
  setBoundary(world, { min: [-6, -1, -6], max: [6, 20, 6] });
  addShape3D(world, addBody(world, { position: [0, -0.5, 0], static: true }), { type: 'box', halfExtents: [6, 0.5, 6] });
  for (let i = 0; i < 20; i++) {
    const box = addBody(world, { position: [-3 + (i % 2) * 1.05, 0.5 + Math.floor(i / 4), -0.5 + ((i >> 1) % 2) * 1.05] });
    addShape3D(world, box, { type: 'box', halfExtents: [0.5, 0.5, 0.5], density: 1, friction: 0.6 });
  }
  // Layers offset by half a ball, so the balls land on each other and pile up.
  for (let i = 0; i < 24; i++) {
    const layer = Math.floor(i / 8),
      shift = (layer % 2) * 0.16;
    addBody(world, { position: [2 + (i % 4) * 0.32 + shift, 1 + layer * 0.4, ((i >> 2) % 2) * 0.32 + shift], radius: 0.15, mass: 1 });
  }
  addShape3D(world, addBody(world, { position: [0, 4, 3] }), { type: 'sphere', radius: 0.4, density: 1 });
  let previous = addBody(world, { position: [3, 8, 3], static: true });
  addShape3D(world, previous, { type: 'box', halfExtents: [0.4, 0.1, 0.1] });
  for (let k = 0; k < 3; k++) {
    const link = addBody(world, { position: [3.8 + k * 0.8, 8, 3] });
    addShape3D(world, link, { type: 'box', halfExtents: [0.4, 0.1, 0.1], density: 1 });
    addHingeJoint3D(world, { a: previous, b: link, anchor: [3.4 + k * 0.8, 8, 3], axis: [0, 0, 1] });
    previous = link;
  }
}
