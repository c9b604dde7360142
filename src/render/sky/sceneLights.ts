import { Color, DirectionalLight, HemisphereLight, type Scene } from 'three';
import { HORIZON, SUN, ZENITH } from '../../sim/optics/skyPainter';

/** Direct sun on lit surfaces, in three's physically based units (lux-like intensity). */
const SUN_INTENSITY = 2.6;
/** Sky light from the whole dome: what keeps the shaded sides of the boat from going black. */
const SKY_INTENSITY = 1.6;
/** Distance of the directional light from its target: only its direction matters. */
const SUN_DISTANCE = 100;

/**
 * The lights for the lit objects in the scene (the boat; the ocean shades itself): a
 * directional light from the sun's direction in the sun's colour, and a hemisphere light
 * whose sky half has the painted sky's colour between zenith and horizon and whose ground
 * half is the deep water's colour, as light bounced off the sea.
 */
export class SceneLights {
  private readonly sun = new DirectionalLight(new Color().setRGB(...SUN), SUN_INTENSITY);
  private readonly sky = new HemisphereLight(
    new Color().setRGB(...ZENITH).lerp(new Color().setRGB(...HORIZON), 0.5),
    new Color(),
    SKY_INTENSITY,
  );

  constructor(scene: Scene) {
    scene.add(this.sun, this.sun.target, this.sky);
  }

  /** Sun direction (towards the sun, unit), and the deep water colour as #rrggbb. */
  update(sunDirection: [number, number, number], waterColor: string): void {
    const [x, y, z] = sunDirection;
    this.sun.position.set(x * SUN_DISTANCE, y * SUN_DISTANCE, z * SUN_DISTANCE);
    // The sun fades out as it sets rather than lighting the boat from below the horizon.
    this.sun.intensity = SUN_INTENSITY * Math.min(1, Math.max(0, (y + 0.02) / 0.12));
    this.sky.groundColor.set(waterColor);
  }
}
