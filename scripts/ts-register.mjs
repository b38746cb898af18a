// Registers ./ts-hooks.mjs (Node runs this file's TypeScript) in the process that imports it first:
// vitest.config.ts passes `--import ./scripts/ts-register.mjs` to the headless tests' workers.
import { register } from 'node:module';

register('./ts-hooks.mjs', import.meta.url);
