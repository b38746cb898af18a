import { nowMs } from '../../threads/adaptive.js';
import type { KernelArray } from '../../threads/kernel-types.js';
import { KERNEL, KERNEL_HELPERS, KERNELS } from '../../threads/kernels.js';
import { MIN_PARALLEL_PER_THREAD, runOnPool } from '../../threads/parallel.js';
import { sharedFloat64, sharedMemoryAvailable, type ThreadPool } from '../../threads/pool.js';
import { CONTROL } from '../../threads/worker-main.js';
import type { PhysicsWorld } from '../../world/options.js';
import {
  BOX_STRIDE,
  BUCKET_RADIX,
  mortonBucketSort,
  mortonKeysHist,
  mortonScatter,
  SORT_PARAMS,
  sortDigitBits,
  treeForces,
  treeGather,
  treeMoments,
} from './gather.js';
import { INFO_STRIDE } from './walk.js';

/**
 * Tree code for mutual gravity: a quadtree in 2D, an octree in 3D, rebuilt over the bodies at every
 * force evaluation (so the force stays a pure function of the positions, as RK4 needs), with Plummer
 * softening and an opening angle theta. Cells interact with cells (a dual-tree walk) through Taylor
 * expansions of the softened potential, so an evaluation costs O(N) after an O(N log N) build, and the
 * forces conserve total momentum to rounding.
 *
 * Sources: Barnes and Hut, Nature 324 (1986) 446 (the tree, the opening angle); Dehnen, ApJ 536
 * (2000) L39 and J. Comput. Phys. 179 (2002) 27 (falcON: mutual cell-cell interactions, the walk,
 * momentum conservation); Greengard and Rokhlin, J. Comput. Phys. 73 (1987) 325 (local expansions);
 * Salmon and Warren, J. Comput. Phys. 111 (1994) 136 (b_max); Warren and Salmon, Supercomputing '93
 * (Morton-ordered trees); Aarseth, Gravitational N-Body Simulations (2003) ch. 2 (Plummer softening).
 *
 * Build. The bodies are sorted by Morton (Z-order) key in the root cube (16 bits per axis in 2D, 10
 * in 3D) into (key, input index) order, the order of a stable sort (mortonSort: buckets of the first
 * sortDigitBits(n) bits, then each bucket on its own), and copied into that order, so every cell holds a contiguous range
 * of bodies and nearby bodies sit near each other in memory. Cells are split into their 4 (8)
 * quadrants down to a leaf of at most LEAF_SIZE bodies: by the key digits down to the key resolution,
 * below it by a stable counting sort on the positions. A cell smaller than MIN_CELL_FRACTION of the
 * root is a leaf whatever it holds (coincident bodies share one leaf and are summed directly). Nodes
 * are stored in depth-first preorder: the first child of node k is k + 1 and `skip[k]` is the node
 * after k's subtree (k + 1 for a leaf); empty quadrants get no node.
 *
 * Moments, about each cell's centre of mass c: mass M, second moment S = sum m (x - c)(x - c)^T, and
 * in 2D the third moment T = sum m (x - c)^3 (combined from the children by the parallel-axis
 * theorem); and r = b_max, a bound on the distance from c to any of the cell's bodies: the smaller of
 * the distance to the farthest corner of its tight bounding box and max over children (|c_child - c| +
 * r_child).
 *
 * Kernel. A body of mass m at y pulls x with G m grad_x g, g = (|y - x|^2 + eps^2)^(-1/2), the Plummer
 * potential; the direct sum and every near interaction here use exactly F = G m m d / (d^2 + eps^2)^(3/2).
 * With u = |R|^2 and D_n = (2 d/du)^n g (D1 = -g^3, D2 = 3 g^5, D3 = -15 g^7, D4 = 105 g^9), the
 * derivative tensors of g at R are T1 = R D1, T2 = R R D2 + I D1, T3 = R R R D3 + (I R)_sym D2,
 * T4 = R R R R D4 + (I R R)_sym D3 + (I I)_sym D2, for any eps: the expansions below are Taylor
 * expansions of the softened potential itself, so small distances need no special case; a cell is
 * only expanded where the series converges, and softening only makes the kernel smoother.
 *
 * Cell-cell interaction (multipole to local, both ways at once). The potential at c_A + delta of B's
 * bodies at c_B + xi, R = c_B - c_A, is -G sum m g(R + xi - delta); expanded to total order p in
 * (xi, delta), the field is a polynomial in delta about c_A:
 *   a(delta) = a0 + J delta + K delta delta / 2 + H delta delta delta / 6, with (p = 4, 2D)
 *   a0 = -G (M_B T1 + T3:S_B / 2 + T4:T_B / 6),  J = G (M_B T2 + T4:S_B / 2),  K = -G M_B T3,  H = G M_B T4,
 * and on B the same with R -> -R (odd tensors change sign). 3D uses p = 3: a0 without the T4 term,
 * J = G M_B T2, no H. Closed forms: T3:S = R (D3 R.S.R + D2 tr S) + 2 D2 S.R; T4:S =
 * R R (D4 R.S.R + D3 tr S) + D3 (I R.S.R + 2 (S.R R + R S.R)) + D2 (I tr S + 2 S); T4:T =
 * R (D4 T:RRR + 3 D3 t.R) + 3 D3 T:RR + 3 D2 t, t_i = T_ijj. The error is O(((r_A + r_B) / |R|)^p)
 * of the monopole field. (Order 4 in 2D because a planar distribution's field nearly cancels, so its
 * relative errors are the large ones: order 3 gave 0.9% median at theta = 0.5 on a 2D uniform
 * square of 100,000 bodies, order 4 gives 0.14%; in 3D order 3 gives 0.05%.) Each cell accumulates
 * these polynomials about its centre of mass; a downward pass shifts them to the children (exactly:
 * they are polynomials) and evaluates them at the bodies. Since everything is expanded about centres
 * of mass with the same tensors both ways, the total forces on A and on B are exactly opposite, as
 * are the direct pair forces: momentum is conserved to rounding.
 *
 * Walk (Dehnen 2002). Starting from the root's self-interaction: a cell's self-interaction becomes
 * those of its children and the interactions of each pair of children; a pair of cells is summed
 * directly (every body pair, once for both) when it holds at most 16 body pairs, interacts
 * by the expansion when |R| > (r_A + r_B) / min(theta, 1) (theta: the opening angle under which the
 * two cells see each other), is summed directly when both are leaves, and otherwise the larger cell
 * (by r) is split. The cells of a pair are disjoint subtrees, so a body is never approximated by a
 * cell containing it and every pair of bodies is counted exactly once, directly or inside one
 * expansion. As theta -> 0 every pair is summed directly and the result is the direct sum, to rounding.
 * (A cell of at most 8 bodies sums its self-interaction directly.)
 *
 * Threads. In a world with threads > 1 (each loop only when long enough, and while an adaptive pool
 * finds the threads faster): the gather with the bounding box, the sort (keys and buckets by ranges
 * of bodies, then runs of buckets a thread, which also put their bodies into tree order) and the
 * moments (whole subtrees a thread; the few nodes above them after, on one thread) run on the
 * threads; the split into cells, cheap once the keys are sorted, stays on one. The walk and the
 * downward pass (forces/barnes-hut/walk.ts, which also adds m g to the bodies' forces) run with the bodies
 * cut into one contiguous part of slots a thread, each part replaying the walk for its own bodies
 * in the one-thread order. Every result is therefore identical to the bit whatever the number of
 * threads. The walk's cuts follow the work each part did at the previous evaluation (counted, not
 * timed), so the parts take about equally long.
 *
 * All arrays live on the tree (one per world), grown by doubling and reused: no allocation per body
 * or per step once they have grown.
 */

