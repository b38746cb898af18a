import { addEmitter } from '../particles/emitter.js';
import type { PhysicsWorld } from '../world/options.js';
import { countAndSeed } from './options.js';
import type { SceneDefinition } from './types.js';

/**
 * Options of the `fountain` scene.
 * @category Scenes
 */
export interface FountainOptions {
  /** Live drops in steady state, integer in [100, 16_000_000] (sets the rate and the capacity). Default 1_000_000. */
  count?: number;
  /** Seed. Default 1. */
  seed?: number;
}

/**
 * Mean lifetime of a drop, s: lifetimes are uniform in [2/3, 1] s.
 * @category Scenes
 */
export const FOUNTAIN_MEAN_LIFETIME = 5 / 6;

/**
 * `fountain`: churn at scale. One emitter on a 0.5 m disc at the origin throws bare drops (Position,
 * Velocity, Lifetime, Particle: gravity only) upwards within 0.35 rad of vertical at 9 to 13 m/s;
 * each lives 2/3 to 1 s. The rate is count / (5/6 s), so after the first second about `count` drops
 * are alive and count / 50 are born and as many expire every step of 1/60 s (1,000,000 live: 20,000
 * births and 20,000 deaths a step). Capacity: count x 1.05 + 16, policy 'drop-new' (the margin is
 * never reached: the live count varies by a few hundred). Gravity (0, -9.81). 2D.
 * @category Scenes
 */
export const fountain: SceneDefinition<FountainOptions, { emitter: number }> = {
  name: 'fountain',
  description: 'Churn at scale: a fountain of count bare drops, count/50 born and expiring every step; 2D',
  defaultCount: 1_000_000,
  worldOptions(options = {}) {
    const count = options.count ?? 1_000_000;
    return { dimensions: 2, capacity: Math.ceil(count * 1.05) + 16, gravity: [0, -9.81], seed: options.seed ?? 1 };
  },
  build(world: PhysicsWorld, options: FountainOptions = {}) {
    const where = 'fountain';
    if (world.dimensions !== 2) throw new RangeError(`${where}: needs a 2D world, got dimensions ${world.dimensions}`);
    const { count } = countAndSeed(where, options, ['count', 'seed'], 1_000_000, 100, 16_000_000);
    const emitter = addEmitter(world, {
      position: [0, 0],
      shape: 'disc',
      size: 0.5,
      direction: [0, 1],
      spread: 0.35,
      speed: [9, 13],
      lifetime: [2 / 3, 1],
      rate: count / FOUNTAIN_MEAN_LIFETIME,
      policy: 'drop-new',
      particle: { colorStart: 0x9fd8ff, colorEnd: 0x2a6fdb, sizeStart: 0.06, sizeEnd: 0.03, alphaStart: 0.9, alphaEnd: 0.2 },
    });
    return { emitter };
  },
};
