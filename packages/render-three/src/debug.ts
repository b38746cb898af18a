import { type ContactView, forEachContact, type PhysicsWorld } from '@bitphysics/physics';
import { type OptionRules, resolveOptions } from '@bitphysics/render-common';
import { BufferAttribute, BufferGeometry, DynamicDrawUsage, Group, LineBasicMaterial, LineSegments, Points, PointsMaterial } from 'three';
import type { InstanceBook } from './book.js';
import {
  drawEmitters,
  drawFields,
  drawJoints,
  drawJoints3D,
  drawPlanes,
  drawSprings,
  SCENERY_PALETTE,
  type SegmentSink,
} from './debug-scenery.js';
import { hexToLinear, rotateInto } from './math.js';

/** Options of the debug layer (`WorldRenderer3DOptions.debug`, `WorldRenderer3D.setDebug`). Unknown fields are rejected. */
export interface DebugOptions {
  /** Draw each body's axes (body x red, y green, z blue), 1.5 times its size long. Default true. */
  axes?: boolean;
  /** Draw each body's velocity as an arrow from its centre. Default true. */
  velocities?: boolean;
  /** Arrow length per unit speed, s (an arrow is |v| velocityScale metres long), > 0. Default 0.1 s. */
  velocityScale?: number;
  /** Draw each body's angular velocity as an arrow (magenta). Default false. */
  angularVelocities?: boolean;
  /** Arrow length per unit angular speed, m s/rad, > 0. Default 0.1. */
  angularVelocityScale?: number;
  /** Most bodies given axes and arrows (the first shown), integer in [0, 100_000]. Default 2000. */
  maxBodies?: number;
  /**
   * Draw the last step's contacts (`forEachContact`: balls, and 3D shapes up to four points a manifold): a dot at each contact point and its normal (from body A to body B).
   * Contacts that carried impulse are red, speculative ones (no impulse) grey. Default true.
   */
  contacts?: boolean;
  /** Length of a drawn contact normal, m, > 0. Default 0.25 m. */
  normalLength?: number;
  /** Most contacts drawn, integer in [0, 1_000_000]. Default 4000. */
  maxContacts?: number;
  /** Size of a contact dot, CSS px, > 0. Default 5. */
  pointSize?: number;
  /** Draw springs as zigzags between their bodies (or anchor). Default true. */
  springs?: boolean;
  /** Draw joints (2D and 3D): the line between their anchors, each body's lever to its anchor, a hinge's axis. Default true. */
  joints?: boolean;
  /** Draw each plane's normal (the environment draws its surface). Default true. */
  planes?: boolean;
  /** Draw field regions: fluid surfaces, and lattices of arrows along the uniform electric and magnetic fields. Default true. */
  fields?: boolean;
  /** Draw emitters: a cross and their direction. Default true. */
  emitters?: boolean;
  /** Most line segments the springs, joints, planes, fields and emitters may use together, integer in [0, 1_000_000]. Default 20 000. */
  maxScenery?: number;
}

/** Fully resolved debug options. */
export type ResolvedDebugOptions = Required<DebugOptions>;

/** Each debug option's check and default (the defaults documented on `DebugOptions`). */
const DEBUG_RULES: OptionRules<DebugOptions> = {
  axes: { kind: 'boolean', default: true },
  velocities: { kind: 'boolean', default: true },
  velocityScale: { kind: 'positive', default: 0.1 },
  angularVelocities: { kind: 'boolean', default: false },
  angularVelocityScale: { kind: 'positive', default: 0.1 },
  maxBodies: { kind: 'integer', default: 2000, min: 0, max: 100_000 },
  contacts: { kind: 'boolean', default: true },
  normalLength: { kind: 'positive', default: 0.25 },
  maxContacts: { kind: 'integer', default: 4000, min: 0, max: 1_000_000 },
  pointSize: { kind: 'positive', default: 5 },
  springs: { kind: 'boolean', default: true },
  joints: { kind: 'boolean', default: true },
  planes: { kind: 'boolean', default: true },
  fields: { kind: 'boolean', default: true },
  emitters: { kind: 'boolean', default: true },
  maxScenery: { kind: 'integer', default: 20_000, min: 0, max: 1_000_000 },
};

