// The bench CLI end to end: built with buildBench() and run with small counts, twice as a process of its
// own (exit codes and output as a shell sees them) and otherwise through the built CLI's `main`, every
// other run one after another in one child process (`queued`). These tests check output shape and error
// handling only; they never assert timings.
import { execFile } from 'node:child_process';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';

const root = resolve(import.meta.dirname, '..', '..');
const cli = join(root, 'packages', 'bench', 'dist', 'cli.js');

/** What one CLI run printed and returned. */
interface CliRun {
  code: number;
  stdout: string;
  stderr: string;
}

/**
 * Node's flags for every CLI run: V8 compiles WebAssembly with its baseline compiler (Liftoff) only.
 * The CLI turns Liftoff off before a peer engine loads (rapier2d.ts `optimizedWasm`) so that peers
 * are timed on optimized code; compiling a peer's whole module that way costs seconds of CPU in every
 * run, and `--liftoff-only` overrides it. These tests check no timing, and WebAssembly computes the same
 * results whichever compiler built it, so every field they compare is the same.
 */
const NODE_FLAGS = ['--liftoff-only'];

/** Runs the built CLI with `args`; resolves with its exit code and output (never rejects on a non-zero exit). */
function runCli(args: string[]): Promise<CliRun> {
  return new Promise((done, fail) => {
    execFile(
      process.execPath,
      [...NODE_FLAGS, cli, ...args],
      { cwd: root, timeout: 60_000, maxBuffer: 16 * 2 ** 20 },
      (error, stdout, stderr) => {
        if (error && typeof error.code !== 'number') {
          fail(error);
          return;
        }
        done({ code: error ? (error.code as number) : 0, stdout, stderr });
      },
    );
  });
}

/**
 * Milliseconds a test that reads a `queued` run may wait: the whole batch (about 25 s of CPU, every run
 * of this file but two) runs before any of its results is read, on a machine busy with other tests.
 */
const BATCH_TIMEOUT_MS = 480_000;

/**
 * Runs the built CLI's `main(argv, io)` once for each of `argvs`, one after another in one Node
 * process (./cli-batch.mjs), and resolves with each run's return value (the exit code the CLI exits
 * with) and output as a process of its own would show them; a run that throws gives code -1.
 */
function runMain(argvs: string[][]): Promise<CliRun[]> {
  return new Promise((done, fail) => {
    execFile(
      process.execPath,
      [...NODE_FLAGS, join(import.meta.dirname, 'cli-batch.mjs')],
      {
        cwd: root,
        timeout: BATCH_TIMEOUT_MS,
        maxBuffer: 16 * 2 ** 20,
        env: { ...process.env, BENCH_CLI: pathToFileURL(cli).href, BENCH_ARGVS: JSON.stringify(argvs) },
      },
      (error, stdout, stderr) => {
        if (error) fail(new Error(`${error.message}\n${stderr}`));
        else done(JSON.parse(stdout) as CliRun[]);
      },
    );
  });
}

/** The argument lists `queued` collected, run in this order. */
const queue: string[][] = [];
let batch: Promise<CliRun[]> | undefined;

/**
 * Adds a CLI run with `args` to the one batch of this file (called while the tests are collected, so
 * the batch is complete before any test runs); returns a function resolving with that run's result,
 * the first call starting the batch in one child process (`runMain`). One process spares each run
 * Node's start and the CLI bundle's load, and with `--same-isolate` a peer engine's module is loaded
 * and compiled once for all the runs that use it, not once a run in a worker thread.
 */
function queued(args: string[]): () => Promise<CliRun> {
  const index = queue.push(args) - 1;
  return async () => (await (batch ??= runMain(queue)))[index]!;
}

/** Parses every stdout line as JSON (fails the test if any line is not). */
function jsonLines(stdout: string): Array<Record<string, unknown>> {
  return stdout
    .trim()
    .split('\n')
    .map((line) => JSON.parse(line) as Record<string, unknown>);
}

