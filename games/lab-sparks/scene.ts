/**
 * The sparks scene, DOM-free (Ramtal and Dobre ch. 12, "sparks"). SI units, y up, g = 9.81 m/s^2.
 *
 * A tool (an angle grinder, or a welding torch) is an emitter throwing hot metal sparks in a cone:
 * narrow and fast for the grinder (the sparks leave the wheel's rim tangentially), wide and slower for
 * welding spatter. Each spark is a particle of mass m = 0.1 g with:
 * - quadratic air drag F = -k |v| v (k in kg/m), so a spark slows quickly while fast and its terminal
 *   fall speed is sqrt(m g / k) (15.7 m/s at the default k = 4e-6 kg/m);
 * - a collider of radius 1 cm, so it bounces off the floor and the back wall (static segments) with
 *   their restitution (pairs use the larger of the two, the spark's own being 0) and slides on with
 *   their friction; contacts slower than the world's restitution threshold (0.5 m/s) do not bounce;
 * - a look over life: white-yellow to orange, shrinking and fading out as it cools.
 * Sparks start spread over a disc of 6 cm about the tool rather than at one point: they have colliders,
 * and the physics has no collision filter, so sparks born on top of each other would be pushed apart
 * and collide inelastically, clumping the cone.
 * Bounces are counted from the last step's contacts: a contact with the floor or the wall whose
 * impact speed exceeds 1 m/s and that pushed.
 */
import {
  addEmitter,
  addSegment,
  ContactKind,
  createPhysicsWorld,
  type PhysicsWorld,
  removeBody,
  setEmitterEnabled,
  setEmitterRate,
  setMaterial,
  setPosition,
  slotOf,
  step,
} from '@bitphysics/physics';

/** Mass of a spark, kg (0.1 g). */
export const SPARK_MASS = 1e-4;
/** Collider radius of a spark, m. */
export const SPARK_RADIUS = 0.01;
/** Most sparks per second. */
export const MAX_RATE = 1500;
/** Where the back wall stands, m, and how long the floor runs. */
export const WALL_X = -7,
  FLOOR_END = 14;

/** The two tools. */
export type SparkTool = 'grinder' | 'welding';

/** Settings of the sparks. */
export interface SparksSettings {
  /** Which tool. Default 'grinder'. */
  tool: SparkTool;
  /** Sparks per second, [0, MAX_RATE]. Default 400. */
  rate: number;
  /** Direction of the cone, degrees counter-clockwise from +x. Default 340 (right, a little down). */
  angle: number;
  /** Half-angle of the cone, degrees, [0, 180]. Default 7. */
  spread: number;
  /** Fastest launch speed, m/s, [1, 40]; the slowest is half of it. Default 14. */
  speed: number;
  /** Quadratic drag coefficient of a spark, kg/m, [0, 1e-4]. Default 4e-6. */
  drag: number;
  /** Restitution of the floor and wall, [0, 1]. Default 0.45. */
  restitution: number;
  /** Seed. Default 1. */
  seed: number;
}

/** Defaults of each tool (the fields a tool changes). */
export const TOOL_PRESETS: Readonly<Record<SparkTool, Pick<SparksSettings, 'rate' | 'angle' | 'spread' | 'speed'>>> = Object.freeze({
  grinder: { rate: 400, angle: 340, spread: 7, speed: 14 },
  welding: { rate: 300, angle: 90, spread: 80, speed: 6 },
});

/** Lifetime range of a spark for each tool, s. */
const LIFETIMES: Record<SparkTool, [number, number]> = { grinder: [0.6, 1.4], welding: [0.4, 1.1] };

/** The running sparks. */
export interface Sparks {
  readonly world: PhysicsWorld;
  /** The tool's emitter (rebuilt when its cone changes). */
  emitter: number;
  /** The floor and back wall segments. */
  readonly floor: number;
  readonly wall: number;
  /** Where the tool is, m. */
  readonly at: [number, number];
  readonly settings: SparksSettings;
  /** Bounces off the floor or wall since the start (impact speed > 1 m/s). */
  bounces: number;
  /** Whether the tool is throwing sparks. */
  on: boolean;
}

function check(where: string, name: string, v: number, min: number, max: number): void {
  if (typeof v !== 'number' || !(v >= min && v <= max))
    throw new RangeError(`${where}: ${name} must be in [${min}, ${max}], got ${String(v)}`);
}

function checkAll(where: string, s: SparksSettings): void {
  if (s.tool !== 'grinder' && s.tool !== 'welding')
    throw new RangeError(`${where}: tool must be 'grinder' or 'welding', got ${String(s.tool)}`);
  check(where, 'rate', s.rate, 0, MAX_RATE);
  check(where, 'angle', s.angle, -360, 360);
  check(where, 'spread', s.spread, 0, 180);
  check(where, 'speed', s.speed, 1, 40);
  check(where, 'drag', s.drag, 0, 1e-4);
  check(where, 'restitution', s.restitution, 0, 1);
}

