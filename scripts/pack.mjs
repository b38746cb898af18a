// `npm run pack`: builds the library packages (JS bundles and declarations into packages/*/dist) and
// packs each with `npm pack` into dist/packages/*.tgz, the tarballs a project outside this
// repository installs (`npm install /path/to/bitphysics/dist/packages/*.tgz`). Tests import packPackages().
import { execFileSync } from 'node:child_process';
import { mkdirSync, rmSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { buildPackages, libraryPackages, root } from './build.mjs';

/** Where `packPackages` writes the tarballs by default. */
export const packDir = join(root, 'dist', 'packages');

/**
 * Builds every library package and packs it.
 * @param {{ destination?: string }} options folder for the tarballs (emptied first; default dist/packages).
 * @returns {Promise<{ name: string, file: string }[]>} each package's name and tarball path, dependencies first.
 * @throws Error if a build or `npm pack` fails.
 */
export async function packPackages({ destination = packDir } = {}) {
  await buildPackages();
  rmSync(destination, { recursive: true, force: true });
  mkdirSync(destination, { recursive: true });
  const args = ['pack', '--json', '--pack-destination', destination, ...libraryPackages.flatMap((n) => ['-w', `packages/${n}`])];
  const out = execFileSync('npm', args, { cwd: root, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  const packed = JSON.parse(out.slice(out.indexOf('[')));
  return packed.map((p) => ({ name: p.name, file: join(destination, p.filename) }));
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  for (const { name, file } of await packPackages()) console.log(`${name}: ${file}`);
}
