/**
 * Linear springs of fixed stiffness, shared by the 2D distance, prismatic and wheel joints
 * (joints/solver-2d.ts) and the 3D distance joint (joints/solver-3d.ts).
 */

/**
 * The coefficients of a linear spring of fixed stiffness at rows[o..o+1]: the bias rate
 * omega / (2 zeta + h omega) (1/s, as Box2D's b2MakeSoft) and the softness
 * gamma = kRef / a (a = h omega (2 zeta + h omega)), so a row solves
 * impulse = -(Cdot + bias C + gamma lambda) / (K + gamma) with K the inverse effective mass of the
 * moment (Catto, "Soft Constraints", GDC 2011: gamma = 1 / (h (c + h k))). The stiffness
 * k = omega^2 / kRef and damping c = 2 zeta omega / kRef come from `kRef`, a mass that no motion
 * changes (in 2D mA + mB + (iA |rA|^2 + iB |rB|^2) / 2, half the trace of the point block; in 3D a third
 * of the 3 x 3 block's trace, solver-3d.ts referenceK), so the spring has
 * a potential 1/2 k C^2 and does no work around a swing. Box2D takes the stiffness from the effective
 * mass along the row, which a lever's rotation changes: a distance spring on a 5 m lever gained
 * 6.4e5 J. With no lever (kRef = K) the update is Box2D's soft row. A spring so soft that a rounds to
 * 0 gives gamma = Infinity (the row only lets go of its impulse); one so stiff that a overflows gives
 * the rigid 1 / h, 0.
 * @category Joints and ropes
 */
export function fixedSpring(rows: Float64Array, o: number, hertz: number, zeta: number, h: number, kRef: number): void {
  const omega = 2 * Math.PI * hertz;
  const hw = h * omega;
  const a = hw * (2 * zeta + hw);
  if (!(a > 0)) {
    rows[o] = 0;
    rows[o + 1] = Infinity;
    return;
  }
  rows[o] = zeta === 0 ? 1 / h : 1 / (h + (2 * zeta) / omega);
  rows[o + 1] = kRef / a;
}
