// `node scripts/solar-system-pilot.mjs [--wait=800] [mission ...]`: a scripted pilot flies the solar
// system's missions (games/solar-system/missions.ts) one after the other, as a player pressing Next
// mission would: each starts on the day the last one arrived (the first on 2012-01-01). For each it
// searches the Kepler plan (planFlightLater) for the cheapest launch that arrives within `--wait`
// days of waiting (launch directions within 40 degrees of the Hohmann transfer's, every 4 degrees;
// speeds every 0.1 km/s), waits that long in the physics world, checks the launch with the page's
// forecast (the flight flown ahead; if it misses, the speed is raised 0.1 km/s at a time, then the
// direction turned 2 degrees either way), then flies it in the world and reports the stars, the score
// (missionScore), the margin to the 3-star line (km/s) and how many of the 8 neighbouring launches
// (0.1 km/s and 2 degrees either way, and both together) also arrive. Exits 1 if a mission cannot be
// won. Takes a few minutes.
import { importSource } from './build.mjs';

const args = process.argv.slice(2);
const waitArg = args.find((a) => a.startsWith('--wait='));
const maxWait = waitArg ? Number(waitArg.slice(7)) : 800;
if (!(Number.isFinite(maxWait) && maxWait >= 0)) throw new RangeError(`solar-system-pilot: --wait must be days >= 0, got ${maxWait}`);

const m = await importSource(
  'solar-system-pilot',
  `export * from './games/solar-system/missions.ts';
export * from './games/solar-system/forecast.ts';
export { createPhysicsWorld, setTimeStep, step } from '@bitphysics/physics';
export { solarSystem } from '@bitphysics/projects';`,
);
const chosen = args.filter((a) => !a.startsWith('--')).map(Number);
for (const n of chosen)
  if (!(Number.isInteger(n) && n >= 1 && n <= m.MISSIONS.length))
    throw new RangeError(`solar-system-pilot: missions are 1 to ${m.MISSIONS.length}, got ${n}`);
const missions = chosen.length ? chosen : m.MISSIONS.map((_, i) => i + 1);

/** The page's aiming step, days (one hour). */
const BASE = 1 / 24;
const GAUSS_MU = 0.01720209895 ** 2;
const wrap = (a) => (a > 180 ? a - 360 : a <= -180 ? a + 360 : a);
const round1 = (x) => Math.round(x * 10) / 10;

const options = { stepHours: 1, integrator: 'rk4', date: '2012-01-01T00:00:00Z' };
const world = m.createPhysicsWorld(m.solarSystem.worldOptions(options));
const handles = m.solarSystem.build(world, options);
const plan = m.createFlightPlan();
let failed = 0;

/** The cheapest launch the Kepler plan calls a hit within maxWait days: { days, angle, speed } or null. */
function cheapest(mission) {
  const vH = m.hohmannSpeed(1, mission.distance, GAUSS_MU);
  const centre = vH >= 0 ? 0 : 180;
  let best = null;
  for (let days = 0; days <= maxWait; days += 10)
    for (
      let speed = round1(Math.max(0.5, Math.abs(vH) - 1));
      speed <= (best ? best.speed - 0.05 : mission.stars2 + 2);
      speed = round1(speed + 0.1)
    )
      for (let turn = -40; turn <= 40; turn += 4) {
        const aim = { angle: wrap(centre + turn), speed };
        if (m.planFlightLater(world, handles, mission, aim, days, plan, 100).hit && (!best || speed < best.speed)) best = { days, ...aim };
      }
  return best;
}

const arrives = (mission, aim) => m.forecastLaunch(world, handles, mission, aim, BASE).outcome === 'arrived';

for (const n of missions) {
  const mission = m.MISSIONS[n - 1];
  const startDay = world.time;
  const found = cheapest(mission);
  if (!found) {
    console.log(`${n} ${mission.target}: no launch within ${maxWait} days arrives by the Kepler plan`);
    failed++;
    continue;
  }
  m.setTimeStep(world, m.missionTimeStep(mission, BASE));
  while (world.time < startDay + found.days - 1e-9) m.step(world);
  let aim = { angle: found.angle, speed: found.speed };
  let tries = 0;
  while (!arrives(mission, aim) && tries < 30) {
    tries++;
    const k = Math.ceil(tries / 3),
      t = tries % 3;
    aim = { angle: wrap(found.angle + (t === 1 ? 2 : t === 2 ? -2 : 0)), speed: round1(found.speed + 0.1 * k) };
  }
  const neighbours = [];
  for (const dv of [-0.1, 0, 0.1])
    for (const da of [-2, 0, 2]) if (dv !== 0 || da !== 0) neighbours.push({ angle: wrap(aim.angle + da), speed: round1(aim.speed + dv) });
  const near = neighbours.filter((a) => arrives(mission, a)).length;
  m.planFlight(world, handles, mission, aim, plan);
  const flight = m.launchProbe(world, handles, mission, aim, plan, BASE);
  m.setTimeStep(world, flight.dt);
  do m.step(world);
  while (m.checkFlight(world, handles, flight) === 'flying');
  m.endFlight(world, flight);
  if (flight.state !== 'arrived') {
    console.log(`${n} ${mission.target}: the pilot's launch ${aim.angle} deg ${aim.speed} km/s ended '${flight.state}'`);
    failed++;
    continue;
  }
  const stars = m.starsFor(mission, aim.speed);
  const score = m.missionScore(mission, aim.speed, flight.elapsed);
  console.log(
    `${n} ${mission.target.padEnd(8)} from day ${Math.round(startDay).toString().padStart(5)}: wait ${String(found.days).padStart(3)} d, ` +
      `${String(aim.angle).padStart(4)} deg ${aim.speed.toFixed(1).padStart(4)} km/s (Hohmann ${Math.abs(m.hohmannSpeed(1, mission.distance, GAUSS_MU)).toFixed(2)}), ` +
      `arrives day ${Math.round(flight.elapsed)}: ${'*'.repeat(stars)} score ${score.total} (${score.budget} + ${score.time}); ` +
      `3-star margin ${(mission.stars3 - aim.speed).toFixed(1)} km/s; neighbours arriving ${near}/8`,
  );
}
if (failed > 0) process.exit(1);
