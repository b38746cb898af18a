/** The snapshot format's public types: a snapshot, its JSON-able header, and the values the header encodes. */

/**
 * Snapshots: the complete state of a world as transferable data, and `restore`, which puts it back.
 *
 * Layout (format version 3): a JSON-able header (the encoded state tree, and a checksum of the header and
 * the buffer's data: snapshot/checksum.ts) and ONE ArrayBuffer holding the
 * contents of every typed array of the state, each at an 8-byte aligned offset. An array is stored up
 * to its last non-zero element only (for a per-entity store that is at most the highest live id; the
 * tail is all zeros and restore writes zeros there), a component store no live entity has is stored as
 * its type and length only, and bitecs' query lists that equal an earlier list (most queries hold the
 * same entities in the same order) as a reference to it, a list of consecutive ids (1 .. N) as its first
 * id and length (a query list neither of whose sets changed
 * since the world's last snapshot found them equal is not compared again: world/lean-ecs.ts counts each
 * set's changes). Component stores are scanned for their last non-zero element from the highest entity
 * id down (their entries above it are zero). Scratch arrays (the broadphase grid and the collision
 * stage's per-step arrays, see SCRATCH; the solver's marks, see STAMPED) are stored as their type and
 * length only, and the 2D contact buffers' columns up to their row count (CONTACT_BUFFERS), their 2D tangents
 * as a note plus the rows that differ from (-ny, nx) (TANGENT_2D); an Int32Array whose element i is i
 * (union-find parents) as its element 0 and count (`iota`, see Writer.arrayTo). Restoring a snapshot object into the world it was taken from (or into
 * one it was restored into before) leaves alone the query lists that have not changed since (their
 * versions say so), and the entity index when it is equal. `restore` writes into the world's own arrays
 * where their type and length match (systems and renderers keep them), so it allocates no big array
 * in a world that already has them.
 *
 * What is captured, generically (so state added later is captured without listing it here):
 * - every field of the world object (stage settings, time, steps, the random generator, every component
 *   store allocated, the collision, joint and cloth state with their warm-start caches and sleeping
 *   islands, spawn stamps), walked recursively: typed arrays are copied into ArrayBuffers, numbers,
 *   booleans and strings go into the JSON header, Sets and Maps as lists;
 * - the state features keep in `world.features` (3D shapes, joints and contacts, the emitters'
 *   particle books, the dissipation stamps), each by its registration in world/external-state.ts;
 * - bitecs' entity index (the order in which removed ids are reused), each entity's component set, and
 *   the order of every query's entities and pending removals (iteration order decides the order of
 *   floating-point sums, so restoring it is what makes stepping after `restore` bit-identical).
 *
 * Not captured: the systems of each stage, removal hooks and particle death hooks (code, not data: the
 * world restored into must have the same ones), and stage timings.
 */

/**
 * A snapshot: a small JSON-able header and the ArrayBuffers it points into (transferable to a Worker, or writable to disk).
 * @category Snapshots
 */
export interface WorldSnapshot {
  /** Format, world shape and the encoded state tree (see `snapshot`); JSON-able. */
  readonly header: SnapshotHeader;
  /** The data of every typed array of the state: one ArrayBuffer, the header's `o` fields are byte offsets into it. */
  readonly buffers: ArrayBuffer[];
}

/**
 * An encoded value: a JSON primitive, an array, an object of encoded values, or a tagged special value.
 * @category Snapshots
 */
export type Encoded = number | boolean | string | null | Encoded[] | { [key: string]: Encoded };

/**
 * Header of a WorldSnapshot.
 * @category Snapshots
 */
export interface SnapshotHeader {
  /** 'bitphysics-snapshot'. */
  format: string;
  /** Format version, 3. */
  version: number;
  /** The world's dimensions and capacity (a snapshot restores only into a world with the same). */
  dimensions: number;
  capacity: number;
  /** The world object's state tree. */
  state: Encoded;
  /** Registered external state by name (null: the world had none). */
  external: Record<string, Encoded>;
  /** bitecs: entity index (aliveCount, maxId, buffer of the dense id list), component bit layout, masks, queries. */
  ecs: Encoded;
  /** Bytes of the buffer that hold data (the buffer may be longer: see `snapshot`'s `reuse`). */
  bytes: number;
  /** 16 hex digits: the hash of every other field (as JSON) and of the buffer's first `bytes` bytes (snapshot/checksum.ts). */
  checksum: string;
}
