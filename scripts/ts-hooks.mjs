// Node module customization hooks that let Node's own loader run this repository's TypeScript, for
// the headless tests (vitest.config.ts: the `node` project imports its files with Node's `import`,
// experimental.viteModuleRunner false; ./ts-register.mjs registers these hooks in each worker).
// Vite's module runner reads every imported name as a property of the imported module's object, in
// every pass of a hot loop; under Node's loader a module's imports are its own bindings, as in the
// packages' dist/ and the pages. The sources import each other as './x.js' (TypeScript's style for
// ES modules): `resolve` finds the x.ts beside it.
import { existsSync, readFileSync } from 'node:fs';
import { dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import * as esbuild from 'esbuild';
import { inlineConstantModules, isConstantModule, isPackageSource, relativeImports } from './build.mjs';

/**
 * Resolves as Node does; a relative or file specifier Node cannot find is tried as TypeScript:
 * './x.js' as './x.ts', './x' as './x.ts' or './x/index.ts'.
 */
export async function resolve(specifier, context, next) {
  try {
    return await next(specifier, context);
  } catch (error) {
    const relative = specifier.startsWith('.') || specifier.startsWith('/') || specifier.startsWith('file:');
    if (error?.code !== 'ERR_MODULE_NOT_FOUND' || !relative || context.parentURL === undefined) throw error;
    for (const candidate of [specifier.replace(/\.js$/, '.ts'), `${specifier}.ts`, `${specifier}/index.ts`]) {
      if (candidate === specifier) continue;
      const url = new URL(candidate, context.parentURL);
      if (existsSync(fileURLToPath(url))) return { url: url.href, format: 'module', shortCircuit: true };
    }
    throw error;
  }
}

/**
 * Loads a .ts or .mts file as an ES module transpiled by esbuild, with an inline source map (test
 * failures point into the TypeScript). A package source that imports a layout module of constants
 * gets them folded in, as the packages' dist/, the bench and the pages have them (scripts/build.mjs
 * inlineConstantModules, minifySyntax); its other imports are kept. Any other file loads as Node loads it.
 */
export async function load(url, context, next) {
  if (!url.startsWith('file:') || !/\.m?ts$/.test(new URL(url).pathname)) return next(url, context);
  const file = fileURLToPath(url);
  const code = readFileSync(file, 'utf8');
  if (isPackageSource(file) && relativeImports(file, code).some(isConstantModule)) {
    const out = await esbuild.build({
      entryPoints: [file],
      bundle: true,
      write: false,
      minifySyntax: true,
      plugins: [inlineConstantModules()],
      format: 'esm',
      platform: 'neutral',
      target: 'node20',
      sourcemap: 'inline',
      outdir: dirname(file),
      logLevel: 'error',
    });
    return { format: 'module', source: out.outputFiles.find((f) => f.path.endsWith('.js')).text, shortCircuit: true };
  }
  const { code: js } = await esbuild.transform(code, {
    loader: 'ts',
    format: 'esm',
    target: 'node20',
    sourcemap: 'inline',
    sourcefile: file,
  });
  return { format: 'module', source: js, shortCircuit: true };
}
