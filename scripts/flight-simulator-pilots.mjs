// `node scripts/flight-simulator-pilots.mjs [seed ...]`: how many of the first 10 rings of the flight
// simulator's course (games/flight-simulator/course.ts, laid as the game lays it: seed + 7, from
// 900 m) two headless pilots pass, flown as the game steps the aircraft (the assist on with its ground floor, the surfaces
// following it at SURFACE_RATE.assist, full stick CONTROL_AUTHORITY degrees, the ailerons AILERON_SCALE times
// that; the marker follows the bank a short touch holds, assist.ts heldBank). Default seeds 1 to 8 (the
// game's default seed is 1).
// - `scripted`: the pilot of test/games/flight-simulator-course.test.ts (wings level in the last
//   250 m, else the bank of the arc to the ring's centre; the path aimed at the ring's height; the
//   throttle held near 125 m/s).
// - `naive`: a newcomer. Sees only the next ring (the game's marker), reacts REACTION s after it
//   becomes the next one and then steers on what it saw LAG s before, with the keys (ramped as the
//   game ramps them, `rampKey`, the bank keys on BANK_KEY_RAMP): banks towards the ring (three times its bearing, at most 35 degrees),
//   climbs or dives while it is over 1.5 degrees off the flight path (no steeper than 10 degrees),
//   else hands off (wings level); never touches the throttle.
// - `keys`: a stranger on the keys. Holds ← / → and ↑ / ↓ (ramped) towards the next ring while it
//   is off the flight path (as seen LAG s before) by more than the ring's radius over DEAD (env,
//   default 4) at its distance, else lets go: all or nothing, so it swings past where the aircraft
//   answers late. Prints how often it reversed the bank key.
// - `marker`: the same stranger steering by the game's flight-path marker (where the aircraft
//   crosses the ring's plane if it lets go now) instead of the ring's bearing.
// - `cue`: the `keys` stranger who also heeds the game's "Let go of ← now" (let-go.ts letGoCue, seen
//   CUE_REACTION s late): lets go of the bank key when it shows and keeps off it while the wings
//   level (1 s), then steers on as `keys` does.
// After a miss the course moves on as in the game (course.ts relayAfterMiss; env RELAY=0 flies
// without it), a ring's first miss laying that ring ahead again for a second try (second-try.ts; env
// SECOND=0 flies without), and the time from each miss to the next ring passed is printed (median, max).
// Prints per seed and pilot the rings passed of 10 and each ring's status (P passed, m missed), then
// each ring's turn (degrees) and change of height (m) for the default seed. Env PILOTS=keys,naive
// flies only those; DEBUG=1 prints where each missed ring's plane was crossed.
import { importSource } from './build.mjs';

/** The naive pilot's reaction to a new ring, s (env REACTION, default 2), and the lag of what it steers on, s. */
const REACTION = Number(process.env.REACTION ?? 2);
const LAG = 0.5;
/** How late the `cue` pilot sees the let-go cue, s (a player's reaction: let-go.ts LET_GO_LEAD). */
const CUE_REACTION = 0.2;
const fs = await importSource(
  'flight-simulator-pilots',
  [
    "export * from './games/flight-simulator/course.ts';",
    "export * from './games/flight-simulator/assist.ts';",
    "export * from './games/flight-simulator/second-try.ts';",
    "export * from './games/flight-simulator/let-go.ts';",
    "export { createPhysicsWorld, setBodyThrust, setControlDeflection, step } from '@bitphysics/physics';",
    "export { AIRCRAFT, aircraft, aircraftLevelDrag, terrainHeight } from '@bitphysics/projects';",
  ].join('\n'),
);
const DEG = Math.PI / 180;
/** Whether the course moves on after a miss (course.ts relayAfterMiss): env RELAY=0 flies the old rule. */
const RELAY = process.env.RELAY !== '0';
/** Whether a ring's first miss gives it a second try, laid ahead again (second-try.ts): env SECOND=0 flies without. */
const SECOND = process.env.SECOND !== '0';
/** Seconds from each miss to the next ring passed (Infinity: none passed after it, rings left), all pilots; a miss of the last ring is not counted. */
const recoveries = [];
const seeds = process.argv.slice(2).map(Number);
const chosen = seeds.length ? seeds : [1, 2, 3, 4, 5, 6, 7, 8];

