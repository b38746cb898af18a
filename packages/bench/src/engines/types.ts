/**
 * The engine adapter interface: what every engine (ours and each peer) exposes to the runner.
 *
 * An adapter builds one scene at a time (`create`), and the instance it returns is stepped by the
 * runner one fixed step at a time. Everything the runner reads back (statistics, a snapshot of the
 * bodies for quality metrics) is in SI units (m, s) whatever the engine uses inside, so scene
 * metrics such as the largest overlap are computed the same way for every engine.
 */

/** Which scene to build and how: the parameters every engine of one benchmark run shares. */
export interface SceneRunOptions {
  /** Scene name, as in the physics package's `SCENES` registry (`--scene`). */
  readonly scene: string;
  /** Number of bodies, integer >= 1, already checked against the scene's limit. */
  readonly count: number;
  /** Seed of the scene's layout (and of our world's random number generator). Any finite number. */
  readonly seed: number;
  /**
   * Scene parameters beyond count and seed, by name (e.g. galaxy's `theta`, the Barnes-Hut opening
   * angle from `--theta`), already checked and with the scene's defaults filled in; absent or empty
   * for scenes without any. The bench scene maps them to the scene builder's options.
   */
  readonly params?: Readonly<Record<string, number>>;
  /** Whether ours adds `stateHash` (the world's state fingerprint) to its statistics (`--hash`). Default false. */
  readonly hash?: boolean;
  /** Threads of our world (`createPhysicsWorld({ threads })`), integer >= 1. Default 1. Peers ignore it. */
  readonly threads?: number;
  /** Whether ours calls `warmUp` before making its world (`--warm-up`). Default false. Peers ignore it. */
  readonly warmUp?: boolean;
}

/** Counters an engine reports after a step. */
export interface EngineStats {
  /** Bodies the scene made (moving bodies; walls excluded). */
  readonly bodies: number;
  /**
   * Contact points in the last step, counted the engine's own way (ours: contact rows of the
   * solver, speculative ones included; rapier: manifold points; matter: active pair contacts),
   * or null when the engine has no collisions (plain-loop).
   */
  readonly contacts: number | null;
  /**
   * Engine-specific counters added to the engine's result line as they are (e.g. rapier's sleeping
   * bodies). Names must not clash with the standard fields.
   */
  readonly extra?: Readonly<Record<string, number | string | boolean | null>>;
}

/**
 * Where the bodies are, in SI units and in the scene layout's order, for metrics computed outside
 * the engine (overlap, checksums). Read once after the timed steps, never while timing.
 */
export interface BodySnapshot {
  /** 2 for (x, y), 3 for (x, y, z). */
  readonly dimensions: 2 | 3;
  /** Number of bodies. */
  readonly count: number;
  /** Centres, m, `dimensions` numbers a body: x0, y0, x1, y1, ... */
  readonly positions: Float64Array;
  /** Collision radius of every body, m; a single number when all share it; absent for points. */
  readonly radius?: number | Float64Array;
  /** Velocities, m/s, laid out like `positions`; absent when the engine does not report them. */
  readonly velocities?: Float64Array;
  /** 3D only: orientations as unit quaternions (x, y, z, w), four numbers a body; absent when the engine does not report them. */
  readonly orientations?: Float64Array;
}

/** One engine with one scene built in it, ready to step. */
export interface EngineInstance {
  /** Engine name, as given to `--vs` ("bitphysics", "rapier2d", ...). */
  readonly engine: string;
  /** How the engine was configured for this scene, one line each (printed as notes; never on stdout in --json mode). */
  readonly notes: readonly string[];
  /** Advances the simulation by one fixed step of 1/60 s. Must not allocate per body. */
  step(): void;
  /** Counters of the last step. Cheap enough to call once after timing, not meant for every step. */
  stats(): EngineStats;
  /** Positions (and radii) of the scene's bodies in SI units; allocates, call after timing. */
  snapshot(): BodySnapshot;
  /** Frees what the engine holds outside the JS heap (WASM memory) and drops references. Idempotent. */
  dispose(): void;
  /**
   * Optional: bytes the adapter keeps for the bench beside the engine (its own copy of the body id list),
   * subtracted from the engine's memory figure. Default 0.
   */
  readonly benchBytes?: number;
  /**
   * Optional: called once right before this engine's first timed step (after warm-up and a forced
   * garbage collection), with the number of timed steps to come. For per-run measurements (heap).
   */
  beginTiming?(steps: number): void;
  /**
   * Optional: called right after every timed step, outside the timed interval, for per-step
   * counters (live particles, spawned, expired). Must not allocate per body.
   */
  afterStep?(): void;
  /** Optional: called once right after this engine's last timed step, before `stats`. */
  endTiming?(): void;
  /**
   * Optional, for an engine stepped in a thread of its own (isolation/isolated-engine.ts): runs `steps`
   * steps there, calling `afterStep` after each when `timed`, and returns each step's milliseconds
   * (`timed`) and the process CPU time of the block less the hooks', ms. The runner then calls it
   * instead of `step`, so no message between threads is timed.
   */
  runSteps?(steps: number, timed: boolean): { readonly times: Float64Array | null; readonly cpuMs: number };
  /** Optional: the scene's build time, ms, measured where the engine runs (its own thread); replaces the runner's figure. */
  readonly setupMs?: number;
  /** Optional: the engine's memory, MB (`engineMemoryMB`), measured where the engine runs; replaces the runner's figure. */
  readonly engineMemoryMB?: number;
  /** Optional: V8 heap in use where the engine runs (its own isolate) as of the last `stats` call, MB; added to the run's `heapUsedMB`. */
  heapUsedMB?(): number;
}

/** An engine the bench can run: a factory of instances plus what it supports. */
export interface EngineAdapter {
  /** Name used on the command line (`--vs`) and in the output's `engine` field. */
  readonly name: string;
  /** One line for `--list`. */
  readonly description: string;
  /** Whether the engine can build `scene` (a scene name). */
  supports(scene: string): boolean;
  /**
   * Loads what the engine needs before any scene is built (a WASM module, a lazily imported
   * library), so that `create`'s time and memory are the scene's alone. Optional; idempotent.
   */
  prepare?(): Promise<void>;
  /**
   * Builds the scene. Asynchronous because peers load lazily (rapier instantiates its WASM module).
   * @throws RangeError | TypeError when the scene rejects the options.
   */
  create(options: SceneRunOptions): Promise<EngineInstance>;
}
