import { hasComponent } from 'bitecs';
import { wakeIsland3D, wakesSleeper3D } from '../islands/shapes-3d.js';
import { jointKeepsApart } from '../joints/connected.js';
import { type Mesh3D, meshesOf } from '../shapes/mesh-3d.js';
import { Shape3DKind, type Shape3DStore, shapes3DOf } from '../shapes/store-3d.js';
import { currentHandle } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import {
  type Contact3DState,
  clearRowIndex,
  contact3DStateOf,
  growManifold3DBuffer,
  insertRow,
  lookupRow,
  pushEvent3D,
  rowKey,
} from './manifolds-3d.js';
import { boxArgs, boxBox3DAt, planeArgs, planeBox3DAt } from './narrowphase/box-box-3d.js';
import { collide3D, collidePlane3D } from './narrowphase/collide-3d.js';
import { type Collider3D, ColliderKind3D, createManifold3D, type Manifold3D } from './narrowphase/manifold-3d.js';
import { BodyType } from './state.js';

/** Sleeping bodies met this pass by a moving or kinematic one (woken with their islands after the pass). */
const wakes = { list: new Int32Array(16), count: 0 };

function queueWake(e: number): void {
  if (wakes.count >= wakes.list.length) {
    const l = new Int32Array(2 * wakes.list.length);
    l.set(wakes.list);
    wakes.list = l;
  }
  wakes.list[wakes.count++] = e;
}

/** Whether a pair of body types is collided: one is dynamic, or a kinematic body meets a sleeping one (to wake it). */
function meets(ta: number, tb: number): boolean {
  return (
    ta === BodyType.Dynamic ||
    tb === BodyType.Dynamic ||
    (ta === BodyType.Kinematic && tb === BodyType.Sleeping) ||
    (ta === BodyType.Sleeping && tb === BodyType.Kinematic)
  );
}

/**
 * Collide stage, 3D shapes (shapes3d/): broadphase, filtering and narrowphase of every 3D shape, and
 * of ball bodies (as spheres), planes and the boundary box's six faces against them, writing manifolds
 * for the contact solver (solver/manifold-rows-3d.ts solves them in the same substeps as the ball contacts).
 * Ball-ball, ball-plane and ball-boundary contacts stay with collision/broadphase/grid.ts and collision/narrowphase/balls.ts.
 *
 * - Poses are those at the start of the step (PreviousPosition, and the orientation turned back by
 *   the step's rotation w h), as the solver measures displacement from there.
 * - Broadphase: bounding boxes (a box's own, tight; other shapes a sphere of their reach about their
 *   centre) fattened by half the shapes' speculative distance (SHAPE_SPECULATIVE_DISTANCE) and what the body's speed covers in the step
 *   (two such boxes overlap when the shapes are within the pair's margin), in a hashed uniform grid (`pairs`);
 *   a resting collider searches it only every few steps (RESTING_SEARCH_PERIOD), its other pairs coming
 *   from searching neighbours and last step's manifolds.
 * - Box pairs carry last step's manifold over while their relative pose barely changes (REUSE_SHIFT).
 * - Filtering as in 2D: shapes of one body never collide; a pair collides when each one's category
 *   meets the other's mask, unless both share a non-zero group (> 0 always, < 0 never); pairs of which
 *   neither body is dynamic are skipped; sensors push nothing.
 * - Sleeping (islands/shapes-3d.ts): a sleeping body takes part as static; one that a moving or
 *   kinematic body's manifold reaches wakes with its island, and the step's pairs are found again.
 * - Speculative contacts (Catto, GDC 2013): a point is kept if its separation is below the speculative
 *   distance plus what the bodies' speeds close in one step, so a fast body is stopped at the surface
 *   it would cross within the step: the continuous collision of bullets.
 * - A spinning cylinder's speculative points off its meridian plane are moved onto it (`meridianPoints`):
 *   its round surface does not move under its spin, though the rim vertices the solver follows do.
 * @category Collision
 */
export function shape3DCollisionSystem(world: PhysicsWorld): void {
  if (world.dimensions !== 3) return;
  const s = shapes3DOf(world);
  if (s === undefined || !s.active) return;
  const st = contact3DStateOf(world, true);
  if (st.eventStep !== world.steps) {
    st.eventStep = world.steps;
    const ev = st.events;
    ev.begin.count = 0;
    ev.end.count = 0;
    ev.sensorBegin.count = 0;
    ev.sensorEnd.count = 0;
  }
  // Last step's rows become the warm-start source.
  const prev = st.previous;
  st.previous = st.current;
  st.current = prev;
  st.current.count = 0;
  const index = st.previousIndex,
    p = st.previous;
  clearRowIndex(index, p.count);
  for (let i = 0; i < p.count; i++) insertRow(index, rowKey(world.capacity, p.shapeA[i]!, p.shapeB[i]!, p.sub[i]!), i);
  // A sleeping island met by a moving body wakes; then the step's pairs are found again with it awake.
  for (let pass = 0; ; pass++) {
    gather(world, s);
    // Room for the rows up front (two a collider, and as many as last step's buffer held): growing by
    // doubling while the rows are written cost a pile's first steps a dozen copies of every array.
    const rows = Math.max(2 * scratch.n, st.previous.bodyA.length);
    if (st.current.bodyA.length < rows) st.current = growManifold3DBuffer(st.current, rows);
    st.sensingNow.clear();
    st.current.count = 0;
    wakes.count = 0;
    rowShift = 0;
    pairs(world, s, st);
    if (wakes.count === 0 || pass >= 8) break;
    let woken = 0;
    for (let i = 0; i < wakes.count; i++) woken += wakeIsland3D(world, wakes.list[i]!);
    if (woken === 0) break;
  }
  // The contact count of the step's statistics includes the 3D shape contact points (solver rows).
  let points = 0;
  for (let i = 0, b = st.current; i < b.count; i++) points += b.points[i]!;
  world.collision.stats.contacts += points;
  sensorEvents(world, st);
}

/** Sensor events: overlaps found this step against those of the last. */
function sensorEvents(world: PhysicsWorld, st: Contact3DState): void {
  const ev = st.events,
    h = (e: number): number => (e === 0 ? 0 : currentHandle(world, e));
  for (const [k, v] of st.sensingNow) if (!st.sensing.has(k)) pushEvent3D(ev.sensorBegin, h(v[0]!), h(v[1]!), h(v[2]!), h(v[3]!));
  for (const [k, v] of st.sensing) if (!st.sensingNow.has(k)) pushEvent3D(ev.sensorEnd, h(v[0]!), h(v[1]!), h(v[2]!), h(v[3]!));
  const t = st.sensing;
  st.sensing = st.sensingNow;
  st.sensingNow = t;
}

