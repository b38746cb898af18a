import type { PhysicsWorld } from '../../world/options.js';
import { query } from '../../world/query.js';
import { classifyDynamic, classifyRanked, lookUpBodyBits } from '../body-class.js';
import { BodyType, type CollisionState, PairKind } from '../state.js';

export { BodyType, PairKind } from '../state.js';

import { wakeTag } from '../../islands/sleep.js';
import { ballPairsStage } from './grid-pairs.js';

/** Bodies whose reach (radius + speculative margin) exceeds this many times the mean reach skip the grid. */
const OVERSIZED_FACTOR = 2.5;

/**
 * The broadphase uses a dense grid (one bucket per cell, in space order) when there are at least
 * DENSE_MIN_BODIES balls and the cells spanned by the ordinary ones, with a cell to spare on every
 * side, number at most DENSE_CELLS_PER_BODY per ball (plus 64); other worlds use the spatial hash (a
 * power-of-two table of at least 2 buckets per body, in an order unrelated to space). The space order
 * is what makes the dense grid pay: the pairs, contacts and solver bodies that follow it read memory
 * near each other, where the hash's order jumps across the whole solver state, which a large world's
 * does not fit in a core's cache (balls-in-box: 22 % less CPU time a step at 5,000 and 20,000 balls,
 * 7 % at 2,000). A small world's state fits in the cache anyway, and keeps the hash's order.
 * @category Collision
 */
export const DENSE_CELLS_PER_BODY = 8;

/**
 * Fewest balls for the dense grid (see DENSE_CELLS_PER_BODY).
 * @category Collision
 */
export const DENSE_MIN_BODIES = 1024;

/**
 * Largest cell coordinate, in cells either side of the origin (2^28). Cell coordinates are clamped to
 * [-CELL_LIMIT, CELL_LIMIT]: bodies farther out than CELL_LIMIT cells (about 2.7e7 m with 0.1 m
 * cells) share the outermost cells of the grid. Clamping keeps neighbouring cells neighbours (it is
 * monotonic), so they are still collided correctly, only tested against more bodies; and it keeps
 * every cell loop finite (a float cell index beyond 2^53 could not be incremented).
 * @category Collision
 */
export const CELL_LIMIT = 268_435_456;

/** The cell coordinate of x (m) for cells of 1 / invCell metres, clamped to +-CELL_LIMIT (NaN gives 0). */
function cellOf(x: number, invCell: number): number {
  return cellClamp(Math.floor(x * invCell));
}

/**
 * A floored cell coordinate c = floor(x / cell) clamped to +-CELL_LIMIT (NaN gives 0): cellOf(x, inv)
 * is cellClamp(Math.floor(x * inv)). The hot loops call this with the floored value, a whole number
 * V8 passes untagged as a small integer, where cellOf's x and invCell were boxed (allocated) at every
 * call it did not inline.
 */
function cellClamp(c: number): number {
  return c > CELL_LIMIT ? CELL_LIMIT : c < -CELL_LIMIT ? -CELL_LIMIT : c === c ? c : 0;
}

/** Scratch of queryBox: the box's lower corner [0..2] and upper corner [3..5], m (no doubles cross the call). Not world state. */
const boxArgs = new Float64Array(6);

function hashCell(cx: number, cy: number, cz: number): number {
  return (Math.imul(cx, 73856093) ^ Math.imul(cy, 19349663) ^ Math.imul(cz, 83492791)) >>> 0;
}

function ensurePairs(cs: CollisionState, needed: number): void {
  if (needed <= cs.pairA.length) return;
  let n = cs.pairA.length;
  while (n < needed) n *= 2;
  const a = new Int32Array(n),
    b = new Int32Array(n),
    k = new Uint8Array(n);
  a.set(cs.pairA.subarray(0, cs.pairCount));
  b.set(cs.pairB.subarray(0, cs.pairCount));
  k.set(cs.pairKind.subarray(0, cs.pairCount));
  cs.pairA = a;
  cs.pairB = b;
  cs.pairKind = k;
}

function pushPair(cs: CollisionState, kind: number, a: number, b: number): void {
  const i = cs.pairCount;
  if (i >= cs.pairA.length) ensurePairs(cs, i + 1);
  cs.pairA[i] = a;
  cs.pairB[i] = b;
  cs.pairKind[i] = kind;
  cs.pairCount = i + 1;
}

