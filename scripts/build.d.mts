// Types of the parts of scripts/build.mjs that TypeScript files import (vitest.config.ts).
import type { Plugin } from 'esbuild';

/** Whether `file` (a .ts path) holds only `export const NAME = number` declarations: a layout module to fold. */
export function isConstantModule(file: string): boolean;
/** The esbuild plugin that bundles constant modules into their importers and keeps every other import. */
export function inlineConstantModules(): Plugin;
