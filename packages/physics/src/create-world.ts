/**
 * Assembly, the top of the physics package: `createPhysicsWorld` builds a world's data (world/options.ts,
 * world/components.ts, the collision, joint and cloth states) and installs the default pipeline
 * (step/stages.ts), the removal hooks and the component defaults. Data sits at the bottom,
 * systems above it, and this file on top: nothing below imports it.
 */

import { createEntityIndex, createWorld, observe, onAdd, onRemove } from 'bitecs';
import { allocateCollisionScratch, createCollisionState } from './collision/state.js';
import { removeSpringsOf } from './forces/spring.js';
import { makeForceLawQueries } from './integrators/fused-gate.js';
import { makeIntegratorQueries } from './integrators/queries.js';
import { makeSleepQueries, wakeTouching } from './islands/sleep.js';
import { removeJointsOf } from './joints/api-2d.js';
import {
  finishJoints,
  gatherJointBodies,
  integrateJointRotations,
  jointsToSolve,
  prepareJoints,
  solveJoints,
  warmStartJoints,
} from './joints/solver-2d.js';
import { Rng } from './math/rng.js';
import { setRowFamily } from './solver/row-families.js';
import { makeCheckQueries } from './step/finite.js';
import { makeGuardQueries } from './step/plan.js';
import { createStages, STAGES } from './step/stages.js';
import { makeThreadPool } from './threads/pool-maker.js';
import { shareStores } from './threads/shared-stores.js';
import {
  assertBoolean,
  assertFinite,
  assertInteger,
  assertNonNegative,
  assertOptions,
  assertVector,
  describe,
  optionOr,
} from './validation/validate.js';
import { createClothState } from './world/cloth-state.js';
import { COMPONENT_DEFAULTS } from './world/component-defaults.js';
import { BODY_STORES, createComponents, LAZY_COMPONENTS, materializeGroup } from './world/components.js';
import { widenToDoubles } from './world/double-fields.js';
import { createForceLawSettings } from './world/force-settings.js';
import { INTEGRATOR_NAMES } from './world/integrator-names.js';
import { createJointState } from './world/joint-state-2d.js';
import { useLeanEcsStorage } from './world/lean-ecs.js';
import {
  addComponentIfMissing,
  assertTimeStep,
  MAX_CAPACITY,
  type PhysicsWorld,
  type PhysicsWorldContext,
  type PhysicsWorldOptions,
  registerForceLaw,
  type StageTimings,
  type System,
} from './world/options.js';
import { addQueryCache, query } from './world/query.js';
import { createWorldScratch, type WorldScratch } from './world/scratch.js';
import { markWritable } from './world/writable-fields.js';

// The contact solver runs the 2D joints' stages as a row family (solver/row-families.ts).
setRowFamily('joints2D', {
  dimensions: 2,
  pushesUnmarked: true,
  toSolve: jointsToSolve,
  gather: gatherJointBodies,
  prepare: prepareJoints,
  warmStart: warmStartJoints,
  solve: (world, hs, useBias) => solveJoints(world, hs, useBias),
  integrate: integrateJointRotations,
  endSubstep: () => {},
  restitution: () => {},
  finish: finishJoints,
});

const KNOWN_OPTIONS = [
  'dimensions',
  'capacity',
  'gravity',
  'dt',
  'substeps',
  'integrator',
  'seed',
  'solverSubsteps',
  'solverIterations',
  'restitutionThreshold',
  'interpolation',
  'sleep',
  'threads',
] as const;

/**
 * Creates a physics world: component stores of fixed capacity, the staged pipeline, collision
 * state and a seeded random number generator.
 *
 * @throws TypeError on options that are not an object, an unknown option name, a null option or a value of
 *   the wrong type (booleans must be booleans).
 * @throws RangeError on a value out of range (dt <= 0, capacity < 1, substeps not an integer, ...).
 * @example
 * const world = createPhysicsWorld({ dimensions: 2, capacity: 1000, gravity: [0, -9.81] });
 * @category World and step
 */
