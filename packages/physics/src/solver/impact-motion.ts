/**
 * The relative motion of a contact row's two bodies as the impact stage (solver/impacts.ts) sweeps it:
 * body B's motion seen from body A, on the packed solver state (CollisionState.bodyState) and the
 * impact rows (CollisionState.bodyImpact, solver/body-state-layout.ts).
 */

import { BodyType } from '../collision/state.js';
import { BI_TIME, BS2_STRIDE, BS2_VX, BS2_VY, BS3_VZ } from './body-state-layout.js';

/**
 * The factor of gravity in body B's acceleration relative to body A's (dimensionless: -1, 0 or 1):
 * 1 for each of the bodies that gravity moves (dynamic; entity `a` 0 is the static world), B counted
 * plus and A minus. `type` is CollisionState.bodyType, by entity.
 */
export function gravitySign(type: Uint8Array, a: number, b: number): number {
  return (type[b] === BodyType.Dynamic ? 1 : 0) - (a !== 0 && type[a] === BodyType.Dynamic ? 1 : 0);
}

/**
 * (v_B - v_A) . n, m/s: the normal relative velocity of the bodies whose packed rows start at `oa` and
 * `ob` in `sb` (stride S: BS2_STRIDE, or BS3_STRIDE with the z component), n = (nx, ny, nz) from A to B
 * (nz unused in 2D). Negative while they approach.
 */
export function normalVelocity(sb: Float64Array, oa: number, ob: number, nx: number, ny: number, nz: number, S: number): number {
  let vn = (sb[ob + BS2_VX]! - sb[oa + BS2_VX]!) * nx + (sb[ob + BS2_VY]! - sb[oa + BS2_VY]!) * ny;
  if (S !== BS2_STRIDE) vn += (sb[ob + BS3_VZ]! - sb[oa + BS3_VZ]!) * nz;
  return vn;
}

/**
 * The later of two bodies' latest impacts this step, s (>= 0; 0, the start of the step, if neither
 * had one): their impact rows start at `qa` and `qb` in `imp` (a row's BI_TIME is -1 when the body is
 * left to the substeps).
 */
export function latestImpactTime(imp: Float64Array, qa: number, qb: number): number {
  const ta = imp[qa + BI_TIME]!,
    tb = imp[qb + BI_TIME]!;
  return ta > tb ? (ta > 0 ? ta : 0) : tb > 0 ? tb : 0;
}
