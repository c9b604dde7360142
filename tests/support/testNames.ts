import { readdirSync } from 'node:fs';
import { join, relative } from 'node:path';
import ts from 'typescript';
import { REPO_ROOT } from './docChecks';

/** The longest a test's name may be: past it, the figures and detail go in a comment beside it. */
export const MAX_TEST_NAME_LENGTH = 110;

/** Every test source under tests/ (.ts, .mts, .mjs), as paths from the repository root. */
export function testSourceFiles(root = REPO_ROOT): string[] {
  const found: string[] = [];
  const walk = (folder: string): void => {
    for (const entry of readdirSync(folder, { withFileTypes: true })) {
      const path = join(folder, entry.name);
      if (entry.isDirectory()) walk(path);
      else if (/\.(ts|mts|mjs)$/.test(entry.name)) found.push(relative(root, path).replaceAll('\\', '/'));
    }
  };
  walk(join(root, 'tests'));
  return found.sort();
}

/** A test's or a suite's name as written, with the line it starts on (1-based). */
export interface TestName {
  name: string;
  line: number;
}

const TEST_CALLS = new Set(['it', 'test', 'describe']);

/** The called name under modifiers and `.each(...)`: `it`, `it.skip`, `describe.each(rows)` all give their root. */
function calleeRoot(expression: ts.Expression): string | undefined {
  if (ts.isIdentifier(expression)) return expression.text;
  if (ts.isPropertyAccessExpression(expression)) return calleeRoot(expression.expression);
  if (ts.isCallExpression(expression)) return calleeRoot(expression.expression);
  return undefined;
}

/**
 * The names of every `it`, `test` and `describe` (with `.each`, `.skip`, `.only` …) in a
 * source, read from its syntax tree: a template's `${…}` parts count as written.
 */
export function testNames(source: string, fileName = 'test.ts'): TestName[] {
  const file = ts.createSourceFile(fileName, source, ts.ScriptTarget.Latest, true);
  const names: TestName[] = [];
  const visit = (node: ts.Node): void => {
    if (ts.isCallExpression(node) && node.arguments.length > 0) {
      const root = calleeRoot(node.expression);
      const first = node.arguments[0];
      if (root && TEST_CALLS.has(root) && (ts.isStringLiteralLike(first) || ts.isTemplateExpression(first))) {
        const name = ts.isStringLiteralLike(first) ? first.text : first.getText(file).slice(1, -1);
        names.push({ name, line: file.getLineAndCharacterOfPosition(first.getStart(file)).line + 1 });
      }
    }
    ts.forEachChild(node, visit);
  };
  visit(file);
  return names;
}

/** The names in a source longer than MAX_TEST_NAME_LENGTH, as "path:line (length)". */
export function overlongTestNames(source: string, path: string): string[] {
  return testNames(source, path)
    .filter(({ name }) => name.length > MAX_TEST_NAME_LENGTH)
    .map(({ name, line }) => `${path}:${line} (${name.length})`);
}

// A tracker's number ("issue" and a number, or "#" and a number), which a reader without the
// tracker cannot follow. A colour such as #06283a is not one: the digits must end the word.
const ISSUE_CITATION = /\bissues? #?\d+(?:\.\d+)?|(?<![\w&])#\d{1,5}\b/gi;

/** Every comment in a source, with the line it starts on (1-based), read from its syntax tree. */
export function sourceComments(source: string, fileName = 'source.ts'): { text: string; line: number }[] {
  const file = ts.createSourceFile(fileName, source, ts.ScriptTarget.Latest, true);
  const seen = new Map<number, { text: string; line: number }>();
  const collect = (ranges: ts.CommentRange[] | undefined): void => {
    for (const range of ranges ?? []) {
      const line = file.getLineAndCharacterOfPosition(range.pos).line + 1;
      seen.set(range.pos, { text: source.slice(range.pos, range.end), line });
    }
  };
  const visit = (node: ts.Node): void => {
    collect(ts.getLeadingCommentRanges(source, node.pos));
    collect(ts.getTrailingCommentRanges(source, node.end));
    ts.forEachChild(node, visit);
  };
  visit(file);
  collect(ts.getLeadingCommentRanges(source, file.endOfFileToken.pos));
  return [...seen.values()].sort((a, b) => a.line - b.line);
}

/** Each place a comment or a test's name cites an issue by number, as "path:line: the citation". */
export function issueCitations(source: string, path: string): string[] {
  const texts = [...sourceComments(source, path), ...testNames(source, path).map(({ name, line }) => ({ text: name, line }))];
  const found: string[] = [];
  for (const { text, line } of texts.sort((a, b) => a.line - b.line)) {
    text.split('\n').forEach((part, offset) => {
      for (const match of part.matchAll(ISSUE_CITATION)) found.push(`${path}:${line + offset}: ${match[0]}`);
    });
  }
  return found;
}
