/**
 * The exact results the bungee lab compares against. Only drawn and shown, never fed back into
 * the simulation.
 */

/**
 * Height during the free fall from rest at y0, m: y = y0 - g t^2 / 2, valid while the fall
 * distance is below the rope length L, i.e. for t <= sqrt(2 L / g); NaN after.
 * Source: Ramtal and Dobre ch. 4 (constant acceleration).
 * @param t s since the jump. @param g m/s^2 (> 0). @param L m (>= 0).
 */
export function freeFallHeight(y0: number, g: number, L: number, t: number): number {
  return t <= freeFallTime(g, L) ? y0 - 0.5 * g * t * t : Number.NaN;
}

/** Duration of the free fall, s: the rope becomes taut after falling L, t = sqrt(2 L / g). */
export function freeFallTime(g: number, L: number): number {
  return Math.sqrt((2 * L) / g);
}

/**
 * Stretch of the rope at the lowest point, m, from energy conservation (no damping): the jumper
 * falls L + x from rest to rest, so m g (L + x) = k x^2 / 2, whose positive root is
 * x = (m g + sqrt((m g)^2 + 2 k m g L)) / k.
 * Source: Ramtal and Dobre ch. 8 (springs, elastic energy k x^2 / 2) and ch. 4 (energy conservation).
 * @param m kg (> 0). @param g m/s^2 (> 0). @param k N/m (> 0). @param L m (>= 0).
 */
export function lowestStretch(m: number, g: number, k: number, L: number): number {
  const w = m * g;
  return (w + Math.sqrt(w * w + 2 * k * w * L)) / k;
}

/** Equilibrium stretch, m: k x = m g, x = m g / k (where the jumper finally hangs with damping). */
export function equilibriumStretch(m: number, g: number, k: number): number {
  return (m * g) / k;
}
