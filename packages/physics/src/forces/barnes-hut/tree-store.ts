import type { KernelArray } from '../../threads/kernel-types.js';
import { sharedFloat64, sharedMemoryAvailable } from '../../threads/pool.js';
import type { PhysicsWorld } from '../../world/options.js';
import * as BOX from './bounds.js';
import * as TASK from './build-task.js';
import * as N2 from './node-2d.js';
import * as N3 from './node-3d.js';
import * as MOMENTS from './slots/moments.js';
import * as SORT from './slots/morton-sort.js';
import * as WALK from './walk.js';

/**
 * The Barnes-Hut tree's storage (see tree.ts for the method): its size constants, the GravityTree
 * arrays of one world, and their growth by doubling. The packed arrays' layouts are modules of their
 * own: a node's moments (node-2d.ts, node-3d.ts), its field polynomial (field-2d.ts, field-3d.ts), its
 * box (bounds.ts), a build task (build-task.ts) and a part's counts (walk.ts).
 */

/** Most parts (threads) an evaluation is cut into. */
export const MAX_PARTS = 32;

/** Most bodies a leaf holds before it splits. */
export const LEAF_SIZE = 8;
/** Cells smaller than this fraction of the root never split (so at most ~31 levels). */
export const MIN_CELL_FRACTION = 1e-9;
/** Depth bound: MIN_CELL_FRACTION > 2^-31, with margin. */
export const MAX_DEPTH = 64;

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
  /** Per node: centre of mass (m), mass (kg), second moment S (kg m^2), r = b_max (m), 2D third moment T (kg m^3); layouts in node-2d.ts and node-3d.ts. */
  node: Float64Array;
  /** Per node, BOX.NODE_STRIDE: tight bounding box min x, y, z, max x, y, z, m (bounds.ts). */
  box: Float64Array;
  /** Per node: first slot, end slot (exclusive), and the node after its subtree (k + 1 for a leaf). */
  start: Int32Array;
  end: Int32Array;
  skip: Int32Array;
  /**
   * The evaluation's scratch, one array a part (forces/barnes-hut/walk.ts): per node, the field
   * polynomial about the centre of mass (without G; layouts in field-2d.ts and field-3d.ts), then the
   * direct sums x, y, z of every slot (without G) from the offsets `accOffset`.
   */
  scratch: Float64Array[];
  /** Offset of the direct sums in each scratch array: node capacity times the polynomial stride. */
  accOffset: number;
  /** Slot boundaries of the parts of the last evaluation (part p: cut[p] .. cut[p + 1] - 1), at leaf starts. */
  cut: Int32Array;
  /** Per part, WALK.INFO_STRIDE: counts and work of the last evaluation (the INFO_ offsets of forces/barnes-hut/walk.ts). */
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
   * (2^keyParams[SORT.BITS] each, at most SORT_RADIX) and a bucket sort's counts (BUCKET_RADIX); each bucket's
   * first slot (2^keyParams[SORT.BITS] + 1), each part's first bucket (MAX_PARTS + 1), and the kernels' array lists.
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
  /** Task stack of the build: a task's integers and numbers (build-task.ts). */
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
    node: F64(nodes * (dims === 3 ? N3.STRIDE : N2.STRIDE)),
    box: F64(nodes * BOX.NODE_STRIDE),
    start: I32(nodes),
    end: I32(nodes),
    skip: I32(nodes),
    scratch: [],
    accOffset: 0,
    cut: I32(MAX_PARTS + 1),
    info: F64(MAX_PARTS * WALK.INFO_STRIDE),
    parts: 1,
    shared,
    cutWant: new Int32Array(MAX_PARTS + 1),
    walkList: [],
    walkParams: new Float64Array(WALK.PARAMS),
    keyParams: new Float64Array(SORT.PARAMS),
    momentParams: new Float64Array(MOMENTS.PARAMS),
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
    taskI: new Int32Array(MAX_DEPTH * 8 * TASK.INT_STRIDE),
    taskF: new Float64Array(MAX_DEPTH * 8 * TASK.FLOAT_STRIDE),
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
export function f64(t: GravityTree, n: number): Float64Array {
  return t.shared ? sharedFloat64(n) : new Float64Array(n);
}

/** An Int32Array of n elements, on a SharedArrayBuffer when the tree is shared. */
export function i32(t: GravityTree, n: number): Int32Array {
  return t.shared ? new Int32Array(new SharedArrayBuffer(4 * n)) : new Int32Array(n);
}

export function growBodies(t: GravityTree, n: number): void {
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

export function growNodes(t: GravityTree, needed: number): void {
  const cap = t.start.length;
  if (needed <= cap) return;
  let n = cap;
  while (n < needed) n *= 2;
  const nf = t.dims === 3 ? N3.STRIDE : N2.STRIDE;
  t.node = copyInto(f64(t, n * nf), t.node);
  t.box = copyInto(f64(t, n * BOX.NODE_STRIDE), t.box);
  t.start = copyInto(i32(t, n), t.start);
  t.end = copyInto(i32(t, n), t.end);
  t.skip = copyInto(i32(t, n), t.skip);
  t.parent = copyInto(i32(t, n), t.parent);
  t.scratch.length = 0;
}

/** Copies `from` to the start of the larger array `into` and returns `into`. */
function copyInto<T extends Float64Array | Int32Array>(into: T, from: T): T {
  into.set(from);
  return into;
}
