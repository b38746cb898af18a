import type { Shape3DStore } from '../../shapes/store-3d.js';
import type { PhysicsWorld } from '../../world/options.js';
import { meets, scratch } from '../colliders-3d.js';
import type { Contact3DState } from '../manifolds-3d.js';
import { pair } from '../pair-manifolds-3d.js';
import { planesAndMeshes } from '../planes-meshes-3d.js';
import { BodyType } from '../state.js';

/**
 * Broadphase of the 3D shape pass: a uniform grid (dense over the colliders' span, hashed when that
 * span is sparse) of the colliders' fattened boxes, searched by
 * the moving colliders (resting ones search every few steps; pairs that touched last step are kept),
 * each overlapping pair handed to the narrowphase (collision/pair-manifolds-3d.ts).
 */

/**
 * A resting collider (its body dynamic and below the sleep thresholds at the end of the last step:
 * rest time > 0) searches its neighbourhood only every RESTING_SEARCH_PERIOD steps (staggered by
 * collider); in between, its pairs are those a searching neighbour finds and those that had a manifold
 * last step. A pair it misses was farther apart than the margin (SHAPE_SPECULATIVE_DISTANCE) at the last
 * search, and each body, under the sleep speeds, moves at most v_sleep + w_sleep reach per second: only
 * colliders for which that stays under a quarter of the speculative distance over the period skip, so a
 * missed pair closes by at most half the margin and is found before it can touch. (At the defaults, dt
 * 1/60 s and the 3D sleep speeds of 0.1, none skips: 0.02 m allows 0.005 m in the period, and 0.1 m/s
 * alone moves 0.013 m.) With a sensor in the world, or sleeping off, every collider
 * searches every step (sensor overlaps have no manifold to carry them).
 */
const RESTING_SEARCH_PERIOD = 8;

/** Broadphase scratch: a uniform grid, dense or hashed (counting sort of colliders by the cell of their box's low corner). */
const grid = {
  start: new Int32Array(0),
  items: new Int32Array(0),
  bucket: new Int32Array(0),
  large: new Int32Array(0),
  width: new Float64Array(0),
  seen: new Int32Array(0),
  packed: new Float64Array(0),
  searching: new Uint8Array(0),
  firstRest: new Int32Array(0),
  /** How many of `large` are in use this step. */
  largeCount: 0,
  /** The dense grid's first cell on each axis (cell coordinates, one below the lowest box's). */
  ox: 0,
  oy: 0,
  oz: 0,
  /** The dense grid's cells along x and y. */
  gx: 0,
  gy: 0,
};

/**
 * A dense grid (every cell of the colliders' span its own bucket, no hashing) is used while it has at
 * most DENSE_CELLS_PER_COLLIDER cells a collider (and DENSE_MIN_CELLS at least); a sparse world (bodies
 * spread far apart) takes the hashed grid instead.
 */
const DENSE_CELLS_PER_COLLIDER = 8;
const DENSE_MIN_CELLS = 4096;

/** Bucket of cell (x, y, z) in a table of mask + 1 buckets (Teschner et al., "Optimized Spatial Hashing for Collision Detection of Deformable Objects", 2003). */
function cellHash(x: number, y: number, z: number, mask: number): number {
  return (Math.imul(x, 73856093) ^ Math.imul(y, 19349663) ^ Math.imul(z, 83492791)) & mask;
}

/**
 * The layout of a box in the grid's packed boxes (`grid.packed`, box k of the bucket order at STRIDE k):
 * the bounds axis by axis, m, so the neighbour search reads memory in sequence.
 */
enum PackedBox {
  MIN_X = 0,
  MAX_X = 1,
  MIN_Y = 2,
  MAX_Y = 3,
  MIN_Z = 4,
  MAX_Z = 5,
  /** The collider's index if it searches this step, else Infinity: a searching collider i takes a neighbour only when KEY > i (the pair of two searching ones is taken from the lower index). */
  KEY = 6,
  /** Numbers a box. */
  STRIDE = 8,
}

