import {
  addBody,
  addShape3D,
  boxMass,
  capsuleMass,
  createPhysicsWorld,
  cylinderMass,
  hullMass,
  hullOfShape3D,
  hullVolume,
  isAlive,
  type MassProperties3D,
  quickhull,
  removeBody,
  restore,
  shapes3DOf,
  shapes3DOfBody,
  slotOf,
  snapshot,
  sphereMass,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/** A seeded generator (LCG, Numerical Recipes constants) so the point clouds are fixed. */
function lcg(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (1664525 * s + 1013904223) >>> 0;
    return s / 2 ** 32;
  };
}

/** Cube corners of half extent h plus `inner` interior points. */
function cubeCloud(h: number, inner: number): number[][] {
  const pts: number[][] = [];
  for (const x of [-h, h]) for (const y of [-h, h]) for (const z of [-h, h]) pts.push([x, y, z]);
  const r = lcg(7);
  for (let i = 0; i < inner; i++) pts.push([(2 * r() - 1) * h * 0.9, (2 * r() - 1) * h * 0.9, (2 * r() - 1) * h * 0.9]);
  return pts;
}

/**
 * Independent reference for capsule and cylinder: midpoint quadrature of mass and moments over a grid
 * of n^3 cells covering the solid's bounding box, with `inside` deciding each cell.
 */
function quadrature(
  inside: (x: number, y: number, z: number) => boolean,
  ex: number,
  ey: number,
  ez: number,
  n: number,
): { m: number; Ix: number; Iy: number } {
  let m = 0,
    Ix = 0,
    Iy = 0;
  const dx = (2 * ex) / n,
    dy = (2 * ey) / n,
    dz = (2 * ez) / n,
    dv = dx * dy * dz;
  for (let i = 0; i < n; i++)
    for (let j = 0; j < n; j++)
      for (let k = 0; k < n; k++) {
        const x = -ex + (i + 0.5) * dx,
          y = -ey + (j + 0.5) * dy,
          z = -ez + (k + 0.5) * dz;
        if (!inside(x, y, z)) continue;
        m += dv;
        Ix += dv * (y * y + z * z);
        Iy += dv * (x * x + z * z);
      }
  return { m, Ix, Iy };
}

describe('quickhull', () => {
  test('a cube with interior points: its 8 corners, 6 square faces, 12 triangles', () => {
    const h = quickhull('test', cubeCloud(0.5, 40));
    expect(h.vertices.length / 3).toBe(8);
    expect(h.triangles.length / 3).toBe(12);
    expect(h.faceStart.length - 1).toBe(6);
    for (let f = 0; f < 6; f++) expect(h.faceStart[f + 1]! - h.faceStart[f]!).toBe(4);
    // Volume exactly that of the cube (tetrahedral decomposition, rounding only).
    expect(hullVolume(h)).toBeCloseTo(1, 12);
  });

  test('random points: every input point lies inside every face plane (to 1e-12 m), faces wind outward', () => {
    const r = lcg(3);
    const pts: number[][] = [];
    for (let i = 0; i < 200; i++) pts.push([r() - 0.5, 2 * r() - 1, 0.3 * (r() - 0.5)]);
    const h = quickhull('test', pts);
    const nf = h.faceStart.length - 1;
    for (const p of pts)
      for (let f = 0; f < nf; f++) {
        const d = h.faceNormals[3 * f]! * p[0]! + h.faceNormals[3 * f + 1]! * p[1]! + h.faceNormals[3 * f + 2]! * p[2]! - h.faceOffsets[f]!;
        expect(d).toBeLessThan(1e-12);
      }
    // Euler's formula for a triangulated convex polyhedron: T = 2 V - 4.
    expect(h.triangles.length / 3).toBe(2 * (h.vertices.length / 3) - 4);
  });

  test('bad clouds get clear errors', () => {
    expect(() =>
      quickhull('addShape3D', [
        [0, 0, 0],
        [1, 0, 0],
        [0, 1, 0],
        [1, 1, 0],
        [0.5, 0.2, 0],
      ]),
    ).toThrow(/addShape3D: vertices must span a volume/);
    expect(() =>
      quickhull('addShape3D', [
        [0, 0, 0],
        [1, 0, 0],
        [0, 1, 0],
      ]),
    ).toThrow(/vertices must hold 4 to 1024 points, got 3/);
    expect(() =>
      quickhull('addShape3D', [
        [0, 0, 0],
        [1, 0, 0],
        [0, 1, 0],
        [0, 0, NaN],
      ]),
    ).toThrow(/vertices\[3\]\[2\] must be a finite number/);
    // 100 points on a sphere all lie on the hull: more than 64 vertices.
    const pts: number[][] = [];
    for (let i = 0; i < 100; i++) {
      const y = 1 - (2 * (i + 0.5)) / 100,
        r = Math.sqrt(1 - y * y),
        a = i * 2.399963;
      pts.push([r * Math.cos(a), y, r * Math.sin(a)]);
    }
    expect(() => quickhull('addShape3D', pts)).toThrow(/at most 64 vertices, got more than 64/);
  });
});

