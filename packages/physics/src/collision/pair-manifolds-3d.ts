import { wakesSleeper } from '../islands/step-wake.js';
import { M00, M01, M02, M10, M11, M12, M20, M21, M22, MAT3_STRIDE } from '../math/mat3-layout.js';
import { Shape3DKind, type Shape3DStore } from '../shapes/store-3d.js';
import { ANCHOR_AX, ANCHOR_AY, ANCHOR_AZ, ANCHOR_BX, ANCHOR_BY, ANCHOR_BZ, ANCHOR_STRIDE } from '../solver/manifold-layout-3d.js';
import { jointKeepsApart } from '../world/joint-no-collide.js';
import type { PhysicsWorld } from '../world/options.js';
import { ColliderMaterial, colA, colB, collider, manifold, queueWake, scratch } from './colliders-3d.js';
import { type Contact3DState, growManifold3DBuffer, lookupRow, rowKey } from './manifolds-3d.js';
import { BOX_A, BOX_B, BOX_CX, BOX_CY, BOX_CZ, BOX_HX, BOX_HY, BOX_HZ, BOX_MARGIN } from './narrowphase/box-args-3d.js';
import { boxArgs, boxBox3DAt } from './narrowphase/box-box-3d.js';
import { collide3D } from './narrowphase/collide-3d.js';
import { BodyType } from './state.js';

/**
 * Manifolds of the 3D shape pairs: the narrowphase of a pair the broadphase found, a resting box pair's
 * manifold reused from the previous step while neither body moved, and the manifold written as contact
 * rows in the bodies' local frames with its feature ids (for warm starting) and events.
 */

function filtered(s: Shape3DStore, a: number, b: number, ballA: boolean, ballB: boolean): boolean {
  const ca = ballA ? 1 : s.category[a]!,
    ma = ballA ? 0xffffffff : s.mask[a]!,
    ga = ballA ? 0 : s.group[a]!;
  const cb = ballB ? 1 : s.category[b]!,
    mb = ballB ? 0xffffffff : s.mask[b]!,
    gb = ballB ? 0 : s.group[b]!;
  if (ga !== 0 && ga === gb) return ga < 0;
  return (ca & mb) === 0 || (cb & ma) === 0;
}

/** The narrowphase of colliders i and j whose boxes overlap: filtering, sensors, then the manifold. */
export function pair(world: PhysicsWorld, s: Shape3DStore, st: Contact3DState, i: number, j: number): void {
  const sc = scratch;
  const bi = sc.body[i]!,
    bj = sc.body[j]!;
  if (bi === bj) return;
  if (jointKeepsApart(world.joints, bi, bj)) return; // jointed without collideConnected (joints/joint-3d.ts)
  // A moving body reaching a sleeping one: the sleeper takes part as static this step, and the sleep system wakes it.
  // Balls against balls are the ball narrowphase's.
  if (sc.ball[i] && sc.ball[j]) return;
  const a = sc.shape[i]! < sc.shape[j]! ? i : j,
    b = a === i ? j : i;
  const ea = sc.shape[a]!,
    eb = sc.shape[b]!;
  // Two shapes of the default filter never filter each other out (their columns in the store are not read).
  const mat = sc.material;
  if (
    (mat[ColliderMaterial.STRIDE * a + ColliderMaterial.PERMISSIVE] !== 1 ||
      mat[ColliderMaterial.STRIDE * b + ColliderMaterial.PERMISSIVE] !== 1) &&
    filtered(s, ea, eb, sc.ball[a] === 1, sc.ball[b] === 1)
  )
    return;
  const halfA = sc.boxHalf[a]!,
    halfB = sc.boxHalf[b]!;
  if (halfA >= 0 && halfB >= 0) {
    // Two boxes, neither a sensor (the common case): straight from the scratch poses, or last step's
    // manifold carried over.
    relativePose(a, b);
    const prev = previousBoxRow(st, ea, eb, world.capacity);
    if (prev >= 0 && reusable(st.previous, prev, a, b)) {
      reuseManifold(st.previous, prev, a, b);
      boxRow.from = prev;
    } else {
      const margin = scratch.spec + (sc.speed[a]! + sc.speed[b]!) * world.h;
      // The numbers go through boxArgs (doubles passed to a call are boxed: garbage every step).
      boxIntoArgs(s, BOX_A, a, ea);
      boxIntoArgs(s, BOX_B, b, eb);
      boxArgs[BOX_MARGIN] = margin;
      boxBox3DAt(sc.R, MAT3_STRIDE * a, sc.R, MAT3_STRIDE * b, manifold);
      boxRow.from = -1;
    }
    boxRow.a = a;
    boxRow.b = b;
    boxRow.prev = prev;
    if (manifold.count > 0) emitPair(world, s, st, a, b, bi, bj);
    boxRow.a = -1;
    return;
  }
  const sa = !sc.ball[a] && s.sensor[ea] === 1,
    sb = !sc.ball[b] && s.sensor[eb] === 1;
  if (sa && sb) return;
  collider(world, s, a, colA);
  collider(world, s, b, colB);
  if (sa || sb) {
    // Sensors report overlap (a point of negative separation) and push nothing.
    if (world.collision.bodyType[bi] !== BodyType.Dynamic && world.collision.bodyType[bj] !== BodyType.Dynamic) return;
    collide3D(colA, colB, 0, manifold);
    let overlap = false;
    for (let k = 0; k < manifold.count; k++) if (manifold.sep[k]! < 0) overlap = true;
    if (overlap)
      st.sensingNow.set(ea * (world.capacity + 1) + eb, sa ? [ea, eb, sc.body[a]!, sc.body[b]!] : [eb, ea, sc.body[b]!, sc.body[a]!]);
    return;
  }
  const margin = scratch.spec + (sc.speed[a]! + sc.speed[b]!) * world.h;
  collide3D(colA, colB, margin, manifold);
  if (manifold.count > 0) emitPair(world, s, st, a, b, bi, bj);
}