/** Most parts (threads) an evaluation is cut into. */
const MAX_PARTS = 32;
/**
 * Fewest bodies a thread for the evaluation to go parallel: below it one thread is faster.
 * @category Forces
 */
export const BARNES_HUT_MIN_PER_THREAD = 2048;

/** Most bodies a leaf holds before it splits. */
const LEAF_SIZE = 8;
/** Cells smaller than this fraction of the root never split (so at most ~31 levels). */
const MIN_CELL_FRACTION = 1e-9;
/** Depth bound: MIN_CELL_FRACTION > 2^-31, with margin. */
const MAX_DEPTH = 64;

/** Float64 slots per node, 2D: [cx, cy, M, Sxx, Sxy, Syy, r, Txxx, Txxy, Txyy, Tyyy, -] (T: third moment). */
const NF2 = 12;
/** 3D: [cx, cy, cz, M, Sxx, Syy, Szz, Sxy, Sxz, Syz, r, -]. */
const NF3 = 12;
/** Local field polynomial per node, 2D: [a0x, a0y, Jxx, Jxy, Jyy, Kxxx, Kxxy, Kxyy, Kyyy, Hxxxx, Hxxxy, Hxxyy, Hxyyy, Hyyyy]. */
const NL2 = 14;
/** 3D: [a0 x y z, J xx yy zz xy xz yz, K xxx xxy xxz xyy xyz xzz yyy yyz yzz zzz]. */
const NL3 = 19;

/**
 * The tree's arrays; one per world, reused between evaluations.
 * @category Forces
 */
