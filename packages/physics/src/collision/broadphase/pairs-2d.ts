import { MOVING, type ShapeScratch } from '../manifolds-2d.js';

/**
 * The shape broadphase of the 2D collide stage (collision/shapes-2d.ts gathers the colliders and runs
 * the narrowphase): a uniform grid of the colliders' fattened boxes, each filed under the cell of its
 * lower corner and met through half its neighbourhood; colliders much larger than the mean stay out
 * of the grid and are tested against each other and against the grid cells their boxes cover.
 */

/** Colliders wider than this many times the mean box width skip the grid. */
const OVERSIZED_FACTOR = 4;

/** Hash of grid cell (cx, cy) (Teschner et al.'s primes). */
function hashCell(cx: number, cy: number): number {
  return (Math.imul(cx, 73856093) ^ Math.imul(cy, 19349663)) >>> 0;
}

/** Candidate pairs a collider findPairs makes room for before its search (8 bytes each). */
const PAIRS_PER_COLLIDER = 6;

/** Half neighbourhood of the lower-corner grid (see the module comment of collision/shapes-2d.ts). */
const HALF = [1, 0, 1, 1, 0, 1, -1, 1];

/**
 * Fills the candidate pairs of colliders whose fattened boxes overlap (before filtering), into
 * sc.pairI/sc.pairJ; `anyMoving` false skips the search (nothing can have met).
 * @category Collision
 */
