import type { PhysicsWorld } from '../world';
import { ContactKind, findWarmStart, storeWarmStart, type ContactBuffer } from './contacts';
import { BodyType } from './broadphase';
import { reportNonFinite } from '../errors';
import { rotateInPlace } from '../math/quaternion';

/**
 * Collide stage, part 3: the contact solver, Box2D v3's "soft step" (Catto, "Solver2D", 2024; Box2D
 * v3.0 solver.c and contact_solver.c), fitted to a pipeline where the integrate stage has already run:
 *
 * 1. gather the moving bodies that have contacts and rewind this step's gravity from their velocity
 *    (the integrate stage added g dt; the substeps add it back in pieces);
 * 2. prepare each contact: combined material, effective masses, tangent basis, the normal relative
 *    velocity at the start of the step (for restitution), and last step's impulses (warm start);
 * 3. `solverSubsteps` times, with h_s = h / substeps:
 *    integrate gravity (v += g h_s); warm start; solve with soft bias (non-penetration, then Coulomb
 *    friction |lambda_t| <= mu lambda_n, mu_s while sticking); move the bodies (dx += v h_s); relax
 *    (solve again without bias, so push-out velocity does not survive as kinetic energy);
 * 4. restitution: contacts that approached faster than the threshold and carried an impulse get
 *    v_n = -e v_n0, with v_n0 the approach speed at the start of the step;
 * 5. write positions and store the impulses for the next step's warm start.
 *
 * Separation is tracked linearly: s = s0 + (dx_B - dx_A) . n, with s0 measured where the bodies
 * were at the start of the step. s > 0 is a speculative gap the bodies may close this substep
 * (bias s / h_s); s < 0 is overlap pushed out by a soft constraint (a damped spring of
 * `contactHertz` and `contactDampingRatio`, at most `contactPushSpeed`). Soft constraints with
 * relaxation are what keeps a deep pile still with few iterations and without adding energy.
 */
export function contactSolverSystem(world: PhysicsWorld): void {
  const cs = world.collision;
  const buf = cs.contacts;
  cs.stats.maxOverlap = 0;
  if (buf.count === 0) {
    cs.contacts = storeWarmStart(cs.cache, buf);
    return;
  }
  gatherBodies(world, buf);
  prepareContacts(world, buf);

  const st = cs.settings;
  const substeps = st.solverSubsteps;
  const hs = world.h / substeps;
  // Softness (Box2D b2MakeSoft): stiffness capped at a quarter of the substep rate; contacts against
  // infinite mass twice as stiff.
  const hertz = Math.min(st.contactHertz, 0.25 / hs);
  const dyn = makeSoft(hertz, st.contactDampingRatio, hs);
  const rigid = makeSoft(2 * hertz, st.contactDampingRatio, hs);
  const is2D = world.dimensions === 2;
  for (let s = 0; s < substeps; s++) {
    integrateVelocities(world, hs);
    warmStart(world, buf);
    for (let it = 0; it < st.solverIterations; it++) {
      if (is2D) solve2D(world, buf, hs, true, dyn, rigid); else solve3D(world, buf, hs, true, dyn, rigid);
    }
    integratePositions(world, hs);
    for (let it = 0; it < st.relaxIterations; it++) {
      if (is2D) solve2D(world, buf, hs, false, dyn, rigid); else solve3D(world, buf, hs, false, dyn, rigid);
    }
    // The accumulated impulse is what this substep delivered (warm start plus corrections).
    const LN = buf.normalImpulse, TOT = buf.totalNormalImpulse;
    for (let i = 0, n = buf.count; i < n; i++) TOT[i] = TOT[i]! + LN[i]!;
  }
  applyRestitution(world, buf);
  finishBodies(world, buf);
  cs.contacts = storeWarmStart(cs.cache, buf);
}

/** Soft constraint coefficients (Box2D v3 b2Softness). */
interface Softness { biasRate: number; massScale: number; impulseScale: number }

/**
 * Coefficients of a soft constraint: a spring of frequency `hertz` and damping ratio `zeta`
 * integrated implicitly over h (Catto, "Soft Constraints", GDC 2011; Box2D v3 b2MakeSoft).
 */
function makeSoft(hertz: number, zeta: number, h: number): Softness {
  if (hertz === 0) return { biasRate: 0, massScale: 1, impulseScale: 0 };
  const omega = 2 * Math.PI * hertz;
  const a1 = 2 * zeta + h * omega;
  const a2 = h * omega * a1;
  const a3 = 1 / (1 + a2);
  return { biasRate: omega / a1, massScale: a2 * a3, impulseScale: a3 };
}

