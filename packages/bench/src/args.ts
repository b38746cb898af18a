import { parseArgs } from 'node:util';
import { catalogEntry, catalogNames, paramDeclarations } from './catalog.js';
import { ENGINES, OURS } from './engines/index.js';
import { UsageError } from './errors.js';
import { describeParam, parseParamValue } from './params.js';
import { sceneNames } from './scenes/index.js';

/** The command line, parsed and checked. */
export interface BenchArgs {
  /** `--list`: list scenes and engines, run nothing. */
  readonly list: boolean;
  /** `--help`. */
  readonly help: boolean;
  /** `--json`: one JSON object a line per engine run (or per study item) on stdout, nothing else there. */
  readonly json: boolean;
  /** Print a fingerprint of bitphysics' final state (stateHash) with its result, to compare runs across processes and machines. */
  readonly hash: boolean;
  /** Soak test: step our world for `steps` steps (default 100,000), reporting the heap and the step time every 10,000. */
  readonly soak: boolean;
  /**
   * `--threads`, default 1: with n > 1 the run adds `bitphysics-threads`, the same scene in a world made
   * with `threads: n`, stepped beside the single-threaded one in the same process; integer in [1, 64].
   */
  readonly threads: number;
  /** `--scene`, default 'balls-in-box': a physics scene or a bench study (see `catalogNames`). */
  readonly scene: string;
  /** Whether `scene` is a bench study (`integrators`, `forces`) rather than a physics scene run by engines. */
  readonly study: boolean;
  /** `--count`, default the scene's defaultCount; integer in [1, the scene's limit]. */
  readonly count: number;
  /** `--steps`, timed steps; default the scene's own default, else 300; integer >= 1. */
  readonly steps: number;
  /** `--warmup`, untimed steps first; default the scene's own default, else 30; integer >= 0. */
  readonly warmup: number;
  /** `--seed`, default 1; a finite number. */
  readonly seed: number;
  /** `--block`, steps an engine runs before the next takes its turn, default 10; integer >= 1. */
  readonly block: number;
  /** `--times`: add every step's milliseconds (`timesMs`) to the JSON lines. */
  readonly times: boolean;
  /**
   * `--same-isolate`: run the `--vs` peers on the bench's thread beside ours, not each in a worker
   * thread (V8 isolate) of its own (the default; see isolation/isolated-engine.ts for why).
   */
  readonly sameIsolate: boolean;
  /**
   * `--warm-up`: call bitphysics' `warmUp` before making its world (a small scene built and stepped
   * first, so its first steps run compiled code; the setup time includes it).
   */
  readonly warmUp: boolean;
  /** Engines to run: ours first, then the `--vs` peers in the order given (duplicates dropped). */
  readonly engines: readonly string[];
  /**
   * The scene's parameters (`--<name> <value>`), every one it declares, the given value or its
   * default; empty for scenes that declare none.
   */
  readonly params: Readonly<Record<string, number>>;
}

/** Default scene, steps, warm-up, seed and block length. */
export const DEFAULTS = Object.freeze({ scene: 'balls-in-box', steps: 300, warmup: 30, seed: 1, block: 10 });

/** The CLI's own flags (with a value or without); scene parameter names must differ from these. */
const BUILTIN_OPTIONS = {
  scene: { type: 'string' },
  count: { type: 'string' },
  steps: { type: 'string' },
  warmup: { type: 'string' },
  seed: { type: 'string' },
  vs: { type: 'string' },
  block: { type: 'string' },
  json: { type: 'boolean' },
  hash: { type: 'boolean' },
  'warm-up': { type: 'boolean' },
  soak: { type: 'boolean' },
  threads: { type: 'string' },
  times: { type: 'boolean' },
  'same-isolate': { type: 'boolean' },
  list: { type: 'boolean' },
  help: { type: 'boolean', short: 'h' },
} as const;

/** The scene parameter section of `--help`: one line per parameter flag, naming the scenes that take it. */
function paramUsage(): string {
  const lines: string[] = [];
  for (const name of catalogNames()) {
    for (const [param, spec] of Object.entries(catalogEntry(name)!.params)) lines.push(`  ${describeParam(param, spec)} [--scene ${name}]`);
  }
  return lines.length > 0 ? lines.join('\n') : '  (none)';
}