/**
 * Offset of the last box pair's previous row from the row it is written to (this pass): pairs come in
 * nearly the same order every step, so the previous row of the next pair is most often at the same
 * offset, found without a hash lookup (a cache miss each in a large pile) and read in sequence.
 */

/** Writes collider i's centre (m) and its box shape e's half extents (m) into boxArgs at `at` (BOX_A or BOX_B). */
function boxIntoArgs(s: Shape3DStore, at: number, i: number, e: number): void {
  const g = boxArgs,
    sc = scratch;
  g[at + BOX_CX] = sc.px[i]!;
  g[at + BOX_CY] = sc.py[i]!;
  g[at + BOX_CZ] = sc.pz[i]!;
  g[at + BOX_HX] = s.hx[e]!;
  g[at + BOX_HY] = s.hy[e]!;
  g[at + BOX_HZ] = s.hz[e]!;
}

/** The previous step's row of box pair (ea, eb), or -1: the row at `rowShift` if it is that pair's, else from the index. */
function previousBoxRow(st: Contact3DState, ea: number, eb: number, capacity: number): number {
  const P = st.previous,
    guess = st.current.count + scratch.rowShift;
  let prev: number;
  if (guess >= 0 && guess < P.count && P.shapeA[guess] === ea && P.shapeB[guess] === eb && P.sub[guess] === 0) prev = guess;
  else prev = lookupRow(st.previousIndex, rowKey(capacity, ea, eb, 0));
  if (prev >= 0) scratch.rowShift = prev - st.current.count;
  return prev;
}

/**
 * Manifold reuse for box pairs (after the persistent manifolds of Bullet and Box2D v2's idea that a
 * contact's features rarely change between steps): a box-box row keeps its pair's relative pose (B's
 * centre in A's frame and R_A^T R_B) from when the manifold was computed, the normal in A's frame and
 * each point's ends on both surfaces in their own frames. While the relative pose stays within
 * REUSE_SHIFT of the smaller box's smallest half extent (each coordinate) and REUSE_TURN (each entry of
 * R_A^T R_B, about radians), the next step rebuilds the manifold from those local points at the
 * current poses: same feature ids, normal R_A n_A, separation (p_B - p_A) . n measured anew (exact for
 * a corner on a face), instead of running the separating-axis test and the clipping. A pair resting
 * together (a stack, a rocking column) so skips the narrowphase; the bounds keep the error of a
 * carried point (a clipped point that would have slid along its edge) below 0.5 % of the box.
 */
const REUSE_SHIFT = 0.005;
const REUSE_TURN = 0.005;