/** Whether a pair of body types should meet even though neither is dynamic: a kinematic body wakes a sleeping one. */
function wakes(ta: number, tb: number): boolean {
  return (ta === BodyType.Kinematic && tb === BodyType.Sleeping) || (ta === BodyType.Sleeping && tb === BodyType.Kinematic);
}

/**
 * Records a ball-ball candidate pair. A sleeping body met by a moving or kinematic body is woken (it
 * joins this step as a dynamic body, given the gravity step the integrator skipped while it slept);
 * met by a resting body it stays asleep and acts as immovable geometry (infinite mass, at rest), so a
 * body resting against a sleeping pile is held up by it and can fall asleep too (Box2D likewise wakes
 * islands only when something moving touches them).
 */
function addBallPair(world: PhysicsWorld, cs: CollisionState, e: number, f: number): void {
  const type = cs.bodyType;
  const te = type[e]!,
    tf = type[f]!;
  if (te === BodyType.Sleeping && tf === BodyType.Sleeping) return;
  const rest = cs.sleep.restTime;
  if (te === BodyType.Sleeping && (tf === BodyType.Kinematic || rest[f] === 0)) wakeForContact(world, cs, e);
  if (tf === BodyType.Sleeping && (te === BodyType.Kinematic || rest[e] === 0)) wakeForContact(world, cs, f);
  pushPair(cs, PairKind.BallBall, e < f ? e : f, e < f ? f : e);
}

/**
 * Wakes a sleeping body met by an awake one during the broadphase: it becomes dynamic for this step,
 * with the velocity and position the skipped integration would have given it (v = g h, x += g h^2 / 2),
 * and is queued so its Sleeping tag is removed after the pass.
 */
function wakeForContact(world: PhysicsWorld, cs: CollisionState, e: number): void {
  const c = world.components;
  classifyDynamic(world, e);
  const g = world.gravity,
    h = world.h;
  c.Velocity.x[e] = g[0]! * h;
  c.Velocity.y[e] = g[1]! * h;
  c.Velocity.z[e] = g[2]! * h;
  c.PreviousPosition.x[e] = c.Position.x[e]!;
  c.PreviousPosition.y[e] = c.Position.y[e]!;
  c.PreviousPosition.z[e] = c.Position.z[e]!;
  const f = 0.5 * h * h;
  c.Position.x[e] = c.Position.x[e]! + g[0]! * f;
  c.Position.y[e] = c.Position.y[e]! + g[1]! * f;
  c.Position.z[e] = c.Position.z[e]! + g[2]! * f;
  if (cs.wakeCount >= cs.wakeList.length) {
    const l = new Int32Array(cs.wakeList.length * 2 + 16);
    l.set(cs.wakeList);
    cs.wakeList = l;
  }
  cs.wakeList[cs.wakeCount++] = e;
}

/**
 * Wakes, for this step, every sleeping body in the islands of the bodies woken since index `from` of
 * the wake list (they were asleep together, so they must be solved together).
 */
function wakeIslands(world: PhysicsWorld, cs: CollisionState, from: number): void {
  const island = cs.sleep.island;
  const ids = new Set<number>();
  for (let i = from; i < cs.wakeCount; i++) ids.add(island[cs.wakeList[i]!]!);
  const asleep = query(world, [world.components.Sleeping]);
  const type = cs.bodyType;
  for (let i = 0; i < asleep.length; i++) {
    const e = asleep[i]!;
    if (type[e] === BodyType.Sleeping && ids.has(island[e]!)) wakeForContact(world, cs, e);
  }
}

function ensureGrid(cs: CollisionState, bodies: number, tableSize: number): void {
  const g = cs.grid;
  if (g.sorted.length < bodies) {
    let n = Math.max(64, g.sorted.length);
    while (n < bodies) n *= 2;
    g.sorted = new Int32Array(n);
    g.cellX = new Int32Array(n);
    g.cellY = new Int32Array(n);
    g.cellZ = new Int32Array(n);
    g.bucketOf = new Int32Array(n);
    g.oversized = new Int32Array(n);
    g.candidates = new Int32Array(n);
  }
  if (g.bucketStart.length < tableSize + 1) g.bucketStart = new Int32Array(tableSize + 1);
  g.tableSize = tableSize;
}

