import { type BufferGeometry, DynamicDrawUsage, InstancedBufferAttribute, InstancedMesh, type Material, type Object3D } from 'three';

/**
 * What an instance group draws: `'ball'` (the shared unit sphere, scaled by each ball's radius),
 * `'box'` (the shared unit cube, scaled to each body's equivalent-inertia box) or `'custom'` (a
 * user geometry and material given with `WorldRenderer3D.setShape`) or `'shapes'` (bodies drawn by their
 * 3D shapes, see shapes.ts: the group only carries their interpolated poses and is never shown).
 */
export type GroupKind = 'ball' | 'box' | 'custom' | 'shapes';

/**
 * One three.js `InstancedMesh` for one (geometry, material) pair: a single draw call (two with
 * shadows) for every entity of the group. Instance matrices and colours are written straight into
 * the mesh's Float32Arrays by the renderer; only the used prefix (0..count-1) is uploaded.
 *
 * The mesh is made with room for `capacity` instances and replaced by one twice as large when it
 * fills up (the old arrays are copied, the old mesh disposed): allocation happens on growth only.
 */
export class InstanceGroup {
  /** What the group draws. */
  readonly kind: GroupKind;
  /** Shared geometry (not owned: the renderer disposes its own geometries, users theirs). */
  readonly geometry: BufferGeometry;
  /** Shared material (not owned, as the geometry). */
  readonly material: Material;
  /** The mesh drawn now (replaced on growth; read it afresh, do not keep it). */
  mesh: InstancedMesh;
  /** Instances the mesh has room for. */
  capacity: number;
  /** Instances in use (the mesh draws this many). */
  count = 0;
  /** A hidden group keeps its instances' bookkeeping but never draws nor uploads (the 'shapes' group). */
  readonly hidden: boolean;
  private readonly parent: Object3D;
  private readonly name: string;

  /**
   * @param parent the object the mesh is added to. @param kind what the group draws.
   * @param initial instances to make room for at first, integer >= 1.
   * @param shadows whether the mesh casts and receives shadows.
   */
  constructor(
    parent: Object3D,
    geometry: BufferGeometry,
    material: Material,
    kind: GroupKind,
    name: string,
    initial: number,
    shadows: boolean,
  ) {
    this.parent = parent;
    this.geometry = geometry;
    this.material = material;
    this.kind = kind;
    this.name = name;
    this.hidden = kind === 'shapes';
    this.capacity = Math.max(1, initial);
    this.mesh = this.makeMesh(this.capacity, shadows);
    if (!this.hidden) parent.add(this.mesh); // a hidden group's mesh stays out of the scene
  }

  /** The instance matrices (16 floats per instance, column-major). */
  get matrices(): Float32Array {
    return this.mesh.instanceMatrix.array as Float32Array;
  }

  /** The instance colours (3 floats per instance, linear RGB). */
  get colors(): Float32Array {
    return this.mesh.instanceColor!.array as Float32Array;
  }

  /** Makes room for at least `n` instances (doubling). */
  ensure(n: number): void {
    if (n <= this.capacity) return;
    let cap = this.capacity;
    while (cap < n) cap *= 2;
    const old = this.mesh;
    const mesh = this.makeMesh(cap, old.castShadow);
    (mesh.instanceMatrix.array as Float32Array).set(old.instanceMatrix.array as Float32Array);
    (mesh.instanceColor!.array as Float32Array).set(old.instanceColor!.array as Float32Array);
    mesh.instanceColor!.needsUpdate = true;
    mesh.count = old.count;
    mesh.visible = old.visible;
    this.parent.remove(old);
    old.dispose();
    if (!this.hidden) this.parent.add(mesh);
    this.mesh = mesh;
    this.capacity = cap;
  }

  /**
   * Marks the first `count` matrices for upload and sets the drawn count (a group with no instances
   * is hidden, so it costs no draw call).
   */
  commit(count: number): void {
    this.count = count;
    const mesh = this.mesh;
    mesh.count = count;
    mesh.visible = count > 0 && !this.hidden;
    if (count === 0 || this.hidden) return;
    const m = mesh.instanceMatrix;
    m.clearUpdateRanges();
    m.addUpdateRange(0, count * 16);
    m.needsUpdate = true;
  }

  /** Marks every colour for upload (after colours were written). */
  colorsChanged(): void {
    this.mesh.instanceColor!.needsUpdate = true;
  }

  /** Sets whether the mesh casts and receives shadows. */
  setShadows(on: boolean): void {
    this.mesh.castShadow = on;
    this.mesh.receiveShadow = on;
  }

  /** Removes the mesh from its parent and frees its GPU buffers (not the shared geometry or material). */
  dispose(): void {
    this.parent.remove(this.mesh);
    this.mesh.dispose();
  }

  private makeMesh(capacity: number, shadows: boolean): InstancedMesh {
    const mesh = new InstancedMesh(this.geometry, this.material, capacity);
    mesh.name = this.name;
    mesh.instanceMatrix.setUsage(DynamicDrawUsage);
    const colors = new InstancedBufferAttribute(new Float32Array(capacity * 3).fill(1), 3);
    colors.setUsage(DynamicDrawUsage);
    mesh.instanceColor = colors;
    mesh.count = 0;
    mesh.visible = false;
    // Instances move every frame; the mesh's bounding sphere would be stale, so never cull the whole mesh.
    mesh.frustumCulled = false;
    mesh.castShadow = shadows;
    mesh.receiveShadow = shadows;
    return mesh;
  }
}
