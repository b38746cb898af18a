/**
 * The free-spin mode's challenge (the cube on its pivot): steer the cube's angular velocity w onto a
 * target spin (a vector, rad/s, world frame) and hold it there, three targets in turn. A cube's three
 * principal moments are equal (I = m s^2 / 6), so its angular momentum L = I w stays parallel to w and
 * a torque tau changes w at tau / I along tau: the player pushes w's tip towards the target's with the
 * torque keys, and brakes before it overshoots. Pure (no DOM, no three.js).
 */
import type { PhysicsWorld } from '@bitphysics/physics';

/** Targets in a round. */
export const SPIN_TARGETS = 3;
/** A target counts while w lies within this of it, rad/s (the length of the difference vector). */
export const SPIN_TOLERANCE = 0.3;
/** How long w must stay within SPIN_TOLERANCE of a target, s (of world time, without a break). */
export const SPIN_HOLD = 2;
/** The target spin's magnitude, rad/s. */
export const SPIN_RATE = 2;
/** Stars for a round's time, s: 3 within SPIN_STAR_TIMES[0], 2 within SPIN_STAR_TIMES[1], else 1. */
export const SPIN_STAR_TIMES: readonly [number, number] = Object.freeze([25, 50]) as readonly [number, number];

/**
 * The round's targets, rad/s, world frame, from the camera's right and up (unit vectors, world frame,
 * so the keys' torque axes line up with them): SPIN_RATE about up (W alone), about right (D alone),
 * then about the line half way between up and -right (W and A at once).
 * @throws RangeError if `right` or `up` is not 3 finite numbers of length near 1.
 */
export function spinTargets(right: ArrayLike<number>, up: ArrayLike<number>): [number, number, number][] {
  for (const [name, v] of [
    ['right', right],
    ['up', up],
  ] as const)
    if (v.length !== 3 || !Array.from(v).every(Number.isFinite) || Math.abs(Math.hypot(v[0]!, v[1]!, v[2]!) - 1) > 1e-6)
      throw new RangeError(`spinTargets: ${name} must be a unit vector of 3 finite numbers, got ${JSON.stringify(Array.from(v))}`);
  const k = SPIN_RATE * Math.SQRT1_2;
  return [
    [SPIN_RATE * up[0]!, SPIN_RATE * up[1]!, SPIN_RATE * up[2]!],
    [SPIN_RATE * right[0]!, SPIN_RATE * right[1]!, SPIN_RATE * right[2]!],
    [k * (up[0]! - right[0]!), k * (up[1]! - right[1]!), k * (up[2]! - right[2]!)],
  ];
}

/**
 * The free-spin round: targets in turn; each step (`update`) reads the body's w, and while it lies
 * within SPIN_TOLERANCE of the lit target the hold time grows; SPIN_HOLD s of it light the next
 * target, and after the last the round is won (`wonAt`). The clock runs from the player's first input
 * (`start`), as the other rounds'.
 */
