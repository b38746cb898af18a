import { type Hull, type Mesh3D, meshesOf, type PhysicsWorld, Shape3DKind, type Shape3DStore, shapes3DOf } from '@bitphysics/physics';
import {
  BoxGeometry,
  BufferGeometry,
  CapsuleGeometry,
  CylinderGeometry,
  Float32BufferAttribute,
  Group,
  type Material,
  Mesh,
  MeshStandardMaterial,
} from 'three';
import { InstanceBook, type InstanceBookListener } from './book.js';
import { InstanceGroup } from './groups.js';
import { composeInto, hexToLinear } from './math.js';

/**
 * The layer that draws the 3D shapes of bodies (physics' `addShape3D`: spheres, boxes, capsules,
 * cylinders, convex hulls, and compounds of them), one instance per shape entity, placed each frame at
 * the pose the renderer drew its body with (interpolated) composed with the shape's placement in the
 * body frame. No three.js scene-graph object per shape: shapes of one kind and size class share one
 * `InstancedMesh` (one draw call, two with shadows).
 *
 * Size classes, so that every instance is its shape exactly:
 * - sphere: one unit sphere, scaled by the radius;
 * - box: one unit cube, scaled to the full edges (2 half extents);
 * - cylinder: one unit cylinder of CYLINDER_SEGMENTS sides (the prism physics collides a cylinder as),
 *   scaled by (r, half height, r);
 * - capsule: a capsule cannot be stretched without bending its caps, so one geometry per ratio
 *   half height / radius (rounded to CAPSULE_RATIO_STEP; the drawn straight part is within
 *   CAPSULE_RATIO_STEP r / 2 of the true one), scaled uniformly by the radius;
 * - hull: its own flat-shaded geometry from the hull's polygonal faces, shared by hulls with the same
 *   vertices (to 1e-6 m).
 *
 * Static triangle meshes and height fields (`addTriangleMesh3D`, `addHeightField3D`) are drawn as one
 * three.js mesh each, built once (smooth normals from the triangles), in `meshColor`.
 *
 * Per-entity state is in typed arrays of capacity + 1 indexed by shape slot; a frame allocates nothing
 * unless a new size class or a new triangle mesh appears.
 */

/** Sides of the drawn cylinder: 16, the sides of the prism a cylinder collides as (physics' CYLINDER_SIDES). */
export const CYLINDER_SEGMENTS = 16;
/** Step of the capsule size classes: ratios half height / radius are rounded to multiples of it. */
export const CAPSULE_RATIO_STEP = 0.01;

/** How many shapes of each kind the layer drew in the last frame. */
export interface ShapeCounts {
  spheres: number;
  boxes: number;
  capsules: number;
  cylinders: number;
  hulls: number;
  /** Instanced meshes in use (draw calls before shadows). */
  meshes: number;
  /** Static triangle meshes and height fields drawn. */
  triangleMeshes: number;
}

/** Per body, what the shape layer reads: where and how the renderer drew it this frame. */
export interface ShapeFrame {
  /** Bodies with shapes shown this frame (slots), 0..count-1. */
  bodies: Int32Array;
  count: number;
  /** Interpolated positions (xyz at 3 slot), m, and orientations (xyzw at 4 slot). */
  drawnPosition: Float64Array;
  drawnOrientation: Float64Array;
  /** Scene units per metre. */
  scale: number;
  /** The colour of a shape (slot) on a body (slot), 0xRRGGBB: the shape's own user colour, else its body's colour. */
  colorOf(shape: number, body: number): number;
}

