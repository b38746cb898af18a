import { assertFinite, assertKnownKeys, assertNonNegative, assertPositive, describe } from '@bitphysics/physics/validate';

/**
 * The camera: the one place where metres become pixels. Physics is SI with y up; the screen is
 * CSS pixels with y down. A world point (x, y) in m lands on the screen at
 *
 *   sx = originX + x * pixelsPerMeter,   sy = originY - y * pixelsPerMeter
 *
 * (the minus sign is the y flip). No pixi and no DOM in here, so the mapping is testable anywhere.
 */

/** An axis-aligned rectangle in world coordinates, m. `maxX > minX` and `maxY > minY`. */
export interface WorldRect {
  /** Left edge, m. */
  minX: number;
  /** Bottom edge, m (y is up). */
  minY: number;
  /** Right edge, m. */
  maxX: number;
  /** Top edge, m. */
  maxY: number;
}

/** A mutable 2D point, used as an output parameter so conversions need not allocate. */
export interface Point2 {
  /** x, in the unit of the conversion's output (m or px). */
  x: number;
  /** y, in the unit of the conversion's output (m or px). */
  y: number;
}

/** Options of `new Camera`. Unknown fields are rejected. */
export interface CameraOptions {
  /**
   * Fixed scale, px/m, finite and > 0. Used when `view` is not given. Default 50 px/m.
   * When `view` is given the scale is computed from it (and recomputed on every resize).
   */
  pixelsPerMeter?: number;
  /**
   * World rectangle to fit into the screen (kept whole and centred, aspect ratio preserved, on
   * every resize). Default: none (fixed `pixelsPerMeter`, world origin at the bottom-left corner).
   */
  view?: WorldRect;
  /** Margin kept free around `view`, px, >= 0. Default 16 px. */
  padding?: number;
  /** Screen width, CSS px, > 0. Default 800. */
  width?: number;
  /** Screen height, CSS px, > 0. Default 600. */
  height?: number;
}

const CAMERA_OPTIONS = ['pixelsPerMeter', 'view', 'padding', 'width', 'height'] as const;

/**
 * Checks a world rectangle. @throws TypeError if `rect` is not an object with numeric minX, minY,
 * maxX, maxY; RangeError if a value is not finite or max <= min on an axis.
 */
export function assertWorldRect(where: string, name: string, rect: unknown): asserts rect is WorldRect {
  if (rect === null || typeof rect !== 'object') {
    throw new TypeError(`${where}: ${name} must be an object { minX, minY, maxX, maxY } in m, got ${describe(rect)}`);
  }
  const r = rect as Record<string, unknown>;
  for (const k of ['minX', 'minY', 'maxX', 'maxY']) assertFinite(where, `${name}.${k}`, r[k]);
  if (!((r.maxX as number) > (r.minX as number)) || !((r.maxY as number) > (r.minY as number))) {
    throw new RangeError(`${where}: ${name} must have maxX > minX and maxY > minY, got ${describe(rect)}`);
  }
}

/** Maps world metres (y up) to screen pixels (y down) and back; fits a world rectangle to the screen. */
export class Camera {
  /** Scale, px/m (> 0). Read-only from outside: change it with `setPixelsPerMeter` or `fit`. */
  pixelsPerMeter: number;
  /** Screen x of the world origin, CSS px. */
  originX = 0;
  /** Screen y of the world origin, CSS px. */
  originY = 0;
  /** Screen width, CSS px (> 0). Change with `resize`. */
  width: number;
  /** Screen height, CSS px (> 0). Change with `resize`. */
  height: number;
  /** Margin kept around a fitted view, px (>= 0). */
  padding: number;
  /**
   * Incremented on every change of scale, origin or screen size; layers that cache screen-space
   * geometry (walls) compare it to know when to redraw. Starts at 1.
   */
  version = 1;
  /** The fitted world rectangle, m, or null in fixed-scale mode. Change with `fit` or `setPixelsPerMeter`. */
  view: WorldRect | null = null;
  /** World point kept at the screen centre in fixed-scale mode, m. */
  private centerX = 0;
  private centerY = 0;

  /**
   * @throws TypeError on an unknown option or a value of the wrong type.
   * @throws RangeError on pixelsPerMeter, width or height <= 0, padding < 0, or a `view` with max <= min.
   */
  constructor(options: CameraOptions = {}) {
    const where = 'Camera';
    assertKnownKeys(where, options, CAMERA_OPTIONS);
    const ppm = options.pixelsPerMeter ?? 50;
    assertPositive(where, 'pixelsPerMeter', ppm);
    const width = options.width ?? 800;
    const height = options.height ?? 600;
    assertPositive(where, 'width', width);
    assertPositive(where, 'height', height);
    const padding = options.padding ?? 16;
    assertNonNegative(where, 'padding', padding);
    this.pixelsPerMeter = ppm;
    this.width = width;
    this.height = height;
    this.padding = padding;
    this.centerX = width / 2 / ppm;
    this.centerY = height / 2 / ppm;
    if (options.view !== undefined) {
      assertWorldRect(where, 'view', options.view);
      this.view = { minX: options.view.minX, minY: options.view.minY, maxX: options.view.maxX, maxY: options.view.maxY };
    }
    this.update();
  }

