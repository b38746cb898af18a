import { describe, expect, it } from 'vitest';
import {
  addBody,
  addBox,
  addShape,
  createPhysicsWorld,
  type PhysicsWorld,
  setMass,
  setShapeFilter,
  shapesOf,
  step,
} from '../../packages/physics/src/index.js';
import { slotOf } from '../../packages/physics/src/world/handles.js';

const G = 9.81;

/** A static incline: a long box turned by `theta`, its top surface through the origin. Returns where a box of half height hy rests, s m along the slope. */
function incline(world: PhysicsWorld, theta: number, friction: number): (s: number, hy: number) => [number, number] {
  const nx = -Math.sin(theta),
    ny = Math.cos(theta),
    tx = Math.cos(theta),
    ty = Math.sin(theta);
  addBox(world, { position: [-0.5 * nx, -0.5 * ny], halfExtents: [40, 0.5], angle: theta, static: true, friction });
  return (s, hy) => [s * tx + hy * nx, s * ty + hy * ny];
}

function along(world: PhysicsWorld, e: number, theta: number): { s: number; v: number } {
  const c = world.components;
  const tx = Math.cos(theta),
    ty = Math.sin(theta);
  return { s: c.Position.x[e]! * tx + c.Position.y[e]! * ty, v: c.Velocity.x[e]! * tx + c.Velocity.y[e]! * ty };
}

describe('boxes on an incline (Coulomb friction)', () => {
  it('slides with a = g (sin theta - mu cos theta)', () => {
    const theta = Math.PI / 6,
      mu = 0.3;
    const world = createPhysicsWorld({ gravity: [0, -G], sleep: false });
    const at = incline(world, theta, mu);
    const box = slotOf(addBox(world, { position: at(0, 0.25), angle: theta, halfExtents: [0.25, 0.25], friction: mu }));
    for (let i = 0; i < 30; i++) step(world); // settle onto the slope, then measure over 1 s
    const a0 = along(world, box, theta);
    for (let i = 0; i < 60; i++) step(world);
    const a1 = along(world, box, theta);
    const expected = -G * (Math.sin(theta) - mu * Math.cos(theta)); // down the slope: negative s
    // Velocity change over exactly 1 s. 1% covers the soft contact's settling (no angle error: the box stays flat).
    expect((a1.v - a0.v) / 1).toBeCloseTo(expected, 1);
    expect(Math.abs(a1.v - a0.v - expected) / Math.abs(expected)).toBeLessThan(0.01);
  });
  it('static friction holds it where kinetic friction alone would not (mu_k < tan theta < mu_s)', () => {
    // tan 20 deg = 0.364: with mu_k = 0.3 alone it would slide at g (sin - mu_k cos) = 0.59 m/s^2, 1.2 m in 2 s.
    const theta = (20 * Math.PI) / 180,
      muK = 0.3,
      muS = 0.5;
    const world = createPhysicsWorld({ gravity: [0, -G] });
    const nx = -Math.sin(theta),
      ny = Math.cos(theta);
    addBox(world, {
      position: [-0.5 * nx, -0.5 * ny],
      halfExtents: [40, 0.5],
      angle: theta,
      static: true,
      friction: muK,
      staticFriction: muS,
    });
    const box = slotOf(
      addBox(world, { position: [0.25 * nx, 0.25 * ny], angle: theta, halfExtents: [0.25, 0.25], friction: muK, staticFriction: muS }),
    );
    for (let i = 0; i < 120; i++) step(world);
    // Sequential impulses let a resting box creep a few mm/s until it sleeps; 1 cm in 2 s is far
    // below the 1.2 m of a slide.
    expect(Math.abs(along(world, box, theta).s)).toBeLessThan(0.01);
  });
  it('a box at rest on a slope below its friction angle stays put: within 1 mm over 600 steps, awake', () => {
    // tan 20 deg = 0.36 < mu = 0.6: static friction holds it exactly (Coulomb). Sleeping is off, so the
    // solver must hold it every step; before the manifold rows marked their bodies as pushed, each
    // step's free-flight correction dropped it 0.34 mm and it crept 35 mm in 600 steps.
    const theta = (20 * Math.PI) / 180,
      mu = 0.6;
    const world = createPhysicsWorld({ gravity: [0, -G], sleep: false });
    const at = incline(world, theta, mu);
    const box = slotOf(addBox(world, { position: at(0, 0.25), angle: theta, halfExtents: [0.25, 0.25], friction: mu }));
    for (let i = 0; i < 10; i++) step(world); // the soft contact settles (tens of micrometres)
    const s0 = along(world, box, theta).s;
    for (let i = 0; i < 600; i++) step(world);
    expect(Math.abs(along(world, box, theta).s - s0)).toBeLessThan(1e-3);
    expect(Math.abs(world.components.Angle.value[box]! - theta)).toBeLessThan(1e-3);
  });
  it('a box of width w and height h tips when tan theta > w / h, and stands below', () => {
    // w / h = 0.5: tips beyond 26.57 degrees; friction 1.5 keeps it from sliding first.
    const run = (deg: number): number => {
      const theta = (deg * Math.PI) / 180;
      const world = createPhysicsWorld({ gravity: [0, -G], sleep: false });
      const at = incline(world, theta, 1.5);
      const box = slotOf(addBox(world, { position: at(0, 0.5), angle: theta, halfExtents: [0.25, 0.5], friction: 1.5 }));
      for (let i = 0; i < 180; i++) step(world);
      return Math.abs(world.components.Angle.value[box]! - theta);
    };
    expect(run(24)).toBeLessThan(0.01);
    expect(run(29)).toBeGreaterThan(0.5);
  });
});

