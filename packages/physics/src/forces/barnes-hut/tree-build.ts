import { nowMs } from '../../threads/adaptive.js';
import type { KernelArray } from '../../threads/kernel-types.js';
import { MIN_PARALLEL_PER_THREAD } from '../../threads/parallel.js';
import type { ThreadPool } from '../../threads/pool.js';
import * as BOX from './bounds.js';
import * as TASK from './build-task.js';
import { mortonBucketSort, mortonKeysHist, mortonScatter, sortDigitBits } from './gather.js';
import { treeMoments } from './moments.js';
import * as MOMENTS from './slots/moments.js';
import * as SORT from './slots/morton-sort.js';
import { type GravityTree, growBodies, growNodes, i32, LEAF_SIZE, MAX_DEPTH, MAX_PARTS, MIN_CELL_FRACTION } from './tree-store.js';

/**
 * Building the Barnes-Hut tree (see tree.ts for the method): the Morton sort of the bodies, the split of
 * cells past the key resolution, and the upward pass of cell moments, on one thread or several.
 */

/** Bits per axis of the Morton keys: 2 x 16 = 32 in 2D, 3 x 10 = 30 in 3D. */
const KEY_BITS2 = 16,
  KEY_BITS3 = 10;

/**
 * Builds the tree over n bodies with positions (x, y, z), m, and masses m, kg (>= 0), arrays indexed
 * 0..n-1 (z is ignored in 2D). Bodies of zero mass are kept (they still get a field) but weigh
 * nothing. A non-finite position (NaN, infinite) builds no tree and makes every field NaN, so that the
 * integrator reports the body instead of the tree degenerating into one O(N^2) leaf.
 *
 * The bodies are sorted by Morton (Z-order) key, computed in the root cube (16 bits per axis in 2D,
 * 10 in 3D) by a stable least-significant-digit radix sort, so the quadtree's cells down to the key
 * resolution are contiguous key ranges; cells still holding more than LEAF_SIZE bodies below that
 * resolution are split further by a stable counting sort on the positions.
 *
 * `bounds`, when given, is the bodies' bounding box already known (a gathered range's box,
 * forces/barnes-hut/bounds.ts; default null: computed here); with `pool` (default null: this thread)
 * the Morton keys are computed on its threads when the arrays are shared and the bodies many enough
 * (MIN_PARALLEL_PER_THREAD a thread).
 * @category Forces
 */
