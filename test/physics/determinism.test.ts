import { execFile } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { promisify } from 'node:util';
import { stateHash, stepMany } from '@bitphysics/physics';
import { build } from 'esbuild';
import { expect, test } from 'vitest';
import { mixedScene, SNAPSHOT_SCENES } from './snapshot-scenes.js';

// Box2D v3's determinism test: the same scene built twice gives the same state to the last bit after
// 1,000 steps, in one process and in separate processes (fresh JIT, fresh heap, other module load
// order). The reference is the other run; the tolerance is zero (stateHash hashes every bit).

const STEPS = 1000;

/** The mixed scene's hash after STEPS steps in this process (the first test's), for the second test. */
let mixedHere: string | undefined;

test('the same scene built twice in one process: identical hashes after 1,000 steps (fireworks and the mixed scene)', () => {
  for (const { name, build: make } of SNAPSHOT_SCENES.filter((s) => s.name === 'fireworks' || s.name.startsWith('mixed'))) {
    const a = make(),
      b = make();
    stepMany(a, STEPS);
    stepMany(b, STEPS);
    expect(stateHash(b), name).toBe(stateHash(a));
    if (make === mixedScene) mixedHere = stateHash(a);
  }
});

test('the same scene in two separate processes: identical hashes after 1,000 steps, equal to this process', async () => {
  const dir = mkdtempSync(join(tmpdir(), 'bitphysics-determinism-'));
  const entry = join(dir, 'run.ts');
  writeFileSync(
    entry,
    [
      `import { stateHash, stepMany } from '@bitphysics/physics';`,
      `import { mixedScene } from ${JSON.stringify(join(__dirname, 'snapshot-scenes.ts'))};`,
      `const world = mixedScene();`,
      `stepMany(world, ${STEPS});`,
      `console.log(stateHash(world));`,
    ].join('\n'),
  );
  const out = join(dir, 'run.mjs');
  await build({
    entryPoints: [entry],
    outfile: out,
    bundle: true,
    platform: 'node',
    format: 'esm',
    logLevel: 'silent',
    conditions: ['bitphysics-source'],
    nodePaths: [join(__dirname, '../../node_modules')],
  });
  const run = promisify(execFile);
  const [one, two] = await Promise.all([run(process.execPath, [out]), run(process.execPath, [out])]);
  let here = mixedHere;
  if (here === undefined) {
    // This test run alone (a filter): step the scene here too.
    const world = mixedScene();
    stepMany(world, STEPS);
    here = stateHash(world);
  }
  expect(one.stdout.trim()).toMatch(/^[0-9a-f]{16}$/);
  expect(two.stdout.trim()).toBe(one.stdout.trim());
  expect(one.stdout.trim()).toBe(here);
}, 120_000);
