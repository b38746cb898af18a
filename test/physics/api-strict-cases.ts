/**
 * The table of bad calls that test/physics/api-strict.test.ts runs: every exported function of
 * @bitphysics/physics that takes an entity or an options object, given a removed entity, an entity
 * of the wrong kind, a missing options object, null, wrong boolean types and unknown keys.
 *
 * Functions are looked up by name on the package's namespace, so the table also runs (as a
 * measurement) against versions of the package that lack some of them.
 */
import * as api from '@bitphysics/physics';
import { hasComponent } from 'bitecs';

type World = api.PhysicsWorld;
type Fn = (...args: never[]) => unknown;
const fn = (name: string): Fn | undefined => (api as unknown as Record<string, Fn | undefined>)[name];

/** The entities every case starts from, each made through the public API. */
export interface Fixture {
  world: World;
  ball: number;
  ball2: number;
  particle: number;
  segment: number;
  plane: number;
  electric: number;
  magnetic: number;
  fluid: number;
  spring: number;
  emitter: number;
  /** A removed ball whose slot now holds `fresh` (bitecs recycles a removed id at once). */
  stale: number;
  fresh: number;
  /** A box body (its own entity is its shape). */
  box: number;
}

export function makeFixture(): Fixture {
  const world = api.createPhysicsWorld({ capacity: 64 });
  const ball = api.addBody(world, { position: [0, 1], radius: 0.5, mass: 2 });
  const ball2 = api.addBody(world, { position: [3, 1], radius: 0.5, mass: 2 });
  const particle = api.addParticle(world, { position: [5, 5] });
  const segment = api.addSegment(world, { a: [-5, 0], b: [5, 0] });
  const plane = api.addPlane(world, { normal: [0, 1] });
  const electric = api.addElectricField(world, { field: [1, 0] });
  const magnetic = api.addMagneticField(world, { field: 1 });
  const fluid = api.addFluidRegion(world, { surface: 0, density: 1000 });
  const spring = api.addSpring(world, { a: ball, b: ball2, stiffness: 10 });
  const emitter = api.addEmitter(world, { position: [0, 3], rate: 10 });
  const stale = api.addBody(world, { position: [7, 7], radius: 0.2 });
  api.removeBody(world, stale);
  const fresh = api.addBody(world, { position: [8, 8], radius: 0.3, mass: 3 });
  const addBox = fn('addBox') as ((w: World, o: object) => number) | undefined;
  const box = addBox ? addBox(world, { position: [-3, 3], halfExtents: [0.5, 0.5] }) : 0;
  return { world, ball, ball2, particle, segment, plane, electric, magnetic, fluid, spring, emitter, stale, fresh, box };
}

/** Which entities a function is for; the first is the one valid calls use. */
type Kind = 'body' | 'emitter' | 'any' | 'electric' | 'magnetic' | 'fluid' | 'spring' | 'shape';

const wrongKinds: Record<Kind, Array<keyof Fixture>> = {
  body: ['electric', 'segment', 'spring', 'emitter'],
  emitter: ['ball', 'magnetic'],
  any: [],
  electric: ['ball', 'magnetic'],
  magnetic: ['ball', 'electric'],
  fluid: ['ball', 'electric'],
  spring: ['ball', 'segment'],
  shape: ['ball', 'electric', 'spring'],
};
const validEntity: Record<Kind, keyof Fixture> = {
  body: 'ball',
  emitter: 'emitter',
  any: 'ball',
  electric: 'electric',
  magnetic: 'magnetic',
  fluid: 'fluid',
  spring: 'spring',
  shape: 'box',
};

/** One function taking (world, entity, arg). */
interface EntityFn {
  name: string;
  kind: Kind;
  /** A valid argument (options object, vector, number) or undefined for none. */
  arg?: unknown;
  /** Calls the function; default fn(world, entity, arg). */
  call?: (f: Fn, world: World, e: number, arg: unknown) => unknown;
  /** The argument is an options object that must be given. */
  options?: boolean;
  /** Keys of the options that must be booleans. */
  booleans?: string[];
  /** Wrong kinds to try instead of the kind's usual ones (e.g. setMaterial accepts segments). */
  wrong?: Array<keyof Fixture>;
}

