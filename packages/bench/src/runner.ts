import { availableParallelism, loadavg } from 'node:os';
import { performance } from 'node:perf_hooks';
import type { EngineAdapter, EngineInstance, SceneRunOptions } from './engines/types.js';
import { collectGarbage, engineMemoryMB, sampleMemory } from './memory.js';
import type { BenchScene, ExtraValue } from './scenes/types.js';
import { summarize, type TimeSummary } from './stats.js';

/**
 * An engine failed to build the scene (the scene rejected the options, or the engine failed).
 * `cause` is the original error; a RangeError or TypeError there means bad options.
 */
export class SceneBuildError extends Error {
  /** The engine that failed. */
  readonly engine: string;
  constructor(engine: string, options: SceneRunOptions, cause: unknown) {
    super(
      `${engine} could not build scene "${options.scene}" with count ${options.count}, seed ${options.seed}: ${(cause as Error)?.message ?? String(cause)}`,
      { cause },
    );
    this.name = 'SceneBuildError';
    this.engine = engine;
  }
}

/** How to time a benchmark run. */
export interface TimingOptions {
  /** Timed steps per engine, integer >= 1. */
  readonly steps: number;
  /** Untimed steps per engine before timing (JIT warm-up, first contacts), integer >= 0. */
  readonly warmup: number;
  /**
   * Steps an engine runs in a row before the next engine takes its turn, integer >= 1. Engines
   * alternate in blocks of this many steps (the order rotating every round), so every engine is
   * timed across the same stretch of machine load; within a block its caches stay warm.
   */
  readonly block: number;
  /** Called after every block with steps done and total steps over all engines (warm-up included). */
  readonly onProgress?: (done: number, total: number) => void;
}

/** One engine's measurements. */
export interface EngineResult {
  /** Engine name. */
  readonly engine: string;
  /** Milliseconds of every timed step, in order. */
  readonly times: Float64Array;
  /** Per-step time summary, ms. */
  readonly msPerStep: TimeSummary;
  /**
   * CPU time of the process (process.cpuUsage, user + system, every thread: the engine's own and V8's
   * helpers) while this engine ran its timed steps, over the steps, ms a step; the `afterStep` hooks
   * are left out. On a loaded machine it is steadier than wall time (a process waiting for a core
   * uses none), though not immune (shared caches). Measured a block of steps at a time.
   */
  readonly cpuMsPerStep: number;
  /** Bodies times steps per second of wall time, at the median step time. */
  readonly bodyStepsPerSecond: number;
  /** Contact points in the last step (engine's own count), null for engines without collisions. */
  readonly contacts: number | null;
  /** Bodies in the scene. */
  readonly bodies: number;
  /** Time to build the scene in this engine, ms. */
  readonly setupMs: number;
  /** Growth of V8 heap plus external memory (typed arrays, WASM) while building the scene, less the adapter's own bookkeeping, MB (`engineMemoryMB`). */
  readonly engineMemoryMB: number;
  /** Engine-specific counters (EngineStats.extra) and the scene's extra fields for this engine. */
  readonly extra: Readonly<Record<string, ExtraValue>>;
  /** How the engine was configured. */
  readonly notes: readonly string[];
}

/** Everything one benchmark run measured. */
export interface BenchResult {
  /** The scene parameters shared by every engine. */
  readonly scene: SceneRunOptions;
  /** Timing parameters. */
  readonly steps: number;
  readonly warmup: number;
  readonly block: number;
  /** One result an engine, in the order the engines were given. */
  readonly engines: readonly EngineResult[];
  /** V8 heap used by the whole process after the timed steps, MB. */
  readonly heapUsedMB: number;
  /** Whether a full garbage collection could be forced before timing (makes memory deltas exact). */
  readonly gcForced: boolean;
  /** The machine's load: 1-minute load average (runnable processes) when timing began and when it ended. */
  readonly load: LoadSample;
}

/** The machine's 1-minute load average at the start and end of the timed steps (os.loadavg; 0 on Windows). */
export interface LoadSample {
  readonly start: number;
  readonly end: number;
  /** Logical CPUs (os.availableParallelism): a load above it means processes waited for a core. */
  readonly cpus: number;
}