/** Checks debug options and fills in defaults. @throws TypeError | RangeError naming the bad option and value. */
export function resolveDebugOptions(where: string, options: DebugOptions = {}): ResolvedDebugOptions {
  return resolveOptions(where, 'debug.', options, DEBUG_RULES);
}
const AXIS_X = 0xff5a5f,
  AXIS_Y = 0x5fd068,
  AXIS_Z = 0x4d8dff;
const ARROW = 0x7cf2a0,
  SPIN = 0xff5ce1;
const CONTACT_ACTIVE = 0xff4d5e,
  CONTACT_SPECULATIVE = 0x9aa0a6;
/** Line segments an arrow takes: the shaft and four head strokes. */
const ARROW_SEGMENTS = 5;

/** What the renderer hands the debug layer each frame: where it drew each entity and how big. */
export interface DebugFrame {
  /** The book of shown entities. */
  book: InstanceBook;
  /** Per entity: interpolated position, m (xyz at 3 eid). */
  drawnPosition: Float64Array;
  /** Per entity: interpolated orientation (xyzw at 4 eid). */
  drawnOrientation: Float64Array;
  /** Per entity: half its largest extent, m (radius of a ball, half the longest edge of a box). */
  size: Float64Array;
  /** Scene units per metre. */
  scale: number;
}

/** How many of each kind of entity the debug layer drew in the last frame. */
export interface DebugCounts {
  /** Spring entities drawn. */
  springs: number;
  /** Joint entities drawn. */
  joints: number;
  /** Plane entities drawn. */
  planes: number;
  /** Fluid regions plus electric and magnetic field entities. */
  fields: number;
  /** Emitter entities drawn. */
  emitters: number;
}

/** Box the field lattices fill when the world has no boundary, m: [minX, minY, minZ, maxX, maxY, maxZ]. */
const DEFAULT_FIELD_EXTENT = Object.freeze([-5, 0, -5, 5, 5, 5]);

/**
 * The debug layer: body axes, velocity and angular-velocity arrows, contact points and normals of
 * the last step, and the scenery that is not a body (springs, joints, plane normals, field regions,
 * emitters: see debug-scenery.ts, the place to add a new kind). One `LineSegments` (per-vertex colours) and one `Points` object, with buffers sized
 * once from the options' maxima: a frame rewrites a prefix of them and allocates nothing. Reads
 * component stores and the contact cache; computes nothing physical.
 */