export interface GravityTree {
  dims: 2 | 3;
  /** Bodies in the last build. */
  n: number;
  /** Nodes in the last build (depth-first preorder, root 0). */
  nodeCount: number;
  /** Bodies in tree order (slot s): position, m, and mass, kg. Length >= n. */
  x: Float64Array;
  y: Float64Array;
  z: Float64Array;
  m: Float64Array;
  /** perm[s]: input index of the body in slot s; slot[i]: slot of input body i. */
  perm: Int32Array;
  slot: Int32Array;
  /** Second buffer of the partition (ping-pong) and the quadrant of each slot. */
  x2: Float64Array;
  y2: Float64Array;
  z2: Float64Array;
  m2: Float64Array;
  perm2: Int32Array;
  code: Uint8Array;
  /** Per node, stride 12 (layouts at NF2, NF3): centre of mass (m), mass (kg), second moment S (kg m^2), r = b_max (m), 2D third moment T (kg m^3). */
  node: Float64Array;
  /** Per node, stride 6: tight bounding box min x, y, z, max x, y, z, m. */
  box: Float64Array;
  /** Per node: first slot, end slot (exclusive), and the node after its subtree (k + 1 for a leaf). */
  start: Int32Array;
  end: Int32Array;
  skip: Int32Array;
  /**
   * The evaluation's scratch, one array a part (forces/barnes-hut/walk.ts): per node, stride 14 (2D) or 19
   * (3D), the field polynomial about the centre of mass (without G; layouts at NL2, NL3), then the
   * direct sums x, y, z of every slot (without G) from the offsets `accOffset`.
   */
  scratch: Float64Array[];
  /** Offset of the direct sums in each scratch array: node capacity times the polynomial stride. */
  accOffset: number;
  /** Slot boundaries of the parts of the last evaluation (part p: cut[p] .. cut[p + 1] - 1), at leaf starts. */
  cut: Int32Array;
  /** Per part, stride 4: counts and work of the last evaluation (see forces/barnes-hut/walk.ts). */
  info: Float64Array;
  /** Parts of the last evaluation (1 on one thread). */
  parts: number;
  /** Whether the arrays the evaluation reads live on SharedArrayBuffers (a world with threads > 1). */
  shared: boolean;
  /** Scratch of the cuts, the kernel's array list and its parameters (reused). */
  cutWant: Int32Array;
  walkList: KernelArray[];
  walkParams: Float64Array;
  keyParams: Float64Array;
  momentParams: Float64Array;
  /**
   * The Morton sort's scratch (mortonSort): per part, the first digit's histogram and first places
   * (2^keyParams[9] each, at most SORT_RADIX) and a bucket sort's counts (BUCKET_RADIX); each bucket's
   * first slot (2^keyParams[9] + 1), each part's first bucket (MAX_PARTS + 1), and the kernels' array lists.
   */
  sortHist: Int32Array;
  sortOffset: Int32Array;
  sortLocal: Int32Array;
  sortBucket: Int32Array;
  sortGroup: Int32Array;
  sortLists: KernelArray[][];
  /**
   * The moments' scratch (treeMomentsAll): the subtree roots (parts' runs cut at momentCut), the
   * nodes above them (momentTop, preorder; momentDown, reversed, with its one-part cut momentCut1),
   * and the kernel's array lists.
   */
  momentList: Int32Array;
  momentCut: Int32Array;
  momentTop: Int32Array;
  momentDown: Int32Array;
  momentCut1: Int32Array;
  momentLists: KernelArray[][];
  /** Quadrant counts and offsets of a split. */
  counts: Int32Array;
  /** Morton keys in sorted order (their input indices are `perm`), and the sort's second buffers (keys, input indices). */
  key: Uint32Array;
  key2: Uint32Array;
  idx2: Int32Array;
  /** Task stack of the build: per task [lo, hi, inA, depth, parent] and [cx, cy, cz, half]. */
  taskI: Int32Array;
  taskF: Float64Array;
  /** Parent of each node (-1 for the root). */
  parent: Int32Array;
  /** Field at each slot, m/s^2 (tree order), from the last treeFieldsSorted call. */
  ax: Float64Array;
  ay: Float64Array;
  az: Float64Array;
  /** Smallest half edge that still splits, m. */
  minHalf: number;
  /** The last build met a non-finite position: no tree was built and every field is NaN. */
  nonFinite: boolean;
  /** Work of the last evaluation: cell-cell expansions, direct body pairs, and cell pairs visited by the walk. */
  stats: { cellPairs: number; bodyPairs: number; visits: number };
}

function createTree(dims: 2 | 3, shared: boolean): GravityTree {
  const nodes = 1024;
  const F64 = (n: number): Float64Array => (shared ? sharedFloat64(n) : new Float64Array(n));
  const I32 = (n: number): Int32Array => (shared ? new Int32Array(new SharedArrayBuffer(4 * n)) : new Int32Array(n));
  return {
    dims,
    n: 0,
    nodeCount: 0,
    x: new Float64Array(0),
    y: new Float64Array(0),
    z: new Float64Array(0),
    m: new Float64Array(0),
    perm: new Int32Array(0),
    slot: new Int32Array(0),
    x2: new Float64Array(0),
    y2: new Float64Array(0),
    z2: new Float64Array(0),
    m2: new Float64Array(0),
    perm2: new Int32Array(0),
    code: new Uint8Array(0),
    node: F64(nodes * (dims === 3 ? NF3 : NF2)),
    box: F64(nodes * 6),
    start: I32(nodes),
    end: I32(nodes),
    skip: I32(nodes),
    scratch: [],
    accOffset: 0,
    cut: I32(MAX_PARTS + 1),
    info: F64(MAX_PARTS * INFO_STRIDE),
    parts: 1,
    shared,
    cutWant: new Int32Array(MAX_PARTS + 1),
    walkList: [],
    walkParams: new Float64Array(10),
    keyParams: new Float64Array(SORT_PARAMS),
    momentParams: new Float64Array(2),
    sortHist: new Int32Array(0),
    sortOffset: new Int32Array(0),
    sortLocal: new Int32Array(0),
    sortBucket: I32(0),
    sortGroup: I32(MAX_PARTS + 1),
    sortLists: [[], [], []],
    momentList: I32(0),
    momentCut: I32(MAX_PARTS + 1),
    momentTop: new Int32Array(256),
    momentDown: new Int32Array(256),
    momentCut1: new Int32Array(2),
    momentLists: [[], []],
    counts: new Int32Array(16),
    key: new Uint32Array(0),
    key2: new Uint32Array(0),
    idx2: new Int32Array(0),
    taskI: new Int32Array(MAX_DEPTH * 8 * 5),
    taskF: new Float64Array(MAX_DEPTH * 8 * 4),
    parent: I32(nodes),
    ax: new Float64Array(0),
    ay: new Float64Array(0),
    az: new Float64Array(0),
    minHalf: 0,
    nonFinite: false,
    stats: { cellPairs: 0, bodyPairs: 0, visits: 0 },
  };
}

/**
 * The tree of a world (created on first use, kept on the world); in a world with threads > 1 the
 * arrays the evaluation reads are on SharedArrayBuffers, so worker threads can walk it.
 * @category Forces
 */
export function worldTree(world: PhysicsWorld): GravityTree {
  const holder = world as { gravityTree?: GravityTree };
  if (!holder.gravityTree || holder.gravityTree.dims !== world.dimensions) {
    holder.gravityTree = createTree(world.dimensions, world.threads > 1 && sharedMemoryAvailable());
  }
  return holder.gravityTree;
}

