import { addComponent, type createEntityIndex, hasComponent, observe, onAdd, type World } from 'bitecs';
import type { CollisionState } from '../collision/state.js';
import type { Rng } from '../math/rng.js';
import type { ThreadPool } from '../threads/pool.js';
import { assertPositive } from '../validation/validate.js';
import type { ClothState } from './cloth-state.js';
import type { Components } from './components.js';
import type { ForceLawSettings } from './force-settings.js';
import type { IntegratorName } from './integrator-names.js';
import type { JointState } from './joint-state-2d.js';
import type { WorldScratch } from './scratch.js';
import type { StageName } from './stage-names.js';

/** Options of `createPhysicsWorld`. Every field is optional; unknown fields and null values are rejected. */
/**
 * Largest fixed time step a world accepts, s: 1e6 (about 11.6 days, enough for orbits in SI units).
 * Bounding it keeps every per-step quantity finite: emitter spawns rate x dt < 2^53 with
 * MAX_EMITTER_RATE, lifetimes, drag rates.
 * @category World and step
 */
export const MAX_TIME_STEP = 1e6;

/**
 * Throws unless dt is a number in (0, MAX_TIME_STEP]; the message names `where`. @throws TypeError | RangeError
 * @category World and step
 */
export function assertTimeStep(where: string, dt: unknown): asserts dt is number {
  assertPositive(where, 'dt', dt);
  if (dt > MAX_TIME_STEP) throw new RangeError(`${where}: dt must be <= ${MAX_TIME_STEP} s (MAX_TIME_STEP), got ${dt}`);
}

/**
 * Options of `createPhysicsWorld`; every field is optional (its default is given), units SI.
 * @category World and step
 */
export interface PhysicsWorldOptions {
  /** 2 for a planar world (x, y), 3 for a spatial one (x, y, z). Default 2. */
  dimensions?: 2 | 3;
  /**
   * Most entities alive at once (bodies, walls, springs, emitters: every entity counts).
   * Integer in [1, 16_777_216]. Stores are allocated once at this size. Default 10_000.
   */
  capacity?: number;
  /** Uniform gravitational acceleration, m/s^2, an array of `dimensions` numbers. Default (0, -9.81[, 0]). */
  gravity?: ArrayLike<number>;
  /** Fixed time step, s, > 0 and at most MAX_TIME_STEP (1e6 s). Default 1/60. */
  dt?: number;
  /** Substeps a step: the force, integrate, collide and constraint stages run this many times with dt / substeps. Integer in [1, 64]. Default 1. */
  substeps?: number;
  /** Integration scheme by name; see `INTEGRATOR_NAMES`. Default 'semi-implicit-euler'. */
  integrator?: IntegratorName;
  /** Seed of the world's random number generator (scenes, emitters, turbulence). Any finite number. Default 1. */
  seed?: number;
  /**
   * Contact solver substeps a step (Box2D v3's soft step: gravity, contacts and positions advance in
   * this many substeps, contacts found once). Integer in [1, 16]. Default 4. The least a step takes:
   * steps whose ball contacts are small take more (2 cm balls at dt 1/60: 12), unless
   * `world.collision.settings.autoSubsteps` is set to false (see solver/contact-scale.ts).
   */
  solverSubsteps?: number;
  /** Sequential-impulse passes per solver substep. Integer in [1, 50]. Default 1. */
  solverIterations?: number;
  /**
   * Approach speed below which a contact does not bounce, m/s, >= 0 (restitution is treated as 0
   * below it, so resting bodies do not jitter). Default 0.5 m/s for contacts with restitution < 1, and
   * 0 for perfectly elastic ones (e = 1 bounces at any speed); given, it applies to both. Box2D uses
   * the same idea with 1 m/s. See `CollisionSettings.restitutionThreshold` for the trade-off.
   */
  restitutionThreshold?: number;
  /**
   * Whether bare particles (no force accumulator, no collider) keep `PreviousPosition`, which
   * renderers interpolate from. Bodies with forces or colliders always keep it (contacts need it).
   * false saves one write per particle per step in headless runs. Default true.
   */
  interpolation?: boolean;
  /**
   * Whether resting islands of colliding bodies go to sleep (skipped until something wakes them; see
   * islands/sleep.ts). Default true.
   */
  sleep?: boolean;
  /**
   * Threads that share the heavy loops (integration, per-body force laws), integer in [1, 64]: the
   * calling thread and threads - 1 workers (Node worker_threads or browser Workers) on component
   * stores allocated on SharedArrayBuffer. Results are identical to the bit to one thread's. Default
   * 1 (no workers, no SharedArrayBuffer). A world with threads > 1 should be ended with
   * `disposeWorld` (its workers never keep Node alive, but they hold memory until disposed). Loops
   * shorter than MIN_PARALLEL_PER_THREAD entities a thread run on the calling thread alone. In a
   * browser the page must be cross-origin isolated, and the loops run on one thread until the
   * workers have started (`threadsReady`). More than 1 needs `enableThreads()` called once before
   * (it loads the pool and its kernels; a program without it does not bundle them): without it
   * `createPhysicsWorld` throws an Error that names it.
   */
  threads?: number;
}