/**
 * Broadphase: every collider's box goes into the cell of a uniform grid holding its low corner, with a
 * cell as wide as the widest ordinary box, so a box can only meet boxes whose low corner lies in its own
 * cell or one of the 26 around it; boxes more than four times the mean width ("large": a ground slab)
 * are tested against every collider instead. The grid is dense (a bucket a cell, a box's neighbours in
 * nine runs of consecutive cells) while the colliders' span has few enough cells (denseCells), else
 * hashed. Each candidate pair is seen once (from its lower collider index) and goes to `pair`. Then every collider against the meshes and the planes.
 */
export function pairs(world: PhysicsWorld, s: Shape3DStore, st: Contact3DState): void {
  const n = scratch.n;
  const cell = gridCell(n);
  // No moving collider (a pile asleep): no pair can be new, and the grid is not built.
  if (!anyMoving(world, n)) {
    planesAndMeshes(world, s, st);
    return;
  }
  const inv = 1 / cell;
  markSearching(world, s, n);
  const cells = denseCells(n, inv);
  if (cells > 0) {
    fillGrid(n, inv, cells, true);
    searchGrid(world, s, st, n, inv, true, 0);
  } else {
    let size = 64;
    while (size < 2 * n) size *= 2;
    fillGrid(n, inv, size, false);
    searchGrid(world, s, st, n, inv, false, size - 1);
  }
  restingPairs(world, s, st);
  largePairs(world, s, st, n);
  planesAndMeshes(world, s, st);
}

/**
 * Each collider's box's widest side (grid.width), the "large" ones (wider than four times the mean: into
 * grid.large, grid.largeCount of them, and sc.order -1; the others 0), and the grid's cell: the widest
 * ordinary box's side (1 when there is none), m.
 */
function gridCell(n: number): number {
  const sc = scratch,
    minX = sc.minX,
    maxX = sc.maxX,
    minY = sc.minY,
    maxY = sc.maxY,
    minZ = sc.minZ,
    maxZ = sc.maxZ;
  // Each box's widest side (written out: Math.max of three arguments is a call), kept for the second loop.
  if (grid.large.length < n) {
    grid.large = new Int32Array(Math.max(64, 2 * n));
    grid.width = new Float64Array(Math.max(64, 2 * n));
  }
  const width = grid.width;
  let mean = 0;
  for (let i = 0; i < n; i++) {
    let w = maxX[i]! - minX[i]!,
      d = maxY[i]! - minY[i]!;
    if (d > w) w = d;
    d = maxZ[i]! - minZ[i]!;
    if (d > w) w = d;
    width[i] = w;
    mean += w;
  }
  mean = n > 0 ? mean / n : 1;
  let cell = 0,
    nl = 0;
  const large = grid.large;
  for (let i = 0; i < n; i++) {
    const w = width[i]!;
    if (w > 4 * mean) {
      large[nl++] = i;
      sc.order[i] = -1;
    } else {
      if (w > cell) cell = w;
      sc.order[i] = 0;
    }
  }
  grid.largeCount = nl;
  return cell > 0 ? cell : 1;
}

/** Whether any of the n colliders belongs to a dynamic or kinematic body. */
function anyMoving(world: PhysicsWorld, n: number): boolean {
  const sc = scratch,
    type = world.collision.bodyType;
  for (let i = 0; i < n; i++) {
    const t = type[sc.body[i]!]!;
    if (t === BodyType.Dynamic || t === BodyType.Kinematic) return true;
  }
  return false;
}