/**
 * Collide stage, part 1: finds candidate pairs of bodies that may touch during this step.
 *
 * Every body with `Position` and `Ball` takes part, placed where it was at the start of the step
 * (`PreviousPosition`) and grown by a speculative margin |v| h + min(d_spec / 2, r / 4), so that pairs that will
 * meet during the step are found before they overlap (speculative contacts, Catto, "Continuous
 * Collision", GDC 2013). Bodies go into a uniform spatial-hash grid whose cell edge is twice the
 * largest reach of ordinary bodies; each body is tested against its own cell and half of its
 * neighbours, so the cost grows linearly with the body count at fixed density. Bodies much larger or
 * faster than the mean are kept out of the grid and query the cells their reach covers. Static
 * segments query the cells along their bounding box.
 *
 * Also fills the per-body scratch the solver reads: effective inverse mass and inertia (0 for static
 * and kinematic bodies), body type and margin.
 * @category Collision
 */
export function broadphaseSystem(world: PhysicsWorld): void {
  const c = world.components;
  const cs = world.collision;
  cs.pairCount = 0;
  const balls = query(world, [c.Position, c.Ball]);
  const n = balls.length;
  cs.stats.pairs = 0;
  if (n === 0) return;
  lookUpBodyBits(world);
  const reachSum = classifyBalls(world, balls);
  // Cell size from the reach of ordinary bodies; outliers go to the oversized list.
  const limit = OVERSIZED_FACTOR * (reachSum / n);
  const maxReachAll = bucketBalls(world, balls, limit);
  const small = n - cs.grid.oversizedCount;
  // Pair generation. Waking a sleeping body wakes its whole island; the pass is then run again so the
  // woken bodies meet their neighbours (which were still asleep, and skipped, in the first pass).
  for (let pass = 0; pass < 4; pass++) {
    cs.pairCount = 0;
    const woken = cs.wakeCount;
    // Pairs among grid bodies: own cell (later entries only) and half the neighbours. A dense grid's
    // buckets hold one cell each (no coordinates to compare), its neighbours a fixed bucket offset away.
    // One range kernel, on the world's threads or here (collision/broadphase/grid-pairs.ts: the same
    // pairs and wakes in the same order on any thread count).
    ballPairsStage(world, cs, small, cs.grid.tableSize - 1, wakeForContact);
    oversizedPairs(world, small);
    segmentPairs(world, small, maxReachAll);
    if (cs.wakeCount === woken) break;
    wakeIslands(world, cs, woken);
  }
  cs.stats.pairs = cs.pairCount;
  for (let i = 0; i < cs.wakeCount; i++) wakeTag(world, cs.wakeList[i]!);
}

/**
 * The per-body scratch the solver reads, for every ball: body type, effective inverse mass and inertia
 * (dynamic here, then classifyRanked's class for the static, kinematic and sleeping ones: 0) and
 * speculative margin; a static ball's previous position is where it is. Needs lookUpBodyBits(world). Returns the sum of the balls' reaches (radius plus margin), m.
 */
function classifyBalls(world: PhysicsWorld, balls: ArrayLike<number>): number {
  const c = world.components;
  const cs = world.collision;
  const n = balls.length;
  const h = world.h;
  const invMass = cs.invMass,
    invInertia = cs.invInertia,
    margin = cs.margin,
    type = cs.bodyType;
  const { x: px, y: py, z: pz } = c.Position;
  const { x: ox, y: oy, z: oz } = c.PreviousPosition;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const radius = c.Ball.radius;
  const mInv = c.Mass.inv;
  const halfSpec = 0.5 * cs.settings.speculativeDistance;

  // Dynamic first, then overwrite the others (collision/body-class.ts ranks them).
  let reachSum = 0;
  for (let i = 0; i < n; i++) {
    const e = balls[i]!;
    invMass[e] = mInv[e]!;
    invInertia[e] = 0;
    type[e] = BodyType.Dynamic;
    const sx = vx[e]!,
      sy = vy[e]!,
      sz = vz[e]!;
    // The speculative pad shrinks for small balls (a quarter radius) so a heap of marbles does not
    // turn every neighbour within 5 cm into a contact.
    const r = radius[e]!;
    const m = Math.sqrt(sx * sx + sy * sy + sz * sz) * h + (halfSpec < 0.25 * r ? halfSpec : 0.25 * r);
    margin[e] = m;
    reachSum += radius[e]! + m;
  }
  const spinning = query(world, [c.Ball, c.Inertia, c.AngularVelocity]);
  const iInv = c.Inertia.inv;
  for (let i = 0; i < spinning.length; i++) {
    const e = spinning[i]!;
    invInertia[e] = iInv[e]!;
  }
  cs.wakeCount = 0;
  const fixed = classifyRanked(world, [c.Ball, c.Position]);
  for (let i = 0; i < fixed.length; i++) {
    const e = fixed[i]!;
    margin[e] = Math.min(halfSpec, 0.25 * radius[e]!);
    // Static bodies are never integrated: where they are is where they were.
    ox[e] = px[e]!;
    oy[e] = py[e]!;
    oz[e] = pz[e]!;
  }
  return reachSum;
}

