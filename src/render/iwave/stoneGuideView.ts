import { BufferAttribute, BufferGeometry, LineBasicMaterial, LineSegments } from 'three';
import { crestRadii, stoneGuideReach, waveFrontRadius } from '../../sim/iwave/cauchyPoissonRings';
import { WAVE_EQUATION_SPEED, type IWaveEquation } from '../../sim/iwave/interactiveField';
import type { Stone } from '../../sim/iwave/iwaveGrid';

/** Segments per ring, stones and rings per stone drawn at most. */
const SEGMENTS = 96;
const MAX_STONES = 12;
const MAX_RINGS = 12;
/** Steps a stone keeps its rings (60 s): by then its crests in the band have left the grid. */
const GUIDE_STEPS = 3600;
/** Metres above the calm water the rings are drawn at (they are drawn over the water regardless). */
const LIFT = 0.05;

/**
 * The `iwaveGuide` overlay: round each stone, where theory puts its crests now. On deep water
 * (iWave) the Cauchy–Poisson crests, r = g t²/(8πn), those inside the grid's band; under the
 * plain wave equation its one ring, r = c t. Side by side, each stone gets its half's.
 */
export class StoneGuideView {
  private readonly positions = new Float32Array(MAX_STONES * MAX_RINGS * SEGMENTS * 6);
  private readonly geometry = new BufferGeometry();
  private readonly material = new LineBasicMaterial({ color: 0xffd23f, depthTest: false, transparent: true, opacity: 0.85 });
  /** The lines, in world coordinates: add them to the scene (the Ocean holds them). */
  readonly lines: LineSegments;
  /** What the positions on the GPU were drawn from: the same again uploads nothing. */
  private drawnFrom = '';

  constructor() {
    this.geometry.setAttribute('position', new BufferAttribute(this.positions, 3));
    this.lines = new LineSegments(this.geometry, this.material);
    this.lines.name = 'StoneGuide';
    this.lines.renderOrder = 10;
    this.lines.frustumCulled = false;
    this.lines.matrixAutoUpdate = false;
    this.lines.visible = false;
  }

  /** How long a stone keeps its rings, in steps. */
  static readonly steps = GUIDE_STEPS;

  /** The rings of `stones` at `time`, the field centred at x = `centreX` (side by side: which half a stone is in), or none. */
  update(visible: boolean, stones: readonly Stone[], time: number, equation: IWaveEquation, centreX: number): void {
    this.lines.visible = visible;
    if (!visible) return;
    const from = `${time} ${equation} ${centreX} ${stones.slice(-MAX_STONES).join(';')}`;
    if (from === this.drawnFrom) return;
    // Rings stop where the sponge starts, and show only the waves the field carries.
    const reach = stoneGuideReach();
    const open = reach.maxRadius;
    let count = 0;
    for (const [dropped, x, z] of stones.slice(-MAX_STONES)) {
      const age = time - dropped;
      const wave = equation === 'non-dispersive' || (equation === 'side-by-side' && x >= centreX);
      const radii = wave ? [waveFrontRadius(age, WAVE_EQUATION_SPEED)].filter((r) => r > 0 && r <= open) : crestRadii(age, reach);
      for (const r of radii.slice(0, MAX_RINGS)) {
        for (let s = 0; s < SEGMENTS; s++) {
          const a = (2 * Math.PI * s) / SEGMENTS;
          const b = (2 * Math.PI * (s + 1)) / SEGMENTS;
          this.positions.set([x + r * Math.cos(a), LIFT, z + r * Math.sin(a), x + r * Math.cos(b), LIFT, z + r * Math.sin(b)], count * 6);
          count++;
        }
      }
    }
    this.geometry.setDrawRange(0, 2 * count);
    this.drawnFrom = from;
    // No rings (every stone's have left the grid): nothing drawn, nothing to upload.
    if (count === 0) return;
    // Only the rings drawn travel to the GPU, not the whole room for twelve stones.
    const position = this.geometry.getAttribute('position') as BufferAttribute;
    position.clearUpdateRanges();
    position.addUpdateRange(0, count * 6);
    position.needsUpdate = true;
  }

  dispose(): void {
    this.lines.removeFromParent();
    this.geometry.dispose();
    this.material.dispose();
  }
}
