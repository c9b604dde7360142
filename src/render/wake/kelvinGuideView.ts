import { BufferAttribute, BufferGeometry, LineBasicMaterial, LineSegments, type Scene } from 'three';
import { kelvinGuideLines } from '../../sim/wake/kelvinGuide';

/** The `wakeGuide` overlay: the ±19.47° lines behind the boat, drawn over the water. */
export class KelvinGuideView {
  private readonly positions = new Float32Array(12);
  private readonly geometry = new BufferGeometry();
  private readonly material = new LineBasicMaterial({ color: 0xffd23f, depthTest: false, transparent: true, opacity: 0.9 });
  private readonly lines: LineSegments;

  constructor(
    private readonly scene: Scene,
    /** Length of each line, metres. */
    private readonly length = 150,
  ) {
    this.geometry.setAttribute('position', new BufferAttribute(this.positions, 3));
    this.lines = new LineSegments(this.geometry, this.material);
    this.lines.name = 'KelvinGuide';
    this.lines.renderOrder = 10;
    this.lines.frustumCulled = false;
    this.lines.visible = false;
    scene.add(this.lines);
  }

  /** Places the lines at the boat (x, z, heading) at height y and shows or hides them. */
  update(visible: boolean, x: number, y: number, z: number, heading: number): void {
    this.lines.visible = visible;
    if (!visible) return;
    const [ax, az, px, pz, sx, sz] = kelvinGuideLines(x, z, heading, this.length);
    this.positions.set([ax, y, az, px, y, pz, ax, y, az, sx, y, sz]);
    (this.geometry.getAttribute('position') as BufferAttribute).needsUpdate = true;
  }

  dispose(): void {
    this.scene.remove(this.lines);
    this.geometry.dispose();
    this.material.dispose();
  }
}
