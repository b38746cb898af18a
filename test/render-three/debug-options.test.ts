/**
 * The renderers' debug options, checked by render-common's table-driven `resolveOptions`: the defaults
 * are the ones `DebugOptions` documents, a given value wins, and bad input is refused with the
 * caller's name, the option and the value (the contract of every public API here).
 */
import { describe, expect, it } from 'vitest';
import { type OptionRules, resolveOptions } from '../../packages/render-common/src/index';
import { resolveDebugOptions } from '../../packages/render-three/src/index';

describe('resolveOptions', () => {
  interface Opts {
    on?: boolean;
    scale?: number;
    most?: number;
  }
  const rules: OptionRules<Opts> = {
    on: { kind: 'boolean', default: true },
    scale: { kind: 'positive', default: 0.5 },
    most: { kind: 'integer', default: 10, min: 0, max: 100 },
  };
  const bad = (o: unknown): Opts => o as Opts;
  it('fills defaults and keeps given values', () => {
    expect(resolveOptions('f', 'o.', {}, rules)).toEqual({ on: true, scale: 0.5, most: 10 });
    expect(resolveOptions('f', 'o.', { on: false, most: 0 }, rules)).toEqual({ on: false, scale: 0.5, most: 0 });
  });
  it('names the caller, the option and the value', () => {
    expect(() => resolveOptions('f', 'o.', { most: 101 }, rules)).toThrow(/^f: o\.most .*101/);
    expect(() => resolveOptions('f', 'o.', { scale: 0 }, rules)).toThrow(/^f: o\.scale must be > 0, got 0/);
    expect(() => resolveOptions('f', 'o.', bad({ on: 1 }), rules)).toThrow(TypeError);
    expect(() => resolveOptions('f', 'o.', bad({ nope: 1 }), rules)).toThrow(/nope/);
  });
});

describe('render-three resolveDebugOptions', () => {
  it('has the documented defaults', () => {
    expect(resolveDebugOptions('WorldRenderer3D.setDebug')).toEqual({
      axes: true,
      velocities: true,
      velocityScale: 0.1,
      angularVelocities: false,
      angularVelocityScale: 0.1,
      maxBodies: 2000,
      contacts: true,
      normalLength: 0.25,
      maxContacts: 4000,
      pointSize: 5,
      springs: true,
      joints: true,
      planes: true,
      fields: true,
      emitters: true,
      maxScenery: 20_000,
    });
  });
  it('refuses a bad value naming it', () => {
    expect(() => resolveDebugOptions('WorldRenderer3D.setDebug', { maxBodies: 100_001 })).toThrow(
      /WorldRenderer3D\.setDebug: debug\.maxBodies/,
    );
  });
});
