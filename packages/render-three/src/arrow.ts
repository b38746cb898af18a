import { assertKnownKeys, assertNonNegative, assertPositive } from '@bitphysics/physics/validate';
import { type ColorInput, parseColor } from '@bitphysics/render-common';
import { ConeGeometry, CylinderGeometry, Group, Mesh, MeshStandardMaterial, Quaternion, Vector3 } from 'three';

/** Options of `new VectorArrow`. Every field optional; unknown fields are rejected. */
export interface VectorArrowOptions {
  /** Colour, 0xRRGGBB or '#rrggbb'. Default 0xffd166. */
  color?: ColorInput;
  /** Shaft radius, scene units, > 0. Default 0.02. */
  radius?: number;
  /** Head length, scene units, > 0 (shorter arrows get a proportionally shorter head). Default 0.12. */
  headLength?: number;
  /** Arrows shorter than this (scene units, >= 0) are hidden. Default 1e-4. */
  minLength?: number;
}

const ARROW_OPTIONS = ['color', 'radius', 'headLength', 'minLength'] as const;
const UP = new Vector3(0, 1, 0);

/**
 * A solid 3D arrow (cylinder shaft and cone head, lit like the scene) for a few physical vectors:
 * angular momentum, angular velocity, a force. `set` places it from an origin along a vector with a
 * scale (scene units per unit of the quantity), allocation-free. For thousands of arrows use the
 * debug layer instead (lines, one draw call).
 */
export class VectorArrow {
  /** The arrow's object; add it to the scene. */
  readonly object = new Group();
  private readonly shaft: Mesh;
  private readonly head: Mesh;
  private readonly material: MeshStandardMaterial;
  private readonly shaftGeometry: CylinderGeometry;
  private readonly headGeometry: ConeGeometry;
  private readonly headLength: number;
  private readonly radius: number;
  private readonly minLength: number;
  private readonly dir = new Vector3();
  private readonly q = new Quaternion();
  /** Length shown by the last `set`, scene units (0 when hidden). */
  length = 0;

  /** @throws TypeError | RangeError on bad options (named). */
  constructor(options: VectorArrowOptions = {}) {
    const where = 'VectorArrow';
    assertKnownKeys(where, options, ARROW_OPTIONS);
    const color = parseColor(where, 'color', options.color ?? 0xffd166);
    this.radius = options.radius ?? 0.02;
    assertPositive(where, 'radius', this.radius);
    this.headLength = options.headLength ?? 0.12;
    assertPositive(where, 'headLength', this.headLength);
    this.minLength = options.minLength ?? 1e-4;
    assertNonNegative(where, 'minLength', this.minLength);
    this.material = new MeshStandardMaterial({ color, roughness: 0.4, metalness: 0.1, emissive: color, emissiveIntensity: 0.25 });
    // Unit shaft from y = 0 to 1 and a unit cone from y = 0 to 1, scaled and placed by `set`.
    this.shaftGeometry = new CylinderGeometry(1, 1, 1, 12, 1);
    this.shaftGeometry.translate(0, 0.5, 0);
    this.headGeometry = new ConeGeometry(1, 1, 16, 1);
    this.headGeometry.translate(0, 0.5, 0);
    this.shaft = new Mesh(this.shaftGeometry, this.material);
    this.head = new Mesh(this.headGeometry, this.material);
    this.object.add(this.shaft, this.head);
    this.object.name = 'vector-arrow';
    this.object.visible = false;
  }

  /**
   * Shows the vector (vx, vy, vz) times `scale` starting at (ox, oy, oz) (scene units); hides the
   * arrow when the result is shorter than `minLength`. Non-finite input hides it too.
   */
  set(ox: number, oy: number, oz: number, vx: number, vy: number, vz: number, scale = 1): void {
    const x = vx * scale,
      y = vy * scale,
      z = vz * scale;
    const len = Math.sqrt(x * x + y * y + z * z);
    if (!(len >= this.minLength) || !Number.isFinite(len) || !Number.isFinite(ox + oy + oz)) {
      this.object.visible = false;
      this.length = 0;
      return;
    }
    this.length = len;
    this.object.visible = true;
    this.object.position.set(ox, oy, oz);
    this.dir.set(x / len, y / len, z / len);
    this.object.quaternion.copy(this.q.setFromUnitVectors(UP, this.dir));
    const head = Math.min(this.headLength, 0.4 * len);
    const shaft = len - head;
    const r = Math.min(this.radius, 0.2 * len);
    this.shaft.scale.set(r, Math.max(shaft, 1e-6), r);
    this.head.position.set(0, shaft, 0);
    this.head.scale.set(2.4 * r, head, 2.4 * r);
  }

  /** Hides the arrow. */
  hide(): void {
    this.object.visible = false;
    this.length = 0;
  }

  /** Frees the geometries and the material and removes the arrow from its parent. */
  dispose(): void {
    this.object.removeFromParent();
    this.shaftGeometry.dispose();
    this.headGeometry.dispose();
    this.material.dispose();
  }
}