/** The box pair being emitted: scratch indices (-1: not a box pair), the previous row reused (-1: computed), and its previous row (-1: none). */
const boxRow = { a: -1, b: -1, from: -1, prev: -1 };
/** Relative pose of the pair in `relativePose`'s order. */
/**
 * The layout of a box-box row's relative pose (Manifold3DBuffer.relPose, collision/manifolds-3d.ts, a row
 * at STRIDE i; and `rel`): B's centre in A's frame, R_A^T (c_B - c_A), m, then R_A^T R_B from TURN on
 * (math/mat3-layout.ts).
 */
enum RelPose {
  /** B's centre in A's frame, x, m. */
  X = 0,
  /** y, m. */
  Y = 1,
  /** z, m. */
  Z = 2,
  /** Where R_A^T R_B starts. */
  TURN = 3,
  /** Numbers a row. */
  STRIDE = 12,
}
const rel = new Float64Array(RelPose.STRIDE);

/** rel = (R_A^T (c_B - c_A), R_A^T R_B) of scratch colliders a and b. */
function relativePose(a: number, b: number): void {
  const sc = scratch,
    R = sc.R,
    oa = MAT3_STRIDE * a,
    ob = MAT3_STRIDE * b;
  const dx = sc.px[b]! - sc.px[a]!,
    dy = sc.py[b]! - sc.py[a]!,
    dz = sc.pz[b]! - sc.pz[a]!;
  for (let i = 0; i < 3; i++) {
    const a0 = R[oa + M00 + i]!,
      a1 = R[oa + M10 + i]!,
      a2 = R[oa + M20 + i]!;
    rel[RelPose.X + i] = a0 * dx + a1 * dy + a2 * dz;
    // Element (i, j) of R_A^T R_B: column i of R_A dotted with column j of R_B.
    for (let j = 0; j < 3; j++) rel[RelPose.TURN + 3 * i + j] = a0 * R[ob + M00 + j]! + a1 * R[ob + M10 + j]! + a2 * R[ob + M20 + j]!;
  }
}

/**
 * Whether previous row `r` is a box-box row whose relative pose is within the reuse bounds of `rel`
 * (its shift bound scaled by the smaller of colliders a's and b's smallest half extents). The colliders'
 * indices are passed rather than the size: a double argument to a call not inlined is boxed.
 */
function reusable(P: Contact3DState['previous'], r: number, a: number, b: number): boolean {
  if (P.local[r] !== 1) return false;
  const halfA = scratch.boxHalf[a]!,
    halfB = scratch.boxHalf[b]!,
    size = halfA < halfB ? halfA : halfB;
  const o = RelPose.STRIDE * r,
    RP = P.relPose,
    shift = REUSE_SHIFT * size;
  for (let k = RelPose.X; k <= RelPose.Z; k++) if (Math.abs(RP[o + k]! - rel[k]!) > shift) return false;
  for (let k = RelPose.TURN; k < RelPose.STRIDE; k++) if (Math.abs(RP[o + k]! - rel[k]!) > REUSE_TURN) return false;
  return true;
}

/** Rebuilds `manifold` from previous row r's local normal and points at the current poses of colliders a and b. */
function reuseManifold(P: Contact3DState['previous'], r: number, a: number, b: number): void {
  const sc = scratch,
    R = sc.R,
    oa = MAT3_STRIDE * a,
    ob = MAT3_STRIDE * b,
    m = manifold;
  const ax = sc.px[a]!,
    ay = sc.py[a]!,
    az = sc.pz[a]!,
    bx = sc.px[b]!,
    by = sc.py[b]!,
    bz = sc.pz[b]!;
  const N = P.localNormal,
    u = N[3 * r]!,
    v = N[3 * r + 1]!,
    w = N[3 * r + 2]!;
  const nx = R[oa + M00]! * u + R[oa + M01]! * v + R[oa + M02]! * w,
    ny = R[oa + M10]! * u + R[oa + M11]! * v + R[oa + M12]! * w,
    nz = R[oa + M20]! * u + R[oa + M21]! * v + R[oa + M22]! * w;
  m.nx = nx;
  m.ny = ny;
  m.nz = nz;
  const LA = P.localA,
    LB = P.localB,
    count = P.points[r]!;
  for (let k = 0; k < count; k++) {
    const q = 3 * (4 * r + k);
    const pax = ax + R[oa + M00]! * LA[q]! + R[oa + M01]! * LA[q + 1]! + R[oa + M02]! * LA[q + 2]!;
    const pay = ay + R[oa + M10]! * LA[q]! + R[oa + M11]! * LA[q + 1]! + R[oa + M12]! * LA[q + 2]!;
    const paz = az + R[oa + M20]! * LA[q]! + R[oa + M21]! * LA[q + 1]! + R[oa + M22]! * LA[q + 2]!;
    const pbx = bx + R[ob + M00]! * LB[q]! + R[ob + M01]! * LB[q + 1]! + R[ob + M02]! * LB[q + 2]!;
    const pby = by + R[ob + M10]! * LB[q]! + R[ob + M11]! * LB[q + 1]! + R[ob + M12]! * LB[q + 2]!;
    const pbz = bz + R[ob + M20]! * LB[q]! + R[ob + M21]! * LB[q + 1]! + R[ob + M22]! * LB[q + 2]!;
    m.x[k] = (pax + pbx) / 2;
    m.y[k] = (pay + pby) / 2;
    m.z[k] = (paz + pbz) / 2;
    m.sep[k] = (pbx - pax) * nx + (pby - pay) * ny + (pbz - paz) * nz;
    m.id[k] = P.id[4 * r + k]!;
  }
  m.count = count;
}