export function buildTree(
  t: GravityTree,
  n: number,
  x: ArrayLike<number>,
  y: ArrayLike<number>,
  z: ArrayLike<number>,
  m: ArrayLike<number>,
  bounds: Float64Array | null = null,
  pool: ThreadPool | null = null,
): void {
  const is3D = t.dims === 3;
  growBodies(t, n);
  let minX = Infinity,
    minY = Infinity,
    minZ = Infinity,
    maxX = -Infinity,
    maxY = -Infinity,
    maxZ = -Infinity;
  let bad = false;
  if (bounds !== null) {
    minX = bounds[BOX.MIN_X]!;
    minY = bounds[BOX.MIN_Y]!;
    minZ = bounds[BOX.MIN_Z]!;
    maxX = bounds[BOX.MAX_X]!;
    maxY = bounds[BOX.MAX_Y]!;
    maxZ = bounds[BOX.MAX_Z]!;
    bad = bounds[BOX.NON_FINITE] !== 0;
  } else {
    for (let i = 0; i < n; i++) {
      const px = x[i]!,
        py = y[i]!;
      if (px < minX) minX = px;
      if (px > maxX) maxX = px;
      if (py < minY) minY = py;
      if (py > maxY) maxY = py;
      if (px - px !== 0 || py - py !== 0) bad = true; // NaN or infinite
      if (is3D) {
        const pz = z[i]!;
        if (pz < minZ) minZ = pz;
        if (pz > maxZ) maxZ = pz;
        if (pz - pz !== 0) bad = true;
      }
    }
  }
  if (!is3D) {
    minZ = 0;
    maxZ = 0;
  }
  t.n = n;
  t.nodeCount = 0;
  t.nonFinite = bad;
  if (bad) {
    // No tree: every field is NaN (see treeFieldsSorted), so the integrator reports the body.
    for (let i = 0; i < n; i++) {
      t.perm[i] = i;
      t.slot[i] = i;
      t.x[i] = x[i]!;
      t.y[i] = y[i]!;
      t.z[i] = is3D ? z[i]! : 0;
      t.m[i] = m[i]!;
    }
    return;
  }
  if (n === 0) return;
  const half = 0.5 * Math.max(maxX - minX, maxY - minY, maxZ - minZ) * (1 + 1e-9) + 1e-300;
  const cx = 0.5 * (minX + maxX),
    cy = 0.5 * (minY + maxY),
    cz = 0.5 * (minZ + maxZ);
  t.minHalf = half * MIN_CELL_FRACTION;
  // Morton keys in the root cube [c - half, c + half]^d.
  const bits = is3D ? KEY_BITS3 : KEY_BITS2,
    top = (1 << bits) - 1;
  const scale = half > 0 && half < Infinity ? (1 << bits) / (2 * half) : 0;
  const x0 = cx - half,
    y0 = cy - half,
    z0 = cz - half;
  const KP = t.keyParams;
  KP[SORT.X0] = x0;
  KP[SORT.Y0] = y0;
  KP[SORT.Z0] = z0;
  KP[SORT.SCALE] = scale;
  KP[SORT.TOP] = top;
  KP[SORT.DIMENSIONS] = t.dims;
  const digitBits = sortDigitBits(n);
  KP[SORT.COUNT] = n;
  KP[SORT.SHIFT] = (is3D ? 3 * KEY_BITS3 : 2 * KEY_BITS2) - digitBits;
  KP[SORT.BITS] = digitBits;
  mortonSort(t, n, x, y, z, m, pool);
  growNodes(t, Math.max(64, Math.ceil((3 * n) / LEAF_SIZE) + 64));
  splitCells(t, n, cx, cy, cz, half, bits);
  treeMomentsAll(t, pool);
}

/**
 * The Morton sort of buildTree and the bodies into tree order: keys (t.key, t.perm) in (key, input
 * index) order, the order of a stable sort, and t.x, t.y, t.z, t.m, t.perm in that order. Three
 * kernels (forces/barnes-hut/gather.ts): the keys with each part's histogram of the first digit (the top
 * sortDigitBits(n) bits), the parts' bodies to their buckets in order, then the buckets sorted by
 * the bits below and the bodies put into tree order, each part a run of buckets holding about n /
 * parts bodies. On `pool`'s threads (one part a thread) when the tree's arrays are shared and the
 * bodies many enough (MIN_PARALLEL_PER_THREAD a thread), and an adaptive pool has found that faster;
 * else here as one part. The order does not depend on the parts, so neither does the tree.
 * The parameters (t.keyParams: forces/barnes-hut/slots/morton-sort.ts) are set by the caller but for the part count.
 */