export function createPhysicsWorld(options: PhysicsWorldOptions = {}): PhysicsWorld {
  const where = 'createPhysicsWorld';
  assertOptions(where, options, KNOWN_OPTIONS);
  const dimensions = options.dimensions ?? 2;
  if (dimensions !== 2 && dimensions !== 3) {
    throw new RangeError(`${where}: dimensions must be 2 or 3, got ${describe(dimensions)}`);
  }
  const capacity = optionOr(where, 'capacity', options.capacity, 10_000, assertInteger, 1, MAX_CAPACITY);
  const gravity = new Float64Array(3);
  if (options.gravity !== undefined) {
    assertVector(where, 'gravity', options.gravity, dimensions);
    for (let i = 0; i < dimensions; i++) gravity[i] = options.gravity[i]!;
  } else {
    gravity[1] = -9.81;
  }
  const dt = options.dt ?? 1 / 60;
  assertTimeStep(where, dt);
  const substeps = optionOr(where, 'substeps', options.substeps, 1, assertInteger, 1, 64);
  const integrator = options.integrator ?? 'semi-implicit-euler';
  if (typeof integrator !== 'string' || !(INTEGRATOR_NAMES as readonly string[]).includes(integrator)) {
    throw new RangeError(
      `${where}: integrator must be one of ${INTEGRATOR_NAMES.map((n) => `'${n}'`).join(', ')}, got ${describe(integrator)}`,
    );
  }
  const seed = optionOr(where, 'seed', options.seed, 1, assertFinite);
  const solverSubsteps = optionOr(where, 'solverSubsteps', options.solverSubsteps, 4, assertInteger, 1, 16);
  const solverIterations = optionOr(where, 'solverIterations', options.solverIterations, 1, assertInteger, 1, 50);
  const restitutionThreshold = optionOr(where, 'restitutionThreshold', options.restitutionThreshold, 0.5, assertNonNegative);
  const interpolation = options.interpolation ?? true;
  assertBoolean(where, 'interpolation', interpolation);
  const sleep = options.sleep ?? true;
  assertBoolean(where, 'sleep', sleep);
  const threads = optionOr(where, 'threads', options.threads, 1, assertInteger, 1, 64);
  // Made before anything else, so a missing SharedArrayBuffer or Worker throws before any allocation.
  const threadPool = threads > 1 ? makeThreadPool(where, threads) : null;
  const restitution = options.restitutionThreshold === undefined ? {} : { restitutionThreshold };
  const settings = { dimensions, gravity, dt, substeps, integrator, seed, solverSubsteps, solverIterations, sleep, interpolation };
  if (!literalsPrimed) {
    // The first world of the program is made twice, once with room for one entity and thrown away:
    // see literalsPrimed.
    literalsPrimed = true;
    assemble({ ...settings, gravity: new Float64Array(gravity), capacity: 1, threads: 1, threadPool: null, restitution });
  }
  return assemble({ ...settings, capacity, threads, threadPool, restitution });
}

/**
 * Whether this program has made a world. V8 (Node, Chrome) makes an object literal's boilerplate the
 * second time the literal runs and then widens the field types of the literal's map, which throws
 * away every optimised function that relied on them: without priming, the second world a program
 * makes would throw away the physics code's optimised code at once (its first step then runs several
 * times slower). Making the first world twice runs every literal of a world's
 * creation twice before any physics code is optimised.
 */
let literalsPrimed = false;

/** What `assemble` builds a world from: createPhysicsWorld's checked options. */
interface WorldSettings {
  dimensions: 2 | 3;
  capacity: number;
  gravity: Float64Array;
  dt: number;
  substeps: number;
  integrator: PhysicsWorldContext['integrator'];
  seed: number;
  solverSubsteps: number;
  solverIterations: number;
  sleep: boolean;
  interpolation: boolean;
  threads: number;
  threadPool: PhysicsWorldContext['threadPool'];
  restitution: { restitutionThreshold?: number };
}

