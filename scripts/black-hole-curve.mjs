// `node scripts/black-hole-curve.mjs [--levels 1-8] [--seeds 12] [--fields 32x24,20x30] [--limit 60] [--players sharp,middle,slow]`: black hole's
// difficulty curve as scripted players who fly by eye meet it (test/games/black-hole-players.ts: a sharp player, a
// middling stranger and a slow thumb, with bounded reaction). Per field, player and level: the seeds cleared within
// --limit s of game time (lives never run out), the share of all tries that cleared (a fall ends a try), and the mean
// time of the clearing try and of the whole level; success: the mean over
// seeds of 1 / tries (a layout failed many times counts once).
import { importSource } from './build.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : fallback;
};
const p = await importSource('black-hole-curve', "export * from './test/games/black-hole-players.ts';");
const [lo, hi] = arg('--levels', '1-8').split('-').map(Number);
const seeds = Number(arg('--seeds', '12'));
const limit = Number(arg('--limit', '60'));
const only = arg('--players', 'sharp,middle,slow').split(',');
const fields = arg('--fields', '32x24,20x30')
  .split(',')
  .map((f) => f.split('x').map(Number));
if (!(lo >= 1 && hi >= lo && seeds >= 1 && limit > 0))
  throw new RangeError('black-hole-curve: --levels a-b (1 <= a <= b), --seeds n >= 1, --limit s > 0');
for (const [width, height] of fields) {
  console.log(`field ${width} x ${height} m, seeds 1-${seeds}, ${limit} s a level:`);
  for (const [name, style] of Object.entries(p.PLAYERS).filter(([n]) => only.includes(n))) {
    console.log(`  ${name} (${JSON.stringify(style)}):`);
    for (let level = lo; level <= hi; level++) {
      const f = p.levelFigures(level, style, seeds, limit, { width, height });
      console.log(
        `    level ${level}: cleared ${f.cleared}/${f.seeds}, ${(100 * f.rate).toFixed(0)} % of tries clear, ` +
          `success ${(100 * f.success).toFixed(0)} % (tries ${f.tries.join(' ')}), ` +
          `clearing try ${f.time.toFixed(1)} s, level ${f.totalTime.toFixed(1)} s`,
      );
    }
  }
}
