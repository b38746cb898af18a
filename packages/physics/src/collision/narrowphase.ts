import { query } from 'bitecs';
import type { PhysicsWorld } from '../world';
import { ContactKind, growContactBuffer, type ContactBuffer } from './contacts';
import { BodyType, PairKind } from './broadphase';

function pushContact(
  buf: ContactBuffer, kind: number, a: number, b: number, feature: number,
  nx: number, ny: number, nz: number, separation: number, ra: number, rb: number,
): void {
  const i = buf.count;
  if (i >= buf.capacity) growContactBuffer(buf, i + 1);
  buf.kind[i] = kind;
  buf.a[i] = a;
  buf.b[i] = b;
  buf.feature[i] = feature;
  buf.nx[i] = nx; buf.ny[i] = ny; buf.nz[i] = nz;
  buf.separation[i] = separation;
  buf.ra[i] = ra;
  buf.rb[i] = rb;
  buf.count = i + 1;
}

/**
 * Collide stage, part 2: turns candidate pairs into contacts, one point a pair, with normal and
 * separation measured where the bodies were at the start of the step. A contact is kept if the gap
 * could close this step: separation < max(0, -v_n) h + d_spec, with v_n the normal relative velocity
 * after integration (speculative contact, Catto GDC 2013; the same test Box2D v3 applies).
 *
 * Shapes: ball-ball (circle-circle in 2D, sphere-sphere in 3D: centre distance minus radii);
 * ball-segment (distance to the closest point of the segment, so end points act as round corners;
 * Ericson, Real-Time Collision Detection, 5.1.2); ball-boundary (distance to each face of the box).
 */
export function narrowphaseSystem(world: PhysicsWorld): void {
  const c = world.components;
  const cs = world.collision;
  const buf = cs.contacts;
  buf.count = 0;
  const h = world.h;
  const spec = cs.settings.speculativeDistance;
  const ox = c.PreviousPosition.x, oy = c.PreviousPosition.y, oz = c.PreviousPosition.z;
  const vx = c.Velocity.x, vy = c.Velocity.y, vz = c.Velocity.z;
  const radius = c.Ball.radius;
  const type = cs.bodyType;

  const pairA = cs.pairA, pairB = cs.pairB, pairKind = cs.pairKind;
  const S = c.Segment;
  for (let i = 0, n = cs.pairCount; i < n; i++) {
    const kind = pairKind[i]!;
    const b = pairB[i]!;
    if (kind === PairKind.BallBall) {
      const a = pairA[i]!;
      let dx = ox[b]! - ox[a]!, dy = oy[b]! - oy[a]!, dz = oz[b]! - oz[a]!;
      const d2 = dx * dx + dy * dy + dz * dz;
      let d = Math.sqrt(d2);
      if (d > 1e-12) { const inv = 1 / d; dx *= inv; dy *= inv; dz *= inv; } else { dx = 0; dy = 1; dz = 0; d = 0; }
      const ra = radius[a]!, rb = radius[b]!;
      const sep = d - ra - rb;
      const ta = type[a]!, tb = type[b]!;
      // Velocity of a static body is 0 by definition (its store is not read).
      const vax = ta === BodyType.Static ? 0 : vx[a]!, vay = ta === BodyType.Static ? 0 : vy[a]!, vaz = ta === BodyType.Static ? 0 : vz[a]!;
      const vbx = tb === BodyType.Static ? 0 : vx[b]!, vby = tb === BodyType.Static ? 0 : vy[b]!, vbz = tb === BodyType.Static ? 0 : vz[b]!;
      const vn = (vbx - vax) * dx + (vby - vay) * dy + (vbz - vaz) * dz;
      if (sep >= (vn < 0 ? -vn * h : 0) + spec) continue;
      if (ta === BodyType.Static) {
        pushContact(buf, ContactKind.StaticBall, 0, b, a, dx, dy, dz, sep, 0, rb);
      } else if (tb === BodyType.Static) {
        pushContact(buf, ContactKind.StaticBall, 0, a, b, -dx, -dy, -dz, sep, 0, ra);
      } else {
        pushContact(buf, ContactKind.Ball, a, b, 0, dx, dy, dz, sep, ra, rb);
      }
    } else {
      const s = pairA[i]!;
      const ax = S.ax[s]!, ay = S.ay[s]!, az = S.az[s]!;
      const ex = S.bx[s]! - ax, ey = S.by[s]! - ay, ez = S.bz[s]! - az;
      const px = ox[b]!, py = oy[b]!, pz = oz[b]!;
      const len2 = ex * ex + ey * ey + ez * ez;
      let t = len2 > 0 ? ((px - ax) * ex + (py - ay) * ey + (pz - az) * ez) / len2 : 0;
      t = t < 0 ? 0 : t > 1 ? 1 : t;
      let dx = px - (ax + t * ex), dy = py - (ay + t * ey), dz = pz - (az + t * ez);
      let d = Math.sqrt(dx * dx + dy * dy + dz * dz);
      if (d > 1e-12) {
        const inv = 1 / d; dx *= inv; dy *= inv; dz *= inv;
      } else {
        // Centre exactly on the segment: push out along the segment's left normal (2D) or +y.
        const el = Math.sqrt(len2);
        if (el > 0 && world.dimensions === 2) { dx = -ey / el; dy = ex / el; dz = 0; } else { dx = 0; dy = 1; dz = 0; }
        d = 0;
      }
      const rb = radius[b]!;
      const sep = d - S.radius[s]! - rb;
      const vn = vx[b]! * dx + vy[b]! * dy + vz[b]! * dz;
      if (sep >= (vn < 0 ? -vn * h : 0) + spec) continue;
      pushContact(buf, ContactKind.Segment, 0, b, s, dx, dy, dz, sep, 0, rb);
    }
  }

  const box = cs.boundary;
  if (box.enabled) {
    const balls = query(world, [c.Position, c.Ball]);
    const minX = box.min[0]!, minY = box.min[1]!, minZ = box.min[2]!;
    const maxX = box.max[0]!, maxY = box.max[1]!, maxZ = box.max[2]!;
    const is3D = world.dimensions === 3;
    for (let i = 0; i < balls.length; i++) {
      const b = balls[i]!;
      if (type[b] === BodyType.Static) continue;
      const r = radius[b]!;
      const x = ox[b]!, y = oy[b]!;
      const sx = vx[b]!, sy = vy[b]!;
      let sep = x - r - minX;
      if (sep < (sx < 0 ? -sx * h : 0) + spec) pushContact(buf, ContactKind.Boundary, 0, b, 0, 1, 0, 0, sep, 0, r);
      sep = maxX - x - r;
      if (sep < (sx > 0 ? sx * h : 0) + spec) pushContact(buf, ContactKind.Boundary, 0, b, 1, -1, 0, 0, sep, 0, r);
      sep = y - r - minY;
      if (sep < (sy < 0 ? -sy * h : 0) + spec) pushContact(buf, ContactKind.Boundary, 0, b, 2, 0, 1, 0, sep, 0, r);
      sep = maxY - y - r;
      if (sep < (sy > 0 ? sy * h : 0) + spec) pushContact(buf, ContactKind.Boundary, 0, b, 3, 0, -1, 0, sep, 0, r);
      if (is3D) {
        const z = oz[b]!, sz = vz[b]!;
        sep = z - r - minZ;
        if (sep < (sz < 0 ? -sz * h : 0) + spec) pushContact(buf, ContactKind.Boundary, 0, b, 4, 0, 0, 1, sep, 0, r);
        sep = maxZ - z - r;
        if (sep < (sz > 0 ? sz * h : 0) + spec) pushContact(buf, ContactKind.Boundary, 0, b, 5, 0, 0, -1, sep, 0, r);
      }
    }
  }
  cs.stats.contacts = buf.count;
}

