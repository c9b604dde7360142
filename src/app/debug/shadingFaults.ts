import { NoToneMapping, type Material } from 'three';
import { drawThroughHighlightRollOff } from '../../render/tone/wholeFrameToneCurve';
import type { OceanView } from '../../render/ocean/oceanView';
import { renderOrigin } from '../../render/ocean/renderOrigin';

/** The fixes for far and very close views, each on unless a negative control turns it off. */
export interface ShadingFixes {
  /** Per-pixel detail normals in the far bands (shaders/ocean.frag, WAVE_DETAIL_NORMALS). */
  detailNormals: boolean;
  /** Positions relative to a render origin near the camera on the GPU (OceanMaterial.originFor). */
  cameraRelative: boolean;
  /** The sea bed marks itself as under the water for the waterline test (shaders/waterline.glsl). */
  seaBedMark: boolean;
  /** Gerstner's and FFT's per-pixel normals and foam at grid points relative to the render origin (ocean.frag). */
  relativePixelNormals: boolean;
  /** The near plane brought in for an eye less than about a metre above the water (src/render/ocean/nearPlane.ts). */
  clearanceNear: boolean;
  /** The glint from slopes a pixel cannot resolve turned into roughness (Cox–Munk, shaders/ocean.frag sunGlint). */
  slopeRoughness: boolean;
  /** The roughness follows the wind (Cox & Munk's σ² for U less what the normals show); off: one roughness, a 10 m/s sea's, at every wind. */
  windRoughness: boolean;
  /** The foam left behind drawn as thin lace that fades (shaders/waves/fft.glsl fftFoamAt), not solid white. */
  foamCoverage: boolean;
  /** The breakup field that keeps the whitecaps off the FFT tiles' lattice (shaders/foam/foamBreakup.glsl). */
  foamBreakup: boolean;
  /** Far away, the two shorter FFT tiles read twice and blended by a field that never repeats (shaders/waves/fft.glsl fftBlendCopies). */
  tileCopies: boolean;
  /** The foam left behind carried by the surface's wind drift (src/sim/waves/fft/foamDrift.ts); off: it stays where it was laid. */
  foamDrift: boolean;
  /** Far foam shaded by the lace's density where the pixel covers many bubbles (shaders/foam/foamMaterial.glsl foamOver), not by its thickness alone. */
  farLace: boolean;
  /** Foam's edges feathered: thinning foam shows only the densest lace (shaders/foam/foamMaterial.glsl foamOver); off, every foam is solid above half its thickness and absent below, cut along a hard line. */
  featheredEdges: boolean;
  /** Foam reflects what measured foam reflects (src/sim/optics/foamReflectance.ts); off: the brighter albedo drawn before, (0.72, 0.77, 0.80), above every measurement. */
  foamReflectance: boolean;
  /** Foam lit by the sky's colour (shaders/foam/foamMaterial.glsl foamOver); off: by the sky's luminance alone, as a grey ambient light. */
  foamSkyColour: boolean;
  /** The subsurface glow only where the surface is a crest (shaders/subsurface.glsl), not on every wave alike. */
  subsurfaceCrests: boolean;
  /** The water's colour as its optics give it; off: 3 % brighter, the smallest change the reference comparison must catch. */
  exactWaterColour: boolean;
  /** The whole frame through the highlight roll-off (src/render/tone/wholeFrameToneCurve.ts); off: the renderer has no tone curve, the sea rolls its own highlights off and the rest clips at white. */
  wholeFrameToneCurve: boolean;
  /** The sun's disc in the sky in its full brightness (src/render/sky/skyBackground.ts); off: only as the cube holds it, white (1). */
  sunInFullBrightness: boolean;
  /** The disc's edge antialiased after the tone curve (src/render/sky/sunDiscSquare.ts); off: it steps by whole pixels. */
  sunDiscEdge: boolean;
  /** A sea of one roughness everywhere (the seed's) reads the sky blurred once for it (src/render/sky/prefilteredSky.ts); off: two of the sky's mip levels per pixel, blended. */
  prefilteredSky: boolean;
  /** The prefiltered sky painted again when the sun moves (and the sky with it); off: it keeps the sky of the sun it was first painted for. */
  prefilterFollowsSun: boolean;
  /** Whole view under the water: back faces only, the sea bed's test skipped below every trough, the far plane at the fog's reach. */
  underwaterShortcuts: boolean;
}

/** A fault planted in a shader's text: each `find` must be there, or the control would test nothing. */
interface ShaderFault {
  name: string;
  fragment: readonly [find: string, replace: string][];
}

