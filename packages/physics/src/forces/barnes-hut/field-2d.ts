/**
 * The layout of a 2D node's local field polynomial in a part's walk scratch (GravityTree.scratch,
 * forces/barnes-hut/walk.ts): node k's at k * STRIDE, the field about the cell's centre of mass c as a
 * polynomial in the offset d from c, a(d) = a0 + J d + K d d / 2 + H d d d / 6, without the factor G
 * (forces/barnes-hut/tree.ts). The walk (walk-kernel.ts) adds the cell-cell expansions into it, and its
 * downward pass shifts it to the children and evaluates it at the bodies. Imported as `L2`
 * (`L[l + L2.JXY]`). A module of numeric constants only, which every build folds into the code that
 * reads it, the thread kernels included (threads/worker-source.ts).
 */

/** a0 x: the field at c without G, kg/m^2. */
export const A0X = 0;
/** a0 y, kg/m^2. */
export const A0Y = 1;
/** J_xx: the field's gradient at c without G, kg/m^3. */
export const JXX = 2;
/** J_xy, kg/m^3. */
export const JXY = 3;
/** J_yy, kg/m^3. */
export const JYY = 4;
/** K_xxx: the field's second derivatives at c without G, kg/m^4. */
export const KXXX = 5;
/** K_xxy, kg/m^4. */
export const KXXY = 6;
/** K_xyy, kg/m^4. */
export const KXYY = 7;
/** K_yyy, kg/m^4. */
export const KYYY = 8;
/** H_xxxx: the field's third derivatives at c without G, kg/m^5. */
export const HXXXX = 9;
/** H_xxxy, kg/m^5. */
export const HXXXY = 10;
/** H_xxyy, kg/m^5. */
export const HXXYY = 11;
/** H_xyyy, kg/m^5. */
export const HXYYY = 12;
/** H_yyyy, kg/m^5. */
export const HYYYY = 13;
/** Numbers a node's polynomial. */
export const STRIDE = 14;
