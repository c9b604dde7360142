import {
  BufferAttribute,
  BufferGeometry,
  DoubleSide,
  Line,
  LineBasicMaterial,
  Mesh,
  MeshBasicMaterial,
  type Camera,
  type Object3D,
} from 'three';

/**
 * The marks the sea tools put on the water: the probe's pin, the ruler's line and its two
 * ends, the keyboard's point. They are drawn over the water (no depth test) because a mark
 * sitting on the surface would otherwise sink half into every trough; and they keep the same
 * size on screen at any distance, so a probe 300 m away can still be seen.
 */

/** A mark's size as a share of its distance from the eye: about 25 px tall on a 768-px-high view. */
const SCREEN_SIZE = 0.03;
/** Drawn after the sea and the boat. */
const OVERLAY_ORDER = 20;

function overlay<T extends Object3D>(object: T): T {
  object.renderOrder = OVERLAY_ORDER;
  object.frustumCulled = false;
  return object;
}

/**
 * A pin's shape, 1 m tall: a cone with its tip at the origin and its base 1 m up, and a flat
 * ring around the tip. Built here rather than from three's ConeGeometry and RingGeometry,
 * which the page's first script (three's chunk) would then carry for every visitor.
 */
function pinGeometry(segments: number): BufferGeometry {
  const positions: number[] = [];
  for (let i = 0; i < segments; i++) {
    const a0 = (2 * Math.PI * i) / segments;
    const a1 = (2 * Math.PI * (i + 1)) / segments;
    const at = (r: number, a: number, y: number) => [r * Math.cos(a), y, r * Math.sin(a)];
    // The cone's side, its top cap, and the ring as two triangles of a quad.
    positions.push(0, 0, 0, ...at(0.25, a0, 1), ...at(0.25, a1, 1));
    positions.push(0, 1, 0, ...at(0.25, a1, 1), ...at(0.25, a0, 1));
    positions.push(...at(0.35, a0, 0), ...at(0.5, a0, 0), ...at(0.5, a1, 0));
    positions.push(...at(0.35, a0, 0), ...at(0.5, a1, 0), ...at(0.35, a1, 0));
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(new Float32Array(positions), 3));
  return geometry;
}

/** A pin standing on the sea: a cone pointing down at the point, and a ring around it. */
export class SeaPin {
  readonly object: Mesh<BufferGeometry, MeshBasicMaterial>;

  constructor(colour: number) {
    // Both faces: the ring is seen from above and the cone from any side.
    const material = new MeshBasicMaterial({ color: colour, depthTest: false, transparent: true, opacity: 0.95, side: DoubleSide });
    this.object = overlay(new Mesh(pinGeometry(16), material));
    this.object.visible = false;
  }

  /** Puts the pin's tip at (x, y, z), sized for `camera`. */
  place(x: number, y: number, z: number, camera: Camera): void {
    this.object.position.set(x, y, z);
    this.object.scale.setScalar(Math.max(0.2, SCREEN_SIZE * camera.position.distanceTo(this.object.position)));
    this.object.visible = true;
  }

  hide(): void {
    this.object.visible = false;
  }

  dispose(): void {
    this.object.removeFromParent();
    this.object.geometry.dispose();
    this.object.material.dispose();
  }
}

/** A line laid on the sea: a polyline through points the caller samples on the surface. */
export class SeaLine {
  readonly object: Line;
  private readonly positions: Float32Array;

  constructor(
    readonly points: number,
    colour: number,
  ) {
    this.positions = new Float32Array(points * 3);
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(this.positions, 3));
    this.object = overlay(new Line(geometry, new LineBasicMaterial({ color: colour, depthTest: false, transparent: true })));
    this.object.visible = false;
  }

  /** Sets point `i` of the line (world metres). */
  set(i: number, x: number, y: number, z: number): void {
    this.positions.set([x, y, z], 3 * i);
  }

  /** Shows the points set since the last call. */
  show(): void {
    this.object.geometry.attributes.position.needsUpdate = true;
    this.object.geometry.computeBoundingSphere();
    this.object.visible = true;
  }

  hide(): void {
    this.object.visible = false;
  }

  dispose(): void {
    this.object.removeFromParent();
    this.object.geometry.dispose();
    (this.object.material as LineBasicMaterial).dispose();
  }
}