/**
 * Sorts the balls into the grid, written to `cs.grid` (ensureGrid sizes its arrays). First its layout
 * for balls whose reach is at most `limit` (m): the cell size (twice the largest reach), and a dense
 * grid over the bodies' cells when they are few enough (buckets in space order: the pairs, contacts
 * and solver bodies follow, which keeps the solver's reads near each other), else the spatial hash.
 * Then a counting sort of the balls by the bucket of their cell (count, prefix sum, place); balls
 * whose reach is over `limit` go to the oversized list (the grid holds the others, n minus
 * `g.oversizedCount`). Returns the largest reach of any ball, oversized ones included, m.
 */
function bucketBalls(world: PhysicsWorld, balls: ArrayLike<number>, limit: number): number {
  const cs = world.collision,
    g = cs.grid;
  const n = balls.length;
  const is3D = world.dimensions === 3;
  const margin = cs.margin,
    radius = world.components.Ball.radius;
  const { x: ox, y: oy, z: oz } = world.components.PreviousPosition;
  // The ordinary bodies' extent too (NaN positions are counted in cell 0, as cellOf puts them).
  let maxReach = 0;
  let maxReachAll = 0;
  let loX = Infinity,
    hiX = -Infinity,
    loY = Infinity,
    hiY = -Infinity,
    loZ = Infinity,
    hiZ = -Infinity;
  let nan = false;
  for (let i = 0; i < n; i++) {
    const e = balls[i]!;
    const r = radius[e]! + margin[e]!;
    if (r > maxReachAll) maxReachAll = r;
    if (r > limit) continue;
    if (r > maxReach) maxReach = r;
    const x = ox[e]!,
      y = oy[e]!,
      z = is3D ? oz[e]! : 0;
    if (x < loX) loX = x;
    if (x > hiX) hiX = x;
    if (y < loY) loY = y;
    if (y > hiY) hiY = y;
    if (z < loZ) loZ = z;
    if (z > hiZ) hiZ = z;
    if (x !== x || y !== y || z !== z) nan = true;
  }
  const cell = 2 * maxReach;
  const invCell = 1 / cell;
  g.cellSize = cell;
  // cellOf is monotonic, so the extreme positions give the extreme cells.
  let cx0 = cellOf(loX, invCell),
    cx1 = cellOf(hiX, invCell),
    cy0 = cellOf(loY, invCell),
    cy1 = cellOf(hiY, invCell);
  let cz0 = cellOf(loZ, invCell),
    cz1 = cellOf(hiZ, invCell);
  if (nan) {
    cx0 = Math.min(cx0, 0);
    cx1 = Math.max(cx1, 0);
    cy0 = Math.min(cy0, 0);
    cy1 = Math.max(cy1, 0);
    cz0 = Math.min(cz0, 0);
    cz1 = Math.max(cz1, 0);
  }
  const spanX = cx1 - cx0 + 3,
    spanY = cy1 - cy0 + 3,
    spanZ = is3D ? cz1 - cz0 + 3 : 1;
  const cells = spanX * spanY * spanZ;
  const dense = n >= DENSE_MIN_BODIES && maxReach > 0 && spanX >= 3 && spanY >= 3 && cells <= DENSE_CELLS_PER_BODY * n + 64;
  let table = 16;
  if (dense) {
    table = cells;
    g.originX = cx0 - 1;
    g.originY = cy1 + 1;
    g.originZ = is3D ? cz0 - 1 : 0;
    g.spanX = spanX;
    g.spanXZ = spanX * spanZ;
  } else {
    while (table < 2 * n) table *= 2;
    g.originX = 0;
    g.originY = 0;
    g.originZ = 0;
    g.spanX = 0;
    g.spanXZ = 0;
  }
  ensureGrid(cs, n, table);
  // The counting sort into the layout just chosen (table, dense and invCell are the grid's now).
  const gx0 = g.originX,
    gy0 = g.originY,
    gz0 = g.originZ,
    sX = g.spanX,
    sXZ = g.spanXZ;
  const mask = table - 1;
  const start = g.bucketStart;
  start.fill(0, 0, table + 1);
  const sorted = g.sorted,
    cellX = g.cellX,
    cellY = g.cellY,
    cellZ = g.cellZ,
    bucketOf = g.bucketOf,
    over = g.oversized;
  let overCount = 0;
  for (let i = 0; i < n; i++) {
    const e = balls[i]!;
    if (radius[e]! + margin[e]! > limit) {
      bucketOf[i] = -1;
      over[overCount++] = e;
      continue;
    }
    const cx = cellClamp(Math.floor(ox[e]! * invCell)),
      cy = cellClamp(Math.floor(oy[e]! * invCell)),
      cz = is3D ? cellClamp(Math.floor(oz[e]! * invCell)) : 0;
    const b = dense ? cx - gx0 + (cz - gz0) * sX + (gy0 - cy) * sXZ : hashCell(cx, cy, cz) & mask;
    bucketOf[i] = b;
    start[b + 1]!++;
  }
  g.oversizedCount = overCount;
  for (let b = 0; b < table; b++) start[b + 1]! += start[b]!;
  // Place: reuse the cell arrays' tail-free layout; a cursor per bucket is start[b] advanced in place,
  // then restored by shifting (start[b] ends at the next bucket's start).
  for (let i = 0; i < n; i++) {
    const b = bucketOf[i]!;
    if (b < 0) continue;
    const e = balls[i]!;
    const p = start[b]!++;
    sorted[p] = e;
    cellX[p] = cellClamp(Math.floor(ox[e]! * invCell));
    cellY[p] = cellClamp(Math.floor(oy[e]! * invCell));
    cellZ[p] = is3D ? cellClamp(Math.floor(oz[e]! * invCell)) : 0;
  }
  for (let b = table; b > 0; b--) start[b] = start[b - 1]!;
  start[0] = 0;
  return maxReachAll;
}

