import { fieldsAt, Joint3DType, joints3DOf, type PhysicsWorld, query } from '@bitphysics/physics';

/**
 * The 3D debug layer's drawings of what is not a body: springs, joints, planes, field regions (fluid
 * regions, uniform electric and magnetic fields) and emitters, as line segments in metres. Each
 * `draw*` function writes through a `SegmentSink` (the layer's buffers) and returns how many entities
 * it drew. Positions are the interpolated ones the renderer placed the bodies at (`drawn`, xyz at
 * 3 eid) for shown bodies, else the current Position.
 *
 * Extension point: a new kind of entity gets a `draw*` function here with the same shape, a palette
 * index in `SceneryColor` (and its colour in `SCENERY_PALETTE`), and one line in `DebugLayer.draw`
 * (packages/render-three/src/debug.ts) behind its own option.
 */

/** Palette indices of the scenery colours in the debug layer (after its own seven). */
export const SceneryColor = Object.freeze({ Spring: 7, Joint: 8, Plane: 9, Fluid: 10, Electric: 11, Magnetic: 12, Emitter: 13 } as const);

/** Colours of the scenery, 0xRRGGBB, in `SceneryColor` order. */
export const SCENERY_PALETTE: readonly number[] = Object.freeze([0xc792ea, 0x4dd0e1, 0xffd166, 0x3a7bd5, 0xffb347, 0x82aaff, 0xff8a65]);

/** Where the scenery is written: the debug layer's segment and arrow appenders (metres, palette index). */
export interface SegmentSink {
  /** Appends the segment from a to b, m, in palette colour `color` (dropped when the buffer is full). */
  segment(ax: number, ay: number, az: number, bx: number, by: number, bz: number, color: number): void;
  /** Appends an arrow from (x, y, z) along (dx, dy, dz), m; @returns false if it was too short to draw (< 1 mm). */
  arrow(x: number, y: number, z: number, dx: number, dy: number, dz: number, color: number): boolean;
}

/** Where the renderer drew the bodies this frame. */
export interface DrawnPositions {
  /** Interpolated positions of shown bodies, m (xyz at 3 eid). */
  drawn: Float64Array;
  /** Interpolated orientations of shown bodies, unit quaternions (xyzw at 4 eid). */
  orientation: Float64Array;
  /** Whether entity `eid` is shown (so `drawn` holds its position). */
  shown(eid: number): boolean;
}

/** Coils of a drawn spring. */
const SPRING_COILS = 8;
const fields = { e: new Float64Array(3), b: new Float64Array(3) };
const p = new Float64Array(6);

/** Writes the drawn (or current) position of `e` into p[o..o+2]. */
function place(world: PhysicsWorld, at: DrawnPositions, e: number, o: number): void {
  if (at.shown(e)) {
    p[o] = at.drawn[3 * e]!;
    p[o + 1] = at.drawn[3 * e + 1]!;
    p[o + 2] = at.drawn[3 * e + 2]!;
  } else {
    const P = world.components.Position;
    p[o] = P.x[e]!;
    p[o + 1] = P.y[e]!;
    p[o + 2] = P.z[e]!;
  }
}

/**
 * Springs: a zigzag of SPRING_COILS coils from body `a` (or the fixed anchor when `a` is 0) to `b`,
 * as wide as a tenth of its length (at most 0.1 m). @returns springs drawn.
 */
