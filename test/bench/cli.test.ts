// The bench CLI end to end: built with buildBench() and run as a child process with small counts.
// These tests check output shape and error handling only; they never assert timings.
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

/** Runs the built CLI with `args`; resolves with its exit code and output (never rejects on a non-zero exit). */
function runCli(args: string[]): Promise<CliRun> {
  return new Promise((done, fail) => {
    execFile(process.execPath, [cli, ...args], { cwd: root, timeout: 60_000, maxBuffer: 16 * 2 ** 20 }, (error, stdout, stderr) => {
      if (error && typeof error.code !== 'number') {
        fail(error);
        return;
      }
      done({ code: error ? (error.code as number) : 0, stdout, stderr });
    });
  });
}

/** Parses every stdout line as JSON (fails the test if any line is not). */
function jsonLines(stdout: string): Array<Record<string, unknown>> {
  return stdout.trim().split('\n').map((line) => JSON.parse(line) as Record<string, unknown>);
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

describe('bench CLI', () => {
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

  it('--vs rapier2d,matter gives one line per engine and ours/peer ratios', async () => {
    const vs = ['--scene', 'balls-in-box', '--vs', 'rapier2d,matter'];
    const [json, human] = await Promise.all([
      runCli([...vs, '--count', '200', '--steps', '20', '--warmup', '2', '--json']),
      runCli([...vs, '--count', '50', '--steps', '5', '--warmup', '1']),
    ]);
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

  it('--vs plain-loop on particles computes the same states', async () => {
    const run = await runCli(['--scene', 'particles', '--count', '1000', '--steps', '10', '--warmup', '2', '--vs', 'plain-loop', '--json']);
    expect(run.code).toBe(0);
    const [ours, plain] = jsonLines(run.stdout);
    expectEngineLine(ours!, 'bitphysics', 'particles', 1000, 10);
    expectEngineLine(plain!, 'plain-loop', 'particles', 1000, 10);
    expect(plain!.contacts).toBeNull();
    expect(plain!.ratioOf).toBe('bitphysics/plain-loop');
    expect(ours!.positionChecksum).toBe(plain!.positionChecksum);
  });

  it('--list lists the scenes and the engines that support each', async () => {
    const [human, json] = await Promise.all([runCli(['--list']), runCli(['--list', '--json'])]);
    expect(human.code).toBe(0);
    expect(human.stdout).toMatch(/^balls-in-box\s+bitphysics, rapier2d, matter\s/m);
    expect(human.stdout).toMatch(/^particles\s+bitphysics, plain-loop\s/m);
    const scenes = jsonLines(json.stdout);
    expect(scenes.map((s) => s.scene)).toEqual(expect.arrayContaining(['balls-in-box', 'particles']));
    for (const s of scenes) expect(typeof s.description).toBe('string');
  });
});

describe.concurrent('bench CLI usage errors exit 2 naming the bad value', () => {
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
  ];
  for (const [what, args, named] of cases) {
    it(what, async () => {
      const run = await runCli([...args, '--json']);
      expect(run.code).toBe(2);
      expect(run.stderr).toContain(named);
      expect(run.stdout).toBe('');
    });
  }
});
