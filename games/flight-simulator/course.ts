/**
 * The flight simulator's course: a chain of rings to fly through, laid out from the start along a
 * path that turns and climbs a little more at each ring, each turn within what the aircraft can fly
 * (`reachable`), always clear of the hills (the first lies on the path flown with no input, a few
 * seconds ahead); the rule that decides when a ring is passed or missed (`flyRings`), and the
 * course's time, in which each missed ring costs MISS_PENALTY s (`courseTime`). Headless (no
 * drawing), so it is tested in node (test/games/flight-simulator-course.test.ts).
 */

import { numberCheck, type StorageOptions, type StoredRecord, shapeCheck, storedRecord } from '@bitphysics/game-kit';
import { Rng } from '@bitphysics/physics';
import { AIRCRAFT, terrainHeight } from '@bitphysics/projects';
import { ASSIST, assertMotion, steadyTurnBank } from './assist';

/**
 * Radius of a ring, m, to the middle of its tube: the aircraft passes when its centre crosses inside
 * (wide enough for a player new to flying: a smaller radius such as 45 or 55 m is a tight fit;
 * the keys pilot of scripts/flight-simulator-pilots.mjs measures the share of rings passed).
 */
export const RING_RADIUS = 65;

/** Radius of the next ring's drawn tube, m (./main.ts draws it RING_RADIUS +- RING_TUBE from the centre). */
export const RING_TUBE = 6;

/**
 * How far from a ring's centre its plane may be crossed and still count as flown through, m: the
 * drawn tube's outer edge (RING_RADIUS + RING_TUBE). The flight-path marker is green inside it, so a
 * marker seen on the tube is a pass (a pass test at RING_RADIUS would call a marker on the tube, at
 * 68 m, a miss).
 */
export const PASS_RADIUS = RING_RADIUS + RING_TUBE;

/**
 * How far from a ring's centre the aircraft's path may meet its plane for the whole aircraft to go
 * through, m: RING_RADIUS less half the 30 m wingspan (2 x AIRCRAFT.wingHalfOffset), 50 m. The
 * flight-path marker is green, and the coach says "let go", only inside it (`clearThrough`): at the
 * tube (66 to 71 m) they said so with a wing through the tube, and a let-go a moment late or the
 * path settling after it took the crossing outside PASS_RADIUS (a stranger missed three rings so).
 */
export const CLEAR_RADIUS = RING_RADIUS - 2 * AIRCRAFT.wingHalfOffset;

/**
 * How far inside CLEAR_RADIUS the marker must come before it turns green, m (`clearThrough`): once
 * let go, the path drifts a few metres from the one predicted, and a marker that turned green at
 * CLEAR_RADIUS went back and forth across it, the tip with it ("let go", "steer left", "let go").
 */
export const CLEAR_MARGIN = 5;

/**
 * Whether a path meeting a ring's plane `offset` m from its centre (Infinity: not at all) takes the
 * whole aircraft through it: offset < CLEAR_RADIUS while it did (`was`, default true), and under
 * CLEAR_RADIUS - CLEAR_MARGIN to become so. Never beyond CLEAR_RADIUS.
 */
export function clearThrough(offset: number, was = true): boolean {
  return offset < CLEAR_RADIUS - (was ? 0 : CLEAR_MARGIN);
}

/** A crossing of a ring's plane farther than this from its centre, m, is not counted (the pilot is elsewhere). */
export const MISS_RANGE = 600;

/** Least height of a ring above the ground under it, m. */
export const RING_CLEARANCE = 150;

/** One ring of the course. */
export interface Ring {
  /** Centre, m (world; y up). */
  x: number;
  y: number;
  z: number;
  /** Unit normal of the ring's plane, the way through it (from the ring before towards this one). */
  nx: number;
  ny: number;
  nz: number;
  /** 'ahead' until the aircraft crosses its plane, then 'passed' (inside the ring) or 'missed'. */
  status: 'ahead' | 'passed' | 'missed';
}

/** Options of `layCourse`. */
export interface CourseOptions {
  /** Terrain parameters of the aircraft scene (`AircraftHandles.terrain`). */
  terrain: Float64Array;
  /** Seed of the layout; any finite number. */
  seed: number;
  /** Rings, integer >= 1. */
  count: number;
  /** Where the aircraft starts, m: the course leads away from here along +x. */
  start: readonly [number, number, number];
}

/**
 * How far apart the rings are laid, m (`layCourse`): `near` plus up to `spread` at random, plus `far`
 * times the ring's difficulty. 600 to 850 m at first (4.5 to 6.5 s at 130 m/s), 950 to 1,200 m at
 * full difficulty, so a ring comes every few seconds and the course keeps its pace (800 to 1,800 m,
 * 6 to 14 s, would feel slow).
 */
export const RING_STEP = Object.freeze({ near: 600, spread: 250, far: 350 });

/** Distance of the first ring straight ahead of the start, m: about 4.5 s at the trim speed. */
export const FIRST_RING_DISTANCE = 520;

/**
 * How hard ring `i` (0-based) is, in [0, 1]: 0 for the first four (the lessons, `LESSONS`), rising
 * evenly to 1 at the 10th and staying there. Scales the spacing, the turn and the change of height
 * in `layCourse`.
 */
export function ringDifficulty(i: number): number {
  return Math.max(0, Math.min(1, (i - 3) / 6));
}

/**
 * The first rings teach one small input each (`layCourse`): ring 1 straight ahead (no input), ring 2
 * a turn of `turn` degrees (at random within it; 70 to 95 m to the side) to one side at the same
 * height (bank), ring 3 straight on `climb` m higher or lower (climb or dive), ring 4 a turn the
 * other way at the same height; rings 2 to 4 `step` m apart (7.7 s at 130 m/s: time to see and react;
 * a newcomer's reaction of 3 s leaves 4.7 s to steer), so no ring asks for a large change (such as
 * 120 m higher) right after rings that asked for nothing.
 */
export const LESSONS = Object.freeze({ turn: [4, 5.5] as const, climb: [30, 40] as const, step: 1000 });

/**
 * Steepest change of height between rings the layout asks for, as a rise over the distance between
 * them: `easy` at difficulty 0 (a 2.3 degree path), up to `easy + hard` at 1 (6.8 degrees).
 */
