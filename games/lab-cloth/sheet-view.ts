/**
 * Draws the sheet: a textured mesh whose vertices follow the cloth's points (interpolated between
 * steps), shaded per vertex by how the cloth is deformed there, with its edges sewn and its tears frayed.
 *
 * - Stretch: where the links at a point are longer than at rest, the weave opens: the fabric turns
 *   lighter and lets the sky through (at a strain of 0.4, a third of the light).
 * - Folds: where the cloth is gathered (the points two links apart along a row or a column closer than
 *   at rest, as between the pegs), it is darker, as a crease in shadow.
 * - Light: the sheet is lit from the upper left, so its upper parts are a little brighter.
 * - Edges: the sheet's own border is drawn as a sewn edge (a darker line), a torn edge as loose
 *   light threads.
 *
 * A cell is drawn as two triangles, split along whichever diagonal keeps more of it whole
 * (ClothCells.drawn): a triangle is drawn while the two structural links on its sides are, so a cut
 * that clips a cell's corner leaves the cell's other half, cut along the diagonal. A cut at 45 degrees
 * either way is drawn as a straight edge (not the stairs of whole cells) and a curved one as a line of
 * short chords, and a piece cut out is drawn in its own shape.
 */
import { type Cloth, isAlive, type PhysicsWorld, slotOf } from '@bitphysics/physics';
import type { Camera } from '@bitphysics/render-pixi';
import { Buffer, BufferUsage, Container, Geometry, Graphics, Mesh, Shader, type Texture } from 'pixi.js';
import type { ClothCells } from './cells';

const VERTEX = `
in vec2 aPosition;
in vec2 aUV;
in vec2 aShade;
out vec2 vUV;
out vec2 vShade;
uniform mat3 uProjectionMatrix;
uniform mat3 uWorldTransformMatrix;
uniform mat3 uTransformMatrix;
void main() {
  mat3 mvp = uProjectionMatrix * uWorldTransformMatrix * uTransformMatrix;
  gl_Position = vec4((mvp * vec3(aPosition, 1.0)).xy, 0.0, 1.0);
  vUV = aUV;
  vShade = aShade;
}`;

const FRAGMENT = `
in vec2 vUV;
in vec2 vShade;
out vec4 finalColor;
uniform sampler2D uTexture;
void main() {
  vec4 c = texture(uTexture, vUV);
  // vShade.x: brightness (1 as printed); vShade.y: opacity (the weave opening as it stretches).
  vec3 rgb = clamp(c.rgb * vShade.x, 0.0, 1.0);
  float a = c.a * vShade.y;
  finalColor = vec4(rgb * a, a);
}`;

/** The sheet's drawing: add `container` to the scene and call `update` every frame. */
export class SheetView {
  /** The mesh and its edges. */
  readonly container = new Container({ label: 'sheet' });
  /** Triangles drawn at the last topology change. */
  triangles = 0;
  /** Largest strain of a point's links drawn in the last frame (for tests: the stretch is shown). */
  shownStretch = 0;
  private readonly mesh: Mesh<Geometry, Shader>;
  private readonly edges = new Graphics({ label: 'sheet edges' });
  private readonly positions: Float32Array;
  private readonly shades: Float32Array;
  private readonly posBuffer: Buffer;
  private readonly shadeBuffer: Buffer;
  private readonly indexBuffer: Buffer;
  private builtVersion = -1;
  /** Boundary edges of the drawn triangles: point indices a, b and whether it is the sheet's own border (1) or a tear (0). */
  private edgeList: number[] = [];
  /** World positions of the points this frame, m. */
  private readonly wx: Float64Array;
  private readonly wy: Float64Array;

  constructor(
    private readonly world: PhysicsWorld,
    private readonly cloth: Cloth,
    private readonly cells: ClothCells,
    texture: Texture,
    /** The link spacing at rest, m. */
    private readonly spacing: number,
  ) {
    const { columns: C, rows: R } = cloth;
    const n = C * R;
    this.positions = new Float32Array(2 * n);
    this.shades = new Float32Array(2 * n).fill(1);
    this.wx = new Float64Array(n);
    this.wy = new Float64Array(n);
    const uvs = new Float32Array(2 * n);
    for (let r = 0; r < R; r++)
      for (let c = 0; c < C; c++) {
        uvs[2 * (r * C + c)] = c / (C - 1);
        uvs[2 * (r * C + c) + 1] = r / (R - 1);
      }
    const usage = BufferUsage.VERTEX | BufferUsage.COPY_DST;
    this.posBuffer = new Buffer({ data: this.positions, usage });
    this.shadeBuffer = new Buffer({ data: this.shades, usage });
    this.indexBuffer = new Buffer({ data: new Uint32Array(6 * (C - 1) * (R - 1)), usage: BufferUsage.INDEX | BufferUsage.COPY_DST });
    const geometry = new Geometry({
      attributes: {
        aPosition: { buffer: this.posBuffer, format: 'float32x2' },
        aUV: { buffer: new Buffer({ data: uvs, usage }), format: 'float32x2' },
        aShade: { buffer: this.shadeBuffer, format: 'float32x2' },
      },
      indexBuffer: this.indexBuffer,
    });
    const shader = Shader.from({ gl: { vertex: VERTEX, fragment: FRAGMENT }, resources: { uTexture: texture.source } });
    this.mesh = new Mesh({ geometry, shader });
    this.container.addChild(this.mesh, this.edges);
  }

