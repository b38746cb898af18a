import { nowMs } from '../../threads/adaptive.js';
import type { KernelArray } from '../../threads/kernel-types.js';
import { MIN_PARALLEL_PER_THREAD, runOnPool } from '../../threads/parallel.js';
import { sharedFloat64, type ThreadPool } from '../../threads/pool.js';
import { CONTROL } from '../../threads/worker-main.js';
import type { PhysicsWorld } from '../../world/options.js';
import * as BOX from './bounds.js';
import * as L2 from './field-2d.js';
import * as L3 from './field-3d.js';
import { treeForces, treeGather } from './gather.js';
import * as N2 from './node-2d.js';
import * as N3 from './node-3d.js';
import * as TREE_FORCES from './slots/tree-forces.js';
import * as TREE_GATHER from './slots/tree-gather.js';
import { buildTree } from './tree-build.js';
import { f64, type GravityTree, MAX_PARTS, worldTree } from './tree-store.js';
import * as WALK from './walk.js';
import { barnesHutWalk } from './walk-kernel.js';

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

/**
 * Fewest bodies a thread for the evaluation to go parallel: below it one thread is faster.
 * @category Forces
 */
export const BARNES_HUT_MIN_PER_THREAD = 2048;

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
    if (forces !== null) treeForces(treeForcesArrays(t, forces), t.walkParams, forces.ents, 0, n);
    return;
  }
  if (n === 0) return;
  // At most MAX_PARTS parts, and a kernel call's arrays (WALK.SCRATCH, a scratch a part, 5 for the forces) within the pool's limit.
  const maxParts = Math.min(MAX_PARTS, CONTROL.MAX_ARRAYS - WALK.SCRATCH - (WALK.ENTS + 1));
  let threads =
    pool !== null && t.shared && n >= BARNES_HUT_MIN_PER_THREAD * pool.threads && pool.threads <= maxParts && pool.usable()
      ? pool.threads
      : 1;
  // An adaptive pool keeps the walk on one thread while that has been faster (threads/adaptive.ts).
  const site = t.dims === 3 ? 'barnes-hut walk 3D' : 'barnes-hut walk 2D';
  const adaptive = threads > 1 && pool!.adaptive;
  if (adaptive && !pool!.chooser.choose(site)) threads = 1;
  const nl = t.dims === 3 ? L3.STRIDE : L2.STRIDE;
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
  P[WALK.G] = G;
  P[WALK.EPS2] = eps2;
  P[WALK.OPEN] = openFactor(theta);
  P[WALK.NODE_COUNT] = t.nodeCount;
  P[WALK.BODY_COUNT] = n;
  P[WALK.ACC_X] = accOffset;
  P[WALK.ACC_Y] = accOffset + t.x.length;
  P[WALK.ACC_Z] = accOffset + 2 * t.x.length;
  P[WALK.ADD_FORCES] = forces !== null ? 1 : 0;
  P[WALK.FORCES_AT] = WALK.SCRATCH + threads;
  P[WALK.DIMENSIONS] = t.dims;
  const t0 = adaptive ? nowMs() : 0;
  if (threads > 1) pool!.run(system, barnesHutWalk, arrays, P, threads, null);
  else barnesHutWalk(arrays, P, null, 0, 1);
  if (adaptive) pool!.chooser.record(site, threads > 1, nowMs() - t0, n);
  const info = t.info;
  for (let p = 0; p < threads; p++) {
    const o = p * WALK.INFO_STRIDE;
    t.stats.cellPairs += info[o + WALK.INFO_CELL_PAIRS]!;
    t.stats.bodyPairs += info[o + WALK.INFO_BODY_PAIRS]!;
    t.stats.visits += info[o + WALK.INFO_VISITS]!;
  }
}

