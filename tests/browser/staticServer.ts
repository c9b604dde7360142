import { createServer, type Server } from 'node:http';
import { readFile } from 'node:fs/promises';
import { extname, join, normalize } from 'node:path';

const DIST = join(import.meta.dirname, '..', '..', 'dist');
const SUB_PATH = '/courses/graphics/week-3/ocean/';
const TYPES: Record<string, string> = {
  '.html': 'text/html',
  '.js': 'text/javascript',
  '.css': 'text/css',
  '.png': 'image/png',
  '.svg': 'image/svg+xml',
  '.glb': 'model/gltf-binary',
};

/**
 * A plain static file server that puts dist/ under a deep sub-path, as a course site would:
 * content types and nothing else, so no cross-origin isolation headers either.
 */
export function serveUnderSubPath(): Promise<{ server: Server; url: string }> {
  return serveFolder(DIST, SUB_PATH);
}

/**
 * Serves `folder` under `subPath` on loopback, as serveUnderSubPath serves dist/; `served`
 * hears each request's path and status; `headers` go with every file (a CDN's CORS header).
 */
export function serveFolder(
  folder: string,
  subPath: string,
  served: (path: string, status: number) => void = () => {},
  headers: Record<string, string> = {},
): Promise<{ server: Server; url: string }> {
  const server = createServer(async (request, response) => {
    const path = decodeURIComponent(new URL(request.url ?? '/', 'http://x').pathname);
    if (!path.startsWith(subPath)) {
      served(path, 404);
      response.writeHead(404).end();
      return;
    }
    const relative = normalize(path.slice(subPath.length) || 'index.html');
    try {
      const body = await readFile(join(folder, relative));
      served(path, 200);
      response.writeHead(200, { ...headers, 'content-type': TYPES[extname(relative)] ?? 'application/octet-stream' }).end(body);
    } catch {
      served(path, 404);
      response.writeHead(404).end();
    }
  });
  return new Promise((resolve) =>
    server.listen(0, '127.0.0.1', () => {
      const address = server.address();
      const port = typeof address === 'object' && address ? address.port : 0;
      resolve({ server, url: `http://127.0.0.1:${port}${subPath}` });
    }),
  );
}
