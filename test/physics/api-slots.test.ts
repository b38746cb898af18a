import * as api from '@bitphysics/physics';
import fc from 'fast-check';
import { describe, expect, test } from 'vitest';

/**
 * Property test of the 2D and 3D rigid-body API under slot reuse and bad input (issue 33).
 *
 * Random programs add bodies (balls, boxes, compounds), shapes, joints, ropes and cloth, remove them
 * and step, in small worlds whose slots have already been used 70 times each (handles of generation
 * 70: past 64, where a handle no longer fits an Int32), so every add recycles a slot. Between the valid
 * calls come bad ones: removed handles, non-handles, null, NaN, negative and non-boolean values,
 * unknown options, '__proto__' as a type.
 *
 * A model independent of the world says what must be alive: every entity the API returned until it,
 * or the body it belongs to (its shapes, the joints on it), was removed. After every call:
 * - a valid call returns (a throw is a crash); a bad call throws a TypeError or RangeError whose
 *   message starts with `<function>: ` (else a crash; no throw at all is a silent acceptance) and
 *   leaves the number of live entities as it was;
 * - lost entities: a modelled live entity whose handle `isAlive` denies, a removed one it affirms, a
 *   live count that differs from the model's, or a body's shape list (`shapesOf`, `shapes3DOfBody`)
 *   that differs from the model's;
 * - hangs: a call that takes more than 2 s (an endless loop would stop the suite: the programs are
 *   bounded, so the test's timeout shows it).
 * The counts are printed and each must be 0 but the calls and clear errors.
 */

type World = api.PhysicsWorld;
type Fn = (...args: unknown[]) => unknown;
const fn = (name: string): Fn => (api as unknown as Record<string, Fn>)[name]!;

const SEED = 33;
const CAPACITY = 40;
const GENERATIONS = 70;

interface Counts {
  calls: number;
  ok: number;
  clear: number;
  silent: number;
  crash: number;
  hang: number;
  lost: number;
}

interface Ent {
  h: number;
  kind: 'body' | 'shape' | 'joint' | 'link';
  /** Shapes: the body they belong to (the body itself for its own shape). Joints: their bodies. */
  owner?: number;
  a?: number;
  b?: number;
  removed: boolean;
}

/** A world whose every slot has lived GENERATIONS times. */
function wornWorld(dimensions: 2 | 3): World {
  const world = api.createPhysicsWorld({ dimensions, capacity: CAPACITY, gravity: dimensions === 2 ? [0, -9.81] : [0, -9.81, 0] });
  const hs: number[] = [];
  for (let g = 0; g < GENERATIONS; g++) {
    for (let i = 0; i < CAPACITY; i++) hs[i] = api.createEntity(world);
    for (let i = 0; i < CAPACITY; i++) api.removeBody(world, hs[i]!);
  }
  return world;
}

class Run {
  readonly ents: Ent[] = [];
  /** Live entities the world has that the model does not (counted as lost when they appeared). */
  orphans = 0;
  constructor(
    readonly world: World,
    readonly counts: Counts,
    readonly notes: string[],
  ) {}

  live(kind?: Ent['kind']): Ent[] {
    return this.ents.filter((e) => !e.removed && (kind === undefined || e.kind === kind));
  }
  pick<T>(list: T[], k: number): T | undefined {
    return list.length === 0 ? undefined : list[k % list.length];
  }
  room(n: number): boolean {
    return this.world.entityIndex.aliveCount + n <= this.world.capacity;
  }

  /** Calls `f` expecting success; returns its result or undefined if it threw (a crash). */
  good<T>(name: string, f: () => T): T | undefined {
    this.counts.calls++;
    const t0 = performance.now();
    try {
      const r = f();
      this.counts.ok++;
      return r;
    } catch (e) {
      this.counts.crash++;
      this.note(`valid ${name} threw: ${String(e)}`);
      return undefined;
    } finally {
      if (performance.now() - t0 > 2000) this.counts.hang++;
    }
  }