const entityFns: EntityFn[] = [
  { name: 'removeBody', kind: 'any', call: (f, w, e) => (f as never as (w: World, e: number) => void)(w, e) },
  { name: 'setMass', kind: 'body', arg: 2 },
  { name: 'setMaterial', kind: 'body', arg: { restitution: 0.5 }, options: true, wrong: ['electric', 'spring', 'emitter'] },
  { name: 'setRadius', kind: 'body', arg: 0.3 },
  { name: 'setPosition', kind: 'body', arg: [1, 2], wrong: ['electric', 'segment', 'spring'] },
  { name: 'setVelocity', kind: 'body', arg: [1, 0], wrong: ['electric', 'segment', 'spring'] },
  { name: 'applyImpulse', kind: 'body', arg: [1, 0] },
  { name: 'setAngularVelocity', kind: 'body', arg: 1 },
  { name: 'setOrientation', kind: 'body', arg: 0.5 },
  { name: 'setInertia', kind: 'body', arg: 0.2 },
  { name: 'applyForceAtPoint', kind: 'body', call: (f, w, e) => (f as never as (...a: unknown[]) => void)(w, e, [1, 0], [0, 0]) },
  { name: 'applyImpulseAtPoint', kind: 'body', call: (f, w, e) => (f as never as (...a: unknown[]) => void)(w, e, [1, 0], [0, 0]) },
  { name: 'spinAngularMomentum', kind: 'body', call: (f, w, e) => (f as never as (...a: unknown[]) => void)(w, e) },
  { name: 'spinKineticEnergy', kind: 'body', call: (f, w, e) => (f as never as (...a: unknown[]) => void)(w, e) },
  { name: 'setAngularDamping', kind: 'body', arg: 0.1 },
  { name: 'setGravityScale', kind: 'body', arg: 0.5 },
  { name: 'enableMutualGravity', kind: 'body', call: (f, w, e) => (f as never as (...a: unknown[]) => void)(w, e) },
  { name: 'setAttractor', kind: 'body', arg: { mass: 10 }, options: true },
  { name: 'setCharge', kind: 'body', arg: 1 },
  { name: 'setCentralForce', kind: 'body', arg: { centre: [0, 0], k: -1, n: 2 }, options: true },
  { name: 'setDrag', kind: 'body', arg: { linear: 0.1 }, options: true },
  { name: 'setLift', kind: 'body', arg: { k: 0.1 }, options: true },
  { name: 'setBuoyancy', kind: 'body', arg: { shape: 'ball', radius: 0.5 }, options: true },
  { name: 'setDrivingForce', kind: 'body', arg: { amplitude: [1, 0], omega: 1 }, options: true },
  { name: 'setRandomForce', kind: 'body', arg: { magnitude: 1, correlationTime: 1 }, options: true },
  { name: 'setThrust', kind: 'body', arg: { exhaustVelocity: 10, massFlowRate: 0.1, fuel: 0.5, direction: [0, 1] }, options: true },
  { name: 'setVortex', kind: 'body', arg: { centre: [0, 0], k: 1 }, options: true },
  { name: 'wakeBody', kind: 'body', call: (f, w, e) => (f as never as (...a: unknown[]) => void)(w, e) },
  { name: 'isSleeping', kind: 'body', call: (f, w, e) => (f as never as (...a: unknown[]) => void)(w, e) },
  { name: 'setEmitter', kind: 'emitter', arg: { rate: 5 }, options: true, booleans: ['enabled'] },
  { name: 'burst', kind: 'emitter', arg: 3 },
  { name: 'emitNow', kind: 'emitter', arg: 2 },
  { name: 'setEmitterEnabled', kind: 'emitter', arg: false },
  { name: 'setEmitterRate', kind: 'emitter', arg: 5 },
  { name: 'setElectricField', kind: 'electric', arg: { field: [0, 1] }, options: true },
  { name: 'setMagneticField', kind: 'magnetic', arg: { field: -1 }, options: true },
  { name: 'setFluidRegion', kind: 'fluid', arg: { surface: 1 }, options: true },
  { name: 'setSpring', kind: 'spring', arg: { stiffness: 5 }, options: true, booleans: ['oneSided'] },
  {
    name: 'addShape',
    kind: 'body',
    arg: { type: 'circle', radius: 0.5 },
    options: true,
    booleans: ['sensor'],
    wrong: ['electric', 'segment', 'spring', 'emitter'],
  },
  { name: 'shapesOf', kind: 'body', call: (f, w, e) => (f as never as (...a: unknown[]) => void)(w, e) },
  { name: 'updateMassFromShapes', kind: 'body', call: (f, w, e) => (f as never as (...a: unknown[]) => void)(w, e) },
  { name: 'setShapeFilter', kind: 'shape', arg: { category: 2 }, options: true },
];