export function drawSprings(world: PhysicsWorld, at: DrawnPositions, out: SegmentSink): number {
  const S = world.components.Spring;
  const springs = query(world, [S]);
  for (let i = 0; i < springs.length; i++) {
    const s = springs[i]!;
    const a = S.a[s]!;
    if (a > 0) place(world, at, a, 0);
    else {
      p[0] = S.anchorX[s]!;
      p[1] = S.anchorY[s]!;
      p[2] = S.anchorZ[s]!;
    }
    place(world, at, S.b[s]!, 3);
    const ax = p[0]!,
      ay = p[1]!,
      az = p[2]!,
      dx = p[3]! - ax,
      dy = p[4]! - ay,
      dz = p[5]! - az;
    const len = Math.sqrt(dx * dx + dy * dy + dz * dz);
    if (len < 1e-6) continue;
    const ux = dx / len,
      uy = dy / len,
      uz = dz / len;
    // A unit vector perpendicular to the spring: u x (an axis not along u).
    let wx: number, wy: number, wz: number;
    if (Math.abs(uy) < 0.9) {
      wx = -uz;
      wy = 0;
      wz = ux;
    } else {
      wx = 0;
      wy = uz;
      wz = -uy;
    }
    const wl = Math.min(0.1, 0.1 * len) / Math.sqrt(wx * wx + wy * wy + wz * wz);
    wx *= wl;
    wy *= wl;
    wz *= wl;
    let qx = ax,
      qy = ay,
      qz = az;
    const n = 2 * SPRING_COILS;
    for (let k = 0; k <= n + 1; k++) {
      const t = k === n + 1 ? len : (k / n) * len;
      const side = k === 0 || k === n + 1 ? 0 : k % 2 === 0 ? 1 : -1;
      const rx = ax + ux * t + wx * side,
        ry = ay + uy * t + wy * side,
        rz = az + uz * t + wz * side;
      if (k > 0) out.segment(qx, qy, qz, rx, ry, rz, SceneryColor.Spring);
      qx = rx;
      qy = ry;
      qz = rz;
    }
  }
  return springs.length;
}

/**
 * Joints (2D joint entities: anchors in the bodies' frames turn with their Angle about z): a line
 * between the two world anchors and each body's lever to its anchor. @returns joints drawn.
 */
export function drawJoints(world: PhysicsWorld, at: DrawnPositions, out: SegmentSink): number {
  const c = world.components;
  const J = c.Joint,
    angle = c.Angle.value;
  const joints = query(world, [J]);
  for (let i = 0; i < joints.length; i++) {
    const j = joints[i]!;
    const a = J.a[j]!,
      b = J.b[j]!;
    let ax = J.localAx[j]!,
      ay = J.localAy[j]!,
      az = 0;
    if (a > 0) {
      place(world, at, a, 0);
      const th = angle[a] ?? 0,
        cs = Math.cos(th),
        sn = Math.sin(th),
        lx = ax,
        ly = ay;
      ax = p[0]! + cs * lx - sn * ly;
      ay = p[1]! + sn * lx + cs * ly;
      az = p[2]!;
      out.segment(p[0]!, p[1]!, p[2]!, ax, ay, az, SceneryColor.Joint);
    }
    place(world, at, b, 3);
    const th = angle[b] ?? 0,
      cs = Math.cos(th),
      sn = Math.sin(th);
    const bx = p[3]! + cs * J.localBx[j]! - sn * J.localBy[j]!,
      by = p[4]! + sn * J.localBx[j]! + cs * J.localBy[j]!,
      bz = p[5]!;
    out.segment(p[3]!, p[4]!, p[5]!, bx, by, bz, SceneryColor.Joint);
    out.segment(ax, ay, az, bx, by, bz, SceneryColor.Joint);
  }
  return joints.length;
}

/** Length of the drawn stub of a hinge axis or cone axis, m. */
const AXIS_STUB = 0.3;
const q = new Float64Array(4);

/** Writes the drawn (or current) orientation of `e` into q (identity for the world, e = 0). */
function orient(world: PhysicsWorld, at: DrawnPositions, e: number): void {
  if (e !== 0 && at.shown(e)) {
    q[0] = at.orientation[4 * e]!;
    q[1] = at.orientation[4 * e + 1]!;
    q[2] = at.orientation[4 * e + 2]!;
    q[3] = at.orientation[4 * e + 3]!;
  } else if (e !== 0) {
    const O = world.components.Orientation;
    q[0] = O.x[e]!;
    q[1] = O.y[e]!;
    q[2] = O.z[e]!;
    q[3] = O.w[e]!;
  } else {
    q[0] = 0;
    q[1] = 0;
    q[2] = 0;
    q[3] = 1;
  }
}

