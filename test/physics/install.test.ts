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
  addParticle,
  addShape3D,
  addSystem,
  createCloth,
  createPhysicsWorld,
  createRope,
  installBalls,
  isAlive,
  type PhysicsWorld,
  PIPELINE,
  removeSystem,
  restore,
  SCENES,
  STAGES,
  type System,
  setRadius,
  snapshot,
  stateHash,
  step,
  stepMany,
} from '@bitphysics/physics';
import { addComponent } from 'bitecs';
import { build } from 'esbuild';
import { expect, test } from 'vitest';
import { PIPELINE_ORDER } from '../../packages/physics/src/world/install.js';

// A world starts with the core's systems and installs a feature's systems (emitters, 3D shapes and
// joints, cloth) when the feature is first used, at their place in the default pipeline, so a bundler
// drops the features a program never calls (world/install.ts). The reference is PIPELINE, the list
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
const BALLS = [FULL.collide![PIPELINE_ORDER.collide.indexOf('broadphase')]!, FULL.collide![PIPELINE_ORDER.collide.indexOf('narrowphase')]!];

test('PIPELINE and PIPELINE_ORDER list the same stages with as many systems', () => {
  expect(PIPELINE.map((p) => p.stage)).toEqual([...STAGES]);
  for (const { stage, systems } of PIPELINE) expect(systems.length, stage).toBe(PIPELINE_ORDER[stage].length);
});

