// A scene's first steps, each in a fresh process: `node scripts/first-steps.mjs [rev] [flags]`.
//
// A world's first steps run code V8 has not compiled yet (issue 36: pyramid 40's first step took about
// 100 ms of the main thread's CPU against about 4 ms once compiled), so they can only be measured in a
// process that has run nothing else: scripts/ab.mjs steps two worlds in one process and times warm
// code. This script builds the scene (from the physics sources bundled as the bench bundles them) in a
// new Node process per run and prints, for each of the first steps, the median over the runs of:
// - main: the CPU time of the thread that steps the world (Linux /proc/thread-self/schedstat, ns
//   resolution): the step's own work, interpreted or compiled, with lazy compilation and the garbage
//   collector's pauses, but not V8's optimising compiler, which runs on background threads;
// - cpu: the process's CPU time (process.cpuUsage), which adds those background threads;
// - wall: the step's wall time (on a loaded machine mostly waiting for a core).
// Then the sums over the steps and, with --deopts, the functions V8 threw back to the interpreter in
// those steps (--trace-deopt-verbose), with V8's reason, the number of runs in which each did, and the
// code where it did: line:column in the bundle and the text there (the innermost function first when
// the deoptimising code had inlined it: `inner < outer`). "Insufficient type feedback" means the code
// there had never run when V8 compiled the function (a branch first taken then, or loads run before the
// function had a feedback vector); "wrong map", "not a Smi", "lost precision or NaN" mean a value of
// another shape or kind than every one seen before.
//
// With a git revision `rev`, the same scene is also built from `rev` (checked out into a temporary
// worktree), the runs alternate between the two, and each line also shows rev's medians and the
// ratio of the working tree's main-thread medians to rev's; the state hashes after the steps are
// compared (equal when a change keeps the results to the bit).
//
// Flags: --scene (default pyramid), --count (scene default), --steps (default 8), --runs (default 7
// per tree), --seed (default 1), --show a-b (the steps printed one by one, default 0-<steps>),
// --deopts, --flags "<Node or V8 flags for every run>" (an experiment: --flags=--no-lazy-feedback-allocation; the = is needed).
// --warm-up (call warmUp(d) of the scene's dimension before making the world, as a program may during
// its loading; the steps then show what is left after it, and a last line the warm-up's own times).
// --compiles (after the timed runs, per tree: what V8's optimising compiler, TurboFan, compiled in
// the steps, and how much: two more runs with its compiles made on the main thread, one of the steps
// and one stopped before them, and the difference of TurboFan's zone memory (--turbo-stats), a measure
// of its work that does not depend on the machine's load; then the functions compiled in each step,
// '(osr)' for a loop's on-stack replacement. On a loaded machine a change to how much the first steps
// compile shows in this figure long before it shows in their CPU times). Exit code 2 on a usage error. Linux only (the main thread's CPU time).

import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { root } from './build.mjs';
import { bundlePhysics } from './physics-bundle.mjs';
import { checkOut, removeCheckout, scriptCli } from './script-cli.mjs';

const { values, positionals, usage, integer } = scriptCli(
  'first-steps',
  'node scripts/first-steps.mjs [rev] [--scene pyramid] [--count n] [--steps 8] [--runs 7] [--seed 1] [--show a-b] [--deopts] [--flags="--v8-flag ..."] [--warm-up] [--compiles]',
  {
    scene: { type: 'string', default: 'pyramid' },
    count: { type: 'string' },
    steps: { type: 'string', default: '8' },
    runs: { type: 'string', default: '7' },
    seed: { type: 'string', default: '1' },
    show: { type: 'string' },
    deopts: { type: 'boolean', default: false },
    flags: { type: 'string', default: '' },
    'warm-up': { type: 'boolean', default: false },
    compiles: { type: 'boolean', default: false },
  },
);
if (positionals.length > 1) usage('give at most one git revision');
const steps = integer('steps', values.steps, 1),
  runs = integer('runs', values.runs, 1),
  seed = integer('seed', values.seed, 0);
const count = values.count === undefined ? undefined : integer('count', values.count, 1);
const nodeFlags = values.flags.split(' ').filter((x) => x !== '');
if (nodeFlags.some((x) => !x.startsWith('--'))) usage(`--flags takes Node or V8 flags (each starting with --), got ${values.flags}`);
const show = /^(\d+)-(\d+)$/.exec(values.show ?? `0-${steps}`);
if (!show || Number(show[1]) >= Number(show[2]) || Number(show[2]) > steps)
  usage(`--show must be a-b with a < b <= steps, got ${values.show}`);
if (!readFileSync('/proc/thread-self/schedstat', { encoding: 'utf8', flag: 'r' })) usage('needs Linux /proc/thread-self/schedstat');

