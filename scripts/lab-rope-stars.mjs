// `node scripts/lab-rope-stars.mjs [--wide] [--engine] [level ...]`: the rope lab's star windows,
// headless. For each level (1-based; default all, of LEVELS or with --wide of WIDE_LEVELS) and its
// plan (games/lab-rope/plans.ts), the widest window of times for the last cut that lands in the
// basket, that catches each star, and that catches all three (by predictFlight from the swing, one
// run of the engine a level); with --engine also each last cut played in the engine, every 0.02 s
// over the plan's times (its stars, or '.' for a miss), and the widest 3-star window (slow: a
// minute or more a level).
import { importSource } from './build.mjs';

const rope = await importSource('lab-rope-stars', "export * from './games/lab-rope/plans.ts';");
const wide = process.argv.includes('--wide');
const engine = process.argv.includes('--engine');
const set = wide ? rope.WIDE_LEVELS : rope.LEVELS;
const picked = process.argv
  .slice(2)
  .filter((a) => !a.startsWith('--'))
  .map(Number);
const fmt = (w) => (w ? `${w[0].toFixed(2)}-${w[1].toFixed(2)} s (${(w[1] - w[0]).toFixed(2)} s)` : 'never');
for (const n of picked.length ? picked : set.map((_, i) => i + 1)) {
  const f = rope.forecastCuts(set, n - 1);
  const won = rope.widestRun(f, (c) => c.lands);
  const each = set[n - 1].stars.map((_, i) => rope.widestRun(f, (c) => c.lands && c.stars[i]));
  const three = rope.widestRun(f, (c) => c.lands && c.stars.every(Boolean));
  console.log(`${wide ? 'wide' : 'upright'} level ${n} (${set[n - 1].name}): lands ${fmt(won)}; 3 stars ${fmt(three)}`);
  for (const [i, w] of each.entries()) console.log(`  star ${i + 1}: ${fmt(w)}`);
  if (engine) {
    const plan = rope.plansOf(set)[n - 1];
    let line = '',
      run = [];
    let best = null;
    for (let t = plan.from; t <= plan.to + 1e-9; t += 0.02) {
      const r = rope.playPlan(set, n - 1, t);
      const ok = r.outcome === 'won' && r.stars === 3;
      line += r.outcome === 'won' ? String(r.stars) : '.';
      if (ok) run.push(t);
      else run = [];
      if (run.length && (!best || run.at(-1) - run[0] > best[1] - best[0])) best = [run[0], run.at(-1)];
    }
    console.log(`  engine from ${plan.from} s every 0.02 s: ${line}`);
    console.log(`  engine 3 stars: ${fmt(best)}`);
  }
}