/** Writes row i's reuse fields: copied from the reused previous row, or from the manifold just computed. */
function storeLocal(st: Contact3DState, buf: Contact3DState['current'], i: number): void {
  buf.local[i] = 1;
  const P = st.previous,
    from = boxRow.from;
  if (from >= 0) {
    const RP = buf.relPose,
      PR = P.relPose,
      NL = buf.localNormal,
      PN = P.localNormal;
    for (let k = 0, o = RelPose.STRIDE * i, po = RelPose.STRIDE * from; k < RelPose.STRIDE; k++) RP[o + k] = PR[po + k]!;
    NL[3 * i] = PN[3 * from]!;
    NL[3 * i + 1] = PN[3 * from + 1]!;
    NL[3 * i + 2] = PN[3 * from + 2]!;
    // Only the points in use (a resting box on a face has four, on an edge two).
    const LA = buf.localA,
      LB = buf.localB,
      PA = P.localA,
      PB = P.localB,
      o = 12 * i,
      po = 12 * from;
    for (let k = 0, e = 3 * P.points[from]!; k < e; k++) {
      LA[o + k] = PA[po + k]!;
      LB[o + k] = PB[po + k]!;
    }
    return;
  }
  const sc = scratch,
    R = sc.R,
    a = boxRow.a,
    b = boxRow.b,
    oa = MAT3_STRIDE * a,
    ob = MAT3_STRIDE * b,
    m = manifold;
  for (let k = 0; k < RelPose.STRIDE; k++) buf.relPose[RelPose.STRIDE * i + k] = rel[k]!;
  const nx = m.nx,
    ny = m.ny,
    nz = m.nz;
  buf.localNormal[3 * i] = R[oa + M00]! * nx + R[oa + M10]! * ny + R[oa + M20]! * nz;
  buf.localNormal[3 * i + 1] = R[oa + M01]! * nx + R[oa + M11]! * ny + R[oa + M21]! * nz;
  buf.localNormal[3 * i + 2] = R[oa + M02]! * nx + R[oa + M12]! * ny + R[oa + M22]! * nz;
  for (let k = 0; k < m.count; k++) {
    const h = m.sep[k]! / 2,
      q = 3 * (4 * i + k);
    // The point's ends on A's surface (back along n by s / 2) and on B's, each in its box's frame.
    const dax = m.x[k]! - nx * h - sc.px[a]!,
      day = m.y[k]! - ny * h - sc.py[a]!,
      daz = m.z[k]! - nz * h - sc.pz[a]!;
    const dbx = m.x[k]! + nx * h - sc.px[b]!,
      dby = m.y[k]! + ny * h - sc.py[b]!,
      dbz = m.z[k]! + nz * h - sc.pz[b]!;
    buf.localA[q] = R[oa + M00]! * dax + R[oa + M10]! * day + R[oa + M20]! * daz;
    buf.localA[q + 1] = R[oa + M01]! * dax + R[oa + M11]! * day + R[oa + M21]! * daz;
    buf.localA[q + 2] = R[oa + M02]! * dax + R[oa + M12]! * day + R[oa + M22]! * daz;
    buf.localB[q] = R[ob + M00]! * dbx + R[ob + M10]! * dby + R[ob + M20]! * dbz;
    buf.localB[q + 1] = R[ob + M01]! * dbx + R[ob + M11]! * dby + R[ob + M21]! * dbz;
    buf.localB[q + 2] = R[ob + M02]! * dbx + R[ob + M12]! * dby + R[ob + M22]! * dbz;
  }
}