/** Hull geometry: flat-shaded triangles fanned from each polygonal face, with the face's normal. */
export function hullGeometry(hull: Hull): BufferGeometry {
  const pos: number[] = [],
    nor: number[] = [];
  const V = hull.vertices,
    F = hull.faceVertices,
    N = hull.faceNormals;
  for (let f = 0; f + 1 < hull.faceStart.length; f++) {
    const s = hull.faceStart[f]!,
      e = hull.faceStart[f + 1]!;
    for (let i = s + 1; i + 1 < e; i++) {
      for (const v of [F[s]!, F[i]!, F[i + 1]!]) {
        pos.push(V[3 * v]!, V[3 * v + 1]!, V[3 * v + 2]!);
        nor.push(N[3 * f]!, N[3 * f + 1]!, N[3 * f + 2]!);
      }
    }
  }
  const g = new BufferGeometry();
  g.setAttribute('position', new Float32BufferAttribute(pos, 3));
  g.setAttribute('normal', new Float32BufferAttribute(nor, 3));
  g.computeBoundingSphere();
  return g;
}

/** The key of a hull's size class: its vertices rounded to 1e-6 m. */
function hullKey(hull: Hull): string {
  let key = 'h';
  const V = hull.vertices;
  for (let i = 0; i < V.length; i++) key += `,${Math.round(V[i]! * 1e6)}`;
  return key;
}

/** Shape layer of `WorldRenderer3D`; see the module comment. */
export class ShapeLayer3D {
  /** Parent of the layer's meshes. */
  readonly object = new Group();
  /** Counts of the last frame. */
  readonly counts: ShapeCounts = { spheres: 0, boxes: 0, capsules: 0, cylinders: 0, hulls: 0, meshes: 0, triangleMeshes: 0 };
  /** The drawn static triangle meshes, by their physics record. */
  private readonly triangleMeshes = new Map<Mesh3D, Mesh>();
  private readonly meshMaterial: MeshStandardMaterial;
  private readonly material: Material;
  private readonly shadows: boolean;
  private readonly sphere: BufferGeometry;
  private readonly box = new BoxGeometry(1, 1, 1);
  private readonly cylinder = new CylinderGeometry(1, 1, 2, CYLINDER_SEGMENTS);
  private readonly owned: BufferGeometry[] = [];
  private readonly groups: InstanceGroup[] = [];
  private readonly groupKind: number[] = [];
  private readonly byKey = new Map<string, number>();
  private book: InstanceBook;
  private scale = new Float64Array(0);
  private written = new Uint32Array(0);
  private colorVersion = 1;
  private readonly listener: InstanceBookListener;

  /**
   * @param capacity the world's capacity. @param material the material of every shape (instance colours tint it).
   * @param sphere the unit sphere geometry to share (not owned). @param shadows cast and receive shadows.
   */
  constructor(capacity: number, material: Material, sphere: BufferGeometry, shadows: boolean, meshColor = 0x4a5568) {
    this.material = material;
    this.meshMaterial = new MeshStandardMaterial({ color: meshColor, roughness: 0.9, metalness: 0, flatShading: false });
    this.sphere = sphere;
    this.shadows = shadows;
    this.object.name = 'shapes3d';
    this.book = new InstanceBook(capacity);
    this.listener = {
      added: (g, i) => this.groups[g]!.ensure(i + 1),
      moved: (_g, _from, _to, e) => {
        this.written[e] = 0;
      },
      removed: () => undefined,
    };
    this.book.listener = this.listener;
    this.allocate(capacity);
  }

  /** Forgets every shape (a new world); `capacity` is the new world's. */
  reset(capacity: number): void {
    this.book.clear();
    if (capacity !== this.book.capacity) {
      this.book = new InstanceBook(capacity);
      this.book.listener = this.listener;
      for (let g = 0; g < this.groups.length; g++) this.book.addGroup(this.groups[g]!.capacity);
      this.allocate(capacity);
    }
    for (const g of this.groups) g.commit(0);
    this.dropTriangleMeshes(null);
  }

  /** Colours are rewritten at the next draw (after a body's colour changed). */
  recolor(): void {
    this.colorVersion++;
  }

  /** Sets shadow casting and receiving of every mesh. */
  setShadows(on: boolean): void {
    for (const g of this.groups) g.setShadows(on);
    for (const m of this.triangleMeshes.values()) {
      m.castShadow = on;
      m.receiveShadow = on;
    }
  }

