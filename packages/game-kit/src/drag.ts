/**
 * Dragging bodies with the pointer through a mouse joint (Box2D's way): press on or near a body to
 * grab it at that point, move to pull it (a soft spring of limited force, so it swings and collides
 * on the way), release to let go. Works on any 2D game's canvas and camera.
 */
import { addMouseJoint, handleOf, isAlive, Not, type PhysicsWorld, query, removeJoint, setMouseTarget } from '@bitphysics/physics';
import type { Camera } from '@bitphysics/render-pixi';
import { pointerOnCanvas } from './pointer.js';

/** Options of `enableMouseDrag`. */
export interface MouseDragOptions {
  /** Farthest from a body's centre a press still grabs it, m (plus its radius if it is a ball). Default 0.5 m. */
  reach?: number;
  /** Stiffness of the pull, Hz. Default 5. */
  hertz?: number;
  /** Largest pulling force as a multiple of the body's weight m |g| (at least m 10 m/s^2). Default 50. */
  strength?: number;
  /** Whether a press may start a drag now (e.g. false while another tool is active). Default always. */
  enabled?: () => boolean;
}

/** The live drag (also useful to tests): the joint's handle, or 0 when nothing is held. */
export interface MouseDrag {
  readonly joint: number;
  readonly body: number;
  /** Lets go (removes the joint). */
  release(): void;
}

/**
 * Lets the pointer drag any dynamic body of `world()` on `canvas` (camera `camera()` maps pixels to
 * metres). @returns the drag state.
 */
export function enableMouseDrag(
  canvas: HTMLCanvasElement,
  world: () => PhysicsWorld,
  camera: () => Camera,
  options: MouseDragOptions = {},
): MouseDrag {
  const reach = options.reach ?? 0.5,
    hertz = options.hertz ?? 5,
    strength = options.strength ?? 50;
  const p = { x: 0, y: 0 };
  const state = { joint: 0, body: 0, world: null as PhysicsWorld | null };
  const toWorld = (e: PointerEvent): [number, number] => {
    pointerOnCanvas(canvas, e, p);
    return [camera().toWorldX(p.x), camera().toWorldY(p.y)];
  };
  const release = (): void => {
    if (state.joint && state.world && isAlive(state.world, state.joint)) removeJoint(state.world, state.joint);
    state.joint = 0;
    state.body = 0;
    state.world = null;
  };
  canvas.addEventListener('pointerdown', (e) => {
    if (e.button !== 0 || (options.enabled && !options.enabled())) return;
    const w = world();
    const [x, y] = toWorld(e);
    const c = w.components;
    const bodies = query(w, [c.Position, c.Mass, c.Angle, Not(c.Static), Not(c.Kinematic)]);
    let best = 0,
      bestD = Infinity;
    for (let i = 0; i < bodies.length; i++) {
      const s = bodies[i]!;
      if (!(c.Mass.inv[s]! > 0)) continue;
      const r = c.Ball.radius.length > s ? c.Ball.radius[s]! : 0;
      const d = Math.hypot(c.Position.x[s]! - x, c.Position.y[s]! - y) - r;
      if (d < bestD) {
        bestD = d;
        best = s;
      }
    }
    if (best === 0 || bestD > reach) return;
    release();
    const g = Math.max(10, Math.hypot(w.gravity[0]!, w.gravity[1]!));
    const body = handleOf(w, best);
    state.joint = addMouseJoint(w, {
      b: body,
      anchor: [x, y],
      target: [x, y],
      hertz,
      dampingRatio: 0.7,
      maxForce: strength * c.Mass.value[best]! * g,
    });
    state.body = body;
    state.world = w;
    canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener('pointermove', (e) => {
    if (!state.joint || !state.world) return;
    if (state.world !== world() || !isAlive(state.world, state.joint)) {
      state.joint = 0;
      state.body = 0;
      return;
    }
    setMouseTarget(state.world, state.joint, toWorld(e));
  });
  const up = (): void => release();
  canvas.addEventListener('pointerup', up);
  canvas.addEventListener('pointercancel', up);
  return {
    get joint() {
      return state.joint;
    },
    get body() {
      return state.body;
    },
    release,
  };
}
