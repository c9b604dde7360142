import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { dirname, join, posix } from 'node:path';

/** The repository's root, from this file (tests/support/). */
export const REPO_ROOT = join(import.meta.dirname, '..', '..');

/** The longest a doc may be: past it, a doc is split by concept. */
export const MAX_DOC_LINES = 500;

/** README.md and every Markdown file in docs/, as paths from the repository root. */
export function docFiles(root = REPO_ROOT): string[] {
  const docs = readdirSync(join(root, 'docs'))
    .filter((name) => name.endsWith('.md'))
    .map((name) => `docs/${name}`);
  return ['README.md', ...docs.sort()];
}

// The folders a doc cites files in, from the repository root. dist/ is left out: it is what a
// build writes, so it exists only after one.
const CITED_FOLDERS = 'src|shaders|tests|scripts|docs|examples|course|public|figures|findings';
const ROOTED_PATH = new RegExp(`(?<![\\w./*-])((?:${CITED_FOLDERS})/[\\w./*+-]*[\\w*/])`, 'g');
// Markdown link targets and HTML src/href attributes, relative to the doc that holds them.
const LINK_TARGET = /\]\(([^)\s#]+)(?:#[^)]*)?\)|\b(?:src|href)="([^"#]+)(?:#[^"]*)?"/g;

/** A file or folder a doc names, and the paths (from the root) it may be read as. */
export interface CitedPath {
  cited: string;
  candidates: string[];
}

/**
 * Every file or folder path `text` (the doc at `docPath`) cites: paths under the project's
 * folders, read from the root or from the doc's own folder, and relative link targets.
 */
export function citedPaths(text: string, docPath: string): CitedPath[] {
  const docDir = posix.dirname(docPath);
  const found = new Map<string, CitedPath>();
  for (const match of text.matchAll(ROOTED_PATH)) {
    const cited = match[1];
    found.set(cited, { cited, candidates: [cited, posix.join(docDir, cited)] });
  }
  // A fenced block's links are an example page's own (an iframe's src), not this repository's.
  const prose = text.replace(/^```[\s\S]*?^```/gm, '');
  for (const match of prose.matchAll(LINK_TARGET)) {
    const cited = match[1] ?? match[2];
    if (/^[a-z]+:/i.test(cited) || cited.startsWith('/')) continue;
    found.set(`link:${cited}`, { cited, candidates: [posix.join(docDir, cited)] });
  }
  return [...found.values()];
}

/** Whether a path exists under `root`; a `*` in its last part matches any run of characters. */
export function pathExists(path: string, root = REPO_ROOT): boolean {
  if (!path.includes('*')) return existsSync(join(root, path));
  const folder = join(root, dirname(path));
  if (!existsSync(folder)) return false;
  const last = path.slice(path.lastIndexOf('/') + 1);
  const pattern = new RegExp(`^${last.replace(/[.+?^${}()|[\]\\]/g, '\\$&').replace(/\*/g, '.*')}$`);
  return readdirSync(folder).some((name) => pattern.test(name));
}

/** The paths a doc cites that exist nowhere in the tree, as "doc: path". */
export function missingPaths(text: string, docPath: string, root = REPO_ROOT): string[] {
  return citedPaths(text, docPath)
    .filter((path) => !path.candidates.some((candidate) => pathExists(candidate, root)))
    .map((path) => `${docPath}: ${path.cited}`);
}

/** The number of lines of a text, as `wc -l` counts them for a file that ends in a newline. */
export function lineCount(text: string): number {
  return text.endsWith('\n') ? text.split('\n').length - 1 : text.split('\n').length;
}

/** The docs longer than MAX_DOC_LINES, as "doc: lines". */
export function overlongDocs(docs: Record<string, string>): string[] {
  return Object.entries(docs)
    .filter(([, text]) => lineCount(text) > MAX_DOC_LINES)
    .map(([path, text]) => `${path}: ${lineCount(text)}`);
}

/** Every number `text` puts directly before `noun` (e.g. "40 lessons"). */
export function statedCounts(text: string, noun: string): number[] {
  return [...text.matchAll(new RegExp(`\\b(\\d+) ${noun}\\b`, 'g'))].map((match) => Number(match[1]));
}

/** A file of the repository, read as text. */
export function readRepoFile(path: string, root = REPO_ROOT): string {
  return readFileSync(join(root, path), 'utf8');
}

// A commit hash as git abbreviates it: 7 to 40 hex digits, with at least one digit and one
// letter, so that plain numbers ("2147483647") and hex-letter words ("decade") are not taken.
const COMMIT_HASH = /\b(?=[0-9a-f]*[0-9])(?=[0-9a-f]*[a-f])[0-9a-f]{7,40}\b/g;
// A calendar date, as 2026-11-27 or as 27 Nov 2026.
const DATE = /\b\d{4}-\d{2}-\d{2}\b|\b\d{1,2} (?:Jan|Feb|Mar|Apr|May|Jun|Jul|Aug|Sep|Oct|Nov|Dec)[a-z]* \d{4}\b/g;

/**
 * The history a doc carries in its prose, as "doc: mark": commit hashes other than the
 * `allowedHashes` (a baseline a budget is defined against) and calendar dates. Git keeps the
 * history; a doc says what the code does now.
 */
export function historyMarks(text: string, docPath: string, allowedHashes: readonly string[]): string[] {
  const hashes = [...text.matchAll(COMMIT_HASH)].map((match) => match[0]).filter((hash) => !allowedHashes.includes(hash));
  const dates = [...text.matchAll(DATE)].map((match) => match[0]);
  return [...hashes, ...dates].map((mark) => `${docPath}: ${mark}`);
}