describe('3D mass properties (kg/m^3)', () => {
  const close = (a: MassProperties3D, b: MassProperties3D, tol: number): void => {
    expect(Math.abs(a.mass - b.mass) / b.mass).toBeLessThan(tol);
    for (let i = 0; i < 9; i++) expect(Math.abs(a.inertia[i]! - b.inertia[i]!)).toBeLessThan(tol * b.inertia[0]!);
  };

  test("a hull of box corners has the box formula's mass and tensor (rounding only, 1e-12)", () => {
    const pts: number[][] = [];
    for (const x of [-0.3, 0.3]) for (const y of [-0.5, 0.5]) for (const z of [-1, 1]) pts.push([x + 2, y - 1, z + 3]);
    const p = hullMass(700, quickhull('test', pts));
    close(p, boxMass(700, 0.3, 0.5, 1), 1e-12);
    expect(p.center[0]).toBeCloseTo(2, 12);
    expect(p.center[1]).toBeCloseTo(-1, 12);
    expect(p.center[2]).toBeCloseTo(3, 12);
  });

  test("a tetrahedron: volume det/6, centroid the vertex mean, tensor from Tonon's closed form", () => {
    const pts = [
      [0, 0, 0],
      [1, 0, 0],
      [0, 2, 0],
      [0, 0, 3],
    ];
    const p = hullMass(1, quickhull('test', pts));
    expect(p.mass).toBeCloseTo(1, 12); // 1 * 2 * 3 / 6
    expect(p.center).toEqual([0.25, 0.5, 0.75].map((v) => expect.closeTo(v, 12)));
    // Right tetrahedron with legs a, b, c at the origin: about the origin, int y^2 + z^2 dV = V (b^2 + c^2) / 10.
    // Moved to the centroid by the parallel-axis theorem.
    const V = 1,
      a = 1,
      b = 2,
      c = 3;
    const Ixx = (V * (b * b + c * c)) / 10 - V * (0.5 ** 2 + 0.75 ** 2);
    expect(p.inertia[0]).toBeCloseTo(Ixx, 12);
    // Product of inertia: -int x y dV = -V a b / 20 about the origin, + V x_c y_c at the centroid.
    expect(p.inertia[1]).toBeCloseTo((-V * a * b) / 20 + V * 0.25 * 0.5, 12);
  });

  test("capsule and cylinder against midpoint quadrature on a 160^3 grid (0.5 %: the grid's resolution of a curved boundary)", () => {
    const r = 0.3,
      hh = 0.5;
    const cap = capsuleMass(1, r, hh);
    const qc = quadrature(
      (x, y, z) => {
        const t = Math.max(-hh, Math.min(hh, y));
        return x * x + (y - t) ** 2 + z * z <= r * r;
      },
      r,
      hh + r,
      r,
      160,
    );
    expect(Math.abs(cap.mass - qc.m) / qc.m).toBeLessThan(5e-3);
    expect(Math.abs(cap.inertia[0]! - qc.Ix) / qc.Ix).toBeLessThan(5e-3);
    expect(Math.abs(cap.inertia[4]! - qc.Iy) / qc.Iy).toBeLessThan(5e-3);
    const cyl = cylinderMass(1, r, hh);
    const qy = quadrature((x, y, z) => x * x + z * z <= r * r && Math.abs(y) <= hh, r, hh, r, 160);
    expect(Math.abs(cyl.mass - qy.m) / qy.m).toBeLessThan(5e-3);
    expect(Math.abs(cyl.inertia[0]! - qy.Ix) / qy.Ix).toBeLessThan(5e-3);
    expect(Math.abs(cyl.inertia[4]! - qy.Iy) / qy.Iy).toBeLessThan(5e-3);
    const s = sphereMass(2, 0.5);
    expect(s.mass).toBeCloseTo((2 * (4 / 3) * Math.PI) / 8, 12);
  });
});

