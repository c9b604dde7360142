import { afterEach, describe, expect, it, vi } from 'vitest';
import { readFileSync } from 'node:fs';
import { Box3, Mesh, type MeshStandardMaterial } from 'three';
import { GLTFLoader, type GLTF } from 'three/addons/loaders/GLTFLoader.js';
import { loadBoatModel } from '../../../../src/render/boat/boatModel';

const GLB = readFileSync(new URL('../../../../public/models/boat.glb', import.meta.url));

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
});

describe('loadBoatModel', () => {
  // fetch answered in-process: each case is a server's answer, and loadBoatModel must turn it
  // into a model or into the message its notice shows.
  const serve = (answer: () => Promise<Response>) => vi.stubGlobal('fetch', vi.fn(answer));
  afterEach(() => {
    vi.unstubAllGlobals();
  });

  it('loads the real model as one mesh and measures its hull from the bounding box', async () => {
    serve(async () => new Response(GLB, { status: 200, headers: { 'content-type': 'model/gltf-binary' } }));
    const model = await loadBoatModel('models/boat.glb');
    expect(model.hull.length).toBeCloseTo(8, 6);
    expect(model.hull.beam).toBeCloseTo(2.6, 6);
    expect((model.object as Mesh).isMesh).toBe(true);
  });

  it('names each failure: unreachable, not found, a web page in its place, not glTF, broken glTF', async () => {
    const cases: [() => Promise<Response>, RegExp][] = [
      [() => Promise.reject(new TypeError('Failed to fetch')), /^The boat model "m\/b\.glb" could not be fetched\.$/],
      [async () => new Response('no', { status: 404 }), /was not found \(HTTP 404\)/],
      [
        async () =>
          new Response('<!doctype html><title>app</title>', { status: 200, headers: { 'content-type': 'text/html; charset=utf-8' } }),
        /is missing: the server sent a web page in its place/,
      ],
      [
        async () => new Response('not a model', { status: 200 }),
        /is not a valid glTF model: it is neither a binary \.glb nor a JSON \.gltf file/,
      ],
      // The GLB's magic and header, cut off in its JSON chunk: GLTFLoader's own error, wrapped.
      [async () => new Response(GLB.subarray(0, 600), { status: 200 }), /is not a valid glTF model \(.+\)\.$/],
      [
        async () => new Response('{"asset": {"version": "2.0"}, "scenes": [{"nodes": []}], "scene": 0}', { status: 200 }),
        /has no geometry to float/,
      ],
    ];
    for (const [answer, message] of cases) {
      serve(answer);
      await expect(loadBoatModel('m/b.glb')).rejects.toThrow(message);
    }
  });
});
