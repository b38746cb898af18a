import { addComponent, createEntityIndex, createWorld, hasComponent, observe, onAdd, type World } from 'bitecs';
import { createComponents, DEFAULT_MATERIAL, DEFAULT_RADIUS, LAZY_COMPONENTS, materializeStore, type Components } from './components.js';
import { createCollisionState, type CollisionState } from './collision/state.js';
import { createStages, type StageName, type System, STAGES } from './pipeline/stages.js';
import { INTEGRATOR_NAMES, type IntegratorName } from './integrators/names.js';
import { Rng } from './rng.js';
import { createForceLawSettings, type ForceLawSettings } from './forces/settings.js';
import { removeSpringsOf } from './forces/spring.js';
import { wakeTouching } from './collision/sleep.js';
import { createJointState, type JointState } from './joints/state.js';
import { removeJointsOf } from './joints/remove.js';
import { createClothState, type ClothState } from './cloth/state.js';
import { createThreadPool, type ThreadPool } from './threads/pool.js';
import { shareStore, shareStores } from './threads/shared-stores.js';
import { assertBoolean, assertFinite, assertInteger, assertNonNegative, assertOptions, assertPositive, assertVector, describe } from './validate.js';

/** Options of `createPhysicsWorld`. Every field is optional; unknown fields and null values are rejected. */
/**
 * Largest fixed time step a world accepts, s: 1e6 (about 11.6 days, enough for orbits in SI units).
 * Bounding it keeps every per-step quantity finite: emitter spawns rate x dt < 2^53 with
 * MAX_EMITTER_RATE, lifetimes, drag rates.
 */
export const MAX_TIME_STEP = 1e6;

/** Throws unless dt is a number in (0, MAX_TIME_STEP]; the message names `where`. @throws TypeError | RangeError */
export function assertTimeStep(where: string, dt: unknown): asserts dt is number {
  assertPositive(where, 'dt', dt);
  if (dt > MAX_TIME_STEP) throw new RangeError(`${where}: dt must be <= ${MAX_TIME_STEP} s (MAX_TIME_STEP), got ${dt}`);
}

/** Options of `createPhysicsWorld`; every field is optional (its default is given), units SI. */
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
   * this many substeps, contacts found once). Integer in [1, 16]. Default 4.
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
   * collision/sleep.ts). Default true.
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
   * workers have started (`threadsReady`).
   */
  threads?: number;
}

const KNOWN_OPTIONS = [
  'dimensions', 'capacity', 'gravity', 'dt', 'substeps', 'integrator', 'seed',
  'solverSubsteps', 'solverIterations', 'restitutionThreshold', 'interpolation', 'sleep', 'threads',
] as const;

/** The largest capacity a world accepts (2^24 entities). */
export const MAX_CAPACITY = 16_777_216;

/** Wall-clock milliseconds spent in each stage during the most recent step (all substeps summed). */
export type StageTimings = Record<StageName, number>;

/** The data a physics world carries besides bitecs' own bookkeeping. */
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
  /** Constants and fields the force laws read (G, softening, Coulomb constant, wind); see forces/settings.ts. */
  readonly laws: ForceLawSettings;
  /** Whole steps taken since creation. */
  steps: number;
  /** The world's seeded random number generator. */
  readonly rng: Rng;
  /** Component stores, see `Components`. */
  readonly components: Components;
  /** The systems of each stage, run in the order of `STAGES`. Add your own with `addSystem`. */
  readonly stages: Record<StageName, System[]>;
  /** Collision configuration, broadphase grid, contacts and solver scratch; see `CollisionState`. */
  readonly collision: CollisionState;
  /** Joint solver state: packed rows, warm-start impulses, break events of the last step (`joints.breaks`); see joints/state.ts. */
  readonly joints: JointState;
  /** Cloth solver state (packed links, iterations, largest stretch); see cloth/state.ts. */
  readonly cloth: ClothState;
  /** Milliseconds spent in each stage in the last step. */
  readonly timings: StageTimings;
  /**
   * Count of times each slot has held an entity (Uint32, capacity + 1; 0 = never used). Caches keyed by
   * slot compare it so data of a removed body never carries over to the body that recycles its slot,
   * and an entity's handle is slot + (spawnStamp[slot] - 1) * 2^25 (see handles.ts).
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
}

/** A bitecs world carrying a physics context. */
export type PhysicsWorld = World<PhysicsWorldContext>;

/**
 * Creates a physics world: component stores of fixed capacity, the staged pipeline, collision
 * state and a seeded random number generator.
 *
 * @throws TypeError on options that are not an object, an unknown option name, a null option or a value of
 *   the wrong type (booleans must be booleans).
 * @throws RangeError on a value out of range (dt <= 0, capacity < 1, substeps not an integer, ...).
 * @example
 * const world = createPhysicsWorld({ dimensions: 2, capacity: 1000, gravity: [0, -9.81] });
 */
