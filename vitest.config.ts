import { availableParallelism } from 'node:os';
import { defineConfig } from 'vitest/config';
import { defaultClientConditions, defaultServerConditions } from 'vite';

// Workspace packages export their TypeScript sources under the 'bitphysics-source' condition, so
// tests run against the sources without a build step.
//
// Two projects: `node` (everything headless) and `browser` (test/browser: pages in Chromium). The
// browser project's global setup builds and serves the site once and starts one Chromium that its
// files share. At least two workers even on a 2-core machine (vitest's default there is one): a
// browser file spends much of its time waiting for frames, which a headless file fills.
export default defineConfig({
  resolve: { conditions: ['bitphysics-source', ...defaultClientConditions] },
  ssr: { resolve: { conditions: ['bitphysics-source', ...defaultServerConditions] } },
  test: {
    pool: 'forks',
    maxWorkers: Math.max(2, availableParallelism()),
    testTimeout: 60_000,
    hookTimeout: 120_000,
    projects: [
      { extends: true, test: { name: 'node', include: ['test/**/*.test.ts'], exclude: ['test/browser/**'] } },
      {
        extends: true,
        test: { name: 'browser', include: ['test/browser/**/*.test.ts'], globalSetup: ['test/browser/global-setup.ts'] },
      },
    ],
  },
});
