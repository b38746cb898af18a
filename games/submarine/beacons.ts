/**
 * The beacon pointer's choice: which beacon the arrow at the screen's edge leads to (the target).
 * It holds one beacon until a beacon is collected, however near the others pass (a target that
 * flips between beacons as the boat goes by them leaves a player not knowing which to chase), and then
 * takes the next one left along the course. Headless (no drawing), so the rule is tested in node.
 */

import { Rng } from '@bitphysics/physics';
import { assertFinite } from '@bitphysics/physics/validate';
import { SUBMARINE, type SubmarineHandles, seabedHeight } from '@bitphysics/projects';
import { hullDistance } from './hull';

/**
 * A beacon is collected when any part of the hull (its 12 m x 3 m box) comes within this of it, m:
 * the radius of the ring drawn round each beacon, so the boat touching the ring collects it (with
 * the hull's centre within 8 m, the bow could be deep inside the drawn disc with nothing happening,
 * which reads as "only at the centre").
 */
export const BEACON_CATCH = 8;

/**
 * Whether the hull, a box `SUBMARINE.length` x `SUBMARINE.height` centred at (x, y) m and turned by
 * `angle` rad, reaches within `BEACON_CATCH` of the beacon at (bx, by), m: the beacon taken into the
 * hull's frame, then its distance to the nearest point of the box.
 * @throws RangeError when a coordinate or the angle is not finite.
 */
export function catchesBeacon(x: number, y: number, angle: number, bx: number, by: number): boolean {
  assertSegment('catchesBeacon', x, y, bx, by);
  assertFinite('catchesBeacon', 'angle', angle);
  return hullDistance(x, y, angle, bx, by) < BEACON_CATCH;
}

/** The course's legs after the first beacon: each next beacon lies this far along x past the one before, at most, m. */
export const LEG_MAX = 130;
/** The shortest leg as a share of the longest one the course allows (`LEG_MAX`, less on a long course). */
export const LEG_MIN_SHARE = 0.65;
/** The straight way from one beacon to the next clears the seabed by this much where it can, m. */
export const LEG_CLEARANCE = 8;

/**
 * Re-lays the beacons after the first (in place) into a course of short, open legs: each next
 * beacon `LEG_MIN_SHARE` to 1 times the longest leg further along x (`LEG_MAX`, or less so that all
 * of them end by x = 1,000 m, inside the scene's seabed), between 8 m over the seabed and 10 m under
 * the surface, at a depth whose straight line from the beacon before clears the seabed by
 * `LEG_CLEARANCE` (of 16 seeded tries, the first that does, else the one that clears it most). The
 * scene's own layout spread them over 900 m whatever their number: legs of up to 300 m, some behind
 * a ridge. The first beacon (close to the start) is kept. Seeded: the same course every time.
 * @param beacons (x, y) pairs, m, as the scene laid them; rewritten from the second pair on.
 * @param seabed the scene's seabed.
 * @param seed any finite number (the course's seed).
 * @throws RangeError when `seed` is not finite.
 */
export function layCourse(beacons: Float64Array, seabed: SubmarineHandles['seabed'], seed: number): void {
  if (!Number.isFinite(seed)) throw new RangeError(`layCourse: seed must be finite, got ${seed}`);
  const n = beacons.length / 2;
  if (n < 2) return;
  const rng = new Rng(seed * 104_729 + 31);
  const bedAt = (x: number) => seabedHeight(seabed, x);
  const longest = Math.min(LEG_MAX, (1000 - beacons[0]!) / (n - 1));
  for (let i = 1; i < n; i++) {
    const px = beacons[2 * i - 2]!,
      py = beacons[2 * i - 1]!;
    const x = px + longest * (LEG_MIN_SHARE + (1 - LEG_MIN_SHARE) * rng.next());
    const floor = bedAt(x) + 8;
    let best = -10,
      bestClear = Number.NEGATIVE_INFINITY;
    for (let k = 0; k < 16; k++) {
      const y = floor + (-10 - floor) * rng.next();
      const clear = clearance(px, py, x, y, bedAt);
      if (clear > bestClear) {
        best = y;
        bestClear = clear;
      }
      if (clear >= LEG_CLEARANCE) break;
    }
    beacons[2 * i] = x;
    beacons[2 * i + 1] = best;
  }
}

