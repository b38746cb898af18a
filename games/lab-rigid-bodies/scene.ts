/**
 * Rigid bodies (Ramtal and Dobre ch. 13), the scenes: pure, seeded builders (no DOM, no pixi; they run
 * in Node and in tests too). Five demos on a 16 m x 10 m stage:
 * - `incline`: a board that tilts slowly (a kinematic body turning at `tiltRate`) under a tall box
 *   and a wide box of the same friction: the tall one tips when tan(angle) > width / height, the wide
 *   one slides when tan(angle) > its static friction coefficient;
 * - `bouncing`: a block dropped corner first (restitution 0.4): its impulses have angular terms;
 * - `colliding`: two blocks thrown at each other;
 * - `torque`: a floating block turned by a constant torque against angular damping: w -> torque / k;
 * - `turbine`: a three-bladed rotor on a pin, driven by the wind's torque against its bearing's damping.
 */
import {
  addBody,
  addBox,
  addRevoluteJoint,
  addShape,
  addSystem,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  Rng,
  setAngularDamping,
  setBoundary,
  setGravityScale,
  slotOf,
} from '@bitphysics/physics';

/** Names of the demos. */
export const SCENE_NAMES = ['incline', 'bouncing', 'colliding', 'torque', 'turbine'] as const;
/** One of SCENE_NAMES. */
export type SceneName = (typeof SCENE_NAMES)[number];

/** Options of the scene. */
export interface SceneOptions {
  scene: SceneName;
  /** Seed of the layout. */
  seed: number;
  /** Gravity, m/s^2 (downwards), >= 0. */
  gravity: number;
  /** Friction coefficient of the boxes and the board (static = kinetic), >= 0. */
  friction: number;
  /** Incline: how fast the board tilts, rad/s. */
  tiltRate: number;
  /** Torque demo: the torque, N m, and the angular damping k, N m s. Turbine: the wind's torque, N m. */
  torque: number;
  damping: number;
}

/** What the game keeps of a scene (entity handles). */
export interface SceneHandles {
  /** Every box the scene or the player added. */
  boxes: number[];
  /** Incline: the board, the tall box and the wide box, and their sizes (width / height). */
  board?: number;
  tall?: number;
  wide?: number;
  tallRatio?: number;
  /** Torque demo: the turned block. Turbine: the rotor. */
  spinner?: number;
}

/** Width and height of the stage, m. */
export const STAGE = { width: 16, height: 10 } as const;

/** Board of the incline: pivot at its left end, half length, half thickness (m). */
const BOARD = { x: 2, y: 1.5, half: 6, thick: 0.1 };

/** The world options: 2D, room for the boxes the player may add. */
export function worldOptions(options: SceneOptions): PhysicsWorldOptions {
  return { dimensions: 2, capacity: 2000, gravity: [0, -options.gravity], sleep: false };
}

