import { addBodyAs, removeBody } from '../bodies/api.js';
import { installBalls } from '../collision/install-balls.js';
import * as check from '../validation/validate.js';
import { isAlive } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { addDistanceJoint } from './distance-joint.js';

/**
 * Options of `createRope`. Unknown fields are rejected.
 * @category Joints and ropes
 */
export interface RopeOptions {
  /** First end, m (x, y). */
  start: ArrayLike<number>;
  /** Other end, m (x, y), where the rope lies straight at first. */
  end: ArrayLike<number>;
  /** Links (bodies) of the rope, integer in [1, 10000]. Default 20. */
  segments?: number;
  /** Total mass, kg, > 0, shared by the bodies. Default 1 kg. */
  mass?: number;
  /** Collision radius of each body, m, >= 0 (0: the rope passes through things). Default 0. */
  radius?: number;
  /** Whether the start is pinned to the world (a fixed point). Default true. */
  pinStart?: boolean;
  /** Whether the end is pinned to the world. Default false. */
  pinEnd?: boolean;
  /** Whether the links are ropes that only pull (true) or rigid rods (false). Default true. */
  slack?: boolean;
  /** Linear drag of each body, N s/m, >= 0 (air resistance; wind acts through it). Default 0. */
  drag?: number;
  /** Force past which a link breaks, N, > 0 (Infinity: never). Default Infinity. */
  breakForce?: number;
}

/**
 * What `createRope` made.
 * @category Joints and ropes
 */
export interface Rope {
  /** The bodies' handles from the start to the end (Float64Array: a handle needs up to 53 bits, see world/handles.ts). */
  readonly bodies: Float64Array;
  /** The distance joints' handles in order along the rope: the start pin (if pinned), the links between bodies, the end pin (if pinned). */
  readonly joints: Float64Array;
}

/**
 * Builds a rope (Ramtal and Dobre ch. 13): `segments` point bodies from `start` to `end` joined by
 * distance joints of equal length (rope links that only pull, or rods), optionally pinned to the world
 * at either end (a pinned end is one segment from its body). The links are joints[0..] in order from the start. The bodies do not rotate (point masses; the joint solver's point links). A 2D world only.
 * @returns the bodies and joints.
 * @throws TypeError | RangeError `createRope: <param> must be ...` on a 3D world, unknown or null options, bad
 *   ends or values, start equal to end, or a world without room for the rope. A refused call adds nothing.
 * @category Joints and ropes
 */
export function createRope(world: PhysicsWorld, options: RopeOptions): Rope {
  const where = 'createRope';
  if (world.dimensions !== 2) throw new RangeError(`${where}: ropes need a 2D world, this world has ${world.dimensions} dimensions`);
  check.assertOptions(where, options, ['start', 'end', 'segments', 'mass', 'radius', 'pinStart', 'pinEnd', 'slack', 'drag', 'breakForce']);
  check.assertVector(where, 'start', options.start, 2);
  check.assertVector(where, 'end', options.end, 2);
  const n = check.optionOr(where, 'segments', options.segments, 20, check.assertInteger, 1, 10000);
  const mass = check.optionOr(where, 'mass', options.mass, 1, check.assertPositive);
  const radius = check.optionOr(where, 'radius', options.radius, 0, check.assertNonNegative);
  const drag = check.optionOr(where, 'drag', options.drag, 0, check.assertNonNegative);
  if (options.breakForce !== undefined && options.breakForce !== Infinity) check.assertPositive(where, 'breakForce', options.breakForce);
  const x0 = options.start[0]!,
    y0 = options.start[1]!,
    x1 = options.end[0]!,
    y1 = options.end[1]!;
  const length = Math.hypot(x1 - x0, y1 - y0);
  if (!(length > 0)) throw new RangeError(`${where}: start and end must differ, got ${check.describe(options.start)} twice`);
  check.assertOptionalBoolean(where, 'pinStart', options.pinStart);
  check.assertOptionalBoolean(where, 'pinEnd', options.pinEnd);
  check.assertOptionalBoolean(where, 'slack', options.slack);
  const pinStart = options.pinStart ?? true,
    pinEnd = options.pinEnd ?? false;
  const slack = options.slack ?? true;
  // Equal segments: (n - 1) between bodies, plus one to each pinned end.
  const spans = n - 1 + (pinStart ? 1 : 0) + (pinEnd ? 1 : 0);
  if (world.entityIndex.aliveCount + n + spans > world.capacity) {
    throw new RangeError(
      `${where}: the rope needs ${n + spans} entities, the world has room for ${world.capacity - world.entityIndex.aliveCount}`,
    );
  }
  const seg = length / Math.max(spans, 1);
  const bodies = new Float64Array(n);
  const joints = new Float64Array(spans);
  const m = mass / n;
  let made = 0,
    linked = 0;
  try {
    for (let i = 0; i < n; i++) {
      const t = spans > 0 ? (i + (pinStart ? 1 : 0)) / spans : 0;
      bodies[i] = addBodyAs(
        world,
        {
          position: [x0 + t * (x1 - x0), y0 + t * (y1 - y0)],
          mass: m,
          rotates: false,
          ...(radius > 0 ? { radius } : {}),
          ...(drag > 0 ? { linearDrag: drag } : {}),
        },
        where,
        ROPE_BODY_OPTIONS,
      );
      made++;
    }
    const link = (a: number | null, b: number, anchorA?: [number, number]): void => {
      joints[linked++] = addDistanceJoint(world, {
        a,
        b,
        ...(anchorA ? { anchorA } : {}),
        length: seg,
        ...(slack ? { minLength: 0 } : {}),
        ...(options.breakForce !== undefined ? { breakForce: options.breakForce } : {}),
      });
    };
    if (pinStart) link(null, bodies[0]!, [x0, y0]);
    for (let i = 1; i < n; i++) link(bodies[i - 1]!, bodies[i]!);
    if (pinEnd) link(null, bodies[n - 1]!, [x1, y1]);
  } catch (err) {
    // A refused rope leaves the world as it was: its bodies go, and their joints with them.
    for (let i = 0; i < made; i++) if (isAlive(world, bodies[i]!)) removeBody(world, bodies[i]!);
    throw err instanceof RangeError || err instanceof TypeError
      ? new (err.constructor as typeof RangeError)(`${where}: ${err.message}`)
      : err;
  }
  // Links with a radius collide as balls (collision/install-balls.ts).
  if (radius > 0) installBalls(world);
  return { bodies, joints };
}

/** The body options createRope passes on (for addBodyAs' check). */
const ROPE_BODY_OPTIONS = ['position', 'mass', 'rotates', 'radius', 'linearDrag'] as const;
