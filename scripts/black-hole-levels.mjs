// `node scripts/black-hole-levels.mjs [--levels 1-6] [--seeds 12] [--field 32x24] [--react 0.1] [--look 1.5] [--simple]`: how long black
// hole's levels take. For each level and seed, a steering pilot (every 0.1 s it keeps the first of
// thrust towards the wall's gap while under it, up, left, right, down and none whose predicted 1.5 s
// path stays clear of the horizons and in the field: games/black-hole/rules.ts predictPath, the path
// the page draws) plays the level for at most 60 s of game time, and a pilot that sees no wall (it
// flies up and dodges, as a stranger does on a first try) plays it too. Prints, per level, the mean
// and the longest game time to the line, the falls, and the levels not cleared. The game runs at
// its 60 Hz step, so game time is what a player's clock shows.
import { importSource } from './build.mjs';

const m = await importSource(
  'black-hole-levels',
  "export * from './games/black-hole/levels.ts'; export * from './games/black-hole/rules.ts'; export { slotOf } from '@bitphysics/physics';",
);
const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : fallback;
};
const [lo, hi] = arg('--levels', '1-6').split('-').map(Number);
const seeds = Number(arg('--seeds', '12'));
const [width, height] = arg('--field', '32x24').split('x').map(Number);
/** The pilot's reaction time (how often it chooses, s) and how far ahead it looks (the drawn path is 1 s), s. */
const react = Number(arg('--react', '0.1')),
  look = Number(arg('--look', '1.5'));
if (!(lo >= 1 && hi >= lo && seeds >= 1 && width > 0 && height > 0))
  throw new RangeError('black-hole-levels: --levels a-b (1 <= a <= b), --seeds n >= 1, --field WxH');

/** The widest clear stretch of the lowest row of holes (a wall's gap): its centre x and the row's height, m. */
function wallGap(g) {
  const P = g.world.components.Position;
  const hs = g.holes.map((h, i) => ({ x: P.x[m.slotOf(h)], y: P.y[m.slotOf(h)], r: g.holeRadius[i] }));
  const y = Math.min(...hs.map((h) => h.y));
  const row = hs.filter((h) => h.y < y + 1).sort((a, b) => a.x - b.x);
  let best = [0, 0],
    at = 0;
  for (const h of [...row, { x: g.field.width, r: 0 }]) {
    if (h.x - h.r - at > best[1] - best[0]) best = [at, h.x - h.r];
    at = h.x + h.r;
  }
  return { x: (best[0] + best[1]) / 2, y };
}

/** Plays level `level` of seed `seed` with the pilot (`eyes`: it steers for the wall's gap). */
function play(level, seed, eyes) {
  const g = m.createBlackHoleGame({ seed, field: { width, height } });
  const run = m.startLevel(g, level);
  const pred = m.createPredictor(g);
  const ahead = Math.round(look / g.world.dt),
    every = Math.max(1, Math.round(react / g.world.dt));
  const path = new Float64Array(2 * (ahead + 1));
  const gap = eyes && run.spec.gate > 0 ? wallGap(g) : null;
  const P = g.world.components.Position,
    V = g.world.components.Velocity;
  const steps = Math.round(60 / g.world.dt);
  for (let k = 0; k < steps; k++) {
    let want = g.thrust;
    if (k % every === 0 && m.canThrust(g, run)) {
      want = 'none';
      let first = 'up';
      const s = m.slotOf(g.ship);
      if (gap && P.y[s] < gap.y) {
        const ax = 2 * (gap.x - P.x[s]) - 2.5 * V.x[s];
        if (Math.abs(ax) > 1.5) first = ax > 0 ? 'right' : 'left';
      }
      for (const t of [first, 'up', 'left', 'right', 'down', 'none']) {
        m.setThrust(g, t);
        const n = m.predictPath(g, pred, path, ahead);
        const x = path[2 * n - 2],
          y = path[2 * n - 1];
        if (x < 0 || x > g.field.width || y < 0) continue;
        if (n === ahead + 1 || y > g.field.height) {
          want = t;
          break;
        }
      }
    }
    if (!m.canThrust(g, run)) want = 'none';
    if (g.thrust !== want) m.setThrust(g, want);
    const e = m.stepLevel(g, run);
    if (e === 'cleared') return { time: run.summary.totalTime, falls: run.summary.falls };
    if (e === 'over') break;
  }
  return { time: Number.NaN, falls: g.falls };
}

/**
 * A stranger's simple tries at level `level`, seed `seed`: thrust sideways (towards the wall's gap, or
 * on a level without one either way) for `nudge` s, then up until the line, a fall or 12 s.
 * @returns the fraction of the nudges 0, 0.2, ..., 2.4 s that clear, and their mean time, s.
 */
function simpleTries(level, seed) {
  const g0 = m.createBlackHoleGame({ seed, field: { width, height } });
  const run0 = m.startLevel(g0, level);
  const sides = run0.spec.gate > 0 ? [wallGap(g0).x < g0.start[0] ? 'left' : 'right'] : ['left', 'right'];
  let cleared = 0,
    tries = 0,
    time = 0;
  for (const side of sides)
    for (let nudge = 0; nudge <= 2.4 + 1e-9; nudge += 0.2) {
      const g = m.createBlackHoleGame({ seed, field: { width, height } });
      const run = m.startLevel(g, level);
      let e = '';
      for (let k = 0; k < 12 / g.world.dt && e !== 'cleared' && e !== 'fell' && e !== 'lost' && e !== 'over'; k++) {
        const want = k * g.world.dt < nudge ? side : 'up';
        if (g.thrust !== want) m.setThrust(g, want);
        e = m.stepLevel(g, run);
      }
      tries++;
      if (e === 'cleared') {
        cleared++;
        time += run.summary.time;
      }
    }
  return { fraction: cleared / tries, time: cleared ? time / cleared : Number.NaN };
}

console.log('simple tries (sideways for 0 to 2.4 s, then up):');
for (let level = lo; level <= hi; level++) {
  const rs = Array.from({ length: seeds }, (_, i) => simpleTries(level, i + 1));
  const f = rs.reduce((a, r) => a + r.fraction, 0) / seeds;
  const ok = rs.filter((r) => Number.isFinite(r.time));
  console.log(
    `  level ${level}: ${(100 * f).toFixed(0)} % of tries clear (about ${(1 / Math.max(f, 1e-9)).toFixed(1)} tries a clear), in ${(ok.reduce((a, r) => a + r.time, 0) / Math.max(1, ok.length)).toFixed(1)} s`,
  );
}
if (process.argv.includes('--simple')) process.exit(0);
for (const eyes of [true, false]) {
  console.log(eyes ? 'pilot that steers for the gap:' : 'pilot that flies up and dodges (no eyes for the gap):');
  for (let level = lo; level <= hi; level++) {
    const rs = Array.from({ length: seeds }, (_, i) => play(level, i + 1, eyes));
    const ok = rs.filter((r) => Number.isFinite(r.time));
    const mean = ok.reduce((a, r) => a + r.time, 0) / Math.max(1, ok.length);
    const longest = Math.max(0, ...ok.map((r) => r.time));
    const falls = rs.reduce((a, r) => a + r.falls, 0) / seeds;
    console.log(
      `  level ${level}: cleared ${ok.length}/${seeds}, time mean ${mean.toFixed(1)} s, longest ${longest.toFixed(1)} s, falls ${falls.toFixed(2)} a level`,
    );
  }
}
