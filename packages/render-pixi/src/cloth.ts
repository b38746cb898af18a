import { isAlive, type PhysicsWorld, slotOf } from '@bitphysics/physics';
import { MeshSimple, Texture } from 'pixi.js';
import type { Camera } from './camera.js';

/** The cloth as `createCloth` returns it (point and link handles, grid size). */
export interface ClothGrid {
  readonly points: ArrayLike<number>;
  readonly links: ArrayLike<number>;
  readonly columns: number;
  readonly rows: number;
}

/** Options of `ClothLayer`. */
export interface ClothLayerOptions {
  /** Texture stretched over the cloth (u across, v down). Default: a checked fabric drawn on a canvas. */
  texture?: Texture;
}

/**
 * Draws a cloth (from `createCloth`) as a textured mesh whose vertices follow the points
 * (interpolated), two triangles a grid cell. A triangle disappears once one of its two edge links
 * (structural: top and left for the upper-left one, right and bottom for the lower-right one) has
 * torn (been removed). Reads Position, PreviousPosition and which link handles are still alive.
 */
export class ClothLayer {
  /** The pixi mesh to add to a container (e.g. the world renderer's root). */
  readonly mesh: MeshSimple;
  private readonly vertices: Float32Array;
  /** Per cell: the handles of its top, left, bottom and right structural links. */
  private readonly cellLinks: Float64Array;
  private builtVersion = -1;
  /** Triangles drawn since the last tear (two a whole cell, one a cell torn on one side). */
  triangles = 0;

  constructor(
    private readonly world: PhysicsWorld,
    private readonly cloth: ClothGrid,
    options: ClothLayerOptions = {},
  ) {
    const { columns: C, rows: R } = cloth;
    if (!(C >= 2 && R >= 2) || cloth.points.length !== C * R)
      throw new RangeError(
        `ClothLayer: cloth must have columns x rows points (>= 2 each), got ${C} x ${R} and ${cloth.points.length} points`,
      );
    this.vertices = new Float32Array(2 * C * R);
    const uvs = new Float32Array(2 * C * R);
    for (let r = 0; r < R; r++)
      for (let c = 0; c < C; c++) {
        const i = r * C + c;
        uvs[2 * i] = c / (C - 1);
        uvs[2 * i + 1] = r / (R - 1);
      }
    // Structural links come first in createCloth's order: for each point, right then down.
    const right = new Float64Array(C * R),
      down = new Float64Array(C * R);
    let k = 0;
    for (let r = 0; r < R; r++)
      for (let c = 0; c < C; c++) {
        const i = r * C + c;
        if (c + 1 < C) right[i] = cloth.links[k++]!;
        if (r + 1 < R) down[i] = cloth.links[k++]!;
      }
    this.cellLinks = new Float64Array(4 * (C - 1) * (R - 1));
    for (let r = 0; r + 1 < R; r++)
      for (let c = 0; c + 1 < C; c++) {
        const i = r * C + c,
          q = 4 * (r * (C - 1) + c);
        this.cellLinks[q] = right[i]!;
        this.cellLinks[q + 1] = down[i]!;
        this.cellLinks[q + 2] = right[i + C]!;
        this.cellLinks[q + 3] = down[i + 1]!;
      }
    this.mesh = new MeshSimple({
      texture: options.texture ?? fabricTexture(),
      vertices: this.vertices,
      uvs,
      indices: new Uint32Array(6 * (C - 1) * (R - 1)),
    });
    this.mesh.label = 'cloth';
  }

  /** Moves the vertices to the points for interpolation factor `alpha` through `camera`; drops torn cells. */
  update(camera: Camera, alpha: number): void {
    const P = this.world.components.Position,
      O = this.world.components.PreviousPosition;
    const v = this.vertices,
      pts = this.cloth.points;
    for (let i = 0; i < pts.length; i++) {
      const e = slotOf(pts[i]!);
      v[2 * i] = camera.toScreenX(O.x[e]! + (P.x[e]! - O.x[e]!) * alpha);
      v[2 * i + 1] = camera.toScreenY(O.y[e]! + (P.y[e]! - O.y[e]!) * alpha);
    }
    this.mesh.vertices = v;
    if (this.builtVersion !== this.world.cloth.version) this.rebuildIndices();
  }

  private rebuildIndices(): void {
    const { columns: C, rows: R } = this.cloth;
    const idx = new Uint32Array(6 * (C - 1) * (R - 1));
    let n = 0;
    for (let r = 0; r + 1 < R; r++)
      for (let c = 0; c + 1 < C; c++) {
        const q = 4 * (r * (C - 1) + c);
        const i = r * C + c;
        const L = this.cellLinks;
        // Each of the cell's two triangles stays while its own two edges hold: the upper-left one
        // (top and left links), the lower-right one (right and bottom). A tear through a cell takes out
        // one triangle, so a rip reads as a cut, not a row of square holes.
        if (isAlive(this.world, L[q]!) && isAlive(this.world, L[q + 1]!)) {
          idx[n++] = i;
          idx[n++] = i + 1;
          idx[n++] = i + C;
        }
        if (isAlive(this.world, L[q + 3]!) && isAlive(this.world, L[q + 2]!)) {
          idx[n++] = i + 1;
          idx[n++] = i + C + 1;
          idx[n++] = i + C;
        }
      }
    this.mesh.geometry.indices = idx.subarray(0, n);
    this.triangles = n / 3;
    this.builtVersion = this.world.cloth.version;
  }

  /** Removes and frees the mesh (and the default texture). */
  destroy(): void {
    this.mesh.destroy();
  }
}

/** A woven-looking checked fabric, 256 px square, drawn on a 2D canvas. */
function fabricTexture(): Texture {
  const size = 256;
  const canvas = document.createElement('canvas');
  canvas.width = size;
  canvas.height = size;
  const g = canvas.getContext('2d')!;
  g.fillStyle = '#b8323c';
  g.fillRect(0, 0, size, size);
  for (let i = 0; i < 16; i++) {
    g.fillStyle = i % 2 ? 'rgba(255, 230, 200, 0.18)' : 'rgba(40, 0, 10, 0.18)';
    g.fillRect(i * 16, 0, 8, size);
    g.fillRect(0, i * 16, size, 8);
  }
  g.strokeStyle = 'rgba(255, 240, 220, 0.5)';
  g.lineWidth = 3;
  g.strokeRect(1.5, 1.5, size - 3, size - 3);
  return Texture.from(canvas);
}