  /** Makes the next `update` rebuild the triangles (after the world was restored to an earlier state). */
  invalidate(): void {
    this.builtVersion = -1;
  }

  /** Moves and shades the mesh for interpolation factor `alpha` through `camera`; rebuilds the triangles after a tear. */
  update(camera: Camera, alpha: number): void {
    const P = this.world.components.Position,
      O = this.world.components.PreviousPosition;
    const pts = this.cloth.points,
      n = pts.length,
      v = this.positions,
      wx = this.wx,
      wy = this.wy;
    for (let i = 0; i < n; i++) {
      const e = slotOf(pts[i]!);
      const x = O.x[e]! + (P.x[e]! - O.x[e]!) * alpha,
        y = O.y[e]! + (P.y[e]! - O.y[e]!) * alpha;
      wx[i] = x;
      wy[i] = y;
      v[2 * i] = camera.toScreenX(x);
      v[2 * i + 1] = camera.toScreenY(y);
    }
    if (this.builtVersion !== this.world.cloth.version) this.rebuild();
    this.shade();
    this.posBuffer.update();
    this.shadeBuffer.update();
    this.drawEdges(camera);
  }

  /** Per point: brightness and opacity from the stretch and the folds around it (see the header). */
  private shade(): void {
    const { columns: C, rows: R } = this.cloth;
    const wx = this.wx,
      wy = this.wy,
      s = this.shades,
      d = this.spacing;
    const alive = this.alive;
    let most = 0;
    for (let r = 0; r < R; r++)
      for (let c = 0; c < C; c++) {
        const i = r * C + c;
        // Stretch: the longest of the point's structural links that are whole, as a strain.
        let strain = 0;
        if (c + 1 < C && alive[2 * i]) strain = Math.max(strain, Math.hypot(wx[i + 1]! - wx[i]!, wy[i + 1]! - wy[i]!) / d - 1);
        if (c > 0 && alive[2 * (i - 1)]) strain = Math.max(strain, Math.hypot(wx[i]! - wx[i - 1]!, wy[i]! - wy[i - 1]!) / d - 1);
        if (r + 1 < R && alive[2 * i + 1]) strain = Math.max(strain, Math.hypot(wx[i + C]! - wx[i]!, wy[i + C]! - wy[i]!) / d - 1);
        if (r > 0 && alive[2 * (i - C) + 1]) strain = Math.max(strain, Math.hypot(wx[i]! - wx[i - C]!, wy[i]! - wy[i - C]!) / d - 1);
        // Folds: how much closer the neighbours two links away (across the point) are than at rest.
        let fold = 0;
        if (c > 0 && c + 1 < C && alive[2 * i] && alive[2 * (i - 1)])
          fold = Math.max(fold, 1 - Math.hypot(wx[i + 1]! - wx[i - 1]!, wy[i + 1]! - wy[i - 1]!) / (2 * d));
        if (r > 0 && r + 1 < R && alive[2 * i + 1] && alive[2 * (i - C) + 1])
          fold = Math.max(fold, 1 - Math.hypot(wx[i + C]! - wx[i - C]!, wy[i + C]! - wy[i - C]!) / (2 * d));
        const st = Math.max(0, strain);
        if (st > most) most = st;
        const light = 1.06 - 0.12 * (r / (R - 1)) - 0.08 * (c / (C - 1));
        s[2 * i] = light * (1 - Math.min(0.55, 2.2 * Math.max(0, fold))) + Math.min(0.45, 1.1 * st);
        s[2 * i + 1] = 1 - Math.min(0.7, Math.max(0, st - 0.08) * 2);
      }
    this.shownStretch = most;
  }

  /** Per point: whether its right (2 i) and down (2 i + 1) structural links are whole, at the last rebuild. */
  private alive = new Uint8Array(0);