/** Builds the floor, the back wall and the tool. @throws RangeError on a setting out of range. */
export function createSparks(options: Partial<SparksSettings> = {}): Sparks {
  const tool = options.tool ?? 'grinder';
  const settings: SparksSettings = { tool, ...TOOL_PRESETS[tool], drag: 4e-6, restitution: 0.45, seed: 1, ...options };
  checkAll('createSparks', settings);
  const capacity = Math.ceil(MAX_RATE * 1.4) + 16;
  const world = createPhysicsWorld({ dimensions: 2, capacity, gravity: [0, -9.81], seed: settings.seed });
  const floor = addSegment(world, { a: [WALL_X, 0], b: [FLOOR_END, 0], restitution: settings.restitution, friction: 0.3 });
  const wall = addSegment(world, { a: [WALL_X, 0], b: [WALL_X, 8], restitution: settings.restitution, friction: 0.3 });
  const sparks: Sparks = { world, emitter: 0, floor, wall, at: [-3, 1.6], settings, bounces: 0, on: true };
  sparks.emitter = makeEmitter(sparks);
  return sparks;
}

function makeEmitter(s: Sparks): number {
  const o = s.settings;
  const a = (o.angle * Math.PI) / 180;
  return addEmitter(s.world, {
    position: s.at,
    rate: o.rate,
    shape: 'disc',
    size: 0.06,
    direction: [Math.cos(a), Math.sin(a)],
    spread: (o.spread * Math.PI) / 180,
    speed: [o.speed * 0.5, o.speed],
    lifetime: LIFETIMES[o.tool],
    policy: 'recycle-oldest',
    enabled: s.on,
    particle: {
      mass: SPARK_MASS,
      quadraticDrag: o.drag,
      radius: SPARK_RADIUS,
      colorStart: 0xfffbe0,
      colorEnd: 0xff4a00,
      sizeStart: 0.07,
      sizeEnd: 0.025,
      alphaStart: 1,
      alphaEnd: 0,
    },
  });
}

/**
 * Changes settings; anything but the rate and the restitution changes the emitter's cone or its
 * sparks, and an emitter's options are fixed when it is made, so the emitter is replaced (same place;
 * sparks already flying keep theirs). Choosing a tool also applies its preset rate, angle, spread
 * and speed unless those are given too. @throws RangeError on a value out of range.
 */
export function configureSparks(s: Sparks, changes: Partial<Omit<SparksSettings, 'seed'>>): void {
  const next: SparksSettings = {
    ...s.settings,
    ...(changes.tool && changes.tool !== s.settings.tool ? TOOL_PRESETS[changes.tool] : {}),
    ...changes,
  };
  checkAll('configureSparks', next);
  const rebuild =
    next.tool !== s.settings.tool ||
    next.angle !== s.settings.angle ||
    next.spread !== s.settings.spread ||
    next.speed !== s.settings.speed ||
    next.drag !== s.settings.drag;
  if (next.restitution !== s.settings.restitution) {
    setMaterial(s.world, s.floor, { restitution: next.restitution });
    setMaterial(s.world, s.wall, { restitution: next.restitution });
  }
  Object.assign(s.settings, next);
  if (rebuild) {
    removeBody(s.world, s.emitter);
    s.emitter = makeEmitter(s);
  } else {
    setEmitterRate(s.world, s.emitter, next.rate);
  }
}

/** Moves the tool to (x, y), m (kept above the floor and in front of the wall). */
export function moveTool(s: Sparks, x: number, y: number): void {
  s.at[0] = Math.max(WALL_X + 0.1, x);
  s.at[1] = Math.max(0.05, y);
  setPosition(s.world, s.emitter, s.at);
}

/** Starts or stops the sparks. */
export function setToolOn(s: Sparks, on: boolean): void {
  s.on = on;
  setEmitterEnabled(s.world, s.emitter, on);
}

/** One step: the world steps, then the new bounces are counted from the contact buffer. */
export function stepSparks(s: Sparks): void {
  step(s.world);
  // The last step's contacts: after a step the solver has moved them into the warm-start cache
  // (`world.collision.contacts` is then the empty spare buffer), as the renderers' debug layers read them.
  const buf = s.world.collision.cache.rows;
  const kind = buf.kind,
    feature = buf.feature,
    impact = buf.impactVelocity,
    pushed = buf.impulse;
  for (let i = 0; i < buf.count; i++) {
    if (
      kind[i] === ContactKind.Segment &&
      (feature[i] === slotOf(s.floor) || feature[i] === slotOf(s.wall)) &&
      impact[i]! < -1 &&
      pushed[i]! > 0
    )
      s.bounces++;
  }
}
