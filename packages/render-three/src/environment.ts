import type { PhysicsWorld } from '@bitphysics/physics';
import { query } from 'bitecs';
import {
  BackSide,
  BoxGeometry,
  BufferAttribute,
  BufferGeometry,
  Color,
  DoubleSide,
  EdgesGeometry,
  FrontSide,
  Group,
  LineBasicMaterial,
  LineSegments,
  type Material,
  Mesh,
  MeshStandardMaterial,
  PlaneGeometry,
  Quaternion,
  Vector3,
} from 'three';

/**
 * How the boundary box (`setBoundary`) is drawn: `'glass'` (translucent walls, an opaque floor that
 * receives shadows, and outlined edges), `'edges'` (outline only) or `'none'`.
 */
export type BoundaryStyle = 'glass' | 'edges' | 'none';

/** Colours and sizes of the static scenery (resolved by the renderer). */
export interface EnvironmentStyle {
  /** How the boundary box is drawn. */
  boundary: BoundaryStyle;
  /** Edge colour of the boundary box, 0xRRGGBB. */
  boundaryColor: number;
  /** Tint of the glass walls, 0xRRGGBB. */
  glassColor: number;
  /** Opacity of the glass walls, [0, 1]. */
  glassOpacity: number;
  /** Floor colour of the boundary box and colour of planes, 0xRRGGBB. */
  floorColor: number;
  /** Colour of static segments, 0xRRGGBB. */
  segmentColor: number;
  /** Edge of the square drawn for each infinite plane, m. 0: from the boundary box, or 40 m without one. */
  planeSize: number;
  /** Whether floors and planes receive shadows. */
  shadows: boolean;
}

/**
 * The static scenery of a world: the boundary box, infinite planes (drawn as large squares) and
 * static segments (drawn as lines). Each frame it compares a cheap signature of what the world holds
 * (the box corners, the plane and segment entities) with what it built, and rebuilds only on a change.
 */
export class EnvironmentLayer {
  /** Parent of the scenery; the renderer adds it to its root. */
  readonly object = new Group();
  private readonly style: EnvironmentStyle;
  private readonly seen = new Float64Array(8);
  private planeSignature = -1;
  private segmentSignature = -1;
  private scaleSeen = -1;
  private boundaryGroup: Group | null = null;
  private planeGroup: Group | null = null;
  private segmentLines: LineSegments | null = null;
  private readonly owned: Array<{ dispose(): void }> = [];
  private readonly planeOwned: Array<{ dispose(): void }> = [];
  private readonly segmentOwned: Array<{ dispose(): void }> = [];
  private planeTerms: object[] = [];
  private segmentTerms: object[] = [];

  /** @param style resolved colours and sizes. */
  constructor(style: EnvironmentStyle) {
    this.style = style;
    this.object.name = 'environment';
    this.seen[0] = -1;
  }

  /** Number of planes drawn. */
  planes = 0;
  /** Number of segments drawn. */
  segments = 0;

  /** Forgets what was built (the next `update` rebuilds for `world`). */
  bind(world: PhysicsWorld): void {
    const c = world.components;
    this.planeTerms = [c.Plane];
    this.segmentTerms = [c.Segment];
    this.seen[0] = -1;
    this.planeSignature = -1;
    this.segmentSignature = -1;
  }

  /** Rebuilds whatever changed in `world` since the last call. @param scale scene units per metre. */
  update(world: PhysicsWorld, scale: number): void {
    const scaleChanged = scale !== this.scaleSeen;
    this.scaleSeen = scale;
    const box = world.collision.boundary;
    const seen = this.seen;
    const on = box.enabled ? 1 : 0;
    if (
      scaleChanged ||
      seen[0] !== on ||
      seen[1] !== box.min[0] ||
      seen[2] !== box.min[1] ||
      seen[3] !== box.min[2] ||
      seen[4] !== box.max[0] ||
      seen[5] !== box.max[1] ||
      seen[6] !== box.max[2]
    ) {
      seen[0] = on;
      seen[1] = box.min[0]!;
      seen[2] = box.min[1]!;
      seen[3] = box.min[2]!;
      seen[4] = box.max[0]!;
      seen[5] = box.max[1]!;
      seen[6] = box.max[2]!;
      this.buildBoundary(world, scale);
      this.planeSignature = -1; // plane size may follow the box
    }
    const planes = query(world, this.planeTerms);
    const ps = signature(world, planes);
    if (scaleChanged || ps !== this.planeSignature) {
      this.planeSignature = ps;
      this.buildPlanes(world, planes, scale);
    }
    const segs = query(world, this.segmentTerms);
    const ss = signature(world, segs);
    if (scaleChanged || ss !== this.segmentSignature) {
      this.segmentSignature = ss;
      this.buildSegments(world, segs, scale);
    }
  }

