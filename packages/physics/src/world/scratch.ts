import type { QueryResult } from 'bitecs';
import type { KernelArray } from '../threads/kernel-types.js';
import type { StageName } from './stage-names.js';

/**
 * A world's scratch (`world.scratch`): the buffers, kernel argument lists and caches that the systems
 * and snapshots keep for one world between calls, on the world itself rather than in module-level
 * WeakMaps keyed by the world, so everything a world holds is reachable from the world object.
 *
 * None of it is state: each field is written before it is read in the call that reads it, or is a
 * cache of the world's own data that is checked or rebuilt when that data changes. So a snapshot does
 * not store it (`scratch` is in snapshot/state-scope.ts NOT_STATE) and `restore` leaves the world's own
 * as it is; a world restored from another's snapshot makes its own as it steps.
 *
 * The types live here (the world layer), not in the modules that use them, so that the world's type
 * names no module above it. Those that hold a system function or a check of the world take the world's
 * type as a parameter `W` (world/options.ts PhysicsWorld), so this module names no module that names it
 * (an import cycle, test/architecture/imports.test.ts). Every field is on the object from the world's creation (`undefined`
 * until its user first runs, or an empty Map), so the object has one layout in every world.
 */

/** The threaded ball-ball contacts' scratch (collision/narrowphase/balls-threads.ts). */
export interface BallContactScratch {
  /** Each range after the first: its contact arrays (the buffer's fields, typed as the buffer's), `cap` rows each; null before the first threaded run. */
  threads: { out: KernelArray[][]; cap: number } | null;
  /** The ranges' contact counts (shared once the world has a pool). */
  counts: Int32Array;
  /** 1 for each pair of the run whose bodies a joint keeps apart. */
  skip: Uint8Array;
  /** The kernel's array arguments (collision/narrowphase/ball-contact-slots.ts). */
  arrays: KernelArray[];
  /** The kernel's number arguments. */
  params: Float64Array;
}

/** The broadphase cell pass's pair buffers (collision/broadphase/grid-pairs.ts). */
export interface PairBuffers {
  /** Each range's pairs (bodies a and b) and the sleeping balls it wakes, one array a range. */
  a: Int32Array[];
  b: Int32Array[];
  w: Int32Array[];
  /** The ranges' pair counts, then their wake counts (collision/broadphase/ball-pair-slots.ts). */
  counts: Int32Array;
  /** The kernel's array and number arguments. */
  arrays: KernelArray[];
  params: Float64Array;
}

/** The threaded preparation of the ball contact rows (solver/ball-prepare.ts). */
export interface BallPrepareScratch {
  /** A shared copy of `world.spawnStamp`, copied in full before each threaded run. */
  stamp: Uint32Array;
  /** The kernel's array and number arguments. */
  arrays: KernelArray[];
  params: Float64Array;
}

/** The threaded solver stages' scratch (solver/stages-threads.ts). */
export interface SolverStageScratch {
  /** The kernels' array and number arguments. */
  arrays: KernelArray[];
  params: Float64Array;
  /** The deepest overlap each thread found, one slot a thread. */
  deepest: Float64Array;
}

/**
 * The coloured solve's scratch (solver/coloring.ts): the packed rows, the plan, the blocks and the
 * strips. Arrays marked shared are on shared memory where there is any (the pool's workers use them).
 */
export interface ColorScratch {
  /** The packed rows (PACK_STRIDE numbers a row). */
  pack: Float64Array;
  /** The solver bodies that take gravity in the kernel. */
  dyn: Uint8Array;
  /** The plan: its head (PLAN_HEAD slots), then the colours' first blocks. */
  plan: Int32Array;
  /** The threads' meeting counters. */
  bar: Int32Array;
  /** The solve kernel's number arguments. */
  params: Float64Array;
  /** The kernel's claim flags, a block of every unit (shared; zeroed before each run). */
  claim: Int32Array;
  /** Each pack row's two bodies' solver state offsets (shared; two a row). */
  pair: Int32Array;
  /** Each pack row's normal impulse delivered over the substeps, and its row in the contact buffer (shared). */
  tot: Float64Array;
  row: Int32Array;
  /** Each contact row's graph colour and each body's used colours (graph colouring). */
  color: Uint8Array;
  mask: Uint32Array;
  /** The solve kernel's array arguments. */
  arrays: KernelArray[];
  /** Each thread's first pack slot of every colour (MAX_COLORS + 1 a thread; the packing stage's cursors). */
  offsets: Int32Array;
  /** Rows a colour, the colours' first rows, the next free row of each (MAX_COLORS + 2 each, shared). */
  counts: Int32Array;
  start: Int32Array;
  next: Int32Array;
  /** Each contact buffer row's pack row (shared; written by the packing, read by coloredRepack2D). */
  slot: Int32Array;
  /** The blocks' first pack rows (block j: bounds[j] .. bounds[j + 1] - 1), shared. */
  bounds: Int32Array;
  /** Strips: the movable solver bodies by strip pair, and each pair's first entry there (shared). */
  bodyOrder: Int32Array;
  bodyBounds: Int32Array;
  /** Strips: each solver body's strip (255: fixed, in no strip); the rows' histogram; each bin's strip. */
  strip: Uint8Array;
  hist: Int32Array;
  binStrip: Uint8Array;
  /** Strips: each solver body's histogram bin (0xffff: fixed). */
  bin: Uint16Array;
  /** The strips of the cut in `strip`, `bin`, `hist`, `binStrip` and `dyn` this step (0: none yet; planRows). */
  cut: number;
  /** The strip plan kernel's arguments (stripPlan2D; its layout helper's for graph colours too). */
  planArrays: KernelArray[];
  planParams: Float64Array;
  /** Whether this step's substeps ran by colours and the restitution stage has not used the plan yet. */
  pending: boolean;
}

