/**
 * `npm run new-game -- <folder outside the repository>` (scripts/new-project.mjs) as a user runs it:
 * the standalone project is made in the system's temp folder, installed there with npm (the
 * bitphysics packages from its vendor/ tarballs, everything else from the npm cache or registry:
 * nothing resolves through this workspace), type-checked with its own tsconfig, built with its own
 * `npm run build`, and served by its own `npm start`; the page must get ready in headless Chromium,
 * draw, take a key (B drops a ball) and log no error.
 */
import { type ChildProcess, execFile, spawn } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { promisify } from 'node:util';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { launchChromium, repoRoot } from '../browser/chromium.mjs';
import { packedPackages, type Tarball } from './packed';

const run = promisify(execFile);
let parent = '';
let project = '';
let server: ChildProcess | null = null;

/** Ends `npm start` and the server it runs: the whole process group (spawned detached). */
function stopServer(child: ChildProcess | null): void {
  if (child?.pid === undefined || child.exitCode !== null) return;
  try {
    process.kill(-child.pid, 'SIGTERM');
  } catch {
    child.kill();
  }
}

beforeAll(async () => {
  parent = mkdtempSync(join(tmpdir(), 'bitphysics-new-project-'));
  const { newProject } = (await import(pathToFileURL(join(repoRoot, 'scripts', 'new-project.mjs')).href)) as {
    newProject(dir: string, options?: { title?: string; tarballs?: readonly Tarball[] }): Promise<{ dir: string; files: string[] }>;
  };
  // The packages as packPackages packs them (packed once for this file and packages.test.ts).
  const tarballs = await packedPackages();
  project = (await newProject(join(parent, 'tower-game'), { title: 'Tower game', tarballs })).dir;
  // --package-lock=false: no lock files, which nothing here reads (less CPU an install).
  await run(
    'npm',
    ['install', '--no-audit', '--no-fund', '--prefer-offline', '--ignore-scripts', '--package-lock=false', '--loglevel=error'],
    { cwd: project },
  );
}, 180_000);

afterAll(() => {
  stopServer(server);
  rmSync(parent, { recursive: true, force: true });
});

describe('a standalone game project from npm run new-game', () => {
  it('refuses a folder inside the repository and a non-empty folder', async () => {
    const { newProject } = (await import(pathToFileURL(join(repoRoot, 'scripts', 'new-project.mjs')).href)) as {
      newProject(dir: string): Promise<unknown>;
    };
    await expect(newProject(join(repoRoot, 'games', 'x'))).rejects.toThrow(/inside the bitphysics repository/);
    await expect(newProject(project)).rejects.toThrow(/exists and is not empty/);
  });

  it('depends on the packed bitphysics packages, not on this workspace', () => {
    const manifest = JSON.parse(readFileSync(join(project, 'package.json'), 'utf8')) as { dependencies: Record<string, string> };
    for (const name of ['@bitphysics/physics', '@bitphysics/render-pixi', '@bitphysics/game-kit'])
      expect(manifest.dependencies[name]).toMatch(/^file:vendor\/.+\.tgz$/);
    // Installed as copies inside the project (npm extracts tarballs; a workspace link would be a symlink).
    expect(existsSync(join(project, 'node_modules', '@bitphysics', 'game-kit', 'dist', 'pixi.js'))).toBe(true);
  });

  it('type-checks and builds with its own scripts', async () => {
    // The project's own `tsc -p tsconfig.json`, told --singleThreaded: the same diagnostics for less
    // CPU than TypeScript's parallel checkers, which each resolve the shared declarations again.
    await run('npm', ['run', 'typecheck', '--silent', '--', '--singleThreaded'], { cwd: project });
    await run('npm', ['run', 'build', '--silent'], { cwd: project });
    expect(existsSync(join(project, 'dist', 'main.js'))).toBe(true);
    expect(existsSync(join(project, 'dist', 'index.html'))).toBe(true);
  }, 120_000);

  it('npm start serves the game: ready, drawn, B drops a ball, no error', async () => {
    // In a process group of its own: npm runs the server as its child, which killing npm alone leaves running.
    const started = spawn('npm', ['start', '--silent', '--', '--port', '0'], {
      cwd: project,
      stdio: ['ignore', 'pipe', 'pipe'],
      detached: true,
    });
    server = started;
    const url = await new Promise<string>((resolveUrl, reject) => {
      let out = '';
      const timer = setTimeout(() => reject(new Error(`npm start printed no address: ${out}`)), 60_000);
      const read = (chunk: Buffer) => {
        out += chunk.toString();
        const m = /http:\/\/[^\s]+/.exec(out);
        if (m) {
          clearTimeout(timer);
          resolveUrl(m[0]);
        }
      };
      started.stdout!.on('data', read);
      started.stderr!.on('data', read);
    });
    const browser = await launchChromium();
    try {
      const page = await (await browser.newContext({ viewport: { width: 800, height: 500 }, locale: 'en-US' })).newPage();
      const errors: string[] = [];
      page.on('console', (m) => {
        if (m.type() === 'error') errors.push(m.text());
      });
      page.on('pageerror', (e) => errors.push(e.message));
      await page.goto(url);
      await page
        .waitForFunction(() => document.body.dataset.ready === 'true', null, { timeout: 30_000 })
        .catch((error: unknown) => {
          throw new Error(`not ready; page errors: ${JSON.stringify(errors)}; ${String(error)}`);
        });
      type Game = { ballCount(): number; stats(): { steps: number } };
      const before = await page.evaluate(() => (window as unknown as { game: Game }).game.ballCount());
      await page.keyboard.press('b');
      await page.waitForFunction((n) => (window as unknown as { game: Game }).game.ballCount() === n + 1, before, { timeout: 10_000 });
      await page.waitForFunction(() => (window as unknown as { game: Game }).game.stats().steps > 2, null, { timeout: 10_000 });
      expect(await page.locator('canvas').count()).toBe(1);
      expect(errors).toEqual([]);
    } finally {
      await browser.close();
      stopServer(started);
    }
  }, 120_000);
});
