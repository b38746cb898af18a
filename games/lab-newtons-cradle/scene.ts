/**
 * Newton's cradle scene: `count` equal balls in a row, each hung from its own anchor by a rigid
 * string (a distance joint to the world) of length L, touching their neighbours; perfectly elastic
 * (e = 1), frictionless. Lifting k balls and letting go sends k balls out of the far end: momentum
 * and kinetic energy can only both be kept that way (Ramtal and Dobre ch. 11, collisions between
 * equal masses). A pure, deterministic builder; no DOM.
 */
import { addBody, addDistanceJoint, type PhysicsWorld, type PhysicsWorldOptions, setPosition, setVelocity } from '@bitphysics/physics';

/** Options of the scene; every field optional. */
export interface CradleOptions {
  /** Balls in the row, integer in [2, 8]. Default 5. */
  count?: number;
  /** Ball radius, m, in [0.02, 0.5]. Default 0.1. */
  radius?: number;
  /** String length from anchor to ball centre, m, in [0.2, 3]. Default 1. */
  length?: number;
  /** Gravity, m/s^2 (downwards), in [0.5, 30]. Default 9.81. */
  gravity?: number;
}

/** Resolved options. */
export type CradleParams = Required<CradleOptions>;

/** Defaults. */
export const CRADLE_DEFAULTS: Readonly<CradleParams> = Object.freeze({ count: 5, radius: 0.1, length: 1, gravity: 9.81 });

/** Mass of each ball, kg. */
export const BALL_MASS = 1;

/** What the builder returns. */
export interface CradleHandles {
  /** The balls, left to right. */
  balls: number[];
  /** The anchors (x, y), m, left to right. */
  anchors: [number, number][];
  /** The options used. */
  params: CradleParams;
}

/** World options of the scene: 2D, its gravity, 2 substeps, no sleeping. */
export function cradleWorldOptions(options: CradleOptions = {}): PhysicsWorldOptions {
  const p = { ...CRADLE_DEFAULTS, ...options };
  return { dimensions: 2, capacity: 64, gravity: [0, -p.gravity], substeps: 2, sleep: false };
}

/**
 * Builds the row hanging at rest, anchors at y = 0 centred on x = 0, 2 radius apart: neighbouring
 * balls exactly touch (test/physics/cradle-hanging.test.ts: 1, 2 or 3 lifted at 5 to 80 degrees send
 * as many out of the far end at the entering speed within 3 %, the others under 2 % of it). The lift
 * must bring the balls to the bottom faster than the impact stage's resting speed, 2 g h with h the
 * world's substep (0.16 m/s at the defaults: lifts above 3 degrees); slower hits are left to the soft
 * contacts, which share the momentum out over the row.
 */
export function buildCradle(world: PhysicsWorld, options: CradleOptions = {}): CradleHandles {
  const params: CradleParams = { ...CRADLE_DEFAULTS, ...options };
  const { count, radius, length } = params;
  const balls: number[] = [];
  const anchors: [number, number][] = [];
  for (let i = 0; i < count; i++) {
    const x = (i - (count - 1) / 2) * 2 * radius;
    const ball = addBody(world, { position: [x, -length], radius, mass: BALL_MASS, restitution: 1, friction: 0 });
    addDistanceJoint(world, { b: ball, anchorA: [x, 0], length });
    balls.push(ball);
    anchors.push([x, 0]);
  }
  return { balls, anchors, params };
}

/**
 * Lifts the balls `from`..`to` (indices, inclusive) to the angle `angle` (rad from the downward
 * vertical, counter-clockwise positive), at rest; the others hang at rest.
 */
export function liftBalls(world: PhysicsWorld, h: CradleHandles, from: number, to: number, angle: number): void {
  const L = h.params.length;
  for (let i = 0; i < h.balls.length; i++) {
    const b = h.balls[i]!,
      [ax, ay] = h.anchors[i]!;
    const a = i >= from && i <= to ? angle : 0;
    setPosition(world, b, [ax + L * Math.sin(a), ay - L * Math.cos(a)]);
    setVelocity(world, b, [0, 0]);
  }
}
