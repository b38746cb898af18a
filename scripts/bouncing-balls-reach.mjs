// `node scripts/bouncing-balls-reach.mjs [--spot x,y,side --tall]`: can a stranger reach each hoop of
// bouncing balls? For every hoop spot of both layouts (games/bouncing-balls/hoop.ts HOOP_SPOTS and
// HOOP_SPOTS_TALL), searches from every natural start (games/bouncing-balls/reach.ts naturalStarts:
// the lower part of the box above the pile, 0.5 m apart) for a robust clean basket (reach.ts
// findBasket: through the opening before touching anything, and the throws 1.5 degrees and 0.4 m/s
// either side too). Prints, per spot, the starts that have one out of all, and one such throw.
// --spot x,y,side [--tall] measures one spot of your own instead; --sweep [--tall] measures every
// spot 0.5 m apart that fits the box clear of the ramps (from starts 1 m apart) and prints the best
// 40 (to choose spots from). --pull desk,phone (full pulls, px; default 420,138: a mouse's at
// 1280 x 800, a finger's at 390 x 844) measures how forgiving the slingshot is: for baskets from
// every third natural start, the window of pull lengths (speed, at the basket's angle) and of
// sideways pull (angle, at its speed) that still score, in px of pull at that full pull
// (games/bouncing-balls/main.ts fullPull; the pull for a speed from hoop.ts slingPull, on the tall box
// with the phone's curve for that start, hoop.ts slingRoom; baskets faster than its full pull left
// out); then, for the
// same baskets, the runs of pull length and of sideways pull round the basket's pull that score as
// thrown without and with the aim assist (games/bouncing-balls/aim-assist.ts assistAim; a finger's on
// the tall box, a mouse's on the wide one), and the share of pulls off the basket's by a normal
// spread (10 % of the length, 4 degrees) that score without and with it. Takes a second or so a spot.
import { importSource } from './build.mjs';