/** CPU time the process has used so far (user + system, all threads), ms. */
function cpuMs(): number {
  const u = process.cpuUsage();
  return (u.user + u.system) / 1000;
}

/** Samples the 1-minute load average now. */
export function loadNow(): number {
  return loadavg()[0]!;
}

/** Logical CPUs of the machine. */
export function cpuCount(): number {
  return availableParallelism();
}

/**
 * Runs one benchmark: prepares every engine, builds the scene in each (one after another, measuring
 * setup time and memory), runs `warmup` then `steps` steps per engine alternating in blocks (see
 * `TimingOptions.block`) with performance.now() around every single step, then reads each engine's
 * statistics and final snapshot and lets the scene compute its extra fields. Engines are disposed
 * at the end, also on error.
 *
 * @throws SceneBuildError if an engine cannot build the scene; whatever a step throws.
 */
export async function runBenchmark(
  adapters: readonly EngineAdapter[],
  scene: BenchScene,
  options: SceneRunOptions,
  timing: TimingOptions,
): Promise<BenchResult> {
  for (const a of adapters) await a.prepare?.();
  const instances: EngineInstance[] = [];
  const setupMs: number[] = [];
  const memoryMB: number[] = [];
  let gcForced = false;
  try {
    for (const a of adapters) {
      let built: MeasuredBuild;
      try {
        built = await buildMeasured(() => a.create(options));
      } catch (error) {
        throw new SceneBuildError(a.name, options, error);
      }
      const inst = built.instance;
      gcForced = built.gcForced;
      instances.push(inst);
      // An engine in a thread of its own measured its build there.
      setupMs.push(inst.setupMs ?? built.setupMs);
      memoryMB.push(inst.engineMemoryMB ?? built.engineMemoryMB);
    }
    const total = (timing.steps + timing.warmup) * instances.length;
    let done = 0;
    const progress = (k: number): void => {
      done += k;
      timing.onProgress?.(done, total);
    };
    runInterleaved(instances, timing.warmup, timing.block, null, progress);
    // The warm-up steps' garbage. Without warm-up steps the builds' own collections were the last
    // thing to run, and a third forced full collection in a row after bitphysics' warmUp threw away
    // the code it had compiled (V8 ages a function's code at each full collection it does not run
    // in): joint-grid 100's first step then took 92 to 130 ms of main-thread CPU instead of 37 to 59.
    if (timing.warmup > 0) collectGarbage();
    const times = instances.map(() => new Float64Array(timing.steps));
    const cpu = new Float64Array(instances.length);
    for (const inst of instances) inst.beginTiming?.(timing.steps);
    const loadStart = loadNow();
    runInterleaved(instances, timing.steps, timing.block, times, progress, cpu);
    const loadEnd = loadNow();
    let heapUsedMB = sampleMemory().heapUsed;
    for (const inst of instances) inst.endTiming?.();

    const engines = instances.map((inst, i): EngineResult => {
      const stats = inst.stats();
      const snapshot = scene.extras ? inst.snapshot() : undefined;
      const sceneExtra = scene.extras && snapshot ? scene.extras(snapshot, options) : {};
      const msPerStep = summarize(times[i]!);
      const measured = { ...(stats.extra ?? {}), ...sceneExtra };
      const derived = scene.derive ? scene.derive(inst.engine, msPerStep, measured) : {};
      return {
        engine: inst.engine,
        times: times[i]!,
        msPerStep,
        cpuMsPerStep: cpu[i]! / timing.steps,
        bodyStepsPerSecond: msPerStep.median > 0 ? (stats.bodies * 1000) / msPerStep.median : Infinity,
        contacts: stats.contacts,
        bodies: stats.bodies,
        setupMs: setupMs[i]!,
        engineMemoryMB: memoryMB[i]!,
        extra: { ...measured, ...derived },
        notes: inst.notes,
      };
    });
    // Engines in isolates of their own: their heaps too (read by `stats` above).
    for (const inst of instances) heapUsedMB += inst.heapUsedMB?.() ?? 0;
    return {
      scene: options,
      steps: timing.steps,
      warmup: timing.warmup,
      block: timing.block,
      engines,
      heapUsedMB,
      gcForced,
      load: { start: loadStart, end: loadEnd, cpus: cpuCount() },
    };
  } finally {
    for (const inst of instances) inst.dispose();
  }
}

