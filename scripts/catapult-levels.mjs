// `node scripts/catapult-levels.mjs [--seed=S] [--share=F] [level ...]`: checks that the catapult's
// levels (1-based; default every level) can be cleared within their shots. For each, a coarse greedy
// search over pull angle and power (games/catapult/solve.ts searchLevel, headless) for throws that
// bring down F of the castle's pieces (default 0.5: a clear, one star; 0.75 two stars, 0.95 three),
// on seed S (default 1, the page's). Prints each level's throws and what they brought down, then the
// throws as a LEVEL_SOLUTIONS literal for games/catapult/solve.ts (the test replays those).
// Exits 1 when a level was not cleared. Takes a few seconds a level (a minute for the last at 0.95).
// With --spread, instead: how hard each level is, as how many of 36 single throws (angles 10 to 60
// degrees by 10, powers 50 to 100 % by 10) clear it (the levels come in that order, easiest first).
// With --grid, instead: of 13 x 15 single throws (angles 10 to 70 degrees by 5, powers 30 to 100 %
// by 5), the share that clears each level and the share that earns three stars (95 % down), and how
// many throws clear more than one of the levels chosen (one throw should not fit every castle).
import { importSource } from './build.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const a = args.find((x) => x.startsWith(`--${name}=`));
  return a === undefined ? fallback : Number(a.slice(name.length + 3));
};
const seed = option('seed', 1);
const share = option('share', 0.5);
if (!Number.isInteger(seed)) throw new RangeError(`catapult-levels: --seed must be an integer, got ${seed}`);
if (!(share > 0 && share <= 1)) throw new RangeError(`catapult-levels: --share must be in (0, 1], got ${share}`);

// The solver and the level rules are TypeScript: bundled with the packages from their sources
// (importSource).
const { searchLevel, playThrows, levelName, LEVEL_COUNT } = await importSource(
  'catapult-levels',
  "export * from './games/catapult/solve.ts';",
);
const levels = args.filter((a) => !a.startsWith('--')).map(Number);
for (const n of levels)
  if (!(Number.isInteger(n) && n >= 1 && n <= LEVEL_COUNT))
    throw new RangeError(`catapult-levels: levels are 1 to ${LEVEL_COUNT}, got ${n}`);
const chosen = levels.length ? levels : Array.from({ length: LEVEL_COUNT }, (_, i) => i + 1);
if (args.includes('--spread')) {
  for (const n of chosen) {
    let clear = 0,
      best = 0,
      pieces = 0;
    for (let angle = 10; angle <= 60; angle += 10)
      for (let p = 50; p <= 100; p += 10) {
        const r = playThrows(n - 1, seed, [{ angle, power: p / 100 }]);
        pieces = r.counted;
        best = Math.max(best, r.down);
        if (r.cleared) clear++;
      }
    console.log(
      `level ${n} ${levelName(n - 1)}: ${clear} of 36 single throws clear it; the best brings down ${best} of the ${pieces} that count`,
    );
  }
}
if (args.includes('--grid')) {
  const clears = new Map();
  for (const n of chosen) {
    let clear = 0,
      three = 0,
      total = 0;
    const t0 = performance.now();
    for (let angle = 10; angle <= 70; angle += 5)
      for (let p = 30; p <= 100; p += 5) {
        const r = playThrows(n - 1, seed, [{ angle, power: p / 100 }]);
        total++;
        if (r.cleared) {
          clear++;
          const key = `${angle}° ${p} %`;
          clears.set(key, [...(clears.get(key) ?? []), n]);
        }
        if (r.down >= Math.ceil(0.95 * r.counted)) three++;
      }
    console.log(
      `level ${n} ${levelName(n - 1)}: ${clear} of ${total} single throws clear it (${((100 * clear) / total).toFixed(1)} %), ${three} earn three stars (${((100 * three) / total).toFixed(1)} %) (${((performance.now() - t0) / 1000).toFixed(1)} s)`,
    );
  }
  const shared = [...clears].filter(([, ls]) => ls.length > 1);
  console.log(
    `throws that clear more than one of levels ${chosen.join(', ')}: ${shared.length}${shared.length ? `: ${shared.map(([k, ls]) => `${k} (${ls.join(', ')})`).join('; ')}` : ''}`,
  );
}
const found = [];
let failed = 0;
for (const n of args.includes('--spread') || args.includes('--grid') ? [] : chosen) {
  const t0 = performance.now();
  const r = searchLevel(n - 1, seed, { share });
  const throws = r.throws.map((t) => ({ angle: t.angle, power: Math.round(100 * t.power) / 100 }));
  found.push([n, throws]);
  if (!r.cleared) failed++;
  console.log(
    `level ${n} ${levelName(n - 1)}: ${r.cleared ? 'done' : 'NOT done'}, ${r.fallen} down with ${throws.length} ${throws.length === 1 ? 'throw' : 'throws'} ${throws
      .map((t) => `${t.angle}° ${Math.round(100 * t.power)} %`)
      .join(', ')} (${((performance.now() - t0) / 1000).toFixed(1)} s)`,
  );
}
if (found.length > 0) console.log(`\nLEVEL_SOLUTIONS (seed ${seed}, share ${share}):`);
for (const [n, throws] of found) console.log(`  // ${n}\n  ${JSON.stringify(throws).replaceAll('"', '')},`);
process.exitCode = failed > 0 ? 1 : 0;
