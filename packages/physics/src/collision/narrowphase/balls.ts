import type { PhysicsWorld } from '../../world/options.js';
import { query } from '../../world/query.js';
import { BodyType, PairKind } from '../broadphase/grid.js';
import { type ContactBuffer, ContactKind, contactRowsEstimate, growContactBuffer } from '../contacts.js';
import { ballContactsStage } from './balls-threads.js';

function pushContact(buf: ContactBuffer, kind: number, a: number, b: number, feature: number): void {
  const i = buf.count;
  if (i >= buf.capacity) growContactBuffer(buf, i + 1);
  const r = rowArgs;
  buf.kind[i] = kind;
  buf.a[i] = a;
  buf.b[i] = b;
  buf.feature[i] = feature;
  buf.nx[i] = r[0]!;
  buf.ny[i] = r[1]!;
  buf.nz[i] = r[2]!;
  buf.separation[i] = r[3]!;
  buf.ra[i] = r[4]!;
  buf.rb[i] = r[5]!;
  buf.count = i + 1;
}

/**
 * Scratch of the narrowphase's calls: the doubles of a contact row for pushContact ([0..2] normal,
 * [3] separation m, [4] ra m, [5] rb m). The narrowphase's doubles reach its helpers through this,
 * `sphereArgs` and `segmentArgs`, not as arguments or returns: V8 boxes (allocates) each double
 * passed to or returned from a call it does not inline, and in a big narrowphase (a Galton board's
 * segments and pegs) it inlined neither the sweeps nor every pushContact (~0.4 MB a step). Not world state.
 */
const rowArgs = new Float64Array(6);

/** Scratch of sphereSweep: [0..2] r, [3..5] w, [6] R, [7] h, then [8] its result t. Not world state. */
const sphereArgs = new Float64Array(9);

/** Scratch of segmentSweep: [0..2] p, [3..5] e, [6..8] w, [9] R, [10] h, then [11] its result t. Not world state. */
const segmentArgs = new Float64Array(12);

/**
 * Sphere sweep on `sphereArgs` (no doubles cross the call): the earliest time t in (0, h] at which two
 * spheres with centre offset r (B minus A, slots 0-2, m) and relative velocity w (slots 3-5, m/s) come
 * to centre distance R (slot 6, m), h in slot 7 (s), i.e. the smaller root of |r + w t|^2 = R^2; 0 if
 * they already touch or overlap, or do not meet within h. t is written to slot 8. (Ericson, Real-Time
 * Collision Detection, 5.5.7.)
 */
function sphereSweep(): void {
  const io = sphereArgs;
  const rx = io[0]!,
    ry = io[1]!,
    rz = io[2]!,
    wx = io[3]!,
    wy = io[4]!,
    wz = io[5]!,
    R = io[6]!,
    h = io[7]!;
  io[8] = 0;
  const c = rx * rx + ry * ry + rz * rz - R * R;
  if (c <= 0) return;
  const b = rx * wx + ry * wy + rz * wz;
  if (b >= 0) return;
  const a = wx * wx + wy * wy + wz * wz;
  const disc = b * b - a * c;
  if (disc < 0) return;
  const t = (-b - Math.sqrt(disc)) / a;
  io[8] = t > 0 && t <= h ? t : 0;
}

/**
 * Segment sweep on `segmentArgs` (no doubles cross the call): the earliest time t in (0, h] at which a
 * sphere centre starting at p (slots 0-2, m, relative to the segment's first end point) and moving
 * with velocity w (slots 6-8, m/s) comes within R (slot 9, m) of the segment from 0 to e (slots 3-5,
 * m), h in slot 10 (s): against the segment's side (the infinite line, accepted if the touching point
 * lies between the end points) or against either end point (sphereSweep). 0 if it already touches or
 * does not reach the segment within h. t is written to slot 11.
 */
function segmentSweep(): void {
  const io = segmentArgs,
    sp = sphereArgs;
  const px = io[0]!,
    py = io[1]!,
    pz = io[2]!,
    ex = io[3]!,
    ey = io[4]!,
    ez = io[5]!,
    wx = io[6]!,
    wy = io[7]!,
    wz = io[8]!;
  sp[6] = io[9]!;
  sp[7] = io[10]!;
  const len2 = ex * ex + ey * ey + ez * ez;
  let best = 0;
  if (len2 > 0) {
    // Side: remove the components along the segment and sweep against the line.
    const pe = (px * ex + py * ey + pz * ez) / len2,
      we = (wx * ex + wy * ey + wz * ez) / len2;
    sp[0] = px - pe * ex;
    sp[1] = py - pe * ey;
    sp[2] = pz - pe * ez;
    sp[3] = wx - we * ex;
    sp[4] = wy - we * ey;
    sp[5] = wz - we * ez;
    sphereSweep();
    const t = sp[8]!;
    if (t > 0) {
      const u = pe + we * t;
      if (u >= 0 && u <= 1) {
        io[11] = t;
        return;
      }
    }
  }
  // End points: the first at p, the second at p - e.
  sp[3] = wx;
  sp[4] = wy;
  sp[5] = wz;
  for (let k = 0; k < 2; k++) {
    sp[0] = k === 0 ? px : px - ex;
    sp[1] = k === 0 ? py : py - ey;
    sp[2] = k === 0 ? pz : pz - ez;
    sphereSweep();
    const t = sp[8]!;
    if (t > 0 && (best === 0 || t < best)) best = t;
  }
  io[11] = best;
}

