/**
 * The warm-up, `warmUp(dimensions)`: a small scene of a dimension, built and stepped (and kept, see
 * `keptWorlds`), so that the JavaScript engine has compiled the physics code the scene runs before a
 * program's own scene runs it.
 *
 * Why: V8 (Node, Chrome) runs a function in its interpreter until the function has run enough, then
 * compiles it on a background thread and keeps interpreting while it compiles. A scene's first steps
 * run every stage's loops over all its bodies and contacts in the interpreter, many times slower than
 * the compiled code, and the bigger the scene the more of its first step is interpreted: a pyramid of
 * 820 boxes took about 110 ms of main-thread CPU for its first step against about 15 ms once compiled,
 * and several steps more before all of its code was compiled. A small scene reaches the compile
 * thresholds of the same functions in fewer operations, so the stall moves out of the first steps to
 * wherever the program calls this, such as a game's loading. In all it costs more CPU than it
 * saves, so it is a call a program makes, not something a world does by itself (and a module of its
 * own, so a program that does not call it does not bundle the scene's shapes and joints).
 *
 * A function called once a step (the broadphase, the manifolds' preparation, the joints' rows) is
 * marked for compiling after a number of loop iterations, not of steps: the scene has enough contacts
 * and joints for most of those to be marked within its few steps (a pyramid of 136 boxes, a grid of
 * 180 joints), and one solver substep in 2D, so that they make a larger part of its steps. It stops
 * there, not once every function is compiled: the compiles end on V8's background threads while the
 * program goes on (building its world, loading), and every step more would run in the interpreter,
 * the warm-up's cost. The few once-a-step functions left are marked in a program's first steps,
 * each a loop that V8 compiles while it runs (on-stack replacement). It covers the paths of the
 * dimension that scenes and games use: boxes stacked on a static ground (two-point manifolds, the
 * block solver, friction, islands), ball bodies piled and a fast stone with restitution (impacts),
 * a circle or sphere shape, welds that break under a falling weight, a hinged chain, bodies without
 * shapes joined in a grid with two of them pinned (2D); a plane, capsules on ball joints hanging from
 * a moving kinematic body with a distance joint, linear drag and two integrator substeps (3D). It
 * touches no state outside the worlds it makes, so a world's trajectory is the same with and without it.
 *
 * The scene's stepped world is kept for the life of the program (`keptWorlds`): V8's compiled code
 * holds weak references to objects it was compiled against (hidden classes, constants), and some of
 * those belong only to the scene's world (a program's own world does not keep them alive). With the
 * scene collected, they died at a later full garbage collection, and every function compiled against
 * one of them was thrown away (--trace-deopt: "marking dependent code ... reason: weak objects": the
 * narrowphase's pairs, the bounds, the manifolds' preparation, the integrator, the sleep system,
 * about 30 functions in 2D), to be interpreted and compiled again in the program's first steps, the
 * stall the warm-up is there to take away.
 */
import { addBody, setBoundary } from './bodies/api.js';
import { addPlane } from './bodies/rigid.js';
import { addBox, addShape } from './bodies/shapes-2d.js';
import { addShape3D } from './bodies/shapes-3d.js';
import { createPhysicsWorld } from './create-world.js';
import { setDrag } from './forces/api.js';
import { addBallJoint3D } from './joints/ball-joint-3d.js';
import { addDistanceJoint3D } from './joints/distance-joint-3d.js';
import { addHingeJoint3D } from './joints/hinge-joint-3d.js';
import { addRevoluteJoint } from './joints/revolute-joint.js';
import { addWeldJoint } from './joints/weld-joint.js';
import { step } from './step/step.js';
import { assertOptionalBoolean, assertOptions, describe } from './validation/validate.js';
import type { PhysicsWorld } from './world/options.js';

/**
 * Steps the warm-up scene runs (`warmUp`): 0.17 s of simulated time at 60 Hz, enough for V8 to have
 * marked the scene's loops for compiling (the compiles end on a background thread while the program
 * goes on loading; the stepping in the interpreter meanwhile is what the warm-up costs).
 * @category World and step
 */
export const WARM_UP_STEPS = 10;

/**
 * Steps of the second, fresh world of the warm-up scene (see warmUp): its first steps run what only
 * a world's first steps run (buffers growing from empty, every contact new).
 */
const FRESH_STEPS = 3;

/**
 * Balls in the pile of `warmUp(d, { balls: true })`: above DENSE_MIN_BODIES (1,024,
 * collision/broadphase/grid.ts), from which the ball grid lays its cells out densely.
 * @category World and step
 */