/**
 * Collects the moving bodies touched by contacts into `solverBodies`, zeroes their displacement,
 * remembers where the integrator put them (so the integrator's own position update is kept beyond
 * what x0 + v h explains) and rewinds this step's gravity from dynamic bodies' velocities.
 */
function gatherBodies(world: PhysicsWorld, buf: ContactBuffer): void {
  const cs = world.collision;
  const c = world.components;
  const n = buf.count;
  const mark = cs.solverMark;
  const stamp = ++cs.solverStamp;
  let list = cs.solverBodies;
  let count = 0;
  const A = buf.a, B = buf.b;
  for (let i = 0; i < n; i++) {
    const a = A[i]!, b = B[i]!;
    if (a !== 0 && mark[a] !== stamp) {
      mark[a] = stamp;
      if (count >= list.length) { const l = new Int32Array(list.length * 2); l.set(list); list = l; }
      list[count++] = a;
    }
    if (mark[b] !== stamp) {
      mark[b] = stamp;
      if (count >= list.length) { const l = new Int32Array(list.length * 2); l.set(list); list = l; }
      list[count++] = b;
    }
  }
  cs.solverBodies = list;
  cs.solverBodyCount = count;

  const [dx, dy, dz, bx, by, bz] = cs.delta as [Float64Array, Float64Array, Float64Array, Float64Array, Float64Array, Float64Array];
  const px = c.Position.x, py = c.Position.y, pz = c.Position.z;
  const vx = c.Velocity.x, vy = c.Velocity.y, vz = c.Velocity.z;
  const h = world.h;
  const g = world.gravity;
  const gx = g[0]! * h, gy = g[1]! * h, gz = g[2]! * h;
  const type = cs.bodyType;
  const invInertia = cs.invInertia;
  const rx = cs.delta[6]!, ry = cs.delta[7]!, rz = cs.delta[8]!;
  const wx = c.AngularVelocity.x, wy = c.AngularVelocity.y, wz = c.AngularVelocity.z;
  for (let k = 0; k < count; k++) {
    const e = list[k]!;
    dx[e] = 0; dy[e] = 0; dz[e] = 0;
    if (type[e] !== BodyType.Dynamic) continue;
    // The integrator turned the body by w h; the substeps will turn it by sum w_k h_s instead.
    if (invInertia[e]! > 0) { rx[e] = -wx[e]! * h; ry[e] = -wy[e]! * h; rz[e] = -wz[e]! * h; }
    // Base: where x0 + v h would not explain the integrator's result (0 for semi-implicit Euler).
    bx[e] = px[e]! - vx[e]! * h; by[e] = py[e]! - vy[e]! * h; bz[e] = pz[e]! - vz[e]! * h;
    vx[e] = vx[e]! - gx; vy[e] = vy[e]! - gy; vz[e] = vz[e]! - gz;
  }
}

/** Adds one substep of gravity to the dynamic solver bodies. */
function integrateVelocities(world: PhysicsWorld, hs: number): void {
  const cs = world.collision;
  const c = world.components;
  const list = cs.solverBodies, count = cs.solverBodyCount, type = cs.bodyType;
  const vx = c.Velocity.x, vy = c.Velocity.y, vz = c.Velocity.z;
  const g = world.gravity;
  const gx = g[0]! * hs, gy = g[1]! * hs, gz = g[2]! * hs;
  for (let k = 0; k < count; k++) {
    const e = list[k]!;
    if (type[e] !== BodyType.Dynamic) continue;
    vx[e] = vx[e]! + gx; vy[e] = vy[e]! + gy; vz[e] = vz[e]! + gz;
  }
}

/** Advances the solver bodies' displacement by one substep. */
function integratePositions(world: PhysicsWorld, hs: number): void {
  const cs = world.collision;
  const c = world.components;
  const list = cs.solverBodies, count = cs.solverBodyCount;
  const vx = c.Velocity.x, vy = c.Velocity.y, vz = c.Velocity.z;
  const dx = cs.delta[0]!, dy = cs.delta[1]!, dz = cs.delta[2]!;
  const rx = cs.delta[6]!, ry = cs.delta[7]!, rz = cs.delta[8]!;
  const wx = c.AngularVelocity.x, wy = c.AngularVelocity.y, wz = c.AngularVelocity.z;
  const invInertia = cs.invInertia;
  for (let k = 0; k < count; k++) {
    const e = list[k]!;
    dx[e] = dx[e]! + vx[e]! * hs; dy[e] = dy[e]! + vy[e]! * hs; dz[e] = dz[e]! + vz[e]! * hs;
    if (invInertia[e]! > 0) { rx[e] = rx[e]! + wx[e]! * hs; ry[e] = ry[e]! + wy[e]! * hs; rz[e] = rz[e]! + wz[e]! * hs; }
  }
}

