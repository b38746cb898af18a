/**
 * The README's code blocks that carry a file name (an info string such as ```` ```ts file=main.ts ````),
 * so tests can write them out and check them: the README is their source and cannot rot.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { repoRoot } from '../browser/chromium.mjs';

/** One named code block: its language, the file name after `file=`, and its text. */
export interface ReadmeBlock {
  lang: string;
  file: string;
  code: string;
}

/**
 * Every fenced block of `markdown` whose info string has `file=<name>`, in order.
 * @throws Error if two blocks name the same file or a fence is not closed.
 */
export function namedBlocks(markdown: string): ReadmeBlock[] {
  const blocks: ReadmeBlock[] = [];
  const seen = new Set<string>();
  const lines = markdown.split('\n');
  for (let i = 0; i < lines.length; i++) {
    const open = /^```(\w+)\s+file=(\S+)\s*$/.exec(lines[i]!);
    if (!open) continue;
    const body: string[] = [];
    let j = i + 1;
    for (; j < lines.length && lines[j] !== '```'; j++) body.push(lines[j]!);
    if (j >= lines.length) throw new Error(`README block ${open[2]} is not closed`);
    const file = open[2]!;
    if (seen.has(file)) throw new Error(`README names ${file} twice`);
    seen.add(file);
    blocks.push({ lang: open[1]!, file, code: `${body.join('\n')}\n` });
    i = j;
  }
  return blocks;
}

/** The named blocks of the repository's README.md, by file name. */
export function readmeBlocks(): Map<string, ReadmeBlock> {
  const blocks = namedBlocks(readFileSync(join(repoRoot, 'README.md'), 'utf8'));
  return new Map(blocks.map((b) => [b.file, b]));
}
