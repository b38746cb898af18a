import {
  addBody,
  addHeightField3D,
  addPlane,
  addShape3D,
  addTriangleMesh3D,
  contactEvents3D,
  createPhysicsWorld,
  type PhysicsWorld,
  rayCast3D,
  rayCastAll3D,
  slotOf,
  step,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

function world3(gravity = -9.81): PhysicsWorld {
  return createPhysicsWorld({ dimensions: 3, gravity: [0, gravity, 0], sleep: false });
}

describe('3D ray casts (hand-computed hits)', () => {
  test('a box turned 45 deg about y, a sphere, a capsule and a plane: fractions, points and normals', () => {
    const world = world3(0);
    const box = addBody(world, { position: [5, 0, 0], static: true });
    const a = Math.PI / 8; // 45 deg about y
    const boxShape = addShape3D(world, box, { type: 'box', halfExtents: [1, 1, 1], rotation: [0, Math.sin(a), 0, Math.cos(a)] });
    // Along +x the turned cube presents an edge at x = 5 - sqrt 2.
    const hit = rayCast3D(world, [0, 0, 0], [10, 0, 0])!;
    expect(hit.shape).toBe(boxShape);
    expect(hit.fraction).toBeCloseTo((5 - Math.SQRT2) / 10, 12);
    // The edge belongs to two faces with normals (-1, 0, +-1) / sqrt 2: either is a correct normal there.
    expect(Math.abs(hit.nx)).toBeCloseTo(Math.SQRT1_2, 12);
    // Off the edge (z = 0.5): the face with normal (-1, 0, 1)/sqrt 2 ... at x = 5 - sqrt2 + 0.5.
    const h2 = rayCast3D(world, [0, 0, 0.5], [10, 0, 0])!;
    expect(h2.x).toBeCloseTo(5 - Math.SQRT2 + 0.5, 12);
    expect([h2.nx, h2.ny, h2.nz].map((v) => v + 0)).toEqual([
      expect.closeTo(-Math.SQRT1_2, 12),
      expect.closeTo(0, 12),
      expect.closeTo(Math.SQRT1_2, 12),
    ]);
    const sph = addBody(world, { position: [0, 5, 0], static: true });
    addShape3D(world, sph, { type: 'sphere', radius: 0.5 });
    const hs = rayCast3D(world, [0, 0, 0], [0, 10, 0])!;
    expect(hs.y).toBeCloseTo(4.5, 12);
    expect(hs.ny).toBeCloseTo(-1, 12);
    const cap = addBody(world, { position: [0, 0, 5], static: true });
    addShape3D(world, cap, { type: 'capsule', radius: 0.25, halfHeight: 1 });
    const hc = rayCast3D(world, [0, 0.5, 0], [0, 0, 10])!; // hits the side at z = 4.75
    expect(hc.z).toBeCloseTo(4.75, 12);
    expect(hc.nz).toBeCloseTo(-1, 12);
    const hcap = rayCast3D(world, [0, 10, 5], [0, -10, 0])!; // the top cap at y = 1.25
    expect(hcap.y).toBeCloseTo(1.25, 12);
    expect(hcap.ny).toBeCloseTo(1, 12);
    addPlane(world, { normal: [0, 1, 0], point: [0, -2, 0] });
    const hp = rayCast3D(world, [1, 0, 1], [0, -4, 0])!;
    expect(hp.fraction).toBeCloseTo(0.5, 12);
    expect(rayCastAll3D(world, [0, 10, 5], [0, -20, 0]).length).toBe(2); // capsule, then plane
    expect(rayCast3D(world, [5, 0, 0], [1, 0, 0])).toBeNull(); // starts inside the box
    expect(() => rayCast3D(world, [0, 0, 0], [0, 0, 0])).toThrow('rayCast3D: translation must not be zero');
  });

  test('a ray hits a height field from above, not from below', () => {
    const world = world3(0);
    addHeightField3D(world, {
      heights: [
        [0, 0, 0],
        [0, 1, 0],
        [0, 0, 0],
      ],
      spacing: [1, 1],
    });
    const h = rayCast3D(world, [1, 5, 1], [0, -10, 0])!;
    expect(h.y).toBeCloseTo(1, 12);
    expect(rayCast3D(world, [1, -5, 1], [0, 10, 0])).toBeNull();
  });
});

describe('3D ground meshes, events, sensors and filtering', () => {
  test('a box slides down a triangle-mesh ramp with a = g (sin t - mu cos t) (1e-3 relative) and a ball rests on a height field', () => {
    const world = world3();
    const th = (35 * Math.PI) / 180,
      mu = 0.3,
      L = 20;
    // A ramp rising along -x: the plane through the z axis with normal (sin, cos, 0).
    const c0 = Math.cos(th),
      s0 = Math.sin(th);
    addTriangleMesh3D(world, {
      vertices: [
        [-L * c0, L * s0, -5],
        [-L * c0, L * s0, 5],
        [L * c0, -L * s0, 5],
        [L * c0, -L * s0, -5],
      ],
      triangles: [
        [0, 1, 2],
        [0, 2, 3],
      ],
      friction: mu,
    });
    const b = addBody(world, { position: [0.5 * s0, 0.5 * c0, 0], orientation: [0, 0, -Math.sin(th / 2), Math.cos(th / 2)] });
    addShape3D(world, b, { type: 'box', halfExtents: [0.5, 0.5, 0.5], friction: mu });
    const c = world.components,
      e = slotOf(b);
    for (let i = 0; i < 20; i++) step(world);
    const v0 = Math.hypot(c.Velocity.x[e]!, c.Velocity.y[e]!);
    for (let i = 0; i < 40; i++) step(world);
    const v1 = Math.hypot(c.Velocity.x[e]!, c.Velocity.y[e]!);
    const want = 9.81 * (s0 - mu * c0);
    expect(Math.abs((v1 - v0) / (40 * world.h) - want) / want).toBeLessThan(1e-3);

    const w2 = world3();
    // Flat at 0.1 m inside, raised at the border (so the grid is not a plane).
    const heights = Array.from({ length: 6 }, (_, r) =>
      Array.from({ length: 6 }, (_, k) => (r === 0 || k === 0 || r === 5 || k === 5 ? 0.5 : 0.1)),
    );
    addHeightField3D(w2, { heights, spacing: [1, 1], origin: [-2.5, 0, -2.5] });
    const ball = addBody(w2, { position: [0.25, 1, 0.25] });
    addShape3D(w2, ball, { type: 'sphere', radius: 0.2 });
    for (let i = 0; i < 240; i++) step(w2);
    expect(Math.abs(w2.components.Velocity.y[slotOf(ball)]!)).toBeLessThan(1e-3);
    expect(Math.abs(w2.components.Position.y[slotOf(ball)]! - 0.3)).toBeLessThan(2e-3);
  });

  test("begin and end touch events, a sensor's overlap events, and a mask that lets a box fall through another", () => {
    const world = world3();
    addPlane(world, { normal: [0, 1, 0] });
    const b = addBody(world, { position: [0, 1, 0] });
    const shape = addShape3D(world, b, { type: 'box', halfExtents: [0.25, 0.25, 0.25] });
    const zone = addBody(world, { position: [0, 0.25, 0], static: true });
    const sensor = addShape3D(world, zone, { type: 'box', halfExtents: [1, 0.25, 1], sensor: true });
    let begin = -1,
      sensed = -1;
    for (let i = 0; i < 60; i++) {
      step(world);
      const ev = contactEvents3D(world);
      for (let k = 0; k < ev.begin.count; k++) if (ev.begin.shapeB[k] === shape && begin < 0) begin = i;
      for (let k = 0; k < ev.sensorBegin.count; k++)
        if (ev.sensorBegin.shapeA[k] === sensor && ev.sensorBegin.shapeB[k] === shape) sensed = i;
    }
    // Falling 0.75 m to the plane takes sqrt(2 * 0.75 / g) = 0.39 s = 23.5 steps; the box's bottom (at
    // 0.75 m) reaches the sensor's top (0.5 m) after 0.25 m, sqrt(0.5 / g) = 0.226 s = 13.5 steps.
    expect(begin).toBeGreaterThanOrEqual(22);
    expect(begin).toBeLessThanOrEqual(25);
    expect(sensed).toBeGreaterThanOrEqual(13);
    expect(sensed).toBeLessThanOrEqual(15);
    // The box rests on the plane (the sensor pushes nothing).
    expect(world.components.Position.y[slotOf(b)]!).toBeCloseTo(0.25, 2);
    // Lift it off: an end event.
    world.components.Position.y[slotOf(b)] = 3;
    world.components.Velocity.y[slotOf(b)] = 0;
    let ended = false,
      left = false;
    for (let i = 0; i < 2; i++) {
      step(world);
      const ev = contactEvents3D(world);
      for (let k = 0; k < ev.end.count; k++) if (ev.end.shapeB[k] === shape) ended = true;
      for (let k = 0; k < ev.sensorEnd.count; k++) if (ev.sensorEnd.shapeA[k] === sensor) left = true;
    }
    expect(ended).toBe(true);
    expect(left).toBe(true);

    // Filtering: the upper box's mask leaves out the lower box's category: it falls through onto the plane.
    const w2 = world3();
    addPlane(w2, { normal: [0, 1, 0] });
    const low = addBody(w2, { position: [0, 0.5, 0] });
    addShape3D(w2, low, { type: 'box', halfExtents: [0.5, 0.5, 0.5], category: 2 });
    const high = addBody(w2, { position: [0, 2, 0] });
    addShape3D(w2, high, { type: 'box', halfExtents: [0.5, 0.5, 0.5], mask: 0xfffffffd });
    for (let i = 0; i < 120; i++) step(w2);
    expect(w2.components.Position.y[slotOf(high)]!).toBeCloseTo(0.5, 2);
  });
});
