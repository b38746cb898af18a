// In-process A/B of the physics package at two revisions: `node scripts/ab.mjs <rev> [flags]`.
//
// The bench's ratios move by up to 10 % from run to run on a shared machine, more than most changes
// to a step's speed; two worlds stepped in turn in one process, one built from the working tree and
// one from <rev> (a git revision, checked out into a temporary worktree), see the same load, step for
// step. Both worlds build the same scene with the same seed; the script prints, for a window of steps,
// the mean and median step time of each and the median of the per-step ratios (working tree / rev),
// and whether the two states' hashes (stateHash) are equal at the end, so a change meant to keep the
// results shows it did. A threaded world's workers spin for a while after each of its steps, so the
// worlds alternate which steps first.
//
// Flags: --scene (default balls-in-box), --count (scene default), --threads (default 1), --steps
// (default 330), --window a-b (default 150-250), --seed (default 1), --clock wall|cpu (default wall).
// Exit code 2 on a usage error.
//
// --clock cpu times each step by the process's CPU time (process.cpuUsage, user + system) instead of
// the wall clock: a step that waits while another process holds the core is not charged for the
// wait, so on a loaded machine its ratios are much steadier. It also counts the process's other
// threads while the step runs (V8's background compiler and garbage collector, and a threaded world's
// workers), so it measures work done, not latency.

import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { root } from './build.mjs';
import { bundlePhysics } from './physics-bundle.mjs';
import { checkOut, removeCheckout, scriptCli } from './script-cli.mjs';

/** A bad flag found only once the packages are built (an unknown scene): reported as a usage error. */
class UsageError extends Error {}

const { values, positionals, usage, integer } = scriptCli(
  'ab',
  'node scripts/ab.mjs <rev> [--scene balls-in-box] [--count n] [--threads n] [--steps n] [--window a-b] [--seed n] [--clock wall|cpu]',
  {
    scene: { type: 'string', default: 'balls-in-box' },
    count: { type: 'string' },
    threads: { type: 'string', default: '1' },
    steps: { type: 'string', default: '330' },
    window: { type: 'string', default: '150-250' },
    seed: { type: 'string', default: '1' },
    clock: { type: 'string', default: 'wall' },
  },
);
if (positionals.length !== 1) usage('give one git revision to compare the working tree with');
const threads = integer('threads', values.threads, 1),
  steps = integer('steps', values.steps, 1),
  seed = integer('seed', values.seed, 0);
const count = values.count === undefined ? undefined : integer('count', values.count, 1);
const win = /^(\d+)-(\d+)$/.exec(values.window);
if (!win || Number(win[1]) >= Number(win[2]) || Number(win[2]) > steps)
  usage(`--window must be a-b with a < b <= steps, got ${values.window}`);
const [w0, w1] = [Number(win[1]), Number(win[2])];
if (values.clock !== 'wall' && values.clock !== 'cpu') usage(`--clock must be wall or cpu, got ${values.clock}`);
/** Now, ms, on the chosen clock: wall time, or the process's CPU time (user + system). */
const now =
  values.clock === 'cpu'
    ? () => {
        const u = process.cpuUsage();
        return (u.user + u.system) / 1000;
      }
    : () => performance.now();

const rev = positionals[0];
const temp = mkdtempSync(join(tmpdir(), 'bitphysics-ab-'));
const base = checkOut(rev, temp, usage);
try {
  const A = await bundlePhysics(temp, base, 'rev'),
    B = await bundlePhysics(temp, root, 'tree');
  const make = (M) => {
    const scene = M.SCENES[values.scene];
    if (!scene) throw new UsageError(`unknown scene ${values.scene} (scenes: ${Object.keys(M.SCENES).join(', ')})`);
    const options = count === undefined ? { seed } : { count, seed };
    // Revisions since enableThreads need it for threads > 1; older ones have none.
    if (threads > 1) M.enableThreads?.();
    const w = M.createPhysicsWorld({ ...scene.worldOptions(options), seed, ...(threads > 1 ? { threads } : {}) });
    scene.build(w, options);
    return w;
  };
  const worlds = [
    [A, make(A), []],
    [B, make(B), []],
  ];
  if (threads > 1) for (const [M, w] of worlds) await M.threadsReady(w);
  for (let s = 0; s < steps; s++) {
    for (const [M, w, times] of s % 2 === 0 ? worlds : [...worlds].reverse()) {
      const t0 = now();
      M.step(w);
      times.push(now() - t0);
    }
  }
  const [[, wa, ta], [, wb, tb]] = worlds;
  const median = (x) => {
    const y = [...x].sort((p, q) => p - q);
    return y[y.length >> 1];
  };
  const mean = (x) => x.reduce((p, q) => p + q, 0) / x.length;
  const a = ta.slice(w0, w1),
    b = tb.slice(w0, w1),
    ratios = b.map((t, i) => t / a[i]);
  const f = (x) => x.toFixed(2);
  console.log(
    `${values.scene}${count === undefined ? '' : ` ${count}`}, threads ${threads}, steps ${w0}-${w1} of ${steps}, ${values.clock} clock:`,
  );
  console.log(`  ${rev}: mean ${f(mean(a))} ms, median ${f(median(a))} ms`);
  console.log(`  working tree: mean ${f(mean(b))} ms, median ${f(median(b))} ms`);
  console.log(`  working tree / ${rev}: mean ${(mean(b) / mean(a)).toFixed(3)}, median of the steps' ratios ${median(ratios).toFixed(3)}`);
  const ha = A.stateHash(wa),
    hb = B.stateHash(wb);
  console.log(`  state hashes after ${steps} steps: ${ha} ${hb} (${ha === hb ? 'equal' : 'different'})`);
  A.disposeWorld(wa);
  B.disposeWorld(wb);
} catch (e) {
  if (!(e instanceof UsageError)) throw e;
  console.error(`ab: ${e.message}`);
  process.exitCode = 2;
} finally {
  removeCheckout(base);
  rmSync(temp, { recursive: true, force: true });
}