/** Which colliders search their neighbourhood this step (grid.searching; see the note at RESTING_SEARCH_PERIOD). */
function markSearching(world: PhysicsWorld, s: Shape3DStore, n: number): void {
  const sc = scratch,
    type = world.collision.bodyType;
  if (grid.searching.length < n) grid.searching = new Uint8Array(Math.max(64, 2 * n));
  const sl = world.collision.sleep,
    searching = grid.searching,
    rest = sl.restTime,
    phase = world.steps;
  // How far a resting collider may move between searches (at the sleep speeds) must stay under a quarter
  // of the speculative distance, so a pair of two closes by at most half the margin.
  const quarterSpec = 0.25 * sc.spec;
  const mayRest = sl.enabled && !sc.anySensor,
    period = RESTING_SEARCH_PERIOD * world.h;
  for (let i = 0; i < n; i++) {
    const b = sc.body[i]!,
      t = type[b]!;
    const reach = sc.ball[i] === 1 ? world.components.Ball.radius[b]! : s.reach[sc.shape[i]!]!;
    const skips =
      mayRest &&
      t === BodyType.Dynamic &&
      rest[b]! > 0 &&
      (sl.linearSpeed + sl.angularSpeed * reach) * period <= quarterSpec &&
      (phase + i) % RESTING_SEARCH_PERIOD !== 0;
    searching[i] = (t === BodyType.Kinematic || t === BodyType.Dynamic) && !skips ? 1 : 0;
  }
}

/** lowCornerSpan's result: the low corners' least and greatest x, y, z (x0, x1, y0, y1, z0, z1), m. */
const span = new Float64Array(6);

/**
 * The span of the low corners (minX, minY, minZ) of the first `n` colliders not dropped (`order` -1) into
 * `out` (x0, x1, y0, y1, z0, z1; x0 > x1 when none); returns 0 when a corner is not finite, else 1. A
 * function that reads nothing before its loop: the first call's first lines run before V8 gives the
 * function type feedback, so code compiled while that loop ran, reading the scratch here, was thrown
 * away at the next call, and the loop then ran interpreted (a boxed number per corner read).
 */
function lowCornerSpan(
  order: Int32Array,
  minX: Float64Array,
  minY: Float64Array,
  minZ: Float64Array,
  n: number,
  out: Float64Array,
): number {
  let x0 = Infinity,
    x1 = -Infinity,
    y0 = Infinity,
    y1 = -Infinity,
    z0 = Infinity,
    z1 = -Infinity;
  for (let i = 0; i < n; i++) {
    if (order[i] === -1) continue;
    const x = minX[i]!,
      y = minY[i]!,
      z = minZ[i]!;
    // NaN fails every comparison: a non-finite span.
    if (!(x >= -Infinity && y >= -Infinity && z >= -Infinity)) return 0;
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
    if (z < z0) z0 = z;
    if (z > z1) z1 = z;
  }
  out[0] = x0;
  out[1] = x1;
  out[2] = y0;
  out[3] = y1;
  out[4] = z0;
  out[5] = z1;
  return 1;
}

/**
 * The dense grid of the ordinary colliders (cells 1 / inv wide): its origin and x, y sizes into grid.ox,
 * oy, oz, gx, gy, and its cell count, spanning one cell beyond the lowest and highest low corner on each
 * axis (a search reaches one cell below a box's low corner and, no box being wider than a cell, at most
 * one above); 0 when that is more than the dense limit (DENSE_CELLS_PER_COLLIDER) or a corner is not
 * finite: then the hashed grid.
 */
function denseCells(n: number, inv: number): number {
  const sc = scratch;
  if (lowCornerSpan(sc.order, sc.minX, sc.minY, sc.minZ, n, span) === 0) return 0;
  const x0 = span[0]!,
    x1 = span[1]!,
    y0 = span[2]!,
    y1 = span[3]!,
    z0 = span[4]!,
    z1 = span[5]!;
  if (x0 > x1) return 0;
  const cx0 = Math.floor(x0 * inv) - 1,
    cy0 = Math.floor(y0 * inv) - 1,
    cz0 = Math.floor(z0 * inv) - 1;
  const gx = Math.floor(x1 * inv) + 2 - cx0,
    gy = Math.floor(y1 * inv) + 2 - cy0,
    gz = Math.floor(z1 * inv) + 2 - cz0;
  const cells = gx * gy * gz;
  if (!(cells <= Math.max(DENSE_MIN_CELLS, DENSE_CELLS_PER_COLLIDER * n))) return 0;
  grid.ox = cx0;
  grid.oy = cy0;
  grid.oz = cz0;
  grid.gx = gx;
  grid.gy = gy;
  return cells;
}