export const RING_GRADIENT = Object.freeze({ easy: 0.04, hard: 0.08 });

/**
 * Speed of the turn every ring is laid to be reachable with, m/s (the starting throttle's trim speed):
 * the course assumes a pilot who flies straight on for REACTION_TIME s after a ring, left EXIT_SLACK
 * off the way the design path came through it, then holds DESIGN_BANK in a level coordinated turn.
 */
export const DESIGN_SPEED = 130;
/** Bank of the turn the course is laid for, rad (40 degrees; the assist gives 45 at full stick: ./assist.ts). */
export const DESIGN_BANK = (40 * Math.PI) / 180;
/** Time flown straight on past a ring before the turn to the next one starts, s. */
export const REACTION_TIME = 2;
/** Radius of the design turn, m: V^2 / (g tan(bank)), about 2,050 m (a turn rate of 3.6 degrees/s). */
export const DESIGN_TURN_RADIUS = DESIGN_SPEED ** 2 / (9.81 * Math.tan(DESIGN_BANK));

/**
 * The design path (REACTION_TIME s straight on, then a turn of DESIGN_TURN_RADIUS, then straight)
 * from a ring flown through along heading 0 to a point `forward` m ahead and `side` m to one side
 * (+ right; the turn is to that side): the heading at the point, rad (+ right), or null when the
 * point lies inside the turn's circle or behind the straight leg (out of reach).
 * @throws RangeError on a forward or side that is not finite.
 */
export function designArrival(forward: number, side: number): number | null {
  if (!Number.isFinite(forward) || !Number.isFinite(side))
    throw new RangeError(`designArrival: forward and side must be finite m, got ${forward}, ${side}`);
  const R = DESIGN_TURN_RADIUS,
    a = forward - DESIGN_SPEED * REACTION_TIME,
    b = Math.abs(side);
  if (a < 0 && b > 0) return null;
  // The point from the turn's centre (0, R): its distance D; the straight leg's length sqrt(D^2 - R^2).
  const D2 = a * a + (b - R) * (b - R);
  if (D2 < R * R) return null;
  const heading = Math.atan2(b - R, a) - Math.atan2(-R, Math.sqrt(D2 - R * R));
  return Math.sign(side) * heading;
}

/**
 * Heading error at a ring's exit the course allows for, rad: the next ring is reached from up to
 * this far off the design path's heading there, turned away from the next ring.
 */
export const EXIT_SLACK = (10 * Math.PI) / 180;

/**
 * Whether the design turn reaches a ring `step` m from the ring before at `turn` rad from the way
 * through it (+ right), when the aircraft leaves that ring EXIT_SLACK off, turned away from it.
 * @throws RangeError on a step that is not finite and > 0 m or a turn that is not finite.
 */
export function reachable(step: number, turn: number): boolean {
  if (!(step > 0 && Number.isFinite(step))) throw new RangeError(`reachable: step must be finite and > 0 m, got ${step}`);
  if (!Number.isFinite(turn)) throw new RangeError(`reachable: turn must be finite rad, got ${turn}`);
  const off = Math.abs(turn) + EXIT_SLACK;
  return designArrival(step * Math.cos(off), step * Math.sin(off)) !== null;
}

/**
 * Lays out `count` rings from `start`: the first FIRST_RING_DISTANCE straight ahead at the start
 * height (on the path the aircraft flies with no input), rings 2 to 4 the lessons (`LESSONS`: a
 * turn, a climb or dive, a turn the other way), then each ring a step after the one before
 * that grows with its difficulty d = ringDifficulty(i) (RING_STEP: 600 to 850 m apart at d = 0, 950
 * to 1,200 m at d = 1), turning by up to 8 + 27 d degrees from the way through the ring before
 * (within 100 degrees of +x), less where the design turn (`designArrival`: DESIGN_BANK at
 * DESIGN_SPEED after REACTION_TIME) would not reach it, and changing height by up to 60 + 190 m d
 * and at most the step times RING_GRADIENT, kept between 400 and 1,300 m and at least
 * RING_CLEARANCE above the ground. The next ring's turn is
 * measured from the heading the design path arrives with (turned on past the line between the
 * rings); each ring's way through is the line from the ring before.
 * @throws RangeError on a count that is not an integer >= 1 or a seed or start that is not finite.
 */
export function layCourse(options: CourseOptions): Ring[] {
  const { terrain, seed, count, start } = options;
  if (!Number.isInteger(count) || count < 1) throw new RangeError(`layCourse: count must be an integer >= 1, got ${count}`);
  if (!Number.isFinite(seed)) throw new RangeError(`layCourse: seed must be finite, got ${seed}`);
  if (!start.every(Number.isFinite)) throw new RangeError(`layCourse: start must be finite, got ${start.join(', ')}`);
  const rng = new Rng(seed);
  const rings: Ring[] = [];
  let [x, y, z] = start;
  // The way through the ring before (the start: along +x).
  let heading = 0;
  let side = 1;
  for (let i = 0; i < count; i++) {
    const d = ringDifficulty(i);
    const lesson = i >= 1 && i <= 3;
    const step =
      i === 0 ? FIRST_RING_DISTANCE : lesson ? LESSONS.step : RING_STEP.near + RING_STEP.far * d + rng.range(0, RING_STEP.spread);
    // The turn asked for, kept within 100 degrees of +x so that the course leads on and never folds
    // back, then eased until the design turn reaches the ring.
    let turn = 0;
    // The lessons' side: ring 2 turns one way, ring 4 the other.
    if (i === 1) side = rng.range(0, 1) < 0.5 ? -1 : 1;
    if (i > 0) {
      const lessonTurn = i === 2 ? 0 : side * (i === 3 ? -1 : 1) * rng.range(LESSONS.turn[0], LESSONS.turn[1]);
      const wanted = (lesson ? lessonTurn : rng.range(-1, 1) * (8 + 27 * d)) * (Math.PI / 180);
      turn = Math.max(-1.75, Math.min(1.75, heading + wanted)) - heading;
      // A lesson's ring is met from the line of the ring before (no slack: the ring before asked for
      // no turn or a small one).
      const reached = (t: number) => (lesson ? designArrival(step * Math.cos(t), step * Math.sin(t)) !== null : reachable(step, t));
      while (Math.abs(turn) > 1e-3 && !reached(turn)) turn *= 0.95;
    }
    // The aircraft comes through this ring turned on past the line from the one before: the next
    // ring is laid from the heading the design path arrives with.
    const arrival = i === 0 ? 0 : (designArrival(step * Math.cos(turn), step * Math.sin(turn)) ?? turn);
    const nx0 = x + step * Math.cos(heading + turn),
      nz0 = z + step * Math.sin(heading + turn);
    const ground = terrainHeight(terrain, nx0, nz0);
    // Level for the turns of the lessons, a small climb or dive for ring 3, else at random within
    // 60 + 190 d m and never steeper than RING_GRADIENT.
    const steepest = step * (RING_GRADIENT.easy + RING_GRADIENT.hard * d);
    const climb =
      i < 2 || i === 3
        ? 0
        : i === 2
          ? (rng.range(0, 1) < 0.5 ? -1 : 1) * rng.range(LESSONS.climb[0], LESSONS.climb[1])
          : Math.max(-steepest, Math.min(steepest, rng.range(-1, 1) * (60 + 190 * d)));
    const ny0 = Math.max(ground + RING_CLEARANCE, Math.min(1300, Math.max(400, y + climb)));
    const dx = nx0 - x,
      dy = ny0 - y,
      dz = nz0 - z,
      length = Math.hypot(dx, dy, dz);
    rings.push({ x: nx0, y: ny0, z: nz0, nx: dx / length, ny: dy / length, nz: dz / length, status: 'ahead' });
    heading += arrival;
    x = nx0;
    y = ny0;
    z = nz0;
  }
  return rings;
}

