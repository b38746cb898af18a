/**
 * The one rule every contact row family uses to pick its softness (ball rows 2D and 3D:
 * solver/prepare-contacts-kernel.ts, read by solver/ball-sweeps.ts and the coloured solve; 2D manifolds:
 * solver/manifold-rows-2d.ts; 3D manifolds: solver/manifold-solve-3d.ts). Self-contained (kernels reach
 * it as KERNEL_HELPERS 19, solver/kernel-helpers.ts; the workers get its source text).
 */

/**
 * 1 if a contact row between bodies of inverse masses `invMassA` and `invMassB` (1/kg, >= 0, as the
 * solver state holds them) is against an infinite-mass partner, else 0. A static body, the static world
 * (solver row 0), a sleeping body and a kinematic body all have inverse mass 0 in the solver: none of
 * them takes the contact's impulse, so the row is a spring on the moving body alone, as against the
 * ground, and takes the stiffer softness (twice the contact stiffness, solver/contact-point.ts
 * prepareContactSoftness). Erin Catto's soft step (solver2d, solve_common.c s2PrepareContacts_Soft)
 * doubles the stiffness by this test, mA == 0 || mB == 0; Box2D v3 itself tests whether a body is
 * outside the awake set (static only), so there a kinematic partner is soft.
 * @category Collision
 */
export function rigidPartner(invMassA: number, invMassB: number): number {
  return invMassA === 0 || invMassB === 0 ? 1 : 0;
}
