import type { PhysicsWorld } from '../world/options.js';
import { readIdLists } from './ecs-capture.js';
import { idList } from './ecs-restore.js';
import type { Encoded } from './format.js';
import { isTagged, type Reader } from './reader.js';
import { TYPED } from './typed-arrays.js';

/**
 * The body state `restore` refuses to write if it is not finite: the fields `step`'s finiteness check
 * reads (step/finite.ts), per dimension. A NaN or infinity there would be restored and then stop the
 * next step with a NonFiniteStateError; a snapshot the engine wrote never holds one, so it can come
 * only from an edited snapshot, and restore names it before it writes anything.
 */
const FIELDS_2D: readonly (readonly [string, string])[] = [
  ['Position', 'x'],
  ['Position', 'y'],
  ['Velocity', 'x'],
  ['Velocity', 'y'],
  ['AngularVelocity', 'z'],
  ['Angle', 'value'],
];
const FIELDS_3D: readonly (readonly [string, string])[] = [
  ['Position', 'x'],
  ['Position', 'y'],
  ['Position', 'z'],
  ['Velocity', 'x'],
  ['Velocity', 'y'],
  ['Velocity', 'z'],
  ['AngularVelocity', 'x'],
  ['AngularVelocity', 'y'],
  ['AngularVelocity', 'z'],
  ['Orientation', 'x'],
  ['Orientation', 'y'],
  ['Orientation', 'z'],
  ['Orientation', 'w'],
];

/** The encoded object under `key` of the encoded object `e`, or undefined. */
function child(e: Encoded | undefined, key: string): Encoded | undefined {
  if (e === undefined || !isTagged(e) || e.$t !== 'o' || !isTagged(e.v)) return undefined;
  return (e.v as Record<string, Encoded>)[key];
}

/**
 * Checks that every live entity's body state in a snapshot is finite: for each field of FIELDS_2D or
 * FIELDS_3D, the entities alive in the snapshot (its entity index) whose component mask holds the
 * field's component. Run by `restore` after its dry run (checkEcs has checked the id lists, masks and
 * layout this reads), before it writes. Slots of removed entities keep old data and are not read.
 * @param state the snapshot header's encoded world state (`world.components` inside it).
 * @param ecs the snapshot header's ECS part.
 * @throws RangeError `restore: snapshot's world.components.<Component>.<field>[<id>] must be a finite
 *   number (entity <id> is alive and has <Component>), got <value>`.
 */
export function checkBodyStateFinite(world: PhysicsWorld, state: Encoded, ecs: Record<string, Encoded>, r: Reader): void {
  const components = child(state, 'components');
  const lists = readIdLists(ecs.lists as Encoded[], r, world.capacity);
  const dense = idList(ecs.dense!, lists, 'ecs.dense').subarray(0, ecs.aliveCount as number);
  const masks = (ecs.masks as Encoded[]).map((m, g) => r.used(m as Record<string, Encoded>, `masks[${g}]`));
  const layout = new Map<string, readonly [number, number]>();
  for (const entry of ecs.layout as [string, number, number][]) layout.set(entry[0], [entry[1], entry[2]]);
  for (const [name, field] of world.dimensions === 2 ? FIELDS_2D : FIELDS_3D) {
    const enc = child(child(components, name), field);
    const at = layout.get(name);
    // Stores no entity has ('unused') or not stored (scratch) hold nothing a body reads.
    if (enc === undefined || !isTagged(enc) || !Object.hasOwn(TYPED, enc.$t as string) || at === undefined) continue;
    const path = `world.components.${name}.${field}`;
    const values = r.used(enc, path);
    const mask = masks[at[0]]!,
      bit = 1 << at[1];
    for (let i = 0; i < dense.length; i++) {
      const e = dense[i]!;
      if (e >= values.length || ((mask[e] ?? 0) & bit) === 0) continue;
      const v = values[e] as number;
      if (!Number.isFinite(v))
        throw new RangeError(`restore: snapshot's ${path}[${e}] must be a finite number (entity ${e} is alive and has ${name}), got ${v}`);
    }
  }
}
