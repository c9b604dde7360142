import { defineConfig } from 'vite';

/**
 * The library build: dist/oceano.js, one ES module that defines <oceano-view> with three.js
 * inside. It is run after the page build (see vite.config.ts) and writes beside it, so the
 * script finds the sky images in dist/sky/ relative to its own URL.
 */
export default defineConfig({
  base: './',
  publicDir: false,
  build: {
    target: 'es2022',
    outDir: 'dist',
    emptyOutDir: false,
    chunkSizeWarningLimit: 900,
    lib: { entry: 'src/lib.ts', formats: ['es'], fileName: () => 'oceano.js' },
  },
});
