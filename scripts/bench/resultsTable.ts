/** Markdown rendering of the benchmark's figures for `bench/results.md` and the README. */

function escapeCell(text: string): string {
  return text.replace(/\|/g, '\\|').replace(/\r?\n/g, ' ');
}

/** A GitHub-flavoured markdown table; every row must have one cell per heading. */
export function markdownTable(headings: readonly string[], rows: readonly (readonly string[])[]): string {
  rows.forEach((row, r) => {
    if (row.length !== headings.length) throw new Error(`Row ${r} has ${row.length} cells for ${headings.length} headings.`);
  });
  const line = (cells: readonly string[]) => `| ${cells.map(escapeCell).join(' | ')} |`;
  return [line(headings), line(headings.map(() => '---')), ...rows.map(line)].join('\n');
}

/** Fixed decimals, or an em dash for a figure that was not measured. */
export function formatFigure(value: number | null | undefined, decimals: number): string {
  return value === null || value === undefined || !Number.isFinite(value) ? '—' : value.toFixed(decimals);
}
