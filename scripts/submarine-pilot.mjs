// `node scripts/submarine-pilot.mjs [--seeds=N] [--react=S] [--warn=S] [--verbose] [--legs] [--no-level-stop] [--naive=R]`: flies the
// submarine's courses headless (games/submarine: the course as the page lays it, beacons.ts layCourse;
// the helm, the physics, the seabed contact and the mines) with a steady pilot on the keys, and counts
// the mines it sets off and the time it takes. The pilot holds Ahead while the boat is slower than
// lets it reach the next beacon's x as it reaches its depth, Astern (the brake) while it is 2 m/s
// faster (between the two it lets go and glides), and Dive or Rise (the keys' steady share, helm.ts
// keyHeaveShare at the boat's speed) until the depth order is at the beacon's depth; when the mine warning by the hull comes (mines.ts mineAhead, as the page
// computes it, on at the share the keys ask for) it waits S s (default 1: mines.ts MINE_REACTION), then holds the Rise or Dive key as
// told while the warning lasts and holds its depth until it is past the mine; when the seabed has
// stopped its dive it lets go of Dive once off the bed and presses it again. It minds neither the
// ridges nor the glow trail, and does not turn back for a beacon it passed: as on the page, a beacon
// left BEACON_PASSED behind (beacons.ts passedBeacon) is missed and the next one is the target, any
// beacon the hull touches on its way is collected, and the run ends at the finish (beacons.ts
// lastBeacon, never passed), whatever was missed. Courses: seeds 1 to N
// (default 20) with 6 and with 10 beacons. --warn: how far ahead the warning looks, s (default
// mines.ts MINE_WARN_TIME). Prints the mines hit (and how long before each the warning came), the
// seabed hits, the beacons collected (beacons.ts catchesBeacon) and missed, the time and the par
// (mines.ts parTime), par over the pilot's time on the courses won, and the totals; --legs prints
// each won course's legs (|dx|, |dy|, m) and time as JSON lines (mines.ts PILOT_LEG is fitted to
// them). A held Dive or Rise stops at the target's depth as on the page (level-stop.ts); --no-level-stop
// leaves that out. --naive=R: the pilot watches the hull, not the order: it presses Dive or Rise while
// the boat is stopped more than 3 m off the target's depth and lets go R s after it sees the hull level
// with the beacon (within 1.5 m or past it). Takes about a minute.
import { importSource } from './build.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const a = args.find((x) => x.startsWith(`--${name}=`));
  return a === undefined ? fallback : Number(a.slice(name.length + 3));
};
const seeds = option('seeds', 20);
const react = option('react', 1);
if (!(Number.isInteger(seeds) && seeds >= 1)) throw new RangeError(`submarine-pilot: --seeds must be an integer >= 1, got ${seeds}`);
if (!(react >= 0)) throw new RangeError(`submarine-pilot: --react must be >= 0 s, got ${react}`);
const warn = option('warn', Number.NaN);
if (!(Number.isNaN(warn) || warn > 0)) throw new RangeError(`submarine-pilot: --warn must be > 0 s, got ${warn}`);
const verbose = args.includes('--verbose');
const levelStops = !args.includes('--no-level-stop');
const naive = option('naive', -1);

const sub = await importSource(
  'submarine-pilot',
  `export * from './games/submarine/helm.ts';
   export * from './games/submarine/beacons.ts';
   export * from './games/submarine/mines.ts';
   export * from './games/submarine/seabed.ts';
   export * from './games/submarine/level-stop.ts';
   export { SUBMARINE, submarine } from '@bitphysics/projects';
   export { applyImpulse, createPhysicsWorld, step } from '@bitphysics/physics';`,
);
const {
  createHelmState,
  catchesBeacon,
  lastBeacon,
  layCourse,
  passedBeacon,
  parTime,
  keyHeaveShare,
  steer,
  courseOrder,
  layMines,
  mineAhead,
  touchesMine,
  MINE_BLAST_IMPULSE,
  seabedInput,
  touchSeabed,
  createLevelStop,
  levelStop,
} = sub;
const { SUBMARINE, submarine, applyImpulse, createPhysicsWorld, step } = sub;