  /**
   * Sets the screen size (call it when the canvas is resized). Refits the view if there is one,
   * otherwise keeps the world point at the screen centre where it was.
   * @param width CSS px, > 0. @param height CSS px, > 0.
   * @throws TypeError | RangeError on a size that is not a finite number > 0.
   */
  resize(width: number, height: number): void {
    assertPositive('Camera.resize', 'width', width);
    assertPositive('Camera.resize', 'height', height);
    if (width === this.width && height === this.height) return;
    this.width = width;
    this.height = height;
    this.update();
  }

  /**
   * Fits `view` (m) into the screen, centred, aspect ratio kept, leaving `padding` px free on every
   * side; refits on every later resize.
   * @param padding px, >= 0; default the camera's current padding.
   * @throws TypeError | RangeError on a bad rectangle or padding.
   */
  fit(view: WorldRect, padding: number = this.padding): void {
    assertWorldRect('Camera.fit', 'view', view);
    assertNonNegative('Camera.fit', 'padding', padding);
    this.view = { minX: view.minX, minY: view.minY, maxX: view.maxX, maxY: view.maxY };
    this.padding = padding;
    this.update();
  }

  /**
   * Switches to a fixed scale of `pixelsPerMeter` px/m with the world point (centerX, centerY), m,
   * at the screen centre (default: the point there now). Stops fitting a view.
   * @throws TypeError | RangeError unless pixelsPerMeter is finite and > 0 and the centre finite.
   */
  setPixelsPerMeter(pixelsPerMeter: number, centerX?: number, centerY?: number): void {
    const where = 'Camera.setPixelsPerMeter';
    assertPositive(where, 'pixelsPerMeter', pixelsPerMeter);
    const cx = centerX ?? this.toWorldX(this.width / 2);
    const cy = centerY ?? this.toWorldY(this.height / 2);
    assertFinite(where, 'centerX', cx);
    assertFinite(where, 'centerY', cy);
    this.view = null;
    this.pixelsPerMeter = pixelsPerMeter;
    this.centerX = cx;
    this.centerY = cy;
    this.update();
  }

  /** Screen x, CSS px, of world x (m). */
  toScreenX(x: number): number {
    return this.originX + x * this.pixelsPerMeter;
  }

  /** Screen y, CSS px, of world y (m); y is flipped (world up is screen down). */
  toScreenY(y: number): number {
    return this.originY - y * this.pixelsPerMeter;
  }

  /** A world length (m) in CSS px. */
  toScreenLength(metres: number): number {
    return metres * this.pixelsPerMeter;
  }

  /** World x, m, of screen x (CSS px). */
  toWorldX(sx: number): number {
    return (sx - this.originX) / this.pixelsPerMeter;
  }

  /** World y, m, of screen y (CSS px). */
  toWorldY(sy: number): number {
    return (this.originY - sy) / this.pixelsPerMeter;
  }

  /**
   * Converts a screen point (CSS px, relative to the canvas' top-left corner) to world metres,
   * written into `out` (allocated if omitted) and returned.
   */
  screenToWorld(sx: number, sy: number, out: Point2 = { x: 0, y: 0 }): Point2 {
    out.x = this.toWorldX(sx);
    out.y = this.toWorldY(sy);
    return out;
  }

  /** Converts a world point (m) to screen CSS px, written into `out` (allocated if omitted) and returned. */
  worldToScreen(x: number, y: number, out: Point2 = { x: 0, y: 0 }): Point2 {
    out.x = this.toScreenX(x);
    out.y = this.toScreenY(y);
    return out;
  }

  /** The world rectangle (m) the screen shows, written into `out` (allocated if omitted) and returned. */
  visibleRect(out: WorldRect = { minX: 0, minY: 0, maxX: 0, maxY: 0 }): WorldRect {
    out.minX = this.toWorldX(0);
    out.maxX = this.toWorldX(this.width);
    out.minY = this.toWorldY(this.height);
    out.maxY = this.toWorldY(0);
    return out;
  }

  private update(): void {
    const v = this.view;
    if (v) {
      const w = v.maxX - v.minX,
        h = v.maxY - v.minY;
      let pad = this.padding;
      if (this.width - 2 * pad <= 0 || this.height - 2 * pad <= 0) pad = 0;
      this.pixelsPerMeter = Math.min((this.width - 2 * pad) / w, (this.height - 2 * pad) / h);
      this.centerX = (v.minX + v.maxX) / 2;
      this.centerY = (v.minY + v.maxY) / 2;
    }
    this.originX = this.width / 2 - this.centerX * this.pixelsPerMeter;
    this.originY = this.height / 2 + this.centerY * this.pixelsPerMeter;
    this.version++;
  }
}