describe('impacts', () => {
  it('a box dropped on its corner keeps its angular momentum about the corner through the impact', () => {
    // Inelastic, sticking impact at the corner P: the contact impulse acts at P, so L_P is conserved
    // across it; only gravity's torque about P over the impact step changes it (m g r_x h, counted here).
    const world = createPhysicsWorld({ gravity: [0, -G], sleep: false });
    addBox(world, { position: [0, -0.5], halfExtents: [20, 0.5], static: true, friction: 2 });
    const angle = 0.4,
      hx = 0.5,
      hy = 0.25;
    const box = slotOf(addBox(world, { position: [0, 2], angle, halfExtents: [hx, hy], friction: 2, velocity: [1, 0] }));
    const c = world.components;
    const m = c.Mass.value[box]!,
      I = c.Inertia.value[box]!;
    const lowest = (): [number, number] => {
      const a = c.Angle.value[box]!,
        ca = Math.cos(a),
        sa = Math.sin(a);
      let bx = 0,
        by = Infinity;
      for (const [lx, ly] of [
        [-hx, -hy],
        [hx, -hy],
        [hx, hy],
        [-hx, hy],
      ] as const) {
        const x = c.Position.x[box]! + ca * lx - sa * ly,
          y = c.Position.y[box]! + sa * lx + ca * ly;
        if (y < by) {
          by = y;
          bx = x;
        }
      }
      return [bx, by];
    };
    const LP = (px: number, py: number): number => {
      const rx = c.Position.x[box]! - px,
        ry = c.Position.y[box]! - py;
      return I * c.AngularVelocity.z[box]! + m * (rx * c.Velocity.y[box]! - ry * c.Velocity.x[box]!);
    };
    // Step until the corner is within the last step's travel of the ground, then take the impact step.
    let before = 0,
      px = 0,
      rx = 0;
    for (let i = 0; i < 200; i++) {
      const [x, y] = lowest();
      const vy = c.Velocity.y[box]!;
      if (y + vy * world.dt * 1.5 < 0) {
        px = x;
        before = LP(x, 0);
        rx = c.Position.x[box]! - x;
        break;
      }
      step(world);
    }
    expect(before).not.toBe(0);
    step(world);
    const after = LP(px, 0);
    const gravityTorque = -m * G * rx * world.dt;
    // 5% of |L|: the corner point moves by |v| h within the impact step and the soft contact spreads the impulse.
    expect(Math.abs(after - (before + gravityTorque))).toBeLessThan(0.05 * Math.abs(before));
  });
  it('a pile of boxes with restitution 0 never holds more energy than it started with', () => {
    const world = createPhysicsWorld({ gravity: [0, -G], sleep: false });
    addBox(world, { position: [0, -0.5], halfExtents: [10, 0.5], static: true });
    addBox(world, { position: [-3.5, 5], halfExtents: [0.5, 6], static: true });
    addBox(world, { position: [3.5, 5], halfExtents: [0.5, 6], static: true });
    const boxes: number[] = [];
    for (let i = 0; i < 30; i++) {
      boxes.push(
        slotOf(
          addBox(world, {
            position: [-2 + (i % 5) * 1.0 + 0.1 * (i % 3), 1 + Math.floor(i / 5) * 1.1],
            angle: 0.3 * (i % 4),
            halfExtents: [0.4, 0.3],
          }),
        ),
      );
    }
    const c = world.components;
    const energy = (): number => {
      let e = 0;
      for (const b of boxes) {
        const m = c.Mass.value[b]!;
        e +=
          0.5 * m * (c.Velocity.x[b]! ** 2 + c.Velocity.y[b]! ** 2) +
          0.5 * c.Inertia.value[b]! * c.AngularVelocity.z[b]! ** 2 +
          m * G * c.Position.y[b]!;
      }
      return e;
    };
    const e0 = energy();
    let max = -Infinity;
    for (let i = 0; i < 240; i++) {
      step(world);
      max = Math.max(max, energy());
    }
    // Push-out of overlaps may lift a box by millimetres; 1e-3 of the start energy allows that and nothing more.
    expect(max).toBeLessThan(e0 + 1e-3 * Math.abs(e0));
    expect(energy()).toBeLessThan(e0 - 0.05 * Math.abs(e0)); // and it did fall and settle
  });
  it('a 0.1 m box at 300 m/s does not pass through a 0.05 m wall', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], sleep: false });
    addBox(world, { position: [10, 0], halfExtents: [0.025, 2], static: true });
    const bullet = slotOf(addBox(world, { position: [0, 0.3], halfExtents: [0.05, 0.05], velocity: [300, 0] }));
    for (let i = 0; i < 30; i++) step(world);
    // It stops at the wall's near face (x = 9.975) or bounces back; it is never beyond it.
    expect(world.components.Position.x[bullet]!).toBeLessThan(9.975);
    expect(world.components.Position.x[bullet]!).toBeGreaterThan(9.5);
  });
  it('a 0.1 m box at 300 m/s does not pass through a 0.05 m wall, static or dynamic, at any angle, phase or spin', () => {
    // 5 m a step against 0.15 m of combined thickness. The start distance sets where in a step the box
    // arrives (its phase); at 45 degrees a contact chosen 3.5 m away took the wall's end face for the
    // one it hits and let the box slip over the end. Passing through: the box's centre is ever beyond
    // the wall's far face (in the wall's frame) within the wall's length.
    const passed: string[] = [];
    for (const dynamic of [false, true])
      for (const deg of [-45, 0, 60])
        for (const phase of [0, 0.37])
          for (const spin of [0, 30]) {
            const world = createPhysicsWorld({ gravity: [0, 0], sleep: false, capacity: 8 });
            const wall = slotOf(
              addBox(
                world,
                dynamic
                  ? { position: [10, 0], halfExtents: [0.025, 3], density: 1 }
                  : { position: [10, 0], halfExtents: [0.025, 3], static: true },
              ),
            );
            const a = (deg * Math.PI) / 180,
              back = 5 + 5 * phase;
            const bullet = slotOf(
              addBox(world, {
                position: [9.9 - back * Math.cos(a), 0.3 - back * Math.sin(a)],
                halfExtents: [0.05, 0.05],
                velocity: [300 * Math.cos(a), 300 * Math.sin(a)],
                angularVelocity: spin,
              }),
            );
            const c = world.components;
            for (let i = 0; i < 8; i++) {
              step(world);
              const w = c.Angle.value[wall]!,
                rx = c.Position.x[bullet]! - c.Position.x[wall]!,
                ry = c.Position.y[bullet]! - c.Position.y[wall]!;
              const lx = Math.cos(w) * rx + Math.sin(w) * ry,
                ly = -Math.sin(w) * rx + Math.cos(w) * ry;
              if (lx > 0.025 && Math.abs(ly) < 3) {
                passed.push(`${dynamic ? 'dynamic' : 'static'} ${deg} deg, phase ${phase}, spin ${spin}`);
                break;
              }
            }
          }
    expect(passed).toEqual([]);
  });
  it('a fast box does not pass through a thin dynamic plank at rest', () => {
    // A 0.2 m box at 120 m/s (2 m a step) at a free 0.04 m plank of 1 kg: it hits it and both move on
    // together (restitution 0): momentum 0.04 kg x 120 m/s shared, and the box stays behind the plank.
    const world = createPhysicsWorld({ gravity: [0, 0], sleep: false });
    const plank = slotOf(addBox(world, { position: [5, 0], halfExtents: [0.02, 1], density: 12.5 })); // 0.04 x 2 m: 1 kg
    const box = slotOf(addBox(world, { position: [0, 0], halfExtents: [0.1, 0.1], density: 1, velocity: [120, 0] })); // 0.04 kg
    for (let i = 0; i < 10; i++) step(world);
    const c = world.components;
    expect(c.Position.x[box]!).toBeLessThan(c.Position.x[plank]!);
    expect(c.Velocity.x[plank]!).toBeGreaterThan((0.5 * (0.04 * 120)) / 1.04);
  });
  it('a kinematic platform lifts a box', () => {
    const world = createPhysicsWorld({ gravity: [0, -G], sleep: false });
    const platform = slotOf(addBox(world, { position: [0, 0], halfExtents: [2, 0.25], kinematic: true, velocity: [0, 1] }));
    const box = slotOf(addBox(world, { position: [0, 0.75], halfExtents: [0.5, 0.5] }));
    for (let i = 0; i < 60; i++) step(world);
    const c = world.components;
    // The platform rose 1 m in 1 s; the box rides on it (rests 0.75 m above its centre, within 1 cm).
    expect(c.Position.y[platform]!).toBeCloseTo(1, 9);
    expect(Math.abs(c.Position.y[box]! - c.Position.y[platform]! - 0.75)).toBeLessThan(0.01);
  });
});