/**
 * What a move of the aircraft's centre from `a` to `b` (m, world) does to `ring`: 'passed' when it
 * crosses the ring's plane the way through it inside PASS_RADIUS of the centre, 'missed' when it
 * crosses it outside but within MISS_RANGE, else null (no crossing, a crossing the wrong way or far
 * off). The crossing point is where the segment meets the plane.
 */
export function crossRing(ring: Ring, a: readonly number[], b: readonly number[]): 'passed' | 'missed' | null {
  const da = (a[0]! - ring.x) * ring.nx + (a[1]! - ring.y) * ring.ny + (a[2]! - ring.z) * ring.nz,
    db = (b[0]! - ring.x) * ring.nx + (b[1]! - ring.y) * ring.ny + (b[2]! - ring.z) * ring.nz;
  if (!(da < 0 && db >= 0)) return null;
  const t = da / (da - db);
  const px = a[0]! + t * (b[0]! - a[0]!) - ring.x,
    py = a[1]! + t * (b[1]! - a[1]!) - ring.y,
    pz = a[2]! + t * (b[2]! - a[2]!) - ring.z;
  const off = Math.hypot(px, py, pz);
  if (off < PASS_RADIUS) return 'passed';
  return off < MISS_RANGE ? 'missed' : null;
}

/**
 * Seconds added to the course time for each ring missed: enough that a miss shows on the clock and
 * a clean run beats one that skips rings, small enough that a miss early on leaves the run worth
 * flying (with 20 s and a star for each miss, three misses would leave nothing to play for).
 */
export const MISS_PENALTY = 10;

/** What a move of the aircraft did to a ring (`flyRings`). */
export interface RingEvent {
  /** The ring's index. */
  ring: number;
  /** Flown through, or its plane crossed outside it (or skipped: the ring after it crossed first). */
  result: 'passed' | 'missed';
}

/**
 * The rule of the course for a move of the aircraft's centre from `a` to `b` (m, world): of the next
 * ring still ahead and the one after it, the first whose plane the move crosses (`crossRing`) is
 * passed or missed; crossing the one after's first also misses the next (it was skipped). Ring
 * `promised` (an index, -1 for none: the ring the flight-path marker showed the aircraft passing
 * inside in the last moment before the crossing) is passed when its plane is crossed within
 * MISS_RANGE: what the marker promised counts even where the flown path strays a little from the
 * predicted one. Marks the rings' statuses and returns what happened, in order (empty when nothing
 * did). A ring is missed once: each miss costs MISS_PENALTY s (`courseTime`).
 */
export function flyRings(rings: Ring[], a: readonly number[], b: readonly number[], promised = -1): RingEvent[] {
  const i = nextRing(rings);
  const events: RingEvent[] = [];
  if (i < 0) return events;
  for (const j of [i, i + 1]) {
    const ring = rings[j];
    if (!ring) continue;
    const crossed = crossRing(ring, a, b);
    if (!crossed) continue;
    const result = j === promised ? 'passed' : crossed;
    if (j === i + 1) {
      rings[i]!.status = 'missed';
      events.push({ ring: i, result: 'missed' });
    }
    ring.status = result;
    events.push({ ring: j, result });
    break;
  }
  return events;
}

/**
 * The course's time, s: the time flown plus MISS_PENALTY for each ring missed.
 * @throws RangeError on a time that is negative or not finite, or a count of misses that is not an integer >= 0.
 */
export function courseTime(flown: number, missed: number): number {
  if (!(flown >= 0 && Number.isFinite(flown))) throw new RangeError(`courseTime: flown must be finite and >= 0 s, got ${flown}`);
  if (!(Number.isInteger(missed) && missed >= 0)) throw new RangeError(`courseTime: missed must be an integer >= 0, got ${missed}`);
  return flown + MISS_PENALTY * missed;
}

/** The first ring still ahead (the one to fly through next), or -1 when none is. */
export function nextRing(rings: readonly Ring[]): number {
  return rings.findIndex((r) => r.status === 'ahead');
}

/**
 * Stars of a course with `missed` rings missed so far: 3 with none, then one less for every second
 * miss (2 after one or two, 1 after three or four, 0 from five on). The HUD shows them while flying.
 * A clean run is the only way to 3; an early miss or two still leaves 2 to keep.
 * @throws RangeError on a count of misses that is not an integer >= 0.
 */
export function courseStars(missed: number): number {
  if (!(Number.isInteger(missed) && missed >= 0)) throw new RangeError(`courseStars: missed must be an integer >= 0, got ${missed}`);
  return Math.max(0, 3 - Math.ceil(missed / 2));
}