/**
 * Collide stage, part 2: turns candidate pairs into contacts, one point a pair, with normal and
 * separation measured where the bodies were at the start of the step. A contact is kept if the gap
 * could close this step: separation < max(0, -v_n) h + d, with v_n the normal relative velocity
 * after integration and d the speculative distance, at most a quarter of the pair's radii (half the
 * ball's against static geometry) so small balls do not collect distant neighbours (speculative
 * contact, Catto GDC 2013; the same test Box2D v3 applies).
 *
 * Shapes: ball-ball (circle-circle in 2D, sphere-sphere in 3D: centre distance minus radii);
 * ball-segment (distance to the closest point of the segment, so end points act as round corners;
 * Ericson, Real-Time Collision Detection, 5.1.2); ball-boundary (distance to each face of the box);
 * ball-plane (signed distance n . x - d minus the radius).
 *
 * The normal of a contact that will close during the step is taken where the bodies first touch
 * (a swept test along their relative velocity), not where they were at the start: an oblique
 * impact then bounces about the true line of centres (Box2D takes the start-of-step normal, which
 * bends the bounce by up to the angle the bodies turn through in one step).
 * @category Collision
 */
export function narrowphaseSystem(world: PhysicsWorld): void {
  const cs = world.collision;
  const buf = cs.contacts;
  buf.count = 0;
  // Once this step's pairs (ballContactsStage makes room for a row each) or twice the last step's rows
  // pass this buffer, grow it in one go to what the world's balls may need (a pile's contacts, reached
  // over the steps after the balls land) rather than by doubling step after step through the first
  // steps: each growth allocates every column. The buffer is empty here, so nothing is copied. Past
  // the estimate, ballContactsStage and pushContact double it as before.
  const need = Math.max(2 * cs.cache.rows.count, cs.pairCount);
  if (need > buf.capacity) {
    const balls = query(world, [world.components.Position, world.components.Ball]).length;
    const estimate = contactRowsEstimate(balls, world.dimensions);
    if (buf.capacity < estimate) growContactBuffer(buf, Math.max(need, estimate));
  }
  const pairA = cs.pairA,
    pairB = cs.pairB,
    pairKind = cs.pairKind;
  for (let i = 0, n = cs.pairCount; i < n; i++) {
    if (pairKind[i] === PairKind.BallBall) {
      // A run of ball-ball pairs: one range kernel, on the world's threads or here
      // (collision/narrowphase/balls-threads.ts: the same contacts in the same order).
      let j = i + 1;
      while (j < n && pairKind[j] === PairKind.BallBall) j++;
      ballContactsStage(world, cs, buf, i, j);
      i = j - 1;
    } else segmentContact(world, buf, pairA[i]!, pairB[i]!);
  }
  if (cs.boundary.enabled) boundaryContacts(world, buf);
  planeContacts(world, buf);
  cs.stats.contacts = buf.count;
}

/**
 * The contact of ball `b` with the static segment `s` (a capsule of the segment's radius), if the ball
 * comes within the speculative distance of it this step: the normal from where the ball's centre first
 * touches the segment (or where it starts), the gap from the start of the step.
 */
