import { hasComponent } from 'bitecs';
import { wakeIslandForStep } from '../islands/step-wake.js';
import { M00, M01, M02, M10, M11, M12, M20, M21, M22, MAT3_STRIDE } from '../math/mat3-layout.js';
import { quaternionProduct, quaternionRotate, rotationMatrix, turnQuaternion } from '../math/quaternion.js';
import { Shape3DKind, type Shape3DStore, shapes3DOf } from '../shapes/store-3d.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { classifyDynamic, lookUpBodyBits, rankedLists, rankedListType } from './body-class.js';
import { pairs } from './broadphase/pairs-3d.js';
import { ColliderMaterial, ensure, keptPose, notePose, ownPoses, SHAPE_SPECULATIVE_DISTANCE, scratch, wakes } from './colliders-3d.js';
import { pushEvent } from './events.js';
import { type Contact3DState, clearRowIndex, contact3DStateOf, growManifold3DBuffer, insertRow, rowKey } from './manifolds-3d.js';
import { carryImpulses } from './pair-manifolds-3d.js';
import { BodyType } from './state.js';

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
 * - Sleeping (islands/sleep.ts, islands/step-wake.ts): a sleeping body takes part as static; one that a moving or
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
  // Last step's rows become the warm-start source.
  const prev = st.previous;
  st.previous = st.current;
  st.current = prev;
  st.current.count = 0;
  indexPreviousRows(st, world.capacity);
  // A sleeping island met by a moving body wakes; then the step's pairs are found again with it awake.
  for (let pass = 0; ; pass++) {
    const posed = gather(world, s);
    if (posed >= 0) {
      scratch.n = posed;
      ownPoses(s, scratch.spec);
    }
    // Room for the rows up front (two a collider, and as many as last step's buffer held): growing by
    // doubling while the rows are written cost a pile's first steps a dozen copies of every array.
    const rows = Math.max(2 * scratch.n, st.previous.bodyA.length);
    if (st.current.bodyA.length < rows) st.current = growManifold3DBuffer(st.current, rows);
    st.sensingNow.clear();
    st.current.count = 0;
    wakes.count = 0;
    scratch.rowShift = 0;
    pairs(world, s, st);
    if (wakes.count === 0 || pass >= 8) break;
    let woken = 0;
    for (let i = 0; i < wakes.count; i++) woken += wakeIslandForStep(world, wakes.list[i]!);
    if (woken === 0) break;
  }
  carryImpulses(st);
  // The contact count of the step's statistics: the ball contacts of this step (their buffer, which the
  // balls' narrowphase refills earlier in the collide stage and which stays empty in a world without
  // it) and the 3D shape contact points (solver rows).
  world.collision.stats.contacts = world.collision.contacts.count + rowPoints(st.current);
  sensorEvents(world, st);
}

/*
 * The loops of the collide step are each the last thing in a function of its own (gather's too: it
 * returns the colliders it posed and the system notes them): V8 compiles a long loop on the stack (OSR)
 * while it runs interpreted, and that code, entered again at the loop of every later call, was thrown
 * away each time at the first operation past the loop it had no type feedback for. Traced on
 * box-pile-3d 5,000 with the rows' loops in shape3DCollisionSystem: once in about 10 runs its code
 * deoptimised every step from the first wake on (81 times in 90 steps), and with those loops moved out
 * but gather's notes after its loop, gather did so every step (200 in 200).
 */

/** Indexes last step's rows (st.previous) by their key, for the warm start and the reuse of this step's pairs. */
function indexPreviousRows(st: Contact3DState, capacity: number): void {
  const index = st.previousIndex,
    p = st.previous;
  clearRowIndex(index, p.count);
  for (let i = 0; i < p.count; i++) insertRow(index, rowKey(capacity, p.shapeA[i]!, p.shapeB[i]!, p.sub[i]!), i);
}

/** The contact points of the rows of `b`. */
function rowPoints(b: Contact3DState['current']): number {
  let points = 0;
  for (let i = 0; i < b.count; i++) points += b.points[i]!;
  return points;
}

/** Sensor events: overlaps found this step against those of the last. */
function sensorEvents(world: PhysicsWorld, st: Contact3DState): void {
  const ev = world.collision.events;
  for (const [k, v] of st.sensingNow) if (!st.sensing.has(k)) pushEvent(world, ev.sensorBegin, v[0]!, v[1]!, v[2]!, v[3]!);
  for (const [k, v] of st.sensing) if (!st.sensingNow.has(k)) pushEvent(world, ev.sensorEnd, v[0]!, v[1]!, v[2]!, v[3]!);
  const t = st.sensing;
  st.sensing = st.sensingNow;
  st.sensingNow = t;
}