const pilots = {
  scripted: ({ s, ring, P, e, trim }) => {
    const dx = ring.x - P.x[e],
      dy = ring.y - P.y[e],
      dz = ring.z - P.z[e],
      far = Math.hypot(dx, dz);
    const error = ((Math.atan2(dz, dx) - s.heading + 3 * Math.PI) % (2 * Math.PI)) - Math.PI;
    const bank = Math.atan((2 * s.speed * s.speed * Math.sin(error)) / far / 9.81);
    const roll = far < 250 ? 0 : Math.abs(error) > Math.PI / 2 ? Math.sign(error) : Math.max(-1, Math.min(1, bank / fs.ASSIST.maxBank));
    const aim = Math.atan2(dy, far);
    const pitch = Math.max(-1, Math.min(1, (aim - s.path) / (10 * DEG) + aim / fs.ASSIST.maxClimb));
    return { roll, pitch, throttle: Math.max(0, Math.min(1, trim + 0.05 * (125 - s.speed))) };
  },
  naive: ({ s, seen, since, start, keys, dt }) => {
    const ready = since >= REACTION && seen;
    // Leans towards the ring: a bank of three times its bearing, at most 35 degrees (what it saw LAG s ago).
    const bank = ready ? Math.max(-35 * DEG, Math.min(35 * DEG, 3 * seen.bearing)) : 0;
    const roll = Math.abs(bank - s.bank) > 5 * DEG ? Math.sign(bank - s.bank) : 0;
    // Climbs or dives towards it while it is over 1.5 degrees off the path, no steeper than 10 degrees.
    const up = ready && Math.abs(seen.elevation) > 1.5 * DEG ? Math.sign(seen.elevation) : 0;
    const pitch = up !== 0 && up * s.path < 10 * DEG ? up : 0;
    keys.roll = fs.rampKey(keys.roll, roll, dt, fs.BANK_KEY_RAMP);
    keys.pitch = fs.rampKey(keys.pitch, pitch, dt);
    return { roll: keys.roll, pitch: keys.pitch, throttle: start };
  },
  // A stranger on the keys: holds the key towards the next ring while it is off the flight path (what
  // it saw LAG s before) by more than RING_RADIUS / DEAD at its distance, else lets go; all or nothing,
  // as a key is, so it overshoots where the aircraft answers late.
  keys: ({ seen, since, start, keys, dt }) => {
    const ready = since >= 1 && seen;
    const dead = ready ? Math.max(1 * DEG, Math.atan(fs.RING_RADIUS / Number(process.env.DEAD ?? 4) / Math.max(1, seen.far))) : 0;
    const roll = ready && Math.abs(seen.bearing) > dead ? Math.sign(seen.bearing) : 0;
    const pitch = ready && Math.abs(seen.elevation) > dead ? Math.sign(seen.elevation) : 0;
    if (roll !== 0 && roll !== keys.lastRoll) keys.reversals = (keys.reversals ?? 0) + 1;
    if (roll !== 0) keys.lastRoll = roll;
    keys.roll = fs.rampKey(keys.roll, roll, dt, fs.BANK_KEY_RAMP);
    keys.pitch = fs.rampKey(keys.pitch, pitch, dt);
    return { roll: keys.roll, pitch: keys.pitch, throttle: start };
  },
  // A stranger on the keys who steers by the flight-path marker (the game's: where the aircraft
  // crosses the ring's plane if it lets go now, course.ts predictThroughRing), as it was LAG s
  // before: holds the key towards the ring while the marker is more than a third of the radius off
  // its centre that way, else lets go.
  cue: (args) => {
    const { keys, dt, cueSeen, start } = args;
    if (keys.wait > 0) {
      keys.wait -= dt;
      keys.roll = fs.rampKey(keys.roll, 0, dt, fs.BANK_KEY_RAMP);
      const pitch = pilots.keys({ ...args, keys: { roll: 0, pitch: keys.pitch } }).pitch;
      keys.pitch = pitch;
      return { roll: keys.roll, pitch, throttle: start };
    }
    if (keys.roll !== 0 && cueSeen) {
      keys.wait = 1;
      return pilots.cue(args);
    }
    return pilots.keys(args);
  },
  marker: ({ seenMarker, since, start, keys, dt }) => {
    const ready = since >= 1 && seenMarker;
    const dead = fs.RING_RADIUS / 3;
    const roll = ready && Math.abs(seenMarker.side) > dead ? Math.sign(seenMarker.side) : 0;
    const pitch = ready && Math.abs(seenMarker.up) > dead ? Math.sign(seenMarker.up) : 0;
    keys.roll = fs.rampKey(keys.roll, roll, dt, fs.BANK_KEY_RAMP);
    keys.pitch = fs.rampKey(keys.pitch, pitch, dt);
    return { roll: keys.roll, pitch: keys.pitch, throttle: start };
  },
};

