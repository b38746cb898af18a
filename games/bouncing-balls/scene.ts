/**
 * The bouncing-balls scene: a pure, seeded builder in the shape of the physics package's scenes
 * (world options + build), kept next to the game. No DOM, no pixi: it runs in Node too.
 *
 * A 16 m x 10 m box (10 m x 16 m with `tall`, for a screen held upright); three inclined static
 * segments (two ramps fixed to the side walls with free inner ends, and a floating bar with two
 * free ends); `count` balls of three densities on a jittered grid in the upper part of the box, kept
 * clear of the segments.
 */
import {
  addBody,
  addComponentIfMissing,
  addSegment,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  Rng,
  removeBody,
  setBoundary,
  setMaterial,
  slotOf,
} from '@bitphysics/physics';

/** Drag law applied to every ball. */
export type DragMode = 'none' | 'linear' | 'quadratic';

/** The drag modes, for menus. */
export const DRAG_MODES: readonly DragMode[] = ['none', 'linear', 'quadratic'];

/** Options of the scene. Every field optional. */
export interface BouncingBallsOptions {
  /** Number of balls, integer in [1, 10_000]. Default 40. */
  count?: number;
  /** Seed of the layout, sizes, densities and starting velocities. Default 1. */
  seed?: number;
  /** Magnitude of gravity, m/s^2, in [0, 100] (pointing down). Default 9.81. */
  gravity?: number;
  /** Restitution of balls, walls and segments, [0, 1]. Default 0.8. */
  restitution?: number;
  /** Friction coefficient of balls, walls and segments, >= 0. Default 0.2. */
  friction?: number;
  /** Drag law. Default 'none'. */
  drag?: DragMode;
  /** Drag coefficient: N s/m (= kg/s) for linear drag, kg/m for quadratic; >= 0. Default 0.05. */
  dragK?: number;
  /** Extra room for balls spawned later (clicks), integer in [0, 100_000]. Default 500. */
  spawnBudget?: number;
  /** The tall layout (BOX_TALL and SEGMENTS_TALL, for a screen taller than wide). Default false. */
  tall?: boolean;
}

/** Resolved options. */
export type BouncingBallsParams = Required<BouncingBallsOptions>;

/** Inner corners of the box, m. */
export const BOX = Object.freeze({ min: [0, 0] as const, max: [16, 10] as const });

/**
 * The inclined walls, m: [ax, ay, bx, by]. Each has at least one free end point balls can hit. Short
 * and kept to the top corners and the top, so they leave open lanes from the lower box to the hoops
 * (hoop.ts HOOP_SPOTS): a long ramp across the middle blocked every throw at some hoops. The ramps
 * from the side walls are 8.8 m or more over the floor, above every hoop's backboard, where the heap
 * cannot get under them: ramps low over the heap made pockets a ball rolled under and could not be
 * thrown from (its throw hit the ramp).
 */
export const SEGMENTS: readonly (readonly [number, number, number, number])[] = Object.freeze([
  [0, 9.3, 1.6, 8.8],
  [16, 9.3, 14.4, 8.8],
  [6.6, 8.4, 8.6, 8.8],
]);

/** The tall layout's box, m: as much room as BOX, turned upright. */
export const BOX_TALL = Object.freeze({ min: [0, 0] as const, max: [10, 16] as const });

/**
 * The tall layout's inclined walls, m: a ramp from each side wall and a floating bar, all short and
 * high in the box (10.8 m or more over the floor, above every hoop of HOOP_SPOTS_TALL): the narrow
 * court has no room beside a ramp, so one at the hoops' height stood across the way from the heap to
 * the hoop, and one low over the heap made a pocket balls rolled under and could not be thrown from.
 * Up there they are for trick shots off them.
 */
export const SEGMENTS_TALL: readonly (readonly [number, number, number, number])[] = Object.freeze([
  [0, 11.6, 3.2, 10.8],
  [10, 13.6, 7.4, 12.8],
  [3.6, 14.4, 5.4, 14.8],
]);

/** A box's inner corners, m. */
export interface BoxCorners {
  readonly min: readonly [number, number];
  readonly max: readonly [number, number];
}

/** The box and walls of a layout (`tall` or the default wide one). */
export function layoutOf(tall: boolean): { box: BoxCorners; segments: typeof SEGMENTS } {
  return tall ? { box: BOX_TALL, segments: SEGMENTS_TALL } : { box: BOX, segments: SEGMENTS };
}