/** A Float64Array of n elements, on a SharedArrayBuffer when the tree is shared. */
function f64(t: GravityTree, n: number): Float64Array {
  return t.shared ? sharedFloat64(n) : new Float64Array(n);
}

/** An Int32Array of n elements, on a SharedArrayBuffer when the tree is shared. */
function i32(t: GravityTree, n: number): Int32Array {
  return t.shared ? new Int32Array(new SharedArrayBuffer(4 * n)) : new Int32Array(n);
}

function growBodies(t: GravityTree, n: number): void {
  if (t.x.length >= n) return;
  const size = Math.max(n, 2 * t.x.length, 64);
  t.x = f64(t, size);
  t.y = f64(t, size);
  t.z = f64(t, size);
  t.m = f64(t, size);
  t.x2 = new Float64Array(size);
  t.y2 = new Float64Array(size);
  t.z2 = new Float64Array(size);
  t.m2 = new Float64Array(size);
  t.perm = i32(t, size);
  t.perm2 = new Int32Array(size);
  t.slot = i32(t, size);
  t.code = new Uint8Array(size);
  t.ax = f64(t, size);
  t.ay = f64(t, size);
  t.az = f64(t, size);
  t.scratch.length = 0;
  const u32 = (k: number): Uint32Array => (t.shared ? new Uint32Array(new SharedArrayBuffer(4 * k)) : new Uint32Array(k));
  t.key = u32(size);
  t.key2 = u32(size);
  t.idx2 = i32(t, size);
}

function growNodes(t: GravityTree, needed: number): void {
  const cap = t.start.length;
  if (needed <= cap) return;
  let n = cap;
  while (n < needed) n *= 2;
  const nf = t.dims === 3 ? NF3 : NF2;
  const node = f64(t, n * nf);
  node.set(t.node);
  t.node = node;
  const box = f64(t, n * 6);
  box.set(t.box);
  t.box = box;
  const s = i32(t, n);
  s.set(t.start);
  t.start = s;
  const e = i32(t, n);
  e.set(t.end);
  t.end = e;
  const k = i32(t, n);
  k.set(t.skip);
  t.skip = k;
  const p = i32(t, n);
  p.set(t.parent);
  t.parent = p;
  t.scratch.length = 0;
}

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
 * @category Forces
 */
export function buildTree(
  t: GravityTree,
  n: number,
  x: ArrayLike<number>,
  y: ArrayLike<number>,
  z: ArrayLike<number>,
  m: ArrayLike<number>,
): void {
  buildTreeWith(t, n, x, y, z, m, null, null);
}

/**
 * buildTree, with the bounding box already known (`bounds`: min x, y, z, max x, y, z, non-finite
 * flag; null: computed here) and the Morton keys computed on `pool`'s threads when the arrays are
 * shared and the bodies many enough (MIN_PARALLEL_PER_THREAD a thread).
 */
function buildTreeWith(
  t: GravityTree,
  n: number,
  x: ArrayLike<number>,
  y: ArrayLike<number>,
  z: ArrayLike<number>,
  m: ArrayLike<number>,
  bounds: Float64Array | null,
  pool: ThreadPool | null,
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
    minX = bounds[0]!;
    minY = bounds[1]!;
    minZ = bounds[2]!;
    maxX = bounds[3]!;
    maxY = bounds[4]!;
    maxZ = bounds[5]!;
    bad = bounds[6] !== 0;
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
  KP[0] = x0;
  KP[1] = y0;
  KP[2] = z0;
  KP[3] = scale;
  KP[4] = top;
  KP[5] = t.dims;
  const digitBits = sortDigitBits(n);
  KP[6] = n;
  KP[8] = (is3D ? 3 * KEY_BITS3 : 2 * KEY_BITS2) - digitBits;
  KP[9] = digitBits;
  mortonSort(t, n, x, y, z, m, pool);
  const KM = t.momentParams;
  KM[0] = t.dims;
  growNodes(t, Math.max(64, Math.ceil((3 * n) / LEAF_SIZE) + 64));
  splitCells(t, n, cx, cy, cz, half, bits);
  treeMomentsAll(t, pool);
}

