import { hasComponent } from 'bitecs';
import { wakeIslandForStep, wakesSleeper } from '../islands/step-wake.js';
import { type ConvexGeometry, createGeometry, ShapeKind } from '../shapes/geometry-2d.js';
import { jointKeepsApart } from '../world/joint-no-collide.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { SHAPE_STRIDE, type ShapeStore } from '../world/shape-store-2d.js';
import { findPairs } from './broadphase/pairs-2d.js';
import { gatherColliders, sharedGeometries } from './colliders-2d.js';
import { pushEvent } from './events.js';
import { BALL, growManifoldBuffer, type ShapeCollisionState } from './manifolds-2d.js';
import { collideHalfPlane, collideShapes, collideShapesAt, createManifold, type Manifold, PairPose } from './narrowphase/manifold-2d.js';
import { BodyType } from './state.js';

/**
 * Collide stage, shapes (2D): the broadphase and narrowphase of every shape (`Components.Shape`) and
 * of balls against shapes, writing manifolds for the contact solver (solver/contact-solver.ts solves them in the same
 * substeps as the ball contacts; solver/manifold-rows-2d.ts). Ball-ball, ball-segment, ball-plane and
 * ball-boundary contacts stay with collision/broadphase/grid.ts and collision/narrowphase/balls.ts.
 *
 * Broadphase: each collider's bounding box where its body was at the start of the step, fattened by a
 * speculative margin (|v| h, plus |w| h times its reach, plus the speculative distance), goes into a
 * uniform grid whose cell is the largest box of the ordinary colliders; a box is filed under the cell
 * of its lower corner, so two ordinary boxes can overlap only if their cells are neighbours, and each
 * pair is met once through half the neighbourhood. Colliders much larger than the mean (a 100 m
 * ground beside half-metre boxes) stay out of the grid and visit the cells their box covers, so mixed
 * sizes keep the cost linear in the number of colliders.
 *
 * Filtering: shapes of one body never collide; a pair collides when each one's category meets the
 * other's mask, unless both share a non-zero group (> 0 always, < 0 never); pairs of which neither
 * body is dynamic are skipped, and so are bodies joined by a joint without `collideConnected`
 * (world/joint-no-collide.ts).
 *
 * Narrowphase (collision/narrowphase/manifold-2d.ts): each candidate pair's manifold at the start-of-step transforms, keeping a
 * point if its separation is below the speculative distance plus what the point's approach speed
 * closes in one step, at most the two shapes' thickness between dynamic and static shapes (speculative
 * contacts, Catto GDC 2013); a body that moves farther than its own size is swept after the solver
 * (collision/continuous-2d.ts: the continuous collision of bullets). Sensor pairs report overlap events instead of
 * manifolds.
 * @category Collision
 */
export function shapeCollisionSystem(world: PhysicsWorld): void {
  const cs = world.collision;
  const st = cs.shapes;
  if (!st.active || world.dimensions !== 2) return;
  // A sleeping island that a moving or kinematic body reaches wakes and joins this step's solve (so
  // the hit's momentum goes into it); the pairs are then found again with it awake. Woken balls are
  // classified by the ball broadphase, which runs again with them (their ball contacts too).
  const c = world.components;
  for (let pass = 0; ; pass++) {
    st.manifolds.count = 0;
    st.wakeNow.length = 0;
    gatherColliders(world, st);
    findPairs(st.scratch, st.anyMoving);
    collidePairs(world, st);
    if (st.wakeNow.length === 0 || pass >= MAX_WAKE_PASSES) break;
    let woken = 0,
      balls = false;
    for (const e of st.wakeNow) {
      if (hasComponent(world, e, c.Ball)) balls = true;
      woken += wakeIslandForStep(world, e);
    }
    if (woken === 0) break;
    // The balls' broadphase and narrowphase (installed with the first ball: collision/install-balls.ts).
    if (balls) {
      world.builtins.get('broadphase')?.(world);
      world.builtins.get('narrowphase')?.(world);
    }
  }
  sensorEvents(world, st);
  collideStatic(world, st);
  // The contact count of the step's statistics: the ball contacts of this step (their buffer, which the
  // balls' narrowphase refills earlier in the collide stage and which stays empty in a world without
  // balls) and the 2D shape contact points (solver rows, static pairs included).
  cs.stats.contacts = cs.contacts.count + manifoldPoints(st.manifolds);
}

