/**
 * The exact results the pendulum lab compares against. Only drawn and shown, never fed back into
 * the simulation.
 */

/**
 * Small-angle solution released from rest at theta0 (rad): theta'' + 2 gamma theta' + omega0^2 theta = 0
 * with omega0 = sqrt(g / L) and gamma = b / (2 m) (linear drag F = -b v on a bob of mass m, whose
 * tangential part is -b L theta'). Without damping this is theta0 cos(sqrt(g / L) t).
 * Underdamped: theta0 e^(-gamma t) (cos(w t) + (gamma / w) sin(w t)), w = sqrt(omega0^2 - gamma^2);
 * critical: theta0 e^(-gamma t) (1 + gamma t); overdamped: theta0 (r2 e^(r1 t) - r1 e^(r2 t)) / (r2 - r1),
 * r1,2 = -gamma -+ sqrt(gamma^2 - omega0^2).
 * Source: Ramtal and Dobre ch. 8 (damped oscillations); Taylor, Classical Mechanics (2005) sect. 5.4.
 * @param g m/s^2 (> 0). @param L m (> 0). @param b N s/m (>= 0). @param m kg (> 0). @param t s.
 * @returns the angle, rad.
 */
export function smallAngle(theta0: number, g: number, L: number, b: number, m: number, t: number): number {
  const w0 = Math.sqrt(g / L);
  const gamma = b / (2 * m);
  if (gamma === 0) return theta0 * Math.cos(w0 * t);
  const disc = w0 * w0 - gamma * gamma;
  if (disc > 1e-12 * w0 * w0) {
    const w = Math.sqrt(disc);
    return theta0 * Math.exp(-gamma * t) * (Math.cos(w * t) + (gamma / w) * Math.sin(w * t));
  }
  if (disc >= -1e-12 * w0 * w0) return theta0 * Math.exp(-gamma * t) * (1 + gamma * t);
  const s = Math.sqrt(-disc);
  const r1 = -gamma - s,
    r2 = -gamma + s;
  return (theta0 * (r2 * Math.exp(r1 * t) - r1 * Math.exp(r2 * t))) / (r2 - r1);
}

/** Small-angle period, s: T0 = 2 pi sqrt(L / g). Source: Ramtal and Dobre ch. 8; Taylor sect. 5.2. */
export function smallAnglePeriod(L: number, g: number): number {
  return 2 * Math.PI * Math.sqrt(L / g);
}

/** Arithmetic-geometric mean of a, b > 0 (converges quadratically; 1e-15 relative). */
export function agm(a: number, b: number): number {
  for (let i = 0; i < 64 && Math.abs(a - b) > 1e-15 * a; i++) {
    const m = 0.5 * (a + b);
    b = Math.sqrt(a * b);
    a = m;
  }
  return a;
}

/**
 * Exact period of the undamped pendulum at any amplitude theta0 (rad, |theta0| < pi), s:
 * T = 4 sqrt(L / g) K(sin(theta0 / 2)) = 2 pi sqrt(L / g) / AGM(1, cos(theta0 / 2)).
 * Source: Carvalhaes and Suppes, "Approximations for the period of the simple pendulum based on the
 * arithmetic-geometric mean", Am. J. Phys. 76, 1150 (2008), eq. 7; Taylor, Classical Mechanics sect. 4.9.
 */
export function largeAmplitudePeriod(L: number, g: number, theta0: number): number {
  return smallAnglePeriod(L, g) / agm(1, Math.cos(theta0 / 2));
}