function segmentContact(world: PhysicsWorld, buf: ContactBuffer, s: number, b: number): void {
  const c = world.components;
  const h = world.h;
  const spec = world.collision.settings.speculativeDistance;
  const { x: ox, y: oy, z: oz } = c.PreviousPosition;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const radius = c.Ball.radius;
  const S = c.Segment;
  const W = rowArgs,
    GA = segmentArgs;
  const ax = S.ax[s]!,
    ay = S.ay[s]!,
    az = S.az[s]!;
  const ex = S.bx[s]! - ax,
    ey = S.by[s]! - ay,
    ez = S.bz[s]! - az;
  const wx = vx[b]!,
    wy = vy[b]!,
    wz = vz[b]!;
  const R = S.radius[s]! + radius[b]!;
  // Where the ball's centre is when it first touches the segment this step (or at the start).
  GA[0] = ox[b]! - ax;
  GA[1] = oy[b]! - ay;
  GA[2] = oz[b]! - az;
  GA[3] = ex;
  GA[4] = ey;
  GA[5] = ez;
  GA[6] = wx;
  GA[7] = wy;
  GA[8] = wz;
  GA[9] = R;
  GA[10] = h;
  segmentSweep();
  const t = GA[11]!;
  const px = ox[b]! + wx * t,
    py = oy[b]! + wy * t,
    pz = oz[b]! + wz * t;
  const len2 = ex * ex + ey * ey + ez * ez;
  let u = len2 > 0 ? ((px - ax) * ex + (py - ay) * ey + (pz - az) * ez) / len2 : 0;
  u = u < 0 ? 0 : u > 1 ? 1 : u;
  const qx = ax + u * ex,
    qy = ay + u * ey,
    qz = az + u * ez;
  let dx = px - qx,
    dy = py - qy,
    dz = pz - qz;
  const d = Math.sqrt(dx * dx + dy * dy + dz * dz);
  if (d > 1e-12) {
    const inv = 1 / d;
    dx *= inv;
    dy *= inv;
    dz *= inv;
  } else {
    // Centre exactly on the segment: push out along the segment's left normal (2D) or +y.
    const el = Math.sqrt(len2);
    if (el > 0 && world.dimensions === 2) {
      dx = -ey / el;
      dy = ex / el;
      dz = 0;
    } else {
      dx = 0;
      dy = 1;
      dz = 0;
    }
  }
  // Gap along that normal from the same feature point, where the ball was at the start of the step.
  const sep = (ox[b]! - qx) * dx + (oy[b]! - qy) * dy + (oz[b]! - qz) * dz - R;
  const vn = wx * dx + wy * dy + wz * dz;
  const rb = radius[b]!;
  if (sep >= (vn < 0 ? -vn * h : 0) + (spec < 0.5 * rb ? spec : 0.5 * rb)) return;
  W[0] = dx;
  W[1] = dy;
  W[2] = dz;
  W[3] = sep;
  W[4] = 0;
  W[5] = radius[b]!;
  pushContact(buf, ContactKind.Segment, 0, b, s);
}

/** Contacts of the moving balls with the faces of the boundary box near which they come this step (2D: four faces, 3D: six). */
function boundaryContacts(world: PhysicsWorld, buf: ContactBuffer): void {
  const c = world.components;
  const cs = world.collision;
  const h = world.h;
  const spec0 = cs.settings.speculativeDistance;
  const { x: ox, y: oy, z: oz } = c.PreviousPosition;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const radius = c.Ball.radius;
  const type = cs.bodyType;
  // A 2D world's z stores hold 0 (bodies/api.ts writes them so; nothing integrates them): not read.
  const is3D = world.dimensions === 3;
  const W = rowArgs;
  const box = cs.boundary;
  const balls = query(world, [c.Position, c.Ball]);
  const minX = box.min[0]!,
    minY = box.min[1]!,
    minZ = box.min[2]!;
  const maxX = box.max[0]!,
    maxY = box.max[1]!,
    maxZ = box.max[2]!;
  for (let i = 0; i < balls.length; i++) {
    const b = balls[i]!;
    if (type[b] >= BodyType.Static) continue;
    const r = radius[b]!;
    const spec = spec0 < 0.5 * r ? spec0 : 0.5 * r;
    // Faces 0 to 3 (5 in 3D): the min and max face of x, y (and z), in that order. The row's radius
    // goes through rowArgs, not as an argument (see rowArgs).
    W[5] = r;
    axisFaces(buf, b, 0, ox[b]! - r - minX, maxX - ox[b]! - r, vx[b]! * h, spec);
    axisFaces(buf, b, 2, oy[b]! - r - minY, maxY - oy[b]! - r, vy[b]! * h, spec);
    if (is3D) axisFaces(buf, b, 4, oz[b]! - r - minZ, maxZ - oz[b]! - r, vz[b]! * h, spec);
  }
}

/**
 * The contacts of ball `b` with the min face `face` and the max face `face + 1` of one axis of the
 * boundary box, if it comes within `spec` (m) of either this step: `sepMin` and `sepMax` its
 * separations from them at the start of the step (m), `move` its displacement along the axis this
 * step (m). Its radius is already in rowArgs[5].
 */
function axisFaces(buf: ContactBuffer, b: number, face: number, sepMin: number, sepMax: number, move: number, spec: number): void {
  if (sepMin < (move < 0 ? -move : 0) + spec) {
    rowArgs[3] = sepMin;
    faceContact(buf, b, face);
  }
  if (sepMax < (move > 0 ? move : 0) + spec) {
    rowArgs[3] = sepMax;
    faceContact(buf, b, face + 1);
  }
}

