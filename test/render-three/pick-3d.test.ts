/**
 * WorldRenderer3D.pick's hit normal against the analytic normal of the face hit, in the physics frame
 * (the renderer's root frame), with the root turned and moved in the scene: a box, a cylinder and a
 * capsule with colliders (the physics' ray cast) and a body drawn without a collider (three.js' ray
 * cast against its instanced inertia box). Node only: three.js scene objects need no GL context.
 */

import { addBody, addShape3D, createPhysicsWorld, type PhysicsWorld, setPosition } from '@bitphysics/physics';
import { PerspectiveCamera, Scene, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { WorldRenderer3D } from '../../packages/render-three/src/index';

/** A renderer whose root is turned in the scene (Euler XYZ: -90 degrees about x, 0.3 rad about z) and moved to (1, 2, 3). */
function setup(): { w: PhysicsWorld; r: WorldRenderer3D; scene: Scene } {
  const w = createPhysicsWorld({ dimensions: 3, capacity: 64, gravity: [0, 0, 0] });
  const scene = new Scene();
  const r = new WorldRenderer3D(w, { lights: false, scene });
  r.root.rotation.set(-Math.PI / 2, 0, 0.3);
  r.root.position.set(1, 2, 3);
  r.root.updateMatrixWorld(true);
  return { w, r, scene };
}

/** A camera at physics point `from` looking at physics point `at` (both mapped through the root into the scene). */
function cameraAt(r: WorldRenderer3D, from: [number, number, number], at: [number, number, number]): PerspectiveCamera {
  const camera = new PerspectiveCamera(50, 1, 0.1, 100);
  const k = r.unitsPerMeter;
  const f = r.root.localToWorld(new Vector3(from[0] * k, from[1] * k, from[2] * k));
  const a = r.root.localToWorld(new Vector3(at[0] * k, at[1] * k, at[2] * k));
  camera.position.copy(f);
  camera.up.set(0, 0, 1);
  camera.lookAt(a);
  camera.updateMatrixWorld();
  return camera;
}

/** The pick's normal against `n` (physics frame): equal to 1e-6 (float32 instance matrices for the three.js hits). */
function expectNormal(got: [number, number, number] | undefined, n: [number, number, number]): void {
  expect(got).toBeDefined();
  for (let i = 0; i < 3; i++) expect(got![i]!).toBeCloseTo(n[i]!, 6);
}

describe('render-three: pick normals in the physics frame', () => {
  it("box, cylinder and capsule colliders: a box face, the cylinder's flat cap and the capsule's side", () => {
    const { w, r } = setup();
    const box = addBody(w, { position: [0, 0, -3] });
    addShape3D(w, box, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
    const cyl = addBody(w, { position: [5, 0, 0] });
    addShape3D(w, cyl, { type: 'cylinder', radius: 0.5, halfHeight: 0.5 });
    const cap = addBody(w, { position: [0, 6, 0] });
    addShape3D(w, cap, { type: 'capsule', radius: 0.3, halfHeight: 0.5 });
    r.render(1);
    // The box's +z face (seen from the origin), the cylinder's flat top, the capsule's side.
    const hb = r.pick(0, 0, cameraAt(r, [0, 0, 0], [0, 0, -3]));
    expect(hb?.eid).toBe(box);
    expectNormal(hb?.normal, [0, 0, 1]);
    const hc = r.pick(0, 0, cameraAt(r, [5, 4, 0.01], [5, 0, 0]));
    expect(hc?.eid).toBe(cyl);
    expectNormal(hc?.normal, [0, 1, 0]);
    const hs = r.pick(0, 0, cameraAt(r, [4, 6, 0], [0, 6, 0]));
    expect(hs?.eid).toBe(cap);
    expectNormal(hs?.normal, [1, 0, 0]);
    // Point on the capsule's side: x = r.
    expect(hs!.point[0]).toBeCloseTo(0.3, 9);
    r.destroy();
  });

  it('a compound: the face of a part turned in the body frame', () => {
    const { w, r } = setup();
    // Two boxes on one body: one at its reference point, one 2 m along x turned 0.3 rad about x. The
    // body itself turns to its principal axes (updateMassFromShapes3D); the part's world pose does not.
    const body = addBody(w, { position: [0, 0, -3] });
    addShape3D(w, body, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
    const t = 0.3;
    addShape3D(w, body, {
      type: 'box',
      halfExtents: [0.5, 0.5, 0.5],
      offset: [2, 0, 0],
      rotation: [Math.sin(t / 2), 0, 0, Math.cos(t / 2)],
    });
    r.render(1);
    // Straight down -z at the part's centre line: its +z face, turned to (0, -sin t, cos t), at z = -3 + 0.5 / cos t.
    const hit = r.pick(0, 0, cameraAt(r, [2, 0, 0], [2, 0, -3]));
    expect(hit?.eid).toBe(body);
    expectNormal(hit?.normal, [0, -Math.sin(t), Math.cos(t)]);
    expect(hit!.point[2]).toBeCloseTo(-3 + 0.5 / Math.cos(t), 9);
    r.destroy();
  });

  it('with the root scaled, a collider hit and a drawn-only hit report scene distances, and the nearer one wins', () => {
    const { w, r } = setup();
    r.root.scale.setScalar(2);
    r.root.updateMatrixWorld(true);
    // A box collider 3 m ahead (face at 2.5 m) and, behind it, a body drawn without a collider (face at 4.5 m).
    const box = addBody(w, { position: [0, 0, -3] });
    addShape3D(w, box, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
    const drawn = addBody(w, { position: [0, 0, -5], mass: 6, inertia: [1, 1, 1] });
    r.render(1);
    const camera = cameraAt(r, [0, 0, 0], [0, 0, -3]);
    const hit = r.pick(0, 0, camera);
    // The scene distance is the physics distance times the root's scale (2): 5, not 2.5.
    expect(hit?.eid).toBe(box);
    expect(hit!.distance).toBeCloseTo(2 * 2.5, 6);
    // Moved aside, the collider-less body behind is hit, 2 x 4.5 = 9 scene units away.
    setPosition(w, box, [0, 10, -3]);
    r.render(1);
    const behind = r.pick(0, 0, camera);
    expect(behind?.eid).toBe(drawn);
    expect(behind!.distance).toBeCloseTo(2 * 4.5, 4);
    r.destroy();
  });

  it("a body drawn without a collider (its inertia box): the face normal in the physics frame, not the scene's", () => {
    const { w, r } = setup();
    // A plain rigid body: principal moments of a 1 x 1 x 1 m, 6 kg cube (m s^2 / 6 = 1): drawn as that cube.
    const body = addBody(w, { position: [0, 0, -3], mass: 6, inertia: [1, 1, 1] });
    r.render(1);
    const hit = r.pick(0, 0, cameraAt(r, [0, 0, 0], [0, 0, -3]));
    expect(hit?.eid).toBe(body);
    expect(hit!.point[2]).toBeCloseTo(-2.5, 5);
    expectNormal(hit?.normal, [0, 0, 1]);
    // From above (physics +y): the top face's normal.
    const top = r.pick(0, 0, cameraAt(r, [0, 4, -2.99], [0, 0, -3]));
    expect(top?.eid).toBe(body);
    expectNormal(top?.normal, [0, 1, 0]);
    r.destroy();
  });
});
