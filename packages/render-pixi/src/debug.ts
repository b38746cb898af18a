import { type ContactView, forEachContact, type PhysicsWorld } from '@bitphysics/physics';
import { type OptionRules, resolveOptions } from '@bitphysics/render-common';
import { query } from 'bitecs';
import { Graphics } from 'pixi.js';
import type { BallLayer } from './balls.js';
import type { Camera } from './camera.js';
import { drawEmitters, drawFields, drawJoints, drawPlanes, drawSprings } from './debug-scenery.js';

/** Options of the debug layer (`WorldRendererOptions.debug`, `WorldRenderer.setDebug`). Unknown fields are rejected. */
export interface DebugOptions {
  /** Draw each ball's velocity as an arrow from its centre. Default true. */
  velocities?: boolean;
  /** Arrow length per unit speed, s (an arrow is |v| velocityScale metres long), > 0. Default 0.1 s. */
  velocityScale?: number;
  /** Most velocity arrows drawn (the first balls shown), integer in [0, 1_000_000]. Default 2000. */
  maxArrows?: number;
  /**
   * Draw the last step's contacts (`forEachContact`: balls and shapes): a dot at each contact point
   * and its normal (from body A to body B). Contacts that carried impulse are red, speculative
   * ones (no impulse) grey. Default true.
   */
  contacts?: boolean;
  /** Length of a drawn contact normal, CSS px, > 0. Default 14 px. */
  normalLength?: number;
  /** Most contacts drawn, integer in [0, 1_000_000]. Default 4000. */
  maxContacts?: number;
  /** Outline walls: segment capsules and their end points, and the boundary box's faces. Default true. */
  walls?: boolean;
  /** Draw springs as zigzags between their bodies (or anchor). Default true. */
  springs?: boolean;
  /** Draw joints: the line between their anchors and each body's lever to its anchor. Default true. */
  joints?: boolean;
  /** Draw planes (lines n . x = d across the view, hatched on the solid side). Default true. */
  planes?: boolean;
  /** Draw field regions: fluid regions, and glyph grids of the uniform electric and magnetic fields. Default true. */
  fields?: boolean;
  /** Draw emitters: a ring, their direction and the edges of their spread. Default true. */
  emitters?: boolean;
}

/** Fully resolved debug options. */
export type ResolvedDebugOptions = Required<DebugOptions>;

/** Each debug option's check and default (the defaults documented on `DebugOptions`). */
const DEBUG_RULES: OptionRules<DebugOptions> = {
  velocities: { kind: 'boolean', default: true },
  velocityScale: { kind: 'positive', default: 0.1 },
  maxArrows: { kind: 'integer', default: 2000, min: 0, max: 1_000_000 },
  contacts: { kind: 'boolean', default: true },
  normalLength: { kind: 'positive', default: 14 },
  maxContacts: { kind: 'integer', default: 4000, min: 0, max: 1_000_000 },
  walls: { kind: 'boolean', default: true },
  springs: { kind: 'boolean', default: true },
  joints: { kind: 'boolean', default: true },
  planes: { kind: 'boolean', default: true },
  fields: { kind: 'boolean', default: true },
  emitters: { kind: 'boolean', default: true },
};

/** Checks debug options and fills in defaults. @throws TypeError | RangeError naming the bad option and value. */
export function resolveDebugOptions(where: string, options: DebugOptions = {}): ResolvedDebugOptions {
  return resolveOptions(where, 'debug.', options, DEBUG_RULES);
}
const ARROW = 0x7cf2a0;
const CONTACT_ACTIVE = 0xff4d5e;
const CONTACT_SPECULATIVE = 0x9aa0a6;
const WALL_DEBUG = 0xffd166;

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

/**
 * The debug overlay: velocity arrows, contact points and normals of the last step, wall outlines,
 * and the scenery that is not a ball (springs, joints, planes, field regions, emitters: see
 * debug-scenery.ts, the place to add a new kind). One pixi Graphics redrawn each frame (pixi
 * allocates its own path objects while drawing; bounded by maxArrows and maxContacts). Reads
 * component stores and the contact cache; computes nothing physical.
 */
export class DebugLayer {
  /** The Graphics the overlay is drawn into; sits above the balls. */
  readonly graphics = new Graphics({ label: 'debug' });
  /** The options in use. */
  readonly options: ResolvedDebugOptions;
  /** Contacts drawn in the last frame. */
  contactsDrawn = 0;
  /** Arrows drawn in the last frame. */
  arrowsDrawn = 0;
  /** Springs, joints, planes, field regions and emitters drawn in the last frame. */
  readonly drawn: DebugCounts = { springs: 0, joints: 0, planes: 0, fields: 0, emitters: 0 };

  /** @param options resolved options (see `resolveDebugOptions`). */
  constructor(options: ResolvedDebugOptions) {
    this.options = options;
  }

