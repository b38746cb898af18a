import { describe, expect, it } from 'vitest';
import { collideHalfPlane, collideShapes, createManifold } from '../../packages/physics/src/collision/narrowphase/manifold-2d.js';
import { makeBox, makeCapsule, makeCircle, makePolygon } from '../../packages/physics/src/shapes/geometry-2d.js';
import { shapeMassProperties } from '../../packages/physics/src/shapes/mass-2d.js';

// Hand-computed cases. Positions and separations are exact sums of the inputs, so 1e-12 allows
// only rounding.
const EPS = 1e-12;

describe('shape geometry', () => {
  it('rejects bad polygons, naming the parameter and value', () => {
    expect(() =>
      makePolygon('addShape', [
        [0, 0],
        [1, 0],
      ]),
    ).toThrow(/addShape: vertices must hold 3 to 8 points, got 2/);
    expect(() =>
      makePolygon('addShape', [
        [0, 0],
        [2, 0],
        [1, 0.2],
        [1, 2],
        [0, 2],
      ]),
    ).toThrow(/vertices must form a convex polygon, got one that is not convex at \[1,0.2\]/);
    expect(() =>
      makePolygon('addShape', [
        [0, 0],
        [1, 0],
        [2, 0],
        [1, 1],
      ]),
    ).toThrow(/three collinear vertices/);
    expect(() =>
      makePolygon('addShape', [
        [0, 0],
        [1, 0],
        [1, 0],
        [0, 1],
      ]),
    ).toThrow(/vertices must be distinct/);
    expect(() =>
      makePolygon(
        'addShape',
        [
          [0, 0],
          [1, 0],
          [0, 1],
        ],
        -1,
      ),
    ).toThrow(/radius must be >= 0, got -1/);
    expect(() => makeBox('addShape', 0, 1)).toThrow(/addShape: halfExtents\[0\] must be > 0, got 0/);
    expect(() => makeCapsule('addShape', 0, 0, 0, 0, 1)).toThrow(/center1 and center2 must differ/);
  });
  it('turns a clockwise polygon counter-clockwise, with outward normals', () => {
    const g = makePolygon('t', [
      [0, 0],
      [0, 1],
      [1, 0],
    ]);
    // Counter-clockwise: (0,0) (1,0) (0,1) after reversal of the order.
    expect([g.vx[0], g.vy[0], g.vx[1], g.vy[1], g.vx[2], g.vy[2]]).toEqual([1, 0, 0, 1, 0, 0]);
    for (let i = 0; i < 3; i++) {
      // Every other vertex lies behind each edge's normal.
      for (let j = 0; j < 3; j++) expect(g.nx[i]! * (g.vx[j]! - g.vx[i]!) + g.ny[i]! * (g.vy[j]! - g.vy[i]!)).toBeLessThanOrEqual(EPS);
    }
  });
});

describe('mass properties (closed forms)', () => {
  it('box: m = rho w h, I = m (w^2 + h^2) / 12', () => {
    const p = shapeMassProperties(makeBox('t', 1, 0.5, 3, -2), 3);
    expect(p.mass).toBeCloseTo(6, 12);
    expect(p.inertia).toBeCloseTo((6 * (4 + 1)) / 12, 12);
    expect(p.cx).toBeCloseTo(3, 12);
    expect(p.cy).toBeCloseTo(-2, 12);
  });
  it('circle: m = rho pi r^2, I = m r^2 / 2', () => {
    const p = shapeMassProperties(makeCircle('t', 2, 1, 1), 0.5);
    expect(p.mass).toBeCloseTo(0.5 * Math.PI * 4, 12);
    expect(p.inertia).toBeCloseTo(0.5 * p.mass * 4, 12);
    expect(p.cx).toBeCloseTo(1, 12);
  });
  it('capsule: a 2r x L rectangle plus two half discs (parallel axis through their centroids)', () => {
    const L = 2,
      r = 0.5,
      rho = 2;
    const p = shapeMassProperties(makeCapsule('t', -1, 0, 1, 0, r), rho);
    const mRect = rho * L * 2 * r,
      mHalf = (rho * Math.PI * r * r) / 2;
    const d = (4 * r) / (3 * Math.PI); // centroid of a half disc from its flat side
    const iHalf = (mHalf * r * r) / 2 - mHalf * d * d + mHalf * (L / 2 + d) ** 2;
    expect(p.mass).toBeCloseTo(mRect + 2 * mHalf, 12);
    expect(p.inertia).toBeCloseTo((mRect * (L * L + 4 * r * r)) / 12 + 2 * iHalf, 12);
  });
  it('rounded box: area 4 hx hy + perimeter r + pi r^2; a triangle about its centroid', () => {
    const p = shapeMassProperties(makeBox('t', 1, 1, 0, 0, 0, 0.1), 1);
    expect(p.area).toBeCloseTo(4 + 8 * 0.1 + Math.PI * 0.01, 12);
    // Right triangle, legs 3 and 3: centroid (1, 1), polar I_c = m (a^2 + b^2 + c^2) / 36 over its sides (a standard table).
    const t = shapeMassProperties(
      makePolygon('t', [
        [0, 0],
        [3, 0],
        [0, 3],
      ]),
      2,
    );
    expect(t.mass).toBeCloseTo(9, 12);
    expect(t.cx).toBeCloseTo(1, 12);
    expect(t.cy).toBeCloseTo(1, 12);
    expect(t.inertia).toBeCloseTo((9 * (9 + 9 + 18)) / 36, 12);
  });
});

