/**
 * Two-body (Kepler) motion about a fixed centre, for the solar system's flight planner: where a
 * probe or a planet will be after a time, on an ellipse, parabola or hyperbola alike. DOM-free.
 *
 * Universal-variable formulation (Curtis, Orbital Mechanics for Engineering Students, 3rd ed., sect.
 * 3.7, Algorithms 3.3 and 3.4; Bate, Mueller and White, Fundamentals of Astrodynamics, ch. 4): with
 * alpha = 2 / r0 - v0^2 / mu (the reciprocal semi-major axis), the universal anomaly chi solves
 *
 *   r0 vr0 / sqrt(mu) chi^2 C(z) + (1 - alpha r0) chi^3 S(z) + r0 chi = sqrt(mu) t,   z = alpha chi^2,
 *
 * with the Stumpff functions C and S; then R = f R0 + g V0 and V = f' R0 + g' V0 with the Lagrange
 * coefficients f = 1 - chi^2 C / r0, g = t - chi^3 S / sqrt(mu), f' = sqrt(mu) / (r r0) (alpha chi^3 S
 * - chi), g' = 1 - chi^2 C / r. The equation is solved by Laguerre's method (Conway 1986, Celestial
 * Mechanics 39, 199), which converges from any start for every conic; an ellipse's time is first
 * reduced modulo its period.
 *
 * Units are the caller's (the game: AU, days, mu in AU^3/day^2).
 */

/** Stumpff function C(z) = (1 - cos sqrt z) / z (z > 0), (cosh sqrt(-z) - 1) / (-z) (z < 0), 1/2 at 0. */
export function stumpffC(z: number): number {
  if (Math.abs(z) < 1e-3) return 0.5 - z / 24 + (z * z) / 720 - (z * z * z) / 40320;
  if (z > 0) return (1 - Math.cos(Math.sqrt(z))) / z;
  return (Math.cosh(Math.sqrt(-z)) - 1) / -z;
}

/** Stumpff function S(z) = (sqrt z - sin sqrt z) / z^1.5 (z > 0), (sinh sqrt(-z) - sqrt(-z)) / (-z)^1.5 (z < 0), 1/6 at 0. */
export function stumpffS(z: number): number {
  if (Math.abs(z) < 1e-3) return 1 / 6 - z / 120 + (z * z) / 5040 - (z * z * z) / 362880;
  if (z > 0) {
    const s = Math.sqrt(z);
    return (s - Math.sin(s)) / (s * s * s);
  }
  const s = Math.sqrt(-z);
  return (Math.sinh(s) - s) / (s * s * s);
}

function assertVector3(where: string, name: string, v: ArrayLike<number>): void {
  if (v.length < 3 || !Number.isFinite(v[0]) || !Number.isFinite(v[1]) || !Number.isFinite(v[2])) {
    throw new RangeError(`${where}: ${name} must hold 3 finite numbers, got ${JSON.stringify(Array.from(v).slice(0, 3))}`);
  }
}

/**
 * The state after time `t` of a body that is at `r0` with velocity `v0` now, moving under a point mass
 * at the origin with gravitational parameter `mu` (no other force): position into out[0..2], velocity
 * into out[3..5]. Units are the caller's (positions L, velocities L/T, t in T, mu in L^3/T^2). Any
 * conic; t may be negative (backwards). Rounding: the relative error of the position is about 1e-12
 * for a few orbits of an ellipse.
 * @returns out.
 * @throws RangeError naming the parameter when r0 or v0 is not 3 finite numbers, r0 is the origin,
 *   mu is not positive and finite, or t is not finite.
 */
export function keplerState(
  r0: ArrayLike<number>,
  v0: ArrayLike<number>,
  mu: number,
  t: number,
  out: Float64Array | number[] = new Float64Array(6),
): Float64Array | number[] {
  const where = 'keplerState';
  assertVector3(where, 'r0', r0);
  assertVector3(where, 'v0', v0);
  if (!(mu > 0 && Number.isFinite(mu))) throw new RangeError(`${where}: mu must be positive and finite, got ${mu}`);
  if (!Number.isFinite(t)) throw new RangeError(`${where}: t must be finite, got ${t}`);
  const x0 = r0[0]!,
    y0 = r0[1]!,
    z0 = r0[2]!,
    vx = v0[0]!,
    vy = v0[1]!,
    vz = v0[2]!;
  const r = Math.hypot(x0, y0, z0);
  if (!(r > 0)) throw new RangeError(`${where}: r0 must not be the origin (the attracting centre)`);
  const sqrtMu = Math.sqrt(mu);
  const vr = (x0 * vx + y0 * vy + z0 * vz) / r;
  const alpha = 2 / r - (vx * vx + vy * vy + vz * vz) / mu;
  let dt = t;
  // An ellipse repeats itself: solve within one period (keeps chi small and the iteration quick).
  if (alpha > 1e-12) {
    const period = (2 * Math.PI) / (sqrtMu * alpha * Math.sqrt(alpha));
    dt = t - period * Math.round(t / period);
  }
  const chi = universalAnomaly(r, vr, alpha, sqrtMu, dt);
  const z = alpha * chi * chi;
  const C = stumpffC(z),
    S = stumpffS(z);
  const f = 1 - ((chi * chi) / r) * C;
  const g = dt - (chi * chi * chi * S) / sqrtMu;
  const x = f * x0 + g * vx,
    y = f * y0 + g * vy,
    zz = f * z0 + g * vz;
  const rr = Math.hypot(x, y, zz);
  const fdot = (sqrtMu / (rr * r)) * (alpha * chi * chi * chi * S - chi);
  const gdot = 1 - ((chi * chi) / rr) * C;
  out[0] = x;
  out[1] = y;
  out[2] = zz;
  out[3] = fdot * x0 + gdot * vx;
  out[4] = fdot * y0 + gdot * vy;
  out[5] = fdot * z0 + gdot * vz;
  return out;
}

/**
 * Solves the universal Kepler equation for chi by Laguerre's method (n = 5), from the usual start
 * sqrt(mu) |alpha| t (an ellipse) or sqrt(mu) t / r0 (otherwise).
 */
function universalAnomaly(r0: number, vr0: number, alpha: number, sqrtMu: number, t: number): number {
  if (t === 0) return 0;
  const a = (r0 * vr0) / sqrtMu,
    b = 1 - alpha * r0,
    target = sqrtMu * t;
  let chi = alpha > 1e-12 ? sqrtMu * alpha * t : (sqrtMu * t) / r0;
  const n = 5;
  for (let i = 0; i < 60; i++) {
    const z = alpha * chi * chi;
    const C = stumpffC(z),
      S = stumpffS(z);
    const chi2 = chi * chi;
    const F = a * chi2 * C + b * chi2 * chi * S + r0 * chi - target;
    // dF/dchi = r(chi) (the distance), d2F/dchi2 = a (1 - z S) + b chi (1 - z C).
    const dF = a * chi * (1 - z * S) + b * chi2 * C + r0;
    const d2F = a * (1 - z * C) + b * chi * (1 - z * S);
    const root = Math.sqrt(Math.abs((n - 1) * (n - 1) * dF * dF - n * (n - 1) * F * d2F));
    const den = dF + (dF >= 0 ? root : -root);
    const step = den !== 0 ? (n * F) / den : F / dF;
    chi -= step;
    if (Math.abs(step) <= 1e-13 * Math.max(1, Math.abs(chi))) break;
  }
  return chi;
}
