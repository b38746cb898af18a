/**
 * The lists of the contact and sensor events of a step: one store a world (`world.collision.events`),
 * written by every contact row (ball contacts, 2D and 3D shape manifolds) and every sensor
 * (collision/events.ts), read by `contactEvents` (collision/contact-events.ts). Data only.
 */

/**
 * One list of contact events, structure of arrays; read rows 0..count-1. Entities are handles (as
 * the API takes them): 0 is the static world (the body of a plane, a segment or the boundary box), and
 * a boundary face is the shape -1 - face (faces 0 -x, 1 +x, 2 -y, 3 +y, 4 -z, 5 +z).
 * @category Events
 */
export interface ContactEventList {
  /** Events in the list (rows 0..count-1). */
  count: number;
  /** Shape A (the sensor, for sensor events). A ball body is its own shape. */
  shapeA: Float64Array;
  /** Shape B. */
  shapeB: Float64Array;
  /** Body of shape A (0: the static world). */
  bodyA: Float64Array;
  /** Body of shape B. */
  bodyB: Float64Array;
  /** Contact point, world frame, x, m (`begin` and `hit`; 0 elsewhere). */
  px: Float64Array;
  /** Contact point y, m (`px` its x). */
  py: Float64Array;
  /** Contact point z, m; 0 in 2D (`px` its x). */
  pz: Float64Array;
  /** Unit normal from shape A to shape B, x (`begin` and `hit`; 0 elsewhere). */
  nx: Float64Array;
  /** Normal y (`nx` its x). */
  ny: Float64Array;
  /** Normal z; 0 in 2D (`nx` its x). */
  nz: Float64Array;
  /** Approach speed along the normal, m/s, >= 0 (`begin` and `hit`; 0 elsewhere). */
  approachSpeed: Float64Array;
  /**
   * Normal impulse the contact carried in the step (or substep) it began, N s, >= 0, summed over its
   * points (`begin` and `hit`; 0 elsewhere). For a body of mass m stopped by the contact from speed v
   * it is about m v (plus the weight's m g dt of the step).
   */
  impulse: Float64Array;
}

/**
 * The events of the step being run or last run, `world.collision.events`, as `contactEvents` returns
 * them. Cleared at the start of every step; the events of a step's substeps accumulate.
 * @category Events
 */
export interface ContactEventLists {
  /** Pairs of shapes that started touching (a point carried a normal impulse or overlapped). */
  readonly begin: ContactEventList;
  /** Pairs that stopped touching, or one of whose shapes or bodies was removed. */
  readonly end: ContactEventList;
  /** The begin events whose approach speed was at least the hit speed of the last `contactEvents` call. */
  readonly hit: ContactEventList;
  /** Shapes that started overlapping a sensor (`shapeA` the sensor). */
  readonly sensorBegin: ContactEventList;
  /** Shapes that stopped overlapping a sensor (`shapeA` the sensor). */
  readonly sensorEnd: ContactEventList;
}

/** The columns of a ContactEventList. */
export const EVENT_FIELDS = ['shapeA', 'shapeB', 'bodyA', 'bodyB', 'px', 'py', 'pz', 'nx', 'ny', 'nz', 'approachSpeed', 'impulse'] as const;

/**
 * An empty list with room for `n` events (grown by doubling as events are pushed).
 * @category Events
 */
export function createContactEventList(n = 16): ContactEventList {
  const f = (): Float64Array => new Float64Array(n);
  return {
    count: 0,
    shapeA: f(),
    shapeB: f(),
    bodyA: f(),
    bodyB: f(),
    px: f(),
    py: f(),
    pz: f(),
    nx: f(),
    ny: f(),
    nz: f(),
    approachSpeed: f(),
    impulse: f(),
  };
}

/**
 * An empty event store (createCollisionState makes the world's).
 * @category Events
 */
export function createContactEventStore(): ContactEventLists {
  return {
    begin: createContactEventList(),
    end: createContactEventList(),
    hit: createContactEventList(),
    sensorBegin: createContactEventList(),
    sensorEnd: createContactEventList(),
  };
}

/**
 * Empties every list of `store` (the start of a step).
 * @category Events
 */
export function clearContactEvents(store: ContactEventLists): void {
  store.begin.count = 0;
  store.end.count = 0;
  store.hit.count = 0;
  store.sensorBegin.count = 0;
  store.sensorEnd.count = 0;
}

/**
 * Makes room for one more row in `list` (doubling its columns, keeping rows 0..count-1).
 * @category Events
 */
export function reserveEvent(list: ContactEventList): void {
  if (list.count >= list.shapeA.length) growEvents(list);
}

/** Rows a list grows to at least when it first overflows. */
const FIRST_GROWTH_ROWS = 1024;

/**
 * Doubles every column of `list` (to at least FIRST_GROWTH_ROWS rows), keeping its rows. Out of line from reserveEvent: V8 inlines
 * reserveEvent wherever an event is written (the touch loops of a world's first step), and this loop
 * of allocations and keyed copies inlined with it made those loops costlier to compile.
 */
function growEvents(list: ContactEventList): void {
  const rec = list as unknown as Record<string, Float64Array>;
  // A step that overflows the first 16 rows is usually a pile landing, whose events run to thousands
  // over the next steps: jump to 1024 rows (98 KB a list) rather than doubling through 32..512.
  const rows = Math.max(2 * list.shapeA.length, FIRST_GROWTH_ROWS);
  for (const k of EVENT_FIELDS) {
    const next = new Float64Array(rows);
    next.set(rec[k]!);
    rec[k] = next;
  }
}

/**
 * Contacts kept touching while their bodies sleep (Box2D v3's rule: a contact does not end when its
 * island falls asleep, nor begin again when it wakes): a touching pair whose rows vanish because every
 * moving body of it fell asleep is kept here instead of ending, and a pair found touching again after
 * the wake resumes without a begin event. `world.collision.sleepingContacts`.
 * @category Events
 */
export interface SleepingContacts {
  /** Pair key (`sleepingPairKey`) -> the pair's shape A, shape B, body A and body B as handles (0: the static world). */
  readonly pairs: Map<number, number[]>;
  /** `sleep.wakes` when the pairs were last checked for bodies that woke (collision/events.ts endWokenContacts). */
  checkedWakes: number;
}

/**
 * An empty set of resting contacts (createCollisionState makes the world's).
 * @category Events
 */
export function createSleepingContacts(): SleepingContacts {
  return { pairs: new Map(), checkedWakes: 0 };
}

/**
 * Key of a pair of shape slots: shape A may be a boundary face's id (-6 to -1), shape B is an entity.
 * @category Events
 */
export function sleepingPairKey(shapeA: number, shapeB: number): number {
  return (shapeA + 8) * 67_108_864 + shapeB;
}