/** Flies course (seed, count) for up to 240 s of game time. @returns mines laid and hit, seabed hits, beacons collected and missed, whether the finish was reached, the time and what happened. */
function fly(seed, count) {
  const world = createPhysicsWorld(submarine.worldOptions());
  const h = submarine.build(world, { seed, count });
  layCourse(h.beacons, h.seabed, seed);
  const mines = layMines(h.beacons, h.seabed, seed);
  const live = mines.map(() => true);
  const state = { ...createHelmState(), touching: false, spared: 0, diveStopped: false };
  const stopState = createLevelStop();
  const press = { beacon: -1, dir: 0, letGoAt: Number.POSITIVE_INFINITY };
  const order = courseOrder(h.beacons);
  const c = world.components,
    e = h.hull;
  let next = 0,
    hits = 0,
    bed = 0,
    told = null,
    warnedAt = Number.NaN,
    evade = null,
    keySince = Number.NaN,
    collected = 0,
    missed = 0,
    finished = false;
  const taken = order.map(() => false),
    finish = lastBeacon(h.beacons);
  const events = [];
  for (let n = 0; n < 240 * 60 && !finished && next < order.length; n++) {
    // The target: the next beacon along the course not collected yet.
    while (next < order.length && taken[order[next]]) next++;
    if (next >= order.length) break;
    const t = world.time,
      x = c.Position.x[e],
      y = c.Position.y[e];
    const b = order[next],
      bx = h.beacons[2 * b],
      by = h.beacons[2 * b + 1];
    const was = told?.index ?? -1;
    // The warning as the page works it out: on at the share a held key asks for now (keyHeaveShare
    // at the boat's speed), the pilot being on the keys.
    told = mineAhead(x, y, c.Velocity.x[e], c.Velocity.y[e], state.holdY, mines, live, h.seabed, {
      prefer: told,
      ...(Number.isNaN(warn) ? {} : { horizon: warn }),
      heaving: state.mode === 'diving' || state.mode === 'rising',
      heave: keyHeaveShare(0, t, c.Velocity.x[e]),
    });
    if (told && told.index !== was) warnedAt = t;
    if (told && t - warnedAt >= react && evade?.index !== told.index) evade = { ...told, warned: warnedAt };
    if (evade && (!live[evade.index] || mines[evade.index].x < x - SUBMARINE.length / 2 - 3)) evade = null;
    const input = { dive: false, rise: false, noseDown: false, noseUp: false, ahead: true, astern: false, heave: 1, drive: 1 };
    if (evade) {
      // Rise (dive) while the warning for it lasts, then hold the depth until past it.
      const on = told?.index === evade.index;
      input.rise = on && evade.side === 'over';
      input.dive = on && evade.side === 'under';
      if (input.rise || input.dive) {
        if (Number.isNaN(keySince)) keySince = t;
        input.heave = keyHeaveShare(keySince, t, c.Velocity.x[e]);
      } else keySince = Number.NaN;
    } else {
      keySince = Number.NaN;
      const dy = by - y;
      // On the keys too: Ahead held while the boat is slower than lets it reach the beacon's x as
      // it reaches its depth (at about 3.5 m/s, the key's 5 m/s at rest less the start, the stop and a margin),
      // Astern (the brake) while it is 2 m/s or more faster, else it lets go (and glides, braking).
      const tv = Math.abs(dy) / 3.5 + 3,
        want = Math.max(3, Math.max(0, bx - x) / tv),
        vx = c.Velocity.x[e];
      input.drive = 1;
      input.ahead = vx < want;
      input.astern = vx > want + 2;
      // On the keys: Dive or Rise held (a steady share, as the page's keys) until the depth order
      // is within 2 m of the beacon's depth.
      const err = by - state.holdY;
      if (naive >= 0) {
        // --naive: watching the hull, not the order: a press toward the beacon's depth while the boat
        // is stopped more than 3 m off it, let go `naive` s after the hull is seen level (within 1.5 m, or past it).
        if (press.beacon !== b) Object.assign(press, { beacon: b, dir: 0, letGoAt: Number.POSITIVE_INFINITY });
        if (press.dir === 0 && Math.abs(dy) > 3 && Math.abs(c.Velocity.y[e]) < 0.3)
          Object.assign(press, { dir: Math.sign(dy), letGoAt: Number.POSITIVE_INFINITY });
        if (press.dir !== 0 && press.letGoAt === Number.POSITIVE_INFINITY && dy * press.dir <= 1.5) press.letGoAt = t + naive;
        if (press.dir !== 0 && t >= press.letGoAt) press.dir = 0;
        input.rise = press.dir > 0;
        input.dive = press.dir < 0;
        input.heave = keyHeaveShare(0, t, c.Velocity.x[e]);
      } else if (Math.abs(dy) > 2 && !(Math.abs(err) < 2)) {
        input.rise = dy > 0;
        input.dive = dy < 0;
        input.heave = keyHeaveShare(0, t, c.Velocity.x[e]);
      }
    }
    // The bed stopped a dive (seabed.ts seabedInput) and the hull is off it again: Dive is let go
    // for a step, as a player presses it again once the boat has cleared the bed.
    if (state.diveStopped && !state.touching && input.dive) input.dive = false;
    const held = seabedInput(state, input);
    // The stop at the target's depth (level-stop.ts), as the page makes it, unless --no-level-stop.
    if (
      levelStops &&
      levelStop(stopState, {
        dir: held.dive === held.rise ? 0 : held.dive ? -1 : 1,
        now: t,
        beacon: b,
        beaconY: by,
        order: state.holdY,
        y,
        vy: c.Velocity.y[e],
        warned: told !== null,
      })
    ) {
      state.holdY = by;
      held.dive = held.rise = false;
    }
    steer(world, h, held, state);
    step(world);
    const contact = touchSeabed(world, h, state, world.time, held.dive, { x: 0, y: 0 });
    if (contact !== '') state.holdY = Number.NaN;
    if (contact === 'hit') bed++;
    for (let i = 0; i < mines.length; i++) {
      const m = mines[i];
      if (!live[i] || !touchesMine(c.Position.x[e], c.Position.y[e], c.Angle.value[e], m.x, m.y)) continue;
      live[i] = false;
      hits++;
      const warned =
        told?.index === i || evade?.index === i
          ? `warned ${(t - (evade?.index === i ? evade.warned : warnedAt)).toFixed(1)} s before`
          : 'not warned';
      events.push(`mine ${i} at (${m.x.toFixed(0)}, ${m.y.toFixed(0)}) at ${t.toFixed(1)} s, ${warned}`);
      const dx = c.Position.x[e] - m.x,
        dy = c.Position.y[e] - m.y,
        r = Math.max(1e-6, Math.hypot(dx, dy));
      applyImpulse(world, e, [(MINE_BLAST_IMPULSE * dx) / r, (MINE_BLAST_IMPULSE * dy) / r]);
    }
    // Any beacon the hull touches is collected (the page's rule), the finish ends the run.
    for (let i = 0; i < order.length; i++) {
      if (taken[i] || !catchesBeacon(c.Position.x[e], c.Position.y[e], c.Angle.value[e], h.beacons[2 * i], h.beacons[2 * i + 1])) continue;
      taken[i] = true;
      collected++;
      if (i === finish) finished = true;
    }
    if (!finished && !taken[b] && passedBeacon(h.beacons, b, c.Position.x[e])) {
      events.push(`missed beacon ${b} at (${bx.toFixed(0)}, ${by.toFixed(0)}): passed at depth ${(-c.Position.y[e]).toFixed(0)} m`);
      missed++;
      next++;
    }
  }
  let px = 0,
    py = 0;
  const legs = order.map((i) => {
    const leg = [Math.abs(h.beacons[2 * i] - px), Math.abs(h.beacons[2 * i + 1] - py)];
    px = h.beacons[2 * i];
    py = h.beacons[2 * i + 1];
    return leg;
  });
  return {
    mines: mines.length,
    hits,
    bed,
    collected,
    missed,
    finished,
    count: order.length,
    time: world.time,
    par: parTime(h.beacons),
    legs,
    events,
  };
}