export class DebugLayer {
  /** Holds the lines and the contact dots; the renderer adds it to its root. */
  readonly object = new Group();
  /** The options in use. */
  readonly options: ResolvedDebugOptions;
  /** Contacts drawn in the last frame. */
  contactsDrawn = 0;
  /** Velocity and angular-velocity arrows drawn in the last frame. */
  arrowsDrawn = 0;
  /** Bodies whose axes were drawn in the last frame. */
  axesDrawn = 0;
  /** Springs, joints, planes, field regions and emitters drawn in the last frame. */
  readonly drawn: DebugCounts = { springs: 0, joints: 0, planes: 0, fields: 0, emitters: 0 };
  /** Where the renderer drew the bodies this frame, for the scenery. */
  private readonly at = {
    drawn: new Float64Array(0) as Float64Array<ArrayBufferLike>,
    orientation: new Float64Array(0) as Float64Array<ArrayBufferLike>,
    book: null as InstanceBook | null,
    shown(eid: number): boolean {
      return this.book?.has(eid) === true;
    },
  };
  /** Scene units per metre of the frame being drawn (for `sink`). */
  private scale = 1;
  /** The segment and arrow appenders handed to the scenery drawers, in metres. */
  private readonly sink: SegmentSink = {
    segment: (ax, ay, az, bx, by, bz, color) => this.segment(ax, ay, az, bx, by, bz, color, this.scale),
    arrow: (x, y, z, dx, dy, dz, color) => this.arrow(x, y, z, dx, dy, dz, color, this.scale),
  };
  private readonly extent = new Float64Array(6);
  private readonly lineGeometry = new BufferGeometry();
  private readonly pointGeometry = new BufferGeometry();
  private readonly lineMaterial = new LineBasicMaterial({ vertexColors: true, depthTest: false, transparent: true });
  private readonly pointMaterial: PointsMaterial;
  private readonly linePos: Float32Array;
  private readonly lineCol: Float32Array;
  private readonly pointPos: Float32Array;
  private readonly pointCol: Float32Array;
  private readonly linePosAttr: BufferAttribute;
  private readonly lineColAttr: BufferAttribute;
  private readonly pointPosAttr: BufferAttribute;
  private readonly pointColAttr: BufferAttribute;
  private readonly rgb = new Float64Array(3 * (7 + SCENERY_PALETTE.length));
  private readonly v = new Float64Array(3);
  private segments = 0;
  /** State of the 3D contact pass (a callback made once, so a frame allocates nothing). */
  private contactPoints = 0;
  private contactFrame: DebugFrame | null = null;
  private contactWorld: PhysicsWorld | null = null;
  private readonly onContact = (v: Readonly<ContactView>): void => {
    const o = this.options,
      f = this.contactFrame!,
      world = this.contactWorld!;
    if (this.contactsDrawn >= o.maxContacts) return;
    // The point is on B where B was at the end of the step; move it with B to where B was drawn.
    const b = v.bodyB,
      P = world.components.Position;
    const shown = f.book.has(b),
      pos = f.drawnPosition;
    const cx = shown ? v.x - P.x[b]! + pos[3 * b]! : v.x,
      cy = shown ? v.y - P.y[b]! + pos[3 * b + 1]! : v.y,
      cz = shown ? v.z - P.z[b]! + pos[3 * b + 2]! : v.z;
    const color = v.impulse > 0 ? 5 : 6,
      L = o.normalLength,
      k = f.scale;
    this.segment(cx, cy, cz, cx + v.nx * L, cy + v.ny * L, cz + v.nz * L, color, k);
    const p = this.contactPoints * 3,
      pp = this.pointPos,
      pc = this.pointCol,
      rgb = this.rgb;
    pp[p] = cx * k;
    pp[p + 1] = cy * k;
    pp[p + 2] = cz * k;
    pc[p] = rgb[3 * color]!;
    pc[p + 1] = rgb[3 * color + 1]!;
    pc[p + 2] = rgb[3 * color + 2]!;
    this.contactPoints++;
    this.contactsDrawn++;
  };

  /** @param options resolved options (see `resolveDebugOptions`). */
  constructor(options: ResolvedDebugOptions) {
    this.options = options;
    const arrowsPerBody = (options.velocities ? 1 : 0) + (options.angularVelocities ? 1 : 0);
    const scenery = options.springs || options.joints || options.planes || options.fields || options.emitters ? options.maxScenery : 0;
    const maxSegments =
      options.maxBodies * ((options.axes ? 3 : 0) + arrowsPerBody * ARROW_SEGMENTS) +
      (options.contacts ? options.maxContacts : 0) +
      scenery;
    this.linePos = new Float32Array(Math.max(1, maxSegments) * 6);
    this.lineCol = new Float32Array(Math.max(1, maxSegments) * 6);
    const maxPoints = options.contacts ? Math.max(1, options.maxContacts) : 1;
    this.pointPos = new Float32Array(maxPoints * 3);
    this.pointCol = new Float32Array(maxPoints * 3);
    this.linePosAttr = new BufferAttribute(this.linePos, 3).setUsage(DynamicDrawUsage);
    this.lineColAttr = new BufferAttribute(this.lineCol, 3).setUsage(DynamicDrawUsage);
    this.pointPosAttr = new BufferAttribute(this.pointPos, 3).setUsage(DynamicDrawUsage);
    this.pointColAttr = new BufferAttribute(this.pointCol, 3).setUsage(DynamicDrawUsage);
    this.lineGeometry.setAttribute('position', this.linePosAttr);
    this.lineGeometry.setAttribute('color', this.lineColAttr);
    this.pointGeometry.setAttribute('position', this.pointPosAttr);
    this.pointGeometry.setAttribute('color', this.pointColAttr);
    this.lineGeometry.setDrawRange(0, 0);
    this.pointGeometry.setDrawRange(0, 0);
    this.pointMaterial = new PointsMaterial({
      size: options.pointSize,
      sizeAttenuation: false,
      vertexColors: true,
      depthTest: false,
      transparent: true,
    });
    const lines = new LineSegments(this.lineGeometry, this.lineMaterial);
    const points = new Points(this.pointGeometry, this.pointMaterial);
    lines.frustumCulled = false;
    points.frustumCulled = false;
    lines.renderOrder = 10;
    points.renderOrder = 11;
    this.object.name = 'debug';
    this.object.add(lines, points);
    const colors = [AXIS_X, AXIS_Y, AXIS_Z, ARROW, SPIN, CONTACT_ACTIVE, CONTACT_SPECULATIVE, ...SCENERY_PALETTE];
    for (let i = 0; i < colors.length; i++) hexToLinear(colors[i]!, this.rgb, 3 * i);
  }