/** The body's start-of-step orientation (x, y, z, w), and the rotation (x, y, z, angle) that turns it back. */
const bodyQ = new Float64Array(4),
  turnBack = new Float64Array(4);

/** Start-of-step orientation of body b into bodyQ (the current one turned back by w h). */
function startOrientation(world: PhysicsWorld, b: number, turning: boolean, isBall: boolean): void {
  const c = world.components,
    Q = c.Orientation;
  // A body with a 3D shape always has an orientation (addShape3D adds it); a ball may not.
  const has = !isBall || hasComponent(world, b, c.Orientation);
  bodyQ[0] = has ? Q.x[b]! : 0;
  bodyQ[1] = has ? Q.y[b]! : 0;
  bodyQ[2] = has ? Q.z[b]! : 0;
  bodyQ[3] = has ? Q.w[b]! : 1;
  if (!turning) return;
  const h = world.h,
    W = c.AngularVelocity;
  const rx = -W.x[b]! * h,
    ry = -W.y[b]! * h,
    rz = -W.z[b]! * h;
  const a = Math.sqrt(rx * rx + ry * ry + rz * rz);
  if (!(a > 0)) return;
  turnBack[0] = rx;
  turnBack[1] = ry;
  turnBack[2] = rz;
  turnBack[3] = a;
  turnQuaternion(bodyQ, turnBack, bodyQ);
  const nx = bodyQ[0]!,
    ny = bodyQ[1]!,
    nz = bodyQ[2]!,
    nw = bodyQ[3]!;
  const l = Math.sqrt(nx * nx + ny * ny + nz * nz + nw * nw);
  bodyQ[0] = nx / l;
  bodyQ[1] = ny / l;
  bodyQ[2] = nz / l;
  bodyQ[3] = nw / l;
}

/** Per body slot: the step stamp and body type of the static, kinematic and sleeping bodies (scratch). */
let classStamp = new Int32Array(0),
  classKind = new Uint8Array(0),
  classStep = 0;

/** Marks the static, kinematic and sleeping bodies with their class (collision/body-class.ts rankedLists); returns the stamp. */
function markClasses(world: PhysicsWorld): number {
  const n = world.capacity + 1;
  if (classStamp.length < n) {
    classStamp = new Int32Array(n);
    classKind = new Uint8Array(n);
    classStep = 0;
  }
  const stamp = ++classStep,
    ranked = rankedLists(world, []);
  for (let k = 0; k < ranked.length; k++) {
    const list = ranked[k]!,
      t = rankedListType(k);
    for (let i = 0; i < list.length; i++) {
      classStamp[list[i]!] = stamp;
      classKind[list[i]!] = t;
    }
  }
  return stamp;
}

/** The offset of a shape's centre from its body's centre, m (world), written by colliderRotation. */
const shapeShift = new Float64Array(3);
/** colliderRotation's shape orientation: the placement, then the world one (the body's composed with it). */
const shapeQ = new Float64Array(4);

/**
 * Writes the world rotation of shape e's collider at R[o + M00] (math/mat3-layout.ts): its body's start-of-step
 * orientation (bodyQ) composed with the shape's placement, and the placement's offset turned by bodyQ into
 * shapeShift; a shapeless ball's is the identity (shapeShift is not written).
 */
function colliderRotation(s: Shape3DStore, e: number, isBall: boolean, R: Float64Array, o: number): void {
  if (isBall) {
    R[o + M00] = 1;
    R[o + M01] = 0;
    R[o + M02] = 0;
    R[o + M10] = 0;
    R[o + M11] = 1;
    R[o + M12] = 0;
    R[o + M20] = 0;
    R[o + M21] = 0;
    R[o + M22] = 1;
    return;
  }
  const px = s.px[e]!,
    py = s.py[e]!,
    pz = s.pz[e]!,
    qx = s.qx[e]!,
    qy = s.qy[e]!,
    qz = s.qz[e]!,
    qw = s.qw[e]!;
  if (px === 0 && py === 0 && pz === 0 && qx === 0 && qy === 0 && qz === 0 && qw === 1) {
    // A shape placed at its body's centre, unturned (a pile's boxes): the body's own rotation, no
    // offset; the composition below would return the same numbers (up to the sign of a zero).
    shapeShift[0] = 0;
    shapeShift[1] = 0;
    shapeShift[2] = 0;
    rotationMatrix(bodyQ[0]!, bodyQ[1]!, bodyQ[2]!, bodyQ[3]!, R, o);
    return;
  }
  // Shape pose: body pose composed with the placement.
  shapeShift[0] = s.px[e]!;
  shapeShift[1] = s.py[e]!;
  shapeShift[2] = s.pz[e]!;
  quaternionRotate(bodyQ, shapeShift, shapeShift);
  shapeQ[0] = s.qx[e]!;
  shapeQ[1] = s.qy[e]!;
  shapeQ[2] = s.qz[e]!;
  shapeQ[3] = s.qw[e]!;
  quaternionProduct(bodyQ, shapeQ, shapeQ);
  rotationMatrix(shapeQ[0]!, shapeQ[1]!, shapeQ[2]!, shapeQ[3]!, R, o);
}