export function findPairs(sc: ShapeScratch, anyMoving: boolean): void {
  const n = sc.count;
  sc.pairCount = 0;
  if (n < 2 || !anyMoving) return;
  // Room for PAIRS_PER_COLLIDER pairs a collider up front (a pile of boxes finds about 5 to 10), so a
  // scene's first search doubles the pair arrays once at most rather than from 1,024 up.
  if (sc.pairI.length < PAIRS_PER_COLLIDER * n) growPairs(sc, PAIRS_PER_COLLIDER * n);
  const fl = sc.flags;
  const minX = sc.minX,
    minY = sc.minY,
    maxX = sc.maxX,
    maxY = sc.maxY;
  let mean = 0;
  for (let i = 0; i < n; i++) mean += Math.max(maxX[i]! - minX[i]!, maxY[i]! - minY[i]!);
  mean /= n;
  const limit = OVERSIZED_FACTOR * mean;
  let cell = 0;
  for (let i = 0; i < n; i++) {
    const w = Math.max(maxX[i]! - minX[i]!, maxY[i]! - minY[i]!);
    if (w <= limit && w > cell) cell = w;
  }
  const inv = 1 / cell;
  let table = 16;
  while (table < 2 * n) table *= 2;
  const start = sc.bucketStart.length < table + 1 ? growBuckets(sc, table + 1) : sc.bucketStart,
    mask = table - 1;
  start.fill(0, 0, table + 1);
  const cellX = sc.cellX,
    cellY = sc.cellY,
    bucket = sc.bucket,
    sorted = sc.sorted,
    over = sc.oversized;
  let overCount = 0;
  for (let i = 0; i < n; i++) {
    const w = Math.max(maxX[i]! - minX[i]!, maxY[i]! - minY[i]!);
    if (w > limit) {
      bucket[i] = -1;
      over[overCount++] = i;
      continue;
    }
    const cx = Math.floor(minX[i]! * inv),
      cy = Math.floor(minY[i]! * inv);
    cellX[i] = cx;
    cellY[i] = cy;
    const b = hashCell(cx, cy) & mask;
    bucket[i] = b;
    start[b + 1]!++;
  }
  for (let b = 0; b < table; b++) start[b + 1]! += start[b]!;
  for (let i = 0; i < n; i++) {
    const b = bucket[i]!;
    if (b >= 0) sorted[start[b]!++] = i;
  }
  for (let b = table; b > 0; b--) start[b] = start[b - 1]!;
  start[0] = 0;
  const small = n - overCount;

  for (let p = 0; p < small; p++) {
    const i = sorted[p]!;
    const mi = fl[i]! & MOVING;
    const cx = cellX[i]!,
      cy = cellY[i]!;
    const ax0 = minX[i]!,
      ay0 = minY[i]!,
      ax1 = maxX[i]!,
      ay1 = maxY[i]!;
    const own = bucket[i]!;
    for (let q = p + 1, end = start[own + 1]!; q < end; q++) {
      const j = sorted[q]!;
      if (cellX[j] !== cx || cellY[j] !== cy || (mi | (fl[j]! & MOVING)) === 0) continue;
      if (minX[j]! <= ax1 && maxX[j]! >= ax0 && minY[j]! <= ay1 && maxY[j]! >= ay0) pushPair(sc, i, j);
    }
    for (let k = 0; k < 8; k += 2) {
      const nx = cx + HALF[k]!,
        ny = cy + HALF[k + 1]!;
      const bk = hashCell(nx, ny) & mask;
      for (let q = start[bk]!, end = start[bk + 1]!; q < end; q++) {
        const j = sorted[q]!;
        if (cellX[j] !== nx || cellY[j] !== ny || (mi | (fl[j]! & MOVING)) === 0) continue;
        if (minX[j]! <= ax1 && maxX[j]! >= ax0 && minY[j]! <= ay1 && maxY[j]! >= ay0) pushPair(sc, i, j);
      }
    }
  }
  for (let a = 0; a < overCount; a++) {
    const i = over[a]!;
    const mi = fl[i]! & MOVING;
    const ax0 = minX[i]!,
      ay0 = minY[i]!,
      ax1 = maxX[i]!,
      ay1 = maxY[i]!;
    for (let b2 = a + 1; b2 < overCount; b2++) {
      const j = over[b2]!;
      if ((mi | (fl[j]! & MOVING)) === 0) continue;
      if (minX[j]! <= ax1 && maxX[j]! >= ax0 && minY[j]! <= ay1 && maxY[j]! >= ay0) pushPair(sc, i, j);
    }
    // Ordinary boxes overlapping this one have their lower corner in [min - cell, max].
    const cx0 = Math.floor((ax0 - cell) * inv),
      cx1 = Math.floor(ax1 * inv);
    const cy0 = Math.floor((ay0 - cell) * inv),
      cy1 = Math.floor(ay1 * inv);
    if ((cx1 - cx0 + 1) * (cy1 - cy0 + 1) > small) {
      for (let p = 0; p < small; p++) {
        const j = sorted[p]!;
        if ((mi | (fl[j]! & MOVING)) === 0) continue;
        if (minX[j]! <= ax1 && maxX[j]! >= ax0 && minY[j]! <= ay1 && maxY[j]! >= ay0) pushPair(sc, i, j);
      }
      continue;
    }
    for (let cy = cy0; cy <= cy1; cy++) {
      for (let cx = cx0; cx <= cx1; cx++) {
        const bk = hashCell(cx, cy) & mask;
        for (let q = start[bk]!, end = start[bk + 1]!; q < end; q++) {
          const j = sorted[q]!;
          if (cellX[j] !== cx || cellY[j] !== cy || (mi | (fl[j]! & MOVING)) === 0) continue;
          if (minX[j]! <= ax1 && maxX[j]! >= ax0 && minY[j]! <= ay1 && maxY[j]! >= ay0) pushPair(sc, i, j);
        }
      }
    }
  }
}

function pushPair(sc: ShapeScratch, i: number, j: number): void {
  const k = sc.pairCount;
  if (k >= sc.pairI.length) growPairs(sc, k * 2);
  sc.pairI[k] = i;
  sc.pairJ[k] = j;
  sc.pairCount = k + 1;
}

/** A new sc.bucketStart of `size` entries, returned (out of line from findPairs, as growPairs). */
function growBuckets(sc: ShapeScratch, size: number): Int32Array {
  sc.bucketStart = new Int32Array(size);
  return sc.bucketStart;
}

/**
 * Grows sc.pairI/sc.pairJ to `size` pairs, keeping the pairs found so far. A function of its own,
 * not in pushPair: findPairs inlines pushPair at each of its call sites, and an allocation and copy
 * of typed arrays inlined there made findPairs several times costlier for V8 to compile (in a scene's
 * first steps, on the threads the step shares the machine with).
 */
function growPairs(sc: ShapeScratch, size: number): void {
  const a = new Int32Array(size),
    b = new Int32Array(size);
  a.set(sc.pairI);
  b.set(sc.pairJ);
  sc.pairI = a;
  sc.pairJ = b;
}