/** Per-step collider scratch (module-level, reused; the step rebuilds it). */
interface Scratch {
  n: number;
  shape: Int32Array;
  body: Int32Array;
  minX: Float64Array;
  maxX: Float64Array;
  minY: Float64Array;
  maxY: Float64Array;
  minZ: Float64Array;
  maxZ: Float64Array;
  px: Float64Array;
  py: Float64Array;
  pz: Float64Array;
  R: Float64Array;
  speed: Float64Array;
  order: Int32Array;
  ball: Uint8Array;
}
const scratch: Scratch = {
  n: 0,
  shape: new Int32Array(0),
  body: new Int32Array(0),
  minX: new Float64Array(0),
  maxX: new Float64Array(0),
  minY: new Float64Array(0),
  maxY: new Float64Array(0),
  minZ: new Float64Array(0),
  maxZ: new Float64Array(0),
  px: new Float64Array(0),
  py: new Float64Array(0),
  pz: new Float64Array(0),
  R: new Float64Array(0),
  speed: new Float64Array(0),
  order: new Int32Array(0),
  ball: new Uint8Array(0),
};

function ensure(n: number): void {
  if (scratch.shape.length >= n) return;
  let m = Math.max(64, scratch.shape.length);
  while (m < n) m *= 2;
  // Grown arrays keep what the pass wrote so far (gather grows them while it fills them).
  const grow = <T extends Float64Array | Int32Array | Uint8Array>(a: T, k: number): T => {
    const b = new (a.constructor as new (k: number) => T)(k);
    b.set(a as never);
    return b;
  };
  const sc = scratch;
  sc.shape = grow(sc.shape, m);
  sc.body = grow(sc.body, m);
  sc.order = grow(sc.order, m);
  sc.ball = grow(sc.ball, m);
  sc.minX = grow(sc.minX, m);
  sc.maxX = grow(sc.maxX, m);
  sc.minY = grow(sc.minY, m);
  sc.maxY = grow(sc.maxY, m);
  sc.minZ = grow(sc.minZ, m);
  sc.maxZ = grow(sc.maxZ, m);
  sc.px = grow(sc.px, m);
  sc.py = grow(sc.py, m);
  sc.pz = grow(sc.pz, m);
  sc.R = grow(sc.R, 9 * m);
  sc.speed = grow(sc.speed, m);
}

const bodyQ = new Float64Array(4);

/** Start-of-step orientation of body b into bodyQ (the current one turned back by w h). */
function startOrientation(world: PhysicsWorld, b: number, turning: boolean, isBall: boolean): void {
  const c = world.components,
    Q = c.Orientation;
  let x = Q.x[b]!,
    y = Q.y[b]!,
    z = Q.z[b]!,
    w = Q.w[b]!;
  // A body with a 3D shape always has an orientation (addShape3D adds it); a ball may not.
  if (isBall && !hasComponent(world, b, c.Orientation)) {
    x = 0;
    y = 0;
    z = 0;
    w = 1;
  }
  if (turning) {
    const h = world.h,
      W = c.AngularVelocity;
    const rx = -W.x[b]! * h,
      ry = -W.y[b]! * h,
      rz = -W.z[b]! * h;
    const a = Math.sqrt(rx * rx + ry * ry + rz * rz);
    if (a > 0) {
      const k = Math.sin(a / 2) / a,
        dx = rx * k,
        dy = ry * k,
        dz = rz * k,
        dw = Math.cos(a / 2);
      const nx = dw * x + dx * w + dy * z - dz * y,
        ny = dw * y - dx * z + dy * w + dz * x,
        nz = dw * z + dx * y - dy * x + dz * w,
        nw = dw * w - dx * x - dy * y - dz * z;
      const l = Math.sqrt(nx * nx + ny * ny + nz * nz + nw * nw);
      x = nx / l;
      y = ny / l;
      z = nz / l;
      w = nw / l;
    }
  }
  bodyQ[0] = x;
  bodyQ[1] = y;
  bodyQ[2] = z;
  bodyQ[3] = w;
}

/**
 * Writes a 3D body's solver class into the collision state (body type, inverse mass, and an inverse
 * inertia that is > 0 exactly when it turns: the largest principal one, or a ball's) and returns the type.
 * @category Collision
 */
export function classifyBody3D(world: PhysicsWorld, b: number): number {
  const c = world.components,
    cs = world.collision;
  let t: number;
  if (hasComponent(world, b, c.Static)) {
    t = BodyType.Static;
    cs.invMass[b] = 0;
    cs.invInertia[b] = 0;
  } else if (hasComponent(world, b, c.Kinematic)) {
    t = BodyType.Kinematic;
    cs.invMass[b] = 0;
    cs.invInertia[b] = 0;
  } else if (hasComponent(world, b, c.Sleeping)) {
    t = BodyType.Sleeping;
    cs.invMass[b] = 0;
    cs.invInertia[b] = 0;
  } else return classifyDynamic3D(world, b);
  cs.bodyType[b] = t;
  return t;
}

/** classifyBody3D's last case, for a body known to be dynamic: its inverse mass and inertia flag; returns BodyType.Dynamic. */
function classifyDynamic3D(world: PhysicsWorld, b: number): number {
  const c = world.components,
    cs = world.collision,
    T = c.InertiaTensor;
  cs.invMass[b] = c.Mass.inv[b]!;
  cs.invInertia[b] = !hasComponent(world, b, c.AngularVelocity)
    ? 0
    : hasComponent(world, b, T)
      ? Math.max(T.invX[b]!, T.invY[b]!, T.invZ[b]!)
      : hasComponent(world, b, c.Inertia)
        ? c.Inertia.inv[b]!
        : 0;
  cs.bodyType[b] = BodyType.Dynamic;
  return BodyType.Dynamic;
}

/** Per shape slot (a ball's body slot): its collider index in the scratch this pass, valid where colliderStamp holds the pass's stamp. */
let colliderOf = new Int32Array(0),
  colliderStamp = new Int32Array(0),
  colliderPass = 0;
/**
 * Speculative distance of the 3D shapes, m: Box2D v3's (b2_speculativeDistance, 4 linear slops of 5 mm),
 * at most the world's `speculativeDistance` (0.1 m by default, which the ball contacts keep). A pair's
 * margin is this plus what the two bodies' speeds close in the step (speculative contacts), so boxes
 * standing 5 cm apart (a pyramid's side neighbours) are no contacts: with 0.1 m they were manifolds that
 * never pushed, a third of a pyramid's. As a fraction of the shape's size (2D's rule) it was too small
 * for thin capsules: a ragdoll's joints stretched 2.6 cm in its landing, against 1.2 cm.
 */
const SHAPE_SPECULATIVE_DISTANCE = 0.02;

/** This pass's speculative distance of the 3D shapes, m (SHAPE_SPECULATIVE_DISTANCE capped by the world's). */
let shapeSpec = SHAPE_SPECULATIVE_DISTANCE;

/** Whether a sensor shape took part in this pass (resting colliders then search every step: sensor events need it). */
let anySensor = false;

/** Per body slot: the step stamp and body type of the static, kinematic and sleeping bodies (scratch). */
let classStamp = new Int32Array(0),
  classKind = new Uint8Array(0),
  classStep = 0;