  /** Calls `f` expecting a clear error from `name`, with nothing changed. */
  bad(name: string, what: string, f: () => unknown): void {
    this.counts.calls++;
    const alive = this.world.entityIndex.aliveCount;
    const t0 = performance.now();
    try {
      f();
      this.counts.silent++;
      this.note(`${name} accepted ${what}`);
    } catch (e) {
      const clear =
        (e instanceof TypeError || e instanceof RangeError) &&
        e.message.startsWith(`${name}: `) &&
        !/Cannot read|is not a function|is not iterable|\(reading /.test(e.message);
      if (clear) this.counts.clear++;
      else {
        this.counts.crash++;
        this.note(`${name} with ${what}: ${String(e)}`);
      }
    } finally {
      if (performance.now() - t0 > 2000) this.counts.hang++;
    }
    if (this.world.entityIndex.aliveCount !== alive) {
      this.counts.lost += Math.abs(this.world.entityIndex.aliveCount - alive);
      this.note(`${name} with ${what} changed the live count ${alive} -> ${this.world.entityIndex.aliveCount}`);
    }
  }

  note(s: string): void {
    if (this.notes.length < 40) this.notes.push(s);
  }

  /** The model's effect of removing entity `h` (and what it takes with it). */
  removeInModel(h: number): void {
    for (const e of this.ents) {
      if (e.removed) continue;
      if (e.h === h) e.removed = true;
    }
    for (const e of this.ents) {
      if (e.removed) continue;
      if (e.kind === 'shape' && e.owner === h) e.removed = true;
      if ((e.kind === 'joint' || e.kind === 'link') && (e.a === h || e.b === h)) e.removed = true;
    }
  }

  /** Compares the model with the world; adds what differs to `lost`. */
  check(): void {
    const w = this.world;
    const liveHandles = new Set<number>();
    for (const e of this.ents) {
      const alive = api.isAlive(w, e.h);
      if (!e.removed) liveHandles.add(e.h); // a box's body and its own shape share one handle
      if (alive !== !e.removed) {
        this.counts.lost++;
        this.note(`${e.kind} ${e.h} alive ${alive}, model says ${!e.removed}`);
      }
    }
    const expectAlive = liveHandles.size + this.orphans;
    if (w.entityIndex.aliveCount !== expectAlive) {
      this.counts.lost += Math.abs(w.entityIndex.aliveCount - expectAlive);
      this.note(`live count ${w.entityIndex.aliveCount}, model ${expectAlive}`);
      // Count each orphan once: the model takes the world's count as its new base.
      this.orphans += w.entityIndex.aliveCount - expectAlive;
    }
    const shapesOf = w.dimensions === 2 ? fn('shapesOf') : fn('shapes3DOfBody');
    for (const b of this.live('body')) {
      const want = this.live('shape')
        .filter((s) => s.owner === b.h)
        .map((s) => s.h);
      let got: number[] = [];
      try {
        got = shapesOf(w, b.h) as number[];
      } catch {
        got = [-1];
      }
      if (got.length !== want.length || got.some((g, i) => g !== want[i])) {
        this.counts.lost++;
        this.note(`body ${b.h}: shapes ${JSON.stringify(got)}, model ${JSON.stringify(want)}`);
      }
    }
  }
}

/** One command of a program: an operation and numbers that pick its entities and bad values. */
interface Cmd {
  op: number;
  i: number;
  j: number;
  v: number;
}
const cmd = fc.record({ op: fc.nat(15), i: fc.nat(1000), j: fc.nat(1000), v: fc.nat(1000) });

/** Values a careless caller passes where a number, vector, boolean or options object goes. */
const JUNK: unknown[] = [null, NaN, -1, Infinity, 'yes', {}, [], [NaN, 0], 0, 1.5, undefined, '__proto__'];

function run2D(r: Run, c: Cmd): void {
  const w = r.world;
  const { op, i, j, v } = c;
  const junk = JUNK[v % JUNK.length];
  const anyEnt = r.pick(r.ents, i);
  switch (op) {
    case 0: {
      if (!r.room(1)) return;
      const h = r.good('addBody', () => api.addBody(w, { position: [i % 20, 1 + (j % 10)], radius: 0.3 }));
      if (h !== undefined) r.ents.push({ h, kind: 'body', removed: false });
      return;
    }
    case 1: {
      if (!r.room(1)) return;
      const h = r.good('addBox', () => api.addBox(w, { position: [i % 20, 1 + (j % 10)], halfExtents: [0.3, 0.2] }));
      if (h !== undefined) r.ents.push({ h, kind: 'body', removed: false }, { h, kind: 'shape', owner: h, removed: false });
      return;
    }
    case 2: {
      // An extra shape on a live body (a compound).
      const b = r.pick(r.live('body'), i);
      if (!b || !r.room(1)) return;
      const own = r.live('shape').some((s) => s.owner === b.h);
      const isBall = w.components.Ball.radius[api.slotOf(b.h)]! > 0 && api.isAlive(w, b.h);
      const s = r.good('addShape', () => api.addShape(w, b.h, { type: 'circle', radius: 0.2, offset: [0.3, 0] }));
      if (s !== undefined) {
        // The first shape of a body without a ball goes on the body's own entity (same handle).
        if (!own && !isBall) r.ents.push({ h: s, kind: 'shape', owner: b.h, removed: false });
        else r.ents.push({ h: s, kind: 'shape', owner: b.h, removed: false });
      }
      return;
    }
    case 3: {
      // Remove a live body, extra shape or joint.
      const e = r.pick(
        r.ents.filter((x) => !x.removed && x.kind !== 'link' && !(x.kind === 'shape' && x.owner === x.h)),
        i,
      );
      if (!e) return;
      const ok = r.good('removeBody', () => api.removeBody(w, e.h));
      if (ok !== undefined || api.isAlive(w, e.h) === false) r.removeInModel(e.h);
      // An extra shape removed on its own leaves its body's list.
      return;
    }
    case 4: {
      const a = r.pick(r.live('body'), i),
        b = r.pick(r.live('body'), j);
      if (!a || !b || a.h === b.h || !r.room(1)) return;
      const names = ['addDistanceJoint', 'addRevoluteJoint', 'addWeldJoint'] as const;
      const name = names[v % 3]!;
      const h = r.good(name, () => fn(name)(w, { a: a.h, b: b.h }) as number);
      if (h !== undefined) r.ents.push({ h, kind: 'joint', a: a.h, b: b.h, removed: false });
      return;
    }
    case 5: {
      const n = 2 + (v % 3);
      if (!r.room(2 * n)) return;
      const rope = r.good('createRope', () => api.createRope(w, { start: [i % 10, 8], end: [(i % 10) + 2, 8], segments: n }));
      if (!rope) return;
      const bodies = Array.from(rope.bodies);
      for (const h of bodies) r.ents.push({ h, kind: 'body', removed: false });
      const js = Array.from(rope.joints);
      // joints[0] pins the first body to the world; the rest link neighbours.
      r.ents.push({ h: js[0]!, kind: 'joint', a: 0, b: bodies[0]!, removed: false });
      for (let k = 1; k < js.length; k++) r.ents.push({ h: js[k]!, kind: 'joint', a: bodies[k - 1]!, b: bodies[k]!, removed: false });
      return;
    }
    case 6: {
      if (!r.room(8)) return;
      const cloth = r.good('createCloth', () =>
        api.createCloth(w, { origin: [i % 10, 9], columns: 2, rows: 2, shearCompliance: null, bendCompliance: null, pinned: 'none' }),
      );
      if (!cloth) return;
      // Cloth points are tracked but not removed here (cloth has no removal hook for its links).
      for (const h of cloth.points) r.ents.push({ h, kind: 'link', removed: false });
      for (const h of cloth.links) r.ents.push({ h, kind: 'link', removed: false });
      return;
    }
    case 7:
      r.good('step', () => api.step(w));
      return;
    case 8: {
      // A removed handle of any kind, given to a function that takes that kind.
      const e = r.pick(
        r.ents.filter((x) => x.removed),
        i,
      );
      if (!e) return;
      const calls: Array<[string, () => unknown]> = [
        ['removeBody', () => api.removeBody(w, e.h)],
        ['addShape', () => api.addShape(w, e.h, { type: 'circle', radius: 0.2 })],
        ['shapesOf', () => api.shapesOf(w, e.h)],
        ['setShapeFilter', () => api.setShapeFilter(w, e.h, { mask: 0 })],
        ['updateMassFromShapes', () => api.updateMassFromShapes(w, e.h)],
        ['setVelocity', () => api.setVelocity(w, e.h, [1, 0])],
        ['addDistanceJoint', () => api.addDistanceJoint(w, { a: null, b: e.h, anchorA: [0, 0] })],
        ['removeJoint', () => api.removeJoint(w, e.h)],
      ];
      const [name, f] = calls[j % calls.length]!;
      r.bad(name, `removed handle ${e.h}`, f);
      return;
    }
    case 9: {
      // A non-handle (junk, an id above the capacity, a slot of a later generation).
      const bogus = [junk, CAPACITY + 1 + (i % 5), 1e6, anyEnt ? anyEnt.h + api.SLOT_RANGE * 3 : 2 ** 40][j % 4];
      if (typeof bogus === 'number' && api.isAlive(w, bogus)) return;
      const calls: Array<[string, () => unknown]> = [
        ['addShape', () => api.addShape(w, bogus as number, { type: 'circle', radius: 0.2 })],
        ['shapesOf', () => api.shapesOf(w, bogus as number)],
        ['setShapeFilter', () => api.setShapeFilter(w, bogus as number, { mask: 0 })],
        ['updateMassFromShapes', () => api.updateMassFromShapes(w, bogus as number)],
        ['removeBody', () => api.removeBody(w, bogus as number)],
      ];
      const [name, f] = calls[v % calls.length]!;
      r.bad(name, `non-handle ${String(bogus)}`, f);
      return;
    }
    case 10: {
      // A bad option value for a constructor.
      const key = ['halfExtents', 'density', 'friction', 'restitution', 'sensor', 'velocity', 'static', 'mass'][i % 8]!;
      if (key === 'density' && (junk === 0 || junk === 1.5)) return;
      if (['friction'].includes(key) && (junk === 0 || junk === 1.5 || junk === Infinity)) return;
      if (key === 'restitution' && junk === 0) return;
      if (junk === undefined && key !== 'halfExtents') return;
      r.bad('addBox', `${key}: ${String(junk)}`, () => api.addBox(w, { halfExtents: [0.3, 0.3], [key]: junk } as never));
      return;
    }
    case 11: {
      const b = r.pick(r.live('body'), i);
      if (!b) return;
      const key = ['type', 'radius', 'offset', 'density', 'sensor', 'bogus'][j % 6]!;
      const value = key === 'type' ? ['__proto__', 'toString', null, 'square'][v % 4] : junk;
      if (value === undefined && key !== 'radius') return;
      if ((key === 'density' && (value === 0 || value === 1.5)) || (key === 'radius' && value === 1.5)) return;
      r.bad('addShape', `${key}: ${String(value)}`, () => api.addShape(w, b.h, { type: 'circle', radius: 0.2, [key]: value } as never));
      return;
    }
    case 12: {
      const s = r.pick(r.live('shape'), i);
      if (!s) return;
      const filter = [undefined, null, { mask: -1 }, { group: 0.5 }, { category: null }, { bogus: 1 }, 'all'][j % 7];
      r.bad('setShapeFilter', `filter ${JSON.stringify(filter)}`, () => api.setShapeFilter(w, s.h, filter as never));
      return;
    }
    case 13: {
      const key = ['segments', 'mass', 'radius', 'pinStart', 'breakForce', 'start'][i % 6]!;
      if (key === 'breakForce' && junk === Infinity) return;
      if (junk === undefined || (key === 'radius' && (junk === 0 || junk === 1.5)) || (key === 'mass' && junk === 1.5)) return;
      r.bad('createRope', `${key}: ${String(junk)}`, () =>
        api.createRope(w, { start: [0, 5], end: [1, 5], segments: 2, [key]: junk } as never),
      );
      return;
    }
    case 14: {
      const a = r.pick(r.live('body'), i);
      if (!a) return;
      const key = ['b', 'breakForce', 'collideConnected', 'length', 'bogus'][j % 5]!;
      if (junk === undefined || (key === 'length' && junk === 1.5) || (key === 'breakForce' && (junk === Infinity || junk === 1.5))) return;
      r.bad('addDistanceJoint', `${key}: ${String(junk)}`, () => api.addDistanceJoint(w, { a: a.h, b: a.h, [key]: junk } as never));
      return;
    }
    default: {
      const key = ['columns', 'mass', 'pinned', 'compliance', 'drag'][i % 5]!;
      if (junk === undefined || (key !== 'columns' && key !== 'pinned' && (junk === 0 || junk === 1.5))) return;
      if (key === 'pinned' && Array.isArray(junk) && junk.length === 0) return; // no pins: valid
      r.bad('createCloth', `${key}: ${String(junk)}`, () => api.createCloth(w, { columns: 2, rows: 2, [key]: junk } as never));
    }
  }
}

function run3D(r: Run, c: Cmd): void {
  const w = r.world;
  const { op, i, j, v } = c;
  const junk = JUNK[v % JUNK.length];
  switch (op % 10) {
    case 0:
    case 1: {
      if (!r.room(2)) return;
      const h = r.good('addBody', () => api.addBody(w, { position: [i % 20, 1 + (j % 10), 0] }));
      if (h === undefined) return;
      r.ents.push({ h, kind: 'body', removed: false });
      const s = r.good('addShape3D', () =>
        api.addShape3D(w, h, op % 2 ? { type: 'box', halfExtents: [0.3, 0.2, 0.3] } : { type: 'sphere', radius: 0.3 }),
      );
      if (s !== undefined) r.ents.push({ h: s, kind: 'shape', owner: h, removed: false });
      return;
    }
    case 2: {
      const b = r.pick(r.live('body'), i);
      if (!b || !r.room(1)) return;
      const s = r.good('addShape3D', () => api.addShape3D(w, b.h, { type: 'sphere', radius: 0.2, offset: [0.3, 0, 0] }));
      if (s !== undefined) r.ents.push({ h: s, kind: 'shape', owner: b.h, removed: false });
      return;
    }
    case 3: {
      const e = r.pick(r.live(), i);
      if (!e) return;
      const removeShape3D = e.kind === 'shape';
      const ok = r.good('removeBody', () => api.removeBody(w, e.h));
      if (ok !== undefined || !api.isAlive(w, e.h)) r.removeInModel(e.h);
      void removeShape3D;
      return;
    }
    case 4: {
      const a = r.pick(r.live('body'), i),
        b = r.pick(r.live('body'), j);
      if (!a || !b || a.h === b.h || !r.room(1)) return;
      const h = r.good('addBallJoint3D', () => api.addBallJoint3D(w, { a: a.h, b: b.h }));
      if (h !== undefined) r.ents.push({ h, kind: 'joint', a: a.h, b: b.h, removed: false });
      return;
    }
    case 5:
      r.good('step', () => api.step(w));
      return;
    case 6: {
      const e = r.pick(
        r.ents.filter((x) => x.removed),
        i,
      );
      if (!e) return;
      const calls: Array<[string, () => unknown]> = [
        ['removeBody', () => api.removeBody(w, e.h)],
        ['addShape3D', () => api.addShape3D(w, e.h, { type: 'sphere', radius: 0.2 })],
        ['shapes3DOfBody', () => api.shapes3DOfBody(w, e.h)],
        ['updateMassFromShapes3D', () => api.updateMassFromShapes3D(w, e.h)],
        ['addBallJoint3D', () => api.addBallJoint3D(w, { b: e.h })],
        ['removeJoint3D', () => api.removeJoint3D(w, e.h)],
      ];
      const [name, f] = calls[j % calls.length]!;
      r.bad(name, `removed handle ${e.h}`, f);
      return;
    }
    case 7: {
      const b = r.pick(r.live('body'), i);
      if (!b) return;
      const key = ['type', 'radius', 'offset', 'density', 'sensor', 'bogus'][j % 6]!;
      const value = key === 'type' ? ['__proto__', 'constructor', null, 'cone'][v % 4] : junk;
      if (value === undefined && key !== 'radius') return;
      if ((key === 'density' && (value === 0 || value === 1.5)) || (key === 'radius' && value === 1.5)) return;
      r.bad('addShape3D', `${key}: ${String(value)}`, () => api.addShape3D(w, b.h, { type: 'sphere', radius: 0.2, [key]: value } as never));
      return;
    }
    case 8: {
      const a = r.pick(r.live('body'), i),
        b = r.pick(r.live('body'), j);
      if (!a || !b || a.h === b.h) return;
      const key = ['breakForce', 'collideConnected', 'anchor', 'bogus'][v % 4]!;
      const value = JUNK[(i + j) % JUNK.length];
      if (value === undefined || (key === 'breakForce' && (value === Infinity || value === 1.5))) return;
      r.bad('addBallJoint3D', `${key}: ${String(value)}`, () => api.addBallJoint3D(w, { a: a.h, b: b.h, [key]: value } as never));
      return;
    }
    default: {
      const key = ['dryMass', 'bogus'][v % 2]!;
      void key;
      const bogus = [junk, CAPACITY + 3, 1e6][j % 3];
      if (typeof bogus === 'number' && api.isAlive(w, bogus)) return;
      r.bad('updateMassFromShapes3D', `body ${String(bogus)}`, () => api.updateMassFromShapes3D(w, bogus as number));
    }
  }
}

function measure(dimensions: 2 | 3, runs: number, length: number): { counts: Counts; notes: string[] } {
  const counts: Counts = { calls: 0, ok: 0, clear: 0, silent: 0, crash: 0, hang: 0, lost: 0 };
  const notes: string[] = [];
  fc.assert(
    fc.property(fc.array(cmd, { minLength: length, maxLength: length }), (program) => {
      const r = new Run(wornWorld(dimensions), counts, notes);
      for (const c of program) {
        const lostBefore = counts.lost;
        if (dimensions === 2) run2D(r, c);
        else run3D(r, c);
        r.check();
        // Count each loss once: after a loss the model follows the world.
        if (counts.lost > lostBefore) for (const e of r.ents) e.removed = !api.isAlive(r.world, e.h);
      }
      return true;
    }),
    { seed: SEED + dimensions, numRuns: runs },
  );
  return { counts, notes };
}

describe('the rigid-body API under slot reuse and bad input', () => {
  for (const d of [2, 3] as const) {
    test(`${d}D: no crash, silent acceptance, hang or lost entity in handles of generation ${GENERATIONS}+`, () => {
      const { counts, notes } = measure(d, 12, 120);
      console.log(`${d}D API property counts: ${JSON.stringify(counts)}`);
      if (notes.length) console.log(notes.slice(0, 20).join('\n'));
      expect(counts.calls).toBeGreaterThan(800);
      expect(counts.clear).toBeGreaterThan(100);
      expect({ silent: counts.silent, crash: counts.crash, hang: counts.hang, lost: counts.lost }).toEqual({
        silent: 0,
        crash: 0,
        hang: 0,
        lost: 0,
      });
    });
  }
});
