import type { Shape3DStore } from '../../shapes/store-3d.js';
import type { PhysicsWorld } from '../../world/options.js';
import { meets, scratch } from '../colliders-3d.js';
import type { Contact3DState } from '../manifolds-3d.js';
import { pair } from '../pair-manifolds-3d.js';
import { planesAndMeshes } from '../planes-meshes-3d.js';
import { BodyType } from '../state.js';

/**
 * Broadphase of the 3D shape pass: a hashed uniform grid of the colliders' fattened boxes, searched by
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

/** Broadphase scratch: a hashed uniform grid (counting sort of colliders by the cell of their box's low corner). */
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
};

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
  /** Numbers a box. */
  STRIDE = 6,
}

/**
 * Broadphase: every collider's box goes into the cell of a uniform grid holding its low corner, with a
 * cell as wide as the widest ordinary box, so a box can only meet boxes whose low corner lies in its own
 * cell or one of the 26 around it; boxes more than four times the mean width ("large": a ground slab)
 * are tested against every collider instead. Each candidate pair is seen once (from its lower collider
 * index) and goes to `pair`. Then every collider against the meshes and the planes.
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
  let size = 64;
  while (size < 2 * n) size *= 2;
  markSearching(world, s, n);
  fillGrid(n, inv, size);
  searchNeighbours(world, s, st, n, inv, size - 1);
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

/**
 * The grid of `size` buckets (a power of two) of the ordinary colliders, by the cell (1 / inv wide) of
 * their box's low corner: grid.items in bucket order from grid.start[b], the searching colliders of a
 * bucket first, then the others from grid.firstRest[b], each part in ascending collider index; and their
 * boxes packed in that order (grid.packed, PackedBox).
 */
function fillGrid(n: number, inv: number, size: number): void {
  const sc = scratch,
    mask = size - 1;
  if (grid.start.length < size + 1) {
    grid.start = new Int32Array(2 * size + 1);
    grid.seen = new Int32Array(2 * size + 1);
  }
  grid.seen.fill(0, 0, size);
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
  // Counting sort by bucket; within a bucket the searching colliders first, then the others (from
  // firstRest[b]), each part in ascending collider index, so a collider meets the searching ones above
  // its own index without testing those below (their own search finds the pair).
  start.fill(0, 0, size + 1);
  firstRest.fill(0, 0, size);
  for (let i = 0; i < n; i++) {
    if (order[i] === -1) continue;
    const b = cellHash(Math.floor(minX[i]! * inv), Math.floor(minY[i]! * inv), Math.floor(minZ[i]! * inv), mask);
    bucket[i] = b;
    start[b + 1]!++;
    firstRest[b] = firstRest[b]! + searching[i]!;
  }
  for (let b = 0; b < size; b++) {
    start[b + 1] = start[b + 1]! + start[b]!;
    firstRest[b] = firstRest[b]! + start[b]!;
  }
  // Fill (start[b] is advanced while filling, then restored from the next bucket's start).
  for (let i = 0; i < n; i++) {
    if (order[i] === -1 || searching[i] === 0) continue;
    const b = bucket[i]!;
    items[start[b]!++] = i;
  }
  for (let i = 0; i < n; i++) {
    if (order[i] === -1 || searching[i] === 1) continue;
    const b = bucket[i]!;
    items[start[b]!++] = i;
  }
  for (let b = size; b > 0; b--) start[b] = start[b - 1]!;
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
  }
}

/**
 * The searching colliders against their grid neighbours (fillGrid's grid, cells 1 / inv wide, bucket
 * mask `mask`): every overlapping pair that may collide goes to `pair`. Sources are the colliders of
 * moving (dynamic or kinematic) bodies; a resting pile's sleeping and static colliders are only ever met
 * as neighbours, so an asleep pile costs no neighbour search.
 */
function searchNeighbours(world: PhysicsWorld, s: Shape3DStore, st: Contact3DState, n: number, inv: number, mask: number): void {
  const sc = scratch,
    type = world.collision.bodyType;
  const start = grid.start,
    items = grid.items,
    seen = grid.seen,
    order = sc.order,
    firstRest = grid.firstRest,
    searching = grid.searching,
    pk = grid.packed;
  const minX = sc.minX,
    maxX = sc.maxX,
    minY = sc.minY,
    maxY = sc.maxY,
    minZ = sc.minZ,
    maxZ = sc.maxZ;
  for (let i = 0; i < n; i++) {
    if (order[i] === -1 || searching[i] === 0) continue;
    const ti = type[sc.body[i]!]!;
    const x0 = minX[i]!,
      x1 = maxX[i]!,
      y0 = minY[i]!,
      y1 = maxY[i]!,
      z0 = minZ[i]!,
      z1 = maxZ[i]!;
    const cx = Math.floor(x0 * inv),
      cy = Math.floor(y0 * inv),
      cz = Math.floor(z0 * inv);
    // A box that overlaps this one has its low corner in [min - cell, max] on each axis (no box is wider
    // than a cell): cells from c - 1 up to the cell of this box's high corner.
    const hx = Math.floor(x1 * inv) - cx,
      hy = Math.floor(y1 * inv) - cy,
      hz = Math.floor(z1 * inv) - cz;
    const mark = i + 1;
    for (let dx = -1; dx <= hx; dx++)
      for (let dy = -1; dy <= hy; dy++)
        for (let dz = -1; dz <= hz; dz++) {
          const b = cellHash(cx + dx, cy + dy, cz + dz, mask);
          // Two neighbour cells may share a bucket: each bucket is searched once per collider.
          if (seen[b] === mark) continue;
          seen[b] = mark;
          // A pair of two searching colliders is taken from its lower index: of the bucket's searching
          // colliders (ascending), only those above i; then every collider that does not search.
          const b0 = start[b]!,
            e = start[b + 1]!;
          let k = firstRest[b]!;
          while (k > b0 && items[k - 1]! > i) k--;
          for (; k < e; k++) {
            const o = PackedBox.STRIDE * k;
            if (
              pk[o + PackedBox.MIN_X]! > x1 ||
              pk[o + PackedBox.MAX_X]! < x0 ||
              pk[o + PackedBox.MIN_Y]! > y1 ||
              pk[o + PackedBox.MAX_Y]! < y0 ||
              pk[o + PackedBox.MIN_Z]! > z1 ||
              pk[o + PackedBox.MAX_Z]! < z0
            )
              continue;
            const j = items[k]!;
            if (!meets(ti, type[sc.body[j]!]!)) continue;
            pair(world, s, st, i, j);
          }
        }
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
    if (searching[i] === 1 || searching[j] === 1 || order[i] === -1 || order[j] === -1) continue;
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
