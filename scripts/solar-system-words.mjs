// `node scripts/solar-system-words.mjs [mission ...]`: a simulated player follows the solar system's
// coarse words before a launch (games/solar-system/meeting-words.ts) from several start days, and
// reports how often the launches it makes on "close" arrive, and how many presses it took. The
// player starts at the page's starting aim (./advice.ts startAim) and each move: short of the
// target's orbit, ↑ (0.1 km/s faster); "far", a tap of Wait (10 days); "a little behind" (the
// target still to come: the probe early), ↓; "a little ahead", ↑; "close", Launch, the forecast's
// outcome being the flight's; when a speed change would flip the side, go short of the orbit or past
// the mission's 2-star speed, a tap of Wait instead. It gives up after 120 moves. Both the words now (the real flight's
// closest approach: forecastWords) and the words before (the target's lag where the probe crosses
// its orbit: 25 and 90 days) are played. Missions default to 2 (Venus) and 4 (Mercury).
import { importSource } from './build.mjs';

const m = await importSource(
  'solar-system-words',
  `export * from './games/solar-system/missions.ts';
export * from './games/solar-system/forecast.ts';
export * from './games/solar-system/meeting-words.ts';
export * from './games/solar-system/orbit-crossing.ts';
export { startAim } from './games/solar-system/advice.ts';
export { createPhysicsWorld, setTimeStep, slotOf, step } from '@bitphysics/physics';
export { solarSystem } from '@bitphysics/projects';`,
);
const chosen = process.argv.slice(2).map(Number);
const missions = chosen.length ? chosen : [2, 4];
const BASE = 1 / 24;

/** The words before: the target's lag at the crossing the page compared (25 / 90 days bands). */
function oldWords(name, f, target, mu) {
  const i = m.meetingPoint(f, target, mu);
  if (i < 0) return null;
  const lag = m.targetLag(f, i, target, mu);
  const days = Math.round(Math.abs(lag));
  if (days <= 25) return `${name} will be close`;
  return `${name} will be ${days > 90 ? 'far' : 'a little'} ${lag > 0 ? 'behind' : 'ahead'}`;
}

for (const n of missions) {
  const mission = m.MISSIONS[n - 1];
  for (const which of ['before', 'now']) {
    let launches = 0,
      hits = 0,
      moves = 0,
      missRings = [];
    for (let start = 0; start < 600; start += 75) {
      const options = { stepHours: 1, integrator: 'rk4', date: '2012-01-01T00:00:00Z' };
      const world = m.createPhysicsWorld(m.solarSystem.worldOptions(options));
      const handles = m.solarSystem.build(world, options);
      const mu = world.laws.gravitationalConstant * world.components.Mass.value[m.slotOf(handles.bodies.Sun)];
      const dt = m.missionTimeStep(mission, BASE);
      m.setTimeStep(world, dt);
      for (let k = Math.round(start / dt); k > 0; k--) m.step(world);
      const aim = { ...m.startAim(world, handles, mission, BASE) };
      let floor = 0,
        lastSide = '';
      for (let move = 0; move < 120; move++) {
        moves++;
        const target = [...m.heliocentricState(world, handles, handles.bodies[mission.target])];
        const f = m.forecastLaunch(world, handles, mission, aim, BASE);
        const crosses = f.outcome !== 'sun' && m.meetingPoint(f, target, mu) >= 0;
        const words = !crosses
          ? null
          : which === 'now'
            ? m.forecastWords(mission.target, f, mission.zone, target)[0]
            : oldWords(mission.target, f, target, mu);
        const side = words === null ? '' : (words.match(/behind|ahead/)?.[0] ?? '');
        const flipped = side !== '' && lastSide !== '' && side !== lastSide;
        if (side !== '') lastSide = side;
        if (words === null) {
          floor = Math.max(floor, aim.speed);
          aim.speed = Math.round((aim.speed + 0.1) * 10) / 10;
        } else if (flipped || (side === 'behind' && aim.speed - 0.1 <= floor + 1e-9) || (side === 'ahead' && aim.speed >= mission.stars2)) {
          for (let k = Math.round(10 / dt); k > 0; k--) m.step(world);
          lastSide = '';
        } else if (/close/.test(words)) {
          launches++;
          if (f.outcome === 'arrived') hits++;
          missRings.push(f.closest / mission.zone);
          break;
        } else if (/far/.test(words)) for (let k = Math.round(10 / dt); k > 0; k--) m.step(world);
        else if (/behind/.test(words)) aim.speed = Math.round((aim.speed - 0.1) * 10) / 10;
        else aim.speed = Math.round((aim.speed + 0.1) * 10) / 10;
      }
    }
    missRings.sort((a, b) => a - b);
    console.log(
      `mission ${n} (${mission.target}), words ${which}: ${launches}/8 starts launched on "close", ${hits} arrived; ` +
        `moves ${moves}; closest approach of the launches (rings): ${missRings.map((r) => r.toFixed(2)).join(' ')}`,
    );
  }
}
