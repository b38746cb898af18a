import { addBody, addShape3D, createPhysicsWorld, forEachContact3D, type PhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';
import { contact3DStateOf } from '../../packages/physics/src/collision/manifolds-3d.js';
import { pairContacts } from './helpers.js';

/**
 * Resting contact and head-on hits of the 3D pairs that go through their own manifold code
 * (packages/physics/src/collision/narrowphase/manifold-3d.ts): capsule-capsule (segment-segment), capsule-box
 * (capsule-polyhedron) and hull-hull (separating axes and face clipping). Each resting case is checked
 * against its geometry (the rest height of the touching surfaces and the manifold's point count), each
 * hit against conservation of linear momentum.
 */

const G = 9.81;
/** Rotation (x, y, z, w) that turns the shape's y axis (a capsule's axis) onto world x: -90 deg about z. */
const ALONG_X = [0, 0, -Math.SQRT1_2, Math.SQRT1_2];
/** Rotation that turns the shape's y axis onto world z: +90 deg about x. */
const ALONG_Z = [Math.SQRT1_2, 0, 0, Math.SQRT1_2];
/** The eight corners of a cube of half size h, for a hull the framework computes. */
const corners = (h: number): number[][] => [-1, 1].flatMap((x) => [-1, 1].flatMap((y) => [-1, 1].map((z) => [x * h, y * h, z * h])));

function world3(gravity: number): PhysicsWorld {
  return createPhysicsWorld({ dimensions: 3, gravity: [0, gravity, 0], sleep: false });
}

function speed(world: PhysicsWorld, b: number): number {
  const c = world.components,
    e = slotOf(b);
  return (
    Math.hypot(c.Velocity.x[e]!, c.Velocity.y[e]!, c.Velocity.z[e]!) +
    Math.hypot(c.AngularVelocity.x[e]!, c.AngularVelocity.y[e]!, c.AngularVelocity.z[e]!)
  );
}

/** Drops `top` a little above its rest height on the static `base`, runs 180 steps (3 s) and returns its height, contact count, speed and how often the manifold's feature ids changed over the last 30 steps. */
function settle(world: PhysicsWorld, base: number, top: number): { y: number; points: number; speed: number; idChanges: number } {
  let ids = '',
    idChanges = 0;
  for (let s = 0; s < 180; s++) {
    step(world);
    if (s < 150) continue;
    // The one manifold's feature ids: the same from step to step at rest, so warm starting finds its points.
    const st = contact3DStateOf(world)!.current;
    const now = st.count === 1 ? Array.from(st.id.subarray(0, st.points[0]!)).sort().join(',') : `rows ${st.count}`;
    if (s > 150 && now !== ids) idChanges++;
    ids = now;
  }
  return {
    y: world.components.Position.y[slotOf(top)]!,
    points: pairContacts(world, base, top).points,
    speed: speed(world, top),
    idChanges,
  };
}

// Rest tolerance: the soft contact lets a body sink a fraction of a millimetre under its own weight
// (the cube-on-plane test in rigid-3d.test.ts sees the same), so 1 mm around the touching height.
// "Stops moving": linear + angular speed below 1e-3 (m/s + rad/s) after 3 s.
describe('3D manifolds: resting pairs sit at their geometric height with the right number of points', () => {
  test('a capsule lying across another at 90 degrees rests at r1 + r2 above its centre line, one point', () => {
    const world = world3(-G);
    const r1 = 0.2,
      r2 = 0.15;
    const base = addBody(world, { position: [0, 0, 0], static: true });
    addShape3D(world, base, { type: 'capsule', radius: r1, halfHeight: 0.6, rotation: ALONG_X });
    const top = addBody(world, { position: [0, r1 + r2 + 0.05, 0] });
    addShape3D(world, top, { type: 'capsule', radius: r2, halfHeight: 0.5, rotation: ALONG_Z, density: 1000 });
    const r = settle(world, base, top);
    expect(Math.abs(r.y - (r1 + r2))).toBeLessThan(1e-3);
    expect(r.points).toBe(1); // crossed segments touch at one point
    expect(r.speed).toBeLessThan(1e-3);
    expect(r.idChanges).toBe(0);
  });

  test('two parallel capsules touch along a line: two points, rest at r1 + r2', () => {
    const world = world3(-G);
    const r1 = 0.2,
      r2 = 0.15;
    const base = addBody(world, { position: [0, 0, 0], static: true });
    addShape3D(world, base, { type: 'capsule', radius: r1, halfHeight: 0.6, rotation: ALONG_X });
    const top = addBody(world, { position: [0.1, r1 + r2 + 0.05, 0] });
    addShape3D(world, top, { type: 'capsule', radius: r2, halfHeight: 0.4, rotation: ALONG_X, density: 1000 });
    const r = settle(world, base, top);
    expect(Math.abs(r.y - (r1 + r2))).toBeLessThan(1e-3);
    expect(r.points).toBe(2); // the overlap of the two segments' spans, one point at each end
    expect(r.speed).toBeLessThan(1e-3);
    expect(r.idChanges).toBe(0);
  });

  test('a capsule lying on a box rests at the box top + r with two points', () => {
    const world = world3(-G);
    const r = 0.2,
      boxHalf = 0.5;
    const base = addBody(world, { position: [0, 0, 0], static: true });
    addShape3D(world, base, { type: 'box', halfExtents: [1, boxHalf, 1] });
    const top = addBody(world, { position: [0.2, boxHalf + r + 0.05, -0.1] });
    addShape3D(world, top, { type: 'capsule', radius: r, halfHeight: 0.5, rotation: ALONG_X, density: 1000 });
    const s = settle(world, base, top);
    expect(Math.abs(s.y - (boxHalf + r))).toBeLessThan(1e-3);
    expect(s.points).toBe(2); // the two ends of the capsule's segment
    expect(s.speed).toBeLessThan(1e-3);
    expect(s.idChanges).toBe(0);
  });

  test('a hull cube (hull of 8 corners) resting on a hull cube has four points and sits at h1 + h2', () => {
    const world = world3(-G);
    const h1 = 0.5,
      h2 = 0.3;
    const base = addBody(world, { position: [0, 0, 0], static: true });
    addShape3D(world, base, { type: 'hull', vertices: corners(h1) });
    const top = addBody(world, { position: [0.05, h1 + h2 + 0.05, 0.1] });
    addShape3D(world, top, { type: 'hull', vertices: corners(h2), density: 1000 });
    const r = settle(world, base, top);
    expect(Math.abs(r.y - (h1 + h2))).toBeLessThan(1e-3);
    expect(r.points).toBe(4); // the incident face's four corners, clipped inside the larger reference face
    expect(r.speed).toBeLessThan(1e-3);
    expect(r.idChanges).toBe(0);
  });
});

describe('3D manifolds: reduction to four points and feature ids', () => {
  test('a hull cube turned 45 degrees on an equal hull cube: the octagon of overlap is cut to four of its vertices around the centre of mass, carrying the weight', () => {
    const SUB = 4; // solver substeps, set here so the impulse check below knows them
    const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -G, 0], sleep: false, solverSubsteps: SUB });
    const h = 0.5;
    const base = addBody(world, { position: [0, 0, 0], static: true });
    addShape3D(world, base, { type: 'hull', vertices: corners(h) });
    const q = Math.PI / 8; // half of 45 degrees about y
    const top = addBody(world, { position: [0, 2 * h + 0.02, 0], orientation: [0, Math.sin(q), 0, Math.cos(q)] });
    addShape3D(world, top, { type: 'hull', vertices: corners(h), density: 1000 });
    const c = world.components,
      e = slotOf(top);
    // The kept four keep their feature ids from step 30 (settled) to 200: all eight octagon vertices
    // are equally deep to ~1e-8 m, and a reduction that picked the deepest by rounding noise alternated
    // between the two interleaved sets every ~32 steps (steps 45, 77, 108, 140, 172), each switch
    // starting the new points without warm start: a ~5 um drop, a 5.6e-5 m/s kick (issue 9).
    let ids = '';
    const changes: number[] = [];
    for (let s = 0; s < 200; s++) {
      step(world);
      const st = contact3DStateOf(world)!.current;
      const now = Array.from(st.id.subarray(0, st.points[0]!)).sort().join(',');
      if (s > 30 && now !== ids) changes.push(s);
      ids = now;
    }
    expect(changes).toEqual([]);
    expect(contact3DStateOf(world)!.current.count).toBe(1);
    // The two squares overlap in a regular octagon: 8 clipped points, of which four are kept.
    const pts: number[][] = [];
    let impulse = 0;
    forEachContact3D(world, (v) => {
      pts.push([v.x, v.z]);
      impulse += v.impulse;
    });
    expect(pts.length).toBe(4);
    // Each kept point is an octagon vertex: at the circumradius h / cos(22.5 deg) from the axis (1 mm).
    for (const [x, z] of pts) expect(Math.abs(Math.hypot(x!, z!) - h / Math.cos(q))).toBeLessThan(1e-3);
    // They surround the centre of mass (the origin in x-z): no angular gap between them reaches pi,
    // else the cube would tip about the edge they leave out.
    const ang = pts.map(([x, z]) => Math.atan2(z!, x!)).sort((a, b) => a - b);
    const gaps = ang.map((a, i) => (i + 1 < ang.length ? ang[i + 1]! : ang[0]! + 2 * Math.PI) - a);
    expect(Math.max(...gaps)).toBeLessThan(Math.PI - 0.1);
    // At rest the last substep's normal impulses carry the weight: sum = m g h_sub, h_sub = dt / solver substeps
    // (1e-5 relative: measured 3e-16 with the four fixed; 2.4e-6 between and +1e-3 at the steps where
    // the kept four switched sets before the fix, issue 9.)
    const hSub = world.h / SUB;
    expect(Math.abs(impulse / (c.Mass.value[e]! * G * hSub) - 1)).toBeLessThan(1e-5);
    expect(Math.abs(c.Position.y[e]! - 2 * h)).toBeLessThan(1e-3);
    expect(speed(world, top)).toBeLessThan(1e-3);
  });
});