/**
 * The largest capacity a world accepts (2^24 entities).
 * @category World and step
 */
export const MAX_CAPACITY = 16_777_216;

/**
 * Wall-clock milliseconds spent in each stage during the most recent step (all substeps summed).
 * @category World and step
 */
export type StageTimings = Record<StageName, number>;

/**
 * The data a physics world carries besides bitecs' own bookkeeping.
 * @category World and step
 */
export interface PhysicsWorldContext {
  /** 2 or 3. */
  readonly dimensions: 2 | 3;
  /** Most entities alive at once. */
  readonly capacity: number;
  /** Uniform gravity, m/s^2 (x, y, z); z is 0 in 2D. Mutable: write through `setGravity`. */
  readonly gravity: Float64Array;
  /** Fixed step, s. Change with `setTimeStep`. */
  dt: number;
  /** Substeps per step. */
  substeps: number;
  /** Current (sub)step length, s, set by `step` while it runs: dt / substeps. */
  h: number;
  /** Name of the integration scheme in use. */
  integrator: IntegratorName;
  /** Simulated time, s, of the current state. Force laws that vary in time read it (integrators set trial times). */
  time: number;
  /** Simulated time at the start of the current (sub)step, s (set by `step`; the rocket law reads it). */
  substepStart: number;
  /** Constants and fields the force laws read (G, softening, Coulomb constant, wind); see world/force-settings.ts. */
  readonly laws: ForceLawSettings;
  /** Whole steps taken since creation. */
  steps: number;
  /** The world's seeded random number generator. */
  readonly rng: Rng;
  /** Component stores, see `Components`. */
  readonly components: Components;
  /**
   * The systems of each stage, run in the order of `STAGES`. Add your own with `addSystem`. A new world
   * holds the core's built-in systems; a feature's (emitters, 3D shapes and joints, cloth) are put in at
   * their place in `PIPELINE` when the feature is first used (world/install.ts).
   */
  readonly stages: Record<StageName, System[]>;
  /**
   * Internal: the built-in systems ever installed in `stages`, by name (world/install.ts PIPELINE_ORDER).
   * A name stays once installed, so a built-in taken out with `removeSystem` is not put back.
   */
  readonly builtins: Map<string, System>;
  /** Collision configuration, broadphase grid, contacts and solver scratch; see `CollisionState`. */
  readonly collision: CollisionState;
  /** Joint solver state: packed rows, warm-start impulses, break events of the last step (`joints.breaks`); see world/joint-state-2d.ts. */
  readonly joints: JointState;
  /** Cloth solver state (packed links, iterations, largest stretch); see world/cloth-state.ts. */
  readonly cloth: ClothState;
  /** Milliseconds spent in each stage in the last step. */
  readonly timings: StageTimings;
  /**
   * Count of times each slot has held an entity (Uint32, capacity + 1; 0 = never used). Caches keyed by
   * slot compare it so data of a removed body never carries over to the body that recycles its slot,
   * and an entity's handle is slot + (spawnStamp[slot] - 1) * 2^25 (see world/handles.ts).
   */
  readonly spawnStamp: Uint32Array;
  /** Internal: bitecs' entity index, read for the live count and the highest id. */
  readonly entityIndex: ReturnType<typeof createEntityIndex>;
  /** Whether bare particles keep PreviousPosition (see PhysicsWorldOptions.interpolation). */
  interpolation: boolean;
  /** Threads of the world (see PhysicsWorldOptions.threads). */
  readonly threads: number;
  /** Internal: the worker pool of a world with threads > 1 (null otherwise, or once disposed). */
  threadPool: ThreadPool | null;
  /** Internal: removal hooks (springs, joints and caches that reference a removed entity). */
  readonly removeHooks: Array<(world: PhysicsWorld, eid: number) => void>;
  /**
   * Internal: the state a feature makes on its first use, by the name it registers for snapshots
   * (world/external-state.ts): `shapes3d`, `joints3d`, `contacts3d`, `meshes3d`, `particles` (the
   * emitters' particle book), `particle-archetypes`, `dissipation`, `contact-scale`. Undefined until
   * the feature is used. Snapshots carry each entry through its registration, not as world state.
   */
  readonly features: Record<string, object | undefined>;
  /**
   * Internal: the buffers, kernel arguments and caches the systems and snapshots keep for this world
   * between calls (world/scratch.ts). Not state: snapshots do not store it, restore leaves it as it is.
   */
  readonly scratch: WorldScratch<PhysicsWorld>;
}

