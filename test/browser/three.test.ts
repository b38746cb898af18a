/**
 * @bitphysics/render-three and the 3D games.
 *
 * In Node (no WebGL: three.js scene objects work without a GL context): the instance bookkeeping
 * (`InstanceBook`), the interpolation maths against three.js' own, and `WorldRenderer3D` itself
 * (instances follow entities, swap-remove, recycled ids, interpolated matrices, shapes, colours,
 * trails, debug, picking, bad options).
 *
 * In headless Chromium (SwiftShader WebGL): each 3D game loads without errors and draws; input
 * changes the game (a drag throws a ball, held keys and clicks turn the cube, the time scale and
 * pause change the Earth-Moon clock); the draw calls of thousands of balls stay a handful.
 */

import {
  addBody,
  addPlane,
  addSegment,
  createEntity,
  createPhysicsWorld,
  inertiaOfSolidBox,
  type PhysicsWorld,
  removeBody,
  rotateFrom,
  setBoundary,
  step,
} from '@bitphysics/physics';
import { BoxGeometry, Color, Matrix4, MeshBasicMaterial, PerspectiveCamera, Quaternion, Scene, Vector3 } from 'three';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import {
  composeInto,
  equivalentBoxEdges,
  frameBox,
  hexToLinear,
  InstanceBook,
  type InstanceBookListener,
  resolveTrailOptions,
  rotateBack,
  slerpInto,
  WorldRenderer3D,
} from '../../packages/render-three/src/index';
import { type GamePage, Harness, START_TIMEOUT_MS } from './harness';

// ---------------------------------------------------------------------------------------------
// Node: bookkeeping and maths
// ---------------------------------------------------------------------------------------------

/** A listener that records every event as a string. */
function recorder(): InstanceBookListener & { log: string[] } {
  const log: string[] = [];
  return {
    log,
    added: (g, i, e) => log.push(`add g${g} i${i} e${e}`),
    moved: (g, from, to, e) => log.push(`move g${g} ${from}->${to} e${e}`),
    removed: (g, e) => log.push(`remove g${g} e${e}`),
  };
}

describe('InstanceBook (entity -> instance, swap-remove)', () => {
  it('adds densely per group and swap-removes, telling the listener what moved', () => {
    const book = new InstanceBook(10);
    const rec = recorder();
    book.listener = rec;
    const a = book.addGroup(2),
      b = book.addGroup();
    expect([a, b]).toEqual([0, 1]);
    expect(book.add(3, a, 1)).toBe(0);
    expect(book.add(5, a, 1)).toBe(1);
    expect(book.add(7, a, 1)).toBe(2); // grows past its initial 2
    expect(book.add(4, b, 1)).toBe(0);
    expect(book.total).toBe(4);
    expect(Array.from(book.eids(a).subarray(0, book.count(a)))).toEqual([3, 5, 7]);
    book.remove(3); // the last (7) moves into slot 0
    expect(Array.from(book.eids(a).subarray(0, book.count(a)))).toEqual([7, 5]);
    expect(book.indexOf[7]).toBe(0);
    expect(book.has(3)).toBe(false);
    book.remove(5); // already last: nothing moves
    book.remove(5); // not shown: no-op
    expect(rec.log).toEqual([
      'add g0 i0 e3',
      'add g0 i1 e5',
      'add g0 i2 e7',
      'add g1 i0 e4',
      'move g0 2->0 e7',
      'remove g0 e3',
      'remove g0 e5',
    ]);
    expect(book.groupOf(7)).toBe(0);
    expect(book.groupOf(4)).toBe(1);
    expect(book.groupOf(9)).toBe(-1);
    expect(book.total).toBe(2);
  });

  it('sweeps entities not marked in a pass, and re-adding moves an entity between groups', () => {
    const book = new InstanceBook(20);
    const g0 = book.addGroup(),
      g1 = book.addGroup();
    for (const e of [1, 2, 3, 4, 5]) book.add(e, e % 2 === 0 ? g1 : g0, 1);
    book.beginPass();
    for (const e of [1, 4, 5]) book.mark(e);
    expect(book.sweep()).toBe(2);
    expect([1, 2, 3, 4, 5].map((e) => book.has(e))).toEqual([true, false, false, true, true]);
    book.add(1, g1, 2); // moves from g0 to g1
    expect(book.groupOf(1)).toBe(g1);
    expect(book.stampOf[1]).toBe(2);
    expect(book.count(g0) + book.count(g1)).toBe(book.total);
    book.clear();
    expect(book.total).toBe(0);
  });

  it('rejects ids outside [1, capacity] and unknown groups', () => {
    const book = new InstanceBook(4);
    const g = book.addGroup();
    expect(() => book.add(0, g, 1)).toThrow(RangeError);
    expect(() => book.add(5, g, 1)).toThrow(/eid must be in \[1, 4\]/);
    expect(() => book.add(1, 3, 1)).toThrow(/unknown group 3/);
    expect(() => new InstanceBook(0)).toThrow(RangeError);
  });
});