/** Functions taking (world, options) (or (options) for createPhysicsWorld). */
interface OptionsFn {
  name: string;
  /** A valid options object (entity fields are filled from the fixture). */
  valid: (fx: Fixture) => Record<string, unknown>;
  /** Whether a missing options object is documented as meaning "all defaults". */
  optional?: boolean;
  booleans?: string[];
  /** Keys of the options that hold entities, with the kind they must be. */
  entities?: Array<[string, Kind]>;
  /** Keys whose documented meaning includes null (a joint's `a: null` is the world). */
  nullable?: string[];
  call?: (f: Fn, world: World, options: unknown) => unknown;
}

const optionsFns: OptionsFn[] = [
  {
    name: 'createPhysicsWorld',
    valid: () => ({ capacity: 8 }),
    optional: true,
    booleans: ['interpolation', 'sleep'],
    call: (f, _w, o) => (f as never as (o: unknown) => unknown)(o),
  },
  { name: 'addBody', valid: () => ({ radius: 0.5, mass: 1 }), optional: true, booleans: ['static', 'kinematic', 'rotates'] },
  { name: 'addParticle', valid: () => ({ position: [1, 1] }), optional: true },
  { name: 'addSegment', valid: () => ({ a: [0, 0], b: [1, 1] }) },
  { name: 'addPlane', valid: () => ({ normal: [0, 1] }) },
  { name: 'setBoundary', valid: () => ({ min: [0, 0], max: [10, 10] }) },
  { name: 'addElectricField', valid: () => ({ field: [1, 0] }) },
  { name: 'addMagneticField', valid: () => ({ field: 1 }) },
  { name: 'addFluidRegion', valid: () => ({ surface: 0, density: 1000 }) },
  {
    name: 'addSpring',
    valid: (fx) => ({ a: fx.ball, b: fx.ball2, stiffness: 1 }),
    booleans: ['oneSided'],
    entities: [
      ['a', 'body'],
      ['b', 'body'],
    ],
  },
  { name: 'addEmitter', valid: () => ({ position: [0, 0], rate: 1 }), optional: true, booleans: ['enabled'] },
  { name: 'addEmitter', valid: (fx) => ({ attachTo: fx.ball2, rate: 1 }), optional: true, entities: [['attachTo', 'body']] },
  { name: 'setGravitation', valid: () => ({ constant: 1 }) },
  { name: 'setElectrostatics', valid: () => ({ constant: 1 }) },
  { name: 'setWind', valid: () => ({ velocity: [1, 0] }) },
  {
    name: 'createFixedStepLoop',
    valid: () => ({ dt: 0.01, step: () => {} }),
    call: (f, _w, o) => (f as never as (o: unknown) => unknown)(o),
  },
  { name: 'createRecorder', valid: () => ({ quantities: { energy: api.kineticEnergy }, every: 1 }) },
  { name: 'addBox', valid: () => ({ halfExtents: [0.5, 0.5], density: 2 }), booleans: ['static', 'kinematic', 'rotates', 'sensor'] },
  { name: 'createRope', valid: () => ({ start: [0, 5], end: [1, 5], segments: 2 }), booleans: ['pinStart', 'pinEnd', 'slack'] },
  { name: 'createCloth', valid: () => ({ columns: 2, rows: 2, mass: 1 }), optional: true },
  ...(['addDistanceJoint', 'addRevoluteJoint', 'addWeldJoint', 'addPrismaticJoint', 'addWheelJoint'] as const).map(
    (name): OptionsFn => ({
      name,
      valid: (fx) => ({ a: fx.ball, b: fx.ball2, breakForce: 100 }),
      booleans: ['collideConnected'],
      nullable: ['a'],
      entities: [
        ['a', 'body'],
        ['b', 'body'],
      ],
    }),
  ),
  { name: 'addMouseJoint', valid: (fx) => ({ b: fx.ball2, hertz: 5 }), entities: [['b', 'body']] },
  {
    name: 'addSystem',
    valid: () => ({}),
    optional: true,
    call: (f, w, o) => (f as never as (...a: unknown[]) => unknown)(w, 'forces', () => {}, o),
  },
];