describe('3D manifolds: head-on hits conserve linear momentum and do not interpenetrate', () => {
  type Maker = (world: PhysicsWorld, position: number[], velocity: number[]) => number;
  const capsuleAlongZ =
    (r: number, hh: number): Maker =>
    (world, position, velocity) => {
      const b = addBody(world, { position, velocity });
      addShape3D(world, b, { type: 'capsule', radius: r, halfHeight: hh, rotation: ALONG_Z, density: 1000, restitution: 0.3 });
      return b;
    };
  const capsuleAlongX =
    (r: number, hh: number): Maker =>
    (world, position, velocity) => {
      const b = addBody(world, { position, velocity });
      addShape3D(world, b, { type: 'capsule', radius: r, halfHeight: hh, rotation: ALONG_X, density: 1000, restitution: 0.3 });
      return b;
    };
  const box =
    (h: number): Maker =>
    (world, position, velocity) => {
      const b = addBody(world, { position, velocity });
      addShape3D(world, b, { type: 'box', halfExtents: [h, h, h], density: 700, restitution: 0.3 });
      return b;
    };
  const hull =
    (h: number): Maker =>
    (world, position, velocity) => {
      const b = addBody(world, { position, velocity });
      addShape3D(world, b, { type: 'hull', vertices: corners(h), density: 900, restitution: 0.3 });
      return b;
    };
  // [name, mover, target, target position]: the mover starts at the origin at (4, 0.5, 0) m/s, the target
  // at rest off its line a little (so the hit also turns them and the normal is not an axis).
  const cases: [string, Maker, Maker, number[]][] = [
    ['capsule-capsule (crossed)', capsuleAlongZ(0.2, 0.4), capsuleAlongX(0.15, 0.3), [1.5, 0.2, 0.1]],
    ['capsule-capsule (end on)', capsuleAlongX(0.2, 0.4), capsuleAlongX(0.15, 0.3), [1.6, 0.1, 0.05]],
    ['capsule-box', capsuleAlongZ(0.2, 0.4), box(0.4), [1.5, 0.3, 0.2]],
    ['hull-hull', hull(0.5), hull(0.4), [1.5, 0.3, 0.2]],
  ];
  // Momentum: the contact impulses act in equal and opposite pairs, so the total changes only by
  // rounding: 1e-9 of |p0|. Overlap: the speculative contact catches the approach before the surfaces
  // meet, so the worst separation any step starts with is bounded by 5 mm (the soft contact's give
  // under a 4 m/s hit; measured: 1.2 mm for capsule-box, none for the others).
  for (const [name, mover, target, at] of cases) {
    test(`${name}: momentum to 1e-9 relative, overlap under 5 mm`, () => {
      const world = world3(0);
      const a = mover(world, [0, 0, 0], [4, 0.5, 0]);
      const b = target(world, at, [0, 0, 0]);
      const c = world.components,
        ea = slotOf(a),
        eb = slotOf(b);
      const p = (): number[] =>
        [c.Velocity.x, c.Velocity.y, c.Velocity.z].map((v) => c.Mass.value[ea]! * v[ea]! + c.Mass.value[eb]! * v[eb]!);
      const p0 = p();
      let minSep = Infinity,
        touched = 0;
      for (let s = 0; s < 60; s++) {
        step(world);
        const k = pairContacts(world, a, b);
        if (k.points > 0) {
          touched++;
          minSep = Math.min(minSep, k.minSep);
        }
      }
      expect(touched).toBeGreaterThan(0);
      expect(c.Velocity.x[eb]!).toBeGreaterThan(0.5); // they did collide
      const p1 = p();
      for (let k = 0; k < 3; k++) expect(Math.abs(p1[k]! - p0[k]!)).toBeLessThan(1e-9 * Math.hypot(...p0));
      expect(minSep).toBeGreaterThan(-5e-3);
    });
  }
});
