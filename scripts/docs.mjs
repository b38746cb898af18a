// `npm run docs`: the API reference of every library package, generated from the docstrings by
// TypeDoc into dist/docs (served by `npm start` at /docs/). TypeDoc needs the TypeScript 5 compiler
// API, which TypeScript 7 does not have, so it lives with its own TypeScript in the tools/docs
// workspace (tools/docs/typedoc.json: entry points, one per package export). An exported name
// without a docstring fails the build (TypeDoc's notDocumented validation, warnings as errors).
import { spawn } from 'node:child_process';
import { existsSync } from 'node:fs';
import { setPriority } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { root } from './build.mjs';

/** Where the API reference is written. */
export const docsDir = join(root, 'dist', 'docs');

/**
 * Runs TypeDoc once.
 * @param {{ quiet?: boolean, background?: boolean }} options quiet: keep TypeDoc's output unless it fails;
 *   background: run TypeDoc at the lowest CPU priority (npm start builds the docs beside the gallery).
 * @returns {Promise<string>} docsDir.
 * @throws Error with TypeDoc's output if it fails (a type error, an undocumented export).
 */
export function buildDocs({ quiet = false, background = false } = {}) {
  const tools = join(root, 'tools', 'docs');
  const typedoc = join(tools, 'node_modules', 'typedoc', 'bin', 'typedoc');
  if (!existsSync(typedoc)) return Promise.reject(new Error(`${typedoc} is missing: run npm install at the repository root`));
  return new Promise((resolveDocs, reject) => {
    const child = spawn(process.execPath, [typedoc, '--options', 'typedoc.json', '--treatValidationWarningsAsErrors'], {
      cwd: tools,
      stdio: quiet ? ['ignore', 'pipe', 'pipe'] : 'inherit',
    });
    if (background && child.pid !== undefined) {
      try {
        setPriority(child.pid, 19); // lowest: the gallery's build and the games come first
      } catch {
        /* not permitted here: run at normal priority */
      }
    }
    let output = '';
    child.stdout?.on('data', (d) => {
      output += d;
    });
    child.stderr?.on('data', (d) => {
      output += d;
    });
    child.on('error', reject);
    child.on('exit', (code) => (code === 0 ? resolveDocs(docsDir) : reject(new Error(`typedoc exited with ${code}\n${output}`))));
  });
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  try {
    console.log(`API reference in ${await buildDocs()}`);
  } catch (error) {
    console.error(error instanceof Error ? error.message : error);
    process.exit(1);
  }
}
