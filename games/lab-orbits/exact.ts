/**
 * The two-body (Kepler) results the orbits lab compares against. Only drawn and shown, never fed
 * back into the simulation.
 */

/**
 * Specific orbital energy of a body around a fixed attractor, J/kg:
 * eps = |v|^2 / 2 - G M / sqrt(r^2 + s^2), s the attractor's softening length (the package's
 * softened potential, as in `newtonianPotentialEnergy`). Computed here because the package's
 * diagnostics only sum over the whole world and the lab follows one orbit.
 * Source: Ramtal and Dobre ch. 6; Taylor, Classical Mechanics (2005) sect. 8.4.
 * @param gm G M, m^3/s^2. @param softening m, >= 0.
 */
export function specificEnergy(x: number, y: number, vx: number, vy: number, gm: number, softening: number): number {
  return 0.5 * (vx * vx + vy * vy) - gm / Math.sqrt(x * x + y * y + softening * softening);
}

/**
 * Semi-major axis of a bound Kepler orbit, m: a = -G M / (2 eps) for eps < 0; Infinity when the
 * body is not bound (eps >= 0). Source: Taylor, Classical Mechanics (2005) eq. 8.58 (vis-viva).
 */
export function semiMajorAxis(eps: number, gm: number): number {
  return eps < 0 ? -gm / (2 * eps) : Infinity;
}

/**
 * Kepler's third law, s: T = 2 pi sqrt(a^3 / (G M)); Infinity for an unbound orbit.
 * Source: Kepler (1619); Ramtal and Dobre ch. 6; Taylor, Classical Mechanics (2005) eq. 8.55.
 */
export function keplerPeriod(a: number, gm: number): number {
  return Number.isFinite(a) ? 2 * Math.PI * Math.sqrt((a * a * a) / gm) : Infinity;
}

/** An orbit's shape: semi-major axis a (m), eccentricity e, argument of periapsis omega (rad). */
export interface OrbitShape {
  a: number;
  e: number;
  omega: number;
}

/**
 * The conic a body at (x, y) with velocity (vx, vy) follows around G M at the origin (unsoftened):
 * eccentricity vector e = ((v^2 - G M / r) r - (r . v) v) / (G M), a from the vis-viva energy.
 * Source: Taylor, Classical Mechanics (2005) sect. 8.6; Vallado, Fundamentals of Astrodynamics (2013) alg. 9.
 */
export function orbitShape(x: number, y: number, vx: number, vy: number, gm: number, out: OrbitShape): OrbitShape {
  const r = Math.sqrt(x * x + y * y);
  const v2 = vx * vx + vy * vy;
  const rv = x * vx + y * vy;
  const ex = ((v2 - gm / r) * x - rv * vx) / gm;
  const ey = ((v2 - gm / r) * y - rv * vy) / gm;
  out.e = Math.sqrt(ex * ex + ey * ey);
  out.omega = Math.atan2(ey, ex);
  out.a = semiMajorAxis(0.5 * v2 - gm / r, gm);
  return out;
}

/**
 * Distance from the focus at polar angle theta on a bound orbit, m: r = a (1 - e^2) / (1 + e cos(theta - omega)).
 * Source: Taylor, Classical Mechanics (2005) eq. 8.49.
 */
export function conicRadius(shape: OrbitShape, theta: number): number {
  return (shape.a * (1 - shape.e * shape.e)) / (1 + shape.e * Math.cos(theta - shape.omega));
}