/** Where a ring lies from the aircraft (`ringBearing`). */
export interface RingBearing {
  /** Angle of the ring's centre to the right of the heading of the velocity, rad, in (-pi, pi] (horizontal). */
  bearing: number;
  /** Angle of the ring's centre above the flight path (the velocity's climb), rad. */
  elevation: number;
  /** Distance to the ring's centre, m. */
  distance: number;
  /** How far the ring's centre lies to the right of the line the aircraft flies, m, at its distance: distance x sin(bearing) (horizontal). */
  side: number;
  /** How far the ring's centre lies above that line, m, at its distance: distance x sin(elevation). */
  up: number;
}

/**
 * Where `ring`'s centre lies from an aircraft at `position` (m, world) flying along `velocity` (m/s,
 * world): to the right or left of its heading and above or below its flight path (the lesson tips
 * say this, worked out from where the aircraft is, not written per ring).
 * @throws RangeError on a position or velocity that is not 3 finite numbers, or a velocity with no
 * horizontal part.
 */
export function ringBearing(ring: Ring, position: readonly number[], velocity: readonly number[]): RingBearing {
  assertMotion('ringBearing', position, velocity);
  const vx = velocity[0]!,
    vy = velocity[1]!,
    vz = velocity[2]!,
    level = Math.hypot(vx, vz);
  if (!(level > 0)) throw new RangeError(`ringBearing: velocity must have a horizontal part, got ${velocity.join(', ')}`);
  const dx = ring.x - position[0]!,
    dy = ring.y - position[1]!,
    dz = ring.z - position[2]!;
  const flat = Math.hypot(dx, dz),
    distance = Math.hypot(flat, dy);
  // Right of the heading (vx, vz) is (-vz, vx): y up, +z to the right of +x.
  const bearing = Math.atan2(dz * vx - dx * vz, dx * vx + dz * vz);
  const elevation = Math.atan2(dy, flat) - Math.atan2(vy, level);
  return { bearing, elevation, distance, side: distance * Math.sin(bearing), up: distance * Math.sin(elevation) };
}

/**
 * How far off the line flown a ring's centre must lie for a tip to name that way, m (`ringWay`): a
 * third of the ring's radius (flying on, the aircraft passes well inside it); past `little` it is
 * not "a little", past `far` it is "far".
 */
export const TIP_OFFSET = Object.freeze({ straight: RING_RADIUS / 3, little: RING_RADIUS, far: 4 * RING_RADIUS });

/** One way of a ring from the line flown (`ringWay`): -1, 0 (on the line) or 1, and how much in words. */
export interface RingWay {
  /** +1 right, -1 left, 0 neither. */
  side: -1 | 0 | 1;
  /** +1 higher, -1 lower, 0 neither. */
  up: -1 | 0 | 1;
  /** '' , 'a little ' or 'far ' (with its space), for the side and for the height. */
  sideAmount: string;
  upAmount: string;
}

/** The ways a ring lies from the line flown (`ringBearing`'s side and up, m), by TIP_OFFSET. */
export function ringWay(b: Pick<RingBearing, 'side' | 'up' | 'bearing'>): RingWay {
  const way = (m: number): -1 | 0 | 1 => (Math.abs(m) < TIP_OFFSET.straight ? 0 : m > 0 ? 1 : -1);
  const amount = (m: number) => (Math.abs(m) < TIP_OFFSET.little ? 'a little ' : Math.abs(m) > TIP_OFFSET.far ? 'far ' : '');
  // A ring behind (bearing past 90 degrees) is to its side however small the offset.
  const side = Math.abs(b.bearing) > Math.PI / 2 ? (b.bearing > 0 ? 1 : -1) : way(b.side);
  return { side, up: way(b.up), sideAmount: Math.abs(b.bearing) > Math.PI / 2 ? 'far ' : amount(b.side), upAmount: amount(b.up) };
}

/**
 * Where a ring lying `way` from the line flown is, in words: "to the left and far higher", or on a
 * phone (`compact`) "left, far higher"; "straight ahead" when it lies on the line. The lesson tip
 * and the banner after a ring is laid ahead both say it with this, from the same `way`, so the two
 * never disagree.
 */
export function ringWhere(way: RingWay, compact: boolean): string {
  const side = way.side > 0 ? 'right' : 'left';
  const sideWords = compact && way.sideAmount ? `${way.sideAmount}${side}` : `${way.sideAmount}to the ${side}`;
  return (
    [way.side ? sideWords : '', way.up ? `${way.upAmount}${way.up > 0 ? 'higher' : 'lower'}` : '']
      .filter(Boolean)
      .join(compact ? ', ' : ' and ') || 'straight ahead'
  );
}

/**
 * The banner when ring `ring` (0-based) has been laid on ahead after a miss (`relayAfterMiss`), lying
 * `way` from the line flown: "Ring 2 is now just ahead of you" when it lies on the line, else
 * "Ring 2 is now ahead: to the left and far higher" (`ringWhere`, the lesson tip's words).
 * @throws RangeError on a ring that is not a non-negative integer.
 */
export function relayText(ring: number, way: RingWay, compact: boolean): string {
  if (!(Number.isInteger(ring) && ring >= 0)) throw new RangeError(`relayText: ring must be a non-negative integer, got ${ring}`);
  const n = `Ring ${ring + 1} is now`;
  return way.side || way.up ? `${n} ahead: ${ringWhere(way, compact)}` : `${n} just ahead of you`;
}

/**
 * The banner after a ring is flown through when another follows: where the next ring, `ring`
 * (0-based), lies `way` from the line flown, "Next, ring 6: to the left and lower", or "Next, ring 6:
 * straight ahead" (`ringWhere`, the lesson tip's words), so that a turn to it is seen coming before
 * the ring is reached, not only after a miss ("is now ahead", `relayText`).
 * @throws RangeError on a ring that is not a non-negative integer.
 */
export function nextRingText(ring: number, way: RingWay, compact: boolean): string {
  if (!(Number.isInteger(ring) && ring >= 0)) throw new RangeError(`nextRingText: ring must be a non-negative integer, got ${ring}`);
  return `Next, ring ${ring + 1}: ${ringWhere(way, compact)}`;
}

