/**
 * The submarine's helm: turns the pilot's held keys into ballast targets, vertical thrusters, dive
 * planes and screw thrust each step, the way a small submersible's control system does. The physics
 * stays the scene's own (Archimedes' buoyancy, the tanks' mass, quadratic drag) and the planes'
 * (./planes.ts: lift of the water flowing past); the helm only decides what the pumps, vents,
 * thrusters and planes do.
 *
 * - The depth order (`HelmState.holdY`, the gauge's ordered depth): Dive / Rise (held) move it down /
 *   up at `HELM.diveSpeed` (`HELM.climbSpeed`) times the stick's share, from the boat, never further
 *   ahead of it than the boat can stop in at `HELM.brake` (plus `HELM.orderLead`) and never nearer.
 *   Let go, the order stays and the boat stops on it without passing it (`approach`), so the gauge
 *   shows at all times where the boat will stop. Held, the order rises over a ridge ahead (`holdFloor`)
 *   and goes back down to the depth set once past it.
 * - Dive / Rise (held): the vertical thrusters and the planes push at once, so the boat starts to
 *   move before the water in the tanks has moved; the tanks go heavier / lighter than neutral
 *   (enough to carry the boat at the asked speed against drag, more while it is slower than that);
 *   the bow dips (rises) by `HELM.diveAngle`, twice that at full speed. On the surface Dive floods the tanks from empty, the
 *   fore tank first. Rise slows the climb near the surface and blows the tanks dry once the deck is
 *   out. Released on the surface: the tanks stay blown and the boat floats.
 * - Under way the planes give first what they can of the push across the hull (their lift grows
 *   with the speed squared), the thrusters the rest, and the helm brakes harder by their share.
 * - Nose down / up (held): pitch to `HELM.noseAngle` by the thrusters at once and by moving water
 *   between the tanks; meanwhile the thrusters stop the hull sliding across its axis, so with the
 *   screw ahead the boat follows its nose. Released, the hull levels out and the depth is held.
 * - The on-screen stick asks for part of the dive or climb speed and of the throttle, as far as it
 *   is pushed (`HelmInput.heave`, `HelmInput.drive`), so a small push makes a small correction.
 * - Ahead / astern (held): the throttle moves at `HELM.throttleRate`. Released, the screw winds
 *   down to stop at `HELM.throttleRelease` and the boat glides on a short way: as the screw's push
 *   goes, the helm brakes its way ahead at up to `HELM.coastBrake` (the screw's blades feathered across the
 *   flow and the planes set as brakes), fading out below `HELM.coastFade`, so a boat let go from full
 *   speed stops within about a hull's length instead of coasting on for a hundred metres on the
 *   water's drag alone (a telegraph that stays at full ahead reads as a stuck key; a screw that
 *   backs on its own brakes the boat as if it had hit something). Astern held is the harder brake:
 *   `HELM.asternBrake` times the coasting brake from its first step, and the screw backing; once the boat is stopped the brake lets the screw back it
 *   (to recover a beacon overshot: the boat always faces ahead), and let go it stops the backing.
 */

import type { PhysicsWorld } from '@bitphysics/physics';
import { setBallastTarget, setBodyThrust } from '@bitphysics/physics';
import { SUBMARINE, SUBMARINE_NEUTRAL_FILL, type SubmarineHandles, seabedHeight, setSubmarineThrusters } from '@bitphysics/projects';
import { divePlanes, PLANES, planeLift } from './planes';

/** Held controls this step: each true while its key or on-screen button is down. */
export interface HelmInput {
  /** Dive (W, the Dive button). */
  dive: boolean;
  /** Rise (S, the Rise button). */
  rise: boolean;
  /** Nose down (Q). */
  noseDown: boolean;
  /** Nose up (E). */
  noseUp: boolean;
  /** Screw ahead (D, right arrow). */
  ahead: boolean;
  /** Screw astern (A, left arrow). */
  astern: boolean;
  /**
   * How hard Dive or Rise is asked, in (0, 1]: the fraction of `HELM.diveSpeed` (`HELM.climbSpeed`)
   * asked for. Default 1 (a key); the on-screen stick sets it from how far it is pushed.
   */
  heave?: number;
  /**
   * How far Ahead or Astern is asked, in (0, 1]: the throttle the screw runs up to (ahead) or
   * -`HELM.asternShare` times it (astern). Default 1 (a key); the on-screen stick sets it from how far it is pushed.
   */
  drive?: number;
  /**
   * The depth ordered directly, as the hull's height, m (./stick.ts stickOrder: the on-screen stick
   * moves it and the gauge marks it): the helm takes the boat there at up to `heave` of the dive or
   * climb speed and levels on it, as it does on a let-go order. Unset or NaN: none (Dive / Rise and
   * the order they move rule).
   */
  orderY?: number;
  /**
   * The pitch asked for by the nose trim, rad (positive: nose up; ./helm.ts noseTrim), in place of
   * `noseDown` / `noseUp` when given and not 0: the boat is steered by the nose at that angle.
   */
  nose?: number;
  /**
   * The screw keeps its throttle while neither Ahead nor Astern is held (default false: it winds
   * down and the boat glides to a stop). The on-screen stick sets it while it is pushed up or down
   * but not sideways, so that rising or diving by the stick under way does not stop the screw.
   */
  keepThrottle?: boolean;
}