/** Usage text for `--help` (the scene parameter section lists every parameter any scene declares). */
export const USAGE = `usage: npm run bench -- [options] [--<param> <value> ...]

  --scene <name>     scene to run (default ${DEFAULTS.scene}); see --list
  --count <n>        bodies (default: the scene's default count)
  --steps <n>        timed steps per engine (default: the scene's, else ${DEFAULTS.steps})
  --warmup <n>       untimed steps per engine before timing (default: the scene's, else ${DEFAULTS.warmup})
  --seed <n>         seed of the scene layout (default ${DEFAULTS.seed})
  --vs <a,b,...>     peer engines to run side by side with bitphysics (e.g. rapier2d,matter; plain-loop)
  --block <n>        engines alternate every n steps (default ${DEFAULTS.block}; not for studies)
  --hash             print bitphysics' state fingerprint after the run (stateHash: every bit of every body; same
                     scene, count, seed and steps give the same hash on every machine)
  --threads <n>      also run bitphysics with threads: n (worker threads on shared arrays) beside the single-
                     threaded world; its line adds threads and speedup (single median / threaded median), the
                     serial fraction (Karp-Flatt) and Amdahl's projection to 8 and 16 cores
  --soak             soak test of bitphysics alone: --steps steps (default 100,000), the heap after a full GC and the
                     median step time printed every 10,000 steps (e.g. --scene fireworks --soak)
  --json             one JSON object per line per engine (or per study item) on stdout; notes and progress go to stderr
  --times            with --json: add every timed step's milliseconds as "timesMs" (not for studies)
  --warm-up          call bitphysics' warmUp before making its world (a small scene built and stepped first, so the
                     first timed steps run compiled code; counted in setup ms; with its pile of 1,100 balls for
                     balls-in-box and spheres-in-box); use with --warmup 0
  --same-isolate     run the --vs peers on bitphysics' thread (one V8 isolate) instead of each in a worker thread
                     of its own; a WASM peer then slows every JavaScript engine in the run (it detaches buffers)
  --list             list scenes, their parameters and the engines that support each
  -h, --help         this text

scene parameters (only the scene that declares one accepts it):
${paramUsage()}

Studies (integrators, forces) measure bitphysics alone: integrators prints each scheme's convergence
order, Kepler energy error and ns per body-step; forces the ns per body-step of each force law.
Scenes print ms per step (median, min, max), body-steps per second, contacts in the last step, memory,
scene-specific quality fields, and for --vs the time ratio ours/peer (< 1: bitphysics is faster).
Exit code 2 on a usage error.`;

/**
 * Parses and checks the command line (without the node and script arguments).
 * @throws UsageError naming the offending flag or value: an unknown flag, scene or engine, a number
 *   out of range, a scene parameter given to a scene that does not declare it, or a peer or
 *   `--block` / `--times` given to a study.
 */