/**
 * Writes the final positions of the dynamic solver bodies (base + displacement) and turns rotating
 * balls by the difference between the spin the solver gave them and the spin the integrator assumed.
 * Records the deepest overlap left, measured linearly as in the solve.
 */
function finishBodies(world: PhysicsWorld, buf: ContactBuffer): void {
  const cs = world.collision;
  const c = world.components;
  const list = cs.solverBodies, count = cs.solverBodyCount, type = cs.bodyType;
  const [dx, dy, dz, bx, by, bz] = cs.delta as [Float64Array, Float64Array, Float64Array, Float64Array, Float64Array, Float64Array];
  const rx = cs.delta[6]!, ry = cs.delta[7]!, rz = cs.delta[8]!;
  const px = c.Position.x, py = c.Position.y, pz = c.Position.z;
  const invInertia = cs.invInertia;
  const angle = c.Angle.value;
  const q = c.Orientation;
  const is2D = world.dimensions === 2;
  let check = 0;
  for (let k = 0; k < count; k++) {
    const e = list[k]!;
    if (type[e] !== BodyType.Dynamic) continue;
    const x = bx[e]! + dx[e]!, y = by[e]! + dy[e]!;
    px[e] = x; py[e] = y;
    check += x + y;
    if (!is2D) { pz[e] = bz[e]! + dz[e]!; check += pz[e]!; }
    if (invInertia[e]! > 0) {
      if (is2D) angle[e] = angle[e]! + rz[e]!;
      else rotateInPlace(q.x, q.y, q.z, q.w, e, rx[e]!, ry[e]!, rz[e]!);
    }
  }
  if (check - check !== 0) reportNonFinite(world, list.subarray(0, count), 'collide');
  let deepest = 0;
  const A = buf.a, B = buf.b, S = buf.separation, NX = buf.nx, NY = buf.ny, NZ = buf.nz;
  for (let i = 0, n = buf.count; i < n; i++) {
    const a = A[i]!, b = B[i]!;
    const s = S[i]! + (dx[b]! - dx[a]!) * NX[i]! + (dy[b]! - dy[a]!) * NY[i]! + (dz[b]! - dz[a]!) * NZ[i]!;
    if (s < deepest) deepest = s;
  }
  cs.stats.maxOverlap = -deepest;
}

