// `node scripts/submarine-dive-curve.mjs`: the depth a held Dive key gives (games/submarine/helm.ts,
// keyHeaveShare as the page applies it), headless on a calm sea: from a hover at 40 m, Dive held for
// each time, let go, and the boat left to stop on its order. Prints the depth gone down (m) for each
// hold time, and the same for Rise from 80 m. Then the glide: from a steady speed ahead at 40 m (full
// ahead, and the screw at a share), Ahead let go (or Astern held) and the distance run until the boat
// is slower than 0.2 m/s. Last, Dive held (as a key, at the boat's speed) for 1.5 s from a steady
// speed at 31 m, with the screw stopped, at half and at full ahead: the depth gone at 0.25 to 1.5 s.
// Last, "let go: stop at the line": Dive held to a depth 20 m below the start, let go when the line seen
// on the screen reaches it, at 60 and 10 frames a second (the pacer putting every frame, or one in two,
// on the screen), with and without release.ts (the let-go holds the line last drawn): how far past
// the line the boat stops, m.
import { importSource } from './build.mjs';

const sub = await importSource(
  'submarine-dive-curve',
  `export * from './games/submarine/helm.ts';
   export { releasedOrder } from './games/submarine/release.ts';
   export { SUBMARINE, SUBMARINE_NEUTRAL_FILL, submarine } from '@bitphysics/projects';
   export { createPhysicsWorld, step } from '@bitphysics/physics';`,
);
const {
  createHelmState,
  keyHeaveShare,
  releasedOrder,
  steer,
  NO_INPUT,
  SUBMARINE,
  SUBMARINE_NEUTRAL_FILL,
  submarine,
  createPhysicsWorld,
  step,
} = sub;

/** Depth change (m, positive the way asked) after holding `key` ('dive' or 'rise') for `held` s from a hover at `y0` m. */
function hold(key, held, y0) {
  const world = createPhysicsWorld(submarine.worldOptions());
  const h = submarine.build(world, { seed: 1, count: 0, fill: SUBMARINE_NEUTRAL_FILL, position: [0, y0] });
  world.components.FluidRegion.surface.fill(0);
  const helm = createHelmState(SUBMARINE_NEUTRAL_FILL);
  const run = (input, seconds) => {
    for (let i = 0; i < Math.round(seconds / world.dt); i++) {
      steer(world, h, { ...NO_INPUT, ...input }, helm);
      step(world);
    }
  };
  run({}, 2);
  const start = world.components.Position.y[h.hull];
  let t = 0;
  for (let i = 0; i < Math.round(held / world.dt); i++, t += world.dt) {
    steer(world, h, { ...NO_INPUT, [key]: true, heave: keyHeaveShare(0, t) }, helm);
    step(world);
  }
  run({}, 6);
  const end = world.components.Position.y[h.hull];
  return key === 'dive' ? start - end : end - start;
}

const times = [0.1, 0.25, 0.5, 1, 2, 3, 4, 6];
console.log(`hold s  | ${times.map((t) => String(t).padStart(5)).join(' ')}`);
console.log(`dive m  | ${times.map((t) => hold('dive', t, -40).toFixed(1).padStart(5)).join(' ')}`);
console.log(`rise m  | ${times.map((t) => hold('rise', t, -90).toFixed(1).padStart(5)).join(' ')}`);

/**
 * From a hover at 40 m, the screw at `drive` (share of full ahead) for 15 s, then `input` held:
 * the speed let go at (m/s), the distance run (m) and the time (s) until slower than 0.2 m/s.
 */
function glide(drive, input) {
  const world = createPhysicsWorld(submarine.worldOptions());
  const h = submarine.build(world, { seed: 1, count: 0, fill: SUBMARINE_NEUTRAL_FILL, position: [0, -40] });
  world.components.FluidRegion.surface.fill(0);
  const helm = createHelmState(SUBMARINE_NEUTRAL_FILL);
  const P = world.components.Position.x,
    V = world.components.Velocity.x,
    e = h.hull;
  for (let i = 0; i < Math.round(15 / world.dt); i++) {
    steer(world, h, { ...NO_INPUT, ahead: true, drive }, helm);
    step(world);
  }
  const x0 = P[e],
    v0 = V[e];
  let t = 0;
  while (V[e] > 0.2 && t < 60) {
    steer(world, h, { ...NO_INPUT, ...input }, helm);
    step(world);
    t += world.dt;
  }
  return `from ${v0.toFixed(1)} m/s: ${(P[e] - x0).toFixed(1)} m in ${t.toFixed(1)} s`;
}
const top = Math.sqrt(SUBMARINE.maxThrust / SUBMARINE.dragCoefficient);
for (const v of [top, 9, 6, 3]) {
  const drive = Math.min(1, (v / top) ** 2);
  console.log(`let go ${glide(drive, {})} | Astern ${glide(drive, { astern: true })}`);
}