/** Rotates (vx, vy, vz) by q into r[o..o+2] (v + 2 w (u x v) + 2 u x (u x v)). */
function turn(vx: number, vy: number, vz: number, r: Float64Array, o: number): void {
  const x = q[0]!,
    y = q[1]!,
    z = q[2]!,
    w = q[3]!;
  const tx = 2 * (y * vz - z * vy),
    ty = 2 * (z * vx - x * vz),
    tz = 2 * (x * vy - y * vx);
  r[o] = vx + w * tx + (y * tz - z * ty);
  r[o + 1] = vy + w * ty + (z * tx - x * tz);
  r[o + 2] = vz + w * tz + (x * ty - y * tx);
}

const arm = new Float64Array(6);

/**
 * 3D joints (physics' joints3d: anchors and axes kept in the bodies' frames about their centres of
 * mass, body A 0 the fixed world): each body's lever from its centre to its anchor, the line between
 * the two anchors (a rope or spring's length), and for hinges, sliders and coned ball joints a short
 * stub of B's axis at its anchor. @returns 3D joints drawn.
 */
export function drawJoints3D(world: PhysicsWorld, at: DrawnPositions, out: SegmentSink): number {
  const s = joints3DOf(world);
  if (s === undefined) return 0;
  const list = s.list;
  for (let i = 0; i < list.length; i++) {
    const j = list[i]!,
      a = s.a[j]!,
      b = s.b[j]!;
    if (a !== 0) {
      place(world, at, a, 0);
      orient(world, at, a);
      turn(s.ax[j]!, s.ay[j]!, s.az[j]!, arm, 0);
    } else {
      p[0] = 0;
      p[1] = 0;
      p[2] = 0;
      arm[0] = s.ax[j]!;
      arm[1] = s.ay[j]!;
      arm[2] = s.az[j]!;
    }
    const ax = p[0]! + arm[0]!,
      ay = p[1]! + arm[1]!,
      az = p[2]! + arm[2]!;
    if (a !== 0) out.segment(p[0]!, p[1]!, p[2]!, ax, ay, az, SceneryColor.Joint);
    place(world, at, b, 3);
    orient(world, at, b);
    turn(s.bx[j]!, s.by[j]!, s.bz[j]!, arm, 3);
    const bx = p[3]! + arm[3]!,
      by = p[4]! + arm[4]!,
      bz = p[5]! + arm[5]!;
    out.segment(p[3]!, p[4]!, p[5]!, bx, by, bz, SceneryColor.Joint);
    out.segment(ax, ay, az, bx, by, bz, SceneryColor.Joint);
    const type = s.type[j]!;
    if (type === Joint3DType.Hinge || type === Joint3DType.Slider || (type === Joint3DType.Ball && s.upper[j]! > 0)) {
      turn(s.ubx[j]!, s.uby[j]!, s.ubz[j]!, arm, 0);
      const h = 0.5 * AXIS_STUB;
      out.segment(
        bx - h * arm[0]!,
        by - h * arm[1]!,
        bz - h * arm[2]!,
        bx + h * arm[0]!,
        by + h * arm[1]!,
        bz + h * arm[2]!,
        SceneryColor.Joint,
      );
    }
  }
  return list.length;
}

/**
 * Planes (n . x = d; the renderer's environment draws their surfaces): the normal as a 1 m arrow from
 * the plane's point nearest the origin. @returns planes drawn.
 */
export function drawPlanes(world: PhysicsWorld, out: SegmentSink): number {
  const P = world.components.Plane;
  const planes = query(world, [P]);
  for (let i = 0; i < planes.length; i++) {
    const e = planes[i]!;
    const nx = P.nx[e]!,
      ny = P.ny[e]!,
      nz = P.nz[e]!,
      d = P.d[e]!;
    out.arrow(nx * d, ny * d, nz * d, nx, ny, nz, SceneryColor.Plane);
  }
  return planes.length;
}