  /** Rewrites the overlay for the frame the renderer just placed (positions in `frame`). */
  draw(world: PhysicsWorld, frame: DebugFrame): void {
    const o = this.options;
    const c = world.components;
    const book = frame.book,
      pos = frame.drawnPosition,
      ori = frame.drawnOrientation,
      size = frame.size,
      k = frame.scale;
    this.segments = 0;
    this.axesDrawn = 0;
    this.arrowsDrawn = 0;
    this.contactsDrawn = 0;
    const v = this.v;
    let budget = o.maxBodies;
    const vx = c.Velocity.x,
      vy = c.Velocity.y,
      vz = c.Velocity.z;
    const wx = c.AngularVelocity.x,
      wy = c.AngularVelocity.y,
      wz = c.AngularVelocity.z;
    for (let g = 0; g < book.groups && budget > 0; g++) {
      const eids = book.eids(g);
      const n = Math.min(book.count(g), budget);
      budget -= n;
      for (let i = 0; i < n; i++) {
        const e = eids[i]!;
        const x = pos[3 * e]!,
          y = pos[3 * e + 1]!,
          z = pos[3 * e + 2]!;
        if (o.axes) {
          const qx = ori[4 * e]!,
            qy = ori[4 * e + 1]!,
            qz = ori[4 * e + 2]!,
            qw = ori[4 * e + 3]!;
          const len = 1.5 * size[e]!;
          for (let axis = 0; axis < 3; axis++) {
            rotateInto(qx, qy, qz, qw, axis === 0 ? len : 0, axis === 1 ? len : 0, axis === 2 ? len : 0, v, 0);
            this.segment(x, y, z, x + v[0]!, y + v[1]!, z + v[2]!, axis, k);
          }
          this.axesDrawn++;
        }
        if (o.velocities) {
          const s = o.velocityScale;
          if (this.arrow(x, y, z, vx[e]! * s, vy[e]! * s, vz[e]! * s, 3, k)) this.arrowsDrawn++;
        }
        if (o.angularVelocities) {
          const s = o.angularVelocityScale;
          if (this.arrow(x, y, z, wx[e]! * s, wy[e]! * s, wz[e]! * s, 4, k)) this.arrowsDrawn++;
        }
      }
    }

    let points = 0;
    if (o.contacts && o.maxContacts > 0) {
      this.contactPoints = 0;
      this.contactFrame = frame;
      this.contactWorld = world;
      forEachContact(world, this.onContact);
      points = this.contactPoints;
    }

    this.drawScenery(world, frame);

    const verts = this.segments * 2;
    this.lineGeometry.setDrawRange(0, verts);
    if (verts > 0) {
      this.linePosAttr.clearUpdateRanges();
      this.linePosAttr.addUpdateRange(0, verts * 3);
      this.linePosAttr.needsUpdate = true;
      this.lineColAttr.clearUpdateRanges();
      this.lineColAttr.addUpdateRange(0, verts * 3);
      this.lineColAttr.needsUpdate = true;
    }
    this.pointGeometry.setDrawRange(0, points);
    if (points > 0) {
      this.pointPosAttr.clearUpdateRanges();
      this.pointPosAttr.addUpdateRange(0, points * 3);
      this.pointPosAttr.needsUpdate = true;
      this.pointColAttr.clearUpdateRanges();
      this.pointColAttr.addUpdateRange(0, points * 3);
      this.pointColAttr.needsUpdate = true;
    }
  }

