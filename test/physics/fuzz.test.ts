import * as physics from '@bitphysics/physics';
import { createPhysicsWorld, INTEGRATOR_NAMES, NonFiniteStateError, type PhysicsWorld, query, slotOf, step } from '@bitphysics/physics';
import fc from 'fast-check';
import { describe, expect, test } from 'vitest';

/**
 * Fuzzing the public API (issue 15): random programs of API calls and steps over the documented
 * ranges and past them (magnitudes log-uniform in [1e-6, 1e6] with either sign, booleans, nulls,
 * undefined and junk options, removed handles, handles of the wrong kind), checking that
 * - every call either succeeds or throws a TypeError or RangeError whose message starts with the
 *   name of the function called (`setDrag: ...`); `step` may also throw the documented
 *   NonFiniteStateError (a RangeError naming the entity, field and stage);
 * - a call that throws leaves the number of live entities as it was;
 * - after every step that returns, every body's position, velocity, angle or orientation and angular
 *   velocity is finite (no state is silently non-finite);
 * - `step` returns: the programs are bounded by size (worlds of at most 48 entities, at most 12
 *   calls and 3 steps a call), so the suite counts steps rather than timing them, and a hang would
 *   show as the test's timeout.
 * Seeded (fast-check's default seed is random; the seed is fixed so CI is reproducible; a failure
 * prints its counterexample).
 */

const SEED = 15;

/** Signed magnitudes log-uniform in [1e-6, 1e6], zero, and the junk a careless caller passes. */
const magnitude = fc.double({ min: -6, max: 6, noNaN: true }).map((e) => 10 ** e);
const signed = fc.tuple(magnitude, fc.boolean()).map(([m, neg]) => (neg ? -m : m));
const junk = fc.constantFrom<unknown>(
  null,
  undefined,
  NaN,
  Infinity,
  -Infinity,
  'yes',
  'false',
  '1',
  {},
  [],
  true,
  false,
  1e308,
  -1e308,
  0,
  -0,
);
const num = fc.oneof({ weight: 4, arbitrary: magnitude }, { weight: 3, arbitrary: signed }, { weight: 1, arbitrary: junk });
const bool = fc.oneof({ weight: 3, arbitrary: fc.boolean() }, { weight: 1, arbitrary: junk });
const vec = (d: number) =>
  fc.oneof(
    { weight: 5, arbitrary: fc.array(signed, { minLength: d, maxLength: d }) },
    { weight: 1, arbitrary: fc.array(num, { minLength: 0, maxLength: 4 }) },
    { weight: 1, arbitrary: junk },
  );
/** An options object built from `fields`, or junk in its place. */
const options = (fields: Record<string, fc.Arbitrary<unknown>>) =>
  fc.oneof(
    { weight: 6, arbitrary: fc.record(fields, { requiredKeys: [] }) },
    { weight: 1, arbitrary: fc.record({ ...fields, bogus: num }, { requiredKeys: ['bogus'] }) },
    { weight: 1, arbitrary: junk },
  );

/** Index into the program's pool of handles (live, removed, other kinds), or a junk id. */
const who = fc.oneof(
  { weight: 6, arbitrary: fc.nat(64).map((i) => ({ pool: i })) },
  {
    weight: 1,
    arbitrary: fc.constantFrom<unknown>(0, -1, 1.5, 2 ** 40, NaN, '1', null, undefined).map((v) => ({ raw: v })),
  },
);

type Who = { pool: number } | { raw: unknown };
interface Call {
  fn: string;
  who?: Who;
  who2?: Who;
  args: unknown[];
}