  /** Frees every geometry and material. */
  destroy(): void {
    this.clearBoundary();
    this.clearPlanes();
    this.clearSegments();
    this.object.removeFromParent();
  }

  private clearBoundary(): void {
    if (this.boundaryGroup) this.object.remove(this.boundaryGroup);
    this.boundaryGroup = null;
    for (const d of this.owned.splice(0)) d.dispose();
  }

  private clearPlanes(): void {
    if (this.planeGroup) this.object.remove(this.planeGroup);
    this.planeGroup = null;
    for (const d of this.planeOwned.splice(0)) d.dispose();
    this.planes = 0;
  }

  private clearSegments(): void {
    if (this.segmentLines) this.object.remove(this.segmentLines);
    this.segmentLines = null;
    for (const d of this.segmentOwned.splice(0)) d.dispose();
    this.segments = 0;
  }

  private buildBoundary(world: PhysicsWorld, k: number): void {
    this.clearBoundary();
    const box = world.collision.boundary;
    const st = this.style;
    if (!box.enabled || st.boundary === 'none' || world.dimensions !== 3) return;
    const min = box.min,
      max = box.max;
    const sx = (max[0]! - min[0]!) * k,
      sy = (max[1]! - min[1]!) * k,
      sz = (max[2]! - min[2]!) * k;
    const cx = 0.5 * (min[0]! + max[0]!) * k,
      cy = 0.5 * (min[1]! + max[1]!) * k,
      cz = 0.5 * (min[2]! + max[2]!) * k;
    const group = new Group();
    group.name = 'boundary';
    const geometry = new BoxGeometry(sx, sy, sz);
    this.owned.push(geometry);
    const edges = new EdgesGeometry(geometry);
    this.owned.push(edges);
    const edgeMaterial = new LineBasicMaterial({ color: st.boundaryColor, transparent: true, opacity: 0.9 });
    this.owned.push(edgeMaterial);
    const lines = new LineSegments(edges, edgeMaterial);
    lines.position.set(cx, cy, cz);
    group.add(lines);
    if (st.boundary === 'glass') {
      // Inner faces first (the far walls, seen through the near ones), then the near faces; both
      // translucent and without depth writes so balls show through. The floor is drawn separately.
      const back = glass(st, BackSide);
      const front = glass(st, FrontSide);
      this.owned.push(back, front);
      // The walls and the ceiling as one index range (one draw call a side): BoxGeometry's groups
      // are +x, -x, +y, -y, +z, -z, and -y (the floor) is drawn separately.
      const walls = geometry.clone();
      const index = geometry.index!.array;
      const kept: number[] = [];
      for (const g of geometry.groups) if (g.materialIndex !== 3) for (let i = g.start; i < g.start + g.count; i++) kept.push(index[i]!);
      walls.setIndex(kept);
      walls.clearGroups();
      this.owned.push(walls);
      const inner = new Mesh(walls, back);
      const outer = new Mesh(walls, front);
      inner.position.set(cx, cy, cz);
      outer.position.set(cx, cy, cz);
      inner.renderOrder = 2;
      outer.renderOrder = 3;
      group.add(inner, outer);
      const floorGeometry = new PlaneGeometry(sx, sz);
      const floorMaterial = new MeshStandardMaterial({ color: st.floorColor, roughness: 0.92, metalness: 0, side: DoubleSide });
      this.owned.push(floorGeometry, floorMaterial);
      const floor = new Mesh(floorGeometry, floorMaterial);
      floor.rotation.x = -Math.PI / 2;
      floor.position.set(cx, min[1]! * k, cz);
      floor.receiveShadow = st.shadows;
      floor.name = 'floor';
      group.add(floor);
    }
    this.boundaryGroup = group;
    this.object.add(group);
  }

