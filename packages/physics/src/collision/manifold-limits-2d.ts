/**
 * The most 2D manifolds a step may hold: 2^24 (their solver rows alone would take 5.5 GB).
 * growManifoldBuffer (collision/manifolds-2d.ts) refuses more, and the solver's loops over the rows are
 * bounded by it, so V8 computes their row offsets in 32-bit integers without overflow checks.
 *
 * A module of numeric constants only, which every build folds into the code that reads it
 * (scripts/build.mjs isConstantModule).
 */

/** Most manifolds a step may hold. */
export const MAX_MANIFOLDS = 16777216;