/** No control held. */
export const NO_INPUT: Readonly<HelmInput> = Object.freeze({
  dive: false,
  rise: false,
  noseDown: false,
  noseUp: false,
  ahead: false,
  astern: false,
});

/** What the helm keeps between steps and last commanded (read by the gauges). */
export interface HelmState {
  /** Screw throttle, fraction of `SUBMARINE.maxThrust`, in [-HELM.asternShare, 1]. */
  throttle: number;
  /** Mean tank fill the pumps move towards, in [0, 1]. */
  fill: number;
  /** Half the fore-minus-aft fill difference asked for (positive: nose down), in [-0.5, 0.5]. */
  trim: number;
  /**
   * The depth order, as the hull's y, m (negative under water): where the boat is going and will
   * stop (see the header); NaN while none (surfaced, steering by the nose, braking after a bump).
   */
  holdY: number;
  /** Vertical thrusters' push last commanded, N: fore and aft, positive up across the hull. */
  fore: number;
  aft: number;
  /** Dive planes' angle last commanded, rad, in [-PLANES.maxAngle, PLANES.maxAngle] (positive: lifting). */
  planes: number;
  /** What the helm is doing: 'surfaced', 'diving', 'rising', 'steering' (a Nose key), 'braking' or 'holding'. */
  mode: 'surfaced' | 'diving' | 'rising' | 'steering' | 'braking' | 'holding';
  /**
   * The depth the pilot set, as the hull's y, m, while a depth is held (NaN or absent: none yet):
   * `holdY` is this, raised over the seabed ahead (`holdFloor`) and back down to it once past.
   */
  setY?: number;
  /** The `holdY` the hold last wrote, m: a `holdY` changed since (a let-go order, the target's depth) is the depth set. */
  heldY?: number;
}

/** A new helm state: screw stopped, tanks empty (the scene's start), no depth held. */
export function createHelmState(fill = 0): HelmState {
  return {
    throttle: 0,
    fill,
    trim: 0,
    holdY: Number.NaN,
    fore: 0,
    aft: 0,
    planes: 0,
    mode: 'surfaced',
    setY: Number.NaN,
    heldY: Number.NaN,
  };
}

const DEG = Math.PI / 180;

