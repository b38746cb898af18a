/**
 * The 3D shapes' and joints' feature: their collision system (collide stage), the contact solver's 3D
 * rows and the sleep system's 3D islands, installed into a world when it gets its first 3D shape or
 * joint (addShape3D, the add*Joint3D functions) or restores a snapshot. A program that never makes
 * one never reaches this module, so a bundler leaves the 3D shapes, manifolds and joints out.
 */

import { setIslands3D } from '../islands/hooks-3d.js';
import { addContactEdges3D, wakeTouching3D, withShape3DBodies } from '../islands/shapes-3d.js';
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
import { setRows3D } from '../solver/rows-3d.js';
import { installSystem } from '../world/install.js';
import type { PhysicsWorld } from '../world/options.js';
import { trustFiniteOutput } from '../world/trusted-systems.js';
import { shape3DCollisionSystem } from './shapes-3d.js';

let loaded = false;

/**
 * Installs the 3D shapes' and joints' systems into `world` (idempotent): `shape3DCollisionSystem` in
 * the collide stage at its place (world/install.ts), and, once for the program, the contact solver's 3D
 * rows and the sleep system's 3D islands.
 * @category Collision
 */
export function install3D(world: PhysicsWorld): void {
  if (!loaded) {
    loaded = true;
    setRows3D({
      joints3DToSolve,
      gatherJoint3DBodies,
      prepareJoints3D,
      warmStartJoints3D,
      solveJoints3D,
      finishJoints3D,
      manifolds3DToSolve,
      gatherManifold3DBodies,
      prepareManifolds3D,
      finishManifolds3D,
      warmStartManifolds3D,
      solveManifolds3D,
      applyManifold3DRestitution,
    });
    setIslands3D({
      withShape3DBodies,
      addIslandEdges3D: (w, e) => {
        addContactEdges3D(w, e);
        addJointEdges3D(w, e);
      },
      wakeTouching3D,
    });
    // Trusted (step/finite.ts) only while it has nothing to collide, when it writes nothing.
    trustFiniteOutput([shape3DCollisionSystem], 'all', (w) => w.dimensions !== 3 || shapes3DOf(w)?.active !== true);
  }
  installSystem(world, 'collide', 'shapes3D', shape3DCollisionSystem);
}
