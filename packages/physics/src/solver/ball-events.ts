/**
 * The contact events of the ball rows (ball-ball, ball-boundary, ball-segment, ball-static-ball,
 * ball-plane), written to the world's one event store (collision/events.ts) next to the shapes' own,
 * at the end of the contact solver: a row touches if it carried a normal impulse in the step or
 * overlapped at its start (as a shape manifold does); a touching row whose contact did not touch in the
 * previous step is a begin event, a previous step's touching row that no row continues is an end event.
 * The previous row of each contact is the one its warm start found (`ContactBuffer.previous`, set when
 * the rows are prepared), so no pair is looked up again. A pair whose rows vanish because its bodies
 * fell asleep is kept touching while they sleep (collision/events.ts keepWhileAsleep), as the shapes' are.
 */

import { type ContactBuffer, ContactKind } from '../collision/contacts.js';
import { keepWhileAsleep, pushEvent, resumeAfterSleep } from '../collision/events.js';
import type { PhysicsWorld } from '../world/options.js';

/**
 * Per row of the previous step: `mark` once a touching row of this step continues it (a stamp, so the
 * array is never cleared). Scratch, not world state.
 */
let continued = new Uint32Array(256);
let mark = 0;

/**
 * Marks this step's ball rows touching or not and writes their begin and end events. `prepared` is
 * false when the solver skipped the rows' preparation (a step without rows): then no row of `buf` is
 * read and every previous touching row ends.
 * @category Collision
 */
export function ballContactEvents(world: PhysicsWorld, buf: ContactBuffer, prepared: boolean): void {
  const cs = world.collision,
    prev = cs.cache.rows;
  const m = prev.count,
    n = prepared ? buf.count : 0;
  if (continued.length < m) continued = new Uint32Array(Math.max(m, 2 * continued.length));
  if (++mark === 0xffffffff) {
    continued.fill(0);
    mark = 1;
  }
  const done = continued,
    stamp = mark;
  const IMP = buf.impulse,
    S0 = buf.separation,
    PREV = buf.previous,
    T = buf.touching,
    pT = prev.touching;
  // A row that touches and continues a touching row of the last step (the common case) only marks it.
  let touchingNow = 0,
    continuing = 0;
  for (let i = 0; i < n; i++) {
    const touching = IMP[i]! > 0 || S0[i]! < 0 ? 1 : 0;
    T[i] = touching;
    if (touching === 0) continue;
    touchingNow++;
    const j = PREV[i]!;
    if (j >= 0) {
      done[j] = stamp;
      if (pT[j] === 1) {
        continuing++;
        continue;
      }
    }
    if (!resumeAfterSleep(world, shapeOf(buf, i, 0), shapeOf(buf, i, 1))) beginEvent(world, buf, i);
  }
  buf.touchingCount = touchingNow;
  // Ends: last step's touching rows that no row continued (none when all of them were continued).
  if (continuing === prev.touchingCount) return;
  for (let j = 0; j < m; j++) {
    if (pT[j] !== 1 || done[j] === stamp) continue;
    if (keepWhileAsleep(world, shapeOf(prev, j, 0), shapeOf(prev, j, 1), bodyOf(prev, j, 0), bodyOf(prev, j, 1))) continue;
    pushRow(world, cs.events.end, prev, j);
  }
}

/** Writes the begin event of row `i` of `buf`: its shapes and bodies, the point on B, the normal, the approach speed at impact and the step's impulse. */
function beginEvent(world: PhysicsWorld, buf: ContactBuffer, i: number): void {
  const list = world.collision.events.begin;
  const k = pushRow(world, list, buf, i);
  const P = world.components.PreviousPosition;
  const b = buf.b[i]!,
    rb = buf.rb[i]!;
  const is3D = world.dimensions === 3;
  const nx = buf.nx[i]!,
    ny = buf.ny[i]!,
    nz = is3D ? buf.nz[i]! : 0;
  list.px[k] = P.x[b]! - rb * nx;
  list.py[k] = P.y[b]! - rb * ny;
  list.pz[k] = is3D ? P.z[b]! - rb * nz : 0;
  list.nx[k] = nx;
  list.ny[k] = ny;
  list.nz[k] = nz;
  list.approachSpeed[k] = Math.max(0, -buf.impactVelocity[i]!);
  list.impulse[k] = buf.impulse[i]!;
}

/**
 * Shape A (`side` 0) or B (1) of row `i` as the events name it (ContactKind): a ball is its own shape,
 * a boundary face is -1 - face, a segment, plane or static ball is its entity.
 */
function shapeOf(rows: ContactBuffer, i: number, side: number): number {
  if (side === 1) return rows.b[i]!;
  const kind = rows.kind[i]!;
  if (kind === ContactKind.Ball) return rows.a[i]!;
  return kind === ContactKind.Boundary ? -1 - rows.feature[i]! : rows.feature[i]!;
}

/** Body A (`side` 0) or B (1) of row `i` as the events name it: a static ball is a body, a segment, plane or boundary face belongs to the static world (0). */
function bodyOf(rows: ContactBuffer, i: number, side: number): number {
  if (side === 1) return rows.b[i]!;
  const kind = rows.kind[i]!;
  if (kind === ContactKind.Ball) return rows.a[i]!;
  return kind === ContactKind.StaticBall ? rows.feature[i]! : 0;
}

/** Pushes an event naming the shapes and bodies of row `i` of `rows` (shapeOf, bodyOf); returns its row. */
function pushRow(world: PhysicsWorld, list: Parameters<typeof pushEvent>[1], rows: ContactBuffer, i: number): number {
  return pushEvent(world, list, shapeOf(rows, i, 0), rows.b[i]!, bodyOf(rows, i, 0), rows.b[i]!);
}
