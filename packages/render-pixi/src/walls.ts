import type { PhysicsWorld } from '@bitphysics/physics';
import { query } from 'bitecs';
import { Graphics } from 'pixi.js';
import type { Camera } from './camera.js';

/**
 * Walls: static segments (entities with Segment, drawn as round-capped lines as thick as their
 * capsule, at least `minWidth` px, with their end points marked) and the boundary box (an outline
 * just outside its inner faces). One pixi Graphics, redrawn only when the camera, the boundary or
 * the set of segments changes (a cheap signature is compared every frame).
 */
export class WallLayer {
  /** The Graphics the walls are drawn into; sits under the trails and balls. */
  readonly graphics = new Graphics({ label: 'walls' });
  /** Colour of segments, 0xRRGGBB. */
  segmentColor: number;
  /** Colour of the boundary box, 0xRRGGBB. */
  boundaryColor: number;
  /** Thinnest a segment is drawn, CSS px (> 0). */
  minWidth = 3;
  /** Width of the boundary outline, CSS px (> 0). */
  boundaryWidth = 4;
  /** Segments drawn in the last redraw. */
  segments = 0;
  private terms: object[] = [];
  private signature = Number.NaN;
  private readonly boxSeen = new Float64Array(5);
  private cameraVersion = -1;

  /** @param segmentColor 0xRRGGBB. @param boundaryColor 0xRRGGBB. */
  constructor(segmentColor: number, boundaryColor: number) {
    this.segmentColor = segmentColor;
    this.boundaryColor = boundaryColor;
  }

  /** Binds to `world`; the next `update` redraws. */
  bind(world: PhysicsWorld): void {
    this.terms = [world.components.Segment];
    this.invalidate();
  }

  /** Forces a redraw on the next `update` (after a colour or width change). */
  invalidate(): void {
    this.signature = Number.NaN;
  }

  /** Redraws if the camera, the boundary or the segments changed since the last redraw. */
  update(world: PhysicsWorld, camera: Camera): void {
    const S = world.components.Segment;
    const segs = query(world, this.terms);
    const stamp = world.spawnStamp;
    // Signature of the segment set: count and a sum over (id, spawn stamp); segments never move.
    let sig = segs.length;
    for (let i = 0; i < segs.length; i++) {
      const e = segs[i]!;
      sig = (sig * 31 + e * 7919 + stamp[e]!) % 2147483647;
    }
    const box = world.collision.boundary;
    const seen = this.boxSeen;
    const boxChanged =
      seen[0] !== (box.enabled ? 1 : 0) ||
      seen[1] !== box.min[0] ||
      seen[2] !== box.min[1] ||
      seen[3] !== box.max[0] ||
      seen[4] !== box.max[1];
    if (sig === this.signature && !boxChanged && camera.version === this.cameraVersion) return;
    this.signature = sig;
    this.cameraVersion = camera.version;
    seen[0] = box.enabled ? 1 : 0;
    seen[1] = box.min[0]!;
    seen[2] = box.min[1]!;
    seen[3] = box.max[0]!;
    seen[4] = box.max[1]!;

    const g = this.graphics;
    g.clear();
    if (box.enabled) {
      const w = this.boundaryWidth;
      const x1 = camera.toScreenX(box.min[0]!) - w / 2,
        x2 = camera.toScreenX(box.max[0]!) + w / 2;
      const y1 = camera.toScreenY(box.max[1]!) - w / 2,
        y2 = camera.toScreenY(box.min[1]!) + w / 2;
      g.rect(x1, y1, x2 - x1, y2 - y1).stroke({ width: w, color: this.boundaryColor, alpha: 1, join: 'miter' });
    }
    for (let i = 0; i < segs.length; i++) {
      const e = segs[i]!;
      const ax = camera.toScreenX(S.ax[e]!),
        ay = camera.toScreenY(S.ay[e]!);
      const bx = camera.toScreenX(S.bx[e]!),
        by = camera.toScreenY(S.by[e]!);
      const width = Math.max(this.minWidth, 2 * camera.toScreenLength(S.radius[e]!));
      g.moveTo(ax, ay).lineTo(bx, by).stroke({ width, color: this.segmentColor, cap: 'round' });
      const dot = Math.max(2, width * 0.35);
      g.circle(ax, ay, dot).circle(bx, by, dot).fill({ color: 0xffffff, alpha: 0.55 });
    }
    this.segments = segs.length;
  }

  /** Releases the Graphics. */
  destroy(): void {
    this.graphics.destroy();
  }
}