/**
 * The contact points of the manifolds in `m`. A function of its own: with this loop in it,
 * shapeCollisionSystem (called once a step) was compiled by V8 a few steps in, with the once-a-step
 * functions it calls inlined before they had type feedback, and thrown away at the next step.
 */
function manifoldPoints(m: ShapeCollisionState['manifolds']): number {
  let points = 0;
  for (let i = 0; i < m.count; i++) points += m.pointCount[i]!;
  return points;
}

/** Passes of the shape collision after which no more sleeping islands are woken within the step. */
const MAX_WAKE_PASSES = 8;

/**
 * Whether the filters of shapes a and b (ball bodies count as category 1, mask all, group 0) let them collide.
 * @category Collision
 */
export function shouldCollide(S: ShapeStore, a: number, aBall: boolean, b: number, bBall: boolean): boolean {
  const ga = aBall ? 0 : S.group[a]!,
    gb = bBall ? 0 : S.group[b]!;
  if (ga === gb && ga !== 0) return ga > 0;
  const ca = aBall ? 1 : S.category[a]!,
    ma = aBall ? 0xffffffff : S.mask[a]!;
  const cb = bBall ? 1 : S.category[b]!,
    mb = bBall ? 0xffffffff : S.mask[b]!;
  return (ca & mb) !== 0 && (cb & ma) !== 0;
}

const gA = createGeometry(),
  gB = createGeometry();
const mf = createManifold();
/** The pair being collided (slots `PairPose`). */
const pairPose = new Float64Array(PairPose.SIZE);

/**
 * Slots of the motion `pushManifold` reads: the bodies' centres at the start of the step (m), their
 * velocities (m/s, rad/s), the speculative distance (m) and the step (s). An array, not arguments:
 * V8 boxes each double argument of a call it does not inline (0.3 MB a step in a pyramid of 820 boxes).
 */
const RowMotion = Object.freeze({
  XA: 0,
  YA: 1,
  XB: 2,
  YB: 3,
  VAX: 4,
  VAY: 5,
  WA: 6,
  VBX: 7,
  VBY: 8,
  WB: 9,
  SPECULATIVE: 10,
  H: 11,
  SIZE: 12,
});
const rowMotion = new Float64Array(RowMotion.SIZE);

/**
 * Reads collider `e`'s geometry: a shape from the store, or a ball body as a circle.
 * @category Collision
 */
export function colliderGeometry(world: PhysicsWorld, e: number, g: ConvexGeometry): boolean {
  const c = world.components,
    S = c.Shape;
  if (S.body.length > e && hasComponent(world, e, c.Shape)) {
    shapeGeometry(S, e, g);
    return false;
  }
  ballGeometry(c.Ball.radius[e]!, g);
  return true;
}

/** Reads shape `e`'s geometry from the store into `g`. */
function shapeGeometry(S: ShapeStore, e: number, g: ConvexGeometry): void {
  const n = S.count[e]!,
    o = SHAPE_STRIDE * e;
  const svx = S.vx,
    svy = S.vy,
    snx = S.nx,
    sny = S.ny;
  const vx = g.vx,
    vy = g.vy,
    nx = g.nx,
    ny = g.ny;
  g.kind = S.kind[e]!;
  g.count = n;
  g.radius = S.radius[e]!;
  for (let i = 0; i < n; i++) {
    vx[i] = svx[o + i]!;
    vy[i] = svy[o + i]!;
    nx[i] = snx[o + i]!;
    ny[i] = sny[o + i]!;
  }
}

/** Makes `g` the circle of a ball body of the given radius (m). */
function ballGeometry(radius: number, g: ConvexGeometry): void {
  g.kind = ShapeKind.Circle;
  g.count = 1;
  g.radius = radius;
  g.vx[0] = 0;
  g.vy[0] = 0;
  g.nx[0] = 0;
  g.ny[0] = 1;
}

/** Fills `g` with the geometry of shape `geo` (sharedGeometries), or for -1 a ball's circle of `radius` (m); returns geo. */
function fillGeometry(S: ShapeStore, geo: number, radius: number, g: ConvexGeometry): number {
  if (geo < 0) ballGeometry(radius, g);
  else shapeGeometry(S, geo, g);
  return geo;
}