/** The helm's settings. */
export const HELM = Object.freeze({
  /**
   * Vertical speed asked for while Dive is held, m/s (the boat runs at up to `topSpeed`, 8 m/s, ahead): a first
   * beacon 15 to 28 m down is reached in 2.5 to 3.5 s of Dive (the thrusters' 600 kN and the flooded
   * tanks' 91 kN take the 110 t boat to it in 1.6 s; drag k v^2 at 10 m/s is 240 kN).
   */
  diveSpeed: 10,
  /**
   * Vertical speed asked for while Rise is held, m/s: as much as diving, so a Rise key climbs as
   * briskly as Dive dives (a key at rest 5 m/s both ways, at full ahead about 8; at 8 m/s asked the
   * climb ran 4 and 6.4 m/s, which strangers read as a sluggish rise). The same honest forces carry
   * it: the thrusters' 600 kN, the tanks blown lighter than neutral (the weight that carries the
   * boat against drag, k v^2 = 240 kN at 10 m/s, plus riseExcess), against the drag; near the surface
   * the climb asked slows to surfacingSpeed, so the tanks refill and the boat comes up as gently.
   */
  climbSpeed: 10,
  /**
   * Most tank fill the helm adds (each tank) to speed a dive up: all of it, so a held Dive floods the
   * tanks full (91 kN more than neutral) at once, on top of the thrusters, until the boat runs at the
   * asked speed.
   */
  ballastExcess: 1,
  /**
   * Most tank fill the helm takes away (each tank) to speed a climb up: 0.3 (118 kN). Blowing more
   * would leave the tanks too light to refill before the surface, and the boat would leap out.
   */
  riseExcess: 0.3,
  /**
   * Most tank fill the helm adds or takes away while holding a depth: all of it, so the tanks blow
   * (flood) as far as the boat's sinking (rising) speed asks, ballastGain per m/s. Stopping 110 t at
   * the dive speed still takes metres (600 kN of thrusters, drag k v^2, and the tanks' weight
   * changing at fillRate x 2 x 20 t x g = 392 kN/s); with only ballastExcess it takes more.
   */
  holdExcess: 1,
  /** Tank fill added per m/s that the boat sinks slower (or rises faster) than asked, s/m. */
  ballastGain: 0.2,
  /** Pitch while a Nose key is held, rad (15 degrees). */
  noseAngle: 15 * DEG,
  /**
   * Pitch diving (bow down) or rising (bow up) adds at rest, rad (5 degrees); twice that at
   * KEY_HEAVE_FULL_SPEED and faster, in proportion to the speed, so a dive under way shows in the
   * bow at once.
   */
  diveAngle: 5 * DEG,
  /** Time constant of the vertical speed loop, s: the thrusters push m dv / heaveTime. */
  heaveTime: 0.2,
  /** Depth hold: climb asked per metre of depth error near the order, 1/s (the P of the hold's PD law; the D is the speed loop). */
  holdGain: 1.5,
  /**
   * Deceleration the helm plans to stop on the order with at rest, m/s^2: what the thrusters' 600 kN
   * give 110 t; the drag and the tanks blowing (392 kN/s) make up for the share the pitch takes.
   */
  brake: 5.5,
  /** Share of the dive planes' lift at full angle the helm counts on when it plans a stop under way. */
  planesShare: 0.6,
  /** How far the order runs ahead of a boat at rest when Dive or Rise is pressed, m (see orderReach). */
  orderLead: 0.5,
  /** Vertical speed under which braking after a bounce off the seabed ends and that depth is held, m/s. */
  holdSpeed: 0.3,
  /**
   * A held depth keeps the keel at least this far over the seabed under the hull and ahead of it
   * (`holdFloor`), m: the order is raised to clear a ridge, never left to drive the hull into it.
   */
  bedClearance: 2.5,
  /**
   * How far ahead the held depth looks for the seabed, s at the boat's speed ahead (`holdFloor`): at
   * full ahead (8 m/s) 32 m. As far as the seabed warning looks (./seabed.ts BED_WARN_TIME), so a
   * held course is never warned of a ridge: the helm is already raising the order over it.
   */
  bedLookAhead: 4,
  /**
   * The climb a held depth counts on to clear a ridge ahead, m/s (`holdFloor`): half the hold's
   * 8 m/s, for the time the boat takes to start climbing.
   */
  bedClimb: 4,
  /**
   * How fast a held order raised over a ridge (`holdFloor`) goes back down to the depth set once
   * past it, m/s: slow, so that a boat sinking back toward a valley can still stop and climb in time
   * for the next ridge (`holdFloor` plans the climb from a level boat).
   */
  returnSpeed: 2,
  /** Pitch loop of the thrusters: torque per radian of pitch error, N m / rad. */
  pitchGain: 3e6,
  /** Pitch loop of the thrusters: torque per rad/s of pitch rate, N m s / rad. */
  pitchDamping: 1.5e6,
  /** Climb asked for as the deck reaches the surface while Rise is held, m/s (more below: holdGain per metre). */
  surfacingSpeed: 0.6,
  /** A surfaced boat counts as surfaced while its deck bobs less than this under the surface, m. */
  surfaceBand: 1.5,
  /**
   * The boat's top speed ahead at full throttle, m/s (15.5 knots, a fast small submersible): the
   * screw's governor (`screwPush`) runs the screw's full 400 kN until the boat nears the speed its
   * throttle asks for (the throttle times this; `asternShare` of it astern) and then only what holds it
   * there. The screw alone would take the 12 m boat to 12.9 m/s (400 kN against drag k v^2), too fast
   * to stop at a beacon reached by holding Ahead.
   */
  topSpeed: 8,
  /** Time constant of the screw's governor, s: it pushes m (v_asked - u) / speedTime on top of the drag at the asked speed. */
  speedTime: 0.5,
  /**
   * Throttle change per second while Ahead or Astern is held: the electric screw spins up to full in
   * a sixth of a second, so a short tap already pushes with most of the screw's 400 kN (a tap of
   * 0.3 s moves the boat about 0.3 m, 0.5 s about 0.7 m, 1 s about 2.6 m).
   */
  throttleRate: 6,
  /**
   * Throttle change per second towards stop while neither is held: the screw winds down from full
   * in a quarter of a second, and the coasting brake (`coastBrake`) takes over as it does.
   */
  throttleRelease: 4,
  /**
   * Deceleration the helm brakes a boat with while Ahead is not held, m/s^2, once the screw has wound
   * down (scaled by the share of full throttle no longer pushing ahead): with the drag k v^2 a boat
   * let go at full speed (8 m/s) glides about 5 m, one at 6 m/s about 4 m.
   */
  coastBrake: 8,
  /**
   * Horizontal speed under which the coasting brake fades in proportion to the speed, m/s, so it
   * slows the boat onto a stop without ever pushing it backwards.
   */
  coastFade: 1,
  /**
   * Share of `coastBrake` the helm brakes with while Astern is held and the boat still moves ahead,
   * from the first step (the blades feathered and the planes set as brakes at once, not as the
   * throttle winds through zero), on top of the screw backing: from full ahead (8 m/s) the boat
   * stops in about 2 m and 0.6 s, at 16 m/s^2 (1.6 g) of brake at most, plus the drag.
   */
  asternBrake: 2,
  /**
   * Share of full throttle the screw runs at astern (Astern held, or the stick pushed back all the
   * way): 0.75, backing at up to 6 m/s, so a boat that ran past a beacon backs 7 m onto its ring from
   * a stop in about 2.5 s (3 s at half, 4 m/s).
   */
  asternShare: 0.75,
});

/**
 * The horizontal force the coasting brake gives, N (against the motion: negative for a boat moving
 * ahead, positive for one backing): a boat of `mass` kg moving at `u` m/s horizontally (positive
 * ahead) with the screw at `throttle` (fraction of full, in [-HELM.asternShare, 1]) is braked at
 * `HELM.coastBrake` times the share of the screw not pushing the way it moves, and in proportion to
 * its speed below `HELM.coastFade`. Moving ahead the share is 1 - throttle (0 at full ahead, 1.5 at
 * full astern), and at least `HELM.asternBrake` while Astern is held (`astern`: the brake); backing it is 1 + throttle / `HELM.asternShare`, in [0, 1.5] (0 at full
 * astern, so the brake never fights the screw backing the boat; 1 with the screw stopped, so a boat
 * let go while backing stops too). Zero for a boat at rest. `astern`: whether Astern is held (default false).
 * @throws RangeError when `mass` is not a finite positive number, or `u` or `throttle` is not finite.
 */
