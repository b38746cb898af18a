import { fieldsAt, type PhysicsWorld, query } from '@bitphysics/physics';
import type { Graphics } from 'pixi.js';
import type { Camera } from './camera.js';

/**
 * The debug layer's drawings of what is not a ball: springs, joints, planes, field regions (fluid
 * regions, uniform electric and magnetic fields) and emitters. Each `draw*` function strokes into
 * the layer's Graphics for the state at interpolation factor `alpha` and returns how many entities
 * it drew. They read component stores only and compute nothing physical beyond placing anchors.
 *
 * Extension point: a new kind of entity (another joint type, a new field) gets a `draw*` function
 * here with the same signature and one line in `DebugLayer.draw` (packages/render-pixi/src/debug.ts)
 * behind its own option.
 */

/** Colours of the scenery, 0xRRGGBB. */
export const SCENERY_COLORS = Object.freeze({
  spring: 0xc792ea,
  joint: 0x4dd0e1,
  plane: 0xffd166,
  fluid: 0x3a7bd5,
  electric: 0xffb347,
  magnetic: 0x82aaff,
  emitter: 0xff8a65,
});

/** Coils of a drawn spring (zigzag corners). */
const SPRING_COILS = 10;
/** Half-width of a drawn spring's zigzag, CSS px. */
const SPRING_WIDTH = 5;
/** Spacing of the field glyph grid, CSS px. */
const FIELD_SPACING = 90;

const fields = { e: new Float64Array(3), b: new Float64Array(3) };

/** Interpolated x (m) of entity `e`: PreviousPosition to Position by alpha. */
function ix(world: PhysicsWorld, e: number, alpha: number): number {
  const P = world.components.Position.x,
    O = world.components.PreviousPosition.x;
  return O[e]! + (P[e]! - O[e]!) * alpha;
}

/** Interpolated y (m) of entity `e`. */
function iy(world: PhysicsWorld, e: number, alpha: number): number {
  const P = world.components.Position.y,
    O = world.components.PreviousPosition.y;
  return O[e]! + (P[e]! - O[e]!) * alpha;
}

/**
 * Springs (entities with Spring): a zigzag from body `a` (or the fixed anchor when `a` is 0) to body
 * `b`, SPRING_COILS coils, SPRING_WIDTH px wide. @returns springs drawn.
 */
export function drawSprings(g: Graphics, world: PhysicsWorld, camera: Camera, alpha: number): number {
  const S = world.components.Spring;
  const springs = query(world, [S]);
  for (let i = 0; i < springs.length; i++) {
    const s = springs[i]!;
    const a = S.a[s]!,
      b = S.b[s]!;
    const ax = camera.toScreenX(a > 0 ? ix(world, a, alpha) : S.anchorX[s]!);
    const ay = camera.toScreenY(a > 0 ? iy(world, a, alpha) : S.anchorY[s]!);
    const bx = camera.toScreenX(ix(world, b, alpha)),
      by = camera.toScreenY(iy(world, b, alpha));
    const dx = bx - ax,
      dy = by - ay;
    const len = Math.sqrt(dx * dx + dy * dy);
    g.moveTo(ax, ay);
    if (len > 4 * SPRING_WIDTH) {
      const ux = dx / len,
        uy = dy / len;
      // Straight leads of 10% at each end, the zigzag between.
      const lead = 0.1 * len,
        body = len - 2 * lead;
      g.lineTo(ax + ux * lead, ay + uy * lead);
      for (let k = 0; k < 2 * SPRING_COILS; k++) {
        const t = lead + ((k + 0.5) / (2 * SPRING_COILS)) * body;
        const side = k % 2 === 0 ? SPRING_WIDTH : -SPRING_WIDTH;
        g.lineTo(ax + ux * t - uy * side, ay + uy * t + ux * side);
      }
      g.lineTo(bx - ux * lead, by - uy * lead);
    }
    g.lineTo(bx, by);
    if (a === 0) g.circle(ax, ay, 3);
  }
  if (springs.length > 0) g.stroke({ width: 1.5, color: SCENERY_COLORS.spring, alpha: 0.95 });
  return springs.length;
}

/**
 * Joints (entities with Joint): a line between the two world anchors with a dot at each, and thin
 * lines from each body's centre to its anchor (anchors rotate with the body's Angle; body A = 0 means
 * its anchor is a world point). @returns joints drawn.
 */