/**
 * Pushes the contact of a ball `b` with face `face` of the boundary box (2k: the min face of axis k,
 * normal +axis; 2k + 1: the max face, normal -axis); its separation and radius (m) already in
 * rowArgs[3] and rowArgs[5].
 */
function faceContact(buf: ContactBuffer, b: number, face: number): void {
  const W = rowArgs;
  W[0] = 0;
  W[1] = 0;
  W[2] = 0;
  W[face >> 1] = (face & 1) === 0 ? 1 : -1;
  W[4] = 0;
  pushContact(buf, ContactKind.Boundary, 0, b, face);
}

/** Contacts of the moving balls with the static planes (half-spaces) they come near this step. */
function planeContacts(world: PhysicsWorld, buf: ContactBuffer): void {
  const c = world.components;
  const cs = world.collision;
  const planes = query(world, [c.Plane]);
  if (planes.length === 0) return;
  const h = world.h;
  const spec = cs.settings.speculativeDistance;
  const { x: ox, y: oy, z: oz } = c.PreviousPosition;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const radius = c.Ball.radius;
  const type = cs.bodyType;
  const W = rowArgs;
  const balls = query(world, [c.Position, c.Ball]);
  const Pl = c.Plane;
  for (let j = 0; j < planes.length; j++) {
    const p = planes[j]!;
    const nx = Pl.nx[p]!,
      ny = Pl.ny[p]!,
      nz = Pl.nz[p]!,
      d = Pl.d[p]!;
    for (let i = 0; i < balls.length; i++) {
      const b = balls[i]!;
      if (type[b] >= BodyType.Static) continue;
      const r = radius[b]!;
      const sep = ox[b]! * nx + oy[b]! * ny + oz[b]! * nz - d - r;
      const vn = vx[b]! * nx + vy[b]! * ny + vz[b]! * nz;
      if (sep < (vn < 0 ? -vn * h : 0) + (spec < 0.5 * r ? spec : 0.5 * r)) {
        W[0] = nx;
        W[1] = ny;
        W[2] = nz;
        W[3] = sep;
        W[4] = 0;
        W[5] = r;
        pushContact(buf, ContactKind.Plane, 0, b, p);
      }
    }
  }
}

/**
 * Separation now (m, negative when overlapping) of row `i` of a contact buffer, measured at the bodies'
 * current positions along the current line of centres (or to the segment's closest point, or the
 * boundary face).
 * @category Collision
 */
export function currentSeparation(world: PhysicsWorld, buf: ContactBuffer, i: number): number {
  const c = world.components;
  const { x: px, y: py, z: pz } = c.Position;
  const radius = c.Ball.radius;
  const kind = buf.kind[i]!,
    b = buf.b[i]!,
    f = buf.feature[i]!;
  if (kind === ContactKind.Ball || kind === ContactKind.StaticBall) {
    const a = kind === ContactKind.Ball ? buf.a[i]! : f;
    const dx = px[b]! - px[a]!,
      dy = py[b]! - py[a]!,
      dz = pz[b]! - pz[a]!;
    return Math.sqrt(dx * dx + dy * dy + dz * dz) - radius[a]! - radius[b]!;
  }
  if (kind === ContactKind.Boundary) {
    const box = world.collision.boundary;
    const r = radius[b]!;
    switch (f) {
      case 0:
        return px[b]! - r - box.min[0]!;
      case 1:
        return box.max[0]! - px[b]! - r;
      case 2:
        return py[b]! - r - box.min[1]!;
      case 3:
        return box.max[1]! - py[b]! - r;
      case 4:
        return pz[b]! - r - box.min[2]!;
      default:
        return box.max[2]! - pz[b]! - r;
    }
  }
  if (kind === ContactKind.Plane) {
    const Pl = c.Plane;
    return px[b]! * Pl.nx[f]! + py[b]! * Pl.ny[f]! + pz[b]! * Pl.nz[f]! - Pl.d[f]! - radius[b]!;
  }
  const S = c.Segment;
  const ax = S.ax[f]!,
    ay = S.ay[f]!,
    az = S.az[f]!;
  const ex = S.bx[f]! - ax,
    ey = S.by[f]! - ay,
    ez = S.bz[f]! - az;
  const len2 = ex * ex + ey * ey + ez * ez;
  const qx = px[b]!,
    qy = py[b]!,
    qz = pz[b]!;
  let t = len2 > 0 ? ((qx - ax) * ex + (qy - ay) * ey + (qz - az) * ez) / len2 : 0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  const dx = qx - (ax + t * ex),
    dy = qy - (ay + t * ey),
    dz = qz - (az + t * ez);
  return Math.sqrt(dx * dx + dy * dy + dz * dz) - S.radius[f]! - radius[b]!;
}
