import type { BodySnapshot, EngineInstance, SceneRunOptions } from './types.js';

type Rapier = typeof import('@dimforge/rapier2d-compat').default;

/**
 * Rapier 2D's `joint-grid` (Box2D v3's joint benchmark, the scene of the physics package's
 * `joint-grid`): a side x side grid of dynamic bodies 1 m apart, each of mass 1 kg and moment of
 * inertia 0.08 kg m^2 (a 0.4 m disc) given as additional mass properties, no colliders; each joined
 * to its left and upper neighbours by an impulse revolute joint at the midpoint; the seven middle
 * bodies of the top row fixed; gravity (0, -10) m/s^2, timestep 1/60 s, every integration parameter
 * at Rapier's default. Its result line adds `maxJointError` (m): the largest distance between a
 * joint's two anchors in the world after any timed step (measured outside the timed interval),
 * `lastJointError` after the last step, and `joints`.
 * `name` is the engine's name in the results (rapier2d or rapier2d-simd: the same API).
 */
export function createRapierJointGrid(R: Rapier, options: SceneRunOptions, name = 'rapier2d'): EngineInstance {
  const n = options.count;
  let world: InstanceType<Rapier['World']> | undefined = new R.World({ x: 0, y: -10 });
  const w = world;
  w.timestep = 1 / 60;
  const inertia = 0.5 * 1 * 0.4 * 0.4;
  const bodies: Array<InstanceType<Rapier['RigidBody']>> = new Array(n * n);
  // Joint j joins bodies ja[j] and jb[j] at local anchors (ax, ay) of the first and (bx, by) of the second.
  const ja: number[] = [],
    jb: number[] = [],
    anchors: number[] = [];
  for (let i = 0; i < n; i++) {
    for (let k = 0; k < n; k++) {
      const pinned = i === 0 && k >= n / 2 - 3 && k <= n / 2 + 3;
      const desc = pinned
        ? R.RigidBodyDesc.fixed().setTranslation(k, -i)
        : R.RigidBodyDesc.dynamic().setTranslation(k, -i).setAdditionalMassProperties(1, { x: 0, y: 0 }, inertia);
      const b = w.createRigidBody(desc);
      const self = i * n + k;
      bodies[self] = b;
      if (i > 0) {
        const up = (i - 1) * n + k;
        w.createImpulseJoint(R.JointData.revolute({ x: 0, y: -0.5 }, { x: 0, y: 0.5 }), bodies[up]!, b, true);
        ja.push(up);
        jb.push(self);
        anchors.push(0, -0.5, 0, 0.5);
      }
      if (k > 0) {
        const left = self - 1;
        w.createImpulseJoint(R.JointData.revolute({ x: 0.5, y: 0 }, { x: -0.5, y: 0 }), bodies[left]!, b, true);
        ja.push(left);
        jb.push(self);
        anchors.push(0.5, 0, -0.5, 0);
      }
    }
  }
  const count = bodies.length,
    joints = ja.length;
  const pose = new Float64Array(3 * count);
  let worst = 0,
    last = 0;
  /** Largest anchor separation of any joint now, m. */
  const jointError = (): number => {
    for (let i = 0; i < count; i++) {
      const t = bodies[i]!.translation();
      pose[3 * i] = t.x;
      pose[3 * i + 1] = t.y;
      pose[3 * i + 2] = bodies[i]!.rotation();
    }
    let e = 0;
    for (let j = 0; j < joints; j++) {
      const a = 3 * ja[j]!,
        b = 3 * jb[j]!,
        q = 4 * j;
      const ca = Math.cos(pose[a + 2]!),
        sa = Math.sin(pose[a + 2]!),
        cb = Math.cos(pose[b + 2]!),
        sb = Math.sin(pose[b + 2]!);
      const dx = pose[b]! + cb * anchors[q + 2]! - sb * anchors[q + 3]! - (pose[a]! + ca * anchors[q]! - sa * anchors[q + 1]!);
      const dy = pose[b + 1]! + sb * anchors[q + 2]! + cb * anchors[q + 3]! - (pose[a + 1]! + sa * anchors[q]! + ca * anchors[q + 1]!);
      const d = Math.sqrt(dx * dx + dy * dy);
      if (d > e) e = d;
    }
    return e;
  };
  const ip = w.integrationParameters;
  return {
    engine: name,
    notes: [
      `${name} ${R.version()}: joint-grid, dt ${w.timestep.toFixed(6)} s, ${ip.numSolverIterations} solver iterations, impulse revolute joints, sleeping allowed (defaults); WASM compiled optimized up front`,
    ],
    step(): void {
      w.step();
    },
    beginTiming(): void {
      worst = 0;
    },
    afterStep(): void {
      last = jointError();
      if (last > worst) worst = last;
    },
    stats() {
      return { bodies: count, contacts: null, extra: { maxJointError: worst, lastJointError: last, joints } };
    },
    snapshot(): BodySnapshot {
      const positions = new Float64Array(2 * count);
      for (let i = 0; i < count; i++) {
        const t = bodies[i]!.translation();
        positions[2 * i] = t.x;
        positions[2 * i + 1] = t.y;
      }
      return { dimensions: 2, count, positions };
    },
    dispose(): void {
      world?.free();
      world = undefined;
    },
  };
}
