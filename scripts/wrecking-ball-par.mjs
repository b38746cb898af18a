// `node scripts/wrecking-ball-par.mjs [--full | --careful] [level ...]`: how many taps the wrecking ball's levels
// (1-based; default 1 to 5) take a first-time player, headless, from the page's start (the jib
// between the structures, `openStart`). Three plain ways a stranger taps (a tap and a second tap on
// the piece, the page's swing along the arrow it shows: `tapTap`), each
// tap 2 s after the last swing's moves end (once the count has settled; the ball still swinging from
// its hit): `top` taps the highest standing piece of each structure in turn (what the eye goes to),
// `biggest` the piece a third of the way up the structure with the most standing raised pieces (those
// that stood above the ground), `near` the standing raised piece nearest the ball. Each way is played
// from first taps a few steps apart (FIRST_TAP_STEPS). Prints, per level, way and start, the fallen
// count after each tap until the level was cleared (or "not in 8") and the stars it earned
// (`swingStars`; none past the budget), a tap whose ball never touched the structure of the piece
// tapped marked "(missed)"; then each level's budget (games/wrecking-ball/scene.ts swingBudget) and
// par beside the most taps any game took, how many games earned each number of stars, the taps that
// missed and the median time from a tap to the ball's first touch of the structure. The ball touches the
// structure when a contact of the two begins, or when it is in contact with it as the swing arrives
// or within half a second after (a ball left resting against a structure begins no contact when the
// swing drives it in). With --full every game goes on to 8 taps (to compare clearing shares). With
// --careful, instead, a careful player's game against the level's par (`swingPar`): each swing the
// standing raised piece that brings down the most (every one tried, from the first start), and the
// pieces a first swing at each raised piece brings down, best first. Takes a minute or two a level
// (--careful a few minutes a swing; meant for the first levels).
import { importSource } from './build.mjs';

/** Most taps a way gets before it counts as not clearing the level. */
const MOST_TAPS = 8;
/**
 * Steps (60 a second) before a way's first tap: each way is played from each. A swing's outcome
 * hangs on such small differences (a step later, a wall's swing brought down 4 bricks instead of 6),
 * so the most taps over these is the measure, not one game's.
 */
const FIRST_TAP_STEPS = [30, 31, 35];
const wb = await importSource(
  'wrecking-ball-par',
  "export * from './games/wrecking-ball/scene.ts'; export { contactEvents, createPhysicsWorld, forEachContact, step } from '@bitphysics/physics';",
);
const full = process.argv.includes('--full');
const careful = process.argv.includes('--careful');
const levels = process.argv
  .slice(2)
  .filter((a) => !a.startsWith('--'))
  .map(Number);
for (const n of levels) if (!(Number.isInteger(n) && n >= 1)) throw new RangeError(`wrecking-ball-par: levels are integers >= 1, got ${n}`);
const chosen = levels.length ? levels : [1, 2, 3, 4, 5];

/**
 * Structures: pieces linked by start centres within LINK m of each other across the ground (a
 * wall's bricks 1.2 m apart, a stack's crossing planks 1.3 m, a tower's cubes one over another;
 * structures stand 3 m apart or more). Grouped around a first piece within 2.5 m, a wall 4.8 m
 * long fell into two structures, and a ball that struck the tapped brick's neighbour counted as
 * a miss.
 */
