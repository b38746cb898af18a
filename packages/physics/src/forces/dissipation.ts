import { registerExternalWorldState } from '../world/external-state.js';
import type { PhysicsWorld } from '../world/options.js';
import { markWritable } from '../world/writable-fields.js';

/**
 * Stiff dissipation: how drag and damping stay stable at every step size.
 *
 * A dissipative law (linear drag, quadratic drag, drag against the wind, buoyancy's fluid drag,
 * angular damping, a spring's damping) removes velocity at a rate lambda per step: lambda = k h / m
 * for linear drag F = -k v_rel, lambda = k |v_rel| h / m for quadratic drag F = -k |v_rel| v_rel,
 * lambda = k h / I for angular damping tau = -k w, lambda = c h (1/m_a + 1/m_b) for a spring's
 * damping -c (v_b - v_a) . u along its direction u (v_rel = v - u, u the wind; h the (sub)step; m the
 * mass, I the moment of inertia). Applied as a force, an explicit scheme multiplies v_rel by about (1 - lambda)
 * each step: past lambda = 1 it reverses the velocity and past lambda = 2 it amplifies it without
 * bound. So each law works in one of two regimes, chosen per body for each (sub)step:
 *
 * - lambda < STIFF_RATE: the law adds its force like any other. Every integrator, multi-stage ones
 *   included, evaluates it at its trial states (`evaluateForces`) and keeps its order of accuracy.
 *   With at most three drag laws on a body their summed rate stays below 3/4, where the velocity
 *   factor of every scheme (explicit Euler 1 - lambda, RK2 and both Verlets 1 - lambda + lambda^2/2,
 *   RK4 its degree-4 Taylor polynomial of e^-lambda, implicit Euler 1 / (1 + lambda)) lies in (0, 1):
 *   the law slows the body, never reverses or amplifies it.
 * - lambda >= STIFF_RATE: the law adds no force. After the scheme has moved the body, the integrate
 *   stage's stiff update of the law (stiffDragSystem, stiffFluidDragSystem, stiffAngularDampingSystem,
 *   stiffSpringDampingSystem) applies the law's own exact solution over h to the scheme's end
 *   velocity (Lie splitting; Hairer, Lubich and Wanner, Geometric Numerical Integration, ch. II.5):
 *     linear drag:     v_rel <- v_rel exp(-k h / m)              (m v' = -k v solved exactly),
 *     quadratic drag:  v_rel <- v_rel / (1 + k |v_rel| h / m)     (m v' = -k |v| v solved exactly:
 *                                                                  v(t) = v0 / (1 + k v0 t / m)),
 *     angular damping: w <- w exp(-k h / I), per principal axis in the body frame for an inertia tensor,
 *     spring damping:  (v_b - v_a) . u <- ((v_b - v_a) . u) exp(-lambda), by equal and opposite impulses
 *                      along u (the pair's exact solution; momentum kept; springs one after another),
 *   and the body then moves over the step with its damped velocity, x = x(start) + h v, as in Box2D's
 *   velocity integration (damping applied as v / (1 + h c) after the forces, positions from the
 *   damped velocity; Catto, box2d.org, b2IntegrateVelocities/b2IntegratePositions). Both updates
 *   multiply v_rel by a factor in [0, 1): they can slow a body to rest, never reverse or amplify it.
 *   At that rate the split is first order in the coupling with the other forces, which is the
 *   accuracy a step this coarse for the drag has anyway; a falling body settles at its terminal
 *   velocity instead of blowing up.
 *
 * Linear drag, angular damping and spring damping decide from constants (k, m, h), so every
 * evaluation of a step agrees. Quadratic and fluid drag depend on the state, and each evaluation
 * decides from the state it sees (the laws stay pure functions of the state arrays): a body found
 * stiff at any evaluation of a (sub)step is stamped with the (sub)step's epoch and gets the exact
 * update after the integrator. If a multi-stage scheme finds it stiff at one stage and not at
 * another, the stages that applied the force did so at a rate below 1/4 with weights summing to 1,
 * which multiplies v_rel by a factor in [3/4, 1]; with the exact factor after it the product still
 * lies in [0, 1].
 * @category Forces
 */
export const STIFF_RATE = 0.25;

/**
 * Per-world bookkeeping of the stiff regime (see the module comment).
 * @category Forces
 */
