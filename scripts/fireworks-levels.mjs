// `node scripts/fireworks-levels.mjs [--reach] [--par] [level ...]`: checks the fireworks lantern show
// (games/fireworks/lanterns.ts) in the show's real physics, headless (default: both checks, every level).
//
// --reach: how far a quick burst's hot stars get (the stars that light lanterns: generation 0 of a
//   burst emitter, in the first HOT_FRACTION of their life), in sky widths W: sideways (the mean of
//   left and right), up and down from the burst point, for a peony and a willow, averaged over shells
//   aimed across the band of a phone's sky (64 x 108 m) and a desktop's (120 x 80 m), 3 seeds each.
//   Compare with lanterns.ts QUICK_REACH (the page's charging ring and the grouping test use it).
// --par: that each level (1-based) can be lit in par shells (and that it gives that many: LEVELS' shells,
//   and whether one shell a lantern would run out), in both skies: each level's plan (below:
//   which lanterns each shell is meant to light, aimed at a point worked out from them, held or not)
//   is searched over aim points around the plan's (every 0.02 W across and up to 0.06 W either way)
//   for the shells that light their group on all 3 seeds. Prints, per level and sky, each shell's
//   share of aim points that light its group (how forgiving it is) and the best aim found, then
//   replays the whole plan (every shell at its best aim, in one show) and says whether it lit every
//   lantern. Exits 1 when a level could not be lit in par.
// --meet: that the finale's meeting cue (lanterns.ts meetCue, the page's ring) is honest: for launches
//   every 0.1 s over a swing, a held shell aimed at the cue's point, on every seed and in both skies,
//   and let go then, lights the meeting pair and the lantern above; prints the share that do where
//   the cue says "let go now!" (release >= 0.5) and where its ring shows for a release at all.
// --random[=N]: how often a newcomer's aims earn three stars: N tries (default 30) per level and sky,
//   each firing par shells 1.6 s apart, every shell at a random point within 0.08 W of a random
//   lantern still dark (where it is at launch, not where it will be), held a random time in
//   [0, MAX_HOLD] where the level allows holding; prints the share that lit every lantern. Then,
//   once those shells' stars are cold, the rest of the level's shells the same way, 1.6 s apart:
//   prints the share that lit every lantern with all the shells the level gives (cleared it, stars
//   or not: a level random aims clear asks for no idea).
// Takes a minute or two.
import { importSource } from './build.mjs';

const fw = await importSource(
  'fireworks-levels',
  "export * from './games/fireworks/show.ts'; export * from './games/fireworks/lanterns.ts'; export { query, slotOf } from '@bitphysics/physics';",
);
const { LEVELS, FUSE, MAX_HOLD, HOT_FRACTION, createFireworks, launchShell, stepFireworks, lanternsOf, lanternAt, startLevel } = fw;
const { lightFromSparks, countShell, bandMiddle, lanternRadius, meetCue, query, slotOf } = fw;

const args = process.argv.slice(2);
const SKIES = [
  { name: 'phone', width: 64, height: 108 },
  { name: 'desktop', width: 120, height: 80 },
];
const SEEDS = [1, 2, 3];
const levels = args.filter((a) => !a.startsWith('--')).map(Number);
for (const n of levels)
  if (!(Number.isInteger(n) && n >= 1 && n <= LEVELS.length))
    throw new RangeError(`fireworks-levels: levels are 1 to ${LEVELS.length}, got ${n}`);
const chosen = levels.length ? levels : LEVELS.map((_, i) => i + 1);
const randomArg = args.find((a) => a.startsWith('--random'));
const both = !args.includes('--reach') && !args.includes('--par') && !args.includes('--meet') && !randomArg;

/** A fresh quiet show in `sky` (one generation: the crackles light nothing). */
function newShow(sky, seed) {
  return createFireworks({ sky: { width: sky.width, height: sky.height }, opening: 0, autoShow: false, generations: 1, seed });
}

/** Slots of the show's burst emitters (as lanterns.ts burstEmittersOf). */
function burstSlots(show) {
  return new Set([...show.emitters.sparks, ...show.recipeEmitters.values()].map(slotOf));
}

