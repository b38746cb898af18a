// The physics engine's source bundled for a script that steps it in this process: scripts/ab.mjs and
// scripts/small-world-step.mjs bundle the working tree's source and a git revision's side by side.
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import * as esbuild from 'esbuild';

/**
 * Bundles `tree`'s packages/physics/src/index.ts into `dir`/`name`.mjs and imports it. As the bench,
 * the pages and the packages' dist/ ship the engine, the constants are folded into the code that reads
 * them (layout offsets imported from their own modules included: minifySyntax).
 * @param {string} dir - A scratch folder for the entry and the bundle.
 * @param {string} tree - The checkout whose source is bundled (the repository root or a worktree).
 * @param {string} name - The files' base name, unique within `dir`.
 * @returns {Promise<Record<string, any>>} the bundle's module (the package's exports).
 */
export async function bundlePhysics(dir, tree, name) {
  const entry = join(dir, `${name}.ts`),
    out = join(dir, `${name}.mjs`);
  writeFileSync(entry, `export * from ${JSON.stringify(join(tree, 'packages', 'physics', 'src', 'index.ts'))};\n`);
  await esbuild.build({
    entryPoints: [entry],
    bundle: true,
    platform: 'node',
    format: 'esm',
    conditions: ['bitphysics-source'],
    minifySyntax: true,
    outfile: out,
    logLevel: 'error',
  });
  return import(out);
}