export function coastBrake(mass: number, u: number, throttle: number, astern = false): number {
  if (!(Number.isFinite(mass) && mass > 0)) throw new RangeError(`coastBrake: mass must be a finite number > 0 kg, got ${mass}`);
  if (!Number.isFinite(u)) throw new RangeError(`coastBrake: u must be finite, got ${u}`);
  if (!Number.isFinite(throttle)) throw new RangeError(`coastBrake: throttle must be finite, got ${throttle}`);
  const t = clamp(throttle, -HELM.asternShare, 1);
  const share = u >= 0 ? (astern ? Math.max(HELM.asternBrake, 1 - t) : 1 - t) : clamp(1 + t / HELM.asternShare, 0, 1.5);
  return -mass * HELM.coastBrake * share * clamp(u / HELM.coastFade, -1, 1);
}

/**
 * The least share of the screw's full push (`SUBMARINE.maxThrust`) the governor may use to reach the
 * speed a small throttle asks for: 0.5. At the throttle's own share (0.15 for the stick's least push
 * astern: 60 kN for 110 t) a boat stopped in a 0.9 m/s current took 4 s to back at 1.2 m/s over the
 * ground, and a stranger read it as doing nothing.
 */
export const SCREW_LEAST_SHARE = 0.5;

/**
 * The screw's push along the hull, N (positive ahead), for a boat of `mass` kg moving at `u` m/s
 * ahead through the water (horizontally, positive ahead) with the throttle at `throttle` (fraction
 * of full, in [-HELM.asternShare, 1]): the throttle's share of `SUBMARINE.maxThrust` (at least SCREW_LEAST_SHARE of it), but no more
 * than holds the boat at the speed ahead the throttle asks for (`throttle` times `HELM.topSpeed`):
 * the drag there (k |v| v_x, the scene's drag coefficient k, with `vy` the boat's vertical speed,
 * m/s: a diving boat drags more) plus m (v_asked - u) / `HELM.speedTime`, pushed along a hull
 * pitched by `angle` rad (so divided by cos(angle)), never pulling the other way. The speed asked is
 * the one ahead, not along the pitched hull: a boat diving with its bow down still makes the speed
 * ahead its throttle asks for. Zero with the throttle at zero. `against`: the speed of a current
 * flowing against the push, m/s (>= 0; default 0): the speed asked is made good over the ground, so
 * it is asked through the water that much faster (a small push astern against a 1.2 m/s current
 * made no headway at all).
 * @throws RangeError when `mass` is not a finite positive number, or `u`, `throttle`, `vy` or `angle` is not finite.
 */
export function screwPush(mass: number, u: number, throttle: number, vy = 0, angle = 0, against = 0): number {
  if (!(Number.isFinite(mass) && mass > 0)) throw new RangeError(`screwPush: mass must be a finite number > 0 kg, got ${mass}`);
  if (!Number.isFinite(u)) throw new RangeError(`screwPush: u must be finite m/s, got ${u}`);
  if (!Number.isFinite(throttle)) throw new RangeError(`screwPush: throttle must be finite, got ${throttle}`);
  if (!Number.isFinite(vy)) throw new RangeError(`screwPush: vy must be finite m/s, got ${vy}`);
  if (!Number.isFinite(angle)) throw new RangeError(`screwPush: angle must be finite rad, got ${angle}`);
  const t = clamp(throttle, -HELM.asternShare, 1);
  if (t === 0) return 0;
  const sign = Math.sign(t),
    asked = Math.abs(t) * HELM.topSpeed + Math.max(0, Number.isFinite(against) ? against : 0);
  const ahead = SUBMARINE.dragCoefficient * asked * Math.hypot(asked, vy) + (mass * (asked - sign * u)) / HELM.speedTime;
  // Along the hull: a pitched hull's push has cos(angle) of it ahead (at most 60 degrees counted).
  // At most the throttle's share of the screw, but never under SCREW_LEAST_SHARE of it: a small
  // push still gets up to its own (small) speed within a second or two, against a current too.
  return sign * clamp(ahead / Math.max(0.5, Math.cos(angle)), 0, Math.max(Math.abs(t), SCREW_LEAST_SHARE) * SUBMARINE.maxThrust);
}

/**
 * The share of full Dive / Rise (`HelmInput.heave`) a Dive or Rise key asks for at rest: a steady 0.5
 * (5 m/s down, 5 m/s up), from the first moment it is held, so the depth gone grows in step with
 * the time held (from a hover about 4.6 m for 1 s, 9.8 m for 2 s, 19.8 m for 4 s) and a short tap
 * still moves the depth order by most of a metre. The thrusters' 5.5 m/s^2 take the boat to 90 % of
 * it in 0.9 s, and let go it runs on 2.2 m and stops within 1.1 s (at 6 m/s: 1.05 s, 3.2 m and
 * 1.4 s, which strangers read as sluggish and then overshooting). (A key that asked for the full
 * 10 m/s at once would take the boat 11 m in 1.5 s; one that ramped up from a tenth would make the
 * depth grow with the square of the time.)
 * Under way the key asks for more (`KEY_HEAVE_SHARE_FAST`). The on-screen stick asks for as much as it
 * is pushed, up to what a key asks for (the page's heldInput), so the two dive alike.
 */
export const KEY_HEAVE_SHARE = 0.5;

