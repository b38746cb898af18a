// The fixed cost of one `step(world)` on small worlds: `node scripts/small-world-step.mjs [rev] [flags]`.
//
// Games step small side worlds every frame (a path predictor, a preview, a level of a handful of
// bodies), where a step's cost is the engine's own overhead rather than its per-body work. This script
// builds five small worlds (one body under gravity; one body and five attractors; ten balls in a box;
// ten 2D boxes; five 3D boxes) from the physics sources bundled as the bench bundles them, and prints
// for each the median nanoseconds a step and the bytes the step allocates (the growth of the used heap
// over a batch of steps in which no garbage collection ran, per step; a median over batches).
//
// With a git revision `rev`, the same worlds are also built from `rev` (checked out into a temporary
// worktree) and stepped in turn with the working tree's, batch by batch in one process (as
// scripts/ab.mjs), and the ratios (working tree / rev) are printed with the state hashes of the two
// at the end (equal when a change keeps the results to the bit).
//
// Flags: --rounds (default 12: fresh worlds each round), --batches (default 30 a round), --batch
// (default 20 steps), --warm (default 120 steps a round before timing), --only <world name>. Exit
// code 2 on a usage error.

import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync, symlinkSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { parseArgs } from 'node:util';
import { root } from './build.mjs';
import { bundlePhysics } from './physics-bundle.mjs';

function usage(message) {
  console.error(
    `small-world-step: ${message}\nusage: node scripts/small-world-step.mjs [rev] [--rounds n] [--batches n] [--batch n] [--warm n] [--only name]`,
  );
  process.exit(2);
}

let parsed;
try {
  parsed = parseArgs({
    allowPositionals: true,
    options: {
      rounds: { type: 'string', default: '12' },
      batches: { type: 'string', default: '30' },
      batch: { type: 'string', default: '20' },
      warm: { type: 'string', default: '120' },
      only: { type: 'string' },
    },
  });
} catch (e) {
  usage(e.message);
}
const { values, positionals } = parsed;
if (positionals.length > 1) usage('give at most one git revision');
const integer = (name, min) => {
  const v = Number(values[name]);
  if (!Number.isInteger(v) || v < min) usage(`--${name} must be an integer >= ${min}, got ${values[name]}`);
  return v;
};
const rounds = integer('rounds', 1),
  batches = integer('batches', 1),
  batch = integer('batch', 1),
  warm = integer('warm', 0);

/** The small worlds: name, and a builder taking the physics module. */
const WORLDS = [
  [
    '1 body, gravity',
    (M) => {
      const w = M.createPhysicsWorld({ dimensions: 2, gravity: [0, -10], capacity: 16, seed: 1 });
      M.addBody(w, { position: [0, 100], velocity: [1, 0], mass: 1 });
      return w;
    },
  ],
  [
    '1 body + 5 attractors',
    (M) => {
      const w = M.createPhysicsWorld({ dimensions: 2, gravity: [0, 0], capacity: 16, seed: 1 });
      M.addBody(w, { position: [0, 0], velocity: [0, 3], mass: 1 });
      for (let i = 0; i < 5; i++) {
        const a = (2 * Math.PI * i) / 5;
        const e = M.addBody(w, { position: [20 * Math.cos(a), 20 * Math.sin(a)], static: true });
        M.setAttractor(w, e, { mass: 50, softening: 0.5 });
      }
      return w;
    },
  ],
  ['10 balls in a box', (M) => scene(M, 'balls-in-box', 10)],
  ['10 boxes 2D', (M) => scene(M, 'pyramid', 4)],
  ['5 boxes 3D', (M) => scene(M, 'box-pile-3d', 5)],
];

function scene(M, name, count) {
  const s = M.SCENES[name];
  const options = { count, seed: 1 };
  const w = M.createPhysicsWorld({ ...s.worldOptions(options), seed: 1 });
  s.build(w, options);
  return w;
}

const median = (x) => {
  const y = [...x].sort((p, q) => p - q);
  return y.length === 0 ? Number.NaN : y[y.length >> 1];
};

/** Runs `batch` steps of `w`; returns [ns a step, bytes a step or NaN when a collection ran]. */
function timeBatch(M, w) {
  const h0 = process.memoryUsage().heapUsed;
  const t0 = process.hrtime.bigint();
  for (let i = 0; i < batch; i++) M.step(w);
  const t1 = process.hrtime.bigint();
  const h1 = process.memoryUsage().heapUsed;
  return [Number(t1 - t0) / batch, h1 >= h0 ? (h1 - h0) / batch : Number.NaN];
}

const rev = positionals[0];
const temp = mkdtempSync(join(tmpdir(), 'bitphysics-small-'));
const base = join(temp, 'tree');
let worktree = false;
try {
  const builds = [];
  if (rev !== undefined) {
    try {
      execFileSync('git', ['-C', root, 'worktree', 'add', '--detach', '--quiet', base, rev], { stdio: ['ignore', 'ignore', 'inherit'] });
    } catch {
      usage(`cannot check out ${rev}`);
    }
    worktree = true;
    symlinkSync(join(root, 'node_modules'), join(base, 'node_modules'), 'dir');
    builds.push([rev, await bundlePhysics(temp, base, 'rev')]);
  }
  builds.push(['working tree', await bundlePhysics(temp, root, 'tree')]);
  const worlds = values.only === undefined ? WORLDS : WORLDS.filter(([n]) => n === values.only);
  if (worlds.length === 0) usage(`--only must name one of: ${WORLDS.map(([n]) => n).join('; ')}`);
  for (const [name, make] of worlds) {
    const ns = builds.map(() => []),
      bytes = builds.map(() => []),
      ratios = [];
    const hashes = builds.map(() => '');
    for (let r = 0; r < rounds; r++) {
      const ws = builds.map(([, M]) => make(M));
      for (let s = 0; s < warm; s++) for (let k = 0; k < builds.length; k++) builds[k][1].step(ws[k]);
      for (let b = 0; b < batches; b++) {
        const order = (b + r) % 2 === 0 ? builds.map((_, k) => k) : builds.map((_, k) => builds.length - 1 - k);
        const t = [];
        for (const k of order) {
          const [tn, by] = timeBatch(builds[k][1], ws[k]);
          t[k] = tn;
          ns[k].push(tn);
          if (!Number.isNaN(by)) bytes[k].push(by);
        }
        if (builds.length === 2) ratios.push(t[1] / t[0]);
      }
      for (let k = 0; k < builds.length; k++) {
        hashes[k] = builds[k][1].stateHash(ws[k]);
        builds[k][1].disposeWorld(ws[k]);
      }
    }
    console.log(`${name}:`);
    for (let k = 0; k < builds.length; k++) {
      console.log(
        `  ${builds[k][0]}: median ${median(ns[k]).toFixed(0)} ns/step, ${median(bytes[k]).toFixed(0)} B/step allocated (${bytes[k].length} clean batches)`,
      );
    }
    if (builds.length === 2) {
      console.log(`  working tree / ${rev}: median of the batches' ratios ${median(ratios).toFixed(3)}`);
      console.log(`  state hashes at the end: ${hashes[0]} ${hashes[1]} (${hashes[0] === hashes[1] ? 'equal' : 'different'})`);
    }
  }
} finally {
  if (worktree) execFileSync('git', ['-C', root, 'worktree', 'remove', '--force', base], { stdio: 'ignore' });
  rmSync(temp, { recursive: true, force: true });
}