/** Marks the static, kinematic and sleeping bodies from three queries (in the order classifyBody3D ranks them); returns the stamp. */
function markClasses(world: PhysicsWorld): number {
  const c = world.components,
    n = world.capacity + 1;
  if (classStamp.length < n) {
    classStamp = new Int32Array(n);
    classKind = new Uint8Array(n);
    classStep = 0;
  }
  const stamp = ++classStep;
  const sleeping = query(world, [c.Sleeping]),
    kinematic = query(world, [c.Kinematic]),
    fixed = query(world, [c.Static]);
  for (let i = 0; i < sleeping.length; i++) {
    classStamp[sleeping[i]!] = stamp;
    classKind[sleeping[i]!] = BodyType.Sleeping;
  }
  for (let i = 0; i < kinematic.length; i++) {
    classStamp[kinematic[i]!] = stamp;
    classKind[kinematic[i]!] = BodyType.Kinematic;
  }
  for (let i = 0; i < fixed.length; i++) {
    classStamp[fixed[i]!] = stamp;
    classKind[fixed[i]!] = BodyType.Static;
  }
  return stamp;
}

/** Classifies the bodies, writes each collider's start-of-step pose and fattened box. */
function gather(world: PhysicsWorld, s: Shape3DStore): void {
  const stamp = markClasses(world);
  if (colliderOf.length < world.capacity + 1) {
    colliderOf = new Int32Array(world.capacity + 1);
    colliderStamp = new Int32Array(world.capacity + 1);
    colliderPass = 0;
  }
  const pass = ++colliderPass;
  anySensor = false;
  const c = world.components,
    cs = world.collision;
  const invInertia = cs.invInertia;
  const balls = query(world, [c.Position, c.Ball]);
  const cap = world.capacity;
  let n = 0;
  ensure(64);
  const h = world.h,
    spec = cs.settings.speculativeDistance < SHAPE_SPECULATIVE_DISTANCE ? cs.settings.speculativeDistance : SHAPE_SPECULATIVE_DISTANCE;
  const halfSpec = 0.5 * spec;
  shapeSpec = spec;
  const ox = c.PreviousPosition.x,
    oy = c.PreviousPosition.y,
    oz = c.PreviousPosition.z;
  const add = (e: number, b: number, isBall: boolean): void => {
    ensure(n + 1);
    const sc = scratch;
    // Static, kinematic and sleeping bodies from this step's queries (no component lookups); dynamic ones classified.
    let t: number;
    if (classStamp[b] === stamp) {
      t = classKind[b]!;
      world.collision.bodyType[b] = t;
      world.collision.invMass[b] = 0;
      world.collision.invInertia[b] = 0;
    } else t = classifyDynamic3D(world, b); // not static, kinematic or sleeping by this step's queries
    const moving = t === BodyType.Dynamic || t === BodyType.Kinematic;
    const turning = (moving && invInertia[b]! > 0) || (t === BodyType.Kinematic && hasComponent(world, b, c.AngularVelocity));
    const x0 = t === BodyType.Static ? c.Position.x[b]! : ox[b]!,
      y0 = t === BodyType.Static ? c.Position.y[b]! : oy[b]!,
      z0 = t === BodyType.Static ? c.Position.z[b]! : oz[b]!;
    startOrientation(world, b, turning, isBall);
    const qx = bodyQ[0]!,
      qy = bodyQ[1]!,
      qz = bodyQ[2]!,
      qw = bodyQ[3]!;
    let cx = x0,
      cy = y0,
      cz = z0,
      reach: number;
    const R = sc.R,
      o = 9 * n;
    if (isBall) {
      reach = c.Ball.radius[b]!;
      R[o] = 1;
      R[o + 1] = 0;
      R[o + 2] = 0;
      R[o + 3] = 0;
      R[o + 4] = 1;
      R[o + 5] = 0;
      R[o + 6] = 0;
      R[o + 7] = 0;
      R[o + 8] = 1;
    } else {
      // Shape pose: body pose composed with the placement.
      const px = s.px[e]!,
        py = s.py[e]!,
        pz = s.pz[e]!;
      const tx = 2 * (qy * pz - qz * py),
        ty = 2 * (qz * px - qx * pz),
        tz = 2 * (qx * py - qy * px);
      cx += px + qw * tx + (qy * tz - qz * ty);
      cy += py + qw * ty + (qz * tx - qx * tz);
      cz += pz + qw * tz + (qx * ty - qy * tx);
      const ax = s.qx[e]!,
        ay = s.qy[e]!,
        az = s.qz[e]!,
        aw = s.qw[e]!;
      const x = qw * ax + qx * aw + qy * az - qz * ay,
        y = qw * ay - qx * az + qy * aw + qz * ax,
        z = qw * az + qx * ay - qy * ax + qz * aw,
        w = qw * aw - qx * ax - qy * ay - qz * az;
      R[o] = 1 - 2 * (y * y + z * z);
      R[o + 1] = 2 * (x * y - z * w);
      R[o + 2] = 2 * (x * z + y * w);
      R[o + 3] = 2 * (x * y + z * w);
      R[o + 4] = 1 - 2 * (x * x + z * z);
      R[o + 5] = 2 * (y * z - x * w);
      R[o + 6] = 2 * (x * z - y * w);
      R[o + 7] = 2 * (y * z + x * w);
      R[o + 8] = 1 - 2 * (x * x + y * y);
      reach = s.reach[e]!;
    }
    let speed = 0;
    if (moving) {
      const V = c.Velocity,
        W = c.AngularVelocity;
      // (Math.sqrt of the sum of squares: Math.hypot is several times slower in V8, and these never overflow.)
      const vx = V.x[b]!,
        vy = V.y[b]!,
        vz = V.z[b]!;
      speed = Math.sqrt(vx * vx + vy * vy + vz * vz);
      if (turning) {
        const wx = W.x[b]!,
          wy = W.y[b]!,
          wz = W.z[b]!,
          dx = cx - x0,
          dy = cy - y0,
          dz = cz - z0;
        speed += Math.sqrt(wx * wx + wy * wy + wz * wz) * (reach + Math.sqrt(dx * dx + dy * dy + dz * dz));
      }
    }
    // Half its speculative distance on each box: two boxes' fattened boxes overlap exactly when they are
    // within spec + (|v_a| + |v_b|) h of each other along every axis, the pair's narrowphase margin.
    const pad = speed * h + halfSpec;
    // Half widths of the box: a box's own (sum of h_k |R_ak|, tight), else the bounding sphere's.
    let wx = reach,
      wy = reach,
      wz = reach;
    if (!isBall && s.kind[e] === Shape3DKind.Box) {
      const ex = s.hx[e]!,
        ey = s.hy[e]!,
        ez = s.hz[e]!;
      wx = ex * Math.abs(R[o]!) + ey * Math.abs(R[o + 1]!) + ez * Math.abs(R[o + 2]!);
      wy = ex * Math.abs(R[o + 3]!) + ey * Math.abs(R[o + 4]!) + ez * Math.abs(R[o + 5]!);
      wz = ex * Math.abs(R[o + 6]!) + ey * Math.abs(R[o + 7]!) + ez * Math.abs(R[o + 8]!);
    }
    sc.shape[n] = e;
    sc.body[n] = b;
    sc.ball[n] = isBall ? 1 : 0;
    sc.speed[n] = speed;
    colliderOf[e] = n;
    colliderStamp[e] = pass;
    if (!isBall && s.sensor[e] === 1) anySensor = true;
    sc.px[n] = cx;
    sc.py[n] = cy;
    sc.pz[n] = cz;
    sc.minX[n] = cx - wx - pad;
    sc.maxX[n] = cx + wx + pad;
    sc.minY[n] = cy - wy - pad;
    sc.maxY[n] = cy + wy + pad;
    sc.minZ[n] = cz - wz - pad;
    sc.maxZ[n] = cz + wz + pad;
    n++;
  };
  // Only static and sleeping colliders (a settled pile): no pair can collide (pairs need a dynamic or
  // kinematic body), so none is posed. A pile asleep cost 0.51 ms a step, 55 % of it posing its boxes.
  if (!anyMoving(s, balls, cap, stamp)) {
    scratch.n = 0;
    return;
  }
  for (let e = 1; e <= cap; e++) if (s.body[e] !== 0) add(e, s.body[e]!, false);
  for (let i = 0; i < balls.length; i++) {
    const b = balls[i]!;
    if (s.first[b] === 0) add(b, b, true);
  }
  scratch.n = n;
}