/**
 * The share a Dive or Rise key asks for at `KEY_HEAVE_FULL_SPEED` ahead or faster: 0.8 (8 m/s down or up).
 * At full ahead a boat diving at 6 m/s ran 18 m ahead for 5 m down in 1.5 s, a dive
 * slow to answer. (All of it, 10 m/s, takes a pilot on the keys into more mines and seabed slopes:
 * scripts/submarine-pilot.mjs.)
 */
export const KEY_HEAVE_SHARE_FAST = 0.8;

/** The speed ahead (or astern) at which a key's share reaches `KEY_HEAVE_SHARE_FAST`, m/s: nearly the boat's top speed (`HELM.topSpeed`). */
export const KEY_HEAVE_FULL_SPEED = 7.5;

/**
 * The share of full Dive / Rise (`HelmInput.heave`) a key held since game time `since` asks for at
 * game time `now` (s) with the boat moving at `u` m/s along its hull (ahead or astern): from
 * `KEY_HEAVE_SHARE` at rest up to `KEY_HEAVE_SHARE_FAST` at `KEY_HEAVE_FULL_SPEED` and faster, in
 * proportion to the speed, whatever the time held (a function of the hold so that the page and the
 * pilot script ask the helm the same way).
 * @throws RangeError when `since`, `now` or `u` is not finite.
 */
export function keyHeaveShare(since: number, now: number, u = 0): number {
  if (!Number.isFinite(since)) throw new RangeError(`keyHeaveShare: since must be finite, got ${since}`);
  if (!Number.isFinite(now)) throw new RangeError(`keyHeaveShare: now must be finite, got ${now}`);
  if (!Number.isFinite(u)) throw new RangeError(`keyHeaveShare: u must be finite m/s, got ${u}`);
  return KEY_HEAVE_SHARE + (KEY_HEAVE_SHARE_FAST - KEY_HEAVE_SHARE) * Math.min(1, Math.abs(u) / KEY_HEAVE_FULL_SPEED);
}

const clamp = (v: number, lo: number, hi: number): number => (v < lo ? lo : v > hi ? hi : v);

/**
 * The nose trim's step per press of a Nose key or button, rad (5 degrees): every tap turns the boat
 * that much more and it stays so (a tap that only held the nose while pressed turned it 1.1 degrees,
 * and it levelled again: a stranger saw nothing).
 */
export const NOSE_STEP = 5 * DEG;
/** How fast a Nose key or button held on turns the trim on, rad/s (10 degrees a second, to HELM.noseAngle). */
export const NOSE_RATE = 10 * DEG;

/**
 * The nose trim after a step of `dt` s, rad (positive: nose up), from `trim`: a new press (`press`:
 * 1 Nose up, -1 Nose down, 0 none this step) adds NOSE_STEP that way; a Nose key held (`held`, the
 * same signs) turns it on at NOSE_RATE; within +-HELM.noseAngle. The helm pitches the boat to it
 * (`HelmInput.nose`) and, under way, the boat follows its nose; Dive or Rise clears it (the page).
 * @throws RangeError when `trim` or `dt` is not finite or `dt` is negative.
 */
export function noseTrim(trim: number, press: -1 | 0 | 1, held: -1 | 0 | 1, dt: number): number {
  if (!Number.isFinite(trim)) throw new RangeError(`noseTrim: trim must be finite rad, got ${trim}`);
  if (!(Number.isFinite(dt) && dt >= 0)) throw new RangeError(`noseTrim: dt must be finite s >= 0, got ${dt}`);
  const next = trim + press * NOSE_STEP + held * NOSE_RATE * dt;
  // A step back through level stops at level, so a tap the other way always levels a small trim.
  const level = press !== 0 && Math.sign(trim) === -press && Math.sign(next) === press;
  return level ? 0 : clamp(next, -HELM.noseAngle, HELM.noseAngle);
}

/** The distance a boat at vertical speed `vy` (m/s) stops in at the deceleration `brake` (m/s^2, > 0), m. */
export function stopping(vy: number, brake: number = HELM.brake): number {
  return (vy * vy) / (2 * brake);
}

/**
 * How far the depth order may run ahead of a boat moving at vertical speed `vy`, m/s: its stopping
 * distance at the deceleration `brake` (m/s^2, > 0) plus `HELM.orderLead`, so a boat let go stops on
 * the order.
 */
export function orderReach(vy: number, brake: number = HELM.brake): number {
  return HELM.orderLead + stopping(vy, brake);
}

/**
 * The vertical speed asked for to close a depth error `error` (the order's y minus the hull's, m):
 * at most `most` (m/s), at most the speed from which the boat stops in `error` at the deceleration
 * `brake` (m/s^2, > 0), and `HELM.holdGain` per metre near the order, so the boat slows onto it
 * without passing it.
 */
export function approach(error: number, most: number, brake: number = HELM.brake): number {
  const d = Math.abs(error);
  return Math.sign(error) * Math.min(most, Math.sqrt(2 * brake * d), HELM.holdGain * d);
}

/**
 * The lowest a held depth may go, as the hull's centre y, m (y up): `HELM.bedClearance` plus half
 * the hull's height over the seabed (`seabed`, the scene's) under a level hull centred at `x` (m),
 * and over the seabed up to `HELM.bedLookAhead` s ahead of its bow at its speed `vx` (m/s; astern
 * the same way behind the stern) less the climb `HELM.bedClimb` makes in the time it takes to get
 * there: the order rises as late as still clears a ridge, so a beacon low in a valley before a
 * slope can still be reached. Sampled every 2 m.
 * @throws RangeError when `x` or `vx` is not finite.
 */