/** The least height of the straight line from (x0, y0) to (x1, y1), m, over the seabed `bedAt`, sampled every metre or less. */
function clearance(x0: number, y0: number, x1: number, y1: number, bedAt: (x: number) => number): number {
  const n = Math.max(1, Math.ceil(Math.abs(x1 - x0)));
  let least = Number.POSITIVE_INFINITY;
  for (let i = 0; i <= n; i++) {
    const u = i / n;
    least = Math.min(least, y0 + u * (y1 - y0) - bedAt(x0 + u * (x1 - x0)));
  }
  return least;
}

/**
 * How far along x the hull's centre may run past a beacon before that beacon counts as passed
 * (skipped), m: the boat always faces ahead and backs at half speed (4 m/s, ./helm.ts), so up to
 * this (about 17 s of backing, over half the shortest leg) an overshoot keeps the beacon as the
 * target to back up to; a first run's mistake, a key held seconds too long past a beacon, is
 * recovered instead of costing the beacon. Further on it hands the target to the next one ahead
 * rather than leading minutes back. A passed beacon is still collectable by going back for it at
 * any time before the finish (the run ends at the last beacon, `lastBeacon`); left uncollected it
 * costs its points and the "every beacon" star. The ring (`BEACON_CATCH`) plus half the hull is
 * 14 m, so a boat that only scrapes past a ring still has it as its target.
 */
export const BEACON_PASSED = 70;

/** Course order: the first beacon (by the start) ranks first, the others by x. */
function courseRank(beacons: ArrayLike<number>, i: number): number {
  return i === 0 ? Number.NEGATIVE_INFINITY : beacons[2 * i]!;
}

/**
 * The last beacon along the course (the finish: collecting it ends the run), its index; -1 with no
 * beacons. `beacons`: (x, y) pairs, m.
 */
export function lastBeacon(beacons: ArrayLike<number>): number {
  let last = -1;
  for (let i = 0; i < beacons.length / 2; i++) if (last < 0 || courseRank(beacons, i) > courseRank(beacons, last)) last = i;
  return last;
}

/**
 * How far the boat can go on before beacon `i` counts as passed (`passedBeacon`), m, while it is
 * moving away from it: the hull's centre at `x` (m) has gone past the beacon by more than its ring
 * and half a hull (`BEACON_CATCH` + 6 m), is moving on ahead at `vx` > 0.5 m/s (m/s along x), and
 * the beacon is not the last (the finish is never passed); NaN otherwise (no warning). The page warns
 * with it, so a beacon is never lost without notice. `beacons`: (x, y) pairs, m.
 * @throws RangeError when `x` or `vx` is not finite or `i` is not an index of `beacons`.
 */
export function missWarning(beacons: ArrayLike<number>, i: number, x: number, vx: number): number {
  assertFinite('missWarning', 'x', x);
  assertFinite('missWarning', 'vx', vx);
  if (!(Number.isInteger(i) && i >= 0 && i < beacons.length / 2)) throw new RangeError(`missWarning: i must be a beacon index, got ${i}`);
  const behind = x - beacons[2 * i]!;
  if (behind <= BEACON_CATCH + 6 || vx <= 0.5 || i === lastBeacon(beacons)) return Number.NaN;
  return Math.max(0, BEACON_PASSED - behind);
}

/**
 * The speed along x above which the boat counts as moving on ahead (a beacon behind it by more than
 * `BEACON_PASSED` is passed, `passedBeacon`) or, below its negative, as backing (towards the beacons
 * behind it, `chooseBeacon`), m/s. Slower it is stopping or stopped: nothing changes.
 */
export const MOVING_ON = 0.5;