/** Who reads a lesson tip (`lessonTipText`). */
export interface TipReader {
  /** Touch first (a phone): the tip names the on-screen stick, not the arrow keys. */
  touch: boolean;
  /** A small scene (a phone): the shorter wording, which keeps the tip to two lines at 390 px. */
  compact: boolean;
  /** The pilot's pitch (↓ climbs, as a real stick pulled back). */
  pilotPitch: boolean;
}

/** Every ring way: side and height each -1, 0 or 1, each with each amount (all `ringWay` gives and more; tests find the longest tip with it). */
export const RING_WAYS: readonly RingWay[] = Object.freeze(
  ([-1, 0, 1] as const).flatMap((side) =>
    ([-1, 0, 1] as const).flatMap((up) =>
      ['', 'a little ', 'far '].flatMap((sideAmount) => ['', 'a little ', 'far '].map((upAmount) => ({ side, up, sideAmount, upAmount }))),
    ),
  ),
);

/**
 * The lesson tip for ring `ring` (0-based, 0 to 3: ring 1 is the start's, rings 2 to 4 the lessons,
 * `LESSONS`) lying `way` from the line flown, in words for someone who has never flown: which way it
 * lies (right or left, higher or lower, how much) and what to do. On a phone (`reader.compact`) the
 * words are shorter ("far right, a little higher"), so the tip stays within two lines whatever it
 * names; with `reader.touch` it names the stick, else the arrow keys.
 * @throws RangeError on a ring that is not an integer in [0, 3].
 */
export function lessonTipText(ring: number, way: RingWay, reader: TipReader): string {
  if (!(Number.isInteger(ring) && ring >= 0 && ring <= 3))
    throw new RangeError(`lessonTipText: ring must be an integer in [0, 3], got ${ring}`);
  const { touch, compact } = reader;
  const input = touch ? 'stick' : 'keys';
  if (ring === 0)
    return compact
      ? `Fly through the yellow rings. ⊕ marks where you pass if you let go of the ${input}.`
      : `Fly through the yellow rings. The marker ⊕ shows where you will pass if you let go of the ${input}.`;
  const w = way;
  const side = w.side > 0 ? 'right' : 'left';
  const where = ringWhere(w, compact);
  const arrow = w.side > 0 ? '→' : '←';
  const key = w.up > 0 !== reader.pilotPitch ? '↑' : '↓';
  const stickUp = key === '↑' ? 'up' : 'down';
  const turnDo = touch ? `push the stick ${side}` : `hold ${arrow}`;
  const climbDo = touch ? `push the stick ${stickUp}` : `hold ${key}`;
  const climb = w.up > 0 ? 'climb' : 'dive';
  const n = `Ring ${ring + 1} is ${where}`;
  if (!w.side && !w.up) return `${n}: let go and fly on through it.`;
  if (w.side && w.up) {
    if (compact) return `${n}: ${touch ? `push the stick ${side} and ${stickUp}` : `hold ${arrow} and ${key}`} until ⊕ is in it.`;
    return touch
      ? `${n}: push the stick ${side} and ${stickUp}; let go when ⊕ is in the ring.`
      : `${n}: hold ${arrow} to bank and ${key} to ${climb}; let go when the marker ⊕ is in the ring.`;
  }
  if (w.up)
    return compact
      ? `${n}: ${climbDo} to ${climb}, then let go to fly level.`
      : `${n}: ${climbDo} to ${climb} gently, and let go to fly level.`;
  if (compact) return `${n}: ${turnDo} to tip the wings and turn, then let go.`;
  if (ring === 1)
    return `${n}. A plane turns by tipping its wings (banking): ${turnDo} and it leans and turns ${side}; let go to fly straight.`;
  return `${n}: tip the wings ${side} (${touch ? `push the stick ${side}` : arrow}) to turn, then let go.`;
}

/**
 * Where a straight line from `position` (m, world) along `velocity` (m/s, world) meets `ring`'s
 * plane: the time to get there (s) and the distance of that point from the ring's centre (m). A
 * line that runs parallel to the plane or away from it (the plane behind) never meets it:
 * { time: Infinity, offset: Infinity }. The flight-path marker is drawn there: with the offset
 * under RING_RADIUS the aircraft, holding its path, flies through.
 * @throws RangeError on a position or velocity that is not 3 finite numbers.
 */
export function pathThroughRing(
  ring: Ring,
  position: readonly number[],
  velocity: readonly number[],
): { time: number; offset: number; point: [number, number, number] } {
  assertMotion('pathThroughRing', position, velocity);
  const gap = (ring.x - position[0]!) * ring.nx + (ring.y - position[1]!) * ring.ny + (ring.z - position[2]!) * ring.nz;
  const closing = velocity[0]! * ring.nx + velocity[1]! * ring.ny + velocity[2]! * ring.nz;
  const time = gap / closing;
  if (!(closing !== 0 && time > 0)) return { time: Infinity, offset: Infinity, point: [Infinity, Infinity, Infinity] };
  const point: [number, number, number] = [
    position[0]! + velocity[0]! * time,
    position[1]! + velocity[1]! * time,
    position[2]! + velocity[2]! * time,
  ];
  return { time, offset: Math.hypot(point[0] - ring.x, point[1] - ring.y, point[2] - ring.z), point };
}

/**
 * How the assisted aircraft settles when the stick is let go (./assist.ts; fitted to the flown
 * response at the trim speed): the roll rate turns from what it is towards a roll back to level, as
 * fast as `rollRate` (rad/s) and within `bankTime` (s, time constant) near level, over the time
 * constant `rollLag` (s: the aircraft's roll inertia and the ailerons' travel); the flight path keeps
 * its rate for `delay` s (the keys' inputs fall back and the elevator follows), then returns to
 * level as fast as `pathRate` (rad/s), within `pathTime` (s) near level. A touch's held bank
 * (./assist.ts heldBank) is rolled to within `heldTime` (s).
 */
export const LET_GO = Object.freeze({
  delay: 0.15,
  rollLag: 0.09,
  bankTime: 0.25,
  heldTime: 0.1,
  rollRate: 1.0,
  pathTime: 0.65,
  pathRate: 0.25,
});

