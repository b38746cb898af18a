/**
 * A game's saved values (a best score, stars per level, the best of each course, a setting) kept in
 * the browser's localStorage across reloads, typed and checked: every value is stored as JSON under
 * a namespaced key ('my-game.best'), and what is read back is checked against the value's shape and
 * range, so a garbled, hand-edited or out-of-range entry reads as the fallback instead of reaching
 * the game. Storage may be missing (Node, a locked-down browser) or throw (private modes, a full
 * quota, blocked cookies): then reading gives the fallback, writing keeps nothing, and nothing
 * throws. Only a programming error throws: a key that is not namespaced, a check with a bad range,
 * or a write of a value that would not read back as itself.
 *
 * ```ts
 * const best = storedValue('my-game.best', numberCheck({ max: 1e9, integer: true }), 0);
 * let points = best.read(); // 0 the first time, and wherever storage is unavailable
 * if (score > points) best.write((points = score));
 * ```
 *
 * A plain number is stored as its decimal text ('12'), which is also its JSON, so a value kept by
 * `localStorage.setItem(key, String(n))` reads back unchanged.
 */

/** The storage the saved values need: localStorage's getItem and setItem (a Map-backed stand-in in tests). */
export interface KeyValueStorage {
  /** The text kept under `key`, or null when there is none. May throw (blocked storage). */
  getItem(key: string): string | null;
  /** Keeps `value` under `key`. May throw (a full quota, private mode). */
  setItem(key: string, value: string): void;
}

/** Where a saved value is kept. */
export interface StorageOptions {
  /**
   * The storage to use: null for none (nothing kept, every read gives the fallback). Default: the
   * page's localStorage, looked up at each read and write (`pageStorage()`), so none in Node.
   */
  storage?: KeyValueStorage | null;
}

/**
 * A check of a value parsed from storage: the value as a `T` when it is one (possibly normalised, as
 * a list's bad entries replaced by its fill), else undefined (the value is refused).
 */
export type StoredCheck<T> = (value: unknown) => T | undefined;

/** The shape of a namespaced key: two or more dot-separated parts of letters, digits, '_' and '-'. */
const KEY_SHAPE = /^[A-Za-z0-9_-]+(\.[A-Za-z0-9_-]+)+$/;

/** The page's localStorage, or null where there is none (Node) or reading it throws (some private modes). */
export function pageStorage(): KeyValueStorage | null {
  try {
    return typeof localStorage === 'undefined' ? null : localStorage;
  } catch {
    return null;
  }
}

/**
 * A check of a number in [`min`, `max`] (a whole number too when `integer`): it refuses anything
 * else, NaN, ±Infinity and numbers out of the range included.
 * @param options.min the least value kept (default 0: negative scores and times are refused).
 * @param options.max the greatest value kept, required: a bound on what the game can reach, so an
 *   absurd stored value (1e300) reads as the fallback.
 * @param options.integer whether only whole numbers are kept (default false).
 * @throws RangeError naming `numberCheck` if `min` or `max` is not finite or `min` > `max`.
 */
export function numberCheck(options: { min?: number; max: number; integer?: boolean }): StoredCheck<number> {
  const min = options.min ?? 0;
  const { max } = options;
  const integer = options.integer === true;
  if (!(Number.isFinite(min) && Number.isFinite(max) && min <= max)) {
    throw new RangeError(`numberCheck: min and max must be finite with min <= max, got min ${min}, max ${max}`);
  }
  return (value) =>
    typeof value === 'number' && value >= min && value <= max && (!integer || Number.isInteger(value)) ? value : undefined;
}

/**
 * A check of a list of `length` entries (one per level, say): a stored array whose entries pass
 * `item` as they are, each other entry (and each one missing from a shorter array) as `fill`, entries
 * past `length` dropped. A value that is not an array is refused.
 * @param item the check of each entry.
 * @param length the number of entries, an integer in [0, 100 000].
 * @param fill the entry put where the stored one is missing or refused (0: a level not yet won).
 * @throws RangeError naming `listCheck` if `length` is out of range or `fill` does not pass `item`.
 */