/**
 * Separation now (m, negative when overlapping) of row `i` of a contact buffer, measured at the bodies'
 * current positions along the current line of centres (or to the segment's closest point, or the
 * boundary face).
 */
export function currentSeparation(world: PhysicsWorld, buf: ContactBuffer, i: number): number {
  const c = world.components;
  const px = c.Position.x, py = c.Position.y, pz = c.Position.z;
  const radius = c.Ball.radius;
  const kind = buf.kind[i]!, b = buf.b[i]!, f = buf.feature[i]!;
  if (kind === ContactKind.Ball || kind === ContactKind.StaticBall) {
    const a = kind === ContactKind.Ball ? buf.a[i]! : f;
    const dx = px[b]! - px[a]!, dy = py[b]! - py[a]!, dz = pz[b]! - pz[a]!;
    return Math.sqrt(dx * dx + dy * dy + dz * dz) - radius[a]! - radius[b]!;
  }
  if (kind === ContactKind.Boundary) {
    const box = world.collision.boundary;
    const r = radius[b]!;
    switch (f) {
      case 0: return px[b]! - r - box.min[0]!;
      case 1: return box.max[0]! - px[b]! - r;
      case 2: return py[b]! - r - box.min[1]!;
      case 3: return box.max[1]! - py[b]! - r;
      case 4: return pz[b]! - r - box.min[2]!;
      default: return box.max[2]! - pz[b]! - r;
    }
  }
  const S = c.Segment;
  const ax = S.ax[f]!, ay = S.ay[f]!, az = S.az[f]!;
  const ex = S.bx[f]! - ax, ey = S.by[f]! - ay, ez = S.bz[f]! - az;
  const len2 = ex * ex + ey * ey + ez * ez;
  const qx = px[b]!, qy = py[b]!, qz = pz[b]!;
  let t = len2 > 0 ? ((qx - ax) * ex + (qy - ay) * ey + (qz - az) * ez) / len2 : 0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  const dx = qx - (ax + t * ex), dy = qy - (ay + t * ey), dz = qz - (az + t * ez);
  return Math.sqrt(dx * dx + dy * dy + dz * dz) - S.radius[f]! - radius[b]!;
}
