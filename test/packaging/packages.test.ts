/**
 * The packages as a user gets them: every library package is built and packed (`npm pack`, via
 * scripts/pack.mjs), the tarballs are installed into a fresh project in the system's temp folder
 * (outside the workspace, so nothing resolves through the workspace's links or the
 * `bitphysics-source` condition; peer dependencies come from the npm cache or registry), and there
 * the README's named code blocks (```` ```ts file=... ````) are
 *  - type-checked under strict, noUncheckedIndexedAccess and skipLibCheck false, once with
 *    moduleResolution bundler and once with node16;
 *  - the headless one run by Node's own resolver (the packages' `exports` for Node);
 *  - the pages bundled with esbuild and opened in headless Chromium, which must draw and log no error.
 */
import { execFile } from 'node:child_process';
import { mkdtempSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { promisify } from 'node:util';
import * as esbuild from 'esbuild';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { launchChromium, repoRoot } from '../browser/chromium.mjs';
import { packedPackages } from './packed';
import { readmeBlocks } from './readme-blocks';

const run = promisify(execFile);
const tsc = join(repoRoot, 'node_modules', 'typescript', 'bin', 'tsc');

/** The examples the README must carry (file names of its named blocks). */
const TS_EXAMPLES = ['headless.ts', 'main.ts', 'main3d.ts'];

/**
 * Diagnostics from pixi.js 8's own declarations under node16: its package.json has no
 * `"type": "module"`, so TypeScript reads its .d.ts files as CommonJS (TS1479, TS1542). The README
 * says so; every other diagnostic fails the test.
 */
const UPSTREAM_NODE16 = /^node_modules\/pixi\.js\/.*error TS(1479|1542):/;

let project = '';

beforeAll(async () => {
  project = mkdtempSync(join(tmpdir(), 'bitphysics-consumer-'));
  const tarballs = await packedPackages();
  expect(tarballs.map((t) => t.name)).toEqual([
    '@bitphysics/physics',
    '@bitphysics/projects',
    '@bitphysics/render-common',
    '@bitphysics/render-pixi',
    '@bitphysics/render-three',
    '@bitphysics/game-kit',
  ]);
  writeFileSync(join(project, 'package.json'), JSON.stringify({ name: 'consumer', private: true, type: 'module' }, null, 2));
  // --package-lock=false: no package-lock.json nor node_modules/.package-lock.json, which nothing here
  // reads (less CPU an install).
  await run(
    'npm',
    [
      'install',
      '--no-audit',
      '--no-fund',
      '--prefer-offline',
      '--ignore-scripts',
      '--package-lock=false',
      '--loglevel=error',
      ...tarballs.map((t) => t.file),
    ],
    { cwd: project },
  );
  const blocks = readmeBlocks();
  for (const file of [...TS_EXAMPLES, 'index.html']) {
    const block = blocks.get(file);
    if (!block) throw new Error(`README.md has no code block named file=${file}`);
    writeFileSync(join(project, file), block.code);
  }
}, 180_000);

afterAll(() => {
  if (project) rmSync(project, { recursive: true, force: true });
});

/** Runs the workspace's tsc on the examples with `moduleResolution`; returns its diagnostics, one a line. */
async function typeCheck(moduleResolution: 'bundler' | 'node16'): Promise<string[]> {
  const config = `tsconfig.${moduleResolution}.json`;
  writeFileSync(
    join(project, config),
    JSON.stringify(
      {
        compilerOptions: {
          target: 'ES2022',
          module: moduleResolution === 'node16' ? 'node16' : 'esnext',
          moduleResolution,
          lib: ['ES2023', 'DOM', 'DOM.Iterable'],
          types: [],
          strict: true,
          noUncheckedIndexedAccess: true,
          skipLibCheck: false,
          noEmit: true,
        },
        files: TS_EXAMPLES,
      },
      null,
      2,
    ),
  );
  try {
    // --singleThreaded: the same diagnostics for less CPU than its parallel checkers, each of which
    // resolves the shared pixi.js and three declarations again.
    await run(process.execPath, [tsc, '-p', config, '--singleThreaded'], { cwd: project });
    return [];
  } catch (error) {
    const out = (error as { stdout?: string }).stdout ?? String(error);
    return out.split('\n').filter((line) => /error TS\d+/.test(line));
  }
}

describe('the packed packages in a fresh project', () => {
  it('hold only dist/, src/, the readme, the changelog and the manifest', () => {
    for (const name of ['physics', 'render-common', 'render-pixi', 'render-three']) {
      const dir = join(project, 'node_modules', '@bitphysics', name);
      expect(readdirSync(dir).sort()).toEqual(['CHANGELOG.md', 'README.md', 'dist', 'package.json', 'src']);
      expect(readdirSync(join(dir, 'dist'))).toContain('index.d.ts.map');
    }
    // One copy of each peer: nothing nested under the bitphysics packages.
    for (const name of ['physics', 'render-pixi', 'render-three']) {
      expect(() => readdirSync(join(project, 'node_modules', '@bitphysics', name, 'node_modules'))).toThrow();
    }
  });

  it('type-check the README examples with moduleResolution bundler', async () => {
    expect(await typeCheck('bundler')).toEqual([]);
  }, 60_000);

  it("type-check the README examples with moduleResolution node16 (only pixi.js's own two CommonJS complaints)", async () => {
    const errors = await typeCheck('node16');
    expect(errors.filter((line) => !UPSTREAM_NODE16.test(line))).toEqual([]);
  }, 60_000);

  it('run the headless example in Node', async () => {
    const { code } = await esbuild.transform(readmeBlocks().get('headless.ts')!.code, { loader: 'ts', format: 'esm', target: 'node20' });
    writeFileSync(join(project, 'headless.mjs'), code);
    const { stdout } = await run(process.execPath, ['headless.mjs'], { cwd: project });
    // The example prints the live particles' count and mean x and y, m, after 5 s of a fountain at
    // x = 10 m: rate 2000/s times lifetime 1 s is 2000 alive (10 % for the rounding of births and
    // deaths to steps); the fan is symmetric about x = 10 (0.5 m); the mean height is between the
    // emitter (a particle lives 1 s, less than the 1.17 s it takes to fall back) and the top of the arc,
    // v^2 / 2g < 3.3 m.
    const [count, x, y] = stdout.trim().split(/\s+/).map(Number);
    expect(Math.abs(count! - 2000)).toBeLessThan(200);
    expect(Math.abs(x! - 10)).toBeLessThan(0.5);
    expect(y).toBeGreaterThan(0);
    expect(y).toBeLessThan(3.3);
  }, 30_000);

  it("the README's 2D example bundles small: the physics tree-shakes, no projects or astronomy-engine", async () => {
    // The physics part of the 2D page, minified, as a user's esbuild makes it from the installed
    // packages (pixi.js, bitecs and the renderer left out). The package ships one module a source
    // file with "sideEffects": false, so only what the example reaches is kept, and a world installs
    // a feature's systems when the feature is first used (world/install.ts): the example, boxes and a
    // joint, does not reach the balls' broadphase, narrowphase and contact rows (collision/install-balls.ts),
    // emitters, 3D shapes and joints, cloth, Barnes-Hut or the thread pool. Bound: the goal,
    // 200 KB (measured 181 KB; 234 KB while every world held the ball contacts, 362 KB while it held
    // every system, 466 KB while the package shipped one bundled file). What remains beyond the 2D
    // shapes, contacts and joints is what every world reaches whatever it uses: every force law (a law
    // is a component users add themselves), every integration scheme (chosen by name) and every 2D
    // joint type's solver.
    const result = await esbuild.build({
      absWorkingDir: project,
      entryPoints: ['main.ts'],
      bundle: true,
      minify: true,
      format: 'esm',
      target: 'es2022',
      write: false,
      metafile: true,
      external: ['pixi.js', 'bitecs', '@bitphysics/render-pixi'],
      logLevel: 'silent',
    });
    const bytes = result.outputFiles[0]!.contents.byteLength;
    const inputs = Object.keys(result.metafile.inputs);
    console.log(`README 2D example, physics only, minified: ${(bytes / 1024).toFixed(1)} KB from ${inputs.length} modules`);
    expect(inputs.filter((f) => /astronomy-engine|@bitphysics\/projects/.test(f))).toEqual([]);
    expect(bytes).toBeLessThan(200 * 1024);
  });

  it('bundle the pages with esbuild and run them in Chromium without an error', async () => {
    const out = join(project, 'site');
    await esbuild.build({
      absWorkingDir: project,
      entryPoints: ['main.ts', 'main3d.ts'],
      outdir: out,
      bundle: true,
      format: 'esm',
      target: 'es2022',
      logLevel: 'silent',
    });
    const html = readmeBlocks().get('index.html')!.code;
    writeFileSync(join(out, 'index.html'), html);
    writeFileSync(join(out, 'index3d.html'), html.replace('./main.js', './main3d.js'));
    const server = await esbuild.context({ entryPoints: [], logLevel: 'silent' });
    const { port } = await server.serve({ host: '127.0.0.1', port: 0, servedir: out });
    const browser = await launchChromium();
    try {
      for (const page of ['index.html', 'index3d.html']) {
        const context = await browser.newContext({ viewport: { width: 640, height: 400 }, locale: 'en-US' });
        const tab = await context.newPage();
        const errors: string[] = [];
        tab.on('console', (m) => {
          if (m.type() === 'error') errors.push(`console.error: ${m.text()}`);
        });
        tab.on('pageerror', (e) => errors.push(`page error: ${e.message}`));
        tab.on('response', (r) => {
          if (r.status() >= 400) errors.push(`HTTP ${r.status()}: ${r.url()}`);
        });
        await tab.goto(`http://127.0.0.1:${port}/${page}`);
        await tab.waitForFunction(() => document.querySelector('canvas') !== null, null, { timeout: 20_000 });
        // A few frames, then the canvas must show more than its background.
        const colors = await tab.evaluate(async () => {
          for (let i = 0; i < 10; i++) await new Promise((r) => requestAnimationFrame(r));
          const canvas = document.querySelector('canvas')!;
          const copy = new OffscreenCanvas(canvas.width, canvas.height).getContext('2d')!;
          await new Promise((r) => requestAnimationFrame(r));
          copy.drawImage(canvas, 0, 0);
          const data = copy.getImageData(0, 0, canvas.width, canvas.height).data;
          const seen = new Set<number>();
          for (let i = 0; i < data.length; i += 4) seen.add((data[i]! << 16) | (data[i + 1]! << 8) | data[i + 2]!);
          return seen.size;
        });
        expect(errors, page).toEqual([]);
        expect(colors, page).toBeGreaterThan(2);
        await context.close();
      }
    } finally {
      await browser.close();
      await server.dispose();
    }
  }, 60_000);
});
