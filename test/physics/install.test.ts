import { execFile } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { promisify } from 'node:util';
import {
  addBallJoint3D,
  addBody,
  addBox,
  addEmitter,
  addShape3D,
  addSystem,
  createCloth,
  createPhysicsWorld,
  type PhysicsWorld,
  PIPELINE,
  removeSystem,
  restore,
  SCENES,
  STAGES,
  type System,
  snapshot,
  stateHash,
  stepMany,
} from '@bitphysics/physics';
import { build } from 'esbuild';
import { expect, test } from 'vitest';
import { PIPELINE_ORDER } from '../../packages/physics/src/step/install.js';

// A world starts with the core's systems and installs a feature's systems (emitters, 3D shapes and
// joints, cloth) when the feature is first used, at their place in the default pipeline, so a bundler
// drops the features a program never calls (step/install.ts). The reference is PIPELINE, the list
// of every built-in system in run order that every world ran before.

const FULL: Record<string, System[]> = {};
for (const { stage, systems } of PIPELINE) FULL[stage] = [...systems];

/** PIPELINE with the given stages' systems left out (systems a world has not installed). */
function pipelineWithout(out: readonly System[]): Record<string, System[]> {
  const r: Record<string, System[]> = {};
  for (const { stage, systems } of PIPELINE) r[stage] = systems.filter((s) => !out.includes(s));
  return r;
}

const emitterSystem = FULL.spawn![PIPELINE_ORDER.spawn.indexOf('emitter')]!;
const shapes3DSystem = FULL.collide![PIPELINE_ORDER.collide.indexOf('shapes3D')]!;
const clothSystem = FULL.constraints![PIPELINE_ORDER.constraints.indexOf('cloth')]!;

test('PIPELINE and PIPELINE_ORDER list the same stages with as many systems', () => {
  expect(PIPELINE.map((p) => p.stage)).toEqual([...STAGES]);
  for (const { stage, systems } of PIPELINE) expect(systems.length, stage).toBe(PIPELINE_ORDER[stage].length);
});

