// `node scripts/rotating-cube-flips.mjs [--source games/rotating-cube]`: what rotating cube's flip round
// (the flipping box) gives to simple inputs. Each row is one key of the page's six (W S, A D, Q E: a
// torque of 0.5 N m times scene.ts FLIP_PUSH about the default view's right, up and viewing axes, as
// the page's keys give) held from the round's first input for 0.5 to 8 s, then nothing until the round
// ends (FLIP_TIME s after);
// the table shows per hold the flips counted and the stars (0: lost). A round needs the player's input
// to start, so no input wins nothing. `--source` plays another copy of the game's scene.ts (a folder
// inside the repository, e.g. an older version checked out under node_modules/, for a before/after).
import { importSource } from './build.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : fallback;
};
const source = arg('--source', 'games/rotating-cube').replace(/\/$/, '');
const m = await importSource(
  'rotating-cube-flips',
  `export * from './${source}/scene.ts'; export { addSystem, createPhysicsWorld, step, spinAngularMomentum } from '@bitphysics/physics';`,
);

// The default view of the pivot modes looks from (1, 0.7, 1.4) at the box (main.ts viewDirectionOf):
// three.js's lookAt gives right = world up x back, up = back x right.
const n = Math.hypot(1, 0.7, 1.4);
const back = [1 / n, 0.7 / n, 1.4 / n];
const rl = Math.hypot(back[2], back[0]);
const right = [back[2] / rl, 0, -back[0] / rl];
const up = [back[1] * right[2] - back[2] * right[1], back[2] * right[0] - back[0] * right[2], back[0] * right[1] - back[1] * right[0]];
/** Each key's torque axis and sign (main.ts updateKeyTorque, flip mode): pitch = S - W about right, yaw = D - A about up, roll = Q - E about back. */
const KEYS = { W: [right, -1], S: [right, 1], A: [up, -1], D: [up, 1], Q: [back, 1], E: [back, -1] };
/** The keys' torque, N m: the panel's 0.5 N m times FLIP_PUSH (1 where the source has none). */
const TORQUE = 0.5 * (m.FLIP_PUSH ?? 1);

/** Plays one round: `key` held from the start for `hold` s. @returns { flips, stars, wonAt } */
function round(key, hold) {
  const world = m.createPhysicsWorld(m.rotatingCubeWorldOptions('flip'));
  const h = m.buildRotatingCube(world, { mode: 'flip', spin: 6 });
  const flips = new m.FlipChallenge();
  const [axis, sign] = KEYS[key];
  const torque = [0, 0, 0];
  m.addSystem(
    world,
    'forces',
    m.torqueCouple(h.body, () => {
      const on = world.time < hold ? TORQUE * sign : 0;
      for (let i = 0; i < 3; i++) torque[i] = on * axis[i];
      return torque;
    }),
  );
  m.addSystem(world, 'finalize', (w) => flips.update(w, h.body));
  flips.input(world.time);
  while (!flips.over(world)) m.step(world);
  return { flips: flips.counter.count, stars: flips.stars(), wonAt: flips.wonAt };
}

const holds = [0.5, 1, 1.5, 2, 2.5, 3, 4, 5, 8];
console.log(`flip round, ${source}: one key held from the first input for each time, then nothing (flips counted / stars)`);
console.log(`key  ${holds.map((s) => `${s.toFixed(1)} s`.padStart(9)).join('')}`);
let wins = 0;
for (const key of Object.keys(KEYS)) {
  const cells = holds.map((hold) => {
    const r = round(key, hold);
    if (r.wonAt >= 0) wins++;
    return `${r.flips}/${r.stars}${r.wonAt >= 0 ? '*' : ' '}`.padStart(9);
  });
  console.log(`${key}    ${cells.join('')}`);
}
console.log(`won (*): ${wins} of ${holds.length * Object.keys(KEYS).length}; no input: the round does not start, nothing won`);