  /** Places every shape of the bodies in `frame` for this frame. */
  draw(world: PhysicsWorld, frame: ShapeFrame): void {
    this.drawTriangleMeshes(world, frame.scale);
    const s = shapes3DOf(world);
    const book = this.book;
    const counts = this.counts;
    counts.spheres = counts.boxes = counts.capsules = counts.cylinders = counts.hulls = counts.meshes = 0;
    counts.triangleMeshes = this.triangleMeshes.size;
    book.beginPass();
    if (s !== undefined) {
      const spawn = world.spawnStamp;
      for (let i = 0; i < frame.count; i++) {
        const b = frame.bodies[i]!;
        for (let e = s.first[b]!; e !== 0; e = s.next[e]!) {
          if (book.has(e)) {
            if (book.stampOf[e] === spawn[e]) {
              book.mark(e);
              continue;
            }
            book.remove(e);
          }
          book.add(e, this.classify(s, e), spawn[e]!);
          this.written[e] = 0;
        }
      }
    }
    book.sweep();
    if (s === undefined) {
      for (const g of this.groups) g.commit(0);
      return;
    }
    const dp = frame.drawnPosition,
      dq = frame.drawnOrientation,
      k = frame.scale;
    const px = s.px,
      py = s.py,
      pz = s.pz,
      qx = s.qx,
      qy = s.qy,
      qz = s.qz,
      qw = s.qw,
      body = s.body;
    const scale = this.scale,
      written = this.written,
      version = this.colorVersion;
    for (let g = 0; g < this.groups.length; g++) {
      const group = this.groups[g]!;
      const n = book.count(g);
      if (n === 0) {
        group.commit(0);
        continue;
      }
      counts.meshes++;
      switch (this.groupKind[g]) {
        case Shape3DKind.Sphere:
          counts.spheres += n;
          break;
        case Shape3DKind.Box:
          counts.boxes += n;
          break;
        case Shape3DKind.Capsule:
          counts.capsules += n;
          break;
        case Shape3DKind.Cylinder:
          counts.cylinders += n;
          break;
        default:
          counts.hulls += n;
      }
      const eids = book.eids(g),
        m = group.matrices;
      let recolored = false;
      for (let i = 0; i < n; i++) {
        const e = eids[i]!,
          b = body[e]!;
        const bx = dp[3 * b]!,
          by = dp[3 * b + 1]!,
          bz = dp[3 * b + 2]!;
        const x = dq[4 * b]!,
          y = dq[4 * b + 1]!,
          z = dq[4 * b + 2]!,
          w = dq[4 * b + 3]!;
        // Shape centre: body position + R(q_body) p_shape (v + 2 w (u x v) + 2 u x (u x v)).
        const vx = px[e]!,
          vy = py[e]!,
          vz = pz[e]!;
        const tx = 2 * (y * vz - z * vy),
          ty = 2 * (z * vx - x * vz),
          tz = 2 * (x * vy - y * vx);
        const cx = bx + vx + w * tx + (y * tz - z * ty),
          cy = by + vy + w * ty + (z * tx - x * tz),
          cz = bz + vz + w * tz + (x * ty - y * tx);
        // Shape orientation: q_body q_shape.
        const sx = qx[e]!,
          sy = qy[e]!,
          sz = qz[e]!,
          sw = qw[e]!;
        const ox = w * sx + x * sw + y * sz - z * sy,
          oy = w * sy - x * sz + y * sw + z * sx;
        const oz = w * sz + x * sy - y * sx + z * sw,
          ow = w * sw - x * sx - y * sy - z * sz;
        composeInto(m, 16 * i, cx * k, cy * k, cz * k, ox, oy, oz, ow, scale[3 * e]! * k, scale[3 * e + 1]! * k, scale[3 * e + 2]! * k);
        if (written[e] !== version) {
          written[e] = version;
          hexToLinear(frame.colorOf(e, b), group.colors, 3 * i);
          recolored = true;
        }
      }
      if (recolored) group.colorsChanged();
      group.commit(n);
    }
  }

