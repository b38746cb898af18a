import { Rng } from '../math/rng.js';
import { assertInRange, assertNonNegative, assertPositive, optionOr } from '../validation/validate.js';
import type { PhysicsWorld } from '../world/options.js';
import { addBallsInBox } from './cubes.js';
import { countAndSeed } from './options.js';
import type { SceneDefinition } from './types.js';

/**
 * Options of the `balls-in-box` scene.
 * @category Scenes
 */
export interface BallsInBoxOptions {
  /** Number of balls, integer in [1, 10_000_000]. Default 1000. */
  count?: number;
  /** Seed of the jitter. Default 1. */
  seed?: number;
  /** Ball radius, m, > 0. Default 0.5 m. */
  radius?: number;
  /** Grid pitch of the starting layout, m; must exceed 2 radius. Default 1.5 m. */
  spacing?: number;
  /** Restitution of balls and walls, [0, 1]. Default 0.5. */
  restitution?: number;
  /** Friction coefficient of balls and walls, >= 0. Default 0.1. */
  friction?: number;
  /** Mass of each ball, kg, > 0. Default 1 kg. */
  mass?: number;
}

/**
 * The resolved layout of `balls-in-box`: what a peer engine needs to build the same scene.
 * @category Scenes
 */
export interface BallsInBoxLayout {
  /** Number of balls. */
  count: number;
  /** Starting centres, m: x0, y0, x1, y1, ... */
  positions: Float64Array;
  /** Ball radius, m. */
  radius: number;
  /** Ball mass, kg. */
  mass: number;
  /** Restitution, friction. */
  restitution: number;
  friction: number;
  /** Inner corners of the box, m. */
  min: [number, number];
  max: [number, number];
  /** Gravity, m/s^2. */
  gravity: [number, number];
}

const OPTIONS = ['count', 'seed', 'radius', 'spacing', 'restitution', 'friction', 'mass'] as const;

/**
 * Computes the `balls-in-box` layout: `count` balls on a grid of pitch `spacing`, jittered by up to
 * 40% of the free space between neighbours (so nothing overlaps), in a closed box ceil(2 sqrt(N))
 * cells wide and one cell taller than the rows of balls; gravity (0, -10) m/s^2.
 * @throws TypeError | RangeError on bad options.
 * @category Scenes
 */
export function ballsInBoxLayout(options: BallsInBoxOptions = {}): BallsInBoxLayout {
  const where = 'balls-in-box';
  const { count, seed } = countAndSeed(where, options, OPTIONS, 1000, 1, 10_000_000);
  const radius = optionOr(where, 'radius', options.radius, 0.5, assertPositive);
  const spacing = optionOr(where, 'spacing', options.spacing, 1.5, assertPositive);
  if (!(spacing > 2 * radius)) throw new RangeError(`${where}: spacing must exceed 2 radius (${2 * radius}), got ${spacing}`);
  const restitution = optionOr(where, 'restitution', options.restitution, 0.5, assertInRange, 0, 1);
  const friction = optionOr(where, 'friction', options.friction, 0.1, assertNonNegative);
  const mass = optionOr(where, 'mass', options.mass, 1, assertPositive);

  const columns = Math.max(1, Math.ceil(2 * Math.sqrt(count)));
  const rows = Math.ceil(count / columns);
  const width = columns * spacing;
  const height = (rows + 1) * spacing;
  const rng = new Rng(seed);
  const jitter = 0.4 * (spacing - 2 * radius);
  const positions = new Float64Array(2 * count);
  for (let i = 0; i < count; i++) {
    const col = i % columns,
      row = Math.floor(i / columns);
    positions[2 * i] = (col + 0.5) * spacing + rng.range(-jitter, jitter);
    positions[2 * i + 1] = (row + 0.5) * spacing + rng.range(-jitter, jitter);
  }
  return {
    count,
    positions,
    radius,
    mass,
    restitution,
    friction,
    min: [0, 0],
    max: [width, height],
    gravity: [0, -10],
  };
}

/**
 * Handles returned by the `balls-in-box` builder.
 * @category Scenes
 */
export interface BallsInBoxHandles {
  /** Entity ids of the balls, in layout order. */
  balls: Uint32Array;
  /** The layout used. */
  layout: BallsInBoxLayout;
}

/**
 * `balls-in-box`: N balls of radius 0.5 m (restitution 0.5, friction 0.1) fall from a jittered 1.5 m
 * grid into a closed box; gravity -10 m/s^2. The benchmark scene compared against rapier2d and matter-js.
 * @category Scenes
 */
export const ballsInBox: SceneDefinition<BallsInBoxOptions, BallsInBoxHandles> = {
  name: 'balls-in-box',
  description: 'N balls (r 0.5 m, e 0.5, mu 0.1) fall from a jittered grid into a closed box; 2D',
  defaultCount: 1000,
  worldOptions(options = {}) {
    const count = options.count ?? 1000;
    return { dimensions: 2, capacity: count + 16, gravity: [0, -10] };
  },
  build(world: PhysicsWorld, options: BallsInBoxOptions = {}): BallsInBoxHandles {
    if (world.dimensions !== 2) throw new RangeError(`balls-in-box: needs a 2D world, got dimensions ${world.dimensions}`);
    const layout = ballsInBoxLayout(options);
    const balls = addBallsInBox(world, layout, 2);
    return { balls, layout };
  },
};