/** The child: builds the scene from `bundle`, steps it, prints one JSON line (per-step times, ms, and the state hash). */
const CHILD = `
import { readFileSync } from 'node:fs';
const [bundle, scene, count, steps, seed, warm] = JSON.parse(process.argv[2]);
const M = await import(bundle);
const s = M.SCENES[scene];
if (!s) { console.log(JSON.stringify({ error: 'unknown scene ' + scene + ' (scenes: ' + Object.keys(M.SCENES).join(', ') + ')' })); process.exit(0); }
const options = count === null ? { seed } : { count, seed };
const thread = () => Number(readFileSync('/proc/thread-self/schedstat', 'utf8').split(' ')[0]) / 1e6;
const cpu = () => { const u = process.cpuUsage(); return (u.user + u.system) / 1000; };
let warmUp = null;
if (warm) {
  const t0 = performance.now(), c0 = cpu(), m0 = thread();
  M.warmUp(s.worldOptions(options).dimensions ?? 2);
  warmUp = [thread() - m0, cpu() - c0, performance.now() - t0];
}
const w = M.createPhysicsWorld({ ...s.worldOptions(options), seed });
s.build(w, options);
const main = [], proc = [], wall = [];
for (let i = 0; i < steps; i++) {
  const t0 = performance.now(), c0 = cpu(), m0 = thread();
  console.log('=== step ' + i);
  M.step(w);
  main.push(thread() - m0); proc.push(cpu() - c0); wall.push(performance.now() - t0);
}
console.log('=== hash');
console.log(JSON.stringify({ main, proc, wall, warmUp, hash: M.stateHash(w) }));
`;

/**
 * Where a deoptimisation happened, from V8's `<file:line:column>, <file:line:column>...` (innermost
 * inlined function first) in `t`'s bundle: the positions, then the code around the first, `>>` before
 * the operation that deoptimised.
 */
function deoptSite(t, positions) {
  const at = [...positions.matchAll(/:(\d+):(\d+)>/g)].map((x) => [Number(x[1]), Number(x[2])]);
  if (at.length === 0) return '(position cut off in the trace)';
  t.lines ??= readFileSync(t.bundle, 'utf8').split('\n');
  const [line, column] = at[0];
  const code = t.lines[line - 1] ?? '',
    i = column - 1; // V8's columns count from 1
  return `${at.map((x) => x.join(':')).join(' < ')}: ${code.slice(Math.max(0, i - 30), i).trimStart()} >>${code.slice(i, i + 30).trimEnd()}`;
}

/**
 * One run of tree `t`'s child over `n` steps with TurboFan's compiles on the main thread (so that
 * which functions it compiles, and when, does not depend on the load), traced: returns TurboFan's
 * zone memory over the whole run (bytes, --turbo-stats) and the functions compiled in each step.
 */
function compileRun(t, n) {
  const out = execFileSync(
    process.execPath,
    [
      ...nodeFlags,
      '--trace-opt',
      '--turbo-stats',
      '--no-concurrent-recompilation',
      '--no-concurrent-osr',
      child,
      JSON.stringify([t.bundle, values.scene, count ?? null, n, seed, values['warm-up']]),
    ],
    { encoding: 'utf8', maxBuffer: 1 << 28 },
  );
  const zone = Number(/^\s*totals\s+[\d.]+\s+\(\s*[\d.]+%\)\s+(\d+)/m.exec(out)?.[1] ?? 0);
  const perStep = new Map();
  let at = -1;
  for (const line of out.split('\n')) {
    const m = /^=== (?:step (\d+)|hash)/.exec(line);
    if (m) at = m[1] === undefined ? -1 : Number(m[1]);
    const c = /completed compiling .*?<JSFunction ([^ >]*).*?\(target TURBOFAN\)( OSR)?/.exec(line);
    if (c && at >= 0) perStep.set(at, [...(perStep.get(at) ?? []), c[1] + (c[2] ? ' (osr)' : '')]);
  }
  return { zone, perStep };
}

/** --compiles: TurboFan's zone memory in tree `t`'s steps (a run of them less one stopped before them) and what it compiled in each. */
function printCompiles(t) {
  const all = compileRun(t, steps),
    none = compileRun(t, 0);
  const mb = (all.zone - none.zone) / 1e6;
  console.log(`  compiles, ${t.name}: TurboFan zone memory in steps 0-${steps - 1}: ${mb.toFixed(1)} MB`);
  for (const [i, list] of all.perStep) console.log(`    step ${i}: ${list.join(', ')}`);
}