/** A query's component names (and, not, or), sorted, or null if it has a component outside world.components. */
export type QueryDescriptor = { and: string[]; not: string[]; or: string[] } | null;

/**
 * What the last snapshot of a world found about one of its query sets (lean storage: sets with a
 * `version`, see world/lean-ecs.ts): its version and length then, and the earlier set of that snapshot it
 * was equal to (null: none) with that set's version and length then.
 */
export interface ListMemo {
  version: number;
  length: number;
  same: object | null;
  sameVersion: number;
  sameLength: number;
}

/** A query set known to hold the same ids in the same order as `peer` while their versions are `version` and `peerVersion`. */
export interface QueryTwin {
  peer: object;
  version: number;
  peerVersion: number;
}

/** The query terms of the force accumulators' clear (forces/clear.ts): every body with `Force`, with `Torque`. */
export interface ClearTerms {
  force: object[];
  torque: object[];
}

/** The query terms of the integrators' body lists (integrators/queries.ts), one list each. */
export interface MoverTerms {
  forced: object[];
  free: object[];
  kinematic: object[];
  torqued: object[];
  tensor: object[];
  spinning2D: object[];
  spinning3D: object[];
  simpleSpinning3D: object[];
}

/** The query terms of the sleep stage (islands/sleep.ts). */
export interface SleepTerms {
  /** Awake dynamic balls. */
  balls: object[];
  /** Awake dynamic bodies with a 2D shape and no ball. */
  shaped: object[];
  /** Awake dynamic bodies that are not balls (those with a 3D shape are the candidates). */
  shaped3D: object[];
  /** Each component that keeps its body awake (time-varying forces), alone. */
  awake: object[][];
  spring: object[];
  sleeping: object[];
}

/** The query terms of the stages' finiteness checks (step/finite.ts). */
export interface CheckTerms {
  force: object[];
  torque: object[];
  linear: object[];
  angular: object[];
}

/**
 * What the fused gate resolved of a world's forces stage (integrators/fused-gate.ts), kept while the
 * stage holds the same systems in the same order: whether its systems allow the fused pass at all (each
 * absorbed law exactly once, every other one torque-only or an idle-when-empty law), and the live query
 * arrays of the laws that must be idle, with the fewest entities each acts on. `W` is the world's type.
 */
export interface ForcesPlan<W> {
  /** The forces stage's systems the plan was made for, in order (a copy). */
  forces: ((world: W) => void)[];
  allowed: boolean;
  idle: QueryResult[];
  least: number[];
  /** The query of every body with a force accumulator. */
  force: QueryResult;
}

/**
 * How a system is trusted not to write NaN (world/trusted-systems.ts `trustFiniteOutput`): its scope,
 * and the condition it is trusted under. `W` is the world's type.
 */
export interface SystemTrust<W> {
  readonly scope: 'all' | 'linear';
  readonly idle?: (world: W) => boolean;
}

/**
 * What `step` resolved once of a stage's systems (step/plan.ts): for each system, the live query arrays
 * whose emptiness means it has nothing to do (its idle guard), and how it is trusted not to write NaN.
 * Remade when the stage's list of systems or the systems' marks change. `W` is the world's type.
 */
export interface StagePlan<W> {
  /** The stage's systems the plan was made for, in order (a copy, compared with the stage's list). */
  readonly systems: ((world: W) => void)[];
  /** For each system, its idle guard's live query arrays (idle when all are empty), or null: always run. */
  readonly guards: (readonly QueryResult[] | null)[];
  /** For each system, how it is trusted not to write NaN (world/trusted-systems.ts finiteTrustOf). */
  readonly trust: (SystemTrust<W> | undefined)[];
  /** The marks' version (world/trusted-systems.ts systemMarksVersion) the plan was made at. */
  readonly version: number;
}

/** A world's stage plans, one a stage (null until the stage first runs). `W` is the world's type. */
export type StagePlans<W> = Record<StageName, StagePlan<W> | null>;

