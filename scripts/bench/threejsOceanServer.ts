import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { build, preview } from 'vite';

/** Where the copy of three.js's ocean example lives (see its main.ts for what it is and is not). */
const PAGE_ROOT = 'scripts/bench/threejsOcean';

export interface ExampleServer {
  baseUrl: string;
  close(): Promise<void>;
}

/**
 * Builds the three.js ocean example page with the installed `three` (minified, like the
 * app's dist/) into a temporary folder and serves it on loopback with the same headers as
 * the app, so both are timed the same way. Vite's own config (the app's) is not used.
 */
export async function serveThreejsOceanExample(headers: Record<string, string>): Promise<ExampleServer> {
  const outDir = mkdtempSync(join(tmpdir(), 'oceano-threejs-ocean-'));
  const common = { configFile: false as const, root: PAGE_ROOT, base: './', logLevel: 'warn' as const };
  await build({ ...common, build: { outDir, emptyOutDir: true, reportCompressedSize: false } });
  const server = await preview({ ...common, build: { outDir }, preview: { port: 0, host: '127.0.0.1', strictPort: false, headers } });
  const address = server.httpServer.address();
  if (!address || typeof address === 'string') throw new Error('The three.js example server has no TCP address.');
  return {
    baseUrl: `http://127.0.0.1:${address.port}/`,
    async close() {
      await new Promise<void>((resolve) => server.httpServer.close(() => resolve()));
      rmSync(outDir, { recursive: true, force: true });
    },
  };
}