export const WARM_UP_PILE_BALLS = 1100;

/** Steps the ball pile of `warmUp(d, { balls: true })` runs. */
const PILE_STEPS = 6;

/**
 * Options of `warmUp`.
 * @category World and step
 */
export interface WarmUpOptions {
  /**
   * Also build a pile of WARM_UP_PILE_BALLS (1,100) balls of that dimension and step it 6 times. A
   * world of 1,024 balls or more lays its ball grid out densely, code the small scene never runs, and
   * the ball stages' once-a-step loops (sorting the balls into cells, their pairs) are compiled
   * only after running over that many balls. For programs whose scenes hold thousands of balls:
   * after it, balls-in-box 20,000's steps 0 and 1 took about 30 to 100 ms of CPU each instead of
   * about 150 to 220, at about 0.3 to 0.5 s more CPU for the call (two cores, loaded). Default false.
   */
  readonly balls?: boolean;
}

/** Warm-ups run in this program: the dimensions (2, 3) and, for their ball piles, 'balls-2', 'balls-3'. */
const warmed = new Set<number | string>();

/**
 * The warm-up scene's world of each dimension warmed up, after its WARM_UP_STEPS steps, kept so that
 * the objects the code compiled during the warm-up refers to, and with them that code, live as long
 * as the program (see the top of warm-up.ts): about 2 to 2.5 MB a dimension. Never stepped again.
 */
const keptWorlds: PhysicsWorld[] = [];

/**
 * Most steps of the resting pyramid of the 2D warm-up (see warmUp): it falls asleep after about 3
 * (it settles at once, then rests REST_TIME_TO_SLEEP), and is stepped once more after.
 */
const REST_STEPS = 10;

/**
 * The resting pyramid's time to sleep, s (its world's `collision.sleep.timeToSleep`, 0.5 s by
 * default): 3 steps at 60 Hz, so that its island sleeps (the branch its steps are there to record)
 * without stepping the sleep system's 0.5 s of rest.
 */
const REST_TIME_TO_SLEEP = 0.05;

/**
 * Warms the physics code of `dimensions` up once a program: in 2D first steps a pyramid of 36 boxes
 * until it falls asleep (a world's first sleep, after 0.05 s of rest), then builds a small scene of
 * that dimension (boxes on a ground, a pile of balls, a disc or sphere, joints of the common kinds),
 * steps it WARM_UP_STEPS (10) times, then a second copy of it 3 times (the paths only a world's first
 * steps run), so that a large scene's first steps afterwards run compiled code (see the top of
 * warm-up.ts). The first copy is kept for the life of the program (about 2 to 2.5 MB a dimension),
 * so that the code compiled against its objects is not thrown away with them. Call it where a pause
 * is expected, such as while a game loads its first level: on two cores loaded by about 30 other
 * processes it took about 0.2 s of main-thread CPU in 2D (0.3 s in 3D), and a pyramid of 820 boxes'
 * first four steps then took about 30 ms of main-thread CPU instead of about 115 (the first one 10 to
 * 15 instead of about 75), a joint grid of 10,000 bodies' first one about 45 to 55 instead of 145. With
 * `{ balls: true }` it also steps a pile of 1,100 balls, for scenes of thousands of balls (see
 * WarmUpOptions.balls). A second call for the same dimension does nothing (but run a pile not run
 * yet). Worlds' states are the same with and without it.
 * @param dimensions 2 or 3. Default 2.
 * @param options `balls` (boolean, default false). Default {}.
 * @returns whether it ran anything (false: this dimension, and its pile if asked, were warmed up already).
 * @throws RangeError if dimensions is not 2 or 3; TypeError if options is not an object, has an
 *   unknown key, or `balls` is not a boolean.
 * @example
 * warmUp(2); // while the game loads
 * warmUp(2, { balls: true }); // a game of 20,000 balls
 * const world = createPhysicsWorld({ dimensions: 2 });
 * @category World and step
 */
export function warmUp(dimensions: 2 | 3 = 2, options: WarmUpOptions = {}): boolean {
  if (dimensions !== 2 && dimensions !== 3) throw new RangeError(`warmUp: dimensions must be 2 or 3, got ${describe(dimensions)}`);
  assertOptions('warmUp', options, ['balls']);
  assertOptionalBoolean('warmUp', 'balls', options.balls);
  const scene = !warmed.has(dimensions),
    pile = options.balls === true && !warmed.has(`balls-${dimensions}`);
  if (scene) warmScene(dimensions);
  if (pile) warmBallPile(dimensions);
  return scene || pile;
}