/** What a case expects: a clear error from `expectFrom` (the function the user called). */
export interface Case {
  /** Short label: function and what is wrong. */
  label: string;
  /** The function the user called, which the error must name. */
  expectFrom: string;
  /** Extra pattern the message must match (e.g. /removed entity/). */
  pattern?: RegExp;
  run: (fx: Fixture) => unknown;
}

const BAD_BOOLEANS: unknown[] = ['false', 'yes', 1, 0, null];
const NOT_ENTITIES: unknown[] = [0, -1, 1.5, '1', NaN, 2 ** 25 + 60, null, undefined];

export function buildCases(): Case[] {
  const cases: Case[] = [];
  for (const d of entityFns) {
    const f = fn(d.name);
    if (!f) continue;
    const call = d.call ?? ((g: Fn, w: World, e: number, a: unknown) => (g as never as (...x: unknown[]) => unknown)(w, e, a));
    const valid = validEntity[d.kind];
    cases.push({
      label: `${d.name}: a removed entity whose slot was recycled`,
      expectFrom: d.name,
      pattern: /removed entity/,
      run: (fx) => call(f, fx.world, fx.stale, d.arg),
    });
    for (const bad of NOT_ENTITIES) {
      cases.push({ label: `${d.name}: entity ${String(bad)}`, expectFrom: d.name, run: (fx) => call(f, fx.world, bad as number, d.arg) });
    }
    for (const k of d.wrong ?? wrongKinds[d.kind]) {
      cases.push({
        label: `${d.name}: ${k} entity where ${d.kind} is meant`,
        expectFrom: d.name,
        pattern: /must be an? /,
        run: (fx) => call(f, fx.world, fx[k] as number, d.arg),
      });
    }
    if (d.options) {
      cases.push({
        label: `${d.name}: options missing`,
        expectFrom: d.name,
        pattern: /must be an object/,
        run: (fx) => call(f, fx.world, fx[valid] as number, undefined),
      });
      cases.push({
        label: `${d.name}: options null`,
        expectFrom: d.name,
        pattern: /must be an object/,
        run: (fx) => call(f, fx.world, fx[valid] as number, null),
      });
      cases.push({ label: `${d.name}: options a string`, expectFrom: d.name, run: (fx) => call(f, fx.world, fx[valid] as number, 'rate') });
      cases.push({
        label: `${d.name}: unknown option`,
        expectFrom: d.name,
        pattern: /unknown option/,
        run: (fx) => call(f, fx.world, fx[valid] as number, { ...(d.arg as object), bogus: 1 }),
      });
      for (const key of Object.keys(d.arg as object)) {
        cases.push({
          label: `${d.name}: ${key} null`,
          expectFrom: d.name,
          pattern: new RegExp(key),
          run: (fx) => call(f, fx.world, fx[valid] as number, { ...(d.arg as object), [key]: null }),
        });
      }
      for (const key of d.booleans ?? []) {
        for (const bad of BAD_BOOLEANS) {
          cases.push({
            label: `${d.name}: ${key} ${JSON.stringify(bad)}`,
            expectFrom: d.name,
            pattern: new RegExp(key),
            run: (fx) => call(f, fx.world, fx[valid] as number, { [key]: bad }),
          });
        }
      }
    } else if (d.arg !== undefined) {
      cases.push({
        label: `${d.name}: argument missing`,
        expectFrom: d.name,
        run: (fx) => call(f, fx.world, fx[valid] as number, undefined),
      });
      cases.push({ label: `${d.name}: argument null`, expectFrom: d.name, run: (fx) => call(f, fx.world, fx[valid] as number, null) });
      if (typeof d.arg === 'boolean') {
        for (const bad of BAD_BOOLEANS) {
          cases.push({
            label: `${d.name}: ${JSON.stringify(bad)} for a boolean`,
            expectFrom: d.name,
            run: (fx) => call(f, fx.world, fx[valid] as number, bad),
          });
        }
      }
    }
  }
  for (const d of optionsFns) {
    const f = fn(d.name);
    if (!f) continue;
    const call = d.call ?? ((g: Fn, w: World, o: unknown) => (g as never as (...x: unknown[]) => unknown)(w, o));
    if (!d.optional)
      cases.push({
        label: `${d.name}: options missing`,
        expectFrom: d.name,
        pattern: /must be an object/,
        run: (fx) => call(f, fx.world, undefined),
      });
    cases.push({
      label: `${d.name}: options null`,
      expectFrom: d.name,
      pattern: /must be an object/,
      run: (fx) => call(f, fx.world, null),
    });
    cases.push({ label: `${d.name}: options a number`, expectFrom: d.name, run: (fx) => call(f, fx.world, 3) });
    cases.push({
      label: `${d.name}: unknown option`,
      expectFrom: d.name,
      pattern: /unknown option/,
      run: (fx) => call(f, fx.world, { ...d.valid(fx), bogus: 1 }),
    });
    const keys = Object.keys(d.valid(makeFixtureKeysOnly()));
    for (const key of keys) {
      if (d.nullable?.includes(key)) continue;
      cases.push({
        label: `${d.name}: ${key} null`,
        expectFrom: d.name,
        pattern: new RegExp(key),
        run: (fx) => call(f, fx.world, { ...d.valid(fx), [key]: null }),
      });
    }
    for (const key of d.booleans ?? []) {
      for (const bad of BAD_BOOLEANS) {
        cases.push({
          label: `${d.name}: ${key} ${JSON.stringify(bad)}`,
          expectFrom: d.name,
          pattern: new RegExp(key),
          run: (fx) => call(f, fx.world, { ...d.valid(fx), [key]: bad }),
        });
      }
    }
    for (const [key, kind] of d.entities ?? []) {
      cases.push({
        label: `${d.name}: ${key} a removed entity`,
        expectFrom: d.name,
        pattern: /removed entity/,
        run: (fx) => call(f, fx.world, { ...d.valid(fx), [key]: fx.stale }),
      });
      for (const k of wrongKinds[kind]) {
        cases.push({
          label: `${d.name}: ${key} a ${k} entity`,
          expectFrom: d.name,
          pattern: /must be an? /,
          run: (fx) => call(f, fx.world, { ...d.valid(fx), [key]: fx[k] }),
        });
      }
    }
  }
  // Nested option objects and entity-valued options of the emitter functions.
  const addEmitter = fn('addEmitter'),
    setEmitter = fn('setEmitter');
  const e2 = (g: Fn | undefined) => g as never as (...x: unknown[]) => unknown;
  if (addEmitter) {
    cases.push({
      label: 'addEmitter: particle null',
      expectFrom: 'addEmitter',
      pattern: /particle/,
      run: (fx) => e2(addEmitter)(fx.world, { particle: null }),
    });
    cases.push({
      label: 'addEmitter: onDeath null',
      expectFrom: 'addEmitter',
      pattern: /onDeath/,
      run: (fx) => e2(addEmitter)(fx.world, { onDeath: null }),
    });
    cases.push({
      label: 'addEmitter: shape "toString"',
      expectFrom: 'addEmitter',
      pattern: /shape/,
      run: (fx) => e2(addEmitter)(fx.world, { shape: 'toString' }),
    });
    cases.push({
      label: 'addEmitter: onDeath.emitter a removed entity',
      expectFrom: 'addEmitter',
      pattern: /removed entity/,
      run: (fx) => e2(addEmitter)(fx.world, { onDeath: { emitter: fx.stale, count: 1, maxGeneration: 1 } }),
    });
    cases.push({
      label: 'addEmitter: onDeath.emitter a body',
      expectFrom: 'addEmitter',
      pattern: /must be an? /,
      run: (fx) => e2(addEmitter)(fx.world, { onDeath: { emitter: fx.ball, count: 1, maxGeneration: 1 } }),
    });
    cases.push({
      label: 'addEmitter: particle.radius null',
      expectFrom: 'addEmitter',
      pattern: /radius/,
      run: (fx) => e2(addEmitter)(fx.world, { particle: { radius: null } }),
    });
  }
  if (setEmitter) {
    cases.push({
      label: 'setEmitter: shape "toString"',
      expectFrom: 'setEmitter',
      pattern: /shape/,
      run: (fx) => e2(setEmitter)(fx.world, fx.emitter, { shape: 'toString' }),
    });
    cases.push({
      label: 'setEmitter: onDeath.emitter a removed entity',
      expectFrom: 'setEmitter',
      pattern: /removed entity/,
      run: (fx) => e2(setEmitter)(fx.world, fx.emitter, { onDeath: { emitter: fx.stale, count: 1, maxGeneration: 1 } }),
    });
    cases.push({
      label: 'setEmitter: particle null',
      expectFrom: 'setEmitter',
      pattern: /particle/,
      run: (fx) => e2(setEmitter)(fx.world, fx.emitter, { particle: null }),
    });
    cases.push({
      label: 'setEmitter: a bad field after a good one',
      expectFrom: 'setEmitter',
      pattern: /spread/,
      run: (fx) => e2(setEmitter)(fx.world, fx.emitter, { rate: 99, spread: 9 }),
    });
  }
  const setBuoyancy = fn('setBuoyancy');
  if (setBuoyancy)
    cases.push({
      label: 'setBuoyancy: shape "toString"',
      expectFrom: 'setBuoyancy',
      pattern: /shape/,
      run: (fx) => e2(setBuoyancy)(fx.world, fx.ball, { shape: 'toString', radius: 1 }),
    });
  const setDrag = fn('setDrag');
  if (setDrag)
    cases.push({
      label: 'setDrag: a bad quadratic after a good linear',
      expectFrom: 'setDrag',
      pattern: /quadratic/,
      run: (fx) => e2(setDrag)(fx.world, fx.ball, { linear: 1, quadratic: -1 }),
    });
  const setInertia = fn('setInertia');
  if (setInertia)
    cases.push({
      label: 'setInertia: -1 on a body without rotation',
      expectFrom: 'setInertia',
      pattern: /inertia/,
      run: (fx) => e2(setInertia)(fx.world, fx.particle, -1),
    });
  const setAngularVelocity = fn('setAngularVelocity');
  if (setAngularVelocity)
    cases.push({
      label: 'setAngularVelocity: NaN on a body without rotation',
      expectFrom: 'setAngularVelocity',
      pattern: /angularVelocity/,
      run: (fx) => e2(setAngularVelocity)(fx.world, fx.particle, NaN),
    });
  const addBody = fn('addBody');
  if (addBody) {
    cases.push({
      label: 'addBody: a bad inertia',
      expectFrom: 'addBody',
      pattern: /inertia/,
      run: (fx) => e2(addBody)(fx.world, { radius: 1, inertia: -1 }),
    });
    cases.push({
      label: 'addBody: principal moments in 2D',
      expectFrom: 'addBody',
      pattern: /inertia/,
      run: (fx) => e2(addBody)(fx.world, { radius: 1, inertia: [1, 1, 1] }),
    });
  }
  return cases;
}