describe('kinematic spin', () => {
  it("a box on top of a spinning kinematic disc is carried along at the disc's surface speed (v + w x r)", () => {
    // Disc of radius 1 m spinning at w = 2 rad/s (counter-clockwise): its top moves at w R = 2 m/s to
    // the left. Friction (mu = 1) drags the box from rest up to that speed in about w R / (mu g) = 0.2 s.
    // Without the spin in the contact rows the disc's surface looks still and the box just sits there.
    const world = createPhysicsWorld({ gravity: [0, -G], sleep: false });
    const disc = addBody(world, { position: [0, 0], kinematic: true, rotates: true, angularVelocity: 2 });
    addShape(world, disc, { type: 'circle', radius: 1, friction: 1 });
    const box = slotOf(addBox(world, { position: [0, 1.1], halfExtents: [0.1, 0.1], friction: 1 }));
    for (let i = 0; i < 18; i++) step(world); // 0.3 s
    const c = world.components;
    // Carried left near the surface speed: between 60% and 110% of w R (it has started down the side).
    expect(c.Velocity.x[box]!).toBeLessThan(-0.6 * 2);
    expect(c.Velocity.x[box]!).toBeGreaterThan(-1.1 * 2);
    expect(c.Position.x[box]!).toBeLessThan(-0.2);
    expect(world.components.Angle.value[slotOf(disc)]!).toBeCloseTo(0.6, 9); // the disc turned w t
  });
});