/** In 2D a resting pyramid first, then the warm-up scene of `dimensions`, stepped, then a fresh copy of it (see warmUp). */
function warmScene(dimensions: 2 | 3): void {
  warmed.add(dimensions);
  // A world's first sleep, which the scene below does not reach until late in its steps: an island
  // put to sleep (the sleep system's last branch, a component added to each of its bodies) and the
  // sleeping steps after it. It runs first, while the stages are still interpreted and record the
  // types they meet (type feedback): code compiled before a branch has run leaves that branch out,
  // and the first time it runs the compiled code is thrown away. Run after the scene, the sleep would
  // throw away the compiled sleep system and force clearing, to be compiled again only in a program's
  // own first steps (on a background thread, while those steps run the slower code).
  if (dimensions === 2) {
    const resting = restingPyramid();
    for (let i = 0; i < REST_STEPS && resting.collision.stats.sleeping === 0; i++) step(resting);
    step(resting);
  }
  const world = warmUpScene(dimensions);
  // The second world is made before the first steps: making a world's stores the second time
  // generalises the field types V8 tracks for them (a store's arrays were of one class in the first
  // world; --trace-generalization), which throws away all code compiled against the first world's
  // (in 3D the broadphase's gather, the narrowphase's pairs, the joints' rows: 30 functions, compiled
  // again only in a program's own first steps). Made before anything is compiled, it costs nothing.
  const fresh = warmUpScene(dimensions);
  for (let i = 0; i < WARM_UP_STEPS; i++) step(world);
  keptWorlds.push(world);
  // V8 gives a function the vector where it records its type feedback only after the function has
  // run a few times, so what a world runs only in its first step (its buffers grown from empty, every
  // contact new) ran in the scene above before anything was recorded, and the code compiled from its
  // later steps lacks those paths: a program's own world then threw that code away in its first step
  // (11 functions recompiled, a pyramid's steps 0 to 3 each several times its compiled cost). A
  // second world of the scene runs those paths again, recorded this time.
  for (let i = 0; i < FRESH_STEPS; i++) step(fresh);
}

/** The ball pile of `warmUp(d, { balls: true })`, stepped PILE_STEPS times. */
function warmBallPile(dimensions: 2 | 3): void {
  warmed.add(`balls-${dimensions}`);
  const world = ballPile(dimensions);
  for (let i = 0; i < PILE_STEPS; i++) step(world);
}

/**
 * WARM_UP_PILE_BALLS balls of radius 0.15 m in a walled box, in rows (2D) or layers (3D) 0.32 m
 * apart, alternate rows shifted by half a ball so that they settle onto each other.
 */
export function ballPile(dimensions: 2 | 3): PhysicsWorld {
  const n = WARM_UP_PILE_BALLS,
    pitch = 0.32;
  const world = createPhysicsWorld({ dimensions, capacity: n + 8, gravity: dimensions === 2 ? [0, -10] : [0, -10, 0] });
  const side = Math.ceil(dimensions === 2 ? Math.sqrt(n) : Math.cbrt(n));
  const wall = side * pitch + 0.5;
  if (dimensions === 2) setBoundary(world, { min: [-0.5, -0.5], max: [wall, 100], restitution: 0.25 });
  else setBoundary(world, { min: [-0.5, -0.5, -0.5], max: [wall, 100, wall], restitution: 0.25 });
  const perLayer = dimensions === 2 ? side : side * side;
  for (let i = 0; i < n; i++) {
    const layer = Math.floor(i / perLayer),
      k = i % perLayer,
      shift = (layer % 2) * 0.5 * pitch;
    const x = (k % side) * pitch + shift,
      y = 0.2 + layer * pitch;
    const position = dimensions === 2 ? [x, y] : [x, y, Math.floor(k / side) * pitch + shift];
    addBody(world, { position, radius: 0.15, mass: 1 });
  }
  return world;
}

/** A pyramid of 36 boxes resting on a static ground (2D, the `pyramid` scene's layout and 8 solver substeps): it sleeps within REST_STEPS (its time to sleep REST_TIME_TO_SLEEP). */
function restingPyramid(): PhysicsWorld {
  const world = createPhysicsWorld({ dimensions: 2, capacity: 64, gravity: [0, -10], solverSubsteps: 8 });
  world.collision.sleep.timeToSleep = REST_TIME_TO_SLEEP;
  addBox(world, { position: [0, -0.5], halfExtents: [10, 0.5], static: true, friction: 0.6 });
  for (let row = 0; row < 8; row++) {
    const n = 8 - row;
    for (let i = 0; i < n; i++)
      addBox(world, { position: [(i - (n - 1) / 2) * 1.05, 0.5 + row], halfExtents: [0.5, 0.5], density: 1, friction: 0.6 });
  }
  return world;
}

