import { installCloth } from '../cloth/create.js';
import { install3D } from '../collision/install-3d.js';
import { installBalls } from '../collision/install-balls.js';
import { barnesHutGravity } from '../forces/barnes-hut/tree.js';
import { setBarnesHutGravity } from '../forces/gravity.js';
import { useEveryJointType3D } from '../joints/types-3d.js';
import { installEmitters } from '../particles/emitter-systems.js';
import { shapeEdits } from '../shapes/edits-3d.js';
import { shareStores } from '../threads/shared-stores.js';
import { describe } from '../validation/validate.js';
import { externalWorldStates } from '../world/external-state.js';
import type { PhysicsWorld } from '../world/options.js';
import { checkBodyStateFinite } from './body-state-check.js';
import { checkSnapshotValues } from './checks.js';
import { snapshotChecksum } from './checksum.js';
import { captureEcs, internals } from './ecs-capture.js';
import { checkEcs, restoreEcs, unusedStores } from './ecs-restore.js';
import type { Encoded, SnapshotHeader, WorldSnapshot } from './format.js';
import { isTagged, Reader } from './reader.js';
import { NOT_STATE, STAMPED } from './state-scope.js';
import { Writer } from './writer.js';

/**
 * The complete state of `world` as transferable data: a JSON-able header and one ArrayBuffer (post it to
 * a Worker in the transfer list, or write it to disk; layout in the module docstring). The world is not changed.
 * Restore it with `restore` into this world or another made with the same options and systems.
 *
 * @param reuse optional: an earlier snapshot that is no longer needed (a rollback ring's oldest entry).
 *   Its buffer is written over and shared by the new snapshot when it is large enough, which saves
 *   allocating (and the system zeroing) a new one; `reuse` itself must not be restored afterwards. When
 *   it is too small, the new buffer is allocated a quarter larger than the data (room for the snapshot
 *   to grow before the ring reuses it again), so the new snapshot's buffer may be longer than its data.
 * @throws TypeError if the world holds state that cannot be copied (a function or a shared object where
 *   data belongs), if `reuse` is not a snapshot, or Error if an entity carries a component outside
 *   `world.components`.
 * @example
 * const saved = snapshot(world); stepMany(world, 100); restore(world, saved); // back 100 steps
 * @category Snapshots
 */
export function snapshot(world: PhysicsWorld, reuse?: WorldSnapshot): WorldSnapshot {
  const old = reuse?.buffers?.[0];
  if (reuse !== undefined && !(old instanceof ArrayBuffer && reuse.buffers.length === 1)) {
    throw new TypeError(`snapshot: reuse must be a snapshot returned by snapshot(world), got ${describe(reuse)}`);
  }
  const ctx = internals(world);
  const registered = new Set<string>();
  for (const [name, store] of Object.entries(world.components)) if (ctx.componentMap.has(store as object)) registered.add(name);
  const w = new Writer(world.capacity + 1, ctx.entityIndex.maxId, registered);
  w.unused = unusedStores(world);
  const state = w.object(world as unknown as Record<string, unknown>, 'world', NOT_STATE);
  const external: Record<string, Encoded> = {};
  for (const ext of externalWorldStates()) {
    const s = ext.get(world, false);
    external[ext.name] = s === undefined ? null : w.object(s as Record<string, unknown>, ext.name, new Set(ext.keep ?? []));
  }
  const ecs = captureEcs(world, w);
  const buffer = w.finish(old);
  const fields = {
    format: FORMAT,
    version: VERSION,
    dimensions: world.dimensions,
    capacity: world.capacity,
    bytes: w.length,
    state,
    external,
    ecs,
  };
  return { header: { ...fields, checksum: snapshotChecksum(fields, buffer, w.length) }, buffers: [buffer] };
}

/** The header's format name. */
const FORMAT = 'bitphysics-snapshot';
/** The format version `snapshot` writes and `restore` reads: 3 (version 2 had no checksum). */
const VERSION = 3;