export function holdFloor(seabed: SubmarineHandles['seabed'], x: number, vx: number): number {
  if (!Number.isFinite(x)) throw new RangeError(`holdFloor: x must be finite m, got ${x}`);
  if (!Number.isFinite(vx)) throw new RangeError(`holdFloor: vx must be finite m/s, got ${vx}`);
  const L = SUBMARINE.length / 2,
    speed = Math.abs(vx),
    dir = vx < 0 ? -1 : 1;
  let bed = Math.max(seabedHeight(seabed, x - L), seabedHeight(seabed, x), seabedHeight(seabed, x + L));
  const reach = speed * HELM.bedLookAhead;
  for (let d = 2; d <= reach; d += 2) bed = Math.max(bed, seabedHeight(seabed, x + dir * (L + d)) - (HELM.bedClimb * d) / speed);
  return bed + SUBMARINE.height / 2 + HELM.bedClearance;
}

/**
 * One step of the helm: reads the hull (position, velocity, angle, mass) and the sea's surface,
 * updates `state` from `input` and writes the ballast targets, the vertical thrusters and the screw
 * into the world. Call it before each `step(world)`. `current`: the water's horizontal velocity at
 * the hull, m/s (default 0, still water; ./current.ts): the screw, the planes and the coasting brake
 * work on the hull's speed through the water, so a boat let go stops in the water and drifts with it.
 */