/**
 * Steps `inst` `steps` times. With `out` (a timed block), writes each step's milliseconds into
 * out[offset + s], calls `afterStep` after each outside the timed interval, and returns the process CPU
 * time of the block less the hooks', ms; untimed, returns 0. Used by the runner, and by a peer's own
 * thread (isolation/engine-thread.ts) for its blocks.
 */
export function runBlock(
  inst: Pick<EngineInstance, 'step' | 'afterStep'>,
  steps: number,
  out: Float64Array | null,
  offset: number,
): number {
  if (out === null) {
    for (let s = 0; s < steps; s++) inst.step();
    return 0;
  }
  const c0 = cpuMs();
  let hooks = 0;
  for (let s = 0; s < steps; s++) {
    const t0 = performance.now();
    inst.step();
    out[offset + s] = performance.now() - t0;
    if (inst.afterStep) {
      const a0 = cpuMs();
      inst.afterStep();
      hooks += cpuMs() - a0;
    }
  }
  return cpuMs() - c0 - hooks;
}

/** An instance built with its build time and memory measured (`buildMeasured`). */
export interface MeasuredBuild {
  readonly instance: EngineInstance;
  /** Time `create` took, ms. */
  readonly setupMs: number;
  /** The instance's memory, MB (`engineMemoryMB`). */
  readonly engineMemoryMB: number;
  /** Whether full garbage collections could be forced around the build (the memory figure is then exact). */
  readonly gcForced: boolean;
}

/**
 * Builds an instance with `create`, between full garbage collections (twice each: the first can leave
 * garbage only a second frees, weak references), timing the build and measuring the memory it kept.
 * Used by the runner, and by a peer's own thread for its isolate. @throws whatever `create` throws.
 */
export async function buildMeasured(create: () => Promise<EngineInstance>): Promise<MeasuredBuild> {
  const gcForced = collectGarbage() && collectGarbage();
  const m0 = sampleMemory();
  const t0 = performance.now();
  const instance = await create();
  const setupMs = performance.now() - t0;
  collectGarbage();
  collectGarbage();
  return { instance, setupMs, engineMemoryMB: engineMemoryMB(m0, sampleMemory(), instance.benchBytes), gcForced };
}

/**
 * Steps every instance `steps` times, alternating in blocks of `block` steps with the engine order
 * rotating every round; records each step's milliseconds into `times[engine][step]` when given, and
 * then (outside the timed interval) calls the instance's `afterStep` hook. An instance with `runSteps`
 * (an engine in a thread of its own) runs and times each block there instead. With `cpu` (timed runs),
 * adds each engine's process CPU time of its blocks, ms, less its hooks', into `cpu[engine]`.
 */
export function runInterleaved(
  instances: readonly Pick<EngineInstance, 'step' | 'afterStep' | 'runSteps'>[],
  steps: number,
  block: number,
  times: Float64Array[] | null,
  progress?: (steps: number) => void,
  cpu?: Float64Array,
): void {
  const m = instances.length;
  for (let start = 0, round = 0; start < steps; start += block, round++) {
    const k = Math.min(block, steps - start);
    for (let j = 0; j < m; j++) {
      const idx = (j + round) % m;
      const inst = instances[idx]!;
      const out = times ? times[idx]! : null;
      if (inst.runSteps) {
        // An engine in a thread of its own runs and times the block there.
        const r = inst.runSteps(k, out !== null);
        if (out && r.times) out.set(r.times, start);
        if (cpu) cpu[idx] = cpu[idx]! + r.cpuMs;
      } else {
        const used = runBlock(inst, k, out, start);
        if (cpu) cpu[idx] = cpu[idx]! + used;
      }
      progress?.(k);
    }
  }
}