/**
 * The grid of `size` buckets (dense: one a cell of denseCells' grid; else hashed, a power of two) of the ordinary colliders, by the cell (1 / inv wide) of
 * their box's low corner: grid.items in bucket order from grid.start[b], the searching colliders of a
 * bucket first, then the others from grid.firstRest[b], each part in ascending collider index; and their
 * boxes packed in that order (grid.packed, PackedBox).
 */
function fillGrid(n: number, inv: number, size: number, dense: boolean): void {
  const sc = scratch,
    mask = size - 1;
  if (grid.start.length < size + 1) {
    grid.start = new Int32Array(2 * size + 1);
    grid.seen = new Int32Array(2 * size + 1);
  }
  if (!dense) grid.seen.fill(0, 0, size);
  if (grid.items.length < n) {
    grid.items = new Int32Array(Math.max(64, 2 * n));
    grid.bucket = new Int32Array(Math.max(64, 2 * n));
  }
  if (grid.firstRest.length < size) grid.firstRest = new Int32Array(2 * size);
  const start = grid.start,
    items = grid.items,
    bucket = grid.bucket,
    order = sc.order,
    firstRest = grid.firstRest,
    searching = grid.searching;
  const minX = sc.minX,
    minY = sc.minY,
    minZ = sc.minZ;
  const ox = grid.ox,
    oy = grid.oy,
    oz = grid.oz,
    gx = grid.gx,
    gy = grid.gy;
  // Counting sort by bucket; within a bucket the searching colliders first, then the others (from
  // firstRest[b]), each part in ascending collider index, so a collider meets the searching ones above
  // its own index without testing those below (their own search finds the pair).
  start.fill(0, 0, size + 1);
  firstRest.fill(0, 0, size);
  for (let i = 0; i < n; i++) {
    if (order[i] === -1) continue;
    const x = Math.floor(minX[i]! * inv),
      y = Math.floor(minY[i]! * inv),
      z = Math.floor(minZ[i]! * inv);
    const b = dense ? x - ox + gx * (y - oy + gy * (z - oz)) : cellHash(x, y, z, mask);
    bucket[i] = b;
    start[b + 1]!++;
    firstRest[b] = firstRest[b]! + searching[i]!;
  }
  for (let b = 0; b < size; b++) {
    start[b + 1] = start[b + 1]! + start[b]!;
    firstRest[b] = firstRest[b]! + start[b]!;
  }
  // Fill: a searching collider at start[b], another at firstRest[b], each cursor advanced past it (one
  // pass without a branch on `searching`: the colliders of a pile are all searching until the first of
  // them rests, and code compiled without the other branch was thrown away then). Then start[b] is the
  // bucket's first resting place and firstRest[b] the next bucket's start: swapped back into place.
  for (let i = 0; i < n; i++) {
    if (order[i] === -1) continue;
    const b = bucket[i]!,
      on = searching[i]!,
      s = start[b]!,
      r = firstRest[b]!;
    items[on * s + (1 - on) * r] = i;
    start[b] = s + on;
    firstRest[b] = r + 1 - on;
  }
  for (let b = size; b > 0; b--) {
    const rest = start[b - 1]!;
    start[b] = firstRest[b - 1]!;
    firstRest[b - 1] = rest;
  }
  start[0] = 0;
  // The boxes in bucket order, packed, so the neighbour search reads memory in sequence instead of
  // jumping through the collider arrays.
  const placed = start[size]!;
  if (grid.packed.length < PackedBox.STRIDE * placed) grid.packed = new Float64Array(2 * PackedBox.STRIDE * placed);
  const pk = grid.packed;
  for (let k = 0; k < placed; k++) {
    const j = items[k]!,
      o = PackedBox.STRIDE * k;
    pk[o + PackedBox.MIN_X] = minX[j]!;
    pk[o + PackedBox.MAX_X] = sc.maxX[j]!;
    pk[o + PackedBox.MIN_Y] = minY[j]!;
    pk[o + PackedBox.MAX_Y] = sc.maxY[j]!;
    pk[o + PackedBox.MIN_Z] = minZ[j]!;
    pk[o + PackedBox.MAX_Z] = sc.maxZ[j]!;
    pk[o + PackedBox.KEY] = searching[j] === 1 ? j : Infinity;
  }
}

