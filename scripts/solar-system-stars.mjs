// `node scripts/solar-system-stars.mjs [launches]`: random launches on the solar system's missions 2
// to 4 as a player who taps Wait (to the next launch window, games/solar-system/wait-pace.ts) then
// picks a speed makes them: start day uniform in [0, 700), launched within 15 days either side of
// the next window, the page's starting direction, speed uniform from 0.4 km/s under the Hohmann
// speed to the mission's 2-star speed, in 0.05 km/s steps, each flown by the page's forecast
// (games/solar-system/forecast.ts forecastLaunch, the flight's own physics): how many arrive, how
// many earned three stars before (an arrival at no more than the 3-star speed) and how many now
// (games/solar-system/aim-depth.ts skillStars: also centred within STAR_RINGS), and how many the
// coarse words call "close". Too many three-star random launches: the mission is too easy.
import { importSource } from './build.mjs';

const m = await importSource(
  'solar-system-stars',
  `export * from './games/solar-system/missions.ts';
export * from './games/solar-system/forecast.ts';
export * from './games/solar-system/meeting-words.ts';
export * from './games/solar-system/aim-depth.ts';
export { startAim } from './games/solar-system/advice.ts';
export { nextLaunchWindow } from './games/solar-system/wait-pace.ts';
export { createPhysicsWorld, setTimeStep, slotOf, step } from '@bitphysics/physics';
export { solarSystem } from '@bitphysics/projects';`,
);
const N = Number(process.argv[2] ?? 40);
const BASE = 1 / 24;
let seed = 12345;
const rand = () => (seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648;
for (const n of [2, 3, 4]) {
  const mission = m.MISSIONS[n - 1];
  let arrived = 0,
    old3 = 0,
    new3 = 0,
    close = 0,
    closeAndNew3 = 0;
  const cheapRings = [];
  for (let i = 0; i < N; i++) {
    const options = { stepHours: 1, integrator: 'rk4', date: '2012-01-01T00:00:00Z' };
    const world = m.createPhysicsWorld(m.solarSystem.worldOptions(options));
    const handles = m.solarSystem.build(world, options);
    const dt = m.missionTimeStep(mission, BASE);
    m.setTimeStep(world, dt);
    for (let k = Math.round((rand() * 700) / dt); k > 0; k--) m.step(world);
    const mu = world.laws.gravitationalConstant * world.components.Mass.value[m.slotOf(handles.bodies.Sun)];
    const earth = [...m.heliocentricState(world, handles, handles.bodies.Earth)];
    const tgt = [...m.heliocentricState(world, handles, handles.bodies[mission.target])];
    const win = m.nextLaunchWindow(earth, tgt, mu, { next: 0, period: 0 });
    for (let k = Math.round(Math.max(0, win.next + (rand() * 30 - 15)) / dt); k > 0; k--) m.step(world);
    const start = m.startAim(world, handles, mission, BASE);
    const vH = Math.abs(m.hohmannSpeed(1, mission.distance, mu));
    const speed = Math.round((vH - 0.4 + rand() * (mission.stars2 - vH + 0.4)) * 20) / 20;
    const aim = { angle: start.angle, speed };
    const f = m.forecastLaunch(world, handles, mission, aim, BASE);
    const rings = m.aimRings(world, handles, mission, aim);
    const target = [...m.heliocentricState(world, handles, handles.bodies[mission.target])];
    // The line names an arrival's stars: "close" here is a line reading ✓ with three of them.
    const words = m.forecastWords(mission.target, f, mission.zone, target, '★'.repeat(m.skillStars(n - 1, mission, speed, rings, 0)))[0];
    const isClose = /★★★/.test(words);
    if (isClose) close++;
    if (f.outcome !== 'arrived') continue;
    arrived++;
    if (m.starsFor(mission, speed) === 3) {
      old3++;
      cheapRings.push(rings.toFixed(2));
    }
    const s = m.skillStars(n - 1, mission, speed, rings, 0);
    if (s === 3) new3++;
    if (s === 3 && isClose) closeAndNew3++;
  }
  console.log(
    `mission ${n} (${mission.target}): ${N} random launches, ${arrived} arrive; 3 stars before ${old3}, now ${new3}; ` +
      `words "close" ${close} (of them 3 stars now: ${closeAndNew3}); aim rings of the cheap arrivals: ${cheapRings.join(' ')}`,
  );
}