/** A snapshot's header without its checksum, in the order `snapshot` wrote it (see snapshotChecksum). */
function checksumFields(h: SnapshotHeader): object {
  const { format, version, dimensions, capacity, bytes, state, external, ecs } = h;
  return { format, version, dimensions, capacity, bytes, state, external, ecs };
}

/**
 * Writes `snap`'s checksum again, for its header and buffer as they are now: for tools that edit a
 * snapshot on purpose (and tests that check what restore makes of edited values). A snapshot taken
 * by `snapshot` needs none of this. Not exported by the package.
 * @category Snapshots
 */
export function sealSnapshot(snap: WorldSnapshot): void {
  const h = snap.header as { -readonly [K in keyof SnapshotHeader]: SnapshotHeader[K] };
  h.checksum = snapshotChecksum(checksumFields(h), snap.buffers[0]!, h.bytes);
}

/**
 * Puts the state of `snap` into `world`: afterwards stepping `world` gives bit-identical results to
 * stepping the world the snapshot was taken from. The world must have been made with the same
 * dimensions and capacity and have the same systems (custom systems, force laws and death hooks are
 * code and are not in a snapshot); stage settings (gravity, dt, integrator, solver settings) come from
 * the snapshot. The snapshot is not changed and can be restored again.
 *
 * Restore is all or nothing: it checks the snapshot first (format and version, the world's
 * dimensions and capacity, the checksum of the header and buffer, every encoded array's type, offset
 * and length, every scalar against the rules of snapshot/checks.ts, the entity ids against the
 * capacity, every live body's state finite: snapshot/body-state-check.ts) by a dry run of the whole restore, and writes only when all of it passed. A refused
 * snapshot leaves the world exactly as it was.
 *
 * Threads: the world keeps its own thread count and worker pool (they are not state: see NOT_STATE),
 * so a snapshot of a world with any number of threads restores into a world with any number. Stepping
 * on is bit-identical for every pair of thread counts (each body's arithmetic and every stage's order
 * do not depend on them; steps solved by colours take the same colours on one thread).
 *
 * @throws RangeError `restore: snapshot ...` if `snap` is not a snapshot, was taken from a world of
 *   other dimensions or capacity or by another version, is damaged (checksum), or holds a value out
 *   of range; the world is then left as it was.
 * @category Snapshots
 */
