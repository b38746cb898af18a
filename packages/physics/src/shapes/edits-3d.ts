/**
 * Counts the writes to any world's 3D shape placements and sizes (addShape3D, updateMassFromShapes3D, a
 * snapshot's restore): the collide stage keeps a sleeping collider's pose from its last pass only while
 * this count is unchanged (collision/colliders-3d.ts keptPose). Shared by every world; only increases.
 * (A module of its own, importing nothing: the snapshot restore bumps it without registering the store.)
 * @category Shapes
 */
export const shapeEdits = { count: 0 };