/** Per-pixel detail normals weighted to nothing: the far bands keep their vertex normals. */
const NO_DETAIL_NORMALS: ShaderFault = {
  name: 'no-detail-normals',
  fragment: [['float weight = smoothstep(DETAIL_FROM', 'float weight = 0.0 * smoothstep(DETAIL_FROM']],
};
/** Per-pixel normals and foam at absolute grid points, where float32 moves in 6 cm steps 10⁶ m out. */
const ABSOLUTE_PIXELS: ShaderFault = {
  name: 'absolute-pixels',
  fragment: [
    ['wavePixelFields(vRelativeGridXZ, true)', 'wavePixelFields(vGridXZ, false)'],
    ['waveNormalNear(vRelativeGridXZ)', 'waveNormal(vGridXZ)'],
    ['waveFoamNear(vRelativeGridXZ)', 'waveFoam(vGridXZ)'],
  ],
};
/**
 * The glint as it was: a fixed pow(…, 900) highlight that does not know the wind, and the
 * sky in a perfect mirror; with every slope in every pixel, however far: each cascade's
 * (fft) or each trochoid's (gerstner).
 */
const FIXED_GLINT: ShaderFault = {
  name: 'fixed-glint',
  fragment: [
    ['color += sunGlint(n, v, roughness, facetReflectance);', 'color += sunLobe(dot(n, halfway), 900.0, 40.0) * reflectance;'],
    ['skyCubeColorRough(r, roughness)', 'skyCubeColor(normalize(r))'],
    ['textureLod(uPrefilteredSky, r, 0.0).rgb', 'sqrt(skyCubeColor(normalize(r)))'],
  ],
};
/** The roughness of a 10 m/s sea (Cox & Munk's 0.055 less a few thousandths resolved) whatever the wind. */
const WINDLESS_ROUGHNESS: ShaderFault = {
  name: 'windless-roughness',
  fragment: [['float roughness = waveUnresolvedSlopeVariance();', 'float roughness = 0.05 + 0.0 * waveUnresolvedSlopeVariance();']],
};
const EVERY_CASCADE_SLOPE: ShaderFault = {
  name: 'every-cascade-slope',
  fragment: [['vec3 share = clamp(', 'vec3 share = vec3(1.0) + 0.0 * clamp(']],
};
const EVERY_TROCHOID_SLOPE: ShaderFault = {
  name: 'every-trochoid-slope',
  fragment: [['float share = gerstnerShare(uGerstnerWaves[i], gerstnerFootprint);', 'float share = 1.0;']],
};
/** The foam left behind drawn solid white wherever it lies, as paint: blotches, and more white than Monahan's. */
const SOLID_KEPT_FOAM: ShaderFault = {
  name: 'solid-kept-foam',
  fragment: [['FOAM_KEPT_THICKNESS * smoothstep(0.5, 2.5, potential)', 'smoothstep(0.5, 1.0, potential)']],
};
/**
 * The whitecaps on the FFT tiles' lattice again: the breakup field read at the grid point
 * folded into the smallest tile, so it repeats with that tile (same statistics, same coverage).
 */
const TILED_FOAM: ShaderFault = {
  name: 'tiled-foam',
  fragment: [
    [
      'float breakup = fftBreakup(p, near);',
      'float breakup = foamBreakup(mod(p + uFftNearOffset[2] / uFftScale.z, uFftN / uFftScale.z), true);',
    ],
  ],
};
/** Every FFT tile read once at every distance: its repeat shows from high above. */
const SINGLE_TILES: ShaderFault = {
  name: 'single-tiles',
  fragment: [['float far = smoothstep(TILE_COPY_FROM, TILE_COPY_FULL, footprint);', 'float far = 0.0;']],
};
/** Far foam's share of a pixel its thickness alone, as smooth grey patches: the lace's patches and streaks averaged away. */
const SMOOTH_FAR_FOAM: ShaderFault = {
  name: 'smooth-far-foam',
  fragment: [['clamp(amount * density / uFoamDensityMean, 0.0, 1.0)', 'amount']],
};
/** Foam cut hard at half its thickness, near and far: no lace thinning towards its edges. */
const HARD_FOAM_EDGES: ShaderFault = {
  name: 'hard-foam-edges',
  fragment: [
    ['float laced = smoothstep(1.0 - amount - FOAM_FEATHER, 1.0 - amount + FOAM_FEATHER, density);', 'float laced = step(0.5, amount);'],
    ['clamp(amount * density / uFoamDensityMean, 0.0, 1.0)', 'step(0.5, amount)'],
  ],
};
/** Foam as bright as the albedo it was drawn with before its reflectance was measured foam's. */
const BRIGHTER_FOAM: ShaderFault = {
  name: 'brighter-foam',
  fragment: [['vec3 foam = FOAM_REFLECTANCE *', 'vec3 foam = vec3(0.72, 0.77, 0.80) *']],
};
/** Foam lit by a grey sky of the sky's luminance: no blue from above. */
const GREY_SKY_ON_FOAM: ShaderFault = {
  name: 'grey-sky-on-foam',
  fragment: [
    [
      'vec3 skyLight = 3.14159265 * skyCubeColor(normalize(nf + vec3(0.0, 1.0, 0.0)));',
      'vec3 skyLight = vec3(3.14159265 * dot(skyCubeColor(normalize(nf + vec3(0.0, 1.0, 0.0))), vec3(0.2126, 0.7152, 0.0722)));',
    ],
  ],
};
/** The subsurface glow on every pixel alike, crest or trough. */
const GLOW_EVERYWHERE: ShaderFault = {
  name: 'glow-everywhere',
  fragment: [['float crest = crestPinch()', 'float crest = 1.0 + 0.0 * crestPinch()']],
};
/** The water's own colour 3 % brighter. */
const BRIGHTER_WATER: ShaderFault = { name: 'brighter-water', fragment: [['vec3 water = vWaterBody;', 'vec3 water = 1.03 * vWaterBody;']] };
/** The sand written with alpha 1, as if it were above the water, for the waterline test. */
const UNMARKED_SEA_BED: ShaderFault = { name: 'unmarked-sea-bed', fragment: [['SEA_BED_ALPHA);', '1.0);']] };