/** The warm-up scene of `dimensions` in a world of its own, built and not stepped. */
export function warmUpScene(dimensions: 2 | 3): PhysicsWorld {
  if (dimensions === 2) {
    // One solver substep: the functions run once a step get a larger part of each step (see the top).
    const world = createPhysicsWorld({ dimensions, capacity: 600, gravity: [0, -10], solverSubsteps: 1 });
    build2D(world);
    return world;
  }
  // Two integrator substeps: the step's own start and end of substeps (a game's chain takes four).
  const world = createPhysicsWorld({ dimensions, capacity: 400, gravity: [0, -10, 0], substeps: 2 });
  build3D(world);
  return world;
}

/** 2D: a pyramid of 136 boxes, 16 balls, a disc, a fast stone and a fast small box, welded boxes a weight breaks, a hinged chain and a pinned joint grid, in a walled box. */
function build2D(world: PhysicsWorld): void {
  // Walls with a fractional restitution, as most scenes give theirs: the field then holds a double
  // from here on, and a program's own setBoundary does not change its representation (from a small
  // integer), which threw away the compiled code of the ball stages that read it ('wrong map').
  setBoundary(world, { min: [-20, -1], max: [20, 40], restitution: 0.25 });
  addBox(world, { position: [0, -0.5], halfExtents: [20, 0.5], static: true, friction: 0.6 });
  for (let row = 0; row < 16; row++) {
    const n = 16 - row;
    for (let i = 0; i < n; i++)
      addBox(world, { position: [(i - (n - 1) / 2) * 1.05 - 8, 0.5 + row], halfExtents: [0.5, 0.5], density: 1, friction: 0.6 });
  }
  // Rows offset by half a ball, so the balls land on each other and pile up.
  for (let i = 0; i < 16; i++) {
    const row = Math.floor(i / 8);
    addBody(world, { position: [2 + (i % 8) * 0.32 + (row % 2) * 0.16, 1 + row * 0.4], radius: 0.15, mass: 1 });
  }
  addShape(world, addBody(world, { position: [-2, 3] }), { type: 'circle', radius: 0.4, density: 1 });
  // A stone thrown into the pyramid's side: a contact with restitution closing fast (the impact stage).
  addBody(world, { position: [-18, 3], velocity: [25, 2], radius: 0.3, mass: 3, restitution: 0.3, friction: 0.6 });
  // A small box moving farther than its size each step, from the first step on: the continuous
  // collision of shapes (collision/continuous-2d.ts), whose sweep a settling pile reaches only late.
  addBox(world, { position: [-18, 8], velocity: [40, 0], halfExtents: [0.1, 0.1], density: 5, friction: 0.3 });
  buildJoints2D(world);
}

/** 2D joints: three boxes welded on a post under a falling weight that breaks a weld, a hinged chain, a 10 x 10 grid of bodies without shapes with two pinned. */
function buildJoints2D(world: PhysicsWorld): void {
  let below = addBox(world, { position: [8, 0.5], halfExtents: [0.2, 0.5], static: true });
  for (let k = 0; k < 3; k++) {
    const box = addBox(world, { position: [8, 1.25 + 0.5 * k], halfExtents: [0.6, 0.25], density: 2, friction: 0.7 });
    addWeldJoint(world, { a: below, b: box, anchor: [8, 1 + 0.5 * k], breakForce: 300, breakTorque: 75 });
    below = box;
  }
  // Falling at 10 m/s from 0.6 m above the top box: it lands within the scene's first steps.
  addBody(world, { position: [8.4, 3.5], velocity: [0, -10], radius: 0.4, mass: 40 });
  let previous = addBox(world, { position: [12, 8], halfExtents: [0.4, 0.1], static: true });
  for (let k = 0; k < 4; k++) {
    const link = addBox(world, { position: [12.8 + k * 0.8, 8], halfExtents: [0.4, 0.1], density: 1 });
    addRevoluteJoint(world, { a: previous, b: link, anchor: [12.4 + k * 0.8, 8] });
    previous = link;
  }
  const side = 10,
    grid: number[] = [];
  for (let i = 0; i < side; i++) {
    for (let k = 0; k < side; k++) {
      const position = [-15 + k, 35 - i];
      const pinned = i === 0 && (k === 2 || k === side - 3);
      const body = pinned ? addBody(world, { position, static: true }) : addBody(world, { position, mass: 1, inertia: 0.08 });
      grid.push(body);
      if (i > 0) addRevoluteJoint(world, { a: grid[(i - 1) * side + k]!, b: body, anchor: [-15 + k, 35.5 - i] });
      if (k > 0) addRevoluteJoint(world, { a: grid[i * side + k - 1]!, b: body, anchor: [-15.5 + k, 35 - i] });
    }
  }
}