  /** Redraws the overlay for the state shown at interpolation factor `alpha`. */
  draw(world: PhysicsWorld, balls: BallLayer, camera: Camera, alpha: number): void {
    const g = this.graphics;
    g.clear();
    const o = this.options;
    const c = world.components;
    const px = c.Position.x,
      py = c.Position.y,
      ox = c.PreviousPosition.x,
      oy = c.PreviousPosition.y;
    const ppm = camera.pixelsPerMeter,
      x0 = camera.originX,
      y0 = camera.originY;
    this.arrowsDrawn = 0;
    this.contactsDrawn = 0;

    if (o.walls) this.drawWalls(world, camera);
    const d = this.drawn;
    d.fields = o.fields ? drawFields(g, world, camera) : 0;
    d.planes = o.planes ? drawPlanes(g, world, camera) : 0;
    d.springs = o.springs ? drawSprings(g, world, camera, alpha) : 0;
    d.joints = o.joints ? drawJoints(g, world, camera, alpha) : 0;
    d.emitters = o.emitters ? drawEmitters(g, world, camera, alpha) : 0;

    if (o.velocities && o.maxArrows > 0) {
      const vx = c.Velocity.x,
        vy = c.Velocity.y;
      const k = o.velocityScale * ppm;
      const n = Math.min(balls.count, o.maxArrows);
      const eids = balls.eids;
      let drawn = 0;
      for (let i = 0; i < n; i++) {
        const e = eids[i]!;
        const dx = vx[e]! * k,
          dy = -vy[e]! * k;
        const len = Math.sqrt(dx * dx + dy * dy);
        if (len < 2) continue;
        const sx = x0 + (ox[e]! + (px[e]! - ox[e]!) * alpha) * ppm;
        const sy = y0 - (oy[e]! + (py[e]! - oy[e]!) * alpha) * ppm;
        const tx = sx + dx,
          ty = sy + dy;
        const hl = Math.min(8, len * 0.35);
        const ux = dx / len,
          uy = dy / len;
        g.moveTo(sx, sy).lineTo(tx, ty);
        g.moveTo(tx - ux * hl - uy * hl * 0.5, ty - uy * hl + ux * hl * 0.5)
          .lineTo(tx, ty)
          .lineTo(tx - ux * hl + uy * hl * 0.5, ty - uy * hl - ux * hl * 0.5);
        drawn++;
      }
      if (drawn > 0) g.stroke({ width: 1.5, color: ARROW, alpha: 0.9 });
      this.arrowsDrawn = drawn;
    }

    if (o.contacts && o.maxContacts > 0) {
      // Every contact point of the last step (balls and shapes), moved with B to where B is drawn.
      const pts = this.gatherContacts(world, o.maxContacts);
      const n = this.contactCount;
      const L = o.normalLength;
      // Two passes (active, then speculative) so each colour is one stroke.
      for (let pass = 0; pass < 2; pass++) {
        let any = false;
        for (let i = 0; i < n; i++) {
          const q = 6 * i;
          const active = pts[q + 5]! > 0;
          if (active !== (pass === 0)) continue;
          const e = pts[q + 4]!;
          const cx = ox[e]! + (px[e]! - ox[e]!) * alpha + pts[q]!;
          const cy = oy[e]! + (py[e]! - oy[e]!) * alpha + pts[q + 1]!;
          const sx = x0 + cx * ppm,
            sy = y0 - cy * ppm;
          g.moveTo(sx, sy).lineTo(sx + pts[q + 2]! * L, sy - pts[q + 3]! * L);
          g.circle(sx, sy, 2.5);
          any = true;
        }
        if (any) g.stroke({ width: 1.25, color: pass === 0 ? CONTACT_ACTIVE : CONTACT_SPECULATIVE, alpha: 0.95 });
      }
      this.contactsDrawn = n;
    }
  }

  /**
   * The last step's contact points (at most `most`), 6 numbers each in the returned scratch: the
   * point's offset from body B's centre at the end of the step (m, x and y), the normal (x, y), B's
   * slot and the impulse (N s); their number in `contactCount`.
   */
  private gatherContacts(world: PhysicsWorld, most: number): Float64Array {
    this.contactCount = 0;
    this.contactMost = most;
    this.contactWorld = world;
    forEachContact(world, this.onContact);
    return this.contactScratch;
  }

  /** Points gathered by the last `gatherContacts`. */
  private contactCount = 0;
  private contactMost = 0;
  private contactWorld: PhysicsWorld | null = null;
  private contactScratch = new Float64Array(6 * 256);
  /** The callback handed to forEachContact (made once, so a frame allocates nothing but growth). */
  private readonly onContact = (v: Readonly<ContactView>): void => {
    if (this.contactCount >= this.contactMost) return;
    const P = this.contactWorld!.components.Position;
    let buf = this.contactScratch;
    const q = 6 * this.contactCount;
    if (q + 6 > buf.length) {
      const grown = new Float64Array(2 * buf.length);
      grown.set(buf);
      this.contactScratch = buf = grown;
    }
    buf[q] = v.x - P.x[v.bodyB]!;
    buf[q + 1] = v.y - P.y[v.bodyB]!;
    buf[q + 2] = v.nx;
    buf[q + 3] = v.ny;
    buf[q + 4] = v.bodyB;
    buf[q + 5] = v.impulse;
    this.contactCount++;
  };

  /** Releases the Graphics. */
  destroy(): void {
    this.graphics.destroy();
  }

  private drawWalls(world: PhysicsWorld, camera: Camera): void {
    const g = this.graphics;
    const S = world.components.Segment;
    const segs = query(world, [S]);
    let any = false;
    for (let i = 0; i < segs.length; i++) {
      const e = segs[i]!;
      const ax = camera.toScreenX(S.ax[e]!),
        ay = camera.toScreenY(S.ay[e]!);
      const bx = camera.toScreenX(S.bx[e]!),
        by = camera.toScreenY(S.by[e]!);
      const r = Math.max(camera.toScreenLength(S.radius[e]!), 0);
      g.moveTo(ax, ay).lineTo(bx, by);
      g.circle(ax, ay, r + 3);
      g.circle(bx, by, r + 3);
      any = true;
    }
    const box = world.collision.boundary;
    if (box.enabled) {
      const x1 = camera.toScreenX(box.min[0]!),
        x2 = camera.toScreenX(box.max[0]!);
      const y1 = camera.toScreenY(box.max[1]!),
        y2 = camera.toScreenY(box.min[1]!);
      g.rect(x1, y1, x2 - x1, y2 - y1);
      any = true;
    }
    if (any) g.stroke({ width: 1, color: WALL_DEBUG, alpha: 0.9 });
  }
}
