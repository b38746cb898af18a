import type { PhysicsWorld } from '../world';

/**
 * Barnes-Hut tree for mutual gravity (Barnes and Hut, Nature 324, 1986): a quadtree in 2D, an octree
 * in 3D, built over the bodies each time forces are evaluated. A far cell acts as one body at its
 * centre of mass. Opening test (Barnes 1994, the "b_max" form): a cell of edge s whose centre of mass
 * lies delta from its geometric centre is opened when the body is nearer than s / theta + delta, so
 * a body is never approximated by a cell it sits in. Leaves hold up to LEAF_SIZE bodies, summed
 * directly with the same Plummer softening as the direct sum.
 *
 * Cost: O(N log N) per evaluation. Unlike the direct sum, forces are not exactly pairwise opposite,
 * so total momentum drifts slightly; the drift is reported by the bench and bounded in the tests.
 * Everything lives in typed arrays grown by doubling and reused between evaluations.
 */

/** Bodies a leaf holds before it splits. */
const LEAF_SIZE = 8;
/** Cells smaller than this fraction of the root never split (coincident bodies share a leaf). */
const MIN_CELL_FRACTION = 1e-9;

/** The tree's arrays; one per world, reused. */
export interface GravityTree {
  dims: 2 | 3;
  nodeCount: number;
  capacity: number;
  /** Cell centre and half edge, m. */
  cx: Float64Array; cy: Float64Array; cz: Float64Array; half: Float64Array;
  /** Mass (kg) and centre of mass (m) of the bodies below. */
  mass: Float64Array; mx: Float64Array; my: Float64Array; mz: Float64Array;
  /** Index of the first of the 4 (8) children, or -1 for a leaf. */
  child: Int32Array;
  /** Leaf: first body (index into the body arrays) of its list, -1 if none; and the count. */
  first: Int32Array; count: Int32Array;
  /** Per body (index i of the input order): next body in its leaf's list; position and mass copies. */
  next: Int32Array; bx: Float64Array; by: Float64Array; bz: Float64Array; bm: Float64Array;
  /** Traversal stack. */
  stack: Int32Array;
}

function createTree(dims: 2 | 3): GravityTree {
  const n = 1024;
  return {
    dims, nodeCount: 0, capacity: n,
    cx: new Float64Array(n), cy: new Float64Array(n), cz: new Float64Array(n), half: new Float64Array(n),
    mass: new Float64Array(n), mx: new Float64Array(n), my: new Float64Array(n), mz: new Float64Array(n),
    child: new Int32Array(n), first: new Int32Array(n), count: new Int32Array(n),
    next: new Int32Array(0), bx: new Float64Array(0), by: new Float64Array(0), bz: new Float64Array(0), bm: new Float64Array(0),
    stack: new Int32Array(4096),
  };
}

function growNodes(t: GravityTree, needed: number): void {
  if (needed <= t.capacity) return;
  let n = t.capacity;
  while (n < needed) n *= 2;
  const f = (a: Float64Array) => { const b = new Float64Array(n); b.set(a); return b; };
  const i = (a: Int32Array) => { const b = new Int32Array(n); b.set(a); return b; };
  t.cx = f(t.cx); t.cy = f(t.cy); t.cz = f(t.cz); t.half = f(t.half);
  t.mass = f(t.mass); t.mx = f(t.mx); t.my = f(t.my); t.mz = f(t.mz);
  t.child = i(t.child); t.first = i(t.first); t.count = i(t.count);
  t.capacity = n;
}

function newNode(t: GravityTree, cx: number, cy: number, cz: number, half: number): number {
  const k = t.nodeCount++;
  if (k >= t.capacity) growNodes(t, k + 1);
  t.cx[k] = cx; t.cy[k] = cy; t.cz[k] = cz; t.half[k] = half;
  t.child[k] = -1; t.first[k] = -1; t.count[k] = 0;
  return k;
}

/** The tree of a world (created on first use). */
export function worldTree(world: PhysicsWorld): GravityTree {
  const holder = world as { gravityTree?: GravityTree };
  if (!holder.gravityTree || holder.gravityTree.dims !== world.dimensions) holder.gravityTree = createTree(world.dimensions);
  return holder.gravityTree;
}

/**
 * Builds the tree over n bodies with positions (x, y, z) and masses m (arrays indexed 0..n-1).
 * Bodies of zero mass are kept (they still get forces) but weigh nothing.
 */
