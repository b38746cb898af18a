import { isAlive, type PhysicsWorld, slotOf } from '@bitphysics/physics';
import { Graphics } from 'pixi.js';
import type { Camera } from './camera.js';

/** Options of `RopeLayer`. */
export interface RopeLayerOptions {
  /** Line colour, 0xRRGGBB. Default 0xd9b38c (hemp). */
  color?: number;
  /** Line width, m (drawn at least 1.5 px). Default 0.05 m. */
  width?: number;
  /** Fixed points drawn before the first and after the last body (pins), m; null for none. */
  start?: readonly [number, number] | null;
  end?: readonly [number, number] | null;
  /** Segments of the smooth curve between two bodies, integer >= 1. Default 6. */
  smoothing?: number;
  /**
   * The links between consecutive drawn points (joint handles, e.g. `createRope`'s `joints` and a bob's
   * link): links[k] joins point k and point k + 1 of the drawn sequence (`start`, the bodies, `end`).
   * Where a link has been removed (a cut rope) the line breaks there, so the two pieces are drawn as
   * two ropes. Absent: only removed bodies break the line.
   */
  links?: ArrayLike<number>;
}

/**
 * Draws a rope (a chain of bodies, e.g. from `createRope`) as one smooth line: a centripetal-free
 * uniform Catmull-Rom spline through the bodies' interpolated positions (and its pins). Where a body
 * has been removed, or a link given in `options.links` (a cut), the line breaks in two. Reads only
 * Position and PreviousPosition (and whether the bodies and links are alive).
 */
export class RopeLayer {
  /** The pixi object to add to a container (e.g. the world renderer's root). */
  readonly graphics = new Graphics({ label: 'rope' });
  /** Pieces drawn by the last `update`: 1 for a whole rope, 2 after one cut (pieces of fewer than 2 points are not drawn). */
  pieces = 0;
  private readonly xs: number[] = [];
  private readonly ys: number[] = [];

  /**
   * @param bodies the rope's body handles in order.
   * @throws RangeError on a smoothing that is not an integer >= 1 or a negative width.
   */
  constructor(
    private readonly world: PhysicsWorld,
    private readonly bodies: ArrayLike<number>,
    private readonly options: RopeLayerOptions = {},
  ) {
    const s = options.smoothing ?? 6;
    if (!Number.isInteger(s) || s < 1) throw new RangeError(`RopeLayer: smoothing must be an integer >= 1, got ${String(s)}`);
    if (options.width !== undefined && !(options.width >= 0))
      throw new RangeError(`RopeLayer: width must be >= 0, got ${String(options.width)}`);
  }

  /** Redraws the rope for interpolation factor `alpha` in [0, 1] through `camera`. */
  update(camera: Camera, alpha: number): void {
    const g = this.graphics;
    g.clear();
    const P = this.world.components.Position,
      O = this.world.components.PreviousPosition;
    const { xs, ys } = this;
    xs.length = 0;
    ys.length = 0;
    this.pieces = 0;
    const flush = (): void => {
      this.stroke(camera, xs, ys);
      xs.length = 0;
      ys.length = 0;
    };
    const start = this.options.start,
      end = this.options.end,
      links = this.options.links;
    // Point k of the drawn sequence (start, bodies, end); a dead body or a dead link before it breaks the line.
    let k = 0;
    const linked = (): boolean => links === undefined || k === 0 || k - 1 >= links.length || isAlive(this.world, links[k - 1]!);
    if (start) {
      xs.push(start[0]);
      ys.push(start[1]);
      k++;
    }
    for (let i = 0; i < this.bodies.length; i++, k++) {
      const h = this.bodies[i]!;
      if (!isAlive(this.world, h)) {
        flush();
        continue;
      }
      if (!linked()) flush();
      const e = slotOf(h);
      xs.push(O.x[e]! + (P.x[e]! - O.x[e]!) * alpha);
      ys.push(O.y[e]! + (P.y[e]! - O.y[e]!) * alpha);
    }
    if (end && (this.bodies.length === 0 || isAlive(this.world, this.bodies[this.bodies.length - 1]!))) {
      if (!linked()) flush();
      xs.push(end[0]);
      ys.push(end[1]);
    }
    flush();
  }

  private stroke(camera: Camera, xs: number[], ys: number[]): void {
    const n = xs.length;
    if (n < 2) return;
    this.pieces++;
    const g = this.graphics;
    const s = this.options.smoothing ?? 6;
    const sx = (x: number) => camera.toScreenX(x),
      sy = (y: number) => camera.toScreenY(y);
    g.moveTo(sx(xs[0]!), sy(ys[0]!));
    for (let i = 0; i + 1 < n; i++) {
      const x0 = xs[Math.max(0, i - 1)]!,
        y0 = ys[Math.max(0, i - 1)]!,
        x1 = xs[i]!,
        y1 = ys[i]!;
      const x2 = xs[i + 1]!,
        y2 = ys[i + 1]!,
        x3 = xs[Math.min(n - 1, i + 2)]!,
        y3 = ys[Math.min(n - 1, i + 2)]!;
      for (let k = 1; k <= s; k++) {
        const t = k / s,
          t2 = t * t,
          t3 = t2 * t;
        // Catmull-Rom: 0.5 (2 p1 + (p2 - p0) t + (2 p0 - 5 p1 + 4 p2 - p3) t^2 + (3 p1 - p0 - 3 p2 + p3) t^3).
        const x = 0.5 * (2 * x1 + (x2 - x0) * t + (2 * x0 - 5 * x1 + 4 * x2 - x3) * t2 + (3 * x1 - x0 - 3 * x2 + x3) * t3);
        const y = 0.5 * (2 * y1 + (y2 - y0) * t + (2 * y0 - 5 * y1 + 4 * y2 - y3) * t2 + (3 * y1 - y0 - 3 * y2 + y3) * t3);
        g.lineTo(sx(x), sy(y));
      }
    }
    g.stroke({
      width: Math.max(1.5, camera.toScreenLength(this.options.width ?? 0.05)),
      color: this.options.color ?? 0xd9b38c,
      cap: 'round',
      join: 'round',
    });
  }

  /** Removes and frees the graphics. */
  destroy(): void {
    this.graphics.destroy();
  }
}