/**
 * Classifies the bodies, writes each collider's start-of-step pose and fattened box; returns how many it
 * posed (the caller notes them: scratch.n, ownPoses), or -1 when none is moving (scratch.n is then 0 and
 * nothing is posed).
 */
function gather(world: PhysicsWorld, s: Shape3DStore): number {
  const stamp = markClasses(world);
  lookUpBodyBits(world);
  if (scratch.colliderOf.length < world.capacity + 1) {
    scratch.colliderOf = new Int32Array(world.capacity + 1);
    scratch.colliderStamp = new Int32Array(world.capacity + 1);
    scratch.colliderPass = 0;
  }
  const pass = ++scratch.colliderPass,
    colliderOf = scratch.colliderOf,
    colliderStamp = scratch.colliderStamp;
  scratch.anySensor = false;
  const c = world.components,
    cs = world.collision;
  const balls = query(world, [c.Position, c.Ball]);
  const cap = world.capacity;
  let n = 0;
  ensure(64);
  const spec = cs.settings.speculativeDistance < SHAPE_SPECULATIVE_DISTANCE ? cs.settings.speculativeDistance : SHAPE_SPECULATIVE_DISTANCE;
  scratch.spec = spec;
  const Q = c.Orientation;
  // Only static and sleeping colliders (a settled pile): no pair can collide (pairs need a dynamic or
  // kinematic body), so none is posed (posing would be most of a sleeping pile's step).
  if (!anyMoving(s, balls, cap, stamp)) {
    scratch.n = 0;
    return -1;
  }
  // Every 3D shape in slot order, then every shapeless ball: collider k's pose and fattened box at
  // scratch index n (a loop, not a closure called per collider: n and the step's constants stay in
  // registers instead of the closure's context).
  const ballCount = balls.length;
  for (let k = 1; k <= cap + ballCount; k++) {
    let e: number, b: number, isBall: boolean;
    if (k <= cap) {
      e = k;
      b = s.body[e]!;
      if (b === 0) continue;
      isBall = false;
    } else {
      b = balls[k - cap - 1]!;
      if (s.first[b] !== 0) continue;
      e = b;
      isBall = true;
    }
    ensure(n + 1);
    // Static, kinematic and sleeping bodies from this step's queries (no component lookups); dynamic ones classified.
    // Written for every body, then overwritten for a dynamic one (one not static, kinematic or sleeping by
    // this step's queries): no branch first taken when the first body of a pile falls asleep.
    let t: number = classKind[b]!;
    cs.bodyType[b] = t;
    cs.invMass[b] = 0;
    cs.invInertia[b] = 0;
    if (classStamp[b] !== stamp) t = classifyDynamic(world, b);
    // A sleeping shape collider keeps what its index holds from the last pass while its body starts the
    // step where it did (keptPose); every other one is posed. (The check and the writes run for every
    // collider: no branch first taken when the first body of a pile falls asleep.)
    const asleep = t === BodyType.Sleeping && !isBall;
    const kept = keptPose(s, spec, n, asleep ? e : -1, c.PreviousPosition, Q, b);
    colliderOf[e] = n;
    colliderStamp[e] = pass;
    if (!isBall && s.sensor[e] === 1) scratch.anySensor = true;
    if (!kept) poseCollider(world, s, n, e, b, t, isBall, asleep);
    // Friction 0 and restitution 0 for a shapeless ball: its pairs read its Material component instead.
    const mo = ColliderMaterial.STRIDE * n,
      mat = scratch.material;
    mat[mo + ColliderMaterial.FRICTION] = isBall ? 0 : s.friction[e]!;
    mat[mo + ColliderMaterial.RESTITUTION] = isBall ? 0 : s.restitution[e]!;
    mat[mo + ColliderMaterial.PERMISSIVE] = !isBall && s.group[e] === 0 && s.mask[e] === 0xffffffff && s.category[e] !== 0 ? 1 : 0;
    n++;
  }
  return n;
}