export function buildTree(
  t: GravityTree, n: number,
  x: ArrayLike<number>, y: ArrayLike<number>, z: ArrayLike<number>, m: ArrayLike<number>,
): void {
  const is3D = t.dims === 3;
  if (t.next.length < n) {
    const size = Math.max(n, 2 * t.next.length);
    t.next = new Int32Array(size); t.bx = new Float64Array(size); t.by = new Float64Array(size);
    t.bz = new Float64Array(size); t.bm = new Float64Array(size);
  }
  let minX = Infinity, minY = Infinity, minZ = Infinity, maxX = -Infinity, maxY = -Infinity, maxZ = -Infinity;
  const bx = t.bx, by = t.by, bz = t.bz, bm = t.bm;
  for (let i = 0; i < n; i++) {
    const px = x[i]!, py = y[i]!, pz = is3D ? z[i]! : 0;
    bx[i] = px; by[i] = py; bz[i] = pz; bm[i] = m[i]!;
    if (px < minX) minX = px; if (px > maxX) maxX = px;
    if (py < minY) minY = py; if (py > maxY) maxY = py;
    if (pz < minZ) minZ = pz; if (pz > maxZ) maxZ = pz;
  }
  const half = 0.5 * Math.max(maxX - minX, maxY - minY, is3D ? maxZ - minZ : 0) * (1 + 1e-9) + 1e-12;
  t.nodeCount = 0;
  growNodes(t, Math.max(16, (2 * n) / LEAF_SIZE + 64));
  newNode(t, 0.5 * (minX + maxX), 0.5 * (minY + maxY), is3D ? 0.5 * (minZ + maxZ) : 0, half);
  const minHalf = half * MIN_CELL_FRACTION;
  for (let i = 0; i < n; i++) insert(t, 0, i, minHalf);
  computeMoments(t);
}

function childIndex(t: GravityTree, node: number, i: number): number {
  let q = 0;
  if (t.bx[i]! >= t.cx[node]!) q |= 1;
  if (t.by[i]! >= t.cy[node]!) q |= 2;
  if (t.dims === 3 && t.bz[i]! >= t.cz[node]!) q |= 4;
  return q;
}

function insert(t: GravityTree, start: number, i: number, minHalf: number): void {
  let node = start;
  for (;;) {
    const c = t.child[node]!;
    if (c >= 0) { node = c + childIndex(t, node, i); continue; }
    if (t.count[node]! < LEAF_SIZE || t.half[node]! < minHalf) {
      t.next[i] = t.first[node]!;
      t.first[node] = i;
      t.count[node] = t.count[node]! + 1;
      return;
    }
    // Split: make the children, then push the leaf's bodies down.
    const h = 0.5 * t.half[node]!;
    const cx = t.cx[node]!, cy = t.cy[node]!, cz = t.cz[node]!;
    const kids = t.dims === 3 ? 8 : 4;
    const base = t.nodeCount;
    growNodes(t, base + kids);
    for (let q = 0; q < kids; q++) {
      newNode(t, cx + (q & 1 ? h : -h), cy + (q & 2 ? h : -h), t.dims === 3 ? cz + (q & 4 ? h : -h) : 0, h);
    }
    let j = t.first[node]!;
    t.child[node] = base; t.first[node] = -1; t.count[node] = 0;
    while (j >= 0) {
      const nextJ = t.next[j]!;
      insert(t, base + childIndex(t, node, j), j, minHalf);
      j = nextJ;
    }
    node = base + childIndex(t, node, i);
  }
}

/** Mass and centre of mass of every cell; children are always created after their parent. */
function computeMoments(t: GravityTree): void {
  const kids = t.dims === 3 ? 8 : 4;
  for (let k = t.nodeCount - 1; k >= 0; k--) {
    let M = 0, X = 0, Y = 0, Z = 0;
    const c = t.child[k]!;
    if (c < 0) {
      for (let j = t.first[k]!; j >= 0; j = t.next[j]!) {
        const w = t.bm[j]!;
        M += w; X += w * t.bx[j]!; Y += w * t.by[j]!; Z += w * t.bz[j]!;
      }
    } else {
      for (let q = 0; q < kids; q++) {
        const w = t.mass[c + q]!;
        M += w; X += w * t.mx[c + q]!; Y += w * t.my[c + q]!; Z += w * t.mz[c + q]!;
      }
    }
    t.mass[k] = M;
    if (M > 0) { t.mx[k] = X / M; t.my[k] = Y / M; t.mz[k] = Z / M; }
    else { t.mx[k] = t.cx[k]!; t.my[k] = t.cy[k]!; t.mz[k] = t.cz[k]!; }
  }
}