/** The aircraft's motion now for `predictThroughRing`. */
export interface Motion {
  /** Centre, m (world). */
  position: readonly number[];
  /** Velocity, m/s (world); its size is kept along the predicted path. */
  velocity: readonly number[];
  /** Bank, rad, + right wing down (./assist.ts FlightState.bank). */
  bank: number;
  /** Rate of the bank, rad/s. */
  rollRate: number;
  /** Rate of the flight-path angle, rad/s. */
  pathRate: number;
  /**
   * The bank the assist still holds after a short touch of the stick (./assist.ts heldBank): rad,
   * + right, for `time` s from now (none when absent or 0).
   */
  held?: { bank: number; time: number };
}

/** Largest bank the prediction turns with, rad (a steeper bank's tangent runs away). */
const PREDICT_BANK = (75 * Math.PI) / 180;

/**
 * Where the aircraft's path meets `ring`'s plane: the time to get there (s), the point (m, world)
 * and its distance from the ring's centre (m), like `pathThroughRing`, but along the curved path the
 * aircraft flies. With `letGo` (the assist on) the pilot lets go now: the bank's roll turns back
 * to level and the flight path settles (LET_GO), the path turning at
 * g tan(bank) / V the while (a coordinated turn); without, the bank and the flight path are held as
 * they are (a steady turn). The speed is kept. Stepped every `dt` s (default 1/30) for at most
 * `horizon` s (default 20): a plane not met by then gives { time: Infinity, offset: Infinity }.
 * This is what the flight-path marker shows: put it in the ring and let go, and the aircraft flies
 * through (test/games/flight-simulator-course.test.ts measures how close).
 * @throws RangeError on a position or velocity that is not 3 finite numbers, or a bank, roll rate or
 * path rate that is not finite.
 */
export function predictThroughRing(
  ring: Ring,
  motion: Motion,
  letGo: boolean,
  opts: { dt?: number; horizon?: number } = {},
): { time: number; offset: number; point: [number, number, number] } {
  const { position, velocity, bank, rollRate, pathRate } = motion;
  const held = motion.held && motion.held.time > 0 && Number.isFinite(motion.held.bank) ? motion.held : null;
  assertMotion('predictThroughRing', position, velocity);
  if (![bank, rollRate, pathRate].every(Number.isFinite))
    throw new RangeError(`predictThroughRing: bank, rollRate and pathRate must be finite, got ${bank}, ${rollRate}, ${pathRate}`);
  const dt = opts.dt ?? 1 / 30,
    horizon = opts.horizon ?? 20;
  const none = { time: Infinity, offset: Infinity, point: [Infinity, Infinity, Infinity] as [number, number, number] };
  const speed = Math.hypot(velocity[0]!, velocity[1]!, velocity[2]!);
  if (!(speed > 0)) return none;
  let x = position[0]!,
    y = position[1]!,
    z = position[2]!,
    b = bank,
    path = Math.asin(Math.max(-1, Math.min(1, velocity[1]! / speed))),
    heading = Math.atan2(velocity[2]!, velocity[0]!);
  // The predicted roll rate, rad/s.
  let omega = rollRate;
  let target = held ? held.bank : 0,
    holding = held !== null;
  const gapOf = (px: number, py: number, pz: number) => (ring.x - px) * ring.nx + (ring.y - py) * ring.ny + (ring.z - pz) * ring.nz;
  let gap = gapOf(x, y, z);
  if (!(gap > 0)) return none;
  // Towards 0 over a step: by the share 1 - e^(-dt / time) of `v`, no faster than `fastest` per second.
  const settle = (v: number, time: number, fastest: number) =>
    v - Math.max(-fastest * dt, Math.min(fastest * dt, v * (1 - Math.exp(-dt / time))));
  for (let t = 0; t < horizon; t += dt) {
    if (letGo) {
      if (holding && !(t < held!.time || (Math.abs(target) > Math.abs(b) && Math.sign(target) === Math.sign(b)))) holding = false;
      if (holding) {
        // A touch's bank held (./assist.ts heldBank), then unwound at ASSIST.bankRate: the bank rolls
        // towards it at the roll rate it has (at least LET_GO.rollRate) while it is short of it.
        const fastest = Math.max(Math.abs(rollRate), LET_GO.rollRate) * dt;
        const roll = Math.max(-fastest, Math.min(fastest, (target - b) * (1 - Math.exp(-dt / LET_GO.heldTime))));
        b += roll;
        omega = roll / dt;
        path = settle(path, LET_GO.pathTime, LET_GO.pathRate);
        if (t >= held!.time) target -= Math.sign(target) * Math.min(Math.abs(target), ASSIST.bankRate * dt);
      } else {
        // The roll rate turns from what it is towards the roll back to level (at most
        // LET_GO.rollRate, within LET_GO.bankTime near level) over the time constant LET_GO.rollLag;
        // the flight path keeps its rate for LET_GO.delay s, then settles.
        const wanted = -Math.sign(b) * Math.min(LET_GO.rollRate, Math.abs(b) / LET_GO.bankTime);
        omega += (wanted - omega) * (1 - Math.exp(-dt / LET_GO.rollLag));
        b += omega * dt;
        if (t < LET_GO.delay) path += pathRate * dt;
        else path = settle(path, LET_GO.pathTime, LET_GO.pathRate);
      }
    }
    const turn = (9.81 * Math.tan(Math.max(-PREDICT_BANK, Math.min(PREDICT_BANK, b)))) / speed;
    heading += turn * dt;
    const nx = x + speed * Math.cos(path) * Math.cos(heading) * dt,
      ny = y + speed * Math.sin(path) * dt,
      nz = z + speed * Math.cos(path) * Math.sin(heading) * dt;
    const next = gapOf(nx, ny, nz);
    if (next <= 0) {
      const f = gap / (gap - next);
      const point: [number, number, number] = [x + f * (nx - x), y + f * (ny - y), z + f * (nz - z)];
      return { time: t + f * dt, offset: Math.hypot(point[0] - ring.x, point[1] - ring.y, point[2] - ring.z), point };
    }
    x = nx;
    y = ny;
    z = nz;
    gap = next;
  }
  return none;
}