/** A fixture stand-in with entity fields only, for listing option keys without making a world. */
function makeFixtureKeysOnly(): Fixture {
  return { ball: 1, ball2: 2 } as Fixture;
}

/** The world's observable state: live entities, their components and every store, counters and settings. */
export function snapshot(world: World): string {
  const c = world.components as unknown as Record<string, Record<string, ArrayLike<number>> | object>;
  const parts: string[] = [];
  parts.push(
    `alive ${world.entityIndex.aliveCount} dense ${Array.from(world.entityIndex.dense.slice(0, world.entityIndex.aliveCount)).join(',')}`,
  );
  parts.push(`stamps ${Array.from(world.spawnStamp).join(',')}`);
  for (const name of Object.keys(c)) {
    const store = c[name]!;
    const members: number[] = [];
    for (let e = 1; e <= world.capacity; e++) if (hasComponent(world, e, store)) members.push(e);
    parts.push(`${name} on ${members.join(',')}`);
    for (const [key, arr] of Object.entries(store)) {
      if (ArrayBuffer.isView(arr)) {
        const a = arr as unknown as ArrayLike<number>;
        const vals: string[] = [];
        for (const e of members) vals.push(String(a[e]));
        parts.push(`${name}.${key} ${vals.join(',')}`);
      }
    }
  }
  parts.push(`gravity ${Array.from(world.gravity).join(',')} dt ${world.dt} substeps ${world.substeps}`);
  parts.push(`boundary ${JSON.stringify(world.collision.boundary)}`);
  parts.push(`laws ${JSON.stringify(world.laws, (_k, v) => (ArrayBuffer.isView(v) ? Array.from(v as unknown as ArrayLike<number>) : v))}`);
  parts.push(`rest ${Array.from(world.collision.sleep.restTime).join(',')}`);
  return parts.join('\n');
}

/** How a case came out: a clear error naming the function, silent acceptance, or a crash (any other throw). */
export type Outcome = 'clear' | 'silent' | 'crash';

export function classify(c: Case, error: unknown): Outcome {
  if (error === undefined) return 'silent';
  if (!(error instanceof TypeError || error instanceof RangeError)) return 'crash';
  if (!error.message.startsWith(`${c.expectFrom}: `)) return 'crash';
  if (/Cannot read|is not a function|is not iterable|\(reading /.test(error.message)) return 'crash';
  return 'clear';
}
