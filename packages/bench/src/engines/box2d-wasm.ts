import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { pyramidLayout } from '@bitphysics/physics';
import { optimizedWasm } from './rapier2d.js';
import type { BodySnapshot, EngineAdapter, EngineInstance, SceneRunOptions } from './types.js';

// The module's typings describe the Emscripten factory loosely; the adapter uses a small part of it.
// biome-ignore lint/suspicious/noExplicitAny: the module ships no usable typings
type Box2D = any;

let box2d: Promise<Box2D> | undefined;

/**
 * Loads box2d-wasm (Box2D v2.4 compiled to WebAssembly with Emscripten) once. Its loader fetches the
 * .wasm file by URL, which Node's fetch refuses for a file path, so the binary is read from the
 * package and handed over (`wasmBinary`); V8 compiles it optimized up front like rapier's.
 */
function loadBox2d(): Promise<Box2D> {
  box2d ??= (async () => {
    optimizedWasm();
    // Loaded at run time with Node's own require (not bundled): its Emscripten glue reads __dirname.
    const load = createRequire(import.meta.url);
    const entry = load.resolve('box2d-wasm');
    const dir = entry.slice(0, entry.lastIndexOf('/') + 1);
    const factory = load('box2d-wasm') as (o: object) => Promise<Box2D>;
    return factory({ wasmBinary: readFileSync(`${dir}Box2D.simd.wasm`) });
  })();
  return box2d;
}

/**
 * box2d-wasm 7 (Box2D v2.4.1 in WebAssembly): `pyramid` with the layout of `pyramidLayout`, boxes as
 * dynamic bodies with polygon fixtures of 1 x 1 m where they touch (a core of 0.49 m half extents inside
 * Box2D's 0.01 m polygon skin; 1 kg each; friction 0.6, restitution 0), a static ground box, steps of 1/60 s with 8 velocity and 3 position iterations (Box2D's recommended values)
 * and sleeping allowed.
 */
export const box2dWasmEngine: EngineAdapter = {
  name: 'box2d-wasm',
  description: 'box2d-wasm (Box2D v2.4 compiled to WebAssembly), 8 velocity and 3 position iterations, sleeping allowed',
  async prepare(): Promise<void> {
    await loadBox2d();
  },
  supports(scene: string): boolean {
    return scene === 'pyramid';
  },
  async create(options: SceneRunOptions): Promise<EngineInstance> {
    if (options.scene !== 'pyramid') throw new RangeError(`box2d-wasm: does not support scene "${options.scene}"`);
    const B = await loadBox2d();
    const layout = pyramidLayout({ count: options.count });
    const made: Box2D[] = [];
    const vec = (x: number, y: number): Box2D => {
      const v = new B.b2Vec2(x, y);
      made.push(v);
      return v;
    };
    let world: Box2D | undefined = new B.b2World(vec(layout.gravity[0], layout.gravity[1]));
    const w = world;
    const groundDef = new B.b2BodyDef();
    groundDef.set_position(vec(0, -layout.groundHalf[1]));
    const groundShape = new B.b2PolygonShape();
    groundShape.SetAsBox(layout.groundHalf[0], layout.groundHalf[1]);
    const groundFixture = new B.b2FixtureDef();
    groundFixture.set_shape(groundShape);
    groundFixture.set_friction(layout.friction);
    groundFixture.set_restitution(layout.restitution);
    w.CreateBody(groundDef).CreateFixture(groundFixture);
    const shape = new B.b2PolygonShape();
    shape.SetAsBox(layout.half, layout.half);
    // Box2D v2 polygons carry a skin (m_radius, b2_polygonRadius = 0.01 m) around their vertices: a core
    // of half - skin makes the box the layout's 1 x 1 m where it touches, and the density is raised so
    // its mass (computed from the core) is the layout's.
    const skin: number = shape.get_m_radius(),
      core = layout.half - skin;
    shape.SetAsBox(core, core);
    const fixture = new B.b2FixtureDef();
    fixture.set_shape(shape);
    fixture.set_density(layout.density * (layout.half / core) ** 2);
    fixture.set_friction(layout.friction);
    fixture.set_restitution(layout.restitution);
    const def = new B.b2BodyDef();
    def.set_type(B.b2_dynamicBody);
    const n = layout.count;
    const bodies: Box2D[] = new Array(n);
    const p = layout.positions;
    for (let i = 0; i < n; i++) {
      def.set_position(vec(p[2 * i]!, p[2 * i + 1]!));
      const body = w.CreateBody(def);
      body.CreateFixture(fixture);
      bodies[i] = body;
    }
    made.push(groundDef, groundShape, groundFixture, shape, fixture, def);
    return {
      engine: 'box2d-wasm',
      notes: ['box2d-wasm 7.0.0 (Box2D 2.4.1): pyramid, dt 1/60 s, 8 velocity and 3 position iterations, sleeping allowed'],
      step(): void {
        w.Step(1 / 60, 8, 3);
      },
      stats() {
        let sleeping = 0;
        for (let i = 0; i < n; i++) if (!bodies[i].IsAwake()) sleeping++;
        return { bodies: n, contacts: null, extra: { sleeping } };
      },
      snapshot(): BodySnapshot {
        const positions = new Float64Array(2 * n);
        for (let i = 0; i < n; i++) {
          const t = bodies[i].GetPosition();
          positions[2 * i] = t.get_x();
          positions[2 * i + 1] = t.get_y();
        }
        return { dimensions: 2, count: n, positions };
      },
      dispose(): void {
        if (!world) return;
        B.destroy(world);
        for (const o of made) B.destroy(o);
        made.length = 0;
        world = undefined;
      },
    };
  },
};