export function restore(world: PhysicsWorld, snap: WorldSnapshot): void {
  const where = 'restore';
  if (
    snap === null ||
    typeof snap !== 'object' ||
    snap.header === null ||
    typeof snap.header !== 'object' ||
    !Array.isArray(snap.buffers)
  ) {
    throw new RangeError(`${where}: snapshot must be a value returned by snapshot(world), got ${describe(snap)}`);
  }
  const h = snap.header;
  if (h.format !== FORMAT || h.version !== VERSION) {
    throw new RangeError(
      `${where}: snapshot must be a bitphysics snapshot of version ${VERSION}, got format ${describe(h.format)} version ${describe(h.version)}`,
    );
  }
  if (h.dimensions !== world.dimensions || h.capacity !== world.capacity) {
    throw new RangeError(
      `${where}: snapshot must come from a world with the same options: it has dimensions ${describe(h.dimensions)} and capacity ${describe(h.capacity)}, this world ${world.dimensions} and ${world.capacity}`,
    );
  }
  const buffer = snap.buffers[0];
  if (snap.buffers.length !== 1 || !(buffer instanceof ArrayBuffer)) {
    throw new RangeError(`${where}: snapshot must hold one ArrayBuffer, got ${snap.buffers.length} buffers`);
  }
  if (!(Number.isInteger(h.bytes) && h.bytes >= 0 && h.bytes <= buffer.byteLength)) {
    throw new RangeError(
      `${where}: snapshot is damaged: its header says ${describe(h.bytes)} bytes of data, its buffer holds ${buffer.byteLength}`,
    );
  }
  const sum = snapshotChecksum(checksumFields(h), buffer, h.bytes);
  if (sum !== h.checksum) {
    throw new RangeError(`${where}: snapshot is damaged: its checksum is ${describe(h.checksum)}, its contents hash to '${sum}'`);
  }
  if (!isTagged(h.state) || h.state.$t !== 'o' || !isTagged(h.state.v) || !isTagged(h.external as Encoded) || !isTagged(h.ecs)) {
    throw new RangeError(`${where}: snapshot is damaged: its header lacks the world's state`);
  }
  const state = h.state.v as Record<string, Encoded>;
  checkSnapshotValues(h.state, h.external, world);
  for (const key of Object.keys(world)) {
    if (!NOT_STATE.has(key) && !(key in state))
      throw new RangeError(`${where}: snapshot has no world.${key} (it was made by another version of bitphysics)`);
  }
  for (const ext of externalWorldStates()) {
    if (!(ext.name in h.external))
      throw new RangeError(`${where}: snapshot has no '${ext.name}' state (it was made by another version of bitphysics)`);
  }
  const oldMaxId = internals(world).entityIndex.maxId;
  const r = new Reader(buffer, world.capacity, oldMaxId);
  // The dry run: everything the restore below reads is checked, nothing is written.
  r.dry = true;
  r.objectInto(world as unknown as Record<string, unknown>, state, 'world', NOT_STATE);
  for (const ext of externalWorldStates()) {
    const enc = h.external[ext.name]!;
    if (enc === null) continue;
    if (!isTagged(enc) || enc.$t !== 'o') throw new RangeError(`${where}: snapshot's ${ext.name} is damaged`);
    const target = ext.get(world, false);
    if (target === undefined) r.fresh(enc, ext.name);
    else r.objectInto(target as Record<string, unknown>, enc.v as Record<string, Encoded>, ext.name, new Set(ext.keep ?? []));
  }
  checkEcs(world, h.ecs, r);
  checkBodyStateFinite(world, h.state, h.ecs as Record<string, Encoded>, r);
  r.dry = false;
  // Stamp counters (see STAMPED): the world's own, before the snapshot's are written.
  const counters = [...STAMPED.values()].map(({ parent, counter }) => parent(world)[counter]);
  r.objectInto(world as unknown as Record<string, unknown>, state, 'world', NOT_STATE);
  let s = 0;
  for (const { parent, counter } of STAMPED.values()) {
    const own = counters[s++],
      target = parent(world);
    if (typeof own === 'number' && typeof target[counter] === 'number' && own > (target[counter] as number)) target[counter] = own;
  }
  // Shape placements may change below: no collider keeps a pose from before (shapes/edits-3d.ts).
  shapeEdits.count++;
  for (const ext of externalWorldStates()) {
    const enc = h.external[ext.name]!;
    if (enc === null) {
      ext.clear(world);
      continue;
    }
    const target = ext.get(world, true)!;
    r.objectInto(
      target as Record<string, unknown>,
      (enc as Record<string, Encoded>).v as Record<string, Encoded>,
      ext.name,
      new Set(ext.keep ?? []),
    );
  }
  restoreEcs(world, h.ecs as Record<string, Encoded>, r, oldMaxId);
  installEveryFeature(world);
  // A store the restore gave a new array (one this world had not allocated) goes on shared memory,
  // where the pool's workers can see it.
  if (world.threadPool !== null) shareStores(world.components, world.capacity);
}

/**
 * Installs every feature's systems into a restored world (world/install.ts): the emitters', the balls', the 3D
 * shapes' and joints' (with every 3D joint type's rows), the cloth's and the Barnes-Hut sum, so the
 * world runs whatever the snapshot's world ran. A feature the snapshot's world never used has nothing to act on and writes nothing.
 */
function installEveryFeature(world: PhysicsWorld): void {
  installEmitters(world);
  installBalls(world);
  install3D(world);
  useEveryJointType3D();
  installCloth(world);
  setBarnesHutGravity(barnesHutGravity);
}