  /** Rebuilds the triangles, the boundary edges and the links' state after the cloth's links changed. */
  private rebuild(): void {
    const { columns: C, rows: R } = this.cloth;
    const cells = this.cells;
    const idx = new Uint32Array(6 * (C - 1) * (R - 1));
    const alive = new Uint8Array(2 * C * R);
    // Edge use counts: an edge of one drawn triangle only is on a boundary.
    const count = new Map<number, number>();
    const key = (a: number, b: number): number => (a < b ? a * C * R + b : b * C * R + a);
    const bump = (a: number, b: number): void => {
      const k = key(a, b);
      count.set(k, (count.get(k) ?? 0) + 1);
    };
    let m = 0;
    for (let r = 0; r + 1 < R; r++)
      for (let c = 0; c + 1 < C; c++) {
        const cell = r * (C - 1) + c,
          i = r * C + c;
        const t = cells.drawn(this.world, cell);
        if (t & 1) {
          idx[m++] = i;
          idx[m++] = i + 1;
          idx[m++] = i + C;
          bump(i, i + 1);
          bump(i, i + C);
          bump(i + 1, i + C);
        }
        if (t & 2) {
          idx[m++] = i + 1;
          idx[m++] = i + C + 1;
          idx[m++] = i + C;
          bump(i + 1, i + C + 1);
          bump(i + C, i + C + 1);
          bump(i + 1, i + C);
        }
        if (t & 4) {
          idx[m++] = i;
          idx[m++] = i + 1;
          idx[m++] = i + C + 1;
          bump(i, i + 1);
          bump(i + 1, i + C + 1);
          bump(i, i + C + 1);
        }
        if (t & 8) {
          idx[m++] = i;
          idx[m++] = i + C + 1;
          idx[m++] = i + C;
          bump(i, i + C);
          bump(i + C, i + C + 1);
          bump(i, i + C + 1);
        }
      }
    for (let r = 0; r < R; r++)
      for (let c = 0; c < C; c++) {
        const i = r * C + c;
        if (c + 1 < C) {
          const cell = Math.min(r, R - 2) * (C - 1) + c,
            side = r < R - 1 ? 0 : 2;
          alive[2 * i] = isAlive(this.world, cells.sides[4 * cell + side]!) ? 1 : 0;
        }
        if (r + 1 < R) {
          const cell = r * (C - 1) + Math.min(c, C - 2),
            side = c < C - 1 ? 1 : 3;
          alive[2 * i + 1] = isAlive(this.world, cells.sides[4 * cell + side]!) ? 1 : 0;
        }
      }
    this.alive = alive;
    const edges: number[] = [];
    const onBorder = (a: number, b: number): boolean => {
      const ra = Math.floor(a / C),
        ca = a % C,
        rb = Math.floor(b / C),
        cb = b % C;
      return (ra === rb && (ra === 0 || ra === R - 1)) || (ca === cb && (ca === 0 || ca === C - 1));
    };
    for (const [k, used] of count) {
      if (used !== 1) continue;
      const a = Math.floor(k / (C * R)),
        b = k % (C * R);
      edges.push(a, b, onBorder(a, b) ? 1 : 0);
    }
    this.edgeList = edges;
    this.indexBuffer.data = idx.subarray(0, m);
    this.triangles = m / 3;
    this.builtVersion = this.world.cloth.version;
  }

  /** Strokes the sheet's border as a sewn edge and its tears as light, loose threads. */
  private drawEdges(camera: Camera): void {
    const g = this.edges;
    g.clear();
    const v = this.positions,
      E = this.edgeList;
    const w = Math.max(1, camera.toScreenLength(0.018));
    for (let k = 0; k < E.length; k += 3) {
      if (E[k + 2] !== 1) continue;
      const a = E[k]!,
        b = E[k + 1]!;
      g.moveTo(v[2 * a]!, v[2 * a + 1]!).lineTo(v[2 * b]!, v[2 * b + 1]!);
    }
    g.stroke({ width: w * 1.6, color: 0x6b5a48, alpha: 0.85, cap: 'round' });
    // A tear: the edge of the drawn cloth, and short threads hanging off it.
    for (let k = 0; k < E.length; k += 3) {
      if (E[k + 2] !== 0) continue;
      const a = E[k]!,
        b = E[k + 1]!;
      g.moveTo(v[2 * a]!, v[2 * a + 1]!).lineTo(v[2 * b]!, v[2 * b + 1]!);
    }
    g.stroke({ width: w, color: 0xf3ead8, alpha: 0.9, cap: 'round' });
    const thread = camera.toScreenLength(0.05);
    for (let k = 0; k < E.length; k += 3) {
      if (E[k + 2] !== 0) continue;
      const a = E[k]!,
        b = E[k + 1]!;
      const mx = (v[2 * a]! + v[2 * b]!) / 2,
        my = (v[2 * a + 1]! + v[2 * b + 1]!) / 2;
      // A thread that hangs down from the middle of the torn edge, bent a little by its index.
      const lean = ((a * 7 + b * 13) % 5) - 2;
      g.moveTo(mx, my).lineTo(mx + lean * 0.4 * w, my + thread);
    }
    g.stroke({ width: Math.max(1, w * 0.6), color: 0xf3ead8, alpha: 0.7 });
  }

  /** Frees the mesh and its buffers (not the texture). */
  destroy(): void {
    this.container.destroy({ children: true });
  }
}