const fly = (seed, pilot) => {
  const world = fs.createPhysicsWorld(fs.aircraft.worldOptions());
  const h = fs.aircraft.build(world, { seed, altitude: 900 });
  const rings = fs.layCourse({ terrain: h.terrain, seed: seed + 7, count: 10, start: [0, 900, 0] });
  const state = fs.createAssistState(),
    surface = { aileron: 0, elevator: 0, rudder: 0 },
    rate = fs.SURFACE_RATE.assist * world.dt,
    full = fs.CONTROL_AUTHORITY * DEG;
  const P = world.components.Position,
    e = h.body;
  const trim = fs.aircraftLevelDrag(125) / fs.AIRCRAFT.maxThrust;
  const start = fs.aircraftLevelDrag(130) / fs.AIRCRAFT.maxThrust;
  const history = [];
  const keys = { roll: 0, pitch: 0 };
  let missedAt = null;
  const tried = new Set();
  let current = 0,
    since = 0,
    lastPath = 0;
  for (let t = 0; t < 200 && fs.nextRing(rings) >= 0; t += world.dt) {
    const s = fs.flightState(world, e);
    const n = fs.nextRing(rings);
    if (n !== current) {
      current = n;
      since = 0;
    }
    since += world.dt;
    const ring = rings[n];
    const dx = ring.x - P.x[e],
      dy = ring.y - P.y[e],
      dz = ring.z - P.z[e],
      far = Math.hypot(dx, dz);
    const bearing = ((Math.atan2(dz, dx) - s.heading + 3 * Math.PI) % (2 * Math.PI)) - Math.PI;
    // The marker: the ring's centre from where the let-go path crosses its plane, to the ring's right
    // (horizontal, across its normal) and up, m.
    const V = world.components.Velocity;
    const through = fs.predictThroughRing(
      ring,
      {
        position: [P.x[e], P.y[e], P.z[e]],
        velocity: [V.x[e], V.y[e], V.z[e]],
        bank: s.bank,
        rollRate: s.rollRate,
        pathRate: (s.path - lastPath) / world.dt,
        held: fs.heldBank(state),
      },
      true,
    );
    lastPath = s.path;
    const across = Math.hypot(ring.nx, ring.nz);
    const marker = Number.isFinite(through.offset)
      ? {
          side: ((ring.x - through.point[0]) * -ring.nz + (ring.z - through.point[2]) * ring.nx) / across,
          up: ring.y - through.point[1],
        }
      : null;
    // The let-go cue as the game shows it (let-go.ts), for the bank keys' input now.
    const runOn = fs.runOnTurn(s.bank, s.rollRate, Math.hypot(V.x[e], V.y[e], V.z[e]));
    const cue = fs.letGoCue(fs.bearingAfterLetGo(dx, dz, Math.atan2(V.z[e], V.x[e]), runOn), runOn, keys.roll);
    history.push({ ring: n, bearing, elevation: Math.atan2(dy, far) - s.path, far: Math.hypot(far, dy), marker, cue });
    const back = history[history.length - 1 - Math.round(LAG / world.dt)];
    const seen = back && back.ring === n ? back : null;
    const cueBack = history[history.length - 1 - Math.round(CUE_REACTION / world.dt)];
    const cueSeen = !!cueBack && cueBack.ring === n && cueBack.cue;
    const c0 = pilot({ s, ring, P, e, trim, start, seen, seenMarker: seen?.marker ?? null, since, keys, dt: world.dt, cueSeen });
    // The ground floor as the game keeps it (assist.ts floorPath; the sea at 60 m).
    const floor = fs.floorPath([P.x[e], P.y[e], P.z[e]], [V.x[e], V.y[e], V.z[e]], (x, z) =>
      Math.max(60, fs.terrainHeight(h.terrain, x, z)),
    );
    const c = fs.assist(s, { roll: c0.roll, pitch: c0.pitch, yaw: 0 }, state, world.dt, floor);
    for (const k of ['aileron', 'elevator', 'rudder']) surface[k] += Math.max(-rate, Math.min(rate, c[k] - surface[k]));
    fs.setControlDeflection(world, h.surfaces.tail, -surface.elevator * full);
    fs.setControlDeflection(world, h.surfaces.leftWing, surface.aileron * full * fs.AILERON_SCALE);
    fs.setControlDeflection(world, h.surfaces.rightWing, -surface.aileron * full * fs.AILERON_SCALE);
    fs.setControlDeflection(world, h.surfaces.fin, -surface.rudder * full);
    fs.setBodyThrust(world, e, [c0.throttle * fs.AIRCRAFT.maxThrust, 0, 0]);
    const a = [P.x[e], P.y[e], P.z[e]];
    fs.step(world);
    const raw = fs.flyRings(rings, a, [P.x[e], P.y[e], P.z[e]]);
    const events = SECOND ? fs.secondTry(rings, raw, tried) : raw;
    for (const ev of events) {
      if (ev.result !== 'passed') missedAt ??= t;
      else if (missedAt !== null) {
        recoveries.push(t - missedAt);
        missedAt = null;
      }
    }
    // After a miss the course moves on, as the game does (course.ts relayAfterMiss; env RELAY=0: the old rule, none).
    if (RELAY && raw.at(-1)?.result === 'missed') {
      const after = fs.flightState(world, e);
      fs.relayAfterMiss(rings, fs.nextRing(rings), [P.x[e], P.y[e], P.z[e]], after.heading, h.terrain);
    }
    for (const ev of events)
      if (process.env.DEBUG && ev.result !== 'passed') {
        const r = rings[ev.ring];
        console.log(
          `  ring ${ev.ring + 1} missed at t ${t.toFixed(1)}: dx ${(P.x[e] - r.x).toFixed(0)} dy ${(P.y[e] - r.y).toFixed(0)} dz ${(P.z[e] - r.z).toFixed(0)} bank ${(s.bank / DEG).toFixed(0)} path ${(s.path / DEG).toFixed(1)}`,
        );
      }
    if (P.y[e] < 0) break;
  }
  rings.reversals = keys.reversals ?? 0;
  rings.tries = tried.size;
  // A miss with rings still ahead and none passed after it before the flight ended: never recovered.
  if (missedAt !== null && fs.nextRing(rings) >= 0) recoveries.push(Infinity);
  return rings;
};