/**
 * The searching colliders against their grid neighbours (fillGrid's grid, cells 1 / inv wide): every
 * overlapping pair that may collide goes to `pair`. Sources are the colliders of moving (dynamic or
 * kinematic) bodies; a resting pile's sleeping and static colliders are only ever met as neighbours, so
 * an asleep pile costs no neighbour search. A box that overlaps a searching one has its low corner in
 * [min - cell, max] on each axis (no box is wider than a cell): cells from c - 1 up to the cell of the
 * searching box's high corner. In the dense grid (`dense`, denseCells' layout) the cells a box reaches
 * along x are consecutive buckets, so each (y, z) row of its neighbourhood is one run of the packed
 * boxes, nine runs at most; in the hashed one (bucket mask `mask`) each cell is a bucket of its own.
 */
function searchGrid(world: PhysicsWorld, s: Shape3DStore, st: Contact3DState, n: number, inv: number, dense: boolean, mask: number): void {
  const sc = scratch;
  const start = grid.start,
    items = grid.items,
    seen = grid.seen,
    order = sc.order,
    firstRest = grid.firstRest,
    searching = grid.searching;
  const minX = sc.minX,
    maxX = sc.maxX,
    minY = sc.minY,
    maxY = sc.maxY,
    minZ = sc.minZ,
    maxZ = sc.maxZ;
  // The hashed grid's cells are not shifted to an origin.
  const ox = dense ? grid.ox : 0,
    oy = dense ? grid.oy : 0,
    oz = dense ? grid.oz : 0,
    gx = grid.gx,
    gy = grid.gy;
  for (let i = 0; i < n; i++) {
    if (order[i] === -1 || searching[i] === 0) continue;
    const x0 = minX[i]!,
      x1 = maxX[i]!,
      y0 = minY[i]!,
      y1 = maxY[i]!,
      z0 = minZ[i]!,
      z1 = maxZ[i]!;
    const cx = Math.floor(x0 * inv) - ox,
      cy = Math.floor(y0 * inv) - oy,
      cz = Math.floor(z0 * inv) - oz;
    const hx = Math.floor(x1 * inv) - ox - cx,
      hy = Math.floor(y1 * inv) - oy - cy,
      hz = Math.floor(z1 * inv) - oz - cz;
    if (dense) {
      // At most c + 1 on each axis, also when rounding puts a box's ends just over a cell apart (the
      // grid spans one cell beyond every low corner).
      const ux = hx < 1 ? hx : 1,
        uy = hy < 1 ? hy : 1,
        uz = hz < 1 ? hz : 1;
      for (let dz = -1; dz <= uz; dz++)
        for (let dy = -1; dy <= uy; dy++) {
          const row = cx + gx * (cy + dy + gy * (cz + dz));
          scanBoxes(world, s, st, i, start[row - 1]!, start[row + ux + 1]!, x0, x1, y0, y1, z0, z1);
        }
      continue;
    }
    const mark = i + 1;
    for (let dx = -1; dx <= hx; dx++)
      for (let dy = -1; dy <= hy; dy++)
        for (let dz = -1; dz <= hz; dz++) {
          const b = cellHash(cx + dx, cy + dy, cz + dz, mask);
          // Two neighbour cells may share a bucket: each bucket is searched once per collider.
          if (seen[b] === mark) continue;
          seen[b] = mark;
          // Of the bucket's searching colliders (ascending) only those above i can be taken: skipped.
          const b0 = start[b]!;
          let k = firstRest[b]!;
          while (k > b0 && items[k - 1]! > i) k--;
          scanBoxes(world, s, st, i, k, start[b + 1]!, x0, x1, y0, y1, z0, z1);
        }
  }
}

/**
 * The packed boxes k to e - 1 (fillGrid's order) against searching collider i's box (x0 to x1, y0 to
 * y1, z0 to z1, m): each that overlaps it, may collide with it (meets) and is not a searching collider
 * at or below i (a pair of two searching colliders is taken from its lower index) goes to `pair`.
 */