function mortonSort(
  t: GravityTree,
  n: number,
  x: ArrayLike<number>,
  y: ArrayLike<number>,
  z: ArrayLike<number>,
  m: ArrayLike<number>,
  pool: ThreadPool | null,
): void {
  let parts =
    pool !== null && t.shared && pool.threads <= MAX_PARTS && n >= MIN_PARALLEL_PER_THREAD * pool.threads && pool.usable()
      ? pool.threads
      : 1;
  const site = 'barnes-hut sort';
  const adaptive = parts > 1 && pool!.adaptive;
  if (adaptive && !pool!.chooser.choose(site)) parts = 1;
  const t0 = adaptive ? nowMs() : 0;
  const R = 1 << t.keyParams[SORT.BITS]!;
  if (t.sortHist.length < parts * R) {
    const size = Math.max(parts, pool?.threads ?? 1) * R;
    t.sortHist = i32(t, size);
    t.sortOffset = i32(t, size);
  }
  if (t.sortBucket.length < R + 1) t.sortBucket = i32(t, R + 1);
  if (t.sortLocal.length < parts * SORT.BUCKET_RADIX) t.sortLocal = i32(t, Math.max(parts, pool?.threads ?? 1) * SORT.BUCKET_RADIX);
  const hist = t.sortHist,
    offset = t.sortOffset,
    bucket = t.sortBucket,
    group = t.sortGroup,
    P = t.keyParams;
  P[SORT.PARTS] = parts;
  const system = 'mutualGravitySystem (Barnes-Hut sort)';
  const A1 = t.sortLists[0]!,
    A2 = t.sortLists[1]!,
    A3 = t.sortLists[2]!;
  A1.length = 0;
  A1[SORT.KEYS_X] = x as Float64Array;
  A1[SORT.KEYS_Y] = y as Float64Array;
  A1[SORT.KEYS_Z] = z as Float64Array;
  A1[SORT.KEYS_KEY] = t.key;
  A1[SORT.KEYS_HIST] = hist;
  if (parts > 1) pool!.run(system, mortonKeysHist, A1, P, parts, null);
  else mortonKeysHist(A1, P, null, 0, 1);
  // First places of each (digit, part), digit-major (so the pass is stable), and each bucket's first slot.
  let acc = 0;
  for (let r = 0; r < R; r++) {
    bucket[r] = acc;
    for (let p = 0; p < parts; p++) {
      const c = hist[p * R + r]!;
      offset[p * R + r] = acc;
      acc += c;
    }
  }
  bucket[R] = acc;
  A2.length = 0;
  A2[SORT.SCATTER_KEY] = t.key;
  A2[SORT.SCATTER_KEY2] = t.key2;
  A2[SORT.SCATTER_IDX2] = t.idx2;
  A2[SORT.SCATTER_OFFSET] = offset;
  if (parts > 1) pool!.run(system, mortonScatter, A2, P, parts, null);
  else mortonScatter(A2, P, null, 0, 1);
  // Runs of buckets of about n / parts bodies each, for the last pass.
  group[0] = 0;
  let r = 0;
  for (let q = 1; q < parts; q++) {
    const goal = (n * q) / parts;
    while (r < R && bucket[r + 1]! <= goal) r++;
    group[q] = r;
  }
  group[parts] = R;
  A3.length = 0;
  A3[SORT.BUCKETS_KEY2] = t.key2;
  A3[SORT.BUCKETS_IDX2] = t.idx2;
  A3[SORT.BUCKETS_KEY] = t.key;
  A3[SORT.BUCKETS_PERM] = t.perm;
  A3[SORT.BUCKETS_FIRST] = bucket;
  A3[SORT.BUCKETS_GROUP] = group;
  A3[SORT.BUCKETS_LOCAL] = t.sortLocal;
  A3[SORT.BUCKETS_X] = x as Float64Array;
  A3[SORT.BUCKETS_Y] = y as Float64Array;
  A3[SORT.BUCKETS_Z] = z as Float64Array;
  A3[SORT.BUCKETS_MASS] = m as Float64Array;
  A3[SORT.BUCKETS_TX] = t.x;
  A3[SORT.BUCKETS_TY] = t.y;
  A3[SORT.BUCKETS_TZ] = t.z;
  A3[SORT.BUCKETS_TM] = t.m;
  if (parts > 1) pool!.run(system, mortonBucketSort, A3, P, parts, null);
  else mortonBucketSort(A3, P, null, 0, 1);
  if (adaptive) pool!.chooser.record(site, parts > 1, nowMs() - t0, n);
}