test("a new world holds the core's systems; each feature's first use puts its systems at PIPELINE's place", () => {
  const world = createPhysicsWorld({ dimensions: 3, capacity: 100 });
  expect(world.stages).toEqual(pipelineWithout([emitterSystem, shapes3DSystem, clothSystem, ...BALLS]));
  addEmitter(world, { position: [0, 0, 0] });
  expect(world.stages).toEqual(pipelineWithout([shapes3DSystem, clothSystem, ...BALLS]));
  const body = addBody(world, { position: [0, 1, 0] });
  addShape3D(world, body, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
  expect(world.stages).toEqual(pipelineWithout([clothSystem, ...BALLS]));
  // A body with a radius is a ball: the balls' broadphase and narrowphase come with it.
  addBody(world, { position: [3, 1, 0], radius: 0.5 });
  expect(world.stages).toEqual(pipelineWithout([clothSystem]));
  // Again: nothing more.
  addEmitter(world, { position: [1, 0, 0] });
  addBody(world, { position: [5, 1, 0], radius: 0.5 });
  expect(world.stages).toEqual(pipelineWithout([clothSystem]));
  // A 3D joint alone brings the 3D systems too; cloth (2D only) comes with the first cloth.
  const jointed = createPhysicsWorld({ dimensions: 3, capacity: 100 });
  const a = addBody(jointed, { position: [0, 1, 0] }),
    b = addBody(jointed, { position: [1, 1, 0] });
  addBallJoint3D(jointed, { a, b, anchor: [0.5, 1, 0] });
  expect(jointed.stages).toEqual(pipelineWithout([emitterSystem, clothSystem, ...BALLS]));
  const flat = createPhysicsWorld({ capacity: 100 });
  createCloth(flat, { rows: 2, columns: 2, origin: [0, 5] });
  expect(flat.stages).toEqual(pipelineWithout([emitterSystem, shapes3DSystem, ...BALLS]));
  // Each ball maker installs them: setRadius, an emitter whose particles have a radius, a rope with a radius.
  const viaRadius = createPhysicsWorld({ capacity: 100 });
  setRadius(viaRadius, addParticle(viaRadius, { position: [0, 1] }), 0.2);
  const viaEmitter = createPhysicsWorld({ capacity: 100 });
  addEmitter(viaEmitter, { position: [0, 0], particle: { radius: 0.05 } });
  const viaRope = createPhysicsWorld({ capacity: 100 });
  createRope(viaRope, { start: [0, 5], end: [2, 5], segments: 4, radius: 0.05 });
  for (const w of [viaRadius, viaEmitter, viaRope]) expect(w.stages.collide).toEqual(expect.arrayContaining(BALLS));
});

test('a Ball given with addComponent alone: step refuses, naming installBalls, and runs once it is called', () => {
  // A ball dropped 1.2 m onto a static ball of radius 1 (top at y = 0): once installed it rests on it
  // (its centre near y = 0.2), where without the ball collisions it would fall through (y < -5 after 2 s).
  const world = createPhysicsWorld({ capacity: 100, gravity: [0, -9.81] });
  const slot = addParticle(world, { position: [0, 1.4] });
  addComponent(world, slot, world.components.Ball);
  world.components.Ball.radius[slot] = 0.2;
  const before = stateHash(world);
  expect(() => step(world)).toThrow(
    /^step: entity \d+ has the Ball component but this world's ball collisions are not installed; .*installBalls\(world\)/,
  );
  expect(stateHash(world)).toBe(before);
  installBalls(world);
  const rest = world.components.Position;
  // The static ball below (made after installBalls: either order works).
  const post = addBody(world, { position: [0, -1], radius: 1, static: true });
  expect(isAlive(world, post)).toBe(true);
  stepMany(world, 120);
  expect(Math.abs(rest.y[slot]! - 0.2)).toBeLessThan(0.05);
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

/**
 * The `count` each scene runs at below: about 300 bodies. For most scenes `count` is the number of
 * bodies (at most 300 here); for these it is a side: 9 gives a 3D pyramid of 285 boxes, 24 a 2D
 * pyramid of 300, 17 a joint net or a cloth of 17 x 17 = 289. That is every system a scene uses
 * (contacts, stacking, joints, sleeping within the 60 steps), as at the scene's default size.
 */
const SIDE_COUNT: Readonly<Record<string, number>> = { 'pyramid-3d': 9, pyramid: 24, 'joint-grid': 17, cloth: 17 };

// Bit-identity with the full pipeline: every scene stepped in a world that installs its features as
// it goes, and in one that has had all of PIPELINE from the start (the pipeline every world ran
// before features were installed on use). stateHash hashes every bit of the state: tolerance zero.
test.each(Object.keys(SCENES))('scene %s: the same state to the bit as with every built-in system from the start', (name) => {
  const scene = SCENES[name]!;
  const make = (full: boolean): PhysicsWorld => {
    const count = SIDE_COUNT[name] ?? Math.min(scene.defaultCount, 300);
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

test('in a fresh process: threads > 1 without enableThreads() throws an Error that names it, and bundles no pool; boxes and joints step as with the ball rows installed, a 3D ball world as with the 3D rows', async () => {
  // A fresh process, since the 3D rows' and the ball rows' families (solver/row-families.ts)
  // and the pool maker are set for the whole process once installed. pyramid and joint-grid (no
  // ball) run before the ball rows exist, then with them installed: the same state to the bit. spheres-in-box (3D balls, no 3D shape or joint) runs first on the
  // rows' stand-ins, then again with install3D: the same state to the bit (stateHash).
  const dir = mkdtempSync(join(tmpdir(), 'bitphysics-no-threads-'));
  const src = resolve(__dirname, '../../packages/physics/src');
  const entry = join(dir, 'run.ts');
  writeFileSync(
    entry,
    [
      `import { createPhysicsWorld, SCENES, stateHash, stepMany } from '@bitphysics/physics';`,
      `import { installBalls } from '${src}/collision/install-balls.ts';`,
      `import { install3D } from '${src}/collision/install-3d.ts';`,
      `import { rowFamilies } from '${src}/solver/row-families.ts';`,
      `try { createPhysicsWorld({ threads: 2 }); console.log('made'); } catch (e) { console.log((e as Error).message); }`,
      // Boxes and joints before any ball exists (the solver skips its ball rows), then with them installed.
      `const runWithout = (name: string, installed: boolean) => {`,
      `  const world = createPhysicsWorld(SCENES[name]!.worldOptions({ count: 12, seed: 3 }));`,
      `  if (installed) installBalls(world);`,
      `  SCENES[name]!.build(world, { count: 12, seed: 3 });`,
      `  stepMany(world, 120);`,
      `  return stateHash(world);`,
      `};`,
      `const boxes = [runWithout('pyramid', false), runWithout('joint-grid', false), rowFamilies(2).balls === null];`,
      `const boxesAfter = [runWithout('pyramid', true), runWithout('joint-grid', true)];`,
      `console.log(boxes[2] && boxes[0] === boxesAfter[0] && boxes[1] === boxesAfter[1] ? 'same' : 'differ ' + boxes + ' ' + boxesAfter);`,
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