let laid = 0,
  hit = 0,
  bedHits = 0,
  beacons = 0,
  collected = 0,
  missedAll = 0,
  unfinished = 0;
const ratios = [];
for (let seed = 1; seed <= seeds; seed++)
  for (const count of [6, 10]) {
    const r = fly(seed, count);
    laid += r.mines;
    hit += r.hits;
    bedHits += r.bed;
    beacons += r.count;
    collected += r.collected;
    missedAll += r.missed;
    if (!r.finished) unfinished++;
    if (r.collected === r.count) ratios.push(r.par / r.time);
    if (args.includes('--legs') && r.collected === r.count) console.log(JSON.stringify({ seed, count, time: r.time, legs: r.legs }));
    if (verbose || r.hits > 0 || r.collected < r.count)
      console.log(
        `seed ${seed}, ${count} beacons: ${r.collected} collected, ${r.missed} missed, ${r.finished ? 'finished' : 'not finished'}, ${r.mines} mines, ${r.hits} hit, ${r.bed} seabed hits, ${r.time.toFixed(0)} s (par ${r.par} s). ${r.events.join('; ')}`,
      );
  }
ratios.sort((a, b) => a - b);
if (ratios.length > 0)
  console.log(
    `Par over the pilot's time, on the ${ratios.length} courses won: least ${ratios[0].toFixed(2)}, median ${ratios[ratios.length >> 1].toFixed(2)}, most ${ratios[ratios.length - 1].toFixed(2)}.`,
  );
console.log(
  `Reaction ${react} s: ${hit} of ${laid} mines hit (${((100 * hit) / Math.max(1, laid)).toFixed(1)} %), ${bedHits} seabed hits, ${collected} of ${beacons} beacons collected, ${missedAll} missed, ${unfinished} courses not finished.`,
);
