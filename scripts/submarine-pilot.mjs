// `node scripts/submarine-pilot.mjs [--seeds=N] [--react=S] [--warn=S] [--verbose]`: flies the submarine's
// courses headless (games/submarine: the helm, the physics, the seabed contact and the mines) with a
// stranger at the helm, and counts the mines it sets off. The pilot runs full ahead (slower when the
// beacon lies steeper than the boat can dive), holds Dive or Rise toward the next beacon, and when the
// mine warning by the hull comes (mines.ts mineAhead, as the page computes it) it waits S s (default
// 1: mines.ts MINE_REACTION), then holds the Rise or Dive key as told while the warning lasts (a key
// asks for a steady share, helm.ts keyHeaveShare, as on the page) and holds its depth until it is past the mine. It minds neither the ridges nor the glow trail. Courses: seeds 1
// to N (default 20) with 6 and with 10 beacons. --warn: how far ahead the warning looks, s (default
// mines.ts MINE_WARN_TIME). Prints the mines hit (and how long before each the
// warning came), the seabed hits, the beacons collected (the hull's centre within 8 m, the page's
// BEACON_CATCH) and the totals. Takes about a minute.
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

const sub = await importSource(
  'submarine-pilot',
  `export * from './games/submarine/helm.ts';
   export * from './games/submarine/mines.ts';
   export * from './games/submarine/seabed.ts';
   export { SUBMARINE, submarine } from '@bitphysics/projects';
   export { applyImpulse, createPhysicsWorld, step } from '@bitphysics/physics';`,
);
const {
  createHelmState,
  keyHeaveShare,
  steer,
  courseOrder,
  layMines,
  mineAhead,
  touchesMine,
  MINE_BLAST_IMPULSE,
  seabedInput,
  touchSeabed,
} = sub;
const { SUBMARINE, submarine, applyImpulse, createPhysicsWorld, step } = sub;

/** Flies course (seed, count) for up to 240 s of game time. @returns mines laid and hit, seabed hits, beacons collected, the time and what happened. */
function fly(seed, count) {
  const world = createPhysicsWorld(submarine.worldOptions());
  const h = submarine.build(world, { seed, count });
  const mines = layMines(h.beacons, h.seabed, seed);
  const live = mines.map(() => true);
  const state = { ...createHelmState(), touching: false, spared: 0, diveStopped: false };
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
    collected = 0;
  const events = [];
  for (let n = 0; n < 240 * 60 && next < order.length; n++) {
    const t = world.time,
      x = c.Position.x[e],
      y = c.Position.y[e];
    const b = order[next],
      bx = h.beacons[2 * b],
      by = h.beacons[2 * b + 1];
    const was = told?.index ?? -1;
    told = mineAhead(x, y, c.Velocity.x[e], c.Velocity.y[e], state.holdY, mines, live, h.seabed, {
      prefer: told,
      ...(Number.isNaN(warn) ? {} : { horizon: warn }),
      heaving: state.mode === 'diving' || state.mode === 'rising',
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
        input.heave = keyHeaveShare(keySince, t);
      } else keySince = Number.NaN;
    } else {
      keySince = Number.NaN;
      const dy = by - y;
      const tv = Math.abs(dy) / 8 + 1,
        th = Math.max(0, bx - x) / 12.9;
      input.drive = th < tv ? Math.max(0.25, th / tv) : 1;
      if (Math.abs(dy) > 2) {
        input.rise = dy > 0;
        input.dive = dy < 0;
        input.heave = Math.max(0.2, Math.min(1, Math.abs(dy) / 15));
      }
    }
    const held = seabedInput(state, input);
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
    const dx = bx - c.Position.x[e],
      dy = by - c.Position.y[e];
    if (dx * dx + dy * dy < 64) {
      collected++;
      next++;
    } else if (c.Position.x[e] > bx + 30) next++;
  }
  return { mines: mines.length, hits, bed, collected, count: order.length, time: world.time, events };
}

let laid = 0,
  hit = 0,
  bedHits = 0,
  beacons = 0,
  collected = 0;
for (let seed = 1; seed <= seeds; seed++)
  for (const count of [6, 10]) {
    const r = fly(seed, count);
    laid += r.mines;
    hit += r.hits;
    bedHits += r.bed;
    beacons += r.count;
    collected += r.collected;
    if (verbose || r.hits > 0 || r.collected < r.count)
      console.log(
        `seed ${seed}, ${count} beacons: ${r.collected} collected, ${r.mines} mines, ${r.hits} hit, ${r.bed} seabed hits, ${r.time.toFixed(0)} s. ${r.events.join('; ')}`,
      );
  }
console.log(
  `Reaction ${react} s: ${hit} of ${laid} mines hit (${((100 * hit) / Math.max(1, laid)).toFixed(1)} %), ${bedHits} seabed hits, ${collected} of ${beacons} beacons collected.`,
);
