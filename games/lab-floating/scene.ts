/**
 * The floating lab's scene (Ramtal and Dobre ch. 7, "upthrust"): a tank of water with balls of
 * different densities and a box, dropped from above the surface. A pure, deterministic builder (no
 * DOM, no pixi): the page, the tests and Node scripts share it.
 *
 * Physics, composed from the physics package: every body has `Buoyancy` (Archimedes' upthrust from
 * the submerged area, and fluid drag scaled by the submerged fraction) and there is one `FluidRegion`
 * (the water). Balls collide with the tank and each other (ball colliders). The box has no collider
 * (the physics package collides balls, segments and planes only), so it lives in a compartment of its
 * own behind a divider wall and a floor rule keeps it in the tank (see `boxFloorSystem`).
 *
 * 2D world: a disc is a cylinder 1 m deep seen end on, so areal densities (kg/m^2) read as kg/m^3 of
 * that 1 m slab, and the submerged measure is the area of a circular segment (not a spherical cap).
 *
 * The only formulas here that are not the physics package's are the exact equilibrium depths the lab
 * compares against (`equilibriumDepth`, `circularSegmentArea`).
 */
import {
  addBody,
  addFluidRegion,
  addSegment,
  addSystem,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  removeBody,
  setBoundary,
  setBuoyancy,
  setMass,
} from '@bitphysics/physics';

/** Inner corners of the tank, m. */
export const TANK = Object.freeze({ minX: 0, minY: 0, maxX: 14, maxY: 9 });
/** Height of the water surface, m. */
export const SURFACE = 4.6;
/** The divider between the box compartment (left) and the balls (right): x, m, and its top, m. */
export const DIVIDER = Object.freeze({ x: 3.2, top: 7.2, radius: 0.06 });
/** Radius of the three starting balls, m. */
export const BALL_RADIUS = 0.55;
/** Half extents of the box, m (1.6 m wide, 0.9 m tall). */
export const BOX_HALF = Object.freeze([0.8, 0.45] as const);
/** Height the bodies are dropped from (their centres), m. */
export const DROP_HEIGHT = 7.6;

/** Kinds of body in the tank, for the panel's "tracked body" menu. */
export type BodyKind = 'light' | 'medium' | 'heavy' | 'box';
/** The tracked-body choices, in menu order. */
export const BODY_KINDS: readonly BodyKind[] = ['light', 'medium', 'heavy', 'box'];

/** Options of the scene; every field optional. Densities are areal, kg/m^2 (see the file comment). */
export interface FloatingOptions {
  /** Density of the light ball, kg/m^2, in [10, 20000]. Default 250 (cork-like). */
  light?: number;
  /** Density of the medium ball, kg/m^2, in [10, 20000]. Default 650 (pine-like). */
  medium?: number;
  /** Density of the heavy ball, kg/m^2, in [10, 20000]. Default 920 (ice-like). */
  heavy?: number;
  /** Density of the box, kg/m^2, in [10, 20000]. Default 500. */
  box?: number;
  /** Density of the fluid, kg/m^2, in [10, 20000]. Default 1000 (water). */
  fluid?: number;
  /** Quadratic drag coefficient of the fluid on a fully submerged body, kg/m, in [0, 5000]. Default 600. */
  drag?: number;
  /** Room for balls dropped later (clicks), integer in [0, 1000]. Default 60. */
  spawnBudget?: number;
}

/** Resolved options. */
export type FloatingParams = Required<FloatingOptions>;

/** What `buildFloating` returns; the page keeps it to change densities and to drop balls. */
export interface FloatingHandles {
  /** The three starting balls by kind. */
  light: number;
  medium: number;
  heavy: number;
  /** The box (no collider). */
  box: number;
  /** The water (a FluidRegion entity). */
  fluid: number;
  /** Every ball, oldest first (starting balls, then dropped ones; the oldest dropped ball goes when full). */
  balls: number[];
  /** Balls dropped by clicks, oldest first. */
  dropped: number[];
  /** The options in force (kept up to date by the setters below). */
  params: FloatingParams;
}

const KNOWN = ['light', 'medium', 'heavy', 'box', 'fluid', 'drag', 'spawnBudget'] as const;

function fail(message: string): never {
  throw new RangeError(`lab-floating: ${message}`);
}

function checkDensity(name: string, value: number): void {
  if (!(typeof value === 'number' && value >= 10 && value <= 20000)) fail(`${name} density must be in [10, 20000] kg/m^2, got ${value}`);
}

function checkDrag(value: number): void {
  if (!(typeof value === 'number' && value >= 0 && value <= 5000)) fail(`drag must be in [0, 5000] kg/m, got ${value}`);
}

/**
 * Fills in defaults and checks the options.
 * @throws TypeError on an unknown option; RangeError naming the option and value when out of range.
 */