/**
 * Poses collider `n` (shape slot `e`, or ball body `b` when `isBall`) of body `b` of type `t`: its
 * start-of-step position and rotation, speed and box fattened by its speed over the step and half
 * this step's speculative distance (scratch.spec), into the scratch at index n; `asleep` notes the
 * pose a sleeping shape was posed from.
 */
function poseCollider(
  world: PhysicsWorld,
  s: Shape3DStore,
  n: number,
  e: number,
  b: number,
  t: number,
  isBall: boolean,
  asleep: boolean,
): void {
  const c = world.components,
    sc = scratch,
    h = world.h,
    invInertia = world.collision.invInertia,
    ox = c.PreviousPosition.x,
    oy = c.PreviousPosition.y,
    oz = c.PreviousPosition.z;
  // The kinematic comparison is made for every collider, not only behind a failed dynamic one: that
  // first ran for a sleeping collider, after V8 had compiled this code without it, and threw it away.
  const kinematic = t === BodyType.Kinematic,
    moving = t === BodyType.Dynamic || kinematic;
  const turning = (moving && invInertia[b]! > 0) || (kinematic && hasComponent(world, b, c.AngularVelocity));
  const x0 = t === BodyType.Static ? c.Position.x[b]! : ox[b]!,
    y0 = t === BodyType.Static ? c.Position.y[b]! : oy[b]!,
    z0 = t === BodyType.Static ? c.Position.z[b]! : oz[b]!;
  // The body's start position for the pair rows' anchors (a kept sleeping pose keeps its entry: its body
  // starts where it did).
  const mo = ColliderMaterial.STRIDE * n;
  sc.material[mo + ColliderMaterial.X] = x0;
  sc.material[mo + ColliderMaterial.Y] = y0;
  sc.material[mo + ColliderMaterial.Z] = z0;
  startOrientation(world, b, turning, isBall);
  const R = sc.R,
    o = MAT3_STRIDE * n;
  colliderRotation(s, e, isBall, R, o);
  let cx = x0,
    cy = y0,
    cz = z0,
    reach: number;
  if (isBall) reach = c.Ball.radius[b]!;
  else {
    cx += shapeShift[0]!;
    cy += shapeShift[1]!;
    cz += shapeShift[2]!;
    reach = s.reach[e]!;
  }
  let speed = 0;
  if (moving) {
    const V = c.Velocity,
      W = c.AngularVelocity;
    // (Math.sqrt of the sum of squares: Math.hypot is slower in V8, and these never overflow.)
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
  // (scratch.spec is read here rather than passed: a double argument to a call not inlined is boxed,
  // one allocation per collider.)
  const pad = speed * h + 0.5 * sc.spec;
  // Half widths of the box: a box's own (sum of h_k |R_ak|, tight), else the bounding sphere's.
  let wx = reach,
    wy = reach,
    wz = reach;
  let boxHalf = -1;
  if (!isBall && s.kind[e] === Shape3DKind.Box) {
    const ex = s.hx[e]!,
      ey = s.hy[e]!,
      ez = s.hz[e]!;
    // (Written out: Math.min of three arguments is a call.)
    if (s.sensor[e] !== 1) {
      boxHalf = ex < ey ? ex : ey;
      if (ez < boxHalf) boxHalf = ez;
    }
    wx = ex * Math.abs(R[o + M00]!) + ey * Math.abs(R[o + M01]!) + ez * Math.abs(R[o + M02]!);
    wy = ex * Math.abs(R[o + M10]!) + ey * Math.abs(R[o + M11]!) + ez * Math.abs(R[o + M12]!);
    wz = ex * Math.abs(R[o + M20]!) + ey * Math.abs(R[o + M21]!) + ez * Math.abs(R[o + M22]!);
  }
  sc.shape[n] = e;
  sc.body[n] = b;
  sc.ball[n] = isBall ? 1 : 0;
  sc.speed[n] = speed;
  sc.boxHalf[n] = boxHalf;
  sc.px[n] = cx;
  sc.py[n] = cy;
  sc.pz[n] = cz;
  sc.minX[n] = cx - wx - pad;
  sc.maxX[n] = cx + wx + pad;
  sc.minY[n] = cy - wy - pad;
  sc.maxY[n] = cy + wy + pad;
  sc.minZ[n] = cz - wz - pad;
  sc.maxZ[n] = cz + wz + pad;
  // A sleeping collider's pose is noted for the next pass (keptPose); another index holds none.
  notePose(n, asleep ? e : 0, sc.material, mo + ColliderMaterial.X, bodyQ);
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