/** Checks the fields every engine line carries. */
function expectEngineLine(line: Record<string, unknown>, engine: string, scene: string, count: number, steps: number): void {
  expect(line.scene).toBe(scene);
  expect(line.engine).toBe(engine);
  expect(line.count).toBe(count);
  expect(line.steps).toBe(steps);
  const ms = line.msPerStep as Record<string, number>;
  for (const k of ['median', 'min', 'max']) expect(Number.isFinite(ms[k])).toBe(true);
  expect(ms.min).toBeLessThanOrEqual(ms.median!);
  expect(ms.median).toBeLessThanOrEqual(ms.max!);
  expect('contacts' in line).toBe(true);
  expect(typeof line.bodyStepsPerSecond).toBe('number');
  expect(typeof line.heapUsedMB).toBe('number');
}

beforeAll(async () => {
  const build = (await import(pathToFileURL(join(root, 'scripts', 'build.mjs')).href)) as { buildBench: () => Promise<void> };
  await build.buildBench();
});

describe('bench CLI', { timeout: BATCH_TIMEOUT_MS }, () => {
  it('--json prints one parseable line with the fields', async () => {
    const run = await runCli(['--scene', 'balls-in-box', '--count', '200', '--steps', '10', '--warmup', '2', '--json']);
    expect(run.code).toBe(0);
    const lines = jsonLines(run.stdout);
    expect(lines).toHaveLength(1);
    const line = lines[0]!;
    expectEngineLine(line, 'bitphysics', 'balls-in-box', 200, 10);
    expect(typeof line.contacts).toBe('number');
    expect(typeof line.maxOverlapPercent).toBe('number');
    expect(line.maxOverlapPercent as number).toBeGreaterThanOrEqual(0);
  });

  // The JSON run: each peer in a worker thread of its own, as a user runs them (the other runs of peers
  // here share the bench's thread, --same-isolate, which the isolation test below compares with this).
  // The human-readable run shares it too: its lines are formatted from the same results whichever
  // thread computed them, and a peer's module is then loaded once for every --same-isolate run of it.
  const vs = ['--scene', 'balls-in-box', '--vs', 'rapier2d,matter'];
  const vsJson = queued([...vs, '--count', '200', '--steps', '20', '--warmup', '2', '--json']);
  const vsHuman = queued([...vs, '--count', '50', '--steps', '5', '--warmup', '1', '--same-isolate']);
  it('--vs rapier2d,matter gives one line per engine and ours/peer ratios', async () => {
    const [json, human] = await Promise.all([vsJson(), vsHuman()]);
    expect(json.code).toBe(0);
    const lines = jsonLines(json.stdout);
    expect(lines.map((l) => l.engine)).toEqual(['bitphysics', 'rapier2d', 'matter']);
    for (const line of lines) {
      expectEngineLine(line, line.engine as string, 'balls-in-box', 200, 20);
      expect(typeof line.contacts).toBe('number');
      expect(typeof line.maxOverlapPercent).toBe('number');
    }
    expect(lines[0]!.ratio).toBeUndefined();
    for (const peer of lines.slice(1)) {
      expect(peer.ratioOf).toBe(`bitphysics/${peer.engine as string}`);
      expect(peer.ratio as number).toBeGreaterThan(0);
    }
    expect(human.code).toBe(0);
    expect(human.stdout).toMatch(/bitphysics\/rapier2d\s+\d+\.\d+/);
    expect(human.stdout).toMatch(/bitphysics\/matter\s+\d+\.\d+/);
    expect(human.stdout).toMatch(/max overlap/);
    expect(human.stdout).toMatch(/matter-js is not SI/);
  });

  const plainLoop = queued([
    '--scene',
    'particles',
    '--count',
    '1000',
    '--steps',
    '10',
    '--warmup',
    '2',
    '--vs',
    'plain-loop',
    '--json',
    '--same-isolate',
  ]);
  it('--vs plain-loop on particles computes the same states', async () => {
    const run = await plainLoop();
    expect(run.code).toBe(0);
    const [ours, plain] = jsonLines(run.stdout);
    expectEngineLine(ours!, 'bitphysics', 'particles', 1000, 10);
    expectEngineLine(plain!, 'plain-loop', 'particles', 1000, 10);
    expect(plain!.contacts).toBeNull();
    expect(plain!.ratioOf).toBe('bitphysics/plain-loop');
    expect(ours!.positionChecksum).toBe(plain!.positionChecksum);
  });

  // 40,000 particles: above 2 x MIN_PARALLEL_PER_THREAD, so the workers take their half.
  const threads = queued([
    '--scene',
    'particles',
    '--count',
    '40000',
    '--steps',
    '5',
    '--warmup',
    '1',
    '--threads',
    '2',
    '--hash',
    '--json',
  ]);
  it('--threads 2 runs bitphysics-threads beside bitphysics: threads, speedup, serial fraction, Amdahl projection and the same state hash', async () => {
    const run = await threads();
    expect(run.code).toBe(0);
    const lines = jsonLines(run.stdout);
    expect(lines.map((l) => l.engine)).toEqual(['bitphysics', 'bitphysics-threads']);
    expect(lines[0]!.threads).toBe(1);
    expect(lines[1]!.threads).toBe(2);
    const ms = (l: Record<string, unknown>) => (l.msPerStep as Record<string, number>).median!;
    expect(lines[1]!.speedup).toBeCloseTo(ms(lines[0]!) / ms(lines[1]!), 2);
    // Karp-Flatt serial fraction of that speedup on 2 threads, (1/S - 1/2) / (1/2) in [0, 1], and
    // Amdahl's projection from it (rounded to 3 digits in the line).
    const S = lines[1]!.speedup as number,
      f = lines[1]!.serialFraction as number;
    expect(f).toBeCloseTo(Math.min(1, Math.max(0, 2 / S - 1)), 2);
    expect(lines[1]!.amdahl8).toBeCloseTo(1 / (f + (1 - f) / 8), 1);
    expect(lines[1]!.amdahl16).toBeCloseTo(1 / (f + (1 - f) / 16), 1);
    expect(lines[1]!.stateHash).toBe(lines[0]!.stateHash);
  });

  const warmUpArgs = ['--scene', 'pyramid', '--count', '6', '--steps', '10', '--warmup', '0', '--hash'];
  const [warmUpPlain, warmUpWarm] = [queued(warmUpArgs), queued([...warmUpArgs, '--warm-up'])];
  it('--warm-up runs the warm-up scene first and leaves the state as it is without it', async () => {
    const [plain, warm] = await Promise.all([warmUpPlain(), warmUpWarm()]);
    expect([plain.code, warm.code]).toEqual([0, 0]);
    const hash = (out: string) => /bitphysics: stateHash ([0-9a-f]+)/.exec(out)?.[1];
    expect(hash(plain.stdout)).toMatch(/^[0-9a-f]{16}$/);
    expect(hash(warm.stdout)).toBe(hash(plain.stdout));
    expect(warm.stdout).toContain('warm-up scene run first');
    expect(plain.stdout).not.toContain('warm-up scene run first');
  });

  const [listHuman, listJson] = [queued(['--list']), queued(['--list', '--json'])];
  it('--list lists the scenes and the engines that support each', async () => {
    const [human, json] = await Promise.all([listHuman(), listJson()]);
    expect(human.code).toBe(0);
    expect(human.stdout).toMatch(/^balls-in-box\s+bitphysics, rapier2d, rapier2d-simd, matter\s/m);
    expect(human.stdout).toMatch(/^particles\s+bitphysics, plain-loop\s/m);
    const scenes = jsonLines(json.stdout);
    expect(scenes.map((s) => s.scene)).toEqual(expect.arrayContaining(['balls-in-box', 'particles']));
    for (const s of scenes) expect(typeof s.description).toBe('string');
  });
});

