// `node scripts/lab-cloth-pulls.mjs [--hold=S] [--pulls=D,...] [--grip=JSON]`: how much of the cloth lab's first sheet a hand's pull
// rips away, headless. The sheet hangs 1 s in still air at the lab's defaults; the hand (grab.ts, the
// lab's grip) takes hold at a point and is drawn `d` m in a straight line over `t` s (a finger's drag),
// held there `--hold` s (default 1), let go, and the sheet runs 3 s more. Prints, per pull, the links
// torn and the points in pieces that came away from the pegs (of the sheet's 768), and for each the
// frames from the hand's start to the first tear. Takes about a minute.
import { importSource } from './build.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const a = args.find((x) => x.startsWith(`--${name}=`));
  return a === undefined ? fallback : Number(a.slice(name.length + 3));
};
const hold = option('hold', 1);
/** --grip='{"give":1}': grip options over the lab's (grab.ts GrabOptions), to try others. */
const gripArg = args.find((x) => x.startsWith('--grip='));
const grip = gripArg ? JSON.parse(gripArg.slice(7)) : {};
/** --pulls=2,3: the pulls' lengths, m (default 1, 1.5, 2 and 3). */
const pullsArg = args.find((x) => x.startsWith('--pulls='));
const lengths = pullsArg ? pullsArg.slice(8).split(',').map(Number) : [1, 1.5, 2, 3];
const lab = await importSource(
  'lab-cloth-pulls',
  `export * from './games/lab-cloth/scene.ts';
   export { ClothGrab, gripFor } from './games/lab-cloth/grab.ts';
   export { ClothCells } from './games/lab-cloth/cells.ts';
   export { findPieces } from './games/lab-cloth/pieces.ts';
   export { step, slotOf } from '@bitphysics/physics';`,
);
const { createClothScene, DEFAULTS, ClothGrab, gripFor, ClothCells, findPieces, step, slotOf } = lab;

/** One pull: grip at (row, column), drawn (dx, dy) m over `t` s. */
function pull(row, column, dx, dy, t) {
  const { world, cloth } = createClothScene({ ...DEFAULTS, wind: 0, gusts: 0 });
  const cells = new ClothCells(cloth);
  for (let i = 0; i < 60; i++) step(world);
  const e = slotOf(cloth.points[row * cloth.columns + column]);
  const x0 = world.components.Position.x[e],
    y0 = world.components.Position.y[e];
  const grab = ClothGrab.at(world, cloth, x0, y0, { ...gripFor(DEFAULTS.size), ...grip });
  const moving = Math.max(1, Math.round(t * 60)),
    held = Math.round(hold * 60);
  let torn = 0,
    first = -1;
  for (let i = 1; i <= moving + held; i++) {
    const f = Math.min(1, i / moving);
    grab.moveTo(x0 + dx * f, y0 + dy * f);
    grab.update(world.dt);
    step(world);
    const b = world.joints.breaks.count;
    if (b > 0 && first < 0) first = i;
    torn += b;
    cells.loosen(world);
  }
  grab.release();
  for (let i = 0; i < 180; i++) {
    step(world);
    torn += world.joints.breaks.count;
    cells.loosen(world);
  }
  const pieces = findPieces(world, cloth);
  let off = 0;
  pieces.size.forEach((n, k) => {
    if (!pieces.held[k]) off += n;
  });
  return { torn, off, first };
}

const GRIPS = [
  ['middle', 12, 16],
  ['lower middle', 19, 16],
  ['hem corner', 23, 2],
  ['upper left', 6, 8],
];
const PULLS = [
  ['down', 0, -1],
  ['down-right', Math.SQRT1_2, -Math.SQRT1_2],
  ['right', 1, 0],
];
console.log(`hold ${hold} s; per pull: links torn / points off (of 768) / frame of the first tear`);
for (const d of lengths)
  for (const t of [0.3, 1]) {
    const row = [];
    for (const [, r, c] of GRIPS)
      for (const [, ux, uy] of PULLS) {
        const p = pull(r, c, ux * d, uy * d, t);
        row.push(`${p.torn}/${p.off}/${p.first}`);
      }
    console.log(`${d} m in ${t} s: ${row.join('  ')}`);
  }
console.log(`columns: ${GRIPS.flatMap(([g]) => PULLS.map(([p]) => `${g} ${p}`)).join(', ')}`);