describe('filtering, sensors and events', () => {
  it('category and mask bits, and groups, decide which shapes collide', () => {
    const drop = (a: object, b: object): number => {
      const world = createPhysicsWorld({ gravity: [0, -G], sleep: false });
      addBox(world, { position: [0, 0], halfExtents: [2, 0.5], static: true, ...a });
      const box = slotOf(addBox(world, { position: [0, 1.5], halfExtents: [0.5, 0.5], ...b }));
      for (let i = 0; i < 60; i++) step(world);
      return world.components.Position.y[box]!;
    };
    expect(drop({}, {})).toBeCloseTo(1, 1); // rests on the ground
    expect(drop({ category: 2 }, { mask: 1 })).toBeLessThan(-2); // the box ignores category 2: falls through
    expect(drop({ group: -1 }, { group: -1 })).toBeLessThan(-2); // same negative group: never collide
    expect(drop({ group: 3, category: 2 }, { group: 3, mask: 1 })).toBeCloseTo(1, 1); // same positive group overrides the bits
  });
  it('a sensor reports one begin and one end, and pushes nothing', () => {
    const world = createPhysicsWorld({ gravity: [0, -G], sleep: false });
    const sensor = slotOf(addBox(world, { position: [0, 0], halfExtents: [2, 0.5], static: true, sensor: true }));
    const box = slotOf(addBox(world, { position: [0, 3], halfExtents: [0.25, 0.25] }));
    let begins = 0,
      ends = 0;
    const ev = world.collision.events;
    for (let i = 0; i < 90; i++) {
      step(world);
      for (let k = 0; k < ev.sensorBegin.count; k++) {
        begins++;
        expect(ev.sensorBegin.shapeA[k]).toBe(sensor);
        expect(ev.sensorBegin.bodyB[k]).toBe(box);
      }
      ends += ev.sensorEnd.count;
    }
    expect(begins).toBe(1);
    expect(ends).toBe(1);
    // Free fall through it: v = -g t exactly (semi-implicit Euler), nothing pushed.
    expect(world.components.Velocity.y[box]!).toBeCloseTo(-G * 1.5, 9);
  });
  it('begin touch is reported once per touch, with the approach speed; end when the pair parts', () => {
    const world = createPhysicsWorld({ gravity: [0, -G], sleep: false });
    const ground = slotOf(addBox(world, { position: [0, -0.5], halfExtents: [5, 0.5], static: true }));
    const box = slotOf(addBox(world, { position: [0, 2.5], halfExtents: [0.5, 0.5] }));
    const ev = world.collision.events;
    let begins = 0,
      ends = 0,
      speed = 0;
    for (let i = 0; i < 120; i++) {
      step(world);
      for (let k = 0; k < ev.begin.count; k++) {
        begins++;
        speed = ev.begin.approachSpeed[k]!;
        expect([ev.begin.bodyA[k], ev.begin.bodyB[k]]).toEqual([ground, box]);
        expect(ev.begin.ny[k]).toBeCloseTo(1, 9);
      }
      ends += ev.end.count;
    }
    expect(begins).toBe(1);
    expect(ends).toBe(0);
    // Dropped from 2 m: v = sqrt(2 g h) = 6.26 m/s; one step's gravity (0.16 m/s) either way.
    expect(Math.abs(speed - Math.sqrt(2 * G * 2))).toBeLessThan(G / 60);
    world.components.Velocity.y[box] = 5;
    for (let i = 0; i < 10; i++) {
      step(world);
      ends += ev.end.count;
    }
    expect(ends).toBe(1);
  });
});

