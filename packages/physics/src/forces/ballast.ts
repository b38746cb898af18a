import { hasComponent } from 'bitecs';
import { assertInRange, assertKnownKeys, assertNonNegative, assertPositive, describe, optionOr } from '../validation/validate.js';
import { resolveKind } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { addComponentIfMissing } from '../world/options.js';
import { query } from '../world/query.js';
import { idleWithout } from '../world/trusted-systems.js';
import type { ForceLaw } from './law.js';

/**
 * Ballast tanks: a submarine dives by flooding tanks with sea water (its mass grows past the mass of
 * water its hull displaces) and rises by blowing them (Ramtal and Dobre ch. 16, "submarine"). The
 * `Ballast` component holds a fore and an aft tank; filling them unequally trims the hull nose down
 * or up. Buoyancy itself is the `Buoyancy` law (forces/fluid.ts): Archimedes' rho V g.
 *
 * Neutral buoyancy of a fully submerged hull: dryMass + capacity (fore + aft) = rho V, so with both
 * tanks at the same fill f the balance is at f = (rho V - dryMass) / (2 capacity).
 */

/** The slot of body handle `body`, which must be dynamic. @throws RangeError naming `where`. */
function dynamicBody(where: string, world: PhysicsWorld, body: number): number {
  const eid = resolveKind(world, body, 'body', where);
  if (hasComponent(world, eid, world.components.Static) || hasComponent(world, eid, world.components.Kinematic)) {
    throw new RangeError(`${where}: entity ${body} is static or kinematic; ballast needs a dynamic body`);
  }
  return eid;
}

/**
 * Options of `setBallast`. Unknown fields are rejected.
 * @category Forces
 */
export interface BallastOptions {
  /** Mass of the body with both tanks empty, kg, > 0. */
  dryMass: number;
  /** Water each tank holds when full, kg, > 0. */
  capacity: number;
  /** Fill fraction of both tanks now, in [0, 1], or [fore, aft]. Default 0 (empty). */
  fill?: number | readonly [number, number];
  /** Fill fraction of both tanks the pumps move towards, or [fore, aft]. Default: the fill. */
  target?: number | readonly [number, number];
  /** How fast a tank floods or blows, fill fraction per second, > 0. Default 0.1 (10 s from empty to full). */
  rate?: number;
  /** 2D: distance of each tank from the centre of mass along the hull (fore at +arm, aft at -arm), m, >= 0. Default 0. */
  arm?: number;
  /** 2D: height of the centre of buoyancy above the centre of mass, m, >= 0 (the hydrostatic righting lever). Default 0. */
  metacentricHeight?: number;
}

function pair(where: string, param: string, v: number | readonly [number, number]): [number, number] {
  if (typeof v === 'number') {
    assertInRange(where, param, v, 0, 1);
    return [v, v];
  }
  if (!Array.isArray(v) || v.length !== 2)
    throw new TypeError(`${where}: ${param} must be a number in [0, 1] or [fore, aft], got ${describe(v)}`);
  assertInRange(where, `${param}[0]`, v[0], 0, 1);
  assertInRange(where, `${param}[1]`, v[1], 0, 1);
  return [v[0]!, v[1]!];
}

/**
 * Gives a dynamic body ballast tanks (the `Ballast` component) and sets its mass to dryMass +
 * capacity (fore + aft). In 2D a body with `arm` or `metacentricHeight` also turns (it needs a
 * moment of inertia: `setInertia`).
 * @throws TypeError on unknown options; RangeError on a missing, static or kinematic body, a
 *   non-positive dry mass, capacity or rate, fills outside [0, 1], or a negative arm or height.
 * @category Forces
 */
export function setBallast(world: PhysicsWorld, body: number, options: BallastOptions): void {
  const where = 'setBallast';
  const eid = dynamicBody(where, world, body);
  assertKnownKeys(where, options, ['dryMass', 'capacity', 'fill', 'target', 'rate', 'arm', 'metacentricHeight']);
  assertPositive(where, 'dryMass', options.dryMass);
  assertPositive(where, 'capacity', options.capacity);
  const fill = pair(where, 'fill', options.fill ?? 0);
  const target = options.target === undefined ? fill : pair(where, 'target', options.target);
  const rate = optionOr(where, 'rate', options.rate, 0.1, assertPositive);
  const arm = options.arm ?? 0,
    gm = options.metacentricHeight ?? 0;
  assertNonNegative(where, 'arm', arm);
  assertNonNegative(where, 'metacentricHeight', gm);
  const c = world.components;
  addComponentIfMissing(world, eid, c.Ballast);
  addComponentIfMissing(world, eid, c.Force);
  addComponentIfMissing(world, eid, c.Mass);
  const B = c.Ballast;
  B.dryMass[eid] = options.dryMass;
  B.capacity[eid] = options.capacity;
  B.fore[eid] = fill[0];
  B.aft[eid] = fill[1];
  B.foreTarget[eid] = target[0];
  B.aftTarget[eid] = target[1];
  B.rate[eid] = rate;
  B.arm[eid] = arm;
  B.metacentricHeight[eid] = gm;
  const m = options.dryMass + options.capacity * (fill[0] + fill[1]);
  c.Mass.value[eid] = m;
  c.Mass.inv[eid] = 1 / m;
}

