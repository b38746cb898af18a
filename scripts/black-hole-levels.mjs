// `node scripts/black-hole-levels.mjs [--levels 1-10] [--seeds 8] [--fields 32x24,20x30] [--tables held,pilot,simple]
// [--source games/black-hole]`: what black hole's levels ask of a player, level by level, on each field (the desktop's
// 32 x 24 m and the upright phone's 20 x 30 m by default). Three tables:
// - held: every arrow and every pair of arrows at right angles held from the start, never changed
//   (up, the four diagonals, left, right, down), on every seed, until the line, a fall, an exit or
//   20 s: how many of these clear (a level that needs no steering shows a count above 0);
// - pilot: two steering pilots. Every `react` s each keeps the first of (thrust towards the wall's
//   gap while under it,) up, left, right, down and none whose predicted path for `look` s stays clear
//   of the horizons and in the field (games/black-hole/rules.ts predictPath, the path the page
//   draws), for at most 60 s of game time with unlimited lives. The sharp one reacts every 0.1 s and
//   looks 1.5 s ahead; the stranger every 0.25 s and 1 s ahead. Per level: seeds cleared, mean and
//   longest time to the line, falls a level (the difficulty curve). The tapper is a newcomer on a
//   phone: it chooses the same way every 0.4 s looking 1 s ahead, but only taps (thrusts for 0.15 s,
//   then lets go until its next choice);
// - simple: a sideways nudge of 0 to 2.4 s, then up: the share of such tries that clear.
// The game runs at its 60 Hz step, so game time is what a player's clock shows. `--source` plays
// another copy of the game's levels.ts and rules.ts (a folder inside the repository, e.g. an older
// version checked out under node_modules/, to print the tables before a change).
import { importSource } from './build.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : fallback;
};
const source = arg('--source', 'games/black-hole').replace(/\/$/, '');
const m = await importSource(
  'black-hole-levels',
  `export * from './${source}/levels.ts'; export * from './${source}/rules.ts'; export { slotOf } from '@bitphysics/physics';`,
);
const [lo, hi] = arg('--levels', '1-10').split('-').map(Number);
const seeds = Number(arg('--seeds', '8'));
const fields = arg('--fields', '32x24,20x30')
  .split(',')
  .map((f) => f.split('x').map(Number));
const tables = arg('--tables', 'held,pilot').split(',');
if (!(lo >= 1 && hi >= lo && seeds >= 1 && fields.every(([w, h]) => w > 0 && h > 0)))
  throw new RangeError('black-hole-levels: --levels a-b (1 <= a <= b), --seeds n >= 1, --fields WxH,WxH');

/** Every thrust an arrow or two arrows at right angles give. */
const HELD = ['up', 'up-left', 'up-right', 'left', 'right', 'down', 'down-left', 'down-right'];

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

/** A new game of `seed` on a `width` x `height` field with level `level` laid out; unlimited lives. */
function newLevel(level, seed, width, height) {
  // The page gives a narrow field (a phone's) its gentler sideways engine.
  const g = m.createBlackHoleGame({
    seed,
    field: { width, height },
    lives: 9,
    ...(width < m.FIELD.width ? { sideRamp: m.PHONE_SIDE_RAMP } : {}),
  });
  const run = m.startLevel(g, level);
  return { g, run };
}

/** Holds `thrust` from the start: whether it reaches the line (before a fall, an exit or 20 s). */
function held(level, seed, width, height, thrust) {
  const { g, run } = newLevel(level, seed, width, height);
  m.setThrust(g, thrust);
  for (let k = 0; k < 20 / g.world.dt; k++) {
    const e = m.stepLevel(g, run);
    if (e === 'cleared') return true;
    if (e !== 'none') return false;
  }
  return false;
}

/**
 * Plays level `level` of seed `seed` with a pilot that chooses every `react` s looking `look` s ahead
 * (see the file's comment). Lives never run out (a fall counts and the ship starts again).
 */