  /** Frees the meshes and the geometries the layer made. */
  destroy(): void {
    this.dropTriangleMeshes(null);
    this.meshMaterial.dispose();
    this.object.removeFromParent();
    for (const g of this.groups) g.dispose();
    this.box.dispose();
    this.cylinder.dispose();
    for (const g of this.owned) g.dispose();
  }

  /** Builds a three.js mesh for each static triangle mesh not drawn yet; drops those removed. */
  private drawTriangleMeshes(world: PhysicsWorld, k: number): void {
    const list = world.dimensions === 3 ? meshesOf(world) : [];
    if (list.length === 0 && this.triangleMeshes.size === 0) return;
    this.dropTriangleMeshes(list);
    for (const m of list) {
      let mesh = this.triangleMeshes.get(m);
      if (mesh === undefined) {
        const g = new BufferGeometry();
        g.setAttribute('position', new Float32BufferAttribute(Array.from(m.vertices), 3));
        g.setIndex(Array.from(m.triangles));
        g.computeVertexNormals();
        mesh = new Mesh(g, this.meshMaterial);
        mesh.name = `triangle-mesh-${m.entity}`;
        mesh.castShadow = this.shadows;
        mesh.receiveShadow = this.shadows;
        this.triangleMeshes.set(m, mesh);
        this.object.add(mesh);
      }
      mesh.scale.setScalar(k);
    }
  }

  /** Removes the drawn triangle meshes not in `keep` (all of them for null). */
  private dropTriangleMeshes(keep: readonly Mesh3D[] | null): void {
    for (const [m, mesh] of this.triangleMeshes) {
      if (keep?.includes(m)) continue;
      mesh.removeFromParent();
      mesh.geometry.dispose();
      this.triangleMeshes.delete(m);
    }
  }

  private allocate(capacity: number): void {
    this.scale = new Float64Array(3 * (capacity + 1));
    this.written = new Uint32Array(capacity + 1);
  }

  /** The group shape `e` is drawn in (made on first use); fills its scale. */
  private classify(s: Shape3DStore, e: number): number {
    const kind = s.kind[e]!,
      o = 3 * e,
      sc = this.scale;
    let key: string;
    let make: () => BufferGeometry;
    switch (kind) {
      case Shape3DKind.Sphere:
        sc[o] = sc[o + 1] = sc[o + 2] = s.radius[e]!;
        key = 'sphere';
        make = () => this.sphere;
        break;
      case Shape3DKind.Box:
        sc[o] = 2 * s.hx[e]!;
        sc[o + 1] = 2 * s.hy[e]!;
        sc[o + 2] = 2 * s.hz[e]!;
        key = 'box';
        make = () => this.box;
        break;
      case Shape3DKind.Cylinder:
        sc[o] = s.radius[e]!;
        sc[o + 1] = s.hy[e]!;
        sc[o + 2] = s.radius[e]!;
        key = 'cylinder';
        make = () => this.cylinder;
        break;
      case Shape3DKind.Capsule: {
        const r = s.radius[e]!;
        const ratio = Math.max(CAPSULE_RATIO_STEP, Math.round(s.hy[e]! / r / CAPSULE_RATIO_STEP) * CAPSULE_RATIO_STEP);
        sc[o] = sc[o + 1] = sc[o + 2] = r;
        key = `capsule:${ratio.toFixed(2)}`;
        make = () => this.keep(new CapsuleGeometry(1, 2 * ratio, 8, 16));
        break;
      }
      default: {
        const hull = s.hulls[s.hull[e]!]!;
        sc[o] = sc[o + 1] = sc[o + 2] = 1;
        key = hullKey(hull);
        make = () => this.keep(hullGeometry(hull));
      }
    }
    const known = this.byKey.get(key);
    if (known !== undefined) return known;
    const g = this.book.addGroup(16);
    this.groups.push(new InstanceGroup(this.object, make(), this.material, 'custom', `shapes-${key.slice(0, 24)}-${g}`, 16, this.shadows));
    this.groupKind.push(kind);
    this.byKey.set(key, g);
    return g;
  }

  private keep(g: BufferGeometry): BufferGeometry {
    this.owned.push(g);
    return g;
  }
}