export function resolveFloatingOptions(options: FloatingOptions = {}): FloatingParams {
  for (const k of Object.keys(options)) {
    if (!(KNOWN as readonly string[]).includes(k))
      throw new TypeError(`lab-floating: unknown option ${JSON.stringify(k)}; known: ${KNOWN.join(', ')}`);
  }
  const p: FloatingParams = {
    light: options.light ?? 250,
    medium: options.medium ?? 650,
    heavy: options.heavy ?? 920,
    box: options.box ?? 500,
    fluid: options.fluid ?? 1000,
    drag: options.drag ?? 600,
    spawnBudget: options.spawnBudget ?? 60,
  };
  for (const k of ['light', 'medium', 'heavy', 'box', 'fluid'] as const) checkDensity(k, p[k]);
  checkDrag(p.drag);
  if (!(Number.isInteger(p.spawnBudget) && p.spawnBudget >= 0 && p.spawnBudget <= 1000))
    fail(`spawnBudget must be an integer in [0, 1000], got ${p.spawnBudget}`);
  return p;
}

/** World options for the scene: 2D, standard gravity, room for the bodies and the dropped balls. */
export function floatingWorldOptions(options: FloatingOptions = {}): PhysicsWorldOptions {
  const p = resolveFloatingOptions(options);
  return { dimensions: 2, capacity: 16 + p.spawnBudget, gravity: [0, -9.81], restitutionThreshold: 0.5 };
}

/** Area of a disc, m^2. */
function discArea(r: number): number {
  return Math.PI * r * r;
}

/**
 * The floor rule of the box: the box has no collider, so after each (sub)step's collide stage it is
 * kept above the tank floor (a resting contact: position clamped, downward velocity removed). Runs in
 * the `constraints` stage. Reads the box id from the handles, so it follows the scene.
 */
function boxFloorSystem(h: FloatingHandles) {
  return (world: PhysicsWorld): void => {
    const e = h.box;
    const P = world.components.Position,
      V = world.components.Velocity;
    const floor = TANK.minY + BOX_HALF[1];
    if (P.y[e]! < floor) {
      P.y[e] = floor;
      if (V.y[e]! < 0) V.y[e] = 0;
    }
  };
}

/**
 * Builds the tank into `world` (a fresh 2D world, ideally from `floatingWorldOptions`): walls, the
 * divider, the water, the three balls (light, medium, heavy) and the box, all at `DROP_HEIGHT`.
 * @throws TypeError | RangeError on bad options or a 3D world.
 */
export function buildFloating(world: PhysicsWorld, options: FloatingOptions = {}): FloatingHandles {
  const p = resolveFloatingOptions(options);
  if (world.dimensions !== 2) fail(`needs a 2D world, got dimensions ${world.dimensions}`);
  setBoundary(world, { min: [TANK.minX, TANK.minY], max: [TANK.maxX, TANK.maxY], restitution: 0.1, friction: 0.3 });
  addSegment(world, { a: [DIVIDER.x, TANK.minY], b: [DIVIDER.x, DIVIDER.top], radius: DIVIDER.radius, restitution: 0.1, friction: 0.3 });
  const fluid = addFluidRegion(world, { surface: SURFACE, density: p.fluid, xRange: [TANK.minX, TANK.maxX] });
  const ball = (x: number, density: number): number => {
    const e = addBody(world, { position: [x, DROP_HEIGHT], radius: BALL_RADIUS, density, restitution: 0.1, friction: 0.3 });
    setBuoyancy(world, e, { shape: 'ball', radius: BALL_RADIUS, dragCoefficient: p.drag });
    return e;
  };
  const light = ball(5.4, p.light);
  const medium = ball(8.3, p.medium);
  const heavy = ball(11.2, p.heavy);
  const box = addBody(world, { position: [(TANK.minX + DIVIDER.x) / 2, DROP_HEIGHT], mass: p.box * 4 * BOX_HALF[0] * BOX_HALF[1] });
  setBuoyancy(world, box, { shape: 'box', halfExtents: BOX_HALF, dragCoefficient: p.drag });
  const handles: FloatingHandles = { light, medium, heavy, box, fluid, balls: [light, medium, heavy], dropped: [], params: p };
  addSystem(world, 'constraints', boxFloorSystem(handles));
  return handles;
}

/** The entity of body `kind`. */
export function bodyOf(h: FloatingHandles, kind: BodyKind): number {
  return h[kind];
}

/**
 * Sets the density of body `kind` (kg/m^2, in [10, 20000]): its mass becomes density x area.
 * @throws RangeError on a density out of range.
 */
export function setBodyDensity(world: PhysicsWorld, h: FloatingHandles, kind: BodyKind, density: number): void {
  checkDensity(kind, density);
  h.params[kind] = density;
  const area = kind === 'box' ? 4 * BOX_HALF[0] * BOX_HALF[1] : discArea(BALL_RADIUS);
  setMass(world, h[kind], density * area);
}