if (both || args.includes('--reach')) {
  console.log(`quick bursts' hot stars (FUSE ${FUSE} s), sky widths from the burst point:`);
  for (const shell of ['peony', 'willow']) {
    const sums = { side: 0, up: 0, down: 0, drift: 0 };
    let n = 0;
    for (const sky of SKIES)
      for (const seed of SEEDS)
        for (const fx of [0.2, 0.35, 0.5, 0.65, 0.8])
          for (const fy of [-0.1, 0, 0.1]) {
            const { world, show } = newShow(sky, seed);
            const W = sky.width;
            const tx = fx * W,
              ty = bandMiddle(sky) * sky.height + fy * W;
            launchShell(world, show, tx, ty, 0, shell);
            while (show.bursts === 0) stepFireworks(world, show);
            const bx = show.flashes[0],
              by = show.flashes[1];
            const slots = burstSlots(show);
            const P = world.components.Particle,
              L = world.components.Lifetime,
              X = world.components.Position;
            // Every hot star's place at every step, relative to the burst point, m.
            const seen = [];
            let hot = true;
            for (let k = 0; hot && k < 600; k++) {
              hot = false;
              for (const e of query(world, [P, X])) {
                if (P.generation[e] !== 0 || !slots.has(P.emitter[e]) || L.age[e] > HOT_FRACTION * L.duration[e]) continue;
                hot = true;
                seen.push(X.x[e] - bx, X.y[e] - by);
              }
              stepFireworks(world, show);
            }
            // How far out along each axis a lantern still lights (some hot star passes within its
            // radius of its centre), less its radius: the reach as lanterns.ts defines it.
            const r = lanternRadius(W);
            const reachAlong = (ux, uy) => {
              let far = 0;
              for (let d = 0; d <= 0.5 * W; d += 0.005 * W) {
                const cx = d * ux,
                  cy = d * uy;
                let lit = false;
                for (let i = 0; i < seen.length && !lit; i += 2) lit = (seen[i] - cx) ** 2 + (seen[i + 1] - cy) ** 2 <= r * r;
                if (lit) far = d;
              }
              return Math.max(0, far - r);
            };
            const right = reachAlong(1, 0),
              left = reachAlong(-1, 0),
              up = reachAlong(0, 1),
              down = reachAlong(0, -1);
            // Outward: away from the sky's middle (a shell launched towards the middle keeps some of its sideways speed).
            sums.drift += (fx < 0.5 ? left - right : fx > 0.5 ? right - left : 0) / W;
            sums.side += (0.5 * (left + right)) / W;
            sums.up += up / W;
            sums.down += down / W;
            n++;
          }
    console.log(
      `  ${shell}: side ${(sums.side / n).toFixed(3)}, up ${(sums.up / n).toFixed(3)}, down ${(sums.down / n).toFixed(3)} W (further outwards than inwards by ${(sums.drift / n).toFixed(3)} W on average)`,
    );
  }
}

/**
 * Each level's par plan: per shell, the lanterns it is meant to light (indices), whether it is held
 * (MAX_HOLD) and when it is launched (world time, s: drifting lanterns are aimed where they will be
 * FUSE later). The aim is the middle of the group's lanterns then, moved by `lift` W (up +).
 */
const PLANS = [
  // 1. First light: the lone lantern, and each close pair with one shell between them.
  [
    { group: [0], hold: false, at: 0, lift: 0 },
    { group: [1, 2], hold: false, at: 0, lift: 0 },
    { group: [3, 4], hold: false, at: 0, lift: 0 },
  ],
  // 2. Pairs: a held burst between each pair.
  [
    { group: [0, 1], hold: true, at: 0, lift: 0 },
    { group: [2, 3], hold: true, at: 0, lift: 0 },
  ],
  // 3. Drifting: the passing pair with one shell where their ghosts meet (closest at 1.25 s: launched
  //    a fuse earlier), then each lone lantern at its ghost (where it will be after the fuse).
  [
    { group: [2, 3], hold: false, at: 1.25 - FUSE, lift: 0 },
    { group: [0], hold: false, at: 1, lift: 0 },
    { group: [1], hold: false, at: 2, lift: 0 },
  ],
  // 4. Willows: a held willow on the top lantern of each column, as the tip says (its stars fall
  //    onto the lower one, 0.28 to 0.3 W under it, beyond a quick willow's reach).
  [
    { group: [0, 1], hold: true, at: 0, lift: 0.12 },
    { group: [2, 3], hold: true, at: 0, lift: 0.12 },
    { group: [4, 5], hold: true, at: 0, lift: 0.12 },
  ],
  // 5. Finale: the two high side lanterns one each, and a held burst between the middle lantern and
  //    the low pair when they meet (closest a quarter period into their swing, 1.5 s), MEET_LIFT over
  //    their mean, where the page's meeting cue aims.
  [
    { group: [0], hold: false, at: 0, lift: 0 },
    { group: [2], hold: false, at: 0, lift: 0 },
    { group: [1, 3, 4], hold: true, at: 1.5 - FUSE + 6, lift: fw.MEET_LIFT },
  ],
];

