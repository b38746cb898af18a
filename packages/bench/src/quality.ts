/**
 * Quality metrics of a settled pile, computed from a snapshot the same way for every engine.
 */

/** Result of `maxBallOverlap`. */
export interface OverlapResult {
  /** Largest overlap r_i + r_j - |x_i - x_j| over all pairs of balls, m (0 if none touch). */
  readonly maxOverlap: number;
  /** The same as a percentage of the radius of the smaller ball of that pair. */
  readonly maxOverlapPercent: number;
  /** Pairs that overlap at all (centre distance below the sum of radii minus 1e-9 m). */
  readonly overlappingPairs: number;
}

/** Multiplicative hash of an integer cell coordinate pair (or triple); any fixed odd constants do. */
function hashCell(cx: number, cy: number, cz: number): number {
  return (Math.imul(cx, 73856093) ^ Math.imul(cy, 19349663) ^ Math.imul(cz, 83492791)) >>> 0;
}

/**
 * Largest overlap between any two balls, found with a uniform grid (not all pairs): cells of edge
 * twice the largest radius in a hash table sorted by counting sort, each ball tested against the
 * balls of its own and neighbouring cells. O(n) for a pile of equal balls.
 *
 * @param positions centres, m, `dimensions` numbers a ball.
 * @param radius one radius for all balls, m, or one a ball.
 * @param dimensions 2 or 3.
 */
export function maxBallOverlap(positions: Float64Array, radius: number | Float64Array, dimensions: 2 | 3): OverlapResult {
  const n = Math.floor(positions.length / dimensions);
  const r = (i: number): number => (typeof radius === 'number' ? radius : radius[i]!);
  let rMax = 0;
  for (let i = 0; i < n; i++) rMax = Math.max(rMax, r(i));
  if (n < 2 || !(rMax > 0)) return { maxOverlap: 0, maxOverlapPercent: 0, overlappingPairs: 0 };
  const cell = 2 * rMax;
  const inv = 1 / cell;
  let table = 16;
  while (table < 2 * n) table *= 2;
  const mask = table - 1;
  const cx = new Int32Array(n),
    cy = new Int32Array(n),
    cz = new Int32Array(n);
  const start = new Int32Array(table + 1);
  const bucket = new Int32Array(n);
  for (let i = 0; i < n; i++) {
    const o = i * dimensions;
    cx[i] = Math.floor(positions[o]! * inv);
    cy[i] = Math.floor(positions[o + 1]! * inv);
    cz[i] = dimensions === 3 ? Math.floor(positions[o + 2]! * inv) : 0;
    const b = hashCell(cx[i]!, cy[i]!, cz[i]!) & mask;
    bucket[i] = b;
    start[b + 1]!++;
  }
  for (let b = 0; b < table; b++) start[b + 1]! += start[b]!;
  const cursor = start.slice(0, table);
  const sorted = new Int32Array(n);
  for (let i = 0; i < n; i++) sorted[cursor[bucket[i]!]!++] = i;

  let deepest = 0,
    deepestPercent = 0,
    overlapping = 0;
  const zRange = dimensions === 3 ? 1 : 0;
  for (let i = 0; i < n; i++) {
    const o = i * dimensions;
    const x = positions[o]!,
      y = positions[o + 1]!,
      z = dimensions === 3 ? positions[o + 2]! : 0;
    const ri = r(i);
    for (let dz = -zRange; dz <= zRange; dz++)
      for (let dy = -1; dy <= 1; dy++)
        for (let dx = -1; dx <= 1; dx++) {
          const nx = cx[i]! + dx,
            ny = cy[i]! + dy,
            nz = cz[i]! + dz;
          const b = hashCell(nx, ny, nz) & mask;
          for (let q = start[b]!, end = start[b + 1]!; q < end; q++) {
            const j = sorted[q]!;
            // Each unordered pair once; skip other cells sharing the bucket.
            if (j <= i || cx[j] !== nx || cy[j] !== ny || cz[j] !== nz) continue;
            const p = j * dimensions;
            const ex = positions[p]! - x,
              ey = positions[p + 1]! - y,
              ez = dimensions === 3 ? positions[p + 2]! - z : 0;
            const rj = r(j);
            const overlap = ri + rj - Math.sqrt(ex * ex + ey * ey + ez * ez);
            if (overlap > 1e-9) overlapping++;
            if (overlap > deepest) deepest = overlap;
            const percent = (100 * overlap) / Math.min(ri, rj);
            if (percent > deepestPercent) deepestPercent = percent;
          }
        }
  }
  return { maxOverlap: deepest, maxOverlapPercent: deepestPercent, overlappingPairs: overlapping };
}

/**
 * Deepest penetration of any ball into the walls of the axis-aligned box [min, max] (inner
 * corners), m: max over balls and faces of r - (distance from the centre to the face), or 0.
 * Balls whose centre left the box count with their full distance outside plus their radius.
 */
export function maxWallPenetration(
  positions: Float64Array,
  radius: number | Float64Array,
  dimensions: 2 | 3,
  min: ArrayLike<number>,
  max: ArrayLike<number>,
): number {
  const n = Math.floor(positions.length / dimensions);
  let deepest = 0;
  for (let i = 0; i < n; i++) {
    const ri = typeof radius === 'number' ? radius : radius[i]!;
    for (let k = 0; k < dimensions; k++) {
      const p = positions[i * dimensions + k]!;
      const low = ri - (p - min[k]!),
        high = ri - (max[k]! - p);
      if (low > deepest) deepest = low;
      if (high > deepest) deepest = high;
    }
  }
  return deepest;
}