const call = (d: number): fc.Arbitrary<Call> =>
  fc.oneof(
    {
      weight: 6,
      arbitrary: options({
        position: vec(d),
        velocity: vec(d),
        mass: num,
        radius: num,
        restitution: num,
        friction: num,
        static: bool,
        rotates: bool,
        linearDrag: num,
        quadraticDrag: num,
        angularVelocity: d === 2 ? num : vec(3),
      }).map((o) => ({ fn: 'addBody', args: [o] })),
    },
    { weight: 2, arbitrary: who.map((w) => ({ fn: 'removeBody', who: w, args: [] })) },
    { weight: 2, arbitrary: fc.tuple(who, vec(d)).map(([w, v]) => ({ fn: 'setVelocity', who: w, args: [v] })) },
    { weight: 2, arbitrary: fc.tuple(who, vec(d)).map(([w, v]) => ({ fn: 'setPosition', who: w, args: [v] })) },
    { weight: 1, arbitrary: fc.tuple(who, vec(d)).map(([w, v]) => ({ fn: 'applyImpulse', who: w, args: [v] })) },
    { weight: 1, arbitrary: fc.tuple(who, num).map(([w, v]) => ({ fn: 'setMass', who: w, args: [v] })) },
    { weight: 1, arbitrary: fc.tuple(who, num).map(([w, v]) => ({ fn: 'setRadius', who: w, args: [v] })) },
    {
      weight: 1,
      arbitrary: fc.tuple(who, options({ restitution: num, friction: num })).map(([w, o]) => ({ fn: 'setMaterial', who: w, args: [o] })),
    },
    {
      weight: 3,
      arbitrary: fc.tuple(who, options({ linear: num, quadratic: num })).map(([w, o]) => ({ fn: 'setDrag', who: w, args: [o] })),
    },
    { weight: 2, arbitrary: fc.tuple(who, num).map(([w, v]) => ({ fn: 'setAngularDamping', who: w, args: [v] })) },
    { weight: 1, arbitrary: fc.tuple(who, d === 2 ? num : vec(3)).map(([w, v]) => ({ fn: 'setAngularVelocity', who: w, args: [v] })) },
    { weight: 1, arbitrary: fc.tuple(who, num).map(([w, v]) => ({ fn: 'setCharge', who: w, args: [v] })) },
    {
      weight: 2,
      arbitrary: options({
        position: vec(d),
        rate: num,
        speed: num,
        lifetime: num,
        enabled: bool,
        policy: fc.constantFrom<unknown>('drop-new', 'recycle-oldest', 'grow', null),
        particle: options({ mass: num, linearDrag: num, quadraticDrag: num }),
      }).map((o) => ({ fn: 'addEmitter', args: [o] })),
    },
    { weight: 2, arbitrary: fc.tuple(who, num).map(([w, v]) => ({ fn: 'setEmitterRate', who: w, args: [v] })) },
    { weight: 1, arbitrary: fc.tuple(who, bool).map(([w, v]) => ({ fn: 'setEmitterEnabled', who: w, args: [v] })) },
    { weight: 1, arbitrary: fc.tuple(who, fc.oneof(fc.nat(100), num)).map(([w, v]) => ({ fn: 'burst', who: w, args: [v] })) },
    {
      weight: 1,
      arbitrary: fc
        .tuple(who, who, options({ stiffness: num, damping: num, restLength: num, oneSided: bool }))
        .map(([a, b, o]) => ({ fn: 'addSpring', who: a, who2: b, args: [o] })),
    },
    { weight: 1, arbitrary: options({ a: vec(d), b: vec(d), restitution: num }).map((o) => ({ fn: 'addSegment', args: [o] })) },
    { weight: 1, arbitrary: options({ min: vec(d), max: vec(d), restitution: num }).map((o) => ({ fn: 'setBoundary', args: [o] })) },
    { weight: 1, arbitrary: options({ velocity: vec(d) }).map((o) => ({ fn: 'setWind', args: [o] })) },
    { weight: 1, arbitrary: options({ surface: num, density: num }).map((o) => ({ fn: 'addFluidRegion', args: [o] })) },
    {
      weight: 1,
      arbitrary: fc
        .tuple(who, options({ shape: fc.constantFrom<unknown>('ball', 'box', 'cone'), radius: num, dragCoefficient: num }))
        .map(([w, o]) => ({ fn: 'setBuoyancy', who: w, args: [o] })),
    },
    { weight: 1, arbitrary: options({ field: d === 2 ? num : vec(3) }).map((o) => ({ fn: 'addMagneticField', args: [o] })) },
    {
      weight: 1,
      arbitrary: fc
        .tuple(num, fc.oneof(fc.constant(undefined), fc.integer({ min: 0, max: 70 })))
        .map(([dt, n]) => ({ fn: 'setTimeStep', args: n === undefined ? [dt] : [dt, n] })),
    },
    { weight: 1, arbitrary: vec(d).map((v) => ({ fn: 'setGravity', args: [v] })) },
    { weight: 6, arbitrary: fc.integer({ min: 1, max: 3 }).map((n) => ({ fn: 'step', args: [n] })) },
  );

