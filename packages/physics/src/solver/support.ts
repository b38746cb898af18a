import { BS2_INV_MASS, BS2_STRIDE, BS3_INV_MASS } from './body-state-layout.js';
/**
 * Support rows of the ball contacts' relax sweep (solver/contact-solver.ts, solve2D and solve3D, and the coloured solve
 * of a threaded 2D world, solver/coloring-kernel.ts, which repeats the test inline for frictionless rows
 * only): shock propagation (Guendelman, Bridson and Fedkiw, "Nonconvex rigid bodies with stacking",
 * SIGGRAPH 2003), limited to the relax sweep of frictionless rows and rows with the heavier ball above,
 * and to row updates that take energy out.
 *
 * Each soft substep solves the contacts with one Gauss-Seidel sweep with bias (which pushes overlaps
 * out), then one relax sweep without bias that should take the push-out velocity away again. Along a
 * tall chain of contacts one relax sweep cannot: relaxing the row under a ball only moves that ball's
 * velocity into the ball below, so the push-out of a 60-layer column stays in it as kinetic energy.
 * With stiff contacts (frequency f up to 0.6 of the substep rate, solver/contact-scale.ts) a column
 * whose rows have no friction to damp them boils: its exact equilibrium is unstable above f h_s ~ 0.27,
 * and balls zigzagging between walls or stacked in a tube keep being thrown up. Rows with friction
 * settle at f h_s 0.6 (their tangent rows damp the column), and are left as they are, unless the upper
 * ball is at least HEAVY_RATIO times heavier: a relax update moves the upper ball by only
 * m_lower / (m_lower + m_upper) of the relative speed, so a heavy ball resting on a light one would keep
 * the push-out speed of every substep and rise. With these rows held (and the relax sweep taking the
 * floor and wall rows of such light balls first, `markFirstRelaxRows`, so the light ball is at rest when
 * its row above is relaxed) such stacks settle and never rise, at mass ratios up to 3,000
 * (test/physics/heavy-on-light.test.ts).
 *
 * In the relax sweep, a row between two dynamic balls with no friction (bound 0) or whose upper ball is
 * at least HEAVY_RATIO times heavier, and whose normal is within acos(SUPPORT_COS) of gravity (one ball rests on the other), is solved with the lower ball held
 * (inverse mass 0, `holdsLower`) when that only slows the ball above: when the lower ball's speed along
 * the normal is at most the upper one's, so making the upper ball move with the lower one along the
 * normal cannot raise its kinetic energy, and the lower ball is not touched. One sweep then clears the
 * push-out speed of a whole column (test/physics/support-rows.test.ts). Otherwise (and always in the
 * sweep with bias, and for the impact stage and restitution) both masses count, so momentum is exchanged
 * as it should be. Balls put exactly touching in an ideal lattice may still sway in place: their rows with the walls are
 * horizontal, not support rows.
 *
 * The trade-off: in such a row the relax sweep does not conserve momentum (the ball above is stopped
 * against the ball below as if that one were immovable). The relax sweep exists to remove speed the
 * bias added, so this changes only how that speed is removed, never adds energy.
 */

/**
 * Smallest |n . g| / |g| (dimensionless, 0..1) for which a frictionless row between two dynamic balls
 * is a support row: 0.3, rows within 72.5 degrees of vertical (a zigzag column's rows lean 41 degrees
 * from horizontal, |n . g| / |g| = 0.66; a row side by side, like a Newton's cradle's, is 0 and never one).
 * @category Collision
 */
export const SUPPORT_COS = 0.3;

/**
 * Least mass ratio, upper ball over lower ball (dimensionless), for which a support row with friction
 * holds its lower ball in the relax sweep: 4, where a relax update moves the upper ball by a fifth of
 * the relative speed or less. Below it the two-mass relax with friction settles (a 2 kg ball rolling
 * onto a column of 1 kg balls, test/physics/collision-accuracy.test.ts's marble run, keeps exchanging
 * momentum).
 * @category Collision
 */
export const HEAVY_RATIO = 4;

/**
 * Whether the upper ball of a support row, of inverse mass `imUpper` (1/kg, > 0), is at least
 * HEAVY_RATIO times as heavy as the lower one, of inverse mass `imLower` (1/kg, > 0).
 * @category Collision
 */
export function heavierAbove(imLower: number, imUpper: number): boolean {
  return imUpper * HEAVY_RATIO <= imLower;
}

/**
 * Whether the relax sweep holds the lower ball of a support row: its normal speed |v_lower . n| (m/s,
 * >= 0) is at most the upper ball's |v_upper . n| (m/s, >= 0), so moving the upper ball to the lower
 * one's normal velocity does not raise its kinetic energy.
 * @category Collision
 */
export function holdsLower(speedLower: number, speedUpper: number): boolean {
  return speedLower <= speedUpper;
}

/**
 * Which ball of a row between two dynamic balls (inverse masses `imA`, `imB`, 1/kg, > 0) is the lower
 * ball of a support row the relax sweep may hold (solver/ball-sweeps.ts): 1 ball A, 2 ball B, 0 neither.
 * A support row is within SUPPORT_COS of vertical (`up` = -n . g / |g|, n from A to B: > 0 puts A
 * below) and frictionless (`frictionBound` 0) or with the upper ball heavierAbove the lower; the sweep
 * then holds the lower ball when holdsLower says so.
 * @category Collision
 */
export function lowerSupportBall(up: number, frictionBound: number, imA: number, imB: number): number {
  if (up > SUPPORT_COS) return frictionBound === 0 || heavierAbove(imA, imB) ? 1 : 0;
  if (up < -SUPPORT_COS) return frictionBound === 0 || heavierAbove(imB, imA) ? 2 : 0;
  return 0;
}