function prepareContacts(world: PhysicsWorld, buf: ContactBuffer): void {
  const c = world.components;
  const cs = world.collision;
  const st = cs.settings;
  const n = buf.count;
  const is2D = world.dimensions === 2;
  const invMass = cs.invMass, invInertia = cs.invInertia;
  const vx = c.Velocity.x, vy = c.Velocity.y, vz = c.Velocity.z;
  const wx = c.AngularVelocity.x, wy = c.AngularVelocity.y, wz = c.AngularVelocity.z;
  const eM = c.Material.restitution, fM = c.Material.friction, sM = c.Material.staticFriction;
  const box = cs.boundary;
  const cache = cs.cache;
  const prev = cache.rows;
  const stamp = world.spawnStamp;
  const stick = st.stickSpeed;
  const A = buf.a, B = buf.b, K = buf.kind, F = buf.feature;
  const NX = buf.nx, NY = buf.ny, NZ = buf.nz;
  const T1X = buf.t1x, T1Y = buf.t1y, T1Z = buf.t1z, T2X = buf.t2x, T2Y = buf.t2y, T2Z = buf.t2z;
  const RA = buf.ra, RB = buf.rb;
  const NM = buf.normalMass, TM = buf.tangentMass, RP = buf.rigidPartner;
  const E = buf.restitution, MU = buf.friction, FB = buf.frictionBound, RV = buf.relativeVelocity;
  const IV = buf.impactVelocity, TOT = buf.totalNormalImpulse, S0 = buf.separation;
  const type = cs.bodyType;
  const g = world.gravity;
  const gx = g[0]!, gy = g[1]!, gz = g[2]!;
  const LN = buf.normalImpulse, L1 = buf.tangentImpulse1, L2 = buf.tangentImpulse2, MAXN = buf.maxNormalImpulse;
  const SA = buf.stampA, SB = buf.stampB;
  const pN = prev.normalImpulse, p1 = prev.tangentImpulse1, p2 = prev.tangentImpulse2;

  for (let i = 0; i < n; i++) {
    const a = A[i]!, b = B[i]!, kind = K[i]!, f = F[i]!;
    const nx = NX[i]!, ny = NY[i]!, nz = NZ[i]!;
    const imA = invMass[a]!, imB = invMass[b]!;
    const iiA = invInertia[a]!, iiB = invInertia[b]!;
    const ra = RA[i]!, rb = RB[i]!;
    const k = imA + imB;
    NM[i] = k > 0 ? 1 / k : 0;
    const kt = k + iiA * ra * ra + iiB * rb * rb;
    TM[i] = kt > 0 ? 1 / kt : 0;
    RP[i] = imA === 0 || imB === 0 ? 1 : 0;

    // Tangent basis.
    let t1x: number, t1y: number, t1z: number;
    if (is2D) {
      t1x = -ny; t1y = nx; t1z = 0;
    } else {
      // A unit vector perpendicular to n, continuous except where n crosses |n_x| = 1/sqrt(3).
      if (Math.abs(nx) < 0.57735) {
        const inv = 1 / Math.sqrt(ny * ny + nz * nz);
        t1x = 0; t1y = nz * inv; t1z = -ny * inv;
      } else {
        const inv = 1 / Math.sqrt(nx * nx + ny * ny);
        t1x = ny * inv; t1y = -nx * inv; t1z = 0;
      }
      T2X[i] = ny * t1z - nz * t1y;
      T2Y[i] = nz * t1x - nx * t1z;
      T2Z[i] = nx * t1y - ny * t1x;
    }
    T1X[i] = t1x; T1Y[i] = t1y; T1Z[i] = t1z;

    // Combined material (Box2D's mixing rules: the bouncier surface wins, friction is the geometric mean).
    let e: number, mu: number, mus: number;
    if (kind === ContactKind.Ball) {
      e = Math.max(eM[a]!, eM[b]!); mu = Math.sqrt(fM[a]! * fM[b]!); mus = Math.sqrt(sM[a]! * sM[b]!);
    } else if (kind === ContactKind.Boundary) {
      e = Math.max(box.restitution, eM[b]!); mu = Math.sqrt(box.friction * fM[b]!); mus = Math.sqrt(box.staticFriction * sM[b]!);
    } else {
      e = Math.max(eM[f]!, eM[b]!); mu = Math.sqrt(fM[f]! * fM[b]!); mus = Math.sqrt(sM[f]! * sM[b]!);
    }
    E[i] = e;
    MU[i] = mu;

    // Relative velocity at the start of the step (gravity rewound): for restitution and stick/slip.
    const dvx = vx[b]! - vx[a]!, dvy = vy[b]! - vy[a]!, dvz = vz[b]! - vz[a]!;
    const rv = dvx * nx + dvy * ny + dvz * nz;
    RV[i] = rv;
    // Speed at impact: v^2 = v0^2 - 2 a_n s across a gap s > 0 with relative normal acceleration a_n from gravity.
    const gap = S0[i]!;
    const an = ((type[b] === BodyType.Dynamic ? 1 : 0) - (a !== 0 && type[a] === BodyType.Dynamic ? 1 : 0)) * (gx * nx + gy * ny + gz * nz);
    const v2 = gap > 0 ? rv * rv - 2 * an * gap : rv * rv;
    IV[i] = rv < 0 && v2 > 0 ? -Math.sqrt(v2) : rv;
    TOT[i] = 0;
    let vt: number;
    if (is2D) {
      vt = Math.abs(dvx * t1x + dvy * t1y - wz[b]! * rb - wz[a]! * ra);
    } else {
      // Contact-point velocity: v + w x r with r_A = ra n, r_B = -rb n.
      const sx = -rb * wx[b]! - ra * wx[a]!, sy = -rb * wy[b]! - ra * wy[a]!, sz = -rb * wz[b]! - ra * wz[a]!;
      const cx = dvx + sy * nz - sz * ny, cy = dvy + sz * nx - sx * nz, cz = dvz + sx * ny - sy * nx;
      const u1 = cx * t1x + cy * t1y + cz * t1z;
      const u2 = cx * T2X[i]! + cy * T2Y[i]! + cz * T2Z[i]!;
      vt = Math.sqrt(u1 * u1 + u2 * u2);
    }
    FB[i] = vt < stick ? Math.max(mus, mu) : mu;

    // Warm start from last step's impulses of the same pair.
    const sA = stamp[kind === ContactKind.Ball ? a : kind === ContactKind.Boundary ? 0 : f]!;
    const sB = stamp[b]!;
    SA[i] = sA;
    SB[i] = sB;
    MAXN[i] = 0;
    const j = findWarmStart(cache, kind, a, b, f, sA, sB);
    if (j >= 0) {
      LN[i] = pN[j]!; L1[i] = p1[j]!; L2[i] = p2[j]!;
    } else {
      LN[i] = 0; L1[i] = 0; L2[i] = 0;
    }
  }
}

