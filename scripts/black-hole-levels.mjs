// `node scripts/black-hole-levels.mjs [--levels 1-10] [--seeds 8] [--fields 32x24,20x30] [--tables held,pilot,route,simple,twophase] [--pilots TEXT]
// [--source games/black-hole]`: what black hole's levels ask of a player, level by level, on each field (the desktop's
// 32 x 24 m and the upright phone's 20 x 30 m by default). Five tables:
// - held: every arrow and every pair of arrows at right angles held from the start, never changed
//   (up, the four diagonals, left, right, down), on every seed, until the line, a fall, an exit or
//   20 s: how many of these clear (a level that needs no steering shows a count above 0);
// - pilot: two steering pilots. Every `react` s each keeps the first of (thrust towards the wall's
//   gap while under it,) up, left, right, down and none whose predicted path for `look` s stays clear
//   of the horizons and in the field (games/black-hole/rules.ts predictPath, the path the page
//   draws), for at most 60 s of game time with unlimited lives. The sharp one reacts every 0.1 s and
//   looks 1.5 s ahead; while a ring is left (levels.ts `LevelSpec.rings`) each first tries the thrust towards it; the stranger every 0.25 s and 1 s ahead. Per level: seeds cleared, mean and
//   longest time to the line, falls a level (the difficulty curve). The tapper is a newcomer on a
//   phone: it chooses the same way every 0.4 s looking 1 s ahead, but only taps (thrusts for 0.15 s,
//   then lets go until its next choice);
//   `--pilots TEXT` keeps the pilots (of both tables) whose name holds TEXT. The newcomers choose
//   the same way but act 0.3 or 0.5 s late (a player's reaction); a fall or an exit lets go of the
//   arrows (as the page does). Each pilot's line ends with the share of its tries that cleared;
// - route: newcomers who fly by eye, not by the predicted path (`flyRoute`): a route kept some horizon
//   radii clear of every hole, followed with a reaction lag; per level the seeds cleared, the falls
//   and the share of tries that cleared (the difficulty curve as a newcomer meets it);
// - simple: a sideways nudge of 0 to 2.4 s, then up: the share of such tries that clear;
// - twophase: blind two-phase inputs flown by the layout check's flight (levels.ts `phasedFlight`):
//   ↑ with ← or → for TWO_PHASE_FIRST s, then ↑ alone TWO_PHASE_THEN s, then nothing (2 x 7 x 13
//   inputs a layout): per level the inputs that clear, the least and most of a seed.
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
// The way a player picks by eye (test/games/black-hole-players.ts planRoute, which the scripted
// players of the difficulty-curve test fly too).
const { planLeg, RING_EASE } = await importSource(
  'black-hole-route',
  "export { planLeg, RING_EASE } from './test/games/black-hole-players.ts';",
);
const [lo, hi] = arg('--levels', '1-10').split('-').map(Number);
const seeds = Number(arg('--seeds', '8'));
const fields = arg('--fields', '32x24,20x30')
  .split(',')
  .map((f) => f.split('x').map(Number));
const tables = arg('--tables', 'held,pilot').split(',');
const pilotFilter = arg('--pilots', '');
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
  const g = m.createBlackHoleGame({ seed, field: { width, height }, lives: 9 });
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

/** The thrust that best points 2 x the distance to `at` less 2.5 x the velocity; null when that is under 1.5 m/s^2. */
function towards(at, x, y, vx, vy) {
  const ax = 2 * (at[0] - x) - 2.5 * vx,
    ay = 2 * (at[1] - y) - 2.5 * vy;
  if (Math.hypot(ax, ay) <= 1.5) return null;
  let best = null,
    dot = -Infinity;
  for (const t of ['up', 'down', 'left', 'right', 'up-left', 'up-right', 'down-left', 'down-right']) {
    const d = m.THRUST_DIRECTION[t][0] * ax + m.THRUST_DIRECTION[t][1] * ay;
    if (d > dot) [dot, best] = [d, t];
  }
  return best;
}

/**
 * Plays level `level` of seed `seed` with a pilot that chooses every `react` s looking `look` s ahead
 * (see the file's comment). Lives never run out (a fall counts and the ship starts again).
 */
