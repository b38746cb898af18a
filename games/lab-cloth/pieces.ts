/**
 * The pieces of a torn cloth, headless: its points grouped by the links still joining them (any kind
 * of link), and which pieces hang free (no point of theirs is fixed: pegged, pinned or held still).
 */
import { type Cloth, type PhysicsWorld, query, slotOf } from '@bitphysics/physics';

/** The pieces of a cloth at one moment. */
export interface ClothPieces {
  /** Per point of the cloth (in `Cloth.points` order), the index of its piece. */
  readonly pieceOf: Int32Array;
  /** Per piece, its number of points. */
  readonly size: number[];
  /** Per piece, whether it holds a fixed point (inverse mass 0): false for a piece that has come away. */
  readonly held: boolean[];
}

/** Groups the cloth's points into pieces by the links (ClothLink entities) alive in `world` now. */
export function findPieces(world: PhysicsWorld, cloth: Cloth): ClothPieces {
  const n = cloth.points.length;
  const index = new Map<number, number>();
  for (let i = 0; i < n; i++) index.set(slotOf(cloth.points[i]!), i);
  const parent = new Int32Array(n);
  for (let i = 0; i < n; i++) parent[i] = i;
  const root = (i: number): number => {
    while (parent[i] !== i) {
      parent[i] = parent[parent[i]!]!;
      i = parent[i]!;
    }
    return i;
  };
  const L = world.components.ClothLink;
  for (const e of query(world, [L])) {
    const a = index.get(L.a[e]!),
      b = index.get(L.b[e]!);
    if (a === undefined || b === undefined) continue;
    const ra = root(a),
      rb = root(b);
    if (ra !== rb) parent[ra] = rb;
  }
  const pieceOf = new Int32Array(n);
  const label = new Map<number, number>();
  const size: number[] = [],
    held: boolean[] = [];
  const inv = world.components.Mass.inv;
  for (let i = 0; i < n; i++) {
    const r = root(i);
    let k = label.get(r);
    if (k === undefined) {
      k = size.length;
      label.set(r, k);
      size.push(0);
      held.push(false);
    }
    pieceOf[i] = k;
    size[k]!++;
    if (!(inv[slotOf(cloth.points[i]!)]! > 0)) held[k] = true;
  }
  return { pieceOf, size, held };
}