/** Builds the scene `options.scene` into an empty `world`. */
export function buildScene(world: PhysicsWorld, options: SceneOptions): SceneHandles {
  setBoundary(world, { min: [0, 0], max: [STAGE.width, STAGE.height], restitution: 0.2, friction: 0.6 });
  const h: SceneHandles = { boxes: [] };
  const mu = options.friction;
  switch (options.scene) {
    case 'incline': {
      // The board turns about its left end: a kinematic body whose centre circles the pivot.
      const board = addBox(world, {
        position: [BOARD.x + BOARD.half, BOARD.y],
        halfExtents: [BOARD.half, BOARD.thick],
        kinematic: true,
        friction: mu,
        angularVelocity: 0,
        rotates: true,
      });
      h.board = board;
      const tall = addBox(world, {
        position: [BOARD.x + 3, BOARD.y + BOARD.thick + 0.75],
        halfExtents: [0.3, 0.75],
        friction: mu,
        density: 1,
      });
      const wide = addBox(world, {
        position: [BOARD.x + 8, BOARD.y + BOARD.thick + 0.3],
        halfExtents: [0.6, 0.3],
        friction: mu,
        density: 1,
      });
      h.tall = tall;
      h.wide = wide;
      h.tallRatio = 0.6 / 1.5;
      h.boxes.push(tall, wide);
      const rate = options.tiltRate;
      // Each step: the board's angle rises at `rate` until 60 degrees; its centre moves on the circle about the pivot.
      addSystem(world, 'forces', (w) => {
        const e = slotOf(board),
          c = w.components;
        const a = c.Angle.value[e]!;
        const wz = a < Math.PI / 3 ? rate : 0;
        c.AngularVelocity.z[e] = wz;
        c.Velocity.x[e] = -Math.sin(a) * BOARD.half * wz;
        c.Velocity.y[e] = Math.cos(a) * BOARD.half * wz;
      });
      break;
    }
    case 'bouncing': {
      const block = addBox(world, {
        position: [8, 7],
        angle: 0.5,
        halfExtents: [0.8, 0.4],
        restitution: 0.4,
        friction: mu,
        angularVelocity: 0.5,
      });
      h.boxes.push(block);
      break;
    }
    case 'colliding': {
      h.boxes.push(
        addBox(world, {
          position: [4, 5],
          angle: 0.3,
          halfExtents: [0.6, 0.4],
          velocity: [6, 2],
          angularVelocity: 1,
          friction: mu,
          restitution: 0.4,
        }),
      );
      h.boxes.push(
        addBox(world, {
          position: [12, 5.5],
          angle: -0.2,
          halfExtents: [0.5, 0.5],
          velocity: [-6, 1.5],
          angularVelocity: -2,
          friction: mu,
          restitution: 0.4,
          density: 2,
        }),
      );
      break;
    }
    case 'torque': {
      const block = addBox(world, { position: [8, 5], halfExtents: [1.5, 0.3], friction: mu });
      setGravityScale(world, block, 0);
      setAngularDamping(world, block, options.damping);
      const tau = options.torque;
      addSystem(world, 'forces', (w) => {
        w.components.Torque.z[slotOf(block)] = w.components.Torque.z[slotOf(block)]! + tau;
      });
      h.spinner = block;
      h.boxes.push(block);
      break;
    }
    case 'turbine': {
      addBox(world, { position: [8, 2.5], halfExtents: [0.15, 2.5], static: true, category: 2, mask: 0 });
      const rotor = addBody(world, { position: [8, 5], rotates: true });
      for (let k = 0; k < 3; k++) {
        const a = (2 * Math.PI * k) / 3;
        addShape(world, rotor, {
          type: 'capsule',
          center1: [0.3 * Math.cos(a), 0.3 * Math.sin(a)],
          center2: [2.2 * Math.cos(a), 2.2 * Math.sin(a)],
          radius: 0.12,
          density: 2,
          category: 2,
          mask: 1,
        });
      }
      addShape(world, rotor, { type: 'circle', radius: 0.3, density: 2, category: 2, mask: 1 });
      addRevoluteJoint(world, { a: null, b: rotor, anchor: [8, 5] });
      setAngularDamping(world, rotor, options.damping);
      const tau = options.torque;
      addSystem(world, 'forces', (w) => {
        w.components.Torque.z[slotOf(rotor)] = w.components.Torque.z[slotOf(rotor)]! + tau;
      });
      h.spinner = rotor;
      break;
    }
  }
  // A few seeded crates on the floor to knock about (not in the incline, whose stage is the board).
  if (options.scene === 'bouncing' || options.scene === 'colliding') {
    const rng = new Rng(options.seed);
    for (let i = 0; i < 3; i++)
      h.boxes.push(addBox(world, { position: [rng.range(2, 14), 0.5 + 1.2 * i], halfExtents: [0.4, 0.4], friction: mu }));
  }
  return h;
}

/** Adds a 0.6 m crate at (x, y), m, and returns its handle. */
export function spawnBox(world: PhysicsWorld, handles: SceneHandles, x: number, y: number): number {
  const box = addBox(world, { position: [x, y], halfExtents: [0.3, 0.3], angle: 0.3, friction: 0.6, restitution: 0.2 });
  handles.boxes.push(box);
  return box;
}