describe('bench CLI scene parameters, studies and newer scenes', { timeout: BATCH_TIMEOUT_MS }, () => {
  /**
   * joint-grid --vs rapier2d: Rapier builds the same net (impulse revolute joints, the same pins) and
   * reports the same joint error, the largest anchor separation after any timed step. A 10 x 10 net
   * has 2 * 10 * 9 = 180 joints; ours solves 174 (the 6 between pinned neighbours join two static
   * bodies). Ours must hold the net at least as tightly as Rapier's default solver (measured: 0.0041
   * against 0.0125 m over 60 steps), and both must hold it to a few centimetres.
   */
  const jointGrid = queued([
    '--scene',
    'joint-grid',
    '--count',
    '10',
    '--steps',
    '60',
    '--warmup',
    '0',
    '--vs',
    'rapier2d',
    '--json',
    '--same-isolate',
  ]);
  it('joint-grid --vs rapier2d: the same net in Rapier, its joint error beside ours', async () => {
    const run = await jointGrid();
    expect(run.code).toBe(0);
    const [ours, rapier] = jsonLines(run.stdout);
    expectEngineLine(ours!, 'bitphysics', 'joint-grid', 10, 60);
    expectEngineLine(rapier!, 'rapier2d', 'joint-grid', 10, 60);
    expect(rapier!.joints).toBe(180);
    expect(ours!.joints).toBe(174);
    expect(rapier!.maxJointError as number).toBeGreaterThan(0);
    expect(rapier!.maxJointError as number).toBeLessThan(0.05);
    expect(ours!.maxJointError as number).toBeLessThanOrEqual(rapier!.maxJointError as number);
    expect(rapier!.ratioOf).toBe('bitphysics/rapier2d');
  });

  const galaxy = queued(['--scene', 'galaxy', '--count', '300', '--steps', '2', '--warmup', '0', '--theta', '0.5', '--json']);
  it('galaxy takes --theta, passes it to the world and echoes it in the JSON line', async () => {
    const run = await galaxy();
    expect(run.code).toBe(0);
    const [line] = jsonLines(run.stdout);
    expectEngineLine(line!, 'bitphysics', 'galaxy', 300, 2);
    expect(line!.params).toEqual({ theta: 0.5 });
    expect(line!.theta).toBe(0.5); // the opening angle the world actually used
  });

  /**
   * balls-in-box --restitution: every engine builds the layout with it and reports energyDrift, the
   * relative change of kinetic plus gravitational energy from the layout at rest. Ours must not gain
   * energy (restitution <= 1 and friction only take it out; 1e-3 allows the final snapshot's soft
   * contact compression, which holds some of the energy as overlap rather than motion).
   */
  const restitution = queued([
    '--scene',
    'balls-in-box',
    '--count',
    '200',
    '--steps',
    '20',
    '--warmup',
    '0',
    '--restitution',
    '1',
    '--vs',
    'rapier2d',
    '--json',
    '--same-isolate',
  ]);
  it('balls-in-box takes --restitution, echoes it and reports energyDrift for every engine', async () => {
    const run = await restitution();
    expect(run.code).toBe(0);
    const lines = jsonLines(run.stdout);
    const ours = lines.find((l) => l.engine === 'bitphysics')!,
      rapier = lines.find((l) => l.engine === 'rapier2d')!;
    expect(ours.params).toEqual({ restitution: 1 });
    expect(ours.restitution).toBe(1);
    expect(rapier.restitution).toBe(1);
    expect(typeof ours.energyDrift).toBe('number');
    expect(typeof rapier.energyDrift).toBe('number');
    expect(ours.energyDrift as number).toBeLessThan(1e-3);
    // A process of its own: the exit code a shell sees.
    const bad = await runCli(['--scene', 'balls-in-box', '--count', '10', '--restitution', '1.5']);
    expect(bad.code).toBe(2);
    expect(bad.stderr).toMatch(/--restitution must be >= 0 and <= 1/);
  });

  const [help, listWithParams] = [queued(['--help']), queued(['--list', '--json'])];
  it('--help and --list show the scene parameters', async () => {
    const [helpRun, list] = await Promise.all([help(), listWithParams()]);
    expect(helpRun.code).toBe(0);
    expect(helpRun.stdout).toMatch(/--theta <x>: galaxy: Barnes-Hut opening angle.*default 0\.7/);
    const galaxy = jsonLines(list.stdout).find((s) => s.scene === 'galaxy')!;
    expect((galaxy.params as Record<string, { default: number }>).theta!.default).toBe(0.7);
  });

  /**
   * Orders are deterministic (no timing: fixed step counts on one orbit), so the only slack needed is
   * for the distance from the asymptotic regime: at dt = T/800 -> T/1600 the measured orders differ
   * from theory by < 0.05 (Euler 0.97, RK4 4.03). +-0.3 keeps the test robust to small changes of
   * the schemes or the step sizes while still telling order 1 from 2 and 4 from 3 or 5.
   */
  const integrators = queued(['--scene', 'integrators', '--orbits', '1', '--count', '100', '--steps', '3', '--warmup', '1', '--json']);
  it('integrators --json: one line per scheme with order, energy error and cost; orders match theory', async () => {
    const run = await integrators();
    expect(run.code).toBe(0);
    const lines = jsonLines(run.stdout);
    const expected: Record<string, number> = {
      'explicit-euler': 1,
      'semi-implicit-euler': 1,
      'implicit-euler': 1,
      rk2: 2,
      rk4: 4,
      'position-verlet': 2,
      'velocity-verlet': 2,
    };
    expect(lines.map((l) => l.integrator)).toEqual(Object.keys(expected));
    for (const line of lines) {
      expect(line.scene).toBe('integrators');
      expect(Math.abs((line.order as number) - expected[line.integrator as string]!)).toBeLessThan(0.3);
      expect(line.expectedOrder).toBe(expected[line.integrator as string]);
      expect(line.energyError === null || (typeof line.energyError === 'number' && line.energyError >= 0)).toBe(true);
      expect(line.nsPerBodyStep as number).toBeGreaterThan(0);
      expect(line.params).toEqual({ orbits: 1 });
    }
    // RK4 conserves the Kepler energy far better than explicit Euler.
    const by = Object.fromEntries(lines.map((l) => [l.integrator, l]));
    expect(by.rk4!.energyError as number).toBeLessThan(1e-6);
    expect(by['explicit-euler']!.energyError as number).toBeGreaterThan(1e-2);
  });

  /**
   * Each cost is a difference of two medians, so a law cheaper than the timing noise could come out
   * near 0 on a loaded machine: every line must have a finite cost, a positive baseline and whole
   * step, and the laws far above the noise (pairwise sums, Barnes-Hut, turbulent wind) a positive cost.
   */
  const forces = queued(['--scene', 'forces', '--count', '2100', '--steps', '4', '--warmup', '1', '--json']);
  it('forces --json: one line per force law with finite costs; pairwise laws capped at 2,000 bodies', async () => {
    const run = await forces();
    expect(run.code).toBe(0);
    const lines = jsonLines(run.stdout);
    expect(lines.length).toBeGreaterThanOrEqual(15);
    expect(new Set(lines.map((l) => l.law)).size).toBe(lines.length);
    for (const line of lines) {
      expect(line.scene).toBe('forces');
      expect(Number.isFinite(line.nsPerBodyStep)).toBe(true);
      expect(line.baselineNsPerBodyStep as number).toBeGreaterThan(0);
      expect(line.wholeNsPerBodyStep as number).toBeGreaterThan(0);
      expect(line.count).toBe(line.pairwise ? 2000 : 2100);
    }
    const by = Object.fromEntries(lines.map((l) => [l.law, l]));
    for (const law of ['coulomb-direct', 'mutual-gravity-direct', 'mutual-gravity-barnes-hut', 'drag-turbulence']) {
      expect(by[law]!.nsPerBodyStep as number).toBeGreaterThan(0);
    }
  });

  const spheres = queued([
    '--scene',
    'spheres-in-box',
    '--count',
    '100',
    '--steps',
    '5',
    '--warmup',
    '1',
    '--vs',
    'rapier3d',
    '--json',
    '--times',
    '--same-isolate',
  ]);
  it('spheres-in-box --vs rapier3d gives a ratio line, on the median and on the mean (whole timed run)', async () => {
    const run = await spheres();
    expect(run.code).toBe(0);
    const [ours, peer] = jsonLines(run.stdout);
    expectEngineLine(ours!, 'bitphysics', 'spheres-in-box', 100, 5);
    expectEngineLine(peer!, 'rapier3d', 'spheres-in-box', 100, 5);
    expect(peer!.ratioOf).toBe('bitphysics/rapier3d');
    expect(peer!.ratio as number).toBeGreaterThan(0);
    // The mean is the total of the timed steps over their count (timesMs rounded to 4 digits: 1e-3 relative).
    const ms = (l: Record<string, unknown>) => l.msPerStep as Record<string, number>;
    const total = (l: Record<string, unknown>) => (l.timesMs as number[]).reduce((x, y) => x + y, 0);
    for (const line of [ours!, peer!]) expect(Math.abs((ms(line).mean! * 5) / total(line) - 1)).toBeLessThan(1e-3);
    expect(ours!.ratioMean).toBeUndefined();
    expect(Math.abs((peer!.ratioMean as number) / (ms(ours!).mean! / ms(peer!).mean!) - 1)).toBeLessThan(1e-3);
    // CPU time: positive, and the ratio is of the two lines' figures (each rounded to 6 digits).
    for (const line of [ours!, peer!]) expect(line.cpuMsPerStep as number).toBeGreaterThan(0);
    expect(Math.abs((peer!.ratioCpu as number) / ((ours!.cpuMsPerStep as number) / (peer!.cpuMsPerStep as number)) - 1)).toBeLessThan(1e-3);
  });

  /**
   * The 3D box scenes against rapier3d: both engines report the scene's quality fields from their own
   * final poses. A pyramid of base 3 (14 boxes) standing on its exact start barely moves in 30 steps
   * (top drop well under the 0.05 m goal in both); a few boxes dropped into the closed box never
   * overlap by half their half extent.
   */
  const pile3d = queued([
    '--scene',
    'box-pile-3d',
    '--count',
    '27',
    '--steps',
    '20',
    '--warmup',
    '0',
    '--vs',
    'rapier3d',
    '--json',
    '--same-isolate',
  ]);
  const pyramid3d = queued(['--scene', 'pyramid-3d', '--count', '3', '--steps', '30', '--vs', 'rapier3d', '--json', '--same-isolate']);
  it('box-pile-3d and pyramid-3d --vs rapier3d report overlap, topDrop, maxDrift and fallen for both engines', async () => {
    const [pile, pyramid] = await Promise.all([pile3d(), pyramid3d()]);
    expect(pile.code).toBe(0);
    expect(pyramid.code).toBe(0);
    for (const line of jsonLines(pile.stdout)) {
      expect(line.scene).toBe('box-pile-3d');
      expect(line.maxOverlapPercent as number).toBeLessThan(50);
      expect(typeof line.overlappingPairs).toBe('number');
      // 27 boxes falling for 20 steps (1/3 s): none can have rested the 0.5 s sleep needs.
      expect(line.halfAsleepStep).toBeNull();
      expect(line.allAsleepStep).toBeNull();
    }
    const lines = jsonLines(pyramid.stdout);
    expect(lines.map((l) => l.engine)).toEqual(['bitphysics', 'rapier3d']);
    for (const line of lines) {
      expect(line.topDrop as number).toBeLessThan(0.05);
      expect(line.fallen).toBe(0);
      expect(typeof line.maxDrift).toBe('number');
    }
  });

  /**
   * The peers users pick for speed (issue 36): the WASM SIMD builds of Rapier and Jolt's WASM build. A
   * pyramid standing on its exact start barely moves in 30 steps in any engine that stacks boxes
   * (top drop well under the 0.05 m goal; none fall), in 2D (base 3: 6 boxes) and 3D (base 3: 14
   * boxes); a few spheres dropped into the closed box never overlap by half their radius.
   */
  const simdFlat = queued(['--scene', 'pyramid', '--count', '3', '--steps', '30', '--vs', 'rapier2d-simd', '--json', '--same-isolate']);
  const simdSolid = queued([
    '--scene',
    'pyramid-3d',
    '--count',
    '3',
    '--steps',
    '30',
    '--vs',
    'rapier3d-simd,jolt',
    '--json',
    '--same-isolate',
  ]);
  const joltSpheres = queued([
    '--scene',
    'spheres-in-box',
    '--count',
    '64',
    '--steps',
    '20',
    '--warmup',
    '0',
    '--vs',
    'jolt',
    '--json',
    '--same-isolate',
  ]);
  it('--vs rapier2d-simd, rapier3d-simd and jolt run the pyramids and spheres with the quality fields', async () => {
    const [flat, solid, spheres] = await Promise.all([simdFlat(), simdSolid(), joltSpheres()]);
    for (const run of [flat, solid, spheres]) expect(run.code).toBe(0);
    expect(jsonLines(flat.stdout).map((l) => l.engine)).toEqual(['bitphysics', 'rapier2d-simd']);
    expect(jsonLines(solid.stdout).map((l) => l.engine)).toEqual(['bitphysics', 'rapier3d-simd', 'jolt']);
    for (const line of [...jsonLines(flat.stdout), ...jsonLines(solid.stdout)]) {
      expect(line.topDrop as number).toBeLessThan(0.05);
      expect(line.fallen).toBe(0);
    }
    const [, jolt] = jsonLines(spheres.stdout);
    expectEngineLine(jolt!, 'jolt', 'spheres-in-box', 64, 20);
    expect(jolt!.ratioOf).toBe('bitphysics/jolt');
    expect(jolt!.maxOverlapPercent as number).toBeLessThan(50);
  });

  /**
   * Each peer runs in a worker thread (a V8 isolate) of its own unless --same-isolate: the isolation
   * must change no result. Both runs of a small box pile give every engine the same contacts, overlap
   * and final quality fields (rapier is deterministic on one machine; ours on every machine), and the
   * peer's setup time and memory are still measured (in its isolate).
   */
  const isolationArgs = [
    '--scene',
    'box-pile-3d',
    '--count',
    '27',
    '--steps',
    '40',
    '--warmup',
    '20',
    '--vs',
    'rapier3d',
    '--json',
    '--hash',
  ];
  const [isolated, shared] = [queued(isolationArgs), queued([...isolationArgs, '--same-isolate'])];
  it('peers in their own isolates compute what they compute beside ours (--same-isolate)', async () => {
    const [apart, together] = await Promise.all([isolated(), shared()]);
    expect(apart.code).toBe(0);
    expect(together.code).toBe(0);
    const a = jsonLines(apart.stdout),
      b = jsonLines(together.stdout);
    expect(a.map((l) => l.engine)).toEqual(['bitphysics', 'rapier3d']);
    for (let i = 0; i < 2; i++) {
      for (const field of ['contacts', 'maxOverlapPercent', 'overlappingPairs', 'maxWallPenetrationPercent', 'stateHash'])
        expect(a[i]![field]).toEqual(b[i]![field]);
      expect(a[i]!.setupMs as number).toBeGreaterThan(0);
      expect(typeof a[i]!.engineMemoryMB).toBe('number');
    }
    // Landed boxes: the compared figures are not zeros.
    expect(a[1]!.contacts as number).toBeGreaterThan(0);
    expect(a[1]!.maxWallPenetrationPercent as number).toBeGreaterThan(0);
    expect(typeof a[0]!.stateHash).toBe('string');
  });

  /**
   * The 2D pyramid against its three peers: every engine runs the same layout and reports the quality
   * fields from its own final poses. A base-3 pyramid (6 boxes) on its exact start barely moves in 30
   * steps in any engine; before the Box2D v2 peers' boxes were shrunk by their 0.01 m polygon skin, the
   * rows started inside each other's skins and planck and box2d-wasm pushed the top up by 0.04 m.
   */
  const pyramid2d = queued([
    '--scene',
    'pyramid',
    '--count',
    '3',
    '--steps',
    '30',
    '--vs',
    'rapier2d,planck,box2d-wasm',
    '--json',
    '--same-isolate',
  ]);
  it('pyramid --vs rapier2d,planck,box2d-wasm runs all three peers on the same 1 m boxes', async () => {
    const run = await pyramid2d();
    expect(run.code).toBe(0);
    const lines = jsonLines(run.stdout);
    expect(lines.map((l) => l.engine)).toEqual(['bitphysics', 'rapier2d', 'planck', 'box2d-wasm']);
    for (const line of lines) {
      expect(Math.abs(line.topDrop as number)).toBeLessThan(0.02);
      expect(line.fallen).toBe(0);
      expect(line.maxDrift as number).toBeLessThan(0.01);
    }
  });

  // 1,000 live particles reach steady churn after ~5 s, as at the default count: 360 warm-up steps.
  const fireworks = queued(['--scene', 'fireworks', '--count', '1000', '--steps', '30', '--warmup', '360', '--json']);
  it('fireworks --json reports spawn and expiry every step', async () => {
    const run = await fireworks();
    expect(run.code).toBe(0);
    const [line] = jsonLines(run.stdout);
    expectEngineLine(line!, 'bitphysics', 'fireworks', 1000, 30);
    expect(line!.spawnedPerStep as number).toBeGreaterThan(0);
    expect(line!.expiredPerStep as number).toBeGreaterThan(0);
    expect(line!.liveMedian as number).toBeGreaterThan(0);
  });
});