describe('shapes: mass, compounds, rolling, bad input', () => {
  it('mass and inertia come from the shapes; a compound moves its centre of mass; setMass overrides', () => {
    const world = createPhysicsWorld({ gravity: [0, -G] });
    const cart = slotOf(addBody(world, { position: [0, 0] }));
    addShape(world, cart, { type: 'box', halfExtents: [1, 0.25], density: 2 }); // 2 x 0.5 m: 2 kg
    const c = world.components;
    expect(c.Mass.value[cart]).toBeCloseTo(2, 12);
    expect(c.Inertia.value[cart]).toBeCloseTo((2 * (4 + 0.25)) / 12, 12);
    // A 0.2 x 2 m mast above (0.4 kg at y = 1.25): centre of mass at y = 0.4 * 1.25 / 2.4.
    const mast = addShape(world, cart, { type: 'box', halfExtents: [0.1, 1], offset: [0, 1.25], density: 1 });
    expect(shapesOf(world, cart)).toEqual([cart, mast]);
    const yc = (0.4 * 1.25) / 2.4;
    expect(c.Mass.value[cart]).toBeCloseTo(2.4, 12);
    expect(c.Position.y[cart]).toBeCloseTo(yc, 12);
    const iMast = (0.4 * (0.04 + 4)) / 12 + 0.4 * (1.25 - yc) ** 2;
    const iCart = (2 * 4.25) / 12 + 2 * yc * yc;
    expect(c.Inertia.value[cart]).toBeCloseTo(iMast + iCart, 12);
    setMass(world, cart, 5);
    expect(c.Mass.value[cart]).toBe(5);
  });
  it('rolling resistance brings a rolling circle to rest; without it, it keeps rolling', () => {
    const roll = (rr: number): number => {
      const world = createPhysicsWorld({ gravity: [0, -G], sleep: false });
      addBox(world, { position: [0, -0.5], halfExtents: [100, 0.5], static: true });
      const ball = slotOf(addBody(world, { position: [0, 0.5], velocity: [3, 0], angularVelocity: -6, rotates: true }));
      addShape(world, ball, { type: 'circle', radius: 0.5, rollingResistance: rr });
      for (let i = 0; i < 240; i++) step(world);
      return Math.abs(world.components.Velocity.x[ball]!);
    };
    expect(roll(0)).toBeGreaterThan(2.9); // rolling without slipping keeps its speed
    expect(roll(0.2)).toBeLessThan(1e-3);
  });
  it('bad shapes are refused with the parameter and value, and change nothing', () => {
    const world = createPhysicsWorld();
    const body = slotOf(addBody(world, { position: [0, 0] }));
    const alive = world.entityIndex.aliveCount;
    expect(() =>
      addShape(world, body, {
        type: 'polygon',
        vertices: [
          [0, 0],
          [1, 0],
        ],
      }),
    ).toThrow('addShape: vertices must hold 3 to 8 points, got 2');
    expect(() =>
      addShape(world, body, {
        type: 'polygon',
        vertices: [
          [0, 0],
          [2, 0],
          [1, 0.5],
          [2, 2],
          [0, 2],
        ],
      }),
    ).toThrow(/addShape: vertices must form a convex polygon, got one that is not convex at \[1,0.5\]/);
    expect(() => addShape(world, body, { type: 'box', halfExtents: [1, 0] })).toThrow('addShape: halfExtents[1] must be > 0, got 0');
    expect(() => addShape(world, body, { type: 'box', halfExtents: [1, 1], density: -1 })).toThrow(
      'addShape: density must be >= 0, got -1',
    );
    expect(() => addShape(world, body, { type: 'circle', radius: 0.5, category: 1.5 })).toThrow(/addShape: category must be an integer/);
    expect(() => addBox(world, { halfExtents: [0, 1] })).toThrow('addBox: halfExtents[0] must be > 0, got 0');
    expect(() => setShapeFilter(world, body, { mask: -1 })).toThrow(/setShapeFilter: shape must be a shape/);
    expect(world.entityIndex.aliveCount).toBe(alive);
    expect(world.components.Mass.value[body]).toBe(1);
  });
});

