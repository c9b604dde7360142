import type { Plugin } from 'vite';
import { readFileSync } from 'node:fs';
import { defineConfig } from 'vitest/config';
import { minifyGlsl, SHADER_RAW_IMPORT } from './scripts/build/glslMinify';
import { lessonQuotes } from './scripts/build/lessonQuotes';

/**
 * The page's Content-Security-Policy: scripts only from this origin (no inline script, no
 * eval), every fetch, image, font and connection to this origin. Styles allow
 * 'unsafe-inline' for the style attributes lil-gui and three.js set. lil-gui's icon font,
 * a data: URL in its stylesheet, is served as a file instead (lilGuiFontFile below), so
 * the page also runs clean under just "default-src 'self'; style-src 'self'
 * 'unsafe-inline'". Only the build gets it: the dev server's hot reload needs more.
 */
export const CONTENT_SECURITY_POLICY = [
  "default-src 'self'",
  "script-src 'self'",
  "style-src 'self' 'unsafe-inline'",
  "img-src 'self' data: blob:",
  "font-src 'self'",
  "connect-src 'self'",
  "object-src 'none'",
  "base-uri 'self'",
  "form-action 'none'",
].join('; ');

/**
 * Headers that make the page cross-origin isolated (COOP + COEP), sent by `npm start` and
 * `vite preview`: Chromium's performance.now() is then fine-grained instead of coarsened,
 * which the bench's and stats()' sub-millisecond CPU figures need. The page itself needs
 * nothing of them: it runs the same on a host that sends no headers (a static copy of dist/
 * on a course site). Everything it loads is its own origin's, so require-corp refuses nothing.
 */
export const CROSS_ORIGIN_ISOLATION = { 'Cross-Origin-Opener-Policy': 'same-origin', 'Cross-Origin-Embedder-Policy': 'require-corp' };

function contentSecurityPolicy(): Plugin {
  return {
    name: 'oceano-content-security-policy',
    apply: 'build',
    transformIndexHtml: () => [
      { tag: 'meta', attrs: { 'http-equiv': 'Content-Security-Policy', content: CONTENT_SECURITY_POLICY }, injectTo: 'head-prepend' },
    ],
  };
}

/**
 * lil-gui's stylesheet (imported by the page with injectStyles off) carries its icon font
 * as a data: URL, which a font-src without data: refuses: point it at the same font as a
 * file in public/fonts (extracted once from lil-gui 0.21's CSS).
 */
function lilGuiFontFile(): Plugin {
  return {
    name: 'oceano-lil-gui-font-file',
    enforce: 'pre',
    transform(code, id) {
      if (!id.replaceAll('\\', '/').includes('/lil-gui/dist/lil-gui.css')) return null;
      const replaced = code.replace(/url\("data:application\/font-woff2[^"]*"\)/, 'url("/fonts/lil-gui.woff2")');
      if (replaced === code) throw new Error('lil-gui.css no longer embeds its icon font as expected: update lilGuiFontFile.');
      return replaced;
    },
  };
}

/** The build's shader text without comments (scripts/build/glslMinify.ts); dev and tests read the files as they are. */
export function shaderText(): Plugin {
  return {
    name: 'oceano-shader-text',
    apply: 'build',
    enforce: 'pre',
    load(id) {
      if (!SHADER_RAW_IMPORT.test(id)) return null;
      return `export default ${JSON.stringify(minifyGlsl(readFileSync(id.replace(/\?raw$/, ''), 'utf8')))};`;
    },
  };
}

export default defineConfig({
  // Relative base: dist/ works when copied under any sub-path of a course site.
  base: './',
  plugins: [contentSecurityPolicy(), lilGuiFontFile(), shaderText(), lessonQuotes()],
  /**
   * One build for the page and dist/oceano.js (the <oceano-view> web component): two
   * entries of one bundle, so both import the same minified three.js chunk and the same
   * app code instead of each carrying its own copy (issue 11.11). oceano.js keeps its
   * fixed name beside index.html: it finds the sky and the boat relative to its own URL.
   */
  build: {
    target: 'es2022',
    chunkSizeWarningLimit: 800,
    // No polyfill for <link rel="modulepreload">, 0.4 KB of the page's first scripts: a browser
    // without it (Safari before 17) loads the same modules, each when first imported.
    modulePreload: { polyfill: false },
    rollupOptions: {
      input: { index: 'index.html', course: 'course/index.html', oceano: 'src/element.ts' },
      // oceano.js is a module pages import from: keep its exports (OceanoViewElement).
      preserveEntrySignatures: 'exports-only',
      output: {
        entryFileNames: (chunk) => (chunk.name === 'oceano' ? 'oceano.js' : 'assets/[name]-[hash].js'),
        // three.js's core in one chunk both entries share; its addons go where they are used,
        // so the glTF loader lands in a chunk of its own, fetched with the boat.
        manualChunks: (id) => (id.includes('/node_modules/three/build/') ? 'three' : undefined),
      },
    },
  },
  server: { host: '127.0.0.1', port: 5173, headers: CROSS_ORIGIN_ISOLATION },
  preview: { host: '127.0.0.1', port: 4173, headers: CROSS_ORIGIN_ISOLATION },
  test: {
    projects: [
      {
        // 60 s per test rather than vitest's 5: `npm test` runs the type check and the build
        // beside the unit tests (tests/runTests.mjs), and on a loaded 2-core machine a test
        // measured at 0.5 s quiet took 6.1 s (fftSpectra's Hasselmann m₀, 11:20 UTC, load 8).
        // A timeout is no check of the results; the assertions are.
        test: { name: 'unit', include: ['tests/unit/**/*.test.ts'], environment: 'node', testTimeout: 60_000 },
      },
      {
        test: {
          name: 'browser',
          include: ['tests/browser/**/*.test.ts'],
          globalSetup: ['tests/browser/sharedBrowser.ts'],
          environment: 'node',
          testTimeout: 120_000,
          hookTimeout: 120_000,
          fileParallelism: false,
        },
      },
    ],
  },
});
