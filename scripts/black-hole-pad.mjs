// `node scripts/black-hole-pad.mjs [--levels 3-5] [--seeds 12] [--fields 32x24,20x30] [--source games/black-hole]`: how
// safe black hole's start pad is, level by level. Per field and level over the seeds: the nearest hole's horizon to the
// start, m (min and mean), and short taps from the pad: every arrow and pair of arrows at right angles (8 thrusts)
// held 0.1, 0.2 or 0.3 s from rest, then let go to coast for 4 s: the share of these taps that fall into a hole, and
// how many fall within 2.5 s of the tap, and the quickest fall, s after the tap began (a newcomer's first taps after a respawn should not end in a hole).
import { importSource } from './build.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : fallback;
};
const source = arg('--source', 'games/black-hole').replace(/\/$/, '');
const m = await importSource(
  'black-hole-pad',
  `export * from './${source}/levels.ts'; export * from './${source}/rules.ts'; export { slotOf } from '@bitphysics/physics';`,
);
const [lo, hi] = arg('--levels', '3-5').split('-').map(Number);
const seeds = Number(arg('--seeds', '12'));
const fields = arg('--fields', '32x24,20x30')
  .split(',')
  .map((f) => f.split('x').map(Number));
const THRUSTS = ['up', 'up-left', 'up-right', 'left', 'right', 'down', 'down-left', 'down-right'];
const TAPS = [0.1, 0.2, 0.3];
const COAST = 4;
for (const [width, height] of fields) {
  console.log(`field ${width} x ${height} m, seeds 1-${seeds}, taps ${TAPS.join(', ')} s then ${COAST} s coasting:`);
  for (let level = lo; level <= hi; level++) {
    let nearMin = Infinity,
      nearSum = 0,
      falls = 0,
      early = 0,
      taps = 0,
      quickest = Infinity;
    const badSeeds = new Set();
    for (let seed = 1; seed <= seeds; seed++) {
      const g0 = m.createBlackHoleGame({ seed, lives: 9, field: { width, height } });
      m.startLevel(g0, level);
      const P = g0.world.components.Position;
      let near = Infinity;
      g0.holes.forEach((h, i) => {
        near = Math.min(near, Math.hypot(P.x[m.slotOf(h)] - g0.start[0], P.y[m.slotOf(h)] - g0.start[1]) - g0.holeRadius[i]);
      });
      nearMin = Math.min(nearMin, near);
      nearSum += near;
      for (const thrust of THRUSTS)
        for (const tap of TAPS) {
          const g = m.createBlackHoleGame({ seed, lives: 9, field: { width, height } });
          const run = m.startLevel(g, level);
          run.rings.length = 0;
          const dt = g.world.dt,
            n = Math.round(tap / dt);
          taps++;
          for (let k = 0; k * dt < tap + COAST; k++) {
            const want = k < n ? thrust : 'none';
            if (g.thrust !== want) m.setThrust(g, want);
            const e = m.stepLevel(g, run);
            if (e === 'fell' || e === 'over') {
              falls++;
              if ((k + 1) * dt < 2.5) early++;
              quickest = Math.min(quickest, (k + 1) * dt);
              badSeeds.add(seed);
              break;
            }
            if (e !== 'none') break;
          }
        }
    }
    console.log(
      `  level ${level}: nearest horizon ${nearMin.toFixed(1)} m (mean ${(nearSum / seeds).toFixed(1)}), ` +
        `taps falling in ${falls}/${taps} (${((100 * falls) / taps).toFixed(0)} %), ${early} within 2.5 s, quickest ${Number.isFinite(quickest) ? `${quickest.toFixed(2)} s` : '-'}, ` +
        `seeds ${[...badSeeds].join(' ') || '-'}`,
    );
  }
}