/**
 * The Morton sort of buildTreeWith and the bodies into tree order: keys (t.key, t.perm) in (key, input
 * index) order, the order of a stable sort, and t.x, t.y, t.z, t.m, t.perm in that order. Three
 * kernels (forces/barnes-hut/gather.ts): the keys with each part's histogram of the first digit (the top
 * sortDigitBits(n) bits), the parts' bodies to their buckets in order, then the buckets sorted by
 * the bits below and the bodies put into tree order, each part a run of buckets holding about n /
 * parts bodies. On `pool`'s threads (one part a thread) when the tree's arrays are shared and the
 * bodies many enough (MIN_PARALLEL_PER_THREAD a thread), and an adaptive pool has found that faster;
 * else here as one part. The order does not depend on the parts, so neither does the tree.
 * The parameters (t.keyParams, SORT_PARAMS) are set by the caller but for the part count.
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
  const R = 1 << t.keyParams[9]!;
  if (t.sortHist.length < parts * R) {
    const size = Math.max(parts, pool?.threads ?? 1) * R;
    t.sortHist = i32(t, size);
    t.sortOffset = i32(t, size);
  }
  if (t.sortBucket.length < R + 1) t.sortBucket = i32(t, R + 1);
  if (t.sortLocal.length < parts * BUCKET_RADIX) t.sortLocal = i32(t, Math.max(parts, pool?.threads ?? 1) * BUCKET_RADIX);
  const hist = t.sortHist,
    offset = t.sortOffset,
    bucket = t.sortBucket,
    group = t.sortGroup,
    P = t.keyParams;
  P[7] = parts;
  const system = 'mutualGravitySystem (Barnes-Hut sort)';
  const A1 = t.sortLists[0]!,
    A2 = t.sortLists[1]!,
    A3 = t.sortLists[2]!;
  A1.length = 0;
  A1.push(x as Float64Array, y as Float64Array, z as Float64Array, t.key, hist);
  if (parts > 1) pool!.run(system, KERNEL.mortonKeysHist, A1, P, parts, null);
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
  A2.push(t.key, t.key2, t.idx2, offset);
  if (parts > 1) pool!.run(system, KERNEL.mortonScatter, A2, P, parts, null);
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
  A3.push(
    t.key2,
    t.idx2,
    t.key,
    t.perm,
    bucket,
    group,
    t.sortLocal,
    x as Float64Array,
    y as Float64Array,
    z as Float64Array,
    m as Float64Array,
    t.x,
    t.y,
    t.z,
    t.m,
  );
  if (parts > 1) pool!.run(system, KERNEL.mortonBucketSort, A3, P, parts, null);
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
  ti[0] = 0;
  ti[1] = n;
  ti[2] = 1;
  ti[3] = 0;
  ti[4] = -1;
  tf[0] = cx;
  tf[1] = cy;
  tf[2] = cz;
  tf[3] = half;
  let tp = 1;
  const minHalf = t.minHalf;
  while (tp > 0) {
    tp--;
    const lo = ti[tp * 5]!,
      hi = ti[tp * 5 + 1]!,
      inA = ti[tp * 5 + 2] === 1,
      depth = ti[tp * 5 + 3]!,
      parent = ti[tp * 5 + 4]!;
    const ccx = tf[tp * 4]!,
      ccy = tf[tp * 4 + 1]!,
      ccz = tf[tp * 4 + 2]!,
      h = tf[tp * 4 + 3]!;
    const k = t.nodeCount++;
    if (k >= t.start.length) growNodes(t, k + 1);
    t.start[k] = lo;
    t.end[k] = hi;
    t.skip[k] = k + 1;
    t.parent[k] = parent;
    if (hi - lo <= LEAF_SIZE || !(h > minHalf) || depth >= MAX_DEPTH - 1) {
      if (!inA) {
        const x = t.x,
          y = t.y,
          z = t.z,
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
    if ((tp + kids) * 5 > ti.length) {
      growTasks(t, tp + kids);
      ti = t.taskI;
      tf = t.taskF;
    }
    let end = hi;
    for (let q = kids - 1; q >= 0; q--) {
      const c = cnt[q]!;
      if (c === 0) continue;
      ti[tp * 5] = end - c;
      ti[tp * 5 + 1] = end;
      ti[tp * 5 + 2] = movedTo ? 1 : 0;
      ti[tp * 5 + 3] = depth + 1;
      ti[tp * 5 + 4] = k;
      tf[tp * 4] = ccx + (q & 1 ? hh : -hh);
      tf[tp * 4 + 1] = ccy + (q & 2 ? hh : -hh);
      tf[tp * 4 + 2] = is3D ? ccz + (q & 4 ? hh : -hh) : 0;
      tf[tp * 4 + 3] = hh;
      tp++;
      end -= c;
    }
  }
}

function growTasks(t: GravityTree, needed: number): void {
  const size = Math.max(needed, 2 * (t.taskF.length / 4));
  const i = new Int32Array(size * 5);
  i.set(t.taskI);
  t.taskI = i;
  const f = new Float64Array(size * 4);
  f.set(t.taskF);
  t.taskF = f;
}

/**
 * Subtree ends (skip) and the moments of every node (kernel treeMoments), children before parents.
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
  P[0] = t.dims;
  P[1] = 0;
  const A = t.momentLists[0]!;
  A.length = 0;
  A.push(t.x, t.y, t.z, t.m, t.node, t.box, t.start, t.end, skip, t.perm, t.slot, list, cut);
  if (parts > 1) pool!.run('mutualGravitySystem (Barnes-Hut moments)', KERNEL.treeMoments, A, P, parts, null);
  else treeMoments(A, P, null, 0, 1);
  if (ntop > 0) {
    // The nodes above the subtrees, deepest first (descending index: children before parents).
    const down = t.momentDown.length >= ntop ? t.momentDown : (t.momentDown = new Int32Array(2 * ntop));
    for (let i = 0; i < ntop; i++) down[i] = t.momentTop[ntop - 1 - i]!;
    const cut1 = t.momentCut1;
    cut1[0] = 0;
    cut1[1] = ntop;
    P[1] = 1;
    const B = t.momentLists[1]!;
    B.length = 0;
    B.push(t.x, t.y, t.z, t.m, t.node, t.box, t.start, t.end, skip, t.perm, t.slot, down, cut1);
    treeMoments(B, P, null, 0, 1);
  }
  if (adaptive) pool!.chooser.record(site, parts > 1, nowMs() - t0, nc);
}

/** 1 / min(theta, 1)^2: cells interact by expansion when |R|^2 > (r_A + r_B)^2 times this. */
function openFactor(theta: number): number {
  return theta < 1 ? 1 / (theta * theta) : 1;
}