/** Whether a 3D shape or shapeless ball's body is dynamic or kinematic (not static or sleeping by markClasses' `stamp`). */
function anyMoving(s: Shape3DStore, balls: ArrayLike<number>, cap: number, stamp: number): boolean {
  const body = s.body;
  for (let e = 1; e <= cap; e++) {
    const b = body[e]!;
    if (b !== 0 && (classStamp[b] !== stamp || classKind[b] === BodyType.Kinematic)) return true;
  }
  for (let i = 0; i < balls.length; i++) {
    const b = balls[i]!;
    if (s.first[b] === 0 && (classStamp[b] !== stamp || classKind[b] === BodyType.Kinematic)) return true;
  }
  return false;
}

const colA: Collider3D = { kind: 0, px: 0, py: 0, pz: 0, R: new Float64Array(9), radius: 0, hy: 0, hull: null, box: 0, hx: 0, hz: 0 };
const colB: Collider3D = { kind: 0, px: 0, py: 0, pz: 0, R: new Float64Array(9), radius: 0, hy: 0, hull: null, box: 0, hx: 0, hz: 0 };
const manifold: Manifold3D = createManifold3D();

function collider(world: PhysicsWorld, s: Shape3DStore, i: number, out: Collider3D): void {
  const sc = scratch,
    e = sc.shape[i]!;
  out.px = sc.px[i]!;
  out.py = sc.py[i]!;
  out.pz = sc.pz[i]!;
  for (let k = 0; k < 9; k++) out.R[k] = sc.R[9 * i + k]!;
  out.box = 0;
  if (sc.ball[i]) {
    out.kind = ColliderKind3D.Sphere;
    out.radius = world.components.Ball.radius[e]!;
    out.hy = 0;
    out.hull = null;
    return;
  }
  const kind = s.kind[e]!;
  out.radius = s.radius[e]!;
  out.hy = s.hy[e]!;
  if (kind === Shape3DKind.Box) {
    out.box = 1;
    out.hx = s.hx[e]!;
    out.hz = s.hz[e]!;
  }
  if (kind === Shape3DKind.Sphere) {
    out.kind = ColliderKind3D.Sphere;
    out.hull = null;
  } else if (kind === Shape3DKind.Capsule) {
    out.kind = ColliderKind3D.Capsule;
    out.hull = null;
  } else {
    out.kind = ColliderKind3D.Polyhedron;
    out.hull = s.hulls[s.hull[e]!]!;
    out.radius = 0;
  }
}

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
};

/** Bucket of cell (x, y, z) in a table of mask + 1 buckets (Teschner et al., "Optimized Spatial Hashing for Collision Detection of Deformable Objects", 2003). */
function cellHash(x: number, y: number, z: number, mask: number): number {
  return (Math.imul(x, 73856093) ^ Math.imul(y, 19349663) ^ Math.imul(z, 83492791)) & mask;
}

/**
 * Broadphase: every collider's box goes into the cell of a uniform grid holding its low corner, with a
 * cell as wide as the widest ordinary box, so a box can only meet boxes whose low corner lies in its own
 * cell or one of the 26 around it; boxes more than four times the mean width ("large": a ground slab)
 * are tested against every collider instead. Each candidate pair is seen once (from its lower collider
 * index) and goes to `pair`. Then every collider against the meshes and the planes.
 */
