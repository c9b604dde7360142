import type { DiagramKind } from '../../../sim/teaching/diagrams/diagram';
import type { Language } from '../../language/i18n';

type Words = Readonly<Record<Language, string>>;

/**
 * A mark's label: `{v}` is its value, written with `digits` decimals in the page's language
 * (19,47° in Spanish), `{i}` its index in a series counted from `first`.
 */
export interface MarkWords extends Words {
  digits: number;
  first?: number;
}

export interface DiagramWords {
  /** What the picture is, before its key value, for its accessible name. */
  name: Words;
  /** The key value in the name, by mark, where that mark's own label is too short to stand alone. */
  headline?: Readonly<Record<string, MarkWords>>;
  /** Axis titles, for a graph; a picture of space has none. */
  xAxis?: Words;
  yAxis?: Words;
  /** Which line is which. */
  key: Words;
  marks: Readonly<Record<string, MarkWords>>;
}

export const DIAGRAM_WORDS: Readonly<Record<DiagramKind, DiagramWords>> = {
  seedDispersion: {
    name: { en: 'Dispersion ω(k) and the seed swell’s two waves', es: 'Dispersión ω(k) y las dos olas del oleaje de la semilla' },
    xAxis: { en: 'k (rad/m)', es: 'k (rad/m)' },
    yAxis: { en: 'ω (rad/s)', es: 'ω (rad/s)' },
    key: {
      en: 'Blue: deep water, ω = √(gk). sin(kx+ωt)·cos(kz+0.7ωt) is two plane waves of wavenumber √2·k at 1.7ω and 0.3ω (dots): neither sits on the curve.',
      es: 'Azul: aguas profundas, ω = √(gk). sen(kx+ωt)·cos(kz+0,7ωt) son dos ondas planas de número de onda √2·k a 1,7ω y 0,3ω (puntos): ninguna cae sobre la curva.',
    },
    marks: {
      sum: { en: '1.7ω: c = {v} m/s', es: '1,7ω: c = {v} m/s', digits: 1 },
      curve: { en: 'ω(√2k): c = {v} m/s', es: 'ω(√2k): c = {v} m/s', digits: 1 },
      difference: { en: '0.3ω: c = {v} m/s', es: '0,3ω: c = {v} m/s', digits: 1 },
    },
  },
  depthDispersion: {
    name: { en: 'Dispersion at the current depth', es: 'Dispersión a la profundidad actual' },
    xAxis: { en: 'k (rad/m)', es: 'k (rad/m)' },
    yAxis: { en: 'ω (rad/s)', es: 'ω (rad/s)' },
    key: {
      en: 'Blue: ω² = gk·tanh(kh) at this depth (grey: deep water). Yellow slope: phase speed ω/k; green tangent: group speed dω/dk, at the spectrum’s peak.',
      es: 'Azul: ω² = gk·tanh(kh) a esta profundidad (gris: aguas profundas). Pendiente amarilla: velocidad de fase ω/k; tangente verde: velocidad de grupo dω/dk, en el pico del espectro.',
    },
    marks: {
      peak: { en: 'peak, λ = {v} m', es: 'pico, λ = {v} m', digits: 0 },
      phase: { en: 'phase speed {v} m/s', es: 'velocidad de fase {v} m/s', digits: 1 },
      group: { en: 'group {v} m/s', es: 'grupo {v} m/s', digits: 1 },
    },
  },
  orbit: {
    name: { en: 'A particle’s orbit under the tallest wave', es: 'La órbita de una partícula bajo la ola más alta' },
    key: {
      en: 'Blue: Gerstner’s trochoid and its orbit, an ellipse QA across, A up. Yellow: Airy’s sine and circle. Grey: Airy’s orbits below, radius A·e^{kz}.',
      es: 'Azul: la trocoide de Gerstner y su órbita, una elipse de QA de ancho y A de alto. Amarillo: el seno y el círculo de Airy. Gris: las órbitas de Airy más abajo, de radio A·e^{kz}.',
    },
    marks: {
      steepness: { en: 'Q = {v}', es: 'Q = {v}', digits: 2 },
      wavelength: { en: 'λ = {v} m', es: 'λ = {v} m', digits: 1 },
      amplitude: { en: 'A = {v} m', es: 'A = {v} m', digits: 2 },
      decay: { en: '{v} %', es: '{v} %', digits: 0 },
      exaggeration: { en: 'heights ×{v}', es: 'alturas ×{v}', digits: 0 },
    },
  },
  snell: {
    name: { en: 'Snell’s window seen from below', es: 'La ventana de Snell vista desde abajo' },
    key: {
      en: 'Blue: rays that leave into the air, bent away from the normal. Yellow: the window’s edge, where the refracted ray grazes the surface. Green: beyond it, total internal reflection.',
      es: 'Azul: rayos que salen al aire, desviados lejos de la normal. Amarillo: el borde de la ventana, donde el rayo refractado roza la superficie. Verde: más allá, reflexión total interna.',
    },
    marks: {
      critical: { en: 'critical angle {v}°', es: 'ángulo crítico {v}°', digits: 1 },
      window: { en: 'radius {v} × depth', es: 'radio {v} × profundidad', digits: 2 },
      eye: { en: 'eye', es: 'ojo', digits: 0 },
    },
  },
  spectrum: {
    name: { en: 'The wind’s spectrum S(ω)', es: 'El espectro del viento S(ω)' },
    xAxis: { en: 'ω (rad/s)', es: 'ω (rad/s)' },
    yAxis: { en: 'S(ω) (m²·s)', es: 'S(ω) (m²·s)' },
    key: {
      en: 'Blue: the spectrum the sea is drawn from, for this wind; grey: the other two spectra for the same wind.',
      es: 'Azul: el espectro del que sale el mar, para este viento; gris: los otros dos espectros con el mismo viento.',
    },
    marks: {
      peak: { en: 'peak ωp = {v} rad/s', es: 'pico ωp = {v} rad/s', digits: 2 },
      wavelength: { en: 'λp = {v} m', es: 'λp = {v} m', digits: 1 },
    },
  },
  butterflies: {
    name: { en: 'The FFT’s butterflies', es: 'Las mariposas de la FFT' },
    key: {
      en: 'An 8-point Stockham inverse FFT, as each fragment reads it: output o takes in[j] (grey) plus (blue) or minus (yellow) a twiddle times in[j+n/2]. No bit reversal. Below, the live sea: the row z = 0 of tile 1, its spectrum and |value| after each stage the sea runs (yellow), ending in the heights it draws (blue).',
      es: 'Una FFT inversa de Stockham de 8 puntos, como la lee cada fragmento: la salida o toma in[j] (gris) más (azul) o menos (amarillo) un factor de giro por in[j+n/2]. Sin inversión de bits. Debajo, el mar en vivo: la fila z = 0 de la tesela 1, su espectro y |valor| tras cada etapa que corre el mar (amarillo), hasta las alturas que dibuja (azul).',
    },
    marks: {
      stage: { en: 'Ns={v}', es: 'Ns={v}', digits: 0 },
      size: { en: 'sea: {v}×{v}', es: 'mar: {v}×{v}', digits: 0 },
      passes: { en: '{v} passes/axis', es: '{v} pasadas/eje', digits: 0 },
      tile: { en: 'tile {i}: {v} m', es: 'tesela {i}: {v} m', digits: 0, first: 1 },
      rowSpectrum: { en: 'live row z = 0: Σ over kz of h̃, {v} points', es: 'fila en vivo z = 0: Σ sobre kz de h̃, {v} puntos', digits: 0 },
      liveStage: { en: 'after stage {i} (radix {v})', es: 'tras la etapa {i} (radix {v})', digits: 0, first: 1 },
      heights: { en: 'heights, up to {v} m', es: 'alturas, hasta {v} m', digits: 2 },
    },
  },
  lodBands: {
    name: { en: 'The distance bands', es: 'Las bandas de distancia' },
    headline: {
      ring: { en: 'first ring at {v} m', es: 'primer anillo a {v} m', digits: 0 },
      spacing: { en: 'one band, vertices {v} m apart', es: 'una banda, vértices cada {v} m', digits: 0 },
    },
    xAxis: { en: 'distance from the camera, m (log scale)', es: 'distancia a la cámara, m (escala log)' },
    key: {
      en: 'Each band starts twice as far as the last (L, 2L, 4L…) and spaces its vertices further apart (above each band, its spacing); the last reaches the horizon. Colours as the LOD view.',
      es: 'Cada banda empieza al doble de distancia que la anterior (L, 2L, 4L…) y separa más sus vértices (sobre cada banda, su separación); la última llega al horizonte. Colores como la vista LOD.',
    },
    marks: {
      ring: { en: '{v}', es: '{v}', digits: 0 },
      spacing: { en: '{v} m', es: '{v} m', digits: 0 },
      camera: { en: 'camera', es: 'cámara', digits: 0 },
    },
  },
  kelvin: {
    name: { en: 'The Kelvin wedge from above', es: 'La cuña de Kelvin vista desde arriba' },
    key: {
      en: 'Yellow: the ±19.47° wedge. Blue: Kelvin’s crests for a point moving left to right; across the track they are the transverse waves, 2πU²/g apart.',
      es: 'Amarillo: la cuña de ±19,47°. Azul: las crestas de Kelvin de un punto que avanza hacia la derecha; a través de la estela son las olas transversales, separadas 2πU²/g.',
    },
    marks: {
      angle: { en: 'half-angle {v}°', es: 'semiángulo {v}°', digits: 2 },
      boat: { en: 'U = {v} m/s', es: 'U = {v} m/s', digits: 1 },
      transverse: { en: 'λ = {v} m', es: 'λ = {v} m', digits: 1 },
    },
  },
  cauchyPoisson: {
    name: { en: 'A stone’s crests, r = g t²/(8πn)', es: 'Las crestas de la piedra, r = g t²/(8πn)' },
    xAxis: { en: 'r (m)', es: 'r (m)' },
    key: {
      en: 'The profile cos(g t²/4r) along a radius, and its crests r = g t²/(8πn), where the rings on the sea stand: the long waves lead.',
      es: 'El perfil cos(g t²/4r) a lo largo de un radio, y sus crestas r = g t²/(8πn), donde están los anillos sobre el mar: las olas largas van delante.',
    },
    marks: {
      crest: { en: '{v} m', es: '{v} m', digits: 1 },
      age: { en: 't = {v} s', es: 't = {v} s', digits: 1 },
    },
  },
  fresnel: {
    name: { en: 'Fresnel against Schlick', es: 'Fresnel frente a Schlick' },
    xAxis: { en: 'angle from the normal (°)', es: 'ángulo con la normal (°)' },
    yAxis: { en: 'reflectance', es: 'reflectancia' },
    key: {
      en: 'Blue: the exact reflectance (the table the shader reads). Yellow: Schlick’s approximation. Green: where they differ most.',
      es: 'Azul: la reflectancia exacta (la tabla que lee el shader). Amarillo: la aproximación de Schlick. Verde: donde más difieren.',
    },
    marks: {
      difference: { en: 'largest difference {v}', es: 'mayor diferencia {v}', digits: 3 },
      normal: { en: 'F₀ = {v}', es: 'F₀ = {v}', digits: 3 },
    },
  },
};
