/**
 * The end of a round in each of the rotating cube's modes, for its banner (game-kit's result card): whether the
 * round is over and what the banner then says: the pads (all reached: the stars by moves against
 * par), the spins (all three held: the stars by time) and the flips (won with FLIP_GOAL flips in
 * time, the stars by that time, or lost, no stars, when FLIP_TIME runs out). Pure (no DOM, no three.js).
 */
import type { PhysicsWorld } from '@bitphysics/physics';
import { FLIP_BAND, FLIP_GOAL, FLIP_STAR_TIMES, type FlipChallenge, type Mode, PAR_SLACK, type PadChallenge, padStars } from './scene';
import { SPIN_STAR_TIMES, type SpinChallenge } from './spin-challenge';

/** `n` stars of three as text: filled then hollow ('★★☆' for 2). @throws RangeError if n is not an integer in [0, 3]. */
export function starText(n: number): string {
  if (!Number.isInteger(n) || n < 0 || n > 3) throw new RangeError(`starText: n must be an integer in [0, 3], got ${n}`);
  return '★'.repeat(n) + '☆'.repeat(3 - n);
}

/** What the banner says at a round's end and what its two buttons are called. */
export interface RoundEndContent {
  /** First line, bold ('All 5 pads!', 'Time!'). */
  title: string;
  /** The result in large gold type ('★★★ 9 moves'). */
  big: string;
  /** A line of detail under it (par, best, time); may be ''. */
  detail: string;
  /** The Next button's words ('New pads'), run by the button and by Enter. */
  next: string;
  /** The Retry button's words ('Same pads'), run by the button (R runs the game's reset, the same). */
  retry: string;
  /** Whether the round was won (a gold edge) or lost (a red one). */
  won: boolean;
}

/** The three rounds' challenges, as the game keeps them. */
export interface Rounds {
  pads: PadChallenge;
  spins: SpinChallenge;
  flips: FlipChallenge;
}

/** The words the flip round's end card needs from the page. */
export interface FlipEndWords {
  /** What kicks the box, as the player sees it ('W or S'; on a phone 'the Pitch ▲ ▼ buttons'). */
  kick?: string;
  /** What spins the box up, as the player sees it ('D'; on a phone 'Yaw ▶'). */
  spinUp?: string;
  /** The fastest FLIP_GOAL flips of this visit before this round, s (Infinity: none). */
  bestFlipTime?: number;
}

/**
 * What the banner says at the end of the round of `mode` in `world`, or null while the round runs.
 * `bestMoves`: the fewest moves of a pad round this visit before this one (Infinity: none);
 * `flipWords`: the flip round's kick keys and best time (FlipEndWords).
 */
export function roundEnd(
  mode: Mode,
  rounds: Rounds,
  world: PhysicsWorld,
  bestMoves = Infinity,
  flipWords: FlipEndWords = {},
): RoundEndContent | null {
  const { pads, spins, flips } = rounds;
  if (mode === 'room') {
    if (!pads.done) return null;
    const par = pads.par;
    return {
      title: `All ${pads.layout.pads.length} pads!`,
      big: `${starText(padStars(pads.moves, par))} ${pads.moves} moves`,
      detail: `par ${par} · ★★★ takes ${par + PAR_SLACK[0]} or fewer · best ${Math.min(bestMoves, pads.moves)} · ${pads.time().toFixed(1)} s`,
      next: 'New pads',
      retry: 'Same pads',
      won: true,
    };
  }
  if (mode === 'cube') {
    if (!spins.won) return null;
    return {
      title: `All ${spins.targets.length} spins!`,
      big: `${starText(spins.stars())} ${spins.time(world.time).toFixed(1)} s`,
      detail: `★★★ within ${SPIN_STAR_TIMES[0]} s, ★★ ${SPIN_STAR_TIMES[1]} s · next: a box that flips over`,
      next: 'Flipping box',
      retry: 'Again',
      won: true,
    };
  }
  if (!flips.over(world)) return null;
  const won = flips.wonAt >= 0;
  const kick = flipWords.kick ?? 'W or S';
  const best = Math.min(flipWords.bestFlipTime ?? Infinity, won ? flips.time(world.time) : Infinity);
  const bestText = Number.isFinite(best) ? `best ${best.toFixed(1)} s · ` : '';
  return {
    title: won ? `${FLIP_GOAL} flips!` : 'Time!',
    big: won
      ? `${starText(flips.stars())} ${flips.time(world.time).toFixed(1)} s`
      : `${starText(flips.stars())} ${flips.counter.count} flips`,
    detail: won
      ? `${bestText}★★★ within ${FLIP_STAR_TIMES[0]} s, ★★ ${FLIP_STAR_TIMES[1]} s: a kick (${kick}) makes it flip sooner`
      : `${bestText}flips count only while the spin stays ${FLIP_BAND[0]} to ${FLIP_BAND[1]} rad/s: it slows down, so tap ${flipWords.spinUp ?? 'D'} each time it sags`,
    next: 'Back to the pads',
    retry: 'Try again',
    won,
  };
}