/** Plants or removes faults in a material's fragment shader; the program is rebuilt with them. */
function plant(material: Material, faults: readonly ShaderFault[]): void {
  material.onBeforeCompile = (shader) => {
    for (const fault of faults) {
      for (const [find, replace] of fault.fragment) {
        if (!shader.fragmentShader.includes(find)) throw new Error(`The fault '${fault.name}' found nothing to replace: '${find}'.`);
        shader.fragmentShader = shader.fragmentShader.split(find).join(replace);
      }
    }
  };
  const key = faults.map((f) => f.name).join('+');
  material.customProgramCacheKey = () => key;
  material.needsUpdate = true;
}

/** What each view has planted, so turning one fix back on keeps the others off. */
const planted = new WeakMap<OceanView, Set<ShaderFault>>();

/** Turns off (or back on) the fixes that tests/browser/shading, waterline and underwater show they catch. */
export function setShadingFixes(view: OceanView, fixes: Partial<ShadingFixes>): void {
  const faults = planted.get(view) ?? new Set<ShaderFault>();
  planted.set(view, faults);
  const toggle = (fault: ShaderFault, fixed: boolean | undefined) => {
    if (fixed === undefined) return;
    if (fixed) faults.delete(fault);
    else faults.add(fault);
  };
  toggle(NO_DETAIL_NORMALS, fixes.detailNormals);
  toggle(ABSOLUTE_PIXELS, fixes.relativePixelNormals);
  toggle(UNMARKED_SEA_BED, fixes.seaBedMark);
  toggle(FIXED_GLINT, fixes.slopeRoughness);
  toggle(WINDLESS_ROUGHNESS, fixes.windRoughness);
  const waves = view.ocean.getAllParams().waves;
  toggle(EVERY_CASCADE_SLOPE, waves === 'fft' ? fixes.slopeRoughness : true);
  toggle(EVERY_TROCHOID_SLOPE, waves === 'gerstner' ? fixes.slopeRoughness : true);
  toggle(SOLID_KEPT_FOAM, fixes.foamCoverage);
  toggle(TILED_FOAM, fixes.foamBreakup);
  toggle(SINGLE_TILES, waves === 'fft' ? fixes.tileCopies : true);
  toggle(SMOOTH_FAR_FOAM, fixes.farLace);
  toggle(HARD_FOAM_EDGES, fixes.featheredEdges);
  toggle(BRIGHTER_FOAM, fixes.foamReflectance);
  toggle(GREY_SKY_ON_FOAM, fixes.foamSkyColour);
  toggle(GLOW_EVERYWHERE, fixes.subsurfaceCrests);
  toggle(BRIGHTER_WATER, fixes.exactWaterColour);
  const ocean = view.ocean;
  const material = ocean.material;
  const oceanFaults = [...faults].filter((f) => f !== UNMARKED_SEA_BED);
  for (const m of [material, material.near]) plant(m, oceanFaults);
  plant(ocean.seaBed.material, faults.has(UNMARKED_SEA_BED) ? [UNMARKED_SEA_BED] : []);
  if (fixes.wholeFrameToneCurve !== undefined) {
    if (fixes.wholeFrameToneCurve) drawThroughHighlightRollOff(view.renderer);
    else view.renderer.toneMapping = NoToneMapping;
  }
  if (fixes.sunInFullBrightness !== undefined) ocean.skyBackground.setSunInFullBrightness(fixes.sunInFullBrightness);
  if (fixes.sunDiscEdge !== undefined) ocean.skyBackground.setSunDiscEdge(fixes.sunDiscEdge);
  if (fixes.prefilteredSky !== undefined) material.prefiltering = fixes.prefilteredSky;
  if (fixes.prefilterFollowsSun !== undefined && material.prefilteredSky) material.prefilteredSky.followsSun = fixes.prefilterFollowsSun;
  if (fixes.cameraRelative !== undefined) material.originFor = fixes.cameraRelative ? renderOrigin : () => [0, 0];
  if (fixes.foamDrift !== undefined) ocean.waveModelView.setFoamDrift?.(fixes.foamDrift);
  if (fixes.clearanceNear !== undefined) view.clearance.nearFitted = fixes.clearanceNear;
  if (fixes.underwaterShortcuts !== undefined) {
    ocean.underwaterShortcuts = fixes.underwaterShortcuts;
    view.clearance.farFitted = fixes.underwaterShortcuts;
    ocean.apply(ocean.getAllParams());
  }
}