describe('queries', () => {
  it('ray casts find the nearest hit and all hits, with the point and normal; overlap at a point and in a box', async () => {
    const { rayCast, rayCastAll, overlapPoint, overlapAABB } = await import('../../packages/physics/src/index.js');
    const world = createPhysicsWorld({ gravity: [0, 0] });
    const box = addBox(world, { position: [5, 0], halfExtents: [1, 1], static: true });
    const ball = addBody(world, { position: [10, 0], radius: 0.5, static: true });
    const cap = addBody(world, { position: [15, 0], static: true });
    const capShape = addShape(world, cap, { type: 'capsule', center1: [0, -1], center2: [0, 1], radius: 0.25 });
    // Hand-computed: the box's left face at x = 4, the ball's left point at x = 9.5, the capsule's side at x = 14.75.
    const first = rayCast(world, [0, 0], [20, 0])!;
    expect(first.shape).toBe(box);
    expect(first.x).toBeCloseTo(4, 12);
    expect(first.fraction).toBeCloseTo(0.2, 12);
    expect(first.nx).toBeCloseTo(-1, 12);
    expect(first.ny).toBeCloseTo(0, 12);
    const all = rayCastAll(world, [0, 0], [20, 0]);
    expect(all.map((h) => h.shape)).toEqual([box, ball, capShape]);
    expect(all[1]!.x).toBeCloseTo(9.5, 12);
    expect(all[2]!.x).toBeCloseTo(14.75, 12);
    // A ray over the top of the box (y = 1.5) misses it and grazes nothing else but the capsule's cap (r 0.25 at y = 1: misses at 1.5).
    expect(rayCast(world, [0, 1.5], [20, 0])).toBeNull();
    // The capsule's upper cap: a ray down from above hits it at y = 1.25.
    expect(rayCast(world, [15, 5], [0, -10])!.y).toBeCloseTo(1.25, 12);
    expect(overlapPoint(world, [5.5, 0.5])).toEqual([box]);
    expect(overlapPoint(world, [15.2, 1.1])).toEqual([capShape]);
    expect(overlapPoint(world, [7, 0])).toEqual([]);
    expect(overlapAABB(world, [9, -3], [14.8, 3]).sort()).toEqual([ball, capShape].sort());
    expect(() => rayCast(world, [0, 0], [0, 0])).toThrow('rayCast: translation must not be zero, got [0,0]');
  });
});

