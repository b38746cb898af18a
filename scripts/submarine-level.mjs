// `node scripts/submarine-level.mjs [--off]`: a naive pilot diving (or rising) to a beacon's depth on the
// keys, headless on a calm sea (games/submarine: the helm as the page steers it, keyHeaveShare for the
// keys' share, level-stop.ts for the stop at the beacon's depth; --off leaves the stop out, as the page
// was before it). From a hover 10 m down (Rise: 50 m down), the screw stopped or at full ahead, Dive
// (Rise) held until the pilot sees the hull level with the beacon D m further down (up; within 1.5 m) and then, after
// a reaction of R s, let go; the boat left to stop. The pilot watches the hull, not the line of the
// order. Prints how far from the beacon's depth the boat stops (m, + past it) for each D, R and screw,
// and how many of the runs stop within the ring's reach (beacons.ts BEACON_CATCH plus half the hull)
// and within 3 m of the beacon's depth.
import { importSource } from './build.mjs';

const off = process.argv.includes('--off');
const sub = await importSource(
  'submarine-level',
  `export * from './games/submarine/helm.ts';
   export * from './games/submarine/level-stop.ts';
   export { BEACON_CATCH } from './games/submarine/beacons.ts';
   export { SUBMARINE, SUBMARINE_NEUTRAL_FILL, submarine } from '@bitphysics/projects';
   export { createPhysicsWorld, step } from '@bitphysics/physics';`,
);
const {
  createHelmState,
  keyHeaveShare,
  steer,
  NO_INPUT,
  createLevelStop,
  levelStop,
  BEACON_CATCH,
  SUBMARINE,
  SUBMARINE_NEUTRAL_FILL,
  submarine,
  createPhysicsWorld,
  step,
} = sub;

/** Stop error (m, positive past the beacon's depth) of a dive (dir -1) or climb (dir 1) of `depth` m, let go `react` s after the hull is level, screw at `drive`. */
function run(dir, depth, react, drive) {
  const world = createPhysicsWorld(submarine.worldOptions());
  const y0 = dir < 0 ? -10 : -50;
  const h = submarine.build(world, { seed: 1, count: 0, fill: SUBMARINE_NEUTRAL_FILL, position: [0, y0] });
  world.components.FluidRegion.surface.fill(0);
  h.seabed.y.fill(-1000);
  const helm = createHelmState(SUBMARINE_NEUTRAL_FILL);
  const c = world.components,
    e = h.hull;
  const by = y0 + dir * depth;
  const stop = createLevelStop();
  let letGoAt = Number.POSITIVE_INFINITY;
  for (let i = 0; i < 60 * 20; i++) {
    const t = world.time,
      y = c.Position.y[e];
    if (letGoAt === Number.POSITIVE_INFINITY && (y - by) * dir >= -SEEN_LEVEL) letGoAt = t + react;
    const held = t < letGoAt;
    const input = { ...NO_INPUT, ahead: drive > 0, drive: drive || 1 };
    if (held) Object.assign(input, { dive: dir < 0, rise: dir > 0, heave: keyHeaveShare(0, t, c.Velocity.x[e]) });
    const hold =
      !off &&
      levelStop(stop, { dir: held ? dir : 0, now: t, beacon: 0, beaconY: by, order: helm.holdY, y, vy: c.Velocity.y[e], warned: false });
    if (hold) {
      helm.holdY = by;
      input.dive = input.rise = false;
    }
    steer(world, h, input, helm);
    step(world);
  }
  return (c.Position.y[e] - by) * dir;
}

/** The pilot sees the hull level with the beacon within this, m (an eighth of the hull's 12 m length). */
const SEEN_LEVEL = 1.5;
const reach = BEACON_CATCH + SUBMARINE.height / 2;
let runs = 0,
  inReach = 0,
  near = 0;
for (const dir of [-1, 1])
  for (const drive of [0, 1]) {
    console.log(
      `${dir < 0 ? 'Dive' : 'Rise'}, screw ${drive ? 'full ahead' : 'stopped'}: stop past the beacon's depth, m (rows: reaction s; columns: depth to go, m)`,
    );
    const depths = [8, 15, 25, 35];
    console.log(`  react | ${depths.map((d) => String(d).padStart(6)).join('')}`);
    for (const react of [0.25, 0.5, 0.75, 1, 1.5]) {
      const row = depths.map((d) => {
        const err = run(dir, d, react, drive);
        runs++;
        if (Math.abs(err) < reach) inReach++;
        if (Math.abs(err) < 3) near++;
        return err.toFixed(1).padStart(6);
      });
      console.log(`  ${String(react).padStart(5)} | ${row.join('')}`);
    }
  }
console.log(
  `${off ? 'without' : 'with'} the level stop: ${inReach} of ${runs} stops within the ring's reach (${reach} m), ${near} within 3 m`,
);
