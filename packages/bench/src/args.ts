import { parseArgs } from 'node:util';
import { UsageError } from './errors';
import { ENGINES, OURS } from './engines/index';
import { resolveScene, sceneNames } from './scenes/index';

/** The command line, parsed and checked. */
export interface BenchArgs {
  /** `--list`: list scenes and engines, run nothing. */
  readonly list: boolean;
  /** `--help`. */
  readonly help: boolean;
  /** `--json`: one JSON object a line per engine run on stdout, nothing else there. */
  readonly json: boolean;
  /** `--scene`, default 'balls-in-box'. */
  readonly scene: string;
  /** `--count`, default the scene's defaultCount; integer in [1, the scene's limit]. */
  readonly count: number;
  /** `--steps`, timed steps, default 300; integer >= 1. */
  readonly steps: number;
  /** `--warmup`, untimed steps first, default 30; integer >= 0. */
  readonly warmup: number;
  /** `--seed`, default 1; a finite number. */
  readonly seed: number;
  /** `--block`, steps an engine runs before the next takes its turn, default 10; integer >= 1. */
  readonly block: number;
  /** `--times`: add every step's milliseconds (`timesMs`) to the JSON lines. */
  readonly times: boolean;
  /** Engines to run: ours first, then the `--vs` peers in the order given (duplicates dropped). */
  readonly engines: readonly string[];
}

/** Default scene, steps, warm-up, seed and block length. */
export const DEFAULTS = Object.freeze({ scene: 'balls-in-box', steps: 300, warmup: 30, seed: 1, block: 10 });

/** Usage text for `--help`. */
export const USAGE = `usage: npm run bench -- [options]

  --scene <name>     scene to run (default ${DEFAULTS.scene}); see --list
  --count <n>        bodies (default: the scene's default count)
  --steps <n>        timed steps per engine (default ${DEFAULTS.steps})
  --warmup <n>       untimed steps per engine before timing (default ${DEFAULTS.warmup})
  --seed <n>         seed of the scene layout (default ${DEFAULTS.seed})
  --vs <a,b,...>     peer engines to run side by side with bitphysics (e.g. rapier2d,matter; plain-loop)
  --block <n>        engines alternate every n steps (default ${DEFAULTS.block})
  --json             one JSON object per line per engine on stdout; notes and progress go to stderr
  --times            with --json: add every timed step's milliseconds as "timesMs"
  --list             list scenes and the engines that support each
  -h, --help         this text

Prints ms per step (median, min, max), body-steps per second, contacts in the last step, memory,
scene-specific quality fields, and for --vs the time ratio ours/peer (< 1: bitphysics is faster).
Exit code 2 on a usage error.`;

/**
 * Parses and checks the command line (without the node and script arguments).
 * @throws UsageError naming the offending flag or value.
 */
export function parseBenchArgs(argv: readonly string[]): BenchArgs {
  let values: Record<string, string | boolean | undefined>;
  try {
    ({ values } = parseArgs({
      args: [...argv],
      strict: true,
      allowPositionals: false,
      options: {
        scene: { type: 'string' },
        count: { type: 'string' },
        steps: { type: 'string' },
        warmup: { type: 'string' },
        seed: { type: 'string' },
        vs: { type: 'string' },
        block: { type: 'string' },
        json: { type: 'boolean' },
        times: { type: 'boolean' },
        list: { type: 'boolean' },
        help: { type: 'boolean', short: 'h' },
      },
    }));
  } catch (error) {
    throw new UsageError((error as Error).message);
  }
  const str = (k: string): string | undefined => values[k] as string | undefined;
  const list = values.list === true, help = values.help === true, json = values.json === true;

  const scene = str('scene') ?? DEFAULTS.scene;
  const resolved = resolveScene(scene);
  if (!resolved) throw new UsageError(`unknown scene ${JSON.stringify(scene)}; scenes: ${sceneNames().join(', ')}`);

  const count = str('count') === undefined ? resolved.definition.defaultCount : parseInteger('--count', str('count')!, 1);
  if (count > resolved.bench.maxCount) {
    throw new UsageError(`--count ${count} is above the limit of scene "${scene}" (${resolved.bench.maxCount})`);
  }
  const steps = str('steps') === undefined ? DEFAULTS.steps : parseInteger('--steps', str('steps')!, 1);
  const warmup = str('warmup') === undefined ? DEFAULTS.warmup : parseInteger('--warmup', str('warmup')!, 0);
  const block = str('block') === undefined ? DEFAULTS.block : parseInteger('--block', str('block')!, 1);
  let seed: number = DEFAULTS.seed;
  if (str('seed') !== undefined) {
    const text = str('seed')!;
    seed = Number(text);
    if (text.trim() === '' || !Number.isFinite(seed)) throw new UsageError(`--seed must be a finite number, got ${JSON.stringify(text)}`);
  }

  const engines = [OURS];
  if (str('vs') !== undefined) {
    for (const raw of str('vs')!.split(',')) {
      const name = raw.trim();
      if (name === '') throw new UsageError(`--vs takes a comma-separated list of engines, got ${JSON.stringify(str('vs'))}`);
      const adapter = ENGINES[name];
      if (!adapter || !Object.prototype.hasOwnProperty.call(ENGINES, name)) {
        throw new UsageError(`unknown engine ${JSON.stringify(name)}; engines: ${Object.keys(ENGINES).join(', ')}`);
      }
      if (!adapter.supports(scene)) {
        const supported = sceneNames().filter((s) => adapter.supports(s));
        throw new UsageError(`engine "${name}" does not support scene "${scene}" (it supports: ${supported.join(', ') || 'none'})`);
      }
      if (!engines.includes(name)) engines.push(name);
    }
  }
  return { list, help, json, times: values.times === true, scene, count, steps, warmup, seed, block, engines };
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
