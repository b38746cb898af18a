// Headless Chromium and the site server for browser tests and scripts (plain JS so that
// scripts/thumbnails.mjs can import it without a TypeScript step; types in chromium.d.mts).

import { createHash } from 'node:crypto';
import { existsSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

/** Repository root. */
export const repoRoot = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');

/**
 * Chromium flags: no sandbox (containers), nothing fetched in the background, WebGL through
 * SwiftShader (software, so it works without a GPU), and 2D canvases drawn in the page's own process
 * (Skia on the CPU) rather than through the GPU process: with a software GPU an "accelerated" 2D
 * canvas is drawn by SwiftShader in the GPU process too, and every read of it (getImageData) waits
 * for the GPU process's queue, which the page's WebGL shaders and frames fill. pixi.js reads one at
 * import (its tint check, a 6 x 1 canvas's getImageData): 0.8-1.4 s of each pixi page's load on a
 * loaded machine. What a page draws is the same either way. Headless is set by `launchChromium`.
 */
export const CHROMIUM_ARGS = Object.freeze([
  '--no-sandbox',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--disable-accelerated-2d-canvas',
]);

/**
 * Path of the Chromium to run: $CHROMIUM_PATH if set, else /usr/bin/chromium if it exists, else the
 * binary bundled with @sparticuz/chromium (unpacked to /tmp on first use; nothing is downloaded).
 * @throws Error if $CHROMIUM_PATH is set but does not exist.
 */
export async function chromiumPath() {
  const fromEnv = process.env.CHROMIUM_PATH;
  if (fromEnv) {
    if (!existsSync(fromEnv)) throw new Error(`CHROMIUM_PATH is ${fromEnv}, which does not exist`);
    return fromEnv;
  }
  if (existsSync('/usr/bin/chromium')) return '/usr/bin/chromium';
  const sparticuz = (await import('@sparticuz/chromium')).default;
  return sparticuz.executablePath();
}

/** Launches headless Chromium with `CHROMIUM_ARGS`. @returns a playwright-core Browser. */
export async function launchChromium() {
  const { chromium } = await import('playwright-core');
  return chromium.launch({ executablePath: await chromiumPath(), headless: true, args: [...CHROMIUM_ARGS] });
}

/**
 * Launches headless Chromium with `CHROMIUM_ARGS` as a server that test files connect to
 * (`connectChromium`): the browser test run shares one browser (test/browser/global-setup.ts).
 * @returns a playwright-core BrowserServer (`wsEndpoint()`, `close()`).
 */
export async function launchChromiumServer() {
  const { chromium } = await import('playwright-core');
  return chromium.launchServer({ executablePath: await chromiumPath(), headless: true, args: [...CHROMIUM_ARGS] });
}

/** Connects to a browser started by `launchChromiumServer` at `wsEndpoint`. @returns a playwright-core Browser. */
export async function connectChromium(wsEndpoint) {
  const { chromium } = await import('playwright-core');
  return chromium.connect(wsEndpoint);
}

/** A TCP port that was free a moment ago on 127.0.0.1 (the OS picks it). */
export function freePort() {
  return new Promise((resolvePort, reject) => {
    const server = createServer();
    server.unref();
    server.on('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const address = server.address();
      const port = typeof address === 'object' && address ? address.port : 0;
      server.close(() => resolvePort(port));
    });
  });
}

function pidAlive(pid) {
  try {
    process.kill(pid, 0);
    return true;
  } catch (error) {
    return error && error.code === 'EPERM';
  }
}

/**
 * Takes the site lock: browser test files (and the thumbnail script) run one after another, each
 * with its Chromium, rather than share the machine's cores at once, and the site build they share
 * (scripts/serve.mjs `cacheDir`) is written by one at a time. Waits until
 * the holder (another test file or the thumbnail script) releases it; a lock whose process is gone
 * is taken over.
 * @param {{ timeoutMs?: number, name?: string }} [options] how long to wait, ms (default 110 s); which
 *   lock ('site' by default; the browser test files take 'browser-lane' to run one at a time). In a
 *   second browser lane of `npm test` (scripts/test.mjs: the environment variable
 *   BITPHYSICS_BROWSER_LANE=<n>, with a Chromium of its own) 'browser-lane' is 'browser-lane-<n>', so
 *   that the lanes' files run one at a time in each lane, not one at a time between them.
 * @returns {Promise<() => void>} a function that releases the lock (idempotent; also runs on exit).
 * @throws Error when the lock is still held after `timeoutMs`, naming the holder's pid.
 */
