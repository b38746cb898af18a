/**
 * Soft constraints and springs, shared by the 2D and 3D joints: Box2D's softness of a row of given
 * frequency and damping (`soft`), and the linear spring of fixed stiffness of the distance joints and
 * the 2D prismatic and wheel joints (`fixedSpring`, `springImpulse`).
 */

/**
 * Writes the soft-constraint coefficients of a spring of `hertz` (Hz, >= 0) and damping ratio `zeta`
 * (>= 0) integrated implicitly over `h` (s) at out[o..o+2]: bias rate omega / (2 zeta + h omega) (1/s),
 * mass scale a / (1 + a) and impulse scale 1 / (1 + a), a = h omega (2 zeta + h omega) (Catto, "Soft
 * Constraints", GDC 2011; Box2D v3 b2MakeSoft). hertz 0 gives the rigid 0, 1, 0. Written so every
 * coefficient stays finite and in range at any hertz: a spring so soft that a rounds to 0 (a denormal
 * hertz) gives 0, 0, 1, no impulse at all; one so stiff that a overflows gives 1 / h, 1, 0.
 */
export function soft(out: Float64Array, o: number, hertz: number, zeta: number, h: number): void {
  if (hertz === 0) {
    out[o] = 0;
    out[o + 1] = 1;
    out[o + 2] = 0;
    return;
  }
  const omega = 2 * Math.PI * hertz;
  const hw = h * omega;
  const a = hw * (2 * zeta + hw);
  if (!(a > 0)) {
    out[o] = 0;
    out[o + 1] = 0;
    out[o + 2] = 1;
    return;
  }
  out[o] = zeta === 0 ? 1 / h : 1 / (h + (2 * zeta) / omega);
  out[o + 1] = 1 / (1 + 1 / a);
  out[o + 2] = 1 / (1 + a);
}

/**
 * The coefficients of a linear spring of fixed stiffness at out[o..o+1]: the bias rate
 * omega / (2 zeta + h omega) (1/s, as Box2D's b2MakeSoft) and the softness
 * gamma = kRef / a (a = h omega (2 zeta + h omega)), so a row solves
 * impulse = -(Cdot + bias C + gamma lambda) / (K + gamma) with K the inverse effective mass of the
 * moment (Catto, "Soft Constraints", GDC 2011: gamma = 1 / (h (c + h k))). The stiffness
 * k = omega^2 / kRef and damping c = 2 zeta omega / kRef come from `kRef`, a mass that no motion
 * changes (in 2D mA + mB + (iA |rA|^2 + iB |rB|^2) / 2, half the trace of the point block; in 3D a third
 * of the 3 x 3 block's trace, rows-3d.ts referenceK), so the spring has a potential 1/2 k C^2 and does
 * no work around a swing. Box2D takes the stiffness from the effective mass along the row, which a
 * lever's rotation changes. With no lever (kRef = K) the update is Box2D's soft row. A spring so soft
 * that a rounds to 0 gives gamma = Infinity (the row only lets go of its impulse); one so stiff that a
 * overflows gives the rigid 1 / h, 0.
 * @category Joints and ropes
 */
export function fixedSpring(out: Float64Array, o: number, hertz: number, zeta: number, h: number, kRef: number): void {
  const omega = 2 * Math.PI * hertz;
  const hw = h * omega;
  const a = hw * (2 * zeta + hw);
  if (!(a > 0)) {
    out[o] = 0;
    out[o + 1] = Infinity;
    return;
  }
  out[o] = zeta === 0 ? 1 / h : 1 / (h + (2 * zeta) / omega);
  out[o + 1] = kRef / a;
}

/**
 * The impulse of a fixed-stiffness spring row (see `fixedSpring`): `cdot` the velocity along the
 * row, `c` its position error, `k` the inverse effective mass of the moment, `lambda` the impulse the
 * row holds, `bias` and `gamma` from `fixedSpring`.
 */
export function springImpulse(cdot: number, c: number, k: number, lambda: number, bias: number, gamma: number): number {
  if (!(gamma < Infinity)) return -lambda;
  const den = k + gamma;
  return den > 0 ? -(cdot + bias * c + gamma * lambda) / den : 0;
}