describe('interpolation maths', () => {
  it('composeInto matches three.js Matrix4.compose', () => {
    const q = new Quaternion().setFromAxisAngle(new Vector3(1, 2, 3).normalize(), 0.9);
    const m = new Matrix4().compose(new Vector3(1, -2, 3), q, new Vector3(0.5, 2, 3));
    const out = new Float32Array(16);
    composeInto(out, 0, 1, -2, 3, q.x, q.y, q.z, q.w, 0.5, 2, 3);
    for (let i = 0; i < 16; i++) expect(out[i]).toBeCloseTo(m.elements[i]!, 6);
  });

  it('slerpInto matches three.js slerp, takes the short way and hits its ends', () => {
    const a = new Quaternion().setFromAxisAngle(new Vector3(0, 1, 0), 0.2);
    const b = new Quaternion().setFromAxisAngle(new Vector3(1, 0, 1).normalize(), 2.5);
    const out = new Float64Array(4);
    for (const t of [0, 0.25, 0.5, 0.9, 1]) {
      slerpInto(a.x, a.y, a.z, a.w, b.x, b.y, b.z, b.w, t, out, 0);
      const ref = a.clone().slerp(b, t);
      const sign = Math.sign(out[3]! * ref.w || 1);
      expect(out[0]! * sign).toBeCloseTo(ref.x, 9);
      expect(out[3]! * sign).toBeCloseTo(ref.w, 9);
    }
    // -b is the same rotation: the result must be the same rotation as with b.
    slerpInto(a.x, a.y, a.z, a.w, -b.x, -b.y, -b.z, -b.w, 0.5, out, 0);
    const mid = a.clone().slerp(b, 0.5);
    expect(Math.abs(out[0]! * mid.x + out[1]! * mid.y + out[2]! * mid.z + out[3]! * mid.w)).toBeCloseTo(1, 9);
  });

  it('rotateBack undoes one step of the physics orientation update (rotateFrom)', () => {
    const q = new Quaternion().setFromAxisAngle(new Vector3(0.3, 1, -0.2).normalize(), 1.1);
    const w = [0.7, -2.5, 1.9],
      h = 1 / 60;
    const x = new Float64Array(1),
      y = new Float64Array(1),
      z = new Float64Array(1),
      ww = new Float64Array(1);
    rotateFrom(x, y, z, ww, 0, q.x, q.y, q.z, q.w, w[0]! * h, w[1]! * h, w[2]! * h);
    const back = new Float64Array(4);
    rotateBack(x[0]!, y[0]!, z[0]!, ww[0]!, w[0]!, w[1]!, w[2]!, h, back, 0);
    expect(back[0]).toBeCloseTo(q.x, 12);
    expect(back[1]).toBeCloseTo(q.y, 12);
    expect(back[2]).toBeCloseTo(q.z, 12);
    expect(back[3]).toBeCloseTo(q.w, 12);
  });

  it('equivalentBoxEdges inverts inertiaOfSolidBox, and clamps impossible tensors', () => {
    const I = inertiaOfSolidBox(3, [0.3, 0.8, 1.4]);
    const out = new Float64Array(3);
    expect(equivalentBoxEdges(3, I[0], I[1], I[2], out)).toBe(true);
    expect(out[0]).toBeCloseTo(0.3, 12);
    expect(out[1]).toBeCloseTo(0.8, 12);
    expect(out[2]).toBeCloseTo(1.4, 12);
    // A locked axis (moment 0) gives a thin box, not NaN.
    expect(equivalentBoxEdges(1, 0, 1, 1, out)).toBe(true);
    expect(Math.min(...out)).toBeGreaterThan(0);
    expect(equivalentBoxEdges(0, 1, 1, 1, out)).toBe(false);
  });

  it('hexToLinear matches three.js Color (sRGB to linear)', () => {
    const out = new Float64Array(3);
    hexToLinear(0x3d7be0, out, 0);
    const c = new Color(0x3d7be0);
    expect(out[0]).toBeCloseTo(c.r, 6);
    expect(out[1]).toBeCloseTo(c.g, 6);
    expect(out[2]).toBeCloseTo(c.b, 6);
  });
});

// ---------------------------------------------------------------------------------------------
// Node: WorldRenderer3D without WebGL
// ---------------------------------------------------------------------------------------------

function world3(capacity = 64): PhysicsWorld {
  return createPhysicsWorld({ dimensions: 3, capacity, gravity: [0, -9.81, 0] });
}

/** The instanced mesh of the renderer's group of `kind` (first match). */
function meshOf(r: WorldRenderer3D, name: RegExp) {
  const found: Array<{
    name: string;
    count: number;
    instanceMatrix: { array: ArrayLike<number> };
    instanceColor: { array: ArrayLike<number> } | null;
  }> = [];
  r.root.traverse((o) => {
    if (name.test(o.name)) found.push(o as never);
  });
  if (found.length === 0) throw new Error(`no mesh named ${name}`);
  return found[0]!;
}