function play(level, seed, width, height, react, look, tap = Infinity, lag = 0) {
  const { g, run } = newLevel(level, seed, width, height);
  // The choices made, applied `lag` s later (a player's reaction time): step -> thrust.
  const lagSteps = Math.round(lag / g.world.dt);
  const queue = new Map();
  const pred = m.createPredictor(g);
  const ahead = Math.round(look / g.world.dt),
    every = Math.max(1, Math.round(react / g.world.dt));
  const path = new Float64Array(2 * (ahead + 1));
  const gap = run.spec.gate > 0 ? wallGap(g) : null;
  const P = g.world.components.Position,
    V = g.world.components.Velocity;
  const steps = Math.round(60 / g.world.dt),
    tapSteps = Math.round(tap / g.world.dt);
  let chosen = 'none',
    chosenAt = -Infinity;
  for (let k = 0; k < steps; k++) {
    const thrustNow = g.thrust;
    if (k % every === 0 && m.canThrust(g, run)) {
      let want = 'none';
      let first = 'up';
      const s = m.slotOf(g.ship);
      const ring = run.rings[run.ringsTaken];
      if (ring) first = towards(ring, P.x[s], P.y[s], V.x[s], V.y[s]) ?? first;
      else if (gap && P.y[s] < gap.y) {
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
      m.setThrust(g, thrustNow);
      queue.set(k + lagSteps, want);
    }
    if (queue.has(k)) {
      chosen = queue.get(k);
      chosenAt = k;
      queue.delete(k);
    }
    let want = k - chosenAt >= tapSteps ? 'none' : chosen;
    if (!m.canThrust(g, run)) want = 'none';
    if (g.thrust !== want) m.setThrust(g, want);
    const e = m.stepLevel(g, run);
    if (e === 'cleared') return { time: run.summary.totalTime, falls: run.summary.falls };
    if (e === 'fell' || e === 'lost') {
      // The page lets go of every arrow after a fall or an exit: choices still pending are dropped.
      queue.clear();
      chosen = 'none';
    }
    if (g.lives < 3) g.lives = 9;
  }
  return { time: Number.NaN, falls: g.falls };
}

/**
 * A newcomer who plans a way by eye and flies it by hand: at the level's start (and again after each
 * fall or exit, and every choice when holes drift) it finds a route (`route`) keeping `keep` horizon
 * radii (plus the ship's size and 0.5 m) from every hole's centre, as a player gives the glowing discs
 * a wide berth. Every `react` s it picks the thrust (of the eight arrows and pairs, or none) that best
 * turns its velocity towards `speed` m/s along the route (aimed 3 m ahead of the nearest point),
 * and presses it `lag` s later (a player's reaction). It never reads the predicted path. Lives never
 * run out, as in `play`.
 */
function flyRoute(level, seed, width, height, { react, lag, keep, speed }) {
  const { g, run } = newLevel(level, seed, width, height);
  const dt = g.world.dt;
  const every = Math.max(1, Math.round(react / dt)),
    lagSteps = Math.round(lag / dt);
  const margin = (r) => keep * r + m.SHIP_RADIUS + 0.5;
  const P = g.world.components.Position,
    V = g.world.components.Velocity;
  let way = planLeg(g, run, margin),
    leg = run.ringsTaken;
  const queue = new Map();
  let chosen = 'none';
  const thrusts = ['none', 'up', 'down', 'left', 'right', 'up-left', 'up-right', 'down-left', 'down-right'];
  for (let k = 0; k < Math.round(60 / dt); k++) {
    if (k % every === 0 && m.canThrust(g, run)) {
      if (run.spec.drift > 0 || leg !== run.ringsTaken) [way, leg] = [planLeg(g, run, margin), run.ringsTaken];
      // Where the ship will be when the choice acts, as a player allows for the engine still pushing.
      const s = m.slotOf(g.ship),
        vx = V.x[s] + g.thrustVec[0] * lag,
        vy = V.y[s] + g.thrustVec[1] * lag,
        x = P.x[s] + V.x[s] * lag,
        y = P.y[s] + V.y[s] * lag;
      // The nearest route point, then the one 3 m further along the route (its points are 0.5 to 0.7 m apart).
      let near = 0;
      for (let i = 1; i < way.length; i++)
        if (Math.hypot(way[i][0] - x, way[i][1] - y) < Math.hypot(way[near][0] - x, way[near][1] - y)) near = i;
      let aim = near;
      for (let along = 0; aim + 1 < way.length && along < 3; aim++)
        along += Math.hypot(way[aim + 1][0] - way[aim][0], way[aim + 1][1] - way[aim][1]);
      const [ax, ay] = way.length ? way[aim] : (run.rings[run.ringsTaken] ?? [x, g.lineY]);
      const d = Math.hypot(ax - x, ay - y) || 1;
      // Nearing a ring it eases off, as the test's players do (RING_EASE).
      const ring = run.rings[run.ringsTaken];
      const v = ring ? Math.min(speed, RING_EASE[0] + RING_EASE[1] * Math.hypot(ring[0] - x, ring[1] - y)) : speed;
      const ex = (v * (ax - x)) / d - vx,
        ey = (v * (ay - y)) / d - vy;
      let want = 'none';
      if (Math.hypot(ex, ey) > 0.6) {
        let best = -Infinity;
        for (const t of thrusts.slice(1)) {
          const [tx, ty] = m.THRUST_DIRECTION[t];
          const dot = (tx * ex + ty * ey) / Math.hypot(ex, ey);
          if (dot > best) [best, want] = [dot, t];
        }
      }
      queue.set(k + lagSteps, want);
    }
    if (queue.has(k)) {
      chosen = queue.get(k);
      queue.delete(k);
    }
    const want = m.canThrust(g, run) ? chosen : 'none';
    if (g.thrust !== want) m.setThrust(g, want);
    const e = m.stepLevel(g, run);
    if (e === 'cleared') return { time: run.summary.totalTime, falls: run.summary.falls, routed: way.length > 0 };
    if (e === 'fell' || e === 'lost') {
      queue.clear();
      chosen = 'none';
      [way, leg] = [planLeg(g, run, margin), run.ringsTaken];
    }
    if (g.lives < 3) g.lives = 9;
  }
  return { time: Number.NaN, falls: g.falls, routed: way.length > 0 };
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

/** The pilots: name, seconds between choices, seconds looked ahead, tap length (s; Infinity: holds), reaction lag (s). */
const PILOTS = [
  ['sharp pilot (0.1 s, 1.5 s ahead)', 0.1, 1.5, Infinity, 0],
  ['stranger pilot (0.25 s, 1 s ahead)', 0.25, 1, Infinity, 0],
  ['newcomer (0.3 s, 1 s ahead, acts 0.3 s late)', 0.3, 1, Infinity, 0.3],
  ['slow newcomer (0.4 s, 1 s ahead, acts 0.5 s late)', 0.4, 1, Infinity, 0.5],
  ['tapper (0.15 s taps every 0.4 s, 1 s ahead)', 0.4, 1, 0.15, 0],
].filter(([name]) => pilotFilter === '' || name.includes(pilotFilter));

/** The route pilots (`flyRoute`): name and style. */
const ROUTE_PILOTS = [
  ['careful newcomer (route 2.6 radii clear, 3 m/s, choices every 0.3 s, 0.35 s late)', { react: 0.3, lag: 0.35, keep: 2.6, speed: 3 }],
  ['bold newcomer (route 1.5 radii clear, 4.5 m/s, choices every 0.3 s, 0.35 s late)', { react: 0.3, lag: 0.35, keep: 1.5, speed: 4.5 }],
  ['slow thumb (route 2 radii clear, 3.5 m/s, choices every 0.4 s, 0.5 s late)', { react: 0.4, lag: 0.5, keep: 2, speed: 3.5 }],
].filter(([name]) => pilotFilter === '' || name.includes(pilotFilter));

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
    for (const [name, react, look, tap, lag] of PILOTS) {
      console.log(`  ${name}:`);
      for (const level of levels) {
        const rs = seedList.map((seed) => play(level, seed, width, height, react, look, tap, lag));
        const ok = rs.filter((r) => Number.isFinite(r.time));
        const mean = ok.reduce((a, r) => a + r.time, 0) / Math.max(1, ok.length);
        const longest = Math.max(0, ...ok.map((r) => r.time));
        const falls = rs.reduce((a, r) => a + r.falls, 0) / seeds;
        // Of all the tries (each fall ends one; a clear ends the last), the share that cleared.
        const rate = ok.length / Math.max(1, ok.length + rs.reduce((a, r) => a + r.falls, 0));
        const failed = rs.flatMap((r, i) => (Number.isFinite(r.time) ? [] : [seedList[i]]));
        console.log(
          `    level ${level}: cleared ${ok.length}/${seeds}${failed.length ? ` (not seeds ${failed.join(' ')})` : ''}, ` +
            `time mean ${mean.toFixed(1)} s, longest ${longest.toFixed(1)} s, falls ${falls.toFixed(2)} a level, ` +
            `${(100 * rate).toFixed(0)} % of tries clear`,
        );
      }
    }
  }
  if (tables.includes('route')) {
    for (const [name, style] of ROUTE_PILOTS) {
      console.log(`  ${name}:`);
      for (const level of levels) {
        const rs = seedList.map((seed) => flyRoute(level, seed, width, height, style));
        const ok = rs.filter((r) => Number.isFinite(r.time));
        const falls = rs.reduce((a, r) => a + r.falls, 0);
        const failed = rs.flatMap((r, i) => (Number.isFinite(r.time) ? [] : [seedList[i]]));
        const noRoute = rs.filter((r) => !r.routed).length;
        console.log(
          `    level ${level}: cleared ${ok.length}/${seeds}${failed.length ? ` (not seeds ${failed.join(' ')})` : ''}, ` +
            `falls ${(falls / seeds).toFixed(2)} a level, ${((100 * ok.length) / Math.max(1, ok.length + falls)).toFixed(0)} % of tries clear` +
            (noRoute ? `, no route found on ${noRoute}` : ''),
        );
      }
    }
  }
  if (tables.includes('twophase')) {
    console.log('  two-phase blind inputs (a diagonal up, then up alone, then nothing): clears / inputs');
    for (const level of levels) {
      const counts = seedList.map((seed) => {
        const { g, run } = newLevel(level, seed, width, height);
        let n = 0;
        for (const side of ['up-left', 'up-right'])
          for (const first of m.TWO_PHASE_FIRST)
            for (const then of m.TWO_PHASE_THEN)
              if (
                m.phasedFlight(g, run, [
                  [side, first],
                  ['up', then],
                ]).end === 'cleared'
              )
                n++;
        return n;
      });
      const of = 2 * m.TWO_PHASE_FIRST.length * m.TWO_PHASE_THEN.length;
      console.log(
        `    level ${level}: ${counts.reduce((a, b) => a + b, 0)}/${of * seeds}, a seed ${Math.min(...counts)} to ${Math.max(...counts)} of ${of}`,
      );
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
