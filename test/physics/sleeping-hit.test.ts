import {
  addBody,
  addBox,
  createPhysicsWorld,
  isSleeping,
  type PhysicsWorld,
  pinClothPoint,
  setVelocity,
  slotOf,
  step,
  stepMany,
} from '@bitphysics/physics';
import RAPIER from '@dimforge/rapier2d-compat';
import { describe, expect, test } from 'vitest';

// A body that a moving body reaches while it sleeps must take part in that step's contact solve: if it
// is held still as geometry for the step, the hit's momentum is lost (a sliding box stops dead against
// a sleeping one, or bounces off it).

type Kind = 'box' | 'ball';

/** A 1 kg body of `kind` (a 1 m box or a ball of radius 0.5 m), frictionless, resting on the floor at x. */
function body(world: PhysicsWorld, kind: Kind, x: number, restitution: number): number {
  if (kind === 'box') return addBox(world, { position: [x, 0.5], halfExtents: [0.5, 0.5], density: 1, friction: 0, restitution });
  return addBody(world, { position: [x, 0.5], radius: 0.5, mass: 1, friction: 0, restitution });
}

/** Body `mover` sent at 2 m/s along a frictionless floor into `target`, asleep 2 m away; x velocities after. */
function hit(mover: Kind, target: Kind, restitution: number) {
  const world = createPhysicsWorld({ gravity: [0, -9.81] });
  addBox(world, { position: [0, -0.5], halfExtents: [50, 0.5], static: true, friction: 0, restitution });
  const a = body(world, mover, 0, restitution);
  const b = body(world, target, 3, restitution);
  stepMany(world, 180); // both settle and fall asleep
  const slept = isSleeping(world, b);
  setVelocity(world, a, [2, 0]);
  stepMany(world, 120); // the hit comes after about 1 s
  const vx = world.components.Velocity.x;
  return { slept, va: vx[slotOf(a)]!, vb: vx[slotOf(b)]! };
}

describe('a hit on a sleeping body keeps its momentum', () => {
  const pairs: [Kind, Kind][] = [
    ['box', 'box'],
    ['ball', 'box'],
    ['box', 'ball'],
    ['ball', 'ball'],
  ];
  for (const [mover, target] of pairs) {
    for (const e of [0, 0.5]) {
      test(`${mover} into a sleeping ${target}, restitution ${e}`, () => {
        const r = hit(mover, target, e);
        expect(r.slept).toBe(true);
        // No horizontal force but the hit's (frictionless floor): momentum 1 kg * 2 m/s is kept; the
        // tolerance is the solver's (soft contacts, speculative margin), far below the 2 kg m/s a
        // sleeper held still loses.
        expect(Math.abs(r.va + r.vb - 2)).toBeLessThan(1e-3);
        // The target takes at least the share of a perfectly inelastic hit (1 m/s), and the mover
        // does not bounce back off it.
        expect(r.vb).toBeGreaterThan(1 - 1e-3);
        expect(r.va).toBeGreaterThan(-1e-3);
      });
    }
  }
});

// A row of dominoes that has fallen asleep, the first tipped over: the time for the wave to reach the
// last one, against rapier2d (default parameters, same scene) and against our own world without sleep.
const N = 20,
  HX = 0.1,
  HY = 1,
  GAP = 1.2,
  SPIN = -1.5,
  FALLEN = 0.5; // rad: the last domino counts as falling once tilted this far

function dominoesOurs(sleep: boolean): { asleep: boolean; t: number } {
  const w = createPhysicsWorld({ gravity: [0, -9.81], sleep });
  addBox(w, { position: [10, -0.5], halfExtents: [40, 0.5], static: true, friction: 0.6 });
  const d: number[] = [];
  for (let i = 0; i < N; i++) d.push(addBox(w, { position: [i * GAP, HY], halfExtents: [HX, HY], density: 1, friction: 0.6 }));
  stepMany(w, 120);
  const asleep = d.every((e) => isSleeping(w, e));
  setVelocity(w, d[0]!, [0, 0]);
  w.components.AngularVelocity.z[slotOf(d[0]!)] = SPIN;
  const A = w.components.Angle.value,
    last = slotOf(d[N - 1]!);
  for (let i = 1; i <= 900; i++) {
    step(w);
    if (Math.abs(A[last]!) > FALLEN) return { asleep, t: i / 60 };
  }
  return { asleep, t: Infinity };
}

function dominoesRapier(): number {
  const w = new RAPIER.World({ x: 0, y: -9.81 });
  w.createCollider(
    RAPIER.ColliderDesc.cuboid(40, 0.5).setTranslation(10, -0.5).setFriction(0.6),
    w.createRigidBody(RAPIER.RigidBodyDesc.fixed()),
  );
  const d: InstanceType<typeof RAPIER.RigidBody>[] = [];
  for (let i = 0; i < N; i++) {
    const b = w.createRigidBody(RAPIER.RigidBodyDesc.dynamic().setTranslation(i * GAP, HY));
    w.createCollider(RAPIER.ColliderDesc.cuboid(HX, HY).setDensity(1).setFriction(0.6), b);
    d.push(b);
  }
  for (let i = 0; i < 120; i++) w.step();
  d[0]!.setAngvel(SPIN, true);
  try {
    for (let i = 1; i <= 900; i++) {
      w.step();
      if (Math.abs(d[N - 1]!.rotation()) > FALLEN) return i / 60;
    }
    return Infinity;
  } finally {
    w.free();
  }
}

test('a row of sleeping dominoes falls in the time rapier2d and our world without sleep take', async () => {
  await RAPIER.init();
  const peer = dominoesRapier();
  const awake = dominoesOurs(false);
  const slept = dominoesOurs(true);
  expect(slept.asleep).toBe(true);
  // Sleeping must not change the dynamics of a hit: same time as without sleep, to a step or two.
  expect(Math.abs(slept.t - awake.t)).toBeLessThanOrEqual(2 / 60);
  // Two engines with different solvers: within 10 % of rapier2d's time (ours was 50 % slower when
  // each domino was held still for the step it was hit in).
  expect(Math.abs(slept.t - peer) / peer).toBeLessThan(0.1);
});

// A kinematic body is driven by its velocity alone: a ball pinned (made kinematic) while it sleeps keeps
// its Sleeping tag, and a ball rolling into it must not wake it into a dynamic body (which was given
// the gravity step of a woken body and then, kinematic again, sank through the floor at g h per step).
test('a sleeping ball pinned in place stays where it is pinned when a ball rolls into it', () => {
  const world = createPhysicsWorld({ gravity: [0, -9.81] });
  addBox(world, { position: [0, -0.5], halfExtents: [50, 0.5], static: true, friction: 0 });
  const a = body(world, 'ball', 0, 0);
  const b = body(world, 'ball', 3, 0);
  stepMany(world, 180);
  expect(isSleeping(world, b)).toBe(true);
  const p = world.components.Position,
    s = slotOf(b);
  const at = [p.x[s]!, p.y[s]!];
  pinClothPoint(world, b, at);
  setVelocity(world, a, [2, 0]);
  stepMany(world, 120); // the hit comes after about 1 s
  // Exact: a kinematic body at rest is not moved by anything.
  expect([p.x[s], p.y[s]]).toEqual(at);
  expect(world.components.Velocity.y[s]).toBe(0);
  // The rolling ball reached it and was stopped (restitution 0): it ends at most 1 m (two radii) short.
  expect(p.x[slotOf(a)]!).toBeGreaterThan(at[0]! - 1 - 1e-3);
  expect(world.components.Velocity.x[slotOf(a)]!).toBeLessThan(0.1);
});