const r = await importSource(
  'bouncing-balls-reach',
  "export * from './games/bouncing-balls/reach.ts'; export * from './games/bouncing-balls/hoop.ts'; export * from './games/bouncing-balls/aim-assist.ts';",
);
const at = process.argv.indexOf('--spot');
const cases = [];
if (process.argv.includes('--sweep')) {
  const tall = process.argv.includes('--tall');
  const [w, h] = tall ? [10, 16] : [16, 10];
  const rows = [];
  for (let y = 2.5; y <= h - 1.6; y += 0.5)
    for (let x = 1.5; x <= w - 1.5; x += 0.5)
      for (const side of [1, -1]) {
        const spot = { x, y, side };
        if (!r.hoopFits(spot, tall)) continue;
        const starts = r.naturalStarts(spot, tall);
        let found = 0;
        for (let k = 0; k < starts.length; k += 2) {
          // Starts 1 m apart: every other one across and up.
          if (Math.round(starts[k] * 2) % 2 || Math.round(starts[k + 1] * 2) % 2) continue;
          if (r.findBasket(spot, tall, starts[k], starts[k + 1])) found++;
        }
        rows.push([found, `(${x}, ${y}, ${side})`]);
      }
  rows.sort((a, b) => b[0] - a[0]);
  for (const [found, s] of rows.slice(0, 40)) console.log(found, s);
  process.exit(0);
}
const pullAt = process.argv.indexOf('--pull');
if (pullAt >= 0) {
  const [desk, phone] = (process.argv[pullAt + 1] ?? '420,138').split(',').map(Number);
  if (!(desk > 0 && phone > 0))
    throw new RangeError(`bouncing-balls-reach: --pull wants desk,phone px > 0, got ${process.argv[pullAt + 1]}`);
  const median = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length / 2)];
  for (const tall of [false, true]) {
    const full = tall ? phone : desk;
    // The slingshot's curve from height y: the phone's (slingRoom) on the tall box, the 20 m/s one on the wide.
    const roomOf = (spot, y) => (tall ? r.slingRoom(y, spot.y, 9.81) : undefined);
    const speedPx = [],
      anglePx = [],
      pulls = [],
      runs = { raw: [[], []], assisted: [[], []] },
      hits = { raw: 0, assisted: 0, n: 0 };
    // A fixed pseudo-random spread of pulls round each basket's: [length factor, degrees] pairs.
    let seed = 1;
    const rnd = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
    const normal = () => Math.sqrt(-2 * Math.log(rnd())) * Math.cos(2 * Math.PI * rnd());
    const spread = Array.from({ length: 40 }, () => [1 + 0.1 * normal(), 4 * normal()]);
    for (const spot of r.hoopSpots(tall)) {
      const starts = r.naturalStarts(spot, tall);
      for (let k = 0; k < starts.length; k += 6) {
        const t = r.findBasket(spot, tall, starts[k], starts[k + 1]);
        const room = roomOf(spot, starts[k + 1]);
        if (!t || t.speed > (room ? room.top : r.MAX_THROW_SPEED)) continue;
        // Pull length, px, of a throw at `speed` m/s (hoop.ts slingPull, the inverse of the slingshot's curve).
        const pullOf = (speed) => r.slingPull(Math.min(room ? room.top : r.MAX_THROW_SPEED, speed), full, room);
        const edge = (key, d) => {
          let v = t[key];
          while (Math.abs(v - t[key]) < 5 && r.cleanBasket(spot, tall, { ...t, [key]: v + d })) v += d;
          return v;
        };
        const pull = pullOf(t.speed);
        pulls.push(pull);
        speedPx.push(pullOf(edge('speed', 0.02)) - pullOf(edge('speed', -0.02)));
        anglePx.push((pull * (edge('angle', 0.05) - edge('angle', -0.05)) * Math.PI) / 180);
        const [x, y] = [starts[k], starts[k + 1]];
        const raw = (px, py) => {
          const l = Math.hypot(px, py);
          if (l === 0 || l > full) return false;
          return r.cleanBasket(spot, tall, { x, y, angle: (Math.atan2(py, -px) * 180) / Math.PI, speed: r.slingSpeed(l, full, room) });
        };
        const assisted = (px, py) => {
          const a = r.assistAim(px, py, x, y, spot, { gravity: 9.81, fullPull: full, finger: tall, ...(room ? { room } : {}) }, raw);
          return a ? raw(a[0], a[1]) : raw(px, py);
        };
        const at = (scores, l, deg) => {
          const b = ((t.angle + deg) * Math.PI) / 180;
          return scores(-Math.cos(b) * l, Math.sin(b) * l);
        };
        const run = (ok) => {
          let hi = 0,
            lo = 0;
          while (hi < 80 && ok(hi + 0.5)) hi += 0.5;
          while (lo > -80 && ok(lo - 0.5)) lo -= 0.5;
          return hi - lo;
        };
        for (const [name, scores] of [
          ['raw', raw],
          ['assisted', assisted],
        ]) {
          runs[name][0].push(run((d) => at(scores, pull + d, 0)));
          runs[name][1].push(run((d) => at(scores, pull, (d / pull) * (180 / Math.PI))));
          for (const [f, deg] of spread) if (at(scores, pull * f, deg)) hits[name]++;
        }
        hits.n += spread.length;
      }
    }
    console.log(
      `${tall ? 'tall (phone)' : 'wide (desktop)'}, full pull ${full} px: ${pulls.length} baskets, pulls ${Math.round(Math.min(...pulls))}..${Math.round(Math.max(...pulls))} px; ` +
        `window of pull length median ${median(speedPx).toFixed(1)} px (least ${Math.min(...speedPx).toFixed(1)}), sideways median ${median(anglePx).toFixed(1)} px (least ${Math.min(...anglePx).toFixed(1)})`,
    );
    const line = (name) =>
      `length ${median(runs[name][0])} px (least ${Math.min(...runs[name][0])}), sideways ${median(runs[name][1])} px (least ${Math.min(...runs[name][1])}), ${Math.round((100 * hits[name]) / hits.n)} % of spread pulls score`;
    console.log(`  runs that score round the basket's pull (medians): as pulled ${line('raw')}; with the aim assist ${line('assisted')}`);
  }
  process.exit(0);
}
if (at >= 0) {
  const [x, y, side] = process.argv[at + 1].split(',').map(Number);
  if (![x, y].every(Number.isFinite) || (side !== 1 && side !== -1))
    throw new RangeError(`bouncing-balls-reach: --spot wants x,y,side (side 1 or -1), got ${process.argv[at + 1]}`);
  cases.push({ tall: process.argv.includes('--tall'), i: 0, spot: { x, y, side } });
} else {
  for (const tall of [false, true]) {
    const spots = r.hoopSpots(tall);
    for (let i = 0; i < spots.length; i++) cases.push({ tall, i, spot: spots[i] });
  }
}
for (const { tall, i, spot } of cases) {
  const starts = r.naturalStarts(spot, tall);
  let found = 0,
    example = null;
  for (let k = 0; k < starts.length; k += 2) {
    const t = r.findBasket(spot, tall, starts[k], starts[k + 1]);
    if (t) {
      found++;
      example ??= t;
    }
  }
  const n = starts.length / 2;
  const ex = example ? `e.g. from (${example.x}, ${example.y}) at ${example.angle} deg, ${example.speed} m/s` : 'none';
  console.log(
    `${tall ? 'tall' : 'wide'} spot ${i} (${spot.x}, ${spot.y}, ${spot.side > 0 ? 'right' : 'left'}): ${found}/${n} starts (${Math.round((100 * found) / Math.max(1, n))} %) ${ex}`,
  );
}
