/**
 * bitphysics-bench: times a scene of @bitphysics/physics headless in Node, optionally side by side
 * with peer engines (rapier2d, matter, plain-loop), and reports ms per step, throughput, contacts,
 * memory, scene-specific quality (e.g. the largest overlap of a settled pile) and ours/peer ratios.
 *
 *   npm run bench -- --scene balls-in-box --count 5000 --steps 300 --vs rapier2d,matter
 *   npm run bench -- --scene particles --count 1000000 --steps 100 --vs plain-loop
 *   npm run bench -- --scene galaxy --count 100000 --theta 0.5
 *   npm run bench -- --scene integrators --json
 *   npm run bench -- --scene forces --count 10000
 *   npm run bench -- --list
 *
 * Exit codes: 0 done, 1 a run failed, 2 usage error (unknown scene, engine or flag; bad number).
 */
import { realpathSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import cliProgress from 'cli-progress';
import { type BenchArgs, DEFAULTS, parseBenchArgs, USAGE } from './args.js';
import { catalogEntry, catalogNames } from './catalog.js';
import { bitphysicsThreadedEngine } from './engines/bitphysics.js';
import { ENGINES, enginesFor, OURS } from './engines/index.js';
import { USAGE_EXIT_CODE, UsageError } from './errors.js';
import { isolated } from './isolation/isolated-engine.js';
import { describeParam } from './params.js';
import { humanReport, jsonRecords, studyReport, table } from './report.js';
import { runBenchmark, SceneBuildError } from './runner.js';
import { resolveScene } from './scenes/index.js';
import { runSoak } from './soak.js';
import { resolveStudy } from './studies/index.js';

/** Where the CLI writes: injectable so the CLI can run inside another program. */
export interface CliIO {
  /** Results (human table or JSON lines). */
  out(text: string): void;
  /** Notes, warnings, errors. */
  err(text: string): void;
  /** Whether stdout is a terminal (enables the progress bar). */
  readonly isTTY: boolean;
}

const processIO: CliIO = {
  out: (text) => process.stdout.write(`${text}\n`),
  err: (text) => process.stderr.write(`${text}\n`),
  isTTY: process.stdout.isTTY === true,
};

/**
 * Runs the CLI with `argv` (arguments after the script name) and returns the exit code:
 * 0 success, 1 failure of a run, 2 usage error. Never calls process.exit.
 */
export async function main(argv: readonly string[], io: CliIO = processIO): Promise<number> {
  let args: BenchArgs;
  try {
    args = parseBenchArgs(argv);
  } catch (error) {
    if (error instanceof UsageError) {
      io.err(`bitphysics-bench: ${error.message}`);
      io.err('run with --help for usage');
      return USAGE_EXIT_CODE;
    }
    throw error;
  }
  if (args.help) {
    io.out(USAGE);
    return 0;
  }
  if (args.list) {
    listScenes(args.json, io);
    return 0;
  }
  if (args.soak && !args.study) {
    const steps = argv.some((a) => a === '--steps' || a.startsWith('--steps=')) ? args.steps : 100_000;
    runSoak({
      scene: args.scene,
      count: args.count,
      seed: args.seed,
      steps,
      every: Math.min(10_000, steps),
      print: (line) => io.out(line),
    });
    return 0;
  }
  return args.study ? runStudy(args, io) : run(args, io);
}

/**
 * Prints every scene and study with its description, default count, limit, parameters and the
 * engines that support it (`--json`: one object a line, `params` by name with default, range and
 * description).
 */
function listScenes(json: boolean, io: CliIO): void {
  const rows: string[][] = [['scene', 'engines', 'default count', 'max count', 'params', 'description']];
  const paramLines: string[] = [];
  for (const name of catalogNames()) {
    const s = catalogEntry(name)!;
    const engines = s.kind === 'study' ? ['bitphysics (study)'] : enginesFor(name);
    const params = Object.entries(s.params);
    if (json) {
      io.out(
        JSON.stringify({
          scene: name,
          kind: s.kind,
          description: s.description,
          engines: s.kind === 'study' ? [OURS] : engines,
          defaultCount: s.defaultCount,
          maxCount: s.maxCount,
          defaultSteps: s.defaults.steps ?? DEFAULTS.steps,
          defaultWarmup: s.defaults.warmup ?? DEFAULTS.warmup,
          params: Object.fromEntries(params),
        }),
      );
    } else {
      rows.push([
        name,
        engines.join(', '),
        String(s.defaultCount),
        String(s.maxCount),
        params.map(([p, spec]) => `--${p} ${spec.default}`).join(' ') || '-',
        s.description,
      ]);
      for (const [p, spec] of params) paramLines.push(`  ${describeParam(p, spec)} [--scene ${name}]`);
    }
  }
  if (!json) {
    io.out(table(rows, ['l', 'l', 'r', 'r', 'l', 'l']));
    if (paramLines.length > 0) io.out(['', 'scene parameters:', ...paramLines].join('\n'));
    io.out('');
    io.out('engines:');
    io.out(
      table(
        Object.values(ENGINES).map((e) => [`  ${e.name}`, e.description]),
        ['l', 'l'],
      ),
    );
  }
}

/**
 * Runs a study (`integrators`, `forces`) and prints its table (or one JSON line per item, each
 * starting with `scene` and, when the study has parameters, ending with `params`). Progress lines go
 * to stderr on a terminal only.
 */
function runStudy(args: BenchArgs, io: CliIO): number {
  const study = resolveStudy(args.scene)!;
  const showProgress = io.isTTY && !args.json;
  try {
    const result = study.run({
      count: args.count,
      steps: args.steps,
      warmup: args.warmup,
      seed: args.seed,
      params: args.params,
      onProgress: showProgress ? (what) => io.err(`${args.scene}: ${what}`) : undefined,
    });
    const hasParams = Object.keys(args.params).length > 0;
    if (args.json) {
      for (const record of result.records) {
        io.out(JSON.stringify({ scene: args.scene, ...record, seed: args.seed, ...(hasParams ? { params: args.params } : {}) }));
      }
    } else {
      io.out(
        studyReport(args.scene, result, {
          count: args.count,
          steps: args.steps,
          warmup: args.warmup,
          seed: args.seed,
          params: args.params,
        }),
      );
    }
    return 0;
  } catch (error) {
    io.err(`bitphysics-bench: ${(error as Error)?.stack ?? String(error)}`);
    return 1;
  }
}

/** Runs the benchmark the arguments describe and prints its results. */
async function run(args: BenchArgs, io: CliIO): Promise<number> {
  const scene = resolveScene(args.scene)!;
  // Peers each in a worker thread of their own (a V8 isolate: isolation/isolated-engine.ts), ours here.
  const adapters = args.engines.map((name) => (name === OURS || args.sameIsolate ? ENGINES[name]! : isolated(ENGINES[name]!)));
  // --threads n: the threaded world runs right after the single-threaded one, in the same process.
  if (args.threads > 1) adapters.splice(1, 0, bitphysicsThreadedEngine(args.threads));
  const showBar = io.isTTY && !args.json;
  const bar = showBar
    ? new cliProgress.SingleBar(
        {
          format: `${args.scene} [{bar}] {percentage}% | {value}/{total} steps | {duration_formatted}`,
          stream: process.stderr,
          hideCursor: true,
          clearOnComplete: true,
        },
        cliProgress.Presets.shades_classic,
      )
    : undefined;
  let started = false;
  try {
    const result = await runBenchmark(
      adapters,
      scene.bench,
      {
        scene: args.scene,
        count: args.count,
        seed: args.seed,
        params: args.params,
        hash: args.hash,
        threads: args.threads,
        warmUp: args.warmUp,
      },
      {
        steps: args.steps,
        warmup: args.warmup,
        block: args.block,
        onProgress: bar
          ? (done, total) => {
              if (!started) {
                bar.start(total, 0);
                started = true;
              }
              bar.update(done);
            }
          : undefined,
      },
    );
    if (started) bar?.stop();
    if (args.json) {
      for (const record of jsonRecords(result, { times: args.times })) io.out(JSON.stringify(record));
    } else {
      io.out(humanReport(result, scene.bench));
    }
    return 0;
  } catch (error) {
    if (started) bar?.stop();
    if (error instanceof SceneBuildError) {
      io.err(`bitphysics-bench: ${error.message}`);
      return error.cause instanceof RangeError || error.cause instanceof TypeError ? USAGE_EXIT_CODE : 1;
    }
    io.err(`bitphysics-bench: ${(error as Error).stack ?? String(error)}`);
    return 1;
  }
}

/** Whether this module is the program being run (not imported). */
function isMain(): boolean {
  const script = process.argv[1];
  if (!script) return false;
  try {
    return realpathSync(script) === realpathSync(fileURLToPath(import.meta.url));
  } catch {
    return false;
  }
}

/**
 * Exits once stdout and stderr have flushed. Exiting explicitly matters: after a run with rapier the
 * process could otherwise linger for a second or more while V8 finishes background WASM compilation.
 */
function exitAfterFlush(code: number): void {
  process.exitCode = code;
  process.stdout.write('', () => process.stderr.write('', () => process.exit(code)));
}

if (isMain()) {
  main(process.argv.slice(2)).then(exitAfterFlush, (error: unknown) => {
    process.stderr.write(`bitphysics-bench: ${(error as Error)?.stack ?? String(error)}\n`);
    exitAfterFlush(1);
  });
}