/** Applies every contact's accumulated impulse (Box2D v3 warm start, once per substep). */
function warmStart(world: PhysicsWorld, buf: ContactBuffer): void {
  const c = world.components;
  const cs = world.collision;
  const n = buf.count;
  const vx = c.Velocity.x, vy = c.Velocity.y, vz = c.Velocity.z;
  const wx = c.AngularVelocity.x, wy = c.AngularVelocity.y, wz = c.AngularVelocity.z;
  const invMass = cs.invMass, invInertia = cs.invInertia;
  const A = buf.a, B = buf.b, NX = buf.nx, NY = buf.ny, NZ = buf.nz, RA = buf.ra, RB = buf.rb;
  const T1X = buf.t1x, T1Y = buf.t1y, T1Z = buf.t1z, T2X = buf.t2x, T2Y = buf.t2y, T2Z = buf.t2z;
  const LN = buf.normalImpulse, L1 = buf.tangentImpulse1, L2 = buf.tangentImpulse2;
  if (world.dimensions === 2) {
    for (let i = 0; i < n; i++) {
      const ln = LN[i]!, lt = L1[i]!;
      if (ln === 0 && lt === 0) continue;
      const a = A[i]!, b = B[i]!;
      const nx = NX[i]!, ny = NY[i]!;
      const Px = ln * nx - lt * ny, Py = ln * ny + lt * nx;
      const imA = invMass[a]!, imB = invMass[b]!;
      vx[a] = vx[a]! - imA * Px; vy[a] = vy[a]! - imA * Py;
      vx[b] = vx[b]! + imB * Px; vy[b] = vy[b]! + imB * Py;
      wz[a] = wz[a]! - invInertia[a]! * RA[i]! * lt;
      wz[b] = wz[b]! - invInertia[b]! * RB[i]! * lt;
    }
    vx[0] = 0; vy[0] = 0; wz[0] = 0;
    return;
  }
  for (let i = 0; i < n; i++) {
    const ln = LN[i]!, l1 = L1[i]!, l2 = L2[i]!;
    if (ln === 0 && l1 === 0 && l2 === 0) continue;
    const a = A[i]!, b = B[i]!;
    const nx = NX[i]!, ny = NY[i]!, nz = NZ[i]!;
    const Px = ln * nx + l1 * T1X[i]! + l2 * T2X[i]!;
    const Py = ln * ny + l1 * T1Y[i]! + l2 * T2Y[i]!;
    const Pz = ln * nz + l1 * T1Z[i]! + l2 * T2Z[i]!;
    const imA = invMass[a]!, imB = invMass[b]!;
    vx[a] = vx[a]! - imA * Px; vy[a] = vy[a]! - imA * Py; vz[a] = vz[a]! - imA * Pz;
    vx[b] = vx[b]! + imB * Px; vy[b] = vy[b]! + imB * Py; vz[b] = vz[b]! + imB * Pz;
    // Angular: dw_A = -I_A^-1 (ra n x P), dw_B = I_B^-1 (-rb n x P).
    const cx = ny * Pz - nz * Py, cy = nz * Px - nx * Pz, cz = nx * Py - ny * Px;
    const ka = invInertia[a]! * RA[i]!, kb = invInertia[b]! * RB[i]!;
    wx[a] = wx[a]! - ka * cx; wy[a] = wy[a]! - ka * cy; wz[a] = wz[a]! - ka * cz;
    wx[b] = wx[b]! - kb * cx; wy[b] = wy[b]! - kb * cy; wz[b] = wz[b]! - kb * cz;
  }
  vx[0] = 0; vy[0] = 0; vz[0] = 0; wx[0] = 0; wy[0] = 0; wz[0] = 0;
}

