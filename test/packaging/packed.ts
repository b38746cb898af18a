/**
 * The library packages built and packed once for the test process (scripts/pack.mjs packPackages),
 * into a folder of the system's temp folder removed when the process exits. packages.test.ts installs
 * these tarballs into a fresh project and new-project.test.ts copies them into the project it makes:
 * the node project runs its files in one worker that keeps its modules (vitest.config.ts), so the
 * second file of the two reuses what the first packed; a file run alone packs for itself.
 */
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { acquireSiteLock, repoRoot } from '../browser/chromium.mjs';

/** One packed package: its name and the path of its tarball. */
export interface Tarball {
  readonly name: string;
  readonly file: string;
}

let packed: Promise<readonly Tarball[]> | undefined;

/**
 * The packed library packages, dependencies first (packPackages' order); packs them on the first
 * call. Packing rebuilds every package's dist/, so it holds the cross-process 'pack' lock meanwhile:
 * two test runs in one checkout pack one at a time.
 * @throws whatever packPackages throws, or the lock's Error after 170 s; a later call tries again.
 */
export function packedPackages(): Promise<readonly Tarball[]> {
  packed ??= pack().catch((error: unknown) => {
    packed = undefined;
    throw error;
  });
  return packed;
}

async function pack(): Promise<readonly Tarball[]> {
  const dir = mkdtempSync(join(tmpdir(), 'bitphysics-packed-'));
  process.once('exit', () => rmSync(dir, { recursive: true, force: true }));
  const { packPackages } = (await import(pathToFileURL(join(repoRoot, 'scripts', 'pack.mjs')).href)) as {
    packPackages(options: { destination: string }): Promise<Tarball[]>;
  };
  const release = await acquireSiteLock({ name: 'pack', timeoutMs: 170_000 });
  try {
    return await packPackages({ destination: dir });
  } finally {
    release();
  }
}
