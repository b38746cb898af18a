import { bitphysicsEngine } from './bitphysics.js';
import { box2dWasmEngine } from './box2d-wasm.js';
import { joltEngine } from './jolt.js';
import { matterEngine } from './matter.js';
import { plainLoopEngine } from './plain-loop.js';
import { planckEngine } from './planck.js';
import { rapier2dEngine, rapier2dSimdEngine } from './rapier2d.js';
import { rapier3dEngine, rapier3dSimdEngine } from './rapier3d.js';
import type { EngineAdapter } from './types.js';

/** Our engine's name; it runs in every benchmark and is the numerator of every ratio. */
export const OURS = 'bitphysics';

/** Every engine the bench can run, by name (`--vs` takes these names). */
export const ENGINES: Readonly<Record<string, EngineAdapter>> = Object.freeze({
  [bitphysicsEngine.name]: bitphysicsEngine,
  [rapier2dEngine.name]: rapier2dEngine,
  [rapier3dEngine.name]: rapier3dEngine,
  [rapier2dSimdEngine.name]: rapier2dSimdEngine,
  [rapier3dSimdEngine.name]: rapier3dSimdEngine,
  [joltEngine.name]: joltEngine,
  [matterEngine.name]: matterEngine,
  [plainLoopEngine.name]: plainLoopEngine,
  [planckEngine.name]: planckEngine,
  [box2dWasmEngine.name]: box2dWasmEngine,
});

/** Names of the engines that can build `scene`, ours first. */
export function enginesFor(scene: string): string[] {
  return Object.values(ENGINES)
    .filter((e) => e.supports(scene))
    .map((e) => e.name);
}

export type { BodySnapshot, EngineAdapter, EngineInstance, EngineStats, SceneRunOptions } from './types.js';
