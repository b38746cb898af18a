/**
 * The layout of a convex hull's edge list (Hull.edges, shapes/hull-3d.ts): edge e's four indices at
 * e * EDGE_STRIDE, an edge between two polygonal faces. A module of numeric constants only, which
 * every build folds into the code that reads it (scripts/build.mjs isConstantModule).
 */

/** The edge's first vertex (an index into the hull's vertices; the smaller of the two). */
export const EDGE_U = 0;
/** The edge's second vertex. */
export const EDGE_V = 1;
/** The polygonal face holding u -> v counter-clockwise seen from outside (an index into the faces). */
export const EDGE_LEFT = 2;
/** The other polygonal face at the edge. */
export const EDGE_RIGHT = 3;
/** Numbers an edge. */
export const EDGE_STRIDE = 4;
