/**
 * The views the light is measured in. The glint: an FFT sea seen toward a sun 25° high from
 * 20 m up, the camera pitched 15° down along the sun's azimuth, so the reflection's centre
 * (25° down) sits below the middle of the frame and the horizon (55° vertical field) at row
 * ≈ 87 of 360. The horizon: the eye 10 m up looking level, the horizon on the middle row.
 */
const SUN_AZIMUTH = 20;
const SUN_ELEVATION = 25;
const GLINT_EYE = 20;
const GLINT_PITCH = -15;

function towards(azimuthDeg: number, pitchDeg: number, distance: number, from: [number, number, number]): [number, number, number] {
  const a = (azimuthDeg * Math.PI) / 180;
  const p = (pitchDeg * Math.PI) / 180;
  return [from[0] + distance * Math.sin(a) * Math.cos(p), from[1] + distance * Math.sin(p), from[2] - distance * Math.cos(a) * Math.cos(p)];
}

const glintEye: [number, number, number] = [0, GLINT_EYE, 0];
const glintTarget = towards(SUN_AZIMUTH, GLINT_PITCH, 100, glintEye);

export const GLINT_VIEW = { width: 640, height: 360, seaTop: 100, t: 10 } as const;

/** The glint's view on any wave model (foam off: it is the spectral sea's alone). */
export function glintQuery(windSpeed: number, waves: 'fft' | 'seed' | 'gerstner' = 'fft'): string {
  const cam = [...glintEye, ...glintTarget].map((c) => c.toFixed(3)).join(',');
  return `waves=${waves}&foam=false&windSpeed=${windSpeed}&sunElevation=${SUN_ELEVATION}&sunAzimuth=${SUN_AZIMUTH}&t=${GLINT_VIEW.t}&cam=${cam}`;
}

/** Rows just below the horizon (the far sea) and at the bottom of the frame (the sea near the eye). */
export const HORIZON_VIEW = { width: 640, height: 360, t: 10, farBand: [182, 198], nearBand: [330, 360] } as const;

export function horizonQuery(windSpeed: number, waves: 'fft' | 'seed' | 'gerstner' = 'fft'): string {
  return `waves=${waves}&windSpeed=${windSpeed}&t=${HORIZON_VIEW.t}&cam=0,10,0,0,10,-1000`;
}

/**
 * Foam seen from 150 m straight above, the sun 30° high: its glint lies 60° off the nadir,
 * outside the 55° frame. Four instants 30 s apart: in a gale the frame holds only a few of the
 * whitecaps' groups (foamBreakup.ts), and one instant's white share scatters by ±30 %.
 */
export const FOAM_VIEW = { width: 480, height: 270, t: 10, sunElevation: 30, times: [10, 40, 70, 100] } as const;

export function foamQuery(windSpeed: number): string {
  return `waves=fft&windSpeed=${windSpeed}&sunElevation=${FOAM_VIEW.sunElevation}&t=${FOAM_VIEW.t}&cam=0,150,0,0,0,-0.01`;
}

/** The sea seen from 400 m straight above, for the foam's repeat: 640 × 360 px, 1.16 m a pixel; four instants 30 s apart. */
export const TILING_VIEW = { width: 640, height: 360, altitude: 400, sunElevation: 30, times: [10, 40, 70, 100] } as const;

export function tilingQuery(windSpeed: number): string {
  return `waves=fft&windSpeed=${windSpeed}&sunElevation=${TILING_VIEW.sunElevation}&t=${TILING_VIEW.times[0]}&cam=0,${TILING_VIEW.altitude},0,0,0,-0.01`;
}

/** Metres per pixel of TILING_VIEW: looking straight down, the sea plane is parallel to the picture, so the scale is the same everywhere. */
export function tilingMetresPerPixel(): number {
  return (2 * TILING_VIEW.altitude * Math.tan((27.5 * Math.PI) / 180)) / TILING_VIEW.height;
}

/**
 * Crests seen against a low sun: the eye 6 m above a 15 m/s sea, looking 2° down towards the
 * sun's azimuth less 12° (the glint off to one side), the sun 5° high, foam off.
 */
export const GLOW_VIEW = { width: 480, height: 270, t: 10, eye: [0, 6, 0], target: [0, 4, -100] } as const;

export function glowQuery(subsurface: boolean, waves: 'fft' | 'seed' | 'gerstner' = 'fft'): string {
  const cam = [...GLOW_VIEW.eye, ...GLOW_VIEW.target].join(',');
  return `waves=${waves}&windSpeed=15&sunElevation=5&sunAzimuth=12&foam=false&subsurface=${subsurface}&t=${GLOW_VIEW.t}&cam=${cam}`;
}