/**
 * Usage errors: `main` returns 2 (the exit code; a real process exits with it in the --restitution
 * test above), names the bad value on stderr and prints nothing on stdout. The cases run in this
 * file's batch (`queued`): each stops at its arguments, so a process apiece would mostly start Node.
 */
describe('bench CLI usage errors exit 2 naming the bad value', { timeout: BATCH_TIMEOUT_MS }, () => {
  const cases: Array<[string, string[], string]> = [
    ['unknown scene', ['--scene', 'no-such-scene'], 'no-such-scene'],
    ['unknown engine', ['--vs', 'rapier2d,box2d'], 'box2d'],
    ['engine without the scene', ['--scene', 'balls-in-box', '--vs', 'plain-loop'], 'plain-loop'],
    ['unknown flag', ['--frobnicate'], '--frobnicate'],
    ['non-integer count', ['--count', '12.5'], '12.5'],
    ['non-numeric count', ['--count', 'many'], 'many'],
    ['count above the limit', ['--scene', 'balls-in-box', '--count', '20000000'], '20000000'],
    ['zero steps', ['--steps', '0'], '--steps'],
    ['bad seed', ['--seed', 'abc'], 'abc'],
    ['non-positive theta', ['--scene', 'galaxy', '--theta', '0'], '--theta'],
    ['non-numeric theta', ['--scene', 'galaxy', '--theta', 'wide'], 'wide'],
    ['theta on a scene without it', ['--scene', 'balls-in-box', '--theta', '0.5'], '--theta'],
    ['non-integer orbits', ['--scene', 'integrators', '--orbits', '1.5'], '1.5'],
    ['peer engine for a study', ['--scene', 'forces', '--vs', 'rapier2d'], '--vs'],
    ['zero threads', ['--threads', '0'], '--threads'],
    ['too many threads', ['--threads', '65'], '--threads'],
  ];
  for (const [what, args, named] of cases) {
    const usage = queued([...args, '--json']);
    it(what, async () => {
      const run = await usage();
      expect(run.code).toBe(2);
      expect(run.stderr).toContain(named);
      expect(run.stdout).toBe('');
    });
  }
});
