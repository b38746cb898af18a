/**
 * The game kit's saved values (packages/game-kit/src/storage.ts) with a Map-backed storage: what a
 * page writes the next reads back; anything stored that is not the value's shape or range (bad JSON,
 * a string, NaN's 'null', a negative, an absurd 1e300) reads as the fallback; a missing storage (Node
 * itself) or one that throws costs only the keeping; the formats the games kept before (a number's
 * text, a JSON list or object) read back as they were. Property tests (fast-check) run the read on
 * any text and the write-read round trip on any valid value.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  type KeyValueStorage,
  listCheck,
  numberCheck,
  pageStorage,
  shapeCheck,
  storedRecord,
  storedValue,
} from '../../packages/game-kit/src/storage';

/** A Map-backed stand-in for localStorage, counting its writes. */
function memory(init: Record<string, string> = {}): KeyValueStorage & { data: Map<string, string>; writes: number } {
  const data = new Map(Object.entries(init));
  const store = {
    data,
    writes: 0,
    getItem: (k: string) => data.get(k) ?? null,
    setItem: (k: string, v: string) => {
      store.writes++;
      data.set(k, v);
    },
  };
  return store;
}

/** A storage whose every call throws, as a blocked or full localStorage. */
const throwing: KeyValueStorage = {
  getItem: () => {
    throw new Error('SecurityError');
  },
  setItem: () => {
    throw new Error('QuotaExceededError');
  },
};

const KEY = 'test-game.best';
const points = numberCheck({ max: 1e9, integer: true });

describe('storedValue', () => {
  it('reads back what was written, as the plain text a number was always kept as', () => {
    const storage = memory();
    const best = storedValue(KEY, points, 0, { storage });
    expect(best.read()).toBe(0);
    expect(best.write(12)).toBe(true);
    expect(storage.data.get(KEY)).toBe('12');
    // A reload: a new handle on the same storage.
    expect(storedValue(KEY, points, 0, { storage }).read()).toBe(12);
  });

  it('reads a bad stored value as the fallback', () => {
    for (const bad of ['', ' ', 'abc', '{', '-4', '2.5', 'NaN', 'null', 'Infinity', '1e400', '1e300', '"12"', '[12]', 'true', '{"v":1}']) {
      expect(storedValue(KEY, points, 7, { storage: memory({ [KEY]: bad }) }).read(), JSON.stringify(bad)).toBe(7);
    }
    // The bounds themselves are kept.
    expect(storedValue(KEY, points, 7, { storage: memory({ [KEY]: '0' }) }).read()).toBe(0);
    expect(storedValue(KEY, points, 7, { storage: memory({ [KEY]: '1000000000' }) }).read()).toBe(1e9);
  });

  it('with no storage, or one that throws, reads the fallback and keeps nothing, without throwing', () => {
    // Node has no localStorage: the default storage is none.
    expect(pageStorage()).toBeNull();
    const plain = storedValue(KEY, points, 3);
    expect(plain.read()).toBe(3);
    expect(plain.write(5)).toBe(false);
    for (const storage of [null, throwing]) {
      const best = storedValue(KEY, points, 3, { storage });
      expect(best.read()).toBe(3);
      expect(best.write(5)).toBe(false);
    }
    // A check that throws on a stored value reads as the fallback too.
    const odd = storedValue(
      KEY,
      (v) => {
        if (v === 1) throw new Error('bad check');
        return typeof v === 'number' ? v : undefined;
      },
      0,
      { storage: memory({ [KEY]: '1' }) },
    );
    expect(odd.read()).toBe(0);
  });

  it('gives a fresh copy of a list fallback each read, so a game changing it in place changes no later read', () => {
    const stars = storedValue('test-game.stars', listCheck(numberCheck({ max: 3, integer: true }), 3, 0), [0, 0, 0], { storage: null });
    const a = stars.read();
    a[0] = 3;
    expect(stars.read()).toEqual([0, 0, 0]);
  });

  it('refuses a key that is not namespaced, a bad range, a fallback or a write that would not read back', () => {
    for (const key of ['best', '', '.best', 'game..best', 'game.best.', 'my game.best', 'game/best']) {
      expect(() => storedValue(key, points, 0), key).toThrow(TypeError);
    }
    expect(() => storedValue('best', points, 0)).toThrow(/storedValue: key must be namespaced.*got "best"/);
    expect(() => numberCheck({ min: 5, max: 1 })).toThrow(/numberCheck: min and max must be finite with min <= max, got min 5, max 1/);
    expect(() => numberCheck({ max: Number.POSITIVE_INFINITY })).toThrow(RangeError);
    expect(() => storedValue(KEY, points, -1)).toThrow(/storedValue\(test-game.best\): fallback must pass the check/);
    const best = storedValue(KEY, points, 0, { storage: memory() });
    for (const bad of [Number.NaN, -1, 2.5, 1e10, Number.POSITIVE_INFINITY]) {
      expect(() => best.write(bad), String(bad)).toThrow(/storedValue\(test-game.best\).write: the value does not pass the check/);
    }
    expect(() => listCheck(points, 2, -1)).toThrow(/listCheck: fill must pass the item check, got -1/);
    expect(() => listCheck(points, 1.5, 0)).toThrow(/listCheck: length must be an integer/);
    // A list value whose bad entry the check would replace by the fill is refused rather than changed silently.
    const list = storedValue('test-game.stars', listCheck(points, 2, 0), [0, 0], { storage: memory() });
    expect(() => list.write([1, Number.NaN])).toThrow(RangeError);
    expect(() => list.write([1])).toThrow(RangeError);
  });

  it('property: any stored text reads as a whole number in range or the fallback, never throwing', () => {
    fc.assert(
      fc.property(
        fc.oneof(
          fc.string(),
          fc.double().map(String),
          fc.jsonValue().map((v) => JSON.stringify(v)),
        ),
        (text) => {
          const v = storedValue(KEY, points, 0, { storage: memory({ [KEY]: text }) }).read();
          expect(Number.isInteger(v) && v >= 0 && v <= 1e9).toBe(true);
        },
      ),
      { numRuns: 1000 },
    );
  });

  it('property: any valid value reads back as written', () => {
    const time = numberCheck({ max: 1e7 });
    fc.assert(
      fc.property(fc.double({ min: 0, max: 1e7, noNaN: true }), (t) => {
        const storage = memory();
        expect(storedValue(KEY, time, 0, { storage }).write(t)).toBe(true);
        expect(storedValue(KEY, time, 0, { storage }).read()).toBe(t);
      }),
      { numRuns: 1000 },
    );
  });
});