export interface DissipationState {
  /** Increments at each new (sub)step seen by a law; decisions are stamped with it. */
  epoch: number;
  /** The (world.steps, world.substepStart) the epoch belongs to. */
  keyStep: number;
  keyTime: number;
  /**
   * Epoch at which quadratic drag / fluid drag last found each entity stiff (capacity + 1 entries;
   * empty until a body is first found stiff or a fluid law runs: `allocateStiffStamps`).
   */
  quadraticStamp: Float64Array;
  fluidStamp: Float64Array;
  /** Coefficient (kg/m) of the quadratic / fluid drag the stiff update applies to a stamped entity. */
  quadraticK: Float64Array;
  fluidK: Float64Array;
  /** Epoch at which each law last found a stiff body (the stiff updates skip laws without one). */
  linearSeen: number;
  quadraticSeen: number;
  fluidSeen: number;
  angularSeen: number;
  springSeen: number;
}

registerExternalWorldState({
  name: 'dissipation',
  get: (world, create) => (world.features.dissipation as DissipationState | undefined) ?? (create ? dissipationState(world) : undefined),
  clear: (world) => {
    world.features.dissipation = undefined;
  },
});

/**
 * The world's dissipation state with its epoch advanced if a new (sub)step has begun (keyed on
 * `world.steps` and `world.substepStart`, which `step` sets before each substep's forces).
 * @category Forces
 */
export function dissipationState(world: PhysicsWorld): DissipationState {
  let s = world.features.dissipation as DissipationState | undefined;
  if (!s) {
    s = {
      epoch: 1,
      keyStep: world.steps,
      keyTime: world.substepStart,
      quadraticStamp: new Float64Array(0),
      fluidStamp: new Float64Array(0),
      quadraticK: new Float64Array(0),
      fluidK: new Float64Array(0),
      linearSeen: 0,
      quadraticSeen: 0,
      fluidSeen: 0,
      angularSeen: 0,
      springSeen: 0,
    };
    // Written from the next step on (world/writable-fields.ts).
    markWritable(s, Object.keys(s) as (keyof DissipationState & string)[]);
    world.features.dissipation = s;
    return s;
  }
  if (s.keyStep !== world.steps || s.keyTime !== world.substepStart) {
    s.epoch++;
    s.keyStep = world.steps;
    s.keyTime = world.substepStart;
  }
  return s;
}

/**
 * Gives the per-entity stamp arrays of `st` room for the world's capacity if they are still empty
 * (every world asks for its dissipation state each step; only one with stiff drag or fluids needs
 * them: 32 bytes an entity). Call before stamping or before pulling them into locals.
 * @category Forces
 */
export function allocateStiffStamps(world: PhysicsWorld, st: DissipationState): void {
  const n = world.capacity + 1;
  if (st.quadraticStamp.length >= n) return;
  st.quadraticStamp = new Float64Array(n);
  st.fluidStamp = new Float64Array(n);
  st.quadraticK = new Float64Array(n);
  st.fluidK = new Float64Array(n);
}

/**
 * Velocity factor of linear drag or damping at rate lambda = k h / m over one step: exp(-lambda),
 * the exact solution of v' = -(k / m) v. In [0, 1] for lambda >= 0.
 * @category Forces
 */
export function linearDecay(lambda: number): number {
  return Math.exp(-lambda);
}

/**
 * Velocity factor of quadratic drag at rate lambda = k |v| h / m over one step: 1 / (1 + lambda),
 * the exact solution v0 / (1 + k v0 t / m) of m v' = -k |v| v. In (0, 1] for lambda >= 0 (0 only
 * when lambda is infinite).
 * @category Forces
 */
export function quadraticDecay(lambda: number): number {
  return 1 / (1 + lambda);
}

/**
 * The stiff systems' update of one body: sets body e's velocity to (vx, vy, vz) (m/s) and moves it
 * from where the (sub)step began (PreviousPosition) with that velocity, x = x_start + h v; in a 2D
 * world z and its velocity are left as they are. Returns the finiteness term of what it wrote:
 * 0 (or -0) when every value is finite, NaN otherwise (x * 0).
 * @category Forces
 */
export function moveFromStart(world: PhysicsWorld, e: number, h: number, vx: number, vy: number, vz: number): number {
  const c = world.components;
  const V = c.Velocity,
    O = c.PreviousPosition,
    X = c.Position;
  V.x[e] = vx;
  V.y[e] = vy;
  const x = O.x[e]! + h * vx,
    y = O.y[e]! + h * vy;
  X.x[e] = x;
  X.y[e] = y;
  if (world.dimensions === 2) return vx * 0 + vy * 0 + x * 0 + y * 0;
  V.z[e] = vz;
  const z = O.z[e]! + h * vz;
  X.z[e] = z;
  return vx * 0 + vy * 0 + x * 0 + y * 0 + vz * 0 + z * 0;
}
