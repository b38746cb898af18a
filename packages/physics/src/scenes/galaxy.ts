import { addBody } from '../bodies/api.js';
import { enableMutualGravity } from '../forces/api.js';
import { setGravitation } from '../forces/configure.js';
import { Rng } from '../math/rng.js';
import { assertPositive, optionOr } from '../validation/validate.js';
import type { PhysicsWorld } from '../world/options.js';
import { countAndSeed } from './options.js';
import type { SceneDefinition } from './types.js';

/**
 * Options of the `galaxy` scene.
 * @category Scenes
 */
export interface GalaxyOptions {
  /** Number of stars, integer in [1, 2_000_000]. Default 100_000. */
  count?: number;
  /** Seed. Default 1. */
  seed?: number;
  /** Barnes-Hut opening angle, > 0. Default 0.5. */
  openingAngle?: number;
  /** 'barnes-hut' (default) or 'direct'. */
  method?: 'barnes-hut' | 'direct';
}

/**
 * `galaxy` in game units (G = 1): a nucleus of mass 1,000 at the origin and N stars of total mass
 * 100 in an exponential disc of scale length 10 (surface density ~ e^(-r/10), truncated at 60),
 * each on a circular orbit about the mass enclosed inside its radius (v = sqrt(G M(r) / r), the
 * disc counted as if spherically enclosed) plus a 5% random velocity; softening 0.3. Every body takes
 * part in mutual gravity, by Barnes-Hut unless asked otherwise. 2D.
 * @category Scenes
 */
export const galaxy: SceneDefinition<GalaxyOptions, { stars: Uint32Array; nucleus: number }> = {
  name: 'galaxy',
  description: 'N stars in an exponential disc around a massive nucleus, mutual gravity by Barnes-Hut (G = 1 units); 2D',
  defaultCount: 100_000,
  worldOptions(options = {}) {
    const count = options.count ?? 100_000;
    return { dimensions: 2, capacity: count + 16, gravity: [0, 0], dt: 1 / 60 };
  },
  build(world: PhysicsWorld, options: GalaxyOptions = {}) {
    const where = 'galaxy';
    if (world.dimensions !== 2) throw new RangeError(`${where}: needs a 2D world, got dimensions ${world.dimensions}`);
    const { count, seed } = countAndSeed(where, options, ['count', 'seed', 'openingAngle', 'method'], 100_000, 1, 2_000_000);
    const theta = optionOr(where, 'openingAngle', options.openingAngle, 0.5, assertPositive);
    const method = options.method ?? 'barnes-hut';
    setGravitation(world, { constant: 1, softening: 0.3, method, openingAngle: theta });
    const rng = new Rng(seed);
    const Mn = 1000,
      Md = 100,
      scale = 10,
      rMax = 60;
    const m = Md / count;
    const nucleus = addBody(world, { position: [0, 0], mass: Mn });
    enableMutualGravity(world, nucleus);
    // Radii by inverse-transform sampling of r e^(-r / s) (the disc's radial mass distribution), then sorted so the enclosed mass is a running count.
    const radii = new Float64Array(count);
    for (let i = 0; i < count; i++) {
      let r: number;
      do {
        r = -scale * Math.log(rng.next() * rng.next() + 1e-300);
      } while (r > rMax || r < 0.5);
      radii[i] = r;
    }
    const order = Array.from(radii.keys()).sort((a, b) => radii[a]! - radii[b]!);
    const rank = new Float64Array(count);
    order.forEach((idx, k) => {
      rank[idx] = k;
    });
    const stars = new Uint32Array(count);
    const p = [0, 0],
      v = [0, 0];
    for (let i = 0; i < count; i++) {
      const r = radii[i]!,
        a = rng.range(0, 2 * Math.PI);
      const enclosed = Mn + m * rank[i]!;
      const speed = Math.sqrt(enclosed / r);
      p[0] = r * Math.cos(a);
      p[1] = r * Math.sin(a);
      v[0] = -speed * Math.sin(a) + 0.05 * speed * rng.normal();
      v[1] = speed * Math.cos(a) + 0.05 * speed * rng.normal();
      stars[i] = addBody(world, { position: p, velocity: v, mass: m });
      enableMutualGravity(world, stars[i]!);
    }
    return { stars, nucleus };
  },
};