describe('WorldRenderer3D in Node (no WebGL)', () => {
  it('gives balls and boxes instances that follow the world: add, remove (swap), recycled ids', () => {
    const w = world3();
    const scene = new Scene();
    const r = new WorldRenderer3D(w, { scene, lights: false });
    expect(scene.children).toContain(r.root);
    const a = addBody(w, { position: [0, 1, 0], radius: 0.1 });
    const b = addBody(w, { position: [1, 1, 0], radius: 0.2 });
    const c = addBody(w, { position: [2, 1, 0], radius: 0.3 });
    const box = addBody(w, { position: [0, 2, 0], mass: 2, inertia: inertiaOfSolidBox(2, [0.2, 0.4, 0.6]) });
    createEntity(w); // an entity with no Position is never drawn
    r.render(1);
    expect(r.stats).toMatchObject({ instances: 4, balls: 3, boxes: 1, custom: 0, meshes: 2 });
    const balls = meshOf(r, /instances-ball/);
    expect(balls.count).toBe(3);
    removeBody(w, a);
    r.render(1);
    expect(balls.count).toBe(2);
    // The instances left are exactly the remaining balls, wherever swap-remove put them.
    const xs = [0, 1].map((i) => balls.instanceMatrix.array[16 * i + 12]).sort();
    expect(xs).toEqual([1, 2]);
    // Each instance's colour moved with its entity (swap-remove moves the tint along).
    const rgb = new Float64Array(3);
    for (let i = 0; i < 2; i++) {
      const eid = balls.instanceMatrix.array[16 * i + 12] === 1 ? b : c;
      hexToLinear(r.colorOf(eid), rgb, 0);
      for (let k = 0; k < 3; k++) expect(balls.instanceColor!.array[3 * i + k]).toBeCloseTo(rgb[k]!, 6);
    }
    // Recycled id: remove c and add a new ball that gets a recycled id; it must be drawn where the new one is.
    removeBody(w, c);
    const d = addBody(w, { position: [5, 1, 0], radius: 0.05 });
    r.render(1);
    expect(r.stats.balls).toBe(2);
    expect(r.drawnPosition(d)).toEqual([5, 1, 0]);
    expect(r.isShown(box)).toBe(true);
    expect(r.drawnPosition(999)).toBeNull();
  });

  it('interpolates positions (lerp) and orientations (slerp between the steps) for alpha', () => {
    const w = createPhysicsWorld({ dimensions: 3, capacity: 8, gravity: [0, 0, 0] });
    const r = new WorldRenderer3D(w, { lights: false });
    const e = addBody(w, { position: [0, 0, 0], velocity: [6, 0, 0], mass: 1, inertia: [1, 1, 1], angularVelocity: [0, 3, 0] });
    r.render(1);
    step(w);
    const q0 = new Quaternion(),
      q1 = new Quaternion();
    r.render(0);
    const O = w.components.Orientation;
    q1.set(O.x[e]!, O.y[e]!, O.z[e]!, O.w[e]!);
    // alpha 0: the start of the step (position and the orientation before it); alpha 1: now.
    expect(r.drawnPosition(e)![0]).toBeCloseTo(0, 12);
    const d0 = r.drawnOrientation(e)!;
    expect(Math.abs(d0[3]!)).toBeCloseTo(1, 12);
    r.render(0.5);
    expect(r.drawnPosition(e)![0]).toBeCloseTo(0.05, 12);
    const half = r.drawnOrientation(e)!;
    const ref = q0.clone().slerp(q1, 0.5);
    expect(Math.abs(half[0]! * ref.x + half[1]! * ref.y + half[2]! * ref.z + half[3]! * ref.w)).toBeCloseTo(1, 12);
    // The instance matrix carries the same pose.
    const mesh = meshOf(r, /instances-box/);
    const m = new Matrix4().fromArray(Array.from(mesh.instanceMatrix.array).slice(0, 16));
    const p = new Vector3(),
      q = new Quaternion(),
      s = new Vector3();
    m.decompose(p, q, s);
    expect(p.x).toBeCloseTo(0.05, 6);
    expect(Math.abs(q.dot(ref))).toBeCloseTo(1, 6);
    // Two steps between frames: alpha 0 shows the orientation one step back (turned back by w dt).
    step(w);
    const mid = new Quaternion(O.x[e]!, O.y[e]!, O.z[e]!, O.w[e]!);
    step(w);
    r.render(0);
    const back = r.drawnOrientation(e)!;
    expect(Math.abs(back[0]! * mid.x + back[1]! * mid.y + back[2]! * mid.z + back[3]! * mid.w)).toBeCloseTo(1, 9);
  });

  it('sizes boxes from the inertia tensor (equivalent box), balls from their radius', () => {
    const w = world3();
    const r = new WorldRenderer3D(w, { lights: false, unitsPerMeter: 2 });
    addBody(w, { position: [0, 0, 0], mass: 3, inertia: inertiaOfSolidBox(3, [0.3, 0.8, 1.4]) });
    addBody(w, { position: [1, 0, 0], radius: 0.25 });
    r.render(1);
    const s = new Vector3();
    new Matrix4()
      .fromArray(Array.from(meshOf(r, /instances-box/).instanceMatrix.array).slice(0, 16))
      .decompose(new Vector3(), new Quaternion(), s);
    expect(s.x).toBeCloseTo(0.6, 5); // edges x unitsPerMeter 2
    expect(s.y).toBeCloseTo(1.6, 5);
    expect(s.z).toBeCloseTo(2.8, 5);
    const p = new Vector3();
    new Matrix4().fromArray(Array.from(meshOf(r, /instances-ball/).instanceMatrix.array).slice(0, 16)).decompose(p, new Quaternion(), s);
    expect(s.x).toBeCloseTo(0.5, 6);
    expect(p.x).toBeCloseTo(2, 6);
  });

  it('keeps thousands of bodies in a handful of instanced meshes that grow by doubling', () => {
    const w = world3(6000);
    const r = new WorldRenderer3D(w, { lights: false, initialInstances: 16 });
    for (let i = 0; i < 5000; i++) addBody(w, { position: [i % 50, Math.floor(i / 50), 0], radius: 0.1 });
    for (let i = 0; i < 20; i++) addBody(w, { position: [0, -5, i], mass: 1, inertia: 0.1 });
    r.render(1);
    expect(r.stats).toMatchObject({ balls: 5000, boxes: 20, meshes: 2 });
    let meshes = 0;
    r.root.traverse((o) => {
      if ((o as { isInstancedMesh?: boolean }).isInstancedMesh) meshes++;
    });
    expect(meshes).toBe(2);
    const balls = meshOf(r, /instances-ball/);
    expect(balls.instanceMatrix.array.length).toBeGreaterThanOrEqual(5000 * 16);
    // A later frame reuses the same mesh (no growth, no new arrays).
    const array = balls.instanceMatrix.array;
    step(w);
    r.render(0.5);
    expect(meshOf(r, /instances-ball/).instanceMatrix.array).toBe(array);
  });

  it('setShape groups entities by geometry and material, tints white under a given material; setColor tints', () => {
    const w = world3();
    const r = new WorldRenderer3D(w, { lights: false });
    const geometry = new BoxGeometry(1, 1, 1),
      material = new MeshBasicMaterial();
    const a = addBody(w, { position: [0, 0, 0], radius: 0.5 });
    const b = addBody(w, { position: [1, 0, 0], radius: 0.5 });
    const c = addBody(w, { position: [2, 0, 0], radius: 0.5 });
    r.setShape(a, { geometry, material, scale: [1, 2, 3] });
    r.setShape(b, { geometry, material });
    r.setColor(c, '#ff0000');
    r.render(1);
    expect(r.stats).toMatchObject({ balls: 1, custom: 2, meshes: 2 });
    const custom = meshOf(r, /instances-custom/);
    expect(custom.count).toBe(2);
    expect(Array.from(custom.instanceColor!.array).slice(0, 6)).toEqual([1, 1, 1, 1, 1, 1]);
    const ball = meshOf(r, /instances-ball/);
    expect(ball.instanceColor!.array[0]).toBeCloseTo(1, 6);
    expect(ball.instanceColor!.array[1]).toBeCloseTo(0, 6);
    expect(r.colorOf(c)).toBe(0xff0000);
    // Back to the default sphere.
    r.setShape(a, null);
    r.render(1);
    expect(r.stats).toMatchObject({ balls: 2, custom: 1 });
    expect(() => r.setShape(a, { geometry: {} as never })).toThrow(/geometry must be a three.js BufferGeometry/);
    expect(() => r.setShape(a, { geometry, scale: -1 })).toThrow(/scale must be > 0, got -1/);
    expect(() => r.setColor(999, 0)).toThrow(RangeError);
  });

  it('trails: bounded, dense, one line object; freed with their entity', () => {
    const w = world3();
    const r = new WorldRenderer3D(w, { lights: false, trails: { length: 8, maxEntities: 2 } });
    const ids = [0, 1, 2].map((i) => addBody(w, { position: [i, 5, 0], radius: 0.1 }));
    r.render(1);
    expect(r.stats.trails).toBe(2); // maxEntities
    expect(ids.filter((e) => r.hasTrail(e)).length).toBe(2);
    for (let i = 0; i < 20; i++) {
      step(w);
      r.render(1);
    }
    const trailed = ids.find((e) => r.hasTrail(e))!;
    removeBody(w, trailed);
    r.render(1);
    // The freed slot goes to the next entity shown (the third ball was waiting).
    addBody(w, { position: [9, 9, 0], radius: 0.1 });
    r.render(1);
    expect(r.stats.trails).toBe(2);
    // A new look (another instanced mesh) keeps the trail.
    const kept = ids.find((e) => r.hasTrail(e))!;
    r.setShape(kept, { geometry: new BoxGeometry(1, 1, 1) });
    r.render(1);
    expect(r.hasTrail(kept)).toBe(true);
    expect(r.stats).toMatchObject({ custom: 1, trails: 2 });
    let lines = 0;
    r.root.traverse((o) => {
      if (o.name === 'trails') lines++;
    });
    expect(lines).toBe(1);
    r.setTrails(false);
    expect(r.trailsEnabled).toBe(false);
    expect(() => resolveTrailOptions('t', { length: 1 })).toThrow(/trails.length must be an integer in \[2, 8192\], got 1/);
    expect(() => resolveTrailOptions('t', { length: 8192, maxEntities: 1000 })).toThrow(/must be <= 4194304/);
  });

  it('debug layer draws axes, arrows and the last step contacts', () => {
    const w = world3();
    setBoundary(w, { min: [-1, 0, -1], max: [1, 2, 1] });
    const r = new WorldRenderer3D(w, { lights: false, debug: { angularVelocities: true } });
    addBody(w, { position: [0, 0.1, 0], radius: 0.1, velocity: [1, 0, 0] });
    addBody(w, { position: [0.5, 0.3, 0], mass: 1, inertia: [1, 2, 3], angularVelocity: [0, 1, 0] });
    step(w);
    r.render(1);
    expect(r.stats.contacts).toBeGreaterThan(0); // the ball on the floor
    expect(r.stats.arrows).toBeGreaterThanOrEqual(3); // two velocities (the box falls) and a spin
    r.setDebug(false);
    r.render(1);
    expect(r.stats.contacts).toBe(0);
  });

  it('draws the scenery: glass boundary with a floor, planes and segments', () => {
    const w = world3();
    setBoundary(w, { min: [-1, 0, -1], max: [1, 2, 1] });
    addPlane(w, { normal: [0, 1, 0], point: [0, -1, 0] });
    addSegment(w, { a: [0, 0, 0], b: [1, 1, 1] });
    const r = new WorldRenderer3D(w, {});
    r.render(1);
    const names: string[] = [];
    r.root.traverse((o) => names.push(o.name));
    expect(names).toEqual(expect.arrayContaining(['boundary', 'floor', 'planes', 'segments', 'lights', 'sun']));
    expect(r.lights!.sun.castShadow).toBe(true);
    // The sun's shadow camera was fitted around the box.
    expect(r.lights!.sun.target.position.y).toBeCloseTo(1, 9);
  });

  it('picks the entity under a screen point and reports the hit on its surface', () => {
    const w = createPhysicsWorld({ dimensions: 3, capacity: 8, gravity: [0, 0, 0] });
    const r = new WorldRenderer3D(w, { lights: false });
    addBody(w, { position: [0, 0, -3], radius: 0.5 });
    const box = addBody(w, { position: [2, 0, -3], mass: 1, inertia: inertiaOfSolidBox(1, [1, 1, 1]) });
    r.render(1);
    const camera = new PerspectiveCamera(50, 1, 0.1, 100);
    camera.position.set(2, 0, 0);
    camera.lookAt(2, 0, -3);
    camera.updateMatrixWorld();
    const hit = r.pick(0, 0, camera);
    expect(hit?.eid).toBe(box);
    expect(hit!.point[2]).toBeCloseTo(-2.5, 6); // the front face of the 1 m cube
    expect(hit!.normal[2]).toBeCloseTo(1, 6);
    expect(r.pick(0.99, 0.99, camera)).toBeNull();
    expect(() => r.pick(Number.NaN, 0, camera)).toThrow(/ndcX must be finite/);
  });

  it('follows a new world (setWorld), including one of another capacity', () => {
    const w = world3(16);
    const r = new WorldRenderer3D(w, { lights: false, trails: true });
    addBody(w, { position: [0, 0, 0], radius: 0.1 });
    r.render(1);
    const w2 = world3(200);
    for (let i = 0; i < 150; i++) addBody(w2, { position: [i, 0, 0], radius: 0.1 });
    r.setWorld(w2);
    r.render(1);
    expect(r.stats.balls).toBe(150);
    expect(r.world).toBe(w2);
    expect(() => r.setWorld(createPhysicsWorld({ dimensions: 2 }))).toThrow(/must be 3D/);
  });

  it('rejects bad options naming the option', () => {
    const w = world3();
    expect(() => new WorldRenderer3D(w, { unitsPerMeter: 0 })).toThrow(/unitsPerMeter must be > 0, got 0/);
    expect(() => new WorldRenderer3D(w, { sphereSegments: 2 })).toThrow(RangeError);
    expect(() => new WorldRenderer3D(w, { boundary: 'fog' as never })).toThrow(/boundary must be 'glass', 'edges' or 'none', got "fog"/);
    expect(() => new WorldRenderer3D(w, { colour: 1 } as never)).toThrow(TypeError);
    expect(() => new WorldRenderer3D(w, { ballMaterial: {} as never })).toThrow(/ballMaterial must be a three.js Material/);
    expect(() => new WorldRenderer3D(w, { lights: { shadowMapSize: 1000 } })).toThrow(/shadowMapSize must be a power of two/);
    expect(() => new WorldRenderer3D(w, { trails: { alpha: 0 } })).toThrow(/trails.alpha must be in \(0, 1\], got 0/);
    expect(() => new WorldRenderer3D(w, { debug: { maxContacts: -1 } })).toThrow(/debug.maxContacts/);
    expect(() => new WorldRenderer3D(createPhysicsWorld({ dimensions: 2 }))).toThrow(/must be 3D/);
    expect(() => new WorldRenderer3D({} as never)).toThrow(TypeError);
    const r = new WorldRenderer3D(w, { lights: false });
    expect(() => r.render(1.5)).toThrow(/alpha must be in \[0, 1\], got 1.5/);
    r.destroy();
    expect(() => r.render(1)).toThrow(/destroyed/);
    const camera = new PerspectiveCamera();
    expect(() => frameBox(camera, null, [0, 0, 0], [-1, 1, 1])).toThrow(/max\[0\] must be >= min\[0\]/);
  });
});