export function parseBenchArgs(argv: readonly string[]): BenchArgs {
  const declarations = paramDeclarations();
  const options: Record<string, { type: 'string' | 'boolean'; short?: string }> = { ...BUILTIN_OPTIONS };
  for (const param of declarations.keys()) {
    if (Object.hasOwn(options, param)) throw new Error(`scene parameter --${param} clashes with a CLI flag`);
    options[param] = { type: 'string' };
  }
  let values: Record<string, string | boolean | undefined>;
  try {
    ({ values } = parseArgs({ args: [...argv], strict: true, allowPositionals: false, options }));
  } catch (error) {
    throw new UsageError((error as Error).message);
  }
  const str = (k: string): string | undefined => values[k] as string | undefined;
  const list = values.list === true,
    help = values.help === true,
    json = values.json === true;

  const scene = str('scene') ?? DEFAULTS.scene;
  const entry = catalogEntry(scene);
  if (!entry) throw new UsageError(`unknown scene ${JSON.stringify(scene)}; scenes: ${catalogNames().join(', ')}`);
  const study = entry.kind === 'study';

  const count = str('count') === undefined ? entry.defaultCount : parseInteger('--count', str('count')!, 1);
  if (count > entry.maxCount) {
    throw new UsageError(`--count ${count} is above the limit of scene "${scene}" (${entry.maxCount})`);
  }
  const steps = str('steps') === undefined ? (entry.defaults.steps ?? DEFAULTS.steps) : parseInteger('--steps', str('steps')!, 1);
  const warmup = str('warmup') === undefined ? (entry.defaults.warmup ?? DEFAULTS.warmup) : parseInteger('--warmup', str('warmup')!, 0);
  const threads = str('threads') === undefined ? 1 : parseInteger('--threads', str('threads')!, 1);
  if (threads > 64) throw new UsageError(`--threads must be at most 64, got ${threads}`);
  const block = str('block') === undefined ? DEFAULTS.block : parseInteger('--block', str('block')!, 1);
  let seed: number = DEFAULTS.seed;
  if (str('seed') !== undefined) {
    const text = str('seed')!;
    seed = Number(text);
    if (text.trim() === '' || !Number.isFinite(seed)) throw new UsageError(`--seed must be a finite number, got ${JSON.stringify(text)}`);
  }

  const params: Record<string, number> = {};
  for (const [param, scenes] of declarations) {
    const text = str(param);
    const spec = entry.params[param];
    if (!spec) {
      if (text !== undefined) {
        const own = Object.keys(entry.params);
        throw new UsageError(
          `--${param} is a parameter of scene ${scenes.map((s) => `"${s}"`).join(', ')}, not of "${scene}" ` +
            `(which takes ${own.length > 0 ? own.map((p) => `--${p}`).join(', ') : 'no parameters'})`,
        );
      }
      continue;
    }
    params[param] = text === undefined ? spec.default : parseParamValue(param, text, spec);
  }

  if (study) {
    if (str('vs') !== undefined) throw new UsageError(`--vs does not apply to "${scene}": it measures bitphysics alone, no peer engines`);
    if (str('block') !== undefined) throw new UsageError(`--block does not apply to "${scene}" (its timed worlds alternate every 5 steps)`);
    if (values.times === true) throw new UsageError(`--times does not apply to "${scene}" (it reports medians per item)`);
    if (threads > 1) throw new UsageError(`--threads does not apply to "${scene}" (it measures single-threaded laws)`);
    if (values['same-isolate'] === true) throw new UsageError(`--same-isolate does not apply to "${scene}": it runs no peer engines`);
  }
  const engines = [OURS];
  if (str('vs') !== undefined) {
    for (const raw of str('vs')!.split(',')) {
      const name = raw.trim();
      if (name === '') throw new UsageError(`--vs takes a comma-separated list of engines, got ${JSON.stringify(str('vs'))}`);
      const adapter = ENGINES[name];
      if (!adapter || !Object.hasOwn(ENGINES, name)) {
        throw new UsageError(`unknown engine ${JSON.stringify(name)}; engines: ${Object.keys(ENGINES).join(', ')}`);
      }
      if (!adapter.supports(scene)) {
        const supported = sceneNames().filter((s) => adapter.supports(s));
        throw new UsageError(`engine "${name}" does not support scene "${scene}" (it supports: ${supported.join(', ') || 'none'})`);
      }
      if (!engines.includes(name)) engines.push(name);
    }
  }
  return {
    list,
    help,
    json,
    hash: values.hash === true,
    soak: values.soak === true,
    threads,
    times: values.times === true,
    sameIsolate: values['same-isolate'] === true,
    warmUp: values['warm-up'] === true,
    scene,
    study,
    count,
    steps,
    warmup,
    seed,
    block,
    engines,
    params,
  };
}

/**
 * Parses a decimal integer (underscores allowed as separators: 1_000_000) of at least `min`.
 * @throws UsageError naming the flag and the value.
 */
export function parseInteger(flag: string, text: string, min: number): number {
  const cleaned = text.trim().replace(/_/g, '');
  if (!/^[+-]?\d+$/.test(cleaned)) throw new UsageError(`${flag} must be an integer, got ${JSON.stringify(text)}`);
  const value = Number(cleaned);
  if (!Number.isSafeInteger(value)) throw new UsageError(`${flag} is too large, got ${JSON.stringify(text)}`);
  if (value < min) throw new UsageError(`${flag} must be at least ${min}, got ${value}`);
  return value;
}
