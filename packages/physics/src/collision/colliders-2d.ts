import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { SHAPE_STRIDE, type ShapeStore } from '../world/shape-store-2d.js';
import { ANGLE, classifyBody, hasBit, lookUpBodyBits, SHAPE, SPIN } from './body-class.js';
import { BALL, MOVING, type ShapeCollisionState, type ShapeScratch } from './manifolds-2d.js';
import { BodyType } from './state.js';

/**
 * The colliders of a 2D shape pass (collision/shapes-2d.ts): each shape entity, and each ball body as
 * its own circle, with its body classified for the step (static, kinematic, sleeping or dynamic; its
 * inverse mass and inertia, angular velocity and start-of-step angle), its start-of-step transform, its
 * fattened bounding box and speculative distance (the broadphase's input, collision/broadphase/pairs-2d.ts),
 * and the shape whose geometry it shares (the narrowphase's copies).
 */

function ensureScratch(sc: ShapeScratch, n: number): void {
  if (sc.shape.length >= n) return;
  let m = Math.max(64, sc.shape.length);
  while (m < n) m *= 2;
  const f = (): Float64Array => new Float64Array(m);
  const i = (): Int32Array => new Int32Array(m);
  sc.shape = i();
  sc.body = i();
  sc.x = f();
  sc.y = f();
  sc.c = f();
  sc.s = f();
  sc.minX = f();
  sc.minY = f();
  sc.maxX = f();
  sc.maxY = f();
  sc.spec = f();
  sc.size = f();
  sc.flags = new Uint8Array(m);
  sc.cellX = i();
  sc.cellY = i();
  sc.bucket = i();
  sc.sorted = i();
  sc.oversized = i();
}

/**
 * Per collider of this step (gatherColliders fills it, collidePairs reads it): the shape entity whose
 * geometry it has, the first of a run of colliders with identical geometry (a pyramid's boxes share
 * one), or -1 for a ball body. The pair loop copies a geometry out of the shape store only when it
 * differs from the one it holds: the store's vertex, normal, count and radius arrays are read at random
 * once a pair otherwise, each a cache miss in a large pile.
 */
let geometryOf = new Int32Array(0);

/** This step's `geometryOf` (valid once gatherColliders ran). */
export function sharedGeometries(): Int32Array {
  return geometryOf;
}

/** `geometryOf` with room for `n` colliders (grown only in a world's first steps, outside the loops). */
function roomForGeometry(n: number): Int32Array {
  if (geometryOf.length < n) geometryOf = new Int32Array(Math.max(n, 2 * geometryOf.length));
  return geometryOf;
}

/**
 * Whether shapes a and b of store S have the same geometry, number for number (kind, vertex count,
 * radius, vertices and normals; -0 and 0 told apart), so that one's copy collides as the other would.
 */
function sameGeometry(S: ShapeStore, a: number, b: number): boolean {
  const n = S.count[a]!;
  if (n !== S.count[b] || S.kind[a] !== S.kind[b] || !same(S.radius[a]!, S.radius[b]!)) return false;
  const oa = SHAPE_STRIDE * a,
    ob = SHAPE_STRIDE * b;
  for (let k = 0; k < n; k++) {
    if (!same(S.vx[oa + k]!, S.vx[ob + k]!) || !same(S.vy[oa + k]!, S.vy[ob + k]!)) return false;
    if (!same(S.nx[oa + k]!, S.nx[ob + k]!) || !same(S.ny[oa + k]!, S.ny[ob + k]!)) return false;
  }
  return true;
}

/** x and y are the same number (Object.is without NaN: a NaN geometry is never shared). */
function same(x: number, y: number): boolean {
  return x === y && (x !== 0 || 1 / x === 1 / y);
}

/**
 * Body type, inverse mass and inertia, angular velocity and start-of-step angle of shape body `b` for
 * this step (CollisionState.bodyType, invMass, invInertia; ShapeCollisionState.bodyW, bodyAngle0).
 */