/**
 * The per-world scratch record, `world.scratch` (see the module comment). Each field names the module
 * that owns it; no other module reads or writes it. `W` is the world's type (world/options.ts PhysicsWorld).
 * @category World and step
 */
export interface WorldScratch<W> {
  /** forces/gravity.ts: the attractors packed for the threads (6 numbers a source), written in full before each use. */
  attractorSources: Float64Array | undefined;
  /** step/step.ts: positions (x, y, z by slot) of the movers at the start of a step with substeps, written back to PreviousPosition at its end. */
  stepStart: [Float64Array, Float64Array, Float64Array] | undefined;
  /** integrators/queries.ts: the query terms of the fused pass's three body lists (built from `world.components` once). */
  fusedTerms: readonly [object[], object[], object[]] | undefined;
  /** integrators/queries.ts: the query terms of the integrators' body lists (built from `world.components` once). */
  moverTerms: MoverTerms | undefined;
  /** integrators/fused-gate.ts: what the gate resolved of the forces stage's systems (remade when they change). */
  forcesPlan: ForcesPlan<W> | undefined;
  /** forces/clear.ts: the query terms of the force and torque clear (built from `world.components` once). */
  clearTerms: ClearTerms | undefined;
  /** forces/gravity.ts: the query terms of the bodies attractors pull (built from `world.components` once). */
  pulledTerms: object[] | undefined;
  /** islands/sleep.ts: the query terms of the sleep stage (built from `world.components` once). */
  sleepTerms: SleepTerms | undefined;
  /** step/finite.ts: the query terms of the stages' finiteness checks (built from `world.components` once). */
  checkTerms: CheckTerms | undefined;
  /** step/plan.ts: each stage's plan (its systems' idle guards and trust), made when the stage first runs, remade when its systems or their marks change. */
  stagePlans: StagePlans<W> | undefined;
  /** collision/broadphase/grid-pairs.ts: the cell pass's pair buffers, one set a range, grown as needed. */
  pairBuffers: PairBuffers | undefined;
  /** collision/narrowphase/balls-threads.ts: the threaded ball-ball contacts' buffers and arguments. */
  ballContacts: BallContactScratch | undefined;
  /** solver/ball-prepare.ts: the threaded row preparation's stamp copy and arguments. */
  ballPrepare: BallPrepareScratch | undefined;
  /** solver/stages-threads.ts: the threaded solver stages' arguments and deepest-overlap slots. */
  solverStages: SolverStageScratch | undefined;
  /** solver/coloring.ts: the coloured solve's packed rows and plan (its `pending` flag is cleared at each step's start). */
  coloring: ColorScratch | undefined;
  /**
   * solver/contact-scale.ts: the contact length, m, the step that last solved each of the world's ball
   * contact buffers used (set by withScaledSubsteps for `collision.contacts`, read by contactLength).
   */
  readonly contactLengths: Map<object, number>;
  /** snapshot/ecs-capture.ts: the world's component stores by name, as last found (rebuilt when world.components changes). */
  componentNames: Map<object, string> | undefined;
  /** snapshot/ecs-capture.ts: each query's descriptor and key, with the name map they were computed from. */
  readonly queryKeys: Map<object, { names: Map<object, string>; d: QueryDescriptor; key: string }>;
  /** snapshot/ecs-capture.ts: what the last snapshot found about each query set (checked against the sets' versions). */
  readonly listMemos: Map<object, ListMemo>;
  /** snapshot/ecs-restore.ts: query sets a restore found holding the same list as another (checked against both versions). */
  readonly queryTwins: Map<object, QueryTwin>;
}

/**
 * A new world's scratch: every field present, nothing made yet (createPhysicsWorld).
 * @category World and step
 */
export function createWorldScratch<W>(): WorldScratch<W> {
  return {
    attractorSources: undefined,
    stepStart: undefined,
    fusedTerms: undefined,
    moverTerms: undefined,
    forcesPlan: undefined,
    clearTerms: undefined,
    pulledTerms: undefined,
    sleepTerms: undefined,
    checkTerms: undefined,
    stagePlans: undefined,
    pairBuffers: undefined,
    ballContacts: undefined,
    ballPrepare: undefined,
    solverStages: undefined,
    coloring: undefined,
    contactLengths: new Map(),
    componentNames: undefined,
    queryKeys: new Map(),
    listMemos: new Map(),
    queryTwins: new Map(),
  };
}

/**
 * Whether a cached list and a current one hold the same entries in the same order (by identity): the
 * test a cached plan of a stage's systems (step/plan.ts, integrators/fused-gate.ts) is kept by.
 * @category World and step
 */
export function sameEntries(cached: readonly unknown[], current: readonly unknown[]): boolean {
  if (cached.length !== current.length) return false;
  for (let i = 0; i < current.length; i++) if (cached[i] !== current[i]) return false;
  return true;
}