/** Thickness radius of the segments, m. */
export const SEGMENT_RADIUS = 0.06;

/** Ball densities, kg/m^2 (2D): light, normal, heavy; and how often each is picked. */
export const DENSITIES = Object.freeze({ light: 0.5, normal: 1, heavy: 4 });

/** What `buildBouncingBalls` returns; the game keeps it to change materials and drag and to spawn. */
export interface BouncingBallsHandles {
  /** Entity ids of the balls, oldest first (spawned balls are appended; the oldest goes when the world is full). */
  balls: number[];
  /** Entity ids of the segments. */
  segments: number[];
  /** Mean ball radius, m; spawned balls use 0.6 to 1.4 times it. */
  meanRadius: number;
  /** The options used (kept up to date by `applyMaterial`, `applyDrag`, `applyGravity`). */
  params: BouncingBallsParams;
  /** Generator of spawned balls' sizes (seeded from the scene seed). */
  rng: Rng;
}

function check(cond: boolean, message: string): void {
  if (!cond) throw new RangeError(`bouncing-balls: ${message}`);
}

/**
 * Fills in defaults and checks the options.
 * @throws TypeError on an unknown option; RangeError naming the option and value when out of range.
 */
export function resolveOptions(options: BouncingBallsOptions = {}): BouncingBallsParams {
  const known = ['count', 'seed', 'gravity', 'restitution', 'friction', 'drag', 'dragK', 'spawnBudget', 'tall'];
  for (const k of Object.keys(options)) {
    if (!known.includes(k))
      throw new TypeError(`bouncing-balls: unknown option ${JSON.stringify(k)}; known options are ${known.join(', ')}`);
  }
  const p: BouncingBallsParams = {
    count: options.count ?? 40,
    seed: options.seed ?? 1,
    gravity: options.gravity ?? 9.81,
    restitution: options.restitution ?? 0.8,
    friction: options.friction ?? 0.2,
    drag: options.drag ?? 'none',
    dragK: options.dragK ?? 0.05,
    spawnBudget: options.spawnBudget ?? 500,
    tall: options.tall ?? false,
  };
  check(Number.isInteger(p.count) && p.count >= 1 && p.count <= 10_000, `count must be an integer in [1, 10000], got ${p.count}`);
  check(Number.isFinite(p.seed), `seed must be finite, got ${p.seed}`);
  check(p.gravity >= 0 && p.gravity <= 100, `gravity must be in [0, 100] m/s^2, got ${p.gravity}`);
  check(p.restitution >= 0 && p.restitution <= 1, `restitution must be in [0, 1], got ${p.restitution}`);
  check(p.friction >= 0 && Number.isFinite(p.friction), `friction must be >= 0, got ${p.friction}`);
  check(DRAG_MODES.includes(p.drag), `drag must be one of ${DRAG_MODES.join(', ')}, got ${JSON.stringify(p.drag)}`);
  check(p.dragK >= 0 && Number.isFinite(p.dragK), `dragK must be >= 0, got ${p.dragK}`);
  check(typeof p.tall === 'boolean', `tall must be a boolean, got ${JSON.stringify(p.tall)}`);
  check(
    Number.isInteger(p.spawnBudget) && p.spawnBudget >= 0 && p.spawnBudget <= 100_000,
    `spawnBudget must be an integer in [0, 100000], got ${p.spawnBudget}`,
  );
  return p;
}

/** World options for the scene: 2D, room for the balls, the segments and the spawn budget, gravity, seed. */
export function bouncingBallsWorldOptions(options: BouncingBallsOptions = {}): PhysicsWorldOptions {
  const p = resolveOptions(options);
  return { dimensions: 2, capacity: p.count + p.spawnBudget + SEGMENTS.length + 8, gravity: [0, -p.gravity], seed: p.seed };
}

/** Mean radius, m, for `count` balls: balls cover about a fifth of the box (either layout's: both are 160 m^2), clamped to [0.035, 0.42] m. */
export function meanRadiusFor(count: number): number {
  const area = (BOX.max[0] - BOX.min[0]) * (BOX.max[1] - BOX.min[1]);
  return Math.min(0.42, Math.max(0.035, Math.sqrt((0.2 * area) / (count * Math.PI))));
}