/** Narrowphase of the candidate pairs: manifolds for the solver, overlaps for sensors. */
function collidePairs(world: PhysicsWorld, st: ShapeCollisionState): void {
  const c = world.components,
    cs = world.collision,
    sc = st.scratch,
    S = c.Shape;
  const type = cs.bodyType;
  const vx = c.Velocity.x,
    vy = c.Velocity.y,
    ballRadius = c.Ball.radius;
  const h = world.h;
  const sensorNow = st.sensorNow;
  sensorNow.clear();
  // A pair makes at most one manifold. Grown here with half again as much room, a settling scene's
  // buffers grow once each rather than double row by row over its first steps (fresh memory is
  // costly to touch: each doubling writes every column anew).
  const needed = st.manifolds.count + sc.pairCount;
  if (needed > st.manifolds.capacity) growManifoldBuffer(st.manifolds, needed + (needed >> 1));
  const pairI = sc.pairI,
    pairJ = sc.pairJ,
    shape = sc.shape,
    body = sc.body,
    flags = sc.flags,
    X = sc.x,
    Y = sc.y,
    C = sc.c,
    Sn = sc.s,
    SPEC = sc.spec,
    SIZE = sc.size,
    minX = sc.minX,
    minY = sc.minY,
    maxX = sc.maxX,
    maxY = sc.maxY;
  const sensorOf = S.sensor,
    bodyW = st.bodyW;
  // The shapes whose geometry gA and gB hold (colliders-2d.ts sharedGeometries; -1: none, or a ball's): pairs come collider by
  // collider from the grid, so A repeats, and colliders of one geometry share it.
  const geometry = sharedGeometries();
  let inA = -1,
    inB = -1;
  for (let k = 0, n = sc.pairCount; k < n; k++) {
    let i = pairI[k]!,
      j = pairJ[k]!;
    let ea = shape[i]!,
      eb = shape[j]!;
    let ba = body[i]!,
      bb = body[j]!;
    if (ba === bb) continue;
    const ta = type[ba]!,
      tb = type[bb]!;
    // Pairs without a dynamic body are skipped, but for a kinematic body reaching a sleeping one.
    if (ta !== BodyType.Dynamic && tb !== BodyType.Dynamic && !kinematicMeetsSleeper(ta, tb)) continue;
    // Keep the lower shape id as A so a pair's key does not depend on the grid's order.
    if (ea > eb) {
      let t = i;
      i = j;
      j = t;
      t = ea;
      ea = eb;
      eb = t;
      t = ba;
      ba = bb;
      bb = t;
    }
    // A ball body without a shape collides as its own circle; every other collider is a shape entity.
    const aBall = (flags[i]! & BALL) !== 0,
      bBall = (flags[j]! & BALL) !== 0;
    if (aBall && bBall) continue; // ball-ball: collision/narrowphase/balls.ts
    if (!shouldCollide(S, ea, aBall, eb, bBall)) continue;
    if (jointKeepsApart(world.joints, ba, bb)) continue;
    const geoA = geometry[i]!,
      geoB = geometry[j]!;
    if (geoA < 0 || geoA !== inA) inA = fillGeometry(S, geoA, ballRadius[ea]!, gA);
    if (geoB < 0 || geoB !== inB) inB = fillGeometry(S, geoB, ballRadius[eb]!, gB);
    const sensor = (!aBall && sensorOf[ea] === 1) || (!bBall && sensorOf[eb] === 1);
    const tA = type[ba]!,
      tB = type[bb]!;
    const mA = tA === BodyType.Dynamic || tA === BodyType.Kinematic,
      mB = tB === BodyType.Dynamic || tB === BodyType.Kinematic;
    const vax = mA ? vx[ba]! : 0,
      vay = mA ? vy[ba]! : 0,
      vbx = mB ? vx[bb]! : 0,
      vby = mB ? vy[bb]! : 0;
    const wa = bodyW[ba]!,
      wb = bodyW[bb]!;
    const spec = SPEC[i]! < SPEC[j]! ? SPEC[i]! : SPEC[j]!;
    const dvx = vbx - vax,
      dvy = vby - vay;
    const reachA = 0.5 * (maxX[i]! - minX[i]! + maxY[i]! - minY[i]!),
      reachB = 0.5 * (maxX[j]! - minX[j]! + maxY[j]! - minY[j]!);
    let closing = (Math.sqrt(dvx * dvx + dvy * dvy) + Math.abs(wa) * reachA + Math.abs(wb) * reachB) * h;
    // Speculation reaches as far as the two shapes are thick; a faster approach between dynamic (or
    // static) shapes is the continuous sweep's (collision/continuous-2d.ts): a normal chosen this far apart is often
    // the wrong face's (a ghost contact that deflects a bullet over a wall's end). Balls and kinematic
    // bodies are not swept, so they keep the whole margin.
    if (!aBall && !bBall && tA !== BodyType.Kinematic && tB !== BodyType.Kinematic) {
      const thick = SIZE[i]! + SIZE[j]!;
      if (closing > thick) closing = thick;
    }
    const q = pairPose;
    q[PairPose.XA] = X[i]!;
    q[PairPose.YA] = Y[i]!;
    q[PairPose.CA] = C[i]!;
    q[PairPose.SA] = Sn[i]!;
    q[PairPose.XB] = X[j]!;
    q[PairPose.YB] = Y[j]!;
    q[PairPose.CB] = C[j]!;
    q[PairPose.SB] = Sn[j]!;
    q[PairPose.SPECULATIVE] = spec + closing;
    collideShapesAt(mf, gA, gB, q);
    if (mf.count === 0) continue;
    if (sensor) {
      let overlap = false;
      for (let p = 0; p < mf.count; p++) if (mf.separation[p]! < 0) overlap = true;
      if (overlap) {
        const sensorFirst = !aBall && sensorOf[ea] === 1;
        sensorNow.add(sensorFirst ? ea * 33554432 + eb : eb * 33554432 + ea);
      }
      continue;
    }
    if (tA === BodyType.Sleeping || tB === BodyType.Sleeping) {
      // A sleeping body reached by a moving (kinematic, or dynamic and not resting) one wakes now and
      // takes part in this step's solve (the pass is run again). Met by a resting body it holds still
      // as immovable geometry this step, and wakes for the next only if the resting body leaned on
      // it (the contact pushed: islands/sleep.ts wakePushedSleepers2D); a resting neighbour within
      // the speculative distance but not touching leaves it asleep (woken, it would rest apart from
      // the neighbour's island, fall asleep after it and wake it in turn, for ever).
      const sleeper = tA === BodyType.Sleeping ? ba : bb,
        other = sleeper === ba ? bb : ba,
        tOther = sleeper === ba ? tB : tA;
      // (The broadphase pairs a sleeper only with a moving body: tOther is dynamic or kinematic.)
      if (wakesSleeper(world, other, tOther)) {
        st.wakeNow.push(sleeper);
        continue;
      }
    }
    const mo = rowMotion;
    mo[RowMotion.XA] = X[i]!;
    mo[RowMotion.YA] = Y[i]!;
    mo[RowMotion.XB] = X[j]!;
    mo[RowMotion.YB] = Y[j]!;
    mo[RowMotion.VAX] = vax;
    mo[RowMotion.VAY] = vay;
    mo[RowMotion.WA] = wa;
    mo[RowMotion.VBX] = vbx;
    mo[RowMotion.VBY] = vby;
    mo[RowMotion.WB] = wb;
    mo[RowMotion.SPECULATIVE] = spec;
    mo[RowMotion.H] = h;
    pushManifold(st, mf, ea, eb, ba, bb, mo);
  }
}

