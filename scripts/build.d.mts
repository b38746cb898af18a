// Types of the parts of scripts/build.mjs that TypeScript files import (vitest.config.ts).
import type { Plugin } from 'esbuild';

/** Whether `file` (a .ts path) holds only `export const NAME = number` declarations: a layout module to fold. */
export function isConstantModule(file: string): boolean;
/** The esbuild plugin that bundles constant modules into their importers and keeps every other import. */
export function inlineConstantModules(): Plugin;
/** Whether `file` (an absolute path) is a TypeScript source of a workspace package (packages/<name>/src/**.ts, not .d.ts). */
export function isPackageSource(file: string): boolean;
/** The files the module `code` at `file` imports by a relative path, as absolute .ts paths. */
export function relativeImports(file: string, code: string): string[];
