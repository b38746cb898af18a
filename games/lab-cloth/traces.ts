/**
 * A hand's traces of a printed line, headless, for checking the fit (pattern.ts) against cuts a
 * player makes: a careful one keeps close to the line, a careless one strays out, wobbles, and cuts
 * across the sharp corners (a star's points). Used by the lab's tests and scripts/lab-cloth-cuts.mjs.
 */
import { type Cloth, type PhysicsWorld, slotOf } from '@bitphysics/physics';
import { cutAlong } from './cut';
import { sheetGrid } from './scene';

/** How a trace strays from its line (all m, >= 0 but `offset`). */
export interface TraceStyle {
  /** How far out of the line the whole trace runs (negative: inside), m. */
  offset?: number;
  /** RMS of a smooth wobble across the line (2 to 9 waves a loop), m. */
  wobble?: number;
  /**
   * How far back from each sharp corner (convex, inside angle under 100 degrees: a star's points, a
   * pane's corners) the trace cuts across it, m along each side (at most 0.9 of the side).
   */
  chop?: number;
  /** Seed of the wobble's waves (an integer). */
  seed?: number;
  /**
   * Depth of a V-shaped notch cut into the shape (a slip of the scissors), m: the trace dips this far
   * inside the line over as far each side along it, at `at` of the way round. 0: none.
   */
  notch?: number;
  /**
   * Length of a stray slit cut straight into the shape from the line (the scissors run in and come
   * back out the same way), m, at `at` of the way round. 0: none.
   */
  slit?: number;
  /** Where round the trace the notch or the slit is, a fraction of its points in [0, 1). Default 0.3. */
  at?: number;
}

/** A small xorshift generator of numbers in [0, 1) from an integer seed. */
function random(seed: number): () => number {
  let s = seed >>> 0 || 1;
  return () => {
    s ^= s << 13;
    s >>>= 0;
    s ^= s >> 17;
    s ^= s << 5;
    s >>>= 0;
    return s / 2 ** 32;
  };
}

/** Twice the signed area of the closed polygon `poly` (x, y interleaved). */
function area2(poly: readonly number[]): number {
  let a = 0;
  const n = poly.length / 2;
  for (let i = 0, j = n - 1; i < n; j = i++) a += poly[2 * j]! * poly[2 * i + 1]! - poly[2 * i]! * poly[2 * j + 1]!;
  return a;
}

/**
 * A trace of the closed line `outline` (sheet coordinates, m, x and y interleaved) in `style`: points
 * about 1 cm apart along it, a closed loop (the last point is not the first repeated).
 * @throws RangeError if the outline has fewer than 3 corners or a length of the style is negative (but `offset`) or not finite.
 */