export class SpinChallenge {
  /** The targets, rad/s, world frame. */
  targets: [number, number, number][];
  /** Index of the lit target, in [0, targets.length] (the length: won). */
  target = 0;
  /** How long w has stayed within SPIN_TOLERANCE of the lit target, s (0 after it leaves). */
  held = 0;
  /** The distance from w to the lit target at the last `update`, rad/s (0 once won). */
  off = 0;
  /** World time the round was won, s, or -1. */
  wonAt = -1;
  /** World time the round's clock started (the first input), s, or -1 before it. */
  startedAt = -1;
  /** World time of the last `update`, s (the hold grows by the step between two). */
  private lastTime = -1;
  /** @param targets the round's targets (rad/s, world frame; `spinTargets`). */
  constructor(targets: [number, number, number][]) {
    this.targets = targets;
  }
  /** Starts again with `targets` when given. */
  reset(targets?: [number, number, number][]): void {
    if (targets) this.targets = targets;
    this.target = 0;
    this.held = 0;
    this.off = 0;
    this.wonAt = -1;
    this.startedAt = -1;
    this.lastTime = -1;
  }
  /** Starts the round's clock at world time `time`, s (only the first call counts). */
  start(time: number): void {
    if (this.startedAt < 0) this.startedAt = time;
  }
  /** Whether the round is won. */
  get won(): boolean {
    return this.wonAt >= 0;
  }
  /** The round's clock at world time `now`, s: 0 before the start, the time taken once won. */
  time(now: number): number {
    if (this.startedAt < 0) return 0;
    return Math.max(0, (this.won ? this.wonAt : now) - this.startedAt);
  }
  /** Stars of a won round by its time (SPIN_STAR_TIMES), 0 while it runs. */
  stars(): number {
    if (!this.won) return 0;
    const t = this.wonAt - this.startedAt;
    return t <= SPIN_STAR_TIMES[0] ? 3 : t <= SPIN_STAR_TIMES[1] ? 2 : 1;
  }
  /**
   * Reads `body`'s angular velocity after a step of `world` and moves the round on (nothing before the
   * start or once won). @returns whether a target was reached by this call.
   */
  update(world: PhysicsWorld, body: number): boolean {
    const dt = this.lastTime >= 0 ? world.time - this.lastTime : 0;
    this.lastTime = world.time;
    const aim = this.targets[this.target];
    if (this.startedAt < 0 || this.won || !aim) return false;
    const W = world.components.AngularVelocity;
    this.off = Math.hypot(W.x[body]! - aim[0], W.y[body]! - aim[1], W.z[body]! - aim[2]);
    this.held = this.off <= SPIN_TOLERANCE ? this.held + dt : 0;
    if (this.held < SPIN_HOLD) return false;
    this.held = 0;
    this.target++;
    if (this.target === this.targets.length) {
      this.wonAt = world.time;
      this.off = 0;
    }
    return true;
  }
}

/** The closeness meter's mark for the ball's edge: ω's tip within SPIN_TOLERANCE of the target reads at least this. */
export const SPIN_IN_BALL = 0.8;

/**
 * How near ω is to the lit target, for the meter beside the numbers, in [0, 1]: 1 on the target,
 * SPIN_IN_BALL at the ball's edge (SPIN_TOLERANCE off), falling linearly from there to 0 at twice
 * SPIN_RATE off (ω spinning the other way at the target's rate) and beyond. Fine steps near the
 * target, where the player eases off, and a clear mark for "in the ball".
 * @param off the distance from ω to the target, rad/s (SpinChallenge `off`).
 * @throws RangeError if `off` is not a finite number >= 0.
 */
export function spinCloseness(off: number): number {
  if (!(off >= 0) || !Number.isFinite(off)) throw new RangeError(`spinCloseness: off must be a finite number >= 0, got ${off}`);
  if (off <= SPIN_TOLERANCE) return SPIN_IN_BALL + (1 - SPIN_IN_BALL) * (1 - off / SPIN_TOLERANCE);
  return SPIN_IN_BALL * Math.max(0, 1 - (off - SPIN_TOLERANCE) / (2 * SPIN_RATE - SPIN_TOLERANCE));
}

/**
 * How well a torque `t` (N m, world frame) points along the gap `gap` from ω to the target (rad/s,
 * the target less ω): the cosine of the angle between them, in [-1, 1]; 0 when either is next to
 * nothing (under 1e-9). A cube's moments are equal, so the torque turns ω's tip straight along it:
 * 1 closes the gap fastest, below 0 widens it.
 */
export function pushAlignment(t: ArrayLike<number>, gap: ArrayLike<number>): number {
  const lt = Math.hypot(t[0]!, t[1]!, t[2]!),
    lg = Math.hypot(gap[0]!, gap[1]!, gap[2]!);
  if (!(lt > 1e-9) || !(lg > 1e-9)) return 0;
  return Math.max(-1, Math.min(1, (t[0]! * gap[0]! + t[1]! * gap[1]! + t[2]! * gap[2]!) / (lt * lg)));
}

/** The closeness as a bar of 10 cells ('▰' filled, '▱' empty), filled to the nearest cell, for the status row. */
export function closenessBar(closeness: number): string {
  const n = Math.round(Math.max(0, Math.min(1, closeness)) * 10);
  return '▰'.repeat(n) + '▱'.repeat(10 - n);
}