describe('listCheck and shapeCheck', () => {
  it('reads a list entry by entry: a bad or missing entry is the fill, extra entries are dropped', () => {
    const stars = listCheck(numberCheck({ min: -1, max: 3, integer: true }), 4, -1);
    expect(stars([3, 'x', -3, 2.5, 1, 2])).toEqual([3, -1, -1, -1]);
    expect(stars([1])).toEqual([1, -1, -1, -1]);
    expect(stars({ 0: 3 })).toBeUndefined();
    expect(stars(null)).toBeUndefined();
  });

  it('property: any JSON read through a list check is the list length with every entry in range', () => {
    const stars = listCheck(numberCheck({ max: 3, integer: true }), 5, 0);
    fc.assert(
      fc.property(fc.jsonValue(), (v) => {
        const out = stars(v);
        if (!Array.isArray(v)) expect(out).toBeUndefined();
        else expect(out!.length === 5 && out!.every((s) => Number.isInteger(s) && s >= 0 && s <= 3)).toBe(true);
      }),
      { numRuns: 1000 },
    );
  });

  it('reads an object field by field, refusing it whole when one field is bad', () => {
    const result = shapeCheck<{ passed: number; time: number }>({
      passed: numberCheck({ max: 1000, integer: true }),
      time: numberCheck({ max: 1e7 }),
    });
    expect(result({ time: 95.5, passed: 8, extra: 1 })).toEqual({ passed: 8, time: 95.5 });
    expect(result({ passed: 8 })).toBeUndefined();
    expect(result({ passed: -8, time: 1 })).toBeUndefined();
    expect(result([8, 95.5])).toBeUndefined();
    expect(result('8')).toBeUndefined();
  });
});

describe('storedRecord', () => {
  const time = numberCheck({ max: 1e7 });

  it('keeps one entry per name, leaving the others, and reads each back', () => {
    const storage = memory({ 'test-game.times': '{"1/5":83.25,"2/5":"x"}' });
    const times = storedRecord('test-game.times', time, { storage });
    // A kept record reads as it was kept; its bad entry is left out.
    expect(times.get('1/5')).toBe(83.25);
    expect(times.get('2/5')).toBeUndefined();
    expect(times.set('3/7', 61)).toBe(true);
    expect(JSON.parse(storage.data.get('test-game.times')!)).toEqual({ '1/5': 83.25, '3/7': 61 });
    expect({ ...times.read() }).toEqual({ '1/5': 83.25, '3/7': 61 });
    // Names an object's prototype holds are ordinary names.
    expect(times.get('toString')).toBeUndefined();
    expect(times.set('__proto__', 5)).toBe(true);
    expect(storedRecord('test-game.times', time, { storage }).get('__proto__')).toBe(5);
    expect(() => times.set('1/5', -1)).toThrow(/storedRecord\(test-game.times\).set: the value does not pass the check/);
  });

  it('replaces a kept record that is not an object, and writes nothing where reading throws', () => {
    for (const junk of ['{', '[1,2]', '5', 'null']) {
      const storage = memory({ 'test-game.times': junk });
      const times = storedRecord('test-game.times', time, { storage });
      expect(times.get('1/5')).toBeUndefined();
      expect(times.set('1/5', 70)).toBe(true);
      expect(storage.data.get('test-game.times')).toBe('{"1/5":70}');
    }
    const failing = { ...memory(), getItem: throwing.getItem };
    expect(storedRecord('test-game.times', time, { storage: failing }).set('1/5', 70)).toBe(false);
    expect(failing.writes).toBe(0);
    expect(storedRecord('test-game.times', time, { storage: throwing }).set('1/5', 70)).toBe(false);
    expect(storedRecord('test-game.times', time, { storage: null }).get('1/5')).toBeUndefined();
  });

  it('property: entries set under any names read back as set', () => {
    fc.assert(
      fc.property(
        fc.dictionary(fc.oneof(fc.string(), fc.constantFrom('__proto__', 'constructor')), fc.double({ min: 0, max: 1e7, noNaN: true })),
        (entries) => {
          const storage = memory();
          const times = storedRecord('test-game.times', time, { storage });
          for (const [name, t] of Object.entries(entries)) times.set(name, t);
          const back = storedRecord('test-game.times', time, { storage }).read();
          expect(Object.keys(back).sort()).toEqual(Object.keys(entries).sort());
          for (const [name, t] of Object.entries(entries)) expect(back[name]).toBe(t);
        },
      ),
      { numRuns: 300 },
    );
  });
});
