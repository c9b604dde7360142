import { describe, expect, it } from 'vitest';
import { readdirSync, readFileSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';

/**
 * The house's layering, checked on the import statements: src/sim is pure (no three.js, no
 * DOM layer above it), src/render may use sim, src/app may use both; nothing imports
 * upwards, and no module imports itself round a circle.
 */
const ROOT = resolve(__dirname, '../..');
const LAYERS = ['sim', 'render', 'app'] as const;

function files(dir: string): string[] {
  return readdirSync(dir, { withFileTypes: true }).flatMap((e) => (e.isDirectory() ? files(join(dir, e.name)) : e.name.endsWith('.ts') ? [join(dir, e.name)] : []));
}

const IMPORT = /^\s*(?:import|export)\s[^;]*?from\s+'([^']+)'/gm;

/** Module → the modules it imports (relative imports resolved to files; packages by name). */
function importGraph(paths: string[]): Map<string, string[]> {
  const graph = new Map<string, string[]>();
  for (const path of paths) {
    const source = readFileSync(path, 'utf8');
    const targets: string[] = [];
    for (const match of source.matchAll(IMPORT)) {
      const spec = match[1];
      if (!spec.startsWith('.')) {
        targets.push(spec);
        continue;
      }
      // `../sim/params` is the file `../sim/params.ts`; shaders and styles keep their extension.
      const file = relative(ROOT, resolve(dirname(path), spec.replace(/\?raw$/, '')));
      targets.push(/\.[a-z]+$/.test(file) ? file : `${file}.ts`);
    }
    graph.set(relative(ROOT, path), targets);
  }
  return graph;
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
});