export function listCheck<T>(item: StoredCheck<T>, length: number, fill: T): StoredCheck<T[]> {
  if (!(Number.isInteger(length) && length >= 0 && length <= 100_000)) {
    throw new RangeError(`listCheck: length must be an integer in [0, 100000], got ${length}`);
  }
  if (item(fill) === undefined) throw new RangeError(`listCheck: fill must pass the item check, got ${JSON.stringify(fill)}`);
  return (value) => {
    if (!Array.isArray(value)) return undefined;
    return Array.from({ length }, (_, i) => (i < value.length ? item(value[i]) : undefined) ?? fill);
  };
}

/**
 * A check of an object with the given fields ({ passed, time }): each field passes its own check, or
 * the whole value is refused. Other fields are dropped.
 * @param fields each field's name and check.
 */
export function shapeCheck<T extends object>(fields: { [K in keyof T]: StoredCheck<T[K]> }): StoredCheck<T> {
  const names = Object.keys(fields) as (keyof T & string)[];
  return (value) => {
    if (typeof value !== 'object' || value === null || Array.isArray(value)) return undefined;
    const out = {} as T;
    for (const name of names) {
      const v = fields[name](Object.hasOwn(value, name) ? (value as Record<string, unknown>)[name] : undefined);
      if (v === undefined) return undefined;
      out[name] = v;
    }
    return out;
  };
}

/** One saved value of type T under its key. */
export interface StoredValue<T> {
  /** The storage key (namespaced, 'my-game.best'). */
  readonly key: string;
  /**
   * The value kept under the key as its check reads it, or a fresh copy of the fallback where there
   * is none, it is not JSON or the check refuses it, or the storage is missing or throws. Never throws.
   */
  read(): T;
  /**
   * Keeps `value` (as JSON) under the key. @returns whether it was kept (false: no storage, or it threw).
   * @throws RangeError naming the key if `value` would not read back as itself (the check refuses or changes it).
   */
  write(value: T): boolean;
}

/**
 * A saved value under `key`, checked on read by `check`, `fallback` where none is kept or it is bad.
 * @param key the storage key, namespaced by the game ('my-game.best', 'my-game.level-3.stars'): two
 *   or more dot-separated parts of letters, digits, '_' and '-'.
 * @param check the check of what is read back (numberCheck, listCheck, shapeCheck or your own).
 * @param fallback the value read where none is kept or it is refused; it must pass `check`.
 * @param options where it is kept (default the page's localStorage).
 * @throws TypeError naming `storedValue` if `key` is not namespaced; RangeError if `fallback` does
 *   not pass `check` unchanged.
 */
export function storedValue<T>(key: string, check: StoredCheck<T>, fallback: T, options: StorageOptions = {}): StoredValue<T> {
  assertKey('storedValue', key);
  if (!readsBackAs(check, fallback)) {
    throw new RangeError(`storedValue(${key}): fallback must pass the check unchanged, got ${JSON.stringify(fallback)}`);
  }
  const copy = (): T => JSON.parse(JSON.stringify(fallback)) as T;
  return {
    key,
    read: () => {
      const v = parseStored(getText(options, key), check);
      return v === undefined ? copy() : v;
    },
    write: (value) => {
      if (!readsBackAs(check, value)) {
        throw new RangeError(`storedValue(${key}).write: the value does not pass the check, got ${JSON.stringify(value)}`);
      }
      return setText(options, key, JSON.stringify(value));
    },
  };
}

/** Saved values of type T by name under one key (the best of each course: '42/7' -> 83.5 s), stored as one JSON object. */
export interface StoredRecord<T> {
  /** The storage key (namespaced, 'my-game.best-times'). */
  readonly key: string;
  /**
   * Every entry kept that passes the entry check (others left out), in an object with no prototype;
   * empty where none is kept, it is not a JSON object, or the storage is missing or throws. Never throws.
   */
  read(): Record<string, T>;
  /** The entry kept under `name`, or undefined where none is (or it is refused, or storage fails). Never throws. */
  get(name: string): T | undefined;
  /**
   * Keeps `value` as the entry `name`, leaving the other entries that pass the check (a kept record
   * that is not a JSON object is replaced). Nothing is written where reading the storage throws, so
   * the other entries are not lost. @returns whether it was kept.
   * @throws TypeError if `name` is not a string; RangeError naming the key if `value` would not read
   *   back as itself.
   */
  set(name: string, value: T): boolean;
}