/** treeForces' arrays (forces/barnes-hut/slots/tree-forces.ts) for the tree's fields and the world's `forces`. */
function treeForcesArrays(t: GravityTree, forces: WalkForces): KernelArray[] {
  const A: KernelArray[] = [];
  A[TREE_FORCES.FX] = forces.fx;
  A[TREE_FORCES.FY] = forces.fy;
  A[TREE_FORCES.FZ] = forces.fz;
  A[TREE_FORCES.SLOT] = t.slot;
  A[TREE_FORCES.MASS] = t.m;
  A[TREE_FORCES.AX] = t.ax;
  A[TREE_FORCES.AY] = t.ay;
  A[TREE_FORCES.AZ] = t.az;
  return A;
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
  for (let p = 0; p < prev; p++) total += info[p * WALK.INFO_STRIDE + WALK.INFO_WORK]!;
  const want = t.cutWant;
  want[0] = 0;
  for (let q = 1; q < parts; q++) {
    let s = Math.round((n * q) / parts);
    if (prev > 0 && total > 0) {
      // The slot where the cumulative work of the last evaluation reaches q / parts of its total.
      const goal = (total * q) / parts;
      let acc = 0,
        p = 0;
      while (p < prev - 1 && acc + info[p * WALK.INFO_STRIDE + WALK.INFO_WORK]! < goal) {
        acc += info[p * WALK.INFO_STRIDE + WALK.INFO_WORK]!;
        p++;
      }
      const w = info[p * WALK.INFO_STRIDE + WALK.INFO_WORK]!,
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
 * with the force arrays after the parts' scratch (at WALK.SCRATCH + parts) when there are `forces`.
 */
function walkArrays(t: GravityTree, parts: number, forces: WalkForces | null): KernelArray[] {
  const a = t.walkList;
  a.length = 0;
  a[WALK.X] = t.x;
  a[WALK.Y] = t.y;
  a[WALK.Z] = t.z;
  a[WALK.MASS] = t.m;
  a[WALK.NODE] = t.node;
  a[WALK.START] = t.start;
  a[WALK.END] = t.end;
  a[WALK.SKIP] = t.skip;
  a[WALK.AX] = t.ax;
  a[WALK.AY] = t.ay;
  a[WALK.AZ] = t.az;
  a[WALK.CUT] = t.cut;
  a[WALK.INFO] = t.info;
  for (let p = 0; p < parts; p++) a[WALK.SCRATCH + p] = t.scratch[p]!;
  if (forces !== null) {
    const f = WALK.SCRATCH + parts;
    a[f + WALK.FORCE_X] = forces.fx;
    a[f + WALK.FORCE_Y] = forces.fy;
    a[f + WALK.FORCE_Z] = forces.fz;
    a[f + WALK.PERM] = t.perm;
    a[f + WALK.ENTS] = forces.ents;
  }
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
    nf = is3D ? N3.STRIDE : N2.STRIDE;
  const F = t.node,
    skip = t.skip,
    start = t.start,
    end = t.end,
    { x: X, y: Y, z: Z } = t,
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
    // The centre of mass is at the same offsets in both dimensions.
    const Dx = F[o + N2.CX]! - xi,
      Dy = F[o + N2.CY]! - yi,
      Dz = is3D ? F[o + N3.CZ]! - zi : 0;
    const u = Dx * Dx + Dy * Dy + Dz * Dz;
    const r = F[o + (is3D ? N3.RADIUS : N2.RADIUS)]!;
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
      sx = F[o + N3.SXX]! * Dx + F[o + N3.SXY]! * Dy + F[o + N3.SXZ]! * Dz;
      sy = F[o + N3.SXY]! * Dx + F[o + N3.SYY]! * Dy + F[o + N3.SYZ]! * Dz;
      sz = F[o + N3.SXZ]! * Dx + F[o + N3.SYZ]! * Dy + F[o + N3.SZZ]! * Dz;
      M = F[o + N3.MASS]!;
      tr = F[o + N3.SXX]! + F[o + N3.SYY]! + F[o + N3.SZZ]!;
    } else {
      sx = F[o + N2.SXX]! * Dx + F[o + N2.SXY]! * Dy;
      sy = F[o + N2.SXY]! * Dx + F[o + N2.SYY]! * Dy;
      sz = 0;
      M = F[o + N2.MASS]!;
      tr = F[o + N2.SXX]! + F[o + N2.SYY]!;
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
    // x, y, z, m, and the bounding box of each thread's range (BOX.RANGE_STRIDE slots a thread).
    holder.gravityGather = {
      f: [f(size), f(size), f(size), f(size), f(BOX.RANGE_STRIDE * 64)],
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
  const arrays: KernelArray[] = [];
  arrays[TREE_GATHER.PX] = c.Position.x;
  arrays[TREE_GATHER.PY] = c.Position.y;
  arrays[TREE_GATHER.PZ] = c.Position.z;
  arrays[TREE_GATHER.MASS] = c.Mass.value;
  arrays[TREE_GATHER.GX] = gx;
  arrays[TREE_GATHER.GY] = gy;
  arrays[TREE_GATHER.GZ] = gz;
  arrays[TREE_GATHER.GM] = gm;
  arrays[TREE_GATHER.BOX] = box;
  arrays[TREE_GATHER.ENTS] = gathered.ents;
  // The gather's numbers, in the sort's parameter array (buildTree writes the sort's over them).
  const P = t.keyParams;
  P[TREE_GATHER.DIMENSIONS] = world.dimensions;
  const system = 'mutualGravitySystem (Barnes-Hut)';
  let parts = world.threadPool?.threads ?? 1;
  // Neutral boxes for the other ranges: an adaptive pool may run the kernel as one range (part 0).
  for (let p = 1; p < parts; p++) {
    const o = p * BOX.RANGE_STRIDE;
    box[o + BOX.MIN_X] = Infinity;
    box[o + BOX.MIN_Y] = Infinity;
    box[o + BOX.MIN_Z] = Infinity;
    box[o + BOX.MAX_X] = -Infinity;
    box[o + BOX.MAX_Y] = -Infinity;
    box[o + BOX.MAX_Z] = -Infinity;
    box[o + BOX.NON_FINITE] = 0;
  }
  if (runOnPool(world.threadPool, system, treeGather, arrays, P, n, ents, MIN_PARALLEL_PER_THREAD) === null) {
    parts = 1;
    treeGather(arrays, P, ents as unknown as Int32Array, 0, n, 0);
  }
  // The bounding box over the ranges (min and max: exact in any order).
  for (let p = 1; p < parts; p++) {
    const o = p * BOX.RANGE_STRIDE;
    // Axis q's smallest at MIN_X + q, its largest at MAX_X + q.
    for (let q = 0; q < 3; q++) {
      const lo = BOX.MIN_X + q,
        hi = BOX.MAX_X + q;
      if (box[o + lo]! < box[lo]!) box[lo] = box[o + lo]!;
      if (box[o + hi]! > box[hi]!) box[hi] = box[o + hi]!;
    }
    if (box[o + BOX.NON_FINITE] !== 0) box[BOX.NON_FINITE] = 1;
  }
  buildTree(t, n, gx, gy, gz, gm, box, world.threadPool);
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