export function createPhysicsWorld(options: PhysicsWorldOptions = {}): PhysicsWorld {
  const where = 'createPhysicsWorld';
  assertOptions(where, options, KNOWN_OPTIONS);
  const dimensions = options.dimensions ?? 2;
  if (dimensions !== 2 && dimensions !== 3) {
    throw new RangeError(`${where}: dimensions must be 2 or 3, got ${describe(dimensions)}`);
  }
  const capacity = options.capacity ?? 10_000;
  assertInteger(where, 'capacity', capacity, 1, MAX_CAPACITY);
  const gravity = new Float64Array(3);
  if (options.gravity !== undefined) {
    assertVector(where, 'gravity', options.gravity, dimensions);
    for (let i = 0; i < dimensions; i++) gravity[i] = options.gravity[i]!;
  } else {
    gravity[1] = -9.81;
  }
  const dt = options.dt ?? 1 / 60;
  assertTimeStep(where, dt);
  const substeps = options.substeps ?? 1;
  assertInteger(where, 'substeps', substeps, 1, 64);
  const integrator = options.integrator ?? 'semi-implicit-euler';
  if (typeof integrator !== 'string' || !(INTEGRATOR_NAMES as readonly string[]).includes(integrator)) {
    throw new RangeError(`${where}: integrator must be one of ${INTEGRATOR_NAMES.map((n) => `'${n}'`).join(', ')}, got ${describe(integrator)}`);
  }
  const seed = options.seed ?? 1;
  assertFinite(where, 'seed', seed);
  const solverSubsteps = options.solverSubsteps ?? 4;
  assertInteger(where, 'solverSubsteps', solverSubsteps, 1, 16);
  const solverIterations = options.solverIterations ?? 1;
  assertInteger(where, 'solverIterations', solverIterations, 1, 50);
  const restitutionThreshold = options.restitutionThreshold ?? 0.5;
  assertNonNegative(where, 'restitutionThreshold', restitutionThreshold);
  const interpolation = options.interpolation ?? true;
  assertBoolean(where, 'interpolation', interpolation);
  const sleep = options.sleep ?? true;
  assertBoolean(where, 'sleep', sleep);
  const threads = options.threads ?? 1;
  assertInteger(where, 'threads', threads, 1, 64);
  // Made before anything else, so a missing SharedArrayBuffer or Worker throws before any allocation.
  const threadPool = threads > 1 ? createThreadPool(where, threads) : null;

  const entityIndex = createEntityIndex();
  const components = createComponents(capacity);
  if (threadPool !== null) shareStores(components, capacity);
  const timings = {} as StageTimings;
  for (const s of STAGES) timings[s] = 0;
  const context: PhysicsWorldContext = {
    dimensions,
    capacity,
    gravity,
    dt,
    substeps,
    h: dt / substeps,
    integrator,
    time: 0,
    substepStart: 0,
    laws: createForceLawSettings(),
    steps: 0,
    rng: new Rng(seed),
    components,
    stages: createStages(),
    // Given: it applies to every contact; not given: e = 1 contacts bounce at any speed (CollisionSettings).
    collision: createCollisionState(capacity, {
      solverSubsteps, solverIterations, sleep, ...(options.restitutionThreshold === undefined ? {} : { restitutionThreshold }),
    }),
    joints: createJointState(),
    cloth: createClothState(),
    timings,
    spawnStamp: new Uint32Array(capacity + 1),
    entityIndex,
    removeHooks: [removeSpringsOf, removeJointsOf, wakeTouching],
    interpolation,
    threads,
    threadPool,
  };
  const world = createWorld(context, entityIndex) as PhysicsWorld;
  installDefaults(world);
  return world;
}

/**
 * Resets a component's fields for an entity when the component is added (ids are recycled and
 * bitecs leaves old data behind), and makes every force-law component bring the Force accumulator.
 */
