// `node scripts/flight-simulator-steering.mjs`: how the flight simulator's aircraft answers the bank
// keys, flown as the game flies it (the assist on, the keys ramped by rampKey, the surfaces following
// the assist at SURFACE_RATE.assist, full deflection CONTROL_AUTHORITY degrees; level at 130 m/s with
// the starting throttle, 900 m up). Prints, in game time:
// - a held half turn: s from pressing → until the heading has turned 180 degrees, and the bank held;
// - taps of → for 100, 150 and 250 ms: the heading's change once the wings are level again, degrees;
// - holds of → from 100 ms to 2 s: the heading each turns in all, degrees;
// - held to a target: → held until the heading has turned 30 / 90 degrees, then let go: how far the
//   heading runs on past the target, degrees, and how long the wings take to come level (within 2 degrees).
// - a 1 s hold (0.5 and 2 s too) at 60 and 5 frames a second, as the page's loop runs it (the keys
//   read once a frame; at most 9 steps of 1/60 s a frame, so at 5 fps the game runs at 0.75 of the
//   clock): the heading's run-on after the release is seen, degrees, and how far from the path
//   marker's "let go now" point (predictThroughRing, from the last frame before the release) the
//   aircraft crosses a ring plane 800 m ahead, m (a ring's radius is 65 m). "keys timed": each step
//   of a frame takes the key as it was at its moment since the last frame (the page's axisKeysAt).
import { importSource } from './build.mjs';

const fs = await importSource(
  'flight-simulator-steering',
  [
    "export * from './games/flight-simulator/assist.ts';",
    "export { predictThroughRing } from './games/flight-simulator/course.ts';",
    "export { createPhysicsWorld, setBodyThrust, setControlDeflection, step } from '@bitphysics/physics';",
    "export { AIRCRAFT, aircraft, aircraftLevelDrag, terrainHeight } from '@bitphysics/projects';",
  ].join('\n'),
);
const DEG = Math.PI / 180;

/**
 * The aircraft level at 130 m/s, 900 m up, with the assist: `steer(s, roll)` asks the assist for the
 * bank stick `roll` from flight state `s`, moves the surfaces towards its answer at SURFACE_RATE.assist,
 * holds the starting throttle and steps the world once (as the page does each step).
 */
function createFlight() {
  const world = fs.createPhysicsWorld(fs.aircraft.worldOptions());
  const h = fs.aircraft.build(world, { seed: 1, altitude: 900 });
  const state = fs.createAssistState(),
    surface = { aileron: 0, elevator: 0, rudder: 0 },
    rate = fs.SURFACE_RATE.assist * world.dt,
    full = fs.CONTROL_AUTHORITY * DEG,
    e = h.body,
    throttle = fs.aircraftLevelDrag(130) / fs.AIRCRAFT.maxThrust;
  const C = world.components;
  const ground = (x, z) => Math.max(60, fs.terrainHeight(h.terrain, x, z));
  const steer = (s, roll, pitch = 0) => {
    const floor =
      process.env.FLOOR === '0'
        ? -Math.PI / 2
        : fs.floorPath([C.Position.x[e], C.Position.y[e], C.Position.z[e]], [C.Velocity.x[e], C.Velocity.y[e], C.Velocity.z[e]], ground);
    const c = fs.assist(s, { roll, pitch, yaw: 0 }, state, world.dt, floor);
    for (const q of ['aileron', 'elevator', 'rudder']) surface[q] += Math.max(-rate, Math.min(rate, c[q] - surface[q]));
    fs.setControlDeflection(world, h.surfaces.tail, -surface.elevator * full);
    fs.setControlDeflection(world, h.surfaces.leftWing, surface.aileron * full * fs.AILERON_SCALE);
    fs.setControlDeflection(world, h.surfaces.rightWing, -surface.aileron * full * fs.AILERON_SCALE);
    fs.setControlDeflection(world, h.surfaces.fin, -surface.rudder * full);
    fs.setBodyThrust(world, e, [throttle * fs.AIRCRAFT.maxThrust, 0, 0]);
    fs.step(world);
  };
  return { world, state, e, steer, ground };
}

/** Flies with the → key held while `hold(t, turned, s)` says so; returns the record. */
function fly(hold, seconds) {
  const { world, e, steer } = createFlight();
  const keys = { roll: 0, pitch: 0 };
  const h0 = fs.flightState(world, e).heading;
  const out = [];
  let unwrapped = 0,
    last = h0;
  for (let t = 0; t < seconds; t += world.dt) {
    const s = fs.flightState(world, e);
    unwrapped += ((s.heading - last + 3 * Math.PI) % (2 * Math.PI)) - Math.PI;
    last = s.heading;
    const key = hold(t, unwrapped / DEG, s) ? 1 : 0;
    keys.roll = fs.rampKey(keys.roll, key, world.dt, fs.BANK_KEY_RAMP);
    out.push({ t, turned: unwrapped / DEG, bank: s.bank / DEG, key, speed: s.speed, path: s.path / DEG, alpha: s.alpha / DEG });
    steer(s, keys.roll);
  }
  return out;
}