/** A course's kept best result: rings passed (0 to the course's count) and course time (s, misses' penalties in). */
export interface BestResult {
  passed: number;
  time: number;
}

/** The storage key of the best results: a JSON object of course key ('seed/rings') to its BestResult. */
export const BEST_KEY = 'bitphysics.flight-simulator.best';
/** The longest course time kept, s (11.6 days of flight): a longer one stored is garbage and reads as none. */
export const MAX_BEST_TIME = 1e6;

/**
 * The best result of each course flown, kept under BEST_KEY in the page's storage (or
 * `options.storage`): rings passed a whole number in [0, 1000], time in [0, MAX_BEST_TIME] s; an
 * entry outside those, or not of that shape, reads as none.
 */
export function courseBests(options?: StorageOptions): StoredRecord<BestResult> {
  const result = shapeCheck<BestResult>({ passed: numberCheck({ max: 1000, integer: true }), time: numberCheck({ max: MAX_BEST_TIME }) });
  return storedRecord(BEST_KEY, result, options);
}

/**
 * How a finished run compares with the best kept for its course: 'first' when none was kept (the
 * run becomes the best, but beat nothing), 'better' when it passed more rings, or as many in a
 * shorter course time (s), else 'not'. Only 'better' is a new best worth praise.
 * @throws RangeError on a `passed` that is not a whole number >= 0 or a `time` that is not finite and >= 0.
 */
export function compareWithBest(previous: BestResult | null, passed: number, time: number): 'first' | 'better' | 'not' {
  if (!Number.isInteger(passed) || passed < 0) throw new RangeError(`compareWithBest: passed must be a whole number >= 0, got ${passed}`);
  if (!Number.isFinite(time) || time < 0) throw new RangeError(`compareWithBest: time must be a finite number >= 0 (s), got ${time}`);
  if (!previous) return 'first';
  return passed > previous.passed || (passed === previous.passed && time < previous.time) ? 'better' : 'not';
}

/**
 * How fast the aircraft must draw away from the next ring's centre, m/s, for the ring to count as
 * falling behind (`recedingSpeed`, `leaveBehind`): a little over 0, so a ring alongside in a turn
 * towards it does not count.
 */
export const LEFT_BEHIND_SPEED = 5;
/**
 * How long the next ring may fall behind (the aircraft drawing away from it faster than
 * LEFT_BEHIND_SPEED) before it counts as missed, s (`leaveBehind`): a ring flown past to the side is
 * left behind, and the course moves on (./course.ts relayAfterMiss), since turning back to it takes
 * about a minute (the design turn comes round at 3.6 degrees/s).
 */
export const LEFT_BEHIND_TIME = 1.5;

/**
 * How fast an aircraft at `position` (m, world) flying along `velocity` (m/s, world) draws away from
 * `ring`'s centre, m/s: + away from it, - closing on it (0 at the centre).
 * @throws RangeError on a position or velocity that is not 3 finite numbers.
 */
export function recedingSpeed(ring: Ring, position: readonly number[], velocity: readonly number[]): number {
  assertMotion('recedingSpeed', position, velocity);
  const dx = ring.x - position[0]!,
    dy = ring.y - position[1]!,
    dz = ring.z - position[2]!,
    d = Math.hypot(dx, dy, dz);
  if (!(d > 0)) return 0;
  return -(velocity[0]! * dx + velocity[1]! * dy + velocity[2]! * dz) / d;
}

/**
 * Radius of the tightest level turn the assist flies at `speed` m/s, m: full stick's bank
 * (./assist.ts steadyTurnBank: ASSIST.maxBank's turn rate at the trim speed, at most
 * ASSIST.steepestBank), speed^2 / (g tan(bank)): about 470 m at 115 m/s.
 * @throws RangeError on a speed that is not finite and > 0.
 */
export function tightestTurnRadius(speed: number): number {
  if (!(speed > 0 && Number.isFinite(speed))) throw new RangeError(`tightestTurnRadius: speed must be finite and > 0 m/s, got ${speed}`);
  return (speed * speed) / (9.81 * Math.tan(steadyTurnBank(ASSIST.maxBank, speed)));
}

/**
 * Whether an aircraft at `position` (m, world) flying along `velocity` (m/s, world) can no longer
 * fly through `ring` without first flying away from it: it is past the ring's plane (on the far side
 * of it), or the ring's centre lies, seen from above, inside the circle of the tightest turn towards
 * it (`tightestTurnRadius`), which no turn reaches. A ring that is only off the line flown (above or
 * below it, or to the side but outside that circle) is in reach, however it draws away now: a ring
 * 750 m ahead under a steep climb was called missed while the pilot could still dive to it.
 * @throws RangeError on a position or velocity that is not 3 finite numbers.
 */
export function outOfReach(ring: Ring, position: readonly number[], velocity: readonly number[]): boolean {
  assertMotion('outOfReach', position, velocity);
  const dx = ring.x - position[0]!,
    dy = ring.y - position[1]!,
    dz = ring.z - position[2]!;
  if (dx * ring.nx + dy * ring.ny + dz * ring.nz <= 0) return true;
  const vx = velocity[0]!,
    vz = velocity[2]!,
    level = Math.hypot(vx, vz);
  if (!(level > 0)) return false;
  // The centre in the heading's frame (ahead, to the right: +z is to the right of +x), and its distance
  // from the centre of the tightest turn its way, that far to its side.
  const ahead = (dx * vx + dz * vz) / level,
    right = (dz * vx - dx * vz) / level,
    radius = tightestTurnRadius(Math.hypot(vx, velocity[1]!, vz));
  return Math.hypot(ahead, Math.abs(right) - radius) < radius;
}

/**
 * The rule for a ring left behind: when the next ring still ahead (`nextRing`) has fallen behind for
 * `behindFor` s (the aircraft drawing away from it faster than LEFT_BEHIND_SPEED without a break,
 * while it is out of reach: ./main.ts counts only those steps, `outOfReach`),
 * LEFT_BEHIND_TIME or more, it is missed (its status set) as if its plane were crossed outside it.
 * Returns what happened (empty when nothing did), as `flyRings` does: a ring passed to the side
 * beyond MISS_RANGE, or flown by without crossing its plane, is not counted by `flyRings`, and
 * without this rule the pilot would have to turn back to it.
 * @throws RangeError on a `behindFor` that is not finite and >= 0.
 */