/** World options: documented values mostly, junk sometimes (createPhysicsWorld must refuse it cleanly). */
const worldOptions: fc.Arbitrary<WorldChoice> = fc.record({
  dimensions: fc.constantFrom<2 | 3>(2, 3),
  capacity: fc.integer({ min: 1, max: 48 }),
  integrator: fc.constantFrom(...INTEGRATOR_NAMES),
  dt: fc.oneof(
    { weight: 4, arbitrary: fc.double({ min: -6, max: 0, noNaN: true }).map((e) => 10 ** e) },
    { weight: 1, arbitrary: magnitude },
  ),
  substeps: fc.integer({ min: 1, max: 4 }),
});

/** Throws unless every live body's motion state is finite. */
function assertFiniteState(world: PhysicsWorld, after: string): void {
  const c = world.components;
  const fields: Array<[string, object, Float64Array[]]> = [
    ['Position', c.Position, [c.Position.x, c.Position.y, c.Position.z]],
    ['Velocity', c.Velocity, [c.Velocity.x, c.Velocity.y, c.Velocity.z]],
    ['AngularVelocity', c.AngularVelocity, [c.AngularVelocity.x, c.AngularVelocity.y, c.AngularVelocity.z]],
    ['Angle', c.Angle, [c.Angle.value]],
    ['Orientation', c.Orientation, [c.Orientation.x, c.Orientation.y, c.Orientation.z, c.Orientation.w]],
  ];
  for (const [name, component, arrays] of fields) {
    const ents = query(world, [component]);
    for (let i = 0; i < ents.length; i++) {
      for (const a of arrays) {
        const v = a[ents[i]!]!;
        if (!Number.isFinite(v)) throw new Error(`after ${after}: entity ${ents[i]} has a silently non-finite ${name} (${v})`);
      }
    }
  }
}

interface Stats {
  calls: number;
  refused: number;
  steps: number;
  nonFinite: number;
}

type WorldChoice = { dimensions: 2 | 3; capacity: number; integrator: (typeof INTEGRATOR_NAMES)[number]; dt: number; substeps: number };

/** Runs one program; throws (failing the property) on an undocumented outcome. */
function run(opts: WorldChoice, calls: Call[], stats: Stats): void {
  const world = createPhysicsWorld({
    dimensions: opts.dimensions,
    capacity: opts.capacity,
    integrator: opts.integrator,
    dt: opts.dt,
    substeps: opts.substeps,
    gravity: opts.dimensions === 2 ? [0, -9.81] : [0, -9.81, 0],
  });
  // Every handle the program has seen: live ones, removed ones, and entities of every kind.
  const pool: unknown[] = [];
  const resolve = (w: Who | undefined): unknown =>
    w === undefined ? undefined : 'raw' in w ? w.raw : pool.length === 0 ? 1 : pool[w.pool % pool.length];
  const api = physics as unknown as Record<string, (...a: unknown[]) => unknown>;
  for (const c of calls) {
    stats.calls++;
    const alive = world.entityIndex.aliveCount;
    try {
      if (c.fn === 'step') {
        for (let i = 0; i < (c.args[0] as number); i++) {
          step(world);
          stats.steps++;
          assertFiniteState(world, 'step');
        }
        continue;
      }
      let result: unknown;
      if (c.fn === 'addSpring') {
        const o = c.args[0];
        const withEnds = o !== null && typeof o === 'object' && !Array.isArray(o) ? { ...o, a: resolve(c.who), b: resolve(c.who2) } : o;
        result = api.addSpring!(world, withEnds);
      } else if (c.who !== undefined) result = api[c.fn]!(world, resolve(c.who), ...c.args);
      else result = api[c.fn]!(world, ...c.args);
      if (typeof result === 'number') pool.push(result);
      assertFiniteState(world, c.fn);
    } catch (e) {
      if (e instanceof NonFiniteStateError && c.fn === 'step') {
        // Documented: the step stopped and named the culprit. The program ends here.
        expect(e.message).toMatch(/^bitphysics: entity \d+ has a non-finite \w+\.\w+ /);
        stats.nonFinite++;
        return;
      }
      if (!(e instanceof TypeError || e instanceof RangeError)) throw e;
      // The message names the function the user called.
      if (!e.message.startsWith(`${c.fn}: `))
        throw new Error(`${c.fn}(${JSON.stringify(c.args)}) threw a message not naming it: ${e.message}`);
      // A refused call leaves no entity behind.
      if (world.entityIndex.aliveCount !== alive)
        throw new Error(`${c.fn} threw but changed the entity count ${alive} -> ${world.entityIndex.aliveCount}: ${e.message}`);
      stats.refused++;
    }
  }
}