/**
 * Whether beacon `i` has been passed by a hull whose centre is at `x`, m, moving along x at `vx`
 * m/s (default 1: moving on ahead): it lies more than `BEACON_PASSED` behind along x, the boat is
 * moving on away from it (`vx` > `MOVING_ON`: never while it backs towards it or has stopped, so a
 * player who turns back on the warning keeps the beacon), and it is not the last beacon along the
 * course (the finish is never passed). `beacons`: (x, y) pairs, m.
 * @throws RangeError when `x` or `vx` is not finite or `i` is not an index of `beacons`.
 */
export function passedBeacon(beacons: ArrayLike<number>, i: number, x: number, vx = 1): boolean {
  assertFinite('passedBeacon', 'x', x);
  assertFinite('passedBeacon', 'vx', vx);
  if (!(Number.isInteger(i) && i >= 0 && i < beacons.length / 2)) throw new RangeError(`passedBeacon: i must be a beacon index, got ${i}`);
  return x - beacons[2 * i]! > BEACON_PASSED && vx > MOVING_ON && i !== lastBeacon(beacons);
}

/**
 * How far ahead of the hull its target may lie while the boat backs and stays its target, m: a
 * player who braked short of it with Astern and backs on a little keeps it; backing on further, the
 * target turns to the beacon behind the boat (`chooseBeacon`). Two ring widths and a hull.
 */
export const TURNED_BACK = 2 * BEACON_CATCH + SUBMARINE.length;

/**
 * How near behind the hull (along x, m) a skipped beacon must be for a boat backing towards it to
 * take it as its target (`chooseBeacon`): 25 m, about half a phone's view at rest (60 m across).
 * Further back the target stays the beacon ahead the player was going for, so braking with Astern
 * or backing a little does not swing the label round to a beacon skipped far behind.
 */
export const BACK_REACH = 25;

/**
 * The hull's speed along x as the beacon rules count it (`chooseBeacon`, `passedBeacon`), m/s:
 * while the pilot asks for Astern (`astern`) only backing counts (min(`vx`, 0)); otherwise only
 * going ahead (max(`vx`, 0)), so a boat carried back by a current, or coasting on after Astern is
 * let go, is not taken to be turning back for a beacon behind it.
 * @throws RangeError when `vx` is not finite.
 */
export function courseSpeed(vx: number, astern: boolean): number {
  assertFinite('courseSpeed', 'vx', vx);
  return astern ? Math.min(vx, 0) : Math.max(vx, 0);
}

/**
 * The beacon the pointer leads to from the hull at (x, y), m, moving along x at `vx` m/s. The target
 * is the beacon the boat is heading for. Backing (`vx` < -`MOVING_ON`), that is the nearest
 * uncollected beacon behind the hull (its x less than the hull's) when a beacon was collected this
 * step, or (once that beacon is within `BACK_REACH` behind) the target is collected or lies more
 * than `TURNED_BACK` ahead: a player backing to fetch
 * a skipped beacon who collects another on the way is led on to the skipped one, not to the next
 * one ahead (one who backs a little after braking short of the target keeps it). Otherwise
 * the target stays ahead of the boat: beacons passed (`passedBeacon`: far behind with the boat
 * moving on, not the finish) are never chosen while another is left. With `justTaken` (a beacon
 * collected this step, its index) the next uncollected one along the course after it (course order:
 * the first beacon, then by x), so a boat that passes beacon A and collects C is led on, not back to
 * A behind it. Otherwise `current` while it is uncollected and not passed (it is held, however near
 * another one comes); a current one passed hands over to the first one left along the course; with
 * no current one (-1, out of range or collected), the nearest one left. Only passed ones left: the
 * first of those along the course. -1 when all are collected.
 * @param beacons (x, y) pairs, m.
 * @param taken Whether each beacon has been collected.
 * @param justTaken the beacon collected this step, or -1 (default) when none was.
 * @param vx the hull's speed along x, m/s (default 1: moving on ahead).
 */
