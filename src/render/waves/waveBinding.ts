import type { IUniform, Material, ShaderMaterial } from 'three';
import type { WaveModelView } from './waveModelView';
import { resolveChunks } from '../shaders/shaderChunks';
import { LateChunks } from '../shaders/lateChunks';

interface BoundShader {
  material: ShaderMaterial;
  vertexShader: string;
  fragmentShader: string;
}

/**
 * Keeps every material that reads the waves bound to the active model: `#include
 * <oceano_waves>` is replaced by the model's own chunk and the model's uniforms are put in
 * the material's uniforms. The text is put in per material, never into three's global
 * ShaderChunk table: two oceans on one page with different models, or a switch of model,
 * then have distinct sources, and three.js stays as it ships for everyone else.
 */
export class WaveBinding {
  private readonly shaders: BoundShader[] = [];
  private readonly patched = new Set<Material>();
  private readonly unsubscribe: () => void;

  /** `late`: the chunks that arrive with code fetched later (lateChunks.ts), shared by every binding of one view. */
  constructor(
    private active: WaveModelView,
    readonly late = new LateChunks(),
  ) {
    this.unsubscribe = late.subscribe(() => this.rebind());
  }

  get model(): WaveModelView {
    return this.active;
  }

  /** The model's uniforms, to merge into a shader three builds itself (onBeforeCompile). */
  get uniforms(): Readonly<Record<string, IUniform>> {
    return this.active.uniforms;
  }

  /** GLSL source with `#include <oceano_waves>` replaced by the active model's chunk, and Oceano's other chunks put in place. */
  resolve(source: string): string {
    return resolveChunks(source, { ...this.late.texts, oceano_waves: this.active.chunk });
  }

  /** Binds a ShaderMaterial whose sources contain `#include <oceano_waves>`; returns it. */
  attach<M extends ShaderMaterial>(material: M): M {
    const bound = { material, vertexShader: material.vertexShader, fragmentShader: material.fragmentShader };
    this.shaders.push(bound);
    this.bind(bound, null);
    return material;
  }

  /** A material patched in onBeforeCompile (reading `resolve` and `uniforms` then): recompiled on a switch. */
  attachPatched(material: Material): void {
    this.patched.add(material);
  }

  detach(material: Material): void {
    const k = this.shaders.findIndex((s) => s.material === material);
    if (k >= 0) this.shaders.splice(k, 1);
    this.patched.delete(material);
  }

  /** Switches every bound material to another model (the caller disposes the old one). */
  setModel(model: WaveModelView): void {
    if (model === this.active) return;
    const previous = this.active;
    this.active = model;
    for (const bound of this.shaders) this.bind(bound, previous);
    for (const material of this.patched) material.needsUpdate = true;
  }

  /** Every bound material again, with the late chunks that have arrived since. */
  private rebind(): void {
    for (const bound of this.shaders) this.bind(bound, null);
    for (const material of this.patched) material.needsUpdate = true;
  }

  /** Stops following the late chunks (the binding's materials are detached and disposed by their owner). */
  dispose(): void {
    this.unsubscribe();
  }

  private bind(bound: BoundShader, previous: WaveModelView | null): void {
    const { material } = bound;
    if (previous) for (const key of Object.keys(previous.uniforms)) delete material.uniforms[key];
    Object.assign(material.uniforms, this.active.uniforms);
    material.vertexShader = this.resolve(bound.vertexShader);
    material.fragmentShader = this.resolve(bound.fragmentShader);
    material.needsUpdate = true;
  }
}
