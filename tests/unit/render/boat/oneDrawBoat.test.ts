import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { DataTexture, DoubleSide, Mesh, type BufferAttribute, type MeshStandardMaterial, type Object3D } from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { oneDrawBoat } from '../../../../src/render/boat/oneDrawBoat';

const GLB = readFileSync(new URL('../../../../public/models/boat.glb', import.meta.url));

async function loadParts(): Promise<Object3D> {
  const buffer = GLB.buffer.slice(GLB.byteOffset, GLB.byteOffset + GLB.byteLength) as ArrayBuffer;
  return (await new GLTFLoader().parseAsync(buffer, '')).scene;
}

function partsOf(model: Object3D): Mesh[] {
  const meshes: Mesh[] = [];
  model.traverse((o) => {
    if (o instanceof Mesh) meshes.push(o);
  });
  return meshes;
}

/** Each vertex's (r, g, b, roughness, metalness) as the merged mesh shades it, rounded, as a sorted multiset of strings. */
function finishes(mesh: Mesh): string[] {
  const material = mesh.material as MeshStandardMaterial;
  const table = (material.roughnessMap as DataTexture).image;
  const colour = mesh.geometry.getAttribute('color') as BufferAttribute;
  const uv = mesh.geometry.getAttribute('uv') as BufferAttribute;
  return Array.from({ length: colour.count }, (_, v) => {
    const texel = Math.floor(uv.getX(v) * table.width);
    const data = table.data as Float32Array;
    return [colour.getX(v), colour.getY(v), colour.getZ(v), data[4 * texel + 1], data[4 * texel + 2]].map((x) => x.toFixed(5)).join(' ');
  }).sort();
}

describe('the boat in one draw', () => {
  it('is one mesh whose vertices carry each part colour and finish, double-sided parts twice', async () => {
    const parts = partsOf(await loadParts());
    const boat = oneDrawBoat(await loadParts()) as Mesh;
    expect(partsOf(boat)).toHaveLength(1);
    const expected = parts
      .flatMap((part) => {
        const m = part.material as MeshStandardMaterial;
        const copies = m.side === DoubleSide ? 2 : 1;
        const count = part.geometry.index?.count ?? part.geometry.getAttribute('position').count;
        const finish = [m.color.r, m.color.g, m.color.b, m.roughness, m.metalness].map((x) => x.toFixed(5)).join(' ');
        return Array<string>(copies * count).fill(finish);
      })
      .sort();
    expect(finishes(boat)).toEqual(expected);
    const material = boat.material as MeshStandardMaterial;
    expect([material.vertexColors, material.roughness, material.metalness, material.color.getHex()]).toEqual([true, 1, 1, 0xffffff]);
  });

  it('a double-sided part is drawn facing both ways: its normals, front and turned over, sum to nothing', async () => {
    const boat = oneDrawBoat(await loadParts()) as Mesh;
    const sails = partsOf(await loadParts()).find((p) => (p.material as MeshStandardMaterial).name === 'Sails') as Mesh;
    const sailColour = (sails.material as MeshStandardMaterial).color;
    const colour = boat.geometry.getAttribute('color') as BufferAttribute;
    const normal = boat.geometry.getAttribute('normal') as BufferAttribute;
    const sum = [0, 0, 0];
    let count = 0;
    for (let v = 0; v < colour.count; v++) {
      const f = Math.fround;
      if (colour.getX(v) !== f(sailColour.r) || colour.getY(v) !== f(sailColour.g) || colour.getZ(v) !== f(sailColour.b)) continue;
      count++;
      for (let c = 0; c < 3; c++) sum[c] += normal.array[3 * v + c];
    }
    const front = sails.geometry.getAttribute('normal') as BufferAttribute;
    expect(count).toBe(2 * front.count);
    for (const s of sum) expect(Math.abs(s)).toBeLessThan(1e-4);
    // The sails alone, one way only, do not cancel.
    expect(Math.abs(Array.from(front.array).reduce((a, b) => a + b, 0))).toBeGreaterThan(1);
  });

  it('a model whose parts differ in more than colour and finish is left as it is', async () => {
    const model = await loadParts();
    const [first] = partsOf(model);
    (first.material as MeshStandardMaterial).emissive.setRGB(1, 0, 0);
    expect(oneDrawBoat(model)).toBe(model);
    expect(partsOf(model).length).toBeGreaterThan(1);
  });
});
