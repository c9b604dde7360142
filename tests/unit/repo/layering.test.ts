import { describe, expect, it } from 'vitest';
import { readdirSync, readFileSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';

/**
 * The house's layering, checked on the import statements: src/sim is pure (no three.js, no
 * DOM layer above it), src/render may use sim, src/app may use both; nothing imports
 * upwards, and no module imports itself round a circle.
 */
const ROOT = resolve(__dirname, '../../..');
const LAYERS = ['sim', 'render', 'app'] as const;

function files(dir: string): string[] {
  return readdirSync(dir, { withFileTypes: true }).flatMap((e) =>
    e.isDirectory() ? files(join(dir, e.name)) : e.name.endsWith('.ts') ? [join(dir, e.name)] : [],
  );
}

/**
 * Every way a module names another here: `import … from`, `export … from`, a bare
 * `import '…'`, a dynamic `import('…')` (and so `typeof import('…')`), and a Worker's entry,
 * `new URL('…', import.meta.url)` or Vite's `import url from '…?worker&url'`. Each alternative
 * captures the specifier in group 1.
 */
const IMPORT_FORMS = [
  /^\s*(?:import|export)\s[^;]*?from\s+['"]([^'"]+)['"]/gm,
  /^\s*import\s+['"]([^'"]+)['"]/gm,
  /\bimport\(\s*['"]([^'"]+)['"]\s*\)/g,
  /\bnew\s+URL\(\s*['"]([^'"]+)['"]\s*,\s*import\.meta\.url\s*\)/g,
];

/** The specifiers `source` imports, each once. */
export function importSpecifiers(source: string): string[] {
  return [...new Set(IMPORT_FORMS.flatMap((form) => [...source.matchAll(form)].map((match) => match[1])))];
}

/** The modules `path` (relative to ROOT) imports: relative imports resolved to files, packages by name. */
function importTargets(path: string, source: string): string[] {
  return importSpecifiers(source).map((spec) => {
    if (!spec.startsWith('.')) return spec;
    // `../sim/params` is the file `../sim/params.ts`; shaders and styles keep their extension.
    const file = relative(ROOT, resolve(ROOT, dirname(path), spec.replace(/\?(raw|worker&url)$/, '')));
    return /\.[a-z]+$/.test(file) ? file : `${file}.ts`;
  });
}

/** Module → the modules it imports. */
function importGraph(paths: string[]): Map<string, string[]> {
  return new Map(paths.map((path) => [relative(ROOT, path), importTargets(relative(ROOT, path), readFileSync(path, 'utf8'))]));
}

function layerOf(module: string): number {
  const m = /^src\/(sim|render|app)\//.exec(module);
  return m ? LAYERS.indexOf(m[1] as (typeof LAYERS)[number]) : -1;
}

/** Imports that go to a higher layer, or from sim to three.js. */
export function layeringViolations(graph: Map<string, string[]>): string[] {
  const found: string[] = [];
  for (const [from, targets] of graph) {
    for (const to of targets) {
      if (layerOf(from) >= 0 && layerOf(to) > layerOf(from)) found.push(`${from} → ${to}`);
      if (layerOf(from) === 0 && (to === 'three' || to.startsWith('three/'))) found.push(`${from} → ${to}`);
    }
  }
  return found;
}

/** One cycle per strongly connected knot found by depth-first search, as the path round it. */
export function importCycles(graph: Map<string, string[]>): string[][] {
  const state = new Map<string, 'open' | 'done'>();
  const stack: string[] = [];
  const cycles: string[][] = [];
  const visit = (node: string) => {
    state.set(node, 'open');
    stack.push(node);
    for (const next of graph.get(node) ?? []) {
      if (!graph.has(next)) continue;
      if (state.get(next) === 'open') cycles.push([...stack.slice(stack.indexOf(next)), next]);
      else if (!state.has(next)) visit(next);
    }
    stack.pop();
    state.set(node, 'done');
  };
  for (const node of graph.keys()) if (!state.has(node)) visit(node);
  return cycles;
}

describe('layering sim ← render ← app', () => {
  const graph = importGraph(files(join(ROOT, 'src')));

  it('resolves the imports it checks (the graph is not empty and finds known edges)', () => {
    expect(graph.get('src/render/ocean/oceanView.ts')).toContain('src/sim/params/params.ts');
    expect(graph.get('src/app/oceanApp.ts')).toContain('src/render/ocean/oceanView.ts');
    // A dynamic import, and the Worker's entry.
    expect(graph.get('src/render/waves/waveViewRegistry.ts')).toContain('src/render/waves/fft/fftModelCode.ts');
    expect(graph.get('src/render/waves/fft/fftFieldsSource.ts')).toContain('src/render/waves/fft/fftFieldsWorker.ts');
  });

  it('has no import from a lower layer to a higher one, and no three.js in sim', () => {
    expect(layeringViolations(graph)).toEqual([]);
  });

  it('has no import cycles', () => {
    expect(importCycles(graph)).toEqual([]);
  });

  it('would report an upward import and a cycle (negative controls)', () => {
    const planted = new Map(graph);
    planted.set('src/sim/planted.ts', ['src/render/ocean/oceanView.ts', 'three']);
    expect(layeringViolations(planted)).toEqual(['src/sim/planted.ts → src/render/ocean/oceanView.ts', 'src/sim/planted.ts → three']);
    planted.set('src/sim/params/params.ts', [...(graph.get('src/sim/params/params.ts') ?? []), 'src/sim/planted.ts']);
    planted.set('src/sim/planted.ts', ['src/sim/params/params.ts']);
    expect(importCycles(planted)).toContainEqual(['src/sim/params/params.ts', 'src/sim/planted.ts', 'src/sim/params/params.ts']);
  });

  // Each form planted alone in a sim module that names a render module: the edge must be seen.
  const plantedForms: [string, string][] = [
    ['a static import', "import { OceanView } from '../../render/ocean/oceanView';"],
    ['a bare import', "import '../../render/ocean/oceanView';"],
    ['a dynamic import', "const view = await import('../../render/ocean/oceanView');"],
    ['a type of a dynamic import', "type View = typeof import('../../render/ocean/oceanView');"],
    ['a Worker entry', "new Worker(new URL('../../render/ocean/oceanView.ts', import.meta.url), { type: 'module' });"],
  ];
  it.each(plantedForms)('would report %s going upwards (negative control)', (_form, source) => {
    const planted = new Map(graph);
    planted.set('src/sim/params/planted.ts', importTargets('src/sim/params/planted.ts', source));
    expect(layeringViolations(planted)).toEqual(['src/sim/params/planted.ts → src/render/ocean/oceanView.ts']);
  });

  it('would report a cycle closed by a Worker entry (negative control)', () => {
    const planted = new Map(graph);
    planted.set(
      'src/render/plantedSource.ts',
      importTargets('src/render/plantedSource.ts', "new Worker(new URL('./plantedWorker.ts', import.meta.url));"),
    );
    planted.set('src/render/plantedWorker.ts', importTargets('src/render/plantedWorker.ts', "import { helper } from './plantedSource';"));
    expect(importCycles(planted)).toContainEqual([
      'src/render/plantedSource.ts',
      'src/render/plantedWorker.ts',
      'src/render/plantedSource.ts',
    ]);
  });

  it('reads a URL that is not a module (no import.meta.url) as no import', () => {
    expect(importSpecifiers("const page = new URL('index.html', base);")).toEqual([]);
  });
});