/**
 * Saved values by name under `key`, each checked on read by `entry`.
 * @param key the storage key, namespaced as for `storedValue`.
 * @param entry the check of each entry.
 * @param options where it is kept (default the page's localStorage).
 * @throws TypeError naming `storedRecord` if `key` is not namespaced.
 */
export function storedRecord<T>(key: string, entry: StoredCheck<T>, options: StorageOptions = {}): StoredRecord<T> {
  assertKey('storedRecord', key);
  const check = recordCheck(entry);
  const read = (): Record<string, T> => parseStored(getText(options, key), check) ?? Object.create(null);
  return {
    key,
    read,
    get: (name) => {
      const all = read();
      return Object.hasOwn(all, name) ? all[name] : undefined;
    },
    set: (name, value) => {
      if (typeof name !== 'string') throw new TypeError(`storedRecord(${key}).set: name must be a string, got ${typeof name}`);
      if (!readsBackAs(entry, value)) {
        throw new RangeError(`storedRecord(${key}).set: the value does not pass the check, got ${JSON.stringify(value)}`);
      }
      let text: string | null;
      try {
        text = pick(options)?.getItem(key) ?? null;
      } catch {
        return false;
      }
      const all = parseStored(text, check) ?? (Object.create(null) as Record<string, T>);
      all[name] = value;
      return setText(options, key, JSON.stringify(all));
    },
  };
}

/** A check of a JSON object whose entries pass `entry` (the others left out), into an object with no prototype ('__proto__' is an ordinary name). */
function recordCheck<T>(entry: StoredCheck<T>): StoredCheck<Record<string, T>> {
  return (value) => {
    if (typeof value !== 'object' || value === null || Array.isArray(value)) return undefined;
    const out = Object.create(null) as Record<string, T>;
    for (const [name, v] of Object.entries(value)) {
      const ok = entry(v);
      if (ok !== undefined) out[name] = ok;
    }
    return out;
  };
}

/** Throws a TypeError naming `fn` unless `key` is a namespaced key (KEY_SHAPE). */
function assertKey(fn: string, key: string): void {
  if (typeof key !== 'string' || !KEY_SHAPE.test(key)) {
    throw new TypeError(
      `${fn}: key must be namespaced, dot-separated parts of letters, digits, '_' and '-' ('my-game.best'), got ${JSON.stringify(key)}`,
    );
  }
}

/** The storage of `options`: its own (null for none), else the page's. */
function pick(options: StorageOptions): KeyValueStorage | null {
  return options.storage === undefined ? pageStorage() : options.storage;
}

/** The text under `key`, null where there is none or the storage is missing or throws. */
function getText(options: StorageOptions, key: string): string | null {
  try {
    return pick(options)?.getItem(key) ?? null;
  } catch {
    return null;
  }
}

/** Keeps `text` under `key`: whether it was kept (false with no storage, or one that throws). */
function setText(options: StorageOptions, key: string, text: string): boolean {
  const storage = pick(options);
  if (!storage) return false;
  try {
    storage.setItem(key, text);
    return true;
  } catch {
    return false;
  }
}

/** `text` parsed as JSON and checked, undefined for none, bad JSON, a refused value or a check that throws. */
function parseStored<T>(text: string | null, check: StoredCheck<T>): T | undefined {
  if (text === null) return undefined;
  try {
    return check(JSON.parse(text));
  } catch {
    return undefined;
  }
}

/** Whether `value`, written as JSON and read back through `check`, comes back equal to itself. */
function readsBackAs<T>(check: StoredCheck<T>, value: T): boolean {
  let text: string | undefined;
  try {
    text = JSON.stringify(value);
  } catch {
    return false;
  }
  if (text === undefined) return false;
  const back = check(JSON.parse(text));
  return back !== undefined && sameJson(back, value);
}

/** Whether two JSON values are equal: the same primitives, or arrays and objects of equal entries. */
function sameJson(a: unknown, b: unknown): boolean {
  if (a === b) return true;
  if (typeof a !== 'object' || typeof b !== 'object' || a === null || b === null) return false;
  if (Array.isArray(a) !== Array.isArray(b)) return false;
  const ka = Object.keys(a),
    kb = Object.keys(b);
  if (ka.length !== kb.length) return false;
  return ka.every((k) => Object.hasOwn(b, k) && sameJson((a as Record<string, unknown>)[k], (b as Record<string, unknown>)[k]));
}