/** A pair's manifold found: wakes a sleeper met by a moving body, and emits the rows unless neither body is dynamic. */
function emitPair(world: PhysicsWorld, s: Shape3DStore, st: Contact3DState, a: number, b: number, bi: number, bj: number): void {
  const sc = scratch,
    type = world.collision.bodyType,
    ta = type[bi]!,
    tb = type[bj]!;
  if (ta === BodyType.Sleeping || tb === BodyType.Sleeping) {
    // The mover wakes the sleeper only if it can reach it this step (its speed, and gravity, over h).
    let gap = Infinity;
    for (let k = 0; k < manifold.count; k++) gap = Math.min(gap, manifold.sep[k]!);
    const g = world.gravity,
      h = world.h,
      fall = Math.sqrt(g[0]! * g[0]! + g[1]! * g[1]! + g[2]! * g[2]!) * h * h;
    const mover = ta === BodyType.Sleeping ? (sc.body[a] === bj ? a : b) : sc.body[a] === bi ? a : b;
    const closing = sc.speed[mover]! * h + fall;
    if (ta === BodyType.Sleeping && wakesSleeper(world, bj, tb, gap, closing)) queueWake(bi);
    else if (tb === BodyType.Sleeping && wakesSleeper(world, bi, ta, gap, closing)) queueWake(bj);
  }
  if (ta !== BodyType.Dynamic && tb !== BodyType.Dynamic) return;
  emit(world, s, st, sc.body[a]!, sc.body[b]!, sc.shape[a]!, sc.shape[b]!, sc.ball[a] === 1, sc.ball[b] === 1);
}