/**
 * A physics world: a bitecs world (entities and their component stores) whose fields are those of
 * {@link PhysicsWorldContext}: `components` (the stores, indexed by slot), `dimensions`, `capacity`,
 * `dt` and `substeps`, `time` and `steps`, `gravity`, `collision` (settings, contacts, shapes,
 * sleep), `joints`, `cloth`, `laws` (force-law settings), `threads`, and the rest listed there. Made by
 * {@link createPhysicsWorld}; advanced by {@link step}; ended by {@link disposeWorld}.
 * @category World and step
 */
export type PhysicsWorld = World<PhysicsWorldContext>;

/**
 * A system: a plain function of the world, run once per (sub)step in its stage.
 * @category World and step
 */
export type System = (world: PhysicsWorld) => void;

/**
 * Declares `component` a force law: whenever it is added to an entity, the Force accumulator is
 * added too, so the law's system has somewhere to write. Use it for your own force-law components.
 * @category World and step
 */
export function registerForceLaw(world: PhysicsWorld, component: object): void {
  const force = world.components.Force;
  observe(world, onAdd(component), (eid: number) => {
    addComponentIfMissing(world, eid, force);
  });
}

/**
 * Adds `component` to `eid` unless it already has it (then its data is left untouched).
 * @category World and step
 */
export function addComponentIfMissing(world: PhysicsWorld, eid: number, component: object): void {
  if (!hasComponent(world, eid, component)) addComponent(world, eid, component);
}

/**
 * Ends a world's worker threads (a world made with threads > 1); the world still steps, on the
 * calling thread alone. Safe on any world and to call twice.
 * @category World and step
 */
export function disposeWorld(world: PhysicsWorld): void {
  const pool = world.threadPool;
  if (pool === null) return;
  world.threadPool = null;
  pool.dispose();
}

/**
 * Resolves once the workers of a world with threads > 1 have started (at once for one thread). A
 * browser page's main thread cannot wait for them, so its loops run on one thread until then; Node
 * waits by itself at the first parallel loop.
 * @category World and step
 */
export function threadsReady(world: PhysicsWorld): Promise<void> {
  return world.threadPool === null ? Promise.resolve() : world.threadPool.ready;
}
