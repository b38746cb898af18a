// `npm start`: builds every game with esbuild, serves the gallery on http://127.0.0.1:8080/ (PORT
// overrides the port), prints the address and rebuilds on change. Tests import startServer().
import * as esbuild from 'esbuild';
import { mkdirSync, rmSync } from 'node:fs';
import { resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { siteDir, siteOptions, writeRegistry } from './build.mjs';

/**
 * Starts esbuild's own dev server on the built site. With `watch` (the default) it rebuilds on
 * change; without, it builds once and serves that site unchanged.
 * @param {{ port?: number, host?: string, watch?: boolean }} options
 * @returns {Promise<{ url: string, stop: () => Promise<void> }>}
 */
export async function startServer({ port = 8080, host = '127.0.0.1', watch = true } = {}) {
  rmSync(siteDir, { recursive: true, force: true });
  mkdirSync(siteDir, { recursive: true });
  const build = await esbuild.context(siteOptions());
  await build.rebuild();
  writeRegistry();
  let ctx = build;
  if (watch) {
    await build.watch();
  } else {
    // Without watch, esbuild's server rebuilds the whole site on every request for a page; a
    // fixed site (the browser tests) is served by a context with nothing to build instead.
    await build.dispose();
    ctx = await esbuild.context({ entryPoints: [], logLevel: 'silent' });
  }
  const { port: actual } = await ctx.serve({ host, port, servedir: siteDir });
  return {
    url: `http://${host}:${actual}/`,
    stop: () => ctx.dispose(),
  };
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const port = process.env.PORT ? Number(process.env.PORT) : 8080;
  if (!Number.isInteger(port) || port < 0 || port > 65535) {
    console.error(`PORT must be an integer in [0, 65535], got ${process.env.PORT}`);
    process.exit(1);
  }
  const { url } = await startServer({ port });
  console.log(`bitphysics gallery: ${url}  (rebuilds on change; Ctrl+C to stop)`);
}