/** Fewest tree nodes a thread for the leaves' moments to be computed in parallel. */
const MIN_NODES_PER_THREAD = 4096;

/**
 * Top-down split of the root cell [0, n) into nodes in depth-first preorder, with an explicit task
 * stack (no recursion). A task is a cell: its slots [lo, hi), whether their data is in the first
 * buffer or the second, its depth, its parent node, centre and half edge. Down to the key resolution
 * (depth < bits) the bodies are already in order and the children are the runs of equal key digits;
 * deeper, a split moves the cell's bodies into the other buffer, grouped by quadrant, and leaves copy
 * theirs back to the first buffer.
 */
function splitCells(t: GravityTree, n: number, cx: number, cy: number, cz: number, half: number, bits: number): void {
  const is3D = t.dims === 3,
    kids = is3D ? 8 : 4,
    dims = is3D ? 3 : 2;
  const cnt = t.counts,
    code = t.code,
    key = t.key;
  let ti = t.taskI,
    tf = t.taskF;
  ti[TASK.LO] = 0;
  ti[TASK.HI] = n;
  ti[TASK.IN_FIRST] = 1;
  ti[TASK.DEPTH] = 0;
  ti[TASK.PARENT] = -1;
  tf[TASK.CX] = cx;
  tf[TASK.CY] = cy;
  tf[TASK.CZ] = cz;
  tf[TASK.HALF] = half;
  let tp = 1;
  const minHalf = t.minHalf;
  while (tp > 0) {
    tp--;
    const oi = tp * TASK.INT_STRIDE,
      of = tp * TASK.FLOAT_STRIDE;
    const lo = ti[oi + TASK.LO]!,
      hi = ti[oi + TASK.HI]!,
      inA = ti[oi + TASK.IN_FIRST] === 1,
      depth = ti[oi + TASK.DEPTH]!,
      parent = ti[oi + TASK.PARENT]!;
    const ccx = tf[of + TASK.CX]!,
      ccy = tf[of + TASK.CY]!,
      ccz = tf[of + TASK.CZ]!,
      h = tf[of + TASK.HALF]!;
    const k = t.nodeCount++;
    if (k >= t.start.length) growNodes(t, k + 1);
    t.start[k] = lo;
    t.end[k] = hi;
    t.skip[k] = k + 1;
    t.parent[k] = parent;
    if (hi - lo <= LEAF_SIZE || !(h > minHalf) || depth >= MAX_DEPTH - 1) {
      if (!inA) {
        const { x, y, z } = t,
          m = t.m,
          p = t.perm,
          x2 = t.x2,
          y2 = t.y2,
          z2 = t.z2,
          m2 = t.m2,
          p2 = t.perm2;
        for (let s = lo; s < hi; s++) {
          x[s] = x2[s]!;
          y[s] = y2[s]!;
          z[s] = z2[s]!;
          m[s] = m2[s]!;
          p[s] = p2[s]!;
        }
      }
      continue;
    }
    let movedTo = inA;
    if (depth < bits) {
      // Runs of equal key digit at this level, in order. The cell's keys are sorted and share every
      // digit above this one, so this digit never decreases over [lo, hi): each run ends where a
      // binary search finds the first larger digit (a few probes a child instead of a pass over the
      // cell's keys at every level; the same counts).
      const shift = dims * (bits - 1 - depth),
        mask = kids - 1;
      let from = lo;
      cnt.fill(0, 0, 8);
      if (hi - lo <= 32) {
        // A small cell: one pass over its keys costs less than the searches.
        for (let s = lo; s < hi; s++) cnt[(key[s]! >>> shift) & mask]!++;
        from = hi;
      }
      for (let q = 0; q < kids && from < hi; q++) {
        let a = from,
          b = hi;
        while (a < b) {
          const mid = (a + b) >>> 1;
          if (((key[mid]! >>> shift) & mask) <= q) a = mid + 1;
          else b = mid;
        }
        cnt[q] = a - from;
        from = a;
      }
    } else {
      // Below the key resolution: stable counting sort by quadrant into the other buffer.
      const sx = inA ? t.x : t.x2,
        sy = inA ? t.y : t.y2,
        sz = inA ? t.z : t.z2,
        sm = inA ? t.m : t.m2,
        sp = inA ? t.perm : t.perm2;
      const dx = inA ? t.x2 : t.x,
        dy = inA ? t.y2 : t.y,
        dz = inA ? t.z2 : t.z,
        dm = inA ? t.m2 : t.m,
        dp = inA ? t.perm2 : t.perm;
      cnt.fill(0, 0, 16);
      for (let s = lo; s < hi; s++) {
        const q = (sx[s]! >= ccx ? 1 : 0) | (sy[s]! >= ccy ? 2 : 0) | (is3D && sz[s]! >= ccz ? 4 : 0);
        code[s] = q;
        cnt[q]!++;
      }
      let acc = lo;
      for (let q = 0; q < kids; q++) {
        cnt[8 + q] = acc;
        acc += cnt[q]!;
      }
      for (let s = lo; s < hi; s++) {
        const d = cnt[8 + code[s]!]!++;
        dx[d] = sx[s]!;
        dy[d] = sy[s]!;
        dz[d] = sz[s]!;
        dm[d] = sm[s]!;
        dp[d] = sp[s]!;
      }
      movedTo = !inA;
    }
    // Children as tasks, last quadrant pushed first so that quadrant 0 is built next (preorder).
    const hh = 0.5 * h;
    if ((tp + kids) * TASK.INT_STRIDE > ti.length) {
      growTasks(t, tp + kids);
      ti = t.taskI;
      tf = t.taskF;
    }
    let end = hi;
    for (let q = kids - 1; q >= 0; q--) {
      const c = cnt[q]!;
      if (c === 0) continue;
      const ci = tp * TASK.INT_STRIDE,
        cf = tp * TASK.FLOAT_STRIDE;
      ti[ci + TASK.LO] = end - c;
      ti[ci + TASK.HI] = end;
      ti[ci + TASK.IN_FIRST] = movedTo ? 1 : 0;
      ti[ci + TASK.DEPTH] = depth + 1;
      ti[ci + TASK.PARENT] = k;
      tf[cf + TASK.CX] = ccx + (q & 1 ? hh : -hh);
      tf[cf + TASK.CY] = ccy + (q & 2 ? hh : -hh);
      tf[cf + TASK.CZ] = is3D ? ccz + (q & 4 ? hh : -hh) : 0;
      tf[cf + TASK.HALF] = hh;
      tp++;
      end -= c;
    }
  }
}

