// `node scripts/lab-cloth-cuts.mjs [--size=N] [--slack=M] [--verbose]`: how the cloth lab's fit
// (games/lab-cloth/pattern.ts) rates a spread of cuts, from careful to careless, of the shapes on the
// first sheet and a pane of the window on the second. Each cut is a hand's trace of the printed line
// (games/lab-cloth/traces.ts) cut on the still sheet of N points across (default the lab's 32): run
// out of the line or inside it, wobbling across it, cutting across a star's points. Prints, for each
// kind of cut, the stars it earned per shape (with --verbose, every cut's fit; with --flaws, its flaw
// in spacings: Fit.flaw), then how many cuts of each care earned 0, 1, 2 and 3 stars. The notched cuts
// follow the line but for one slip: a V notch or a slit cut into the shape. --slack adds a finger's slack, m (the phone's: 0.09).
// Takes about half a minute.
import { importSource } from './build.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const a = args.find((x) => x.startsWith(`--${name}=`));
  return a === undefined ? fallback : Number(a.slice(name.length + 3));
};
const size = option('size', 32);
const slack = option('slack', 0);
if (!(Number.isInteger(size) && size >= 8 && size <= 48))
  throw new RangeError(`lab-cloth-cuts: --size must be an integer in [8, 48], got ${size}`);
if (!(slack >= 0)) throw new RangeError(`lab-cloth-cuts: --slack must be >= 0 m, got ${slack}`);
/** --verbose: every cut's fit after its stars; --flaws: its flaw (Fit.flaw) in link spacings. */
const verbose = args.includes('--flaws') ? 'flaw' : args.includes('--verbose');

const lab = await importSource(
  'lab-cloth-cuts',
  `export * from './games/lab-cloth/traces.ts';
   export * from './games/lab-cloth/pattern.ts';
   export { LEVELS } from './games/lab-cloth/levels.ts';
   export { ClothCells } from './games/lab-cloth/cells.ts';
   export * from './games/lab-cloth/scene.ts';
   export { snapshot, restore } from '@bitphysics/physics';`,
);
const { traceLine, cutTrace, Challenge, LEVELS, ClothCells, createClothScene, DEFAULTS, sheetGrid, snapshot, restore } = lab;
const s = sheetGrid(size).spacing;

// The cuts, by care: offsets, wobbles and chops in link spacings (0.13 m at 32 points across; 15 px
// on a 1280 x 800 screen, 11 px on a 390 px phone).
const CUTS = [
  { care: 'careful', name: 'on the line', style: { offset: 0 } },
  { care: 'careful', name: '0.3 out', style: { offset: 0.3 * s } },
  { care: 'careful', name: '0.3 out, wobble 0.3', style: { offset: 0.3 * s, wobble: 0.3 * s } },
  { care: 'careful', name: '0.3 in', style: { offset: -0.3 * s } },
  { care: 'careful', name: '0.5 out, wobble 0.4', style: { offset: 0.5 * s, wobble: 0.4 * s } },
  { care: 'fair', name: '0.8 out', style: { offset: 0.8 * s } },
  { care: 'fair', name: '0.3 out, wobble 0.7', style: { offset: 0.3 * s, wobble: 0.7 * s } },
  { care: 'fair', name: '0.7 in', style: { offset: -0.7 * s } },
  { care: 'fair', name: '0.3 out, chop 1', style: { offset: 0.3 * s, chop: 1 * s } },
  { care: 'careless', name: '1.2 out', style: { offset: 1.2 * s } },
  { care: 'careless', name: '0.5 out, wobble 1.2', style: { offset: 0.5 * s, wobble: 1.2 * s } },
  { care: 'careless', name: '1 in', style: { offset: -1 * s } },
  { care: 'careless', name: '0.5 out, chop 2', style: { offset: 0.5 * s, chop: 2 * s } },
  { care: 'careless', name: '0.8 out, wobble 1, chop 1.5', style: { offset: 0.8 * s, wobble: 1 * s, chop: 1.5 * s } },
  { care: 'notched', name: 'on the line, notch 1', style: { offset: 0, notch: 1 * s } },
  { care: 'notched', name: 'on the line, notch 1.5', style: { offset: 0, notch: 1.5 * s } },
  { care: 'notched', name: '0.3 out, notch 2', style: { offset: 0.3 * s, notch: 2 * s } },
  { care: 'notched', name: 'on the line, slit 1.5', style: { offset: 0, slit: 1.5 * s } },
  { care: 'notched', name: '0.3 out, slit 2.5', style: { offset: 0.3 * s, slit: 2.5 * s } },
  { care: 'sloppy', name: '2 out', style: { offset: 2 * s } },
  { care: 'sloppy', name: '1 out, wobble 2', style: { offset: 1 * s, wobble: 2 * s } },
  { care: 'sloppy', name: '3 out', style: { offset: 3 * s } },
];
const SEEDS = [1, 2, 3];

/** The still sheet of level `n` (0-based), its challenge, and a save to start each cut from. */
function sheet(n) {
  const L = LEVELS[n];
  const scene = createClothScene({ ...DEFAULTS, size, wind: 0, gusts: 0 }, L.prepare);
  const cells = new ClothCells(scene.cloth);
  const shapes = L.shapes(size);
  return { ...scene, cells, shapes, save: snapshot(scene.world) };
}
const sheets = [sheet(0), sheet(1)];
const targets = [
  ...sheets[0].shapes.map((shape, i) => ({ sheet: sheets[0], shape, i })),
  { sheet: sheets[1], shape: sheets[1].shapes[0], i: 0 },
];

const tally = new Map();
console.log(
  `Sheet of ${size} points across (spacing ${(s * 100).toFixed(1)} cm)${slack ? `, slack ${slack} m` : ''}: stars per seed ${SEEDS.join(', ')}`,
);
console.log(`${'cut (spacings)'.padEnd(34)}${targets.map((t) => t.shape.name.padEnd(16)).join('')}`);
for (const cut of CUTS) {
  let row = `${cut.care.padEnd(9)}${cut.name.padEnd(25)}`;
  for (const t of targets) {
    const stars = [];
    for (const seed of SEEDS) {
      const { world, cloth, cells, shapes, save } = t.sheet;
      restore(world, save);
      cells.invalidate();
      const challenge = new Challenge(world, cloth, cells, shapes);
      challenge.setSlack(slack);
      challenge.update();
      // A notch or a slit along a side (a third of the way round; a pane's first third ends at a corner).
      const at = t.shape.style === 'pane' ? 0.65 : 0.3;
      cutTrace(world, cloth, traceLine(t.shape.outline, { at, ...cut.style, seed }), challenge.marks);
      cells.loosen(world);
      const d = challenge.update().find((x) => x.shape === t.i);
      const star = d ? d.stars : 0;
      stars.push(
        verbose === 'flaw'
          ? `${star}(${d?.flaw !== undefined ? (d.flaw / s).toFixed(2) : '-'})`
          : verbose
            ? `${star}(${d ? d.fit.toFixed(2) : 'kept'})`
            : String(star),
      );
      const k = tally.get(cut.care) ?? [0, 0, 0, 0];
      k[star]++;
      tally.set(cut.care, k);
    }
    row += stars.join(' ').padEnd(16);
  }
  console.log(row);
}
console.log('\nCuts earning 0 / 1 / 2 / 3 stars:');
for (const [care, k] of tally) console.log(`  ${care.padEnd(9)} ${k.join(' / ')}`);