function pairs(world: PhysicsWorld, s: Shape3DStore, st: Contact3DState): void {
  const sc = scratch,
    n = sc.n,
    type = world.collision.bodyType;
  const minX = sc.minX,
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
  if (!(cell > 0)) cell = 1;
  // No moving collider (a pile asleep): no pair can be new, and the grid is not built.
  let sources = 0;
  for (let i = 0; i < n; i++) {
    const t = type[sc.body[i]!]!;
    if (t === BodyType.Dynamic || t === BodyType.Kinematic) {
      sources++;
      break;
    }
  }
  if (sources === 0) {
    planesAndMeshes(world, s, st);
    return;
  }
  const inv = 1 / cell;
  let size = 64;
  while (size < 2 * n) size *= 2;
  const mask = size - 1;
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
    seen = grid.seen,
    order = sc.order,
    firstRest = grid.firstRest;
  // Which colliders search their neighbourhood this step (see the note at RESTING_SEARCH_PERIOD).
  if (grid.searching.length < n) grid.searching = new Uint8Array(Math.max(64, 2 * n));
  const sl = world.collision.sleep,
    searching = grid.searching,
    rest = sl.restTime,
    phase = world.steps;
  // How far a resting collider may move between searches (at the sleep speeds) must stay under a quarter
  // of the speculative distance, so a pair of two closes by at most half the margin.
  const mayRest = sl.enabled && !anySensor,
    period = RESTING_SEARCH_PERIOD * world.h;
  for (let i = 0; i < n; i++) {
    const b = sc.body[i]!,
      t = type[b]!;
    const reach = sc.ball[i] === 1 ? world.components.Ball.radius[b]! : s.reach[sc.shape[i]!]!;
    const skips =
      mayRest &&
      t === BodyType.Dynamic &&
      rest[b]! > 0 &&
      (sl.linearSpeed + sl.angularSpeed * reach) * period <= 0.25 * shapeSpec &&
      (phase + i) % RESTING_SEARCH_PERIOD !== 0;
    searching[i] = (t === BodyType.Kinematic || t === BodyType.Dynamic) && !skips ? 1 : 0;
  }
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
  // The boxes in bucket order, packed (min x, max x, min y, max y, min z, max z), so the neighbour
  // search below reads memory in sequence instead of jumping through the collider arrays.
  const placed = start[size]!;
  if (grid.packed.length < 6 * placed) grid.packed = new Float64Array(12 * placed);
  const pk = grid.packed;
  for (let k = 0; k < placed; k++) {
    const j = items[k]!,
      o = 6 * k;
    pk[o] = minX[j]!;
    pk[o + 1] = maxX[j]!;
    pk[o + 2] = minY[j]!;
    pk[o + 3] = maxY[j]!;
    pk[o + 4] = minZ[j]!;
    pk[o + 5] = maxZ[j]!;
  }
  // Sources: the colliders of moving (dynamic or kinematic) bodies; a resting pile's sleeping and static
  // colliders are only ever met as neighbours, so an asleep pile costs no neighbour search.
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
            const o = 6 * k;
            if (pk[o]! > x1 || pk[o + 1]! < x0 || pk[o + 2]! > y1 || pk[o + 3]! < y0 || pk[o + 4]! > z1 || pk[o + 5]! < z0) continue;
            const j = items[k]!;
            if (!meets(ti, type[sc.body[j]!]!)) continue;
            pair(world, s, st, i, j);
          }
        }
  }
  // Pairs of which neither collider searched: those that had a manifold last step (resting neighbours).
  const P = st.previous,
    cap = world.capacity;
  for (let r = 0, np = P.count; r < np; r++) {
    if (P.sub[r] !== 0 || P.bodyA[r] === 0) continue; // planes and mesh triangles: planesAndMeshes
    const ea = P.shapeA[r]!,
      eb = P.shapeB[r]!;
    if (ea > cap || eb > cap || colliderStamp[ea] !== colliderPass || colliderStamp[eb] !== colliderPass) continue;
    const i = colliderOf[ea]!,
      j = colliderOf[eb]!;
    if (searching[i] === 1 || searching[j] === 1 || order[i] === -1 || order[j] === -1) continue;
    if (
      minX[j]! > maxX[i]! ||
      maxX[j]! < minX[i]! ||
      minY[j]! > maxY[i]! ||
      maxY[j]! < minY[i]! ||
      minZ[j]! > maxZ[i]! ||
      maxZ[j]! < minZ[i]!
    )
      continue;
    if (!meets(type[sc.body[i]!]!, type[sc.body[j]!]!)) continue;
    pair(world, s, st, i, j);
  }
  for (let l = 0; l < nl; l++) {
    const i = large[l]!;
    const ti = type[sc.body[i]!]!;
    for (let j = 0; j < n; j++) {
      if (j === i || (order[j] === -1 && j < i)) continue;
      if (
        minX[j]! > maxX[i]! ||
        maxX[j]! < minX[i]! ||
        minY[j]! > maxY[i]! ||
        maxY[j]! < minY[i]! ||
        minZ[j]! > maxZ[i]! ||
        maxZ[j]! < minZ[i]!
      )
        continue;
      if (!meets(ti, type[sc.body[j]!]!)) continue;
      pair(world, s, st, i, j);
    }
  }
  planesAndMeshes(world, s, st);
}

/** The narrowphase of colliders i and j whose boxes overlap: filtering, sensors, then the manifold. */
function pair(world: PhysicsWorld, s: Shape3DStore, st: Contact3DState, i: number, j: number): void {
  const sc = scratch;
  const bi = sc.body[i]!,
    bj = sc.body[j]!;
  if (bi === bj) return;
  if (jointKeepsApart(world.joints, bi, bj)) return; // jointed without collideConnected (joints/api-3d.ts)
  // A moving body reaching a sleeping one: the sleeper takes part as static this step, and the sleep system wakes it.
  // Balls against balls are the ball narrowphase's.
  if (sc.ball[i] && sc.ball[j]) return;
  const a = sc.shape[i]! < sc.shape[j]! ? i : j,
    b = a === i ? j : i;
  const ea = sc.shape[a]!,
    eb = sc.shape[b]!;
  if (filtered(s, ea, eb, sc.ball[a] === 1, sc.ball[b] === 1)) return;
  const sa = !sc.ball[a] && s.sensor[ea] === 1,
    sb = !sc.ball[b] && s.sensor[eb] === 1;
  if (sa && sb) return;
  if (!sa && !sb && !sc.ball[a] && !sc.ball[b] && s.kind[ea] === Shape3DKind.Box && s.kind[eb] === Shape3DKind.Box) {
    // Two boxes (the common case): straight from the scratch poses, or last step's manifold carried over.
    relativePose(a, b);
    // The smaller box's smallest half extent (written out: Math.min of six arguments is not inlined).
    let size = s.hx[ea]!,
      h = s.hy[ea]!;
    if (h < size) size = h;
    h = s.hz[ea]!;
    if (h < size) size = h;
    h = s.hx[eb]!;
    if (h < size) size = h;
    h = s.hy[eb]!;
    if (h < size) size = h;
    h = s.hz[eb]!;
    if (h < size) size = h;
    const prev = previousBoxRow(st, ea, eb, world.capacity);
    if (prev >= 0 && reusable(st.previous, prev, size)) {
      reuseManifold(st.previous, prev, a, b);
      boxRow.from = prev;
    } else {
      const margin = shapeSpec + (sc.speed[a]! + sc.speed[b]!) * world.h;
      // The numbers go through boxArgs (doubles passed to a call are boxed: garbage every step).
      const g = boxArgs;
      g[0] = sc.px[a]!;
      g[1] = sc.py[a]!;
      g[2] = sc.pz[a]!;
      g[3] = s.hx[ea]!;
      g[4] = s.hy[ea]!;
      g[5] = s.hz[ea]!;
      g[6] = sc.px[b]!;
      g[7] = sc.py[b]!;
      g[8] = sc.pz[b]!;
      g[9] = s.hx[eb]!;
      g[10] = s.hy[eb]!;
      g[11] = s.hz[eb]!;
      g[12] = margin;
      boxBox3DAt(sc.R, 9 * a, sc.R, 9 * b, manifold);
      boxRow.from = -1;
    }
    boxRow.a = a;
    boxRow.b = b;
    boxRow.prev = prev;
    if (manifold.count > 0) emitPair(world, s, st, a, b, bi, bj);
    boxRow.a = -1;
    return;
  }
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
  const margin = shapeSpec + (sc.speed[a]! + sc.speed[b]!) * world.h;
  collide3D(colA, colB, margin, manifold);
  if (manifold.count > 0) emitPair(world, s, st, a, b, bi, bj);
}

/**
 * Offset of the last box pair's previous row from the row it is written to (this pass): pairs come in
 * nearly the same order every step, so the previous row of the next pair is most often at the same
 * offset, found without a hash lookup (a cache miss each in a large pile) and read in sequence.
 */
let rowShift = 0;