export function traceLine(outline: readonly number[], style: TraceStyle = {}): number[] {
  const { offset = 0, wobble = 0, chop = 0, seed = 1, notch = 0, slit = 0, at: where = 0.3 } = style;
  if (outline.length < 6 || outline.length % 2)
    throw new RangeError(`traceLine: outline needs 3 or more corners (x, y pairs), got ${outline.length} numbers`);
  for (const [name, v] of [
    ['wobble', wobble],
    ['chop', chop],
    ['notch', notch],
    ['slit', slit],
  ] as const)
    if (!(v >= 0) || !Number.isFinite(v)) throw new RangeError(`traceLine: ${name} must be a finite number >= 0 m, got ${v}`);
  if (!Number.isFinite(offset)) throw new RangeError(`traceLine: offset must be finite, got ${offset}`);
  if (!(where >= 0 && where < 1)) throw new RangeError(`traceLine: at must be in [0, 1), got ${where}`);
  const sign = Math.sign(area2(outline)) || 1;
  const n = outline.length / 2;
  const at = (k: number): [number, number] => [outline[2 * ((k + n) % n)]!, outline[2 * ((k + n) % n) + 1]!];
  // Cut across the sharp corners.
  const corners: number[] = [];
  for (let k = 0; k < n; k++) {
    const [px, py] = at(k - 1),
      [x, y] = at(k),
      [qx, qy] = at(k + 1);
    const ax = px - x,
      ay = py - y,
      bx = qx - x,
      by = qy - y;
    const la = Math.hypot(ax, ay),
      lb = Math.hypot(bx, by);
    // A convex corner turns the way the outline winds; a sharp one has an inside angle under 100 degrees.
    const convex = sign * ((x - px) * (qy - y) - (y - py) * (qx - x)) > 0;
    if (chop > 0 && convex && la > 0 && lb > 0 && (ax * bx + ay * by) / (la * lb) > Math.cos((100 * Math.PI) / 180)) {
      const ta = Math.min(chop, 0.9 * la) / la,
        tb = Math.min(chop, 0.9 * lb) / lb;
      corners.push(x + ax * ta, y + ay * ta, x + bx * tb, y + by * tb);
    } else corners.push(x, y);
  }
  // Points about 1 cm apart.
  const m = corners.length / 2;
  const pts: number[] = [];
  for (let i = 0; i < m; i++) {
    const j = (i + 1) % m;
    const x = corners[2 * i]!,
      y = corners[2 * i + 1]!,
      dx = corners[2 * j]! - x,
      dy = corners[2 * j + 1]! - y;
    const steps = Math.max(1, Math.ceil(Math.hypot(dx, dy) / 0.01));
    for (let t = 0; t < steps; t++) pts.push(x + (dx * t) / steps, y + (dy * t) / steps);
  }
  // Moved along the outward normal (the direction over 8 cm of the trace): the offset and the wobble.
  const rand = random(seed);
  const waves = Array.from({ length: 4 }, () => ({ f: 2 + Math.floor(rand() * 8), phase: rand() * 2 * Math.PI, a: 0.5 + rand() }));
  const rms = Math.sqrt(waves.reduce((s, w) => s + (w.a * w.a) / 2, 0));
  const count = pts.length / 2;
  const k0 = Math.floor(where * count);
  const out: number[] = [];
  /** The slit's points (in, then back out), spliced in at k0. */
  let slitPoints: number[] = [];
  for (let k = 0; k < count; k++) {
    const a = (k - 4 + count) % count,
      b = (k + 4) % count;
    let tx = pts[2 * b]! - pts[2 * a]!,
      ty = pts[2 * b + 1]! - pts[2 * a + 1]!;
    const l = Math.hypot(tx, ty) || 1;
    tx /= l;
    ty /= l;
    const u = k / count;
    let w = 0;
    for (const v of waves) w += v.a * Math.sin(2 * Math.PI * v.f * u + v.phase);
    // The notch: a V into the shape, its sides about 1 cm apart per point (the points' spacing).
    const along = Math.min(Math.abs(k - k0), count - Math.abs(k - k0)) * 0.01;
    const d = offset + (wobble * w) / rms - (notch > 0 ? notch * Math.max(0, 1 - along / notch) : 0);
    // The outward normal: the tangent turned a quarter against the winding.
    const x = pts[2 * k]! + sign * ty * d,
      y = pts[2 * k + 1]! - sign * tx * d;
    out.push(x, y);
    if (k === k0 && slit > 0) {
      const steps = Math.max(1, Math.ceil(slit / 0.01));
      const go: number[] = [];
      for (let i = 1; i <= steps; i++) go.push(x - (sign * ty * slit * i) / steps, y + (sign * tx * slit * i) / steps);
      const back: number[] = [];
      for (let i = steps - 1; i >= 0; i--) back.push(x - (sign * ty * slit * i) / steps, y + (sign * tx * slit * i) / steps);
      slitPoints = [...go, ...back];
    }
  }
  if (slitPoints.length > 0) out.splice(2 * k0 + 2, 0, ...slitPoints);
  return out;
}

/**
 * Where the sheet's point (x, y) (sheet coordinates: m from its left edge and down from its top, at
 * rest) is now in the world, m: its grid cell's corners interpolated, as the printed line moves with the cloth.
 */
export function onSheet(world: PhysicsWorld, cloth: Cloth, x: number, y: number): [number, number] {
  const { spacing } = sheetGrid(cloth.columns);
  const C = cloth.columns;
  const c = Math.max(0, Math.min(C - 2, Math.floor(x / spacing))),
    r = Math.max(0, Math.min(cloth.rows - 2, Math.floor(y / spacing)));
  const u = x / spacing - c,
    v = y / spacing - r;
  const P = world.components.Position;
  let wx = 0,
    wy = 0;
  for (const [i, j, w] of [
    [0, 0, (1 - u) * (1 - v)],
    [1, 0, u * (1 - v)],
    [0, 1, (1 - u) * v],
    [1, 1, u * v],
  ] as const) {
    const e = slotOf(cloth.points[(r + j) * C + c + i]!);
    wx += w * P.x[e]!;
    wy += w * P.y[e]!;
  }
  return [wx, wy];
}

/**
 * Cuts the sheet along the closed trace `path` (sheet coordinates, as traceLine) as the sheet lies
 * now, and pushes the trace to `marks` if given (as ScissorsStroke does: Challenge.marks). @returns links cut.
 */
export function cutTrace(world: PhysicsWorld, cloth: Cloth, path: readonly number[], marks?: number[]): number {
  const n = path.length / 2;
  if (marks) for (let k = 0; k < path.length; k++) marks.push(path[k]!);
  // Cut in chords half a spacing long or more (a step of the cut scans every link; a chord 6 cm
  // long strays 1 mm from a circle of the lab's 0.46 m).
  const step = sheetGrid(cloth.columns).spacing / 2;
  let cut = 0;
  let k0 = 0;
  let from = onSheet(world, cloth, path[0]!, path[1]!);
  for (let k = 1; k <= n; k++) {
    const j = k % n;
    if (k < n && Math.hypot(path[2 * j]! - path[2 * k0]!, path[2 * j + 1]! - path[2 * k0 + 1]!) < step) continue;
    const to = onSheet(world, cloth, path[2 * j]!, path[2 * j + 1]!);
    cut += cutAlong(world, from[0], from[1], to[0], to[1]).length / 2;
    from = to;
    k0 = j;
  }
  return cut;
}