export function leaveBehind(rings: Ring[], behindFor: number): RingEvent[] {
  if (!(behindFor >= 0 && Number.isFinite(behindFor)))
    throw new RangeError(`leaveBehind: behindFor must be finite and >= 0 s, got ${behindFor}`);
  const i = nextRing(rings);
  if (i < 0 || behindFor < LEFT_BEHIND_TIME) return [];
  rings[i]!.status = 'missed';
  return [{ ring: i, result: 'missed' }];
}

/**
 * Turns `ring` to face an aircraft at `from` (m, world): its way through becomes the line from
 * `from` to its centre, so that a ring met after a miss, or flown past far off and come back to, is
 * seen face on, not edge on, and is flown through the way the aircraft comes. Changes the ring's
 * normal only (its centre stays); nothing changes when `from` is at the centre.
 * @throws RangeError on a `from` that is not 3 finite numbers.
 */
export function faceRing(ring: Ring, from: readonly number[]): void {
  if (from.length < 3 || !from.slice(0, 3).every(Number.isFinite))
    throw new RangeError(`faceRing: from must be 3 finite numbers, got ${from.join(', ')}`);
  const dx = ring.x - from[0]!,
    dy = ring.y - from[1]!,
    dz = ring.z - from[2]!,
    length = Math.hypot(dx, dy, dz);
  if (!(length > 0)) return;
  ring.nx = dx / length;
  ring.ny = dy / length;
  ring.nz = dz / length;
}

/**
 * How far ahead of the aircraft the next ring is laid after a miss, m (`relayAfterMiss`): about 6 s
 * at the trim speed, time to see it and line up.
 */
export const RECOVERY_DISTANCE = 800;

/**
 * Largest turn off the aircraft's heading the ring laid after a miss asks for, rad (15 degrees): it
 * leans towards where the course went, eased until the design turn reaches it (`designArrival`).
 */
export const RECOVERY_TURN = (15 * Math.PI) / 180;

/** Steepest change of height from the aircraft the ring laid after a miss asks for, as a rise over RECOVERY_DISTANCE. */
export const RECOVERY_GRADIENT = 0.15;

/**
 * After a miss the course moves on: the rest of it (`rings` from `from`, 0-based, to the end) is
 * carried as one piece, turned about the vertical and moved, so that ring `from` lies
 * RECOVERY_DISTANCE m ahead of the aircraft at `position` (m, world) flying along `heading` (rad,
 * in the level plane from +x towards +z, as ./assist.ts flightState gives it), turned towards where
 * it was by at most RECOVERY_TURN (less where the design turn would not reach it from the heading
 * flown now: `designArrival`), at its own height kept within RECOVERY_GRADIENT times
 * RECOVERY_DISTANCE of the aircraft's and between 400 and 1,300 m. The rings after it keep their spacing, turns
 * and climbs (each was laid reachable from the one before); each is then raised to RING_CLEARANCE
 * above the ground under its new place where it would be lower. Ring `from` faces the aircraft.
 * Changes the rings in place; nothing when `from` is not a ring still ahead. Without this a miss
 * would leave the next ring laid from the missed one, often inside the aircraft's turning circle,
 * half a minute's turn away.
 * @throws RangeError on a `position` that is not 3 finite numbers, a `heading` that is not finite,
 * or a `from` that is not an integer.
 */
export function relayAfterMiss(rings: Ring[], from: number, position: readonly number[], heading: number, terrain: Float64Array): void {
  if (position.length < 3 || !position.slice(0, 3).every(Number.isFinite))
    throw new RangeError(`relayAfterMiss: position must be 3 finite numbers, got ${position.join(', ')}`);
  if (!Number.isFinite(heading)) throw new RangeError(`relayAfterMiss: heading must be a finite number (rad), got ${heading}`);
  if (!Number.isInteger(from)) throw new RangeError(`relayAfterMiss: from must be an integer, got ${from}`);
  const first = rings[from];
  if (first?.status !== 'ahead') return;
  const [px, py, pz] = position as [number, number, number];
  // Towards where the ring was, within RECOVERY_TURN, eased until the design turn reaches it.
  const bearing = Math.atan2(first.z - pz, first.x - px) - heading;
  let turn = Math.max(-RECOVERY_TURN, Math.min(RECOVERY_TURN, Math.atan2(Math.sin(bearing), Math.cos(bearing))));
  // Met from the heading flown now (no EXIT_SLACK: the aircraft is not leaving a ring).
  while (Math.abs(turn) > 1e-3 && designArrival(RECOVERY_DISTANCE * Math.cos(turn), RECOVERY_DISTANCE * Math.sin(turn)) === null)
    turn *= 0.9;
  const way = heading + turn;
  const qx = px + RECOVERY_DISTANCE * Math.cos(way),
    qz = pz + RECOVERY_DISTANCE * Math.sin(way),
    // Its own height, kept within a climb or dive of RECOVERY_GRADIENT from the aircraft's.
    reach = RECOVERY_GRADIENT * RECOVERY_DISTANCE,
    qy = Math.max(
      terrainHeight(terrain, qx, qz) + RING_CLEARANCE,
      Math.min(1300, Math.max(400, py - reach, Math.min(py + reach, first.y))),
    );
  // The rest of the course turned by `spin` about the vertical through the ring, which then moves to (qx, qy, qz).
  const spin = way - Math.atan2(first.nz, first.nx);
  const c = Math.cos(spin),
    s = Math.sin(spin);
  const ox = first.x,
    oy = first.y,
    oz = first.z;
  for (let k = from; k < rings.length; k++) {
    const r = rings[k]!;
    const dx = r.x - ox,
      dz = r.z - oz;
    r.x = qx + c * dx - s * dz;
    r.z = qz + s * dx + c * dz;
    r.y = Math.max(terrainHeight(terrain, r.x, r.z) + RING_CLEARANCE, qy + (r.y - oy));
    const nx = c * r.nx - s * r.nz;
    r.nz = s * r.nx + c * r.nz;
    r.nx = nx;
  }
  faceRing(first, position);
}