/** The previous step's row of box pair (ea, eb), or -1: the row at `rowShift` if it is that pair's, else from the index. */
function previousBoxRow(st: Contact3DState, ea: number, eb: number, capacity: number): number {
  const P = st.previous,
    guess = st.current.count + rowShift;
  let prev: number;
  if (guess >= 0 && guess < P.count && P.shapeA[guess] === ea && P.shapeB[guess] === eb && P.sub[guess] === 0) prev = guess;
  else prev = lookupRow(st.previousIndex, rowKey(capacity, ea, eb, 0));
  if (prev >= 0) rowShift = prev - st.current.count;
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
const rel = new Float64Array(12);

/** rel = (R_A^T (c_B - c_A), R_A^T R_B) of scratch colliders a and b. */
function relativePose(a: number, b: number): void {
  const sc = scratch,
    R = sc.R,
    oa = 9 * a,
    ob = 9 * b;
  const dx = sc.px[b]! - sc.px[a]!,
    dy = sc.py[b]! - sc.py[a]!,
    dz = sc.pz[b]! - sc.pz[a]!;
  for (let i = 0; i < 3; i++) {
    const a0 = R[oa + i]!,
      a1 = R[oa + 3 + i]!,
      a2 = R[oa + 6 + i]!;
    rel[i] = a0 * dx + a1 * dy + a2 * dz;
    for (let j = 0; j < 3; j++) rel[3 + 3 * i + j] = a0 * R[ob + j]! + a1 * R[ob + 3 + j]! + a2 * R[ob + 6 + j]!;
  }
}

/** Whether previous row `r` is a box-box row whose relative pose is within the reuse bounds of `rel`. */
function reusable(P: Contact3DState['previous'], r: number, size: number): boolean {
  if (P.local[r] !== 1) return false;
  const o = 12 * r,
    RP = P.relPose,
    shift = REUSE_SHIFT * size;
  for (let k = 0; k < 3; k++) if (Math.abs(RP[o + k]! - rel[k]!) > shift) return false;
  for (let k = 3; k < 12; k++) if (Math.abs(RP[o + k]! - rel[k]!) > REUSE_TURN) return false;
  return true;
}

/** Rebuilds `manifold` from previous row r's local normal and points at the current poses of colliders a and b. */
function reuseManifold(P: Contact3DState['previous'], r: number, a: number, b: number): void {
  const sc = scratch,
    R = sc.R,
    oa = 9 * a,
    ob = 9 * b,
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
  const nx = R[oa]! * u + R[oa + 1]! * v + R[oa + 2]! * w,
    ny = R[oa + 3]! * u + R[oa + 4]! * v + R[oa + 5]! * w,
    nz = R[oa + 6]! * u + R[oa + 7]! * v + R[oa + 8]! * w;
  m.nx = nx;
  m.ny = ny;
  m.nz = nz;
  const LA = P.localA,
    LB = P.localB,
    count = P.points[r]!;
  for (let k = 0; k < count; k++) {
    const q = 3 * (4 * r + k);
    const pax = ax + R[oa]! * LA[q]! + R[oa + 1]! * LA[q + 1]! + R[oa + 2]! * LA[q + 2]!;
    const pay = ay + R[oa + 3]! * LA[q]! + R[oa + 4]! * LA[q + 1]! + R[oa + 5]! * LA[q + 2]!;
    const paz = az + R[oa + 6]! * LA[q]! + R[oa + 7]! * LA[q + 1]! + R[oa + 8]! * LA[q + 2]!;
    const pbx = bx + R[ob]! * LB[q]! + R[ob + 1]! * LB[q + 1]! + R[ob + 2]! * LB[q + 2]!;
    const pby = by + R[ob + 3]! * LB[q]! + R[ob + 4]! * LB[q + 1]! + R[ob + 5]! * LB[q + 2]!;
    const pbz = bz + R[ob + 6]! * LB[q]! + R[ob + 7]! * LB[q + 1]! + R[ob + 8]! * LB[q + 2]!;
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
    for (let k = 0, o = 12 * i, po = 12 * from; k < 12; k++) RP[o + k] = PR[po + k]!;
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
    oa = 9 * a,
    ob = 9 * b,
    m = manifold;
  for (let k = 0; k < 12; k++) buf.relPose[12 * i + k] = rel[k]!;
  const nx = m.nx,
    ny = m.ny,
    nz = m.nz;
  buf.localNormal[3 * i] = R[oa]! * nx + R[oa + 3]! * ny + R[oa + 6]! * nz;
  buf.localNormal[3 * i + 1] = R[oa + 1]! * nx + R[oa + 4]! * ny + R[oa + 7]! * nz;
  buf.localNormal[3 * i + 2] = R[oa + 2]! * nx + R[oa + 5]! * ny + R[oa + 8]! * nz;
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
    buf.localA[q] = R[oa]! * dax + R[oa + 3]! * day + R[oa + 6]! * daz;
    buf.localA[q + 1] = R[oa + 1]! * dax + R[oa + 4]! * day + R[oa + 7]! * daz;
    buf.localA[q + 2] = R[oa + 2]! * dax + R[oa + 5]! * day + R[oa + 8]! * daz;
    buf.localB[q] = R[ob]! * dbx + R[ob + 3]! * dby + R[ob + 6]! * dbz;
    buf.localB[q + 1] = R[ob + 1]! * dbx + R[ob + 4]! * dby + R[ob + 7]! * dbz;
    buf.localB[q + 2] = R[ob + 2]! * dbx + R[ob + 5]! * dby + R[ob + 8]! * dbz;
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
    if (ta === BodyType.Sleeping && wakesSleeper3D(world, bj, tb, gap, closing)) queueWake(bi);
    else if (tb === BodyType.Sleeping && wakesSleeper3D(world, bi, ta, gap, closing)) queueWake(bj);
  }
  if (ta !== BodyType.Dynamic && tb !== BodyType.Dynamic) return;
  emit(world, s, st, sc.body[a]!, sc.body[b]!, sc.shape[a]!, sc.shape[b]!, sc.ball[a] === 1, sc.ball[b] === 1);
}

/** Every collider against the triangle meshes and the planes. */
function planesAndMeshes(world: PhysicsWorld, s: Shape3DStore, st: Contact3DState): void {
  const sc = scratch,
    n = sc.n,
    type = world.collision.bodyType;
  const h = world.h;
  const meshList = meshesOf(world);
  if (meshList.length > 0) for (let i = 0; i < n; i++) for (const m of meshList) collideMesh(world, s, st, m, i);
  // Planes and the boundary box's six faces: static, A side.
  const c = world.components;
  const planes = query(world, [c.Plane]);
  const box = world.collision.boundary;
  if (planes.length === 0 && !box.enabled) return;
  const P = c.Plane,
    lo = box.min,
    hi = box.max;
  for (let i = 0; i < n; i++) {
    if (sc.ball[i]) continue; // balls against planes and the boundary are the ball narrowphase's
    if (type[sc.body[i]!] !== BodyType.Dynamic) continue;
    const e = sc.shape[i]!;
    if (s.sensor[e]) continue;
    posed = false;
    const margin = shapeSpec + sc.speed[i]! * h;
    for (let k = 0; k < planes.length; k++) {
      const p = planes[k]!;
      if (collidePlaneAt(world, s, i, P.nx[p]!, P.ny[p]!, P.nz[p]!, P.d[p]!, margin))
        emit(world, s, st, 0, sc.body[i]!, p, e, false, false, p);
    }
    if (!box.enabled) continue;
    // The faces as planes n . x = d with n pointing into the box (solid outside it).
    for (let f = 0; f < 6; f++) {
      const axis = f >> 1,
        sign = (f & 1) === 0 ? 1 : -1;
      const d = sign > 0 ? lo[axis]! : -hi[axis]!;
      const nx = axis === 0 ? sign : 0,
        ny = axis === 1 ? sign : 0,
        nz = axis === 2 ? sign : 0;
      if (collidePlaneAt(world, s, i, nx, ny, nz, d, margin)) emit(world, s, st, 0, sc.body[i]!, 0, e, false, false, 0, BOUNDARY_SUB + f);
    }
  }
}

/**
 * The row `sub` of a boundary face (0 to 5: -x, +x, -y, +y, -z, +z walls' faces, in the order of
 * `planesAndMeshes`), with no shape on the A side: above every mesh triangle's (triangle index + 1,
 * under 2^22 - 6), so a face's warm start never meets a triangle's.
 */
const BOUNDARY_SUB = 4194304 - 6;

/** Whether collider i's pose has been written to `colB` in the current collider's pass over the planes. */
let posed = false;

/**
 * The manifold (in `manifold`) of collider i against the plane n . x = d (solid below), within
 * `margin`; false, without posing the collider, when its bounding sphere is farther than the margin.
 */
function collidePlaneAt(
  world: PhysicsWorld,
  s: Shape3DStore,
  i: number,
  nx: number,
  ny: number,
  nz: number,
  d: number,
  margin: number,
): boolean {
  const sc = scratch,
    e = sc.shape[i]!;
  // Cheap reject: the bounding sphere above the plane by more than the margin.
  if (nx * sc.px[i]! + ny * sc.py[i]! + nz * sc.pz[i]! - d - s.reach[e]! > margin) return false;
  if (s.kind[e] === Shape3DKind.Box) {
    const g = planeArgs;
    g[0] = nx;
    g[1] = ny;
    g[2] = nz;
    g[3] = d;
    g[4] = sc.px[i]!;
    g[5] = sc.py[i]!;
    g[6] = sc.pz[i]!;
    g[7] = s.hx[e]!;
    g[8] = s.hy[e]!;
    g[9] = s.hz[e]!;
    g[10] = margin;
    planeBox3DAt(sc.R, 9 * i, manifold);
  } else {
    if (!posed) {
      collider(world, s, i, colB);
      posed = true;
    }
    collidePlane3D(nx, ny, nz, d, colB, margin, manifold);
  }
  return manifold.count > 0;
}

/** Writes the manifold into the buffer as solver rows with their anchors, material and warm start. */
function emit(
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
  const fa = wall ? bound.friction : plane !== 0 || ballA ? c.Material.friction[ea]! : s.friction[ea]!,
    ra = wall ? bound.restitution : plane !== 0 || ballA ? c.Material.restitution[ea]! : s.restitution[ea]!;
  const fb = ballB ? c.Material.friction[eb]! : s.friction[eb]!,
    rb = ballB ? c.Material.restitution[eb]! : s.restitution[eb]!;
  buf.friction[i] = Math.sqrt(fa * fb);
  buf.restitution[i] = Math.max(ra, rb);
  // Anchors from where the narrowphase measured: PreviousPosition, or Position for a static body.
  const type = world.collision.bodyType;
  let ax = 0,
    ay = 0,
    az = 0,
    bx = 0,
    by = 0,
    bz = 0;
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
  if (bodyB !== 0 && !ballB) meridianPoints(world, s, eb, bodyB);
  if (bodyA !== 0 && !ballA && plane === 0) meridianPoints(world, s, ea, bodyA);
  // A box pair's reuse fields (see REUSE_SHIFT); other rows are never reused.
  if (boxRow.a >= 0) storeLocal(st, buf, i);
  else buf.local[i] = 0;
  const prev = boxRow.a >= 0 ? boxRow.prev : lookupRow(st.previousIndex, rowKey(world.capacity, ea, eb, sub));
  const P = st.previous,
    reused = boxRow.a >= 0 && boxRow.from >= 0;
  for (let k = 0; k < m.count; k++) {
    const q = 4 * i + k;
    buf.rax[q] = m.x[k]! - ax;
    buf.ray[q] = m.y[k]! - ay;
    buf.raz[q] = m.z[k]! - az;
    buf.rbx[q] = m.x[k]! - bx;
    buf.rby[q] = m.y[k]! - by;
    buf.rbz[q] = m.z[k]! - bz;
    buf.sep[q] = m.sep[k]!;
    buf.id[q] = m.id[k]!;
    buf.ln[q] = 0;
    buf.maxLn[q] = 0;
    if (reused) {
      // A reused manifold has the previous row's points in the same order (reuseManifold).
      buf.ln[q] = P.ln[4 * prev + k]!;
    } else if (prev >= 0) {
      for (let j = 0; j < P.points[prev]!; j++) {
        const pq = 4 * prev + j;
        if (P.id[pq] === m.id[k]) {
          buf.ln[q] = P.ln[pq]!;
          break;
        }
      }
    }
  }
  // The manifold's friction (one anchor a row) from the pair's last row while the normal barely turned (t1 follows n).
  if (prev >= 0 && P.nx[prev]! * nx + P.ny[prev]! * ny + P.nz[prev]! * nz > 0.99) {
    buf.ft1[i] = P.ft1[prev]!;
    buf.ft2[i] = P.ft2[prev]!;
    buf.ftw[i] = P.ftw[prev]!;
  } else {
    buf.ft1[i] = 0;
    buf.ft2[i] = 0;
    buf.ftw[i] = 0;
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
  if (colliderStamp[e] !== colliderPass || s.kind[e] !== Shape3DKind.Cylinder) return;
  // The normal is the manifold's (read here: doubles passed to a call are boxed).
  const nx = manifold.nx,
    ny = manifold.ny,
    nz = manifold.nz;
  const i = colliderOf[e]!,
    sc = scratch,
    R = sc.R,
    o = 9 * i,
    W = world.components.AngularVelocity;
  if (!(W.x.length > body)) return;
  // The cylinder's axis (its shape y axis) and u = a x n, across the meridian plane.
  const ax = R[o + 1]!,
    ay = R[o + 4]!,
    az = R[o + 7]!;
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

const triQ = new Float64Array(3);

/** Closest point of triangle a b c to p into triQ (Ericson, Real-Time Collision Detection, 5.1.5). */
function closestOnTriangle(V: Float64Array, a: number, b: number, c: number, px: number, py: number, pz: number): void {
  const ax = V[a]!,
    ay = V[a + 1]!,
    az = V[a + 2]!;
  const abx = V[b]! - ax,
    aby = V[b + 1]! - ay,
    abz = V[b + 2]! - az,
    acx = V[c]! - ax,
    acy = V[c + 1]! - ay,
    acz = V[c + 2]! - az;
  const apx = px - ax,
    apy = py - ay,
    apz = pz - az;
  const d1 = abx * apx + aby * apy + abz * apz,
    d2 = acx * apx + acy * apy + acz * apz;
  const set = (u: number, v: number): void => {
    triQ[0] = ax + abx * u + acx * v;
    triQ[1] = ay + aby * u + acy * v;
    triQ[2] = az + abz * u + acz * v;
  };
  if (d1 <= 0 && d2 <= 0) {
    set(0, 0);
    return;
  }
  const bpx = px - V[b]!,
    bpy = py - V[b + 1]!,
    bpz = pz - V[b + 2]!;
  const d3 = abx * bpx + aby * bpy + abz * bpz,
    d4 = acx * bpx + acy * bpy + acz * bpz;
  if (d3 >= 0 && d4 <= d3) {
    set(1, 0);
    return;
  }
  const vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    set(d1 / (d1 - d3), 0);
    return;
  }
  const cpx = px - V[c]!,
    cpy = py - V[c + 1]!,
    cpz = pz - V[c + 2]!;
  const d5 = abx * cpx + aby * cpy + abz * cpz,
    d6 = acx * cpx + acy * cpy + acz * cpz;
  if (d6 >= 0 && d5 <= d6) {
    set(0, 1);
    return;
  }
  const vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    set(0, d2 / (d2 - d6));
    return;
  }
  const va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const w = (d4 - d3) / (d4 - d3 + d5 - d6);
    set(1 - w, w);
    return;
  }
  const den = 1 / (va + vb + vc);
  set(vb * den, vc * den);
}

