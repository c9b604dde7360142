import { join } from 'node:path';
import { build } from 'vite';

/**
 * A test page's code: tests/browser/fixtures/<name>.ts bundled by Vite into one ES module
 * (shaders inlined as the app inlines them), to be put on a blank page with addScriptTag.
 */
export async function fixtureBundle(name: string, inlineDynamicImports = false): Promise<string> {
  const output = await build({
    configFile: false,
    logLevel: 'warn',
    build: {
      write: false,
      minify: false,
      target: 'es2022',
      lib: { entry: join(import.meta.dirname, `fixtures/${name}.ts`), formats: ['es'], fileName: name },
      ...(inlineDynamicImports ? { rollupOptions: { output: { inlineDynamicImports: true } } } : {}),
    },
  });
  const bundles = Array.isArray(output) ? output : [output];
  const chunk = bundles.flatMap((b) => ('output' in b ? b.output : [])).find((o) => o.type === 'chunk');
  if (!chunk || chunk.type !== 'chunk') throw new Error(`No bundle for the test page ${name}.`);
  return chunk.code;
}
