import { describe, expect, it } from 'vitest';
import {
  BoxGeometry,
  Group,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshStandardMaterial,
  Scene,
  ShaderChunk,
  ShaderMaterial,
  type WebGLProgramParametersWithUniforms,
  type WebGLRenderer,
} from 'three';
import {
  encodeSceneForPost,
  markOceanoMaterial,
  SCENE_BRIGHTEST,
  SCENE_ENCODE_CHUNK,
  SCENE_LOW_CODES,
} from '../../../../src/render/underwater/sceneEncoding';
import { SCENE_DECODE_CHUNK, withPassChunks } from '../../../../src/render/underwater/passChunks';
import { resolveChunks } from '../../../../src/render/shaders/shaderChunks';

const DEFINE = 'OCEANO_SCENE_ENCODE';
const THREE_CHUNKS = { ...ShaderChunk };

function sceneOfEveryKind() {
  const scene = new Scene();
  const ours = markOceanoMaterial(new ShaderMaterial({ defines: { KEEP: '' } }));
  const standard = new MeshStandardMaterial();
  const pair = [new MeshStandardMaterial(), new MeshStandardMaterial()];
  const line = new LineBasicMaterial();
  const nested = new Group();
  nested.add(new Mesh(new BoxGeometry(), pair));
  scene.add(new Mesh(new BoxGeometry(), ours), new Mesh(new BoxGeometry(), standard), new LineSegments(new BoxGeometry(), line), nested);
  return { scene, ours, others: [standard, ...pair, line] };
}

/** What three hands a material's onBeforeCompile, reduced to the part the patch reads. */
function compiled(material: MeshStandardMaterial): string {
  const shader = {
    fragmentShader: 'main {\n#include <colorspace_fragment>\n}',
    vertexShader: '',
    uniforms: {},
  } as unknown as WebGLProgramParametersWithUniforms;
  material.onBeforeCompile(shader, null as unknown as WebGLRenderer);
  return shader.fragmentShader;
}

describe("the underwater passes' scene encoding (src/render/underwater/sceneEncoding.ts)", () => {
  it("flips only Oceano's own materials unless every material is asked for", () => {
    const { scene, ours, others } = sceneOfEveryKind();
    encodeSceneForPost(scene, true);
    expect(ours.defines[DEFINE]).toBe('');
    for (const m of others) expect(m.defines && DEFINE in m.defines).toBeFalsy();
    encodeSceneForPost(scene, false);
    expect(DEFINE in ours.defines).toBe(false);
    expect(ours.defines.KEEP).toBe('');
  });

  it('opted in, patches every other material, nested and multi-material ones included, and removes the define again', () => {
    const { scene, others } = sceneOfEveryKind();
    encodeSceneForPost(scene, true, true);
    for (const m of others) expect(m.defines?.[DEFINE]).toBe('');
    encodeSceneForPost(scene, false, true);
    for (const m of others) expect(m.defines && DEFINE in m.defines).toBe(false);
  });

  // The encoding goes after three's colour-space chunk.
  it("chains a material's own onBeforeCompile and program key, and appends the encoding", () => {
    const standard = new MeshStandardMaterial();
    standard.onBeforeCompile = (shader) => void (shader.fragmentShader = `// hull caustics\n${shader.fragmentShader}`);
    standard.customProgramCacheKey = () => 'hull';
    const scene = new Scene().add(new Mesh(new BoxGeometry(), standard));
    encodeSceneForPost(scene, true, true);
    const text = compiled(standard);
    expect(text.startsWith('// hull caustics')).toBe(true);
    expect(text.indexOf('#include <colorspace_fragment>')).toBeLessThan(text.indexOf('#ifdef OCEANO_SCENE_ENCODE'));
    expect(standard.customProgramCacheKey()).toBe('hull|oceano-scene-encode');
    // Patched once: a second frame adds nothing.
    encodeSceneForPost(scene, true, true);
    expect(compiled(standard).match(/#ifdef OCEANO_SCENE_ENCODE/g)).toHaveLength(1);
  });

  it('recompiles a material only when its encoding changes', () => {
    const { scene, ours } = sceneOfEveryKind();
    const start = ours.version;
    encodeSceneForPost(scene, false);
    expect(ours.version).toBe(start);
    encodeSceneForPost(scene, true);
    expect(ours.version).toBe(start + 1);
    encodeSceneForPost(scene, true);
    expect(ours.version).toBe(start + 1);
  });

  it("resolves Oceano's chunks per shader and leaves three's ShaderChunk table as three ships it", () => {
    const text = resolveChunks(
      withPassChunks('#include <common>\n#include <colorspace_fragment>\n#include <oceano_scene_encode>\n#include <oceano_scene_decode>'),
    );
    expect(text).toContain('#include <common>');
    expect(text).toContain(SCENE_ENCODE_CHUNK);
    expect(text).toContain(SCENE_DECODE_CHUNK);
    expect(SCENE_DECODE_CHUNK).toContain(`#define SCENE_LOW_SHARE ${SCENE_LOW_CODES / 255}`);
    expect(SCENE_DECODE_CHUNK).toContain(`#define SCENE_BRIGHTEST ${SCENE_BRIGHTEST}.0`);
    expect(() => resolveChunks('#include <oceano_nonesuch>')).toThrow(/oceano_nonesuch/);
    expect({ ...ShaderChunk }).toEqual(THREE_CHUNKS);
    expect(Object.keys(ShaderChunk).filter((name) => name.startsWith('oceano'))).toEqual([]);
  });
});