const half = fly((_t, turned) => turned < 180, 60);
const done = half.find((r) => r.turned >= 180);
const held = half.filter((r) => r.t < (done?.t ?? 60));
console.log(
  `held half turn: ${done ? done.t.toFixed(1) : '> 60'} s, bank at most ${Math.max(...held.map((r) => r.bank)).toFixed(0)}°, speed ${held[held.length - 1].speed.toFixed(0)} m/s, alpha at most ${Math.max(...held.map((r) => r.alpha)).toFixed(1)}°, path ${Math.min(...held.map((r) => r.path)).toFixed(1)}..${Math.max(...held.map((r) => r.path)).toFixed(1)}°`,
);
for (const ms of [100, 150, 250]) {
  const r = fly((t) => t < ms / 1000, 8);
  console.log(`tap ${ms} ms: heading ${r[r.length - 1].turned.toFixed(2)}°, bank at most ${Math.max(...r.map((x) => x.bank)).toFixed(1)}°`);
}
// The heading a hold of → of each length turns in all (the wings level again): proportional and
// predictable when it grows steadily with the hold, with no jump.
const sweep = [100, 150, 250, 400, 500, 600, 800, 1000, 1500, 2000].map((ms) => {
  const r = fly((t) => t < ms / 1000, 12);
  return `${ms} ${r[r.length - 1].turned.toFixed(1)}°`;
});
console.log(`hold (ms) → heading turned: ${sweep.join(', ')}`);
for (const target of [30, 90]) {
  let released = -1;
  const r = fly((t, turned) => {
    if (released < 0 && turned >= target) released = t;
    return released < 0;
  }, 30);
  const level = r.find((x) => x.t > released && Math.abs(x.bank) < 2);
  console.log(
    `held to ${target}°: let go at ${released.toFixed(1)} s, heading runs on ${(r[r.length - 1].turned - target).toFixed(1)}° past it, wings level after ${level ? (level.t - released).toFixed(1) : '?'} s`,
  );
}

// Let go: the bank at the release and 0.5 s and 1 s after it, degrees, and when the wings are within
// 3 degrees of level, s after the release; and the heading rate 1 s into the hold, degrees/s (the
// turn's feel: how soon a held key turns the nose).
for (const ms of [150, 500, 1000, 2000]) {
  const r = fly((t) => t < ms / 1000, 6);
  const at = (dt) => r[Math.min(r.length - 1, Math.round((ms / 1000 + dt) * 60))];
  const level = r.find(
    (x) => x.t > ms / 1000 && Math.abs(x.bank) < 3 && x.t > ms / 1000 + 0.05 && r.every((y) => y.t < x.t || Math.abs(y.bank) < 3),
  );
  console.log(
    `let go after ${ms} ms: bank ${at(0).bank.toFixed(1)}° at the release, ${at(0.5).bank.toFixed(1)}° 0.5 s after, ${at(1).bank.toFixed(1)}° 1 s after; level (< 3°) ${level ? (level.t - ms / 1000).toFixed(2) : '?'} s after`,
  );
}
{
  const r = fly(() => true, 3);
  const rate = (t) => (r[Math.round((t + 0.1) * 60)].turned - r[Math.round((t - 0.1) * 60)].turned) / 0.2;
  console.log(
    `held →: heading rate ${rate(0.5).toFixed(1)}°/s at 0.5 s, ${rate(1).toFixed(1)}°/s at 1 s, ${rate(2).toFixed(1)}°/s at 2 s; turned ${r[60].turned.toFixed(1)}° in 1 s`,
  );
}

