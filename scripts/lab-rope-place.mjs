// `node scripts/lab-rope-place.mjs [--wide] [--min=0.5] [--margin=0.08] [--spread=0.9] level [from to]`: a place for the three stars of a rope
// lab level (1-based, of LEVELS or with --wide of WIDE_LEVELS) that its plan (games/lab-rope/plans.ts)
// earns over as wide a window of last cuts as can be had. Plays the last cut every 0.04 s from
// `from` to `to` s (default the plan's times) in the engine and records each winning flight; then
// looks over a 0.1 m grid for points that every flight of a run of winning cuts passes within
// STAR_REACH less --margin m of (a margin for a changed step), that the swing left untouched for 8 s
// keeps 15 cm clear of, and that lie in the room below the banner; and prints, of the runs of cuts
// --min s wide (0.5 s by default), the one with three such points farthest apart (at least --spread m). A design aid, slow (a
// minute a level).
import { importSource } from './build.mjs';

const rope = await importSource(
  'lab-rope-place',
  "export * from './games/lab-rope/plans.ts'; export * from './games/lab-rope/scene.ts'; export { slotOf, step } from '@bitphysics/physics';",
);
const wide = process.argv.includes('--wide');
const args = process.argv
  .slice(2)
  .filter((a) => !a.startsWith('--'))
  .map(Number);
const set = wide ? rope.WIDE_LEVELS : rope.LEVELS;
const index = args[0] - 1;
const plan = rope.plansOf(set)[index];
const level = set[index];
const from = args[1] ?? plan.from,
  to = args[2] ?? plan.to;
const option = (name, fallback) => Number(process.argv.find((a) => a.startsWith(`--${name}=`))?.split('=')[1] ?? fallback);
const DT = 0.04,
  MARGIN = option('margin', 0.08),
  SPREAD = option('spread', 0.9);

/** The ball's path (x, y pairs) played with the plan's earlier cuts and the last at `t` (null: never), and the outcome. */
function trace(t) {
  const s = rope.createRopeScene(index, rope.DEFAULTS, set);
  const g = new rope.RopeGame(s);
  const e = rope.slotOf(s.ball);
  const P = s.world.components.Position;
  if (plan.push && t !== null) s.world.components.Velocity.x[e] = plan.push;
  const cuts = t === null ? [] : [...plan.before.map(([time, r]) => [time, r]), [t, plan.last]].sort((a, b) => a[0] - b[0]);
  const path = [];
  let k = 0;
  for (let i = 0; i < 60 * (t === null ? 8 : 14) && g.outcome === 'playing'; i++) {
    while (k < cuts.length && s.world.time >= cuts[k][0]) rope.cutAlong(s, cuts[k++][1]);
    rope.step(s.world);
    g.update();
    path.push(P.x[e], P.y[e]);
  }
  return { path, won: g.outcome === 'won' };
}
const idle = trace(null).path;
const times = [];
for (let t = from; t <= to + 1e-9; t += DT) times.push(Number(t.toFixed(3)));
const flights = times.map((t) => trace(t));
console.log(times.map((t, i) => `${t}${flights[i].won ? '+' : '.'}`).join(' '));
const room = rope.roomHalfWidth(level);
const near = (path, x, y, r) => {
  for (let i = 0; i < path.length; i += 2) if (Math.hypot(path[i] - x, path[i + 1] - y) < r) return true;
  return false;
};
const inBlock = (x, y) =>
  (level.blocks ?? []).some((b) => Math.abs(x - b.at[0]) < b.half[0] + 0.3 && Math.abs(y - b.at[1]) < b.half[1] + 0.3) ||
  (Math.abs(x - level.basket[0]) < level.basketWidth / 2 + 0.4 && y < level.basket[1] + level.basketDepth + 0.6);
const points = [];
for (let x = -room + 0.35; x <= room - 0.35; x += 0.1)
  for (let y = 0.9; y <= level.view.maxY - 2.0; y += 0.1) {
    if (inBlock(x, y) || near(idle, x, y, rope.STAR_REACH + 0.15)) continue;
    const cover = flights.map((f) => f.won && near(f.path, x, y, rope.STAR_REACH - MARGIN));
    if (cover.some(Boolean)) points.push({ x, y, cover });
  }
const minWidth = option('min', 0.5);
const span = Math.round(minWidth / DT);
let best = null;
for (let i = 0; i + span < times.length; i++) {
  const j = i + span;
  const ok = points.filter((p) => p.cover.slice(i, j + 1).every(Boolean));
  let pick = null,
    spread = best ? best.spread : SPREAD;
  for (let a = 0; a < ok.length; a++)
    for (let b = a + 1; b < ok.length; b++) {
      const dab = Math.hypot(ok[a].x - ok[b].x, ok[a].y - ok[b].y);
      if (dab <= spread) continue;
      for (let c = b + 1; c < ok.length; c++) {
        const m = Math.min(dab, Math.hypot(ok[a].x - ok[c].x, ok[a].y - ok[c].y), Math.hypot(ok[b].x - ok[c].x, ok[b].y - ok[c].y));
        if (m > spread) {
          spread = m;
          pick = [ok[a], ok[b], ok[c]];
        }
      }
    }
  if (pick) best = { w: times[j] - times[i], from: times[i], to: times[j], pick, spread, n: ok.length };
}
if (!best) console.log('no three stars found');
else
  console.log(
    `3 stars for cuts ${best.from}-${best.to} s (${best.w.toFixed(2)} s), ${best.n} points, ${best.spread.toFixed(2)} m apart:`,
    JSON.stringify(best.pick.sort((p, q) => q.y - p.y).map((p) => [Number(p.x.toFixed(2)), Number(p.y.toFixed(2))])),
  );