/**
 * Field (m/s^2) at every body of the built tree, with constant G (m^3 kg^-1 s^-2), Plummer softening
 * eps2 = eps^2 (m^2, >= 0) and opening angle theta (> 0). Written into t.ax, t.ay, t.az in tree order
 * (slot s holds input body t.perm[s]); see treeFields for input order. Interaction counts go to t.stats.
 * With a thread pool (`pool`, of a world with threads > 1, whose tree is shared) and at least
 * BARNES_HUT_MIN_PER_THREAD bodies a thread, the evaluation runs on the pool's threads (an adaptive
 * pool keeps it on one thread while that has been faster); the fields are identical to the bit to
 * the one-thread evaluation (see the file's header).
 * @throws Error naming `system` if a worker thread failed.
 * @category Forces
 */
export function treeFieldsSorted(
  t: GravityTree,
  G: number,
  eps2: number,
  theta: number,
  pool: ThreadPool | null = null,
  system = 'treeFieldsSorted',
): void {
  treeFieldsWith(t, G, eps2, theta, pool, system, null);
}

/**
 * The world's forces a walk adds to (treeFieldsWith): the Force store's x, y, z (N) and the entity
 * of each input body (Int32, on a SharedArrayBuffer when the tree is shared).
 */
interface WalkForces {
  fx: Float64Array;
  fy: Float64Array;
  fz: Float64Array;
  ents: Int32Array;
}

/**
 * treeFieldsSorted, and with `forces` (null: none) the downward pass also adds m g to the force of
 * each body (entity forces.ents[t.perm[s]]; x and y only in 2D), on whichever thread evaluates it,
 * so there is no separate pass over the bodies; each body's force gets the same single addition
 * as a pass after the walk would make.
 */
function treeFieldsWith(
  t: GravityTree,
  G: number,
  eps2: number,
  theta: number,
  pool: ThreadPool | null,
  system: string,
  forces: WalkForces | null,
): void {
  const n = t.n;
  t.stats.cellPairs = 0;
  t.stats.bodyPairs = 0;
  t.stats.visits = 0;
  if (t.nonFinite) {
    t.ax.fill(NaN, 0, n);
    t.ay.fill(NaN, 0, n);
    t.az.fill(NaN, 0, n);
    // Every force NaN too (m NaN), so the integrator names the bodies.
    if (forces !== null) treeForces([forces.fx, forces.fy, forces.fz, t.slot, t.m, t.ax, t.ay, t.az], t.walkParams, forces.ents, 0, n);
    return;
  }
  if (n === 0) return;
  // At most MAX_PARTS parts, and a kernel call's arrays (13, a scratch a part, 5 for the forces) within the pool's limit.
  const maxParts = Math.min(MAX_PARTS, CONTROL.MAX_ARRAYS - 18);
  let threads =
    pool !== null && t.shared && n >= BARNES_HUT_MIN_PER_THREAD * pool.threads && pool.threads <= maxParts && pool.usable()
      ? pool.threads
      : 1;
  // An adaptive pool keeps the walk on one thread while that has been faster (threads/adaptive.ts).
  const site = t.dims === 3 ? 'barnes-hut walk 3D' : 'barnes-hut walk 2D';
  const adaptive = threads > 1 && pool!.adaptive;
  if (adaptive && !pool!.chooser.choose(site)) threads = 1;
  const nl = t.dims === 3 ? NL3 : NL2;
  const accOffset = t.start.length * nl,
    size = accOffset + 3 * t.x.length;
  if (t.scratch.length < threads || t.scratch[0]!.length !== size) {
    for (let p = 0; p < threads; p++)
      if (p >= t.scratch.length || t.scratch[p]!.length !== size)
        t.scratch[p] = threads > 1 || t.shared ? f64(t, size) : new Float64Array(size);
    t.accOffset = accOffset;
  }
  cutParts(t, threads);
  const arrays = walkArrays(t, threads, forces);
  const P = t.walkParams;
  P[0] = G;
  P[1] = eps2;
  P[2] = openFactor(theta);
  P[3] = t.nodeCount;
  P[4] = n;
  P[5] = accOffset;
  P[6] = accOffset + t.x.length;
  P[7] = accOffset + 2 * t.x.length;
  P[8] = forces !== null ? 1 : 0;
  P[9] = 13 + threads;
  const kernel = t.dims === 3 ? KERNEL.barnesHutWalk3 : KERNEL.barnesHutWalk2;
  const t0 = adaptive ? nowMs() : 0;
  if (threads > 1) pool!.run(system, kernel, arrays, P, threads, null);
  else KERNELS[kernel]!(arrays, P, null, 0, 1, 0, KERNEL_HELPERS);
  if (adaptive) pool!.chooser.record(site, threads > 1, nowMs() - t0, n);
  const info = t.info;
  for (let p = 0; p < threads; p++) {
    t.stats.cellPairs += info[p * INFO_STRIDE]!;
    t.stats.bodyPairs += info[p * INFO_STRIDE + 1]!;
    t.stats.visits += info[p * INFO_STRIDE + 2]!;
  }
}

/**
 * Cuts the slots into `parts` parts at leaf starts (t.cut). With the same number of parts and bodies
 * as the last evaluation, the cuts split the work that evaluation counted (t.info) evenly, assuming
 * it spread uniformly over each part's slots; otherwise they split the slots evenly.
 */
