/**
 * The cloth lab's scene, headless: the sheet (createCloth pinned along its top edge, in wind) and the
 * player's grab. A pure builder (no DOM, no Pixi), shared by the page and its tests.
 *
 * The grab is soft: pressing on the cloth takes hold of the points within a hand's radius of the press,
 * each by a soft pin (pinClothPoint with options: a spring solved in the cloth solver's small steps, its
 * force capped) toward its place under the pointer, the nearest points holding hardest. The pull spreads
 * over the patch and from it into the sheet, which stretches, swings and lags behind the hand; links
 * tear only where a pull far past where the cloth can follow, or a fast yank, strains them past the tear
 * strain. A hard pin on the one point under the pointer (pinClothPoint without options) puts all the
 * strain in the few links at that point: the slow 0.5 m pulls measured for GRAB tear 1 to 21 links
 * with it (every one of 40 pulls tears some).
 */
import {
  type Cloth,
  createCloth,
  createPhysicsWorld,
  isAlive,
  type PhysicsWorld,
  pinClothPoint,
  setBoundary,
  setWind,
  slotOf,
} from '@bitphysics/physics';

/** Side of the square sheet, m. */
export const SIDE = 4;
/** Total mass of the sheet, kg. */
export const CLOTH_MASS = 0.6;
/**
 * The room the sheet hangs in, m: floor, walls and ceiling of the world's boundary box, which keeps the
 * cloth's points inside (a torn piece lands on the floor and the wind piles it against the right wall).
 * The floor is 1.3 m below the hem, which the default wind and the sheet's own stretch keep above it.
 */
export const ROOM = Object.freeze({ minX: -1, minY: -1.3, maxX: SIDE + 3, maxY: SIDE + 10 });

/**
 * The lab's cloth solver substeps a step. The links are inextensible (compliance 0), so a link's strain
 * is the small steps' leftover error, which falls as the substeps rise: at 24 the default 7 m/s wind
 * stretches the sheet's upwind top corner 9% (12: 24%, 16: 15%, 32: 6%), at about the same step time
 * as 12 (1.26 ms against 1.20 ms for 32 points a side, measured headless).
 */
export const CLOTH_SUBSTEPS = 24;

/** The lab's settings that shape its world. */
export interface ClothSceneParams {
  /** Points a side, integer in [4, 64]. */
  size: number;
  /** Wind speed to the right, m/s, >= 0. */
  wind: number;
  /** Turbulence of the wind, m/s RMS, >= 0. */
  turbulence: number;
  /** Strain past which structural and shear links tear, > 0. */
  tear: number;
  /** Cloth solver substeps a step, integer >= 1. */
  substeps: number;
}

/** Sets the world's wind from the lab's settings (a steady wind with seeded turbulence). */
export function applyWind(world: PhysicsWorld, p: Pick<ClothSceneParams, 'wind' | 'turbulence'>): void {
  setWind(world, { velocity: [p.wind, 0], turbulence: { intensity: p.turbulence, lengthScale: 1.5, timeScale: 0.8, seed: 3 } });
}

/** Builds the lab's world: a SIDE x SIDE sheet of `size` x `size` points pinned along its top edge at y = SIDE, in the ROOM box. */
export function createClothScene(p: ClothSceneParams): { world: PhysicsWorld; cloth: Cloth } {
  const n = p.size;
  const world = createPhysicsWorld({ gravity: [0, -9.81], capacity: 7 * n * n + 64 });
  const cloth = createCloth(world, {
    columns: n,
    rows: n,
    width: SIDE,
    height: SIDE,
    origin: [0, SIDE],
    mass: CLOTH_MASS,
    tearStretch: p.tear,
    // Air drag a point, N s/m, by its share of the sheet (20 N s/m over it): the default 7 m/s wind
    // sways the hem about 0.7 m sideways in 3 s, and a 10 m/s gale tears the sheet from its pins.
    drag: 20 / (n * n),
  });
  world.cloth.substeps = p.substeps;
  setBoundary(world, { min: [ROOM.minX, ROOM.minY], max: [ROOM.maxX, ROOM.maxY], friction: 0.8 });
  applyWind(world, p);
  return { world, cloth };
}

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
 * The lab's grip at 32 points a side: a 0.35 m hand, 400 N/m, at most 800 N. Measured headless at
 * CLOTH_SUBSTEPS and tear strain 0.2 (grabs at four places, 2 s after the start, in the default 7 m/s
 * wind and in still air): a 0.5 m pull over 1 s in any of five directions tears no link (40 of 40
 * pulls), the most stretched link reaches 5-18% and the held point follows the hand 0.09-0.32 m; a 2 m
 * yank in 0.12 s tears 105-569 links.
 */
export const GRAB: GrabOptions = { radius: 0.35, stiffness: 400, maxForce: 800 };

/**
 * The lab's grip for a sheet of `size` points a side: GRAB with its stiffness and force scaled by
 * (31 / (size - 1))^2 and its radius at least 1.5 link spacings. The solver's sheet is stiffer the
 * coarser it is (a link's strain is the small steps' leftover error, which grows with the links in a
 * chain). Measured at CLOTH_SUBSTEPS and tear strain 0.2, pulling the middle point: a slow 0.5 m pull
 * tears nothing and stretches the sheet 8-16% at 8 and 16 points a side (in the default wind and in
 * still air) and at 48 and 64 in still air, and a 2 m yank in 0.15 s tears 46-80 links at 8 and 16 and
 * 484-800 at 48 and 64. In the default wind a 48-point sheet already stretches 17% and a slow pull
 * tears a few links; a 64-point sheet stretches past the tear strain by itself (lower the wind).
 */
export function gripFor(size: number): GrabOptions {
  const s = (31 / (size - 1)) ** 2;
  return {
    radius: Math.max(GRAB.radius, (1.5 * SIDE) / (size - 1)),
    stiffness: GRAB.stiffness * s,
    maxForce: GRAB.maxForce * s,
  };
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
      const w = this.weights[i]!;
      pinClothPoint(this.world, this.points[i]!, [x + this.offsets[2 * i]!, y + this.offsets[2 * i + 1]!], {
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

  /** Lets go of the cloth. */
  release(): void {
    for (const h of this.points) if (isAlive(this.world, h)) pinClothPoint(this.world, h, null);
  }
}