const LINK = 1.5;
const structures = (pieces) => {
  const groups = [];
  for (const p of pieces) {
    const near = groups.filter((g) => g.some((q) => Math.hypot(q.x0 - p.x0, q.z0 - p.z0) < LINK));
    const merged = [p];
    for (const g of near) {
      merged.push(...g);
      groups.splice(groups.indexOf(g), 1);
    }
    groups.push(merged);
  }
  return groups
    .map((g) => [...g].sort((a, b) => pieces.indexOf(a) - pieces.indexOf(b)))
    .sort((a, b) => pieces.indexOf(a[0]) - pieces.indexOf(b[0]));
};
/** Whether a piece stood above the ground (a bottom row piece rarely falls: a player goes for what stands tall). */
const raised = (p) => p.y0 - p.half[p.upAxis] > 0.01;
const ways = {
  top: ({ taps, groups }) => {
    const live = groups.filter((g) => g.some((p) => !p.fallen));
    if (live.length === 0) return null;
    const g = live[taps % live.length];
    return g.filter((p) => !p.fallen).reduce((a, b) => (b.y0 > a.y0 ? b : a));
  },
  biggest: ({ groups }) => {
    const g = groups.map((g) => g.filter((p) => !p.fallen && raised(p))).reduce((a, b) => (b.length > a.length ? b : a));
    const s = g.sort((a, b) => a.y0 - b.y0);
    return s[Math.floor(s.length / 3)] ?? null;
  },
  near: ({ world, h }) => {
    const P = world.components.Position;
    let best = null,
      d = Number.POSITIVE_INFINITY;
    for (const p of h.pieces) {
      if (p.fallen || !raised(p)) continue;
      const e = Math.hypot(P.x[p.body] - P.x[h.ball], P.z[p.body] - P.z[h.ball]);
      if (e < d) {
        d = e;
        best = p;
      }
    }
    return best;
  },
};
/**
 * The page's tap on piece `piece` and a second tap on it: the swing the arrow shows, the ball coming
 * straight from where it hangs at the tap's power (games/wrecking-ball/main.ts beginAim, TAP_POWER
 * 1: swingSpeed(1), FULL_SWING_SPEED, 0.8 HIT_SPEED), struck at the piece's own height as the page's swings are.
 */
const tapTap = (world, h, piece) => {
  const P = world.components.Position;
  const direction = Math.atan2(P.z[piece] - P.z[h.ball], P.x[piece] - P.x[h.ball]);
  wb.aimAt(world, h, piece, { direction, speed: wb.swingSpeed(1) });
};
const most = {},
  stars = {},
  missed = {},
  tapped = {},
  toHit = {};
/** Median of a list of numbers (null when empty). */
const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length ? s[Math.floor(s.length / 2)] : null;
};
/**
 * Level `level` played from step FIRST_TAP_STEPS[0] by tapping the pieces at indices `taps` in turn,
 * each tap once the last swing has settled as in the ways' games: the pieces and the fallen count.
 */