export function steer(world: PhysicsWorld, handles: SubmarineHandles, input: HelmInput, state: HelmState, current = 0): void {
  const c = world.components,
    e = handles.hull,
    dt = world.dt,
    S = SUBMARINE;
  const heaveAsked = clamp(input.heave ?? 1, 0, 1),
    driveAsked = clamp(input.drive ?? 1, 0, 1);
  // The throttle runs at throttleRate toward the one asked for (drive ahead, -drive / 2 astern) and
  // winds back at throttleRelease toward it when it is past it (a stick eased back) or to stop.
  // Neither held: the screw winds down to stop and the boat coasts, slowed by the water's drag.
  const keep = input.keepThrottle === true && !input.ahead && !input.astern;
  const asked = keep ? state.throttle : input.ahead === input.astern ? 0 : input.ahead ? driveAsked : -HELM.asternShare * driveAsked;
  // Winding towards stop (a key let go, or Astern from ahead) is at the faster of the two rates.
  const pushing =
    (asked > 0 && state.throttle < asked && state.throttle >= 0) || (asked < 0 && state.throttle > asked && state.throttle <= 0);
  const rate = (pushing ? HELM.throttleRate : Math.max(HELM.throttleRate, HELM.throttleRelease)) * dt;
  state.throttle = state.throttle < asked ? Math.min(asked, state.throttle + rate) : Math.max(asked, state.throttle - rate);

  const y = c.Position.y[e]!,
    vy = c.Velocity.y[e]!,
    angle = c.Angle.value[e]!,
    spin = c.AngularVelocity.z[e]!,
    mass = c.Mass.value[e]!;
  const surface = c.FluidRegion.surface[handles.sea]!;
  const top = y + S.height / 2; // the deck's height (level hull), m
  const dive = input.dive && !input.rise,
    rise = input.rise && !input.dive;
  // Afloat: the deck out, or bobbing within surfaceBand of the surface since it surfaced.
  const afloat = top > surface || (state.mode === 'surfaced' && top > surface - HELM.surfaceBand);
  const ordered = dive || rise ? Number.NaN : (input.orderY ?? Number.NaN);
  const neutral = SUBMARINE_NEUTRAL_FILL;

  // The boat under way brakes harder: its planes (./planes.ts) add up to their lift at full angle.
  const u = (c.Velocity.x[e]! - current) * Math.cos(angle) + vy * Math.sin(angle);
  const submerged = clamp((surface - (y - S.height / 2)) / S.height, 0, 1);
  const brake = HELM.brake + (HELM.planesShare * Math.abs(planeLift(PLANES.maxAngle, u, submerged))) / mass;
  // Vertical: the depth ordered (state.holdY), the speed asked for (NaN: none asked) and the tanks' mean target.
  let vCmd = Number.NaN;
  if (dive) {
    // The order runs down at the asked speed from where the boat is, never further ahead of it than
    // it can stop in (orderReach), so that when the key is let go the boat stops on the order.
    state.mode = 'diving';
    const ask = HELM.diveSpeed * heaveAsked;
    const from = Number.isNaN(state.holdY) ? y : Math.min(state.holdY, y);
    state.holdY = Math.min(Math.max(from - ask * dt, y - orderReach(vy, brake)), y - stopping(Math.min(0, vy), brake));
    // Never ordered into the seabed: at least the hold's clearance over the bed under the hull.
    state.holdY = Math.max(state.holdY, holdFloor(handles.seabed, c.Position.x[e]!, 0));
    vCmd = -ask;
  } else if (Number.isFinite(ordered) && !(afloat && ordered >= y - HELM.orderLead)) {
    // The stick's order (input.orderY): to it at up to the asked speed, slowing onto it as on a
    // let-go order (approach); the bow dips or rises as a held Dive or Rise does while it goes.
    // Never ordered into the seabed, and slower near the surface as a held Rise is.
    state.holdY = Math.max(ordered, holdFloor(handles.seabed, c.Position.x[e]!, c.Velocity.x[e]!));
    // Let go on it, the hold keeps the order as the depth set, not the raised one.
    state.setY = ordered;
    state.heldY = state.holdY;
    const error = state.holdY - y;
    state.mode = error < -HELM.orderLead ? 'diving' : error > HELM.orderLead ? 'rising' : 'holding';
    vCmd = approach(error, (error < 0 ? HELM.diveSpeed : HELM.climbSpeed) * heaveAsked, brake);
    const below = Math.max(0, surface - top);
    if (vCmd > 0) vCmd = Math.min(vCmd, HELM.surfacingSpeed + Math.min(HELM.holdGain * below, Math.sqrt(brake * below)));
  } else if (afloat) {
    // On the surface and not told to dive: tanks blown, the boat floats (Rise there does the same).
    // It stays surfaced while it bobs within surfaceBand of the surface.
    state.mode = 'surfaced';
  } else if (rise) {
    state.mode = 'rising';
    const ask = HELM.climbSpeed * heaveAsked;
    const from = Number.isNaN(state.holdY) ? y : Math.max(state.holdY, y);
    state.holdY = Math.max(Math.min(from + ask * dt, y + orderReach(vy, brake)), y + stopping(Math.max(0, vy), brake));
    // Slower near the surface, so the boat comes up to it gently instead of leaping out.
    // (the speed from which it stops at half the planned deceleration, and holdGain per metre near it).
    const below = Math.max(0, surface - top);
    vCmd = Math.min(ask, HELM.surfacingSpeed + Math.min(HELM.holdGain * below, Math.sqrt(brake * below)));
  } else if (input.noseDown !== input.noseUp || (input.nose ?? 0) !== 0) {
    // Steering by the nose: no depth held, so with the screw ahead the boat follows its nose.
    state.mode = 'steering';
  } else {
    // Let go: the boat goes on to the order and holds it. Coming from steering (no order) the order
    // is where the boat can stop. After a bounce off the seabed (holdY cleared while braking or
    // holding) the helm brakes first and holds where the boat stops instead.
    if (state.mode === 'steering' || (state.mode === 'surfaced' && Number.isNaN(state.holdY)))
      state.holdY = y + Math.sign(vy) * stopping(vy, brake);
    if (Number.isNaN(state.holdY) && Math.abs(vy) < HELM.holdSpeed) state.holdY = y;
    // A held depth never drives the hull into the seabed: over a ridge ahead the order is raised,
    // and once past it goes back down to the depth set (it stayed up, and the boat drifted off the
    // depth the pilot had levelled at). A holdY written since the last step (a let-go order, the
    // page's stop at the target's depth) is the depth set.
    if (!Number.isNaN(state.holdY)) {
      if (!(Number.isFinite(state.setY) && state.holdY === state.heldY)) state.setY = state.holdY;
      const floor = holdFloor(handles.seabed, c.Position.x[e]!, c.Velocity.x[e]!);
      // Back down no faster than HELM.returnSpeed, so a boat sinking back can stop for the next rise.
      state.holdY = Math.max(state.setY!, floor, state.holdY - HELM.returnSpeed * dt);
      state.heldY = state.holdY;
    }
    state.mode = Number.isNaN(state.holdY) ? 'braking' : 'holding';
    vCmd = Number.isNaN(state.holdY) ? 0 : approach(state.holdY - y, HELM.climbSpeed, brake);
  }
  if (state.mode !== 'braking' && state.mode !== 'holding' && state.mode !== 'diving' && state.mode !== 'rising') state.holdY = Number.NaN;
  // Diving or rising on a key, the depth set is wherever the order stops.
  if (dive || rise || Number.isNaN(state.holdY)) state.setY = Number.NaN;
  if (state.mode === 'surfaced') state.fill = 0;
  else if (Number.isNaN(vCmd)) state.fill = neutral;
  else {
    // The weight that carries the boat at vCmd against drag (k v^2 = 2 capacity g df), and more
    // while the boat is slower or faster than asked (heavier while it rises too fast).
    const carry = (-Math.sign(vCmd) * S.dragCoefficient * vCmd * vCmd) / (2 * S.tankCapacity * 9.81);
    const hold = state.mode === 'holding' || state.mode === 'braking';
    const excess = hold ? HELM.holdExcess : state.mode === 'rising' ? HELM.riseExcess : HELM.ballastExcess;
    state.fill = clamp(neutral + carry + clamp(HELM.ballastGain * (vy - vCmd), -excess, excess), 0, 1);
  }
  // The thrusters push across the hull. Steering by the nose, they stop the hull sliding across its
  // own axis (the speed v_n = -vx sin(angle) + vy cos(angle)), so it goes where it points, as a moving
  // boat does with its hydroplanes; otherwise they chase the vertical speed asked for.
  const vn = -c.Velocity.x[e]! * Math.sin(angle) + vy * Math.cos(angle);
  let heave = state.mode === 'steering' ? (-mass * vn) / HELM.heaveTime : Number.isNaN(vCmd) ? 0 : (mass * (vCmd - vy)) / HELM.heaveTime;
  // The dive planes (./planes.ts) give what they can of that push first (the water's flow past a
  // boat under way lifts for nothing), turning at their rate; the thrusters give the rest.
  const planes = divePlanes(world, handles);
  const perRadian = planeLift(1, u, submerged);
  const want = state.mode === 'surfaced' || Math.abs(perRadian) < 1 ? 0 : clamp(heave / perRadian, -PLANES.maxAngle, PLANES.maxAngle);
  const turn = PLANES.rate * dt;
  planes[0] = clamp(want, planes[0]! - turn, planes[0]! + turn);
  state.planes = planes[0]!;
  heave -= planeLift(state.planes, u, submerged);

  // Pitch: the angle asked for (positive: nose up), by the thrusters now and by the water for good.
  const pitch =
    (input.nose ? clamp(input.nose, -HELM.noseAngle, HELM.noseAngle) : HELM.noseAngle * (Number(input.noseUp) - Number(input.noseDown))) +
    HELM.diveAngle *
      (1 + Math.min(1, Math.abs(u) / KEY_HEAVE_FULL_SPEED)) *
      (Number(state.mode === 'rising') - Number(state.mode === 'diving'));
  // Static trim (forces/ballast.ts): arm capacity (f_fore - f_aft) g cos = -M g GM sin, so the
  // half difference is -tan(pitch) M GM / (2 arm capacity).
  // Limited so that both tanks stay within [0, 1] around the mean (the thrusters give the rest).
  const room = Math.min(state.fill, 1 - state.fill);
  state.trim = clamp((-Math.tan(pitch) * mass * S.metacentricHeight) / (2 * S.tankArm * S.tankCapacity), -room, room);
  const fore = clamp(state.fill + state.trim, 0, 1),
    aft = clamp(state.fill - state.trim, 0, 1);
  setBallastTarget(world, e, fore, aft);

  // Thrusters: the pitch torque gets up to half of each one's push, the heave the rest.
  const T = S.thrusterForce,
    a = S.thrusterArm;
  const torque = clamp(HELM.pitchGain * (pitch - angle) - HELM.pitchDamping * spin, -T * a, T * a);
  const tPart = torque / (2 * a),
    left = T - Math.abs(tPart);
  const hPart = clamp(heave / 2, -left, left);
  state.fore = hPart + tPart;
  state.aft = hPart - tPart;
  // At the surface with nothing asked the thrusters rest (they would only churn the water).
  if (state.mode === 'surfaced' && pitch === 0) state.fore = state.aft = 0;
  setSubmarineThrusters(handles, state.fore, state.aft);
  // The coasting brake on top of the screw, except while the key held pushes the way the boat
  // moves (Ahead going ahead, Astern backing): let go, it stops the boat either way; Astern held
  // going ahead (or Ahead backing), brake and screw stop it together. It brakes the horizontal
  // speed only (pushing horizontally: in the hull's frame cos / -sin of its angle), so it never
  // slows a dive or a climb of a pitched boat.
  const ux = c.Velocity.x[e]! - current;
  const along = keep || (input.ahead && !input.astern && ux >= 0) || (input.astern && !input.ahead && ux <= 0);
  const brakeForce = along ? 0 : coastBrake(mass, ux, state.throttle, input.astern && !input.ahead);
  // Against the current the speed asked is made good over the ground (the screw pushes harder).
  const push = screwPush(mass, ux, state.throttle, vy, angle, Math.max(0, -Math.sign(state.throttle) * current));
  setBodyThrust(world, e, [push + brakeForce * Math.cos(angle), -brakeForce * Math.sin(angle)]);
}