export function chooseBeacon(
  beacons: ArrayLike<number>,
  taken: readonly boolean[],
  x: number,
  y: number,
  current: number,
  justTaken = -1,
  vx = 1,
): number {
  const valid = (i: number) => i >= 0 && i < taken.length;
  const behindHull = (i: number) => beacons[2 * i]! < x;
  const held = !valid(justTaken) && valid(current) && !taken[current];
  if (vx < -MOVING_ON && !(held && beacons[2 * current]! - x <= TURNED_BACK)) {
    let back = -1;
    for (let i = 0; i < taken.length; i++) if (!taken[i] && behindHull(i) && (back < 0 || beacons[2 * i]! > beacons[2 * back]!)) back = i;
    if (back >= 0 && (valid(justTaken) || x - beacons[2 * back]! <= BACK_REACH)) return back;
  }
  const open = (i: number) => !taken[i] && !passedBeacon(beacons, i, x, vx);
  if (!valid(justTaken) && valid(current) && open(current)) return current;
  const passedOn = !valid(justTaken) && valid(current) && !taken[current];
  if (valid(justTaken) || passedOn) {
    const from = valid(justTaken) ? courseRank(beacons, justTaken) : Number.NEGATIVE_INFINITY;
    let after = -1,
      first = -1;
    for (let i = 0; i < taken.length; i++) {
      if (taken[i]) continue;
      const r = courseRank(beacons, i);
      if (open(i) && r > from && (after < 0 || r < courseRank(beacons, after))) after = i;
      if (first < 0 || r < courseRank(beacons, first)) first = i;
    }
    return after >= 0 ? after : first;
  }
  let nearest = -1,
    best = Infinity;
  for (let i = 0; i < taken.length; i++) {
    if (taken[i]) continue;
    // A passed beacon only when no other is left.
    const d = Math.hypot(beacons[2 * i]! - x, beacons[2 * i + 1]! - y) + (open(i) ? 0 : 1e9);
    if (d < best) {
      best = d;
      nearest = i;
    }
  }
  return nearest;
}

/**
 * The longest line the pointer's label may have, characters: at its 15 px bold type some 9 px each,
 * 33 of them and the label's pill fit a phone's 390 px view beside the depth gauge (364 px; a
 * line of 49 ran off the right edge).
 */
export const LABEL_LINE_MAX = 33;

/**
 * What the pointer's label adds while the boat goes away from its target (`missWarning` is `left`
 * m, >= 0): two lines of at most LABEL_LINE_MAX characters.
 * @throws RangeError when `left` is not finite or negative.
 */
export function missWarningText(left: number): string {
  if (!Number.isFinite(left) || left < 0) throw new RangeError(`missWarningText: left must be finite and >= 0, got ${left}`);
  return `⚠ going away: Astern to fetch it\n(skipped in ${Math.ceil(left)} m)`;
}

/** What the pointer's label adds when the seabed rises between the hull and its beacon. */
export const RIDGE_WARNING = '⚠ ridge in the way: climb over it';

/**
 * What the pointer's label adds when a live mine lies on the straight way to its beacon
 * (./mines.ts `mineOnWay`): which side to pass it.
 */
export const MINE_WARNING = Object.freeze({ over: '⚠ mine on the way: pass over it', under: '⚠ mine on the way: pass under it' });

/**
 * Throws unless the segment from (x0, y0) to (x1, y1), m, has finite ends; `where` names the caller.
 * @throws RangeError naming the first coordinate that is not finite.
 */
export function assertSegment(where: string, x0: number, y0: number, x1: number, y1: number): void {
  assertFinite(where, 'x0', x0);
  assertFinite(where, 'y0', y0);
  assertFinite(where, 'x1', x1);
  assertFinite(where, 'y1', y1);
}

/**
 * Whether the straight line from the hull at (x0, y0) to the beacon at (x1, y1), m (y up), passes
 * below the seabed anywhere: sampled every metre or less along x, and true where the line is under
 * `bedAt(x)` (the seabed's height there, m). Going straight for the beacon would then run into a ridge.
 * @throws RangeError when a coordinate is not finite.
 */