/** Where the plan's shell `s` aims in `sky` at launch, m (before the search's offset). */
function planAim(level, sky, s) {
  const ls = lanternsOf(level, sky);
  const pts = s.group.map((i) => lanternAt(ls[i], sky, s.at + FUSE));
  const x = pts.reduce((a, p) => a + p[0], 0) / pts.length;
  const y = pts.reduce((a, p) => a + p[1], 0) / pts.length;
  return [x, y + s.lift * sky.width];
}

/**
 * Plays shells [{ x, y, hold, at }] of `level` in `sky` on `seed` (each launched at world time `at`),
 * lighting lanterns as the page does, until every star is cold. @returns which lanterns are lit.
 */
function play(level, sky, seed, shells) {
  const { world, show } = newShow(sky, seed);
  const run = startLevel(level, 0);
  const order = [...shells].sort((a, b) => a.at - b.at);
  const end = Math.max(...order.map((s) => s.at)) + FUSE + 2.5;
  let next = 0;
  while (world.time < end) {
    while (next < order.length && world.time >= order[next].at - 1e-9) {
      const s = order[next++];
      if (launchShell(world, show, s.x, s.y, s.hold ? MAX_HOLD : 0, LEVELS[level].shell) === 0) throw new Error('launch refused');
      countShell(run);
    }
    stepFireworks(world, show);
    lightFromSparks(world, show, run);
  }
  return run.lit;
}

let failed = 0;
if (both || args.includes('--par'))
  for (const n of chosen) {
    const level = n - 1;
    const lv = LEVELS[level];
    const plan = PLANS[level];
    if (plan.length !== lv.par) throw new Error(`fireworks-levels: level ${n}'s plan has ${plan.length} shells, par is ${lv.par}`);
    if (lv.shells < lv.par) throw new Error(`fireworks-levels: level ${n} gives ${lv.shells} shells, fewer than its par ${lv.par}`);
    // Not trivial: one shell a lantern runs out of shells where the level gives fewer than lanterns.
    console.log(
      `level ${n}: ${lv.shells} shells for ${lv.lanterns.length} lanterns (par ${lv.par})${lv.shells < lv.lanterns.length ? ': one shell a lantern runs out' : ''}`,
    );
    for (const sky of SKIES) {
      const W = sky.width;
      const best = [];
      const shares = [];
      for (const s of plan) {
        const [ax, ay] = planAim(level, sky, s);
        let good = 0,
          total = 0,
          pick = null,
          pickD = Infinity;
        for (let dx = -0.06; dx <= 0.06 + 1e-9; dx += 0.02)
          for (let dy = -0.06; dy <= 0.06 + 1e-9; dy += 0.02) {
            total++;
            const shot = { x: ax + dx * W, y: ay + dy * W, hold: s.hold, at: s.at };
            const ok = SEEDS.every((seed) => {
              const lit = play(level, sky, seed, [shot]);
              return s.group.every((i) => lit[i]);
            });
            if (!ok) continue;
            good++;
            // The best aim: the one nearest the plan's point.
            const d = Math.hypot(dx, dy);
            if (d < pickD) {
              pickD = d;
              pick = shot;
            }
          }
        shares.push(`${s.group.join('+')}${s.hold ? ' held' : ''}: ${good}/${total}`);
        best.push(pick);
      }
      const whole = best.every(Boolean) ? SEEDS.map((seed) => play(level, sky, seed, best).every(Boolean)) : [false];
      const ok = whole.every(Boolean);
      if (!ok) failed++;
      console.log(
        `level ${n} ${lv.name}, ${sky.name}: par ${lv.par} ${ok ? 'lit' : 'NOT lit'} (aims that light each shell's group on every seed: ${shares.join(', ')}; best aims ${best
          .map((b) => (b ? `(${(b.x / W).toFixed(2)}, ${((b.y - bandMiddle(sky) * sky.height) / W).toFixed(2)}) W` : 'none'))
          .join(', ')})`,
      );
    }
  }
