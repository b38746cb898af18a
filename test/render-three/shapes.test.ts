/**
 * render-three and 3D shapes, in Node (three.js scene objects need no GL context): every shape kind is
 * drawn as an instance whose matrix is the shape's world pose, instanced per kind and size class;
 * compounds keep their parts where they were placed; picking goes through the physics' ray cast;
 * `BodyDrag3D` holds a body at the pointer with a spring; the debug layer draws 3D joints and contacts.
 */

import {
  addBallJoint3D,
  addBody,
  addHeightField3D,
  addHingeJoint3D,
  addPlane,
  addShape3D,
  createPhysicsWorld,
  isAlive,
  type PhysicsWorld,
  step,
} from '@bitphysics/physics';
import { Color, Matrix4, PerspectiveCamera, Quaternion, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { BodyDrag3D, type ShapeLayer3D, WorldRenderer3D } from '../../packages/render-three/src/index';

function world3(capacity = 64, gravity: [number, number, number] = [0, 0, 0]): PhysicsWorld {
  return createPhysicsWorld({ dimensions: 3, capacity, gravity });
}

/** The shape layer's mesh named like `prefix`, and instance i's matrix decomposed. */
function instance(r: WorldRenderer3D, prefix: string, i = 0): { p: Vector3; q: Quaternion; s: Vector3; count: number } {
  const layer = (r as unknown as { shapes: ShapeLayer3D }).shapes;
  const mesh = layer.object.children.find((o) => o.name.startsWith(prefix)) as import('three').InstancedMesh;
  expect(mesh, prefix).toBeDefined();
  const m = new Matrix4();
  mesh.getMatrixAt(i, m);
  const p = new Vector3(),
    q = new Quaternion(),
    s = new Vector3();
  m.decompose(p, q, s);
  return { p, q, s, count: mesh.count };
}

describe('render-three: 3D shapes', () => {
  it('draws each shape kind as an instance at its body pose and size (float32 matrices: 1e-6)', () => {
    const w = world3();
    const r = new WorldRenderer3D(w, { lights: false });
    const q = [Math.sin(0.3), 0, 0, Math.cos(0.3)]; // 0.6 rad about x
    const box = addBody(w, { position: [1, 2, 3], orientation: q });
    addShape3D(w, box, { type: 'box', halfExtents: [0.5, 0.25, 0.1] });
    const ball = addBody(w, { position: [-1, 0, 0] });
    addShape3D(w, ball, { type: 'sphere', radius: 0.3 });
    const cyl = addBody(w, { position: [0, 3, 0] });
    addShape3D(w, cyl, { type: 'cylinder', radius: 0.2, halfHeight: 0.4 });
    const hull = addBody(w, { position: [0, -3, 0] });
    addShape3D(w, hull, {
      type: 'hull',
      vertices: [
        [0, 0, 0],
        [1, 0, 0],
        [0, 1, 0],
        [0, 0, 1],
      ],
    });
    r.render(1);
    expect(r.stats.shaped).toBe(4);
    expect(r.stats.boxes).toBe(0); // not drawn as equivalent-inertia boxes any more
    expect(r.stats.shapes).toMatchObject({ boxes: 1, spheres: 1, cylinders: 1, hulls: 1, capsules: 0, meshes: 4 });
    const b = instance(r, 'shapes-box');
    expect(b.p.distanceTo(new Vector3(1, 2, 3))).toBeLessThan(1e-6);
    // The box's principal frame may differ from the user's by axis swaps; its drawn corners do not:
    // the instance maps the unit cube's corner (0.5, 0.5, 0.5) to the body's (0.5, 0.25, 0.1) rotated by q.
    const corner = new Vector3(0.5, 0.5, 0.5).multiply(b.s).applyQuaternion(b.q);
    const want = new Vector3(0.5, 0.25, 0.1).applyQuaternion(new Quaternion(q[0], q[1], q[2], q[3]));
    const sorted = (v: Vector3): number[] => [Math.abs(v.x), Math.abs(v.y), Math.abs(v.z)].sort();
    expect(
      sorted(corner)
        .map((x, i) => Math.abs(x - sorted(want)[i]!))
        .every((d) => d < 1e-6),
    ).toBe(true);
    expect(instance(r, 'shapes-sphere').s.x).toBeCloseTo(0.3, 6);
    const c = instance(r, 'shapes-cylinder');
    expect([c.s.x, c.s.y, c.s.z].sort()).toEqual([expect.closeTo(0.2, 6), expect.closeTo(0.2, 6), expect.closeTo(0.4, 6)]);
    // The hull's centre of mass is the tetrahedron's centroid (1/4, 1/4, 1/4) from its first vertex: the body moved there.
    const P = w.components.Position;
    expect(P.x[hull]).toBeCloseTo(0.25, 9);
    expect(P.y[hull]).toBeCloseTo(-2.75, 9);
    // Its geometry's vertices, placed by the instance, are the four points given (as placed at (0, -3, 0)).
    const layer = (r as unknown as { shapes: ShapeLayer3D }).shapes;
    const mesh = layer.object.children.find((o) => o.name.startsWith('shapes-h')) as import('three').InstancedMesh;
    const m = new Matrix4();
    mesh.getMatrixAt(0, m);
    const pos = mesh.geometry.getAttribute('position');
    const seen = new Set<string>();
    for (let i = 0; i < pos.count; i++) {
      const v = new Vector3(pos.getX(i), pos.getY(i), pos.getZ(i)).applyMatrix4(m);
      seen.add([v.x, v.y + 3, v.z].map((x) => Math.round(x * 1e5) / 1e5 + 0).join(','));
    }
    expect([...seen].sort()).toEqual(['0,0,0', '0,0,1', '0,1,0', '1,0,0']);
    expect(mesh.geometry.getAttribute('position').count).toBe(12); // 4 triangular faces
  });

  it('places the parts of a compound where they were put, and classes capsules by shape (one mesh a ratio)', () => {
    const w = world3();
    const r = new WorldRenderer3D(w, { lights: false });
    const body = addBody(w, { position: [2, 1, 0] });
    addShape3D(w, body, { type: 'box', halfExtents: [0.2, 0.2, 0.2] });
    addShape3D(w, body, { type: 'sphere', radius: 0.25, offset: [1, 0, 0], density: 3000 });
    const caps = [0.1, 0.2, 0.1].map((radius, i) => {
      const e = addBody(w, { position: [0, 0, 2 * i] });
      addShape3D(w, e, { type: 'capsule', radius, halfHeight: i === 1 ? 0.2 : 0.3 });
      return e;
    });
    r.render(1);
    // The sphere was placed 1 m along x from the body's first position: it is drawn there, although the
    // body's centre moved to the compound's centre of mass.
    expect(instance(r, 'shapes-sphere').p.distanceTo(new Vector3(3, 1, 0))).toBeLessThan(1e-6);
    expect(instance(r, 'shapes-box').p.distanceTo(new Vector3(2, 1, 0))).toBeLessThan(1e-6);
    expect(w.components.Position.x[body]).toBeGreaterThan(2.5);
    // Capsules of ratio 3 (0.3 / 0.1) share a mesh; the one of ratio 1 has its own.
    expect(r.stats.shapes.capsules).toBe(3);
    expect(instance(r, 'shapes-capsule:3.00').count).toBe(2);
    expect(instance(r, 'shapes-capsule:1.00').count).toBe(1);
    expect(caps.length).toBe(3);
    r.destroy();
  });

  it('fills shapes with the colour set on their body, or on the shape itself', () => {
    const w = world3();
    const r = new WorldRenderer3D(w, { lights: false });
    const body = addBody(w, { position: [0, 0, 0] });
    addShape3D(w, body, { type: 'box', halfExtents: [0.2, 0.2, 0.2] });
    const second = addShape3D(w, body, { type: 'box', halfExtents: [0.2, 0.2, 0.2], offset: [1, 0, 0] });
    // Instance colours are stored linear (three's colour management): pure red, green and blue stay
    // pure, so each channel reads 0 or 1 (1e-6: float32 storage).
    const colorAt = (x: number): [number, number, number] => {
      const layer = (r as unknown as { shapes: ShapeLayer3D }).shapes;
      const mesh = layer.object.children.find((o) => o.name.startsWith('shapes-box')) as import('three').InstancedMesh;
      const m = new Matrix4(),
        p = new Vector3(),
        c = new Color();
      for (let i = 0; i < mesh.count; i++) {
        mesh.getMatrixAt(i, m);
        p.setFromMatrixPosition(m);
        if (Math.abs(p.x - x) > 1e-3) continue;
        mesh.getColorAt(i, c);
        return [c.r, c.g, c.b];
      }
      throw new Error(`no box instance at x = ${x}`);
    };
    const near = (got: [number, number, number], want: [number, number, number]): void => {
      for (let k = 0; k < 3; k++) expect(got[k]).toBeCloseTo(want[k]!, 6);
    };
    const x0 = w.components.Position.x[body]! - 0.5; // the body's centre moved to the pair's middle
    r.setColor(body, 0xff0000);
    r.render(1);
    near(colorAt(x0), [1, 0, 0]);
    near(colorAt(x0 + 1), [1, 0, 0]);
    r.setColor(second, 0x0000ff);
    expect(r.colorOf(second)).toBe(0x0000ff);
    r.render(1);
    near(colorAt(x0), [1, 0, 0]);
    near(colorAt(x0 + 1), [0, 0, 1]);
    r.clearColor(second);
    r.render(1);
    near(colorAt(x0 + 1), [1, 0, 0]);
    r.destroy();
  });

  it('picks through the physics ray cast: a shaped body at its face; a plane in front hides it', () => {
    const w = world3();
    const r = new WorldRenderer3D(w, { lights: false });
    const box = addBody(w, { position: [0, 0, -3] });
    addShape3D(w, box, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
    r.render(1);
    const camera = new PerspectiveCamera(50, 1, 0.1, 100);
    camera.position.set(0, 0, 0);
    camera.lookAt(0, 0, -3);
    camera.updateMatrixWorld();
    const hit = r.pick(0, 0, camera);
    expect(hit?.eid).toBe(box);
    expect(hit!.point[2]).toBeCloseTo(-2.5, 9); // the physics' exact face, not a tessellation
    expect(hit!.normal[2]).toBeCloseTo(1, 9);
    expect(hit!.distance).toBeCloseTo(2.5, 9);
    addPlane(w, { normal: [0, 0, 1], point: [0, 0, -1] });
    expect(r.pick(0, 0, camera)).toBeNull();
  });

  it('BodyDrag3D grabs the body under the pointer and carries it on a spring to the pointer', () => {
    const w = world3(64, [0, -9.81, 0]);
    const r = new WorldRenderer3D(w, { lights: false });
    const box = addBody(w, { position: [0, 0, -3] });
    addShape3D(w, box, { type: 'box', halfExtents: [0.25, 0.25, 0.25], density: 500 });
    r.render(1);
    const camera = new PerspectiveCamera(50, 1, 0.1, 100);
    camera.lookAt(0, 0, -3);
    camera.updateMatrixWorld();
    const drag = new BodyDrag3D(r, { hertz: 4, dampingRatio: 1 });
    expect(drag.grab(0.9, 0.9, camera)).toBe(0); // nothing there
    expect(drag.grab(0, 0, camera)).toBe(box);
    expect(drag.body).toBe(box);
    const hand = drag.hand;
    // The pointer lifts the front face's centre 1 m in 1 s, then holds still for 4 s.
    for (let i = 0; i < 300; i++) {
      if (i < 60) drag.moveTo([0, (i + 1) / 60, -2.75]);
      step(w);
    }
    // The body hangs and swings about the point held: its centre stays 0.25 m (face centre to centre)
    // from the hand plus the spring's stretch under its weight (static g / (2 pi f)^2 = 1.55 cm; the
    // soft joint measured 6-8 cm while swinging), below the hand. Free, it would have fallen 120 m.
    const P = w.components.Position;
    const arm = Math.hypot(P.x[box]!, P.y[box]! - 1, P.z[box]! + 2.75);
    expect(arm).toBeGreaterThan(0.25);
    expect(arm).toBeLessThan(0.25 + 0.12);
    expect(P.y[box]).toBeLessThan(1);
    drag.release();
    expect(isAlive(w, hand)).toBe(false);
    expect(drag.body).toBe(0);
  });

  it('debug layer: 3D joints, and the four contact points of a cube resting on a plane', () => {
    const w = world3(64, [0, -9.81, 0]);
    addPlane(w, { normal: [0, 1, 0], point: [0, 0, 0] });
    const cube = addBody(w, { position: [0, 0.5, 0] });
    addShape3D(w, cube, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
    const a = addBody(w, { position: [3, 2, 0] });
    addShape3D(w, a, { type: 'sphere', radius: 0.2 });
    addBallJoint3D(w, { b: a, anchor: [3, 3, 0] });
    const c = addBody(w, { position: [5, 2, 0] });
    addShape3D(w, c, { type: 'capsule', radius: 0.1, halfHeight: 0.3 });
    addHingeJoint3D(w, { a, b: c, anchor: [4, 2, 0], axis: [0, 0, 1] });
    for (let i = 0; i < 10; i++) step(w);
    const r = new WorldRenderer3D(w, { lights: false, debug: { axes: false, velocities: false } });
    r.render(1);
    expect(r.stats.scenery.joints).toBe(2);
    expect(r.stats.contacts).toBe(4);
  });

  it('draws a height field as one mesh through its grid points (the physics vertices)', () => {
    const w = world3();
    addHeightField3D(w, {
      heights: [
        [0, 1, 0],
        [1, 2, 1],
        [0, 1, 0],
      ],
      spacing: [2, 3],
      origin: [-2, 0, -3],
    });
    const r = new WorldRenderer3D(w, { lights: false });
    r.render(1);
    expect(r.stats.shapes.triangleMeshes).toBe(1);
    const layer = (r as unknown as { shapes: ShapeLayer3D }).shapes;
    const mesh = layer.object.children.find((o) => o.name.startsWith('triangle-mesh')) as import('three').Mesh;
    const pos = mesh.geometry.getAttribute('position');
    expect(pos.count).toBe(9);
    let top = -Infinity;
    for (let i = 0; i < pos.count; i++) top = Math.max(top, pos.getY(i));
    expect(top).toBe(2); // the middle grid point
    expect(mesh.geometry.index!.count).toBe(8 * 3); // 2 x 2 cells, two triangles each
    r.setWorld(world3());
    r.render(1);
    expect(r.stats.shapes.triangleMeshes).toBe(0);
  });
});