/** Sensor events: the overlaps found this step (`sensorNow`) that began or ended since the last. */
function sensorEvents(world: PhysicsWorld, st: ShapeCollisionState): void {
  const S = world.components.Shape,
    sensorNow = st.sensorNow;
  const prev = st.sensorPairs,
    ev = world.collision.events;
  for (const key of sensorNow) {
    if (prev.has(key)) continue;
    const a = Math.floor(key / 33554432),
      b = key - a * 33554432;
    pushEvent(world, ev.sensorBegin, a, b, S.body[a]!, sensorBody(world, b));
  }
  for (const key of prev) {
    if (sensorNow.has(key)) continue;
    const a = Math.floor(key / 33554432),
      b = key - a * 33554432;
    pushEvent(world, ev.sensorEnd, a, b, S.body[a]!, sensorBody(world, b));
  }
  st.sensorPairs = sensorNow;
  st.sensorNow = prev;
}

/** Whether one of two body types is kinematic and the other sleeping (a pair met only to wake the sleeper). */
function kinematicMeetsSleeper(ta: number, tb: number): boolean {
  return (ta === BodyType.Kinematic && tb === BodyType.Sleeping) || (ta === BodyType.Sleeping && tb === BodyType.Kinematic);
}

function sensorBody(world: PhysicsWorld, e: number): number {
  const c = world.components;
  return c.Shape.body.length > e && hasComponent(world, e, c.Shape) ? c.Shape.body[e]! : e;
}

