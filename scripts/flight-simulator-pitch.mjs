// `node scripts/flight-simulator-pitch.mjs`: how the flight simulator's aircraft answers the climb
// and dive keys, flown as the game flies it (the assist on, the keys ramped by rampKey on KEY_RAMP,
// the surfaces following the assist at SURFACE_RATE.assist, full deflection CONTROL_AUTHORITY degrees;
// level at 130 m/s with the starting throttle, 900 m up). Prints, in game time:
// - ↑ held: s from the press until the flight path is 2, 5 and 10 degrees up, and the pitch rate's peak, degrees/s;
// - ↓ held: the same, down;
// - taps of ↑ for 100, 200 and 400 ms: the flight path's largest change, degrees, and how high it
//   settles 4 s after (the assist flies level when the key is let go: the path comes back to about 0).
import { importSource } from './build.mjs';

const fs = await importSource(
  'flight-simulator-pitch',
  [
    "export * from './games/flight-simulator/assist.ts';",
    "export { createPhysicsWorld, setBodyThrust, setControlDeflection, step } from '@bitphysics/physics';",
    "export { AIRCRAFT, aircraft, aircraftLevelDrag } from '@bitphysics/projects';",
  ].join('\n'),
);
const DEG = Math.PI / 180;

/** The aircraft level at 130 m/s, 900 m up, with the assist; `fly(pitchKey)` steps it once with the climb / dive key held (+1, -1) or not (0). */
function createFlight() {
  const world = fs.createPhysicsWorld(fs.aircraft.worldOptions());
  const h = fs.aircraft.build(world, { seed: 1, altitude: 900 });
  const state = fs.createAssistState(),
    surface = { aileron: 0, elevator: 0, rudder: 0 },
    rate = fs.SURFACE_RATE.assist * world.dt,
    full = fs.CONTROL_AUTHORITY * DEG,
    thrust = fs.aircraftLevelDrag(130);
  let key = 0;
  const fly = (direction) => {
    key = fs.rampKey(key, direction, world.dt);
    const s = fs.flightState(world, h.body);
    const c = fs.assist(s, { roll: 0, pitch: key, yaw: 0 }, state, world.dt);
    for (const k of ['aileron', 'elevator', 'rudder']) surface[k] += Math.max(-rate, Math.min(rate, c[k] - surface[k]));
    fs.setControlDeflection(world, h.surfaces.tail, -surface.elevator * full);
    const a = Math.max(-Math.PI / 4, Math.min(Math.PI / 4, surface.aileron * full * fs.AILERON_SCALE));
    fs.setControlDeflection(world, h.surfaces.leftWing, a);
    fs.setControlDeflection(world, h.surfaces.rightWing, -a);
    fs.setControlDeflection(world, h.surfaces.fin, -surface.rudder * full);
    fs.setBodyThrust(world, h.body, [thrust, 0, 0]);
    fs.step(world);
    return fs.flightState(world, h.body);
  };
  // Settle level first.
  for (let k = 0; k < 120; k++) fly(0);
  return { world, fly };
}

for (const sign of [1, -1]) {
  const { world, fly } = createFlight();
  const marks = [2, 5, 10],
    at = {};
  let peak = 0;
  for (let t = 0; t < 4; t += world.dt) {
    const s = fly(sign);
    peak = Math.max(peak, sign * s.pitchRate);
    for (const m of marks) if (at[m] === undefined && sign * s.path >= m * DEG) at[m] = t;
  }
  console.log(
    `${sign > 0 ? '↑' : '↓'} held: path ${marks.map((m) => `${m}° at ${at[m]?.toFixed(2) ?? '-'} s`).join(', ')}; peak pitch rate ${(peak / DEG).toFixed(1)}°/s`,
  );
}
for (const ms of [100, 200, 400]) {
  const { world, fly } = createFlight();
  let most = 0,
    s;
  for (let t = 0; t < 5; t += world.dt) {
    s = fly(t < ms / 1000 ? 1 : 0);
    most = Math.max(most, s.path);
  }
  console.log(`↑ tap ${ms} ms: path up to ${(most / DEG).toFixed(1)}°, ${(s.path / DEG).toFixed(1)}° after 5 s`);
}