export function seabedBetween(x0: number, y0: number, x1: number, y1: number, bedAt: (x: number) => number): boolean {
  assertSegment('seabedBetween', x0, y0, x1, y1);
  const n = Math.max(1, Math.ceil(Math.abs(x1 - x0)));
  for (let i = 0; i <= n; i++) {
    const u = i / n;
    if (y0 + u * (y1 - y0) < bedAt(x0 + u * (x1 - x0))) return true;
  }
  return false;
}

/** How far under the keel a ridge's crest must lie for the label's ridge warning to clear, m (`ridgeInWay`). */
export const RIDGE_CLEAR_BELOW = 2;
/** The speed along x, m/s, from which a boat going away from its target is moving off the ridge between them (`ridgeInWay`). */
export const RIDGE_LEAVING_SPEED = 0.5;

/**
 * Whether the label warns "climb over it" (`RIDGE_WARNING`) for the hull at (x0, y0), m (y up), its
 * keel at `keel` (m) and moving along x at `vx` (m/s), and its beacon at (x1, y1): the straight way
 * runs under the seabed (`seabedBetween`), the way's crest (the highest bed between the two, sampled
 * every metre or less) stands higher than `RIDGE_CLEAR_BELOW` under the keel (a crest far below the
 * boat asks no climb: the boat goes on over it and dives after), and the boat is not going away
 * from the beacon at `RIDGE_LEAVING_SPEED` or more (the ridge then lies behind it; the warning comes
 * back once it turns for the beacon).
 * @throws RangeError when a coordinate, `keel` or `vx` is not finite.
 */
export function ridgeInWay(
  x0: number,
  y0: number,
  x1: number,
  y1: number,
  bedAt: (x: number) => number,
  keel: number,
  vx: number,
): boolean {
  assertFinite('ridgeInWay', 'keel', keel);
  assertFinite('ridgeInWay', 'vx', vx);
  if (!seabedBetween(x0, y0, x1, y1, bedAt)) return false;
  if ((x1 - x0) * vx < 0 && Math.abs(vx) >= RIDGE_LEAVING_SPEED) return false;
  const n = Math.max(1, Math.ceil(Math.abs(x1 - x0)));
  let crest = Number.NEGATIVE_INFINITY;
  for (let i = 0; i <= n; i++) crest = Math.max(crest, bedAt(x0 + ((x1 - x0) * i) / n));
  return crest > keel - RIDGE_CLEAR_BELOW;
}

/** The pointer's label's depth part while the boat is going to pass at the target's depth (`beaconLabel`). */
export const LEVEL_WORDS = 'level ✓';

/**
 * The pointer's label: how far ahead or behind the beacon lies (level, along the course: the hull's
 * pitch does not change the figures, so a boat nosing down or up reads the same beacon the same way)
 * and how far down or up, each when it is 3 m or more, e.g.
 * "beacon 85 m ahead, 30 m down". The boat moves nearly twice as fast ahead as it dives, so the depth
 * to make up is the part a player must start on early. `dx`, `dy`: the beacon's position minus the
 * hull's, m (y up); `ridge`: a ridge to climb lies across the straight way
 * to it (`ridgeInWay`), which adds `RIDGE_WARNING` on a second line; `mine`: a live mine lies on
 * that way (./mines.ts `mineOnWay`) and on which side to pass it, which adds `MINE_WARNING` there
 * instead when there is no ridge; `name`: the beacon's name (`beaconName`), put first as
 * "target C: 85 m ahead" (the one beacon to steer for, held until collected), so a change of target
 * is seen; without a name the label starts "beacon"; `level`: the boat is going to pass at the
 * beacon's depth (./level-stop.ts `levelWith`), which puts `LEVEL_WORDS` in place of the depth.
 */
