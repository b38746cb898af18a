import { addEmitter } from '../particles/emitter.js';
import type { PhysicsWorld } from '../world/options.js';
import { countAndSeed } from './options.js';
import type { SceneDefinition } from './types.js';

/**
 * Options of the `fireworks` scene.
 * @category Scenes
 */
export interface FireworksOptions {
  /** Target number of live sparks in steady state (sets the world's capacity and the shell rate). Default 50_000. */
  count?: number;
  /** Seed. Default 1. */
  seed?: number;
}

/**
 * `fireworks`: steady churn. Shells rise from the ground at a constant rate, burst after ~1 s into
 * 200 sparks with quadratic drag that live 1 to 2 s, a third of which burst again into 20 (second
 * generation); the rate is set so about `count` sparks are alive, and the world's capacity is a
 * quarter above that with 'recycle-oldest', so spawn and expiry happen every step without the world
 * ever filling. Gravity (0, -9.81). 2D.
 * @category Scenes
 */
export const fireworks: SceneDefinition<FireworksOptions, { shells: number; sparks: number; embers: number }> = {
  name: 'fireworks',
  description: 'Steady churn: shells burst into sparks that burst again, spawn and expiry every step; 2D',
  defaultCount: 50_000,
  worldOptions(options = {}) {
    const count = options.count ?? 50_000;
    return { dimensions: 2, capacity: Math.ceil(count * 1.25) + 64, gravity: [0, -9.81], seed: options.seed ?? 1 };
  },
  build(world: PhysicsWorld, options: FireworksOptions = {}) {
    const where = 'fireworks';
    if (world.dimensions !== 2) throw new RangeError(`${where}: needs a 2D world, got dimensions ${world.dimensions}`);
    const { count } = countAndSeed(where, options, ['count', 'seed'], 50_000, 100, 10_000_000);
    const embers = addEmitter(world, {
      speed: [1, 3],
      lifetime: [0.5, 1],
      policy: 'recycle-oldest',
      particle: { mass: 0.001, quadraticDrag: 2e-5, colorStart: 0xffee88, colorEnd: 0xff3300, sizeStart: 0.15, sizeEnd: 0.02 },
    });
    const sparks = addEmitter(world, {
      speed: [4, 12],
      lifetime: [1, 2],
      inheritVelocity: 1,
      policy: 'recycle-oldest',
      particle: { mass: 0.002, quadraticDrag: 4e-5, colorStart: 0xffffff, colorEnd: 0xff6600, sizeStart: 0.25, sizeEnd: 0.05 },
      onDeath: { emitter: embers, count: 7, maxGeneration: 2 },
    });
    // Each shell makes 200 sparks living 1.5 s on average and 200 x 7 embers living 0.75 s:
    // live sparks per shell-per-second = 200 x 1.5 + 1400 x 0.75 = 1350.
    const rate = count / 1350;
    const shells = addEmitter(world, {
      position: [0, 0],
      shape: 'line',
      size: 60,
      rate,
      direction: [0, 1],
      spread: 0.15,
      speed: [28, 34],
      lifetime: [0.9, 1.2],
      policy: 'recycle-oldest',
      particle: { mass: 0.1, colorStart: 0xffcc66, sizeStart: 0.3 },
      onDeath: { emitter: sparks, count: 200, maxGeneration: 1 },
    });
    return { shells, sparks, embers };
  },
};
