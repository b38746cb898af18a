// `npm start`: builds src/ into dist/ with esbuild and serves it on http://127.0.0.1:8000 (another
// port with --port N or PORT), building again on every request after a source file changed.
import { context } from 'esbuild';
import { options } from './build.mjs';

const at = process.argv.indexOf('--port');
const port = Number(at >= 0 ? process.argv[at + 1] : (process.env.PORT ?? 8000));
const ctx = await context(options());
const { hosts, port: bound } = await ctx.serve({ host: '127.0.0.1', port, servedir: 'dist' });
console.log(`serving the game on http://${hosts[0] ?? '127.0.0.1'}:${bound}/ (Ctrl+C stops)`);