function installDefaults(world: PhysicsWorld): void {
  const c = world.components;
  // First: lazily allocated stores get their arrays before any other observer writes defaults.
  for (const name of LAZY_COMPONENTS) {
    const store = c[name];
    observe(world, onAdd(store), () => {
      materializeStore(store, world.capacity);
      if (world.threads > 1) shareStore(store, world.capacity);
    });
  }
  const zero3 = (s: { x: Float64Array; y: Float64Array; z: Float64Array }) => (eid: number) => {
    s.x[eid] = 0; s.y[eid] = 0; s.z[eid] = 0;
  };
  // Position is where every body starts: reset all its per-entity motion state, so a recycled id
  // never inherits velocity, spin or force from the entity that had it before.
  observe(world, onAdd(c.Position), (eid: number) => {
    c.Position.x[eid] = 0; c.Position.y[eid] = 0; c.Position.z[eid] = 0;
    c.PreviousPosition.x[eid] = 0; c.PreviousPosition.y[eid] = 0; c.PreviousPosition.z[eid] = 0;
    c.Velocity.x[eid] = 0; c.Velocity.y[eid] = 0; c.Velocity.z[eid] = 0;
    c.AngularVelocity.x[eid] = 0; c.AngularVelocity.y[eid] = 0; c.AngularVelocity.z[eid] = 0;
    c.Force.x[eid] = 0; c.Force.y[eid] = 0; c.Force.z[eid] = 0;
    c.Torque.x[eid] = 0; c.Torque.y[eid] = 0; c.Torque.z[eid] = 0;
  });
  observe(world, onAdd(c.Velocity), zero3(c.Velocity));
  observe(world, onAdd(c.Force), zero3(c.Force));
  observe(world, onAdd(c.AngularVelocity), zero3(c.AngularVelocity));
  observe(world, onAdd(c.Torque), zero3(c.Torque));
  observe(world, onAdd(c.Mass), (eid: number) => { c.Mass.value[eid] = 1; c.Mass.inv[eid] = 1; });
  observe(world, onAdd(c.Ball), (eid: number) => { c.Ball.radius[eid] = DEFAULT_RADIUS; });
  observe(world, onAdd(c.Material), (eid: number) => {
    c.Material.restitution[eid] = DEFAULT_MATERIAL.restitution;
    c.Material.friction[eid] = DEFAULT_MATERIAL.friction;
    c.Material.staticFriction[eid] = DEFAULT_MATERIAL.friction;
  });
  observe(world, onAdd(c.Segment), (eid: number) => {
    const s = c.Segment;
    s.ax[eid] = 0; s.ay[eid] = 0; s.az[eid] = 0; s.bx[eid] = 0; s.by[eid] = 0; s.bz[eid] = 0; s.radius[eid] = 0;
  });
  observe(world, onAdd(c.Angle), (eid: number) => { c.Angle.value[eid] = 0; });
  observe(world, onAdd(c.Orientation), (eid: number) => {
    c.Orientation.x[eid] = 0; c.Orientation.y[eid] = 0; c.Orientation.z[eid] = 0; c.Orientation.w[eid] = 1;
  });
  observe(world, onAdd(c.Inertia), (eid: number) => { c.Inertia.value[eid] = 0; c.Inertia.inv[eid] = 0; });
  observe(world, onAdd(c.InertiaTensor), (eid: number) => {
    const T = c.InertiaTensor; T.x[eid] = 0; T.y[eid] = 0; T.z[eid] = 0; T.invX[eid] = 0; T.invY[eid] = 0; T.invZ[eid] = 0;
  });
  observe(world, onAdd(c.AngularDamping), (eid: number) => {
    c.AngularDamping.k[eid] = 0;
    addComponentIfMissing(world, eid, c.Torque);
  });
  observe(world, onAdd(c.Plane), (eid: number) => { c.Plane.nx[eid] = 0; c.Plane.ny[eid] = 1; c.Plane.nz[eid] = 0; c.Plane.d[eid] = 0; });
  observe(world, onAdd(c.LinearDrag), (eid: number) => { c.LinearDrag.k[eid] = 0; });
  observe(world, onAdd(c.QuadraticDrag), (eid: number) => { c.QuadraticDrag.k[eid] = 0; });
  observe(world, onAdd(c.GravityScale), (eid: number) => { c.GravityScale.value[eid] = 1; });
  observe(world, onAdd(c.Attractor), (eid: number) => { c.Attractor.mass[eid] = 0; c.Attractor.softening[eid] = 0; });
  observe(world, onAdd(c.Charge), (eid: number) => { c.Charge.value[eid] = 0; });
  const zeroField = (F: typeof c.ElectricField) => (eid: number) => {
    F.x[eid] = 0; F.y[eid] = 0; F.z[eid] = 0; F.ampX[eid] = 0; F.ampY[eid] = 0; F.ampZ[eid] = 0; F.omega[eid] = 0; F.phase[eid] = 0;
  };
  observe(world, onAdd(c.ElectricField), zeroField(c.ElectricField));
  observe(world, onAdd(c.MagneticField), zeroField(c.MagneticField));
  observe(world, onAdd(c.CentralForce), (eid: number) => {
    const C = c.CentralForce; C.cx[eid] = 0; C.cy[eid] = 0; C.cz[eid] = 0; C.k[eid] = 0; C.n[eid] = 2;
  });
  observe(world, onAdd(c.Lift), (eid: number) => { c.Lift.k[eid] = 0; c.Lift.axisX[eid] = 0; c.Lift.axisY[eid] = 0; c.Lift.axisZ[eid] = 1; });
  observe(world, onAdd(c.Buoyancy), (eid: number) => {
    const B = c.Buoyancy; B.shape[eid] = 0; B.radius[eid] = 0.5; B.halfX[eid] = 0.5; B.halfY[eid] = 0.5; B.halfZ[eid] = 0.5; B.dragCoefficient[eid] = 0;
  });
  observe(world, onAdd(c.FluidRegion), (eid: number) => {
    const F = c.FluidRegion; F.surface[eid] = 0; F.density[eid] = 1000;
    F.minX[eid] = -Infinity; F.maxX[eid] = Infinity; F.minZ[eid] = -Infinity; F.maxZ[eid] = Infinity;
  });
  observe(world, onAdd(c.Spring), (eid: number) => {
    const S = c.Spring; S.a[eid] = 0; S.b[eid] = 0; S.restLength[eid] = 1; S.stiffness[eid] = 0; S.damping[eid] = 0;
    S.oneSided[eid] = 0; S.anchorX[eid] = 0; S.anchorY[eid] = 0; S.anchorZ[eid] = 0;
  });
  observe(world, onAdd(c.DrivingForce), (eid: number) => {
    const D = c.DrivingForce; D.x[eid] = 0; D.y[eid] = 0; D.z[eid] = 0; D.omega[eid] = 0; D.phase[eid] = 0;
  });
  observe(world, onAdd(c.RandomForce), (eid: number) => { c.RandomForce.magnitude[eid] = 0; c.RandomForce.correlationTime[eid] = 1; c.RandomForce.seed[eid] = eid; });
  observe(world, onAdd(c.Thrust), (eid: number) => {
    const T = c.Thrust; T.exhaustVelocity[eid] = 0; T.massFlowRate[eid] = 0; T.fuel[eid] = 0; T.dirX[eid] = 0; T.dirY[eid] = 1; T.dirZ[eid] = 0;
  });
  observe(world, onAdd(c.Vortex), (eid: number) => {
    const V = c.Vortex; V.cx[eid] = 0; V.cy[eid] = 0; V.cz[eid] = 0; V.axisX[eid] = 0; V.axisY[eid] = 0; V.axisZ[eid] = 1; V.k[eid] = 0; V.n[eid] = 1;
  });
  observe(world, onAdd(c.Lifetime), (eid: number) => { c.Lifetime.age[eid] = 0; c.Lifetime.duration[eid] = 1; });
  for (const law of [
    c.LinearDrag, c.Vortex, c.QuadraticDrag, c.GravityScale, c.MutualGravity, c.Charge, c.CentralForce, c.Lift, c.Buoyancy,
    c.DrivingForce, c.RandomForce, c.Thrust,
  ]) registerForceLaw(world, law);
  // A force accumulator needs a mass to turn force into acceleration; a collider needs a mass and a material.
  observe(world, onAdd(c.Force), (eid: number) => addComponentIfMissing(world, eid, c.Mass));
  // A collider is always a body with a force accumulator: contacts need its start-of-step position,
  // which only bare particles may skip saving (see the `interpolation` option).
  observe(world, onAdd(c.Ball), (eid: number) => {
    addComponentIfMissing(world, eid, c.Mass);
    addComponentIfMissing(world, eid, c.Material);
    addComponentIfMissing(world, eid, c.Force);
  });
}

/**
 * Declares `component` a force law: whenever it is added to an entity, the Force accumulator is
 * added too, so the law's system has somewhere to write. Use it for your own force-law components.
 */
export function registerForceLaw(world: PhysicsWorld, component: object): void {
  const force = world.components.Force;
  observe(world, onAdd(component), (eid: number) => {
    addComponentIfMissing(world, eid, force);
  });
}

/** Adds `component` to `eid` unless it already has it (then its data is left untouched). */
export function addComponentIfMissing(world: PhysicsWorld, eid: number, component: object): void {
  if (!hasComponent(world, eid, component)) addComponent(world, eid, component);
}

/** Names the stage order for documentation and tooling. */
export { STAGES };

/**
 * Ends a world's worker threads (a world made with threads > 1); the world still steps, on the
 * calling thread alone. Safe on any world and to call twice.
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
 */
export function threadsReady(world: PhysicsWorld): Promise<void> {
  return world.threadPool === null ? Promise.resolve() : world.threadPool.ready;
}