export function drawJoints(g: Graphics, world: PhysicsWorld, camera: Camera, alpha: number): number {
  const c = world.components;
  const J = c.Joint,
    angle = c.Angle.value;
  const joints = query(world, [J]);
  for (let i = 0; i < joints.length; i++) {
    const j = joints[i]!;
    const a = J.a[j]!,
      b = J.b[j]!;
    let ax = J.localAx[j]!,
      ay = J.localAy[j]!;
    let acx = ax,
      acy = ay;
    if (a > 0) {
      const th = angle[a] ?? 0,
        cs = Math.cos(th),
        sn = Math.sin(th);
      acx = ix(world, a, alpha);
      acy = iy(world, a, alpha);
      const lx = ax,
        ly = ay;
      ax = acx + cs * lx - sn * ly;
      ay = acy + sn * lx + cs * ly;
    }
    const th = angle[b] ?? 0,
      cs = Math.cos(th),
      sn = Math.sin(th);
    const bcx = ix(world, b, alpha),
      bcy = iy(world, b, alpha);
    const bx = bcx + cs * J.localBx[j]! - sn * J.localBy[j]!,
      by = bcy + sn * J.localBx[j]! + cs * J.localBy[j]!;
    const sax = camera.toScreenX(ax),
      say = camera.toScreenY(ay),
      sbx = camera.toScreenX(bx),
      sby = camera.toScreenY(by);
    g.moveTo(camera.toScreenX(acx), camera.toScreenY(acy)).lineTo(sax, say);
    g.moveTo(camera.toScreenX(bcx), camera.toScreenY(bcy)).lineTo(sbx, sby);
    g.moveTo(sax, say).lineTo(sbx, sby);
    g.circle(sax, say, 3);
    g.circle(sbx, sby, 3);
  }
  if (joints.length > 0) g.stroke({ width: 1.5, color: SCENERY_COLORS.joint, alpha: 0.95 });
  return joints.length;
}

/**
 * Planes (entities with Plane; in 2D the line n . x = d): the line across the whole view, with short
 * hatches on the solid side (against n). @returns planes drawn.
 */
export function drawPlanes(g: Graphics, world: PhysicsWorld, camera: Camera): number {
  const P = world.components.Plane;
  const planes = query(world, [P]);
  // Long enough to cross the view from any point on it: the view's diagonal, px.
  const reach = Math.hypot(camera.width, camera.height);
  const cx = camera.toWorldX(camera.width / 2),
    cy = camera.toWorldY(camera.height / 2);
  for (let i = 0; i < planes.length; i++) {
    const e = planes[i]!;
    const nx = P.nx[e]!,
      ny = P.ny[e]!,
      d = P.d[e]!;
    // The point of the line nearest the view's centre, then along the tangent (-ny, nx).
    const s = nx * cx + ny * cy - d;
    const px = camera.toScreenX(cx - nx * s),
      py = camera.toScreenY(cy - ny * s);
    const tx = -ny,
      ty = -nx; // tangent in screen axes (y flipped)
    g.moveTo(px - tx * reach, py - ty * reach).lineTo(px + tx * reach, py + ty * reach);
    // Hatches every 16 px on the solid side (screen normal is (nx, -ny)).
    for (let k = -Math.ceil(reach / 16); k <= Math.ceil(reach / 16); k++) {
      const hx = px + tx * k * 16,
        hy = py + ty * k * 16;
      g.moveTo(hx, hy).lineTo(hx - nx * 8 - tx * 6, hy + ny * 8 - ty * 6);
    }
  }
  if (planes.length > 0) g.stroke({ width: 1.5, color: SCENERY_COLORS.plane, alpha: 0.9 });
  return planes.length;
}

/**
 * Field regions: each fluid region (below its surface, within its x range, clipped to the view) as a
 * translucent fill with its surface line; the world's uniform electric field E(t) (the sum of every
 * ElectricField at world.time) as a grid of arrows along E; the magnetic field's z component as a grid
 * of dots (B out of the screen) or crosses (into it). @returns fluid regions plus field entities drawn.
 */