test("a new world holds the core's systems; each feature's first use puts its systems at PIPELINE's place", () => {
  const world = createPhysicsWorld({ dimensions: 3, capacity: 100 });
  expect(world.stages).toEqual(pipelineWithout([emitterSystem, shapes3DSystem, clothSystem]));
  addEmitter(world, { position: [0, 0, 0] });
  expect(world.stages).toEqual(pipelineWithout([shapes3DSystem, clothSystem]));
  const body = addBody(world, { position: [0, 1, 0] });
  addShape3D(world, body, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
  expect(world.stages).toEqual(pipelineWithout([clothSystem]));
  // Again: nothing more.
  addEmitter(world, { position: [1, 0, 0] });
  expect(world.stages).toEqual(pipelineWithout([clothSystem]));
  // A 3D joint alone brings the 3D systems too; cloth (2D only) comes with the first cloth.
  const jointed = createPhysicsWorld({ dimensions: 3, capacity: 100 });
  const a = addBody(jointed, { position: [0, 1, 0] }),
    b = addBody(jointed, { position: [1, 1, 0] });
  addBallJoint3D(jointed, { a, b, anchor: [0.5, 1, 0] });
  expect(jointed.stages).toEqual(pipelineWithout([emitterSystem, clothSystem]));
  const flat = createPhysicsWorld({ capacity: 100 });
  createCloth(flat, { rows: 2, columns: 2, origin: [0, 5] });
  expect(flat.stages).toEqual(pipelineWithout([emitterSystem, shapes3DSystem]));
});

test('user systems keep their place around an installed built-in; a built-in a user removed stays out', () => {
  const world = createPhysicsWorld({ capacity: 100 });
  const mine: System = () => {};
  const first: System = () => {};
  addSystem(world, 'spawn', mine);
  addSystem(world, 'constraints', first);
  addEmitter(world, { position: [0, 0] });
  createCloth(world, { rows: 2, columns: 2, origin: [0, 5] });
  // As in a world that had every built-in from the start and appended the user's systems.
  expect(world.stages.spawn).toEqual([...FULL.spawn!, mine]);
  expect(world.stages.constraints).toEqual([clothSystem, first]);
  expect(removeSystem(world, 'spawn', emitterSystem)).toBe(true);
  addEmitter(world, { position: [1, 0] });
  expect(world.stages.spawn).not.toContain(emitterSystem);
});

test("restore installs every feature: the restored world runs PIPELINE's systems", () => {
  const a = createPhysicsWorld({ capacity: 100 });
  addBox(a, { position: [0, 1], halfExtents: [0.5, 0.5] });
  const b = createPhysicsWorld({ capacity: 100 });
  restore(b, snapshot(a));
  expect(b.stages).toEqual(pipelineWithout([]));
});

// Bit-identity with the full pipeline: every scene stepped in a world that installs its features as
// it goes, and in one that has had all of PIPELINE from the start (the pipeline every world ran
// before features were installed on use). stateHash hashes every bit of the state: tolerance zero.
test.each(Object.keys(SCENES))('scene %s: the same state to the bit as with every built-in system from the start', (name) => {
  const scene = SCENES[name]!;
  const make = (full: boolean): PhysicsWorld => {
    const count = Math.min(scene.defaultCount, 300);
    const world = createPhysicsWorld(scene.worldOptions({ count, seed: 3 }));
    if (full) {
      for (const stage of STAGES) {
        world.stages[stage].splice(0, Infinity, ...FULL[stage]!);
        for (const [i, n] of PIPELINE_ORDER[stage].entries()) world.builtins.set(n, FULL[stage]![i]!);
      }
    }
    scene.build(world, { count, seed: 3 });
    return world;
  };
  const lazy = make(false),
    full = make(true);
  stepMany(lazy, 60);
  stepMany(full, 60);
  expect(stateHash(lazy)).toBe(stateHash(full));
});

test('in a fresh process: threads > 1 without enableThreads() throws an Error that names it, and bundles no pool; a 3D ball world steps as with the 3D rows installed', async () => {
  // A fresh process, since the 3D rows' table (solver/rows-3d.ts) and the pool maker are set for the
  // whole process once installed. spheres-in-box (3D balls, no 3D shape or joint) runs first on the
  // rows' stand-ins, then again with install3D: the same state to the bit (stateHash).
  const dir = mkdtempSync(join(tmpdir(), 'bitphysics-no-threads-'));
  const src = resolve(__dirname, '../../packages/physics/src');
  const entry = join(dir, 'run.ts');
  writeFileSync(
    entry,
    [
      `import { createPhysicsWorld, SCENES, stateHash, stepMany } from '@bitphysics/physics';`,
      `import { install3D } from '${src}/collision/install-3d.ts';`,
      `try { createPhysicsWorld({ threads: 2 }); console.log('made'); } catch (e) { console.log((e as Error).message); }`,
      `const scene = SCENES['spheres-in-box']!;`,
      `const run = (installed: boolean) => {`,
      `  const world = createPhysicsWorld(scene.worldOptions({ count: 300, seed: 3 }));`,
      `  if (installed) install3D(world);`,
      `  scene.build(world, { count: 300, seed: 3 });`,
      `  stepMany(world, 120);`,
      `  return stateHash(world);`,
      `};`,
      `const before = run(false);`,
      `const after = run(true);`,
      `console.log(before === after ? 'same' : 'differ ' + before + ' ' + after);`,
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
  const { stdout } = await promisify(execFile)(process.execPath, [out], { timeout: 60_000 });
  expect(stdout.trim().split('\n')).toEqual([
    "createPhysicsWorld: threads: 2 needs the thread pool, which a program loads by calling enableThreads() once before making the world (import { enableThreads } from '@bitphysics/physics')",
    'same',
  ]);
  // A program that makes a world and never calls enableThreads bundles neither the workers' source nor
  // the kernel table.
  const plain = await build({
    stdin: { contents: `import { createPhysicsWorld } from '@bitphysics/physics'; createPhysicsWorld();`, resolveDir: dir, loader: 'ts' },
    bundle: true,
    format: 'esm',
    write: false,
    logLevel: 'silent',
    metafile: true,
    external: ['bitecs'],
    conditions: ['bitphysics-source'],
    nodePaths: [join(__dirname, '../../node_modules')],
  });
  const kept = Object.entries(Object.values(plain.metafile.outputs)[0]!.inputs).filter(([, v]) => v.bytesInOutput > 0);
  expect(kept.map(([f]) => f).filter((f) => /threads\/(worker-source|worker-main|kernel-table)\.ts$/.test(f))).toEqual([]);
}, 90_000);
