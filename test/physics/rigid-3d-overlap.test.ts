import {
  addBody,
  addPlane,
  addShape3D,
  addTriangleMesh3D,
  createPhysicsWorld,
  overlapAABB3D,
  overlapPoint3D,
  type PhysicsWorld,
  Rng,
  rayCast3D,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/**
 * 3D point and box queries, and the exact cylinder ray cast, against geometry worked out here by
 * other means: a rotation matrix built from the quaternion (not the library's quaternion rotation), a
 * cylinder's and capsule's distance formulas, an octahedron's |x| + |y| + |z| <= 1. Points are put
 * 1e-9 of the size inside and outside each surface: the queries' arithmetic errs by ~1e-15 m, so a
 * wrong side of 1e-9 is a wrong answer, not rounding.
 */

function world3(): PhysicsWorld {
  return createPhysicsWorld({ dimensions: 3, gravity: [0, 0, 0], sleep: false });
}

/** Row-major rotation matrix of the unit quaternion (x, y, z, w) (the textbook formula, written out). */
function matrix(q: readonly number[]): number[] {
  const [x, y, z, w] = q as [number, number, number, number];
  return [
    1 - 2 * (y * y + z * z),
    2 * (x * y - z * w),
    2 * (x * z + y * w),
    2 * (x * y + z * w),
    1 - 2 * (x * x + z * z),
    2 * (y * z - x * w),
    2 * (x * z - y * w),
    2 * (y * z + x * w),
    1 - 2 * (x * x + y * y),
  ];
}
const apply = (R: number[], v: readonly number[]): number[] =>
  [0, 1, 2].map((i) => R[3 * i]! * v[0]! + R[3 * i + 1]! * v[1]! + R[3 * i + 2]! * v[2]!);
const unit = (v: number[]): number[] => {
  const l = Math.hypot(v[0]!, v[1]!, v[2]!);
  return v.map((c) => c / l);
};
const axisAngle = (axis: number[], angle: number): number[] => {
  const u = unit(axis),
    s = Math.sin(angle / 2);
  return [u[0]! * s, u[1]! * s, u[2]! * s, Math.cos(angle / 2)];
};

describe("overlapPoint3D against each shape's own geometry", () => {
  test('points 1e-9 inside and outside the surface of a turned box, sphere, capsule and cylinder', () => {
    const q = axisAngle([1, 2, 3], 0.7),
      R = matrix(q),
      c = [2, -1, 3];
    const at = (local: number[]): number[] => apply(R, local).map((v, i) => v + c[i]!);
    const cases: Array<{ shape: Parameters<typeof addShape3D>[2]; surface: number[][] }> = [
      // Each: points on the surface, in the shape's frame, with the outward direction implied (centre to point).
      {
        shape: { type: 'box', halfExtents: [0.5, 1, 1.5] },
        surface: [
          [0.5, 0.2, -0.3],
          [0.1, 1, 1.2],
          [-0.4, -0.9, -1.5],
        ],
      },
      { shape: { type: 'sphere', radius: 0.8 }, surface: [unit([1, 1, 1]).map((v) => 0.8 * v), [0, -0.8, 0]] },
      {
        shape: { type: 'capsule', radius: 0.4, halfHeight: 1 },
        surface: [
          [0.4, 0.5, 0],
          [0, 1.4, 0],
          [0, -1 - 0.4 * Math.SQRT1_2, 0.4 * Math.SQRT1_2],
        ],
      },
      {
        shape: { type: 'cylinder', radius: 0.6, halfHeight: 0.9 },
        surface: [
          [0.6 * Math.cos(0.3), 0.1, 0.6 * Math.sin(0.3)],
          [0.2, 0.9, -0.1],
          [0.6 * Math.cos(Math.PI / 16), -0.5, 0.6 * Math.sin(Math.PI / 16)],
        ],
      },
    ];
    for (const { shape, surface } of cases) {
      const w = world3();
      const body = addBody(w, { position: c, orientation: q, static: true });
      const e = addShape3D(w, body, shape);
      for (const p of surface) {
        expect(overlapPoint3D(w, at(p.map((v) => v * (1 - 1e-9))))).toEqual([e]);
        expect(overlapPoint3D(w, at(p.map((v) => v * (1 + 1e-9))))).toEqual([]);
      }
    }
    // The cylinder is the round one: a point between the 16-sided prism the solver uses and the
    // circle (on the circle, halfway between two of the prism's corners) is inside.
    const w = world3();
    const body = addBody(w, { position: c, orientation: q, static: true });
    const cyl = addShape3D(w, body, { type: 'cylinder', radius: 1, halfHeight: 1 });
    const mid = Math.PI / 16;
    expect(overlapPoint3D(w, at([Math.cos(mid) * (1 - 1e-6), 0, Math.sin(mid) * (1 - 1e-6)]))).toEqual([cyl]);
  });

  test('2,000 random points in a turned octahedron hull agree with |x| + |y| + |z| <= 1 in its frame; balls and planes too', () => {
    const world = world3();
    const q = axisAngle([-1, 0.5, 2], 1.1),
      R = matrix(q),
      c = [0.5, 4, -2];
    const body = addBody(world, { position: c, orientation: q, static: true });
    const hull = addShape3D(world, body, {
      type: 'hull',
      vertices: [
        [1, 0, 0],
        [-1, 0, 0],
        [0, 1, 0],
        [0, -1, 0],
        [0, 0, 1],
        [0, 0, -1],
      ],
    });
    const ball = addBody(world, { position: [10, 0, 0], radius: 0.5, mass: 1 });
    const ground = addPlane(world, { normal: [0, 1, 0], point: [0, -3, 0] });
    const rng = new Rng(7),
      random = (): number => rng.next();
    let inside = 0;
    for (let i = 0; i < 2000; i++) {
      const local = [0, 1, 2].map(() => 2.4 * random() - 1.2);
      const l1 = Math.abs(local[0]!) + Math.abs(local[1]!) + Math.abs(local[2]!);
      if (Math.abs(l1 - 1) < 1e-9) continue; // on the surface: either answer is right
      const p = apply(R, local).map((v, k) => v + c[k]!);
      const want = l1 < 1;
      if (want) inside++;
      expect(overlapPoint3D(world, p)).toEqual(want ? [hull] : []);
    }
    expect(inside).toBeGreaterThan(100); // the sample reaches inside (1/3 / 13.8 of the cube is the octahedron)
    expect(overlapPoint3D(world, [10, 0.5 * (1 - 1e-9), 0])).toEqual([ball]);
    expect(overlapPoint3D(world, [10, 0.5 * (1 + 1e-9), 0])).toEqual([]);
    // A plane is solid below its surface (against its normal).
    expect(overlapPoint3D(world, [0, -3 - 1e-9, 0])).toEqual([ground]);
    expect(overlapPoint3D(world, [0, -3 + 1e-9, 0])).toEqual([]);
  });
});

describe('overlapAABB3D: tight boxes of turned shapes', () => {
  test('a box turned 45 deg about z reaches sqrt 2 along x; a tilted cylinder |u_x| h + r sqrt(1 - u_x^2); a ball, a plane and a mesh', () => {
    const world = world3();
    const box = addShape3D(world, addBody(world, { position: [0, 0, 0], orientation: axisAngle([0, 0, 1], Math.PI / 4), static: true }), {
      type: 'box',
      halfExtents: [1, 1, 1],
    });
    const s2 = Math.SQRT2;
    const slab = (x0: number, x1: number): number[] => overlapAABB3D(world, [x0, -0.1, -0.1], [x1, 0.1, 0.1]);
    expect(slab(s2 * (1 - 1e-9), 5)).toEqual([box]);
    expect(slab(s2 * (1 + 1e-9), 5)).toEqual([]);
    // A cylinder whose axis is turned 60 deg from y towards x: u = (sin 60, cos 60, 0).
    const w2 = world3();
    const t = Math.PI / 3,
      r = 0.5,
      h = 2;
    const cyl = addShape3D(w2, addBody(w2, { position: [0, 0, 0], orientation: axisAngle([0, 0, -1], t), static: true }), {
      type: 'cylinder',
      radius: r,
      halfHeight: h,
    });
    const ux = Math.sin(t),
      ex = Math.abs(ux) * h + r * Math.sqrt(1 - ux * ux);
    const ey = Math.cos(t) * h + r * Math.sqrt(1 - Math.cos(t) ** 2),
      ez = r;
    const probe = (axis: number, at: number): number[] => {
      const lo = [-9, -9, -9],
        hi = [9, 9, 9];
      lo[axis] = at;
      hi[axis] = 20;
      return overlapAABB3D(w2, lo, hi);
    };
    for (const [axis, e] of [
      [0, ex],
      [1, ey],
      [2, ez],
    ] as const) {
      expect(probe(axis, e * (1 - 1e-9))).toEqual([cyl]);
      expect(probe(axis, e * (1 + 1e-9))).toEqual([]);
    }
    // A ball (no 3D shape), a ground plane touched from above, and a mesh triangle.
    const w3 = world3();
    const ball = addBody(w3, { position: [3, 3, 3], radius: 1, mass: 1 });
    const ground = addPlane(w3, { normal: [0, 1, 0], point: [0, 0, 0] });
    const mesh = addTriangleMesh3D(w3, {
      vertices: [
        [10, 0, 10],
        [12, 0, 10],
        [10, 1, 12],
      ],
      triangles: [[0, 2, 1]],
    });
    expect(overlapAABB3D(w3, [3.9, 3.9, 3.9], [5, 5, 5])).toEqual([ball]);
    expect(overlapAABB3D(w3, [-1, 1e-9, -1], [1, 1, 1])).toEqual([]);
    expect(overlapAABB3D(w3, [-1, 0, -1], [1, 1, 1])).toEqual([ground]);
    expect(overlapAABB3D(w3, [11, 0.5, 11], [11.5, 2, 11.5])).toEqual([mesh]);
  });

  test('bad input: 2D world, vectors that are not 3 finite numbers, min above max', () => {
    const w2 = createPhysicsWorld({ dimensions: 2 });
    expect(() => overlapPoint3D(w2, [0, 0, 0])).toThrow(/overlapPoint3D: needs a 3D world \(use overlapPoint in 2D\)/);
    expect(() => overlapAABB3D(w2, [0, 0, 0], [1, 1, 1])).toThrow(/overlapAABB3D: needs a 3D world/);
    const world = world3();
    expect(() => overlapPoint3D(world, [0, Number.NaN, 0])).toThrow(/overlapPoint3D.*point/);
    expect(() => overlapAABB3D(world, [0, 0], [1, 1, 1])).toThrow(/overlapAABB3D.*min/);
    expect(() => overlapAABB3D(world, [0, 2, 0], [1, 1, 1])).toThrow('overlapAABB3D: min must not exceed max');
  });
});

describe('rayCast3D against a round cylinder', () => {
  test('side and end-disc hits of a turned cylinder at the analytic distance and normal (1e-12), not the 16-sided prism', () => {
    const world = world3();
    // Axis along world x: the shape's y turned -90 deg about z.
    const q = axisAngle([0, 0, -1], Math.PI / 2),
      R = matrix(q);
    const r = 1,
      h = 2,
      c = [0, 0, 0];
    const e = addShape3D(world, addBody(world, { position: c, orientation: q, static: true }), {
      type: 'cylinder',
      radius: r,
      halfHeight: h,
    });
    expect(apply(R, [0, 1, 0]).map((v) => v + 0)).toEqual([expect.closeTo(1, 15), expect.closeTo(0, 15), expect.closeTo(0, 15)]);
    // A ray along -y at z = 0.3 meets the side at y = sqrt(1 - 0.09); the prism's face there is up to
    // 1 - cos(pi/16) = 1.9 % of r lower.
    const z = 0.3,
      yHit = Math.sqrt(r * r - z * z);
    const side = rayCast3D(world, [0.5, 5, z], [0, -10, 0])!;
    expect(side.shape).toBe(e);
    expect(side.fraction).toBeCloseTo((5 - yHit) / 10, 12);
    expect([side.nx, side.ny, side.nz].map((v) => v + 0)).toEqual([expect.closeTo(0, 12), expect.closeTo(yHit, 12), expect.closeTo(z, 12)]);
    // Along the axis onto the end disc at x = -h, normal -x.
    const end = rayCast3D(world, [-10, 0.2, -0.4], [20, 0, 0])!;
    expect(end.x).toBeCloseTo(-h, 12);
    expect([end.nx, end.ny, end.nz].map((v) => v + 0)).toEqual([expect.closeTo(-1, 12), expect.closeTo(0, 12), expect.closeTo(0, 12)]);
    // Past the rim: a ray along x at radius 1.01 misses; from inside: no hit.
    expect(rayCast3D(world, [-10, 1.01, 0], [20, 0, 0])).toBeNull();
    expect(rayCast3D(world, [0, 0, 0], [0, 5, 0])).toBeNull();
  });
});