function scanBoxes(
  world: PhysicsWorld,
  s: Shape3DStore,
  st: Contact3DState,
  i: number,
  k: number,
  e: number,
  x0: number,
  x1: number,
  y0: number,
  y1: number,
  z0: number,
  z1: number,
): void {
  const sc = scratch,
    type = world.collision.bodyType,
    items = grid.items,
    pk = grid.packed;
  for (; k < e; k++) {
    const o = PackedBox.STRIDE * k;
    if (
      !(pk[o + PackedBox.KEY]! > i) ||
      pk[o + PackedBox.MIN_X]! > x1 ||
      pk[o + PackedBox.MAX_X]! < x0 ||
      pk[o + PackedBox.MIN_Y]! > y1 ||
      pk[o + PackedBox.MAX_Y]! < y0 ||
      pk[o + PackedBox.MIN_Z]! > z1 ||
      pk[o + PackedBox.MAX_Z]! < z0
    )
      continue;
    const j = items[k]!;
    if (!meets(type[sc.body[i]!]!, type[sc.body[j]!]!)) continue;
    pair(world, s, st, i, j);
  }
}

/** Pairs of which neither collider searched: those that had a manifold last step (resting neighbours), to `pair` if their boxes still overlap. */
function restingPairs(world: PhysicsWorld, s: Shape3DStore, st: Contact3DState): void {
  const sc = scratch,
    type = world.collision.bodyType,
    order = sc.order,
    searching = grid.searching;
  const P = st.previous,
    cap = world.capacity,
    colliderOf = sc.colliderOf,
    colliderStamp = sc.colliderStamp,
    colliderPass = sc.colliderPass;
  for (let r = 0, np = P.count; r < np; r++) {
    if (P.sub[r] !== 0 || P.bodyA[r] === 0) continue; // planes and mesh triangles: planesAndMeshes
    const ea = P.shapeA[r]!,
      eb = P.shapeB[r]!;
    if (ea > cap || eb > cap || colliderStamp[ea] !== colliderPass || colliderStamp[eb] !== colliderPass) continue;
    const i = colliderOf[ea]!,
      j = colliderOf[eb]!;
    // Every test for every row (bits, not short-circuits): the rows of a pile all have a searching collider
    // until its first body rests, and code compiled before then without the other tests was thrown away.
    if ((searching[i]! | searching[j]! | +(order[i] === -1) | +(order[j] === -1)) !== 0) continue;
    if (!boxesOverlap(i, j)) continue;
    if (!meets(type[sc.body[i]!]!, type[sc.body[j]!]!)) continue;
    pair(world, s, st, i, j);
  }
}

/** The large colliders (gridCell) against every other collider whose box overlaps theirs, to `pair`. */
function largePairs(world: PhysicsWorld, s: Shape3DStore, st: Contact3DState, n: number): void {
  const sc = scratch,
    type = world.collision.bodyType,
    order = sc.order,
    large = grid.large,
    nl = grid.largeCount;
  for (let l = 0; l < nl; l++) {
    const i = large[l]!;
    const ti = type[sc.body[i]!]!;
    for (let j = 0; j < n; j++) {
      if (j === i || (order[j] === -1 && j < i)) continue;
      if (!boxesOverlap(i, j)) continue;
      if (!meets(ti, type[sc.body[j]!]!)) continue;
      pair(world, s, st, i, j);
    }
  }
}

/** Whether the fattened boxes of colliders i and j overlap (touching counts). */
function boxesOverlap(i: number, j: number): boolean {
  const sc = scratch;
  return !(
    sc.minX[j]! > sc.maxX[i]! ||
    sc.maxX[j]! < sc.minX[i]! ||
    sc.minY[j]! > sc.maxY[i]! ||
    sc.maxY[j]! < sc.minY[i]! ||
    sc.minZ[j]! > sc.maxZ[i]! ||
    sc.maxZ[j]! < sc.minZ[i]!
  );
}