/**
 * Appends manifold `m` (A's body at (xa, ya), B's at (xb, yb), start of step) as a solver row, keeping
 * the points whose separation the step can close (speculative test with each point's own approach speed).
 */
function pushManifold(st: ShapeCollisionState, m: Manifold, ea: number, eb: number, ba: number, bb: number, motion: Float64Array): void {
  const xa = motion[RowMotion.XA]!,
    ya = motion[RowMotion.YA]!,
    xb = motion[RowMotion.XB]!,
    yb = motion[RowMotion.YB]!,
    vax = motion[RowMotion.VAX]!,
    vay = motion[RowMotion.VAY]!,
    wa = motion[RowMotion.WA]!,
    vbx = motion[RowMotion.VBX]!,
    vby = motion[RowMotion.VBY]!,
    wb = motion[RowMotion.WB]!,
    spec = motion[RowMotion.SPECULATIVE]!,
    h = motion[RowMotion.H]!;
  const buf = st.manifolds;
  const nx = m.nx,
    ny = m.ny;
  let row = buf.count;
  if (row >= buf.capacity) growManifoldBuffer(buf, row + 1);
  const PX = buf.px,
    PY = buf.py,
    RAX = buf.rAx,
    RAY = buf.rAy,
    RBX = buf.rBx,
    RBY = buf.rBy,
    SEP = buf.separation,
    ID = buf.id,
    VN = buf.relativeVelocity;
  let count = 0;
  for (let p = 0, n = m.count; p < n; p++) {
    const x = m.px[p]!,
      y = m.py[p]!;
    const rax = x - xa,
      ray = y - ya,
      rbx = x - xb,
      rby = y - yb;
    const vn = (vbx - wb * rby - vax + wa * ray) * nx + (vby + wb * rbx - vay - wa * rax) * ny;
    const sep = m.separation[p]!;
    // The distance the point closes this step if it approaches (-vn h > 0), else 0; negated on every
    // point, not only approaching ones, which a world's first step (bodies at rest) may not meet before V8 compiles this.
    const closing = -vn * h;
    if (sep >= (closing > 0 ? closing : 0) + spec) continue;
    const q = 2 * row + count;
    PX[q] = x;
    PY[q] = y;
    RAX[q] = rax;
    RAY[q] = ray;
    RBX[q] = rbx;
    RBY[q] = rby;
    SEP[q] = sep;
    ID[q] = m.id[p]!;
    VN[q] = vn;
    count++;
  }
  if (count === 0) return;
  buf.shapeA[row] = ea;
  buf.shapeB[row] = eb;
  buf.bodyA[row] = ba;
  buf.bodyB[row] = bb;
  buf.nx[row] = nx;
  buf.ny[row] = ny;
  buf.pointCount[row] = count;
  buf.count = row + 1;
  row++;
}