/**
 * How far a submerged boat moving ahead at `u` m/s (horizontally, level) glides once Ahead is let
 * go with the screw at `throttle` (fraction of full, in [-HELM.asternShare, 1]), m: the same law the helm and
 * the sea apply, stepped at `dt` s (the world's step): the throttle winds down to stop at
 * max(`HELM.throttleRate`, `HELM.throttleRelease`) per second, the screw pushes `screwPush`, the
 * coasting brake `coastBrake` and the drag k u^2 (`SUBMARINE.dragCoefficient`) hold it back, until
 * the boat stops. 0 for a boat not moving ahead. The pointer's brake hint uses it to say when to let go.
 * @param mass the hull's mass now, kg (finite, > 0; tanks included).
 * @throws RangeError when `mass` or `dt` is not a finite positive number, or `u` or `throttle` is not finite.
 */
export function coastDistance(mass: number, u: number, throttle: number, dt = 1 / 60): number {
  if (!(Number.isFinite(mass) && mass > 0)) throw new RangeError(`coastDistance: mass must be a finite number > 0 kg, got ${mass}`);
  if (!Number.isFinite(u)) throw new RangeError(`coastDistance: u must be finite m/s, got ${u}`);
  if (!Number.isFinite(throttle)) throw new RangeError(`coastDistance: throttle must be finite, got ${throttle}`);
  if (!(Number.isFinite(dt) && dt > 0)) throw new RangeError(`coastDistance: dt must be a finite number > 0 s, got ${dt}`);
  const rate = Math.max(HELM.throttleRate, HELM.throttleRelease) * dt;
  let t = clamp(throttle, -HELM.asternShare, 1),
    v = u,
    x = 0;
  // At most 60 s of glide: the coasting brake stops any boat the screw can drive long before.
  for (let i = 0; i < 60 / dt && v > 1e-3; i++) {
    t = t > 0 ? Math.max(0, t - rate) : Math.min(0, t + rate);
    const f = screwPush(mass, v, t) + coastBrake(mass, v, t) - SUBMARINE.dragCoefficient * v * v;
    v = Math.max(0, v + (f / mass) * dt);
    x += v * dt;
  }
  return x;
}