/** Sets the fluid's density, kg/m^2 in [10, 20000], on its FluidRegion. @throws RangeError out of range. */
export function setFluidDensity(world: PhysicsWorld, h: FloatingHandles, density: number): void {
  checkDensity('fluid', density);
  h.params.fluid = density;
  world.components.FluidRegion.density[h.fluid] = density;
}

/** Sets the fluid drag coefficient of every body, kg/m in [0, 5000]. @throws RangeError out of range. */
export function setFluidDrag(world: PhysicsWorld, h: FloatingHandles, k: number): void {
  checkDrag(k);
  h.params.drag = k;
  const B = world.components.Buoyancy;
  for (const e of h.balls) B.dragCoefficient[e] = k;
  B.dragCoefficient[h.box] = k;
}

/**
 * Drops a ball of `radius` m (in [0.15, 1]) and `density` kg/m^2 at (x, y) m, kept inside the ball
 * compartment; when the world is full the oldest dropped ball is removed first.
 * @returns the new entity. @throws RangeError on non-finite coordinates, or a radius or density out of range.
 */
export function dropBall(world: PhysicsWorld, h: FloatingHandles, x: number, y: number, density: number, radius: number): number {
  if (!Number.isFinite(x) || !Number.isFinite(y)) fail(`dropBall: x and y must be finite, got ${x}, ${y}`);
  checkDensity('ball', density);
  if (!(radius >= 0.15 && radius <= 1)) fail(`dropBall: radius must be in [0.15, 1] m, got ${radius}`);
  const cx = Math.min(TANK.maxX - radius, Math.max(DIVIDER.x + DIVIDER.radius + radius, x));
  const cy = Math.min(TANK.maxY - radius, Math.max(TANK.minY + radius, y));
  if (world.entityIndex.aliveCount >= world.capacity && h.dropped.length > 0) {
    const old = h.dropped.shift()!;
    h.balls.splice(h.balls.indexOf(old), 1);
    removeBody(world, old);
  }
  const e = addBody(world, { position: [cx, cy], radius, density, restitution: 0.1, friction: 0.3 });
  setBuoyancy(world, e, { shape: 'ball', radius, dragCoefficient: h.params.drag });
  h.balls.push(e);
  h.dropped.push(e);
  return e;
}

/**
 * Immersion depth (draft) of body `eid`, m: how far its lowest point lies below the surface (0 when
 * it is above the water, up to its height when fully under; deeper than that when sunk).
 */
export function immersionDepth(world: PhysicsWorld, h: FloatingHandles, eid: number): number {
  const extent = eid === h.box ? BOX_HALF[1] : world.components.Ball.radius[eid]!;
  return SURFACE - (world.components.Position.y[eid]! - extent);
}

/**
 * Area of the circular segment of height `depth` cut from a disc of radius r, m^2:
 * A = r^2 acos((r - d) / r) - (r - d) sqrt(2 r d - d^2), for d in [0, 2r] (clamped).
 * Source: CRC Standard Mathematical Tables, "circular segment".
 */
export function circularSegmentArea(r: number, depth: number): number {
  const d = Math.min(2 * r, Math.max(0, depth));
  const a = r - d;
  return r * r * Math.acos(a / r) - a * Math.sqrt(Math.max(0, 2 * r * d - d * d));
}

/**
 * Exact equilibrium draft, m, where upthrust equals weight (Archimedes: rho_f A_sub g = rho_b A g):
 * for a disc of radius `size` the depth d with circularSegmentArea(r, d) = (rho_b / rho_f) pi r^2,
 * found by bisection (the area grows monotonically with d) to 1e-12 m; for a box of half height `size`,
 * d = (rho_b / rho_f) 2 halfY. NaN when the body is at least as dense as the fluid (it sinks).
 * Source: Ramtal and Dobre ch. 7 (upthrust); Archimedes' principle.
 */
export function equilibriumDepth(shape: 'ball' | 'box', size: number, bodyDensity: number, fluidDensity: number): number {
  const ratio = bodyDensity / fluidDensity;
  if (!(ratio < 1) || !(ratio > 0)) return Number.NaN;
  if (shape === 'box') return ratio * 2 * size;
  const target = ratio * discArea(size);
  let lo = 0,
    hi = 2 * size;
  for (let i = 0; i < 80 && hi - lo > 1e-12; i++) {
    const mid = 0.5 * (lo + hi);
    if (circularSegmentArea(size, mid) < target) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

/** Exact equilibrium draft of body `kind` of the scene with the densities in force, m (NaN if it sinks). */
export function equilibriumOf(h: FloatingHandles, kind: BodyKind): number {
  const p = h.params;
  return kind === 'box' ? equilibriumDepth('box', BOX_HALF[1], p.box, p.fluid) : equilibriumDepth('ball', BALL_RADIUS, p[kind], p.fluid);
}
