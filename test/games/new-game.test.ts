/**
 * The game template: `npm run new-game -- <name>` (scripts/new-game.mjs) scaffolds a game that
 * type-checks, builds, is listed in the gallery's registry and runs its page contract in headless
 * Chromium (ready flag, window.game, a drawn canvas, B drops a ball, no error). The README's "Build
 * your own game" blocks (```` ```ts file=game/... ````) are written into the new game and type-checked
 * with it. So that no other test sees a half-made game in games/, everything happens in a scratch
 * copy of the layout under dist/new-game-check/ (test/browser's helpers linked in; the game kit comes
 * from its workspace package, @bitphysics/game-kit),
 * removed afterwards; the generated test itself is type-checked there and runs unchanged in
 * test/browser/ when a user makes a game.
 */
import { execFile } from 'node:child_process';
import { existsSync, mkdirSync, readdirSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { promisify } from 'node:util';
import * as esbuild from 'esbuild';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { launchChromium, repoRoot } from '../browser/chromium.mjs';
import { readmeBlocks } from '../packaging/readme-blocks';

const run = promisify(execFile);
const NAME = 'template-check';
const scratch = join(repoRoot, 'dist', 'new-game-check');
const gamesDir = join(scratch, 'games');
const testDir = join(scratch, 'test', 'browser');
const gameDir = join(gamesDir, NAME);

interface NewGameModule {
  newGame(name: string, options: { gamesDir: string; testDir: string }): { dir: string; test: string; files: string[] };
}
interface BuildModule {
  readRegistry(games: string): { folder: string; title: string }[];
}
const load = async <T>(file: string): Promise<T> => (await import(pathToFileURL(join(repoRoot, 'scripts', file)).href)) as T;

beforeAll(async () => {
  rmSync(scratch, { recursive: true, force: true });
  mkdirSync(testDir, { recursive: true });
  mkdirSync(gamesDir, { recursive: true });
  for (const file of readdirSync(join(repoRoot, 'test', 'browser'))) {
    if (/\.(ts|mjs|d\.mts)$/.test(file) && !file.endsWith('.test.ts'))
      symlinkSync(join(repoRoot, 'test', 'browser', file), join(testDir, file));
  }
  const { newGame } = await load<NewGameModule>('new-game.mjs');
  newGame(NAME, { gamesDir, testDir });
  for (const [file, block] of readmeBlocks()) {
    if (file.startsWith('game/')) writeFileSync(join(gameDir, file.slice('game/'.length)), block.code);
  }
});

afterAll(() => {
  rmSync(scratch, { recursive: true, force: true });
});

describe('npm run new-game', () => {
  it('writes the scene, page, manifest, thumbnail and browser test', () => {
    for (const file of ['scene.ts', 'main.ts', 'index.html', 'game.json', 'thumbnail.png'])
      expect(existsSync(join(gameDir, file)), file).toBe(true);
    expect(existsSync(join(testDir, `${NAME}.test.ts`))).toBe(true);
  });

  it('refuses a bad or taken name', async () => {
    const { newGame } = await load<NewGameModule>('new-game.mjs');
    expect(() => newGame('Bad Name', { gamesDir, testDir })).toThrow(/name must be lower-case words joined by dashes/);
    expect(() => newGame(NAME, { gamesDir, testDir })).toThrow(/already exists/);
  });

  it('is listed in the gallery registry', async () => {
    const { readRegistry } = await load<BuildModule>('build.mjs');
    expect(readRegistry(gamesDir).map((e) => e.folder)).toContain(NAME);
  });

  it("type-checks with its test and the README walkthrough's files (strict, the workspace's options)", async () => {
    const extra = [...readmeBlocks().keys()].filter((f) => f.startsWith('game/')).map((f) => `games/${NAME}/${f.slice('game/'.length)}`);
    expect(extra.length).toBeGreaterThan(0);
    writeFileSync(
      join(scratch, 'tsconfig.json'),
      JSON.stringify({
        extends: '../../tsconfig.base.json',
        files: [`games/${NAME}/main.ts`, `test/browser/${NAME}.test.ts`, ...extra, '../../packages/game-kit/src/assets.d.ts'],
      }),
    );
    const tsc = join(repoRoot, 'node_modules', 'typescript', 'bin', 'tsc');
    // --singleThreaded: the same diagnostics for less CPU than TypeScript's parallel checkers.
    const result = await run(process.execPath, [tsc, '-p', join(scratch, 'tsconfig.json'), '--singleThreaded'], { cwd: repoRoot }).then(
      () => '',
      (error: { stdout?: string }) => error.stdout ?? String(error),
    );
    expect(result).toBe('');
  }, 90_000);

  it('builds and runs its page in Chromium: ready, window.game, drawn, B drops a ball, no error', async () => {
    const out = join(scratch, 'site');
    await esbuild.build({
      entryPoints: [join(gameDir, 'main.ts')],
      outdir: out,
      bundle: true,
      format: 'esm',
      target: 'es2022',
      platform: 'browser',
      conditions: ['bitphysics-source'],
      inject: [join(repoRoot, 'packages', 'game-kit', 'src', 'page-errors.ts')],
      loader: { '.png': 'file' },
      logLevel: 'silent',
    });
    writeFileSync(join(out, 'index.html'), (await import('node:fs')).readFileSync(join(gameDir, 'index.html'), 'utf8'));
    const server = await esbuild.context({ entryPoints: [], logLevel: 'silent' });
    const { port } = await server.serve({ host: '127.0.0.1', port: 0, servedir: out });
    const browser = await launchChromium();
    try {
      const context = await browser.newContext({ viewport: { width: 800, height: 500 }, locale: 'en-US' });
      const page = await context.newPage();
      const errors: string[] = [];
      page.on('console', (m) => {
        if (m.type() === 'error') errors.push(m.text());
      });
      page.on('pageerror', (e) => errors.push(e.message));
      await page.goto(`http://127.0.0.1:${port}/index.html?count=5`);
      await page
        .waitForFunction(() => document.body.dataset.ready === 'true', null, { timeout: 30_000 })
        .catch((error: unknown) => {
          throw new Error(`not ready; page errors: ${JSON.stringify(errors)}; ${String(error)}`);
        });
      type Game = { ballCount(): number; stats(): { entities: number; steps: number; fps: number } };
      expect(await page.evaluate(() => (window.game as unknown as Game).ballCount())).toBe(5);
      await page.keyboard.press('b');
      await page.waitForFunction(() => (window.game as unknown as Game).ballCount() === 6, null, { timeout: 10_000 });
      await page.waitForFunction(() => (window.game as unknown as Game).stats().steps > 2, null, { timeout: 10_000 });
      // Drawn: the canvas, read right after a frame the game drew, holds more than the background's
      // colour. The game paces its frames to the GPU (packages/game-kit/src/frame-pacer.ts): an animation frame
      // in which it drew nothing leaves a blank buffer, so wait (20 s at most) for one in which its
      // pacer's count of drawn frames moved, as test/browser/harness.ts canvasColors does.
      const colors = await page.evaluate(async () => {
        const canvas = document.querySelector('canvas')!;
        const drawn = (): number | undefined => (window.game as unknown as { pacer?: { drawn?: number } }).pacer?.drawn;
        let last = drawn();
        const until = performance.now() + 20_000;
        for (;;) {
          await new Promise((r) => requestAnimationFrame(r));
          const now = drawn();
          if (now === undefined || now !== last || performance.now() > until) break;
          last = now;
        }
        const copy = new OffscreenCanvas(canvas.width, canvas.height).getContext('2d')!;
        copy.drawImage(canvas, 0, 0);
        const data = copy.getImageData(0, 0, canvas.width, canvas.height).data;
        const seen = new Set<number>();
        for (let i = 0; i < data.length; i += 4) seen.add((data[i]! << 16) | (data[i + 1]! << 8) | data[i + 2]!);
        return seen.size;
      });
      expect(colors).toBeGreaterThan(4);
      expect(errors).toEqual([]);
      await context.close();
    } finally {
      await browser.close();
      await server.dispose();
    }
  }, 90_000);
});
