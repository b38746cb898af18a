/**
 * Vitest global setup of the browser project (vitest.config.ts): builds and serves the site once
 * and launches one headless Chromium as a server, for every browser test file of the run. Files
 * connect to both through `Harness.start` (./harness), so they can run side by side (one context a
 * page) without each building, serving and launching its own.
 *
 * The site lock (chromium.mjs `acquireSiteLock`) is held for the whole run, so the thumbnail script
 * does not write the site cache at the same time.
 */
import type { TestProject } from 'vitest/node';
import { launchChromiumServer, startSite } from './chromium.mjs';

declare module 'vitest' {
  export interface ProvidedContext {
    /** URL of the site served for this run, ending with '/'. */
    bitphysicsSiteUrl: string;
    /** WebSocket endpoint of the run's shared Chromium (playwright's BrowserServer). */
    bitphysicsBrowserWs: string;
  }
}

export default async function setup(project: TestProject): Promise<() => Promise<void>> {
  const site = await startSite({ lockTimeoutMs: 590_000 });
  try {
    const server = await launchChromiumServer();
    project.provide('bitphysicsSiteUrl', site.url);
    project.provide('bitphysicsBrowserWs', server.wsEndpoint());
    return async () => {
      try { await server.close(); } finally { await site.stop(); }
    };
  } catch (error) {
    await site.stop();
    throw error;
  }
}