/** Collider i against the triangles of mesh m whose boxes meet its box: a manifold per triangle touched. */
function collideMesh(world: PhysicsWorld, s: Shape3DStore, st: Contact3DState, m: Mesh3D, i: number): void {
  const sc = scratch,
    b = sc.body[i]!;
  if (world.collision.bodyType[b] !== BodyType.Dynamic) return;
  const e = sc.shape[i]!;
  if (!sc.ball[i] && s.sensor[e]) return;
  const Bd = m.bounds,
    N = m.normals,
    V = m.vertices,
    T = m.triangles;
  const margin = shapeSpec + sc.speed[i]! * world.h;
  // The triangles' boxes are not fattened: the collider's box takes the other half of its speculative distance here.
  const g = 0.5 * shapeSpec;
  collider(world, s, i, colB);
  const reach = sc.ball[i] ? colB.radius : s.reach[e]!;
  const out = manifold;
  for (let t = 0, nt = T.length / 3; t < nt; t++) {
    const o = 6 * t;
    if (
      Bd[o]! > sc.maxX[i]! + g ||
      Bd[o + 3]! < sc.minX[i]! - g ||
      Bd[o + 1]! > sc.maxY[i]! + g ||
      Bd[o + 4]! < sc.minY[i]! - g ||
      Bd[o + 2]! > sc.maxZ[i]! + g ||
      Bd[o + 5]! < sc.minZ[i]! - g
    )
      continue;
    const nx = N[3 * t]!,
      ny = N[3 * t + 1]!,
      nz = N[3 * t + 2]!;
    const a = 3 * T[3 * t]!,
      bb = 3 * T[3 * t + 1]!,
      c = 3 * T[3 * t + 2]!;
    const d = nx * V[a]! + ny * V[a + 1]! + nz * V[a + 2]!;
    // Behind the triangle by more than the shape's size: pushed through, let go.
    const centre = nx * colB.px + ny * colB.py + nz * colB.pz - d;
    if (centre < -reach || centre - reach > margin) continue;
    out.count = 0;
    out.nx = nx;
    out.ny = ny;
    out.nz = nz;
    if (colB.kind !== ColliderKind3D.Polyhedron) {
      // Sphere or capsule: each end sphere against the triangle's closest point.
      const hy = colB.kind === ColliderKind3D.Capsule ? colB.hy : 0,
        r = colB.radius;
      for (let end = 0; end < (hy > 0 ? 2 : 1); end++) {
        const sgn = end === 0 ? -1 : 1;
        const px = colB.px + sgn * colB.R[1]! * hy,
          py = colB.py + sgn * colB.R[4]! * hy,
          pz = colB.pz + sgn * colB.R[7]! * hy;
        closestOnTriangle(V, a, bb, c, px, py, pz);
        let ux = px - triQ[0]!,
          uy = py - triQ[1]!,
          uz = pz - triQ[2]!;
        const dist = Math.hypot(ux, uy, uz);
        if (dist - r > margin || nx * ux + ny * uy + nz * uz < 0) continue;
        if (dist > 1e-12) {
          ux /= dist;
          uy /= dist;
          uz /= dist;
        } else {
          ux = nx;
          uy = ny;
          uz = nz;
        }
        if (out.count === 0) {
          out.nx = ux;
          out.ny = uy;
          out.nz = uz;
        }
        const sep = dist - r;
        const k = out.count++;
        out.x[k] = triQ[0]! + (ux * sep) / 2;
        out.y[k] = triQ[1]! + (uy * sep) / 2;
        out.z[k] = triQ[2]! + (uz * sep) / 2;
        out.sep[k] = sep;
        out.id[k] = end;
      }
    } else {
      // Polyhedron: its vertices over the triangle, below the margin.
      const h = colB.hull!,
        HV = h.vertices,
        R = colB.R;
      let best = -1,
        cnt = 0;
      for (let v = 0, nv = HV.length / 3; v < nv; v++) {
        const lx = HV[3 * v]!,
          ly = HV[3 * v + 1]!,
          lz = HV[3 * v + 2]!;
        const wx = colB.px + R[0]! * lx + R[1]! * ly + R[2]! * lz,
          wy = colB.py + R[3]! * lx + R[4]! * ly + R[5]! * lz,
          wz = colB.pz + R[6]! * lx + R[7]! * ly + R[8]! * lz;
        const sep = nx * wx + ny * wy + nz * wz - d;
        if (sep > margin) continue;
        // Inside the triangle's prism (barycentric signs of the projection).
        let inside = true;
        for (const [p, q] of [
          [a, bb],
          [bb, c],
          [c, a],
        ] as const) {
          const ex = V[q]! - V[p]!,
            ey = V[q + 1]! - V[p + 1]!,
            ez = V[q + 2]! - V[p + 2]!;
          const qx = wx - V[p]!,
            qy = wy - V[p + 1]!,
            qz = wz - V[p + 2]!;
          if (nx * (ey * qz - ez * qy) + ny * (ez * qx - ex * qz) + nz * (ex * qy - ey * qx) < 0) {
            inside = false;
            break;
          }
        }
        if (!inside) continue;
        cnt++;
        if (out.count < 4) {
          const k = out.count++;
          out.x[k] = wx - (nx * sep) / 2;
          out.y[k] = wy - (ny * sep) / 2;
          out.z[k] = wz - (nz * sep) / 2;
          out.sep[k] = sep;
          out.id[k] = v;
        } else {
          // Keep the four deepest.
          best = 0;
          for (let k = 1; k < 4; k++) if (out.sep[k]! > out.sep[best]!) best = k;
          if (sep < out.sep[best]!) {
            out.x[best] = wx - (nx * sep) / 2;
            out.y[best] = wy - (ny * sep) / 2;
            out.z[best] = wz - (nz * sep) / 2;
            out.sep[best] = sep;
            out.id[best] = v;
          }
        }
      }
      void cnt;
    }
    if (out.count > 0) emit(world, s, st, 0, b, m.entity, e, false, sc.ball[i] === 1, m.entity, t + 1);
  }
}
