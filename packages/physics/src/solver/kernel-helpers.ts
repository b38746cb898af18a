/**
 * The functions kernels call, by index: a module of its own so a program that runs the block loops
 * of the coloured solve on one thread does not bring in the whole kernel table (step/kernel-table.ts).
 */

import { rotateFrom } from '../math/quaternion.js';
import { awaitBlocks, claimBlock } from '../threads/block-claim.js';
import type { KernelHelper } from '../threads/kernel-types.js';
import { coloredBodies2D, coloredPack2D, coloredRows2D, coloredUnpack2D } from './coloring-kernel.js';
import { prepareRowMasses, prepareRowWarmStart } from './prepare-contacts-kernel.js';
import { restitutionCap, restitutionTarget } from './restitution.js';
import { rigidPartner } from './rigid-partner.js';
import {
  approachSpeeds,
  containBodies,
  deepestRow,
  finishBodyRows,
  restitutionRows,
  restitutionTargets,
  runUnitBlocks,
} from './stages-kernel.js';
import { stripLayout2D } from './strip-plan-kernel.js';
import { stripCut2D } from './strips-kernel.js';

/**
 * Functions kernels call, by index (passed to every kernel as its last argument; the workers get
 * their source text, like the kernels'): 0 to 3 the coloured contact solve's block loops
 * (solver/coloring-kernel.ts: pack, unpack, body stage, rows); 4 to 6 finishBodies's loops
 * (solver/stages-kernel.ts: bodies, boundary, deepest row); 7 and 8 restitutionColored's (targets,
 * a pass's block); 9 claimBlock (block-claim.ts: the next block a thread takes of a unit, for both of
 * those kernels); 10 stripCut2D and 11 stripLayout2D (solver/strips-kernel.ts and
 * solver/strip-plan-kernel.ts: the strip cut and the pack layout, for stripPlan2D); 12 approachSpeeds
 * (solver/stages-kernel.ts, for solveColored2D); 13 and 14 prepareContactRows' passes
 * (solver/prepare-contacts-kernel.ts: masses and material, warm start); 15 rotateFrom
 * (math/quaternion.ts, for finishBodies' 3D orientations); 16 awaitBlocks (block-claim.ts: a thread's
 * wait for the next unit, for the kernels of 9); 17 and 18 the restitution stage's one definition
 * (solver/restitution.ts: target and cap, for restitutionTargets); 19 rigidPartner (solver/rigid-partner.ts:
 * a row's softness rule, for prepareRowMasses); 20 runUnitBlocks (solver/stages-kernel.ts: a thread's share of a
 * unit's blocks, for solveColored2D and restitutionColored). A kernel's hot loops live here when the kernel runs
 * once a step: V8 then compiles the loops as whole functions with full type feedback.
 * @category Threads
 */
export const KERNEL_HELPERS: readonly KernelHelper[] = /* @__PURE__ */ Object.freeze([
  coloredPack2D,
  coloredUnpack2D,
  coloredBodies2D,
  coloredRows2D,
  finishBodyRows,
  containBodies,
  deepestRow,
  restitutionTargets,
  restitutionRows,
  claimBlock,
  stripCut2D,
  stripLayout2D,
  approachSpeeds,
  prepareRowMasses,
  prepareRowWarmStart,
  rotateFrom,
  awaitBlocks,
  restitutionTarget,
  restitutionCap,
  rigidPartner,
  runUnitBlocks,
]);
