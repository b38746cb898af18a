/**
 * Quality metrics of a settled pile of equal cubes (3D), computed from a snapshot's centres and
 * orientations the same way for every engine.
 */

/** Result of `maxBoxOverlap3D`. */
export interface BoxOverlapResult {
  /** Largest penetration depth between two cubes, m (0 if none overlap): minus the largest separation over the 15 separating axes. */
  readonly maxOverlap: number;
  /** The same in % of the half extent. */
  readonly maxOverlapPercent: number;
  /** Pairs that overlap by more than 1e-9 m. */
  readonly overlappingPairs: number;
}

/** Rotation matrix (row-major, columns the box axes) of quaternion i of `q` into R. */
function matrix(q: Float64Array, i: number, R: Float64Array, o: number): void {
  let x = q[4 * i]!,
    y = q[4 * i + 1]!,
    z = q[4 * i + 2]!,
    w = q[4 * i + 3]!;
  const l = Math.hypot(x, y, z, w) || 1;
  x /= l;
  y /= l;
  z /= l;
  w /= l;
  R[o] = 1 - 2 * (y * y + z * z);
  R[o + 1] = 2 * (x * y - z * w);
  R[o + 2] = 2 * (x * z + y * w);
  R[o + 3] = 2 * (x * y + z * w);
  R[o + 4] = 1 - 2 * (x * x + z * z);
  R[o + 5] = 2 * (y * z - x * w);
  R[o + 6] = 2 * (x * z - y * w);
  R[o + 7] = 2 * (y * z + x * w);
  R[o + 8] = 1 - 2 * (x * x + y * y);
}

/**
 * Penetration depth of two cubes of half extent h (centres a, b; rotations at RA[oa..], RB[ob..]):
 * minus the largest separation over the separating axes (3 + 3 face normals, 9 edge cross products;
 * Gottschalk et al., "OBBTree", SIGGRAPH 1996), so > 0 means overlap by that much along the best axis.
 */
export function boxPenetration(
  a: Float64Array,
  ia: number,
  b: Float64Array,
  ib: number,
  R: Float64Array,
  oa: number,
  ob: number,
  h: number,
): number {
  const t = [b[3 * ib]! - a[3 * ia]!, b[3 * ib + 1]! - a[3 * ia + 1]!, b[3 * ib + 2]! - a[3 * ia + 2]!];
  const axis = (k: number, o: number): number[] => [R[o + k]!, R[o + 3 + k]!, R[o + 6 + k]!];
  const A = [axis(0, oa), axis(1, oa), axis(2, oa)],
    B = [axis(0, ob), axis(1, ob), axis(2, ob)];
  const dot = (u: number[], v: number[]): number => u[0]! * v[0]! + u[1]! * v[1]! + u[2]! * v[2]!;
  let best = -Infinity;
  const test = (L: number[]): void => {
    const len = Math.hypot(L[0]!, L[1]!, L[2]!);
    if (len < 1e-6) return;
    const r =
      h *
      (Math.abs(dot(A[0]!, L)) +
        Math.abs(dot(A[1]!, L)) +
        Math.abs(dot(A[2]!, L)) +
        Math.abs(dot(B[0]!, L)) +
        Math.abs(dot(B[1]!, L)) +
        Math.abs(dot(B[2]!, L)));
    const s = (Math.abs(dot(t, L)) - r) / len;
    if (s > best) best = s;
  };
  for (const u of A) test(u);
  for (const v of B) test(v);
  for (const u of A) for (const v of B) test([u[1]! * v[2]! - u[2]! * v[1]!, u[2]! * v[0]! - u[0]! * v[2]!, u[0]! * v[1]! - u[1]! * v[0]!]);
  return -best;
}

/**
 * Largest overlap between any two of n equal cubes of half extent `half`, with a uniform grid of cells
 * one circumscribed diameter wide (each cube tested against the cubes of its own and the 26 cells
 * around it). Orientations absent: axis-aligned.
 */
export function maxBoxOverlap3D(positions: Float64Array, orientations: Float64Array | undefined, half: number): BoxOverlapResult {
  const n = Math.floor(positions.length / 3);
  const R = new Float64Array(9 * n);
  const q = orientations ?? new Float64Array(4 * n).map((_, i) => (i % 4 === 3 ? 1 : 0));
  for (let i = 0; i < n; i++) matrix(q, i, R, 9 * i);
  const cell = 2 * half * Math.sqrt(3);
  const cells = new Map<string, number[]>();
  const key = (x: number, y: number, z: number): string => `${x},${y},${z}`;
  for (let i = 0; i < n; i++) {
    const k = key(Math.floor(positions[3 * i]! / cell), Math.floor(positions[3 * i + 1]! / cell), Math.floor(positions[3 * i + 2]! / cell));
    const list = cells.get(k);
    if (list) list.push(i);
    else cells.set(k, [i]);
  }
  let maxOverlap = 0,
    pairs = 0;
  for (let i = 0; i < n; i++) {
    const cx = Math.floor(positions[3 * i]! / cell),
      cy = Math.floor(positions[3 * i + 1]! / cell),
      cz = Math.floor(positions[3 * i + 2]! / cell);
    for (let dx = -1; dx <= 1; dx++)
      for (let dy = -1; dy <= 1; dy++)
        for (let dz = -1; dz <= 1; dz++) {
          for (const j of cells.get(key(cx + dx, cy + dy, cz + dz)) ?? []) {
            if (j <= i) continue;
            const d = Math.hypot(
              positions[3 * j]! - positions[3 * i]!,
              positions[3 * j + 1]! - positions[3 * i + 1]!,
              positions[3 * j + 2]! - positions[3 * i + 2]!,
            );
            if (d >= cell) continue;
            const p = boxPenetration(positions, i, positions, j, R, 9 * i, 9 * j, half);
            if (p > 1e-9) pairs++;
            if (p > maxOverlap) maxOverlap = p;
          }
        }
  }
  return { maxOverlap, maxOverlapPercent: (100 * maxOverlap) / half, overlappingPairs: pairs };
}

/** Deepest a cube of half extent `half` reaches past the walls of the box [min, max], m (0 if none). */
export function maxBoxWallPenetration3D(
  positions: Float64Array,
  orientations: Float64Array | undefined,
  half: number,
  min: readonly number[],
  max: readonly number[],
): number {
  const n = Math.floor(positions.length / 3);
  const R = new Float64Array(9);
  const identity = new Float64Array([0, 0, 0, 1]);
  let worst = 0;
  for (let i = 0; i < n; i++) {
    matrix(orientations ?? identity, orientations ? i : 0, R, 0);
    for (let a = 0; a < 3; a++) {
      const reach = half * (Math.abs(R[3 * a]!) + Math.abs(R[3 * a + 1]!) + Math.abs(R[3 * a + 2]!));
      const c = positions[3 * i + a]!;
      worst = Math.max(worst, min[a]! - (c - reach), c + reach - max[a]!);
    }
  }
  return worst;
}
