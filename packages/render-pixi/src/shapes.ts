import type { PhysicsWorld } from '@bitphysics/physics';
import { seededColor } from '@bitphysics/render-common';
import { hasComponent, query } from 'bitecs';
import { Graphics } from 'pixi.js';
import type { Camera } from './camera.js';

/** Vertices a shape store holds per entity (the physics package's SHAPE_STRIDE). */
const STRIDE = 8;
/** Line segments per quarter turn of a rounded corner or cap. */
const ARC_STEPS = 4;

/**
 * Shapes of 2D bodies (`Components.Shape`: boxes, polygons, capsules, circles, rounded polygons): one
 * pixi Graphics redrawn every frame, each shape filled with its colour and outlined (the colour set on
 * the shape with `WorldRenderer.setColor`, else the one set on its body, else the body's seeded one), at
 * its body's position interpolated between PreviousPosition and Position and its angle taken back by
 * (1 - alpha) of the step's turn. A rounded outline follows the shape exactly: its core's edges moved
 * out by the radius, joined by arcs at the vertices. Sensors are drawn as outlines only. Internal to
 * the renderer; `WorldRenderer` owns one.
 */
export class ShapeLayer {
  /** The Graphics the shapes are drawn into; sits under the balls. */
  readonly graphics = new Graphics({ label: 'shapes' });
  /** Seed of the per-body colours. */
  colorSeed: number;
  /** Palette the seeded colours are picked from, or null for free hues. */
  palette: readonly number[] | null;
  /** Shapes drawn in the last frame. */
  drawn = 0;
  private readonly points: number[] = [];

  constructor(colorSeed: number, palette: readonly number[] | null) {
    this.colorSeed = colorSeed;
    this.palette = palette;
  }

  /**
   * Redraws every shape for interpolation factor `alpha` in [0, 1]. `userColorOf(world, slot)` gives
   * an entity's user colour (0xRRGGBB) or -1 for none.
   */
  update(world: PhysicsWorld, camera: Camera, alpha: number, userColorOf: (world: PhysicsWorld, slot: number) => number): void {
    const g = this.graphics;
    g.clear();
    this.drawn = 0;
    const c = world.components;
    const S = c.Shape;
    if (world.dimensions !== 2 || !S || S.body.length === 0) return;
    const shapes = query(world, [c.Shape]);
    const P = c.Position,
      O = c.PreviousPosition,
      A = c.Angle.value,
      W = c.AngularVelocity.z;
    const back = (1 - alpha) * world.dt;
    const pts = this.points;
    for (let k = 0; k < shapes.length; k++) {
      const e = shapes[k]!;
      const b = S.body[e]!;
      if (!hasComponent(world, b, c.Position)) continue;
      const x = O.x[b]! + (P.x[b]! - O.x[b]!) * alpha,
        y = O.y[b]! + (P.y[b]! - O.y[b]!) * alpha;
      let a = hasComponent(world, b, c.Angle) ? A[b]! : 0;
      if (!hasComponent(world, b, c.Static) && hasComponent(world, b, c.AngularVelocity)) a -= W[b]! * back;
      const ca = Math.cos(a),
        sa = Math.sin(a);
      const n = S.count[e]!,
        r = S.radius[e]!,
        o = STRIDE * e;
      pts.length = 0;
      let color = userColorOf(world, e);
      if (color < 0 && b !== e) color = userColorOf(world, b);
      if (color < 0) color = seededColor(this.colorSeed, b, world.spawnStamp[b]!, this.palette);
      if (n === 1) {
        const cx = x + ca * S.vx[o]! - sa * S.vy[o]!,
          cy = y + sa * S.vx[o]! + ca * S.vy[o]!;
        g.circle(camera.toScreenX(cx), camera.toScreenY(cy), camera.toScreenLength(r));
        // A radius line shows the turn.
        if (S.sensor[e] === 1) g.stroke({ width: 1.5, color, alpha: 0.8 });
        else {
          g.fill({ color, alpha: 0.85 }).stroke({ width: 1.5, color: 0x1d2330, alpha: 0.9 });
          g.moveTo(camera.toScreenX(cx), camera.toScreenY(cy))
            .lineTo(camera.toScreenX(cx + ca * r), camera.toScreenY(cy + sa * r))
            .stroke({ width: 1.5, color: 0x1d2330, alpha: 0.9 });
        }
        this.drawn++;
        continue;
      }
      for (let i = 0; i < n; i++) {
        // Vertex i in the world; with a radius, the arc around it from the previous edge's normal to this edge's.
        const lx = S.vx[o + i]!,
          ly = S.vy[o + i]!;
        const vx = x + ca * lx - sa * ly,
          vy = y + sa * lx + ca * ly;
        if (r > 0) {
          const p = i === 0 ? n - 1 : i - 1;
          const a0 = Math.atan2(sa * S.nx[o + p]! + ca * S.ny[o + p]!, ca * S.nx[o + p]! - sa * S.ny[o + p]!);
          let a1 = Math.atan2(sa * S.nx[o + i]! + ca * S.ny[o + i]!, ca * S.nx[o + i]! - sa * S.ny[o + i]!);
          if (a1 < a0) a1 += 2 * Math.PI;
          const steps = Math.max(1, Math.ceil(((a1 - a0) / (Math.PI / 2)) * ARC_STEPS));
          for (let s = 0; s <= steps; s++) {
            const t = a0 + ((a1 - a0) * s) / steps;
            pts.push(camera.toScreenX(vx + r * Math.cos(t)), camera.toScreenY(vy + r * Math.sin(t)));
          }
        } else {
          pts.push(camera.toScreenX(vx), camera.toScreenY(vy));
        }
      }
      // A copy: pixi keeps the array it is given until the frame is built, and `pts` is reused for the next shape.
      g.poly(pts.slice(), true);
      if (S.sensor[e] === 1) g.stroke({ width: 1.5, color, alpha: 0.8 });
      else g.fill({ color, alpha: 0.85 }).stroke({ width: 1.5, color: 0x1d2330, alpha: 0.9 });
      this.drawn++;
    }
  }

  /** Frees the Graphics. */
  destroy(): void {
    this.graphics.destroy();
  }
}