function classifyShapeBody(world: PhysicsWorld, st: ShapeCollisionState, b: number): void {
  const c = world.components;
  const t = classifyBody(world, b);
  // Static bodies are never integrated: where they are is where they were.
  if (t === BodyType.Static) {
    c.PreviousPosition.x[b] = c.Position.x[b]!;
    c.PreviousPosition.y[b] = c.Position.y[b]!;
  }
  const turns = (t === BodyType.Dynamic || t === BodyType.Kinematic) && hasBit(SPIN, b);
  st.bodyW[b] = turns ? c.AngularVelocity.z[b]! : 0;
  st.bodyAngle0[b] = (hasBit(ANGLE, b) ? c.Angle.value[b]! : 0) - st.bodyW[b]! * world.h;
}

/**
 * Lists this step's colliders (shape entities, and ball bodies as circles), fills the per-body solver
 * scratch of shape bodies (body type, inverse mass and inertia) and each collider's start-of-step
 * transform and fattened box.
 * @category Collision
 */
export function gatherColliders(world: PhysicsWorld, st: ShapeCollisionState): void {
  // Here, not in classifyColliders: code V8 compiled of that loop with this call inlined was thrown
  // away a few steps in, the call's own small functions having no type feedback yet.
  lookUpBodyBits(world);
  const shapeCount = classifyColliders(world, st);
  // With no collider moving no pair is searched (findPairs) and nothing reads the poses and boxes (the
  // static contacts and the sweeps are of dynamic bodies): a scene asleep skips them.
  if (st.anyMoving) boundColliders(world, st, shapeCount);
}

/**
 * gatherColliders, first: lists the colliders (sc.count, shape, body), classifies their bodies, sets
 * their flags and `anyMoving`. Returns how many of them are shape entities (the ball bodies follow).
 * Reads the body bits gatherColliders looked up (lookUpBodyBits) just before.
 */
function classifyColliders(world: PhysicsWorld, st: ShapeCollisionState): number {
  const c = world.components,
    cs = world.collision,
    sc = st.scratch;
  const shapes = query(world, [c.Shape]);
  const balls = query(world, [c.Position, c.Ball]);
  const n = shapes.length + balls.length;
  ensureScratch(sc, n);
  sc.count = n;
  const type = cs.bodyType,
    BODY = c.Shape.body,
    wz = c.AngularVelocity.z;
  const mark = ++st.bodyMark;
  st.anyMoving = false;
  const bodyMarks = st.bodyMarks;
  for (let i = 0; i < n; i++) {
    const isBall = i >= shapes.length;
    const e = isBall ? balls[i - shapes.length]! : shapes[i]!;
    const b = isBall ? e : BODY[e]!;
    sc.shape[i] = e;
    sc.body[i] = b;
    if (!isBall && bodyMarks[b] !== mark) {
      // Shape bodies: classify once a step (balls were classified by the ball broadphase).
      bodyMarks[b] = mark;
      classifyShapeBody(world, st, b);
    } else if (isBall) {
      st.bodyW[b] = type[b] === BodyType.Dynamic && hasBit(SPIN, b) ? wz[b]! : 0;
      st.bodyAngle0[b] = 0;
    }
    const t = type[b]!;
    const moving = t === BodyType.Dynamic || t === BodyType.Kinematic;
    sc.flags[i] = (moving ? MOVING : 0) | (isBall && !hasBit(SHAPE, b) ? BALL : 0);
    if (moving) st.anyMoving = true;
  }
  return shapes.length;
}

/**
 * gatherColliders, then: each collider's start-of-step transform, the shape whose geometry it shares
 * (`geometryOf`), its speculative distance and size, and its fattened box. Colliders from
 * `shapeCount` on are ball bodies. Everything outside the loop is read or computed here and the loop
 * is `boundRange`, whose body reads nothing before it: a function called once a step runs its first
 * call's first lines before V8 gives it type feedback, and code compiled while that call's loop ran
 * lacked feedback for them and was thrown away at the next step's call.
 */
