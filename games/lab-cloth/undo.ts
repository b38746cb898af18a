/**
 * Undo of the scissors and the hand, headless: before each action (a scissors stroke, or a pull of
 * the hand) the whole world is saved (`snapshot`: every point's position and velocity, every link,
 * the wind's state and the clock), with the challenge's shapes cut out and scissors' marks so far and
 * the lab's own counts. An action that cut or tore a link keeps its save on a stack (`depth` deep),
 * with the links it parted and the marks it left.
 *
 * `undo` undoes the last action only: it puts that action's save back (`restore`), so the cuts made
 * before it stay as they were (a pull that tore the sheet goes without taking good cuts with it).
 */
import { type PhysicsWorld, query, restore, snapshot, type WorldSnapshot } from '@bitphysics/physics';
import type { ClothCells } from './cells';
import type { Challenge } from './pattern';

/** A cloth link's key: its two points' slots, a * 2^25 + b (slots are under 2^25). */
const linkKey = (a: number, b: number): number => a * 2 ** 25 + b;

/** The keys of the world's cloth links now. */
function linkKeys(world: PhysicsWorld): Set<number> {
  const L = world.components.ClothLink;
  const keys = new Set<number>();
  for (const e of query(world, [L])) keys.add(linkKey(L.a[e]!, L.b[e]!));
  return keys;
}

/** One action's save (see the header); `T` is the lab's own counts. */
interface Save<T> {
  world: WorldSnapshot;
  extra: T;
  /** Challenge.done's length before the action. */
  done: number;
  /** Challenge.marks' length before the action. */
  marks: number;
  /** The cloth links there were before the action (linkKey); dropped once it ends. */
  before: Set<number> | null;
  /** The links the action cut or tore (linkKey), set as it ends. */
  severed: number[];
  /** The marks the action left (Challenge.marks), set as it ends. */
  left: number[];
}

/** What `CutUndo.undo` did. */
export interface Undone<T> {
  /** The lab's counts saved with the undone action. */
  extra: T;
}

/** Undo of the scissors on one sheet (see the header). */
export class CutUndo<T> {
  private readonly stack: Save<T>[] = [];
  private open: Save<T> | null = null;

  /**
   * @param depth actions kept, at most (an integer >= 1; the oldest goes first).
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

  /** Actions that can be undone. */
  get count(): number {
    return this.stack.length;
  }

  /** Saves the sheet as an action begins, with the lab's counts `extra` (an action already begun is dropped). */
  begin(extra: T): void {
    this.open = {
      world: snapshot(this.world),
      extra,
      done: this.challenge.done.length,
      marks: this.challenge.marks.length,
      before: linkKeys(this.world),
      severed: [],
      left: [],
    };
  }

  /** Ends the action begun last: keeps its save if it cut or tore a link. @returns whether it did. */
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
    if (this.stack.length > this.depth) this.stack.shift();
    return true;
  }

  /** Forgets every action (a new sheet). */
  clear(): void {
    this.stack.length = 0;
    this.open = null;
  }

  /**
   * Undoes the last action (see the header): the sheet as it was just before it, its shapes and
   * marks. @returns what it did, or null when there is nothing to undo or an action is under way.
   */
  undo(): Undone<T> | null {
    if (this.open || this.stack.length === 0) return null;
    const save = this.stack.pop()!;
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
    return { extra: save.extra };
  }
}
