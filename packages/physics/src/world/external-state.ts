import type { PhysicsWorld } from './options.js';

/**
 * Per-world state a feature makes on its first use and keeps in `world.features` under its name (3D
 * shapes, joints and contacts, meshes, the emitters' particle book and archetype tables, dissipation,
 * contact scale), which `snapshot` and `restore` carry by this registration: its name in the
 * snapshot's header, how to make it in a world that has none, and which of its keys are code. Every
 * module that keeps such state registers it here once. Per-world buffers and caches that are not state
 * go in `world.scratch` (world/scratch.ts); the snapshot test fails for a module-level WeakMap keyed by
 * a world or by one of its parts.
 * @category Snapshots
 */
export interface ExternalWorldState {
  /** Name in the snapshot header (unique). */
  readonly name: string;
  /** The state of `world`; with `create` true it is made if missing, else undefined when the world has none. */
  get(world: PhysicsWorld, create: boolean): object | undefined;
  /** Forgets the state of `world` (a restored world whose snapshot had none). */
  clear(world: PhysicsWorld): void;
  /** Keys of the state that are configuration made by code (functions), kept as they are in the target world. */
  readonly keep?: readonly string[];
}

const registry = new Map<string, ExternalWorldState>();

/**
 * Registers per-world state held outside the world (see ExternalWorldState). @throws Error on a duplicate name.
 * @category Snapshots
 */
export function registerExternalWorldState(state: ExternalWorldState): void {
  if (registry.has(state.name)) throw new Error(`registerExternalWorldState: name '${state.name}' is already registered`);
  registry.set(state.name, state);
}

/**
 * Registers per-world state kept in `world.features` under `name` (see ExternalWorldState), made by
 * `make` on first use. @returns its getter: the state of a world, made if missing when `create` is
 * true, else undefined when the world has none. @throws Error on a duplicate name.
 * @category Snapshots
 */
export function registerFeatureState<T extends object>(
  name: string,
  make: (world: PhysicsWorld) => T,
): (world: PhysicsWorld, create: boolean) => T | undefined {
  const get = (world: PhysicsWorld, create: boolean): T | undefined => {
    let s = world.features[name] as T | undefined;
    if (s === undefined && create) {
      s = make(world);
      world.features[name] = s;
    }
    return s;
  };
  registerExternalWorldState({
    name,
    get,
    clear: (world) => {
      world.features[name] = undefined;
    },
  });
  return get;
}

/**
 * Every registered external state, in registration order.
 * @category Snapshots
 */
export function externalWorldStates(): readonly ExternalWorldState[] {
  return [...registry.values()];
}