if (args.includes('--meet'))
  for (const [level, lv] of LEVELS.entries()) {
    if (!lv.meet) continue;
    for (const sky of SKIES) {
      const tally = { label: [0, 0], ring: [0, 0] };
      const lit0 = lanternsOf(level, sky).map(() => false);
      for (let at = 6; at < 12 - 1e-9; at += 0.1) {
        const cue = meetCue(level, sky, at, lit0);
        if (!cue || cue.release <= 0) continue;
        const group = [...lv.meet.pair, lv.meet.with];
        const ok = SEEDS.every((seed) => {
          const lit = play(level, sky, seed, [{ x: cue.x, y: cue.y, hold: true, at }]);
          return group.every((i) => lit[i]);
        });
        for (const key of cue.release >= 0.5 ? ['label', 'ring'] : ['ring']) {
          tally[key][0] += ok ? 1 : 0;
          tally[key][1]++;
        }
      }
      console.log(
        `level ${level + 1} ${lv.name}, ${sky.name}: a held shell at the cue lights the meeting three on every seed from ${tally.label[0]}/${tally.label[1]} launch times with "let go now!", ${tally.ring[0]}/${tally.ring[1]} with the ring`,
      );
    }
  }
if (randomArg) {
  const tries = randomArg.includes('=') ? Number(randomArg.split('=')[1]) : 30;
  if (!(Number.isInteger(tries) && tries > 0))
    throw new RangeError(`fireworks-levels: --random=N needs an integer N > 0, got ${randomArg}`);
  // A small seeded generator (mulberry32), so the shares are the same run to run.
  let state = 12345;
  const rand = () => {
    state = (state + 0x6d2b79f5) | 0;
    let t = Math.imul(state ^ (state >>> 15), 1 | state);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  for (const n of chosen) {
    const level = n - 1;
    const lv = LEVELS[level];
    const shares = [];
    for (const sky of SKIES) {
      let good = 0,
        cleared = 0;
      for (let k = 0; k < tries; k++) {
        const { world, show } = newShow(sky, SEEDS[k % SEEDS.length]);
        const run = startLevel(level, 0);
        const ls = lanternsOf(level, sky);
        let fired = 0;
        const parEnd = (lv.par - 1) * 1.6 + FUSE + 2.5;
        // Shell n fires at n x 1.6 s; those over par after the par shells' stars are cold.
        const fireAt = (n) => (n < lv.par ? n * 1.6 : parEnd + (n - lv.par) * 1.6);
        const end = fireAt(lv.shells - 1) + FUSE + 2.5;
        let litInPar = false;
        while (world.time < end && !run.lit.every(Boolean)) {
          if (fired < lv.shells && world.time >= fireAt(fired) - 1e-9) {
            const dark = run.lit.flatMap((l, i) => (l ? [] : [i]));
            const [lx, ly] = lanternAt(ls[dark[Math.floor(rand() * dark.length)]], sky, world.time);
            const a = 2 * Math.PI * rand(),
              d = 0.08 * sky.width * Math.sqrt(rand());
            launchShell(world, show, lx + d * Math.cos(a), ly + d * Math.sin(a), lv.hold ? rand() * MAX_HOLD : 0, lv.shell);
            countShell(run);
            fired++;
          }
          stepFireworks(world, show);
          lightFromSparks(world, show, run);
          if (run.lit.every(Boolean) && fired <= lv.par && world.time < parEnd) litInPar = true;
        }
        if (litInPar) good++;
        if (run.lit.every(Boolean)) cleared++;
      }
      shares.push(`${sky.name} ${good}/${tries} (cleared with its ${lv.shells} shells ${cleared}/${tries})`);
    }
    console.log(`level ${n} ${lv.name}: random aims near dark lanterns that light it in par ${lv.par}: ${shares.join(', ')}`);
  }
}
process.exitCode = failed > 0 ? 1 : 0;