function cutParts(t: GravityTree, parts: number): void {
  const cut = t.cut,
    info = t.info,
    n = t.n;
  const prev = t.parts === parts && cut[parts] === n ? parts : 0;
  let total = 0;
  for (let p = 0; p < prev; p++) total += info[p * INFO_STRIDE + 3]!;
  const want = t.cutWant;
  want[0] = 0;
  for (let q = 1; q < parts; q++) {
    let s = Math.round((n * q) / parts);
    if (prev > 0 && total > 0) {
      // The slot where the cumulative work of the last evaluation reaches q / parts of its total.
      const goal = (total * q) / parts;
      let acc = 0,
        p = 0;
      while (p < prev - 1 && acc + info[p * INFO_STRIDE + 3]! < goal) {
        acc += info[p * INFO_STRIDE + 3]!;
        p++;
      }
      const w = info[p * INFO_STRIDE + 3]!,
        a = cut[p]!,
        b = cut[p + 1]!;
      s = w > 0 ? Math.round(a + ((goal - acc) / w) * (b - a)) : a;
    }
    want[q] = Math.min(n, Math.max(want[q - 1]!, leafStart(t, s)));
  }
  for (let q = 1; q < parts; q++) cut[q] = want[q]!;
  cut[0] = 0;
  cut[parts] = n;
  t.parts = parts;
}

/** The first slot of the leaf that holds slot s (n for s >= n). */
function leafStart(t: GravityTree, s: number): number {
  if (s >= t.n) return t.n;
  if (s <= 0) return 0;
  const skip = t.skip,
    start = t.start,
    end = t.end;
  let k = 0;
  while (skip[k] !== k + 1) {
    let c = k + 1;
    while (end[c]! <= s) c = skip[c]!;
    k = c;
  }
  return start[k]!;
}

/**
 * The kernel's arrays for `parts` parts (order in forces/barnes-hut/walk.ts), in a list kept on the tree,
 * with the force arrays after the parts' scratch (at 13 + parts) when there are `forces`.
 */
function walkArrays(t: GravityTree, parts: number, forces: WalkForces | null): KernelArray[] {
  const a = t.walkList;
  a.length = 0;
  a.push(t.x, t.y, t.z, t.m, t.node, t.start, t.end, t.skip, t.ax, t.ay, t.az, t.cut, t.info);
  for (let p = 0; p < parts; p++) a.push(t.scratch[p]!);
  if (forces !== null) a.push(forces.fx, forces.fy, forces.fz, t.perm, forces.ents);
  return a;
}

/**
 * Field (m/s^2) at every body of the built tree, in input order: body i gets (ax[i], ay[i], az[i]).
 * Same method and arguments as treeFieldsSorted.
 * @category Forces
 */
export function treeFields(
  t: GravityTree,
  G: number,
  eps2: number,
  theta: number,
  ax: Float64Array,
  ay: Float64Array,
  az: Float64Array,
): void {
  treeFieldsSorted(t, G, eps2, theta);
  const perm = t.perm,
    tx = t.ax,
    ty = t.ay,
    tz = t.az;
  for (let s = 0; s < t.n; s++) {
    const i = perm[s]!;
    ax[i] = tx[s]!;
    ay[i] = ty[s]!;
    az[i] = tz[s]!;
  }
}

/**
 * Field (m/s^2) at input body i of the built tree by a classic Barnes-Hut walk for that body alone:
 * a cell is used as a whole (monopole plus quadrupole, the same softened expansion as above with
 * delta = 0) when the body is farther than r / min(theta, 1) from its centre of mass, otherwise
 * opened; leaves are summed directly, excluding i itself. Written into out[0..2]. For a few bodies;
 * treeFields is much faster for all of them and more accurate at the same theta (on a clustered 2D
 * set at theta = 0.5: median error 0.4% here, 0.07% there).
 * @category Forces
 */
export function treeField(t: GravityTree, i: number, G: number, eps2: number, theta: number, out: Float64Array): void {
  if (t.nonFinite) {
    out[0] = NaN;
    out[1] = NaN;
    out[2] = NaN;
    return;
  }
  const s = t.slot[i]!;
  const is3D = t.dims === 3,
    nf = is3D ? NF3 : NF2;
  const F = t.node,
    skip = t.skip,
    start = t.start,
    end = t.end,
    X = t.x,
    Y = t.y,
    Z = t.z,
    Mb = t.m;
  const xi = X[s]!,
    yi = Y[s]!,
    zi = is3D ? Z[s]! : 0;
  const f = openFactor(theta);
  let ax = 0,
    ay = 0,
    az = 0;
  let k = 0;
  while (k < t.nodeCount) {
    const o = k * nf;
    const Dx = F[o]! - xi,
      Dy = F[o + 1]! - yi,
      Dz = is3D ? F[o + 2]! - zi : 0;
    const u = Dx * Dx + Dy * Dy + Dz * Dz;
    const r = F[o + (is3D ? 10 : 6)]!;
    const next = skip[k]!;
    if (!(u > r * r * f)) {
      if (next === k + 1) {
        for (let j = start[k]!; j < end[k]!; j++) {
          const dx = X[j]! - xi,
            dy = Y[j]! - yi,
            dz = is3D ? Z[j]! - zi : 0;
          const r2 = dx * dx + dy * dy + dz * dz + eps2;
          if (j === s || r2 === 0) continue;
          const w = Mb[j]! / (r2 * Math.sqrt(r2));
          ax += w * dx;
          ay += w * dy;
          az += w * dz;
        }
      }
      k++;
      continue;
    }
    // a = D (M g^3 + (15/2) g^7 D.S.D - (3/2) tr S g^5) - 3 g^5 S.D (the cell-cell a0 term with delta = 0).
    const g2 = 1 / (u + eps2),
      g = Math.sqrt(g2),
      g3 = g * g2,
      g5 = g3 * g2;
    let sx: number, sy: number, sz: number, M: number, tr: number;
    if (is3D) {
      sx = F[o + 4]! * Dx + F[o + 7]! * Dy + F[o + 8]! * Dz;
      sy = F[o + 7]! * Dx + F[o + 5]! * Dy + F[o + 9]! * Dz;
      sz = F[o + 8]! * Dx + F[o + 9]! * Dy + F[o + 6]! * Dz;
      M = F[o + 3]!;
      tr = F[o + 4]! + F[o + 5]! + F[o + 6]!;
    } else {
      sx = F[o + 3]! * Dx + F[o + 4]! * Dy;
      sy = F[o + 4]! * Dx + F[o + 5]! * Dy;
      sz = 0;
      M = F[o + 2]!;
      tr = F[o + 3]! + F[o + 5]!;
    }
    const w = M * g3 + g5 * (7.5 * g2 * (Dx * sx + Dy * sy + Dz * sz) - 1.5 * tr);
    ax += w * Dx - 3 * g5 * sx;
    ay += w * Dy - 3 * g5 * sy;
    az += w * Dz - 3 * g5 * sz;
    k = next;
  }
  out[0] = G * ax;
  out[1] = G * ay;
  out[2] = G * az;
}