function boundColliders(world: PhysicsWorld, st: ShapeCollisionState, shapeCount: number): void {
  const c = world.components,
    sc = st.scratch,
    n = sc.count,
    spec0 = world.collision.settings.speculativeDistance;
  const geometry = roomForGeometry(n);
  boundRange(
    st,
    sc,
    n,
    shapeCount,
    geometry,
    c.Shape,
    c.Shape.vx,
    c.Shape.vy,
    c.Shape.radius,
    c.Shape.count,
    c.Ball,
    c.PreviousPosition.x,
    c.PreviousPosition.y,
    c.Velocity.x,
    c.Velocity.y,
    world.h,
    spec0,
    0.5 * spec0,
  );
}

/** boundColliders' loop over its `n` colliders (see there), on the arrays and values it passes. */
function boundRange(
  st: ShapeCollisionState,
  sc: ShapeCollisionState['scratch'],
  n: number,
  shapeCount: number,
  geometry: Int32Array,
  S: PhysicsWorld['components']['Shape'],
  SX: PhysicsWorld['components']['Shape']['vx'],
  SY: PhysicsWorld['components']['Shape']['vy'],
  R: PhysicsWorld['components']['Shape']['radius'],
  CNT: PhysicsWorld['components']['Shape']['count'],
  ball: PhysicsWorld['components']['Ball'],
  ox: Float64Array,
  oy: Float64Array,
  vx: Float64Array,
  vy: Float64Array,
  h: number,
  spec0: number,
  halfSpec: number,
): void {
  let shared = -1; // the shape whose geometry the last run of colliders has
  for (let i = 0; i < n; i++) {
    const isBall = i >= shapeCount;
    const e = sc.shape[i]!,
      b = sc.body[i]!;
    const moving = (sc.flags[i]! & MOVING) !== 0;
    const x = ox[b]!,
      y = oy[b]!,
      a0 = st.bodyAngle0[b]!;
    const co = Math.cos(a0),
      si = Math.sin(a0);
    sc.x[i] = x;
    sc.y[i] = y;
    sc.c[i] = co;
    sc.s[i] = si;
    let x0 = Infinity,
      y0 = Infinity,
      x1 = -Infinity,
      y1 = -Infinity,
      reach = 0,
      r: number;
    if (isBall) {
      geometry[i] = -1;
      r = ball.radius[b]!;
      x0 = x;
      x1 = x;
      y0 = y;
      y1 = y;
    } else {
      if (shared < 0 || !sameGeometry(S, e, shared)) shared = e;
      geometry[i] = shared;
      r = R[e]!;
      const o = SHAPE_STRIDE * e;
      for (let k = 0, m = CNT[e]!; k < m; k++) {
        const lx = SX[o + k]!,
          ly = SY[o + k]!;
        const wx = x + co * lx - si * ly,
          wy = y + si * lx + co * ly;
        if (wx < x0) x0 = wx;
        if (wx > x1) x1 = wx;
        if (wy < y0) y0 = wy;
        if (wy > y1) y1 = wy;
        const d2 = lx * lx + ly * ly;
        if (d2 > reach) reach = d2;
      }
    }
    reach = Math.sqrt(reach) + r;
    const size = 0.5 * Math.min(x1 - x0, y1 - y0) + r;
    const spec = spec0 < SPECULATIVE_FRACTION * size ? spec0 : SPECULATIVE_FRACTION * size;
    sc.spec[i] = spec;
    sc.size[i] = size;
    let pad = r + (spec < halfSpec ? spec : halfSpec);
    if (moving) {
      const sx = vx[b]!,
        sy = vy[b]!;
      pad += Math.sqrt(sx * sx + sy * sy) * h + Math.abs(st.bodyW[b]!) * h * reach;
    }
    sc.minX[i] = x0 - pad;
    sc.minY[i] = y0 - pad;
    sc.maxX[i] = x1 + pad;
    sc.maxY[i] = y1 + pad;
  }
}

/**
 * Speculative distance of a shape as a fraction of its size (half its smaller extent), at most the
 * world's `speculativeDistance`: 0.02 m for a 1 m box, Box2D's 4 linear slops, so neighbours standing
 * 5 cm apart in a row do not become contacts; smaller shapes get proportionally less.
 */
const SPECULATIVE_FRACTION = 0.04;