/** Writes the manifold into the buffer as solver rows with their anchors, material and warm start. */
export function emit(
  world: PhysicsWorld,
  s: Shape3DStore,
  st: Contact3DState,
  bodyA: number,
  bodyB: number,
  ea: number,
  eb: number,
  ballA: boolean,
  ballB: boolean,
  plane = 0,
  sub = 0,
): void {
  let buf = st.current;
  if (buf.count >= buf.bodyA.length) {
    buf = growManifold3DBuffer(buf);
    st.current = buf;
  }
  const i = buf.count++;
  const m = manifold,
    c = world.components;
  buf.bodyA[i] = bodyA;
  buf.bodyB[i] = bodyB;
  buf.shapeA[i] = ea;
  buf.shapeB[i] = eb;
  buf.sub[i] = sub;
  buf.points[i] = m.count;
  const nx = m.nx,
    ny = m.ny,
    nz = m.nz;
  buf.nx[i] = nx;
  buf.ny[i] = ny;
  buf.nz[i] = nz;
  // Tangent t1: perpendicular to n, from the axis n is least along (Box2D v3 / Erin Catto's b2Perp-like choice in 3D).
  let tx: number, ty: number, tz: number;
  if (Math.abs(nx) < 0.57735) {
    tx = 0;
    ty = nz;
    tz = -ny;
  } else {
    tx = -nz;
    ty = 0;
    tz = nx;
  }
  const tl = Math.sqrt(tx * tx + ty * ty + tz * tz);
  buf.t1x[i] = tx / tl;
  buf.t1y[i] = ty / tl;
  buf.t1z[i] = tz / tl;
  // Materials: the bouncier surface wins, friction is the geometric mean (Box2D's mixing).
  // A side without body or shape: the boundary box (its walls' material).
  const wall = bodyA === 0 && ea === 0,
    bound = world.collision.boundary;
  let fa: number, ra: number, fb: number, rb: number;
  // Anchors from where the narrowphase measured: PreviousPosition, or Position for a static body.
  let ax = 0,
    ay = 0,
    az = 0,
    bx = 0,
    by = 0,
    bz = 0;
  if (boxRow.a >= 0) {
    // A box pair: both shapes' materials and both bodies' start positions from the colliders' scratch
    // entries (the store's numbers; gather took the positions by the same rule).
    const mat = scratch.material,
      oa = ColliderMaterial.STRIDE * boxRow.a,
      ob = ColliderMaterial.STRIDE * boxRow.b;
    fa = mat[oa + ColliderMaterial.FRICTION]!;
    ra = mat[oa + ColliderMaterial.RESTITUTION]!;
    fb = mat[ob + ColliderMaterial.FRICTION]!;
    rb = mat[ob + ColliderMaterial.RESTITUTION]!;
    ax = mat[oa + ColliderMaterial.X]!;
    ay = mat[oa + ColliderMaterial.Y]!;
    az = mat[oa + ColliderMaterial.Z]!;
    bx = mat[ob + ColliderMaterial.X]!;
    by = mat[ob + ColliderMaterial.Y]!;
    bz = mat[ob + ColliderMaterial.Z]!;
  } else {
    fa = wall ? bound.friction : plane !== 0 || ballA ? c.Material.friction[ea]! : s.friction[ea]!;
    ra = wall ? bound.restitution : plane !== 0 || ballA ? c.Material.restitution[ea]! : s.restitution[ea]!;
    fb = ballB ? c.Material.friction[eb]! : s.friction[eb]!;
    rb = ballB ? c.Material.restitution[eb]! : s.restitution[eb]!;
    const type = world.collision.bodyType;
    if (bodyA !== 0) {
      const P = type[bodyA] === BodyType.Static ? c.Position : c.PreviousPosition;
      ax = P.x[bodyA]!;
      ay = P.y[bodyA]!;
      az = P.z[bodyA]!;
    }
    if (bodyB !== 0) {
      const P = type[bodyB] === BodyType.Static ? c.Position : c.PreviousPosition;
      bx = P.x[bodyB]!;
      by = P.y[bodyB]!;
      bz = P.z[bodyB]!;
    }
  }
  buf.friction[i] = Math.sqrt(fa * fb);
  buf.restitution[i] = Math.max(ra, rb);
  // Cylinders only (a box pair has none).
  if (boxRow.a < 0) {
    if (bodyB !== 0 && !ballB) meridianPoints(world, s, eb, bodyB);
    if (bodyA !== 0 && !ballA && plane === 0) meridianPoints(world, s, ea, bodyA);
  }
  // A box pair's reuse fields (see REUSE_SHIFT); other rows are never reused.
  if (boxRow.a >= 0) storeLocal(st, buf, i);
  else buf.local[i] = 0;
  const prev = boxRow.a >= 0 ? boxRow.prev : lookupRow(st.previousIndex, rowKey(world.capacity, ea, eb, sub));
  buf.prevRow[i] = prev;
  // The warm start is carried over from the previous row after the pass (carryImpulses).
  if (reusedRows.length <= i) reusedRows = grownRows(reusedRows, buf.bodyA.length);
  reusedRows[i] = boxRow.a >= 0 && boxRow.from >= 0 ? 1 : 0;
  const R = buf.anchors;
  for (let k = 0; k < m.count; k++) {
    const q = 4 * i + k;
    const o = ANCHOR_STRIDE * q;
    R[o + ANCHOR_AX] = m.x[k]! - ax;
    R[o + ANCHOR_AY] = m.y[k]! - ay;
    R[o + ANCHOR_AZ] = m.z[k]! - az;
    R[o + ANCHOR_BX] = m.x[k]! - bx;
    R[o + ANCHOR_BY] = m.y[k]! - by;
    R[o + ANCHOR_BZ] = m.z[k]! - bz;
    buf.sep[q] = m.sep[k]!;
    buf.id[q] = m.id[k]!;
    buf.carried[q] = 0;
  }
}

/** Per row of the pass (st.current): 1 when emit reused the previous row's manifold (its points in that row's order), else 0. */
let reusedRows: Uint8Array = new Uint8Array(64);

/** A copy of `rows` with room for at least `n` rows (twice its length). */
function grownRows(rows: Uint8Array, n: number): Uint8Array {
  const grown = new Uint8Array(Math.max(n, 2 * rows.length));
  grown.set(rows);
  return grown;
}

/**
 * The warm start of the pass's rows (st.current), from each row's previous row (prevRow, -1: none): a
 * point's normal impulse from the previous point of the same feature id (a reused manifold's points
 * are the previous row's, in order), the friction impulses while the normal barely turned (t1 follows
 * n), else 0. Run once the rows are final, in a loop of its own rather than in `emit`: the previous
 * rows' impulses and normals are read in row order, from memory the step has not touched since, and a
 * short loop keeps many of those reads in flight where emit's long body waited for each.
 * @category Collision
 */