/** Distance from (px, py) to the segment (ax, ay)-(bx, by), m. Layout helper (keeps starting balls clear of walls). */
function distanceToSegment(px: number, py: number, ax: number, ay: number, bx: number, by: number): number {
  const ex = bx - ax,
    ey = by - ay;
  const t = Math.max(0, Math.min(1, ((px - ax) * ex + (py - ay) * ey) / (ex * ex + ey * ey)));
  const dx = px - ax - t * ex,
    dy = py - ay - t * ey;
  return Math.sqrt(dx * dx + dy * dy);
}

/**
 * Builds the scene into `world` (a fresh 2D world, ideally from `bouncingBallsWorldOptions`).
 * @throws TypeError | RangeError on bad options, a 3D world, or a count that does not fit the box.
 */
export function buildBouncingBalls(world: PhysicsWorld, options: BouncingBallsOptions = {}): BouncingBallsHandles {
  const p = resolveOptions(options);
  check(world.dimensions === 2, `needs a 2D world, got dimensions ${world.dimensions}`);
  const rng = new Rng(p.seed);
  const { box, segments: walls } = layoutOf(p.tall);
  setBoundary(world, { min: box.min, max: box.max, restitution: p.restitution, friction: p.friction });
  const segments: number[] = [];
  for (const [ax, ay, bx, by] of walls) {
    segments.push(
      addSegment(world, { a: [ax, ay], b: [bx, by], radius: SEGMENT_RADIUS, restitution: p.restitution, friction: p.friction }),
    );
  }
  const rMean = meanRadiusFor(p.count);
  // The solver keeps contacts within a speculative gap (default 0.1 m, sized for balls of about a
  // metre). For small balls that gap spans several neighbours and multiplies the contacts; keep it
  // at most one mean radius (Box2D scales its speculative distance with the length unit the same way).
  const settings = world.collision.settings;
  settings.speculativeDistance = Math.min(settings.speculativeDistance, rMean);
  const rMax = 1.4 * rMean;
  const pitch = 2 * rMax + Math.max(0.02, 0.3 * rMax);
  const x0 = box.min[0] + rMax + 0.05,
    x1 = box.max[0] - rMax - 0.05;
  const cols = Math.max(1, Math.floor((x1 - x0) / pitch) + 1);
  const jitter = 0.5 * (pitch - 2 * rMax);
  const handles: BouncingBallsHandles = { balls: [], segments, meanRadius: rMean, params: p, rng };
  const pos = [0, 0],
    vel = [0, 0];
  let y = box.max[1] - rMax - 0.05;
  while (handles.balls.length < p.count) {
    check(y >= box.min[1] + rMax, `${p.count} balls do not fit the box`);
    for (let c = 0; c < cols && handles.balls.length < p.count; c++) {
      const cx = x0 + c * pitch;
      let clear = true;
      for (const [ax, ay, bx, by] of walls) {
        if (distanceToSegment(cx, y, ax, ay, bx, by) < rMax + SEGMENT_RADIUS + jitter + 0.05) {
          clear = false;
          break;
        }
      }
      if (!clear) continue;
      pos[0] = cx + rng.range(-jitter, jitter);
      pos[1] = y + rng.range(-jitter, jitter);
      vel[0] = rng.range(-1.5, 1.5);
      vel[1] = rng.range(-1, 1);
      const radius = rMean * rng.range(0.6, 1.4);
      const u = rng.next();
      const density = u < 0.3 ? DENSITIES.light : u < 0.8 ? DENSITIES.normal : DENSITIES.heavy;
      handles.balls.push(addBallUnchecked(world, p, pos, vel, radius, density));
    }
    y -= pitch;
  }
  return handles;
}

function addBallUnchecked(
  world: PhysicsWorld,
  p: BouncingBallsParams,
  position: number[],
  velocity: number[],
  radius: number,
  density: number,
): number {
  return addBody(world, {
    position,
    velocity,
    radius,
    density,
    restitution: p.restitution,
    friction: p.friction,
    ...(p.drag === 'linear' ? { linearDrag: p.dragK } : {}),
    ...(p.drag === 'quadratic' ? { quadraticDrag: p.dragK } : {}),
  });
}

/** Whether a ball is heavy (density `DENSITIES.heavy`), from its mass and radius. */
export function isHeavy(world: PhysicsWorld, eid: number): boolean {
  const s = slotOf(eid);
  const r = world.components.Ball.radius[s]!;
  return world.components.Mass.value[s]! > 2 * Math.PI * r * r * DENSITIES.normal;
}

