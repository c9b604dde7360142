import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { Box3, Mesh, type MeshStandardMaterial } from 'three';
import { GLTFLoader, type GLTF } from 'three/addons/loaders/GLTFLoader.js';

const GLB = readFileSync(new URL('../../public/models/boat.glb', import.meta.url));

function parse(bytes: Buffer): Promise<GLTF> {
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) as ArrayBuffer;
  return new Promise((resolve, reject) => new GLTFLoader().parse(buffer, '', resolve, reject));
}

describe('public/models/boat.glb', () => {
  it('parses with three.js GLTFLoader into a boat-sized hull with its named materials', async () => {
    const gltf = await parse(GLB);
    const meshes: Mesh[] = [];
    gltf.scene.traverse((o) => {
      if (o instanceof Mesh) meshes.push(o);
    });
    const names = meshes.map((m) => (m.material as MeshStandardMaterial).name).sort();
    expect(names).toEqual(['Boot stripe', 'Cabin', 'Hull', 'Mast and boom', 'Sails', 'Teak deck', 'Windows']);
    const box = new Box3().setFromObject(gltf.scene);
    // Bow to stern along z, beam along x, waterline at y = 0 with the keel below it.
    expect(box.max.z - box.min.z).toBeCloseTo(8, 6);
    expect(box.max.x - box.min.x).toBeCloseTo(2.6, 6);
    expect(box.min.y).toBeCloseTo(-0.62, 6);
    expect(box.max.y).toBeCloseTo(9.6, 6);
    for (const mesh of meshes) {
      const normals = mesh.geometry.getAttribute('normal');
      for (let i = 0; i < normals.count; i++) expect(Math.hypot(normals.getX(i), normals.getY(i), normals.getZ(i))).toBeCloseTo(1, 5);
    }
  });

  it('rejects bytes that are not a GLB, which is what the app turns into a notice', async () => {
    await expect(parse(Buffer.from('not a model'))).rejects.toThrow();
  });
});
