/**
 * The flight simulator's "let go now" cue for a turn: let go of a bank key or the stick and the assist
 * rolls the wings level (./assist.ts), but the aircraft goes on turning while they roll, several
 * degrees from a steep bank (`runOnTurn`), so a player who lets go when the ring is straight ahead
 * swings past it. The cue says when to let go so that the turn ends on the ring (`letGoCue`): the
 * ring's bearing is within the turn still to come. Headless (no DOM), tested in node
 * (test/games/flight-simulator-let-go.test.ts).
 */

import { LET_GO } from './course';

/** Gravity, m/s^2 (the turn rate of a coordinated turn is g tan(bank) / V). */
const G = 9.81;
/** Largest bank the run-on is reckoned with, rad (a steeper bank's tangent runs away). */
const STEEPEST = (75 * Math.PI) / 180;

/** What a let-go now does to the path before the wings are level (`runOnTurn`). */
export interface RunOn {
  /** The heading the path turns on, rad (+ right). */
  turn: number;
  /** The path's turn rate now, rad/s (+ right): g tan(bank) / speed. */
  rate: number;
  /** Where the aircraft is when the wings are level, m, from where it is now: along its path's heading now and to its right. */
  forward: number;
  side: number;
}

/**
 * What the aircraft's path still does after a let-go now, until the wings are level: its bank `bank`
 * (rad, + right) rolled back to level as ./course.ts predictThroughRing rolls it (LET_GO: the roll
 * rate `rollRate` rad/s turning towards a roll back to level), the path turning at g tan(bank) /
 * `speed` the while, flown level at `speed` m/s. From a 70 degree bank at 115 m/s it turns about 6
 * degrees on; from wings level, nothing.
 * @throws RangeError on a bank or roll rate that is not finite, or a speed that is not > 0.
 */
export function runOnTurn(bank: number, rollRate: number, speed: number): RunOn {
  if (!Number.isFinite(bank) || !Number.isFinite(rollRate))
    throw new RangeError(`runOnTurn: bank and rollRate must be finite, got ${bank}, ${rollRate}`);
  if (!(speed > 0 && Number.isFinite(speed))) throw new RangeError(`runOnTurn: speed must be finite and > 0 m/s, got ${speed}`);
  const dt = 1 / 60;
  let b = bank,
    omega = rollRate;
  const turnRate = (bank: number) => (G * Math.tan(Math.max(-STEEPEST, Math.min(STEEPEST, bank)))) / speed;
  const out = { turn: 0, rate: turnRate(bank), forward: 0, side: 0 };
  for (let t = 0; t < 4 && Math.abs(b) > 1e-3; t += dt) {
    const wanted = -Math.sign(b) * Math.min(LET_GO.rollRate, Math.abs(b) / LET_GO.bankTime);
    omega += (wanted - omega) * (1 - Math.exp(-dt / LET_GO.rollLag));
    b += omega * dt;
    out.turn += turnRate(b) * dt;
    out.forward += speed * Math.cos(out.turn) * dt;
    out.side += speed * Math.sin(out.turn) * dt;
  }
  return out;
}

/**
 * How early the cue shows, s of the turn: a player lets go a moment after seeing it (about 0.2 s), so
 * it shows once the ring is within the run-on plus what the path turns in that moment (2.7 degrees
 * at full bank, under a degree at 30 degrees), and one let go that much later ends the turn on the
 * ring rather than past it.
 */
export const LET_GO_LEAD = 0.2;
/** Least lead of the cue, rad (0.5 degrees: a shallow turn's cue still shows for a frame or two). */
export const LET_GO_WINDOW = 0.5 * (Math.PI / 180);
/** How far past the ring a held turn still shows the cue, rad (20 degrees): past that the ring is the other way and the ring's own pointer says so. */
export const LET_GO_PAST = 20 * (Math.PI / 180);

/**
 * The bearing of a point (`dx`, `dz`: m, world, from the aircraft) from the path's heading once the
 * wings are level after a let-go now (`runOn`, from `runOnTurn`), the path's heading now being
 * `heading` (rad, atan2(vz, vx)): rad, + to the right, in (-pi, pi].
 * @throws RangeError on a value that is not finite.
 */
export function bearingAfterLetGo(dx: number, dz: number, heading: number, runOn: RunOn): number {
  if (![dx, dz, heading, runOn.turn, runOn.forward, runOn.side].every(Number.isFinite))
    throw new RangeError(
      `bearingAfterLetGo: dx, dz, heading and runOn must be finite, got ${dx}, ${dz}, ${heading}, ${JSON.stringify(runOn)}`,
    );
  // The point in the path's frame now (forward, right: +z is to the right of +x), less where the
  // aircraft will be, seen along the heading it will have.
  const c = Math.cos(heading),
    s = Math.sin(heading);
  const f = dx * c + dz * s - runOn.forward,
    r = -dx * s + dz * c - runOn.side;
  const b = Math.atan2(r, f) - runOn.turn;
  return Math.atan2(Math.sin(b), Math.cos(b));
}

/**
 * Whether to show "let go now": a bank is held (`rollInput`, the stick's or keys' sideways input in
 * [-1, 1], not 0) the way the aircraft turns (`runOn.turn`), and let go now, the path would end with
 * the ring's centre (`after`: its `bearingAfterLetGo`) no farther round that way than the path turns in
 * LET_GO_LEAD s (at least LET_GO_WINDOW): let go as it shows, or a moment after, and the turn ends on the ring, or past it if the cue came late (up to LET_GO_PAST: let go all the
 * more). A turn the other way, or a ring farther round, does not show it.
 * @throws RangeError on a bearing or input that is not finite.
 */
export function letGoCue(after: number, runOn: RunOn, rollInput: number): boolean {
  if (![after, runOn.turn, runOn.rate, rollInput].every(Number.isFinite))
    throw new RangeError(
      `letGoCue: after, runOn.turn, runOn.rate and rollInput must be finite, got ${after}, ${runOn.turn}, ${runOn.rate}, ${rollInput}`,
    );
  if (rollInput === 0 || runOn.turn === 0 || Math.sign(rollInput) !== Math.sign(runOn.turn)) return false;
  // The turn still to come to the ring, measured the way the aircraft turns.
  const ahead = Math.sign(runOn.turn) * after;
  return ahead >= -LET_GO_PAST && ahead <= Math.max(LET_GO_WINDOW, Math.abs(runOn.rate) * LET_GO_LEAD);
}
