/**
 * Instance bookkeeping: which instance of which group each entity occupies. No three.js, no DOM,
 * so it is tested in Node.
 *
 * A group is one instanced draw (one geometry and one material); its instances are a dense list
 * `eids(group)[0..count(group)-1]`, and instance i of the group's mesh shows entity eids[i]. An
 * entity is in at most one group. Removing an entity swap-removes it: the group's last instance
 * moves into the hole, so the instances in use stay 0..count-1 and the mesh draws exactly `count`.
 *
 * Per-entity state lives in typed arrays of capacity + 1 indexed by entity id (bitecs ids start at
 * 1); dense lists double when full. Nothing is allocated per entity per frame.
 */

/** Told about every change of the book, so the owner can move per-instance data along. */
export interface InstanceBookListener {
  /** Entity `eid` now occupies instance `index` of `group` (the last one). */
  added(group: number, index: number, eid: number): void;
  /** Entity `eid`, which occupied instance `from` of `group`, now occupies instance `to` (a swap-remove filled a hole). */
  moved(group: number, from: number, to: number, eid: number): void;
  /** Entity `eid` no longer occupies an instance of `group`. */
  removed(group: number, eid: number): void;
}

/** The most groups a book holds (group ids are stored in a Uint16Array with 0 meaning none). */
export const MAX_GROUPS = 65_535;

/** Entity -> (group, instance) map with swap-remove; see the module comment. */
export class InstanceBook {
  /** Largest entity id the book can hold (the world's capacity). */
  readonly capacity: number;
  /** Receives every change, or null. */
  listener: InstanceBookListener | null = null;
  /** Per entity: its group + 1, 0 when not shown. Read-only for users of the book. */
  readonly groupPlusOne: Uint16Array;
  /** Per entity: its instance index in its group (meaningful while shown). */
  readonly indexOf: Int32Array;
  /** Per entity: the spawn stamp it had when it was added (detects recycled ids). */
  readonly stampOf: Uint32Array;
  private readonly seen: Uint32Array;
  private pass = 0;
  private lists: Int32Array[] = [];
  private counts: number[] = [];
  private shown = 0;

  /** @param capacity largest entity id, integer >= 1. @throws RangeError otherwise. */
  constructor(capacity: number) {
    if (!Number.isInteger(capacity) || capacity < 1)
      throw new RangeError(`InstanceBook: capacity must be an integer >= 1, got ${capacity}`);
    this.capacity = capacity;
    this.groupPlusOne = new Uint16Array(capacity + 1);
    this.indexOf = new Int32Array(capacity + 1);
    this.stampOf = new Uint32Array(capacity + 1);
    this.seen = new Uint32Array(capacity + 1);
  }

  /**
   * Adds an empty group with room for `initial` instances (the list doubles as needed).
   * @returns its id (0, 1, 2, ... in order of creation). @throws RangeError past MAX_GROUPS groups.
   */
  addGroup(initial = 16): number {
    if (this.lists.length >= MAX_GROUPS) throw new RangeError(`InstanceBook.addGroup: at most ${MAX_GROUPS} groups`);
    this.lists.push(new Int32Array(Math.max(1, Math.min(initial, this.capacity))));
    this.counts.push(0);
    return this.lists.length - 1;
  }

  /** Number of groups. */
  get groups(): number {
    return this.lists.length;
  }

  /** Entities shown, over every group. */
  get total(): number {
    return this.shown;
  }

  /** Instances in use in `group`. */
  count(group: number): number {
    return this.counts[group]!;
  }

  /** The dense entity list of `group` (entries 0..count(group)-1 are valid; the array may be longer). */
  eids(group: number): Int32Array {
    return this.lists[group]!;
  }

  /** Whether `eid` is shown (in any group). */
  has(eid: number): boolean {
    return eid > 0 && eid <= this.capacity && this.groupPlusOne[eid] !== 0;
  }

  /** The group of `eid`, or -1 if it is not shown. */
  groupOf(eid: number): number {
    return this.has(eid) ? this.groupPlusOne[eid]! - 1 : -1;
  }

  /**
   * Gives `eid` the next instance of `group` and records its spawn `stamp`. An entity already shown
   * is removed from its group first.
   * @returns the instance index. @throws RangeError on an id outside [1, capacity] or an unknown group.
   */
  add(eid: number, group: number, stamp: number): number {
    if (!(eid >= 1 && eid <= this.capacity)) throw new RangeError(`InstanceBook.add: eid must be in [1, ${this.capacity}], got ${eid}`);
    if (!(group >= 0 && group < this.lists.length)) throw new RangeError(`InstanceBook.add: unknown group ${group}`);
    if (this.groupPlusOne[eid] !== 0) this.remove(eid);
    let list = this.lists[group]!;
    const i = this.counts[group]!;
    if (i === list.length) {
      const grown = new Int32Array(Math.min(this.capacity, list.length * 2));
      grown.set(list);
      this.lists[group] = list = grown;
    }
    list[i] = eid;
    this.counts[group] = i + 1;
    this.groupPlusOne[eid] = group + 1;
    this.indexOf[eid] = i;
    this.stampOf[eid] = stamp;
    this.seen[eid] = this.pass;
    this.shown++;
    this.listener?.added(group, i, eid);
    return i;
  }

  /** Removes `eid` from its group (swap-remove); a no-op if it is not shown. */
  remove(eid: number): void {
    if (!this.has(eid)) return;
    const group = this.groupPlusOne[eid]! - 1;
    const list = this.lists[group]!;
    const i = this.indexOf[eid]!;
    const last = this.counts[group]! - 1;
    this.groupPlusOne[eid] = 0;
    this.counts[group] = last;
    this.shown--;
    if (i !== last) {
      const moved = list[last]!;
      list[i] = moved;
      this.indexOf[moved] = i;
      this.listener?.moved(group, last, i, moved);
    }
    this.listener?.removed(group, eid);
  }

  /** Removes every entity from every group (listeners hear each removal). */
  clear(): void {
    for (let g = 0; g < this.lists.length; g++) {
      const list = this.lists[g]!;
      for (let i = this.counts[g]! - 1; i >= 0; i--) this.remove(list[i]!);
    }
  }

  /** Starts a sync pass: entities not `mark`ed before `sweep` are removed by it. */
  beginPass(): void {
    this.pass = (this.pass + 1) >>> 0;
    if (this.pass === 0) {
      this.seen.fill(0);
      this.pass = 1;
    }
  }

  /** Marks `eid` as still present in this pass. */
  mark(eid: number): void {
    this.seen[eid] = this.pass;
  }

  /** Removes every shown entity not marked since `beginPass`. @returns how many were removed. */
  sweep(): number {
    let removed = 0;
    const seen = this.seen,
      pass = this.pass;
    for (let g = 0; g < this.lists.length; g++) {
      const list = this.lists[g]!;
      for (let i = this.counts[g]! - 1; i >= 0; i--) {
        const e = list[i]!;
        if (seen[e] !== pass) {
          this.remove(e);
          removed++;
        }
      }
    }
    return removed;
  }
}