/** Every non-ball shape of a dynamic body against planes, static segments and the boundary box. */
function collideStatic(world: PhysicsWorld, st: ShapeCollisionState): void {
  const c = world.components,
    cs = world.collision,
    sc = st.scratch,
    S = c.Shape;
  const type = cs.bodyType,
    h = world.h;
  const { x: vx, y: vy } = c.Velocity;
  const planes = query(world, [c.Plane]);
  const segs = query(world, [c.Segment]);
  const box = cs.boundary;
  if (planes.length === 0 && segs.length === 0 && !box.enabled) return;
  const Pl = c.Plane,
    Sg = c.Segment;
  for (let i = 0; i < sc.count; i++) {
    const e = sc.shape[i]!,
      b = sc.body[i]!;
    if (type[b] !== BodyType.Dynamic) continue;
    if (!(S.body.length > e && hasComponent(world, e, c.Shape)) || S.sensor[e] === 1) continue;
    colliderGeometry(world, e, gB);
    const x = sc.x[i]!,
      y = sc.y[i]!,
      co = sc.c[i]!,
      si = sc.s[i]!;
    const w = st.bodyW[b]!,
      vbx = vx[b]!,
      vby = vy[b]!;
    const spec = sc.spec[i]!;
    const mo = rowMotion;
    mo[RowMotion.XA] = 0;
    mo[RowMotion.YA] = 0;
    mo[RowMotion.XB] = x;
    mo[RowMotion.YB] = y;
    mo[RowMotion.VAX] = 0;
    mo[RowMotion.VAY] = 0;
    mo[RowMotion.WA] = 0;
    mo[RowMotion.VBX] = vbx;
    mo[RowMotion.VBY] = vby;
    mo[RowMotion.WB] = w;
    mo[RowMotion.SPECULATIVE] = spec;
    mo[RowMotion.H] = h;
    const reach = 0.5 * (sc.maxX[i]! - sc.minX[i]! + sc.maxY[i]! - sc.minY[i]!);
    const closing = (Math.sqrt(vbx * vbx + vby * vby) + Math.abs(w) * reach) * h;
    const x0 = sc.minX[i]!,
      y0 = sc.minY[i]!,
      x1 = sc.maxX[i]!,
      y1 = sc.maxY[i]!;
    if (box.enabled) {
      const bx0 = box.min[0]!,
        by0 = box.min[1]!,
        bx1 = box.max[0]!,
        by1 = box.max[1]!;
      if (x0 < bx0) {
        collideHalfPlane(mf, 1, 0, bx0, gB, x, y, co, si, spec + closing, 0);
        pushStatic(st, mf, -1, e, b);
      }
      if (x1 > bx1) {
        collideHalfPlane(mf, -1, 0, -bx1, gB, x, y, co, si, spec + closing, 0);
        pushStatic(st, mf, -2, e, b);
      }
      if (y0 < by0) {
        collideHalfPlane(mf, 0, 1, by0, gB, x, y, co, si, spec + closing, 0);
        pushStatic(st, mf, -3, e, b);
      }
      if (y1 > by1) {
        collideHalfPlane(mf, 0, -1, -by1, gB, x, y, co, si, spec + closing, 0);
        pushStatic(st, mf, -4, e, b);
      }
    }
    for (let k = 0; k < planes.length; k++) {
      const p = planes[k]!;
      const pnx = Pl.nx[p]!,
        pny = Pl.ny[p]!,
        d = Pl.d[p]!;
      // Reject by the box's corner nearest the plane.
      const near = (pnx > 0 ? x0 : x1) * pnx + (pny > 0 ? y0 : y1) * pny - d;
      if (near > 0) continue;
      collideHalfPlane(mf, pnx, pny, d, gB, x, y, co, si, spec + closing, 0);
      pushStatic(st, mf, p, e, b);
    }
    for (let k = 0; k < segs.length; k++) {
      const s = segs[k]!;
      const r = Sg.radius[s]!;
      const ax = Sg.ax[s]!,
        ay = Sg.ay[s]!,
        bx = Sg.bx[s]!,
        by = Sg.by[s]!;
      if (Math.min(ax, bx) - r > x1 || Math.max(ax, bx) + r < x0 || Math.min(ay, by) - r > y1 || Math.max(ay, by) + r < y0) continue;
      const len = Math.hypot(bx - ax, by - ay);
      if (!(len > 0)) continue;
      gA.kind = ShapeKind.Capsule;
      gA.count = 2;
      gA.radius = r;
      gA.vx[0] = ax;
      gA.vy[0] = ay;
      gA.vx[1] = bx;
      gA.vy[1] = by;
      gA.nx[0] = (by - ay) / len;
      gA.ny[0] = -(bx - ax) / len;
      gA.nx[1] = -gA.nx[0]!;
      gA.ny[1] = -gA.ny[0]!;
      collideShapes(mf, gA, 0, 0, 1, 0, gB, x, y, co, si, spec + closing);
      pushStatic(st, mf, s, e, b);
    }
  }
}

function pushStatic(st: ShapeCollisionState, m: Manifold, feature: number, e: number, b: number): void {
  if (m.count === 0) return;
  pushManifold(st, m, feature, e, 0, b, rowMotion);
}
