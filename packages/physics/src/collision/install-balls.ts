/**
 * The balls' collision feature: the ball broadphase and narrowphase (collide stage) and the contact
 * solver's ball rows (solver/ball-rows.ts), installed into a world when it gets its first ball
 * (`addBody` or `addParticle` with a radius, `setRadius`, an emitter whose particles collide) or
 * restores a snapshot. A program that never makes a ball never reaches this module, so a bundler
 * leaves the ball contacts, the impact stage and the coloured solve out of a game of shapes and joints.
 */

import { ballContactEvents } from '../solver/ball-events.js';
import {
  approachBallRows,
  ballRestitution,
  endBallSubstep,
  gatherBallBodies,
  planBallRows,
  prepareBallRows,
  solveBallRows,
  storeBallRows,
  warmStartBallRows,
} from '../solver/ball-rows.js';
import { setRowFamily } from '../solver/row-families.js';
import { installSystem } from '../world/install.js';
import type { PhysicsWorld } from '../world/options.js';
import { trustFiniteOutput } from '../world/trusted-systems.js';
import { broadphaseSystem } from './broadphase/grid.js';
import { narrowphaseSystem } from './narrowphase/balls.js';

let loaded = false;

/**
 * Installs the balls' collision into `world` (idempotent): `broadphaseSystem` and `narrowphaseSystem`
 * in the collide stage at their places (world/install.ts), and, once for the program, the contact
 * solver's ball rows. The package's functions that make a ball call it; call it yourself only if you
 * give an entity the `Ball` component with `addComponent` (`step` throws until you do).
 * @param world - The world to install into; it is left unchanged if the balls' systems are in it already.
 * @category Collision
 */
export function installBalls(world: PhysicsWorld): void {
  if (!loaded) {
    loaded = true;
    // The ball rows' stages read the step's contact buffer (solver/ball-rows.ts).
    setRowFamily('balls', {
      dimensions: 0,
      pushesUnmarked: false,
      toSolve: (w) => w.collision.contacts.count > 0,
      gather: (w, count) => gatherBallBodies(w, w.collision.contacts, count),
      prepare: (w) => prepareBallRows(w, w.collision.contacts),
      warmStart: (w) => warmStartBallRows(w, w.collision.contacts),
      solve: (w, _hs, useBias) => solveBallRows(w, w.collision.contacts, useBias),
      integrate: () => {},
      endSubstep: (w) => endBallSubstep(w.collision.contacts),
      restitution: (w) => ballRestitution(w, w.collision.contacts),
      finish: () => {},
      approach: approachBallRows,
      plan: planBallRows,
      events: ballContactEvents,
      store: storeBallRows,
    });
    // The broadphase and narrowphase write only pairs and contacts (step/finite.ts).
    trustFiniteOutput([broadphaseSystem, narrowphaseSystem]);
  }
  world.collision.looseBall = 0;
  installSystem(world, 'collide', 'broadphase', broadphaseSystem);
  installSystem(world, 'collide', 'narrowphase', narrowphaseSystem);
}
