// `node scripts/lab-rope-cuts.mjs [--wide] [level ...]`: how the rope lab's levels (1-based; default
// all, of LEVELS or with --wide of WIDE_LEVELS) answer the time and the place of their last cut,
// headless. For each level the earlier cuts are made at fixed times at their ropes' middles, and the
// last cut is swept over a range of times, made at a tenth, half and nine tenths of the way down its
// rope (a swipe may cross it anywhere). Prints, per place, one character a time: the stars won
// (0-3), '.' lost, '?' undecided after 14 s; then the windows won at the middle place (and their
// width in all, each time won counting its step), the share of
// times at which the three places agree on win or loss, and the times won or lost unlike both their
// neighbours (a lottery for the player); last, each level's window width in one table. Takes a
// minute or two a level.
import { importSource } from './build.mjs';

const rope = await importSource(
  'lab-rope-cuts',
  "export * from './games/lab-rope/scene.ts'; export { PLANS, WIDE_PLANS } from './games/lab-rope/plans.ts'; export { slotOf, step } from '@bitphysics/physics';",
);
const wide = process.argv.includes('--wide');
const levels = process.argv
  .slice(2)
  .filter((a) => !a.startsWith('--'))
  .map(Number);
for (const n of levels)
  if (!(Number.isInteger(n) && n >= 1 && n <= rope.LEVELS.length))
    throw new RangeError(`lab-rope-cuts: levels are integers 1-${rope.LEVELS.length}, got ${n}`);

/** Per level: its plan (games/lab-rope/plans.ts), the last cut swept every 0.04 s (0.02 s on upright level 1). */
const PLANS = (wide ? rope.WIDE_PLANS : rope.PLANS).map((p, i) => ({
  before: p.before,
  last: p.last,
  times: [p.from, p.to, !wide && i === 0 ? 0.02 : 0.04],
  push: p.push ?? 0,
}));
const PLACES = [0.1, 0.5, 0.9];
const set = wide ? rope.WIDE_LEVELS : rope.LEVELS;

/** Plays level `index` with the plan's earlier cuts and the last at `t` s, `place` of the way down its rope: '0'-'3', '.' or '?'. */
function play(index, plan, t, place) {
  const s = rope.createRopeScene(index, rope.DEFAULTS, set);
  const g = new rope.RopeGame(s);
  if (plan.push) s.world.components.Velocity.x[rope.slotOf(s.ball)] = plan.push;
  const cuts = [...plan.before.map(([time, r]) => [time, r, 0.5]), [t, plan.last, place]].sort((a, b) => a[0] - b[0]);
  let k = 0;
  for (let i = 0; i < 60 * 14 && g.outcome === 'playing'; i++) {
    while (k < cuts.length && s.world.time >= cuts[k][0]) {
      const [, r, at] = cuts[k++];
      const links = s.ropes[r].links;
      rope.cutRope(s.world, s.ropes[r], links[Math.min(links.length - 1, Math.floor(at * links.length))]);
    }
    rope.step(s.world);
    g.update();
  }
  return g.outcome === 'won' ? String(g.stars()) : g.outcome === 'lost' ? '.' : '?';
}

/** Per level measured: its number, the windows won at the middle place and their width in all, s. */
const summary = [];
for (const n of levels.length ? levels : set.map((_, i) => i + 1)) {
  const plan = PLANS[n - 1];
  const [from, to, dt] = plan.times;
  const times = [];
  for (let t = from; t <= to + 1e-9; t += dt) times.push(Number(t.toFixed(3)));
  const rows = PLACES.map((place) => times.map((t) => play(n - 1, plan, t, place)).join(''));
  console.log(
    `${wide ? 'wide ' : ''}level ${n} (${set[n - 1].name}), last cut at ${from}-${to} s every ${dt} s${plan.push ? `, pushed ${plan.push} m/s` : ''}:`,
  );
  for (const [i, place] of PLACES.entries()) console.log(`  at ${place} of its rope: ${rows[i]}`);
  const won = (c) => c >= '0' && c <= '3';
  const windows = [];
  let width = 0;
  let open = -1;
  rows[1].split('').forEach((c, i) => {
    if (won(c) && open < 0) open = i;
    if ((!won(c) || i === times.length - 1) && open >= 0) {
      const end = won(c) ? i : i - 1;
      windows.push(`${times[open]}-${times[end]} s`);
      width += times[end] - times[open] + dt;
      open = -1;
    }
  });
  const agree = times.filter((_, i) => new Set(rows.map((r) => won(r[i]))).size === 1).length;
  let lone = 0;
  for (const r of rows) for (let i = 1; i + 1 < r.length; i++) if (won(r[i]) !== won(r[i - 1]) && won(r[i]) !== won(r[i + 1])) lone++;
  summary.push({ n, windows, width });
  console.log(
    `  won (middle place) ${windows.join(', ') || 'never'} (${width.toFixed(2)} s in all); places agree at ${agree} of ${times.length} times (${Math.round((100 * agree) / times.length)} %); lone outcomes ${lone}`,
  );
}
console.log(`${wide ? 'wide' : 'upright'} room, the last cut's window at the middle place:`);
for (const { n, windows, width } of summary)
  console.log(`  level ${n} (${set[n - 1].name}): ${width.toFixed(2)} s (${windows.join(', ') || 'never'})`);