/**
 * Adds a ball at (x, y), m, with velocity (vx, vy), m/s, radius `radius` m (default: random around the
 * mean) and normal density, clamped inside the box. If the world is full, the oldest ball is removed first.
 * @returns the new entity id. @throws RangeError on non-finite input or radius <= 0.
 */
export function spawnBall(world: PhysicsWorld, h: BouncingBallsHandles, x: number, y: number, vx = 0, vy = 0, radius?: number): number {
  for (const [name, v] of [
    ['x', x],
    ['y', y],
    ['vx', vx],
    ['vy', vy],
  ] as const) {
    check(Number.isFinite(v), `spawnBall: ${name} must be finite, got ${v}`);
  }
  const r = radius ?? h.meanRadius * h.rng.range(0.6, 1.4);
  check(r > 0 && Number.isFinite(r), `spawnBall: radius must be > 0, got ${r}`);
  const { box } = layoutOf(h.params.tall);
  const cx = Math.min(box.max[0] - r, Math.max(box.min[0] + r, x));
  const cy = Math.min(box.max[1] - r, Math.max(box.min[1] + r, y));
  if (world.entityIndex.aliveCount >= world.capacity && h.balls.length > 0) removeBody(world, h.balls.shift()!);
  const eid = addBallUnchecked(world, h.params, [cx, cy], [vx, vy], r, DENSITIES.normal);
  h.balls.push(eid);
  return eid;
}

/**
 * Removes ball `eid` from the world and from `h.balls`.
 * @throws RangeError if `eid` is not one of the scene's balls.
 */
export function removeBall(world: PhysicsWorld, h: BouncingBallsHandles, eid: number): void {
  const i = h.balls.indexOf(eid);
  check(i >= 0, `removeBall: ${eid} is not a ball of this scene`);
  h.balls.splice(i, 1);
  removeBody(world, eid);
}

/** Sets restitution and friction of every ball, segment and the box. @throws RangeError on values out of range. */
export function applyMaterial(world: PhysicsWorld, h: BouncingBallsHandles, restitution: number, friction: number): void {
  check(restitution >= 0 && restitution <= 1, `restitution must be in [0, 1], got ${restitution}`);
  check(friction >= 0 && Number.isFinite(friction), `friction must be >= 0, got ${friction}`);
  h.params.restitution = restitution;
  h.params.friction = friction;
  const m = { restitution, friction };
  for (const e of h.balls) setMaterial(world, e, m);
  for (const e of h.segments) setMaterial(world, e, m);
  const { box } = layoutOf(h.params.tall);
  setBoundary(world, { min: box.min, max: box.max, restitution, friction });
}

/**
 * Switches every ball to drag law `mode` with coefficient `k` (N s/m linear, kg/m quadratic) through
 * the LinearDrag / QuadraticDrag components; the law not in use gets k = 0.
 * @throws RangeError on an unknown mode or k < 0.
 */
export function applyDrag(world: PhysicsWorld, h: BouncingBallsHandles, mode: DragMode, k: number): void {
  check(DRAG_MODES.includes(mode), `drag must be one of ${DRAG_MODES.join(', ')}, got ${JSON.stringify(mode)}`);
  check(k >= 0 && Number.isFinite(k), `dragK must be >= 0, got ${k}`);
  h.params.drag = mode;
  h.params.dragK = k;
  const c = world.components;
  for (const ball of h.balls) {
    const e = slotOf(ball);
    if (mode === 'linear') {
      addComponentIfMissing(world, e, c.LinearDrag);
      c.LinearDrag.k[e] = k;
    } else if (c.LinearDrag.k[e]) {
      c.LinearDrag.k[e] = 0;
    }
    if (mode === 'quadratic') {
      addComponentIfMissing(world, e, c.QuadraticDrag);
      c.QuadraticDrag.k[e] = k;
    } else if (c.QuadraticDrag.k[e]) {
      c.QuadraticDrag.k[e] = 0;
    }
  }
}

/**
 * Sets gravity to g m/s^2 downwards. Writes `world.gravity` directly: the physics package documents
 * a `setGravity` but does not export one yet.
 * @throws RangeError unless g is in [0, 100].
 */
export function applyGravity(world: PhysicsWorld, h: BouncingBallsHandles, g: number): void {
  check(g >= 0 && g <= 100, `gravity must be in [0, 100] m/s^2, got ${g}`);
  h.params.gravity = g;
  world.gravity[0] = 0;
  world.gravity[1] = -g;
}