const temp = mkdtempSync(join(tmpdir(), 'bitphysics-first-steps-'));
const child = join(temp, 'child.mjs');
writeFileSync(child, CHILD);
const rev = positionals[0];
const base = rev === undefined ? null : checkOut(rev, temp, usage);
const trees = [];
try {
  if (base !== null) {
    await bundlePhysics(temp, base, 'rev');
    trees.push({ name: rev, bundle: join(temp, 'rev.mjs'), results: [], deopts: new Map() });
  }
  await bundlePhysics(temp, root, 'tree');
  trees.push({ name: 'working tree', bundle: join(temp, 'tree.mjs'), results: [], deopts: new Map() });

  for (let r = 0; r < runs; r++) {
    // Alternate which tree runs first, so both see the same load on average.
    for (const t of r % 2 === 0 ? trees : [...trees].reverse()) {
      const out = execFileSync(
        process.execPath,
        [
          ...nodeFlags,
          ...(values.deopts ? ['--trace-deopt-verbose'] : []),
          child,
          JSON.stringify([t.bundle, values.scene, count ?? null, steps, seed, values['warm-up']]),
        ],
        { encoding: 'utf8', maxBuffer: 1 << 28 },
      );
      const lines = out.trimEnd().split('\n');
      // The result is the last line holding '{"', but V8's verbose deopt trace may write the start of a
      // line before it, or a line of its own (marking dependent code) after it.
      const last = lines.findLast((line) => line.includes('{"')) ?? '';
      const result = JSON.parse(last.slice(Math.max(0, last.indexOf('{"'))));
      if (result.error) throw new Error(result.error);
      t.results.push(result);
      let at = -1,
        pending = null;
      const seen = new Set();
      for (const line of lines) {
        const m = /^=== (?:step (\d+)|hash)/.exec(line);
        if (m) at = m[1] === undefined ? -1 : Number(m[1]);
        // The position belongs to the bailout before; a trace line may be cut by the next one's start.
        const where = /;;; deoptimize at ([^[]*)/.exec(line);
        if (pending !== null && (where || line.startsWith('[bailout end'))) {
          seen.add(where ? `${pending} at ${deoptSite(t, where[1])}` : pending);
          pending = null;
        }
        const d = /bailout \(kind: [^,]*, reason: ([^)]*)\): begin\. deoptimizing (?:0x[0-9a-f]+ )?<JSFunction ([^ >]*)/.exec(line);
        if (d) pending = at >= 0 ? `step ${at}: ${d[2]} (${d[1]})` : null;
      }
      for (const k of seen) t.deopts.set(k, (t.deopts.get(k) ?? 0) + 1);
    }
  }

  const median = (x) => {
    const y = [...x].sort((p, q) => p - q);
    const h = y.length >> 1;
    return y.length % 2 === 1 ? y[h] : (y[h - 1] + y[h]) / 2;
  };
  const f = (x) => x.toFixed(1).padStart(7);
  const perStep = (t, key, i) => median(t.results.map((x) => x[key][i]));
  const sums = (t, key) => median(t.results.map((x) => x[key].reduce((p, q) => p + q, 0)));
  console.log(
    `${values.scene}${count === undefined ? '' : ` ${count}`}, steps 0-${steps - 1}, ${runs} fresh process${runs > 1 ? 'es' : ''} a tree, medians (ms):`,
  );
  const cur = trees.at(-1),
    old = rev === undefined ? null : trees[0];
  console.log(`  step     main      cpu     wall${old ? `  | ${rev}: main      cpu     wall   main ratio` : ''}`);
  const row = (label, a, b) => {
    let s = `  ${label.padEnd(6)}${f(a[0])}  ${f(a[1])}  ${f(a[2])}`;
    if (b) s += `  |       ${f(b[0])}  ${f(b[1])}  ${f(b[2])}   ${(a[0] / b[0]).toFixed(3).padStart(6)}`;
    console.log(s);
  };
  const keys = ['main', 'proc', 'wall'];
  for (let i = Number(show[1]); i < Number(show[2]); i++)
    row(
      String(i),
      keys.map((k) => perStep(cur, k, i)),
      old && keys.map((k) => perStep(old, k, i)),
    );
  row(
    'sum',
    keys.map((k) => sums(cur, k)),
    old && keys.map((k) => sums(old, k)),
  );
  const worsts = (t) => keys.map((k) => median(t.results.map((x) => Math.max(...x[k]))));
  row('worst', worsts(cur), old && worsts(old));
  if (values['warm-up']) {
    const warmUps = (t) => [0, 1, 2].map((k) => median(t.results.map((x) => x.warmUp[k])));
    row('warmUp', warmUps(cur), old && warmUps(old));
  }
  if (old) {
    const [ha, hb] = [old, cur].map((t) => new Set(t.results.map((x) => x.hash)));
    const same = ha.size === 1 && hb.size === 1 && [...ha][0] === [...hb][0];
    console.log(`  state hashes after ${steps} steps: ${[...ha].join(',')} ${[...hb].join(',')} (${same ? 'equal' : 'different'})`);
  }
  if (values.deopts)
    for (const t of trees) {
      console.log(`  deopts, ${t.name} (runs in which each happened, of ${runs}):`);
      const list = [...t.deopts].sort((a, b) => Number(/\d+/.exec(a[0])[0]) - Number(/\d+/.exec(b[0])[0]));
      if (list.length === 0) console.log('    none');
      for (const [k, n] of list) console.log(`    ${n} ${k}`);
    }
  if (values.compiles) for (const t of trees) printCompiles(t);
} finally {
  if (base !== null) removeCheckout(base);
  rmSync(temp, { recursive: true, force: true });
}