export function beaconLabel(dx: number, dy: number, ridge = false, mine: '' | 'over' | 'under' = '', name = '', level = false): string {
  const parts: string[] = [];
  if (Math.abs(dx) >= 3) parts.push(`${Math.abs(dx).toFixed(0)} m ${dx > 0 ? 'ahead' : 'behind'}`);
  if (level) parts.push(LEVEL_WORDS);
  else if (Math.abs(dy) >= 3) parts.push(`${Math.abs(dy).toFixed(0)} m ${dy < 0 ? 'down' : 'up'}`);
  const warning = ridge ? RIDGE_WARNING : mine ? MINE_WARNING[mine] : '';
  return `${name ? `target ${name}: ` : 'beacon '}${parts.length > 0 ? parts.join(', ') : 'here'}${warning ? `\n${warning}` : ''}`;
}

/**
 * The name of beacon `index` (0-based, an integer >= 0) on the page: a letter A to Z, then A2, B2...
 * (letters, so that it is not read as the count of "Beacon 2 of 6").
 * @throws RangeError on an index that is not an integer >= 0.
 */
export function beaconName(index: number): string {
  if (!(Number.isInteger(index) && index >= 0)) throw new RangeError(`beaconName: index must be an integer >= 0, got ${index}`);
  const letter = String.fromCharCode(65 + (index % 26));
  return index < 26 ? letter : `${letter}${Math.floor(index / 26) + 1}`;
}

/**
 * Where the brake hint aims the boat to stop: its centre this far short of the beacon along the
 * heading, m: 0, the hull abeam the beacon, so that a boat whose course passes up to
 * `BRAKE_HINT_COURSE` above or below the beacon stops with its side inside the catch ring (a stop
 * with the bow on the beacon leaves a boat passing 10 m off it with its hull 0.8 m outside the ring).
 * A boat coming in level touches the ring with its bow long before and collects it on the way.
 */
export const LET_GO_SHORT = 0;
/**
 * The brake hint is given on a course (the line of the boat's velocity) that passes at most this
 * close to the target, m: 9, the catch ring (BEACON_CATCH) and half the hull's height less 0.5 m,
 * so that a glide stopped abeam the beacon (`LET_GO_SHORT`) ends with the hull inside the ring. A
 * course further off must first dive or rise to the beacon.
 */
export const BRAKE_HINT_COURSE = BEACON_CATCH + SUBMARINE.height / 2 - 0.5;
/** The hint says "let go now" while the glide overshoots its aim by at most this, m, or falls short by at most `LET_GO_EARLY`. */
export const LET_GO_LATE = 3;
/** See `LET_GO_LATE`: how far short of its aim a glide may stop while the hint says "let go now", m. */
export const LET_GO_EARLY = 2;

/**
 * The brake hint's words for a boat whose centre lies `along` m short of its target along the
 * heading and that would glide `coast` m if Ahead were let go now (./helm.ts coastDistance):
 * "let go at N m ahead" while the glide would stop more than `LET_GO_EARLY` short of the aim (the
 * centre `LET_GO_SHORT` before the beacon), "let go now" from then until it would overshoot the aim
 * by `LET_GO_LATE`, and "Astern now to stop" after that (Astern brakes harder than a glide). N is in
 * the label's own figure, `ahead` (the level distance the line above it reads, "target B: 33 m
 * ahead"; default `along`): the figure at which the glide stops on the aim, the moment "let go now"
 * comes on, so the player compares two numbers on the label. (A count of metres still to go, "let go
 * in 21 m" beside "33 m ahead", was read as "let go at 21 m ahead": 12 m early, 16 m short.)
 * @throws RangeError when `along` or `ahead` is not finite or `coast` is not a finite number >= 0.
 */
export function letGoHint(along: number, coast: number, ahead = along): string {
  assertFinite('letGoHint', 'along', along);
  assertFinite('letGoHint', 'ahead', ahead);
  if (!(Number.isFinite(coast) && coast >= 0)) throw new RangeError(`letGoHint: coast must be a finite number >= 0 m, got ${coast}`);
  const rest = along - LET_GO_SHORT - coast;
  if (rest > LET_GO_EARLY) return `let go at ${Math.max(0, Math.round(ahead - rest + LET_GO_EARLY))} m ahead`;
  if (rest >= -LET_GO_LATE) return 'let go now';
  return 'Astern now to stop';
}