function solve2D(world: PhysicsWorld, buf: ContactBuffer, hs: number, useBias: boolean, dyn: Softness, rigid: Softness): void {
  const c = world.components;
  const cs = world.collision;
  const n = buf.count;
  const invH = 1 / hs;
  const push = cs.settings.contactPushSpeed;
  const vx = c.Velocity.x, vy = c.Velocity.y, wz = c.AngularVelocity.z;
  const dx = cs.delta[0]!, dy = cs.delta[1]!;
  const invMass = cs.invMass, invInertia = cs.invInertia;
  const A = buf.a, B = buf.b, NX = buf.nx, NY = buf.ny, RA = buf.ra, RB = buf.rb, S0 = buf.separation;
  const NM = buf.normalMass, TM = buf.tangentMass, FB = buf.frictionBound, RP = buf.rigidPartner;
  const LN = buf.normalImpulse, LT = buf.tangentImpulse1, MAXN = buf.maxNormalImpulse;
  const dBias = dyn.biasRate, dMass = dyn.massScale, dImp = dyn.impulseScale;
  const rBias = rigid.biasRate, rMass = rigid.massScale, rImp = rigid.impulseScale;

  for (let i = 0; i < n; i++) {
    const a = A[i]!, b = B[i]!;
    const nx = NX[i]!, ny = NY[i]!;
    const imA = invMass[a]!, imB = invMass[b]!;
    let vax = vx[a]!, vay = vy[a]!, vbx = vx[b]!, vby = vy[b]!;

    // Non-penetration, soft when overlapping and useBias, speculative when apart.
    const s = S0[i]! + (dx[b]! - dx[a]!) * nx + (dy[b]! - dy[a]!) * ny;
    let bias = 0, massScale = 1, impulseScale = 0;
    if (s > 0) {
      bias = s * invH;
    } else if (useBias) {
      if (RP[i] === 1) { bias = rBias * s; massScale = rMass; impulseScale = rImp; }
      else { bias = dBias * s; massScale = dMass; impulseScale = dImp; }
      if (bias < -push) bias = -push;
    }
    const vn = (vbx - vax) * nx + (vby - vay) * ny;
    const oldN = LN[i]!;
    let lambda = -NM[i]! * massScale * (vn + bias) - impulseScale * oldN;
    let newN = oldN + lambda;
    if (newN < 0) newN = 0;
    lambda = newN - oldN;
    LN[i] = newN;
    if (lambda > MAXN[i]!) MAXN[i] = lambda;
    let Px = lambda * nx, Py = lambda * ny;
    vax -= imA * Px; vay -= imA * Py; vbx += imB * Px; vby += imB * Py;

    // Coulomb friction along t = (-ny, nx) at the contact point.
    const ra = RA[i]!, rb = RB[i]!;
    let wa = wz[a]!, wb = wz[b]!;
    const vt = (vbx - vax) * -ny + (vby - vay) * nx - wb * rb - wa * ra;
    lambda = -TM[i]! * vt;
    const maxF = FB[i]! * newN;
    const oldT = LT[i]!;
    let newT = oldT + lambda;
    newT = newT < -maxF ? -maxF : newT > maxF ? maxF : newT;
    lambda = newT - oldT;
    LT[i] = newT;
    Px = -lambda * ny; Py = lambda * nx;
    vax -= imA * Px; vay -= imA * Py; vbx += imB * Px; vby += imB * Py;
    wa -= invInertia[a]! * ra * lambda; wb -= invInertia[b]! * rb * lambda;

    vx[a] = vax; vy[a] = vay; vx[b] = vbx; vy[b] = vby;
    wz[a] = wa; wz[b] = wb;
  }
  // Index 0 is the static world; keep it at rest whatever rounding wrote there.
  vx[0] = 0; vy[0] = 0; wz[0] = 0;
}