describe('manifolds (hand-computed)', () => {
  const m = createManifold();
  it('box on box: two points at the clipped face, separation -0.1', () => {
    const A = makeBox('t', 1, 1),
      B = makeBox('t', 0.5, 0.5);
    collideShapes(m, A, 0, 0, 1, 0, B, 0, 1.4, 1, 0, 0.1);
    expect(m.count).toBe(2);
    expect(m.nx).toBeCloseTo(0, 12);
    expect(m.ny).toBeCloseTo(1, 12);
    const xs = [m.px[0]!, m.px[1]!].sort((a, b) => a - b);
    expect(xs[0]).toBeCloseTo(-0.5, 12);
    expect(xs[1]).toBeCloseTo(0.5, 12);
    expect(m.py[0]).toBeCloseTo(0.95, 12);
    expect(m.separation[0]).toBeCloseTo(-0.1, 12);
    expect(m.separation[1]).toBeCloseTo(-0.1, 12);
    // The same pair the other way round: the normal flips, the points stay.
    collideShapes(m, B, 0, 1.4, 1, 0, A, 0, 0, 1, 0, 0.1);
    expect(m.count).toBe(2);
    expect(m.ny).toBeCloseTo(-1, 12);
    expect(m.separation[0]).toBeCloseTo(-0.1, 12);
  });
  it('box on a turned box: clipped to the overlap of the faces', () => {
    // B: unit half extents turned by 90 degrees (same square), shifted right by 1.5: the faces overlap on x in [0.5, 1].
    const A = makeBox('t', 1, 1),
      B = makeBox('t', 1, 1);
    collideShapes(m, A, 0, 0, 1, 0, B, 1.5, 1.95, 0, 1, 0.1);
    expect(m.count).toBe(2);
    expect(m.ny).toBeCloseTo(1, 12);
    const xs = [m.px[0]!, m.px[1]!].sort((a, b) => a - b);
    expect(xs[0]).toBeCloseTo(0.5, 12);
    expect(xs[1]).toBeCloseTo(1, 12);
    expect(m.separation[0]).toBeCloseTo(-0.05, 12);
  });
  it('box standing on its corner: one point at the corner', () => {
    const A = makeBox('t', 5, 1),
      B = makeBox('t', 0.5, 0.5, 0, 0, 0);
    const c = Math.cos(Math.PI / 4),
      s = Math.sin(Math.PI / 4);
    const y = 1 + Math.SQRT1_2 - 0.01; // corner 0.01 below A's top
    collideShapes(m, A, 0, 0, 1, 0, B, 0, y, c, s, 0.05);
    expect(m.count).toBe(1);
    expect(m.ny).toBeCloseTo(1, 12);
    expect(m.separation[0]).toBeCloseTo(-0.01, 12);
    expect(m.px[0]).toBeCloseTo(0, 12);
    expect(m.py[0]).toBeCloseTo(0.995, 12);
  });
  it('polygon-circle: face and vertex regions', () => {
    const A = makeBox('t', 1, 1),
      C = makeCircle('t', 0.5);
    collideShapes(m, A, 0, 0, 1, 0, C, 0.3, 1.4, 1, 0, 0.1);
    expect(m.count).toBe(1);
    expect(m.ny).toBeCloseTo(1, 12);
    expect(m.separation[0]).toBeCloseTo(-0.1, 12);
    expect(m.px[0]).toBeCloseTo(0.3, 12);
    expect(m.py[0]).toBeCloseTo(0.95, 12);
    collideShapes(m, A, 0, 0, 1, 0, C, 2, 2, 1, 0, 1);
    expect(m.count).toBe(1);
    expect(m.nx).toBeCloseTo(Math.SQRT1_2, 12);
    expect(m.ny).toBeCloseTo(Math.SQRT1_2, 12);
    expect(m.separation[0]).toBeCloseTo(Math.SQRT2 - 0.5, 12);
    // Circle as A: normal reversed.
    collideShapes(m, C, 0.3, 1.4, 1, 0, A, 0, 0, 1, 0, 0.1);
    expect(m.ny).toBeCloseTo(-1, 12);
  });
  it('capsule-capsule (parallel, two points), capsule-circle, capsule end on a box (round)', () => {
    const K = makeCapsule('t', -1, 0, 1, 0, 0.25);
    collideShapes(m, K, 0, 0, 1, 0, K, 0.5, 0.45, 1, 0, 0.1);
    expect(m.count).toBe(2);
    expect(m.ny).toBeCloseTo(1, 12);
    expect(m.separation[0]).toBeCloseTo(-0.05, 12);
    expect(m.separation[1]).toBeCloseTo(-0.05, 12);
    const xs = [m.px[0]!, m.px[1]!].sort((a, b) => a - b);
    expect(xs[0]).toBeCloseTo(-0.5, 12);
    expect(xs[1]).toBeCloseTo(1, 12);
    collideShapes(m, K, 0, 0, 1, 0, makeCircle('t', 0.5), 1.5, 0, 1, 0, 0.1);
    expect(m.count).toBe(1);
    expect(m.nx).toBeCloseTo(1, 12);
    expect(m.separation[0]).toBeCloseTo(-0.25, 12);
    // A capsule standing upright on a box: its lower end cap is round.
    const U = makeCapsule('t', 0, -1, 0, 1, 0.25);
    collideShapes(m, makeBox('t', 2, 1), 0, 0, 1, 0, U, 0, 2.2, 1, 0, 0.1);
    expect(m.count).toBe(1);
    expect(m.ny).toBeCloseTo(1, 12);
    expect(m.separation[0]).toBeCloseTo(-0.05, 12);
  });
  it('apart: speculative points are kept within the margin only', () => {
    const A = makeBox('t', 1, 1),
      B = makeBox('t', 0.5, 0.5);
    collideShapes(m, A, 0, 0, 1, 0, B, 0, 1.6, 1, 0, 0.05);
    expect(m.count).toBe(0);
    collideShapes(m, A, 0, 0, 1, 0, B, 0, 1.6, 1, 0, 0.2);
    expect(m.count).toBe(2);
    expect(m.separation[0]).toBeCloseTo(0.1, 12);
  });
  it('half-plane: a box tilted on the floor touches with its lowest corner, a flat one with two', () => {
    const B = makeBox('t', 0.5, 0.5);
    collideHalfPlane(m, 0, 1, 0, B, 0, 0.49, 1, 0, 0.05, 0);
    expect(m.count).toBe(2);
    expect(m.separation[0]).toBeCloseTo(-0.01, 12);
    expect(m.py[0]).toBeCloseTo(-0.005, 12);
    const c = Math.cos(0.3),
      s = Math.sin(0.3);
    collideHalfPlane(m, 0, 1, 0, B, 0, 0.6, c, s, 0.05, 0);
    expect(m.count).toBe(1);
    expect(m.separation[0]).toBeCloseTo(0.6 - 0.5 * (c + s), 12);
  });
  it('feature ids stay the same as a box slides along a face', () => {
    const A = makeBox('t', 3, 1),
      B = makeBox('t', 0.5, 0.5);
    collideShapes(m, A, 0, 0, 1, 0, B, 0, 1.49, 1, 0, 0.1);
    const ids = [m.id[0], m.id[1]];
    collideShapes(m, A, 0, 0, 1, 0, B, 0.7, 1.48, 1, 0, 0.1);
    expect([m.id[0], m.id[1]]).toEqual(ids);
  });
});