/** Builds a world from checked settings (see createPhysicsWorld). */
function assemble(o: WorldSettings): PhysicsWorld {
  const { dimensions, capacity, gravity, dt, substeps, integrator, seed, solverSubsteps, solverIterations, sleep } = o;
  const { interpolation, threads, threadPool } = o;
  const entityIndex = createEntityIndex();
  // Without interpolation bare particles never write PreviousPosition: it waits for the first body
  // (threads keep it: the parallel loops take only shared arrays).
  const components = createComponents(capacity, interpolation || threadPool !== null);
  if (threadPool !== null) shareStores(components, capacity);
  const builtins = new Map<string, System>();
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
    stages: createStages(builtins),
    builtins,
    // Given: it applies to every contact; not given: e = 1 contacts bounce at any speed (CollisionSettings).
    collision: createCollisionState(capacity, {
      solverSubsteps,
      solverIterations,
      sleep,
      dimensions,
      ...o.restitution,
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
    // Every feature's entry from the start (undefined until the feature is used): the object then
    // has one layout in every world, whatever order a world's features are first used in, so code
    // compiled while one world ran reads another's entries without being thrown away.
    features: {
      shapes3d: undefined,
      joints3d: undefined,
      contacts3d: undefined,
      meshes3d: undefined,
      particles: undefined,
      'particle-archetypes': undefined,
      dissipation: undefined,
      'contact-scale': undefined,
    },
    scratch: createWorldScratch(),
  };
  const world = createWorld(context, entityIndex) as PhysicsWorld;
  // Fields the first step writes fractions into (world/double-fields.ts), and the query cache the
  // first step's queries would add: the world keeps the hidden class it has here.
  widenToDoubles(world, ['time', 'substepStart']);
  // Fields every step writes, and the caches and features filled on first use (world/writable-fields.ts).
  markWritable(world, ['h', 'steps']);
  markWritable(
    world.scratch,
    Object.keys(world.scratch).filter(
      (k) => world.scratch[k as keyof WorldScratch<PhysicsWorld>] === undefined,
    ) as (keyof WorldScratch<PhysicsWorld> & string)[],
  );
  markWritable(world.features, Object.keys(world.features));
  addQueryCache(world);
  widenToDoubles(timings, STAGES);
  installDefaults(world);
  // bitecs' per-entity bookkeeping in fixed typed arrays, component Sets answered from the masks.
  useLeanEcsStorage(world, capacity);
  // The queries the integrators, the state checks, the sleep stage, the stages' idle guards, the
  // forces plan, the 2D colliders and the 2D joints ask every step, made while no entity exists: bitecs
  // keeps them as bodies are added, where the first step, with the scene built, would fill each by a
  // pass over every entity.
  makeIntegratorQueries(world);
  makeCheckQueries(world);
  makeSleepQueries(world);
  makeGuardQueries(world);
  makeForceLawQueries(world);
  const c = world.components;
  query(world, [c.Shape]);
  query(world, [c.Position, c.Ball]);
  if (dimensions === 2) {
    query(world, [c.Plane]);
    query(world, [c.Segment]);
    query(world, [c.Joint]);
  }
  return world;
}

/**
 * Gives PreviousPosition its arrays if it has none (a world made with interpolation: false), holding
 * the current positions: bodies with forces or colliders write it every step; bare particles, which
 * do not, keep where they were when the first body came.
 */
function allocatePreviousPosition(world: PhysicsWorld): void {
  const O = world.components.PreviousPosition,
    P = world.components.Position;
  if (O.x.length > world.capacity) return;
  O.x = P.x.slice();
  O.y = P.y.slice();
  O.z = P.z.slice();
}

/**
 * Resets a component's fields for an entity when the component is added (ids are recycled and
 * bitecs leaves old data behind), and makes every force-law component bring the Force accumulator.
 */
function installDefaults(world: PhysicsWorld): void {
  // In this order: a lazily allocated store gets its arrays before any other observer writes defaults.
  allocateOnAdd(world);
  resetMotionOnAdd(world);
  resetFieldsOnAdd(world);
  completeBodiesOnAdd(world);
}

/** installDefaults, first: a lazily allocated store (and a body's collision scratch) gets its arrays when its component is first added. */
function allocateOnAdd(world: PhysicsWorld): void {
  const c = world.components;
  // First: lazily allocated stores get their arrays before any other observer writes defaults.
  // The check reads one array of the component's own store: empty until its group is allocated (and
  // again after a restore that replaced it), so a later add allocates again when needed.
  for (const name of LAZY_COMPONENTS) {
    const store = c[name] as unknown as Record<string, ArrayLike<number>>;
    const probe = Object.keys(store).find((k) => ArrayBuffer.isView(store[k]));
    if (probe === undefined) continue;
    const body = BODY_STORES.includes(name);
    observe(world, onAdd(store), () => {
      if (store[probe]!.length <= world.capacity) materializeGroup(c, name, world.capacity, world.threads > 1);
      if (body) {
        allocateCollisionScratch(world.collision, world.capacity);
        allocatePreviousPosition(world);
      }
    });
  }
}

/** installDefaults: position and motion (velocity, spin, force and torque) reset when their components are added. */
function resetMotionOnAdd(world: PhysicsWorld): void {
  const c = world.components;
  const zero3 = (s: { x: Float64Array; y: Float64Array; z: Float64Array }) => (eid: number) => {
    s.x[eid] = 0;
    s.y[eid] = 0;
    s.z[eid] = 0;
  };
  // Position is where every body starts: reset all its per-entity motion state, so a recycled id
  // never inherits velocity, spin or force from the entity that had it before.
  observe(world, onAdd(c.Position), (eid: number) => {
    c.Position.x[eid] = 0;
    c.Position.y[eid] = 0;
    c.Position.z[eid] = 0;
    c.PreviousPosition.x[eid] = 0;
    c.PreviousPosition.y[eid] = 0;
    c.PreviousPosition.z[eid] = 0;
    c.Velocity.x[eid] = 0;
    c.Velocity.y[eid] = 0;
    c.Velocity.z[eid] = 0;
    c.AngularVelocity.x[eid] = 0;
    c.AngularVelocity.y[eid] = 0;
    c.AngularVelocity.z[eid] = 0;
    c.Force.x[eid] = 0;
    c.Force.y[eid] = 0;
    c.Force.z[eid] = 0;
    c.Torque.x[eid] = 0;
    c.Torque.y[eid] = 0;
    c.Torque.z[eid] = 0;
  });
  // Velocity is reset when an entity comes to have both Position and Velocity: the same query as the
  // integrators' (no membership of its own, 16 bytes an entity), and a velocity means nothing without
  // a position (Position's own reset above clears it too).
  observe(world, onAdd(c.Position, c.Velocity), zero3(c.Velocity));
  observe(world, onAdd(c.Force), zero3(c.Force));
  observe(world, onAdd(c.AngularVelocity), zero3(c.AngularVelocity));
  observe(world, onAdd(c.Torque), zero3(c.Torque));
}

/**
 * installDefaults: every component of COMPONENT_DEFAULTS (world/component-defaults.ts) gets its fields'
 * defaults when added; the inertia tensor is zeroed on removal too; angular damping brings a Torque;
 * a random force is seeded with its entity's id.
 */
function resetFieldsOnAdd(world: PhysicsWorld): void {
  const c = world.components;
  const stores = c as unknown as Record<string, Record<string, Float64Array>>;
  const reset = (name: string, defaults: Readonly<Record<string, number | undefined>>) => {
    // The store is looked up at each add: a lazily allocated component's arrays are replaced when its
    // group is first allocated (allocateOnAdd).
    const store = stores[name]!;
    const fields = Object.keys(defaults),
      values = fields.map((f) => defaults[f]!);
    return (eid: number) => {
      for (let i = 0; i < fields.length; i++) store[fields[i]!]![eid] = values[i]!;
    };
  };
  for (const [name, defaults] of Object.entries(COMPONENT_DEFAULTS) as [string, Record<string, number>][])
    observe(world, onAdd(stores[name]!), reset(name, defaults));
  // Zeroed on removal too: the 3D contact solver and angular damping read a body's tensor wherever it
  // is non-zero, so a ball body made later in the slot (which has none) must find zeros there, not the
  // inverse moments of the shape body that held the slot before (a snapshot keeps no store that no live
  // entity has, so a restored world would read zeros where the original read the stale tensor).
  observe(world, onRemove(c.InertiaTensor), reset('InertiaTensor', COMPONENT_DEFAULTS.InertiaTensor!));
  observe(world, onAdd(c.AngularDamping), (eid: number) => addComponentIfMissing(world, eid, c.Torque));
  observe(world, onAdd(c.RandomForce), (eid: number) => {
    c.RandomForce.seed[eid] = eid;
  });
}

/** installDefaults, last: force laws bring the Force accumulator, a Force brings a Mass, and a ball brings a Mass, a Material and a Force. */
function completeBodiesOnAdd(world: PhysicsWorld): void {
  const c = world.components;
  for (const law of [
    c.LinearDrag,
    c.Vortex,
    c.QuadraticDrag,
    c.GravityScale,
    c.MutualGravity,
    c.Charge,
    c.CentralForce,
    c.Lift,
    c.Buoyancy,
    c.DrivingForce,
    c.RandomForce,
    c.Thrust,
  ])
    registerForceLaw(world, law);
  // A force accumulator needs a mass to turn force into acceleration; a collider needs a mass and a material.
  observe(world, onAdd(c.Force), (eid: number) => addComponentIfMissing(world, eid, c.Mass));
  // A collider is always a body with a force accumulator: contacts need its start-of-step position,
  // which only bare particles may skip saving (see the `interpolation` option).
  observe(world, onAdd(c.Ball), (eid: number) => {
    // A ball made without the package's ball makers: its collisions are not installed (step refuses).
    if (!world.builtins.has('narrowphase')) world.collision.looseBall = eid;
    addComponentIfMissing(world, eid, c.Mass);
    addComponentIfMissing(world, eid, c.Material);
    addComponentIfMissing(world, eid, c.Force);
  });
}
