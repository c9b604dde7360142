import { describe, expect, it } from 'vitest';
import { BoxGeometry, Group, LineBasicMaterial, LineSegments, Mesh, MeshStandardMaterial, Scene, ShaderChunk, ShaderMaterial } from 'three';
import { encodeSceneForPost, SCENE_BRIGHTEST, SCENE_LOW_CODES } from '../../src/render/underwater/sceneEncoding';
import { registerShaderChunks } from '../../src/render/shaders/shaderChunks';

const DEFINE = 'OCEANO_SCENE_ENCODE';

function sceneOfEveryKind() {
  const scene = new Scene();
  const shader = new ShaderMaterial({ defines: { KEEP: '' } });
  const standard = new MeshStandardMaterial();
  const pair = [new MeshStandardMaterial(), new MeshStandardMaterial()];
  const line = new LineBasicMaterial();
  const nested = new Group();
  nested.add(new Mesh(new BoxGeometry(), pair));
  scene.add(new Mesh(new BoxGeometry(), shader), new Mesh(new BoxGeometry(), standard), new LineSegments(new BoxGeometry(), line), nested);
  return { scene, materials: [shader, standard, ...pair, line] };
}

describe("the underwater passes' scene encoding (src/render/underwater/sceneEncoding.ts)", () => {
  it('defines the encoding on every material in the scene, nested and multi-material ones included, and removes it again', () => {
    const { scene, materials } = sceneOfEveryKind();
    encodeSceneForPost(scene, true);
    for (const m of materials) expect(m.defines?.[DEFINE]).toBe('');
    encodeSceneForPost(scene, false);
    for (const m of materials) expect(m.defines && DEFINE in m.defines).toBe(false);
    expect((materials[0] as ShaderMaterial).defines.KEEP).toBe('');
  });

  it('recompiles a material only when its encoding changes', () => {
    const { scene, materials } = sceneOfEveryKind();
    const versions = () => materials.map((m) => m.version);
    const start = versions();
    encodeSceneForPost(scene, false);
    expect(versions()).toEqual(start);
    encodeSceneForPost(scene, true);
    const encoded = versions();
    expect(encoded).toEqual(start.map((v) => v + 1));
    encodeSceneForPost(scene, true);
    expect(versions()).toEqual(encoded);
  });

  it("ends three.js's colour-space chunk with the encoding, and keeps three's own text", () => {
    const three = ShaderChunk.colorspace_fragment;
    registerShaderChunks();
    registerShaderChunks();
    const chunk = ShaderChunk.colorspace_fragment;
    expect(chunk.startsWith(three.split('\n')[0])).toBe(true);
    expect(chunk.match(/#ifdef OCEANO_SCENE_ENCODE/g)).toHaveLength(1);
    expect(chunk.indexOf('linearToOutputTexel')).toBeLessThan(chunk.indexOf('sqrt('));
    const decode = (ShaderChunk as unknown as Record<string, string>).oceano_scene_decode;
    expect(decode).toContain(`#define SCENE_LOW_SHARE ${SCENE_LOW_CODES / 255}`);
    expect(decode).toContain(`#define SCENE_BRIGHTEST ${SCENE_BRIGHTEST}.0`);
  });
});