function play(level, seed, width, height, react, look, tap = Infinity) {
  const { g, run } = newLevel(level, seed, width, height);
  const pred = m.createPredictor(g);
  const ahead = Math.round(look / g.world.dt),
    every = Math.max(1, Math.round(react / g.world.dt));
  const path = new Float64Array(2 * (ahead + 1));
  const gap = run.spec.gate > 0 ? wallGap(g) : null;
  const P = g.world.components.Position,
    V = g.world.components.Velocity;
  const steps = Math.round(60 / g.world.dt),
    tapSteps = Math.round(tap / g.world.dt);
  for (let k = 0; k < steps; k++) {
    let want = k % every >= tapSteps ? 'none' : g.thrust;
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
    if (g.lives < 3) g.lives = 9;
  }
  return { time: Number.NaN, falls: g.falls };
}

/**
 * A stranger's simple tries: thrust sideways (towards the wall's gap, or on a level without one
 * either way) for 0, 0.2, ..., 2.4 s, then up until the line, a fall or 12 s.
 * @returns the fraction of the tries that clear, and their mean time, s.
 */
function simpleTries(level, seed, width, height) {
  const first = newLevel(level, seed, width, height);
  const sides = first.run.spec.gate > 0 ? [wallGap(first.g).x < first.g.start[0] ? 'left' : 'right'] : ['left', 'right'];
  let cleared = 0,
    tries = 0,
    time = 0;
  for (const side of sides)
    for (let nudge = 0; nudge <= 2.4 + 1e-9; nudge += 0.2) {
      const { g, run } = newLevel(level, seed, width, height);
      let e = 'none';
      for (let k = 0; k < 12 / g.world.dt && e === 'none'; k++) {
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

const levels = Array.from({ length: hi - lo + 1 }, (_, i) => lo + i);
const seedList = Array.from({ length: seeds }, (_, i) => i + 1);
for (const [width, height] of fields) {
  console.log(`field ${width} x ${height} m, seeds 1-${seeds}:`);
  if (tables.includes('held')) {
    console.log('  held (an arrow or two at right angles held from the start, never changed): clears / tries');
    for (const level of levels) {
      const wins = {};
      let n = 0;
      for (const seed of seedList)
        for (const t of HELD) {
          if (held(level, seed, width, height, t)) wins[t] = (wins[t] ?? 0) + 1;
          n++;
        }
      const total = Object.values(wins).reduce((a, b) => a + b, 0);
      const which = Object.entries(wins)
        .map(([t, k]) => `${t} ${k}`)
        .join(', ');
      console.log(`    level ${level}: ${total}/${n}${which ? ` (${which})` : ''}`);
    }
  }
  if (tables.includes('pilot')) {
    for (const [name, react, look, tap] of [
      ['sharp pilot (0.1 s, 1.5 s ahead)', 0.1, 1.5],
      ['stranger pilot (0.25 s, 1 s ahead)', 0.25, 1],
      ['tapper (0.15 s taps every 0.4 s, 1 s ahead)', 0.4, 1, 0.15],
    ]) {
      console.log(`  ${name}:`);
      for (const level of levels) {
        const rs = seedList.map((seed) => play(level, seed, width, height, react, look, tap));
        const ok = rs.filter((r) => Number.isFinite(r.time));
        const mean = ok.reduce((a, r) => a + r.time, 0) / Math.max(1, ok.length);
        const longest = Math.max(0, ...ok.map((r) => r.time));
        const falls = rs.reduce((a, r) => a + r.falls, 0) / seeds;
        const failed = rs.flatMap((r, i) => (Number.isFinite(r.time) ? [] : [seedList[i]]));
        console.log(
          `    level ${level}: cleared ${ok.length}/${seeds}${failed.length ? ` (not seeds ${failed.join(' ')})` : ''}, ` +
            `time mean ${mean.toFixed(1)} s, longest ${longest.toFixed(1)} s, falls ${falls.toFixed(2)} a level`,
        );
      }
    }
  }
  if (tables.includes('simple')) {
    console.log('  simple tries (sideways for 0 to 2.4 s, then up):');
    for (const level of levels) {
      const rs = seedList.map((seed) => simpleTries(level, seed, width, height));
      const f = rs.reduce((a, r) => a + r.fraction, 0) / seeds;
      const ok = rs.filter((r) => Number.isFinite(r.time));
      console.log(
        `    level ${level}: ${(100 * f).toFixed(0)} % of tries clear, in ${(ok.reduce((a, r) => a + r.time, 0) / Math.max(1, ok.length)).toFixed(1)} s`,
      );
    }
  }
}