describe('addShape3D', () => {
  test('one box: mass and principal moments from density (m = 8 rho hx hy hz, I = m (b^2 + c^2) / 12)', () => {
    const world = createPhysicsWorld({ dimensions: 3 });
    const body = addBody(world, { position: [0, 2, 0] });
    addShape3D(world, body, { type: 'box', halfExtents: [0.5, 0.25, 1], density: 400 });
    const b = slotOf(body),
      c = world.components;
    const m = 400 * 8 * 0.5 * 0.25 * 1;
    expect(c.Mass.value[b]).toBeCloseTo(m, 12);
    expect(c.InertiaTensor.x[b]).toBeCloseTo((m * (0.5 ** 2 + 2 ** 2)) / 12, 10);
    expect(c.InertiaTensor.y[b]).toBeCloseTo((m * (1 + 4)) / 12, 10);
    expect(c.InertiaTensor.z[b]).toBeCloseTo((m * (1 + 0.25)) / 12, 10);
    expect([c.Orientation.x[b], c.Orientation.y[b], c.Orientation.z[b], c.Orientation.w[b]]).toEqual([0, 0, 0, 1]);
  });

  test('a compound of two unit cubes side by side is a 2 x 1 x 1 box: mass, centre of mass, moments', () => {
    const world = createPhysicsWorld({ dimensions: 3 });
    const body = addBody(world, { position: [1, 0, 0] });
    addShape3D(world, body, { type: 'box', halfExtents: [0.5, 0.5, 0.5], density: 10 });
    addShape3D(world, body, { type: 'box', halfExtents: [0.5, 0.5, 0.5], offset: [1, 0, 0], density: 10 });
    const b = slotOf(body),
      c = world.components;
    expect(c.Mass.value[b]).toBeCloseTo(20, 12);
    expect(c.Position.x[b]).toBeCloseTo(1.5, 12);
    const ref = boxMass(10, 1, 0.5, 0.5);
    // The principal axes may come out in any order of equal moments; compare the sorted moments.
    const got = [c.InertiaTensor.x[b]!, c.InertiaTensor.y[b]!, c.InertiaTensor.z[b]!].sort();
    const want = [ref.inertia[0]!, ref.inertia[4]!, ref.inertia[8]!].sort();
    for (let i = 0; i < 3; i++) expect(got[i]).toBeCloseTo(want[i]!, 10);
    // A third shape placed about the original reference point lands where meant: a cube at x = 2 makes 3 x 1 x 1 centred at x = 2.
    addShape3D(world, body, { type: 'box', halfExtents: [0.5, 0.5, 0.5], offset: [2, 0, 0], density: 10 });
    expect(c.Position.x[b]).toBeCloseTo(2, 12);
    expect(c.Mass.value[b]).toBeCloseTo(30, 12);
    expect(shapes3DOfBody(world, body)).toHaveLength(3);
  });

  test("a rotated box: the world-frame tensor R diag(I) R^T equals the turned box's (1e-10)", () => {
    const world = createPhysicsWorld({ dimensions: 3 });
    const body = addBody(world, {});
    const a = 0.7,
      q = [Math.sin(a / 2) / Math.SQRT2, 0, Math.sin(a / 2) / Math.SQRT2, Math.cos(a / 2)];
    addShape3D(world, body, { type: 'box', halfExtents: [0.2, 0.5, 1], rotation: q, density: 1 });
    const b = slotOf(body),
      c = world.components;
    const ref = boxMass(1, 0.2, 0.5, 1);
    // Expected world tensor: R_q diag R_q^T. Ours: R_body diag(InertiaTensor) R_body^T.
    const mat = (x: number, y: number, z: number, w: number): number[] => [
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
    const tensor = (R: number[], d: number[]): number[] => {
      const out: number[] = [];
      for (let i = 0; i < 3; i++)
        for (let j = 0; j < 3; j++) {
          let s = 0;
          for (let k = 0; k < 3; k++) s += R[3 * i + k]! * d[k]! * R[3 * j + k]!;
          out.push(s);
        }
      return out;
    };
    const want = tensor(mat(q[0]!, q[1]!, q[2]!, q[3]!), [ref.inertia[0]!, ref.inertia[4]!, ref.inertia[8]!]);
    const O = c.Orientation;
    const got = tensor(mat(O.x[b]!, O.y[b]!, O.z[b]!, O.w[b]!), [c.InertiaTensor.x[b]!, c.InertiaTensor.y[b]!, c.InertiaTensor.z[b]!]);
    for (let i = 0; i < 9; i++) expect(Math.abs(got[i]! - want[i]!)).toBeLessThan(1e-10 * ref.inertia[8]!);
  });

  test('a hull shape keeps its hull; removing the body removes its shapes; snapshot carries them', () => {
    const world = createPhysicsWorld({ dimensions: 3, capacity: 20 });
    const body = addBody(world, {});
    const s = addShape3D(world, body, { type: 'hull', vertices: cubeCloud(0.5, 10), density: 2 });
    expect(hullOfShape3D(world, s).vertices.length).toBe(24);
    expect(world.components.Mass.value[slotOf(body)]).toBeCloseTo(2, 12);
    const saved = snapshot(world);
    const copy = createPhysicsWorld({ dimensions: 3, capacity: 20 });
    restore(copy, saved);
    expect(shapes3DOf(copy)!.hulls[0]!.vertices).toEqual(shapes3DOf(world)!.hulls[0]!.vertices);
    removeBody(world, body);
    expect(isAlive(world, s)).toBe(false);
    expect(shapes3DOf(world)!.first[slotOf(body)]).toBe(0);
  });

  test('shapes of one geometry share one polyhedron, so adding and removing boxes keeps the hull list bounded', () => {
    const world = createPhysicsWorld({ dimensions: 3, capacity: 100 });
    const hulls = () => shapes3DOf(world)!.hulls.length;
    // 20 rounds of 10 same-size boxes added and removed: before sharing, every box pushed a hull of its
    // own and the list held 200 after the rounds (a long-running game spawning crates grew without bound).
    for (let round = 0; round < 20; round++) {
      const bodies: number[] = [];
      for (let i = 0; i < 10; i++) {
        const b = addBody(world, { position: [2 * i, 1, 0] });
        addShape3D(world, b, { type: 'box', halfExtents: [0.5, 0.25, 0.5] });
        bodies.push(b);
      }
      for (const b of bodies) removeBody(world, b);
    }
    expect(hulls()).toBe(1);
    const a = addBody(world, {}),
      b = addBody(world, {});
    const sa = addShape3D(world, a, { type: 'box', halfExtents: [0.5, 0.25, 0.5] });
    const sb = addShape3D(world, b, { type: 'box', halfExtents: [0.5, 0.25, 0.5] });
    expect(hullOfShape3D(world, sa)).toBe(hullOfShape3D(world, sb));
    // Other geometries get their own: another size, a cylinder (twice), a point cloud (twice).
    const sc = addShape3D(world, a, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
    expect(hullOfShape3D(world, sc).vertices).toContain(0.5);
    expect(hullOfShape3D(world, sc)).not.toBe(hullOfShape3D(world, sa));
    addShape3D(world, a, { type: 'cylinder', radius: 0.3, halfHeight: 0.4 });
    addShape3D(world, b, { type: 'cylinder', radius: 0.3, halfHeight: 0.4 });
    const cloud = cubeCloud(0.5, 10);
    const h1 = addShape3D(world, a, { type: 'hull', vertices: cloud });
    const h2 = addShape3D(world, b, { type: 'hull', vertices: cloud.map((p) => [...p]) });
    expect(hullOfShape3D(world, h1)).toBe(hullOfShape3D(world, h2));
    expect(hulls()).toBe(4);
    // A call that throws after the geometry was checked (a bad density) stores no hull.
    expect(() => addShape3D(world, a, { type: 'box', halfExtents: [1, 2, 3], density: -1 })).toThrow('addShape3D: density');
    expect(hulls()).toBe(4);
    // A restored copy shares as the original does.
    const copy = createPhysicsWorld({ dimensions: 3, capacity: 100 });
    restore(copy, snapshot(world));
    const c = addBody(copy, {});
    addShape3D(copy, c, { type: 'box', halfExtents: [0.5, 0.25, 0.5] });
    expect(shapes3DOf(copy)!.hulls.length).toBe(4);
  });

  test('bad input gets clear errors and changes nothing', () => {
    const world = createPhysicsWorld({ dimensions: 3 });
    const body = addBody(world, {});
    expect(() => addShape3D(world, body, { type: 'box', halfExtents: [0.5, 0, 0.5] })).toThrow(
      'addShape3D: halfExtents[1] must be > 0, got 0',
    );
    expect(() => addShape3D(world, body, { type: 'sphere', radius: 1, halfExtents: [1, 1, 1] })).toThrow(
      'addShape3D: halfExtents does not apply to a sphere',
    );
    expect(() =>
      addShape3D(world, body, {
        type: 'hull',
        vertices: [
          [0, 0, 0],
          [1, 0, 0],
          [0, 1, 0],
          [1, 1, 0],
        ],
      }),
    ).toThrow(/addShape3D: vertices must span a volume/);
    expect(() => addShape3D(world, body, { type: 'cone' as 'box' })).toThrow(/addShape3D: type must be one of/);
    expect(() => addShape3D(world, body, { type: 'capsule', radius: 0.2 })).toThrow(/addShape3D: halfHeight must be/);
    expect(() => addShape3D(world, body, { type: 'sphere', radius: 1, rotation: [0, 0, 0, 0] })).toThrow(
      /rotation must be a non-zero quaternion/,
    );
    expect(() => addShape3D(world, body, { type: 'sphere', radius: 1, restitution: 2 })).toThrow(/restitution/);
    expect(() => addShape3D(world, body, { type: 'sphere', radius: 1, density: -1 })).toThrow(/density/);
    expect(shapes3DOfBody(world, body)).toHaveLength(0);
    expect(world.components.Mass.value[slotOf(body)]).toBe(1);
    const flat = createPhysicsWorld({ dimensions: 2 });
    expect(() => addShape3D(flat, addBody(flat, {}), { type: 'sphere', radius: 1 })).toThrow(/3D shapes need a 3D world/);
    removeBody(world, body);
    expect(() => addShape3D(world, body, { type: 'sphere', radius: 1 })).toThrow(/addShape3D: body/);
  });
});