  private buildPlanes(world: PhysicsWorld, planes: ArrayLike<number>, k: number): void {
    this.clearPlanes();
    if (planes.length === 0 || world.dimensions !== 3) return;
    const st = this.style;
    const box = world.collision.boundary;
    let size = st.planeSize;
    if (!(size > 0)) size = box.enabled ? 3 * Math.max(box.max[0]! - box.min[0]!, box.max[2]! - box.min[2]!) : 40;
    const group = new Group();
    group.name = 'planes';
    const geometry = new PlaneGeometry(size * k, size * k);
    const material = new MeshStandardMaterial({ color: st.floorColor, roughness: 0.95, metalness: 0, side: DoubleSide });
    this.planeOwned.push(geometry, material);
    const P = world.components.Plane;
    const from = new Vector3(0, 0, 1),
      to = new Vector3();
    const q = new Quaternion();
    for (let i = 0; i < planes.length; i++) {
      const e = planes[i]!;
      to.set(P.nx[e]!, P.ny[e]!, P.nz[e]!);
      q.setFromUnitVectors(from, to);
      const mesh = new Mesh(geometry, material);
      mesh.quaternion.copy(q);
      const d = P.d[e]! * k;
      // The point of the plane nearest the boundary's centre (or the origin) keeps the square in view.
      const cx = box.enabled ? 0.5 * (box.min[0]! + box.max[0]!) * k : 0;
      const cy = box.enabled ? 0.5 * (box.min[1]! + box.max[1]!) * k : 0;
      const cz = box.enabled ? 0.5 * (box.min[2]! + box.max[2]!) * k : 0;
      const off = d - (to.x * cx + to.y * cy + to.z * cz);
      mesh.position.set(cx + to.x * off, cy + to.y * off, cz + to.z * off);
      mesh.receiveShadow = st.shadows;
      mesh.name = `plane-${e}`;
      group.add(mesh);
    }
    this.planes = planes.length;
    this.planeGroup = group;
    this.object.add(group);
  }

  private buildSegments(world: PhysicsWorld, segs: ArrayLike<number>, k: number): void {
    this.clearSegments();
    if (segs.length === 0) return;
    const S = world.components.Segment;
    const positions = new Float32Array(segs.length * 6);
    for (let i = 0; i < segs.length; i++) {
      const e = segs[i]!;
      positions.set([S.ax[e]! * k, S.ay[e]! * k, S.az[e]! * k, S.bx[e]! * k, S.by[e]! * k, S.bz[e]! * k], i * 6);
    }
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(positions, 3));
    const material = new LineBasicMaterial({ color: new Color(this.style.segmentColor) });
    this.segmentOwned.push(geometry, material);
    const lines = new LineSegments(geometry, material);
    lines.name = 'segments';
    this.segments = segs.length;
    this.segmentLines = lines;
    this.object.add(lines);
  }
}

function glass(st: EnvironmentStyle, side: typeof FrontSide | typeof BackSide): Material {
  return new MeshStandardMaterial({
    color: st.glassColor,
    transparent: true,
    opacity: side === BackSide ? st.glassOpacity * 0.6 : st.glassOpacity,
    roughness: 0.08,
    metalness: 0,
    depthWrite: false,
    side,
  });
}

/** A number that changes when the set of entities (or a recycled id) changes: count and stamp-weighted id sum. */
function signature(world: PhysicsWorld, ents: ArrayLike<number>): number {
  let s = ents.length * 7919;
  const stamps = world.spawnStamp;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    s = (Math.imul(s, 31) + e * 131 + stamps[e]!) | 0;
  }
  return s;
}
