/**
 * Argument checks for the API boundary: every message reads `<function>: <param> must be <rule>, got <value>`.
 *
 * @packageDocumentation
 * @module @bitphysics/physics/validate
 */
export * from '../../../packages/physics/src/validation/validate.js';
