// `npm test` after the type-check: the headless tests (vitest project `node`) and the browser tests
// (project `browser`) in two vitest processes at the same time, so a machine with two cores runs
// both lanes at once: the browser files run one at a time (test/browser/harness.ts holds a lock; pages
// side by side in one software-rendered Chromium ran about four times slower each) and would
// otherwise leave the second core idle. Each line of output is prefixed with its lane; the exit code
// is non-zero if either lane fails. Arguments are passed to both vitest runs.
import { spawn } from 'node:child_process';
import { dirname, join } from 'node:path';
import { createInterface } from 'node:readline';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const vitest = join(root, 'node_modules', 'vitest', 'vitest.mjs');
const extra = process.argv.slice(2);

/** Runs one vitest project; resolves with its exit code (1 if it was killed by a signal). */
function lane(project) {
  return new Promise((resolve) => {
    const child = spawn(process.execPath, [vitest, 'run', '--project', project, ...extra], {
      cwd: root,
      stdio: ['ignore', 'pipe', 'pipe'],
      env: { ...process.env, FORCE_COLOR: process.env.FORCE_COLOR ?? '0' },
    });
    const prefix = `[${project}] `;
    createInterface({ input: child.stdout }).on('line', (line) => process.stdout.write(`${prefix + line}\n`));
    createInterface({ input: child.stderr }).on('line', (line) => process.stderr.write(`${prefix + line}\n`));
    child.on('close', (code, signal) => resolve(signal ? 1 : (code ?? 1)));
  });
}

const codes = await Promise.all([lane('node'), lane('browser')]);
const failed = ['node', 'browser'].filter((_, i) => codes[i] !== 0);
console.log(failed.length === 0 ? 'all tests passed (node and browser)' : `failed: ${failed.join(', ')}`);
process.exitCode = failed.length === 0 ? 0 : 1;
