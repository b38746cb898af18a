import { existsSync, readFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import * as esbuild from 'esbuild';
import { defaultClientConditions, defaultServerConditions, type Plugin } from 'vite';
import { defineConfig } from 'vitest/config';
import { BaseSequencer, type TestSpecification } from 'vitest/node';
import { inlineConstantModules, isConstantModule } from './scripts/build.mjs';

/**
 * Folds the layout constants into the package sources that import them, as the packages' dist/, the
 * bench and the pages have them (scripts/build.mjs inlineConstantModules, with minifySyntax). Vite
 * runs each source as its own module and reads an imported constant as a property of the imported
 * module in every pass of a hot loop: with the solver's body-state offsets imported
 * (solver/body-state-layout.ts), test/physics/pile.test.ts took 75-85 s instead of 21 s. A source
 * that imports no constant module is left to Vite as it is.
 */
function foldConstantModules(): Plugin {
  const known = new Map<string, boolean>();
  const constant = (file: string): boolean => {
    const seen = known.get(file);
    if (seen !== undefined) return seen;
    const v = isConstantModule(file);
    known.set(file, v);
    return v;
  };
  const packageSource = (id: string): boolean => /\/packages\/[^/]+\/src\/.*\.ts$/.test(id) && !id.endsWith('.d.ts');
  /** The files `code` (the module `id`) imports by a relative path, as .ts paths. */
  const relativeImports = (id: string, code: string): string[] =>
    [...code.matchAll(/from\s+['"](\.{1,2}\/[^'"]+)['"]/g)].map((m) => resolve(dirname(id), m[1]!).replace(/\.js$/, '.ts'));
  return {
    name: 'fold-constant-modules',
    enforce: 'pre',
    // With vitest's module cache (experimental.fsModuleCache below), a package source's cached
    // transform is keyed on the text of every file it imports by a relative path as well as its own:
    // a folded module holds its constant modules' values, so a changed constant is a changed key.
    configureVitest({ experimental_defineCacheKeyGenerator }) {
      experimental_defineCacheKeyGenerator(({ id, sourceCode }) =>
        packageSource(id)
          ? relativeImports(id, sourceCode)
              .map((f) => (existsSync(f) ? readFileSync(f, 'utf8') : ''))
              .join('\0')
          : undefined,
      );
    },
    async transform(code, id) {
      if (!packageSource(id)) return null;
      const dir = dirname(id);
      const imports = relativeImports(id, code);
      if (!imports.some(constant)) return null;
      const out = await esbuild.build({
        entryPoints: [id],
        bundle: true,
        write: false,
        minifySyntax: true,
        plugins: [inlineConstantModules()],
        format: 'esm',
        platform: 'neutral',
        target: 'es2022',
        sourcemap: 'external',
        outdir: dir,
        logLevel: 'error',
      });
      const js = out.outputFiles.find((f) => f.path.endsWith('.js'))!;
      const map = out.outputFiles.find((f) => f.path.endsWith('.map'));
      return { code: js.text, map: map ? map.text : null };
    },
  };
}

/**
 * Runs the headless files first (longest first, side by side on every worker), then the browser
 * files. Browser files run one at a time anyway (test/browser/harness.ts takes a lock: pages side by
 * side in one software-rendered Chromium ran about four times slower each), so a worker that picked
 * one early would wait for the lock instead of running headless files. With BITPHYSICS_TEST_ORDER=reverse
 * the headless files run in the opposite order: the second `node` lane of `npm test` (scripts/test.mjs)
 * takes the files the first lane would reach last, and the two meet in the middle.
 */
class HeadlessFirst extends BaseSequencer {
  override async sort(files: TestSpecification[]): Promise<TestSpecification[]> {
    const sorted = await super.sort(files);
    const headless = sorted.filter((f) => f.project.name !== 'browser');
    if (process.env.BITPHYSICS_TEST_ORDER === 'reverse') headless.reverse();
    return [...headless, ...sorted.filter((f) => f.project.name === 'browser')];
  }
}

// Workspace packages export their TypeScript sources under the 'bitphysics-source' condition, so
// tests run against the sources without a build step.
//
// Two projects: `node` (the headless files, and the two files outside test/browser that open a
// Chromium of their own: test/packaging/packages.test.ts and test/games/new-game.test.ts) and
// `browser` (test/browser's pages). The browser project's global setup builds and serves the site
// once and starts one Chromium that test/browser's files share, one file at a time. `npm test`
// (scripts/test.mjs) runs the two projects in two vitest processes at once, one file at a time each
// on two cores (vitest's default: cores - 1 workers), and a second `node` process on the headless
// files still waiting when the browser lane is done; a plain `npx vitest run` runs both projects in
// one process, headless files first.

export default defineConfig({
  plugins: [foldConstantModules()],
  resolve: { conditions: ['bitphysics-source', ...defaultClientConditions] },
  ssr: { resolve: { conditions: ['bitphysics-source', ...defaultServerConditions] } },
  test: {
    // Transformed modules kept on disk (node_modules/.experimental-vitest-cache; `npx vitest
    // --clearCache` empties it), so a vitest process reuses what an earlier one transformed: the second
    // node lane of `npm test`, and every later run. Keyed on each file's text, the config and its
    // imports (vitest), and for the package sources the files they import (foldConstantModules).
    experimental: { fsModuleCache: true },
    pool: 'forks',
    testTimeout: 60_000,
    hookTimeout: 120_000,
    sequence: { sequencer: HeadlessFirst },
    projects: [
      {
        extends: true,
        test: {
          name: 'node',
          include: ['test/**/*.test.ts'],
          exclude: ['test/browser/**'],
          // The headless files share their worker's modules (no new module graph per file): each file
          // otherwise imported and evaluated the physics sources afresh, the largest single cost of
          // the lane. No headless file mocks a module or stubs a global, and every test builds its own
          // world, so a file sees the same library state it would alone.
          isolate: false,
          // vitest's runner, which also claims each file as it starts, so that the two node lanes of
          // `npm test` (scripts/test.mjs) run every file once between them.
          runner: './scripts/test-claims.mjs',
        },
      },
      {
        extends: true,
        test: {
          name: 'browser',
          include: ['test/browser/**/*.test.ts'],
          globalSetup: ['test/browser/global-setup.ts'],
          // The browser files share one worker process and its modules, as the headless ones do: with
          // vitest's default (a new module graph per file) every file started a worker process of its
          // own and imported vitest's runner, playwright-core and the harness afresh, one file after
          // another on the lane. A file's own state (its Harness, its pages) is in its own module, still evaluated
          // once a file; the shared modules (./harness, ./page-contract, ./chromium.mjs) keep no state
          // between files, and no browser file mocks a module or stubs a global.
          isolate: false,
          // A file's beforeAll may wait for the browser file before it (the lock in ./harness).
          hookTimeout: 600_000,
          // One more try for a failed browser test, kept as a safety net. Every page shares one
          // software-rendered GPU process (SwiftShader). The known causes of first-attempt failures
          // are handled where they arise: pages pace their frames to the GPU (packages/game-kit/src/frame-pacer.ts),
          // a page stuck at its start is reopened (test/browser/harness.ts STUCK_MS), a page opened in
          // a test is closed when it ends, and input tests wait on the game's state, not the clock.
          // With those, five full browser lanes at load 3 to 20 (2026-11-22) needed no retry (a page
          // stuck at its start was reopened in two of them).
          // A test that fails twice fails the run.
          retry: 1,
        },
      },
    ],
  },
});