describe('shapes against static geometry', () => {
  it('a box rests on a plane, a capsule on a segment, a ball on a box, a triangle on the boundary box floor', async () => {
    const { addPlane, addSegment, setBoundary } = await import('../../packages/physics/src/index.js');
    // Resting heights from the geometry; 5 mm covers the soft contacts' sink under their own weight.
    const settle = (world: PhysicsWorld): Float64Array => {
      for (let i = 0; i < 120; i++) step(world);
      return world.components.Position.y;
    };
    let world = createPhysicsWorld({ gravity: [0, -G], sleep: false });
    addPlane(world, { normal: [0, 1], point: [0, 0] });
    const box = slotOf(addBox(world, { position: [0, 0.6], halfExtents: [0.5, 0.5] }));
    expect(Math.abs(settle(world)[box]! - 0.5)).toBeLessThan(5e-3);

    world = createPhysicsWorld({ gravity: [0, -G], sleep: false });
    addSegment(world, { a: [10, 2], b: [14, 2], radius: 0.05 });
    const cap = slotOf(addBody(world, { position: [12, 2.4] }));
    addShape(world, cap, { type: 'capsule', center1: [-0.5, 0], center2: [0.5, 0], radius: 0.25 });
    addBox(world, { position: [5, 1], halfExtents: [1, 0.25], static: true });
    const ball = slotOf(addBody(world, { position: [5, 2], radius: 0.3 }));
    const y = settle(world);
    expect(Math.abs(y[cap]! - (2 + 0.05 + 0.25))).toBeLessThan(5e-3);
    expect(Math.abs(y[ball]! - (1 + 0.25 + 0.3))).toBeLessThan(5e-3);

    world = createPhysicsWorld({ gravity: [0, -G], sleep: false });
    setBoundary(world, { min: [20, -1], max: [30, 10] });
    const tri = slotOf(addBody(world, { position: [25, 0] }));
    addShape(world, tri, {
      type: 'polygon',
      vertices: [
        [-0.5, -0.3],
        [0.5, -0.3],
        [0, 0.6],
      ],
    });
    // Its centroid is 0.3 m above its base.
    expect(Math.abs(settle(world)[tri]! - (-1 + 0.3))).toBeLessThan(5e-3);
  });
});