export async function acquireSiteLock({ timeoutMs = 110_000, name = 'site' } = {}) {
  const key = createHash('sha1').update(repoRoot).digest('hex').slice(0, 12);
  const lane = process.env.BITPHYSICS_BROWSER_LANE;
  const lockName = name === 'browser-lane' && lane ? `${name}-${lane}` : name;
  const dir = join(tmpdir(), `bitphysics-${lockName}-${key}.lock`);
  const owner = join(dir, 'owner');
  const deadline = Date.now() + timeoutMs;
  for (;;) {
    try {
      mkdirSync(dir);
      writeFileSync(owner, String(process.pid));
      break;
    } catch (error) {
      if (error.code !== 'EEXIST') throw error;
      let pid = NaN;
      try {
        pid = Number(readFileSync(owner, 'utf8'));
      } catch {
        /* being written or removed */
      }
      if (Number.isInteger(pid) && pid > 0 && !pidAlive(pid)) {
        rmSync(dir, { recursive: true, force: true });
        continue;
      }
      if (Date.now() > deadline) {
        let holder = '';
        try {
          holder = readFileSync(`/proc/${pid}/cmdline`, 'utf8').split('\0').join(' ').slice(0, 200);
        } catch {
          /* not Linux, or gone */
        }
        throw new Error(
          `acquireSiteLock: ${dir} still held by pid ${pid}${holder ? ` (${holder})` : ''} after ${timeoutMs} ms: another browser test file or the thumbnail script is running`,
        );
      }
      await new Promise((r) => setTimeout(r, 100));
    }
  }
  let released = false;
  const release = () => {
    if (released) return;
    released = true;
    process.off('exit', release);
    try {
      if (readFileSync(owner, 'utf8') === String(process.pid)) rmSync(dir, { recursive: true, force: true });
    } catch {
      /* already gone */
    }
  };
  process.on('exit', release);
  return release;
}

/**
 * Serves the site (scripts/serve.mjs `startServer`, no watching) on a free port, holding the site
 * lock until `stop`. The build is reused from the previous run when none of its inputs changed
 * since (`cache`), so the browser test files after the first one start without building.
 * With the environment variable BITPHYSICS_SITE_LOCK=off the lock is not taken.
 * @param {{ lockTimeoutMs?: number }} [options] how long to wait for the lock, ms (default 110 s).
 * @returns {Promise<{ url: string, stop: () => Promise<void> }>} url ends with '/'.
 */
export async function startSite({ lockTimeoutMs = 110_000 } = {}) {
  // BITPHYSICS_SITE_LOCK=off runs this file beside the others (a machine with cores to spare).
  const release = process.env.BITPHYSICS_SITE_LOCK === 'off' ? () => undefined : await acquireSiteLock({ timeoutMs: lockTimeoutMs });
  try {
    const { startServer } = await import(pathToFileURL(join(repoRoot, 'scripts', 'serve.mjs')).href);
    const port = await freePort();
    const server = await startServer({ port, watch: false, cache: true });
    return {
      url: server.url,
      stop: async () => {
        try {
          await server.stop();
        } finally {
          release();
        }
      },
    };
  } catch (error) {
    release();
    throw error;
  }
}

/**
 * The gallery registry (scripts/build.mjs `readRegistry`): one entry per game folder.
 * @returns {Promise<Array<{ folder: string, title: string, summary: string, category: string, order: number }>>}
 */
export async function readRegistry() {
  const build = await import(pathToFileURL(join(repoRoot, 'scripts', 'build.mjs')).href);
  return build.readRegistry();
}
