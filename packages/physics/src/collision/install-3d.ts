/**
 * The 3D shapes' and joints' feature: their collision system (collide stage), the contact solver's 3D
 * rows and the 3D joints' island edges, installed into a world when it gets its first 3D shape or
 * joint (addShape3D, the add*Joint3D functions) or restores a snapshot. A program that never makes
 * one never reaches this module, so a bundler leaves the 3D shapes, manifolds and joints out.
 */

import { setJointEdges3D } from '../islands/edges.js';
import {
  finishJoints3D,
  gatherJoint3DBodies,
  joints3DToSolve,
  prepareJoints3D,
  solveJoints3D,
  warmStartJoints3D,
} from '../joints/solver-3d.js';
import { addJointEdges3D } from '../joints/store-3d.js';
import { shapes3DOf } from '../shapes/store-3d.js';
import { prepareManifolds3D } from '../solver/manifold-prepare-3d.js';
import { finishManifolds3D, gatherManifold3DBodies, manifolds3DToSolve } from '../solver/manifold-rows-3d.js';
import { applyManifold3DRestitution, solveManifolds3D, warmStartManifolds3D } from '../solver/manifold-solve-3d.js';
import { setRowFamily } from '../solver/row-families.js';
import { installSystem } from '../world/install.js';
import type { PhysicsWorld } from '../world/options.js';
import { trustFiniteOutput } from '../world/trusted-systems.js';
import { shape3DCollisionSystem } from './shapes-3d.js';

let loaded = false;

/**
 * Installs the 3D shapes' and joints' systems into `world` (idempotent): `shape3DCollisionSystem` in
 * the collide stage at its place (world/install.ts), and, once for the program, the contact solver's 3D
 * rows and the 3D joints' island edges.
 * @category Collision
 */
export function install3D(world: PhysicsWorld): void {
  if (!loaded) {
    loaded = true;
    setRowFamily('joints3D', {
      dimensions: 3,
      pushesUnmarked: false,
      toSolve: joints3DToSolve,
      gather: gatherJoint3DBodies,
      prepare: prepareJoints3D,
      warmStart: warmStartJoints3D,
      solve: (w, hs, useBias) => solveJoints3D(w, hs, useBias),
      integrate: () => {},
      endSubstep: () => {},
      restitution: () => {},
      finish: finishJoints3D,
    });
    setRowFamily('manifolds3D', {
      dimensions: 3,
      pushesUnmarked: false,
      toSolve: manifolds3DToSolve,
      gather: gatherManifold3DBodies,
      prepare: (w) => prepareManifolds3D(w),
      warmStart: warmStartManifolds3D,
      solve: (w, hs, useBias) => solveManifolds3D(w, hs, useBias),
      integrate: () => {},
      endSubstep: () => {},
      restitution: applyManifold3DRestitution,
      finish: finishManifolds3D,
    });
    setJointEdges3D(addJointEdges3D);
    // Trusted (step/finite.ts) only while it has nothing to collide, when it writes nothing.
    trustFiniteOutput([shape3DCollisionSystem], 'all', (w) => w.dimensions !== 3 || shapes3DOf(w)?.active !== true);
  }
  installSystem(world, 'collide', 'shapes3D', shape3DCollisionSystem);
}
