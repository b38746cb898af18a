/**
 * The warm-up, `warmUp(dimensions)`: a small scene of a dimension, built, stepped and thrown away, so
 * that the JavaScript engine has compiled the physics code the scene runs before a program's own scene
 * runs it.
 *
 * Why: V8 (Node, Chrome) runs a function in its interpreter until the function has run enough, then
 * compiles it on a background thread and keeps interpreting while it compiles. A scene's first steps
 * run every stage's loops over all its bodies and contacts in the interpreter, many times slower than
 * the compiled code, and the bigger the scene the more of its first step is interpreted: a pyramid of
 * 820 boxes took about 130 ms of main-thread CPU for its first step against about 10 ms for a later
 * one, and several steps more before all of its code was compiled, although only 9 compiled functions
 * were thrown away again. A small scene reaches the compile thresholds of the same functions in far
 * fewer operations, so most of the stall moves out of the first steps to wherever the program calls
 * this, such as a game's loading. In all it costs a little more CPU than it saves, so it is a call a
 * program makes, not something a world does by itself (and a module of its own, so a program that
 * does not call it does not bundle the scene's shapes and joints).
 *
 * The scene covers the common paths of the dimension: boxes stacked on a static ground (polygon
 * manifolds, friction, islands, sleep), ball bodies (the ball rows), a circle or sphere shape, and a
 * chain of joints. It touches no state outside the world it makes, so a world's trajectory is the same
 * with and without it.
 */
import { addBody, setBoundary } from './bodies/api.js';
import { addBox, addShape } from './bodies/shapes-2d.js';
import { addShape3D } from './bodies/shapes-3d.js';
import { createPhysicsWorld } from './create-world.js';
import { addHingeJoint3D } from './joints/hinge-joint-3d.js';
import { addRevoluteJoint } from './joints/revolute-joint.js';
import { step } from './step/step.js';
import { describe } from './validation/validate.js';
import type { PhysicsWorld } from './world/options.js';

/**
 * Steps the warm-up scene runs (`warmUp`): about 1.3 s of simulated time at 60 Hz, enough for its loops to be compiled.
 * @category World and step
 */
export const WARM_UP_STEPS = 80;

/** Dimensions (2, 3) whose warm-up ran in this program. */
const warmed = new Set<number>();

/**
 * Warms the physics code of `dimensions` up once a program: builds a small scene of that dimension
 * (boxes on a ground, a pile of balls, a disc or sphere, a hinged chain), steps it WARM_UP_STEPS (80)
 * times and throws it away, so that a large scene's first steps afterwards run compiled code (see the
 * top of warm-up.ts). Call it where a pause is expected, such as while a game loads its first level:
 * it takes about 0.2 to 0.5 s of main-thread time, and a pyramid of 820 boxes' first step then takes
 * about 50 ms of CPU instead of about 130. A second call for the same dimension does nothing. Worlds'
 * states are the same with and without it.
 * @param dimensions 2 or 3. Default 2.
 * @returns whether it ran (false: this dimension was already warmed up).
 * @throws RangeError if dimensions is not 2 or 3.
 * @example
 * warmUp(2); // while the game loads
 * const world = createPhysicsWorld({ dimensions: 2 });
 * @category World and step
 */
export function warmUp(dimensions: 2 | 3 = 2): boolean {
  if (dimensions !== 2 && dimensions !== 3) throw new RangeError(`warmUp: dimensions must be 2 or 3, got ${describe(dimensions)}`);
  if (warmed.has(dimensions)) return false;
  warmed.add(dimensions);
  const world = warmUpScene(dimensions);
  for (let i = 0; i < WARM_UP_STEPS; i++) step(world);
  return true;
}

/** The warm-up scene of `dimensions` in a world of its own, built and not stepped. */
export function warmUpScene(dimensions: 2 | 3): PhysicsWorld {
  const world = createPhysicsWorld({ dimensions, capacity: 96, gravity: dimensions === 2 ? [0, -10] : [0, -10, 0] });
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
