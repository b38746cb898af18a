import { defineConfig } from 'vitest/config';
import { defaultClientConditions, defaultServerConditions } from 'vite';

// Workspace packages export their TypeScript sources under the 'bitphysics-source' condition, so
// tests run against the sources without a build step.
export default defineConfig({
  resolve: { conditions: ['bitphysics-source', ...defaultClientConditions] },
  ssr: { resolve: { conditions: ['bitphysics-source', ...defaultServerConditions] } },
  test: {
    include: ['test/**/*.test.ts'],
    pool: 'forks',
    testTimeout: 60_000,
    hookTimeout: 120_000,
  },
});