/** A calm sea's boat at 31 m after 15 s with the screw at `drive` (share of full ahead): world, handles, helm. */
function steadyAt31(drive) {
  const world = createPhysicsWorld(submarine.worldOptions());
  const h = submarine.build(world, { seed: 1, count: 0, fill: SUBMARINE_NEUTRAL_FILL, position: [0, -31] });
  world.components.FluidRegion.surface.fill(0);
  const helm = createHelmState(SUBMARINE_NEUTRAL_FILL);
  for (let i = 0; i < Math.round(15 / world.dt); i++) {
    steer(world, h, { ...NO_INPUT, ahead: true, drive }, helm);
    step(world);
  }
  return { world, h, helm };
}

/**
 * From a steady speed at 31 m (the screw at `drive`, share of full ahead, for 15 s), Dive held (as a
 * key) with Ahead for `held` s: the depth gone at each of `marks` s (m) and the speed down at the end (m/s).
 */
function diveUnderWay(drive, held, marks) {
  const { world, h, helm } = steadyAt31(drive);
  const Y = world.components.Position.y,
    e = h.hull;
  const y0 = Y[e];
  const out = [];
  let t = 0;
  for (let i = 0; i < Math.round(held / world.dt); i++) {
    steer(world, h, { ...NO_INPUT, ahead: true, drive, dive: true, heave: keyHeaveShare(0, t, world.components.Velocity.x[e]) }, helm);
    step(world);
    t += world.dt;
    for (const m of marks) if (Math.abs(t - m) < world.dt / 2) out.push((y0 - Y[e]).toFixed(1).padStart(5));
  }
  return `${out.join(' ')} | ${(-world.components.Velocity.y[e]).toFixed(1)} m/s down, ${world.components.Velocity.x[e].toFixed(1)} m/s ahead`;
}
const marks = [0.25, 0.5, 0.75, 1, 1.5];
console.log(`Dive held under way, m gone at ${marks.join(', ')} s:`);
for (const drive of [0, 0.5, 1]) console.log(`screw ${drive}: ${diveUnderWay(drive, 1.5, marks)}`);

/**
 * Dive held (a key, with the screw at `drive`) from 31 m, frames of `k` steps (k = 1: 60 fps), one
 * in `every` put on the screen, each seen a frame after it is drawn; the pilot lets go `react` s after
 * the line seen reaches 20 m further down, the key-up read at the next frame. With `hold` (release.ts)
 * the let-go holds the line last drawn. Returns how far past the target the boat stops, m.
 */
function stopAtLine(drive, k, every, react, hold) {
  const { world, h, helm } = steadyAt31(drive);
  const Y = world.components.Position.y,
    e = h.hull;
  const target = Y[e] - 20;
  let diving = true,
    drawn = Number.NaN,
    onScreen = Number.NaN,
    onScreenAt = Number.POSITIVE_INFINITY,
    letGoAt = Number.POSITIVE_INFINITY,
    t = 0;
  for (let f = 0; t < 20; f++) {
    if (diving && t >= letGoAt) {
      diving = false;
      if (hold) helm.holdY = releasedOrder(helm.holdY, onScreen, helm.mode);
    }
    for (let i = 0; i < k; i++, t += world.dt) {
      const u = world.components.Velocity.x[e];
      steer(world, h, { ...NO_INPUT, ahead: drive > 0, drive, dive: diving, heave: keyHeaveShare(0, t, u) }, helm);
      step(world);
    }
    // The frame drawn a frame ago reaches the screen now; this one is drawn (or skipped by the pacer).
    if (f >= onScreenAt) onScreen = drawn;
    if (f % every === 0) {
      drawn = helm.holdY;
      onScreenAt = f + 1;
    }
    if (diving && letGoAt === Number.POSITIVE_INFINITY && onScreen <= target) letGoAt = t + react;
  }
  return target - Y[e];
}
console.log('Let go at the line 20 m down: stopped past it, m (before | after release.ts):');
for (const drive of [0, 1])
  for (const react of [0, 0.25])
    for (const [k, every, name] of [
      [1, 1, '60 fps'],
      [6, 1, '10 fps'],
      [6, 2, '10 fps, 1 in 2 drawn'],
    ])
      console.log(
        `screw ${drive}, react ${react} s, ${name.padEnd(20)}: ${stopAtLine(drive, k, every, react, false).toFixed(1).padStart(5)} | ${stopAtLine(drive, k, every, react, true).toFixed(1).padStart(5)}`,
      );
