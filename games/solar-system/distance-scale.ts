/**
 * The solar system's drawing scale: a compressed distance scale that puts all eight planets on one
 * screen with room between the inner four, and the true scale, with any blend between the two (the
 * page slides from one to the other). DOM-free.
 *
 * A heliocentric point at distance r (AU) is drawn in the same direction at the display radius
 *
 *   rho(r) = (1 - u) L ln(1 + r / L) + u r,     L = COMPRESSION_LENGTH (1 AU),
 *
 * where u in [0, 1] is the share of the true scale (0: compressed, 1: true). Near the Sun (r << L) both
 * are the true scale; far out the compressed one grows as a logarithm, so Neptune (30 AU) is drawn 5
 * times as far out as the Earth instead of 30 times. Directions from the Sun are kept; a small step
 * away from a point stretches by d rho / dr along the radius and by rho / r across it.
 */

/** Length at which the compressed scale turns from true to logarithmic, AU. */
export const COMPRESSION_LENGTH = 1;

function checkBlend(where: string, u: number): void {
  if (!(u >= 0 && u <= 1)) throw new RangeError(`${where}: trueScale must be in [0, 1], got ${u}`);
}

/**
 * The display radius of heliocentric distance `r` (AU, >= 0) with a share `trueScale` in [0, 1] of the
 * true scale (see the file's header), AU-equivalents. @throws RangeError on r < 0 or NaN, or a bad share.
 */
export function displayRadius(r: number, trueScale: number): number {
  if (!(r >= 0)) throw new RangeError(`displayRadius: r must be >= 0 AU, got ${r}`);
  checkBlend('displayRadius', trueScale);
  return (1 - trueScale) * COMPRESSION_LENGTH * Math.log1p(r / COMPRESSION_LENGTH) + trueScale * r;
}

/**
 * The inverse of `displayRadius`: the heliocentric distance (AU) drawn at display radius `rho` (>= 0).
 * Newton's method on the increasing, concave rho(r) (after its first step it rises monotonically to the root). @throws RangeError on rho < 0 or NaN, or a bad share.
 */
export function trueRadius(rho: number, trueScale: number): number {
  if (!(rho >= 0)) throw new RangeError(`trueRadius: rho must be >= 0, got ${rho}`);
  checkBlend('trueRadius', trueScale);
  const L = COMPRESSION_LENGTH;
  if (trueScale === 0) return L * Math.expm1(rho / L);
  if (trueScale === 1) return rho;
  // rho(r) >= u r, so the root is at most rho / u: start there.
  let r = rho / trueScale;
  for (let i = 0; i < 60; i++) {
    const f = (1 - trueScale) * L * Math.log1p(r / L) + trueScale * r - rho;
    const df = (1 - trueScale) / (1 + r / L) + trueScale;
    const next = Math.max(0, r - f / df);
    if (Math.abs(next - r) <= 1e-14 * Math.max(1, r)) return next;
    r = next;
  }
  return r;
}

/**
 * Maps the heliocentric vector (x, y, z) (AU) to its drawn place, written into out[offset..offset+2]:
 * the same direction at `displayRadius`. @returns out.
 */
export function toDisplay<T extends { [index: number]: number }>(
  x: number,
  y: number,
  z: number,
  trueScale: number,
  out: T,
  offset = 0,
): T {
  const r = Math.hypot(x, y, z);
  const k = r > 0 ? displayRadius(r, trueScale) / r : 1;
  out[offset] = x * k;
  out[offset + 1] = y * k;
  out[offset + 2] = z * k;
  return out;
}

/**
 * Maps a drawn place (x, y, z) back to the heliocentric vector (AU) drawn there, written into
 * out[offset..offset+2] (the inverse of `toDisplay`). @returns out.
 */
export function fromDisplay<T extends { [index: number]: number }>(
  x: number,
  y: number,
  z: number,
  trueScale: number,
  out: T,
  offset = 0,
): T {
  const rho = Math.hypot(x, y, z);
  const k = rho > 0 ? trueRadius(rho, trueScale) / rho : 1;
  out[offset] = x * k;
  out[offset + 1] = y * k;
  out[offset + 2] = z * k;
  return out;
}