  /** Appends the springs, joints, plane normals, field regions and emitters (debug-scenery.ts). */
  private drawScenery(world: PhysicsWorld, frame: DebugFrame): void {
    const o = this.options,
      d = this.drawn,
      at = this.at;
    at.drawn = frame.drawnPosition;
    at.orientation = frame.drawnOrientation;
    at.book = frame.book;
    this.scale = frame.scale;
    d.springs = o.springs ? drawSprings(world, at, this.sink) : 0;
    d.joints = o.joints ? drawJoints(world, at, this.sink) + drawJoints3D(world, at, this.sink) : 0;
    d.planes = o.planes ? drawPlanes(world, this.sink) : 0;
    if (o.fields) {
      const box = world.collision.boundary,
        ext = this.extent;
      for (let i = 0; i < 3; i++) {
        ext[i] = box.enabled ? (box.min[i] ?? 0) : DEFAULT_FIELD_EXTENT[i]!;
        ext[i + 3] = box.enabled ? (box.max[i] ?? 0) : DEFAULT_FIELD_EXTENT[i + 3]!;
      }
      if (!(ext[2]! < ext[5]!)) {
        ext[2] = -0.5;
        ext[5] = 0.5;
      } // a 2D world's box has no depth
      const smallest = Math.min(ext[3]! - ext[0]!, ext[4]! - ext[1]!, ext[5]! - ext[2]!);
      d.fields = drawFields(world, ext, 0.2 * smallest, this.sink);
    } else {
      d.fields = 0;
    }
    d.emitters = o.emitters ? drawEmitters(world, at, this.sink) : 0;
  }

  /** Frees the geometries and materials. */
  destroy(): void {
    this.object.removeFromParent();
    this.lineGeometry.dispose();
    this.pointGeometry.dispose();
    this.lineMaterial.dispose();
    this.pointMaterial.dispose();
  }

  /** Appends a segment from a to b (m) in palette colour `color`, converting to scene units with k. */
  private segment(ax: number, ay: number, az: number, bx: number, by: number, bz: number, color: number, k: number): void {
    const s = this.segments;
    if ((s + 1) * 6 > this.linePos.length) return;
    const p = this.linePos,
      c = this.lineCol,
      rgb = this.rgb;
    const o = s * 6;
    p[o] = ax * k;
    p[o + 1] = ay * k;
    p[o + 2] = az * k;
    p[o + 3] = bx * k;
    p[o + 4] = by * k;
    p[o + 5] = bz * k;
    const r = rgb[3 * color]!,
      g = rgb[3 * color + 1]!,
      b = rgb[3 * color + 2]!;
    c[o] = r;
    c[o + 1] = g;
    c[o + 2] = b;
    c[o + 3] = r;
    c[o + 4] = g;
    c[o + 5] = b;
    this.segments = s + 1;
  }

  /**
   * Appends an arrow from (x, y, z) along (dx, dy, dz) (m): the shaft and a four-stroke head a quarter
   * of its length (at most 0.3 m). Arrows shorter than 1 mm are skipped. @returns whether one was drawn.
   */
  private arrow(x: number, y: number, z: number, dx: number, dy: number, dz: number, color: number, k: number): boolean {
    const len = Math.sqrt(dx * dx + dy * dy + dz * dz);
    if (len < 1e-3) return false;
    const tx = x + dx,
      ty = y + dy,
      tz = z + dz;
    this.segment(x, y, z, tx, ty, tz, color, k);
    const ux = dx / len,
      uy = dy / len,
      uz = dz / len;
    // Two unit vectors perpendicular to the arrow: p = u x (an axis not along u), q = u x p.
    let px: number, py: number, pz: number;
    if (Math.abs(uy) < 0.9) {
      px = -uz;
      py = 0;
      pz = ux;
    } else {
      px = 0;
      py = uz;
      pz = -uy;
    }
    const pl = 1 / Math.sqrt(px * px + py * py + pz * pz);
    px *= pl;
    py *= pl;
    pz *= pl;
    const qx = uy * pz - uz * py,
      qy = uz * px - ux * pz,
      qz = ux * py - uy * px;
    const h = Math.min(0.25 * len, 0.3),
      w = 0.45 * h;
    const bx = tx - ux * h,
      by = ty - uy * h,
      bz = tz - uz * h;
    this.segment(tx, ty, tz, bx + px * w, by + py * w, bz + pz * w, color, k);
    this.segment(tx, ty, tz, bx - px * w, by - py * w, bz - pz * w, color, k);
    this.segment(tx, ty, tz, bx + qx * w, by + qy * w, bz + qz * w, color, k);
    this.segment(tx, ty, tz, bx - qx * w, by - qy * w, bz - qz * w, color, k);
    return true;
  }
}
