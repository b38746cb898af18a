/**
 * The player's hand on the cloth, headless: a soft grip of the patch under the pointer.
 *
 * Pressing on the cloth takes hold of the points within a hand's radius of the press, each by a soft
 * pin (pinClothPoint with options: a spring solved in the cloth solver's small steps, its force
 * capped) toward its place under the pointer, the nearest points holding hardest. The pull spreads
 * over the patch and from it into the sheet, which stretches, swings and lags behind the hand; links
 * tear where the pull strains them past the tear strain (a long pull, or a fast yank).
 */
import { type Cloth, isAlive, type PhysicsWorld, pinClothPoint, slotOf } from '@bitphysics/physics';
import { SHEET_WIDTH } from './scene';

/** How the hand holds the cloth (see ClothGrab). */
export interface GrabOptions {
  /** Radius of the held patch, m, > 0: the moving points this close to the press are held. */
  radius: number;
  /** Stiffness of the grip, N/m, > 0, shared by the held points by weight. */
  stiffness: number;
  /** Largest total pull of the grip, N, > 0, shared by weight. */
  maxForce: number;
}

/**
 * The lab's grip: a 0.4 m hand, 300 N/m, at most 80 N (the sheet weighs about 10 N). Stiff enough that
 * the held patch keeps within a few centimetres of the hand while the sheet gives, so a short pull
 * (0.4 m down from the lower middle) stretches the links by the hand to 20-25%, and strong enough that
 * a long one (1.5 m) tears the sheet at the default tear strain, the hand keeping the torn piece
 * (test/games/lab-cloth.test.ts).
 */
export const GRAB: GrabOptions = { radius: 0.4, stiffness: 300, maxForce: 80 };

/**
 * The lab's grip for a sheet of `size` points across: GRAB with its radius at least 1.5 link spacings,
 * so a coarse sheet is still held by several points.
 */
export function gripFor(size: number): GrabOptions {
  return { ...GRAB, radius: Math.max(GRAB.radius, (1.5 * SHEET_WIDTH) / (size - 1)) };
}

/**
 * A soft grab of a cloth: `ClothGrab.at` presses at (x, y) and holds the moving points within
 * `radius`, each by a soft pin (pinClothPoint with options) toward t_i = hand + o_i, o_i its offset from
 * the press, with stiffness w_i k (compliance 1 / (w_i k)) and largest force w_i maxForce, where the
 * weights w_i = (1 - d_i / radius)^2, normalised to sum 1, favour the points nearest the press.
 */
export class ClothGrab {
  /** Held points' handles. */
  readonly points: number[] = [];
  /** Held points' weights (sum 1). */
  readonly weights: number[] = [];
  /** Held points' offsets from the hand, m (x, y interleaved). */
  readonly offsets: number[] = [];
  /** Where the hand is, m. */
  readonly hand: [number, number];

  private constructor(
    private readonly world: PhysicsWorld,
    x: number,
    y: number,
    readonly options: GrabOptions,
  ) {
    this.hand = [x, y];
  }

  /**
   * Presses at (x, y), m: holds the cloth's moving points within options.radius.
   * @returns the grab, or null when no moving point is that close.
   */
  static at(world: PhysicsWorld, cloth: Cloth, x: number, y: number, options: GrabOptions = GRAB): ClothGrab | null {
    const P = world.components.Position,
      inv = world.components.Mass.inv;
    const g = new ClothGrab(world, x, y, options);
    let total = 0;
    for (let i = 0; i < cloth.points.length; i++) {
      const e = slotOf(cloth.points[i]!);
      if (!(inv[e]! > 0)) continue;
      const dx = P.x[e]! - x,
        dy = P.y[e]! - y,
        d = Math.hypot(dx, dy);
      if (d >= options.radius) continue;
      const w = (1 - d / options.radius) ** 2;
      g.points.push(cloth.points[i]!);
      g.weights.push(w);
      g.offsets.push(dx, dy);
      total += w;
    }
    if (g.points.length === 0) return null;
    for (let i = 0; i < g.weights.length; i++) g.weights[i]! /= total;
    g.moveTo(x, y);
    return g;
  }

  /** Moves the hand to (x, y), m: each held point is pulled toward its place under it. */
  moveTo(x: number, y: number): void {
    this.hand[0] = x;
    this.hand[1] = y;
    const o = this.options;
    for (let i = 0; i < this.points.length; i++) {
      const h = this.points[i]!;
      if (!isAlive(this.world, h)) continue;
      const w = this.weights[i]!;
      pinClothPoint(this.world, h, [x + this.offsets[2 * i]!, y + this.offsets[2 * i + 1]!], {
        compliance: 1 / (w * o.stiffness),
        maxForce: w * o.maxForce,
      });
    }
  }

  /** Total force the grip pulled with in the last substep, N. */
  force(): number {
    const cl = this.world.cloth;
    let f = 0;
    for (let i = 0; i < cl.softPinCount; i++) f += cl.softPinForce[i]!;
    return f;
  }

  /** Where the held patch is, m: the weighted mean of the held points (the hand when none is left). */
  patch(out: [number, number]): [number, number] {
    const P = this.world.components.Position;
    let x = 0,
      y = 0,
      w = 0;
    for (let i = 0; i < this.points.length; i++) {
      const h = this.points[i]!;
      if (!isAlive(this.world, h)) continue;
      const e = slotOf(h);
      x += this.weights[i]! * P.x[e]!;
      y += this.weights[i]! * P.y[e]!;
      w += this.weights[i]!;
    }
    out[0] = w > 0 ? x / w : this.hand[0];
    out[1] = w > 0 ? y / w : this.hand[1];
    return out;
  }

  /** Lets go of the cloth. */
  release(): void {
    for (const h of this.points) if (isAlive(this.world, h)) pinClothPoint(this.world, h, null);
  }
}