/**
 * Gravitational field (acceleration, m/s^2) at body i of the built tree: sum of G m_j d / (d^2 + eps^2)^(3/2)
 * over the accepted cells and the leaf bodies met, excluding i itself. Written into out[0..2].
 */
export function treeField(t: GravityTree, i: number, G: number, eps2: number, theta: number, out: Float64Array): void {
  const x = t.bx[i]!, y = t.by[i]!, z = t.bz[i]!;
  const kids = t.dims === 3 ? 8 : 4;
  const invTheta = 1 / theta;
  let ax = 0, ay = 0, az = 0;
  let stack = t.stack;
  let sp = 0;
  stack[sp++] = 0;
  while (sp > 0) {
    const k = stack[--sp]!;
    const M = t.mass[k]!;
    if (M === 0) continue;
    const c = t.child[k]!;
    if (c < 0) {
      for (let j = t.first[k]!; j >= 0; j = t.next[j]!) {
        if (j === i) continue;
        const dx = t.bx[j]! - x, dy = t.by[j]! - y, dz = t.bz[j]! - z;
        const r2 = dx * dx + dy * dy + dz * dz + eps2;
        if (r2 === 0) continue;
        const f = t.bm[j]! / (r2 * Math.sqrt(r2));
        ax += f * dx; ay += f * dy; az += f * dz;
      }
      continue;
    }
    const dx = t.mx[k]! - x, dy = t.my[k]! - y, dz = t.mz[k]! - z;
    const d2 = dx * dx + dy * dy + dz * dz;
    const ox = t.mx[k]! - t.cx[k]!, oy = t.my[k]! - t.cy[k]!, oz = t.mz[k]! - t.cz[k]!;
    const open = 2 * t.half[k]! * invTheta + Math.sqrt(ox * ox + oy * oy + oz * oz);
    if (d2 < open * open) {
      if (sp + kids > stack.length) { const s2 = new Int32Array(stack.length * 2); s2.set(stack); t.stack = stack = s2; }
      for (let q = 0; q < kids; q++) stack[sp++] = c + q;
      continue;
    }
    const r2 = d2 + eps2;
    const f = M / (r2 * Math.sqrt(r2));
    ax += f * dx; ay += f * dy; az += f * dz;
  }
  out[0] = G * ax; out[1] = G * ay; out[2] = G * az;
}

const field = new Float64Array(3);

/**
 * Mutual gravity by Barnes-Hut for the bodies `ents` (tagged MutualGravity): adds m_i g_i to each
 * body's force accumulator. Called by mutualGravitySystem when the world's method is 'barnes-hut'.
 */
export function barnesHutGravity(world: PhysicsWorld, ents: ArrayLike<number>): void {
  const c = world.components;
  const n = ents.length;
  const t = worldTree(world);
  const px = c.Position.x, py = c.Position.y, pz = c.Position.z, m = c.Mass.value;
  // Gather into the tree's body order (index i = position in ents).
  const xs = gatherScratch(world, n);
  for (let i = 0; i < n; i++) { const e = ents[i]!; xs[0]![i] = px[e]!; xs[1]![i] = py[e]!; xs[2]![i] = pz[e]!; xs[3]![i] = m[e]!; }
  buildTree(t, n, xs[0]!, xs[1]!, xs[2]!, xs[3]!);
  const L = world.laws;
  const G = L.gravitationalConstant, eps2 = L.gravitySoftening * L.gravitySoftening, theta = L.openingAngle;
  const fx = c.Force.x, fy = c.Force.y, fz = c.Force.z;
  for (let i = 0; i < n; i++) {
    const e = ents[i]!;
    treeField(t, i, G, eps2, theta, field);
    const mass = m[e]!;
    fx[e] = fx[e]! + mass * field[0]!; fy[e] = fy[e]! + mass * field[1]!; fz[e] = fz[e]! + mass * field[2]!;
  }
}

function gatherScratch(world: PhysicsWorld, n: number): Float64Array[] {
  const holder = world as { gravityGather?: Float64Array[] };
  if (!holder.gravityGather || holder.gravityGather[0]!.length < n) {
    const size = Math.max(n, 1024);
    holder.gravityGather = [new Float64Array(size), new Float64Array(size), new Float64Array(size), new Float64Array(size)];
  }
  return holder.gravityGather;
}