function solve3D(world: PhysicsWorld, buf: ContactBuffer, hs: number, useBias: boolean, dyn: Softness, rigid: Softness): void {
  const c = world.components;
  const cs = world.collision;
  const n = buf.count;
  const invH = 1 / hs;
  const push = cs.settings.contactPushSpeed;
  const vx = c.Velocity.x, vy = c.Velocity.y, vz = c.Velocity.z;
  const wx = c.AngularVelocity.x, wy = c.AngularVelocity.y, wz = c.AngularVelocity.z;
  const dx = cs.delta[0]!, dy = cs.delta[1]!, dz = cs.delta[2]!;
  const invMass = cs.invMass, invInertia = cs.invInertia;
  const A = buf.a, B = buf.b, NX = buf.nx, NY = buf.ny, NZ = buf.nz, RA = buf.ra, RB = buf.rb, S0 = buf.separation;
  const T1X = buf.t1x, T1Y = buf.t1y, T1Z = buf.t1z, T2X = buf.t2x, T2Y = buf.t2y, T2Z = buf.t2z;
  const NM = buf.normalMass, TM = buf.tangentMass, FB = buf.frictionBound, RP = buf.rigidPartner;
  const LN = buf.normalImpulse, L1 = buf.tangentImpulse1, L2 = buf.tangentImpulse2, MAXN = buf.maxNormalImpulse;

  for (let i = 0; i < n; i++) {
    const a = A[i]!, b = B[i]!;
    const nx = NX[i]!, ny = NY[i]!, nz = NZ[i]!;
    const imA = invMass[a]!, imB = invMass[b]!;

    const s = S0[i]! + (dx[b]! - dx[a]!) * nx + (dy[b]! - dy[a]!) * ny + (dz[b]! - dz[a]!) * nz;
    let bias = 0, massScale = 1, impulseScale = 0;
    if (s > 0) {
      bias = s * invH;
    } else if (useBias) {
      const soft = RP[i] === 1 ? rigid : dyn;
      bias = soft.biasRate * s; massScale = soft.massScale; impulseScale = soft.impulseScale;
      if (bias < -push) bias = -push;
    }
    const vn = (vx[b]! - vx[a]!) * nx + (vy[b]! - vy[a]!) * ny + (vz[b]! - vz[a]!) * nz;
    const oldN = LN[i]!;
    let newN = oldN - NM[i]! * massScale * (vn + bias) - impulseScale * oldN;
    if (newN < 0) newN = 0;
    const dl = newN - oldN;
    LN[i] = newN;
    if (dl > MAXN[i]!) MAXN[i] = dl;
    if (dl !== 0) {
      vx[a] = vx[a]! - imA * dl * nx; vy[a] = vy[a]! - imA * dl * ny; vz[a] = vz[a]! - imA * dl * nz;
      vx[b] = vx[b]! + imB * dl * nx; vy[b] = vy[b]! + imB * dl * ny; vz[b] = vz[b]! + imB * dl * nz;
    }

    // Friction in the tangent plane, clamped to the Coulomb cone.
    const ra = RA[i]!, rb = RB[i]!;
    let ux = vx[b]! - vx[a]!, uy = vy[b]! - vy[a]!, uz = vz[b]! - vz[a]!;
    const sx = -rb * wx[b]! - ra * wx[a]!, sy = -rb * wy[b]! - ra * wy[a]!, sz = -rb * wz[b]! - ra * wz[a]!;
    ux += sy * nz - sz * ny; uy += sz * nx - sx * nz; uz += sx * ny - sy * nx;
    const t1x = T1X[i]!, t1y = T1Y[i]!, t1z = T1Z[i]!, t2x = T2X[i]!, t2y = T2Y[i]!, t2z = T2Z[i]!;
    const tm = TM[i]!;
    const o1 = L1[i]!, o2 = L2[i]!;
    let n1 = o1 - tm * (ux * t1x + uy * t1y + uz * t1z);
    let n2 = o2 - tm * (ux * t2x + uy * t2y + uz * t2z);
    const maxF = FB[i]! * newN;
    const mag2 = n1 * n1 + n2 * n2;
    if (mag2 > maxF * maxF) { const k = maxF / Math.sqrt(mag2); n1 *= k; n2 *= k; }
    const d1 = n1 - o1, d2 = n2 - o2;
    L1[i] = n1; L2[i] = n2;
    if (d1 !== 0 || d2 !== 0) {
      const Px = d1 * t1x + d2 * t2x, Py = d1 * t1y + d2 * t2y, Pz = d1 * t1z + d2 * t2z;
      vx[a] = vx[a]! - imA * Px; vy[a] = vy[a]! - imA * Py; vz[a] = vz[a]! - imA * Pz;
      vx[b] = vx[b]! + imB * Px; vy[b] = vy[b]! + imB * Py; vz[b] = vz[b]! + imB * Pz;
      const cx = ny * Pz - nz * Py, cy = nz * Px - nx * Pz, cz = nx * Py - ny * Px;
      const ka = invInertia[a]! * ra, kb = invInertia[b]! * rb;
      wx[a] = wx[a]! - ka * cx; wy[a] = wy[a]! - ka * cy; wz[a] = wz[a]! - ka * cz;
      wx[b] = wx[b]! - kb * cx; wy[b] = wy[b]! - kb * cy; wz[b] = wz[b]! - kb * cz;
    }
  }
  vx[0] = 0; vy[0] = 0; vz[0] = 0; wx[0] = 0; wy[0] = 0; wz[0] = 0;
}