const playTaps = (level, taps) => {
  const world = wb.createPhysicsWorld(wb.wreckingBallWorldOptions());
  const h = wb.buildWreckingBall(world, { level, openStart: true });
  const run = () => {
    wb.step(world);
    wb.scorePieces(world, h.pieces);
  };
  for (let k = 0; k < FIRST_TAP_STEPS[0]; k++) wb.step(world);
  for (const index of taps) {
    tapTap(world, h, h.pieces[index].body);
    let idle = 0;
    for (let k = 0; k < 60 * 15 && (h.controls.moves.length > 0 || idle++ < 30); k++) run();
    for (let k = 0; k < 90; k++) run();
  }
  return { pieces: h.pieces, down: wb.fallenCount(h.pieces) };
};
if (careful) {
  for (const level of chosen) {
    const first = playTaps(level, []);
    const target = wb.clearTarget(first.pieces, level);
    const taps = [],
      downs = [],
      alone = [];
    let pieces = first.pieces,
      down = 0;
    while (down < target && taps.length < wb.swingBudget(level)) {
      let best = null;
      pieces.forEach((p, i) => {
        if (p.fallen || !raised(p)) return;
        const r = playTaps(level, [...taps, i]);
        if (taps.length === 0) alone.push(r.down);
        if (best === null || r.down > best.r.down) best = { i, r, kind: p.kind };
      });
      if (best === null) break;
      taps.push(best.i);
      pieces = best.r.pieces;
      down = best.r.down;
      downs.push(`${down} (${best.kind})`);
    }
    alone.sort((a, b) => b - a);
    console.log(
      `level ${level} careful: ${down >= target ? `cleared in ${taps.length}` : `not in ${taps.length}`} (par ${wb.swingPar(level)}, clear at ${target}; down after each swing ${downs.join(' ')}); a first swing at each of the ${alone.length} raised pieces downs ${alone.join(' ')}, ${alone.filter((d) => d >= target).length} of them clearing it alone`,
    );
  }
  process.exit(0);
}
for (const level of chosen) {
  most[level] = 0;
  stars[level] = [];
  missed[level] = 0;
  tapped[level] = 0;
  toHit[level] = [];
  for (const [name, choose] of Object.entries(ways))
    for (const first of FIRST_TAP_STEPS) {
      const world = wb.createPhysicsWorld(wb.wreckingBallWorldOptions());
      const h = wb.buildWreckingBall(world, { level, openStart: true });
      const groups = structures(h.pieces);
      const target = wb.clearTarget(h.pieces, level);
      for (let k = 0; k < first; k++) wb.step(world);
      let taps = 0,
        cleared = false;
      const downs = [];
      while (taps < MOST_TAPS && !cleared) {
        const piece = choose({ world, h, taps, groups });
        if (!piece) break;
        tapTap(world, h, piece.body);
        taps++;
        const structure = new Set(groups.find((g) => g.includes(piece)).map((p) => p.body));
        let idle = 0,
          touched = false,
          steps = 0,
          arrival = -1;
        const run = () => {
          wb.step(world);
          steps++;
          wb.scorePieces(world, h.pieces);
          if (touched) return;
          const ev = wb.contactEvents(world).begin;
          for (let i = 0; i < ev.count; i++)
            if ((ev.bodyA[i] === h.ball && structure.has(ev.bodyB[i])) || (ev.bodyB[i] === h.ball && structure.has(ev.bodyA[i])))
              touched = true;
          // The swing's arrival: its follow-through has begun (or no moves are left); contacts in
          // the half second from there count.
          if (arrival < 0 && (h.controls.moves.length === 0 || h.controls.moves[0].follow === true)) arrival = steps;
          if (!touched && arrival >= 0 && steps <= arrival + 30)
            wb.forEachContact(world, (c) => {
              if (c.separation > 0.01) return;
              if ((c.bodyA === h.ball && structure.has(c.bodyB)) || (c.bodyB === h.ball && structure.has(c.bodyA))) touched = true;
            });
          if (touched) toHit[level].push(steps / 60);
        };
        for (let k = 0; k < 60 * 15 && (h.controls.moves.length > 0 || idle++ < 30); k++) run();
        // A player looks at the count once the dust settles: 1.5 s more.
        for (let k = 0; k < 90; k++) run();
        tapped[level]++;
        if (!touched) missed[level]++;
        downs.push(`${wb.fallenCount(h.pieces)}${touched ? '' : ' (missed)'}`);
        cleared = !full && wb.fallenCount(h.pieces) >= target;
      }
      most[level] = Math.max(most[level], cleared ? taps : MOST_TAPS + 1);
      const earned = cleared && taps <= wb.swingBudget(level) ? wb.swingStars(taps, true, level) : 0;
      stars[level].push(earned);
      console.log(
        `level ${level} ${name.padEnd(7)} first tap at step ${String(first).padEnd(2)} ${cleared ? `cleared in ${taps} taps, ${earned} stars` : `not in ${MOST_TAPS}`} (${wb.fallenCount(h.pieces)} of ${h.pieces.length} down, clear at ${target}; down after each tap ${downs.join(' ')})`,
      );
    }
}
for (const level of chosen)
  console.log(
    `level ${level}: budget ${wb.swingBudget(level)}, par ${wb.swingPar(level)}, the most any way took ${most[level] > MOST_TAPS ? `over ${MOST_TAPS}` : most[level]}; stars ${[3, 2, 1, 0].map((n) => `${n}: ${stars[level].filter((e) => e === n).length}`).join(', ')}; missed ${missed[level]} of ${tapped[level]} taps; tap to touch median ${median(toHit[level])?.toFixed(2) ?? '-'} s, longest ${toHit[level].length ? Math.max(...toHit[level]).toFixed(2) : '-'} s`,
  );