/**
 * Field regions: each fluid region's surface (the rectangle y = surface over its x and z range, or
 * over `extent` where it is unlimited) with a cross on it; the uniform electric field E(t) and
 * magnetic field B(t) (sums over their entities at world.time) as arrows of `arrowLength` m on a
 * 3 x 3 x 3 lattice filling `extent`. @returns fluid regions plus field entities drawn.
 * @param extent the box to fill, m: [minX, minY, minZ, maxX, maxY, maxZ] (the boundary box, or a default).
 */
export function drawFields(world: PhysicsWorld, extent: ArrayLike<number>, arrowLength: number, out: SegmentSink): number {
  const c = world.components;
  const F = c.FluidRegion;
  const regions = query(world, [F]);
  for (let i = 0; i < regions.length; i++) {
    const e = regions[i]!;
    const x1 = Math.max(extent[0]!, F.minX[e]!),
      x2 = Math.min(extent[3]!, F.maxX[e]!);
    const z1 = Math.max(extent[2]!, F.minZ[e]!),
      z2 = Math.min(extent[5]!, F.maxZ[e]!);
    const y = F.surface[e]!,
      col = SceneryColor.Fluid;
    out.segment(x1, y, z1, x2, y, z1, col);
    out.segment(x2, y, z1, x2, y, z2, col);
    out.segment(x2, y, z2, x1, y, z2, col);
    out.segment(x1, y, z2, x1, y, z1, col);
    out.segment(x1, y, z1, x2, y, z2, col);
    out.segment(x1, y, z2, x2, y, z1, col);
  }
  const electric = query(world, [c.ElectricField]).length;
  const magnetic = query(world, [c.MagneticField]).length;
  if (electric + magnetic > 0) {
    fieldsAt(world, world.time, fields.e, fields.b);
    const E = fields.e,
      B = fields.b;
    const eLen = Math.hypot(E[0]!, E[1]!, E[2]!),
      bLen = Math.hypot(B[0]!, B[1]!, B[2]!);
    for (let i = 0; i < 3; i++)
      for (let j = 0; j < 3; j++)
        for (let k = 0; k < 3; k++) {
          const x = extent[0]! + ((i + 0.5) / 3) * (extent[3]! - extent[0]!);
          const y = extent[1]! + ((j + 0.5) / 3) * (extent[4]! - extent[1]!);
          const z = extent[2]! + ((k + 0.5) / 3) * (extent[5]! - extent[2]!);
          if (electric > 0 && eLen > 0) {
            const s = arrowLength / eLen;
            out.arrow(x, y, z, E[0]! * s, E[1]! * s, E[2]! * s, SceneryColor.Electric);
          }
          if (magnetic > 0 && bLen > 0) {
            const s = arrowLength / bLen;
            out.arrow(x + 0.25 * arrowLength, y, z, B[0]! * s, B[1]! * s, B[2]! * s, SceneryColor.Magnetic);
          }
        }
  }
  return regions.length + electric + magnetic;
}

/**
 * Emitters (Emitter and Position): a small three-axis cross (its `size`, at least 0.1 m) and its
 * direction as a 0.5 m arrow. @returns emitters drawn.
 */
export function drawEmitters(world: PhysicsWorld, at: DrawnPositions, out: SegmentSink): number {
  const c = world.components;
  const E = c.Emitter;
  const emitters = query(world, [E, c.Position]);
  for (let i = 0; i < emitters.length; i++) {
    const e = emitters[i]!;
    place(world, at, e, 0);
    const x = p[0]!,
      y = p[1]!,
      z = p[2]!,
      r = Math.max(0.1, E.size[e] ?? 0);
    const col = SceneryColor.Emitter;
    out.segment(x - r, y, z, x + r, y, z, col);
    out.segment(x, y - r, z, x, y + r, z, col);
    out.segment(x, y, z - r, x, y, z + r, col);
    const dx = E.dirX[e]!,
      dy = E.dirY[e]!,
      dz = E.dirZ[e]!;
    const dl = Math.hypot(dx, dy, dz);
    if (dl > 0) out.arrow(x, y, z, (dx / dl) * 0.5, (dy / dl) * 0.5, (dz / dl) * 0.5, col);
  }
  return emitters.length;
}
