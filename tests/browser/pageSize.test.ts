import { readdirSync, readFileSync } from 'node:fs';
import { pageEntry, scriptSizes, staticImports } from '../../scripts/build/distScripts';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';

/** What the page's first load costs: minified scripts, three.js once, and what is fetched only on use. */

describe('packaging', () => {
  const dist = join(import.meta.dirname, '..', '..', 'dist');
  const scripts = [
    ...readdirSync(join(dist, 'assets'))
      .filter((f) => f.endsWith('.js'))
      .map((f) => `assets/${f}`),
    'oceano.js',
  ];
  const text = (file: string) => readFileSync(join(dist, file), 'utf8');

  it('ships minified scripts, three.js once, imported by both the page and oceano.js', () => {
    for (const file of scripts) {
      const code = text(file);
      // Minified: no indented methods, no class keeping its source name (GLSL strings keep their lines, so line length says nothing).
      expect(code, file).not.toMatch(/\n\s+constructor\(/);
      expect(code, file).not.toMatch(/class (OceanApp|WebGLRenderer|OceanView)\b/);
    }
    const withThree = scripts.filter((file) => text(file).includes('THREE.WebGLRenderer'));
    expect(withThree).toHaveLength(1);
    const threeChunk = withThree[0].split('/').pop()!;
    const entry = pageEntry(dist);
    expect(text(entry)).toContain(threeChunk);
    expect(text('oceano.js')).toContain(threeChunk);
    // What a page loads before its first frame: its entry and what that imports statically
    // (scripts/build/distScripts.ts, which the bench's size figures use too). Chunks loaded only on
    // use (the physics panel's plots, the FFT twin's worker) are left out.
    const sizes = scriptSizes(dist);
    const loaded = new Set([...sizes.pageFiles, ...staticImports(dist, 'oceano.js')]);
    expect(loaded.size).toBeLessThan(scripts.length);
    // Fetched on first use, never before the first frame: the glTF loader (with the boat), the
    // underwater passes, the FFT and Gerstner models, the control panel (lil-gui, after the
    // first frame), the physics estimators, the GPU probe and the sky prefiltered for the seed's sea.
    for (const lazy of [
      'GLTFLoader',
      'oceanUnderwater',
      'fftModelCode',
      'gerstnerModelCode',
      'controlPanel',
      'physicsReport',
      'surfaceProbe',
      'prefilteredSky',
      'physicsPanel',
    ]) {
      const chunk = scripts.find((file) => file.startsWith(`assets/${lazy}-`));
      expect(chunk, lazy).toBeDefined();
      expect(loaded.has(chunk!), lazy).toBe(false);
    }
    // The lessons' catalog: fetched by a page when its URL names a lesson, or with the drawer; the element carries it.
    const catalog = scripts.find((file) => file.startsWith('assets/lessonCatalog-'));
    expect(catalog).toBeDefined();
    expect(sizes.pageFiles).not.toContain(catalog);
    expect(staticImports(dist, 'oceano.js').has(catalog!)).toBe(true);
    // three.js's core alone is 142 KB gzipped; `npm run bench` reports the page's sizes as they are.
    // The bounds keep a first visit fast: 200 KB gzipped before the first frame, and under 20 KB
    // more for a page that embeds <oceano-view>.
    expect(sizes.pageKB).toBeLessThanOrEqual(200);
    expect(sizes.componentExtraKB).toBeLessThan(20);
    // The shaders arrive without their comments (scripts/build/glslMinify.ts) but with their code.
    const shaderCode = sizes.pageFiles.map(text).join('\n');
    expect(shaderCode).toContain('vec3 waveDisplacement(vec2 gridXZ)');
    expect(shaderCode).not.toContain('// The contract every model');
  });
});