// ---------------------------------------------------------------------------------------------
// Browser: the 3D games
// ---------------------------------------------------------------------------------------------

interface ThreeGame {
  paused: boolean;
  reset(): void;
  step(): void;
  world: { time: number; steps: number; dt: number; components: { Velocity: { x: Float64Array; y: Float64Array; z: Float64Array } } };
  renderer: { stats: { instances: number; balls: number; meshes: number } };
  app: { info(): { calls: number; triangles: number; framesDrawn: number; framesSkipped: number }; render(): boolean };
}

describe('3D games in headless Chromium', () => {
  let h: Harness;
  beforeAll(async () => {
    h = await Harness.start();
  }, START_TIMEOUT_MS);
  afterAll(async () => {
    await h?.close();
  });

  /** Opens `folder` with `query`, checks it is drawn and error-free. */
  async function open(folder: string, query: Record<string, string | number | boolean>): Promise<GamePage> {
    const g = await h.openGame(folder, { query, readyTimeoutMs: 60_000 });
    expect(await g.canvasColors()).toBeGreaterThan(16);
    expect(g.errors).toEqual([]);
    return g;
  }

  it('balls-3d: draws, a drag throws one ball into the box, Space throws another; frames are paced to the GPU', async () => {
    const g = await open('balls-3d', { count: 30, trails: 0, shadows: 0 });
    const before = await g.page.evaluate(() => (window.game as unknown as { ballIds(): number[] }).ballIds().length);
    expect(before).toBe(30);
    await g.press('p'); // paused: the thrown ball keeps the velocity it was thrown with
    await g.dragCanvas([0.5, 0.55], [0.5, 0.75], 10);
    const thrown = await g.waitFor(() => {
      const game = window.game as unknown as ThreeGame & { ballIds(): number[] };
      const ids = game.ballIds();
      if (ids.length !== 31) return null;
      const e = ids[ids.length - 1]!,
        V = game.world.components.Velocity;
      return { vx: V.x[e]!, vy: V.y[e]!, vz: V.z[e]! };
    }, null);
    // The camera looks at the box from +z: a throw goes into the screen (-z), and the 200 px drag is faster than the slowest throw.
    expect(thrown.vz).toBeLessThan(0);
    expect(Math.hypot(thrown.vx, thrown.vy, thrown.vz)).toBeGreaterThan(2.5);
    await g.press('Space');
    await g.waitFor(() => (window.game as unknown as { ballIds(): number[] }).ballIds().length === 32, null);
    await g.press('p');
    await g.waitFor(() => (window.game as unknown as ThreeGame).renderer.stats.balls === 32, null);
    expect((await g.stats()).entities).toBe(32);
    // three.js pages pace their frames to the GPU (createThreeApp): two frames of GPU work outstanding at most.
    const r = await g.evaluate(
      () => {
        const app = (window.game as unknown as ThreeGame).app;
        const before = app.info();
        // A fence cannot signal before the page returns to its event loop (WebGL 2 spec, 5.27), so in
        // one task the third of three draws finds the two before it unfinished, whatever the GPU's speed.
        const drew = [app.render(), app.render(), app.render()];
        const after = app.info();
        return {
          drew,
          total: after.framesDrawn,
          drawn: after.framesDrawn - before.framesDrawn,
          skipped: after.framesSkipped - before.framesSkipped,
        };
      },
      null,
      'drawing three frames in one task',
    );
    expect(r.drew[2]).toBe(false);
    expect(r.drawn).toBeLessThanOrEqual(2);
    expect(r.drawn + r.skipped).toBe(3);
    // And the page goes on drawing afterwards: the fences signal between tasks.
    await g.waitFor((n) => (window.game as unknown as ThreeGame).app.info().framesDrawn > n + 2, r.total);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  // 3,000 balls with shadows are the heaviest GPU work of the suite: under SwiftShader on a busy machine
  // a frame took 1 to 2 s of GPU time. Before createThreeApp paced its frames to the GPU the page queued
  // about 4 frames a second without bound, and the read-back in canvasColors (or any call that waits for
  // the GPU) blocked the page for the whole queue: 5 s, then 16 s after 25 s of running, and in 2 of 6
  // CI runs for the test's whole 150 s. Paced, such a wait is at most two frames. Even paced, one
  // clean-clone run of three (2026-11-22, 5297c9e) stalled here for 60 s, and two more pages after it
  // (one of them 2D) timed out or lagged, as if the GPU process still drained this page's work: the
  // test now runs without shadows (the 2048^2 shadow map of 3,000 instances was most of that work;
  // the page-contract test still opens balls-3d at its defaults, shadows on). Without shadows it
  // stalled once more (a clean clone at 109b14c: 120 s, then the retry passed in 4 s). Cause, found
  // 2026-11-22 (harness STUCK_MS): now and then the page opened right after the 30-ball page closed
  // never got past its start, its main thread waiting without end on a GPU process whose main and
  // compositor threads sat idle in waits; the harness now reopens such a page after about 18 s.
  it('balls-3d: 3000 balls are a handful of draw calls and keep running', async () => {
    const g = await open('balls-3d', { count: 3000, trails: 0, shadows: 0 });
    const s0 = await g.stats();
    await g.waitFor((n) => window.game!.stats().steps > n + 2, s0.steps, 40_000);
    const info = await g.evaluate(
      () => {
        const game = window.game as unknown as ThreeGame;
        return { ...game.app.info(), meshes: game.renderer.stats.meshes, balls: game.renderer.stats.balls };
      },
      null,
      'reading the frame info',
    );
    expect(info.balls).toBe(3000);
    expect(info.meshes).toBe(1);
    // Balls (and their shadow pass when shadows are on), two glass sides, floor, edges (and trails
    // when on): 7 at most, whatever the ball count.
    expect(info.calls).toBeLessThanOrEqual(7);
    expect(info.framesDrawn).toBeGreaterThan(1);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it("rotating-cube: on the pivot each held key moves ω's tip its labelled way on screen; a click on a face changes ω", async () => {
    const g = await open('rotating-cube', { mode: 'cube' }); // on its pivot (the default is the room)
    // It starts tumbling slowly; X stops it.
    const w0 = await g.page.evaluate(() => (window.game as unknown as { angularVelocity(): number[] }).angularVelocity());
    expect(Math.hypot(...w0)).toBeGreaterThan(0.1);
    await g.press('x');
    await g.waitFor(() => Math.hypot(...(window.game as unknown as { angularVelocity(): number[] }).angularVelocity()) === 0, null);
    // Each key, held from rest, moves the ω arrow's tip the way its label says on screen: W up, S down,
    // A left, D right (the tip's page position through the game's camera, against the pivot's; page y
    // grows downwards), Q toward the camera, E away (ω along the camera's back axis, from its matrix).
    const want: Record<string, [number, number, number]> = {
      w: [0, -1, 0],
      s: [0, 1, 0],
      a: [-1, 0, 0],
      d: [1, 0, 0],
      q: [0, 0, 1],
      e: [0, 0, -1],
    };
    for (const [key, [sx, sy, sb]] of Object.entries(want)) {
      await g.page.keyboard.down(key);
      await g.waitFor(
        () => Math.hypot(...(window.game as unknown as { angularVelocity(): number[] }).angularVelocity()) > 0.2,
        null,
        20_000,
      );
      await g.page.keyboard.up(key);
      // The key torque is refreshed once a frame: let a frame see the key released before X stops the spin
      // (under load an X between the release and that frame was undone by one more step of torque).
      await g.frames(3);
      const seen = await g.page.evaluate(() => {
        type V = { x: number; y: number; z: number; project(c: unknown): V; applyMatrix4(m: unknown): V };
        const game = window.game as unknown as {
          angularVelocity(): number[];
          omegaArrow(): { from: number[]; scale: number };
          app: { camera: { position: { constructor: new (x: number, y: number, z: number) => V }; matrixWorldInverse: unknown } };
        };
        const w = game.angularVelocity();
        const { from, scale } = game.omegaArrow();
        const V3 = game.app.camera.position.constructor;
        const page = (v: V) => {
          const p = v.project(game.app.camera);
          const r = document.querySelector('canvas')!.getBoundingClientRect();
          return [r.left + ((p.x + 1) / 2) * r.width, r.top + ((1 - p.y) / 2) * r.height];
        };
        const o = page(new V3(from[0]!, from[1]!, from[2]!));
        const tip = page(new V3(from[0]! + w[0]! * scale, from[1]! + w[1]! * scale, from[2]! + w[2]! * scale));
        // ω in the camera's frame (a direction: the view matrix's rotation only); z is the camera's back axis.
        const inView = new V3(w[0]!, w[1]!, w[2]!).applyMatrix4(game.app.camera.matrixWorldInverse);
        const origin = new V3(0, 0, 0).applyMatrix4(game.app.camera.matrixWorldInverse);
        return { dx: tip[0]! - o[0]!, dy: tip[1]! - o[1]!, back: inView.z - origin.z, w: Math.hypot(...w) };
      });
      const moved = Math.hypot(seen.dx, seen.dy);
      if (sb === 0) {
        // On screen along the label's direction, within 15 degrees (cos 15° = 0.966), by more than 10 px.
        expect(moved, `${key}: the tip moved ${moved.toFixed(1)} px`).toBeGreaterThan(10);
        expect(
          (seen.dx * sx + seen.dy * sy) / moved,
          `${key}: tip moved (${seen.dx.toFixed(1)}, ${seen.dy.toFixed(1)}) px`,
        ).toBeGreaterThan(0.966);
      } else expect((seen.back * sb) / seen.w, `${key}: ω along the camera's back axis`).toBeGreaterThan(0.966);
      await g.page.keyboard.press('x');
      await g.waitFor(() => Math.hypot(...(window.game as unknown as { angularVelocity(): number[] }).angularVelocity()) === 0, null);
    }
    await g.press('p');
    // A click a little off the centre of the cube hits a face off its centre: torque r x J != 0.
    await g.clickCanvas(0.54, 0.46);
    const w2 = await g.waitFor(() => {
      const w = (window.game as unknown as { angularVelocity(): number[] }).angularVelocity();
      return Math.hypot(...w) > 1e-3 ? w : null;
    }, null);
    expect(Math.hypot(...w2)).toBeGreaterThan(0.01);
    // Away from the cube, a click does nothing.
    const missed = await g.page.evaluate(() => (window.game as unknown as { clickAt(x: number, y: number): boolean }).clickAt(0.95, 0.95));
    expect(missed).toBe(false);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('rotating-cube: the flip mode turns the box over while its angular momentum stays put', async () => {
    const g = await open('rotating-cube', { mode: 'flip' });
    const r = await g.page.evaluate(() => {
      const game = window.game as unknown as ThreeGame & { bodyUp(): number[]; angularMomentum(): number[] };
      game.paused = true;
      game.reset();
      const L0 = game.angularMomentum();
      let minUp = 1;
      for (let i = 0; i < 600; i++) {
        game.step();
        minUp = Math.min(minUp, game.bodyUp()[1]!);
      }
      const L1 = game.angularMomentum();
      return { minUp, L0, L1 };
    });
    expect(r.minUp).toBeLessThan(-0.9); // turned upside down
    for (let i = 0; i < 3; i++) expect(r.L1[i]).toBeCloseTo(r.L0[i]!, 6);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('rotating-cube: each flip counted pops its number; one made with the spin under the band pops why it did not count', async () => {
    // The status row's count and ✗ alone were missed while watching the box turn over.
    const g = await open('rotating-cube', { mode: 'flip' });
    type Cube = ThreeGame & {
      body(): number;
      challenge(): { flips: number };
      startClock(): void;
      pop(): { text: string; count: number };
      world: { components: { AngularVelocity: Record<'x' | 'y' | 'z', Float64Array> } };
    };
    // Paused, a fresh round spun at 10 rad/s (in the band) about the box's intermediate axis and tipped
    // 0.5 rad/s off it, so it flips within a second or two; the pivot's drag takes it under 8 rad/s in
    // about 2 s, after which its flips do not count. Steps in small batches, a frame between (the pops come with frames).
    await g.page.evaluate(() => {
      const game = window.game as unknown as Cube;
      game.paused = true;
      game.reset();
      const W = game.world.components.AngularVelocity;
      [W.x[game.body()], W.y[game.body()], W.z[game.body()]] = [0.5, 10, 0.5];
      game.startClock();
    });
    const pops: string[] = [];
    for (let batch = 0; batch < 120 && !pops.some((t) => t.startsWith('✗')); batch++) {
      const p = await g.page.evaluate(() => {
        const game = window.game as unknown as Cube;
        for (let i = 0; i < 6; i++) game.step();
        return game.pop();
      });
      await g.frames(1);
      const after = await g.page.evaluate(() => (window.game as unknown as Cube).pop());
      if (after.count > p.count) pops.push(after.text);
    }
    expect(pops[0]).toBe('Flip 1 of 10 ✓');
    expect(pops.find((t) => t.startsWith('✗'))).toMatch(/^✗ Not counted: spin [67]\.\d, under 8$/);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('rotating-cube: the flip challenge is lost left alone and holding D (it spins out of the band); the status row says so', async () => {
    const g = await open('rotating-cube', { mode: 'flip' });
    type Cube = ThreeGame & { challenge(): { flips: number; flipsWonAt: number }; startClock(): void };
    // 21 s of steps from a fresh world (the round is 20 s), paused so that only the steps count. The
    // round's clock starts at the first input (not the mode switch), so each round starts it as a
    // first key press would (startClock), before its steps.
    const round = () =>
      g.page.evaluate(() => {
        const game = window.game as unknown as Cube;
        game.paused = true;
        game.reset();
        game.startClock();
        for (let i = 0; i < 1260; i++) game.step();
        return game.challenge();
      });
    const idle = await round();
    expect(idle.flipsWonAt).toBe(-1);
    expect(idle.flips).toBeLessThan(10);
    await g.waitFor(() => document.querySelector('[data-hud="challenge"]')?.textContent?.includes('Time!') ?? false, null);
    // Running again, D held: a frame turns the keys held into the torque, which the steps then apply.
    await g.page.evaluate(() => {
      (window.game as unknown as Cube).paused = false;
    });
    await g.page.keyboard.down('d');
    await g.frames(3);
    const held = await round();
    await g.page.keyboard.up('d');
    // Flips count only with the spin in FLIP_BAND (8 to 12 rad/s): held through it and beyond, the box
    // makes few that count (scene.ts FlipChallenge; the headless test wins it by keeping in the band).
    expect(held.flipsWonAt).toBe(-1);
    expect(held.flips).toBeLessThan(5);
    await g.waitFor(() => document.querySelector('[data-hud="challenge"]')?.textContent?.includes('Time!') ?? false, null);
    // Held again for 6 s of a fresh round (spun up past 12 rad/s): the status row says to brake.
    await g.page.keyboard.down('d');
    await g.frames(3);
    await g.page.evaluate(() => {
      const game = window.game as unknown as Cube;
      game.reset();
      for (let i = 0; i < 360; i++) game.step();
    });
    await g.waitFor(() => document.querySelector('[data-hud="challenge"]')?.textContent?.includes('too fast') ?? false, null);
    await g.page.keyboard.up('d');
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('earth-moon: pause stops the clock, the time scale sets the simulated time a step', async () => {
    const g = await open('earth-moon', { texture: 256 });
    const day = 86_400;
    const r = await g.page.evaluate(() => {
      const game = window.game as unknown as ThreeGame & { setTimeScale(d: number): void; separation(): number };
      game.paused = true;
      const t0 = game.world.time;
      game.setTimeScale(1);
      game.step();
      const dt1 = game.world.time - t0;
      game.setTimeScale(10);
      const t1 = game.world.time,
        d1 = game.separation();
      game.step();
      const dt10 = game.world.time - t1;
      return { dt1, dt10, moved: Math.abs(game.separation() - d1), steps: game.world.steps };
    });
    expect(r.dt1).toBeCloseTo(day / 60, 6);
    expect(r.dt10).toBeCloseTo((10 * day) / 60, 6);
    expect(r.moved).toBeGreaterThan(0);
    // Paused: frames pass, the clock stands.
    const t = await g.page.evaluate(() => (window.game as unknown as ThreeGame).world.time);
    await g.frames(5);
    expect(await g.page.evaluate(() => (window.game as unknown as ThreeGame).world.time)).toBe(t);
    // P resumes: the clock runs again.
    await g.press('p');
    await g.waitFor((t0) => (window.game as unknown as ThreeGame).world.time > t0, t);
    // The panel's time-scale field drives the same parameter.
    const field = g.page.getByLabel('time scale (days/s)', { exact: true });
    await field.fill('0.5');
    await field.press('Enter');
    expect(await g.page.evaluate(() => (window.game as unknown as { params: { timeScale: number } }).params.timeScale)).toBe(0.5);
    // Both bodies are named on screen (the Moon is a few pixels across at the scale of its orbit).
    await g.waitFor(
      () => ['Earth', 'Moon'].every((n) => document.querySelector<HTMLElement>(`[data-label="${n}"]`)?.style.display === 'block'),
      null,
    );
    expect(g.errors).toEqual([]);
    await g.close();
  });
});
