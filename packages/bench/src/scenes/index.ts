import { MAX_CAPACITY, SCENES, type SceneDefinition } from '@bitphysics/physics';
import { ballsInBoxBench } from './balls-in-box.js';
import { boxPile3DBench } from './box-pile-3d.js';
import { clothBench } from './cloth.js';
import { fireworksBench } from './fireworks.js';
import { fountainBench } from './fountain.js';
import { galaxyBench } from './galaxy.js';
import { jointGridBench } from './joint-grid.js';
import { particlesBench } from './particles.js';
import { pyramidBench } from './pyramid.js';
import { pyramid3DBench } from './pyramid-3d.js';
import { spheresInBoxBench } from './spheres-in-box.js';
import type { BenchScene } from './types.js';

/** Bench-side scene adapters by scene name; add one a scene that needs a limit, ids or extra fields. */
const BENCH_SCENES: Readonly<Record<string, BenchScene>> = Object.freeze({
  [ballsInBoxBench.name]: ballsInBoxBench,
  [particlesBench.name]: particlesBench,
  [spheresInBoxBench.name]: spheresInBoxBench,
  [galaxyBench.name]: galaxyBench,
  [fireworksBench.name]: fireworksBench,
  [fountainBench.name]: fountainBench,
  [pyramidBench.name]: pyramidBench,
  [jointGridBench.name]: jointGridBench,
  [clothBench.name]: clothBench,
  [boxPile3DBench.name]: boxPile3DBench,
  [pyramid3DBench.name]: pyramid3DBench,
});

/** A scene as the bench sees it: the physics package's definition plus the bench adapter. */
export interface ResolvedScene {
  /** The physics package's definition (name, description, defaultCount, builder). */
  readonly definition: SceneDefinition<{ count?: number; seed?: number }, unknown>;
  /** The bench adapter; a generic one (limit = world capacity, no extras) for scenes without their own. */
  readonly bench: BenchScene;
}

/** Names of every scene in the physics package's registry, in registry order. */
export function sceneNames(): string[] {
  return Object.keys(SCENES);
}

/** The scene called `name`, or undefined if the physics package has none by that name. */
export function resolveScene(name: string): ResolvedScene | undefined {
  if (!Object.hasOwn(SCENES, name)) return undefined;
  const definition = SCENES[name]!;
  const bench = BENCH_SCENES[name] ?? { name, maxCount: MAX_CAPACITY };
  return { definition, bench };
}

export type { BenchScene, ExtraColumn, ExtraValue, SceneParam, SceneProbe } from './types.js';
