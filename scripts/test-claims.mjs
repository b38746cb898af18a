// The vitest runner of the `node` project (vitest.config.ts): vitest's own, plus a claim on each test
// file just before it runs, so that two vitest processes can share one list of files (scripts/test.mjs
// starts a second `node` lane when the browser lane has finished). With BITPHYSICS_TEST_CLAIMS set to
// a folder, a file runs in the process that first creates its entry there (an exclusive create, so
// exactly one does); the other process reports the file as skipped. Without it, every file runs.
import { writeFileSync } from 'node:fs';
import { join, relative } from 'node:path';
import { TestRunner } from 'vitest';

/**
 * The claim folder's entry of a test file: its path from the repository root with `/` as `__`
 * (scripts/test.mjs reads the entries back the same way).
 * @param {string} root the repository root. @param {string} file the test file's absolute path.
 */
function claimName(root, file) {
  return relative(root, file).replaceAll('\\', '/').replaceAll('/', '__');
}

/** Marks a task and everything under it skipped. */
function skipAll(task) {
  task.mode = 'skip';
  task.result = { state: 'skip' };
  for (const child of task.tasks ?? []) skipAll(child);
}

/** vitest's runner, claiming each file before it runs (see the top of this file). */
export default class ClaimingRunner extends TestRunner {
  /** Claims `suite` if it is a file (and skips it if the other lane has), then runs vitest's hook. */
  async onBeforeRunSuite(suite) {
    const claims = process.env.BITPHYSICS_TEST_CLAIMS;
    if (claims && suite.file === suite) {
      try {
        writeFileSync(join(claims, claimName(this.config.root, suite.filepath)), process.env.BITPHYSICS_TEST_LANE ?? '', { flag: 'wx' });
      } catch (error) {
        if (error.code !== 'EEXIST') throw error;
        skipAll(suite); // the other lane runs it
      }
    }
    return super.onBeforeRunSuite(suite);
  }
}
