// `npm test` after the type-check: the headless tests (vitest project `node`) and the browser tests
// (project `browser`) in two vitest processes at the same time, so a machine with two cores runs
// both lanes at once: the browser files run one at a time in a lane (test/browser/harness.ts holds a
// lock; pages side by side in one software-rendered Chromium ran about four times slower each) and
// would otherwise leave the second core idle. Every lane claims each file as it starts
// (scripts/test-claims.mjs), so that two lanes of a project can share one list of files: a file runs
// in one lane, and the other reports it as skipped. When the node lane is done and browser files are
// still waiting, a second browser lane (`browser-2`: a Chromium and a lane lock of its own) takes them
// from the other end of the list (BITPHYSICS_TEST_ORDER=reverse in vitest.config.ts), so that the core
// the node lane leaves does not idle; when the browser lane is done first and headless files are still
// waiting, a second `node` lane does the same with those. BITPHYSICS_BROWSER_LANES=1 keeps every
// browser file in the one lane (for comparing the two). Each line of output is prefixed with its
// lane; the exit code is non-zero if any lane fails. Arguments are passed to the vitest runs; with
// arguments (a filter, say) there is no second lane.
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
 * Fewest waiting browser files worth a second browser lane (its start costs a Chromium launch and a
 * few seconds of imports, and the file the first lane is running meanwhile shares the cores with it).
 */
const SECOND_BROWSER_LANE_MIN_FILES = 3;

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

/** Every .test.ts file under test/, from the root. */
function testFiles() {
  return readdirSync(join(root, 'test'), { recursive: true })
    .map((f) => `test/${String(f).replaceAll('\\', '/')}`)
    .filter((f) => f.endsWith('.test.ts'));
}

/** The browser project's test files (vitest.config.ts: every .test.ts file under test/browser/), from the root. */
const isBrowserFile = (f) => f.startsWith('test/browser/');

/** A claim folder's entry for a file (its path from the root), as scripts/test-claims.mjs names it. */
const claimName = (file) => file.replaceAll('/', '__');

const claims = mkdtempSync(join(tmpdir(), 'bitphysics-test-claims-'));
const claimEnv = { BITPHYSICS_TEST_CLAIMS: claims };

/** The files of `project` ('node' or 'browser') that no lane has started yet. */
function waitingFiles(project) {
  const claimed = new Set(readdirSync(claims));
  return testFiles().filter((f) => isBrowserFile(f) === (project === 'browser') && !claimed.has(claimName(f)));
}

try {
  let nodeDone = false;
  let browserDone = false;
  const first = lane('node', ['--project', 'node', ...extra], { ...claimEnv, BITPHYSICS_TEST_LANE: 'node' });
  const browser = lane('browser', ['--project', 'browser', ...extra], { ...claimEnv, BITPHYSICS_TEST_LANE: 'browser' });
  first.then(() => {
    nodeDone = true;
  });
  browser.then(() => {
    browserDone = true;
  });
  // The second browser lane: once the node lane is done, on the browser files no lane has started. Its
  // global setup serves the site the first lane built (no site lock: that lane holds it) and launches
  // its own Chromium; its files take their own lane lock (BITPHYSICS_BROWSER_LANE, test/browser/chromium.mjs).
  const secondBrowser = first.then(() => {
    if (browserDone || extra.length > 0 || process.env.BITPHYSICS_BROWSER_LANES === '1') return 0;
    const waiting = waitingFiles('browser');
    if (waiting.length < SECOND_BROWSER_LANE_MIN_FILES) return 0;
    return lane('browser-2', ['--project', 'browser', ...waiting], {
      ...claimEnv,
      BITPHYSICS_TEST_LANE: 'browser-2',
      BITPHYSICS_TEST_ORDER: 'reverse',
      BITPHYSICS_BROWSER_LANE: '2',
      BITPHYSICS_SITE_LOCK: 'off',
    });
  });
  // The second node lane: once the browser lane is done, on the headless files no lane has started.
  const second = browser.then(() => {
    if (nodeDone || extra.length > 0) return 0;
    const waiting = waitingFiles('node');
    if (waiting.length < SECOND_LANE_MIN_FILES) return 0;
    return lane('node-2', ['--project', 'node', ...waiting], {
      ...claimEnv,
      BITPHYSICS_TEST_LANE: 'node-2',
      BITPHYSICS_TEST_ORDER: 'reverse',
    });
  });
  const codes = { node: await first, browser: await browser, 'node-2': await second, 'browser-2': await secondBrowser };
  const byLane = new Map();
  for (const entry of readdirSync(claims)) {
    const who = readFileSync(join(claims, entry), 'utf8');
    byLane.set(who, (byLane.get(who) ?? 0) + 1);
  }
  if (byLane.has('node-2'))
    console.log(
      `headless files: ${byLane.get('node') ?? 0} in [node], ${byLane.get('node-2')} in [node-2] (each lane lists the other's as skipped)`,
    );
  if (byLane.has('browser-2'))
    console.log(
      `browser files: ${byLane.get('browser') ?? 0} in [browser], ${byLane.get('browser-2')} in [browser-2] (each lane lists the other's as skipped)`,
    );
  const failed = Object.keys(codes).filter((name) => codes[name] !== 0);
  console.log(failed.length === 0 ? 'all tests passed (node and browser)' : `failed: ${failed.join(', ')}`);
  process.exitCode = failed.length === 0 ? 0 : 1;
} finally {
  rmSync(claims, { recursive: true, force: true });
}
