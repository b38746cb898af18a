/**
 * The cells of a cloth's grid and the links on their sides, headless: what the drawing, the pattern's
 * scoring and the tearing share. Cell (r, c), for r < rows - 1 and c < columns - 1, has corners
 * (r, c), (r, c + 1), (r + 1, c) and (r + 1, c + 1); its upper-left triangle is whole while its top and
 * left links are, its lower-right one while its bottom and right links are.
 *
 * A tear goes through the cloth, not round it: `loosen` takes out a cell's shear links (its diagonals)
 * once a link on its side is gone, and a bending link once a link it spans is gone, so that soft
 * diagonals and bending links, which stretch far before they would tear, never hold a tear shut.
 */
import { type Cloth, isAlive, type PhysicsWorld, removeJoint } from '@bitphysics/physics';

/** The cells of one cloth: per cell, the handles of its top, left, bottom and right structural links. */
export class ClothCells {
  /** Cells across and down (one fewer than the points). */
  readonly across: number;
  readonly down: number;
  /** Per cell (row-major), its top, left, bottom and right link handles (4 numbers a cell). */
  readonly sides: Float64Array;
  /** Per cell, its two shear links' handles (0 without shear links). */
  readonly diagonals: Float64Array;
  /** Bending links and the two structural links each spans (handles: bend, first, second; 3 numbers a link). */
  readonly spans: Float64Array;
  /** The cloth's link version `loosen` last saw. */
  private loosened = -1;

  /** @throws RangeError if the cloth's links are not in createCloth's order (structural first, each point's right then down link). */
  constructor(readonly cloth: Cloth) {
    const { columns: C, rows: R } = cloth;
    if (cloth.links.length < 2 * C * R - C - R)
      throw new RangeError(`ClothCells: the cloth has ${cloth.links.length} links, fewer than its ${2 * C * R - C - R} structural ones`);
    this.across = C - 1;
    this.down = R - 1;
    // createCloth makes the structural links first: for each point, its right link, then its down link.
    const right = new Float64Array(C * R),
      below = new Float64Array(C * R);
    let k = 0;
    for (let r = 0; r < R; r++)
      for (let c = 0; c < C; c++) {
        const i = r * C + c;
        if (c + 1 < C) right[i] = cloth.links[k++]!;
        if (r + 1 < R) below[i] = cloth.links[k++]!;
      }
    this.sides = new Float64Array(4 * (C - 1) * (R - 1));
    for (let r = 0; r + 1 < R; r++)
      for (let c = 0; c + 1 < C; c++) {
        const i = r * C + c,
          q = 4 * (r * (C - 1) + c);
        this.sides[q] = right[i]!;
        this.sides[q + 1] = below[i]!;
        this.sides[q + 2] = right[i + C]!;
        this.sides[q + 3] = below[i + 1]!;
      }
    // Then createCloth's shear links (if any): both diagonals of each cell, in cell order; then its
    // bending links: for each point, the one two to the right, then the one two down.
    const cellCount = (C - 1) * (R - 1);
    const bendCount = (C - 2) * R + (R - 2) * C;
    const structural = 2 * C * R - C - R;
    const shear = cloth.links.length - structural - bendCount === 2 * cellCount;
    this.diagonals = new Float64Array(2 * cellCount);
    if (shear) for (let q = 0; q < 2 * cellCount; q++) this.diagonals[q] = cloth.links[structural + q]!;
    const bends = cloth.links.length - structural - (shear ? 2 * cellCount : 0) === bendCount;
    const spans: number[] = [];
    if (bends) {
      let b = structural + (shear ? 2 * cellCount : 0);
      for (let r = 0; r < R; r++)
        for (let c = 0; c < C; c++) {
          const i = r * C + c;
          if (c + 2 < C) spans.push(cloth.links[b++]!, right[i]!, right[i + 1]!);
          if (r + 2 < R) spans.push(cloth.links[b++]!, below[i]!, below[i + C]!);
        }
    }
    this.spans = Float64Array.from(spans);
  }

  /**
   * Takes out the shear links of every cell with a side gone and the bending links over a gone link
   * (see the header), if the cloth's links changed since the last call. @returns links taken out.
   */
  loosen(world: PhysicsWorld): number {
    if (world.cloth.version === this.loosened) return 0;
    let n = 0;
    const s = this.sides,
      d = this.diagonals;
    for (let cell = 0; cell < this.across * this.down; cell++) {
      const q = 4 * cell;
      if (isAlive(world, s[q]!) && isAlive(world, s[q + 1]!) && isAlive(world, s[q + 2]!) && isAlive(world, s[q + 3]!)) continue;
      for (const h of [d[2 * cell]!, d[2 * cell + 1]!])
        if (h && isAlive(world, h)) {
          removeJoint(world, h);
          n++;
        }
    }
    const b = this.spans;
    for (let k = 0; k < b.length; k += 3)
      if (isAlive(world, b[k]!) && !(isAlive(world, b[k + 1]!) && isAlive(world, b[k + 2]!))) {
        removeJoint(world, b[k]!);
        n++;
      }
    this.loosened = world.cloth.version;
    return n;
  }

  /** Makes the next `loosen` look at the links again (after the world was restored to an earlier state). */
  invalidate(): void {
    this.loosened = -1;
  }

  /**
   * Which triangles of cell `cell` (row-major index) are whole in `world`: bit 1 the upper-left one
   * (top and left links alive), bit 2 the lower-right one (bottom and right links alive).
   */
  triangles(world: PhysicsWorld, cell: number): number {
    const s = this.sides,
      q = 4 * cell;
    return (isAlive(world, s[q]!) && isAlive(world, s[q + 1]!) ? 1 : 0) | (isAlive(world, s[q + 2]!) && isAlive(world, s[q + 3]!) ? 2 : 0);
  }

  /**
   * The triangles to draw of cell `cell` (row-major index) in `world`, split along whichever diagonal
   * keeps more of them whole (the cell's own split, `triangles`, on a tie): bit 1 the upper-left
   * triangle (top and left links alive) and bit 2 the lower-right one (bottom and right), or bit 4 the
   * upper-right one (top and right) and bit 8 the lower-left one (left and bottom). A cut that clips
   * the cell's upper-right or lower-left corner thus leaves the cell's other half drawn.
   */
  drawn(world: PhysicsWorld, cell: number): number {
    const s = this.sides,
      q = 4 * cell;
    const top = isAlive(world, s[q]!),
      left = isAlive(world, s[q + 1]!),
      bottom = isAlive(world, s[q + 2]!),
      right = isAlive(world, s[q + 3]!);
    const own = (top && left ? 1 : 0) + (bottom && right ? 1 : 0),
      other = (top && right ? 1 : 0) + (left && bottom ? 1 : 0);
    if (other > own) return (top && right ? 4 : 0) | (left && bottom ? 8 : 0);
    return (top && left ? 1 : 0) | (bottom && right ? 2 : 0);
  }
}
