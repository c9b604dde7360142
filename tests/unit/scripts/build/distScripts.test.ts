import { mkdirSync, mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { scriptSizes, staticImports } from '../../../../scripts/build/distScripts';

/** A dist/ in miniature: the page's entry imports the shared chunks; one chunk is only imported dynamically. */
function fixtureDist(): string {
  const dist = mkdtempSync(join(tmpdir(), 'oceano-dist-'));
  mkdirSync(join(dist, 'assets'));
  writeFileSync(join(dist, 'index.html'), '<script type="module" crossorigin src="./assets/index-a.js"></script>');
  writeFileSync(join(dist, 'assets/index-a.js'), 'import{a}from"./shared-b.js";import"./three-c.js";a();');
  writeFileSync(join(dist, 'assets/shared-b.js'), 'import"./three-c.js";export const a=()=>import("./lazy-d.js");');
  writeFileSync(join(dist, 'assets/three-c.js'), 'export const three="x".repeat(5000);');
  writeFileSync(join(dist, 'assets/lazy-d.js'), `export const lazy=${JSON.stringify('y'.repeat(3000))};`);
  writeFileSync(join(dist, 'oceano.js'), 'import{a}from"./assets/shared-b.js";import"./assets/only-component-e.js";');
  writeFileSync(join(dist, 'assets/only-component-e.js'), 'export const e=1;');
  return dist;
}

describe('the built scripts, as the bench weighs them', () => {
  it('follows static imports (named and bare) from the page entry, not dynamic ones', () => {
    const dist = fixtureDist();
    expect([...staticImports(dist, 'assets/index-a.js')].sort()).toEqual(['assets/index-a.js', 'assets/shared-b.js', 'assets/three-c.js']);
    const sizes = scriptSizes(dist);
    expect(sizes.pageFiles.sort()).toEqual(['assets/index-a.js', 'assets/shared-b.js', 'assets/three-c.js']);
    // The component's extra is itself and the chunk the page does not load; the lazy chunk counts only in the total.
    expect(sizes.componentExtraKB).toBeGreaterThan(0);
    expect(sizes.componentExtraKB).toBeLessThan(sizes.pageKB);
    expect(sizes.allKB).toBeGreaterThan(sizes.pageKB + sizes.componentExtraKB);
  });
});
