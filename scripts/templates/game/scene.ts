/**
 * __TITLE__: the scene, a pure and seeded builder (no DOM, no pixi: it runs in Node and in tests
 * too). A 16 m x 10 m box with a ramp; `count` balls dropped from the top.
 */
import { addBody, addSegment, type PhysicsWorld, type PhysicsWorldOptions, Rng, setBoundary } from '@bitphysics/physics';

/** Options of the scene. */
export interface SceneOptions {
  /** Balls at the start, integer >= 0. */
  count: number;
  /** Seed of the layout. */
  seed: number;
  /** Gravity, m/s^2 (downwards), >= 0. */
  gravity: number;
  /** Restitution of balls and walls, in [0, 1]. */
  restitution: number;
}

/** What the game keeps of the scene: the balls' entity handles, oldest first. */
export interface SceneHandles {
  balls: number[];
}

/** Width and height of the box, m. */
export const BOX = { width: 16, height: 10 } as const;
/** Radius of a ball, m. */
export const BALL_RADIUS = 0.3;

/** The world options of the scene: 2D, room for the balls the game may add. */
export function worldOptions(options: SceneOptions): PhysicsWorldOptions {
  return { dimensions: 2, capacity: options.count + 2000, gravity: [0, -options.gravity] };
}

/** Builds the scene into an empty `world`. */
export function buildScene(world: PhysicsWorld, options: SceneOptions): SceneHandles {
  setBoundary(world, { min: [0, 0], max: [BOX.width, BOX.height], restitution: options.restitution, friction: 0.3 });
  addSegment(world, { a: [1, 5], b: [9, 2.5], friction: 0.3 });
  const handles: SceneHandles = { balls: [] };
  const rng = new Rng(options.seed);
  for (let i = 0; i < options.count; i++) {
    spawnBall(world, handles, rng.range(1, BOX.width - 1), rng.range(6, BOX.height - 1), options.restitution);
  }
  return handles;
}

/** Adds a ball at (x, y), m, and returns its handle. */
export function spawnBall(world: PhysicsWorld, handles: SceneHandles, x: number, y: number, restitution = 0.7): number {
  const ball = addBody(world, { position: [x, y], radius: BALL_RADIUS, mass: 1, restitution, friction: 0.3 });
  handles.balls.push(ball);
  return ball;
}