/**
 * Which ball of a row between two dynamic balls the relax sweep holds (inverse mass 0 for the row's
 * normal impulse): 1 ball A, 2 ball B, 0 neither. The row's lowerSupportBall (`up`, `frictionBound`,
 * `imA`, `imB` as there) is held when holdsLower says so for the balls' speeds along the normal,
 * |`vnA`| and |`vnB`| (vnA = v_A . n, vnB = v_B . n, m/s).
 * @category Collision
 */
export function heldSupportBall(up: number, frictionBound: number, imA: number, imB: number, vnA: number, vnB: number): number {
  const lower = lowerSupportBall(up, frictionBound, imA, imB);
  if (lower === 0) return 0;
  const va = Math.abs(vnA),
    vb = Math.abs(vnB);
  return (lower === 1 ? holdsLower(va, vb) : holdsLower(vb, va)) ? lower : 0;
}

/**
 * Writes the relax sweep's row order (solver/ball-sweeps.ts, `n` rows) into out[0 ..] and returns its
 * length, n plus the number of marked rows: first the rows `first` marks (markFirstRelaxRows), then the
 * rows between two balls, then the rows against static bodies (`ia` 0), the marked ones among them
 * again. `out` needs room for 2 n indices. The sweep with bias takes the rows in buffer order.
 * @category Collision
 */
export function relaxOrderInto(first: Uint8Array, ia: Int32Array, n: number, out: Int32Array): number {
  let k = 0;
  for (let i = 0; i < n; i++) if (first[i] !== 0) out[k++] = i;
  for (let i = 0; i < n; i++) if (ia[i] !== 0) out[k++] = i;
  for (let i = 0; i < n; i++) if (ia[i] === 0) out[k++] = i;
  return k;
}

/**
 * Writes the unit vector along `g` (m/s^2, 2 or 3 components; the first two used), or (0, 0) for no
 * gravity, into out[at] and out[at + 1] (no array made: the solvers ask once a step).
 * @category Collision
 */
export function downwardInto(g: ArrayLike<number>, out: Float64Array, at: number): void {
  const gx = g[0]!,
    gy = g[1]!;
  const l = Math.sqrt(gx * gx + gy * gy);
  if (l > 0) {
    out[at] = gx / l;
    out[at + 1] = gy / l;
  } else {
    out[at] = 0;
    out[at + 1] = 0;
  }
}

/**
 * Writes the unit vector along `g` (m/s^2, 3 components), or (0, 0, 0) for no gravity, into out[at],
 * out[at + 1] and out[at + 2] (the 3D solver's support rows).
 * @category Collision
 */
export function downward3Into(g: ArrayLike<number>, out: Float64Array, at: number): void {
  const gx = g[0]!,
    gy = g[1]!,
    gz = g[2] ?? 0;
  const l = Math.sqrt(gx * gx + gy * gy + gz * gz);
  const k = l > 0 ? 1 / l : 0;
  out[at] = gx * k;
  out[at + 1] = gy * k;
  out[at + 2] = gz * k;
}

/** Per solver body: whether it is the lower ball of a support row with a heavier ball above (scratch, not world state). */
let underHeavier = new Uint8Array(64);
/** Per row: 1 if the row holds a ball that is under a heavier ball against a static body (scratch, not world state). */
let firstRelax = new Uint8Array(64);

/**
 * Marks the rows the relax sweep solves first (solver/contact-solver.ts solve2D and solve3D): rows against a static
 * body (solver index 0 on side A) whose ball is the lower ball of a support row with a heavier ball
 * above. Relaxed first, such a ball is at rest when the row above it is relaxed, so that row may hold
 * it (`holdsLower`). Returns the per-row flags (valid for the first `buf.count` rows until the next call).
 * @param stride the solver state's row stride (BS2_STRIDE in 2D, BS3_STRIDE in 3D, solver/body-state-layout.ts); the
 *   inverse mass sits at BS2_INV_MASS or BS3_INV_MASS.
 * @param down the unit vector along gravity (its first 2 or 3 components at `at`).
 * @category Collision
 */
export function markFirstRelaxRows(
  ia: Int32Array,
  ib: Int32Array,
  nx: Float64Array,
  ny: Float64Array,
  nz: Float64Array | null,
  count: number,
  bodyCount: number,
  state: Float64Array,
  stride: number,
  down: Float64Array,
  at: number,
): Uint8Array {
  if (underHeavier.length < bodyCount) underHeavier = new Uint8Array(Math.max(bodyCount, 2 * underHeavier.length));
  if (firstRelax.length < count) firstRelax = new Uint8Array(Math.max(count, 2 * firstRelax.length));
  const under = underHeavier,
    flags = firstRelax;
  under.fill(0, 0, bodyCount);
  const im = stride === BS2_STRIDE ? BS2_INV_MASS : BS3_INV_MASS;
  const dx = down[at]!,
    dy = down[at + 1]!,
    dz = nz === null ? 0 : down[at + 2]!;
  let any = false;
  for (let i = 0; i < count; i++) {
    const a = ia[i]!;
    if (a === 0) continue;
    const b = ib[i]!;
    const imA = state[a * stride + im]!,
      imB = state[b * stride + im]!;
    if (!(imA > 0 && imB > 0)) continue;
    const up = -(dx * nx[i]! + dy * ny[i]! + (nz === null ? 0 : dz * nz[i]!));
    if (up > SUPPORT_COS && heavierAbove(imA, imB)) {
      under[a] = 1;
      any = true;
    } else if (up < -SUPPORT_COS && heavierAbove(imB, imA)) {
      under[b] = 1;
      any = true;
    }
  }
  for (let i = 0; i < count; i++) flags[i] = any && ia[i] === 0 && under[ib[i]!] === 1 ? 1 : 0;
  return flags;
}