function growTasks(t: GravityTree, needed: number): void {
  const size = Math.max(needed, 2 * (t.taskF.length / TASK.FLOAT_STRIDE));
  const i = new Int32Array(size * TASK.INT_STRIDE);
  i.set(t.taskI);
  t.taskI = i;
  const f = new Float64Array(size * TASK.FLOAT_STRIDE);
  f.set(t.taskF);
  t.taskF = f;
}

/**
 * Subtree ends (skip) and the moments of every node (kernel treeMoments, moments.ts), children before parents.
 * With `pool` (shared tree arrays, at least MIN_NODES_PER_THREAD nodes a thread, and an adaptive
 * pool finding it faster), the tree is cut into its largest subtrees of at most 1 / (8 parts) of
 * the nodes, handed out to the threads in runs of about equal node counts, and the few nodes above
 * them (their ancestors) are done afterwards on this thread, deepest first. Each node's moments
 * come from its own bodies or its children's moments alone, so they do not depend on the cut.
 */
function treeMomentsAll(t: GravityTree, pool: ThreadPool | null): void {
  const nc = t.nodeCount,
    skip = t.skip,
    parent = t.parent;
  for (let k = nc - 1; k > 0; k--) {
    const p = parent[k]!;
    if (skip[k]! > skip[p]!) skip[p] = skip[k]!;
  }
  let parts =
    pool !== null && t.shared && pool.threads <= MAX_PARTS && nc >= MIN_NODES_PER_THREAD * pool.threads && pool.usable() ? pool.threads : 1;
  const site = 'barnes-hut moments';
  const adaptive = parts > 1 && pool!.adaptive;
  if (adaptive && !pool!.chooser.choose(site)) parts = 1;
  const t0 = adaptive ? nowMs() : 0;
  if (t.momentList.length < nc) t.momentList = i32(t, Math.max(nc, 2 * t.momentList.length));
  const list = t.momentList,
    cut = t.momentCut,
    top = t.momentTop;
  let nl = 0,
    ntop = 0;
  if (parts === 1) {
    list[nl++] = 0;
  } else {
    // The largest subtrees of at most `bound` nodes, in preorder; the nodes above them into `top`.
    const bound = Math.max(1, Math.floor(nc / (8 * parts)));
    for (let k = 0; k < nc; ) {
      if (skip[k]! - k <= bound) {
        list[nl++] = k;
        k = skip[k]!;
      } else {
        if (ntop >= top.length) {
          const grown = new Int32Array(2 * top.length);
          grown.set(top);
          t.momentTop = grown;
        }
        t.momentTop[ntop++] = k;
        k++;
      }
    }
  }
  // Runs of subtrees of about equal node counts.
  const total = nc - ntop;
  let acc = 0,
    q = 1;
  cut[0] = 0;
  for (let i = 0; i < nl; i++) {
    while (q < parts && acc >= (total * q) / parts) cut[q++] = i;
    acc += skip[list[i]!]! - list[i]!;
  }
  while (q < parts) cut[q++] = nl;
  cut[parts] = nl;
  const P = t.momentParams;
  P[MOMENTS.ALONE] = 0;
  P[MOMENTS.DIMENSIONS] = t.dims;
  const A = momentArrays(t, t.momentLists[0]!, list, cut);
  if (parts > 1) pool!.run('mutualGravitySystem (Barnes-Hut moments)', treeMoments, A, P, parts, null);
  else treeMoments(A, P, null, 0, 1);
  if (ntop > 0) {
    // The nodes above the subtrees, deepest first (descending index: children before parents).
    const down = t.momentDown.length >= ntop ? t.momentDown : (t.momentDown = new Int32Array(2 * ntop));
    for (let i = 0; i < ntop; i++) down[i] = t.momentTop[ntop - 1 - i]!;
    const cut1 = t.momentCut1;
    cut1[0] = 0;
    cut1[1] = ntop;
    P[MOMENTS.ALONE] = 1;
    treeMoments(momentArrays(t, t.momentLists[1]!, down, cut1), P, null, 0, 1);
  }
  if (adaptive) pool!.chooser.record(site, parts > 1, nowMs() - t0, nc);
}

/** The moments kernels' arrays (forces/barnes-hut/slots/moments.ts) in the list `A`, for the nodes `list` cut into parts at `cut`. */
function momentArrays(t: GravityTree, A: KernelArray[], list: Int32Array, cut: Int32Array): KernelArray[] {
  A.length = 0;
  A[MOMENTS.X] = t.x;
  A[MOMENTS.Y] = t.y;
  A[MOMENTS.Z] = t.z;
  A[MOMENTS.MASS] = t.m;
  A[MOMENTS.NODE] = t.node;
  A[MOMENTS.BOX] = t.box;
  A[MOMENTS.START] = t.start;
  A[MOMENTS.END] = t.end;
  A[MOMENTS.SKIP] = t.skip;
  A[MOMENTS.PERM] = t.perm;
  A[MOMENTS.SLOT] = t.slot;
  A[MOMENTS.LIST] = list;
  A[MOMENTS.CUT] = cut;
  return A;
}
