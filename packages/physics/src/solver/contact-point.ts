import type { CollisionSettings } from '../collision/state.js';
import { SN_BIAS, SN_RIGID, SN_RIGID_BIAS, SN_SCALES, SN_SOFT_ROW } from './contact-point-layout.js';
import { makeSoftInto, shapeContactHertz } from './contact-scale.js';

/**
 * The per-point rows of the shape contacts, which the 2D rows (solver/manifold-rows-2d.ts) and the 3D
 * rows (solver/manifold-solve-3d.ts) both solve with these functions (Box2D v3 contact_solver.c,
 * b2SolveContact): a normal row's regime and bias, its accumulated impulse, and the bounded rows
 * (friction, twist, rolling resistance). Each works on scalars, the dimension's vector parts (the
 * normal velocity, the impulses' application) stay with its caller; V8 inlines these small calls into
 * the solver loops. Layouts: solver/contact-point-layout.ts.
 */

/** prepareContactSoftness's scratch: one soft constraint's bias rate, mass scale and impulse scale. */
const coefficients = new Float64Array(3);

/**
 * Fills the contact softness table `T` (SN_STRIDE numbers, solver/contact-point-layout.ts) for substeps
 * of `hs` (s > 0): rows between moving bodies soft at the shape contact stiffness (shapeContactHertz),
 * rows against an infinite-mass partner twice as stiff, both at `settings.contactDampingRatio`.
 * @category Collision
 */
export function prepareContactSoftness(T: Float64Array, settings: CollisionSettings, hs: number): void {
  const hertz = shapeContactHertz(settings, hs);
  for (let rigid = 0; rigid < 2; rigid++) {
    makeSoftInto(coefficients, 0, (1 + rigid) * hertz, settings.contactDampingRatio, hs);
    const o = SN_SCALES + SN_RIGID * rigid;
    T[o] = 1;
    T[o + 1] = 0;
    T[o + SN_SOFT_ROW] = coefficients[1]!;
    T[o + SN_SOFT_ROW + 1] = coefficients[2]!;
    T[rigid === 0 ? SN_BIAS : SN_RIGID_BIAS] = coefficients[0]!;
  }
}

/** The effective mass 1 / k of a row of inverse effective mass `k` (1/kg or 1/(kg m^2), >= 0), or 0 for a row that moves nothing (k = 0). */
export function effectiveMass(k: number): number {
  return k > 0 ? 1 / k : 0;
}

/**
 * 1 if a normal row at separation `s` (m) is soft, else 0: it overlaps (s <= 0) in a biased pass
 * (`biasOn` 1; 0 in a relax pass). A row that is not soft is speculative (s > 0) or relaxed.
 */
export function softRow(s: number, biasOn: number): number {
  return +!(s > 0) & biasOn;
}

/**
 * A normal row's velocity bias (m/s): s / h (`invH` = 1 / h_s, 1/s) for a speculative row (s > 0, m), the
 * soft bias `biasRate` s (1/s times m) kept above `minBias` (minus the push-out speed cap, m/s) for a soft
 * row (`soft` 1, see softRow), else 0 (a relaxed row; it may be -0, which adds the same). Selected
 * without a branch: which regime a row is in changes from point to point in a pile, and a mispredicted
 * branch costs more than the row.
 */
export function normalBias(s: number, invH: number, biasRate: number, minBias: number, soft: number): number {
  return +(s > 0) * (s * invH) + soft * Math.max(biasRate * s, minBias);
}

/**
 * A normal row's new accumulated impulse (N s, >= 0) from the old one `old` (N s), its effective mass
 * `normalMass` (kg), its softness scales (`massScale`, `impulseScale`: 1 and 0 unless soft), its normal
 * relative velocity `vn` and bias (m/s): Box2D's soft update, old - s_m m (v_n + bias) - s_i old,
 * clamped at 0.
 */
export function normalImpulse(old: number, normalMass: number, massScale: number, impulseScale: number, vn: number, bias: number): number {
  return Math.max(old - normalMass * massScale * (vn + bias) - impulseScale * old, 0);
}

/**
 * A bounded row's new accumulated impulse (friction, twist, rolling resistance): `old` less `mass`
 * times the row's relative velocity `v`, clamped to [-bound, bound] (bound >= 0: mu times the normal
 * impulse, or a torque limit). Units: N s with kg and m/s, or N m s with kg m^2 and rad/s.
 */
export function boundedImpulse(old: number, mass: number, v: number, bound: number): number {
  const next = old - mass * v;
  return next < -bound ? -bound : next > bound ? bound : next;
}

/** bouncingList's scratch (not world state). */
let bouncing = new Int32Array(0);

/**
 * The restitution stages' worklist, with room for `n` manifolds (n >= 0): which points bounce does not
 * change from pass to pass, so the 2D and 3D stages visit every manifold in their first pass and list
 * there, in order, those with a bouncing point; later passes visit only those. Scratch shared by both
 * stages (one stage fills and reads it at a time), grown to twice what is asked when too small.
 */
export function bouncingList(n: number): Int32Array {
  if (bouncing.length < n) bouncing = new Int32Array(2 * n);
  return bouncing;
}
