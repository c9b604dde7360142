/**
 * Shader chunks whose text arrives with code fetched later (a dynamic import), so the page's
 * first load does not carry them: the foam material (`oceano_foam`) comes with the foam's detail
 * texture, the boat's wake (`oceano_wake`) with the wake (src/render/wake/wakeChunk.ts), the
 * interactive waves' field (`oceano_iwave`) with their code, the coast (`oceano_coast`) with
 * its code (src/render/coast/coastChunk.ts). Until a chunk arrives its include resolves to nothing, and the program that needs it
 * is not compiled (its #define stays off). When it arrives, every WaveBinding that shares this
 * supply binds its materials again (WaveBinding.resolve reads `texts`).
 */
export type LateChunkName = 'oceano_foam' | 'oceano_wake' | 'oceano_iwave' | 'oceano_coast';

export class LateChunks {
  /** Every late chunk's text, '' until it arrives. */
  readonly texts: Record<LateChunkName, string> = { oceano_foam: '', oceano_wake: '', oceano_iwave: '', oceano_coast: '' };
  private readonly listeners = new Set<() => void>();

  has(name: LateChunkName): boolean {
    return this.texts[name] !== '';
  }

  provide(name: LateChunkName, text: string): void {
    if (this.texts[name] === text) return;
    this.texts[name] = text;
    for (const listener of this.listeners) listener();
  }

  /** Calls `listener` whenever a chunk arrives; returns what stops it. */
  subscribe(listener: () => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }
}
