/**
 * A mistake on the command line (unknown scene, engine or flag; a value that is not an integer or
 * is out of range). The CLI prints its message and exits with code 2.
 */
export class UsageError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'UsageError';
  }
}

/** Exit code for usage errors. */
export const USAGE_EXIT_CODE = 2;