/** Pairs of the oversized balls: against each other directly, against the `small` grid balls by a range query. */
function oversizedPairs(world: PhysicsWorld, small: number): void {
  const cs = world.collision,
    g = cs.grid;
  const over = g.oversized,
    overCount = g.oversizedCount;
  const type = cs.bodyType,
    margin = cs.margin,
    radius = world.components.Ball.radius;
  const { x: ox, y: oy, z: oz } = world.components.PreviousPosition;
  for (let i = 0; i < overCount; i++) {
    const e = over[i]!;
    const x = ox[e]!,
      y = oy[e]!,
      z = oz[e]!;
    const reach = radius[e]! + margin[e]!;
    const te = type[e]!;
    const B = boxArgs;
    B[0] = x - reach;
    B[1] = y - reach;
    B[2] = z - reach;
    B[3] = x + reach;
    B[4] = y + reach;
    B[5] = z + reach;
    // The grid balls near e (queryBox reads only the grid, which the wakes below leave alone).
    const found = queryBox(world, cs, small);
    const cand = g.candidates;
    // The oversized balls after e, then those grid balls: each pair once, in that order.
    for (let k = i + 1, end = overCount + found; k < end; k++) {
      const f = k < overCount ? over[k]! : cand[k - overCount]!;
      if (te !== BodyType.Dynamic && type[f] !== BodyType.Dynamic && !wakes(te, type[f]!)) continue;
      const dx = ox[f]! - x,
        dy = oy[f]! - y,
        dz = oz[f]! - z;
      const rr = reach + radius[f]! + margin[f]!;
      if (dx * dx + dy * dy + dz * dz < rr * rr) addBallPair(world, cs, e, f);
    }
  }
}