export function drawFields(g: Graphics, world: PhysicsWorld, camera: Camera): number {
  const c = world.components;
  const F = c.FluidRegion;
  const regions = query(world, [F]);
  const left = camera.toWorldX(0),
    right = camera.toWorldX(camera.width);
  const bottom = camera.toWorldY(camera.height);
  for (let i = 0; i < regions.length; i++) {
    const e = regions[i]!;
    const x1 = Math.max(left, F.minX[e]!),
      x2 = Math.min(right, F.maxX[e]!);
    const top = F.surface[e]!;
    if (!(x2 > x1) || !(top > bottom)) continue;
    const sx1 = camera.toScreenX(x1),
      sx2 = camera.toScreenX(x2),
      sy = camera.toScreenY(top),
      sb = camera.toScreenY(bottom);
    g.rect(sx1, sy, sx2 - sx1, sb - sy).fill({ color: SCENERY_COLORS.fluid, alpha: 0.18 });
    g.moveTo(sx1, sy).lineTo(sx2, sy).stroke({ width: 1.5, color: SCENERY_COLORS.fluid, alpha: 0.9 });
  }
  const electric = query(world, [c.ElectricField]).length;
  const magnetic = query(world, [c.MagneticField]).length;
  if (electric + magnetic > 0) {
    fieldsAt(world, world.time, fields.e, fields.b);
    const ex = fields.e[0]!,
      ey = fields.e[1]!,
      bz = fields.b[2]!;
    const eLen = Math.hypot(ex, ey);
    const cols = Math.max(1, Math.floor(camera.width / FIELD_SPACING)),
      rows = Math.max(1, Math.floor(camera.height / FIELD_SPACING));
    const stepX = camera.width / cols,
      stepY = camera.height / rows;
    // Two passes over the grid (arrows, then glyphs), each one stroke: a pixi path takes every
    // command since the last stroke.
    if (electric > 0 && eLen > 0) {
      const ux = ex / eLen,
        uy = -ey / eLen; // screen y flipped
      for (let r = 0; r < rows; r++) {
        for (let q = 0; q < cols; q++) {
          // A 24 px arrow along E, centred on the grid point.
          const gx = (q + 0.5) * stepX,
            gy = (r + 0.5) * stepY;
          const tx = gx + ux * 12,
            ty = gy + uy * 12;
          g.moveTo(gx - ux * 12, gy - uy * 12).lineTo(tx, ty);
          g.moveTo(tx - ux * 6 - uy * 4, ty - uy * 6 + ux * 4)
            .lineTo(tx, ty)
            .lineTo(tx - ux * 6 + uy * 4, ty - uy * 6 - ux * 4);
        }
      }
      g.stroke({ width: 1.25, color: SCENERY_COLORS.electric, alpha: 0.6 });
    }
    if (magnetic > 0 && bz !== 0) {
      for (let r = 0; r < rows; r++) {
        for (let q = 0; q < cols; q++) {
          const mx = (q + 0.75) * stepX,
            my = (r + 0.75) * stepY;
          g.circle(mx, my, 6);
          if (bz > 0) g.circle(mx, my, 1.5);
          else
            g.moveTo(mx - 4, my - 4)
              .lineTo(mx + 4, my + 4)
              .moveTo(mx - 4, my + 4)
              .lineTo(mx + 4, my - 4);
        }
      }
      g.stroke({ width: 1.25, color: SCENERY_COLORS.magnetic, alpha: 0.7 });
    }
  }
  return regions.length + electric + magnetic;
}

/**
 * Emitters (entities with Emitter and Position): a ring at the emitter (its `size` when that is
 * larger than 6 px), its direction as a 30 px line and the edges of its spread (half-angle `spread`)
 * as two 20 px lines; disabled emitters are drawn faint. @returns emitters drawn.
 */
export function drawEmitters(g: Graphics, world: PhysicsWorld, camera: Camera, alpha: number): number {
  const c = world.components;
  const E = c.Emitter;
  const emitters = query(world, [E, c.Position]);
  for (let pass = 0; pass < 2; pass++) {
    let any = false;
    for (let i = 0; i < emitters.length; i++) {
      const e = emitters[i]!;
      if ((E.enabled[e] === 1) !== (pass === 0)) continue;
      const sx = camera.toScreenX(ix(world, e, alpha)),
        sy = camera.toScreenY(iy(world, e, alpha));
      const r = Math.max(6, camera.toScreenLength(E.size[e] ?? 0));
      g.circle(sx, sy, r);
      const dx = E.dirX[e]!,
        dy = E.dirY[e]!;
      const dl = Math.hypot(dx, dy);
      if (dl > 0) {
        const th = Math.atan2(-dy, dx),
          spread = E.spread[e]!;
        g.moveTo(sx, sy).lineTo(sx + Math.cos(th) * 30, sy + Math.sin(th) * 30);
        if (spread > 0) {
          g.moveTo(sx, sy).lineTo(sx + Math.cos(th - spread) * 20, sy + Math.sin(th - spread) * 20);
          g.moveTo(sx, sy).lineTo(sx + Math.cos(th + spread) * 20, sy + Math.sin(th + spread) * 20);
        }
      }
      any = true;
    }
    if (any) g.stroke({ width: 1.5, color: SCENERY_COLORS.emitter, alpha: pass === 0 ? 0.95 : 0.35 });
  }
  return emitters.length;
}
