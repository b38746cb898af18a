// `npm run build`: bundles src/main.ts (and copies src/index.html) into dist/, minified, ready for
// any static web host. serve.mjs uses the same options.
import { resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { build } from 'esbuild';

/** esbuild options of the game: one ESM bundle for the browser, its page copied beside it. */
export function options({ minify = false } = {}) {
  return {
    entryPoints: ['src/main.ts', 'src/index.html'],
    outbase: 'src',
    outdir: 'dist',
    bundle: true,
    format: 'esm',
    platform: 'browser',
    target: 'es2022',
    minify,
    sourcemap: true,
    loader: { '.html': 'copy', '.png': 'file' },
    logLevel: 'info',
  };
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  await build(options({ minify: true }));
}