/** Static segments against the moving balls near their bounding box, padded by the largest ball reach `maxReachAll` (m). */
function segmentPairs(world: PhysicsWorld, small: number, maxReachAll: number): void {
  const c = world.components;
  const segs = query(world, [c.Segment]);
  if (segs.length === 0) return;
  const cs = world.collision,
    g = cs.grid,
    type = cs.bodyType;
  const over = g.oversized,
    overCount = g.oversizedCount;
  const S = c.Segment;
  for (let i = 0; i < segs.length; i++) {
    const s = segs[i]!;
    const pad = S.radius[s]! + maxReachAll;
    const ax = S.ax[s]!,
      ay = S.ay[s]!,
      az = S.az[s]!,
      bx = S.bx[s]!,
      by = S.by[s]!,
      bz = S.bz[s]!;
    const B = boxArgs;
    B[0] = Math.min(ax, bx) - pad;
    B[1] = Math.min(ay, by) - pad;
    B[2] = Math.min(az, bz) - pad;
    B[3] = Math.max(ax, bx) + pad;
    B[4] = Math.max(ay, by) + pad;
    B[5] = Math.max(az, bz) + pad;
    const found = queryBox(world, cs, small);
    const cand = g.candidates;
    for (let k = 0; k < found; k++) {
      const f = cand[k]!;
      if (type[f] < BodyType.Static) pushPair(cs, PairKind.SegmentBall, s, f);
    }
    for (let j = 0; j < overCount; j++) {
      const f = over[j]!;
      if (type[f] < BodyType.Static) pushPair(cs, PairKind.SegmentBall, s, f);
    }
  }
}

/**
 * Writes into `cs.grid.candidates` every grid body whose cell overlaps the box [lo, hi] (`boxArgs`) widened by
 * half a cell (so bodies whose reach crosses into the box are included) and returns their count;
 * scans every grid body instead when the box covers more cells than there are bodies. Cell ranges are
 * clamped like the grid's cells (see CELL_LIMIT), so the loops are finite at any coordinate.
 */
function queryBox(world: PhysicsWorld, cs: CollisionState, small: number): number {
  const g = cs.grid;
  const inv = 1 / g.cellSize;
  const half = 0.5 * g.cellSize;
  const is3D = world.dimensions === 3;
  const B = boxArgs;
  const x0 = B[0]!,
    y0 = B[1]!,
    z0 = B[2]!,
    x1 = B[3]!,
    y1 = B[4]!,
    z1 = B[5]!;
  const cx0 = cellClamp(Math.floor((x0 - half) * inv)),
    cx1 = cellClamp(Math.floor((x1 + half) * inv));
  const cy0 = cellClamp(Math.floor((y0 - half) * inv)),
    cy1 = cellClamp(Math.floor((y1 + half) * inv));
  const cz0 = is3D ? cellClamp(Math.floor((z0 - half) * inv)) : 0,
    cz1 = is3D ? cellClamp(Math.floor((z1 + half) * inv)) : 0;
  const cells = (cx1 - cx0 + 1) * (cy1 - cy0 + 1) * (cz1 - cz0 + 1);
  const sorted = g.sorted,
    cellX = g.cellX,
    cellY = g.cellY,
    cellZ = g.cellZ,
    start = g.bucketStart;
  const out = g.candidates;
  let count = 0;
  if (!(cells <= small)) {
    for (let p = 0; p < small; p++) {
      const x = cellX[p]!,
        y = cellY[p]!,
        z = cellZ[p]!;
      if (x >= cx0 && x <= cx1 && y >= cy0 && y <= cy1 && z >= cz0 && z <= cz1) out[count++] = sorted[p]!;
    }
    return count;
  }
  const mask = g.tableSize - 1;
  const sX = g.spanX,
    sXZ = g.spanXZ,
    gx0 = g.originX,
    gy0 = g.originY,
    gz0 = g.originZ;
  // A dense grid holds nothing outside its range: the loops are clipped to it (cells there are empty).
  const lx = sX > 0 ? Math.max(cx0, gx0) : cx0,
    hx = sX > 0 ? Math.min(cx1, gx0 + sX - 1) : cx1;
  const ly = sX > 0 ? Math.max(cy0, gy0 - g.tableSize / sXZ + 1) : cy0,
    hy = sX > 0 ? Math.min(cy1, gy0) : cy1;
  const lz = sX > 0 ? Math.max(cz0, gz0) : cz0,
    hz = sX > 0 ? Math.min(cz1, gz0 + sXZ / sX - 1) : cz1;
  for (let cz = lz; cz <= hz; cz++)
    for (let cy = ly; cy <= hy; cy++)
      for (let cx = lx; cx <= hx; cx++) {
        const b = sX > 0 ? cx - gx0 + (cz - gz0) * sX + (gy0 - cy) * sXZ : hashCell(cx, cy, cz) & mask;
        for (let q = start[b]!, end = start[b + 1]!; q < end; q++) {
          if (cellX[q] === cx && cellY[q] === cy && cellZ[q] === cz) out[count++] = sorted[q]!;
        }
      }
  return count;
}
