/**
 * Undo of the scissors, headless: before each stroke the whole world is saved (`snapshot`: every
 * point's position and velocity, every link, the wind's state and the clock), with the challenge's
 * shapes cut out and scissors' marks so far and the lab's own counts. A stroke that cut something
 * keeps its save on a stack (`depth` deep), with the links it cut and the marks it left.
 *
 * `undo` undoes the last stroke that did not cut out a shape with three stars: it puts that stroke's
 * save back (`restore`), then cuts again the links of the strokes after it, so a good cut made after
 * a bad one stays (its piece comes away again) while the bad one is undone. Tears made since are
 * undone with it. A stroke is kept (passed over) once a shape it helped cut out (it cut a link with
 * an end in that shape's piece) scored three stars; when every stroke is kept, the last one goes.
 */
import { handleOf, type PhysicsWorld, query, removeJoint, restore, slotOf, snapshot, type WorldSnapshot } from '@bitphysics/physics';
import type { ClothCells } from './cells';
import type { Challenge, CutOut } from './pattern';

/** A cloth link's key: its two points' slots, a * 2^25 + b (slots are under 2^25). */
const linkKey = (a: number, b: number): number => a * 2 ** 25 + b;

/** The keys of the world's cloth links now. */
function linkKeys(world: PhysicsWorld): Set<number> {
  const L = world.components.ClothLink;
  const keys = new Set<number>();
  for (const e of query(world, [L])) keys.add(linkKey(L.a[e]!, L.b[e]!));
  return keys;
}

/** Cuts the world's cloth links whose keys are in `keys`. @returns how many were cut. */
function cutLinks(world: PhysicsWorld, keys: ReadonlySet<number>): number {
  const L = world.components.ClothLink;
  const doomed: number[] = [];
  for (const e of query(world, [L])) if (keys.has(linkKey(L.a[e]!, L.b[e]!))) doomed.push(handleOf(world, e));
  for (const h of doomed) removeJoint(world, h);
  return doomed.length;
}

/** One stroke's save (see the header); `T` is the lab's own counts. */
interface Save<T> {
  world: WorldSnapshot;
  extra: T;
  /** Challenge.done's length before the stroke. */
  done: number;
  /** Challenge.marks' length before the stroke. */
  marks: number;
  /** The cloth links there were before the stroke (linkKey); dropped once the stroke ends. */
  before: Set<number> | null;
  /** The links the stroke cut (linkKey), set as it ends. */
  severed: number[];
  /** The marks the stroke left (Challenge.marks), set as it ends. */
  left: number[];
  /** Whether the stroke cut out a shape with three stars (undo passes over it while there is another). */
  kept: boolean;
}

/** What `CutUndo.undo` did. */
export interface Undone<T> {
  /** The lab's counts saved with the undone stroke. */
  extra: T;
  /** Links cut again: the strokes after the undone one. */
  recut: number;
  /** Strokes cut again (made after the undone one and kept). */
  redone: number;
  /** The shapes those strokes cut out again. */
  cutOut: CutOut[];
}

/** Undo of the scissors on one sheet (see the header). */
export class CutUndo<T> {
  private readonly stack: Save<T>[] = [];
  private open: Save<T> | null = null;

  /**
   * @param depth strokes kept, at most (an integer >= 1; the oldest goes first).
   * @throws RangeError if `depth` is not an integer >= 1.
   */
  constructor(
    private readonly world: PhysicsWorld,
    private readonly cells: ClothCells,
    private readonly challenge: Challenge,
    readonly depth = 10,
  ) {
    if (!(Number.isInteger(depth) && depth >= 1)) throw new RangeError(`CutUndo: depth must be an integer >= 1, got ${depth}`);
  }

  /** Strokes that can be undone. */
  get count(): number {
    return this.stack.length;
  }

  /** Saves the sheet as a stroke begins, with the lab's counts `extra` (a stroke already begun is dropped). */
  begin(extra: T): void {
    this.open = {
      world: snapshot(this.world),
      extra,
      done: this.challenge.done.length,
      marks: this.challenge.marks.length,
      before: linkKeys(this.world),
      severed: [],
      left: [],
      kept: false,
    };
  }

  /**
   * Ends the stroke begun last: keeps its save if it cut a link, and marks as kept the strokes that
   * cut out (with this one) a shape that scored three stars. @returns whether it cut a link.
   */
  end(): boolean {
    const save = this.open;
    this.open = null;
    if (!save) return false;
    const now = linkKeys(this.world);
    save.severed = [...save.before!].filter((key) => !now.has(key));
    save.before = null;
    if (save.severed.length === 0) return false;
    save.left = this.challenge.marks.slice(save.marks);
    this.stack.push(save);
    for (const d of this.challenge.done.slice(save.done)) if (d.stars === 3 && d.piece >= 0) this.keepStrokesOf(d.piece);
    if (this.stack.length > this.depth) this.stack.shift();
    return true;
  }

  /** Forgets every stroke (a new sheet). */
  clear(): void {
    this.stack.length = 0;
    this.open = null;
  }

  /** Marks as kept the strokes that cut a link with an end in piece `piece` of the challenge's last update. */
  private keepStrokesOf(piece: number): void {
    const pieceOf = this.challenge.pieces?.pieceOf;
    if (!pieceOf) return;
    const points = this.challenge.cloth.points;
    const inside = new Set<number>();
    for (let i = 0; i < points.length; i++) if (pieceOf[i] === piece) inside.add(slotOf(points[i]!));
    for (const s of this.stack)
      if (!s.kept) s.kept = s.severed.some((key) => inside.has(Math.floor(key / 2 ** 25)) || inside.has(key % 2 ** 25));
  }

  /**
   * Undoes the last stroke that did not cut out a shape with three stars (the last stroke if every
   * one did; see the header): the sheet as it was just before it, its shapes and marks, then the cuts
   * of the strokes after it made again (each with a new save, its counts `recount(extra, recut)`: from
   * the undone stroke's counts and the links cut again before it). @returns what it did, or null when
   * there is no stroke to undo or a stroke is under way.
   */
  undo(recount: (extra: T, recut: number) => T = (extra) => extra): Undone<T> | null {
    if (this.open || this.stack.length === 0) return null;
    let k = this.stack.length - 1;
    while (k >= 0 && this.stack[k]!.kept) k--;
    if (k < 0) k = this.stack.length - 1;
    const later = this.stack.splice(k);
    const save = later.shift()!;
    const { world, challenge, cells } = this;
    restore(world, save.world);
    challenge.done.length = save.done;
    challenge.marks.length = save.marks;
    // The cloth's link version went back with the world: the cells and the pieces are worked out
    // again from the links as they are now.
    cells.invalidate();
    challenge.invalidate();
    cells.loosen(world);
    challenge.update();
    let recut = 0;
    const cutOut: CutOut[] = [];
    for (const j of later) {
      const again: Save<T> = {
        ...j,
        world: snapshot(world),
        extra: recount(save.extra, recut),
        done: challenge.done.length,
        marks: challenge.marks.length,
      };
      challenge.marks.push(...j.left);
      recut += cutLinks(world, new Set(j.severed));
      cells.loosen(world);
      cutOut.push(...challenge.update());
      this.stack.push(again);
    }
    return { extra: save.extra, recut, redone: later.length, cutOut };
  }
}