/** The gathered bodies of a world's tree: x, y, z, m (input order), each range's bounding box, and each body's entity. */
interface Gathered {
  f: Float64Array[];
  ents: Int32Array;
}
interface GatherHolder {
  gravityGather?: Gathered;
}

function gatherScratch(world: PhysicsWorld, n: number, shared: boolean): Gathered {
  const holder = world as GatherHolder;
  if (!holder.gravityGather || holder.gravityGather.ents.length < n) {
    const size = Math.max(n, 2 * (holder.gravityGather?.ents.length ?? 0), 1024);
    const f = (k: number): Float64Array => (shared ? sharedFloat64(k) : new Float64Array(k));
    // x, y, z, m, and the bounding box of each thread's range (BOX_STRIDE slots a thread).
    holder.gravityGather = {
      f: [f(size), f(size), f(size), f(size), f(BOX_STRIDE * 64)],
      ents: shared ? new Int32Array(new SharedArrayBuffer(4 * size)) : new Int32Array(size),
    };
  }
  return holder.gravityGather;
}

/**
 * Builds the world's tree over the bodies `ents` (entity ids) from their Position and Mass, and
 * evaluates the field at all of them with the world's G, softening and opening angle. Returns the
 * tree: the field of entity ents[t.perm[s]] is (t.ax[s], t.ay[s], t.az[s]), m/s^2. In a world with
 * threads > 1, the gathering, the sort, the moments and the evaluation run on its threads (the
 * split into cells on one; see the file's header); the tree and the fields are the same as on one
 * thread, to the bit.
 * @category Forces
 */
export function worldTreeFields(world: PhysicsWorld, ents: ArrayLike<number>): GravityTree {
  return worldTreeFieldsWith(world, ents, false);
}

/** worldTreeFields; with `addForces`, the walk also adds m g to each body's Force (treeFieldsWith). */
function worldTreeFieldsWith(world: PhysicsWorld, ents: ArrayLike<number>, addForces: boolean): GravityTree {
  const c = world.components;
  const n = ents.length;
  const t = worldTree(world);
  const gathered = gatherScratch(world, n, t.shared),
    xs = gathered.f;
  const gx = xs[0]!,
    gy = xs[1]!,
    gz = xs[2]!,
    gm = xs[3]!,
    box = xs[4]!;
  const arrays = [c.Position.x, c.Position.y, c.Position.z, c.Mass.value, gx, gy, gz, gm, box, gathered.ents] as KernelArray[];
  const P = t.keyParams;
  P[0] = world.dimensions;
  const system = 'mutualGravitySystem (Barnes-Hut)';
  let parts = world.threadPool?.threads ?? 1;
  // Neutral boxes for the other ranges: an adaptive pool may run the kernel as one range (part 0).
  for (let p = 1; p < parts; p++) {
    const o = p * BOX_STRIDE;
    box[o] = Infinity;
    box[o + 1] = Infinity;
    box[o + 2] = Infinity;
    box[o + 3] = -Infinity;
    box[o + 4] = -Infinity;
    box[o + 5] = -Infinity;
    box[o + 6] = 0;
  }
  if (runOnPool(world.threadPool, system, KERNEL.treeGather, arrays, P, n, ents, MIN_PARALLEL_PER_THREAD) === null) {
    parts = 1;
    treeGather(arrays, P, ents as unknown as Int32Array, 0, n, 0);
  }
  // The bounding box over the ranges (min and max: exact in any order).
  for (let p = 1; p < parts; p++) {
    const o = p * BOX_STRIDE;
    for (let q = 0; q < 3; q++) {
      if (box[o + q]! < box[q]!) box[q] = box[o + q]!;
      if (box[o + 3 + q]! > box[3 + q]!) box[3 + q] = box[o + 3 + q]!;
    }
    if (box[o + 6] !== 0) box[6] = 1;
  }
  buildTreeWith(t, n, gx, gy, gz, gm, box, world.threadPool);
  const L = world.laws;
  const forces = addForces ? { fx: c.Force.x, fy: c.Force.y, fz: c.Force.z, ents: gathered.ents } : null;
  treeFieldsWith(t, L.gravitationalConstant, L.gravitySoftening * L.gravitySoftening, L.openingAngle, world.threadPool, system, forces);
  return t;
}

/**
 * Mutual gravity by the tree for the bodies `ents` (tagged MutualGravity): adds m_i g_i to each
 * body's force accumulator, g_i the tree field. Called by mutualGravitySystem when the world's method
 * is 'barnes-hut'.
 * @category Forces
 */
export function barnesHutGravity(world: PhysicsWorld, ents: ArrayLike<number>): void {
  // The walk's downward pass adds the forces as it writes the fields (no pass of its own).
  worldTreeFieldsWith(world, ents, true);
}
