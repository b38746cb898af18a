// `npm test` after the type-check: the headless tests (vitest project `node`) and the browser tests
// (project `browser`) in two vitest processes at the same time, so a machine with two cores runs
// both lanes at once: the browser files run one at a time (test/browser/harness.ts holds a lock; pages
// side by side in one software-rendered Chromium ran about four times slower each) and would
// otherwise leave the second core idle. When the browser lane is done and headless files are still
// waiting, a second `node` lane takes them from the other end of the list (BITPHYSICS_TEST_ORDER=reverse
// in vitest.config.ts) so that the core the browser lane leaves does not idle either: both node lanes
// claim each file as it starts (scripts/test-claims.mjs), a file runs in one lane, and the other
// reports it as skipped. Each line of output is prefixed with its lane; the exit code is non-zero if
// any lane fails. Arguments are passed to the vitest runs; with arguments (a filter, say) there is no
// second node lane.
import { spawn } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { createInterface } from 'node:readline';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const vitest = join(root, 'node_modules', 'vitest', 'vitest.mjs');
const extra = process.argv.slice(2);

/** Fewest waiting headless files worth a second node lane (its start costs a few seconds of imports). */
const SECOND_LANE_MIN_FILES = 4;

/**
 * Runs vitest on `args` as the lane `name`, its output prefixed with the name; resolves with its exit
 * code (1 if it was killed by a signal).
 */
function lane(name, args, env = {}) {
  return new Promise((resolve) => {
    const child = spawn(process.execPath, [vitest, 'run', ...args], {
      cwd: root,
      stdio: ['ignore', 'pipe', 'pipe'],
      env: { ...process.env, FORCE_COLOR: process.env.FORCE_COLOR ?? '0', ...env },
    });
    const prefix = `[${name}] `;
    createInterface({ input: child.stdout }).on('line', (line) => process.stdout.write(`${prefix + line}\n`));
    createInterface({ input: child.stderr }).on('line', (line) => process.stderr.write(`${prefix + line}\n`));
    child.on('close', (code, signal) => resolve(signal ? 1 : (code ?? 1)));
  });
}

/** The node project's test files (vitest.config.ts: every .test.ts file under test/ but test/browser/), from the root. */
function headlessFiles() {
  return readdirSync(join(root, 'test'), { recursive: true })
    .map((f) => `test/${String(f).replaceAll('\\', '/')}`)
    .filter((f) => f.endsWith('.test.ts') && !f.startsWith('test/browser/'));
}

/** A claim folder's entry for a file (its path from the root), as scripts/test-claims.mjs names it. */
const claimName = (file) => file.replaceAll('/', '__');

const claims = mkdtempSync(join(tmpdir(), 'bitphysics-test-claims-'));
const claimEnv = { BITPHYSICS_TEST_CLAIMS: claims };
try {
  const first = lane('node', ['--project', 'node', ...extra], { ...claimEnv, BITPHYSICS_TEST_LANE: 'node' });
  let nodeDone = false;
  first.then(() => {
    nodeDone = true;
  });
  const browser = lane('browser', ['--project', 'browser', ...extra]);
  // The second node lane: once the browser lane is done, on the files no node lane has started.
  const second = browser.then(() => {
    if (nodeDone || extra.length > 0) return 0;
    const claimed = new Set(readdirSync(claims));
    const waiting = headlessFiles().filter((f) => !claimed.has(claimName(f)));
    if (waiting.length < SECOND_LANE_MIN_FILES) return 0;
    return lane('node-2', ['--project', 'node', ...waiting], {
      ...claimEnv,
      BITPHYSICS_TEST_LANE: 'node-2',
      BITPHYSICS_TEST_ORDER: 'reverse',
    });
  });
  const codes = { node: await first, browser: await browser, 'node-2': await second };
  const byLane = new Map();
  for (const entry of readdirSync(claims)) {
    const who = readFileSync(join(claims, entry), 'utf8');
    byLane.set(who, (byLane.get(who) ?? 0) + 1);
  }
  if (byLane.has('node-2'))
    console.log(
      `headless files: ${byLane.get('node') ?? 0} in [node], ${byLane.get('node-2')} in [node-2] (each lane lists the other's as skipped)`,
    );
  const failed = Object.keys(codes).filter((name) => codes[name] !== 0);
  console.log(failed.length === 0 ? 'all tests passed (node and browser)' : `failed: ${failed.join(', ')}`);
  process.exitCode = failed.length === 0 ? 0 : 1;
} finally {
  rmSync(claims, { recursive: true, force: true });
}
