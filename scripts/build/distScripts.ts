import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';

/**
 * What the built app's JavaScript weighs, as issue 14 states its targets: the page (what
 * index.html loads before its first frame: its entry and every chunk that entry imports
 * statically), the component (dist/oceano.js and what it loads that the page does not),
 * and everything in dist/ (lazy chunks included: the glTF loader, the underwater passes,
 * the physics plots, the FFT twin's worker). Each file is gzipped alone, as a web server
 * would send it.
 */
export interface ScriptSizes {
  pageKB: number;
  componentExtraKB: number;
  allKB: number;
  pageFiles: string[];
}

/** Every script under dist/, as paths relative to it. */
export function distScripts(dist: string, dir = ''): string[] {
  return readdirSync(join(dist, dir), { withFileTypes: true }).flatMap((entry) => {
    const path = dir ? `${dir}/${entry.name}` : entry.name;
    if (entry.isDirectory()) return distScripts(dist, path);
    return /\.m?js$/.test(entry.name) ? [path] : [];
  });
}

/** A script and every script it imports statically (minified `from"./x.js"`), relative to dist/. */
export function staticImports(dist: string, entry: string, into = new Set<string>()): Set<string> {
  if (into.has(entry)) return into;
  into.add(entry);
  const code = readFileSync(join(dist, entry), 'utf8');
  const dir = entry.includes('/') ? entry.slice(0, entry.lastIndexOf('/') + 1) : '';
  for (const [, path] of code.matchAll(/(?:from|import)\s*"\.\/([^"]+\.js)"/g)) staticImports(dist, `${dir}${path}`, into);
  return into;
}

/** The page's module entry, named by index.html's script tag. */
export function pageEntry(dist: string): string {
  const entry = /<script type="module"[^>]*src="\.\/([^"]+)"/.exec(readFileSync(join(dist, 'index.html'), 'utf8'));
  if (!entry) throw new Error(`${dist}/index.html has no module script: run vite build first.`);
  return entry[1];
}

const gzipKB = (dist: string, files: Iterable<string>) =>
  [...files].reduce((sum, file) => sum + gzipSync(readFileSync(join(dist, file))).length, 0) / 1024;

export function scriptSizes(dist: string): ScriptSizes {
  const all = distScripts(dist);
  if (all.length === 0) throw new Error(`No JavaScript in ${dist}: run vite build first.`);
  const page = staticImports(dist, pageEntry(dist));
  const component = [...staticImports(dist, 'oceano.js')].filter((file) => !page.has(file));
  return { pageKB: gzipKB(dist, page), componentExtraKB: gzipKB(dist, component), allKB: gzipKB(dist, all), pageFiles: [...page] };
}