/** The pilots to fly (env PILOTS, comma-separated; default all). */
const only = process.env.PILOTS?.split(',');
const totals = { scripted: 0, naive: 0, keys: 0, cue: 0, marker: 0 };
const tries = { scripted: 0, naive: 0, keys: 0, cue: 0, marker: 0 };
for (const seed of chosen)
  for (const [name, pilot] of Object.entries(pilots).filter(([name]) => !only || only.includes(name))) {
    const rings = fly(seed, pilot);
    const passed = rings.filter((r) => r.status === 'passed').length;
    totals[name] += passed;
    tries[name] += rings.tries;
    console.log(
      `seed ${seed} ${name.padEnd(8)} ${passed}/10  ${rings.map((r) => (r.status === 'passed' ? 'P' : r.status === 'missed' ? 'm' : '.')).join('')}  second tries ${rings.tries}${name === 'keys' || name === 'cue' ? `  bank reversals ${rings.reversals}` : ''}`,
    );
  }
for (const [name, n] of Object.entries(totals))
  if (!only || only.includes(name)) console.log(`${name}: ${n} of ${10 * chosen.length} rings, ${tries[name]} second tries`);
{
  const sorted = [...recoveries].sort((p, q) => p - q);
  const median = sorted.length ? sorted[Math.floor((sorted.length - 1) / 2)] : NaN;
  console.log(
    `miss to next ring passed: ${sorted.length} misses, median ${median.toFixed(1)} s, 90th percentile ${(sorted[Math.floor(0.9 * (sorted.length - 1))] ?? NaN).toFixed(1)} s, never ${sorted.filter((v) => v === Infinity).length} (course ${RELAY ? 'moves on after a miss' : 'not moved'})`,
  );
}
const world = fs.createPhysicsWorld(fs.aircraft.worldOptions());
const h = fs.aircraft.build(world, { seed: 1, altitude: 900 });
const rings = fs.layCourse({ terrain: h.terrain, seed: 8, count: 10, start: [0, 900, 0] });
let px = 0,
  py = 900,
  pz = 0,
  heading = 0;
const lines = [];
for (const r of rings) {
  const to = Math.atan2(r.z - pz, r.x - px);
  lines.push(`${((to - heading) / DEG).toFixed(0)}° ${(r.y - py).toFixed(0)} m / ${Math.hypot(r.x - px, r.z - pz).toFixed(0)} m`);
  heading = to;
  px = r.x;
  py = r.y;
  pz = r.z;
}
console.log(`seed 1 rings (turn from the line before, height change / distance): ${lines.join(', ')}`);