/**
 * Sets the fill fractions the pumps move a body's tanks towards: `fore` and `aft` in [0, 1] (aft
 * defaults to fore). The tanks get there at the component's `rate`.
 * @throws RangeError on a body without ballast or a fraction outside [0, 1].
 * @category Forces
 */
export function setBallastTarget(world: PhysicsWorld, body: number, fore: number, aft: number = fore): void {
  const where = 'setBallastTarget';
  const eid = dynamicBody(where, world, body);
  if (!hasComponent(world, eid, world.components.Ballast))
    throw new RangeError(`${where}: entity ${eid} has no ballast (call setBallast first)`);
  assertInRange(where, 'fore', fore, 0, 1);
  assertInRange(where, 'aft', aft, 0, 1);
  world.components.Ballast.foreTarget[eid] = fore;
  world.components.Ballast.aftTarget[eid] = aft;
}

/**
 * 2D trim torques of ballasted hulls (Rawson and Tupper, Basic Ship Theory, ch. 4): the water of the
 * fore tank (m_f) weighs at +arm along the hull and that of the aft tank (m_a) at -arm, so about the
 * centre of mass tau = arm (m_f - m_a) (cos(theta) g_y - sin(theta) g_x); the hydrostatic righting
 * moment of a hull whose centre of buoyancy is GM above its centre of mass, with the buoyancy taken
 * equal to the weight M g (a floating or neutrally buoyant hull), tau = M GM (sin(theta) g_y +
 * cos(theta) g_x): -M g GM sin(theta) for g = (0, -g). theta is the hull's `Angle`. Position-only.
 * @category Forces
 */
export const ballastTrimSystem: ForceLaw = (world: PhysicsWorld): void => {
  if (world.dimensions !== 2) return;
  const c = world.components;
  const ents = query(world, [c.Ballast, c.Angle, c.Torque, c.Mass]);
  if (ents.length === 0) return;
  const B = c.Ballast,
    angle = c.Angle.value,
    tz = c.Torque.z,
    m = c.Mass.value;
  const gx = world.gravity[0]!,
    gy = world.gravity[1]!;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const arm = B.arm[e]!,
      gm = B.metacentricHeight[e]!;
    if (arm === 0 && gm === 0) continue;
    const s = Math.sin(angle[e]!),
      co = Math.cos(angle[e]!);
    const dm = B.capacity[e]! * (B.fore[e]! - B.aft[e]!);
    tz[e] = tz[e]! + arm * dm * (co * gy - s * gx) + m[e]! * gm * (s * gy + co * gx);
  }
};
ballastTrimSystem.velocityDependent = false;

/**
 * Floods or blows the tanks after each integration: each fill moves towards its target by at most
 * rate h, then mass = dryMass + capacity (fore + aft) and the inverse mass follow (the moment of
 * inertia is left as set). Runs in the integrate stage right after the scheme, so the mass is
 * constant within a step and every scheme sees the same mass at all its stages.
 * @category Forces
 */
export function ballastFillSystem(world: PhysicsWorld): void {
  const c = world.components;
  const ents = query(world, [c.Ballast, c.Mass]);
  if (ents.length === 0) return;
  const B = c.Ballast,
    M = c.Mass;
  const h = world.h;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const step = B.rate[e]! * h;
    const f = B.fore[e]!,
      a = B.aft[e]!;
    const df = B.foreTarget[e]! - f,
      da = B.aftTarget[e]! - a;
    const nf = f + (df > step ? step : df < -step ? -step : df);
    const na = a + (da > step ? step : da < -step ? -step : da);
    if (nf === f && na === a) continue;
    B.fore[e] = nf;
    B.aft[e] = na;
    const mass = B.dryMass[e]! + B.capacity[e]! * (nf + na);
    M.value[e] = mass;
    M.inv[e] = 1 / mass;
  }
}

// What makes each system of this module idle (world/trusted-systems.ts idleWithout): its first query.
idleWithout(ballastTrimSystem, (w) =>
  w.dimensions === 2 ? [[w.components.Ballast, w.components.Angle, w.components.Torque, w.components.Mass]] : null,
);
idleWithout(ballastFillSystem, (w) => [[w.components.Ballast, w.components.Mass]]);