/** 3D: a plane and a slab, a pile of 75 boxes, a row of 8 boxes on the plane, 24 balls, a sphere shape with drag, a capsule chain on a moving hook and a hinged chain. */
function build3D(world: PhysicsWorld): void {
  // A fractional restitution, as in 2D (see build2D).
  setBoundary(world, { min: [-12, -1, -12], max: [12, 30, 12], restitution: 0.25 });
  addPlane(world, { normal: [0, 1, 0], point: [0, 0, 0], friction: 0.7 });
  addShape3D(world, addBody(world, { position: [0, 0.25, 0], static: true }), { type: 'box', halfExtents: [6, 0.25, 6] });
  for (let l = 0; l < 3; l++) {
    for (let i = 0; i < 5; i++) {
      for (let k = 0; k < 5; k++) {
        const box = addBody(world, { position: [-3 + i * 1.05, 1 + l, -2 + k * 1.05] });
        addShape3D(world, box, { type: 'box', halfExtents: [0.5, 0.5, 0.5], density: 1, friction: 0.6, restitution: 0.05 });
      }
    }
  }
  // Layers offset by half a ball, so the balls land on each other and pile up.
  for (let i = 0; i < 24; i++) {
    const layer = Math.floor(i / 8),
      shift = (layer % 2) * 0.16;
    addBody(world, { position: [3 + (i % 4) * 0.32 + shift, 1 + layer * 0.4, ((i >> 2) % 2) * 0.32 + shift], radius: 0.15, mass: 1 });
  }
  const sphere = addBody(world, { position: [-1.5, 6, -0.5], velocity: [0, -4, 0] });
  addShape3D(world, sphere, { type: 'sphere', radius: 0.5, density: 2, friction: 0.4, restitution: 0.1 });
  setDrag(world, sphere, { linear: 0.5 });
  // A row of boxes standing on the plane beside the slab (box-plane manifolds, as a box pile on a plane ground).
  for (let i = 0; i < 8; i++) {
    const box = addBody(world, { position: [-7 + i * 1.2, 0.5, 8] });
    addShape3D(world, box, { type: 'box', halfExtents: [0.5, 0.5, 0.5], density: 1, friction: 0.6 });
  }
  buildJoints3D(world);
}

/** 3D joints: four capsules on ball joints from a kinematic hook moving sideways, a heavy sphere at their end held by a distance joint, and three boxes on hinges. */
function buildJoints3D(world: PhysicsWorld): void {
  const hook = addBody(world, { position: [8, 10, 0], kinematic: true, velocity: [-2, 0, 0] });
  let above = hook,
    top = 10;
  for (let k = 0; k < 4; k++) {
    const link = addBody(world, { position: [8, top - 0.4, 0] });
    addShape3D(world, link, { type: 'capsule', radius: 0.08, halfHeight: 0.32, density: 7800 });
    addBallJoint3D(world, { a: above, b: link, anchor: [8, top, 0] });
    above = link;
    top -= 0.8;
  }
  const ball = addBody(world, { position: [8, top - 0.5, 0] });
  addShape3D(world, ball, { type: 'sphere', radius: 0.5, density: 800, friction: 0.4, restitution: 0.1 });
  addBallJoint3D(world, { a: above, b: ball, anchor: [8, top, 0] });
  addDistanceJoint3D(world, { a: hook, b: ball, anchorA: [8, 10, 0], anchorB: [8, top - 0.5, 0], minLength: 0 });
  let previous = addBody(world, { position: [-8, 8, 3], static: true });
  addShape3D(world, previous, { type: 'box', halfExtents: [0.4, 0.1, 0.1] });
  for (let k = 0; k < 3; k++) {
    const link = addBody(world, { position: [-7.2 + k * 0.8, 8, 3] });
    addShape3D(world, link, { type: 'box', halfExtents: [0.4, 0.1, 0.1], density: 1 });
    addHingeJoint3D(world, { a: previous, b: link, anchor: [-7.6 + k * 0.8, 8, 3], axis: [0, 0, 1] });
    previous = link;
  }
}