/**
 * Restitution, after Box2D v3 b2ApplyRestitution but solved as a small LCP rather than one pass.
 * A contact that approached faster than the threshold and carried an impulse this step must leave
 * with normal speed v_n >= -e v_impact, where v_impact is the approach speed at impact (start-of-step
 * speed plus gravity across the speculative gap); every other contact that carried an impulse must
 * not approach (v_n >= 0). `restitutionIterations` sequential-impulse passes solve these together with
 * a non-negative accumulated impulse, so coupled bounces in a dense pile share the rebound instead of
 * each contact adding its own on top of its neighbours'. A contact's rebound impulse is capped at e
 * times its compression impulse (delivered this step, plus what still stops a residual approach):
 * Poisson's hypothesis (Stronge, Impact Mechanics, 2000, ch. 2), which keeps a perfectly elastic
 * pile from creating energy.
 */
function applyRestitution(world: PhysicsWorld, buf: ContactBuffer): void {
  const c = world.components;
  const cs = world.collision;
  const threshold = cs.settings.restitutionThreshold;
  const iterations = cs.settings.restitutionIterations;
  const n = buf.count;
  const vx = c.Velocity.x, vy = c.Velocity.y, vz = c.Velocity.z;
  const invMass = cs.invMass;
  const A = buf.a, B = buf.b, NX = buf.nx, NY = buf.ny, NZ = buf.nz;
  const NM = buf.normalMass, E = buf.restitution, RV = buf.relativeVelocity, IV = buf.impactVelocity;
  const MAXN = buf.maxNormalImpulse, TOT = buf.totalNormalImpulse;
  // Reuse relativeVelocity as the target speed and maxNormalImpulse as the rebound's accumulated
  // impulse (both are spent by now); a negative target marks a contact that takes no part.
  // A contact that closed its gap only in the last substep may still be approaching: the impulse to
  // stop that is part of its compression, so it counts toward the cap too.
  let bouncing = 0;
  for (let i = 0; i < n; i++) {
    const e = E[i]!;
    if (MAXN[i] === 0) { RV[i] = -1; continue; }
    MAXN[i] = 0;
    if (e > 0 && RV[i]! < -threshold) {
      RV[i] = -e * IV[i]!;
      const a = A[i]!, b = B[i]!;
      const vn = (vx[b]! - vx[a]!) * NX[i]! + (vy[b]! - vy[a]!) * NY[i]! + (vz[b]! - vz[a]!) * NZ[i]!;
      const stop = vn < 0 ? -NM[i]! * vn : 0;
      TOT[i] = stop + e * (TOT[i]! + stop);
      bouncing++;
    } else RV[i] = 0;
  }
  if (bouncing === 0) return;
  for (let it = 0; it < iterations; it++) {
    for (let i = 0; i < n; i++) {
      const target = RV[i]!;
      if (target < 0) continue;
      const a = A[i]!, b = B[i]!;
      const nx = NX[i]!, ny = NY[i]!, nz = NZ[i]!;
      const vn = (vx[b]! - vx[a]!) * nx + (vy[b]! - vy[a]!) * ny + (vz[b]! - vz[a]!) * nz;
      const old = MAXN[i]!;
      let acc = old - NM[i]! * (vn - target);
      if (acc < 0) acc = 0;
      if (target > 0 && acc > TOT[i]!) acc = TOT[i]!;
      const dl = acc - old;
      if (dl === 0) continue;
      MAXN[i] = acc;
      const imA = invMass[a]!, imB = invMass[b]!;
      vx[a] = vx[a]! - imA * dl * nx; vy[a] = vy[a]! - imA * dl * ny; vz[a] = vz[a]! - imA * dl * nz;
      vx[b] = vx[b]! + imB * dl * nx; vy[b] = vy[b]! + imB * dl * ny; vz[b] = vz[b]! + imB * dl * nz;
    }
  }
  vx[0] = 0; vy[0] = 0; vz[0] = 0;
}