describe('fuzz: random programs of API calls and steps (fast-check)', () => {
  test('every call succeeds or throws a documented error naming its function; no silent non-finite state; step returns', () => {
    const stats: Stats = { calls: 0, refused: 0, steps: 0, nonFinite: 0 };
    const program = worldOptions.chain((o) => fc.tuple(fc.constant(o), fc.array(call(o.dimensions), { minLength: 1, maxLength: 12 })));
    fc.assert(
      fc.property(program, ([o, calls]) => {
        run(o, calls, stats);
      }),
      { numRuns: 1300, seed: SEED },
    );
    // The programs did exercise both outcomes and the steps.
    expect(stats.refused).toBeGreaterThan(500);
    expect(stats.calls - stats.refused).toBeGreaterThan(500);
    expect(stats.steps).toBeGreaterThan(500);
  }, 180_000);

  test('createPhysicsWorld with any options returns a world or throws a documented error naming it', () => {
    const anyOptions = options({
      dimensions: fc.oneof(fc.constantFrom<unknown>(2, 3), num),
      capacity: fc.oneof(fc.integer({ min: -2, max: 64 }), num),
      dt: num,
      substeps: fc.oneof(fc.integer({ min: -1, max: 70 }), num),
      integrator: fc.oneof(fc.constantFrom<unknown>(...INTEGRATOR_NAMES), junk),
      gravity: vec(2),
      seed: num,
    });
    let made = 0;
    fc.assert(
      fc.property(anyOptions, (o) => {
        let world: PhysicsWorld | undefined;
        try {
          world = createPhysicsWorld(o as never);
        } catch (e) {
          if (!(e instanceof TypeError || e instanceof RangeError) || !e.message.startsWith('createPhysicsWorld: ')) throw e;
          return;
        }
        made++;
        step(world);
        assertFiniteState(world, 'step');
      }),
      { numRuns: 500, seed: SEED },
    );
    expect(made).toBeGreaterThan(10);
  });

  test('removed handles are refused by every call, never aimed at the entity that reuses the slot', () => {
    fc.assert(
      fc.property(
        fc.constantFrom<2 | 3>(2, 3),
        fc.array(
          fc.constantFrom(
            'setVelocity',
            'setPosition',
            'setMass',
            'setRadius',
            'setDrag',
            'setAngularDamping',
            'setCharge',
            'applyImpulse',
            'removeBody',
          ),
          { minLength: 1, maxLength: 8 },
        ),
        (d, fns) => {
          const world = createPhysicsWorld({ dimensions: d, capacity: 4 });
          const old = physics.addBody(world, { mass: 1 });
          physics.removeBody(world, old);
          const fresh = physics.addBody(world, { mass: 2, velocity: d === 2 ? [1, 2] : [1, 2, 3] });
          expect(slotOf(fresh)).toBe(slotOf(old));
          const api = physics as unknown as Record<string, (...a: unknown[]) => unknown>;
          const args: Record<string, unknown[]> = {
            setVelocity: [d === 2 ? [9, 9] : [9, 9, 9]],
            setPosition: [d === 2 ? [9, 9] : [9, 9, 9]],
            setMass: [9],
            setRadius: [9],
            setDrag: [{ linear: 9 }],
            setAngularDamping: [9],
            setCharge: [9],
            applyImpulse: [d === 2 ? [9, 9] : [9, 9, 9]],
            removeBody: [],
          };
          const s = slotOf(fresh),
            c = world.components;
          for (const fn of fns) {
            expect(() => api[fn]!(world, old, ...args[fn]!)).toThrow(new RegExp(`^${fn}: `));
            expect(physics.isAlive(world, fresh)).toBe(true);
            expect(c.Velocity.x[s]).toBe(1);
            expect(c.Mass.value[s]).toBe(2);
          }
        },
      ),
      { numRuns: 200, seed: SEED },
    );
  });
});
