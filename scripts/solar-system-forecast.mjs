// `node scripts/solar-system-forecast.mjs [--dates=0,150,400] [mission ...]`: checks that the solar
// system's forecast (games/solar-system/forecast.ts), which the page shows before a launch, is what
// the launch does. For each mission (1-based; default all seven) and each start (days after
// 2012-01-01), it takes a spread of launches around the first the Kepler plan calls a hit (that
// launch, turned 2 and 6 degrees either way, 0.1 and 0.3 km/s faster and slower, and a clear miss),
// forecasts each, then launches it in the physics world (games/solar-system/missions.ts
// launchProbe, stepped with the flight's step and checked after every step, as the page flies it)
// and compares: the verdict (arrived, fell into the Sun, missed), the day it ended and the closest
// approach. Also counts how often the Kepler plan's verdict disagreed with the flight, and how often
// the page's earlier line, "reaches Mars's orbit · if Mars is there: ★★★" (any launch whose Kepler
// path reached the target's orbit), was shown for a launch that then missed. Prints one line a
// launch and a summary; exits 1 if a forecast's verdict differs from its flight. Takes a few
// minutes (each flight is thousands of world steps).
import { importSource } from './build.mjs';

const args = process.argv.slice(2);
const datesArg = args.find((a) => a.startsWith('--dates='));
const dates = (datesArg ? datesArg.slice(8) : '0,150,400').split(',').map(Number);
for (const d of dates)
  if (!(Number.isFinite(d) && d >= 0)) throw new RangeError(`solar-system-forecast: --dates must be days >= 0, got ${d}`);

const m = await importSource(
  'solar-system-forecast',
  `export * from './games/solar-system/missions.ts';
export * from './games/solar-system/forecast.ts';
export { createPhysicsWorld, setTimeStep, step } from '@bitphysics/physics';
export { solarSystem } from '@bitphysics/projects';`,
);
const chosen = args.filter((a) => !a.startsWith('--')).map(Number);
for (const n of chosen)
  if (!(Number.isInteger(n) && n >= 1 && n <= m.MISSIONS.length))
    throw new RangeError(`solar-system-forecast: missions are 1 to ${m.MISSIONS.length}, got ${n}`);
const missions = chosen.length ? chosen : m.MISSIONS.map((_, i) => i + 1);

/** The page's aiming step, days (one hour). */
const BASE = 1 / 24;

/** A world at 2012-01-01 stepped on `days` with the mission's step (as the page waits). */
function worldAt(mission, days) {
  const options = { stepHours: 1, integrator: 'rk4', date: '2012-01-01T00:00:00Z' };
  const world = m.createPhysicsWorld(m.solarSystem.worldOptions(options));
  const handles = m.solarSystem.build(world, options);
  m.setTimeStep(world, m.missionTimeStep(mission, BASE));
  while (world.time < days - 1e-9) m.step(world);
  return { world, handles };
}

/** The first launch on a coarse grid (15 degrees, 0.25 km/s) the Kepler plan calls a hit, or null. */
function firstHit(world, handles, mission) {
  const plan = m.createFlightPlan();
  for (let speed = 0.5; speed <= m.MAX_SPEED; speed += 0.25)
    for (let angle = -165; angle <= 180; angle += 15)
      if (m.planFlight(world, handles, mission, { angle, speed }, plan, 100).hit) return { angle, speed };
  return null;
}

const wrap = (a) => (a > 180 ? a - 360 : a <= -180 ? a + 360 : a);
let flights = 0,
  reachesShown = 0,
  reachesMissed = 0,
  disagree = 0,
  keplerWrong = 0,
  worstClosest = 0,
  worstDay = 0,
  arrivals = 0;
for (const n of missions) {
  const mission = m.MISSIONS[n - 1];
  for (const day of dates) {
    const probe = worldAt(mission, day);
    const hit = firstHit(probe.world, probe.handles, mission);
    if (!hit) {
      console.log(`${mission.target} day ${day}: no launch on the grid arrives by the Kepler plan`);
      continue;
    }
    const aims = [
      hit,
      ...[-6, -2, 2, 6].map((t) => ({ angle: wrap(hit.angle + t), speed: hit.speed })),
      ...[-0.3, -0.1, 0.1, 0.3].map((dv) => ({ angle: hit.angle, speed: Math.round((hit.speed + dv) * 100) / 100 })),
      { angle: wrap(hit.angle + 90), speed: Math.max(0, hit.speed - 1) },
    ];
    for (const aim of aims) {
      const { world, handles } = worldAt(mission, day);
      const now = m.heliocentricState(world, handles, handles.bodies[mission.target]);
      const rT = Math.hypot(now[0], now[1], now[2]);
      const forecast = m.forecastLaunch(world, handles, mission, aim, BASE);
      const plan = m.planFlight(world, handles, mission, aim, m.createFlightPlan());
      const flight = m.launchProbe(world, handles, mission, aim, plan, BASE);
      m.setTimeStep(world, flight.dt);
      do m.step(world);
      while (m.checkFlight(world, handles, flight) === 'flying');
      flights++;
      if (flight.state === 'arrived') arrivals++;
      const same = forecast.outcome === flight.state;
      if (!same) disagree++;
      if (plan.hit !== (flight.state === 'arrived')) keplerWrong++;
      // The earlier line: "reaches <target>'s orbit · if <target> is there" for a path that got there.
      const outward = mission.distance > 1;
      if (!plan.sun && (outward ? plan.farthest >= rT - mission.zone : plan.nearest <= rT + mission.zone)) {
        reachesShown++;
        if (flight.state !== 'arrived') reachesMissed++;
      }
      const dClosest = Math.abs(forecast.closest - flight.closest),
        dDay = Math.abs(forecast.end - flight.elapsed);
      worstClosest = Math.max(worstClosest, dClosest);
      worstDay = Math.max(worstDay, dDay);
      console.log(
        `${mission.target.padEnd(8)} day ${String(day).padStart(3)} ${String(aim.angle).padStart(5)} deg ${aim.speed.toFixed(2).padStart(5)} km/s: ` +
          `forecast ${forecast.outcome.padEnd(7)} day ${forecast.end.toFixed(1).padStart(6)} closest ${forecast.closest.toFixed(4)} AU | ` +
          `flight ${flight.state.padEnd(7)} day ${flight.elapsed.toFixed(1).padStart(6)} closest ${flight.closest.toFixed(4)} AU | ` +
          `Kepler plan ${plan.hit ? 'hit ' : 'miss'} ${plan.distance.toFixed(4)} AU${same ? '' : '   <-- forecast differs'}`,
      );
    }
  }
}
console.log(
  `\n${flights} launches (${arrivals} arrived): the forecast's verdict differs from the flight's in ${disagree}; ` +
    `largest difference ${worstClosest.toExponential(1)} AU in the closest approach, ${worstDay.toExponential(1)} days in the end. ` +
    `The Kepler plan's verdict (hit within ${m.PLAN_MARGIN} of the ring) differed in ${keplerWrong}. ` +
    `The earlier "reaches the orbit · if it is there" line was shown for ${reachesShown}, of which ${reachesMissed} missed.`,
);
if (disagree > 0) process.exit(1);
