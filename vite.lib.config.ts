import type { Plugin } from 'vite';
import { readFileSync } from 'node:fs';
import { defineConfig } from 'vite';
import { shaderText } from './vite.config';
import { lessonQuotes } from './scripts/build/lessonQuotes';

/**
 * The npm package's two builds (`npm run build:package`, run by `npm pack`'s prepack), one
 * per mode, because they treat three.js oppositely:
 * - `--mode library`: dist/lib/oceano.js, the `Ocean` library for three.js users. three.js
 *   stays an import (a peer dependency: the user's own copy, so `Ocean` is an Object3D of
 *   the same three the user's scene is); everything else (fft.js, our shaders) is bundled.
 * - `--mode element`: dist/element/oceano-view.js, the `<oceano-view>` element, one file with
 *   three.js inside, and beside it the boat it looks up relative to its own URL.
 * Both keep the FFT twin's Worker as a file of its own in assets/, found relative to the
 * script that starts it. Shaders go in as text without comments, as in the app's build.
 */
/**
 * What the element loads beside itself: the boat. Its sky is painted from the sun; the six
 * images of public/sky are the app's sample for `sky=`, which a page resolves against itself.
 */
const ELEMENT_ASSETS = ['models/boat.glb'];

function elementAssets(): Plugin {
  return {
    name: 'oceano-element-assets',
    generateBundle() {
      for (const fileName of ELEMENT_ASSETS) this.emitFile({ type: 'asset', fileName, source: readFileSync(`public/${fileName}`) });
    },
  };
}

/** `three` and its addons (`three/addons/…`): the only imports the library leaves to the user. */
export function isThreeImport(id: string): boolean {
  return id === 'three' || id.startsWith('three/');
}

export default defineConfig(({ mode }) => {
  if (mode === 'library') {
    return {
      // Relative: the Worker's URL is resolved against the script's own, wherever it is installed.
      base: './',
      publicDir: false,
      plugins: [shaderText()],
      build: {
        outDir: 'dist/lib',
        emptyOutDir: true,
        target: 'es2022',
        // Students read it, and the user's own bundler minifies it.
        minify: false,
        lib: { entry: 'src/index.ts', formats: ['es'], fileName: () => 'oceano.js' },
        // allow-extension: the entry file holds the code itself (the lazy wave models import from
        // it) instead of re-exporting a hashed chunk.
        rollupOptions: { external: isThreeImport, preserveEntrySignatures: 'allow-extension' as const },
      },
    };
  }
  if (mode === 'element') {
    // An application build of one script rather than a library build: Vite's library mode
    // never strips an ES module's whitespace (1.5 MB instead of about half that), and its
    // lazy parts (the glTF loader, the physics panel and its stylesheet) stay lazy, loaded
    // from assets/ beside it exactly as the app's dist/oceano.js loads them.
    return {
      base: './',
      publicDir: false,
      plugins: [shaderText(), lessonQuotes(), elementAssets()],
      build: {
        outDir: 'dist/element',
        emptyOutDir: true,
        target: 'es2022',
        chunkSizeWarningLimit: 1000,
        rollupOptions: {
          input: { 'oceano-view': 'src/element.ts' },
          preserveEntrySignatures: 'allow-extension' as const,
          output: { entryFileNames: '[name].js' },
        },
      },
    };
  }
  throw new Error(`vite.lib.config.ts builds --mode library or --mode element, not ${mode}.`);
});