/** Flies a hold of → for `holdReal` s of the clock at `fps` frames a second; see the header. */
function flyFrames(fps, holdReal, timed) {
  const { world, state, e, steer } = createFlight();
  const C = world.components;
  let roll = 0,
    unwrapped = 0,
    last = fs.flightState(world, e).heading,
    motion = null,
    marker = null,
    turnedAtRelease = 0;
  const track = [];
  const press = 0.05; // the clock's time of the press, s: between frames
  const steps = Math.min(9, Math.round(60 / fps));
  for (let frame = 0; frame * (1 / fps) < 40; frame++) {
    const clock = frame / fps;
    const key = clock >= press && clock < press + holdReal ? 1 : 0;
    if (clock < press + holdReal && motion) marker = motion; // the marker the pilot sees when letting go: the last frame's
    if (key === 0 && clock >= press + holdReal && turnedAtRelease === 0) turnedAtRelease = unwrapped / DEG || 1e-9;
    for (let k = 0; k < steps; k++) {
      const s = fs.flightState(world, e);
      // Timed (the page's axisKeysAt): each step takes the key as it was at its moment of the span
      // since the last frame; else the key as it is at the frame.
      const at = clock - 1 / fps + ((k + 1) / steps) * (1 / fps);
      const stepKey = timed ? (at >= press && at < press + holdReal ? 1 : 0) : key;
      roll = fs.rampKey(roll, stepKey, world.dt, fs.BANK_KEY_RAMP);
      steer(s, roll);
      const a = fs.flightState(world, e);
      unwrapped += ((a.heading - last + 3 * Math.PI) % (2 * Math.PI)) - Math.PI;
      last = a.heading;
      track.push([C.Position.x[e], C.Position.y[e], C.Position.z[e]]);
      motion = {
        position: [C.Position.x[e], C.Position.y[e], C.Position.z[e]],
        velocity: [C.Velocity.x[e], C.Velocity.y[e], C.Velocity.z[e]],
        bank: a.bank,
        rollRate: a.rollRate,
        pathRate: (a.path - s.path) / world.dt,
        held: fs.heldBank(state),
        at: track.length - 1,
      };
    }
  }
  if (!marker) return { runOn: unwrapped / DEG - turnedAtRelease, turned: unwrapped / DEG, miss: Number.NaN };
  // A ring plane 800 m ahead of the marker's frame, across its level velocity, centred where the marker points.
  const v = marker.velocity,
    n = Math.hypot(v[0], v[2]);
  const ring0 = {
    x: marker.position[0] + (v[0] / n) * 800,
    y: marker.position[1],
    z: marker.position[2] + (v[2] / n) * 800,
    nx: v[0] / n,
    ny: 0,
    nz: v[2] / n,
  };
  const p = fs.predictThroughRing(ring0, marker, true).point;
  const ring = { ...ring0, x: p[0], y: p[1], z: p[2] };
  let miss = Infinity;
  for (let i = marker.at + 1; i < track.length; i++) {
    const g = (q) => (ring.x - q[0]) * ring.nx + (ring.y - q[1]) * ring.ny + (ring.z - q[2]) * ring.nz;
    const a = g(track[i - 1]),
      b = g(track[i]);
    if (a > 0 && b <= 0) {
      const f = a / (a - b),
        q = [0, 1, 2].map((k) => track[i - 1][k] + f * (track[i][k] - track[i - 1][k]));
      miss = Math.hypot(q[0] - ring.x, q[1] - ring.y, q[2] - ring.z);
      break;
    }
  }
  return { runOn: unwrapped / DEG - turnedAtRelease, turned: unwrapped / DEG, miss };
}
for (const hold of [0.15, 0.5, 1, 2])
  for (const [fps, timed] of [
    [60, false],
    [5, false],
    [5, true],
  ]) {
    const r = flyFrames(fps, hold, timed);
    console.log(
      `held ${hold} s at ${fps} fps${timed ? ', keys timed' : ''}: turned ${r.turned.toFixed(1)}°, ${r.runOn.toFixed(1)}° of it after the release was seen; ${Number.isNaN(r.miss) ? 'no frame saw the key held' : `ring plane 800 m ahead crossed ${r.miss.toFixed(0)} m from the marker's point`}`,
    );
  }

// The ground floor (assist.ts floorPath; env FLOOR=0 flies without it): ↓ held from `above` m over
// the ground for 15 s: the steepest path, the lowest height over the ground and when, and whether it crashed.
for (const above of [150, 300, 600]) {
  const { world, e, steer, ground } = createFlight();
  const C = world.components;
  C.Position.y[e] = ground(0, 0) + above;
  let key = 0,
    steepest = 0,
    lowest = Infinity,
    when = 0,
    crashed = false;
  for (let t = 0; t < 15 && !crashed; t += world.dt) {
    key = fs.rampKey(key, -1, world.dt);
    steer(fs.flightState(world, e), 0, key);
    const agl = C.Position.y[e] - ground(C.Position.x[e], C.Position.z[e]);
    steepest = Math.min(steepest, fs.flightState(world, e).path / DEG);
    if (agl < lowest) {
      lowest = agl;
      when = t;
    }
    crashed = agl < 2;
  }
  console.log(
    `↓ held from ${above} m over the ground: path down to ${steepest.toFixed(0)}°, lowest ${lowest.toFixed(0)} m over the ground at ${when.toFixed(1)} s${crashed ? ', CRASHED' : ''}`,
  );
}
