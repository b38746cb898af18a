// `node scripts/flight-simulator-naive-turn.mjs`: a naive player's turn onto a ring, flown as the game
// flies it (the assist on, the → key ramped by rampKey on BANK_KEY_RAMP, the surfaces following the
// assist at SURFACE_RATE.assist, 900 m up at the start's speed). The ring lies 5 km away (so the error is the heading's, not the place's), 20 to 120
// degrees to the right. "naive X": → held until the path's heading (the way the chase view looks) is
// within X degrees of the ring's bearing, then let go; "cue": let go when the game's "let go now" cue
// shows (./games/flight-simulator/let-go.ts letGoCue). Prints the ring's bearing from the path's
// heading 6 s after the release (the heading error, degrees; - means turned past it), and for the cue
// the run-on the cue reckoned at the release against the turn the path made after it; the cue is
// also let go 0.2 s after it shows (a player's reaction).
import { importSource } from './build.mjs';

const fs = await importSource(
  'flight-simulator-naive-turn',
  [
    "export * from './games/flight-simulator/assist.ts';",
    "export * from './games/flight-simulator/let-go.ts';",
    "export { createPhysicsWorld, setBodyThrust, setControlDeflection, step } from '@bitphysics/physics';",
    "export { AIRCRAFT, aircraft, aircraftLevelDrag } from '@bitphysics/projects';",
  ].join('\n'),
);
const DEG = Math.PI / 180;
const wrap = (a) => Math.atan2(Math.sin(a), Math.cos(a));

/** One turn onto a ring `target` degrees right; `letGo(bearing, s, key)` says when to let go. */
function turn(target, letGo) {
  const world = fs.createPhysicsWorld(fs.aircraft.worldOptions());
  const h = fs.aircraft.build(world, { seed: 1, altitude: 900 });
  const C = world.components,
    e = h.body;
  const ring = [C.Position.x[e] + 5000 * Math.cos(target * DEG), C.Position.z[e] + 5000 * Math.sin(target * DEG)];
  const state = fs.createAssistState(),
    surface = { aileron: 0, elevator: 0, rudder: 0 },
    rate = fs.SURFACE_RATE.assist * world.dt,
    full = fs.CONTROL_AUTHORITY * DEG,
    throttle = fs.aircraftLevelDrag(130) / fs.AIRCRAFT.maxThrust;
  let key = 0,
    released = -1,
    reckoned = 0,
    trackAtRelease = 0,
    track = 0,
    bearing = 0;
  for (let i = 0; i < 60 * 40; i++) {
    const s = fs.flightState(world, e);
    track = Math.atan2(C.Velocity.z[e], C.Velocity.x[e]);
    bearing = wrap(Math.atan2(ring[1] - C.Position.z[e], ring[0] - C.Position.x[e]) - track);
    if (released < 0 && i > 0 && letGo(bearing, s, key, ring[0] - C.Position.x[e], ring[1] - C.Position.z[e], track, i * world.dt)) {
      released = i;
      reckoned = fs.runOnTurn(s.bank, s.rollRate, s.speed).turn;
      trackAtRelease = track;
    }
    if (released >= 0 && i - released >= 360) break;
    key = fs.rampKey(key, released < 0 ? 1 : 0, world.dt, fs.BANK_KEY_RAMP);
    const c = fs.assist(s, { roll: key, pitch: 0, yaw: 0 }, state, world.dt);
    for (const q of ['aileron', 'elevator', 'rudder']) surface[q] += Math.max(-rate, Math.min(rate, c[q] - surface[q]));
    fs.setControlDeflection(world, h.surfaces.tail, -surface.elevator * full);
    fs.setControlDeflection(world, h.surfaces.leftWing, surface.aileron * full * fs.AILERON_SCALE);
    fs.setControlDeflection(world, h.surfaces.rightWing, -surface.aileron * full * fs.AILERON_SCALE);
    fs.setControlDeflection(world, h.surfaces.fin, -surface.rudder * full);
    fs.setBodyThrust(world, e, [throttle * fs.AIRCRAFT.maxThrust, 0, 0]);
    fs.step(world);
  }
  return { error: bearing / DEG, reckoned: reckoned / DEG, turned: wrap(track - trackAtRelease) / DEG };
}

for (const within of [0, 2, 5]) {
  const rows = [20, 45, 90, 120].map((target) => `${target}°: ${turn(target, (b) => b < within * DEG).error.toFixed(1)}`);
  console.log(`naive ${within}°: heading error ${rows.join(' | ')}`);
}
for (const reaction of [0, 0.2]) {
  const cue = [20, 45, 90, 120].map((target) => {
    let seen = -1;
    const r = turn(target, (_b, s, key, dx, dz, track, t) => {
      const runOn = fs.runOnTurn(s.bank, s.rollRate, s.speed);
      if (seen < 0 && fs.letGoCue(fs.bearingAfterLetGo(dx, dz, track, runOn), runOn, key)) seen = t;
      return seen >= 0 && t >= seen + reaction - 1e-9;
    });
    return `${target}°: ${r.error.toFixed(1)} (run-on reckoned ${r.reckoned.toFixed(1)}, flown ${r.turned.toFixed(1)})`;
  });
  console.log(`cue, let go ${reaction} s after it shows: heading error ${cue.join(' | ')}`);
}
