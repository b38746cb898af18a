// scripts/ab.mjs end to end (the in-process A/B of the physics package at a git revision against the
// working tree), run as a child process on a small world. It checks what the tool promises, never a
// timing: the same revision against itself reaches the same state (the hashes printed equal, as
// stateHash makes them for identical code and seeds), the temporary worktree is removed, and bad
// flags exit with 2 and a message.
import { execFile, execFileSync } from 'node:child_process';
import { join, resolve } from 'node:path';
import { expect, test } from 'vitest';

const root = resolve(import.meta.dirname, '..', '..');

function ab(args: string[]): Promise<{ code: number; stdout: string; stderr: string }> {
  return new Promise((done, fail) => {
    execFile(process.execPath, [join(root, 'scripts', 'ab.mjs'), ...args], { cwd: root, timeout: 120_000 }, (error, stdout, stderr) => {
      if (error && typeof error.code !== 'number') {
        fail(error);
        return;
      }
      done({ code: error ? (error.code as number) : 0, stdout, stderr });
    });
  });
}

const worktrees = (): number => execFileSync('git', ['-C', root, 'worktree', 'list'], { encoding: 'utf8' }).trim().split('\n').length;

test('HEAD against the working tree: both worlds step the window, the same state when the physics is unchanged, the worktree removed', async () => {
  const before = worktrees();
  const run = await ab(['HEAD', '--count', '300', '--steps', '30', '--window', '10-30', '--clock', 'cpu']);
  expect(run.code).toBe(0);
  expect(run.stdout).toMatch(/^balls-in-box 300, threads 1, steps 10-30 of 30, cpu clock:$/m);
  expect(run.stdout).toMatch(/^ {2}HEAD: mean \d+\.\d\d ms, median \d+\.\d\d ms$/m);
  expect(run.stdout).toMatch(/^ {2}working tree \/ HEAD: mean \d+\.\d{3}, median of the steps' ratios \d+\.\d{3}$/m);
  const hashes = /state hashes after 30 steps: ([0-9a-f]{16}) ([0-9a-f]{16}) \((equal|different)\)/.exec(run.stdout);
  expect(hashes).not.toBeNull();
  expect(hashes![3]).toBe(hashes![1] === hashes![2] ? 'equal' : 'different');
  // With the physics package as committed (a clean clone, as in CI) the two worlds are the same code
  // with the same seed, so their states must be equal to the bit.
  let unchanged = true;
  try {
    execFileSync('git', ['-C', root, 'diff', '--quiet', 'HEAD', '--', 'packages/physics']);
  } catch {
    unchanged = false;
  }
  if (unchanged) expect(hashes![1]).toBe(hashes![2]);
  expect(worktrees()).toBe(before);
}, 120_000);

test('bad flags: exit code 2 and a message naming the flag', async () => {
  const none = await ab([]);
  expect(none.code).toBe(2);
  expect(none.stderr).toMatch(/ab: give one git revision/);
  const window = await ab(['HEAD', '--steps', '10', '--window', '5-20']);
  expect(window.code).toBe(2);
  expect(window.stderr).toMatch(/ab: --window must be a-b with a < b <= steps, got 5-20/);
  const clock = await ab(['HEAD', '--clock', 'sundial']);
  expect(clock.code).toBe(2);
  expect(clock.stderr).toMatch(/ab: --clock must be wall or cpu, got sundial/);
  const threads = await ab(['HEAD', '--threads', '0']);
  expect(threads.code).toBe(2);
  expect(threads.stderr).toMatch(/ab: --threads must be an integer >= 1, got 0/);
  const before = worktrees();
  const scene = await ab(['HEAD', '--scene', 'nope', '--steps', '5', '--window', '1-5']);
  expect(scene.code).toBe(2);
  expect(scene.stderr).toMatch(/ab: unknown scene nope \(scenes: balls-in-box/);
  expect(worktrees()).toBe(before);
}, 120_000);
