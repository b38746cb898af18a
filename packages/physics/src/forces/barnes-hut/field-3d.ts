/**
 * The layout of a 3D node's local field polynomial in a part's walk scratch (GravityTree.scratch,
 * forces/barnes-hut/walk.ts): node k's at k * STRIDE, the field about the cell's centre of mass c as a
 * polynomial in the offset d from c, a(d) = a0 + J d + K d d / 2, without the factor G
 * (forces/barnes-hut/tree.ts). The walk (walk-kernel.ts) adds the cell-cell expansions into it, and its
 * downward pass shifts it to the children and evaluates it at the bodies. Imported as `L3`
 * (`L[l + L3.JXY]`). A module of numeric constants only, which every build folds into the code that
 * reads it, the thread kernels included (threads/worker-source.ts).
 */

/** a0 x: the field at c without G, kg/m^2. */
export const A0X = 0;
/** a0 y, kg/m^2. */
export const A0Y = 1;
/** a0 z, kg/m^2. */
export const A0Z = 2;
/** J_xx: the field's gradient at c without G, kg/m^3. */
export const JXX = 3;
/** J_yy, kg/m^3. */
export const JYY = 4;
/** J_zz, kg/m^3. */
export const JZZ = 5;
/** J_xy, kg/m^3. */
export const JXY = 6;
/** J_xz, kg/m^3. */
export const JXZ = 7;
/** J_yz, kg/m^3. */
export const JYZ = 8;
/** K_xxx: the field's second derivatives at c without G, kg/m^4 (K_xxx to K_zzz are the last ten numbers). */
export const KXXX = 9;
/** K_xxy, kg/m^4. */
export const KXXY = 10;
/** K_xxz, kg/m^4. */
export const KXXZ = 11;
/** K_xyy, kg/m^4. */
export const KXYY = 12;
/** K_xyz, kg/m^4. */
export const KXYZ = 13;
/** K_xzz, kg/m^4. */
export const KXZZ = 14;
/** K_yyy, kg/m^4. */
export const KYYY = 15;
/** K_yyz, kg/m^4. */
export const KYYZ = 16;
/** K_yzz, kg/m^4. */
export const KYZZ = 17;
/** K_zzz, kg/m^4. */
export const KZZZ = 18;
/** Numbers a node's polynomial. */
export const STRIDE = 19;
