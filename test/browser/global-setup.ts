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
// The provided values' types (vitest's ProvidedContext) are declared in ./harness, which reads them.

export default async function setup(project: TestProject): Promise<() => Promise<void>> {
  const site = await startSite({ lockTimeoutMs: 590_000 });
  try {
    const server = await launchChromiumServer();
    project.provide('bitphysicsSiteUrl', site.url);
    project.provide('bitphysicsBrowserWs', server.wsEndpoint());
    return async () => {
      try {
        await server.close();
      } finally {
        await site.stop();
      }
    };
  } catch (error) {
    await site.stop();
    throw error;
  }
}