export function carryImpulses(st: Contact3DState): void {
  const buf = st.current,
    P = st.previous;
  const LN = buf.ln,
    FT = buf.ft,
    PL = P.ln,
    PF = P.ft,
    ID = buf.id,
    PID = P.id,
    reused = reusedRows;
  for (let i = 0, count = buf.count; i < count; i++) {
    const prev = buf.prevRow[i]!,
      m = buf.points[i]!;
    for (let k = 0; k < m; k++) {
      const q = 4 * i + k;
      LN[q] = 0;
      if (prev < 0) continue;
      if (reused[i] === 1) LN[q] = PL[4 * prev + k]!;
      else
        for (let j = 0, pm = P.points[prev]!; j < pm; j++) {
          const pq = 4 * prev + j;
          if (PID[pq] === ID[q]) {
            LN[q] = PL[pq]!;
            break;
          }
        }
    }
    if (prev >= 0 && P.nx[prev]! * buf.nx[i]! + P.ny[prev]! * buf.ny[i]! + P.nz[prev]! * buf.nz[i]! > 0.99) {
      FT[3 * i] = PF[3 * prev]!;
      FT[3 * i + 1] = PF[3 * prev + 1]!;
      FT[3 * i + 2] = PF[3 * prev + 2]!;
    } else {
      FT[3 * i] = 0;
      FT[3 * i + 1] = 0;
      FT[3 * i + 2] = 0;
    }
  }
}

/**
 * A cylinder's speculative points that its spin would sweep into contact are moved onto its meridian
 * plane (the plane through its axis a and the normal n), across n, so their separation stays.
 *
 * A cylinder is collided as a hull whose cap rims are polygons, and the solver follows each point as a
 * point of the body, its rotation in the step linearised (solver/manifold-rows-3d.ts). A round surface does
 * not move under its spin about its own axis, and a contact force on it has no torque about that axis
 * (its normal meets the axis); a rim vertex off the meridian does move, by w_a h (p - c) . (a x n)
 * along n in a step of spin w_a. A fast top's disc (100 rad/s, 0.5 m, dt 1/60: 0.25 m a step) then had
 * rim points 0.1 m up "hit" the floor: one such push threw the test top 0.46 m up. Only speculative points
 * (separation s > 0) that the spin could carry by more than s / 2 are moved, so a cylinder resting on its
 * rim points, or landing flat without much spin, keeps them where they are.
 */
function meridianPoints(world: PhysicsWorld, s: Shape3DStore, e: number, body: number): void {
  if (scratch.colliderStamp[e] !== scratch.colliderPass || s.kind[e] !== Shape3DKind.Cylinder) return;
  // The normal is the manifold's (read here: doubles passed to a call are boxed).
  const nx = manifold.nx,
    ny = manifold.ny,
    nz = manifold.nz;
  const i = scratch.colliderOf[e]!,
    sc = scratch,
    R = sc.R,
    o = MAT3_STRIDE * i,
    W = world.components.AngularVelocity;
  if (!(W.x.length > body)) return;
  // The cylinder's axis (its shape y axis) and u = a x n, across the meridian plane.
  const ax = R[o + M01]!,
    ay = R[o + M11]!,
    az = R[o + M21]!;
  const ux = ay * nz - az * ny,
    uy = az * nx - ax * nz,
    uz = ax * ny - ay * nx,
    uu = ux * ux + uy * uy + uz * uz;
  if (!(uu > 1e-12)) return; // flat on the surface: the spin moves no point along n
  const spin = Math.abs(W.x[body]! * ax + W.y[body]! * ay + W.z[body]! * az) * world.h;
  if (spin === 0) return;
  const m = manifold,
    cx = sc.px[i]!,
    cy = sc.py[i]!,
    cz = sc.pz[i]!;
  for (let k = 0; k < m.count; k++) {
    const sep = m.sep[k]!;
    if (!(sep > 0)) continue;
    const off = ((m.x[k]! - cx) * ux + (m.y[k]! - cy) * uy + (m.z[k]! - cz) * uz) / uu;
    // Travel along n the spin gives it in the step, spin h |(p - c) . u| = spin h |off| |u|^2, doubled:
    // the relax pass after the last substep looks a substep ahead of where the step ends.
    if (2 * spin * Math.abs(off) * uu <= sep) continue;
    m.x[k] = m.x[k]! - off * ux;
    m.y[k] = m.y[k]! - off * uy;
    m.z[k] = m.z[k]! - off * uz;
  }
}
