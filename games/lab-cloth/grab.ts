/**
 * The player's hand on the cloth, headless: a soft grip of the patch under the pointer.
 *
 * Pressing on the cloth takes hold of the points within a hand's radius of the press, each by a soft
 * pin (pinClothPoint with options: a spring solved in the cloth solver's small steps, its force
 * capped) toward its place under the pointer, the nearest points holding hardest. The pull spreads
 * over the patch and from it into the sheet, which stretches, swings and lags behind the hand.
 *
 * The grip's pull is capped by how far the hand has gone from the patch it holds (ClothGrab.update):
 * up to a firm pull (enough to lift and swing the sheet, well under what tears it) the patch keeps to
 * the hand; past it the pull grows slowly with the hand's lead, as a rubber cord, so a gentle pull
 * stretches and moves the sheet, and only a deliberate hard pull, the hand led a metre or more past the
 * cloth, pulls hard enough to tear it. Each tear lets the cord go half slack, so a rip runs as far as
 * the hand pulls it and stops when the hand stops, rather than running on across the sheet.
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
  /** The firm pull, N, in (0, maxForce]: the grip pulls up to this much with the patch at the hand. */
  firm: number;
  /** How fast the pull grows past `firm` with the hand's lead on the patch, N/m, >= 0. */
  slope: number;
  /**
   * How fast a held pull hardens, N/s per m of the hand's lead past `holdLead`, >= 0: the grip pulls
   * harder the longer the hand is held well past the cloth (ClothGrab.update with a time step).
   */
  hold: number;
  /** The hand's lead on the patch, m, >= 0, past which a held pull hardens. */
  holdLead: number;
  /**
   * The share of the pull past the firm pull that a tear lets go, in [0, 1]: 1 goes slack to the firm
   * pull at each tear, 0 keeps pulling as hard (ClothGrab.update).
   */
  give: number;
}

/**
 * The lab's grip: a 0.4 m hand, 300 N/m, a firm pull of 15 N growing by 20 N a metre of the hand's lead
 * past it, at most 80 N (the sheet weighs about 10 N; a grip pulling 20-55 N tears it at the default
 * tear strain, least near the pegs, most near the hem). Stiff enough that the held patch keeps within
 * a few centimetres of the hand while the sheet follows, so a short pull (0.4 m down from the lower
 * middle) stretches the links by the hand to about 20% and tears nothing; pulled down from the middle of
 * the sheet, it tears once the hand is about 1.1 m from where it took hold (0.57 m with a grip of a
 * fixed 80 N cap), and the hand keeps the torn piece (test/games/lab-cloth.test.ts). Held there, the
 * pull hardens by 30 N a second for each metre the hand leads the patch past 0.5 m, so a hand held well
 * past the sheet tears it within seconds even where the sheet's give leaves the pull just short of
 * tearing (a 1 m pull from the middle, held: without it the links by the hand level off at 43.4% and
 * never tear; with it the sheet tears 1.9 s in), while a gentle pull (0.8 m: the patch within 0.45 m
 * of the hand) never hardens. Each tear lets go half the pull past the firm pull (give 0.5): a 2 m pull
 * from the middle, held 1 s, tears 5 links under the hem and the sheet stays on the line; kept at full
 * pull the rip ran across under the hem and 578 of the 768 points fell (scripts/lab-cloth-pulls.mjs:
 * 4-11 links torn by 2-3 m pulls from four places, at most 2 points off).
 */
export const GRAB: GrabOptions = { radius: 0.4, stiffness: 300, maxForce: 80, firm: 15, slope: 20, hold: 30, holdLead: 0.5, give: 0.5 };

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
 * weights w_i = (1 - d_i / radius)^2, normalised to sum 1, favour the points nearest the press. The
 * grip's total pull is capped at F(L) = min(maxForce, firm + slope max(0, L - G - firm / stiffness) + H),
 * L the hand's distance from the patch, G the lead the cloth has given by tearing (`given`) and H the
 * held pull's hardening (update).
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
  /** How much the held pull has hardened, N (the cap's H: grows by hold (L - G - holdLead) a second while positive). */
  hardened = 0;
  /**
   * The lead the cloth has given, m (the cap's G): the hand's lead on the patch when the cloth last tore
   * under the grip, brought down as the lead falls below it. A tear lets the pull go slack (update).
   */
  given = 0;

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

  /** Moves the hand to (x, y), m: each held point is pulled toward its place under it (update). */
  moveTo(x: number, y: number): void {
    this.hand[0] = x;
    this.hand[1] = y;
    this.update();
  }

  /** The grip's largest total pull now, N: F(L) (see the class) for the hand's lead L on the patch. */
  cap(): number {
    const o = this.options;
    const lead = Math.max(0, this.lead() - this.given);
    return Math.min(o.maxForce, o.firm + o.slope * Math.max(0, lead - o.firm / o.stiffness) + this.hardened);
  }

  /** The hand's distance from the patch it holds now, m. */
  lead(): number {
    const [px, py] = this.patch(this.at);
    return Math.hypot(this.hand[0] - px, this.hand[1] - py);
  }

  /**
   * Pulls each held point toward its place under the hand with its share of the cap (cap). Call before
   * every step with the step's `dt`, s (>= 0; 0, as moveTo does, leaves the hardening and the give as
   * they are): the cap follows the patch as the sheet gives, a pull held past holdLead hardens, and a
   * tear in the last step (the world's joint breaks) lets go the share `give` of the pull past the firm pull.
   */
  update(dt = 0): void {
    const o = this.options;
    const lead = this.lead();
    this.given = Math.min(this.given, lead);
    if (dt > 0) {
      if (this.world.joints.breaks.count > 0) {
        // The cloth tore in the last step: the pull past the firm pull goes part slack, and grows again
        // only as the hand leads on past where it tore. Kept at full pull, the rip ran on across the
        // sheet (a 2 m pull took 578 of its 768 points off the line); eased, it runs as far as the hand pulls.
        this.given += o.give * (lead - this.given);
        this.hardened *= 1 - o.give;
      }
      const past = lead - this.given - o.holdLead;
      // Hardens while held far past where the cloth last gave.
      this.hardened = Math.max(0, Math.min(o.maxForce, this.hardened + o.hold * Math.max(0, past) * dt));
    }
    const [x, y] = this.hand,
      cap = this.cap();
    for (let i = 0; i < this.points.length; i++) {
      const h = this.points[i]!;
      if (!isAlive(this.world, h)) continue;
      const w = this.weights[i]!;
      this.target[0] = x + this.offsets[2 * i]!;
      this.target[1] = y + this.offsets[2 * i + 1]!;
      this.pin.compliance = 1 / (w * o.stiffness);
      this.pin.maxForce = w * cap;
      pinClothPoint(this.world, h, this.target, this.pin);
    }
  }
  /** Scratch: the patch's place and a held point's target, m. */
  private readonly at: [number, number] = [0, 0];
  private readonly target: [number, number] = [0, 0];
  /** Scratch: a held point's pin options. */
  private readonly pin = { compliance: 0, maxForce: 1 };

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
